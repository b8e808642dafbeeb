/*
 * interpolateAtOffset, interpolateAtSample, interpolateAtCentroid: a
 * shader input at another point of its pixel, by the interpolator that
 * made the input, in its own number format.
 *
 * The point is the pixel's centre plus an offset in the XY format: the
 * shader's offset (in pixels) rounded to the format's grid, clamped to the
 * pixel, or sample k's offset on a multisampled target exactly as the
 * sample's walk takes it (msaa.c).  Each family of registers then answers
 * as it would at that point:
 *
 *   PERSPECTIVE: the division of seeds 002/003 on the numerators at the
 *      point (rast_interp_perspective_at): the walk's operations, so an
 *      offset of zero gives the walk's bits;
 *   LINEAR (noperspective): the float walk's subpixel correction from
 *      the pixel's value, v + dx·∂v/∂x + dy·∂v/∂y, (dx, dy) the point less
 *      where the walk took v (the centre, or the sample it walks);
 *   COLOR: the fixed walk's subpixel correction (seed 000, eq. 1) on the
 *      pixel's register likewise, rounded and saturated in the colour
 *      format, or the per-pixel mode of FIXPIPE_INTERP (seeds 001, 002)
 *      at the point;
 *   flat, and what is not interpolated (gl_FragCoord, facing): the
 *      pixel's value.
 *
 * Centroid is the point the model already shaded at: a pixel's centre
 * when the centre is covered, else its first covered sample (msaa.c's
 * rule), or the sample itself when shaded once a sample; so the pixel's
 * values are the answer.  Range events count as the walk's do.
 */
#include <math.h>
#include "rast/setup/front.h"
#include "rast/interp/interp_modes.h"

/* An offset in pixels on the XY format's grid, within the pixel:
 * [-S/2, S/2 - 1] (GL's [-0.5, 0.5) to FRAGMENT_INTERPOLATION_OFFSET_BITS
 * or finer).  NaN is the centre. */
static int64_t offset_xy(const struct rast_front *fr, float o)
{
   if (!(o == o))
      return 0;
   const float s = o * (float)fr->S;
   const int64_t lo = -fr->S / 2, hi = fr->S / 2 - 1;
   if (s <= (float)lo)
      return lo;
   if (s >= (float)hi)
      return hi;
   return (int64_t)floorf(s + 0.5f);
}

/* Which register family holds component (var, chan): the list and index. */
enum at_family { AT_NONE, AT_PERSP, AT_LIN, AT_COLOR };

static enum at_family find(const struct rast_front *fr, unsigned var, unsigned chan,
                           unsigned *idx)
{
   for (unsigned i = 0; i < fr->npersp; i++)
      if (fr->persp[i].var == var && fr->persp[i].chan == chan)
         return *idx = i, AT_PERSP;
   for (unsigned i = 0; i < fr->nlin; i++)
      if (fr->lin[i].var == var && fr->lin[i].chan == chan)
         return *idx = i, AT_LIN;
   for (unsigned i = 0; i < fr->ncolor; i++)
      if (fr->color[i].var == var && fr->color[i].chan == chan)
         return *idx = i, AT_COLOR;
   return AT_NONE;
}

void rast_interp_at(struct rast_context *rc, const struct rast_quad *q, unsigned var,
                    enum rast_interp_at_kind kind, const float arg0[RAST_QUAD_SIZE],
                    const float arg1[RAST_QUAD_SIZE], float out[4][RAST_QUAD_SIZE])
{
   struct rast_front *fr = rast_front(rc);
   const bool samples = rc->fb.samples > 1 && !rc->rs.single_sample;
   int64_t ox[RAST_QUAD_SIZE], oy[RAST_QUAD_SIZE], px[RAST_QUAD_SIZE], py[RAST_QUAD_SIZE];
   int64_t dx[RAST_QUAD_SIZE], dy[RAST_QUAD_SIZE];
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      ox[i] = oy[i] = 0;
      if (kind == RAST_INTERP_AT_OFFSET) {
         ox[i] = offset_xy(fr, arg0[i]);
         oy[i] = offset_xy(fr, arg1[i]);
      } else if (kind == RAST_INTERP_AT_SAMPLE && samples) {
         /* GL leaves an index beyond the samples undefined: sample 0 */
         union { float f; uint32_t u; } k = { arg0[i] };
         const unsigned s = k.u < RAST_MSAA_SAMPLES ? k.u : 0;
         ox[i] = -fr->S / 2 + (int64_t)(rast_sample_pos_4x[s][0] * (float)fr->S);
         oy[i] = -fr->S / 2 + (int64_t)(rast_sample_pos_4x[s][1] * (float)fr->S);
      }
      /* the pixel's centre in the pass (H, not a sample's) plus the offset */
      px[i] = ((int64_t)q->x + (i & 1) - rc->org_x) * fr->S + fr->H + ox[i];
      py[i] = ((int64_t)q->y + (i >> 1) - rc->org_y) * fr->S + fr->H + oy[i];
      /* from where the walk running now took the pixel's registers: its
       * centre, or a sample's position on a multisampled target */
      dx[i] = fr->H + ox[i] - fr->Hx;
      dy[i] = fr->H + oy[i] - fr->Hy;
   }
   const unsigned frac = rc->profile->xy.frac_bits;
   /* span.c's choice of the Z and colour interpolator */
   const unsigned mode = fr->md.on ? rc->interp & 3u : RAST_INTERP_SCANLINE;
   for (unsigned c = 0; c < 4; c++) {
      const float *in = q->in[var][c];
      unsigned j = 0;
      const enum at_family f =
         kind == RAST_INTERP_AT_CENTROID || var >= RAST_MAX_VARYINGS ? AT_NONE
                                                                     : find(fr, var, c, &j);
      switch (f) {
      case AT_PERSP:
         rast_interp_perspective_at(fr, j, px, py, out[c]);
         break;
      case AT_LIN:
         for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
            out[c][i] = in[i] + (float)dx[i] * fr->inv_S * fr->flt_dx[1 + j] +
                        (float)dy[i] * fr->inv_S * fr->flt_dy[1 + j];
         break;
      case AT_COLOR: {
         const unsigned k = 1 + j;
         if (mode != RAST_INTERP_SCANLINE) {
            /* a per-pixel mode evaluates any point as it does a centre */
            for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
               int64_t v[FR_MAX_FIX];
               if (mode == RAST_INTERP_BARYCENTRIC)
                  modes_barycentric(rc, fr, px[i], py[i], k + 1, v);
               else
                  modes_vector(rc, fr, px[i], py[i], k + 1, v);
               out[c][i] = (float)v[k] * fr->color_scale;
            }
            break;
         }
         /* the pixel's register back from its value: exact, the colour
          * format's 21 bits being within binary32's 24 */
         const double cs = (double)fr->color_scale;
         for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
            const int64_t reg = llround((double)in[i] / cs);
            const fx_i128 d = (fx_i128)dx[i] * fr->fix_dx[k] + (fx_i128)dy[i] * fr->fix_dy[k];
            out[c][i] = (float)fr_fix_sat(fr, k, (fx_i128)reg + fx_shr_round_i128(d, frac)) *
                        fr->color_scale;
         }
         break;
      }
      case AT_NONE:
         for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
            out[c][i] = in[i];
         break;
      }
   }
}
