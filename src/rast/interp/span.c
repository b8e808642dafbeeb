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
#include "rast/setup/front.h"
#include "rast/interp/interp_modes.h"
#include "fixed/dfx_ops.h"
#include "rast/host/lanes.h"
#include "fixed/dfx_lanes.h"
#include "rast/interp/persp.h"

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
   int64_t d = x0 * fr->S + fr->Hx - row->xl;      /* c_x - X_left, XY format */
   for (unsigned k = 0; k < nfix; k++)
      fix[k] = fr_fix_sat(fr, k, (fx_i128)row->fix[k] +
                                 fx_shr_round_i128((fx_i128)d * fr->fix_dx[k], frac));
}

static inline void row_start_flt(const struct rast_front *fr, const struct fr_row *row,
                                 int64_t x0, unsigned nflt, float *flt)
{
   /* exact c_x - X_left: the float walk has the bits to use the remainder */
   float fd = ((float)(x0 * fr->S + fr->Hx - row->xl) - row->xl_frac) * fr->inv_S;
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
   int64_t d = x0 * fr->S + fr->Hx - other->xl;
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

/* The scan line walk's operations for a quad row of nq quads (its two
 * rows' starts and a step per pixel and register), and seed 002's baseline:
 * each pixel walked alone from the primitive's first scan line and its
 * row's first covered pixel (docs/interp-modes.md), for triangles and
 * lines. */
static inline void count_walk(struct rast_context *rc, const struct rast_front *fr, int64_t y,
                              const int64_t *xa, int64_t xq, uint64_t nq, unsigned nfix)
{
   rc->stats.interp_add += 2 * (2 + nfix) + 4 * nq * nfix;
   rc->stats.interp_mul += 2 * (1 + nfix);
   if (!fr->md.on)
      return;        /* a point: no first scan line of its own */
   const int64_t n = 2 * (int64_t)nq;
   uint64_t steps = 0;
   for (unsigned r = 0; r < 2; r++) {
      const int64_t left = xa[r] - xq < 0 ? 0 : (xa[r] - xq > n ? n : xa[r] - xq);
      const int64_t right = n - left, down = y + r - fr->md.row0;
      steps += (uint64_t)(left * (left + 1) / 2 + right * (right - 1) / 2) +
               (uint64_t)n * (uint64_t)(down > 0 ? down + 1 : 1);
   }
   rc->stats.interp_indep_add += steps * nfix + 4 * nq * 2;
   rc->stats.interp_indep_mul += 4 * nq * (1 + 3 * nfix);
}

/* The operations of nq quads of a per-pixel mode (interp_modes.h). */
static inline void count_modes(struct rast_context *rc, const unsigned mode, uint64_t nq,
                               unsigned nfix)
{
   const uint64_t px = 4 * nq;
   if (mode == RAST_INTERP_BARYCENTRIC) {
      rc->stats.interp_add += px * (MODES_BARY_ADD + MODES_BARY_ADD_REG * nfix);
      rc->stats.interp_mul += px * (MODES_BARY_MUL + MODES_BARY_MUL_REG * nfix);
      rc->stats.interp_div += px * MODES_BARY_DIV;
   } else {
      rc->stats.interp_add += px * (MODES_VEC_ADD + MODES_VEC_ADD_REG * nfix);
      rc->stats.interp_mul += px * (MODES_VEC_MUL + MODES_VEC_MUL_REG * nfix);
   }
}

/* The fix registers of the quad at x (pass-local) in a per-pixel mode. */
static inline void modes_quad(struct rast_context *rc, const struct rast_front *fr,
                              const unsigned mode, int64_t x, int64_t y, unsigned nfix,
                              int64_t v[RAST_QUAD_SIZE][FR_MAX_FIX])
{
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      const int64_t px = (x + (i & 1)) * fr->S + fr->Hx, py = (y + (i >> 1)) * fr->S + fr->Hy;
      if (mode == RAST_INTERP_BARYCENTRIC)
         modes_barycentric(rc, fr, px, py, nfix, v[i]);
      else
         modes_vector(rc, fr, px, py, nfix, v[i]);
   }
}

/* RAST_INTERP_MEASURE: register k of the quad's covered pixels. */
static inline void measure_quad(struct rast_context *rc, const struct rast_front *fr, unsigned k,
                                int64_t x, int64_t y, unsigned mask, const int64_t *v)
{
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
      if (mask & (1u << i))
         modes_measure(rc, fr, k, (x + (i & 1)) * fr->S + fr->Hx, (y + (i >> 1)) * fr->S + fr->Hy,
                       v[i]);
}

static inline __attribute__((always_inline)) void
pair_impl(struct rast_context *rc, struct rast_front *fr, int64_t y,
          const bool has_z, const bool has_color, const bool has_lin, const bool has_persp,
          const unsigned mode, const bool measure)
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

   /* without Z (fr->nfix_scan 0) there is no colour register either */
   const unsigned nfix = has_color ? fr->nfix : has_z ? 1 : 0;
   const unsigned nflt = has_lin ? fr->nwalk : 1;
   const unsigned flt_lin_end = 1 + (has_lin ? fr->nlin : 0);
   const unsigned frac = rc->profile->xy.frac_bits;

   /* the registers of both scan lines; only the first nfix and nflt are
    * started and read (zeroing both arrays whole, 3 KiB, took a tenth of
    * this function's time) */
   int64_t fix[2][FR_MAX_FIX];
   float flt[2][FR_MAX_FLT];
   /* A scan line with no covered pixel in this quad row holds only helpers:
    * each of them is computed from an unclamped base, so one that clamps
    * cannot shift the next. */
   const bool direct[2] = { !e0, !e1 };
   int64_t xa[2] = { e0 ? r0->xs : xq, e1 ? r1->xs : xq };
   /* the per-pixel modes start no fix register from a row */
   const unsigned nrow = mode == RAST_INTERP_SCANLINE ? nfix : 0;
   if (r0->valid) {
      if (e0)
         row_start_fix(fr, r0, xa[0], nrow, fix[0], frac);
      else
         row_base_derived(fr, r0, xq, 0, nrow, fix[0], frac);
      row_start_flt(fr, r0, xq, nflt, flt[0]);
      if (r1->valid) {
         if (e1)
            row_start_fix(fr, r1, xa[1], nrow, fix[1], frac);
         else
            row_base_derived(fr, r1, xq, 0, nrow, fix[1], frac);
         row_start_flt(fr, r1, xq, nflt, flt[1]);
      } else {
         row_base_derived(fr, r0, xq, 1, nrow, fix[1], frac);
         for (unsigned k = 0; k < nflt; k++)
            flt[1][k] = flt[0][k] + fr->flt_dy[k];
      }
   } else {
      /* here e1: r1 has the covered pixels */
      row_start_fix(fr, r1, xa[1], nrow, fix[1], frac);
      row_start_flt(fr, r1, xq, nflt, flt[1]);
      row_base_derived(fr, r1, xq, -1, nrow, fix[0], frac);
      for (unsigned k = 0; k < nflt; k++)
         flt[0][k] = flt[1][k] - fr->flt_dy[k];
   }
   {
      const uint64_t nq = (uint64_t)((xe - xq) / 2 + 1);
      if (mode == RAST_INTERP_SCANLINE)
         count_walk(rc, fr, y, xa, xq, nq, nfix);
      else
         count_modes(rc, mode, nq, nfix);
   }

   struct rast_quad *q = &fr->quad[fr->npending];
   /* gl_FragCoord's z and w only for a shader that reads them, and for the
    * RTL vectors, which record w */
   const bool fragcoord =
      has_z && (rc->fs.reads_fragcoord || (rc->opts & RAST_OPT_NOSKIP) || rc->vec);
   const double zs = fr->z_scale;
   const float cs = fr->color_scale;
   /* divided as a group when it goes to the back end (fr_tex.num), two of
    * the shader's groups together: the division is a long chain of
    * dependent operations, and a group's alone would leave the processor
    * waiting on it between two calls of the shader; two side by side
    * overlap.  The back end still takes them a group at a time, in order. */
   const bool grouped = has_persp && fr->tex.lanes && fr->tex.skip && rc->quads;
   const unsigned hold = grouped && 2 * rc->fs.group <= FR_AHEAD_MAX ? 2 * rc->fs.group
                                                                     : rc->fs.group;
   if (has_persp)
      fr->tex.begin(fr, xq, y);
   /* the pass's origin back: the quad's place in the target */
   const int qy = (int)(y + rc->org_y);
   q->y = qy;

   /* counted when the row is done: the shader and the back end called in
    * between would make the compiler store each count every quad */
   uint64_t covered = 0, pixels = 0;
   for (int64_t x = xq; x <= xe; x += 2) {
      unsigned mask = span_bits(r0, x) | (span_bits(r1, x) << 2);

      int64_t mv[RAST_QUAD_SIZE][FR_MAX_FIX];
      if (mode != RAST_INTERP_SCANLINE)
         modes_quad(rc, fr, mode, x, y, nfix, mv);
      /* Z: the seed's Z_left + ∂Z/∂x walk, or the mode's. */
      if (!has_z)
         ;
      else if (mode == RAST_INTERP_SCANLINE)
         fix_quad(fr, 0, fix, xa, direct, x, q->z);
      else
         for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
            q->z[i] = mv[i][0];
      if (measure)
         measure_quad(rc, fr, 0, x, y, mask, q->z);
      if (fragcoord)
         for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
            q->frag_z[i] = (float)((double)q->z[i] * zs);
      if (has_color) {
         for (unsigned k = 1; k < nfix; k++) {
            const struct fr_comp *c = &fr->color[k - 1];
            int64_t p[RAST_QUAD_SIZE];
            if (mode == RAST_INTERP_SCANLINE)
               fix_quad(fr, k, fix, xa, direct, x, p);
            else
               for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
                  p[i] = mv[i][k];
            if (measure)
               measure_quad(rc, fr, k, x, y, mask, p);
            float *o = q->in[c->var][c->chan];
            for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
               o[i] = (float)p[i] * cs;
         }
      }
      if (fragcoord) {
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
      if (grouped) {
         struct fr_tex *t = &fr->tex;
         if (mask) {
            /* the quad's slot: the covered quads before it in the group
             * each left theirs */
            int64_t *n = t->num[fr->npending];
            n[0] = t->an[0]; n[1] = t->an[1]; n[2] = t->bn[0]; n[3] = t->bn[1];
            t->nrec = fr->npending + 1;
         }
         tex_numerators_next(t);
      } else if (has_persp) {
         /* the covered quads that follow, for the lanes to divide with
          * this one (not needed while they hold divided ones) */
         unsigned ahead = 0;
         if (mask && !fr->tex.pending)
            for (int64_t nx = x + 2;
                 ahead < fr->tex.lookahead && nx <= xe && (span_bits(r0, nx) | span_bits(r1, nx));
                 nx += 2)
               ahead++;
         fr->tex.quad(fr, q, mask != 0, ahead);
      }
      if (!mask)
         continue;
      q->x = (int)(x + rc->org_x);
      q->mask = mask;
      covered++;
      pixels += (mask & 1) + ((mask >> 1) & 1) + ((mask >> 2) & 1) + (mask >> 3);
      if (!rc->quads) {
         rc->quad(rc, q);
      } else if (++fr->npending < hold) {
         q = &fr->quad[fr->npending];
         q->y = qy;
      } else {
         if (grouped)
            rast_interp_divide_group(rc, fr, false);
         fr_quads_out(rc, fr);
         q = &fr->quad[0];
         q->y = qy;
      }
   }
   rc->stats.quads += covered;
   rc->stats.skip_fragcoord += fragcoord ? 0 : covered;
   rc->stats.skip_z += has_z ? 0 : covered;
   rc->stats.pixels_covered += pixels;
   if (has_persp) {
      fr->tex.n_divided += covered;
      tex_end(rc, fr);
   }
}

#define PAIR_VARIANT(name, z, c, l, p)                                     \
   static void name(struct rast_context *rc, struct rast_front *fr, int64_t y) \
   { pair_impl(rc, fr, y, z, c, l, p, RAST_INTERP_SCANLINE, false); }

PAIR_VARIANT(pair_z,      true,  false, false, false)
PAIR_VARIANT(pair_c,      true,  true,  false, false)
PAIR_VARIANT(pair_l,      true,  false, true,  false)
PAIR_VARIANT(pair_cl,     true,  true,  true,  false)
PAIR_VARIANT(pair_p,      true,  false, false, true)
PAIR_VARIANT(pair_cp,     true,  true,  false, true)
PAIR_VARIANT(pair_lp,     true,  false, true,  true)
PAIR_VARIANT(pair_clp,    true,  true,  true,  true)
/* the Z walk skipped (fr->nfix_scan 0): no colour register then */
PAIR_VARIANT(pair_0,      false, false, false, false)
PAIR_VARIANT(pair_0l,     false, false, true,  false)
PAIR_VARIANT(pair_0p,     false, false, false, true)
PAIR_VARIANT(pair_0lp,    false, false, true,  true)

/* FIXPIPE_INTERP other than the walk, or measured: one function for every
 * input, the mode taken per primitive (a point keeps the walk). */
static void pair_modes(struct rast_context *rc, struct rast_front *fr, int64_t y)
{
   const unsigned mode = fr->md.on ? rc->interp & 3u : RAST_INTERP_SCANLINE;
   const bool measure = (rc->interp & RAST_INTERP_MEASURE) && fr->md.on;
   pair_impl(rc, fr, y, true, fr->ncolor != 0, fr->nlin != 0, fr->npersp != 0, mode, measure);
}

fr_pair_func rast_interp_choose(const struct rast_context *rc, const struct rast_front *fr)
{
   if (rc->interp != RAST_INTERP_SCANLINE)
      return pair_modes;
   static const fr_pair_func table[8] = {
      pair_z, pair_c, pair_l, pair_cl, pair_p, pair_cp, pair_lp, pair_clp
   };
   static const fr_pair_func no_z[4] = { pair_0, pair_0l, pair_0p, pair_0lp };
   if (!fr->nfix_scan)
      return no_z[(fr->nlin ? 1u : 0u) | (fr->npersp ? 2u : 0u)];
   unsigned i = (fr->ncolor ? 1u : 0u) | (fr->nlin ? 2u : 0u) | (fr->npersp ? 4u : 0u);
   return table[i];
}
