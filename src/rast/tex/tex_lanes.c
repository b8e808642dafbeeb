/*
 * The texture unit's quad for dfx24 on lanes (2-D and 2-D array targets):
 * the quad's four coordinates enter the unit, give the LOD and are
 * addressed together through dfx_lanes.h, each lane the operations of
 * tex_fast.c's quad in its order; the texels are read per tap and
 * filtered on lanes too, one channel of the quad's pixels a vector
 * (soa_level2, the operations of tex_fast_path.h's level).  Pixels of one quad
 * at different levels (a per-pixel bias or explicit LOD that differs) and
 * coordinates outside the coordinate input's direct range take the scalar
 * operations for that pixel or lane: the same operations, so the same bits.
 * The operations on lanes are tex_lanes_ops.h's; here the calls: one quad,
 * two quads (pair2), and four (pairs4, with the window's texel rows).
 */
#include "rast/tex/tex_lanes_ops.h"

#if DFXL_N == 4
/* tex_fast_path.h's level for two dimensions, the quad's addresses at
 * once; the result one channel per vector, and whether in the order after
 * the swizzle (the one-channel-per-vector filter) or before. */
static inline __attribute__((always_inline)) bool
level2(const struct tex_unit *u, const struct quad_kind k, const bool linear, unsigned l,
       struct dfxl cs, struct dfxl ct, const int layer[TEX_QUAD], const float ref[TEX_QUAD],
       lanes_v4f out[4], struct dfxl_stats *st)
{
   const struct tex_level *lv = &u->view.level[l];
   const struct lanes_axis ax[2] = { axis_of(u, l, 0), axis_of(u, l, 1) };
   struct lanes_addr A, B;
   lanes_addr_of(u, linear, k.ws < 0 ? u->samp.wrap[0] : (unsigned)k.ws, &ax[0], cs, &A, st);
   lanes_addr_of(u, linear, k.wt < 0 ? u->samp.wrap[1] : (unsigned)k.wt, &ax[1], ct, &B, st);
   if (k.soa > 0 || (k.soa < 0 && u->lanes_soa)) {
      const lanes_i zoff = { layer[0], layer[1], layer[2], layer[3] };
      soa_level2(u, linear, may_border(k.ws, linear) || may_border(k.wt, linear), l, &A, &B,
                 zoff * (int32_t)lv->img_stride, out);
      return true;
   }
   for (unsigned p = 0; p < TEX_QUAD; p++) {
      const int z = layer[p];
      v4f t;
      if (!linear)
         t = tap(u, lv, A.i0[p], B.i0[p], z, ref[p]);
      else
         t = lerp4(lerp4(tap(u, lv, A.i0[p], B.i0[p], z, ref[p]),
                         tap(u, lv, A.i1[p], B.i0[p], z, ref[p]), (uint32_t)A.w[p]),
                   lerp4(tap(u, lv, A.i0[p], B.i1[p], z, ref[p]),
                         tap(u, lv, A.i1[p], B.i1[p], z, ref[p]), (uint32_t)A.w[p]),
                   (uint32_t)B.w[p]);
      for (unsigned ch = 0; ch < 4; ch++)
         out[ch][p] = t[ch];
   }
   return false;
}

/* tex_lod_diffs for two dimensions: the four differences in one vector. */
static inline __attribute__((always_inline)) int32_t
lod2(const struct tex_unit *u, struct dfxl cs, struct dfxl ct, struct dfxl_stats *st)
{
   const struct dfxl d1 = { { cs.v[3], cs.v[0], ct.v[3], ct.v[0] } };
   const struct dfxl d0 = { { cs.v[2], cs.v[2], ct.v[2], ct.v[2] } };
   const double ss = u->laxis[0][0][0], st_ = u->laxis[0][1][0];
   const struct dfxl sc = { { ss, ss, st_, st_ } };
   const dfxl_d m = dfxl_abs(dfxl_mul(dfxl_sub(d1, d0, st), sc, st).v);
   double rho = 0;
   for (unsigned i = 0; i < 4; i++)
      rho = m[i] > rho ? m[i] : rho;
   ns_val r = { .x = 0 };
   r.d = dfxl_fields(rho);
   return tex_lod_from_rho(u, r);
}

/* The quad; `optimistic` (dfx_lanes.h): false, leaving nothing counted,
 * when a lane had a range event. */
static inline __attribute__((always_inline)) bool
quad2(const struct tex_unit *u, const struct tex_quad *q, enum tex_lod_control ctl,
      float rgba[4][TEX_QUAD], const struct quad_kind k, const bool optimistic)
{
   if (ctl == TEX_LOD_DERIVS) {
      tex_unit_sample_generic(u, q, ctl, rgba);
      return true;
   }
   struct tex_fst x = { { 0, 0 }, { 0, 0 } };
   struct dfxl_stats st = DFXL_STATS(optimistic);
   const bool array = u->view.target == TEX_TARGET_2D_ARRAY;
   struct dfxl cs, ct;
   coords(u, q, &cs, &ct, &x);
   int layer[TEX_QUAD] = { 0, 0, 0, 0 };
   int32_t lod[TEX_QUAD];
   lanes_v4f out[4];
   bool swizzled;
   if (array)
      for (unsigned p = 0; p < TEX_QUAD; p++)
         layer[p] = layer_of(u, q->layer[p]);

   int32_t cl[TEX_QUAD];
   if (!k.nolod) {
      lods(ctl, tex_lod_from_diffs(ctl) ? lod2(u, cs, ct, &st) : 0, q, lod);
      for (unsigned p = 0; p < TEX_QUAD; p++)
         cl[p] = tex_clamp_lod(u, lod[p]);
   }
   if (k.nolod) {
      /* tex_unit_lod_unused: level 0, no fraction, the one filter */
      if (u->samp.mag_filter != TEX_FILTER_NEAREST)
         swizzled = level2(u, k, true, 0, cs, ct, layer, q->ref, out, &st);
      else
         swizzled = level2(u, k, false, 0, cs, ct, layer, q->ref, out, &st);
   } else if (cl[0] == cl[1] && cl[0] == cl[2] && cl[0] == cl[3]) {
      unsigned l0, l1;
      uint32_t frac;
      enum tex_filter f;
      tex_unit_select(u, cl[0], &l0, &l1, &frac, &f);
      const bool linear = f != TEX_FILTER_NEAREST;
      /* one level, or two: one copy of each level function in the code */
      lanes_v4f o[2][4];
      swizzled = false;
      for (unsigned i = 0; i < (frac ? 2u : 1u); i++) {
         if (linear)
            swizzled = level2(u, k, true, i ? l1 : l0, cs, ct, layer, q->ref, o[i], &st);
         else
            swizzled = level2(u, k, false, i ? l1 : l0, cs, ct, layer, q->ref, o[i], &st);
      }
      const float fr = (float)frac * (1.0f / TEX_WEIGHT_ONE);
      for (unsigned ch = 0; ch < 4; ch++)
         out[ch] = frac ? o[0][ch] + fr * (o[1][ch] - o[0][ch]) : o[0][ch];   /* lerp4 */
   } else {
      /* levels differ inside the quad: pixel by pixel, as tex_fast.c */
      swizzled = false;
      for (unsigned p = 0; p < TEX_QUAD; p++) {
         ns_val c[3] = { { .x = 0 }, { .x = 0 }, { .x = 0 } };
         c[0].d = dfxl_fields(cs.v[p]);
         c[1].d = dfxl_fields(ct.v[p]);
         unsigned l0, l1;
         uint32_t frac;
         enum tex_filter f;
         tex_unit_select(u, cl[p], &l0, &l1, &frac, &f);
         v4f t = level_f(u, TEX_FK_DFX19, 2, f, l0, c, layer[p], q->ref[p], &x);
         if (frac)
            t = lerp4(t, level_f(u, TEX_FK_DFX19, 2, f, l1, c, layer[p], q->ref[p], &x), frac);
         for (unsigned ch = 0; ch < 4; ch++)
            out[ch][p] = t[ch];
      }
   }

   if (swizzled) {
      memcpy(rgba, out, sizeof(out));
   } else {
      for (unsigned ch = 0; ch < 4; ch++) {
         const unsigned s = u->view.swizzle[ch];
         const float konst = s == TEX_SWZ_1 ? tex_one(&u->view) : 0.0f;
         const lanes_v4f v = s < 4 ? out[s] : (lanes_v4f){ konst, konst, konst, konst };
         memcpy(rgba[ch], &v, sizeof(v));
      }
   }
   if (optimistic && dfxl_any(dfxl_trouble(&st)))
      return false;
   dfxl_stats_add(&x.d, st);
   tex_fst_flush(&x, u->stats);
   return true;
}

/* The quad functions, specialised per sampler state where the replays
 * spend their time; the generic one reads everything from the unit. */
/* The careful way, for every wrap mode: taken for noskip, and where an
 * optimistic quad had a range event (rare: one copy of the code, with and
 * without the LOD). */
static void quad2_precise(const struct tex_unit *u, const struct tex_quad *q,
                          enum tex_lod_control ctl, float rgba[4][TEX_QUAD])
{
   quad2(u, q, ctl, rgba, (struct quad_kind){ -1, -1, -1, false }, false);
}

static void quad2_precise_nolod(const struct tex_unit *u, const struct tex_quad *q,
                                enum tex_lod_control ctl, float rgba[4][TEX_QUAD])
{
   quad2(u, q, ctl, rgba, (struct quad_kind){ -1, -1, -1, true }, false);
}

#define QUAD2_FN(name, ws, wt, soa, nolod)                                                   \
   static void name(const struct tex_unit *u, const struct tex_quad *q,                      \
                    enum tex_lod_control ctl, float rgba[4][TEX_QUAD])                       \
   {                                                                                         \
      if (!quad2(u, q, ctl, rgba, (struct quad_kind){ ws, wt, soa, nolod }, true))           \
         (nolod ? quad2_precise_nolod : quad2_precise)(u, q, ctl, rgba);                     \
   }

QUAD2_FN(quad2_generic, -1, -1, -1, false)
QUAD2_FN(quad2_generic_nolod, -1, -1, -1, true)
QUAD2_FN(quad2_rr, TEX_WRAP_REPEAT, TEX_WRAP_REPEAT, 1, false)
QUAD2_FN(quad2_rr_nolod, TEX_WRAP_REPEAT, TEX_WRAP_REPEAT, 1, true)
QUAD2_FN(quad2_ee, TEX_WRAP_CLAMP_TO_EDGE, TEX_WRAP_CLAMP_TO_EDGE, 1, false)
QUAD2_FN(quad2_ee_nolod, TEX_WRAP_CLAMP_TO_EDGE, TEX_WRAP_CLAMP_TO_EDGE, 1, true)
QUAD2_FN(quad2_mm, TEX_WRAP_MIRROR_REPEAT, TEX_WRAP_MIRROR_REPEAT, 1, false)
QUAD2_FN(quad2_mm_nolod, TEX_WRAP_MIRROR_REPEAT, TEX_WRAP_MIRROR_REPEAT, 1, true)

/* Whether a pair's s follows the screen's x axis (the same down each
 * column of both quads) and whether its t follows the y axis (the same
 * along each row, both quads on the same rows), as a 2-D window's texture
 * coordinates do.  The registers the coordinate input made are compared,
 * bit for bit. */
static inline __attribute__((always_inline)) bool s_by_column(const struct dfxl cs[2])
{
   const dfxl_i s0 = (dfxl_i)cs[0].v, s1 = (dfxl_i)cs[1].v;
   return !dfxl_any((s0 != __builtin_shufflevector(s0, s0, 2, 3, 0, 1)) |
                    (s1 != __builtin_shufflevector(s1, s1, 2, 3, 0, 1)));
}

static inline __attribute__((always_inline)) bool t_by_row(const struct dfxl ct[2])
{
   const dfxl_i t0 = (dfxl_i)ct[0].v, t1 = (dfxl_i)ct[1].v;
   return !dfxl_any((t0 != __builtin_shufflevector(t0, t0, 1, 0, 3, 2)) | (t1 != t0));
}

/* A quad's addresses from one computed per column (lanes c, c + 1) or per
 * row (lanes 0, 1). */
static inline __attribute__((always_inline)) struct lanes_addr
columns(const struct lanes_addr *a, unsigned c)
{
   struct lanes_addr r;
   if (c == 0) {
      r.i0 = __builtin_shufflevector(a->i0, a->i0, 0, 1, 0, 1);
      r.i1 = __builtin_shufflevector(a->i1, a->i1, 0, 1, 0, 1);
      r.w = __builtin_shufflevector(a->w, a->w, 0, 1, 0, 1);
   } else {
      r.i0 = __builtin_shufflevector(a->i0, a->i0, 2, 3, 2, 3);
      r.i1 = __builtin_shufflevector(a->i1, a->i1, 2, 3, 2, 3);
      r.w = __builtin_shufflevector(a->w, a->w, 2, 3, 2, 3);
   }
   return r;
}

static inline __attribute__((always_inline)) struct lanes_addr rows(const struct lanes_addr *a)
{
   struct lanes_addr r;
   r.i0 = __builtin_shufflevector(a->i0, a->i0, 0, 0, 1, 1);
   r.i1 = __builtin_shufflevector(a->i1, a->i1, 0, 0, 1, 1);
   r.w = __builtin_shufflevector(a->w, a->w, 0, 0, 1, 1);
   return r;
}

/* Two quads of a unit that reads one level without its LOD and filters one
 * channel per vector (the specialised quads' state): quad2's operations
 * for both, each step for the two before the next.  A sample's chain of
 * dependent operations is long and the compiled shader's calls come one
 * after the other, so one quad a call leaves the processor waiting on
 * latencies; two side by side overlap.  Where s follows the screen's x
 * axis, each column's s goes through the address unit once (four lanes of
 * eight), and where t follows y, each row's t (two of eight): the same
 * operations on the same registers.  `shared`: how many of the two axes
 * were addressed so.  False, leaving nothing counted,
 * when a lane had a range event (the caller then takes each quad alone). */
static inline __attribute__((always_inline)) bool
pair2(const struct tex_unit *u, const struct tex_quad q[2], float rgba[2][4][TEX_QUAD],
      const struct quad_kind k, const bool linear, unsigned *shared)
{
   struct tex_fst x = { { 0, 0 }, { 0, 0 } };
   struct dfxl_stats st = DFXL_STATS(true);
   struct dfxl cs[2], ct[2];
   lanes_i zoff[2] = { { 0, 0, 0, 0 }, { 0, 0, 0, 0 } };
   const struct tex_level *lv = &u->view.level[0];
   for (unsigned i = 0; i < 2; i++) {
      coords(u, &q[i], &cs[i], &ct[i], &x);
      if (u->view.target == TEX_TARGET_2D_ARRAY)
         for (unsigned p = 0; p < TEX_QUAD; p++)
            zoff[i][p] = layer_of(u, q[i].layer[p]) * (int32_t)lv->img_stride;
   }
   /* each axis once per column or row where its coordinate follows it */
   const struct lanes_axis ax[2] = { axis_of(u, 0, 0), axis_of(u, 0, 1) };
   struct lanes_addr A[2], B[2];
   const bool s_col = s_by_column(cs), t_row = t_by_row(ct);
   if (s_col) {
      struct lanes_addr SA;
      const struct dfxl sv = { { cs[0].v[0], cs[0].v[1], cs[1].v[0], cs[1].v[1] } };
      lanes_addr_of(u, linear, (unsigned)k.ws, &ax[0], sv, &SA, &st);
      A[0] = columns(&SA, 0);
      A[1] = columns(&SA, 2);
   } else {
      for (unsigned i = 0; i < 2; i++)
         lanes_addr_of(u, linear, (unsigned)k.ws, &ax[0], cs[i], &A[i], &st);
   }
   if (t_row) {
      struct lanes_addr TB;
      const struct dfxl tv = { { ct[0].v[0], ct[0].v[2], ct[0].v[0], ct[0].v[2] } };
      lanes_addr_of(u, linear, (unsigned)k.wt, &ax[1], tv, &TB, &st);
      B[0] = B[1] = rows(&TB);
   } else {
      for (unsigned i = 0; i < 2; i++)
         lanes_addr_of(u, linear, (unsigned)k.wt, &ax[1], ct[i], &B[i], &st);
   }
   /* a count (a saturating floor) of a lane shared by several pixels would
    * be counted once: such a pair (rare) is taken quad by quad.  The counts
    * are numbers, not masks, so compared with zero first. */
   if ((s_col || t_row) && dfxl_any((st.sat | st.flush) != 0))
      return false;
   *shared = (unsigned)s_col + (unsigned)t_row;
   const bool border = may_border(k.ws, linear) || may_border(k.wt, linear);
   lanes_v4f out[2][4];
   for (unsigned i = 0; i < 2; i++)
      soa_level2(u, linear, border, 0, &A[i], &B[i], zoff[i], out[i]);
   if (dfxl_any(dfxl_trouble(&st)))
      return false;
   memcpy(rgba, out, sizeof(out));
   dfxl_stats_add(&x.d, st);
   tex_fst_flush(&x, u->stats);
   return true;
}

#else
/* Whether the pair's s follows the screen's x axis (the same down each
 * column of both quads: lanes 0-3 are quad 0's pixels, 4-7 quad 1's) and
 * whether its t follows the y axis (the same along each row, both quads
 * on the same rows), as pair2's with a quad a vector. */
static inline __attribute__((always_inline)) bool s_by_column(struct dfxl cs)
{
   const dfxl_i s = (dfxl_i)cs.v;
   return !dfxl_any(s != __builtin_shufflevector(s, s, 2, 3, 0, 1, 6, 7, 4, 5));
}

static inline __attribute__((always_inline)) bool t_by_row(struct dfxl ct)
{
   const dfxl_i t = (dfxl_i)ct.v;
   return !dfxl_any((t != __builtin_shufflevector(t, t, 1, 0, 3, 2, 5, 4, 7, 6)) |
                    (t != __builtin_shufflevector(t, t, 4, 5, 6, 7, 0, 1, 2, 3)));
}

/* The pixels' addresses from those computed once per column (lanes 0-3:
 * quad 0's columns, then quad 1's) or once per row (lanes 0, 1). */
#define SPREAD(a, ...)                                                                      \
   ((struct lanes_addr){ __builtin_shufflevector((a).i0, (a).i0, __VA_ARGS__),              \
                         __builtin_shufflevector((a).i1, (a).i1, __VA_ARGS__),              \
                         __builtin_shufflevector((a).w, (a).w, __VA_ARGS__) })

/* The addresses of a pair in one vector (pair2 below, and each vector
 * of pairs4): where s follows the columns, the four columns' s go through
 * the address unit (four lanes of eight, the others a copy), where t
 * follows the rows, the two rows'.  Returns how many of the two axes were
 * shared, or -1 where a count fell in a shared lane (it would be counted
 * once for the several pixels: such a pair, rare, is taken quad by quad). */
static inline __attribute__((always_inline)) int
pair_addr(const struct tex_unit *u, const struct quad_kind k, const bool linear,
          struct dfxl cs, struct dfxl ct, struct lanes_addr *A, struct lanes_addr *B,
          struct dfxl_stats *st)
{
   const bool s_col = s_by_column(cs), t_row = t_by_row(ct);
   const struct lanes_axis ax[2] = { axis_of(u, 0, 0), axis_of(u, 0, 1) };
   if (s_col && t_row && k.ws == k.wt) {
      /* both shared, as a 2-D window's coordinates are: the four columns'
       * s in lanes 0-3 and the two rows' t in lanes 4-7 (twice) through
       * the address unit at once, each lane with its own axis's constants:
       * one pass of the unit where each axis alone would fill a vector
       * with copies */
      struct lanes_axis both;
      memcpy(&both.scale, u->laxis_st[0], sizeof(both.scale));
      memcpy(&both.lo, u->laxis_st[1], sizeof(both.lo));
      memcpy(&both.hi, u->laxis_st[2], sizeof(both.hi));
      memcpy(&both.size, u->lsize_st, sizeof(both.size));
      const struct dfxl st_v = { __builtin_shufflevector(cs.v, ct.v, 0, 1, 4, 5, 8, 10, 8, 10) };
      struct lanes_addr AB;
      lanes_addr_of(u, linear, (unsigned)k.ws, &both, st_v, &AB, st);
      *A = SPREAD(AB, 0, 1, 0, 1, 2, 3, 2, 3);
      *B = SPREAD(AB, 4, 4, 5, 5, 4, 4, 5, 5);
   } else {
      /* the address unit once per axis, on the columns' s or the rows' t
       * where they are shared (one copy of its code an axis) */
      const struct dfxl sv = { __builtin_shufflevector(cs.v, cs.v, 0, 1, 4, 5, 0, 1, 4, 5) };
      const struct dfxl tv = { __builtin_shufflevector(ct.v, ct.v, 0, 2, 0, 2, 0, 2, 0, 2) };
      lanes_addr_of(u, linear, (unsigned)k.ws, &ax[0], s_col ? sv : cs, A, st);
      lanes_addr_of(u, linear, (unsigned)k.wt, &ax[1], t_row ? tv : ct, B, st);
      if (s_col)
         *A = SPREAD(*A, 0, 1, 0, 1, 2, 3, 2, 3);
      if (t_row)
         *B = SPREAD(*B, 0, 0, 1, 1, 0, 0, 1, 1);
   }
   /* the counts are numbers, not masks: compared with zero first */
   if ((s_col || t_row) && dfxl_any((st->sat | st->flush) != 0))
      return -1;
   return (int)s_col + (int)t_row;
}

/* The four quads' addresses where, in both vectors, t follows the rows,
 * and both vectors are on the same two rows (a 2-D window's four quads
 * side by side): the two rows' t through the address unit only where the
 * unit's rows memo does not hold them already, and s, where it follows
 * the columns in both vectors, as the eight columns' s in one vector, or
 * else each pixel's (pair_addr's passes: a coordinate interpolated across
 * the rows may differ in its last bits from one row to the next, as in
 * half of glmark2's desktop blur).  The memo holds rows
 * whose pass raised nothing, and a pass is a function of its inputs and
 * the unit's state (its wrap modes and filter too: a unit's four-quad
 * function filters one way): taking it gives the very registers, and
 * leaves out no count (a shared lane with a count declines, as in
 * pair_addr).
 * false where the vectors are not such; *st_s, *st_t: the passes' events. */
static inline __attribute__((always_inline)) bool
pairs4_addr_rows(const struct tex_unit *u, const struct quad_kind k, const bool linear,
                 const struct dfxl cs[2], const struct dfxl ct[2], struct lanes_addr A[2],
                 struct lanes_addr B[2], struct dfxl_stats *st_s, struct dfxl_stats *st_t,
                 int sh[2])
{
   /* the registers compared bit for bit, as s_by_column and t_by_row do */
   const dfxl_i t_0 = (dfxl_i)ct[0].v, t_1 = (dfxl_i)ct[1].v;
   if (k.ws != k.wt || !t_by_row(ct[0]) || !t_by_row(ct[1]) || t_0[0] != t_1[0] ||
       t_0[2] != t_1[2])
      return false;
   const struct lanes_axis ax[2] = { axis_of(u, 0, 0), axis_of(u, 0, 1) };
   const bool col[2] = { s_by_column(cs[0]), s_by_column(cs[1]) };
   if (col[0] && col[1]) {
      const struct dfxl sv = { __builtin_shufflevector(cs[0].v, cs[1].v, 0, 1, 4, 5, 8, 9,
                                                       12, 13) };
      struct lanes_addr S;
      lanes_addr_of(u, linear, (unsigned)k.ws, &ax[0], sv, &S, st_s);
      A[0] = SPREAD(S, 0, 1, 0, 1, 2, 3, 2, 3);
      A[1] = SPREAD(S, 4, 5, 4, 5, 6, 7, 6, 7);
   } else {
#pragma GCC unroll 2
      for (unsigned v = 0; v < 2; v++)
         lanes_addr_of(u, linear, (unsigned)k.ws, &ax[0], cs[v], &A[v], st_s);
   }
   /* the slot: bits of the registers' digits (a register's low 33 bits are
    * zero), folded */
   const uint64_t h = (uint64_t)t_0[0] >> 33 ^ (uint64_t)t_0[0] >> 38 ^ (uint64_t)t_0[2] >> 35;
   struct tex_rows_memo *m = (struct tex_rows_memo *)&u->rows_memo[h & (TEX_ROWS_MEMO - 1)];
   int64_t m0, m1;
   memcpy(&m0, &m->t[0], 8);
   memcpy(&m1, &m->t[1], 8);
   if (m->valid && t_0[0] == m0 && t_0[2] == m1) {
      memcpy(&B[0].i0, m->i0, sizeof(B[0].i0));
      memcpy(&B[0].i1, m->i1, sizeof(B[0].i1));
      memcpy(&B[0].w, m->w, sizeof(B[0].w));
   } else {
      const struct dfxl tv = { __builtin_shufflevector(ct[0].v, ct[0].v, 0, 2, 0, 2, 0, 2, 0,
                                                       2) };
      struct lanes_addr T;
      lanes_addr_of(u, linear, (unsigned)k.wt, &ax[1], tv, &T, st_t);
      B[0] = SPREAD(T, 0, 0, 1, 1, 0, 0, 1, 1);
      m->valid = !dfxl_any(dfxl_trouble(st_t) | (st_t->sat != 0) | (st_t->flush != 0));
      memcpy(m->t, (const double[2]){ ct[0].v[0], ct[0].v[2] }, sizeof(m->t));
      memcpy(m->i0, &B[0].i0, sizeof(m->i0));
      memcpy(m->i1, &B[0].i1, sizeof(m->i1));
      memcpy(m->w, &B[0].w, sizeof(m->w));
   }
   B[1] = B[0];
   /* the quad-axes each vector's pair would count: t, and s where it
    * follows the columns in that vector (the lanes' registers are the same
    * either way: a pass is lane by lane) */
   for (unsigned v = 0; v < 2; v++)
      sh[v] = 1 + (int)col[v];
   return true;
}

/* A vector's pixels' layers, as byte offsets. */
static inline __attribute__((always_inline)) lanes_i pair_layers(const struct tex_unit *u,
                                                                 const struct tex_quad q[2])
{
   lanes_i zoff = splat_i(0);
   if (u->view.target == TEX_TARGET_2D_ARRAY)
      for (unsigned p = 0; p < DFXL_N; p++)
         zoff[p] = layer_of(u, q[p / TEX_QUAD].layer[p % TEX_QUAD]) *
                   (int32_t)u->view.level[0].img_stride;
   return zoff;
}

/* A vector's results to its two quads' arrays: each quad's four channels
 * (the channels' low halves, then their high halves) are one vector. */
static inline __attribute__((always_inline)) void pair_store(const lanes_f out[4],
                                                             float rgba[2][4][TEX_QUAD])
{
   const taps_f rg = CONCAT(out[0], out[1]), ba = CONCAT(out[2], out[3]);
   const taps_f q0 = __builtin_shufflevector(rg, ba, 0, 1, 2, 3, 8, 9, 10, 11, 16, 17, 18, 19,
                                             24, 25, 26, 27),
                q1 = __builtin_shufflevector(rg, ba, 4, 5, 6, 7, 12, 13, 14, 15, 20, 21, 22, 23,
                                             28, 29, 30, 31);
   _Static_assert(sizeof(q0) == sizeof(rgba[0]), "a quad's channels are one vector");
   memcpy(rgba[0], &q0, sizeof(q0));
   memcpy(rgba[1], &q1, sizeof(q1));
}

/* pair2 above with both quads in one vector: each of its operations is
 * one instruction for the eight pixels, the same operations on the same
 * registers lane by lane. */
static inline __attribute__((always_inline)) bool
pair2(const struct tex_unit *u, const struct tex_quad q[2], float rgba[2][4][TEX_QUAD],
      const struct quad_kind k, const bool linear, unsigned *shared)
{
   struct tex_fst x = { { 0, 0 }, { 0, 0 } };
   struct dfxl_stats st = DFXL_STATS(true);
   struct dfxl cs, ct;
   coords(u, q, &cs, &ct, &x);
   const lanes_i zoff = pair_layers(u, q);
   struct lanes_addr A, B;
   const int sh = pair_addr(u, k, linear, cs, ct, &A, &B, &st);
   if (sh < 0)
      return false;
   *shared = (unsigned)sh;
   const bool border = may_border(k.ws, linear) || may_border(k.wt, linear);
   lanes_f out[4];
   soa_level2(u, linear, border, 0, &A, &B, zoff, out);
   if (dfxl_any(dfxl_trouble(&st)))
      return false;
   pair_store(out, rgba);
   dfxl_stats_add(&x.d, st);
   tex_fst_flush(&x, u->stats);
   return true;
}

#if defined(__AVX512F__)
/* A guess at the four quads' leftmost tap column from the binary32
 * coordinates as they came, before the coordinate input and the address
 * unit: the lesser s of the first quad's left column and the last quad's
 * right one, scaled to texels, less 1.5 (the filter's half texel, and a
 * texel of margin for the registers' truncation), truncated; 0 at least.
 * Only a guess: rows_words checks it against the addresses (a repeated
 * texture, for one, takes its fraction first). */
static inline __attribute__((always_inline)) int32_t
window_guess(const struct tex_unit *u, const struct tex_quad q[4])
{
   const float s = q[0].s[0] < q[3].s[1] ? q[0].s[0] : q[3].s[1];
   /* truncation by the instruction: a NaN or a value past int32 gives
    * INT32_MIN, where a C conversion would be undefined */
   const int32_t g = _mm_cvttss_si32(_mm_set_ss(s * (float)u->laxis[0][0][0] - 1.5f));
   return g < 0 ? 0 : g;
}

/* Whether every tap column of the four quads lies in the 16 from `base`. */
static inline __attribute__((always_inline)) bool
window_holds(__m512i lo, __m512i hi, int32_t base)
{
   const __m512i b = _mm512_set1_epi32(base);
   return !(_mm512_cmplt_epi32_mask(lo, b) |
            _mm512_cmpgt_epi32_mask(_mm512_sub_epi32(hi, b), _mm512_set1_epi32(15)));
}

/* The taps of four quads on the same two rows (pairs4_addr_rows) read from
 * their texel rows instead of gathered: where every column of the four
 * quads' taps lies within 16 texels of the leftmost, each of the (up to)
 * four texel rows is one load of 16 words, and each vector of taps is
 * picked from two of them.  The words are the ones the gathers read
 * (soa_level2: w0 taps (i0, j0) and (i0, j1), w1 (i1, j0) and (i1, j1), in
 * a level without layers and without a border), so the filter's bits are
 * the same; the processor reads four rows where it would gather 64 words.
 * False where the columns spread wider. */
static inline __attribute__((always_inline)) bool
rows_words(const struct tex_level *lv, const struct lanes_addr A[2], const struct lanes_addr *B,
           int32_t guess, taps_i w0[2], taps_i w1[2], uint64_t *reduced)
{
   const __m512i i0 = (__m512i)CONCAT(A[0].i0, A[1].i0), i1 = (__m512i)CONCAT(A[0].i1, A[1].i1);
   const __m512i lo = _mm512_min_epi32(i0, i1), hi = _mm512_max_epi32(i0, i1);
   /* The first column of the texel rows to load.  The loads, and all that
    * follows them, would wait on it, so it is not found by a reduction
    * over the sixteen lanes (a chain of eight operations, about an eighth
    * of the call) but taken from `guess`, which the caller made from the
    * coordinates themselves, in parallel with the address unit; else from
    * the two end quads' columns (where s runs one way along the row, the
    * leftmost is at one end); else by the reduction.  Each is checked on
    * the whole vector: any first column the taps lie within 16 of reads
    * the same words. */
   int32_t base = guess;
   if (!window_holds(lo, hi, base)) {
      base = A[0].i0[0] < A[1].i0[5] ? A[0].i0[0] : A[1].i0[5];
      if (!window_holds(lo, hi, base)) {
         base = _mm512_reduce_min_epi32(lo);
         if (_mm512_reduce_max_epi32(hi) - base > 15)
            return false;
         ++*reduced;
      }
   }
   /* the words of the row from `base` on, those inside the level */
   const int32_t n = lv->w - base;
   const __mmask16 m = n >= 16 ? (__mmask16)0xffff : (__mmask16)((1u << n) - 1);
   const int32_t row[4] = { B->i0[0], B->i0[2], B->i1[0], B->i1[2] };
   __m512i r[4];
   for (unsigned k = 0; k < 4; k++)
      r[k] = _mm512_maskz_loadu_epi32(
         m, lv->data + (size_t)row[k] * lv->row_stride + (size_t)base * 4);
   /* lane p of a vector: pixel p & 7, on pixel row (p >> 1) & 1 (16 picks
    * the second row of a pair), texel row j0 in lanes 0-7, j1 in 8-15 */
   const __m512i second = _mm512_setr_epi32(0, 0, 16, 16, 0, 0, 16, 16, 0, 0, 16, 16, 0, 0, 16,
                                            16);
   const __m512i bv = _mm512_set1_epi32(base);
#pragma GCC unroll 2
   for (unsigned v = 0; v < 2; v++) {
      const __m512i c0 = _mm512_add_epi32(_mm512_sub_epi32((__m512i)TWICE(A[v].i0), bv), second);
      const __m512i c1 = _mm512_add_epi32(_mm512_sub_epi32((__m512i)TWICE(A[v].i1), bv), second);
      w0[v] = (taps_i)_mm512_mask_blend_epi32(0xff00, _mm512_permutex2var_epi32(r[0], c0, r[1]),
                                              _mm512_permutex2var_epi32(r[2], c0, r[3]));
      w1[v] = (taps_i)_mm512_mask_blend_epi32(0xff00, _mm512_permutex2var_epi32(r[0], c1, r[1]),
                                              _mm512_permutex2var_epi32(r[2], c1, r[3]));
   }
   return true;
}
#endif

/* Four quads, two vectors of pair2, each step for both vectors before the
 * next: a pair's chain of dependent operations (coordinate input,
 * addressing, offsets, gathers, filter) is long, and one chain a call
 * leaves the processor waiting on its latencies where two side by side
 * overlap.  Each vector is pair2's operations on its own registers and
 * bounds; false, leaving nothing counted, where either would have
 * returned false (the caller then takes each pair alone, which decides
 * exactly as pair2 does). */
static inline __attribute__((always_inline)) bool
pairs4(const struct tex_unit *u, const struct tex_quad q[4], float rgba[4][4][TEX_QUAD],
       const struct quad_kind k, const bool linear, unsigned *shared)
{
   struct tex_fst x = { { 0, 0 }, { 0, 0 } };
   struct dfxl_stats st[2] = { DFXL_STATS(true), DFXL_STATS(true) };
   struct dfxl cs[2], ct[2];
   lanes_i zoff[2];
   struct lanes_addr A[2], B[2];
   int sh[2];
   const bool border = may_border(k.ws, linear) || may_border(k.wt, linear);
   lanes_f out[2][4];
#pragma GCC unroll 2
   for (unsigned v = 0; v < 2; v++) {
      coords(u, &q[2 * v], &cs[v], &ct[v], &x);
      zoff[v] = pair_layers(u, &q[2 * v]);
   }
#if defined(__AVX512F__)
   /* before the address unit, so as to be ready with it */
   const int32_t guess = window_guess(u, q);
#endif
   const bool rows = pairs4_addr_rows(u, k, linear, cs, ct, A, B, &st[0], &st[1], sh);
   if (rows) {
      /* the counts are numbers, not masks: compared with zero first */
      if (dfxl_any((st[0].sat | st[0].flush | st[1].sat | st[1].flush) != 0))
         return false;
   } else {
#pragma GCC unroll 2
      for (unsigned v = 0; v < 2; v++)
         sh[v] = pair_addr(u, k, linear, cs[v], ct[v], &A[v], &B[v], &st[v]);
      if ((sh[0] | sh[1]) < 0)
         return false;
   }
#if defined(__AVX512F__)
   taps_i w0[2], w1[2];
   if (linear && rows && !border && u->view.target != TEX_TARGET_2D_ARRAY &&
       rows_words(&u->view.level[0], A, &B[0], guess, w0, w1,
                  &((struct tex_unit *)u)->rows_reduced)) {
      struct tex_unit *mu = (struct tex_unit *)u;
      mu->rows_loaded++;
#pragma GCC unroll 2
      for (unsigned v = 0; v < 2; v++)
         soa_filter2(u, false, &A[v], &B[v], w0[v], (taps_i){ 0 }, w1[v], (taps_i){ 0 },
                     out[v]);
   } else
#endif
#pragma GCC unroll 2
   for (unsigned v = 0; v < 2; v++)
      soa_level2(u, linear, border, 0, &A[v], &B[v], zoff[v], out[v]);
   if (dfxl_any(dfxl_trouble(&st[0]) | dfxl_trouble(&st[1])))
      return false;
   *shared = (unsigned)(sh[0] + sh[1]);
   pair_store(out[0], &rgba[0]);
   pair_store(out[1], &rgba[2]);
   dfxl_stats_add(&x.d, st[0]);
   dfxl_stats_add(&x.d, st[1]);
   tex_fst_flush(&x, u->stats);
   return true;
}
#endif

/* The pair functions; where a lane had a range event, each quad alone
 * through the unit's quad function (with DFXL_N = 8, the AVX2 set's). */
#if DFXL_N == 4
#define PAIR2_QUAD(quad_fn) quad_fn
#else
#define PAIR2_QUAD(quad_fn) u->quad
#endif
#define PAIR2_FN(name, quad_fn, ws, wt)                                                      \
   static void name(const struct tex_unit *u, const struct tex_quad q[2],                    \
                    enum tex_lod_control ctl, float rgba[2][4][TEX_QUAD])                    \
   {                                                                                         \
      const struct quad_kind k = { ws, wt, 1, true };                                        \
      unsigned sh = 0;                                                                       \
      if (ctl != TEX_LOD_DERIVS &&                                                           \
          (u->samp.mag_filter != TEX_FILTER_NEAREST ? pair2(u, q, rgba, k, true, &sh)        \
                                                    : pair2(u, q, rgba, k, false, &sh))) {   \
         if (u->axes_shared)                                                                 \
            *u->axes_shared += 2 * sh;                                                       \
         return;                                                                             \
      }                                                                                      \
      PAIR2_QUAD(quad_fn)(u, &q[0], ctl, rgba[0]);                                           \
      PAIR2_QUAD(quad_fn)(u, &q[1], ctl, rgba[1]);                                           \
   }

PAIR2_FN(pair2_rr_nolod, quad2_rr_nolod, TEX_WRAP_REPEAT, TEX_WRAP_REPEAT)
PAIR2_FN(pair2_ee_nolod, quad2_ee_nolod, TEX_WRAP_CLAMP_TO_EDGE, TEX_WRAP_CLAMP_TO_EDGE)
PAIR2_FN(pair2_mm_nolod, quad2_mm_nolod, TEX_WRAP_MIRROR_REPEAT, TEX_WRAP_MIRROR_REPEAT)

#if DFXL_N == 8
/* The four-quad functions; where pairs4 declines, each pair alone. */
#define PAIRS4_FN(name, pair_fn, ws, wt)                                                     \
   static void name(const struct tex_unit *u, const struct tex_quad q[4],                    \
                    enum tex_lod_control ctl, float rgba[4][4][TEX_QUAD])                    \
   {                                                                                         \
      const struct quad_kind k = { ws, wt, 1, true };                                        \
      unsigned sh = 0;                                                                       \
      if (ctl != TEX_LOD_DERIVS &&                                                           \
          (u->samp.mag_filter != TEX_FILTER_NEAREST ? pairs4(u, q, rgba, k, true, &sh)       \
                                                    : pairs4(u, q, rgba, k, false, &sh))) {  \
         if (u->axes_shared)                                                                 \
            *u->axes_shared += 2 * sh;                                                       \
         return;                                                                             \
      }                                                                                      \
      pair_fn(u, &q[0], ctl, &rgba[0]);                                                      \
      pair_fn(u, &q[2], ctl, &rgba[2]);                                                      \
   }

PAIRS4_FN(pairs4_rr_nolod, pair2_rr_nolod, TEX_WRAP_REPEAT, TEX_WRAP_REPEAT)
PAIRS4_FN(pairs4_ee_nolod, pair2_ee_nolod, TEX_WRAP_CLAMP_TO_EDGE, TEX_WRAP_CLAMP_TO_EDGE)
PAIRS4_FN(pairs4_mm_nolod, pair2_mm_nolod, TEX_WRAP_MIRROR_REPEAT, TEX_WRAP_MIRROR_REPEAT)
#define FOUR(fn) fn
#else
#define FOUR(fn) NULL
#endif

/* The states with a pair function, and with the 512-bit set a four-quad one. */
static const struct {
   enum tex_wrap ws, wt;
   tex_quad2_fn pair_nolod;
   tex_quad4_fn four_nolod;
} pairs[] = {
   { TEX_WRAP_REPEAT, TEX_WRAP_REPEAT, pair2_rr_nolod, FOUR(pairs4_rr_nolod) },
   { TEX_WRAP_CLAMP_TO_EDGE, TEX_WRAP_CLAMP_TO_EDGE, pair2_ee_nolod, FOUR(pairs4_ee_nolod) },
   { TEX_WRAP_MIRROR_REPEAT, TEX_WRAP_MIRROR_REPEAT, pair2_mm_nolod, FOUR(pairs4_mm_nolod) },
};
#undef FOUR

static tex_quad2_fn pair_of(const struct tex_unit *u, bool nolod, tex_quad4_fn *four)
{
   *four = NULL;
   if (u->lanes_soa && nolod)
      for (unsigned i = 0; i < sizeof(pairs) / sizeof(pairs[0]); i++)
         if (u->samp.wrap[0] == pairs[i].ws && u->samp.wrap[1] == pairs[i].wt) {
            *four = pairs[i].four_nolod;
            return pairs[i].pair_nolod;
         }
   return NULL;
}

#if DFXL_N == 4
tex_quad_fn LANES_FN(tex_dfx19_2d_lanes)(const struct tex_unit *u, bool noskip, bool nolod,
                                        tex_quad2_fn *pair, tex_quad4_fn *four)
{
   *pair = NULL;
   *four = NULL;
   if (noskip)
      return quad2_precise;
   static const struct {
      enum tex_wrap ws, wt;
      tex_quad_fn fn[2];
   } special[] = {
      { TEX_WRAP_REPEAT, TEX_WRAP_REPEAT, { quad2_rr, quad2_rr_nolod } },
      { TEX_WRAP_CLAMP_TO_EDGE, TEX_WRAP_CLAMP_TO_EDGE, { quad2_ee, quad2_ee_nolod } },
      { TEX_WRAP_MIRROR_REPEAT, TEX_WRAP_MIRROR_REPEAT, { quad2_mm, quad2_mm_nolod } },
   };
   if (u->lanes_soa)
      for (unsigned i = 0; i < sizeof(special) / sizeof(special[0]); i++)
         if (u->samp.wrap[0] == special[i].ws && u->samp.wrap[1] == special[i].wt) {
            *pair = pair_of(u, nolod, four);
            return special[i].fn[nolod];
         }
   return nolod ? quad2_generic_nolod : quad2_generic;
}
#else
/* A lone quad fills half a vector: the AVX2 set's quad functions, and the
 * pairs here where that set has one. */
tex_quad_fn LANES_FN(tex_dfx19_2d_lanes)(const struct tex_unit *u, bool noskip, bool nolod,
                                        tex_quad2_fn *pair, tex_quad4_fn *four)
{
   const tex_quad_fn quad = tex_dfx19_2d_lanes_avx2(u, noskip, nolod, pair, four);
   if (*pair)
      *pair = pair_of(u, nolod, four);
   return quad;
}
#endif
