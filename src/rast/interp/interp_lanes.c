/*
 * The perspective division of persp.c (seeds 002, 003) for dfx24 on
 * lanes: the quad's four pixels through dfx_lanes.h, each lane the scalar
 * tex_quad_impl's operations in its order:
 *
 *    a = (n_a in the system) · recip(det)     b likewise
 *    w = recip(v0 + a·Δ1 + b·Δ2)              the plane of 1/w
 *    A = (v0 + a·Δ1 + b·Δ2) · w               every PERSPECTIVE component
 *
 * The components go step by step over all of them (every product a·Δ1,
 * then every sum, ...): each step's operations are independent, so the
 * processor overlaps them; one component after the other would wait on
 * each operation's latency.
 *
 * The skips of rast_interp_perspective_setup (docs/datapath.md): a plane
 * whose differences are both zero is its v0 (the multiplier gives zero,
 * the adder returns v0 unchanged, neither with an event), so a constant
 * 1/w takes its reciprocal once per primitive, and a constant component
 * with a constant w is one value; the events those operations would have
 * raised are counted per pixel all the same.  Each quad is first computed
 * optimistically (dfx_lanes.h), and again with its range events handled
 * where one happened; not with noskip.
 *
 * Compiled with DFXL_N = 8 (the 512-bit set, lanes.h), a vector holds both
 * quads of a pair, quad 0 in lanes 0-3: the pair's operations are each one
 * instruction, and only the pair function is compiled (a lone quad takes
 * the 256-bit set's).
 */
#include "rast/setup/front.h"
#include "rast/host/lanes_fns.h"
#include "fixed/dfx_lanes.h"

static inline __attribute__((always_inline)) struct dfxl splat(double v)
{
   struct dfxl r = { dfxl_splatd(v) };
   return r;
}

/* The quads a vector holds. */
#define QPV (DFXL_N / RAST_QUAD_SIZE)

/* Vector k of a pass's results to its quads' inputs, at offset `off`. */
static inline __attribute__((always_inline)) void
store(struct dfxl v, float *const *in, unsigned k, unsigned off)
{
#if DFXL_N == 8
   float f[8];
   dfxl_to_float(v, f);
   memcpy(in[2 * k] + off, f, 4 * sizeof(float));
   memcpy(in[2 * k + 1] + off, f + 4, 4 * sizeof(float));
#else
   dfxl_to_float(v, in[k] + off);
#endif
}

/* `nq` quads (1, or 2 side by side on a row: their operations interleave,
 * each quad's chain of dependent operations being long and the two
 * independent; or one vector with both; or, 512-bit set, 4: two vectors
 * of two, interleaved the same way), each lane a pixel's operations as
 * the scalar path does them; quad k's planes go to in[k] + the component's
 * offset, and an[v], bn[v] are vector v's numerators.
 * `optimistic` (dfx_lanes.h): false, leaving nothing counted, when a lane
 * had a range event.  `n`: the planes evaluated per pixel (t->ln), a
 * constant in the common cases so that the planes stay in registers. */
static inline __attribute__((always_inline)) bool
persp(struct rast_front *fr, float *const *in, const dfxl_i *an, const dfxl_i *bn,
      const bool optimistic, const unsigned n, const unsigned nq)
{
   struct fr_tex *t = &fr->tex;
   struct dfxl_stats st = DFXL_STATS(optimistic);
   const struct dfxl rdet = splat(t->lrdet);
   const unsigned nv = nq / QPV;
   struct dfxl a[2], b[2];
   for (unsigned k = 0; k < nv; k++)
      a[k] = dfxl_mul(dfxl_from_fixed(an[k], (int)t->k, &st), rdet, &st);
   for (unsigned k = 0; k < nv; k++)
      b[k] = dfxl_mul(dfxl_from_fixed(bn[k], (int)t->k, &st), rdet, &st);

   struct dfxl v[2][1 + FR_MAX_COMP], u[2][1 + FR_MAX_COMP];
   /* v0 + a·Δ1 + b·Δ2, one bound an operation (dfxl_add_terms); a term
    * whose difference is zero is left out (t->lterm) */
   for (unsigned i = 0; i < n; i++)
      if (t->lterm[i] & FR_TERM_A)
         for (unsigned k = 0; k < nv; k++)
            v[k][i] = dfxl_term(a[k], splat(t->lv[t->lidx[i]][1]), &st);
   for (unsigned i = 0; i < n; i++)
      if (t->lterm[i] & FR_TERM_B)
         for (unsigned k = 0; k < nv; k++)
            u[k][i] = dfxl_term(b[k], splat(t->lv[t->lidx[i]][2]), &st);
   for (unsigned i = 0; i < n; i++)
      for (unsigned k = 0; k < nv; k++)
         v[k][i] = t->lterm[i] & FR_TERM_A
                      ? dfxl_add_terms(splat(t->lv[t->lidx[i]][0]), v[k][i], &st)
                      : splat(t->lv[t->lidx[i]][0]);
   for (unsigned i = 0; i < n; i++)
      if (t->lterm[i] & FR_TERM_B)
         for (unsigned k = 0; k < nv; k++)
            v[k][i] = dfxl_add_terms(v[k][i], u[k][i], &st);

   struct dfxl w[2];
   unsigned first = 0;
   for (unsigned k = 0; k < nv; k++)
      w[k] = t->w_const ? splat(t->lw) : dfxl_recip(v[k][0], &st);
   if (!t->w_const)
      first = 1;
   for (unsigned i = first; i < n; i++)
      for (unsigned k = 0; k < nv; k++) {
         if (!t->w_one)
            v[k][i] = dfxl_mul(v[k][i], w[k], &st);
         store(v[k][i], in, k, t->lout[i]);
      }
   for (unsigned i = 0; i < t->n_const; i++) {
      if (t->w_const) {
         for (unsigned k = 0; k < nq; k++)
            for (unsigned p = 0; p < RAST_QUAD_SIZE; p++)
               in[k][t->cout[i] + p] = t->cval[i];
         continue;
      }
      for (unsigned k = 0; k < nv; k++)
         store(dfxl_mul(splat(t->lv[t->cidx[i]][0]), w[k], &st), in, k, t->cout[i]);
   }
   if (optimistic && dfxl_any(dfxl_trouble(&st)))
      return false;
   dfxl_stats_add(&t->dst, st);
   fr_tex_counted(t, nq);
   return true;
}

/* The optimistic quads for the common plane counts. */
#define PERSP_N(nn)                                                                           \
   static bool persp_##nn(struct rast_front *fr, float *const *in, const dfxl_i an[2],        \
                          const dfxl_i bn[2], unsigned nq)                                    \
   {                                                                                          \
      if (QPV == 2 && nq == 4)                                                               \
         return persp(fr, in, an, bn, true, nn, 4);                                          \
      return nq == 2 || QPV == 2 ? persp(fr, in, an, bn, true, nn, 2)                       \
                                 : persp(fr, in, an, bn, true, nn, 1);                       \
   }
PERSP_N(1)
PERSP_N(2)
PERSP_N(3)
PERSP_N(4)
PERSP_N(5)
PERSP_N(6)
PERSP_N(7)
PERSP_N(8)

static bool persp_optimistic(struct rast_front *fr, float *const *in, const dfxl_i an[2],
                             const dfxl_i bn[2], unsigned nq)
{
   switch (fr->tex.ln) {
   case 1: return persp_1(fr, in, an, bn, nq);
   case 2: return persp_2(fr, in, an, bn, nq);
   case 3: return persp_3(fr, in, an, bn, nq);
   case 4: return persp_4(fr, in, an, bn, nq);
   case 5: return persp_5(fr, in, an, bn, nq);
   case 6: return persp_6(fr, in, an, bn, nq);
   case 7: return persp_7(fr, in, an, bn, nq);
   case 8: return persp_8(fr, in, an, bn, nq);
   default:
      if (QPV == 2 && nq == 4)
         return persp(fr, in, an, bn, true, fr->tex.ln, 4);
      return nq == 2 || QPV == 2 ? persp(fr, in, an, bn, true, fr->tex.ln, 2)
                     : persp(fr, in, an, bn, true, fr->tex.ln, 1);
   }
}

#if DFXL_N == 8
#include "fixed/dfx_lanes32.h"

/* Four quads in one vector of binary32 lanes (dfx_lanes32.h), quad k in
 * lanes 4k to 4k + 3: persp's operations in its order, optimistic only,
 * from the numerators' entry into the system (dfxf_from_fixed: integers up
 * to 2^52, whose top 24 bits decide the register) on.  False, with nothing
 * written, where a lane had a range event or a reciprocal of zero: the
 * caller then divides the four quads on the binary64 lanes. */
static inline __attribute__((always_inline)) void store16(__m512 v, float *const *in,
                                                          unsigned off)
{
   _mm_storeu_ps(in[0] + off, _mm512_castps512_ps128(v));
   _mm_storeu_ps(in[1] + off, _mm512_extractf32x4_ps(v, 1));
   _mm_storeu_ps(in[2] + off, _mm512_extractf32x4_ps(v, 2));
   _mm_storeu_ps(in[3] + off, _mm512_extractf32x4_ps(v, 3));
}

static inline __attribute__((always_inline)) bool
persp16(struct rast_front *fr, float *const *in, const dfxl_i an[2], const dfxl_i bn[2],
        const unsigned n)
{
   struct fr_tex *t = &fr->tex;
   struct dfxf_stats sf = dfxf_stats_init();
   const struct dfxf rdet = dfxf_splat((float)t->lrdet);
   const struct dfxf a = dfxf_mul(dfxf_from_fixed((__m512i)an[0], (__m512i)an[1], (int)t->k,
                                                  &sf), rdet, &sf);
   const struct dfxf b = dfxf_mul(dfxf_from_fixed((__m512i)bn[0], (__m512i)bn[1], (int)t->k,
                                                  &sf), rdet, &sf);

   struct dfxf v[1 + FR_MAX_COMP], u[1 + FR_MAX_COMP];
   for (unsigned i = 0; i < n; i++)
      if (t->lterm[i] & FR_TERM_A)
         v[i] = dfxf_term(a, dfxf_splat((float)t->lv[t->lidx[i]][1]), &sf);
   for (unsigned i = 0; i < n; i++)
      if (t->lterm[i] & FR_TERM_B)
         u[i] = dfxf_term(b, dfxf_splat((float)t->lv[t->lidx[i]][2]), &sf);
   for (unsigned i = 0; i < n; i++)
      v[i] = t->lterm[i] & FR_TERM_A
                ? dfxf_add_terms(dfxf_splat((float)t->lv[t->lidx[i]][0]), v[i], &sf)
                : dfxf_splat((float)t->lv[t->lidx[i]][0]);
   for (unsigned i = 0; i < n; i++)
      if (t->lterm[i] & FR_TERM_B)
         v[i] = dfxf_add_terms(v[i], u[i], &sf);

   const struct dfxf w = t->w_const ? dfxf_splat((float)t->lw) : dfxf_recip(v[0], &sf);
   struct dfxf out[1 + FR_MAX_COMP], cout[FR_MAX_COMP];
   for (unsigned i = t->w_const ? 0 : 1; i < n; i++)
      out[i] = t->w_one ? v[i] : dfxf_mul(v[i], w, &sf);
   if (!t->w_const)
      for (unsigned i = 0; i < t->n_const; i++)
         cout[i] = dfxf_mul(dfxf_splat((float)t->lv[t->cidx[i]][0]), w, &sf);
   if (dfxf_trouble(&sf))
      return false;

   for (unsigned i = t->w_const ? 0 : 1; i < n; i++)
      store16(out[i].v, in, t->lout[i]);
   for (unsigned i = 0; i < t->n_const; i++) {
      if (t->w_const) {
         for (unsigned k = 0; k < 4; k++)
            _mm_storeu_ps(in[k] + t->cout[i], _mm_set1_ps(t->cval[i]));
         continue;
      }
      store16(cout[i].v, in, t->cout[i]);
   }
   return true;
}

#define PERSP16_N(nn)                                                                         \
   static bool persp16_##nn(struct rast_front *fr, float *const *in, const dfxl_i an[2],      \
                            const dfxl_i bn[2])                                               \
   {                                                                                          \
      return persp16(fr, in, an, bn, nn);                                                     \
   }
PERSP16_N(1)
PERSP16_N(2)
PERSP16_N(3)
PERSP16_N(4)
PERSP16_N(5)
PERSP16_N(6)

/* Four quads, or 3 and a fourth that repeats the third (its numerators
 * the same, so the same bounds: it marks nothing the third does not; its
 * planes go to in[3], a scratch quad).  Nothing counted: the caller counts
 * the quads it divided (fr_tex_counted) where this returns true. */
static bool persp16_optimistic(struct rast_front *fr, float *const *in, const dfxl_i an[2],
                               const dfxl_i bn[2])
{
   switch (fr->tex.ln) {
   case 1: return persp16_1(fr, in, an, bn);
   case 2: return persp16_2(fr, in, an, bn);
   case 3: return persp16_3(fr, in, an, bn);
   case 4: return persp16_4(fr, in, an, bn);
   case 5: return persp16_5(fr, in, an, bn);
   case 6: return persp16_6(fr, in, an, bn);
   default: return persp16(fr, in, an, bn, fr->tex.ln);
   }
}
#endif

/* The lanes' numerators of quad q0 (a at the left pixel of both scan
 * lines, then b) and, with the 512-bit set, q1: each pixel pair the left
 * one and the registers' step right.  Built here as vectors: written as
 * numbers and read as one vector they would wait on the processor's store
 * forwarding. */
static inline __attribute__((always_inline)) void
quad_numerators(const struct fr_tex *t, const int64_t q0[4], const int64_t q1[4], dfxl_i *an,
                dfxl_i *bn)
{
#if DFXL_N == 8
   *an = (dfxl_i){ q0[0], q0[0] + t->a_dx, q0[1], q0[1] + t->a_dx,
                   q1[0], q1[0] + t->a_dx, q1[1], q1[1] + t->a_dx };
   *bn = (dfxl_i){ q0[2], q0[2] + t->b_dx, q0[3], q0[3] + t->b_dx,
                   q1[2], q1[2] + t->b_dx, q1[3], q1[3] + t->b_dx };
#else
   (void)q1;
   *an = (dfxl_i){ q0[0], q0[0] + t->a_dx, q0[1], q0[1] + t->a_dx };
   *bn = (dfxl_i){ q0[2], q0[2] + t->b_dx, q0[3], q0[3] + t->b_dx };
#endif
}

/* The numerators of the quads from `step` quads on from the registers'
 * (the sums are the registers' own steps, tex_numerators). */
static inline __attribute__((always_inline)) void
numerators(const struct fr_tex *t, unsigned step, dfxl_i *an, dfxl_i *bn)
{
   const int64_t a = step * 2 * t->a_dx, b = step * 2 * t->b_dx;
   const int64_t a2 = 2 * t->a_dx, b2 = 2 * t->b_dx;
   const int64_t q0[4] = { t->an[0] + a, t->an[1] + a, t->bn[0] + b, t->bn[1] + b };
   const int64_t q1[4] = { q0[0] + a2, q0[1] + a2, q0[2] + b2, q0[3] + b2 };
   quad_numerators(t, q0, q1, an, bn);
}

/* nq quads (1 or 2 one a vector, 2 or 4 two a vector) from their
 * numerators: optimistically with the skips, and where a lane had a range
 * event again the careful way, both vectors together (two quads a vector)
 * or each quad alone. */
static void divide(struct rast_front *fr, float *const *in, const dfxl_i an[2],
                   const dfxl_i bn[2], unsigned nq)
{
   struct fr_tex *t = &fr->tex;
   /* The binary32 lanes mark exactly what the binary64 ones would (the same
    * bounds), and a reciprocal of zero: where they fail, the careful way. */
#if DFXL_N == 8
   if (nq == 4 && t->skip && t->f32) {
      if (persp16_optimistic(fr, in, an, bn))
         fr_tex_counted(t, 4);
      else
         persp(fr, in, an, bn, false, t->ln, nq);
      return;
   }
#endif
   if (t->skip && persp_optimistic(fr, in, an, bn, nq))
      return;
   if (QPV == 2 || nq == 1) {
      persp(fr, in, an, bn, false, t->ln, nq);
      return;
   }
   float *const in_0[2] = { in[0], NULL }, *const in_1[2] = { in[1], NULL };
   persp(fr, in_0, &an[0], &bn[0], false, t->ln, 1);
   persp(fr, in_1, &an[1], &bn[1], false, t->ln, 1);
}

#if DFXL_N == 4
void LANES_FN(persp_dfx19_lanes)(struct rast_front *fr, struct rast_quad *q)
{
   dfxl_i an[2], bn[2];
   float *const in[2] = { &q->in[0][0][0], NULL };
   numerators(&fr->tex, 0, &an[0], &bn[0]);
   divide(fr, in, an, bn, 1);
}
#endif

void LANES_FN(persp2_dfx19_lanes)(struct rast_front *fr, float *in0, float *in1)
{
   dfxl_i an[2], bn[2];
   float *const in[2] = { in0, in1 };
   numerators(&fr->tex, 0, &an[0], &bn[0]);
   if (QPV == 1)
      numerators(&fr->tex, 1, &an[1], &bn[1]);
   divide(fr, in, an, bn, 2);
}

#if DFXL_N == 8
/* Three quads on the binary32 lanes (the skips taken), the third's
 * numerators q0..q2 repeated as a fourth quad's; false, with nothing
 * written, where the binary64 lanes must divide them. */
static bool three_f32(struct rast_front *fr, float *const in[3], const int64_t q0[4],
                      const int64_t q1[4], const int64_t q2[4])
{
   struct fr_tex *t = &fr->tex;
   if (!t->skip || !t->f32)
      return false;
   float scratch[RAST_MAX_VARYINGS * 4 * RAST_QUAD_SIZE];
   float *const in4[4] = { in[0], in[1], in[2], scratch };
   dfxl_i an[2], bn[2];
   quad_numerators(t, q0, q1, &an[0], &bn[0]);
   quad_numerators(t, q2, q2, &an[1], &bn[1]);
   if (!persp16_optimistic(fr, in4, an, bn))
      return false;
   fr_tex_counted(t, 3);
   return true;
}

/* Three quads of a row from the registers' (the row's last three). */
bool LANES_FN(persp3_dfx19_lanes)(struct rast_front *fr, float *const in[3])
{
   const struct fr_tex *t = &fr->tex;
   const int64_t a = 2 * t->a_dx, b = 2 * t->b_dx;
   const int64_t q0[4] = { t->an[0], t->an[1], t->bn[0], t->bn[1] };
   const int64_t q1[4] = { q0[0] + a, q0[1] + a, q0[2] + b, q0[3] + b };
   const int64_t q2[4] = { q1[0] + a, q1[1] + a, q1[2] + b, q1[3] + b };
   return three_f32(fr, in, q0, q1, q2);
}

/* Four recorded quads on the binary32 lanes with nothing counted:
 * interp_axes.c's tables, whose pixels count when they are drawn. */
bool LANES_FN(persp4_probe_dfx19_lanes)(struct rast_front *fr, float *const in[4],
                                        const int64_t (*num)[4])
{
   struct fr_tex *t = &fr->tex;
   if (!t->skip || !t->f32)
      return false;
   dfxl_i an[2], bn[2];
   quad_numerators(t, num[0], num[1], &an[0], &bn[0]);
   quad_numerators(t, num[2], num[3], &an[1], &bn[1]);
   return persp16_optimistic(fr, in, an, bn);
}
#endif

/* nq recorded quads in one call: 2 or 4 with the 512-bit set, 1 or 2
 * with the others. */
static void persp_recorded(struct rast_front *fr, float *const *in, const int64_t (*num)[4],
                           unsigned nq)
{
   dfxl_i an[2], bn[2];
   for (unsigned v = 0; v < nq / QPV; v++)
      quad_numerators(&fr->tex, num[v * QPV], num[v * QPV + QPV - 1], &an[v], &bn[v]);
   divide(fr, in, an, bn, nq);
}

void LANES_FN(persp_group_dfx19_lanes)(struct rast_front *fr, float *const in[],
                                       const int64_t (*num)[4], unsigned n)
{
#if DFXL_N == 8
   /* four in one call (two groups of four: one call after the other, the
    * processor overlapping their chains); two; a lone quad fills half a
    * vector: the 256-bit set's */
   for (; n > 4; n -= 4, in += 4, num += 4)
      persp_recorded(fr, in, num, 4);
   unsigned k = 0;
   if (n == 4) {
      persp_recorded(fr, in, num, 4);
      return;
   }
   if (n == 3 && three_f32(fr, in, num[0], num[1], num[2]))
      return;
   if (n >= 2) {
      persp_recorded(fr, in, num, 2);
      k = 2;
   }
   if (k < n)
      persp_group_dfx19_lanes_avx2(fr, in + k, num + k, 1);
#else
   unsigned k = 0;
   for (; k + 2 <= n; k += 2)
      persp_recorded(fr, in + k, num + k, 2);
   if (k < n)
      persp_recorded(fr, in + k, num + k, 1);
#endif
}

#if DFXL_N == 8
/* Four quads of a row: the numerators of quads 0-1 in one vector, 2-3 in
 * the other; a range event in either: all four the careful way. */
void LANES_FN(persp4_dfx19_lanes)(struct rast_front *fr, float *const in[4])
{
   dfxl_i an[2], bn[2];
   numerators(&fr->tex, 0, &an[0], &bn[0]);
   numerators(&fr->tex, 2, &an[1], &bn[1]);
   divide(fr, in, an, bn, 4);
}
#endif

/* A primitive's planes, as rast_interp_perspective_setup's plane_set makes
 * each: v0 = from_float(V0), Δ1 = from_float(V1) − v0, Δ2 = from_float(V2)
 * − v0, one plane a lane (plane 0, 1/w, from vertex value 0, plane j from
 * value p0 + j − 1); and recip(det·2^−k) in lane 0 of its own
 * vector.  These are scalar operations through the number system's table
 * on the fields, a few hundred cycles per primitive, which the meshes'
 * small triangles pay thousands of times a frame.  From binary32 is the
 * integer input's rounding (dfxl_from_int: a double holds the value, and
 * its 24 bits plus half a step of its digit fit 53); + 0.0 makes −0 the
 * register's zero.  Optimistic: false, with nothing written, where a lane
 * had a range event or a value is not finite, or det is 0 (a line snapped
 * to a point); the caller then takes the scalar path, which counts them. */
bool LANES_FN(planes_dfx19_lanes)(const float *const vtx[3], unsigned p0, unsigned n,
                                  int64_t det, unsigned k, double (*lv)[3], double *lrdet)
{
   struct dfxl_stats st = DFXL_STATS(true);
   dfxl_i bad = dfxl_splat(0);
   dfxl_d out[3][(1 + RAST_PLANES_MAX + DFXL_N - 1) / DFXL_N];
   unsigned nv = 0;
   for (unsigned j0 = 0; j0 < n; j0 += DFXL_N, nv++) {
      struct dfxl x[3];
      for (unsigned i = 0; i < 3; i++) {
         double v[DFXL_N];
         for (unsigned l = 0, j = j0; l < DFXL_N; l++, j++)
            v[l] = j >= n ? 0.0 : (double)vtx[i][j ? p0 + j - 1 : 0];
         memcpy(&x[i].v, v, sizeof(v));
         bad |= ~(dfxl_abs(x[i].v) < 0x1p32);       /* a NaN compares false */
         x[i] = dfxl_from_int(x[i].v, &st);
         x[i].v += 0.0;
      }
      out[0][nv] = x[0].v;
      out[1][nv] = dfxl_sub(x[1], x[0], &st).v;
      out[2][nv] = dfxl_sub(x[2], x[0], &st).v;
   }
   struct dfxl r = dfxl_recip(dfxl_from_fixed(dfxl_splat(det), (int)k, &st), &st);
   if (!det || dfxl_any(dfxl_trouble(&st) | bad))
      return false;
   for (unsigned j = 0; j < n; j++)
      for (unsigned i = 0; i < 3; i++)
         lv[j][i] = out[i][j / DFXL_N][j % DFXL_N];
   *lrdet = r.v[0];
   return true;
}
