/*
 * dfx24 (W = 19) on sixteen binary32 lanes: four quads in one 512-bit
 * vector where dfx_lanes.h's binary64 lanes hold two.  Only the optimistic
 * way (dfx_lanes.h): a lane with a range event, or a reciprocal of zero,
 * marks the vector, and the caller computes it again on the binary64
 * lanes, which handle and count every event.  Each lane is dfx_lanes.h's
 * operation in its order; tests/unit/test_dfx_lanes.c holds each operation
 * here to the scalar data path bit for bit on millions of random operands,
 * and test_persp_fast the division built on them.
 *
 * Why binary32 holds it.  A register's value ±M·2^(4L-47), M below 2^19,
 * L in 0..15, is a binary32 exactly (24-bit significand, normal from
 * 2^-126).  The binary64 lanes get each result from the exact value (or
 * one within 2^-53 of it) truncated to its digit's grid.  binary32 cannot
 * hold a 38-bit product, but AVX-512 rounds an operation toward zero when
 * told to ({rz-sae}): the exact result truncated to 24 significant bits.
 * Truncating that again to the digit's grid (16 to 19 significant bits,
 * the same leading one: truncating a magnitude never crosses the power of
 * two below it) is truncating the exact result to that grid, which is
 * the data path's result.  So products and reciprocals are one
 * instruction each, as on the binary64 lanes.  The adder's aligned sum
 * (dfxl_add: the larger operand on its grid 2^(4L-47) or coarser, the
 * smaller cut to the guard digit's grid 2^(4L-51)) spans at most the 24
 * bits from 2^(4L-28) down, so binary32 holds it exactly.  The bounds of
 * the optimistic way read the truncated result: it reaches 2^32 exactly
 * when the exact one does, and a nonzero one stays nonzero and on the same
 * side of 2^-32.
 *
 * Only for the 512-bit set (the rounding toward zero is written into the
 * instruction; elsewhere it would need the MXCSR).
 */
#ifndef FIXPIPE_DFX_LANES32_H
#define FIXPIPE_DFX_LANES32_H

#if !defined(__AVX512F__) || !defined(__AVX512DQ__)
#error "dfx_lanes32.h needs AVX-512F and DQ"
#endif

#include <immintrin.h>
#include <stdbool.h>

#define DFXF_INLINE static inline __attribute__((always_inline))
#define DFXF_RZ (_MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC)

struct dfxf {
   __m512 v;            /* the register's value, exactly */
};

/* The optimistic way's bounds per lane (dfxl_stats): the largest |x| and
 * the smallest nonzero |x| one step of its bits down. */
struct dfxf_stats {
   __m512 hi, lo;
};

DFXF_INLINE struct dfxf_stats dfxf_stats_init(void)
{
   return (struct dfxf_stats){ _mm512_setzero_ps(), _mm512_set1_ps(__builtin_inff()) };
}

DFXF_INLINE struct dfxf dfxf_splat(float v)
{
   return (struct dfxf){ _mm512_set1_ps(v) };
}

DFXF_INLINE __m512 dfxf_abs(__m512 x)
{
   return _mm512_castsi512_ps(
      _mm512_and_si512(_mm512_castps_si512(x), _mm512_set1_epi32(INT32_MAX)));
}

/* Some result at or above 2^32 (L > 15) or nonzero below 2^-32 (L < 0);
 * `lo` holds the magnitudes' bits less one, so its threshold is the
 * binary32 below 2^-32. */
DFXF_INLINE __mmask16 dfxf_trouble(const struct dfxf_stats *st)
{
   return _mm512_cmp_ps_mask(st->hi, _mm512_set1_ps(0x1p32f), _CMP_GE_OQ) |
          _mm512_cmp_ps_mask(st->lo, _mm512_set1_ps(0x1.fffffep-33f), _CMP_LT_OQ);
}

/* x truncated to its digit's grid: with binary32's biased exponent e the
 * digit keeps 16 + (e + 1) mod 4 significant bits, so 8 - (e + 1) mod 4
 * fraction bits go; the mask from a table by e mod 16 (the permutation
 * reads an index's low four bits; the sign above e leaves them alone). */
#define DFXF_GRID_MASK(e) ((int)(~0u << (8 - (((e) + 1) & 3))))
DFXF_INLINE __m512 dfxf_to_grid(__m512 x)
{
   const __m512i masks = _mm512_set_epi32(
      DFXF_GRID_MASK(15), DFXF_GRID_MASK(14), DFXF_GRID_MASK(13), DFXF_GRID_MASK(12),
      DFXF_GRID_MASK(11), DFXF_GRID_MASK(10), DFXF_GRID_MASK(9), DFXF_GRID_MASK(8),
      DFXF_GRID_MASK(7), DFXF_GRID_MASK(6), DFXF_GRID_MASK(5), DFXF_GRID_MASK(4),
      DFXF_GRID_MASK(3), DFXF_GRID_MASK(2), DFXF_GRID_MASK(1), DFXF_GRID_MASK(0));
   const __m512i xi = _mm512_castps_si512(x);
   const __m512i e = _mm512_srli_epi32(xi, 23);
   return _mm512_castsi512_ps(_mm512_and_si512(xi, _mm512_permutexvar_epi32(e, masks)));
}
#undef DFXF_GRID_MASK

/* dfxl_round_optimistic: the truncation, and the bounds asked for.  A
 * zero's bits less one are a NaN, which the minimum passes over (it
 * returns its second operand where either is a NaN). */
DFXF_INLINE struct dfxf dfxf_round(__m512 x, struct dfxf_stats *st, bool hi, bool lo)
{
   const __m512 ax = dfxf_abs(x);
   /* the larger magnitude, its sign cleared: max(|x|, hi) in one operation
    * where |x| is not needed for the lower bound */
   if (hi && !lo)
      st->hi = _mm512_range_ps(x, st->hi, 0x0b);
   else if (hi)
      st->hi = _mm512_max_ps(ax, st->hi);
   if (lo)
      st->lo = _mm512_min_ps(
         _mm512_castsi512_ps(_mm512_sub_epi32(_mm512_castps_si512(ax), _mm512_set1_epi32(1))),
         st->lo);
   return (struct dfxf){ dfxf_to_grid(x) };
}

/* A product's +0 for -0 (a register is never -0): + 0.0 rounds to
 * nearest, where -0 + +0 is +0. */
DFXF_INLINE __m512 dfxf_product(__m512 a, __m512 b)
{
   return _mm512_add_ps(_mm512_mul_round_ps(a, b, DFXF_RZ), _mm512_setzero_ps());
}

/* dfxl_mul */
DFXF_INLINE struct dfxf dfxf_mul(struct dfxf a, struct dfxf b, struct dfxf_stats *st)
{
   return dfxf_round(dfxf_product(a.v, b.v), st, true, true);
}

/* dfxl_term: a product as a term of dfxf_add_terms, which bounds it above.
 * A -0 is left as it is: the sum it enters gives what +0 would (a zero
 * addend of either sign leaves the other operand, and +0 + -0 is +0 when
 * rounding toward zero), through dfxf_add where the signs differ. */
DFXF_INLINE struct dfxf dfxf_term(struct dfxf a, struct dfxf b, struct dfxf_stats *st)
{
   return dfxf_round(_mm512_mul_round_ps(a.v, b.v, DFXF_RZ), st, false, true);
}

/* dfxl_add: order by magnitude; the smaller cut to the guard digit's grid
 * 2^(4 L_hi - 51), or dropped where it is 5 digits down or more; the exact
 * sum, truncated.  With D = (e_hi + 1) & ~3 = 4 L_hi + 96 (binary32's
 * bias 127): the smaller is dropped where |lo| < 2^(4 L_hi - 48), the
 * power of two with biased exponent D - 17, and otherwise loses its bits
 * below the guard grid: 3 - e_lo + D of them, 1 to 20.  Magnitudes compare
 * as their bits (non-negative binary32s order as integers). */
DFXF_INLINE struct dfxf dfxf_add(struct dfxf a, struct dfxf b, struct dfxf_stats *st)
{
   const __m512i aa = _mm512_castps_si512(dfxf_abs(a.v)),
                 ab = _mm512_castps_si512(dfxf_abs(b.v));
   const __mmask16 swap = _mm512_cmpgt_epi32_mask(ab, aa);
   const __m512 hi = _mm512_mask_blend_ps(swap, a.v, b.v),
                lo = _mm512_mask_blend_ps(swap, b.v, a.v);
   const __m512i ahi = _mm512_mask_blend_epi32(swap, aa, ab),
                 alo = _mm512_mask_blend_epi32(swap, ab, aa);
   const __m512i d = _mm512_andnot_si512(
      _mm512_set1_epi32(3), _mm512_add_epi32(_mm512_srli_epi32(ahi, 23), _mm512_set1_epi32(1)));
   const __mmask16 drop = _mm512_cmplt_epi32_mask(
      alo, _mm512_slli_epi32(_mm512_sub_epi32(d, _mm512_set1_epi32(17)), 23));
   const __m512i c = _mm512_sub_epi32(_mm512_add_epi32(d, _mm512_set1_epi32(3)),
                                      _mm512_srli_epi32(alo, 23));
   const __m512i cut = _mm512_maskz_sllv_epi32((__mmask16)~drop, _mm512_set1_epi32(-1), c);
   const __m512 lo_al = _mm512_castsi512_ps(_mm512_and_si512(_mm512_castps_si512(lo), cut));
   return dfxf_round(_mm512_add_round_ps(hi, lo_al, DFXF_RZ), st, true, true);
}

/* dfxl_add_terms: where every lane's operands have the same sign bit the
 * exact sum truncated (dfxl_add_same_sign), bounded above only. */
DFXF_INLINE struct dfxf dfxf_add_terms(struct dfxf a, struct dfxf b, struct dfxf_stats *st)
{
   const __m512i x = _mm512_xor_si512(_mm512_castps_si512(a.v), _mm512_castps_si512(b.v));
   if (__builtin_expect(!_mm512_movepi32_mask(x), 1))
      return dfxf_round(_mm512_add_round_ps(a.v, b.v, DFXF_RZ), st, true, false);
   st->hi = _mm512_max_ps(_mm512_max_ps(dfxf_abs(a.v), dfxf_abs(b.v)), st->hi);
   return dfxf_add(a, b, st);
}

/* dfxl_from_fixed for the sixteen numerators v0 (lanes 0-7) and v1 (8-15),
 * fixed point with k fraction bits: the magnitude rounded half up to its
 * digit's grid (the aligner's rounding), then truncated to the grid of the
 * digit that reached.  The conversion toward zero keeps the numerator's top
 * 24 bits, T; the exact value is T + r with r below T's last bit, and T's
 * half step is a whole number of those bits, so T + half and the exact
 * value + half lie between the same two grid points and in the same
 * binade (a carry into the next power of two truncates to that power
 * either way: the next digit's step is larger than the half step).  The
 * binary64 lanes mark numerators from 2^52 on, where their conversion is
 * not exact; so do these, for the same lanes.  A half step below the
 * binary32 range is left out: such a value is far below 2^-32, and marked. */
DFXF_INLINE struct dfxf dfxf_from_fixed(__m512i v0, __m512i v1, int k, struct dfxf_stats *st)
{
   const __m512 t = _mm512_insertf32x8(
      _mm512_castps256_ps512(_mm512_cvt_roundepi64_ps(v0, DFXF_RZ)),
      _mm512_cvt_roundepi64_ps(v1, DFXF_RZ), 1);
   const __mmask16 big = _mm512_cmp_ps_mask(dfxf_abs(t), _mm512_set1_ps(0x1p52f), _CMP_GE_OQ);
   st->hi = _mm512_mask_blend_ps(big, st->hi, _mm512_set1_ps(__builtin_inff()));
   /* 2^-k exactly: k is 1 to 62 (det·2^-k in [1/2, 1)) */
   const __m512 x = _mm512_mul_ps(t, _mm512_castsi512_ps(_mm512_set1_epi32((127 - k) << 23)));
   const __m512i xi = _mm512_castps_si512(x);
   const __m512i e = _mm512_and_si512(_mm512_srli_epi32(xi, 23), _mm512_set1_epi32(255));
   /* the half step's biased exponent: e - 16 - (e + 1) mod 4 */
   const __m512i he = _mm512_sub_epi32(
      _mm512_sub_epi32(e, _mm512_set1_epi32(16)),
      _mm512_and_si512(_mm512_add_epi32(e, _mm512_set1_epi32(1)), _mm512_set1_epi32(3)));
   const __mmask16 has_half =
      _mm512_cmpgt_epi32_mask(he, _mm512_setzero_si512()) &
      _mm512_cmpneq_epi32_mask(_mm512_andnot_si512(_mm512_set1_epi32(INT32_MIN), xi),
                               _mm512_setzero_si512());
   const __m512i half = _mm512_maskz_or_epi32(
      has_half, _mm512_slli_epi32(he, 23), _mm512_and_si512(xi, _mm512_set1_epi32(INT32_MIN)));
   return dfxf_round(_mm512_add_round_ps(x, _mm512_castsi512_ps(half), DFXF_RZ), st, true, true);
}

/* dfxl_recip: the quotient truncated.  1/0, which saturates and is
 * counted, marks the lane for the binary64 lanes instead. */
DFXF_INLINE struct dfxf dfxf_recip(struct dfxf a, struct dfxf_stats *st)
{
   const __mmask16 zero = _mm512_cmp_ps_mask(a.v, _mm512_setzero_ps(), _CMP_EQ_OQ);
   st->hi = _mm512_mask_blend_ps(zero, st->hi, _mm512_set1_ps(__builtin_inff()));
   const __m512 one = _mm512_set1_ps(1.0f);
   return dfxf_round(_mm512_div_round_ps(one, _mm512_mask_blend_ps(zero, a.v, one), DFXF_RZ),
                     st, true, true);
}

#endif
