/*
 * The per-pixel independent interpolators of Z and colour (FIXPIPE_INTERP,
 * docs/interp-modes.md), per pixel: a pixel's registers from its own
 * centre and the primitive's registers (struct fr_modes), nothing from a
 * neighbour, so any core can take any pixel.
 *
 *  barycentric (seed 001): the three sub-triangle areas with the pixel,
 *     each divided by the whole area into a weight (8.24, rounded), and
 *     A = round(λ0·A0 + λ1·A1 + λ2·A2) into the register's format;
 *  vector (seed 002): the edge-vector coordinates a = n_a·recip(det) and
 *     b = n_b·recip(det) (8.24, rounded; recip once per primitive), and
 *     A = A0 + round(a·(A1 - A0) + b·(A2 - A0)).
 *
 * Every product and sum is exact (128 bits); a value rounds where the
 * hardware's register would take it, and saturates, counted, in its class.
 */
#ifndef FIXPIPE_INTERP_MODES_H
#define FIXPIPE_INTERP_MODES_H

#include "rast/setup/front.h"
#include "fixed/fx_wide.h"

/* The operations of one pixel, per mode: fixed, and per register. */
#define MODES_BARY_ADD 9u    /* the pixel's offsets from the vertices (6), the areas (3) */
#define MODES_BARY_MUL 6u    /* the areas' products */
#define MODES_BARY_DIV 3u    /* each area by the whole */
#define MODES_BARY_ADD_REG 2u
#define MODES_BARY_MUL_REG 3u
#define MODES_VEC_ADD 4u     /* the offset from V0 (2), the numerators (2) */
#define MODES_VEC_MUL 6u     /* the numerators (4), a and b by recip(det) (2) */
#define MODES_VEC_ADD_REG 2u
#define MODES_VEC_MUL_REG 2u

static inline int64_t modes_weight(struct rast_context *rc, const struct fr_modes *m, fx_i128 w)
{
   return fx_sat_i128(w, m->wmin, m->wmax, &rc->stats.sat[RAST_REG_WEIGHT].high,
                      &rc->stats.sat[RAST_REG_WEIGHT].low);
}

/* Seed 001: the registers at the centre (px, py) (XY format, the pass's). */
static inline void modes_barycentric(struct rast_context *rc, const struct rast_front *fr,
                                     int64_t px, int64_t py, unsigned nfix, int64_t *out)
{
   const struct fr_modes *m = &fr->md;
   int64_t dx[3], dy[3], w[3];
   for (unsigned i = 0; i < 3; i++) {
      dx[i] = m->vx[i] - px;
      dy[i] = m->vy[i] - py;
   }
   /* area(P V1 V2), area(P V2 V0), area(P V0 V1): each vertex's weight */
   for (unsigned i = 0; i < 3; i++) {
      const unsigned j = (i + 1) % 3, k = (i + 2) % 3;
      const int64_t area = dx[j] * dy[k] - dy[j] * dx[k];
      const fx_i128 scaled = (fx_i128)area * ((fx_i128)1 << m->wbits);
      w[i] = m->det ? modes_weight(rc, m, fx_div_round_i128(scaled, m->det))
                    : (i == 0 ? INT64_C(1) << m->wbits : 0);
   }
   for (unsigned k = 0; k < nfix; k++) {
      const fx_i128 s = (fx_i128)w[0] * m->v[0][k] + (fx_i128)w[1] * m->v[1][k] +
                        (fx_i128)w[2] * m->v[2][k];
      out[k] = fr_fix_sat(fr, k, fx_shr_round_i128(s, m->wbits));
   }
}

/* The exact numerators of a and b at the centre (px, py). */
static inline void modes_numerators(const struct fr_modes *m, int64_t px, int64_t py,
                                    int64_t *na, int64_t *nb)
{
   const int64_t rx = px - m->vx[0], ry = py - m->vy[0];
   *na = rx * m->e2y - ry * m->e2x;
   *nb = m->e1x * ry - m->e1y * rx;
}

/* Seed 002: the registers at the centre (px, py). */
static inline void modes_vector(struct rast_context *rc, const struct rast_front *fr,
                                int64_t px, int64_t py, unsigned nfix, int64_t *out)
{
   const struct fr_modes *m = &fr->md;
   int64_t na, nb;
   modes_numerators(m, px, py, &na, &nb);
   const int64_t a = modes_weight(rc, m, fx_shr_round_i128((fx_i128)na * m->rdet, m->rshift));
   const int64_t b = modes_weight(rc, m, fx_shr_round_i128((fx_i128)nb * m->rdet, m->rshift));
   for (unsigned k = 0; k < nfix; k++)
      out[k] = fr_fix_sat(fr, k, (fx_i128)m->v[0][k] +
                                 fx_shr_round_i128((fx_i128)a * m->d1[k] + (fx_i128)b * m->d2[k],
                                                   m->wbits));
}

/* RAST_INTERP_MEASURE: register k's value v at the centre (px, py) against
 * the exact plane through the three vertices, A0 + (n_a·ΔA1 + n_b·ΔA2)/det,
 * in 2^-16 of the register's last bit; exact in 128 bits. */
static inline void modes_measure(struct rast_context *rc, const struct rast_front *fr,
                                 unsigned k, int64_t px, int64_t py, int64_t v)
{
   const struct fr_modes *m = &fr->md;
   if (!m->det)
      return;
   int64_t na, nb;
   modes_numerators(m, px, py, &na, &nb);
   fx_i128 num = (fx_i128)(v - m->v[0][k]) * m->det - (fx_i128)na * m->d1[k] -
                 (fx_i128)nb * m->d2[k];
   const fx_i128 den = m->det < 0 ? -(fx_i128)m->det : (fx_i128)m->det;
   if (num < 0)
      num = -num;
   const uint64_t e = (uint64_t)((num * 65536 + den / 2) / den);
   const unsigned c = k ? 1 : 0;
   rc->stats.interp_err_n[c]++;
   rc->stats.interp_err_sum[c] += e;
   if (e > rc->stats.interp_err_max[c])
      rc->stats.interp_err_max[c] = e;
}

#endif
