/*
 * The logic-op stage of the fragment back end (desktop GL's glLogicOp):
 * when enabled it replaces blending on normalized targets and combines the
 * source with the colour buffer's stored bits, byte for byte.
 *
 * The source is first stored as the target stores it (Mesa's float_to_ubyte
 * on the 8-bit layouts, the driver's `store` on the others), so the op sees
 * exactly the bits a plain store would write; the colour mask keeps the
 * bits of the channels it does not write.  The op is a function chosen at
 * validation and runs once per quad on all of it: no branch on state per
 * pixel.
 */
#include <stddef.h>
#include <string.h>
#include "rast/backend/backend_priv.h"

static inline uint8_t *lpixel(const struct rast_cbuf_plan *p, int x, int y)
{
   return p->base + (ptrdiff_t)y * p->stride + (ptrdiff_t)x * (ptrdiff_t)p->cpp;
}

/* ------------------------------------------------------------------ */
/* The sixteen ops, in GL's order.                                      */

#define LOP(NAME, EXPR) \
   static void lop_##NAME(const uint8_t *s, const uint8_t *d, uint8_t *r, unsigned n) \
   { \
      (void)s; \
      (void)d; \
      for (unsigned k = 0; k < n; k++) \
         r[k] = (uint8_t)(EXPR); \
   }

LOP(CLEAR, 0)
LOP(NOR, ~(s[k] | d[k]))
LOP(AND_INVERTED, ~s[k] & d[k])
LOP(COPY_INVERTED, ~s[k])
LOP(AND_REVERSE, s[k] & ~d[k])
LOP(INVERT, ~d[k])
LOP(XOR, s[k] ^ d[k])
LOP(NAND, ~(s[k] & d[k]))
LOP(AND, s[k] & d[k])
LOP(EQUIV, ~(s[k] ^ d[k]))
LOP(NOOP, d[k])
LOP(OR_INVERTED, ~s[k] | d[k])
LOP(COPY, s[k])
LOP(OR_REVERSE, s[k] | ~d[k])
LOP(OR, s[k] | d[k])
LOP(SET, 0xff)

static const rast_lop_func lop_table[16] = {
   lop_CLEAR, lop_NOR, lop_AND_INVERTED, lop_COPY_INVERTED,
   lop_AND_REVERSE, lop_INVERT, lop_XOR, lop_NAND,
   lop_AND, lop_EQUIV, lop_NOOP, lop_OR_INVERTED,
   lop_COPY, lop_OR_REVERSE, lop_OR, lop_SET
};

/* The result bytes r of the live pixels into the buffer, through the masks;
 * d holds what the pixels were. */
static inline void lop_write(const struct rast_cbuf_plan *p, int x, int y, unsigned mask,
                             unsigned cpp, const uint8_t *d, const uint8_t *r)
{
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      if (!(mask & (1u << i)))
         continue;
      uint8_t *px = lpixel(p, rast_qx(x, i), rast_qy(y, i));
      const uint8_t *di = d + i * cpp, *ri = r + i * cpp;
      for (unsigned k = 0; k < cpp; k++)
         px[k] = (uint8_t)(((ri[k] | p->lop_set[k]) & p->lop_wmask[k]) |
                           (di[k] & ~p->lop_wmask[k]));
   }
}

/* ------------------------------------------------------------------ */
/* 8-bit layouts: byte offsets and the X fill are constants per instance. */

static inline void c8_logicop(const struct rast_cbuf_plan *p, int x, int y, unsigned mask,
                              const float (*src)[RAST_QUAD_SIZE],
                              unsigned r, unsigned g, unsigned b, unsigned a, bool x8)
{
   uint8_t s[4 * RAST_QUAD_SIZE], d[4 * RAST_QUAD_SIZE], res[4 * RAST_QUAD_SIZE];
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      uint8_t *si = s + 4 * i, *di = d + 4 * i;
      if (!(mask & (1u << i))) {
         memset(si, 0, 4);
         memset(di, 0, 4);
         continue;
      }
      memcpy(di, lpixel(p, rast_qx(x, i), rast_qy(y, i)), 4);
      si[r] = rast_f2ub(src[0][i]);
      si[g] = rast_f2ub(src[1][i]);
      si[b] = rast_f2ub(src[2][i]);
      si[a] = x8 ? 255 : rast_f2ub(src[3][i]);
   }
   p->lop(s, d, res, sizeof res);
   lop_write(p, x, y, mask, 4, d, res);
}

#define C8_LOGICOP(NAME, R, G, B, A, X8) \
   static void c8_logicop_##NAME(const struct rast_cbuf_plan *p, int x, int y, unsigned mask, \
                                 const float (*src)[RAST_QUAD_SIZE], \
                                 const float (*src1)[RAST_QUAD_SIZE]) \
   { \
      (void)src1; \
      c8_logicop(p, x, y, mask, src, R, G, B, A, X8); \
   }

C8_LOGICOP(RGBA8, 0, 1, 2, 3, false)
C8_LOGICOP(BGRA8, 2, 1, 0, 3, false)
C8_LOGICOP(BGRX8, 2, 1, 0, 3, true)

/* ------------------------------------------------------------------ */
/* Driver formats: the source through the target's own store.            */

static void gen_logicop(const struct rast_cbuf_plan *p, int x, int y, unsigned mask,
                        const float (*src)[RAST_QUAD_SIZE], const float (*src1)[RAST_QUAD_SIZE])
{
   (void)src1;
   const unsigned cpp = p->cpp;
   uint8_t s[RAST_LOP_MAX_CPP * RAST_QUAD_SIZE], d[RAST_LOP_MAX_CPP * RAST_QUAD_SIZE];
   uint8_t res[RAST_LOP_MAX_CPP * RAST_QUAD_SIZE];
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      uint8_t *si = s + i * cpp, *di = d + i * cpp;
      if (!(mask & (1u << i))) {
         memset(si, 0, cpp);
         memset(di, 0, cpp);
         continue;
      }
      memcpy(di, lpixel(p, rast_qx(x, i), rast_qy(y, i)), cpp);
      float v[1][4];
      for (unsigned c = 0; c < 4; c++)
         v[0][c] = rast_clamp_lo(src[c][i], p->clamp_lo);
      p->store(si, 1, (const float (*)[4])v);
   }
   p->lop(s, d, res, RAST_QUAD_SIZE * cpp);
   lop_write(p, x, y, mask, cpp, d, res);
}

/* ------------------------------------------------------------------ */
/* Planning.                                                            */

/* The bits of a driver format's pixel that the colour mask writes: those
 * that differ between storing 0 and storing 1 in a written channel (1.0 is
 * all ones in every unorm channel, sRGB included).  Bits no channel owns
 * (X) are written only with the full mask, as a plain store would. */
static void generic_wmask(const struct rast_cbuf_plan *p, uint8_t *wm)
{
   memset(wm, 0, RAST_LOP_MAX_CPP);
   if (p->colormask == 0xf) {
      memset(wm, 0xff, p->cpp);
      return;
   }
   const float zero[1][4] = { { 0.0f, 0.0f, 0.0f, 0.0f } };
   uint8_t z[RAST_LOP_MAX_CPP] = { 0 };
   p->store(z, 1, zero);
   for (unsigned c = 0; c < 4; c++) {
      if (!(p->colormask & (1u << c)))
         continue;
      float one[1][4] = { { 0.0f, 0.0f, 0.0f, 0.0f } };
      one[0][c] = 1.0f;
      uint8_t o[RAST_LOP_MAX_CPP] = { 0 };
      p->store(o, 1, (const float (*)[4])one);
      for (unsigned k = 0; k < p->cpp; k++)
         wm[k] |= (uint8_t)(o[k] ^ z[k]);
   }
}

bool rast_logicop_plan(struct rast_cbuf_plan *p, enum rast_color_layout layout,
                       enum rast_logicop op)
{
   if (p->cpp == 0 || p->cpp > RAST_LOP_MAX_CPP || (unsigned)op > RAST_LOGICOP_SET)
      return false;
   p->lop = lop_table[op];
   memset(p->lop_set, 0, sizeof p->lop_set);

   if (layout == RAST_CL_GENERIC) {
      generic_wmask(p, p->lop_wmask);
      p->func = gen_logicop;
      return true;
   }

   /* Byte of channel c in the 8-bit layouts. */
   static const uint8_t rgba_off[4] = { 0, 1, 2, 3 }, bgra_off[4] = { 2, 1, 0, 3 };
   const uint8_t *off = layout == RAST_CL_RGBA8 ? rgba_off : bgra_off;
   memset(p->lop_wmask, 0, sizeof p->lop_wmask);
   for (unsigned c = 0; c < 4; c++)
      if (p->colormask & (1u << c))
         p->lop_wmask[off[c]] = 0xff;
   switch (layout) {
   case RAST_CL_RGBA8: p->func = c8_logicop_RGBA8; break;
   case RAST_CL_BGRA8: p->func = c8_logicop_BGRA8; break;
   default:
      p->func = c8_logicop_BGRX8;
      p->lop_set[3] = 0xff;
      break;
   }
   return true;
}
