/*
 * The dfx24 data paths on lanes (src/fixed/dfx_lanes.h) against their
 * scalar twins (dfx_ops.h), bit for bit and event for event: millions of
 * random operands, weighted toward the cases with their own logic (zero,
 * equal digits, shifts of 4 and 5 digits, cancellation, the ends of the
 * range, mantissas at 2^15 and 2^19 - 1).  Built once per instruction set
 * (TEST_ISA names it; the AVX-512 one on eight lanes, DFXL_N = 8); the
 * AVX2 and AVX-512 builds check the CPU first.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "fixed/dfx_lanes.h"
#include "tutil.h"

#ifndef TEST_ISA
#define TEST_ISA "sse2"
#endif

static const struct dfx_format F = { DFX_MANT_BITS_SEED };
static uint64_t rng = 0x9e3779b97f4a7c15ull;

static uint64_t rnd(void)
{
   return t_xorshift(&rng);
}

static struct dfx rnd_dfx(void)
{
   const uint32_t lo = 1u << 15, hi = (1u << 19) - 1;
   struct dfx a;
   switch (rnd() % 16) {
   case 0:
      return dfx_zero();
   case 1:
      a.m = lo;
      break;
   case 2:
      a.m = hi;
      break;
   case 3:
      a.m = lo + (uint32_t)(rnd() % 16);
      break;
   default:
      a.m = lo + (uint32_t)(rnd() % (hi - lo + 1));
      break;
   }
   a.s = rnd() & 1;
   const unsigned r = rnd() % 8;
   a.l = r == 0 ? 0 : r == 1 ? DFX_L_MAX : (uint8_t)(rnd() % 16);
   return a;
}

/* b near a: equal digits and shifts of 0..6 digits, both signs, for the
 * adder's alignment and cancellation. */
static struct dfx rnd_near(struct dfx a)
{
   struct dfx b = rnd_dfx();
   if (!a.m || rnd() % 2)
      return b;
   int l = a.l - (int)(rnd() % 7);
   b.l = (uint8_t)(l < 0 ? 0 : l);
   if (rnd() % 4 == 0)
      b.m = a.m ^ (uint32_t)(rnd() % 8);
   if (b.m < (1u << 15))
      b.m |= 1u << 15;
   return b;
}

static bool same(struct dfx a, struct dfx b)
{
   return a.s == b.s && a.l == b.l && a.m == b.m;
}

static uint64_t n_checked, n_marked;

static void check(const char *op, const struct dfx *in_a, const struct dfx *in_b,
                  const struct dfx want[DFXL_N], struct dfx_stats ws, struct dfxl r,
                  struct dfxl_stats rs)
{
   struct dfx got[DFXL_N];
   struct dfx_stats gs = { 0, 0 };
   dfxl_store(r, got);
   dfxl_stats_add(&gs, rs);
   for (int i = 0; i < DFXL_N; i++) {
      n_checked++;
      CHECK(same(got[i], want[i]),
            "%s lane %d: a = (%u,%u,%u) b = (%u,%u,%u): got (%u,%u,%u) want (%u,%u,%u)", op, i,
            in_a[i].s, in_a[i].l, in_a[i].m, in_b ? in_b[i].s : 0, in_b ? in_b[i].l : 0,
            in_b ? in_b[i].m : 0, got[i].s, got[i].l, got[i].m, want[i].s, want[i].l,
            want[i].m);
   }
   CHECK(gs.sat == ws.sat && gs.flush == ws.flush,
         "%s: events sat %llu flush %llu, want %llu %llu", op, (unsigned long long)gs.sat,
         (unsigned long long)gs.flush, (unsigned long long)ws.sat,
         (unsigned long long)ws.flush);
}

/* The optimistic way (dfx_lanes.h): a lane is marked only where the
 * scalar path raised a range event, or where `may_mark` (an input the
 * optimistic way does not take: from_fixed's beyond 2^52); an unmarked lane
 * has the scalar bits and counts the scalar events (those whose result
 * needs no handling, as the reciprocal of zero). */
static void check_optimistic(const char *op, const struct dfx want[DFXL_N],
                             const struct dfx_stats ev[DFXL_N], struct dfxl r,
                             struct dfxl_stats rs, dfxl_i may_mark)
{
   struct dfx got[DFXL_N];
   dfxl_store(r, got);
   const dfxl_i marked = dfxl_trouble(&rs);
   for (int i = 0; i < DFXL_N; i++) {
      n_checked++;
      if (marked[i]) {
         n_marked++;
         CHECK(ev[i].sat || ev[i].flush || may_mark[i],
               "%s (optimistic) lane %d: marked without an event", op, i);
         continue;
      }
      CHECK(!may_mark[i], "%s (optimistic) lane %d: an input beyond the optimistic way, "
            "not marked", op, i);
      CHECK(same(got[i], want[i]), "%s (optimistic) lane %d: got (%u,%u,%u) want (%u,%u,%u)",
            op, i, got[i].s, got[i].l, got[i].m, want[i].s, want[i].l, want[i].m);
      CHECK((uint64_t)rs.sat[i] == ev[i].sat && (uint64_t)rs.flush[i] == ev[i].flush,
            "%s (optimistic) lane %d: events sat %lld flush %lld, want %llu %llu", op, i,
            (long long)rs.sat[i], (long long)rs.flush[i], (unsigned long long)ev[i].sat,
            (unsigned long long)ev[i].flush);
   }
}

/* Each operation both ways: the scalar results, lane by lane with their
 * events, against the lanes handling every event and the optimistic lanes. */
#define BOTH_WAYS(name, scalar, lanes, in_b, may_mark)                                                  \
   do {                                                                                      \
      struct dfx_stats ws = { 0, 0 }, ev[DFXL_N];                                            \
      for (int i = 0; i < DFXL_N; i++) {                                                     \
         struct dfx_stats wl = { 0, 0 };                                                     \
         want[i] = scalar;                                                                   \
         ev[i] = wl;                                                                         \
         ws.sat += wl.sat;                                                                   \
         ws.flush += wl.flush;                                                               \
      }                                                                                      \
      struct dfxl_stats rs = DFXL_STATS(false), ro = DFXL_STATS(true);                       \
      check(name, a, in_b, want, ws, lanes(&rs), rs);                                        \
      check_optimistic(name, want, ev, lanes(&ro), ro, may_mark);                            \
   } while (0)

static void test_binary(void)
{
   struct dfx a[DFXL_N], b[DFXL_N], want[DFXL_N];
   for (int i = 0; i < DFXL_N; i++) {
      a[i] = rnd_dfx();
      b[i] = rnd_near(a[i]);
   }
   const struct dfxl A = dfxl_load(a), B = dfxl_load(b);
#define ADD(st) dfxl_add(A, B, st)
#define SUB(st) dfxl_sub(A, B, st)
#define MUL(st) dfxl_mul(A, B, st)
#define RECIP(st) dfxl_recip(A, st)
   BOTH_WAYS("add", dfx_add_i(F, a[i], b[i], &wl), ADD, b, dfxl_splat(0));
   BOTH_WAYS("sub", dfx_add_i(F, a[i], dfx_neg(b[i]), &wl), SUB, b, dfxl_splat(0));
   BOTH_WAYS("mul", dfx_mul_i(F, a[i], b[i], &wl), MUL, b, dfxl_splat(0));
   BOTH_WAYS("recip", dfx_recip_i(F, a[i], &wl), RECIP, NULL, dfxl_splat(0));

   /* the adder without its aligner, where the signs are the same */
   struct dfx bs[DFXL_N];
   for (int i = 0; i < DFXL_N; i++) {
      bs[i] = b[i];
      bs[i].s = a[i].s;
   }
   const struct dfxl BS = dfxl_load(bs);
#define ADD_SAME_SIGN(st) dfxl_add_same_sign(A, BS, st)
   BOTH_WAYS("add_same_sign", dfx_add_i(F, a[i], bs[i], &wl), ADD_SAME_SIGN, bs, dfxl_splat(0));

   float fw[DFXL_N], fg[DFXL_N];
   for (int i = 0; i < DFXL_N; i++)
      fw[i] = (float)dfx_to_double_i(F, a[i]);
   dfxl_to_float(A, fg);
   for (int i = 0; i < DFXL_N; i++) {
      n_checked++;
      CHECK(!memcmp(&fw[i], &fg[i], sizeof(float)), "to_float (%u,%u,%u): %a, want %a",
            a[i].s, a[i].l, a[i].m, (double)fg[i], (double)fw[i]);
   }
}

static struct dfx rnd_between(int lo, int hi, unsigned sign);

/* A plane's sum v0 + a·d1 + b·d2 the scalar way, its events in *ev. */
static struct dfx plane_i(struct dfx v0, struct dfx a, struct dfx d1, struct dfx b, struct dfx d2,
                          struct dfx_stats *ev)
{
   const struct dfx t1 = dfx_mul_i(F, a, d1, ev), t2 = dfx_mul_i(F, b, d2, ev);
   return dfx_add_i(F, dfx_add_i(F, v0, t1, ev), t2, ev);
}

/* The same on lanes with one bound an operation (dfxl_term,
 * dfxl_add_terms): with the signs of every lane's terms the same (the
 * adders without their aligner), and at random (the aligner's way). */
static void test_plane_sums(void)
{
   struct dfx v0[DFXL_N], a[DFXL_N], d1[DFXL_N], b[DFXL_N], d2[DFXL_N], want[DFXL_N];
   const bool same_signs = rnd() & 1;
   for (int i = 0; i < DFXL_N; i++) {
      v0[i] = rnd_dfx();
      a[i] = rnd_dfx();
      d1[i] = rnd_near(v0[i]);
      b[i] = rnd_dfx();
      d2[i] = rnd_near(d1[i]);
      if (same_signs) {
         v0[i].s = a[i].s = b[i].s = d1[i].s = d2[i].s = 0;
         if (!v0[i].m)
            v0[i] = rnd_between(-32, 32, 0);
      }
   }
   const struct dfxl V0 = dfxl_load(v0), A = dfxl_load(a), D1 = dfxl_load(d1),
                     B = dfxl_load(b), D2 = dfxl_load(d2);
#define PLANE(st) dfxl_add_terms(dfxl_add_terms(V0, dfxl_term(A, D1, st), st), \
                                 dfxl_term(B, D2, st), st)
   BOTH_WAYS("plane sum", plane_i(v0[i], a[i], d1[i], b[i], d2[i], &wl), PLANE, d1,
             dfxl_splat(0));
}

/* A register of magnitude in [2^lo, 2^hi) (lo, hi multiples of 4 from -32
 * to 32), any mantissa, near a power of two now and then. */
static struct dfx rnd_between(int lo, int hi, unsigned sign)
{
   struct dfx a = rnd_dfx();
   if (!a.m)
      a.m = 1u << 15;
   a.s = (uint8_t)sign;
   a.l = (uint8_t)((lo + 32) / 4 + (int)(rnd() % (uint64_t)((hi - lo) / 4)));
   return a;
}

/* The texture unit's subtractions without the aligner (dfx_lanes.h): the
 * linear filter's texel offset from a scaled coordinate, and a coordinate's
 * floor from it, where their conditions hold, against the scalar adder. */
static void test_tex_subtractions(void)
{
   struct dfx a[DFXL_N], k[DFXL_N], want[DFXL_N];
   struct dfx_stats loads = { 0, 0 };   /* exact: none */
   const struct dfx off = dfx_from_double(F, DFXL_TEXEL_OFFSET, &loads);
   for (int i = 0; i < DFXL_N; i++) {
      k[i] = off;
      do {
         switch (rnd() % 4) {
         case 0: a[i] = rnd_dfx(); break;                              /* anything */
         case 1: a[i] = rnd_between(-8, 0, 0); break;                  /* near the offset */
         case 2: a[i] = rnd_between(-12, 16, 0); break;                /* across the bounds */
         default: a[i] = rnd_between(-32, 32, 1); break;               /* negative */
         }
      } while (!dfxl_sub_texel_offset_direct(dfxl_splatd(dfxl_value(a[i]))));
   }
   struct dfxl A = dfxl_load(a);
   CHECK(dfxl_sub_texel_offset_direct(A.v), "texel offset: a lane outside the condition");
#define SUB_OFFSET(st) dfxl_sub_texel_offset(A, st)
   BOTH_WAYS("sub_texel_offset", dfx_add_i(F, a[i], dfx_neg(off), &wl), SUB_OFFSET, k,
             dfxl_splat(0));

   struct dfx n[DFXL_N];
   for (int i = 0; i < DFXL_N; i++) {
      a[i] = rnd() % 8 ? rnd_between(-32, 16, 0) : dfx_zero();
      n[i] = dfx_from_double(F, floor(dfxl_value(a[i])), &loads);
   }
   A = dfxl_load(a);
   CHECK(dfxl_sub_floor_direct(A.v), "floor: a lane outside the condition");
   const dfxl_d N = dfxl_floor(A.v);
#define SUB_FLOOR(st) dfxl_sub_floor(A, N, st)
   BOTH_WAYS("sub_floor", dfx_add_i(F, a[i], dfx_neg(n[i]), &wl), SUB_FLOOR, n, dfxl_splat(0));
   CHECK(!loads.sat && !loads.flush, "the offset and the floors are not exact registers");
}

/* A numerator as the perspective division makes one: any sign, up to 2^60. */
static int64_t rnd_numerator(void)
{
   const unsigned bits = (unsigned)(rnd() % 61);
   int64_t x = bits ? (int64_t)(rnd() >> (64 - bits)) : 0;
   if (rnd() % 8 == 0)
      x = (int64_t)1 << (rnd() % 60);                 /* a power of two */
   if (rnd() % 8 == 0)
      x |= (int64_t)((1ull << (rnd() % 40)) - 1);     /* rounding carries */
   return rnd() & 1 ? -x : x;
}

/* Numerators with k (the determinant's length) 1..60. */
static void test_from_fixed(void)
{
   int64_t v[DFXL_N];
   struct dfx want[DFXL_N], in[DFXL_N];
   const int k = 1 + (int)(rnd() % 60);
   for (int i = 0; i < DFXL_N; i++) {
      v[i] = rnd_numerator();
      in[i] = dfx_zero();
   }
   const struct fx_format fx = { 0, (uint8_t)k };
   dfxl_i V;
   memcpy(&V, v, sizeof(V));
   const struct dfx *a = in;
#define FROM_FIXED(st) dfxl_from_fixed(V, k, st)
   const dfxl_i beyond = (V >= dfxl_splat((int64_t)1 << 52)) | (V <= -dfxl_splat((int64_t)1 << 52));
   BOTH_WAYS("from_fixed", dfx_from_fixed_i(F, fx, v[i], &wl), FROM_FIXED, NULL, beyond);
}

#if defined(__AVX512F__) && DFXL_N == 8
#include "fixed/dfx_lanes32.h"

/* dfx_lanes32.h: sixteen binary32 lanes, the optimistic way only.  A lane
 * is marked only where the scalar path raised a range event (or divided
 * by zero); an unmarked one has the scalar bits, +0 for zero, and the
 * scalar path counted nothing for it. */
static uint64_t n_checked32, n_marked32;

static __m512 load32(const struct dfx a[16])
{
   float f[16];
   for (int i = 0; i < 16; i++)
      f[i] = (float)dfxl_value(a[i]);
   return _mm512_loadu_ps(f);
}

static void check32(const char *op, const struct dfx want[16], const struct dfx_stats ev[16],
                    struct dfxf r, struct dfxf_stats st)
{
   float got[16];
   _mm512_storeu_ps(got, r.v);
   const __mmask16 marked = dfxf_trouble(&st);
   for (int i = 0; i < 16; i++) {
      n_checked32++;
      if (marked >> i & 1) {
         n_marked32++;
         CHECK(ev[i].sat || ev[i].flush, "%s (binary32) lane %d: marked without an event", op,
               i);
         continue;
      }
      const struct dfx g = dfxl_fields((double)got[i]);
      uint32_t bits;
      memcpy(&bits, &got[i], sizeof(bits));
      CHECK(same(g, want[i]) && bits != 0x80000000u,
            "%s (binary32) lane %d: got (%u,%u,%u) %a want (%u,%u,%u)", op, i, g.s, g.l, g.m,
            (double)got[i], want[i].s, want[i].l, want[i].m);
      CHECK(!ev[i].sat && !ev[i].flush, "%s (binary32) lane %d: an event not marked", op, i);
   }
}

#define WAY32(name, scalar, lanes)                                                            \
   do {                                                                                      \
      struct dfx want[16];                                                                   \
      struct dfx_stats ev[16];                                                               \
      for (int i = 0; i < 16; i++) {                                                         \
         struct dfx_stats wl = { 0, 0 };                                                     \
         want[i] = scalar;                                                                   \
         ev[i] = wl;                                                                         \
      }                                                                                      \
      struct dfxf_stats st = dfxf_stats_init();                                              \
      const struct dfxf r = lanes;                                                           \
      check32(name, want, ev, r, st);                                                        \
   } while (0)

/* dfxf_from_fixed on test_from_fixed's numerators: besides the lanes with
 * an event, it may mark those from 2^52 on, as the binary64 lanes do. */
static void test_from_fixed32(void)
{
   int64_t v[16];
   struct dfx want[16];
   struct dfx_stats ev[16];
   const int k = 1 + (int)(rnd() % 60);
   const struct fx_format fx = { 0, (uint8_t)k };
   for (int i = 0; i < 16; i++) {
      v[i] = rnd_numerator();
      struct dfx_stats wl = { 0, 0 };
      want[i] = dfx_from_fixed_i(F, fx, v[i], &wl);
      ev[i] = wl;
   }
   struct dfxf_stats st = dfxf_stats_init();
   const struct dfxf r = dfxf_from_fixed(_mm512_loadu_si512(v), _mm512_loadu_si512(v + 8), k, &st);
   float got[16];
   _mm512_storeu_ps(got, r.v);
   const __mmask16 marked = dfxf_trouble(&st);
   for (int i = 0; i < 16; i++) {
      const bool beyond = v[i] >= (int64_t)1 << 52 || v[i] <= -((int64_t)1 << 52);
      n_checked32++;
      if (marked >> i & 1) {
         n_marked32++;
         CHECK(ev[i].sat || ev[i].flush || beyond,
               "from_fixed (binary32) lane %d: %lld marked without an event", i, (long long)v[i]);
         continue;
      }
      const struct dfx g = dfxl_fields((double)got[i]);
      uint32_t bits;
      memcpy(&bits, &got[i], sizeof(bits));
      CHECK(same(g, want[i]) && bits != 0x80000000u,
            "from_fixed (binary32) lane %d: %lld, k %d: got (%u,%u,%u) %a want (%u,%u,%u)", i,
            (long long)v[i], k, g.s, g.l, g.m, (double)got[i], want[i].s, want[i].l, want[i].m);
      CHECK(!ev[i].sat && !ev[i].flush, "from_fixed (binary32) lane %d: an event not marked",
            i);
   }
}

static void test_binary32(void)
{
   struct dfx a[16], b[16], bs[16], v0[16], d1[16], p[16], d2[16];
   const bool same_signs = rnd() & 1;
   for (int i = 0; i < 16; i++) {
      a[i] = rnd_dfx();
      b[i] = rnd_near(a[i]);
      bs[i] = b[i];
      bs[i].s = a[i].s;
      v0[i] = rnd_dfx();
      d1[i] = rnd_near(v0[i]);
      p[i] = rnd_dfx();
      d2[i] = rnd_near(d1[i]);
      if (same_signs) {
         v0[i].s = a[i].s = p[i].s = d1[i].s = d2[i].s = 0;
         if (!v0[i].m)
            v0[i] = rnd_between(-32, 32, 0);
      }
   }
   const struct dfxf A = { load32(a) }, B = { load32(b) }, BS = { load32(bs) },
                     V0 = { load32(v0) }, D1 = { load32(d1) }, P = { load32(p) },
                     D2 = { load32(d2) };
   WAY32("add", dfx_add_i(F, a[i], b[i], &wl), dfxf_add(A, B, &st));
   WAY32("add_terms", dfx_add_i(F, a[i], b[i], &wl), dfxf_add_terms(A, B, &st));
   WAY32("add_terms (same sign)", dfx_add_i(F, a[i], bs[i], &wl), dfxf_add_terms(A, BS, &st));
   WAY32("mul", dfx_mul_i(F, a[i], b[i], &wl), dfxf_mul(A, B, &st));
   WAY32("recip", dfx_recip_i(F, a[i], &wl), dfxf_recip(A, &st));
   /* a term alone keeps no upper bound (the sum it enters does) */
   WAY32("plane sum", plane_i(v0[i], a[i], d1[i], p[i], d2[i], &wl),
         dfxf_add_terms(dfxf_add_terms(V0, dfxf_term(A, D1, &st), &st), dfxf_term(P, D2, &st),
                        &st));
}
#endif

int main(void)
{
#if defined(__AVX512F__)
   __builtin_cpu_init();
   if (!__builtin_cpu_supports("avx512f") || !__builtin_cpu_supports("avx512dq") ||
       !__builtin_cpu_supports("avx512vl") || !__builtin_cpu_supports("avx512bw")) {
      printf("dfx_lanes (%s): this CPU has no AVX-512; the driver takes the AVX2 lanes\n",
             TEST_ISA);
      return 77;
   }
#elif defined(__AVX2__)
   __builtin_cpu_init();
   if (!__builtin_cpu_supports("avx2")) {
      printf("dfx_lanes (%s): this CPU has no AVX2; the driver takes the baseline lanes\n",
             TEST_ISA);
      return 77;
   }
#endif
   for (long n = 0; n < 1500000; n++) {
      test_binary();
      test_from_fixed();
      test_tex_subtractions();
      test_plane_sums();
#if defined(__AVX512F__) && DFXL_N == 8
      test_binary32();
      test_from_fixed32();
#endif
   }
   printf("dfx_lanes (%s): %llu lane results compared with the scalar data paths, "
          "%llu optimistic lanes marked for the careful way\n", TEST_ISA,
          (unsigned long long)n_checked, (unsigned long long)n_marked);
   CHECK(n_marked > 100000, "too few range events to test the optimistic way");
#if defined(__AVX512F__) && DFXL_N == 8
   printf("dfx_lanes (%s): %llu binary32 lane results compared, %llu marked for the binary64 "
          "lanes\n", TEST_ISA, (unsigned long long)n_checked32, (unsigned long long)n_marked32);
   CHECK(n_marked32 > 100000, "too few range events to test the binary32 lanes");
#endif
   return t_summary("dfx_lanes");
}
