/*
 * An 8-bit colour quad on four lanes: a pixel is its 32-bit word, a
 * channel the byte at its offset, and each lane does the per-pixel
 * code's float operations (backend_priv.h's rast_f2ub, rast_ub2f) in
 * their order, so the same bytes.  RAST_OPT_SCALAR (rast_cbuf_plan.quad4
 * false) keeps the per-pixel code, the reference; test_backend_color holds the
 * two to each other.
 */
#ifndef FIXPIPE_C8_LANES_H
#define FIXPIPE_C8_LANES_H

#include <string.h>
#include "rast/backend/backend_priv.h"

typedef float v4f __attribute__((vector_size(16)));
typedef int32_t v4i __attribute__((vector_size(16)));
typedef uint32_t v4u __attribute__((vector_size(16)));

/* The per-pixel conversions on N lanes (vf, vi, vu: N floats, int32s,
 * uint32s): splatN, clamp01_N (rast_clamp01), f2ubN (rast_f2ub, in the
 * low byte), ub2fN (rast_ub2f of each word's byte).  Four lanes here, a
 * quad; sixteen in backend_lanes.c, a group of four quads. */
#define C8_LANE_OPS(N, vf, vi, vu)                                                            \
   static inline vf splat##N(float v)           /* v's bits in every lane (-0 too) */        \
   {                                                                                          \
      int32_t bits;                                                                           \
      memcpy(&bits, &v, sizeof(bits));                                                        \
      return (vf)((vi){ 0 } + bits);                                                          \
   }                                                                                          \
   static inline vf clamp01_##N(vf v)                                                        \
   {                                                                                          \
      v = (vf)((vi)v & (v > splat##N(0.0f)));          /* NaN and -0 to +0 */                 \
      const vi below = v < splat##N(1.0f);                                                    \
      return (vf)(((vi)v & below) | ((vi)splat##N(1.0f) & ~below));                          \
   }                                                                                          \
   static inline vu f2ub##N(vf f)                                                            \
   {                                                                                          \
      return (vu)(clamp01_##N(f) * splat##N(255.0f / 256.0f) + splat##N(32768.0f)) & 0xff;  \
   }                                                                                          \
   static inline vf ub2f##N(vu words, unsigned byte)                                         \
   {                                                                                          \
      return __builtin_convertvector((vi)((words >> (8 * byte)) & 0xff), vf) *               \
             splat##N(1.0f / 255.0f);                                                         \
   }

C8_LANE_OPS(4, v4f, v4i, v4u)

/* The quad's two rows of two words. */
static inline v4u c8_load4(const struct rast_cbuf_plan *p, int x, int y)
{
   uint32_t px[RAST_QUAD_SIZE];
   memcpy(&px[0], p->base + (ptrdiff_t)y * p->stride + (ptrdiff_t)x * 4, 8);
   memcpy(&px[2], p->base + (ptrdiff_t)(y + 1) * p->stride + (ptrdiff_t)x * 4, 8);
   v4u d;
   memcpy(&d, px, sizeof(d));
   return d;
}

static inline void c8_write4(const struct rast_cbuf_plan *p, int x, int y, v4u out)
{
   uint32_t px[RAST_QUAD_SIZE];
   memcpy(px, &out, sizeof(out));
   memcpy(p->base + (ptrdiff_t)y * p->stride + (ptrdiff_t)x * 4, &px[0], 8);
   memcpy(p->base + (ptrdiff_t)(y + 1) * p->stride + (ptrdiff_t)x * 4, &px[2], 8);
}

/* out where the mask has the pixel, d (the buffer's word) elsewhere. */
static inline v4u c8_merge(v4u out, v4u d, unsigned mask)
{
   const v4u keep = (v4u)((v4i){ 1, 2, 4, 8 } & (int32_t)mask) == 0;
   return (out & ~keep) | (d & keep);
}

/* Whether the quad at (x, y) can take the lanes: a full quad, or a partial
 * one whose four pixels are in the framebuffer (the masked-off ones are
 * written back as they were; a quad is one thread's). */
static inline bool c8_lanes_ok(const struct rast_cbuf_plan *p, int x, int y, unsigned mask)
{
   return p->quad4 && rast_quad_whole(x, y, mask, p->fb_w, p->fb_h);
}

/* rast_store8_quad on the lanes: every channel converted, unblended. */
static inline void c8_store_quad4(const struct rast_cbuf_plan *p, int x, int y, unsigned mask,
                                  const float (*src)[RAST_QUAD_SIZE], unsigned r, unsigned g,
                                  unsigned b, unsigned a, bool x8)
{
   v4f s[4];
   memcpy(s, src, sizeof(s));
   v4u out = (f2ub4(s[0]) << (8 * r)) | (f2ub4(s[1]) << (8 * g)) | (f2ub4(s[2]) << (8 * b)) |
             ((x8 ? (v4u){ 255, 255, 255, 255 } : f2ub4(s[3])) << (8 * a));
   if (mask != 0xf)
      out = c8_merge(out, c8_load4(p, x, y), mask);
   c8_write4(p, x, y, out);
}

/* The unblended store of an 8-bit target, on the lanes where it can. */
static inline void c8_store_quad(const struct rast_cbuf_plan *p, int x, int y, unsigned mask,
                                 const float (*src)[RAST_QUAD_SIZE], unsigned r, unsigned g,
                                 unsigned b, unsigned a, bool x8)
{
   if (c8_lanes_ok(p, x, y, mask))
      c8_store_quad4(p, x, y, mask, src, r, g, b, a, x8);
   else
      rast_store8_quad(p->base, p->stride, x, y, mask, src, r, g, b, a, x8);
}

#endif
