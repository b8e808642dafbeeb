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
 * test_backend holds the groups to it.
 */
#include "rast/backend_priv.h"
#include "rast/c8_lanes.h"
#include "rast/lanes_fns.h"

#if defined(__AVX512F__)
#include <immintrin.h>

typedef float v16f __attribute__((vector_size(64)));
typedef int32_t v16i __attribute__((vector_size(64)));
typedef uint32_t v16u __attribute__((vector_size(64)));

C8_LANE_OPS(16, v16f, v16i, v16u)

/* A row of quad i: its top-left pixel's word, and the row below. */
static inline uint8_t *quad_row(const struct rast_cbuf_plan *p, const struct rast_quad *q)
{
   return p->base + (ptrdiff_t)q->y * p->stride + (ptrdiff_t)q->x * 4;
}

/* The words of the quads in `which` (bit i: quad i), their two rows of two
 * pixels in lanes 4i to 4i + 3; the others' lanes 0.  Built in registers
 * from 8-byte loads: through memory, a 64-byte load of what narrower
 * stores have just written waits for them to retire. */
static inline __m128i rows_of(const struct rast_cbuf_plan *p, const struct rast_quad *q,
                              bool drawn)
{
   if (!drawn)
      return _mm_setzero_si128();
   const uint8_t *row = quad_row(p, q);
   uint64_t r0, r1;
   memcpy(&r0, row, 8);
   memcpy(&r1, row + p->stride, 8);
   return _mm_set_epi64x((long long)r1, (long long)r0);
}

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
   uint8_t *row = quad_row(p, q);
   const uint64_t r0 = (uint64_t)_mm_cvtsi128_si64(rows),
                  r1 = (uint64_t)_mm_extract_epi64(rows, 1);
   memcpy(row, &r0, 8);               /* a row is 4-byte aligned only */
   memcpy(row + p->stride, &r1, 8);
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
#else
rast_c8_group_fn LANES_FN(c8_group_lanes)(enum rast_color_layout layout, bool blend)
{
   (void)layout;
   (void)blend;
   return NULL;
}
#endif
