/*
 * The perspective division of the texture path (seeds 002, 003), the one
 * place where texture coordinates are divided: the vector method
 * of seed 002 in the number system of rast_set_texfmt (seed 003).  Per
 * primitive (rast_interp_perspective_setup): det, the doubled area of
 * V0 V1 V2 from the fixed-point vertices (an exact integer), recip(det) in
 * the system, and for 1/w and each A/w the value at V0 and the differences
 * Δ1 = v1 - v0, Δ2 = v2 - v0, all in the system.  Per pixel centre p:
 *
 *    a = ((p - V0) x (V2 - V0)) / det,   b = ((V1 - V0) x (p - V0)) / det
 *
 * (Cramer's rule: Vp = V0 + a·(V1 - V0) + b·(V2 - V0)), whose numerators
 * are exact integers stepped per pixel; each enters the system and is
 * multiplied by recip(det); then v = v0 + a·Δ1 + b·Δ2 for 1/w and every
 * A/w, and A = (A/w) · recip(1/w), one reciprocal per pixel.  Each pixel
 * rounds a fixed number of operations (no error grows along a span), and a
 * helper gets the plane's value at its own centre.  A format that cannot
 * hold a coordinate, its 1/w or their reciprocal shows it on the screen
 * (seed 003: 8.24 saturates w > 128); range events go to rast_stats.tex_sat
 * and tex_flush.
 *
 * One body, specialised at validation: binary32 inline on float vectors,
 * dfx through dfx_ops.h inline (the seed's W = 19 as a constant, other
 * widths at run time), any other system through its numsys table.  The
 * span processor (span.c) walks the quads and calls it.
 */
#include <float.h>
#include <math.h>
#include <string.h>
#include "rast/setup/front.h"
#include "rast/interp/interp_modes.h"
#include "fixed/dfx_ops.h"
#include "rast/host/lanes.h"
#include "fixed/dfx_lanes.h"
#include "rast/interp/persp.h"

enum tex_kind { TEX_FLOAT, TEX_DFX19, TEX_DFX, TEX_NS };

static inline __attribute__((always_inline)) bool tex_is_dfx(const enum tex_kind k)
{
   return k == TEX_DFX19 || k == TEX_DFX;
}

static inline __attribute__((always_inline)) struct dfx_format
tex_df(const struct fr_tex *t, const enum tex_kind k)
{
   if (k == TEX_DFX19) {
      struct dfx_format f = { DFX_MANT_BITS_SEED };
      return f;
   }
   return t->ns->dfx;
}

static inline __attribute__((always_inline)) float tex_fcount(struct ns_stats *ls, float r)
{
   /* branch-free: the float path stays cheap */
   float a = fabsf(r);
   ls->sat += a > FLT_MAX;
   ls->flush += (a < FLT_MIN) & (a != 0);
   return r;
}

/* An exact numerator n of a or b: n·2^-k in the system. */
static inline __attribute__((always_inline)) ns_val
tex_scaled(struct fr_tex *t, struct ns_stats *ls, const enum tex_kind k, int64_t n)
{
   ns_val r;
   if (k == TEX_FLOAT)
      r.f = (float)n * t->fscale;        /* the power of two is exact */
   else if (tex_is_dfx(k))
      r.d = dfx_from_fixed_i(tex_df(t, k), t->kfmt, n, &t->dst);
   else
      r = t->ns->from_scaled(t->ns, n, t->k, ls);
   return r;
}

static inline __attribute__((always_inline)) ns_val
tex_add(struct fr_tex *t, struct ns_stats *ls, const enum tex_kind k, ns_val a, ns_val b)
{
   ns_val r;
   if (k == TEX_FLOAT)
      r.f = tex_fcount(ls, a.f + b.f);
   else if (tex_is_dfx(k))
      r.d = dfx_add_i(tex_df(t, k), a.d, b.d, &t->dst);
   else
      r = t->ns->add(t->ns, a, b, ls);
   return r;
}

static inline __attribute__((always_inline)) ns_val
tex_mul(struct fr_tex *t, struct ns_stats *ls, const enum tex_kind k, ns_val a, ns_val b)
{
   ns_val r;
   if (k == TEX_FLOAT) {
      r.f = tex_fcount(ls, a.f * b.f);
      ls->flush += (r.f == 0) & (a.f != 0) & (b.f != 0);
   } else if (tex_is_dfx(k)) {
      r.d = dfx_mul_i(tex_df(t, k), a.d, b.d, &t->dst);
   } else {
      r = t->ns->mul(t->ns, a, b, ls);
   }
   return r;
}

static inline __attribute__((always_inline)) ns_val
tex_recip(struct fr_tex *t, struct ns_stats *ls, const enum tex_kind k, ns_val a)
{
   ns_val r;
   if (k == TEX_FLOAT)
      r.f = tex_fcount(ls, 1.0f / a.f);
   else if (tex_is_dfx(k))
      r.d = dfx_recip_i(tex_df(t, k), a.d, &t->dst);
   else
      r = t->ns->recip(t->ns, a, ls);
   return r;
}

static inline __attribute__((always_inline)) float
tex_out(struct fr_tex *t, const enum tex_kind k, ns_val a)
{
   if (k == TEX_FLOAT)
      return a.f;
   if (tex_is_dfx(k))
      return (float)dfx_to_double_i(tex_df(t, k), a.d);
   return t->ns->to_float(t->ns, a);
}

/* v0 + a·Δ1 + b·Δ2 */
static inline __attribute__((always_inline)) ns_val
tex_plane(struct fr_tex *t, struct ns_stats *ls, const enum tex_kind k,
          const struct fr_plane *p, ns_val a, ns_val b)
{
   ns_val s = tex_add(t, ls, k, p->v0, tex_mul(t, ls, k, a, p->d1));
   return tex_add(t, ls, k, s, tex_mul(t, ls, k, b, p->d2));
}

static ns_val plane_vertex(const struct numsys *ns, float v, struct ns_stats *st)
{
   return ns->from_float(ns, v, st);
}

static void plane_set(struct fr_plane *p, const struct numsys *ns, float v0, float v1,
                      float v2, struct ns_stats *st)
{
   ns_val a = plane_vertex(ns, v0, st), b = plane_vertex(ns, v1, st),
          c = plane_vertex(ns, v2, st);
   p->v0 = a;
   p->d1 = ns->sub(ns, b, a, st);
   p->d2 = ns->sub(ns, c, a, st);
}

static bool plane_is_const(const struct fr_plane *p)
{
   return !p->d1.d.m && !p->d2.d.m;
}

/* Plane `idx` into the planes the lanes evaluate per pixel, its output at
 * float offset `out`, with the terms it has.  A plane with one zero
 * difference (a 2-D window's texture coordinate along an edge that follows
 * its axis) leaves that term out: a·0 and b·0 are zero registers, and the
 * adder returns the other operand unchanged, neither with a range event. */
static void lanes_plane(struct fr_tex *t, unsigned idx, uint16_t out)
{
   const struct fr_plane *p = &t->pl[idx];
   const unsigned i = t->ln++;
   t->lidx[i] = (uint8_t)idx;
   t->lout[i] = out;
   t->lterm[i] = FR_TERM_A | FR_TERM_B;
   if (t->skip) {
      t->lterm[i] = (uint8_t)((p->d1.d.m ? FR_TERM_A : 0u) | (p->d2.d.m ? FR_TERM_B : 0u));
      t->n_zero_terms += (p->d1.d.m == 0) + (p->d2.d.m == 0);
   }
}

/* The skips of the dfx24 lanes (interp_lanes.c) for this primitive: which
 * planes are constant, and what a constant 1/w and the constant
 * components give, with the range events each pixel would raise. */
static void lanes_skips_setup(struct rast_front *fr)
{
   struct fr_tex *t = &fr->tex;
   const struct dfx_format f = { DFX_MANT_BITS_SEED };
   struct dfx w = dfx_zero();
   t->w_const = t->skip && plane_is_const(&t->pl[0]);
   t->w_one = false;
   t->const_ev = (struct dfx_stats){ 0, 0 };
   if (t->w_const) {
      w = dfx_recip_i(f, t->pl[0].v0.d, &t->const_ev);
      t->lw = dfxl_value(w);
      t->w_one = t->lw == 1.0;
   }
   t->ln = 0;
   t->n_const = 0;
   t->n_zero_terms = 0;
   if (!t->w_const)
      lanes_plane(t, 0, 0);
   for (unsigned j = 0; j < fr->npersp; j++) {
      const uint16_t out = (uint16_t)(&fr->quad[0].in[fr->persp[j].var][fr->persp[j].chan][0] -
                                      &fr->quad[0].in[0][0][0]);
      if (!(t->skip && plane_is_const(&t->pl[1 + j]))) {
         lanes_plane(t, 1 + j, out);
         continue;
      }
      if (t->w_const)
         t->cval[t->n_const] = (float)dfx_to_double_i(f, dfx_mul_i(f, t->pl[1 + j].v0.d, w,
                                                                   &t->const_ev));
      t->cout[t->n_const] = out;
      t->cidx[t->n_const++] = (uint8_t)(1 + j);
   }
}

_Static_assert(FR_MAX_COMP == RAST_PLANES_MAX, "the lanes' planes are the front's");

/* The planes of plane_set and the determinant's reciprocal on the lanes,
 * the same bits (test_persp_fast), where no operation has a range event;
 * the registers' fields from their values. */
static bool lanes_planes(struct rast_front *fr, unsigned i0, unsigned i1, unsigned i2,
                         int64_t det)
{
   struct fr_tex *t = &fr->tex;
   const unsigned n = 1 + fr->npersp;
   const float *const vtx[3] = { fr->vflt[i0], fr->vflt[i1], fr->vflt[i2] };
   if (!rast_lanes()->planes_dfx19(vtx, 1 + fr->nlin, n, det, t->k, t->lv, &t->lrdet))
      return false;
   for (unsigned j = 0; j < n; j++) {
      t->pl[j].v0.d = dfxl_fields(t->lv[j][0]);
      t->pl[j].d1.d = dfxl_fields(t->lv[j][1]);
      t->pl[j].d2.d = dfxl_fields(t->lv[j][2]);
   }
   t->rdet.d = dfxl_fields(t->lrdet);
   return true;
}

void rast_interp_perspective_setup(struct rast_context *rc, struct rast_front *fr,
                                   unsigned i0, unsigned i1, unsigned i2)
{
   struct fr_tex *t = &fr->tex;
   const struct numsys *ns = t->ns;
   struct ns_stats st = { 0, 0 };
   const int64_t S = fr->S;
   t->x0 = fr->X[i0];
   t->y0 = fr->Y[i0];
   t->e1x = fr->X[i1] - t->x0;
   t->e1y = fr->Y[i1] - t->y0;
   t->e2x = fr->X[i2] - t->x0;
   t->e2y = fr->Y[i2] - t->y0;
   /* |e| < 2^29 (the XY formats have at most 28 bits with the sign), so
    * det and every numerator below fit in 64 bits */
   int64_t det = t->e1x * t->e2y - t->e1y * t->e2x;
   t->a_dx = t->e2y * S;
   t->a_dy = -t->e2x * S;
   t->b_dx = -t->e1y * S;
   t->b_dy = t->e1x * S;
   t->k = fx_bitlen64(det < 0 ? -(uint64_t)det : (uint64_t)det);
   t->kfmt = (struct fx_format){ 0, (uint8_t)t->k };
   t->fscale = (float)fx_pow2(-(int)t->k);
   t->frdet = det ? 1.0f / ((float)det * t->fscale) : 0.0f;
   const float *v0 = fr->vflt[i0], *v1 = fr->vflt[i1], *v2 = fr->vflt[i2];
   const unsigned p0 = 1 + fr->nlin;       /* vflt[]: 1/w, LINEAR, PERSPECTIVE */
   if (!(t->lanes && lanes_planes(fr, i0, i1, i2, det))) {
      /* det = 0: a line snapped to a point, every pixel takes V0's values */
      t->rdet = det ? ns->recip(ns, ns->from_scaled(ns, det, t->k, &st), &st)
                    : ns->from_float(ns, 0.0f, &st);
      plane_set(&t->pl[0], ns, v0[0], v1[0], v2[0], &st);
      if (t->any_color)
         plane_set(&t->fow, t->fns, v0[0], v1[0], v2[0], &st);
      for (unsigned j = 0; j < fr->npersp; j++)
         plane_set(&t->pl[1 + j], t->is_color[j] ? t->fns : ns, v0[p0 + j], v1[p0 + j],
                   v2[p0 + j], &st);
      if (t->lanes) {
         for (unsigned j = 0; j < 1 + fr->npersp; j++) {
            t->lv[j][0] = dfxl_value(t->pl[j].v0.d);
            t->lv[j][1] = dfxl_value(t->pl[j].d1.d);
            t->lv[j][2] = dfxl_value(t->pl[j].d2.d);
         }
         t->lrdet = dfxl_value(t->rdet.d);
      }
   }
   if (t->lanes)
      lanes_skips_setup(fr);
   rast_interp_axes_setup(fr);
   rc->stats.tex_sat += st.sat;
   rc->stats.tex_flush += st.flush;
}

/* The numerators at the centres of pixel x of scan lines y and y + 1. */
static void tex_begin(struct rast_front *fr, int64_t x, int64_t y)
{
   struct fr_tex *t = &fr->tex;
   int64_t px = x * fr->S + fr->Hx - t->x0, py = y * fr->S + fr->Hy - t->y0;
   t->an[0] = px * t->e2y - py * t->e2x;
   t->bn[0] = t->e1x * py - t->e1y * px;
   t->an[1] = t->an[0] + t->a_dy;
   t->bn[1] = t->bn[0] + t->b_dy;
   t->pending = 0;
}

/* The quad's numerators (pixels x, x+1 of both scan lines), and the
 * registers moved on to the next quad. */
static inline __attribute__((always_inline)) void
tex_numerators(struct fr_tex *t, int64_t an[RAST_QUAD_SIZE], int64_t bn[RAST_QUAD_SIZE])
{
   for (unsigned r = 0; r < 2; r++) {
      an[2 * r] = t->an[r];
      an[2 * r + 1] = t->an[r] + t->a_dx;
      bn[2 * r] = t->bn[r];
      bn[2 * r + 1] = t->bn[r] + t->b_dx;
   }
   tex_numerators_next(t);
}

/* COLOR components of a non-float system: the same form in binary32. */
static void tex_color_weights(struct fr_tex *t, struct ns_stats *ls,
                              const int64_t an[RAST_QUAD_SIZE], const int64_t bn[RAST_QUAD_SIZE],
                              ns_val fa[RAST_QUAD_SIZE], ns_val fb[RAST_QUAD_SIZE],
                              ns_val fw[RAST_QUAD_SIZE])
{
   ns_val r;
   r.f = t->frdet;
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      fa[i] = tex_mul(t, ls, TEX_FLOAT, tex_scaled(t, ls, TEX_FLOAT, an[i]), r);
      fb[i] = tex_mul(t, ls, TEX_FLOAT, tex_scaled(t, ls, TEX_FLOAT, bn[i]), r);
      fw[i] = tex_recip(t, ls, TEX_FLOAT, tex_plane(t, ls, TEX_FLOAT, &t->fow, fa[i], fb[i]));
   }
}

static inline __attribute__((always_inline)) void
tex_quad_impl(struct rast_front *fr, struct rast_quad *q, bool divide, const enum tex_kind k)
{
   struct fr_tex *t = &fr->tex;
   int64_t an[RAST_QUAD_SIZE], bn[RAST_QUAD_SIZE];
   tex_numerators(t, an, bn);
   if (!divide)
      return;
   struct ns_stats ls = { 0, 0 };
   ns_val a[RAST_QUAD_SIZE], b[RAST_QUAD_SIZE], w[RAST_QUAD_SIZE];
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      a[i] = tex_mul(t, &ls, k, tex_scaled(t, &ls, k, an[i]), t->rdet);
      b[i] = tex_mul(t, &ls, k, tex_scaled(t, &ls, k, bn[i]), t->rdet);
      w[i] = tex_recip(t, &ls, k, tex_plane(t, &ls, k, &t->pl[0], a[i], b[i]));
   }
   ns_val fa[RAST_QUAD_SIZE], fb[RAST_QUAD_SIZE], fw[RAST_QUAD_SIZE];
   if (t->any_color)
      tex_color_weights(t, &ls, an, bn, fa, fb, fw);
   for (unsigned j = 0; j < fr->npersp; j++) {
      float *o = q->in[fr->persp[j].var][fr->persp[j].chan];
      const struct fr_plane *p = &t->pl[1 + j];
      if (t->is_color[j]) {
         for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
            o[i] = tex_mul(t, &ls, TEX_FLOAT, tex_plane(t, &ls, TEX_FLOAT, p, fa[i], fb[i]),
                           fw[i]).f;
         continue;
      }
      for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
         o[i] = tex_out(t, k, tex_mul(t, &ls, k, tex_plane(t, &ls, k, p, a[i], b[i]), w[i]));
   }
   t->st.sat += ls.sat;
   t->st.flush += ls.flush;
}

/* tex_quad_impl for one number system: the entries of the quad table
 * (fr_tex.quad) that divide each quad alone, so take no look-ahead.
 * tex_quad_float_ref is binary32's reference: tex_quad_float must give its
 * bits and range events (test_persp_fast). */
#define TEX_QUAD_ALONE(name, kind)                                                      \
   static void name(struct rast_front *fr, struct rast_quad *q, bool divide, unsigned ahead) \
   {                                                                                    \
      (void)ahead;                                                                      \
      tex_quad_impl(fr, q, divide, kind);                                               \
   }
TEX_QUAD_ALONE(tex_quad_dfx19, TEX_DFX19)
TEX_QUAD_ALONE(tex_quad_float_ref, TEX_FLOAT)
TEX_QUAD_ALONE(tex_quad_dfx, TEX_DFX)
TEX_QUAD_ALONE(tex_quad_ns, TEX_NS)
#undef TEX_QUAD_ALONE

/* With the skips taken, two quads of a row that both divide are divided
 * together (persp2_dfx19), the second one's planes kept for its turn. */
static void tex_quad_dfx19_lanes(struct rast_front *fr, struct rast_quad *q, bool divide,
                                 unsigned ahead)
{
   struct fr_tex *t = &fr->tex;
   if (t->pending) {
      float *in = &q->in[0][0][0];
      const float *next = t->next[t->n_next - t->pending];
      for (unsigned i = t->w_const ? 0 : 1; i < t->ln; i++)
         memcpy(in + t->lout[i], next + t->lout[i], sizeof(float[RAST_QUAD_SIZE]));
      for (unsigned i = 0; i < t->n_const; i++)
         memcpy(in + t->cout[i], next + t->cout[i], sizeof(float[RAST_QUAD_SIZE]));
      t->pending--;
   } else if (divide && ahead >= 3) {          /* t->lookahead: the skips, and persp4 */
      float *const in[4] = { &q->in[0][0][0], t->next[0], t->next[1], t->next[2] };
      rast_lanes()->persp4_dfx19(fr, in);
      t->pending = t->n_next = 3;
   } else if (divide && ahead == 2 && rast_lanes()->persp3_dfx19 &&
              rast_lanes()->persp3_dfx19(fr, (float *const[3]){ &q->in[0][0][0], t->next[0],
                                                                 t->next[1] })) {
      t->pending = t->n_next = 2;
   } else if (divide && ahead) {
      rast_lanes()->persp2_dfx19(fr, &q->in[0][0][0], t->next[0]);
      t->pending = t->n_next = 1;
   } else if (divide) {
      rast_lanes()->persp_dfx19(fr, q);
   }
   tex_numerators_next(t);
}




/* binary32: tex_quad_impl's operations, in the same order, on float[4]
 * vectors, so that the compiler keeps them in SIMD registers (an ns_val
 * array is strided); the range events are counted branch-free over each
 * vector. */
static inline void tex_fcount4(struct ns_stats *ls, const float v[RAST_QUAD_SIZE])
{
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
      tex_fcount(ls, v[i]);
}

static inline void tex_fplane4(const struct fr_plane *p, const float a[RAST_QUAD_SIZE],
                               const float b[RAST_QUAD_SIZE], float v[RAST_QUAD_SIZE])
{
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
      v[i] = (p->v0.f + a[i] * p->d1.f) + b[i] * p->d2.f;
}

static void tex_quad_float(struct rast_front *fr, struct rast_quad *q, bool divide,
                           unsigned ahead)
{
   (void)ahead;
   struct fr_tex *t = &fr->tex;
   int64_t an[RAST_QUAD_SIZE], bn[RAST_QUAD_SIZE];
   tex_numerators(t, an, bn);
   if (!divide)
      return;
   struct ns_stats ls = { 0, 0 };
   float a[RAST_QUAD_SIZE], b[RAST_QUAD_SIZE], ow[RAST_QUAD_SIZE], w[RAST_QUAD_SIZE];
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      a[i] = (float)an[i] * t->fscale * t->rdet.f;
      b[i] = (float)bn[i] * t->fscale * t->rdet.f;
   }
   tex_fplane4(&t->pl[0], a, b, ow);
   tex_fcount4(&ls, ow);
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
      w[i] = 1.0f / ow[i];
   tex_fcount4(&ls, w);
   for (unsigned j = 0; j < fr->npersp; j++) {
      float aw[RAST_QUAD_SIZE];
      float *o = q->in[fr->persp[j].var][fr->persp[j].chan];
      tex_fplane4(&t->pl[1 + j], a, b, aw);
      tex_fcount4(&ls, aw);
      for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
         o[i] = aw[i] * w[i];
         ls.flush += (o[i] == 0) & (aw[i] != 0);
      }
      tex_fcount4(&ls, o);
   }
   t->st.sat += ls.sat;
   t->st.flush += ls.flush;
}

/* tex_quad_impl's operations for component j alone, on numerators taken
 * anywhere (rast_interp_perspective_at). */
static inline __attribute__((always_inline)) void
persp_at_impl(struct rast_front *fr, unsigned j, const int64_t an[RAST_QUAD_SIZE],
              const int64_t bn[RAST_QUAD_SIZE], float out[RAST_QUAD_SIZE], const enum tex_kind k)
{
   struct fr_tex *t = &fr->tex;
   struct ns_stats ls = { 0, 0 };
   const struct fr_plane *p = &t->pl[1 + j];
   if (t->is_color[j]) {
      ns_val fa[RAST_QUAD_SIZE], fb[RAST_QUAD_SIZE], fw[RAST_QUAD_SIZE];
      tex_color_weights(t, &ls, an, bn, fa, fb, fw);
      for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
         out[i] = tex_mul(t, &ls, TEX_FLOAT, tex_plane(t, &ls, TEX_FLOAT, p, fa[i], fb[i]),
                          fw[i]).f;
   } else {
      for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
         const ns_val a = tex_mul(t, &ls, k, tex_scaled(t, &ls, k, an[i]), t->rdet);
         const ns_val b = tex_mul(t, &ls, k, tex_scaled(t, &ls, k, bn[i]), t->rdet);
         const ns_val w = tex_recip(t, &ls, k, tex_plane(t, &ls, k, &t->pl[0], a, b));
         out[i] = tex_out(t, k, tex_mul(t, &ls, k, tex_plane(t, &ls, k, p, a, b), w));
      }
   }
   t->st.sat += ls.sat;
   t->st.flush += ls.flush;
}

void rast_interp_perspective_at(struct rast_front *fr, unsigned j,
                                const int64_t px[RAST_QUAD_SIZE],
                                const int64_t py[RAST_QUAD_SIZE], float out[RAST_QUAD_SIZE])
{
   const struct fr_tex *t = &fr->tex;
   int64_t an[RAST_QUAD_SIZE], bn[RAST_QUAD_SIZE];
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      /* tex_begin's numerators, at the point instead of a centre */
      const int64_t rx = px[i] - t->x0, ry = py[i] - t->y0;
      an[i] = rx * t->e2y - ry * t->e2x;
      bn[i] = t->e1x * ry - t->e1y * rx;
   }
   switch ((enum tex_kind)t->kind) {
   case TEX_DFX19: persp_at_impl(fr, j, an, bn, out, TEX_DFX19); break;
   case TEX_DFX:   persp_at_impl(fr, j, an, bn, out, TEX_DFX); break;
   case TEX_FLOAT: persp_at_impl(fr, j, an, bn, out, TEX_FLOAT); break;
   default:        persp_at_impl(fr, j, an, bn, out, TEX_NS); break;
   }
}

void rast_interp_perspective_choose(struct rast_context *rc, struct rast_front *fr)
{
   const struct numsys *ns = rc->texfmt ? rc->texfmt : numsys_default();
   struct fr_tex *t = &fr->tex;
   bool is_float = ns->family == NUMSYS_FLOAT;
   t->ns = ns;
   t->fns = numsys_by_name("float");
   t->any_color = false;
   for (unsigned j = 0; j < fr->npersp; j++) {
      unsigned v = fr->persp[j].var;
      /* in the float system a COLOR component is just another plane; an
       * array layer (float_mask) is divided as a COLOR component is */
      t->is_color[j] = !is_float && v < rc->vl.num_varyings &&
                       (rc->vl.varying[v].interp == RAST_INTERP_COLOR ||
                        (rc->vl.varying[v].float_mask >> fr->persp[j].chan & 1u));
      t->any_color |= t->is_color[j];
   }
   t->begin = tex_begin;
   t->skip = !(rc->opts & RAST_OPT_NOSKIP);
   t->f32 = !(rc->opts & RAST_OPT_NOF32);
   t->w_const = t->w_one = false;
   t->lanes = !t->reference && !(rc->opts & RAST_OPT_SCALAR) && !t->any_color &&
              ns->dfx.mant_bits == DFX_MANT_BITS_SEED;
   /* how many following quads the span processor looks for: the lanes
    * divide 2 or 4 at once with the skips taken, nothing else does */
   t->lookahead = !t->lanes || !t->skip ? 0 : rast_lanes()->persp4_dfx19 ? 3 : 1;
   t->nrec = 0;
   t->kind = (uint8_t)(ns->dfx.mant_bits == DFX_MANT_BITS_SEED ? TEX_DFX19
                       : ns->dfx.mant_bits                    ? TEX_DFX
                       : is_float                              ? TEX_FLOAT
                                                               : TEX_NS);
   if (t->lanes)
      t->quad = tex_quad_dfx19_lanes;
   else if (t->reference)
      t->quad = ns->dfx.mant_bits ? tex_quad_dfx : is_float ? tex_quad_float_ref : tex_quad_ns;
   else if (ns->dfx.mant_bits == DFX_MANT_BITS_SEED)
      t->quad = tex_quad_dfx19;
   else if (ns->dfx.mant_bits)
      t->quad = tex_quad_dfx;
   else if (is_float)
      t->quad = tex_quad_float;
   else
      t->quad = tex_quad_ns;
}

void rast_interp_perspective_reference(struct rast_context *rc, bool on)
{
   rast_validate(rc);
   struct rast_front *fr = rast_front(rc);
   fr->tex.reference = on;
   rast_interp_perspective_choose(rc, fr);
}

/* The waiting quads are fr->quad[0 .. nrec - 1], all of them covered. */
void rast_interp_divide_group(struct rast_context *rc, struct rast_front *fr, bool row_done)
{
   struct fr_tex *t = &fr->tex;
   if (!rast_interp_axes_fill(rc, fr)) {
      float *in[FR_AHEAD_MAX];
      for (unsigned k = 0; k < t->nrec; k++)
         in[k] = &fr->quad[k].in[0][0][0];
      rast_lanes()->persp_group_dfx19(fr, in, (const int64_t (*)[4])t->num, t->nrec);
   }
   t->nrec = 0;
   if (row_done)
      tex_end(rc, fr);
}
