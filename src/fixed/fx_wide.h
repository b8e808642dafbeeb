/*
 * 128-bit intermediates for the set-up arithmetic (slopes, subpixel
 * corrections), where a product of two register values can exceed 64 bits
 * in the wide profile.  Private to src/fixed and src/rast.
 */
#ifndef FIXPIPE_FX_WIDE_H
#define FIXPIPE_FX_WIDE_H

#include <stdint.h>

__extension__ typedef __int128 fx_i128;

/* n / d rounded to nearest, ties away from zero, in 64 bits: n, d not
 * INT64_MIN, d != 0 (the quotient and |2r| then fit). */
static inline int64_t fx_div_round_i64(int64_t n, int64_t d)
{
   int64_t q = n / d, r = n % d;
   uint64_t ar = (uint64_t)(r < 0 ? -r : r), ad = (uint64_t)(d < 0 ? -d : d);
   if (2 * ar >= ad)
      q += ((n < 0) != (d < 0)) ? -1 : 1;
   return q;
}

/* n / d rounded to nearest, ties away from zero; d != 0.  Where both fit
 * 64 bits (the seed profile's set-up, nearly always) the 64-bit divide:
 * a 128-bit one is a call into libgcc and several times slower. */
static inline fx_i128 fx_div_round_i128(fx_i128 n, fx_i128 d)
{
   if (n > INT64_MIN && n <= INT64_MAX && d > INT64_MIN && d <= INT64_MAX)
      return fx_div_round_i64((int64_t)n, (int64_t)d);
   fx_i128 q = n / d, r = n % d;
   fx_i128 ar = r < 0 ? -r : r, ad = d < 0 ? -d : d;
   if (2 * ar >= ad)
      q += ((n < 0) != (d < 0)) ? -1 : 1;
   return q;
}

/* floor(n / d) and the remainder in [0, d); d > 0. */
static inline fx_i128 fx_floor_div_i128(fx_i128 n, fx_i128 d, fx_i128 *rem)
{
   fx_i128 q = n / d, r = n % d;
   if (r < 0) { q--; r += d; }
   *rem = r;
   return q;
}

/* v * 2^-s rounded to nearest, ties away from zero; s >= 0. */
static inline fx_i128 fx_shr_round_i128(fx_i128 v, unsigned s)
{
   if (s == 0)
      return v;
   fx_i128 half = (fx_i128)1 << (s - 1);
   return v >= 0 ? (v + half) >> s : -((-v + half) >> s);
}

/* Clamp to [lo, hi], counting. */
static inline int64_t fx_sat_i128(fx_i128 v, int64_t lo, int64_t hi, uint64_t *high, uint64_t *low)
{
   if (v > hi) { (*high)++; return hi; }
   if (v < lo) { (*low)++; return lo; }
   return (int64_t)v;
}

#endif
