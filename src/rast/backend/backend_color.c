/*
 * Colour of the fragment back end: blend, colour mask and store.
 *
 * Blending is GL's, in float: with the target's `clamp` set, the source
 * colours, the destination and the constant colour are clamped to [0, 1]
 * ([-1, 1] for a signed normalized target) first (and so is the result); MIN and MAX ignore the factors;
 * SRC_ALPHA_SATURATE is min(As, 1 - Ad) for RGB and 1 for alpha.  The
 * factor and equation are chosen once per quad and channel, never per
 * pixel.  Unorm8 pixels read as x * (1/255) (Mesa's ubyte_to_float) and
 * are written as Mesa's float_to_ubyte: clamp, then round to nearest.
 */
#include <string.h>
#include <stddef.h>
#include "rast/backend/backend_priv.h"
#include "rast/backend/c8_lanes.h"

uint8_t rast_float_to_ubyte(float f)
{
   return rast_f2ub(f);
}

static inline uint8_t *cpixel(const struct rast_cbuf_plan *p, int x, int y)
{
   return p->base + (ptrdiff_t)y * p->stride + (ptrdiff_t)x * (ptrdiff_t)p->cpp;
}

#define clamp01 rast_clamp01

/* ------------------------------------------------------------------ */
/* Blend of a whole quad, [chan][pixel].                                */

typedef float quadf[4][RAST_QUAD_SIZE];

static inline void blend_factor(enum rast_blend_factor f, unsigned c, const quadf s,
                         const quadf s1, const quadf d, const float k[4],
                         float out[RAST_QUAD_SIZE])
{
   unsigned i;
#define EACH(expr) for (i = 0; i < RAST_QUAD_SIZE; i++) out[i] = (expr); break
   switch (f) {
   case RAST_BF_ZERO: EACH(0.0f);
   case RAST_BF_ONE: EACH(1.0f);
   case RAST_BF_SRC_COLOR: EACH(s[c][i]);
   case RAST_BF_INV_SRC_COLOR: EACH(1.0f - s[c][i]);
   case RAST_BF_SRC_ALPHA: EACH(s[3][i]);
   case RAST_BF_INV_SRC_ALPHA: EACH(1.0f - s[3][i]);
   case RAST_BF_DST_COLOR: EACH(d[c][i]);
   case RAST_BF_INV_DST_COLOR: EACH(1.0f - d[c][i]);
   case RAST_BF_DST_ALPHA: EACH(d[3][i]);
   case RAST_BF_INV_DST_ALPHA: EACH(1.0f - d[3][i]);
   case RAST_BF_CONST_COLOR: EACH(k[c]);
   case RAST_BF_INV_CONST_COLOR: EACH(1.0f - k[c]);
   case RAST_BF_CONST_ALPHA: EACH(k[3]);
   case RAST_BF_INV_CONST_ALPHA: EACH(1.0f - k[3]);
   case RAST_BF_SRC_ALPHA_SATURATE:
      if (c == 3) {
         EACH(1.0f);
      } else {
         EACH(s[3][i] < 1.0f - d[3][i] ? s[3][i] : 1.0f - d[3][i]);
      }
   case RAST_BF_SRC1_COLOR: EACH(s1[c][i]);
   case RAST_BF_INV_SRC1_COLOR: EACH(1.0f - s1[c][i]);
   case RAST_BF_SRC1_ALPHA: EACH(s1[3][i]);
   case RAST_BF_INV_SRC1_ALPHA: EACH(1.0f - s1[3][i]);
   default: EACH(0.0f);
   }
#undef EACH
}

static void blend_quad(const struct rast_cbuf_plan *p, const float (*src_in)[RAST_QUAD_SIZE],
                       const float (*src1_in)[RAST_QUAD_SIZE], const quadf d_in, quadf res)
{
   quadf s, s1, d;
   const float (*sp)[RAST_QUAD_SIZE] = src_in, (*s1p)[RAST_QUAD_SIZE] = src1_in;
   const float (*dp)[RAST_QUAD_SIZE] = d_in;

   const float lo = p->clamp_lo;
   if (p->clamp) {
      for (unsigned c = 0; c < 4; c++)
         for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
            s[c][i] = rast_clamp_lo(src_in[c][i], lo);
      sp = (const float (*)[RAST_QUAD_SIZE])s;
      if (p->uses_src1) {
         for (unsigned c = 0; c < 4; c++)
            for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
               s1[c][i] = rast_clamp_lo(src1_in[c][i], lo);
         s1p = (const float (*)[RAST_QUAD_SIZE])s1;
      }
      if (p->clamp_dst) {
         for (unsigned c = 0; c < 4; c++)
            for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
               d[c][i] = rast_clamp_lo(d_in[c][i], lo);
         dp = (const float (*)[RAST_QUAD_SIZE])d;
      }
   }

   for (unsigned c = 0; c < 4; c++) {
      const bool a = c == 3;
      const enum rast_blend_eq eq = a ? p->bt.alpha_eq : p->bt.rgb_eq;
      float sf[RAST_QUAD_SIZE], df[RAST_QUAD_SIZE];
      unsigned i;

      if (eq == RAST_BLEND_MIN) {
         for (i = 0; i < RAST_QUAD_SIZE; i++)
            res[c][i] = sp[c][i] < dp[c][i] ? sp[c][i] : dp[c][i];
      } else if (eq == RAST_BLEND_MAX) {
         for (i = 0; i < RAST_QUAD_SIZE; i++)
            res[c][i] = sp[c][i] > dp[c][i] ? sp[c][i] : dp[c][i];
      } else {
         blend_factor(a ? p->bt.alpha_src : p->bt.rgb_src, c, sp, s1p, dp, p->konst, sf);
         blend_factor(a ? p->bt.alpha_dst : p->bt.rgb_dst, c, sp, s1p, dp, p->konst, df);
         if (eq == RAST_BLEND_SUBTRACT)
            for (i = 0; i < RAST_QUAD_SIZE; i++)
               res[c][i] = sp[c][i] * sf[i] - dp[c][i] * df[i];
         else if (eq == RAST_BLEND_REVERSE_SUBTRACT)
            for (i = 0; i < RAST_QUAD_SIZE; i++)
               res[c][i] = dp[c][i] * df[i] - sp[c][i] * sf[i];
         else
            for (i = 0; i < RAST_QUAD_SIZE; i++)
               res[c][i] = sp[c][i] * sf[i] + dp[c][i] * df[i];
      }
      if (p->clamp_dst)    /* 8-bit stores clamp by themselves */
         for (i = 0; i < RAST_QUAD_SIZE; i++)
            res[c][i] = rast_clamp_lo(res[c][i], lo);
   }
}

/* ------------------------------------------------------------------ */
/* 8-bit layouts: offsets and the alpha fill are constants per instance. */

static inline void load8(const struct rast_cbuf_plan *p, int x, int y, unsigned mask,
                         unsigned r, unsigned g, unsigned b, unsigned a, bool x8, quadf d)
{
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      if (!(mask & (1u << i))) {
         d[0][i] = d[1][i] = d[2][i] = d[3][i] = 0.0f;
         continue;
      }
      const uint8_t *px = cpixel(p, rast_qx(x, i), rast_qy(y, i));
      d[0][i] = rast_ub2f(px[r]);
      d[1][i] = rast_ub2f(px[g]);
      d[2][i] = rast_ub2f(px[b]);
      d[3][i] = x8 ? 1.0f : rast_ub2f(px[a]);
   }
}

static inline void store8_masked(const struct rast_cbuf_plan *p, int x, int y, unsigned mask,
                                 const float (*v)[RAST_QUAD_SIZE], const uint8_t off[4],
                                 bool x8)
{
   const unsigned cm = p->colormask;
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      if (!(mask & (1u << i)))
         continue;
      uint8_t *px = cpixel(p, rast_qx(x, i), rast_qy(y, i));
      for (unsigned c = 0; c < 4; c++)
         if (cm & (1u << c))
            px[off[c]] = (c == 3 && x8) ? 255 : rast_f2ub(v[c][i]);
   }
}

/* The usual alpha blends (straight, premultiplied, additive) on 8-bit
 * targets with all channels written: each factor is k0 + k1 * As, so one
 * loop without branches covers them; the arithmetic is that of blend_quad
 * (s * (0 + 1 * a) == s * a and 1 + -1 * a == 1 - a exactly). */
/* The same on a full quad, the four pixels on four lanes: each lane the
 * loop's operations above in their order, so the same bits (the scalar
 * loop is the reference: RAST_OPT_SCALAR, and test_backend_color holds the two
 * to each other).  A pixel is its 32-bit word, a channel the byte at its
 * offset. */
static inline void c8_blend_affine4(const struct rast_cbuf_plan *p, int x, int y,
                                    unsigned mask, const float (*src)[RAST_QUAD_SIZE],
                                    unsigned r, unsigned g, unsigned b, unsigned a, bool x8)
{
   const float (*k)[2] = (const float (*)[2])p->affine;
   const unsigned off[3] = { r, g, b };
   const v4u d = c8_load4(p, x, y);
   v4u out;
   v4f s[4];
   memcpy(s, src, sizeof(s));
   const v4f sa = clamp01_4(s[3]);
   const v4f fs = splat4(k[0][0]) + splat4(k[0][1]) * sa,
             fd = splat4(k[1][0]) + splat4(k[1][1]) * sa;
   if (x8)
      out = (v4u){ 255, 255, 255, 255 } << (8 * a);
   else
      out = f2ub4(sa * (splat4(k[2][0]) + splat4(k[2][1]) * sa) +
                  ub2f4(d, a) * (splat4(k[3][0]) + splat4(k[3][1]) * sa)) << (8 * a);
   for (unsigned c = 0; c < 3; c++)
      out |= f2ub4(clamp01_4(s[c]) * fs + ub2f4(d, off[c]) * fd) << (8 * off[c]);
   c8_write4(p, x, y, c8_merge(out, d, mask));
}

static inline void c8_blend_affine(const struct rast_cbuf_plan *p, int x, int y, unsigned mask,
                                   const float (*src)[RAST_QUAD_SIZE],
                                   unsigned r, unsigned g, unsigned b, unsigned a, bool x8)
{
   /* a partial quad too, where all four pixels are in the framebuffer:
    * the lanes are independent, and the masked-off ones are written back
    * as they were (a quad is one thread's) */
   if (c8_lanes_ok(p, x, y, mask)) {
      c8_blend_affine4(p, x, y, mask, src, r, g, b, a, x8);
      return;
   }
   const float (*k)[2] = (const float (*)[2])p->affine;
   const unsigned off[3] = { r, g, b };
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      if (!(mask & (1u << i)))
         continue;
      uint8_t *px = cpixel(p, rast_qx(x, i), rast_qy(y, i));
      const float sa = clamp01(src[3][i]);
      const float fs = k[0][0] + k[0][1] * sa, fd = k[1][0] + k[1][1] * sa;
      for (unsigned c = 0; c < 3; c++)
         px[off[c]] = rast_f2ub(clamp01(src[c][i]) * fs + rast_ub2f(px[off[c]]) * fd);
      if (x8)
         px[a] = 255;
      else
         px[a] = rast_f2ub(sa * (k[2][0] + k[2][1] * sa) +
                           rast_ub2f(px[a]) * (k[3][0] + k[3][1] * sa));
   }
}

#define C8_FUNCS(NAME, R, G, B, A, X8) \
   static void c8_affine_##NAME(const struct rast_cbuf_plan *p, int x, int y, unsigned mask, \
                                const float (*src)[RAST_QUAD_SIZE], \
                                const float (*src1)[RAST_QUAD_SIZE]) \
   { \
      (void)src1; \
      c8_blend_affine(p, x, y, mask, src, R, G, B, A, X8); \
   } \
   static const uint8_t off_##NAME[4] = { R, G, B, A }; \
   static void c8_store_##NAME(const struct rast_cbuf_plan *p, int x, int y, unsigned mask, \
                               const float (*src)[RAST_QUAD_SIZE], \
                               const float (*src1)[RAST_QUAD_SIZE]) \
   { \
      (void)src1; \
      c8_store_quad(p, x, y, mask, src, R, G, B, A, X8); \
   } \
   static void c8_masked_##NAME(const struct rast_cbuf_plan *p, int x, int y, unsigned mask, \
                                const float (*src)[RAST_QUAD_SIZE], \
                                const float (*src1)[RAST_QUAD_SIZE]) \
   { \
      (void)src1; \
      store8_masked(p, x, y, mask, src, off_##NAME, X8); \
   } \
   static void c8_blend_##NAME(const struct rast_cbuf_plan *p, int x, int y, unsigned mask, \
                               const float (*src)[RAST_QUAD_SIZE], \
                               const float (*src1)[RAST_QUAD_SIZE]) \
   { \
      quadf d, res; \
      load8(p, x, y, mask, R, G, B, A, X8, d); \
      blend_quad(p, src, src1, (const float (*)[RAST_QUAD_SIZE])d, res); \
      store8_masked(p, x, y, mask, (const float (*)[RAST_QUAD_SIZE])res, off_##NAME, X8); \
   }

C8_FUNCS(RGBA8, 0, 1, 2, 3, false)
C8_FUNCS(BGRA8, 2, 1, 0, 3, false)
C8_FUNCS(BGRX8, 2, 1, 0, 3, true)

/* ------------------------------------------------------------------ */
/* Driver-supplied formats.                                             */

static void gen_store(const struct rast_cbuf_plan *p, int x, int y, unsigned mask,
                      const float (*src)[RAST_QUAD_SIZE], const float (*src1)[RAST_QUAD_SIZE])
{
   (void)src1;
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      if (!(mask & (1u << i)))
         continue;
      uint8_t *px = cpixel(p, rast_qx(x, i), rast_qy(y, i));
      float v[1][4];
      if (p->colormask != 0xf)
         p->load(px, 1, v);
      for (unsigned c = 0; c < 4; c++)
         if (p->colormask & (1u << c))
            v[0][c] = p->clamp ? rast_clamp_lo(src[c][i], p->clamp_lo) : src[c][i];
      p->store(px, 1, (const float (*)[4])v);
   }
}

static void gen_blend(const struct rast_cbuf_plan *p, int x, int y, unsigned mask,
                      const float (*src)[RAST_QUAD_SIZE], const float (*src1)[RAST_QUAD_SIZE])
{
   quadf d, res;
   float v[RAST_QUAD_SIZE][4];
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      if (mask & (1u << i)) {
         p->load(cpixel(p, rast_qx(x, i), rast_qy(y, i)), 1, &v[i]);
      } else {
         v[i][0] = v[i][1] = v[i][2] = v[i][3] = 0.0f;
      }
      for (unsigned c = 0; c < 4; c++)
         d[c][i] = v[i][c];
   }
   blend_quad(p, src, src1, (const float (*)[RAST_QUAD_SIZE])d, res);
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      if (!(mask & (1u << i)))
         continue;
      for (unsigned c = 0; c < 4; c++)
         if (p->colormask & (1u << c))
            v[i][c] = res[c][i];
      p->store(cpixel(p, rast_qx(x, i), rast_qy(y, i)), 1, (const float (*)[4])&v[i]);
   }
}

/* ------------------------------------------------------------------ */
/* Planning.                                                            */

/* Blending that can only give the source back. */
static bool blend_is_replace(const struct rast_blend_target *bt, bool clamp)
{
   /* src*1 + dst*0 is src only when dst cannot be NaN or infinite: the
    * clamped (normalized) formats. */
   return clamp &&
          (bt->rgb_eq == RAST_BLEND_ADD || bt->rgb_eq == RAST_BLEND_SUBTRACT) &&
          (bt->alpha_eq == RAST_BLEND_ADD || bt->alpha_eq == RAST_BLEND_SUBTRACT) &&
          bt->rgb_src == RAST_BF_ONE && bt->alpha_src == RAST_BF_ONE &&
          bt->rgb_dst == RAST_BF_ZERO && bt->alpha_dst == RAST_BF_ZERO;
}

/* k0 + k1 * As, or false. */
static bool affine_factor(enum rast_blend_factor f, float k[2])
{
   switch (f) {
   case RAST_BF_ZERO: k[0] = 0.0f; k[1] = 0.0f; return true;
   case RAST_BF_ONE: k[0] = 1.0f; k[1] = 0.0f; return true;
   case RAST_BF_SRC_ALPHA: k[0] = 0.0f; k[1] = 1.0f; return true;
   case RAST_BF_INV_SRC_ALPHA: k[0] = 1.0f; k[1] = -1.0f; return true;
   default: return false;
   }
}

static bool plan_affine(struct rast_cbuf_plan *p)
{
   const struct rast_blend_target *bt = &p->bt;
   return p->colormask == 0xf &&
          bt->rgb_eq == RAST_BLEND_ADD && bt->alpha_eq == RAST_BLEND_ADD &&
          affine_factor(bt->rgb_src, p->affine[0]) && affine_factor(bt->rgb_dst, p->affine[1]) &&
          affine_factor(bt->alpha_src, p->affine[2]) && affine_factor(bt->alpha_dst, p->affine[3]);
}

static bool is_src1(enum rast_blend_factor f)
{
   return f >= RAST_BF_SRC1_COLOR && f <= RAST_BF_INV_SRC1_ALPHA;
}

static bool uses_src1(const struct rast_blend_target *bt)
{
   return is_src1(bt->rgb_src) || is_src1(bt->rgb_dst) ||
          is_src1(bt->alpha_src) || is_src1(bt->alpha_dst);
}

void rast_color_plan(struct rast_backend *be, const struct rast_context *rc)
{
   be->ncbufs = 0;
   const unsigned n = rc->fb.nr_cbufs < RAST_MAX_CBUFS ? rc->fb.nr_cbufs : RAST_MAX_CBUFS;

   for (unsigned i = 0; i < n; i++) {
      const struct rast_color_target *t = &rc->fb.cbuf[i];
      const struct rast_blend_target *bt = &rc->blend.rt[rc->blend.independent ? i : 0];
      const unsigned src = rc->fs.color0_to_all ? 0 : i;

      if (!t->base || !(bt->colormask & 0xf))
         continue;
      /* An output the shader does not write leaves its buffer alone. */
      if (src >= rc->fs.num_outputs)
         continue;

      enum rast_color_layout layout = t->layout;
      if (layout != RAST_CL_GENERIC && t->cpp != 4)
         layout = RAST_CL_GENERIC;
      /* Logic ops replace blending, and act on normalized targets only;
       * COPY is the plain store and NOOP leaves the buffer as it is. */
      const bool lop = rc->blend.logicop_enable && (t->clamp || layout != RAST_CL_GENERIC);
      const enum rast_logicop lop_func = rc->blend.logicop_func;
      if (lop && lop_func == RAST_LOGICOP_NOOP)
         continue;

      struct rast_cbuf_plan *p = &be->cbuf[be->ncbufs++];
      memset(p, 0, sizeof *p);
      p->base = p->base0 = t->base;
      p->sample_stride = t->sample_stride;
      p->layers = t->layers;
      p->layer_stride = t->layer_stride;
      p->stride = t->stride;
      p->cpp = t->cpp;
      p->load = t->load;
      p->store = t->store;
      p->clamp = t->clamp;
      p->clamp_lo = t->clamp && t->snorm ? -1.0f : 0.0f;
      p->colormask = bt->colormask & 0xf;
      p->quad4 = !(rc->opts & RAST_OPT_SCALAR);
      p->fb_w = (int)rc->fb.width;
      p->fb_h = (int)rc->fb.height;
      p->bt = *bt;
      p->src = src;

      const bool blend = !rc->blend.logicop_enable && bt->blend_enable &&
                         !blend_is_replace(bt, t->clamp || layout != RAST_CL_GENERIC);
      if (layout != RAST_CL_GENERIC)
         p->clamp = true;     /* unorm8 by definition */
      p->clamp_dst = p->clamp && layout == RAST_CL_GENERIC;
      p->uses_src1 = uses_src1(bt);

      if (lop && lop_func != RAST_LOGICOP_COPY && rast_logicop_plan(p, layout, lop_func))
         continue;

      switch (layout) {
      case RAST_CL_RGBA8:
         p->func = blend ? (plan_affine(p) ? c8_affine_RGBA8 : c8_blend_RGBA8)
                       : p->colormask == 0xf ? c8_store_RGBA8 : c8_masked_RGBA8;
         if (p->func == c8_store_RGBA8)
            p->fast8 = RAST_CL_RGBA8;
         break;
      case RAST_CL_BGRA8:
         p->func = blend ? (plan_affine(p) ? c8_affine_BGRA8 : c8_blend_BGRA8)
                       : p->colormask == 0xf ? c8_store_BGRA8 : c8_masked_BGRA8;
         if (p->func == c8_store_BGRA8)
            p->fast8 = RAST_CL_BGRA8;
         break;
      case RAST_CL_BGRX8:
         p->func = blend ? (plan_affine(p) ? c8_affine_BGRX8 : c8_blend_BGRX8)
                       : p->colormask == 0xf ? c8_store_BGRX8 : c8_masked_BGRX8;
         if (p->func == c8_store_BGRX8)
            p->fast8 = RAST_CL_BGRX8;
         break;
      default:
         p->func = blend ? gen_blend : gen_store;
         break;
      }
      /* the affine blend and the full store, a group's quads on one vector */
      const bool affine = p->func == c8_affine_RGBA8 || p->func == c8_affine_BGRA8 ||
                          p->func == c8_affine_BGRX8;
      if (p->quad4 && rast_lanes()->c8_group && (affine || p->fast8 != RAST_CL_GENERIC))
         p->group = rast_lanes()->c8_group(layout, affine);
      for (unsigned c = 0; c < 4; c++)
         p->konst[c] = p->clamp ? rast_clamp_lo(rc->blend_color[c], p->clamp_lo)
                                : rc->blend_color[c];
   }
}
