/*
 * The data paths of the dynamic fixed-point unit (dfx.h) as inline
 * functions: dfx.c's add, sub, mul, recip, from_fixed and to_double are
 * these, and the perspective division (src/rast/interp/persp.c) calls them
 * directly, where a constant format (W = 19) lets the compiler fold the
 * widths.  One implementation: rounding and range events as dfx.c states.
 * Private to src/fixed and src/rast.
 */
#ifndef FIXPIPE_DFX_OPS_H
#define FIXPIPE_DFX_OPS_H

#include "fixed/dfx.h"

/* Exponent of the mantissa's last bit: value = M * 2^dfx_exp_i(f, L). */
static inline int dfx_exp_i(struct dfx_format f, int l)
{
   return 4 * l + 4 - (int)f.mant_bits - 32;
}

static inline struct dfx dfx_max_mag_i(struct dfx_format f, unsigned s)
{
   struct dfx r = { (uint8_t)s, DFX_L_MAX, (UINT32_C(1) << f.mant_bits) - 1 };
   return r;
}

/* The range check every operation ends with. */
static inline struct dfx dfx_finish_i(struct dfx_format f, unsigned s, int l, uint64_t m,
                                      struct dfx_stats *st)
{
   if (l > DFX_L_MAX) {
      st->sat++;
      return dfx_max_mag_i(f, s);
   }
   if (l < 0) {
      st->flush++;
      return dfx_zero();
   }
   struct dfx r = { (uint8_t)s, (uint8_t)l, (uint32_t)m };
   return r;
}

static inline int dfx_floor_div4_i(int v)
{
   return v >= 0 ? v / 4 : -((-v + 3) / 4);
}

/* (-1)^s * n * 2^e into the format: truncated (nearest = false) or rounded
 * to nearest, ties away from zero; n != 0.  The kept mantissa has W-3 to W
 * bits, so every shift stays inside 64 bits. */
static inline struct dfx dfx_from_exact_i(struct dfx_format f, unsigned s, uint64_t n, int e,
                                          bool nearest, struct dfx_stats *st)
{
   /* The top bit weighs 2^p, bit p + 32 of the virtual word: its digit is L. */
   int p = (int)fx_bitlen64(n) - 1 + e;
   int l = dfx_floor_div4_i(p + 32);
   int sh = dfx_exp_i(f, l) - e;        /* drop sh bits of n (or append -sh) */
   uint64_t m;
   if (sh <= 0) {
      m = n << -sh;
   } else {
      m = n >> sh;
      if (nearest && ((n >> (sh - 1)) & 1))
         m++;
      if (m >> f.mant_bits) {           /* rounded up into the next digit */
         m >>= 4;
         l++;
      }
   }
   return dfx_finish_i(f, s, l, m, st);
}

/* v * 2^-fx.frac_bits, to nearest. */
static inline struct dfx dfx_from_fixed_i(struct dfx_format f, struct fx_format fx, int64_t v,
                                          struct dfx_stats *st)
{
   if (v == 0)
      return dfx_zero();
   unsigned s = v < 0;
   uint64_t n = s ? -(uint64_t)v : (uint64_t)v;
   return dfx_from_exact_i(f, s, n, -(int)fx.frac_bits, true, st);
}

static inline double dfx_to_double_i(struct dfx_format f, struct dfx a)
{
   /* M * 2^e as a product with an exact power of two (e is within
    * -60..20, far from the double range's ends): no libm call per pixel. */
   double v = (double)a.m * fx_pow2(dfx_exp_i(f, a.l));
   return a.s ? -v : v;
}

/* The adder: order by magnitude, align the smaller by whole digits through
 * a 5-way multiplexer (0..4 digits; 5 or more leave nothing of it), add or
 * subtract with one guard digit below the mantissa, renormalize by whole
 * digits (the leading-zero digits counted at once), keep the top W bits.
 * The guard digit is our addition: without it a one-digit cancellation
 * would shift four zero bits into the result (up to 16 ulps of error); with
 * it add and sub stay within 17/16 ulp. */
static inline struct dfx dfx_add_i(struct dfx_format f, struct dfx a, struct dfx b,
                                   struct dfx_stats *st)
{
   if (!b.m)
      return a;
   if (!a.m)
      return b;
   if (b.l > a.l || (b.l == a.l && b.m > a.m)) {
      struct dfx t = a;
      a = b;
      b = t;
   }
   unsigned d = (unsigned)(a.l - b.l);
   if (d >= 5)
      return a;
   uint64_t A = (uint64_t)a.m << 4;
   uint64_t B = ((uint64_t)b.m << 4) >> (4 * d);
   uint64_t S = a.s == b.s ? A + B : A - B;
   if (!S)
      return dfx_zero();                /* exact cancellation: not a flush */
   int l = a.l;
   const unsigned w = f.mant_bits;
   if (S >> (w + 4)) {                  /* carry out of the top digit */
      S >>= 4;
      l++;
   }
   unsigned bl = fx_bitlen64(S);
   if (bl <= w) {                       /* leading-zero digits */
      unsigned z = (w + 4 - bl) / 4;
      S <<= 4 * z;
      l -= (int)z;
   }
   return dfx_finish_i(f, a.s, l, S >> 4, st);
}

/* Fig. 9. */
static inline struct dfx dfx_mul_i(struct dfx_format f, struct dfx a, struct dfx b,
                                   struct dfx_stats *st)
{
   if (!a.m || !b.m)
      return dfx_zero();
   const unsigned w = f.mant_bits;
   uint64_t P = (uint64_t)a.m * b.m;    /* 2W bits */
   int l = a.l + b.l - 7;
   uint64_t m;
   if (!(P >> (2 * w - 4))) {           /* top digit of P is zero */
      m = P >> (w - 4);
      l--;
   } else {
      m = P >> w;
   }
   return dfx_finish_i(f, a.s ^ b.s, l, m, st);
}

/* 1/a by exact mantissa division: q = floor(2^(2W+4) / M) has W+5 to W+8
 * bits, so truncating q to W significant bits gives exactly the truncated
 * reciprocal (floor of a floor).  A divider of that width is the model's
 * statement of the unit; the paper names no method.  1/0 saturates. */
static inline struct dfx dfx_recip_i(struct dfx_format f, struct dfx a, struct dfx_stats *st)
{
   if (!a.m) {
      st->sat++;
      return dfx_max_mag_i(f, 0);
   }
   const unsigned w = f.mant_bits, k = 2 * w + 4;
   uint64_t q = (UINT64_C(1) << k) / a.m;   /* in (2^(W+4), 2^(W+8)] */
   /* 1/v = q * 2^(-k - e), e = 4L + 4 - W - 32: dropping two digits of q
    * leaves a normalized W-bit mantissa at L' = 15 - L (derivation in
    * docs/dfx.md); only q = 2^(W+8) needs a third. */
   if (q >> (w + 8))                         /* M = 2^(W-4): 1/v is 16^n */
      return dfx_finish_i(f, a.s, 16 - a.l, q >> 12, st);
   return dfx_finish_i(f, a.s, 15 - a.l, q >> 8, st);
}

#endif
