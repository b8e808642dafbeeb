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
#include "rast/front.h"

/* The one place where A/w is divided by 1/w.  It works on a quad so that
 * the divider (today a float reciprocal, later the seed 003 dynamic
 * fixed-point unit) runs once per pixel, shared by all components. */
void rast_interp_perspective(struct rast_quad *q, const struct rast_front *fr,
                             const float (*aw)[RAST_QUAD_SIZE],
                             const float oow[RAST_QUAD_SIZE])
{
   float w[RAST_QUAD_SIZE];
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
      w[i] = 1.0f / oow[i];
   for (unsigned k = 0; k < fr->npersp; k++) {
      const struct fr_comp *c = &fr->persp[k];
      for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
         q->in[c->var][c->chan][i] = aw[k][i] * w[i];
   }
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
   float aw[FR_MAX_COMP][RAST_QUAD_SIZE];
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
      float oow[RAST_QUAD_SIZE];
      {
         float d = fr->flt_dx[0];
         float a0 = flt[0][0], a1 = a0 + d, b0 = flt[1][0], b1 = b0 + d;
         flt[0][0] = a1 + d;
         flt[1][0] = b1 + d;
         oow[0] = a0; oow[1] = a1; oow[2] = b0; oow[3] = b1;
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
      if (has_persp) {
         for (unsigned k = flt_lin_end; k < nflt; k++) {
            float d = fr->flt_dx[k];
            float a0 = flt[0][k], a1 = a0 + d, b0 = flt[1][k], b1 = b0 + d;
            flt[0][k] = a1 + d;
            flt[1][k] = b1 + d;
            float *o = aw[k - flt_lin_end];
            o[0] = a0; o[1] = a1; o[2] = b0; o[3] = b1;
         }
      }
      if (!mask)
         continue;
      if (has_persp)
         rast_interp_perspective(q, fr, (const float (*)[RAST_QUAD_SIZE])aw, oow);
      q->x = (int)x;
      q->mask = mask;
      rc->stats.quads++;
      rc->stats.pixels_covered += (mask & 1) + ((mask >> 1) & 1) + ((mask >> 2) & 1) + (mask >> 3);
      rc->quad(rc, q);
   }
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
