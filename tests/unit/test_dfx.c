/*
 * dfx.c against exact arithmetic (__int128 at a common exponent), with the
 * bounds docs/dfx.md states, in ulps of the result (ulp = 2^e of its last
 * mantissa bit):
 *   from_double, from_fixed  |err| <= 1/2 ulp (nearest, ties away)
 *   add, sub                 |err| < 17/16 ulp; a shift of 5+ digits
 *                            returns the larger operand unchanged
 *   mul                      0 <= |exact| - |r| < 1 ulp (truncation)
 *   recip                    0 <= 1/|b| - |r| < 1 ulp (truncation)
 *   div = a * recip(b)       0 <= |a/b| - |r| < 1 ulp + |a/b| / M(recip(b))
 *   results >= 2^32 saturate, results < 2^-32 flush; both counted.
 * Random operands over all L, both signs, W = 12..24 (millions for W = 19);
 * exhaustive: W = 12 mul and add over all mantissa pairs at fixed L pairs,
 * W = 19 recip over all mantissas, all 2^24 packed W = 19 images.
 */
#include <math.h>
#include <string.h>
#include "tutil.h"
#include "fixed/dfx.h"

__extension__ typedef __int128 i128;

static struct dfx_format F;

static int ex(int l) { return 4 * l + 4 - F.mant_bits - 32; }
static uint32_t mlo(void) { return UINT32_C(1) << (F.mant_bits - 4); }
static uint32_t mhi(void) { return (UINT32_C(1) << F.mant_bits) - 1; }

#ifndef FUZZ_TARGET   /* the unit test's random operands */
static uint64_t rng = 88172645463325252ull;

static uint64_t rnd(void)
{
   return t_xorshift(&rng);
}

static struct dfx rnd_dfx(void)
{
   struct dfx a;
   a.s = rnd() & 1;
   a.l = rnd() % 16;
   a.m = mlo() + (uint32_t)(rnd() % (mhi() - mlo() + 1));
   return a;
}
#endif

static bool valid(struct dfx a)
{
   if (!a.m)
      return a.s == 0 && a.l == 0;
   return a.l <= 15 && a.m >= mlo() && a.m <= mhi();
}

static bool same(struct dfx a, struct dfx b)
{
   return a.s == b.s && a.l == b.l && a.m == b.m;
}

/* signed n * 2^e, scaled to exponent e0 <= e */
static i128 at(i128 n, int e, int e0)
{
   return n * ((i128)1 << (e - e0));
}

static i128 sval(struct dfx a) { return a.s ? -(i128)a.m : (i128)a.m; }

static const double BIG = 4294967296.0;           /* 2^32: first value beyond max */
static const double SMALL = 1.0 / 4294967296.0;   /* 2^-32: smallest normalized */

static uint64_t n_checked;

/* r against the exact value x * 2^ex (x signed), bound in sixteenths of
 * r's ulp; trunc: |r| <= |exact| as well. */
static void check_near(const char *what, struct dfx r, i128 x, int xe, unsigned bound16,
                       bool trunc, struct dfx_stats *st, struct dfx_stats before)
{
   n_checked++;
   CHECK(valid(r), "%s: not normalized (s %u l %u m %x)", what, r.s, r.l, r.m);
   double xd = ldexp((double)x, xe), ax = fabs(xd);
   if (x == 0) {
      CHECK(!r.m && st->sat == before.sat && st->flush == before.flush,
            "%s: an exact zero is no range event", what);
      return;
   }
   /* within a few ulps of a range end either outcome is right; beyond
    * it, the event must have happened (and been counted) or not */
   double tol = ldexp(1, -(int)F.mant_bits + 4);
   bool sat = st->sat != before.sat, flush = st->flush != before.flush;
   if (ax >= BIG * (1 + tol) || (sat && ax >= BIG * (1 - tol))) {
      CHECK(st->sat == before.sat + 1 && r.l == 15 && r.m == mhi() && r.s == (x < 0),
            "%s: %g should saturate", what, xd);
      return;
   }
   if (ax < SMALL * (1 - tol) || (flush && ax < SMALL * (1 + tol))) {
      CHECK(st->flush == before.flush + 1 && r.m == 0, "%s: %g should flush", what, xd);
      return;
   }
   CHECK(!sat && !flush, "%s: spurious range event at %g", what, xd);
   if (!r.m) {
      CHECK(x == 0, "%s: zero for %g", what, xd);
      return;
   }
   int er = ex(r.l);
   int e0 = er < xe ? er : xe;
   if (er - e0 > 100 || xe - e0 > 100) {
      CHECK(0, "%s: exponents too far apart (%d, %d)", what, er, xe);
      return;
   }
   i128 X = at(x, xe, e0), R = at(sval(r), er, e0), U = at(1, er, e0);
   i128 d = X - R;
   i128 ad = d < 0 ? -d : d;
   bool ok = bound16 == 8 ? ad * 16 <= U * 8 : ad * 16 < U * bound16;
   CHECK(ok, "%s: %.17g vs exact %.17g (%.3f ulp, bound %u/16)", what,
         dfx_to_double(F, r), xd, (double)ad / (double)U, bound16);
   if (trunc)
      CHECK((x >= 0 ? d >= 0 : d <= 0) && r.s == (x < 0), "%s: truncation went away from zero", what);
}

static void test_mul(struct dfx a, struct dfx b)
{
   struct dfx_stats st = { 0, 0 }, b0 = st;
   struct dfx r = dfx_mul(F, a, b, &st);
   i128 x = sval(a) * sval(b);
   check_near("mul", r, x, ex(a.l) + ex(b.l), 16, true, &st, b0);
}

static void test_addsub(struct dfx a, struct dfx b, bool sub)
{
   struct dfx_stats st = { 0, 0 }, b0 = st;
   struct dfx r = sub ? dfx_sub(F, a, b, &st) : dfx_add(F, a, b, &st);
   struct dfx bb = sub ? dfx_neg(b) : b;
   int big = a.l > bb.l ? a.l : bb.l, small = a.l > bb.l ? bb.l : a.l;
   if (a.m && bb.m && big - small >= 5) {
      n_checked++;
      CHECK(same(r, a.l > bb.l ? a : bb) && st.sat == 0 && st.flush == 0,
            "add: a shift of %d digits must leave the larger operand", big - small);
      return;
   }
   int e0 = ex(a.l) < ex(bb.l) ? ex(a.l) : ex(bb.l);
   i128 x = at(sval(a), ex(a.l), e0) + at(sval(bb), ex(bb.l), e0);
   /* the exact sum's sign is r's; truncation here is not one-sided (sub
    * truncates the subtrahend), so only the magnitude bound applies */
   check_near(sub ? "sub" : "add", r, x, e0, 17, false, &st, b0);
}

static void test_recip(struct dfx b)
{
   struct dfx_stats st = { 0, 0 };
   struct dfx r = dfx_recip(F, b, &st);
   n_checked++;
   double bd = fabs(dfx_to_double(F, b));
   if (1 / bd >= BIG) {
      CHECK(st.sat == 1 && r.l == 15 && r.m == mhi(), "recip of %g should saturate", bd);
      return;
   }
   CHECK(st.sat == 0 && st.flush == 0 && valid(r) && r.m && r.s == b.s, "recip of %g", bd);
   /* 0 <= 1 - |r||b| < ulp(r)|b|, scaled by 2^-(er+eb) */
   int e = ex(r.l) + ex(b.l);
   CHECK(e < 0 && -e < 120, "recip exponent %d", e);
   i128 one = (i128)1 << -e, rb = (i128)r.m * b.m;
   CHECK(rb <= one && one - rb < (i128)b.m, "recip of %.17g: %.17g", bd, dfx_to_double(F, r));
}

static void test_div(struct dfx a, struct dfx b)
{
   struct dfx_stats st = { 0, 0 };
   struct dfx r = dfx_div(F, a, b, &st);
   struct dfx_stats s2 = { 0, 0 };
   struct dfx rb = dfx_recip(F, b, &s2);
   double q = dfx_to_double(F, a) / dfx_to_double(F, b);
   n_checked++;
   double tol = ldexp(1, -(int)F.mant_bits + 6);   /* > the div's relative bound */
   if (s2.sat || fabs(q) >= BIG * (1 - tol) || fabs(q) < SMALL * (1 + tol)) {
      /* a range event in recip or mul: counted, and the value is one of
       * the ends; near an end either outcome is right */
      if (s2.sat)          /* 1/b beyond the range: the clamped recip is used */
         CHECK(st.sat >= 1, "div %g: recip saturation not counted", q);
      else if (fabs(q) >= BIG * (1 + tol))
         CHECK(st.sat >= 1 && r.l == 15 && r.m == mhi(), "div %g: saturation not counted", q);
      if (fabs(q) < SMALL * (1 - tol))
         CHECK(st.flush >= 1 && !r.m, "div %g: flush not counted", q);
      return;
   }
   CHECK(st.sat == 0 && st.flush == 0 && valid(r) && r.m && r.s == (a.s ^ b.s), "div %g", q);
   /* |a| - |r||b| in [0, ulp(r)|b| + |a|/M_rb): times M_rb, at a common exponent */
   int ea = ex(a.l), erb = ex(r.l) + ex(b.l);
   int e0 = ea < erb ? ea : erb;
   i128 A = at(a.m, ea, e0), RB = at((i128)r.m * b.m, erb, e0), UB = at(b.m, erb, e0);
   i128 d = A - RB;
   CHECK(d >= 0 && d * rb.m < UB * rb.m + A, "div %.17g: %.17g", q, dfx_to_double(F, r));
}

static void test_from_double(double d)
{
   struct dfx_stats st = { 0, 0 }, b0 = st;
   struct dfx r = dfx_from_double(F, d, &st);
   int e;
   double fr = frexp(d, &e);
   i128 x = (i128)ldexp(fr, 53);
   check_near("from_double", r, x, e - 53, 8, false, &st, b0);
}

#ifdef FUZZ_TARGET
/* libFuzzer (tests/fuzz, ./fixpipe fuzz): the same checks on operands from
 * the input's bytes: a format W, an operation, two registers (sign, L,
 * a mantissa in range) and a double; a result off its bound aborts. */
static struct dfx fuzz_dfx(const uint8_t *p)
{
   uint32_t m;
   memcpy(&m, p + 1, 4);
   struct dfx a;
   a.s = p[0] & 1;
   a.l = (uint8_t)((p[0] >> 1) % 16);
   a.m = mlo() + m % (mhi() - mlo() + 1);
   return a;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
   if (size < 2 + 5 + 5 + 8)
      return 0;
   F.mant_bits = (uint8_t)(DFX_MANT_BITS_MIN + data[0] % (DFX_MANT_BITS_MAX - DFX_MANT_BITS_MIN + 1));
   const struct dfx a = fuzz_dfx(data + 2), b = fuzz_dfx(data + 7);
   double d;
   memcpy(&d, data + 12, 8);
   switch (data[1] % 6) {
   case 0: test_mul(a, b); break;
   case 1: test_addsub(a, b, false); break;
   case 2: test_addsub(a, b, true); break;
   case 3: test_recip(b); break;
   case 4: test_div(a, b); break;
   default:
      if (isfinite(d) && d != 0)
         test_from_double(d);
      break;
   }
   if (t_failures)
      abort();
   return 0;
}
#else
static void random_ops(unsigned n)
{
   for (unsigned i = 0; i < n; i++) {
      struct dfx a = rnd_dfx(), b = rnd_dfx();
      if (i % 4 == 0)        /* near locations: the interesting adds */
         b.l = (uint8_t)(a.l > 5 ? a.l - rnd() % 6 : a.l + rnd() % 6);
      test_mul(a, b);
      test_addsub(a, b, false);
      test_addsub(a, b, true);
      test_recip(b);
      test_div(a, b);
      double d = ldexp((double)(rnd() >> 11) + 1, (int)(rnd() % 140) - 150) * ((rnd() & 1) ? -1 : 1);
      test_from_double(d);
      if (i % 64 == 0)       /* subnormal doubles: their fields have no implicit one */
         test_from_double(ldexp((double)(rnd() >> 12), -1074) * ((rnd() & 1) ? -1 : 1));
   }
}

static void conversions(void)
{
   struct dfx_stats st = { 0, 0 };
   for (unsigned i = 0; i < 200000; i++) {
      struct dfx a = rnd_dfx();
      double v = dfx_to_double(F, a);
      CHECK(v == (a.s ? -1 : 1) * ldexp(a.m, ex(a.l)), "to_double");
      struct dfx b = dfx_from_double(F, v, &st);
      CHECK(same(a, b), "from_double(to_double) round trip");
      /* fixed point: to_fixed rounds like fx_from_double; from_fixed is
       * from_double of the exact value */
      struct fx_format fxs[] = { { 16, 16 }, { 8, 24 }, { 24, 8 }, { 33, 30 } };
      for (unsigned k = 0; k < 4; k++) {
         struct fx_sat s1 = { 0, 0 }, s2 = { 0, 0 };
         int64_t x = dfx_to_fixed(F, a, fxs[k], &s1);
         int64_t y = fx_from_double(fxs[k], v, &s2);
         CHECK(x == y && s1.high == s2.high && s1.low == s2.low, "to_fixed %u.%u of %g: %lld vs %lld",
               fxs[k].int_bits, fxs[k].frac_bits, v, (long long)x, (long long)y);
         struct dfx_stats t1 = { 0, 0 }, t2 = { 0, 0 };
         struct dfx c = dfx_from_fixed(F, fxs[k], y, &t1);
         struct dfx e = dfx_from_double(F, fx_to_double(fxs[k], y), &t2);
         CHECK(same(c, e) && t1.flush == t2.flush && t1.sat == t2.sat, "from_fixed");
      }
      /* floor_int: the floor and the fraction bits of v * 2^fb */
      unsigned fb = (unsigned)(rnd() % 21);
      uint32_t frac;
      int64_t ip = dfx_floor_int(F, a, &frac, fb);
      double t = floor(ldexp(v, (int)fb));
      CHECK((double)ip * ldexp(1, (int)fb) + frac == t && frac < (UINT64_C(1) << fb),
            "floor_int(%g, %u): %lld + %u", v, fb, (long long)ip, frac);
   }
   CHECK(st.sat == 0 && st.flush == 0, "round trips are in range");
}

static void edges(void)
{
   struct dfx_stats st = { 0, 0 };
   struct dfx z = dfx_zero(), one = dfx_from_double(F, 1.0, &st);
   struct dfx smallest = { 0, 0, mlo() }, largest = { 0, 15, mhi() };
   CHECK(one.l == 8 && one.m == mlo(), "1.0 is L = 8, M = 2^(W-4)");
   CHECK(dfx_to_double(F, smallest) == SMALL, "smallest is 2^-32");
   CHECK(dfx_to_double(F, largest) == BIG - ldexp(1, 32 - F.mant_bits), "largest");
   CHECK(dfx_is_zero(dfx_mul(F, z, largest, &st)) && dfx_is_zero(dfx_add(F, z, z, &st)), "zero");
   CHECK(same(dfx_add(F, z, one, &st), one) && same(dfx_sub(F, one, z, &st), one), "x + 0");
   CHECK(dfx_is_zero(dfx_sub(F, one, one, &st)) && st.flush == 0, "x - x is an exact zero, no flush");
   CHECK(dfx_is_zero(dfx_from_double(F, 0.0, &st)) && dfx_is_zero(dfx_from_double(F, -0.0, &st)), "+-0");
   CHECK(st.sat == 0 && st.flush == 0, "no events so far");
   /* saturation: counted, sign kept */
   struct dfx r = dfx_add(F, largest, largest, &st);
   CHECK(same(r, largest) && st.sat == 1, "max + max saturates");
   r = dfx_mul(F, dfx_neg(largest), one, &st);
   CHECK(same(r, dfx_neg(largest)) && st.sat == 1, "max * 1 is exact");
   r = dfx_mul(F, dfx_neg(largest), dfx_from_double(F, 2.0, &st), &st);
   CHECK(same(r, dfx_neg(largest)) && st.sat == 2, "-max * 2 saturates negative");
   r = dfx_from_double(F, BIG, &st);
   CHECK(same(r, largest) && st.sat == 3, "2^32 saturates");
   r = dfx_from_double(F, INFINITY, &st);
   CHECK(same(r, largest) && st.sat == 4, "inf saturates");
   r = dfx_from_double(F, NAN, &st);
   CHECK(dfx_is_zero(r) && st.sat == 5, "NaN is zero, counted");
   r = dfx_recip(F, smallest, &st);
   CHECK(same(r, largest) && st.sat == 6, "1/2^-32 saturates");
   r = dfx_recip(F, z, &st);
   CHECK(same(r, largest) && st.sat == 7, "1/0 saturates");
   /* flush */
   r = dfx_mul(F, smallest, smallest, &st);
   CHECK(dfx_is_zero(r) && st.flush == 1, "smallest^2 flushes");
   r = dfx_from_double(F, SMALL / 2, &st);
   CHECK(dfx_is_zero(r) && st.flush == 2, "2^-33 flushes");
   r = dfx_from_double(F, SMALL * (1 - ldexp(1, -(int)F.mant_bits - 2)), &st);
   CHECK(same(r, smallest) && st.flush == 2, "just below 2^-32 rounds up to the smallest");
   struct dfx s2 = smallest;
   s2.m++;
   r = dfx_sub(F, s2, smallest, &st);
   CHECK(dfx_is_zero(r) && st.flush == 3, "cancellation below the smallest flushes");
   /* a carry out of the top digit moves L up one digit */
   struct dfx a = { 0, 7, mhi() }, b = { 0, 7, mlo() };
   r = dfx_add(F, a, b, &st);
   CHECK(r.l == 8 && r.m == ((uint32_t)((uint64_t)mhi() + mlo()) >> 4), "digit carry: l %u m %x", r.l, r.m);
   /* cancellation: 1 + 2^-k - 1 renormalizes by several digits, exactly */
   struct dfx x = one;
   x.m |= 1;                                 /* 1 + ulp at L = 8 */
   r = dfx_sub(F, x, one, &st);
   CHECK(dfx_to_double(F, r) == ldexp(1, ex(8)) && r.m >= mlo(), "cancellation: %g", dfx_to_double(F, r));
   /* 5-way alignment: 4 digits still count, 5 leave nothing */
   struct dfx t4 = { 0, 4, mhi() }, t3 = { 0, 3, mhi() };
   if (F.mant_bits > 16)    /* 16 bits shifted out: W - 16 remain */
      CHECK(!same(dfx_add(F, one, t4, &st), one), "a 4-digit shift keeps bits");
   CHECK(same(dfx_add(F, one, t3, &st), one), "a 5-digit shift leaves nothing");
   /* Fig. 9's one-digit correction: 1/16-ish mantissas */
   struct dfx lo = { 0, 7, mlo() };          /* 1/16 */
   r = dfx_mul(F, lo, lo, &st);
   CHECK(dfx_to_double(F, r) == 1.0 / 256 && r.m == mlo() && r.l == 6, "1/16 * 1/16: l %u m %x", r.l, r.m);
   /* division */
   r = dfx_div(F, dfx_from_double(F, 3.0, &st), dfx_from_double(F, 4.0, &st), &st);
   CHECK(dfx_to_double(F, r) == 0.75, "3/4 = %g", dfx_to_double(F, r));
   CHECK(st.sat == 7 && st.flush == 3, "event counts: sat %llu flush %llu",
         (unsigned long long)st.sat, (unsigned long long)st.flush);
}

/* W = 12: all mantissa pairs (3840^2) at a fixed L pair. */
static void exhaustive_w12(void)
{
   F.mant_bits = 12;
   for (uint32_t m1 = mlo(); m1 <= mhi(); m1++)
      for (uint32_t m2 = mlo(); m2 <= mhi(); m2++) {
         struct dfx a = { 0, 7, m1 }, b = { 1, 9, m2 }, c = { 0, 8, m2 };
         test_mul(a, b);
         test_addsub(a, c, (m2 & 1) != 0);
         if (m2 % 64 == 0)
            test_addsub(a, b, true);
      }
}

static void exhaustive_recip_w19(void)
{
   F.mant_bits = 19;
   for (uint32_t m = mlo(); m <= mhi(); m++) {
      struct dfx b = { (uint8_t)(m & 1), (uint8_t)(m % 16), m };
      test_recip(b);
   }
}

static void exhaustive_pack(void)
{
   F.mant_bits = 19;
   uint64_t canon = 0;
   for (uint32_t bits = 0; bits < (UINT32_C(1) << 24); bits++) {
      struct dfx a = dfx_unpack(F, bits);
      uint32_t m = bits & 0x7FFFF, l = (bits >> 19) & 15, s = bits >> 23;
      double img = (s ? -1 : 1) * ldexp(m, ex((int)l));
      double v = dfx_to_double(F, a);
      if (m >= mlo()) {
         canon++;
         struct dfx_stats st = { 0, 0 };
         if (dfx_pack(F, a) != bits || v != img || !same(dfx_from_double(F, v, &st), a) || st.sat || st.flush)
            CHECK(0, "image %06x does not round-trip", bits);
      } else if (v != (fabs(img) >= SMALL ? img : 0) || !valid(a) ||
                 dfx_pack(F, dfx_unpack(F, dfx_pack(F, a))) != dfx_pack(F, a)) {
         CHECK(0, "non-canonical image %06x: %g vs %g", bits, v, img);
      }
   }
   CHECK(canon == 2ull * 16 * (0x80000 - 0x8000), "canonical images: %llu", (unsigned long long)canon);
}

int main(void)
{
   F.mant_bits = DFX_MANT_BITS_SEED;
   edges();
   conversions();
   random_ops(2000000);
   uint64_t n19 = n_checked;
   for (unsigned w = DFX_MANT_BITS_MIN; w <= DFX_MANT_BITS_MAX; w++) {
      F.mant_bits = (uint8_t)w;
      edges();
      conversions();
      random_ops(100000);
   }
   exhaustive_w12();
   exhaustive_recip_w19();
   exhaustive_pack();
   printf("dfx: %llu results checked (%llu random at W = 19), 2^24 packed images\n",
          (unsigned long long)n_checked, (unsigned long long)n19);
   return t_summary("dfx");
}
#endif
