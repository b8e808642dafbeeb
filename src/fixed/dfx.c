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
 * The one derivation the paper leaves out: with value = 0.M * 16^(L-7)
 * (0.M = M / 2^W in [1/16, 1) when normalized), a product is
 * 0.M1*0.M2 * 16^(L1+L2-14) = 0.P * 16^((L1+L2-7) - 7), so L = L1 + L2 - 7
 * for every mantissa width W: the 7 is the position of the binary point in
 * the virtual 32.32 word (32 fraction bits = 8 digits, point after digit 7),
 * not a property of W.
 */
#include <math.h>
#include "fixed/dfx.h"
#include "fixed/fx_wide.h"

__extension__ typedef unsigned __int128 dfx_u128;

static inline unsigned W(struct dfx_format f) { return f.mant_bits; }

/* Exponent of the mantissa's last bit: value = M * 2^dfx_exp(f, L). */
static inline int dfx_exp(struct dfx_format f, int l)
{
   return 4 * l + 4 - (int)f.mant_bits - 32;
}

static struct dfx dfx_max_mag(struct dfx_format f, unsigned s)
{
   struct dfx r = { (uint8_t)s, DFX_L_MAX, (UINT32_C(1) << W(f)) - 1 };
   return r;
}

/* The range check every operation ends with. */
static inline struct dfx finish(struct dfx_format f, unsigned s, int l, uint64_t m,
                                struct dfx_stats *st)
{
   if (l > DFX_L_MAX) {
      st->sat++;
      return dfx_max_mag(f, s);
   }
   if (l < 0) {
      st->flush++;
      return dfx_zero();
   }
   struct dfx r = { (uint8_t)s, (uint8_t)l, (uint32_t)m };
   return r;
}

static inline int floor_div4(int v)
{
   return v >= 0 ? v / 4 : -((-v + 3) / 4);
}

static inline unsigned bitlen128(dfx_u128 n)
{
   uint64_t hi = (uint64_t)(n >> 64);
   if (hi)
      return 128 - (unsigned)__builtin_clzll(hi);
   return 64 - (unsigned)__builtin_clzll((uint64_t)n);
}

/* (-1)^s * n * 2^e into the format: truncated (nearest = false) or rounded
 * to nearest, ties away from zero; n != 0. */
static struct dfx from_exact(struct dfx_format f, unsigned s, dfx_u128 n, int e, bool nearest,
                             struct dfx_stats *st)
{
   /* The top bit weighs 2^p, bit p + 32 of the virtual word: its digit is L. */
   int p = (int)bitlen128(n) - 1 + e;
   int l = floor_div4(p + 32);
   int sh = dfx_exp(f, l) - e;          /* drop sh bits of n (or append -sh) */
   dfx_u128 m;
   if (sh <= 0) {
      m = n << -sh;
   } else {
      m = n >> sh;
      if (nearest && ((n >> (sh - 1)) & 1))
         m++;
      if (m >> W(f)) {                  /* rounded up into the next digit */
         m >>= 4;
         l++;
      }
   }
   return finish(f, s, l, (uint64_t)m, st);
}

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
      return dfx_max_mag(f, s);
   }
   int e;
   double fr = frexp(fabs(d), &e);      /* |d| = fr * 2^e, fr in [1/2, 1) */
   uint64_t n = (uint64_t)ldexp(fr, 53);
   return from_exact(f, s, n, e - 53, true, st);
}

double dfx_to_double(struct dfx_format f, struct dfx a)
{
   /* M * 2^e built as a product with an exact power of two (e is within
    * -60..20, far from the double range's ends): no libm call per pixel. */
   union { uint64_t u; double d; } p;
   p.u = (uint64_t)(1023 + dfx_exp(f, a.l)) << 52;
   double v = (double)a.m * p.d;
   return a.s ? -v : v;
}

struct dfx dfx_from_fixed(struct dfx_format f, struct fx_format fx, int64_t v,
                          struct dfx_stats *st)
{
   if (v == 0)
      return dfx_zero();
   unsigned s = v < 0;
   uint64_t n = s ? -(uint64_t)v : (uint64_t)v;
   return from_exact(f, s, n, -(int)fx.frac_bits, true, st);
}

int64_t dfx_to_fixed(struct dfx_format f, struct dfx a, struct fx_format fx, struct fx_sat *s)
{
   if (!a.m)
      return 0;
   int sh = dfx_exp(f, a.l) + fx.frac_bits;
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
   int sh = dfx_exp(f, a.l) + (int)frac_bits;
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

/* The adder: order by magnitude, align the smaller by whole digits through
 * a 5-way multiplexer (0..4 digits; 5 or more leave nothing of it), add or
 * subtract with one guard digit below the mantissa, renormalize a digit at a
 * time, keep the top W bits.  The guard digit is our addition: without it a
 * one-digit cancellation would shift four zero bits into the result (up to
 * 16 ulps of error); with it add and sub stay within 17/16 ulp. */
static struct dfx add_signed(struct dfx_format f, struct dfx a, struct dfx b, struct dfx_stats *st)
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
   const unsigned w = W(f);
   if (S >> (w + 4)) {                  /* carry out of the top digit */
      S >>= 4;
      l++;
   }
   while (!(S >> w)) {                  /* leading-zero digit */
      S <<= 4;
      l--;
   }
   return finish(f, a.s, l, S >> 4, st);
}

struct dfx dfx_add(struct dfx_format f, struct dfx a, struct dfx b, struct dfx_stats *st)
{
   return add_signed(f, a, b, st);
}

struct dfx dfx_sub(struct dfx_format f, struct dfx a, struct dfx b, struct dfx_stats *st)
{
   return add_signed(f, a, dfx_neg(b), st);
}

/* Fig. 9. */
struct dfx dfx_mul(struct dfx_format f, struct dfx a, struct dfx b, struct dfx_stats *st)
{
   if (!a.m || !b.m)
      return dfx_zero();
   const unsigned w = W(f);
   uint64_t P = (uint64_t)a.m * b.m;    /* 2W bits */
   int l = a.l + b.l - 7;
   uint64_t m;
   if (!(P >> (2 * w - 4))) {           /* top digit of P is zero */
      m = P >> (w - 4);
      l--;
   } else {
      m = P >> w;
   }
   return finish(f, a.s ^ b.s, l, m, st);
}

/* 1/a by exact mantissa division: q = floor(2^(2W+4) / M) has W+5 to W+8
 * bits, so truncating q to W significant bits gives exactly the truncated
 * reciprocal (floor of a floor).  A divider of that width is the model's
 * statement of the unit; the paper names no method.  1/0 saturates. */
struct dfx dfx_recip(struct dfx_format f, struct dfx a, struct dfx_stats *st)
{
   if (!a.m) {
      st->sat++;
      return dfx_max_mag(f, 0);
   }
   const unsigned w = W(f), k = 2 * w + 4;
   uint64_t q = (UINT64_C(1) << k) / a.m;   /* in (2^(W+4), 2^(W+8)] */
   /* 1/v = q * 2^(-k - e), e = 4L + 4 - W - 32: dropping two digits of q
    * leaves a normalized W-bit mantissa at L' = 15 - L (derivation in
    * docs/dfx.md); only q = 2^(W+8) needs a third. */
   if (q >> (w + 8))                         /* M = 2^(W-4): 1/v is 16^n */
      return finish(f, a.s, 16 - a.l, q >> 12, st);
   return finish(f, a.s, 15 - a.l, q >> 8, st);
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
      return dfx_max_mag(f, a.s);
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
