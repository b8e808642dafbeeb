/*
 * Span processing (seed 000, eq. 1) for two scan lines at a time: from the
 * left-edge registers of each scan line, one subpixel correction gives the
 * value at the quad row's first pixel centre; then every pixel adds ∂/∂x,
 * saturating for the fixed registers.  Pixels of a quad outside the triangle
 * (helpers) walk on with the same slopes, and a scan line with no edge
 * registers (outside the triangle or the clip) takes the other one's plane
 * ± ∂/∂y, so every pixel of a quad has a plane value and derivatives work.
 *
 * The variants differ in which register families exist; they are chosen once
 * per state change (rast_interp_choose), never per pixel.
 */
#include <float.h>
#include <math.h>
#include <string.h>
#include "rast/front.h"

/* ---- The perspective division of the texture path (seed 003) ----
 *
 * The one place where A/w is divided by 1/w: as (A/w) * recip(1/w) in the
 * number system of rast_set_texfmt, once per pixel for the reciprocal and
 * once per component for the multiply.  The registers 1/w and A/w enter the
 * system at the first quad of each quad row (from the float edge walk) and
 * are stepped by ∂/∂x with the system's own adds, so a format that cannot
 * hold a small step or a far-away 1/w shows it on the screen (seed 003:
 * 8.24 underflows, the dynamic format does not).  Range events go to
 * rast_stats.tex_sat / tex_flush.
 *
 * One body, specialised three ways at validation: binary32 inline (the same
 * float operations, in the same order, as the float walk had), dfx through
 * dfx.c directly, and any other system through its numsys table. */
enum tex_kind { TEX_FLOAT, TEX_DFX, TEX_NS };

static inline __attribute__((always_inline)) float tex_fcount(struct ns_stats *ls, float r)
{
   /* branch-free: the float path stays as cheap as the plain walk */
   float a = fabsf(r);
   ls->sat += a > FLT_MAX;
   ls->flush += (a < FLT_MIN) & (a != 0);
   return r;
}

static inline __attribute__((always_inline)) ns_val
tex_from(struct fr_tex *t, const enum tex_kind k, float v)
{
   ns_val r;
   if (k == TEX_FLOAT)
      r.f = v;
   else if (k == TEX_DFX)
      r.d = dfx_from_double(t->ns->dfx, v, &t->dst);
   else
      r = t->ns->from_float(t->ns, v, &t->st);
   return r;
}

static inline __attribute__((always_inline)) ns_val
tex_add(struct fr_tex *t, struct ns_stats *ls, const enum tex_kind k, ns_val a, ns_val b)
{
   ns_val r;
   if (k == TEX_FLOAT)
      r.f = tex_fcount(ls, a.f + b.f);
   else if (k == TEX_DFX)
      r.d = dfx_add(t->ns->dfx, a.d, b.d, &t->dst);
   else
      r = t->ns->add(t->ns, a, b, ls);
   return r;
}

static inline __attribute__((always_inline)) ns_val
tex_recip(struct fr_tex *t, struct ns_stats *ls, const enum tex_kind k, ns_val a)
{
   ns_val r;
   if (k == TEX_FLOAT)
      r.f = tex_fcount(ls, 1.0f / a.f);
   else if (k == TEX_DFX)
      r.d = dfx_recip(t->ns->dfx, a.d, &t->dst);
   else
      r = t->ns->recip(t->ns, a, ls);
   return r;
}

static inline __attribute__((always_inline)) float
tex_mul_out(struct fr_tex *t, struct ns_stats *ls, const enum tex_kind k, ns_val a, ns_val b)
{
   if (k == TEX_FLOAT) {
      float r = tex_fcount(ls, a.f * b.f);
      ls->flush += (r == 0) & (a.f != 0) & (b.f != 0);
      return r;
   }
   if (k == TEX_DFX)
      return (float)dfx_to_double(t->ns->dfx, dfx_mul(t->ns->dfx, a.d, b.d, &t->dst));
   return t->ns->to_float(t->ns, t->ns->mul(t->ns, a, b, ls));
}

static inline __attribute__((always_inline)) void
tex_begin_impl(struct rast_front *fr, const float *row0, const float *row1, const enum tex_kind k)
{
   struct fr_tex *t = &fr->tex;
   const unsigned p0 = 1 + fr->nlin;       /* flt[]: 1/w, LINEAR, PERSPECTIVE */
   t->ow[0] = tex_from(t, k, row0[0]);
   t->ow[1] = tex_from(t, k, row1[0]);
   t->ow_dx = tex_from(t, k, fr->flt_dx[0]);
   t->fow[0] = row0[0];
   t->fow[1] = row1[0];
   t->fow_dx = fr->flt_dx[0];
   for (unsigned j = 0; j < fr->npersp; j++) {
      if (k != TEX_FLOAT && t->is_color[j]) {
         t->aw[0][j] = tex_from(t, TEX_FLOAT, row0[p0 + j]);
         t->aw[1][j] = tex_from(t, TEX_FLOAT, row1[p0 + j]);
         t->aw_dx[j] = tex_from(t, TEX_FLOAT, fr->flt_dx[p0 + j]);
         continue;
      }
      t->aw[0][j] = tex_from(t, k, row0[p0 + j]);
      t->aw[1][j] = tex_from(t, k, row1[p0 + j]);
      t->aw_dx[j] = tex_from(t, k, fr->flt_dx[p0 + j]);
   }
}

/* Pixels x, x+1 of both scan lines from the running registers. */
static inline __attribute__((always_inline)) void
tex_step(struct fr_tex *t, struct ns_stats *ls, const enum tex_kind k, ns_val *run0,
         ns_val *run1, ns_val d, ns_val v[RAST_QUAD_SIZE])
{
   v[0] = *run0;
   v[1] = tex_add(t, ls, k, v[0], d);
   *run0 = tex_add(t, ls, k, v[1], d);
   v[2] = *run1;
   v[3] = tex_add(t, ls, k, v[2], d);
   *run1 = tex_add(t, ls, k, v[3], d);
}

static inline __attribute__((always_inline)) void
tex_quad_impl(struct rast_front *fr, struct rast_quad *q, bool divide, const enum tex_kind k)
{
   struct fr_tex *t = &fr->tex;
   struct ns_stats ls = { 0, 0 };    /* in registers for the float path */
   ns_val ow[RAST_QUAD_SIZE], w[RAST_QUAD_SIZE];
   tex_step(t, &ls, k, &t->ow[0], &t->ow[1], t->ow_dx, ow);
   if (divide)
      for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
         w[i] = tex_recip(t, &ls, k, ow[i]);
   ns_val fw[RAST_QUAD_SIZE];
   if (k != TEX_FLOAT && t->any_color) {
      ns_val fo[RAST_QUAD_SIZE], r0, r1, d;
      r0.f = t->fow[0];
      r1.f = t->fow[1];
      d.f = t->fow_dx;
      tex_step(t, &ls, TEX_FLOAT, &r0, &r1, d, fo);
      t->fow[0] = r0.f;
      t->fow[1] = r1.f;
      if (divide)
         for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
            fw[i] = tex_recip(t, &ls, TEX_FLOAT, fo[i]);
   }
   for (unsigned j = 0; j < fr->npersp; j++) {
      ns_val aw[RAST_QUAD_SIZE];
      float *o = q->in[fr->persp[j].var][fr->persp[j].chan];
      if (k != TEX_FLOAT && t->is_color[j]) {
         tex_step(t, &ls, TEX_FLOAT, &t->aw[0][j], &t->aw[1][j], t->aw_dx[j], aw);
         if (divide)
            for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
               o[i] = tex_mul_out(t, &ls, TEX_FLOAT, aw[i], fw[i]);
         continue;
      }
      tex_step(t, &ls, k, &t->aw[0][j], &t->aw[1][j], t->aw_dx[j], aw);
      if (divide)
         for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
            o[i] = tex_mul_out(t, &ls, k, aw[i], w[i]);
   }
   t->st.sat += ls.sat;
   t->st.flush += ls.flush;
}

#define TEX_VARIANT(suffix, kind)                                                        \
   static void tex_begin_##suffix(struct rast_front *fr, const float *r0, const float *r1) \
   { tex_begin_impl(fr, r0, r1, kind); }                                                  \
   static void tex_quad_##suffix(struct rast_front *fr, struct rast_quad *q, bool divide)  \
   { tex_quad_impl(fr, q, divide, kind); }

TEX_VARIANT(dfx, TEX_DFX)
TEX_VARIANT(ns, TEX_NS)

static void tex_begin_float(struct rast_front *fr, const float *r0, const float *r1)
{
   tex_begin_impl(fr, r0, r1, TEX_FLOAT);
}

/* binary32: tex_quad_impl's operations on float[4] vectors, so that the
 * compiler keeps them in SIMD registers (an ns_val array is strided); the
 * range events are counted branch-free over each vector. */
static inline void tex_fcount4(struct ns_stats *ls, const float v[RAST_QUAD_SIZE])
{
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
      tex_fcount(ls, v[i]);
}

static void tex_quad_float(struct rast_front *fr, struct rast_quad *q, bool divide)
{
   struct fr_tex *t = &fr->tex;
   struct ns_stats ls = { 0, 0 };
   float ow[RAST_QUAD_SIZE], w[RAST_QUAD_SIZE];
   {
      float d = t->ow_dx.f;
      ow[0] = t->ow[0].f; ow[1] = ow[0] + d; ow[2] = t->ow[1].f; ow[3] = ow[2] + d;
      t->ow[0].f = ow[1] + d;
      t->ow[1].f = ow[3] + d;
      tex_fcount4(&ls, ow);
   }
   if (divide) {
      for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
         w[i] = 1.0f / ow[i];
      tex_fcount4(&ls, w);
   }
   for (unsigned j = 0; j < fr->npersp; j++) {
      float d = t->aw_dx[j].f, aw[RAST_QUAD_SIZE];
      aw[0] = t->aw[0][j].f; aw[1] = aw[0] + d; aw[2] = t->aw[1][j].f; aw[3] = aw[2] + d;
      t->aw[0][j].f = aw[1] + d;
      t->aw[1][j].f = aw[3] + d;
      tex_fcount4(&ls, aw);
      if (divide) {
         float *o = q->in[fr->persp[j].var][fr->persp[j].chan];
         for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
            o[i] = aw[i] * w[i];
            ls.flush += (o[i] == 0) & (aw[i] != 0) & (w[i] != 0);
         }
         tex_fcount4(&ls, o);
      }
   }
   t->st.sat += ls.sat;
   t->st.flush += ls.flush;
}

void rast_interp_perspective_choose(struct rast_context *rc, struct rast_front *fr)
{
   const struct numsys *ns = rc->texfmt ? rc->texfmt : numsys_default();
   struct fr_tex *t = &fr->tex;
   t->ns = ns;
   t->any_color = false;
   for (unsigned j = 0; j < fr->npersp; j++) {
      unsigned v = fr->persp[j].var;
      t->is_color[j] = v < rc->vl.num_varyings && rc->vl.varying[v].interp == RAST_INTERP_COLOR;
      t->any_color |= t->is_color[j];
   }
   if (ns->dfx.mant_bits) {
      t->begin = tex_begin_dfx;
      t->quad = tex_quad_dfx;
   } else if (!strcmp(ns->name, "float")) {
      t->begin = tex_begin_float;
      t->quad = tex_quad_float;
   } else {
      t->begin = tex_begin_ns;
      t->quad = tex_quad_ns;
   }
}

/* The quad row's range events into the context's counters. */
static inline void tex_end(struct rast_context *rc, struct fr_tex *t)
{
   rc->stats.tex_sat += t->st.sat + t->dst.sat;
   rc->stats.tex_flush += t->st.flush + t->dst.flush;
   t->st.sat = t->st.flush = t->dst.sat = t->dst.flush = 0;
}

static inline unsigned span_bits(const struct fr_row *r, int64_t x)
{
   return (unsigned)(x >= r->xs && x <= r->xe) |
          ((unsigned)(x + 1 >= r->xs && x + 1 <= r->xe) << 1);
}

/* The fixed registers at the centre of pixel x0 of one scan line: one
 * subpixel correction from X_left. */
static inline void row_start_fix(const struct rast_front *fr, const struct fr_row *row,
                                 int64_t x0, unsigned nfix, int64_t *fix, unsigned frac)
{
   int64_t d = x0 * fr->S + fr->H - row->xl;      /* c_x - X_left, XY format */
   for (unsigned k = 0; k < nfix; k++)
      fix[k] = fr_fix_sat(fr, k, (fx_i128)row->fix[k] +
                                 fx_shr_round_i128((fx_i128)d * fr->fix_dx[k], frac));
}

static inline void row_start_flt(const struct rast_front *fr, const struct fr_row *row,
                                 int64_t x0, unsigned nflt, float *flt)
{
   /* exact c_x - X_left: the float walk has the bits to use the remainder */
   float fd = ((float)(x0 * fr->S + fr->H - row->xl) - row->xl_frac) * fr->inv_S;
   for (unsigned k = 0; k < nflt; k++)
      flt[k] = row->flt[k] + fd * fr->flt_dx[k];
}

/* Pixels x and x+1 of a fixed register walked from the anchor pixel xa (the
 * first covered pixel of the scan line).  Helpers left of the anchor are
 * extrapolated from it and never feed the walk, so a helper that clamps
 * cannot shift the covered pixels after it. */
static inline void fix_pair(const struct rast_front *fr, unsigned k, int64_t *run, int64_t xa,
                            int64_t x, int64_t d, int64_t *p0, int64_t *p1)
{
   if (x >= xa) {
      *p0 = *run;
      *p1 = fr_fix_add(fr, k, *p0, d);
      *run = fr_fix_add(fr, k, *p1, d);
   } else if (x + 1 == xa) {
      *p1 = *run;
      *p0 = fr_fix_add(fr, k, *p1, -d);
      *run = fr_fix_add(fr, k, *p1, d);
   } else {
      *p0 = fr_fix_sat(fr, k, (fx_i128)*run - (fx_i128)(xa - x) * d);
      *p1 = fr_fix_sat(fr, k, (fx_i128)*run - (fx_i128)(xa - x - 1) * d);
   }
}

/* The unclamped fixed registers at pixel x0 of a scan line without covered
 * pixels, from a scan line's left-edge registers, -/+ ∂/∂y when they are
 * the other scan line's (outside the triangle or the clip). */
static inline void row_base_derived(const struct rast_front *fr, const struct fr_row *other,
                                    int64_t x0, int64_t sign, unsigned nfix, int64_t *base,
                                    unsigned frac)
{
   int64_t d = x0 * fr->S + fr->H - other->xl;
   for (unsigned k = 0; k < nfix; k++)
      base[k] = other->fix[k] + (int64_t)fx_shr_round_i128((fx_i128)d * fr->fix_dx[k], frac) +
                sign * fr->fix_dy[k];
}

/* Register k's four pixels. */
static inline void fix_quad(const struct rast_front *fr, unsigned k, int64_t (*run)[FR_MAX_FIX],
                            const int64_t *xa, const bool *direct, int64_t x, int64_t *p)
{
   int64_t d = fr->fix_dx[k];
   for (unsigned r = 0; r < 2; r++) {
      if (!direct[r]) {
         fix_pair(fr, k, &run[r][k], xa[r], x, d, &p[2 * r], &p[2 * r + 1]);
      } else {
         /* run holds the unclamped value at xa */
         p[2 * r] = fr_fix_sat(fr, k, (fx_i128)run[r][k] + (fx_i128)(x - xa[r]) * d);
         p[2 * r + 1] = fr_fix_sat(fr, k, (fx_i128)run[r][k] + (fx_i128)(x + 1 - xa[r]) * d);
      }
   }
}

static inline __attribute__((always_inline)) void
pair_impl(struct rast_context *rc, struct rast_front *fr, int64_t y,
          const bool has_color, const bool has_lin, const bool has_persp)
{
   const struct fr_row *r0 = &fr->row[0], *r1 = &fr->row[1];
   bool e0 = r0->valid && r0->xs <= r0->xe;
   bool e1 = r1->valid && r1->xs <= r1->xe;
   if ((!e0 && !e1) || (!r0->valid && !r1->valid))
      return;
   int64_t xs, xe;
   if (e0 && e1) {
      xs = r0->xs < r1->xs ? r0->xs : r1->xs;
      xe = r0->xe > r1->xe ? r0->xe : r1->xe;
   } else if (e0) {
      xs = r0->xs; xe = r0->xe;
   } else {
      xs = r1->xs; xe = r1->xe;
   }
   int64_t xq = xs & ~(int64_t)1;

   const unsigned nfix = has_color ? fr->nfix : 1;
   const unsigned nflt = (has_lin || has_persp) ? fr->nflt : 1;
   const unsigned flt_lin_end = 1 + (has_lin ? fr->nlin : 0);
   const unsigned frac = rc->profile->xy.frac_bits;

   int64_t fix[2][FR_MAX_FIX] = {{0}};
   float flt[2][FR_MAX_FLT] = {{0}};
   /* A scan line with no covered pixel in this quad row holds only helpers:
    * each of them is computed from an unclamped base, so one that clamps
    * cannot shift the next. */
   const bool direct[2] = { !e0, !e1 };
   int64_t xa[2] = { e0 ? r0->xs : xq, e1 ? r1->xs : xq };
   if (r0->valid) {
      if (e0)
         row_start_fix(fr, r0, xa[0], nfix, fix[0], frac);
      else
         row_base_derived(fr, r0, xq, 0, nfix, fix[0], frac);
      row_start_flt(fr, r0, xq, nflt, flt[0]);
      if (r1->valid) {
         if (e1)
            row_start_fix(fr, r1, xa[1], nfix, fix[1], frac);
         else
            row_base_derived(fr, r1, xq, 0, nfix, fix[1], frac);
         row_start_flt(fr, r1, xq, nflt, flt[1]);
      } else {
         row_base_derived(fr, r0, xq, 1, nfix, fix[1], frac);
         for (unsigned k = 0; k < nflt; k++)
            flt[1][k] = flt[0][k] + fr->flt_dy[k];
      }
   } else {
      /* here e1: r1 has the covered pixels */
      row_start_fix(fr, r1, xa[1], nfix, fix[1], frac);
      row_start_flt(fr, r1, xq, nflt, flt[1]);
      row_base_derived(fr, r1, xq, -1, nfix, fix[0], frac);
      for (unsigned k = 0; k < nflt; k++)
         flt[0][k] = flt[1][k] - fr->flt_dy[k];
   }

   struct rast_quad *q = &fr->quad;
   const double zs = fr->z_scale;
   const float cs = fr->color_scale;
   if (has_persp)
      fr->tex.begin(fr, flt[0], flt[1]);
   q->y = (int)y;

   for (int64_t x = xq; x <= xe; x += 2) {
      unsigned mask = span_bits(r0, x) | (span_bits(r1, x) << 2);

      /* Z: the seed's Z_left + ∂Z/∂x walk. */
      fix_quad(fr, 0, fix, xa, direct, x, q->z);
      for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
         q->frag_z[i] = (float)((double)q->z[i] * zs);
      if (has_color) {
         for (unsigned k = 1; k < nfix; k++) {
            const struct fr_comp *c = &fr->color[k - 1];
            int64_t p[RAST_QUAD_SIZE];
            fix_quad(fr, k, fix, xa, direct, x, p);
            float *o = q->in[c->var][c->chan];
            for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
               o[i] = (float)p[i] * cs;
         }
      }
      {
         float d = fr->flt_dx[0];
         float a0 = flt[0][0], a1 = a0 + d, b0 = flt[1][0], b1 = b0 + d;
         flt[0][0] = a1 + d;
         flt[1][0] = b1 + d;
         q->frag_w[0] = a0; q->frag_w[1] = a1; q->frag_w[2] = b0; q->frag_w[3] = b1;
      }
      if (has_lin) {
         for (unsigned k = 1; k < flt_lin_end; k++) {
            const struct fr_comp *c = &fr->lin[k - 1];
            float d = fr->flt_dx[k];
            float a0 = flt[0][k], a1 = a0 + d, b0 = flt[1][k], b1 = b0 + d;
            flt[0][k] = a1 + d;
            flt[1][k] = b1 + d;
            float *o = q->in[c->var][c->chan];
            o[0] = a0; o[1] = a1; o[2] = b0; o[3] = b1;
         }
      }
      if (has_persp)
         fr->tex.quad(fr, q, mask != 0);
      if (!mask)
         continue;
      q->x = (int)x;
      q->mask = mask;
      rc->stats.quads++;
      rc->stats.pixels_covered += (mask & 1) + ((mask >> 1) & 1) + ((mask >> 2) & 1) + (mask >> 3);
      rc->quad(rc, q);
   }
   if (has_persp)
      tex_end(rc, &fr->tex);
}

#define PAIR_VARIANT(name, c, l, p)                                        \
   static void name(struct rast_context *rc, struct rast_front *fr, int64_t y) \
   { pair_impl(rc, fr, y, c, l, p); }

PAIR_VARIANT(pair_z,      false, false, false)
PAIR_VARIANT(pair_c,      true,  false, false)
PAIR_VARIANT(pair_l,      false, true,  false)
PAIR_VARIANT(pair_cl,     true,  true,  false)
PAIR_VARIANT(pair_p,      false, false, true)
PAIR_VARIANT(pair_cp,     true,  false, true)
PAIR_VARIANT(pair_lp,     false, true,  true)
PAIR_VARIANT(pair_clp,    true,  true,  true)

fr_pair_func rast_interp_choose(const struct rast_front *fr)
{
   static const fr_pair_func table[8] = {
      pair_z, pair_c, pair_l, pair_cl, pair_p, pair_cp, pair_lp, pair_clp
   };
   unsigned i = (fr->ncolor ? 1u : 0u) | (fr->nlin ? 2u : 0u) | (fr->npersp ? 4u : 0u);
   return table[i];
}
