/*
 * The 8-bit colour stage of a group of quads (rast_shader.shade_n's, up to
 * RAST_GROUP_MAX = 4) in one vector of sixteen lanes, a pixel a lane:
 * c8_lanes.h's four-lane operations, which are the per-pixel code's float
 * operations in their order, so the same bytes.  Quad i of the group is
 * lanes 4i to 4i + 3.  Where a quad's operations on four lanes take a
 * quarter of a 512-bit vector, the group's take one vector, and the
 * loads, the conversions and the stores of the four quads overlap.  The
 * 512-bit set only: elsewhere sixteen lanes are two or four vectors, no
 * fewer than the quads' own (its function returns NULL there).
 * RAST_OPT_SCALAR (rast_cbuf_plan.quad4 false) keeps the per-pixel code;
 * test_backend_color holds the groups to it.
 */
#include "rast/backend/backend_priv.h"
#include "rast/backend/c8_lanes.h"
#include "rast/host/lanes_fns.h"

#if defined(__AVX512F__)
#include <immintrin.h>

typedef float v16f __attribute__((vector_size(64)));
typedef int32_t v16i __attribute__((vector_size(64)));
typedef uint32_t v16u __attribute__((vector_size(64)));

C8_LANE_OPS(16, v16f, v16i, v16u)

/* A quad's words in a buffer of 4-byte pixels: its row of two, then the
 * row below (a quad's pixel order), from 8-byte loads (a row is 4-byte
 * aligned only); and their store. */
static inline __m128i quad_words(const uint8_t *base, ptrdiff_t stride, const struct rast_quad *q)
{
   const uint8_t *row = base + (ptrdiff_t)q->y * stride + (ptrdiff_t)q->x * 4;
   uint64_t r0, r1;
   memcpy(&r0, row, 8);
   memcpy(&r1, row + stride, 8);
   return _mm_set_epi64x((long long)r1, (long long)r0);
}

static inline void quad_words_store(uint8_t *base, ptrdiff_t stride, const struct rast_quad *q,
                                    __m128i rows)
{
   uint8_t *row = base + (ptrdiff_t)q->y * stride + (ptrdiff_t)q->x * 4;
   const uint64_t r0 = (uint64_t)_mm_cvtsi128_si64(rows),
                  r1 = (uint64_t)_mm_extract_epi64(rows, 1);
   memcpy(row, &r0, 8);
   memcpy(row + stride, &r1, 8);
}

static inline __m128i rows_of(const struct rast_cbuf_plan *p, const struct rast_quad *q,
                              bool drawn)
{
   return drawn ? quad_words(p->base, p->stride, q) : _mm_setzero_si128();
}

/* The words of the quads in `which` (bit i: quad i), their two rows of two
 * pixels in lanes 4i to 4i + 3; the others' lanes 0.  Built in registers
 * from 8-byte loads: through memory, a 64-byte load of what narrower
 * stores have just written waits for them to retire. */
static inline v16u load16(const struct rast_cbuf_plan *p, const struct rast_quad *q,
                          unsigned which)
{
   __m512i v = _mm512_castsi128_si512(rows_of(p, &q[0], which & 1));
   v = _mm512_inserti32x4(v, rows_of(p, &q[1], which >> 1 & 1), 1);
   v = _mm512_inserti32x4(v, rows_of(p, &q[2], which >> 2 & 1), 2);
   v = _mm512_inserti32x4(v, rows_of(p, &q[3], which >> 3 & 1), 3);
   return (v16u)v;
}

static inline void store_rows(const struct rast_cbuf_plan *p, const struct rast_quad *q,
                              __m128i rows)
{
   quad_words_store(p->base, p->stride, q, rows);
}

static inline void store16(const struct rast_cbuf_plan *p, const struct rast_quad *q,
                           unsigned which, v16u out)
{
   const __m512i o = (__m512i)out;
   if (which & 1)
      store_rows(p, &q[0], _mm512_castsi512_si128(o));
   if (which >> 1 & 1)
      store_rows(p, &q[1], _mm512_extracti32x4_epi32(o, 1));
   if (which >> 2 & 1)
      store_rows(p, &q[2], _mm512_extracti32x4_epi32(o, 2));
   if (which >> 3 & 1)
      store_rows(p, &q[3], _mm512_extracti32x4_epi32(o, 3));
}

/* Channel c of the quads' colours (every quad of the array: those not
 * drawn are computed and not stored), from the shader's 16-byte rows. */
static inline v16f source16(const struct rast_cbuf_plan *p,
                            const struct rast_shaded_quad *out, unsigned c)
{
   __m512 v = _mm512_castps128_ps512(_mm_loadu_ps(out[0].color[p->src][c]));
   v = _mm512_insertf32x4(v, _mm_loadu_ps(out[1].color[p->src][c]), 1);
   v = _mm512_insertf32x4(v, _mm_loadu_ps(out[2].color[p->src][c]), 2);
   v = _mm512_insertf32x4(v, _mm_loadu_ps(out[3].color[p->src][c]), 3);
   return (v16f)v;
}

/* out where the pixel is drawn (bit 4i + k of `masks`, quad i in `which`),
 * d elsewhere: c8_merge on sixteen lanes. */
static inline v16u merge16(v16u out, v16u d, unsigned which, unsigned masks)
{
   unsigned m = 0;
   for (unsigned i = 0; i < RAST_GROUP_MAX; i++)
      m |= (which >> i & 1) ? (masks & 15u << 4 * i) : 0;
   const v16u bit = { 1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024, 2048, 4096, 8192, 16384,
                      32768 };
   const v16u keep = (v16u)((bit & m) == 0);
   return (out & ~keep) | (d & keep);
}

/* c8_blend_affine4 on the group. */
static inline void affine16(const struct rast_cbuf_plan *p, const struct rast_quad *q,
                            const struct rast_shaded_quad *o, unsigned which, unsigned masks,
                            unsigned r, unsigned g, unsigned b, unsigned a, bool x8)
{
   const float (*k)[2] = (const float (*)[2])p->affine;
   const unsigned off[3] = { r, g, b };
   const v16u d = load16(p, q, which);
   v16u out;
   const v16f sa = clamp01_16(source16(p, o, 3));
   const v16f fs = splat16(k[0][0]) + splat16(k[0][1]) * sa,
              fd = splat16(k[1][0]) + splat16(k[1][1]) * sa;
   if (x8)
      out = (v16u){ 0 } + (255u << (8 * a));
   else
      out = f2ub16(sa * (splat16(k[2][0]) + splat16(k[2][1]) * sa) +
                   ub2f16(d, a) * (splat16(k[3][0]) + splat16(k[3][1]) * sa)) << (8 * a);
   for (unsigned c = 0; c < 3; c++)
      out |= f2ub16(clamp01_16(source16(p, o, c)) * fs + ub2f16(d, off[c]) * fd) << (8 * off[c]);
   store16(p, q, which, merge16(out, d, which, masks));
}

/* c8_store_quad4 on the group. */
static inline void store_group16(const struct rast_cbuf_plan *p, const struct rast_quad *q,
                                 const struct rast_shaded_quad *o, unsigned which,
                                 unsigned masks, unsigned r, unsigned g, unsigned b, unsigned a,
                                 bool x8)
{
   v16u out = (f2ub16(source16(p, o, 0)) << (8 * r)) | (f2ub16(source16(p, o, 1)) << (8 * g)) |
              (f2ub16(source16(p, o, 2)) << (8 * b)) |
              ((x8 ? (v16u){ 0 } + 255u : f2ub16(source16(p, o, 3))) << (8 * a));
   bool partial = false;
   for (unsigned i = 0; i < RAST_GROUP_MAX; i++)
      partial |= (which >> i & 1) && (masks >> 4 * i & 15) != 15;
   if (partial)
      out = merge16(out, load16(p, q, which), which, masks);
   store16(p, q, which, out);
}

#define C8_GROUP_FNS(NAME, R, G, B, A, X8)                                                   \
   static void affine_##NAME(const struct rast_cbuf_plan *p, const struct rast_quad *q,       \
                             const struct rast_shaded_quad *out, unsigned which,             \
                             unsigned masks)                                                 \
   {                                                                                         \
      affine16(p, q, out, which, masks, R, G, B, A, X8);                                     \
   }                                                                                         \
   static void store_##NAME(const struct rast_cbuf_plan *p, const struct rast_quad *q,        \
                            const struct rast_shaded_quad *out, unsigned which,              \
                            unsigned masks)                                                  \
   {                                                                                         \
      store_group16(p, q, out, which, masks, R, G, B, A, X8);                                \
   }

C8_GROUP_FNS(RGBA8, 0, 1, 2, 3, false)
C8_GROUP_FNS(BGRA8, 2, 1, 0, 3, false)
C8_GROUP_FNS(BGRX8, 2, 1, 0, 3, true)

rast_c8_group_fn LANES_FN(c8_group_lanes)(enum rast_color_layout layout, bool blend)
{
   switch (layout) {
   case RAST_CL_RGBA8: return blend ? affine_RGBA8 : store_RGBA8;
   case RAST_CL_BGRA8: return blend ? affine_BGRA8 : store_BGRA8;
   case RAST_CL_BGRX8: return blend ? affine_BGRX8 : store_BGRX8;
   default: return NULL;
   }
}

/* ---- the early depth test of a group (lanes.h's rast_zgroup_fn) ----
 *
 * Sixteen lanes, quad i's pixels in lanes 4i to 4i + 3, each lane the
 * per-quad path's operations on its pixel: zconv_mul's clamp (to the
 * viewport's bounds, rast_zrange) and rule (backend_zs.c), the comparison
 * with the stored 24 bits, and where it passes on a covered pixel the
 * write that keeps the word's top byte.
 * zconv_mul divides t = (2 z max + full) >> s by B with a multiply;
 * here a division of doubles gives the same floor(t / B) for the states
 * rast_zs_plan lets through (zdiv_exact_in_doubles). */

/* The unorm depth of quads a and b (eight 64-bit lanes, then eight
 * 32-bit ones).  The registers are read one by one: the span processor has
 * just stored them so, and a wider load over several stores would wait for
 * them to reach the cache. */
static inline __m256i zs_unorm8(const struct rast_backend *be, const struct rast_quad *a,
                                const struct rast_quad *b)
{
   __m512i z = _mm512_set_epi64(b->z[3], b->z[2], b->z[1], b->z[0], a->z[3], a->z[2], a->z[1],
                                a->z[0]);
   z = _mm512_min_epi64(_mm512_max_epi64(z, _mm512_set1_epi64((long long)be->zr.lo)),
                        _mm512_set1_epi64((long long)be->zr.hi));
   const __m512i n = _mm512_add_epi64(_mm512_mullo_epi64(z, _mm512_set1_epi64((long long)(2 * be->z_max))),
                                      _mm512_set1_epi64((long long)be->z_full));
   const __m512i t = _mm512_srl_epi64(n, _mm_cvtsi32_si128((int)be->zdiv.s));
   const __m512d q = _mm512_div_pd(_mm512_cvtepu64_pd(t), _mm512_set1_pd(be->zgroup_b));
   return _mm512_cvttpd_epu32(q);
}

static inline __attribute__((always_inline)) __mmask16 zs_compare(enum rast_func f, __m512i z,
                                                                    __m512i stored)
{
   switch (f) {
   case RAST_FUNC_NEVER: return 0;
   case RAST_FUNC_LESS: return _mm512_cmp_epu32_mask(z, stored, _MM_CMPINT_LT);
   case RAST_FUNC_EQUAL: return _mm512_cmp_epu32_mask(z, stored, _MM_CMPINT_EQ);
   case RAST_FUNC_LEQUAL: return _mm512_cmp_epu32_mask(z, stored, _MM_CMPINT_LE);
   case RAST_FUNC_GREATER: return _mm512_cmp_epu32_mask(z, stored, _MM_CMPINT_NLE);
   case RAST_FUNC_NOTEQUAL: return _mm512_cmp_epu32_mask(z, stored, _MM_CMPINT_NE);
   case RAST_FUNC_GEQUAL: return _mm512_cmp_epu32_mask(z, stored, _MM_CMPINT_NLT);
   default: return 0xffff;
   }
}

static inline __attribute__((always_inline)) unsigned
zgroup_u24lo(const struct rast_backend *be, const struct rast_quad *q, unsigned n,
             unsigned covered, const enum rast_func f, const bool write)
{
   /* quads past n repeat the first: read, never written or counted */
   const struct rast_quad *q1 = n > 1 ? &q[1] : q, *q2 = n > 2 ? &q[2] : q,
                          *q3 = n > 3 ? &q[3] : q;
   const __m512i z = _mm512_inserti64x4(_mm512_castsi256_si512(zs_unorm8(be, q, q1)),
                                        zs_unorm8(be, q2, q3), 1);
   uint8_t *const base = be->zs_base;
   const ptrdiff_t stride = be->zs_stride;
   __m512i words = _mm512_castsi128_si512(quad_words(base, stride, q));
   words = _mm512_inserti32x4(words, quad_words(base, stride, q1), 1);
   words = _mm512_inserti32x4(words, quad_words(base, stride, q2), 2);
   words = _mm512_inserti32x4(words, quad_words(base, stride, q3), 3);
   const unsigned pass =
      covered & zs_compare(f, z, _mm512_and_si512(words, _mm512_set1_epi32(0xffffff)));
   if (write && pass) {
      const __m512i top = _mm512_and_si512(words, _mm512_set1_epi32((int)0xff000000u));
      const __m512i out = _mm512_mask_blend_epi32((__mmask16)pass, words, _mm512_or_si512(top, z));
      if (pass & 15)
         quad_words_store(base, stride, q, _mm512_castsi512_si128(out));
      if (pass >> 4 & 15)
         quad_words_store(base, stride, q1, _mm512_extracti32x4_epi32(out, 1));
      if (pass >> 8 & 15)
         quad_words_store(base, stride, q2, _mm512_extracti32x4_epi32(out, 2));
      if (pass >> 12 & 15)
         quad_words_store(base, stride, q3, _mm512_extracti32x4_epi32(out, 3));
   }
   return pass;
}

#define ZGROUP_FNS(FUNC)                                                                     \
   static unsigned zgroup_##FUNC##_0(const struct rast_backend *be, const struct rast_quad *q, \
                                     unsigned n, unsigned covered)                           \
   {                                                                                         \
      return zgroup_u24lo(be, q, n, covered, RAST_FUNC_##FUNC, false);                       \
   }                                                                                         \
   static unsigned zgroup_##FUNC##_1(const struct rast_backend *be, const struct rast_quad *q, \
                                     unsigned n, unsigned covered)                           \
   {                                                                                         \
      return zgroup_u24lo(be, q, n, covered, RAST_FUNC_##FUNC, true);                        \
   }

ZGROUP_FNS(NEVER)
ZGROUP_FNS(LESS)
ZGROUP_FNS(EQUAL)
ZGROUP_FNS(LEQUAL)
ZGROUP_FNS(GREATER)
ZGROUP_FNS(NOTEQUAL)
ZGROUP_FNS(GEQUAL)
ZGROUP_FNS(ALWAYS)

rast_zgroup_fn LANES_FN(zgroup_lanes)(enum rast_func func, bool write)
{
   static const rast_zgroup_fn fns[8][2] = {
      { zgroup_NEVER_0, zgroup_NEVER_1 },       { zgroup_LESS_0, zgroup_LESS_1 },
      { zgroup_EQUAL_0, zgroup_EQUAL_1 },       { zgroup_LEQUAL_0, zgroup_LEQUAL_1 },
      { zgroup_GREATER_0, zgroup_GREATER_1 },   { zgroup_NOTEQUAL_0, zgroup_NOTEQUAL_1 },
      { zgroup_GEQUAL_0, zgroup_GEQUAL_1 },     { zgroup_ALWAYS_0, zgroup_ALWAYS_1 },
   };
   return fns[func & 7][write];
}
#else
rast_c8_group_fn LANES_FN(c8_group_lanes)(enum rast_color_layout layout, bool blend)
{
   (void)layout;
   (void)blend;
   return NULL;
}

rast_zgroup_fn LANES_FN(zgroup_lanes)(enum rast_func func, bool write)
{
   (void)func;
   (void)write;
   return NULL;
}
#endif
