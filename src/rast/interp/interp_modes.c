/*
 * What a primitive gives the per-pixel independent interpolators of
 * interp_modes.h once: its three vertices, seed 002's recip(det) and the
 * registers' differences, and the pixels of its bounding box (the pixels
 * seed 001's coordinate manager hands out).  The operations are counted as
 * docs/interp-modes.md lists them.
 */
#include "rast/interp/interp_modes.h"

/* Sampling points c·S + h in [lo, hi] (XY format), inside [clo, chi): how many. */
static int64_t centres(const struct fx_format xy, int64_t h, int64_t lo, int64_t hi,
                       int64_t clo, int64_t chi)
{
   int64_t first = fx_ceil_int(xy, lo - h), last = fx_floor_int(xy, hi - h);
   if (first < clo) first = clo;
   if (last > chi - 1) last = chi - 1;
   return last >= first ? last - first + 1 : 0;
}

/* The vertices i0, i1, i2, the edges, det, 002's recip(det) and the
 * registers' differences: what a per-pixel mode, or a measure, reads. */
static void modes_planes(struct rast_context *rc, struct rast_front *fr, const unsigned idx[3])
{
   struct fr_modes *m = &fr->md;
   for (unsigned i = 0; i < 3; i++) {
      m->vx[i] = fr->X[idx[i]];
      m->vy[i] = fr->Y[idx[i]];
      for (unsigned k = 0; k < fr->nfix; k++)
         m->v[i][k] = fr->vfix[idx[i]][k];
   }
   m->e1x = m->vx[1] - m->vx[0];
   m->e1y = m->vy[1] - m->vy[0];
   m->e2x = m->vx[2] - m->vx[0];
   m->e2y = m->vy[2] - m->vy[0];
   m->det = m->e1x * m->e2y - m->e1y * m->e2x;
   m->wbits = rc->profile->weight.frac_bits;
   m->wmin = fx_min(rc->profile->weight);
   m->wmax = fx_max(rc->profile->weight);
   /* recip(det): k + W bits over det, so a = n_a·rdet >> k keeps W bits */
   const unsigned kbits = fx_bitlen64(m->det < 0 ? -(uint64_t)m->det : (uint64_t)m->det);
   m->rshift = kbits;
   m->rdet = m->det ? (int64_t)fx_div_round_i128((fx_i128)1 << (kbits + m->wbits), m->det) : 0;
   for (unsigned k = 0; k < fr->nfix; k++) {
      m->d1[k] = m->v[1][k] - m->v[0][k];
      m->d2[k] = m->v[2][k] - m->v[0][k];
   }
}

void rast_interp_modes_off(struct rast_front *fr)
{
   fr->md.on = false;
   fr->nfix_walk = fr->nfix_scan;
}

void rast_interp_modes_setup(struct rast_context *rc, struct rast_front *fr, unsigned i0,
                             unsigned i1, unsigned i2)
{
   struct fr_modes *m = &fr->md;
   const struct fx_format xy = rc->profile->xy;
   const unsigned mode = rc->interp & 3u;
   const unsigned idx[3] = { i0, i1, i2 };
   m->on = true;
   fr->nfix_walk = mode == RAST_INTERP_SCANLINE ? fr->nfix_scan : 0;
   int64_t xmin = INT64_MAX, xmax = INT64_MIN, ymin = INT64_MAX, ymax = INT64_MIN;
   for (unsigned i = 0; i < fr->nverts; i++) {
      xmin = fr->X[i] < xmin ? fr->X[i] : xmin;
      xmax = fr->X[i] > xmax ? fr->X[i] : xmax;
      ymin = fr->Y[i] < ymin ? fr->Y[i] : ymin;
      ymax = fr->Y[i] > ymax ? fr->Y[i] : ymax;
   }
   rc->stats.interp_box_pixels +=
      (uint64_t)(centres(xy, fr->Hx, xmin, xmax, rc->clip.minx, rc->clip.maxx) *
                 centres(xy, fr->Hy, ymin, ymax, rc->clip.miny, rc->clip.maxy));
   m->row0 = fx_ceil_int(xy, ymin - fr->Hy);

   /* the walk needs none of the planes (measuring compares with them) */
   if (rc->interp != RAST_INTERP_SCANLINE)
      modes_planes(rc, fr, idx);

   /* the set-up's operations: the edges and det (4 differences, 2
    * products, 1 difference) in the two per-pixel modes; 002's recip and
    * differences of the registers; the walk's in tri_gradients and scan.c */
   switch (mode) {
   case RAST_INTERP_BARYCENTRIC:
      rc->stats.interp_add += 5;
      rc->stats.interp_mul += 2;
      break;
   case RAST_INTERP_VECTOR:
      rc->stats.interp_add += 5 + 2 * fr->nfix;
      rc->stats.interp_mul += 2;
      rc->stats.interp_div += 1;
      break;
   default:
      /* tri_gradients: det; per register two differences, six products,
       * two differences of products, two quotients */
      rc->stats.interp_add += 5 + 4 * fr->nfix;
      rc->stats.interp_mul += 2 + 6 * fr->nfix;
      rc->stats.interp_div += 2 * fr->nfix;
      break;
   }
}
