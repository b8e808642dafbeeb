/*
 * The seed 003 dynamic fixed-point unit (dfx.h), as data paths on the three
 * register fields.  Rounding (docs/dfx.md, tests/unit/test_dfx.c):
 *
 *   arithmetic (add, sub, mul, recip, div): truncation toward zero, as the
 *       paper's Fig. 9 keeps the top W bits of the product;
 *   conversions in (from_double, from_fixed): to nearest, ties away from
 *       zero, because they are the interface to the float world, not a data
 *       path of the unit;
 *   conversions out: to_double exact, to_fixed to nearest (as fx.c),
 *       floor_int exact floor.
 *
 * The data paths themselves (add, mul, recip, the conversions in) are the
 * inline functions of dfx_ops.h, which the perspective division calls
 * directly; this file is their callable form and the rest of the unit.
 *
 * The one derivation the paper leaves out: with value = 0.M * 16^(L-7)
 * (0.M = M / 2^W in [1/16, 1) when normalized), a product is
 * 0.M1*0.M2 * 16^(L1+L2-14) = 0.P * 16^((L1+L2-7) - 7), so L = L1 + L2 - 7
 * for every mantissa width W: the 7 is the position of the binary point in
 * the virtual 32.32 word (32 fraction bits = 8 digits, point after digit 7),
 * not a property of W.
 */
#include <math.h>
#include <string.h>
#include "fixed/dfx.h"
#include "fixed/fx_wide.h"
#include "fixed/dfx_ops.h"

__extension__ typedef unsigned __int128 dfx_u128;

static inline unsigned W(struct dfx_format f) { return f.mant_bits; }

struct dfx dfx_from_double(struct dfx_format f, double d, struct dfx_stats *st)
{
   if (isnan(d)) {
      st->sat++;                        /* garbage is a range event, not a value */
      return dfx_zero();
   }
   unsigned s = signbit(d) ? 1 : 0;
   if (d == 0)
      return dfx_zero();
   if (isinf(d)) {
      st->sat++;
      return dfx_max_mag_i(f, s);
   }
   /* |d| = n * 2^e from the double's fields (a subnormal has no implicit
    * one and the exponent of the smallest normal); dfx_from_exact_i takes
    * n of any length */
   uint64_t b;
   memcpy(&b, &d, sizeof(b));
   const int be = (int)((b >> 52) & 0x7ff);
   const uint64_t n = (b & ((UINT64_C(1) << 52) - 1)) | (be ? UINT64_C(1) << 52 : 0);
   return dfx_from_exact_i(f, s, n, (be ? be : 1) - 1075, true, st);
}

double dfx_to_double(struct dfx_format f, struct dfx a)
{
   return dfx_to_double_i(f, a);
}

struct dfx dfx_from_fixed(struct dfx_format f, struct fx_format fx, int64_t v,
                          struct dfx_stats *st)
{
   return dfx_from_fixed_i(f, fx, v, st);
}

int64_t dfx_to_fixed(struct dfx_format f, struct dfx a, struct fx_format fx, struct fx_sat *s)
{
   if (!a.m)
      return 0;
   int sh = dfx_exp_i(f, a.l) + fx.frac_bits;
   fx_i128 t = (fx_i128)a.m;
   if (a.s)
      t = -t;
   /* |value| < 2^32 and N < 64: the shifted mantissa fits in 128 bits */
   t = sh >= 0 ? t * ((fx_i128)1 << sh) : fx_shr_round_i128(t, (unsigned)-sh);
   return fx_sat_i128(t, fx_min(fx), fx_max(fx), &s->high, &s->low);
}

int64_t dfx_floor_int(struct dfx_format f, struct dfx a, uint32_t *frac, unsigned frac_bits)
{
   fx_i128 t;                           /* floor(a * 2^frac_bits) */
   int sh = dfx_exp_i(f, a.l) + (int)frac_bits;
   if (!a.m) {
      t = 0;
   } else if (sh >= 0) {
      t = (fx_i128)a.m << sh;
      if (a.s)
         t = -t;
   } else {
      unsigned r = (unsigned)-sh;
      dfx_u128 m = a.m;
      if (r >= 64)
         t = a.s ? -1 : 0;
      else if (a.s)
         t = -(fx_i128)((m + (((dfx_u128)1 << r) - 1)) >> r);
      else
         t = (fx_i128)(m >> r);
   }
   fx_i128 ip = t >> frac_bits;         /* arithmetic: floor */
   if (frac)
      *frac = (uint32_t)(t - ip * ((fx_i128)1 << frac_bits));
   return (int64_t)ip;
}

struct dfx dfx_add(struct dfx_format f, struct dfx a, struct dfx b, struct dfx_stats *st)
{
   return dfx_add_i(f, a, b, st);
}

struct dfx dfx_sub(struct dfx_format f, struct dfx a, struct dfx b, struct dfx_stats *st)
{
   return dfx_add_i(f, a, dfx_neg(b), st);
}

struct dfx dfx_mul(struct dfx_format f, struct dfx a, struct dfx b, struct dfx_stats *st)
{
   return dfx_mul_i(f, a, b, st);
}

struct dfx dfx_recip(struct dfx_format f, struct dfx a, struct dfx_stats *st)
{
   return dfx_recip_i(f, a, st);
}

/* The paper's A/B = A * (1/B): the multiplier is shared. */
struct dfx dfx_div(struct dfx_format f, struct dfx a, struct dfx b, struct dfx_stats *st)
{
   if (!a.m) {
      if (!b.m)
         st->sat++;                     /* 0/0 */
      return dfx_zero();
   }
   if (!b.m) {
      st->sat++;
      return dfx_max_mag_i(f, a.s);
   }
   return dfx_mul(f, a, dfx_recip(f, b, st), st);
}

uint32_t dfx_pack(struct dfx_format f, struct dfx a)
{
   if (!a.m)
      return 0;
   return ((uint32_t)a.s << (W(f) + 4)) | ((uint32_t)a.l << W(f)) | a.m;
}

/* An image whose top digit is zero (the unit never makes one) is
 * normalized; one below the smallest normalized value reads as zero. */
struct dfx dfx_unpack(struct dfx_format f, uint32_t bits)
{
   const unsigned w = W(f);
   uint32_t m = bits & ((UINT32_C(1) << w) - 1);
   int l = (int)((bits >> w) & 15);
   unsigned s = (bits >> (w + 4)) & 1;
   if (!m)
      return dfx_zero();
   while (!(m >> (w - 4))) {
      m <<= 4;
      l--;
   }
   if (l < 0)
      return dfx_zero();
   struct dfx r = { (uint8_t)s, (uint8_t)l, m };
   return r;
}
