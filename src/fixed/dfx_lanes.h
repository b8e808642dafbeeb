/*
 * The dfx24 data paths of dfx_ops.h (W = 19, the seed's width) on four
 * lanes at once, or eight (DFXL_N, set by the includer: a quad of pixels,
 * or two quads side by side where the instruction set has 512-bit
 * vectors): the perspective division and the texture unit work on whole
 * quads, and each lane is the scalar data path, operation for operation.  The scalar functions stay the reference (FIXPIPE_DEBUG=scalar
 * selects them); tests/unit/test_dfx_lanes.c holds every function here to
 * its scalar twin bit for bit, range events included, on millions of
 * random operands.
 *
 * Written with GCC's vector extensions: a branch of the scalar code becomes
 * a lane mask and a select.  Its users are compiled once per instruction
 * set (AVX2, and the baseline's SSE2), and the driver picks the set at run
 * time (src/rast/host/lanes.c).
 *
 * A register on a lane is its value, held exactly in a double (below): the
 * fields of struct dfx are a function of the value, so the data paths keep
 * the value and find the fields (the digit L, the mantissa's grid) where
 * they decide something.  docs/datapath.md argues each step's exactness.
 * Range events are counted per lane and summed once per quad, so the
 * totals are the scalar path's.
 */
#ifndef FIXPIPE_DFX_LANES_H
#define FIXPIPE_DFX_LANES_H

#include <stdint.h>
#include <string.h>
#include "fixed/dfx_ops.h"
#ifdef __AVX__
#include <immintrin.h>
#endif

#ifndef DFXL_N
#define DFXL_N 4
#endif
_Static_assert(DFXL_N == 4 || DFXL_N == 8, "a quad, or two");

/* The instructions that say one operation in one, where the lanes fill
 * the set's vector; the plain expressions otherwise. */
#if defined(__AVX512F__) && defined(__AVX512DQ__) && DFXL_N == 8
#define DFXL_AVX512 1
#elif defined(__AVX__) && DFXL_N == 4
#define DFXL_AVX 1
#endif

/* Every function here is inline: no vector crosses a call, so the
 * baseline build's warning about the AVX calling convention is moot. */
#pragma GCC diagnostic ignored "-Wpsabi"

typedef int64_t dfxl_i __attribute__((vector_size(8 * DFXL_N)));
typedef uint64_t dfxl_u __attribute__((vector_size(8 * DFXL_N)));
typedef double dfxl_d __attribute__((vector_size(8 * DFXL_N)));

#define DFXL_INLINE static inline __attribute__((always_inline))
#define DFXL_W 19

struct dfxl {
   dfxl_d v;            /* the register's value, exactly (below) */
};

/* Range events per lane.  With `optimistic` (a constant in each user, so
 * the compiler keeps one of the two ways), the data paths leave out the
 * saturation and flush of their results and only keep, per lane, the
 * largest magnitude any operation produced and the smallest nonzero one:
 * range events are rare, so a quad computes this way and, if those bounds
 * show an event in some lane (dfxl_trouble), again with every event
 * handled and counted.  Where no lane is marked the results are the same
 * bits: an operation without a range event is the plain truncation.  Two
 * bounds cost two instructions per operation where a mask of the events
 * would cost seven. */
struct dfxl_stats {
   dfxl_i sat, flush;
   dfxl_d hi, lo;       /* optimistic: max |x|; min over nonzero x of |x| one step down */
   bool optimistic;
};

#define DFXL_STATS(opt)                                                                      \
   ((struct dfxl_stats){ dfxl_splat(0), dfxl_splat(0), dfxl_splatd(0),                        \
                         dfxl_splatd(__builtin_inf()), (opt) })

/* Whether some lane is marked. */
DFXL_INLINE bool dfxl_any(dfxl_i m)
{
#if defined(DFXL_AVX512)
   return _mm512_movepi64_mask((__m512i)m) != 0;    /* a mask lane is all ones or zeros */
#elif defined(DFXL_AVX)
   return _mm256_movemask_pd((__m256d)m) != 0;
#else
   int64_t o = 0;
   for (int i = 0; i < DFXL_N; i++)
      o |= m[i];
   return o != 0;
#endif
}

DFXL_INLINE dfxl_i dfxl_splat(int64_t v)
{
   return (dfxl_i){ 0 } + v;
}

DFXL_INLINE dfxl_d dfxl_splatd(double v)
{
   return (dfxl_d){ 0 } + v;
}

/* mask ? a : b, mask lanes all ones or all zeros (a vector comparison) */
DFXL_INLINE dfxl_i dfxl_sel(dfxl_i mask, dfxl_i a, dfxl_i b)
{
#if defined(__AVX2__) && DFXL_N == 4
   /* one instruction where the expression below is three: blendv reads
    * each lane's sign, and a mask lane is all ones or all zeros */
   return (dfxl_i)_mm256_blendv_pd((__m256d)b, (__m256d)a, (__m256d)mask);
#else
   return (a & mask) | (b & ~mask);      /* one vpternlogq with AVX-512 */
#endif
}

/* Logical shifts by per-lane counts in 0..63 (the fields are never
 * negative, and a logical shift is one instruction where an arithmetic
 * 64-bit one is not). */
DFXL_INLINE dfxl_i dfxl_shr(dfxl_i a, dfxl_i n)
{
   return (dfxl_i)((dfxl_u)a >> (dfxl_u)n);
}

DFXL_INLINE dfxl_i dfxl_shl(dfxl_i a, dfxl_i n)
{
   return (dfxl_i)((dfxl_u)a << (dfxl_u)n);
}

/* Exact conversions between integers in [0, 2^52) and doubles. */
#define DFXL_MAGIC 0x4330000000000000LL   /* the bits of 2^52 */
DFXL_INLINE dfxl_d dfxl_to_d(dfxl_i a)
{
   return (dfxl_d)(a | dfxl_splat(DFXL_MAGIC)) - 0x1p52;
}

/* bitlen of any a >= 0 (below 2^63): a priority encoder in six steps. */
DFXL_INLINE dfxl_i dfxl_bitlen64(dfxl_i a)
{
   dfxl_i n = dfxl_splat(0);
   for (int b = 32; b >= 1; b >>= 1) {
      const dfxl_i hi = dfxl_shr(a, dfxl_splat(b)) != 0;
      n += hi & b;
      a = dfxl_sel(hi, dfxl_shr(a, dfxl_splat(b)), a);
   }
   return n - (a != 0);
}

/* ---- The register on a lane: its value, exactly, in a double ----
 *
 * Every dfx24 value is ±M·2^(4L-47) with M below 2^19: a double holds it
 * exactly, and so it holds the exact sum of two aligned operands and the
 * exact 38-bit product of two mantissas.  The data paths then reduce to one
 * step, the one the scalar code spells out in fields: truncate an exact
 * value toward zero to the grid of its leading digit, 2^(4L-47) for the
 * digit L holding its leading one, and check L against 0..15.  Zero is +0.
 */

DFXL_INLINE dfxl_d dfxl_pow2(dfxl_i e)        /* 2^e, e in -1022..1023 */
{
   return (dfxl_d)dfxl_shl(e + 1023, dfxl_splat(52));
}


DFXL_INLINE dfxl_d dfxl_abs(dfxl_d x)
{
   return (dfxl_d)((dfxl_i)x & dfxl_splat(INT64_MAX));
}

DFXL_INLINE dfxl_d dfxl_seld(dfxl_i mask, dfxl_d a, dfxl_d b)
{
   return (dfxl_d)dfxl_sel(mask, (dfxl_i)a, (dfxl_i)b);
}

#define DFXL_MAX_MAG (((1 << DFXL_W) - 1) * 0x1p13)   /* M = 2^W - 1 at L = 15 */

DFXL_INLINE dfxl_i dfxl_exponent(dfxl_d x)        /* biased: p + 1023 */
{
   return dfxl_shr((dfxl_i)x, dfxl_splat(52)) & 0x7ff;
}

/* x truncated toward zero to multiples of 2^g, g at most x's exponent - 3:
 * a double's sign and magnitude are apart, so truncating its magnitude is
 * clearing the fraction bits below 2^g, c = 52 - (p - g) of them. */
DFXL_INLINE dfxl_d dfxl_clear_low(dfxl_d x, dfxl_i c)
{
   return (dfxl_d)((dfxl_i)x & dfxl_shl(dfxl_splat(-1), c));
}

/* a < b ? a : b and a > b ? a : b per lane: where a is a NaN, b (the
 * instructions' own rule). */
DFXL_INLINE dfxl_d dfxl_mind(dfxl_d a, dfxl_d b)
{
#if defined(DFXL_AVX512)
   return (dfxl_d)_mm512_min_pd((__m512d)a, (__m512d)b);
#elif defined(DFXL_AVX)
   return (dfxl_d)_mm256_min_pd((__m256d)a, (__m256d)b);
#else
   return dfxl_seld(a < b, a, b);
#endif
}

DFXL_INLINE dfxl_d dfxl_maxd(dfxl_d a, dfxl_d b)
{
#if defined(DFXL_AVX512)
   return (dfxl_d)_mm512_max_pd((__m512d)a, (__m512d)b);
#elif defined(DFXL_AVX)
   return (dfxl_d)_mm256_max_pd((__m256d)a, (__m256d)b);
#else
   return dfxl_seld(a > b, a, b);
#endif
}

/* The lanes of an optimistic way that had a range event: some result at or
 * above 2^32 (L > 15), or a nonzero one below 2^-32 (L < 0).  `lo` holds
 * the magnitudes' bits less one (dfxl_round), so its threshold is 2^-32's
 * bits less one. */
DFXL_INLINE dfxl_i dfxl_trouble(const struct dfxl_stats *st)
{
   const double lo_t = 0x1.fffffffffffffp-33;   /* the double below 2^-32 */
   return (st->hi >= 0x1p32) | (st->lo < lo_t);
}

/* `from`'s bounds into `st` where `m` (optimistic), its counts where `m`. */
DFXL_INLINE void dfxl_merge_where(struct dfxl_stats *st, const struct dfxl_stats *from, dfxl_i m)
{
   st->sat += from->sat & m;
   st->flush += from->flush & m;
   if (st->optimistic) {
      const dfxl_d h = dfxl_seld(m, from->hi, dfxl_splatd(0));
      const dfxl_d l = dfxl_seld(m, from->lo, dfxl_splatd(__builtin_inf()));
      st->hi = dfxl_maxd(h, st->hi);
      st->lo = dfxl_mind(l, st->lo);
   }
}

/* x truncated to its digit's grid: the bits below it cleared, a mask
 * that depends on the biased exponent e mod 4 only.  With 512-bit
 * vectors, a table of the masks indexed by e mod 8 (the permutation reads
 * the low three bits of each index, and the sign above e leaves those
 * alone): one shift and one permutation where the count is four
 * operations and a variable shift. */
#define DFXL_GRID_MASK(e) ((int64_t)(~UINT64_C(0) << (37 - (((e) + 1) & 3))))
DFXL_INLINE dfxl_d dfxl_to_grid(dfxl_d x)
{
#if defined(DFXL_AVX512)
   const __m512i masks = _mm512_set_epi64(DFXL_GRID_MASK(7), DFXL_GRID_MASK(6),
                                          DFXL_GRID_MASK(5), DFXL_GRID_MASK(4),
                                          DFXL_GRID_MASK(3), DFXL_GRID_MASK(2),
                                          DFXL_GRID_MASK(1), DFXL_GRID_MASK(0));
   const dfxl_i e = dfxl_shr((dfxl_i)x, dfxl_splat(52));
   return (dfxl_d)((dfxl_i)x & (dfxl_i)_mm512_permutexvar_epi64((__m512i)e, masks));
#elif defined(__AVX2__) && DFXL_N == 4
   /* The mask clears 34 to 37 bits: the low half of each lane whole, and
    * 2 to 5 bits of the high half.  The high half shifted right by 20
    * holds e in its low bits, and a permutation within each 128-bit lane
    * reads an element of the table by an index's low two bits: the high
    * half's mask by e mod 4, four instructions where the count is six. */
#define DFXL_GRID_HMASK(e) ((int)(DFXL_GRID_MASK(e) >> 32))
   const __m256 hmasks = (__m256)_mm256_setr_epi32(
      DFXL_GRID_HMASK(0), DFXL_GRID_HMASK(1), DFXL_GRID_HMASK(2), DFXL_GRID_HMASK(3),
      DFXL_GRID_HMASK(0), DFXL_GRID_HMASK(1), DFXL_GRID_HMASK(2), DFXL_GRID_HMASK(3));
#undef DFXL_GRID_HMASK
   const __m256i idx = _mm256_srli_epi32((__m256i)x, 20);
   const __m256i m = (__m256i)_mm256_permutevar_ps(hmasks, idx);
   return (dfxl_d)_mm256_blend_epi32(_mm256_and_si256((__m256i)x, m), _mm256_setzero_si256(),
                                     0x55);
#else
   return dfxl_clear_low(x, 37 - ((dfxl_shr((dfxl_i)x, dfxl_splat(52)) + 1) & 3));
#endif
}
#undef DFXL_GRID_MASK

/* The optimistic way's rounding: the plain truncation, and the bounds
 * asked for (both, except in a plane's sum: dfxl_add_terms). */
DFXL_INLINE struct dfxl dfxl_round_optimistic(dfxl_d x, struct dfxl_stats *st, bool hi, bool lo)
{
   const dfxl_d ax = dfxl_abs(x);
   if (hi)
      st->hi = dfxl_maxd(ax, st->hi);
   if (lo)
      st->lo = dfxl_mind((dfxl_d)((dfxl_i)ax - 1), st->lo);
   struct dfxl o = { dfxl_to_grid(x) };
   return o;
}

/* dfx_finish_i after the data path: the exact result x truncated toward
 * zero to its digit's grid; above L = 15 the largest magnitude, below
 * L = 0 zero, both counted.  An exact zero is +0.
 *
 * With x's leading one at 2^p, L = floor((p + 32) / 4) and the grid is
 * 2^(4L - 47), so p - g = ((p + 32) mod 4) + 15: the mantissa keeps 16 to
 * 19 bits, and with the biased exponent e = p + 1023 the bits to clear are
 * 37 - ((e + 1) mod 4) (the sign above e's eleven bits leaves that alone).
 * L > 15 is |x| >= 2^32, L < 0 is |x| < 2^-32.
 *
 * The optimistic way keeps the bounds: the largest |x|, and the smallest
 * |x| less one step of its bits, where zero becomes a NaN, which
 * dfxl_mind passes over.  It takes x's zero as it is: only a product is
 * ever -0 (dfxl_mul makes it +0). */
DFXL_INLINE struct dfxl dfxl_round(dfxl_d x, struct dfxl_stats *st)
{
   if (st->optimistic)
      return dfxl_round_optimistic(x, st, true, true);
   const dfxl_d ax = dfxl_abs(x);
   const dfxl_i nz = ax != 0;
   const dfxl_i sat = ax >= 0x1p32, flush = nz & (ax < 0x1p-32);
   st->sat -= sat;
   st->flush -= flush;
   dfxl_d r = dfxl_to_grid(x);
   const dfxl_d big = (dfxl_d)((dfxl_i)dfxl_splatd(DFXL_MAX_MAG) |
                               ((dfxl_i)x & dfxl_splat(INT64_MIN)));
   r = dfxl_seld(sat, big, r);
   struct dfxl o = { (dfxl_d)((dfxl_i)r & nz & ~flush) };
   return o;
}

/* dfx_from_fixed_i: v * 2^-k to nearest, ties away from zero.
 *
 * Careful: an integer up to 2^63 does not fit a double, so this way works
 * on the fields.  Optimistic: below 2^52 (every numerator of a primitive
 * in the 12.12 screen) v is a double exactly, and so is v * 2^-k; half a
 * step of its digit's grid added to its magnitude, truncated, is the
 * nearest with ties away from zero (dfxl_from_int), and the sum is exact:
 * the magnitude has at most 52 significant bits, so even with a carry into
 * the next power of two the bits down to the half step fit 53.  Larger v
 * mark the lane (a quad the careful way recomputes). */
/* 2^(g) for the grid g of a nonzero value's digit: g = p - 15 - ((e + 1) mod 4). */
DFXL_INLINE dfxl_d dfxl_grid(dfxl_d x)
{
   const dfxl_i e = dfxl_exponent(x);
   return (dfxl_d)dfxl_shl(e - 15 - ((e + 1) & 3), dfxl_splat(52));
}

DFXL_INLINE struct dfxl dfxl_from_fixed(dfxl_i v, int k, struct dfxl_stats *st)
{
   const dfxl_i neg = v < 0;
   const dfxl_i n = dfxl_sel(neg, -v, v);
   if (st->optimistic) {
      const dfxl_i big = dfxl_shr(n, dfxl_splat(52)) != 0;     /* -INT64_MIN too */
      st->hi = dfxl_seld(big, dfxl_splatd(0x1p32), st->hi);
      const dfxl_d ax = dfxl_to_d(n & dfxl_splat(((int64_t)1 << 52) - 1)) * fx_pow2(-k);
      const dfxl_d up = ax + (dfxl_d)((dfxl_i)(dfxl_grid(ax) * 0.5) & (ax != 0));
      return dfxl_round((dfxl_d)((dfxl_i)up | dfxl_shl(neg & 1, dfxl_splat(63))), st);
   }
   /* L = floor((bitlen - 1 - k + 32) / 4), biased to stay non-negative */
   const dfxl_i l = dfxl_shr(dfxl_bitlen64(n) - 1 - k + 32 + 64, dfxl_splat(2)) - 16;
   const dfxl_i sh = 4 * l - 47 + k;           /* bits of n to drop */
   const dfxl_i up = sh <= 0;
   dfxl_i m = dfxl_sel(up, dfxl_shl(n, dfxl_sel(up, -sh, dfxl_splat(0))),
                       dfxl_shr(n, dfxl_sel(up, dfxl_splat(0), sh)));
   m += dfxl_shr(n, dfxl_sel(up, dfxl_splat(0), sh - 1)) & ~up & 1;
   /* a carry into the next digit is one more digit of the same value:
    * the value below is exact either way, and dfxl_round finds its digit */
   const dfxl_i lc = dfxl_sel(l < -20, dfxl_splat(-20), dfxl_sel(l > 40, dfxl_splat(40), l));
   dfxl_d x = dfxl_to_d(m) * dfxl_pow2(4 * lc - 47);
   x = (dfxl_d)((dfxl_i)x | dfxl_shl(neg & 1, dfxl_splat(63)));
   return dfxl_round(x, st);
}

/* dfx_add_i: order by magnitude; the smaller truncated to the larger's
 * grid with one guard digit (the 5-way aligner; 5 digits or more leave
 * nothing of it); the exact sum; truncated to its own digit's grid.
 *
 * With D = (e_hi + 1) & ~3 = 4 L_hi + 992: the smaller is 5 digits below
 * or more (L_lo <= L_hi - 5) exactly when |lo| < 2^(4 L_hi - 48), a power
 * of two with the biased exponent D - 17 (zero is below it too); else the
 * bits of lo below the guard digit's grid 2^(4 L_hi - 51) are
 * 32 - e_lo + D, 30 to 49 of them.  Where lo is dropped the sum is hi,
 * which the truncation leaves as it is, without an event. */
DFXL_INLINE struct dfxl dfxl_add(struct dfxl a, struct dfxl b, struct dfxl_stats *st)
{
   const dfxl_d aa = dfxl_abs(a.v), ab = dfxl_abs(b.v);
   const dfxl_i swap = ab > aa;
   const dfxl_d hi = dfxl_seld(swap, b.v, a.v), lo = dfxl_seld(swap, a.v, b.v);
   const dfxl_d alo = dfxl_seld(swap, aa, ab);
   const dfxl_i d = (dfxl_shr((dfxl_i)dfxl_seld(swap, ab, aa), dfxl_splat(52)) + 1) & ~3;
   const dfxl_i keep = alo < (dfxl_d)dfxl_shl(d - 17, dfxl_splat(52));
   const dfxl_i c = (32 - dfxl_shr((dfxl_i)alo, dfxl_splat(52)) + d) & ~keep;
   const dfxl_d lo_al = (dfxl_d)((dfxl_i)dfxl_clear_low(lo, c) & ~keep);
   return dfxl_round(hi + lo_al, st);
}

/* dfxl_add where the operands have the same sign: the exact sum truncated,
 * without the aligner.  The aligner's truncation of the smaller operand
 * cannot matter then: the larger, hi, lies on its digit's grid G, the sum
 * on a grid G' >= G (its magnitude is at least hi's), and the smaller is
 * cut to g = G/16, so hi + cut(lo) is a multiple of g and the bits cut, less
 * than g, cannot carry it across a multiple of G'.  Where the aligner drops
 * lo (below G/2), |hi| + |lo| stays below the next multiple of G in hi's
 * digit, so the sum truncates to hi.  The double sum is exact where lo is
 * kept (at most 35 bits apart); where it is dropped, rounding the double
 * stays below |hi| + G.  Registers are never -0 (dfxl_round), so a zero
 * operand's sign is +. */
DFXL_INLINE struct dfxl dfxl_add_same_sign(struct dfxl a, struct dfxl b, struct dfxl_stats *st)
{
   return dfxl_round(a.v + b.v, st);
}

/* A plane's sum v0 + a·Δ1 + b·Δ2 with one bound an operation where the
 * optimistic way keeps two.  A sum of operands of the same sign is at least
 * as large as either (in the double too: rounding is monotonic), so:
 * - a term's upper bound is its sum's: a product at or above 2^32 (whose
 *   truncation is too: 2^32 lies on every grid up there) makes the sum
 *   reach 2^32, and dfxl_term leaves the upper bound to the sum;
 * - a nonzero sum of operands that are 0 or at least 2^-32 is at least
 *   2^-32, so the sum keeps no lower bound; an operand below it has
 *   marked its lane already (a product's own lower bound; v0 is a
 *   primitive's register, checked when it was set up).
 * Where the signs differ (the aligner's way, which can cancel) the sum
 * takes its operands' upper bounds itself, then rounds as dfxl_add.  The
 * careful way is every operation's own, unchanged. */
DFXL_INLINE struct dfxl dfxl_round_bound(dfxl_d x, struct dfxl_stats *st, bool hi, bool lo)
{
   return st->optimistic ? dfxl_round_optimistic(x, st, hi, lo) : dfxl_round(x, st);
}

/* dfxl_mul, as a term of dfxl_add_terms: its upper bound is the sum's. */
DFXL_INLINE struct dfxl dfxl_term(struct dfxl a, struct dfxl b, struct dfxl_stats *st)
{
   return dfxl_round_bound(a.v * b.v + 0.0, st, false, true);
}

/* dfxl_add of a register or sum and a dfxl_term, without the aligner where
 * every lane's operands have the same sign bit: a plane's terms have the
 * signs of its vertex values and differences over a primitive, so the
 * branch is predicted. */
DFXL_INLINE struct dfxl dfxl_add_terms(struct dfxl a, struct dfxl b, struct dfxl_stats *st)
{
   const dfxl_i differ = ((dfxl_i)a.v ^ (dfxl_i)b.v) < 0;
   if (__builtin_expect(!dfxl_any(differ), 1))
      return dfxl_round_bound(a.v + b.v, st, true, false);
   if (st->optimistic)
      st->hi = dfxl_maxd(dfxl_maxd(dfxl_abs(a.v), dfxl_abs(b.v)), st->hi);
   return dfxl_add(a, b, st);
}

/* Whether every lane of a mask is set. */
DFXL_INLINE bool dfxl_all(dfxl_i m)
{
   return !dfxl_any(~m);
}

DFXL_INLINE struct dfxl dfxl_neg(struct dfxl a)
{
   a.v = dfxl_seld(a.v == 0, a.v, -a.v);
   return a;
}

DFXL_INLINE struct dfxl dfxl_sub(struct dfxl a, struct dfxl b, struct dfxl_stats *st)
{
   return dfxl_add(a, dfxl_neg(b), st);
}

/* dfx_mul_i (Fig. 9): the exact product truncated to W bits. */
DFXL_INLINE struct dfxl dfxl_mul(struct dfxl a, struct dfxl b, struct dfxl_stats *st)
{
   return dfxl_round(a.v * b.v + 0.0, st);      /* a zero product is +0 */
}

/* dfx_recip_i: the truncated reciprocal.  The double quotient 1/v is
 * within 2^-53 of the exact one, which is at least 2^-19 of its grid step
 * away from the next grid point unless it lies on one (M divides the
 * power of two): truncating the double gives the exact truncation.  1/0
 * saturates to the largest positive value. */
DFXL_INLINE struct dfxl dfxl_recip(struct dfxl a, struct dfxl_stats *st)
{
   const dfxl_i zero = a.v == 0;
   const dfxl_d one = dfxl_splatd(1);
   struct dfxl r = dfxl_round(one / dfxl_seld(zero, one, a.v), st);
   st->sat -= zero;
   r.v = dfxl_seld(zero, dfxl_splatd(DFXL_MAX_MAG), r.v);
   return r;
}

/* dfx_to_double_i, then binary32 (exact: W bits in binary32's range). */
DFXL_INLINE void dfxl_to_float(struct dfxl a, float out[DFXL_N])
{
   typedef float v4f __attribute__((vector_size(4 * DFXL_N)));
   const v4f f = __builtin_convertvector(a.v, v4f);
   memcpy(out, &f, sizeof(f));
}

/* Between struct dfx and lanes. */
DFXL_INLINE double dfxl_value(struct dfx a)
{
   return a.m ? dfx_to_double_i((struct dfx_format){ DFXL_W }, a) : 0.0;
}

DFXL_INLINE struct dfxl dfxl_load(const struct dfx a[DFXL_N])
{
   struct dfxl r;
   for (int i = 0; i < DFXL_N; i++)
      r.v[i] = dfxl_value(a[i]);
   return r;
}

/* The fields of a value (tests, the scalar fall-backs). */
DFXL_INLINE struct dfx dfxl_fields(double v)
{
   uint64_t b;
   memcpy(&b, &v, sizeof(b));
   const int e = (int)((b >> 52) & 0x7ff);      /* biased; a value is never subnormal */
   if (!e)
      return dfx_zero();
   /* as dfxl_round: L = (e + 1) / 4 - 248, M = the 53-bit mantissa's top
    * 16 + (e + 1) mod 4 bits */
   const uint64_t mant = (b & ((UINT64_C(1) << 52) - 1)) | (UINT64_C(1) << 52);
   struct dfx r = { (uint8_t)(b >> 63), (uint8_t)(((e + 1) >> 2) - 248),
                    (uint32_t)(mant >> (37 - ((e + 1) & 3))) };
   return r;
}

DFXL_INLINE void dfxl_store(struct dfxl a, struct dfx out[DFXL_N])
{
   for (int i = 0; i < DFXL_N; i++)
      out[i] = dfxl_fields(a.v[i]);
}

/* ---- What the texture unit adds: floor, the integer input, the coordinate
 *      input, comparisons (tex_fast.h's scalar operations) ---- */

/* floor(x) for |x| < 2^51: to nearest by the 2^52 trick, then down; one
 * rounding instruction where the processor has it.  floor(-0) is +0 either
 * way (the trick's sum is +0; + 0.0 makes the instruction's -0 one). */
DFXL_INLINE dfxl_d dfxl_floor(dfxl_d x)
{
#if defined(DFXL_AVX512)
   return (dfxl_d)_mm512_roundscale_pd((__m512d)x, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC) +
          0.0;
#elif defined(DFXL_AVX)
   return (dfxl_d)_mm256_round_pd((__m256d)x, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC) + 0.0;
#else
   const dfxl_d M =
      (dfxl_d)(((dfxl_i)x & dfxl_splat(INT64_MIN)) | (dfxl_i)dfxl_splatd(0x1p52));
   const dfxl_d r = (x + M) - M;
   return dfxl_seld(r > x, r - 1, r);
#endif
}

/* dfx_from_fixed_i of an integer (k = 0) that a double holds: to nearest,
 * ties away from zero, on the grid of its digit (half a step added to the
 * magnitude, then truncated; a carry into the next digit lands on a power
 * of two, which every coarser grid holds). */
DFXL_INLINE struct dfxl dfxl_from_int(dfxl_d x, struct dfxl_stats *st)
{
   const dfxl_d ax = dfxl_abs(x);
   const dfxl_d h = dfxl_grid(ax) * 0.5;
   const dfxl_d up = ax + dfxl_seld(ax == 0, dfxl_splatd(0), h);
   const dfxl_d sgn = (dfxl_d)((dfxl_i)x & dfxl_splat(INT64_MIN));
   return dfxl_round((dfxl_d)((dfxl_i)up | (dfxl_i)sgn), st);
}

/* The linear filter's texel offset, 1/2 - 2^-9 (tex_bind.c), taken from a
 * coordinate scaled to texels, s - k, where the difference needs no
 * aligner (dfxl_sub_texel_offset_direct): where s <= 0 the operands have
 * the same sign (dfxl_add_same_sign); where 1/2 > s >= 2^-8, k's digit
 * L = 7 puts the guard digit's grid at 2^-23, and s, with L >= 6, lies on
 * it and is too large to drop; where 2^12 > s >= 1/2, s's digit L <= 10
 * puts the guard grid at 2^-11 or finer, which holds k's 2^-9 bits whole.
 * Either way the exact difference, truncated, is the adder's. */
#define DFXL_TEXEL_OFFSET (0.5 - 0x1p-9)
DFXL_INLINE bool dfxl_sub_texel_offset_direct(dfxl_d s)
{
   return dfxl_all((s <= 0) | ((s >= 0x1p-8) & (s < 0x1p12)));
}

DFXL_INLINE struct dfxl dfxl_sub_texel_offset(struct dfxl s, struct dfxl_stats *st)
{
   return dfxl_round(s.v - DFXL_TEXEL_OFFSET, st);
}

/* c less the register of its floor n, for 0 <= c < 2^16
 * (dfxl_sub_floor_direct), as the wrap modes' fraction takes it: n is below
 * 2^16, so exact in binary32 and in the register (dfxl_from_int leaves
 * it); c has digit L <= 11, so the guard digit's grid (2^-7 or finer)
 * holds n whole, and a nonzero n is too large to drop: the exact
 * difference, truncated (+ 0.0: a zero difference is +0, as the adder's). */
DFXL_INLINE bool dfxl_sub_floor_direct(dfxl_d c)
{
   return dfxl_all((c >= 0) & (c < 0x1p16));
}

DFXL_INLINE struct dfxl dfxl_sub_floor(struct dfxl c, dfxl_d n, struct dfxl_stats *st)
{
   return dfxl_round(c.v - n + 0.0, st);
}

DFXL_INLINE void dfxl_stats_add(struct dfx_stats *to, struct dfxl_stats st)
{
   for (int i = 0; i < DFXL_N; i++) {
      to->sat += (uint64_t)st.sat[i];
      to->flush += (uint64_t)st.flush[i];
   }
}

#endif
