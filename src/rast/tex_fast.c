/*
 * The unit's quad for dfx24 and binary32, chosen at bind: the data path of
 * tex_sample.c, tex_lod.c, tex_addr.c and tex_filter.c in the same order of
 * operations, with the arithmetic inline (tex_fast.h), the wrap mode a
 * switch instead of a call, the common 8-bit RGBA layouts read in place and
 * level selection shared by pixels of equal LOD.  One instance per number
 * system and dimensionality.  Cube maps and explicit derivatives (rare,
 * and the longest paths) stay on the generic quad.
 */
#include "rast/tex_fast.h"

/* c - floor(c) and the parity of floor(c). */
TEX_FAST_INLINE ns_val frac_of(const enum tex_fk k, ns_val c, bool *odd, struct tex_fst *x)
{
   uint32_t unused;
   const int64_t fl = tex_ffloor(k, c, &unused, 0, x);
   *odd = fl & 1;
   return tex_fsub(k, c, tex_fint(k, fl, x), x);
}

/* tex_addr.c's functions, the wrap mode a switch (invalid modes as
 * CLAMP_TO_EDGE, as tex_addr_choose). */
TEX_FAST_INLINE void addr(const struct tex_unit *u, const enum tex_fk k, const bool linear,
                          unsigned wrap, const struct tex_axis *ax, ns_val c,
                          struct tex_addr *a, struct tex_fst *x)
{
   const int nk = tex_fk_ns(k);
   bool border = false;
   bool odd;
   uint32_t w;
   switch (wrap) {
   case TEX_WRAP_REPEAT: {
      const ns_val s = tex_fmul(k, frac_of(k, c, &odd, x), ax->scale, x);
      if (!linear) {
         a->i0 = a->i1 = tex_clampi(tex_ffloor(k, s, &w, TEX_WEIGHT_BITS, x), 0, ax->size - 1);
         a->w = 0;
         return;
      }
      int64_t i = tex_ffloor(k, tex_fsub(k, s, u->k_texel_offset, x), &a->w,
                             TEX_WEIGHT_BITS, x);
      i = tex_clampi(i, -1, ax->size - 1);
      a->i0 = i < 0 ? ax->size - 1 : (int32_t)i;
      a->i1 = i + 1 >= ax->size ? 0 : (int32_t)i + 1;
      return;
   }
   case TEX_WRAP_MIRROR_REPEAT: {
      const ns_val f = frac_of(k, c, &odd, x);
      c = odd ? tex_fsub(k, u->k_one, f, x) : f;
      break;
   }
   case TEX_WRAP_CLAMP:
      c = tex_ns_clamp(nk, c, ax->lo, ax->hi);
      border = linear;
      break;
   case TEX_WRAP_CLAMP_TO_BORDER:
      c = tex_ns_clamp(nk, c, ax->lo, ax->hi);
      border = true;
      break;
   case TEX_WRAP_MIRROR_CLAMP:
      c = tex_ns_clamp(nk, tex_ns_abs(nk, c), ax->lo, ax->hi);
      border = linear;
      break;
   case TEX_WRAP_MIRROR_CLAMP_TO_EDGE:
      c = tex_ns_clamp(nk, tex_ns_abs(nk, c), ax->lo, ax->hi);
      break;
   case TEX_WRAP_MIRROR_CLAMP_TO_BORDER:
      c = tex_ns_clamp(nk, tex_ns_abs(nk, c), ax->lo, ax->hi);
      border = true;
      break;
   default:
      c = tex_ns_clamp(nk, c, ax->lo, ax->hi);
      break;
   }
   ns_val s = tex_fmul(k, c, ax->scale, x);
   if (!linear) {
      const int64_t i = tex_ffloor(k, s, &w, TEX_WEIGHT_BITS, x);
      a->i0 = a->i1 = border ? tex_inside(i, ax->size) : tex_clampi(i, 0, ax->size - 1);
      a->w = 0;
      return;
   }
   s = tex_fsub(k, s, u->k_texel_offset, x);
   const int64_t i = tex_ffloor(k, s, &a->w, TEX_WEIGHT_BITS, x);
   if (border) {
      a->i0 = tex_inside(i, ax->size);
      a->i1 = tex_inside(i + 1, ax->size);
   } else {
      a->i0 = tex_clampi(i, 0, ax->size - 1);
      a->i1 = tex_clampi(i + 1, 0, ax->size - 1);
   }
}


/* A texel in one SSE register: the taps' blend then reads no value just
 * stored as four scalars (a store-forwarding stall per tap).  Element by
 * element the same IEEE operations as tex_filter.c's float[4] code. */
typedef float v4f __attribute__((vector_size(16)));

TEX_FAST_INLINE v4f load4(const float a[4])
{
   v4f v;
   memcpy(&v, a, sizeof(v));
   return v;
}

/* tex_fetch.c's decoders of the 4-byte layouts in place; others call the
 * bound fetch function. */
TEX_FAST_INLINE v4f fetch(const struct tex_unit *u, const struct tex_level *lv, int x, int y,
                          int z)
{
   const enum tex_format f = u->view.format;
   if (f >= TEX_FMT_RGBA8 && f <= TEX_FMT_BGRX8) {
      const uint8_t *p = lv->data + (size_t)z * lv->img_stride + (size_t)y * lv->row_stride +
                         (size_t)x * 4;
      const bool bgr = f == TEX_FMT_BGRA8 || f == TEX_FMT_BGRX8;
      const v4f o = { tex_unorm8(p[bgr ? 2 : 0]), tex_unorm8(p[1]), tex_unorm8(p[bgr ? 0 : 2]),
                      f == TEX_FMT_RGBX8 || f == TEX_FMT_BGRX8 ? 1.0f : tex_unorm8(p[3]) };
      return o;
   }
   float o[4];
   u->fetch(&u->view, lv, x, y, z, o);
   return load4(o);
}

/* tex_filter.c's tap_color / tap_shadow. */
TEX_FAST_INLINE v4f tap(const struct tex_unit *u, const struct tex_level *lv, int x, int y,
                        int z, float ref)
{
   const bool shadow = u->samp.compare && u->view.depth;
   float d;
   if ((x | y | z) < 0) {
      if (!shadow)
         return load4(u->samp.border);
      d = u->samp.border[0];
   } else {
      const v4f t = fetch(u, lv, x, y, z);
      if (!shadow)
         return t;
      d = t[0];
   }
   const float c = tex_compare(u->samp.func, ref, d) ? 1.0f : 0.0f;
   const v4f o = { c, c, c, 1.0f };
   return o;
}

TEX_FAST_INLINE v4f lerp4(v4f a, v4f b, uint32_t w)
{
   const float f = (float)w * (1.0f / TEX_WEIGHT_ONE);
   return a + f * (b - a);
}

/* tex_filter.c's level_{1d,2d,3d}_{nearest,linear}. */
TEX_FAST_INLINE v4f level(const struct tex_unit *u, const enum tex_fk k, const unsigned dims,
                          const bool linear, unsigned l, const ns_val c[3], int layer,
                          float ref, struct tex_fst *x)
{
   const struct tex_level *lv = &u->view.level[l];
   const struct tex_axis *ax = u->axis[l];
   struct tex_addr A, B = { 0, 0, 0 }, C = { 0, 0, 0 };
   addr(u, k, linear, u->samp.wrap[0], &ax[0], c[0], &A, x);
   if (dims > 1)
      addr(u, k, linear, u->samp.wrap[1], &ax[1], c[1], &B, x);
   if (dims > 2)
      addr(u, k, linear, u->samp.wrap[2], &ax[2], c[2], &C, x);
   const int z0 = dims > 2 ? C.i0 : layer, z1 = dims > 2 ? C.i1 : layer;
   if (!linear)
      return tap(u, lv, A.i0, B.i0, z0, ref);
   if (dims == 1)
      return lerp4(tap(u, lv, A.i0, 0, layer, ref), tap(u, lv, A.i1, 0, layer, ref), A.w);
   const v4f e = lerp4(lerp4(tap(u, lv, A.i0, B.i0, z0, ref), tap(u, lv, A.i1, B.i0, z0, ref), A.w),
                       lerp4(tap(u, lv, A.i0, B.i1, z0, ref), tap(u, lv, A.i1, B.i1, z0, ref), A.w),
                       B.w);
   if (dims == 2)
      return e;
   const v4f f = lerp4(lerp4(tap(u, lv, A.i0, B.i0, z1, ref), tap(u, lv, A.i1, B.i0, z1, ref), A.w),
                       lerp4(tap(u, lv, A.i0, B.i1, z1, ref), tap(u, lv, A.i1, B.i1, z1, ref), A.w),
                       B.w);
   return lerp4(e, f, C.w);
}

TEX_FAST_INLINE v4f level_f(const struct tex_unit *u, const enum tex_fk k, const unsigned dims,
                            enum tex_filter f, unsigned l, const ns_val c[3], int layer,
                            float ref, struct tex_fst *x)
{
   if (f == TEX_FILTER_NEAREST)
      return level(u, k, dims, false, l, c, layer, ref, x);
   return level(u, k, dims, true, l, c, layer, ref, x);
}

static int32_t layer_of(const struct tex_unit *u, float l)
{
   float f = floorf(l + 0.5f);
   if (!(f > 0.0f))
      return 0;
   return f >= (float)(u->view.layers - 1) ? u->view.layers - 1 : (int32_t)f;
}

/* tex_lod_diffs. */
TEX_FAST_INLINE int32_t lod_diffs(const struct tex_unit *u, const enum tex_fk k,
                                  const unsigned dims, ns_val c[TEX_QUAD][3], struct tex_fst *x)
{
   const int nk = tex_fk_ns(k);
   ns_val rho = u->k_zero;
   for (unsigned a = 0; a < dims; a++) {
      const ns_val dx = tex_fsub(k, c[1][a], c[0][a], x);
      const ns_val dy = tex_fsub(k, c[2][a], c[0][a], x);
      rho = tex_ns_max(nk, rho, tex_ns_abs(nk, tex_fmul(k, dx, u->axis[0][a].scale, x)));
      rho = tex_ns_max(nk, rho, tex_ns_abs(nk, tex_fmul(k, dy, u->axis[0][a].scale, x)));
   }
   return tex_lod_from_rho(u, rho);
}

TEX_FAST_INLINE void quad(const struct tex_unit *u, const struct tex_quad *q,
                          enum tex_lod_control ctl, float rgba[4][TEX_QUAD],
                          const enum tex_fk k, const unsigned dims)
{
   if (ctl == TEX_LOD_DERIVS) {
      tex_unit_sample_generic(u, q, ctl, rgba);
      return;
   }
   struct tex_fst x = { { 0, 0 }, { 0, 0 } };
   const bool array = u->view.target == TEX_TARGET_1D_ARRAY ||
                      u->view.target == TEX_TARGET_2D_ARRAY;
   ns_val c[TEX_QUAD][3];
   int layer[TEX_QUAD];
   int32_t lod[TEX_QUAD];
   v4f out[TEX_QUAD];

   for (unsigned p = 0; p < TEX_QUAD; p++) {
      c[p][0] = tex_fcoord(u, k, q->s[p], &x);
      if (dims > 1)
         c[p][1] = tex_fcoord(u, k, q->t[p], &x);
      if (dims > 2)
         c[p][2] = tex_fcoord(u, k, q->r[p], &x);
      layer[p] = array ? layer_of(u, q->layer[p]) : 0;
   }

   switch (ctl) {
   case TEX_LOD_IMPLICIT:
   case TEX_LOD_BIAS: {
      const int32_t l = lod_diffs(u, k, dims, c, &x);
      for (unsigned p = 0; p < TEX_QUAD; p++)
         lod[p] = ctl == TEX_LOD_BIAS && l != TEX_LOD_NONE ? l + tex_lod_fixed(q->lod[p]) : l;
      break;
   }
   case TEX_LOD_EXPLICIT:
      for (unsigned p = 0; p < TEX_QUAD; p++)
         lod[p] = tex_lod_fixed(q->lod[p]);
      break;
   default:
      for (unsigned p = 0; p < TEX_QUAD; p++)
         lod[p] = 0;
      break;
   }

   unsigned l0 = 0, l1 = 0;
   uint32_t frac = 0;
   enum tex_filter f = TEX_FILTER_NEAREST;
   int32_t prev = 0;
   for (unsigned p = 0; p < TEX_QUAD; p++) {
      const int32_t cl = tex_clamp_lod(u, lod[p]);
      if (!p || cl != prev)   /* selection depends on the LOD alone */
         tex_unit_select(u, cl, &l0, &l1, &frac, &f);
      prev = cl;
      out[p] = level_f(u, k, dims, f, l0, c[p], layer[p], q->ref[p], &x);
      if (frac)
         out[p] = lerp4(out[p], level_f(u, k, dims, f, l1, c[p], layer[p], q->ref[p], &x), frac);
   }

   for (unsigned ch = 0; ch < 4; ch++) {
      const unsigned s = u->view.swizzle[ch];
      for (unsigned p = 0; p < TEX_QUAD; p++)
         rgba[ch][p] = s < 4 ? out[p][s] : s == TEX_SWZ_1 ? 1.0f : 0.0f;
   }
   tex_fst_flush(&x, u->stats);
}

#define QUAD_FN(name, k, dims)                                                              \
   static void name(const struct tex_unit *u, const struct tex_quad *q,                     \
                    enum tex_lod_control ctl, float rgba[4][TEX_QUAD])                      \
   {                                                                                        \
      quad(u, q, ctl, rgba, k, dims);                                                       \
   }

QUAD_FN(quad_dfx19_1d, TEX_FK_DFX19, 1)
QUAD_FN(quad_dfx19_2d, TEX_FK_DFX19, 2)
QUAD_FN(quad_dfx19_3d, TEX_FK_DFX19, 3)
QUAD_FN(quad_float_1d, TEX_FK_FLOAT, 1)
QUAD_FN(quad_float_2d, TEX_FK_FLOAT, 2)
QUAD_FN(quad_float_3d, TEX_FK_FLOAT, 3)

tex_quad_fn tex_fast_choose(const struct tex_unit *u)
{
   static const tex_quad_fn table[2][3] = {
      { quad_dfx19_1d, quad_dfx19_2d, quad_dfx19_3d },
      { quad_float_1d, quad_float_2d, quad_float_3d },
   };
   if (u->view.target == TEX_TARGET_CUBE || u->dims < 1 || u->dims > 3)
      return NULL;
   if (u->kind == TEX_NS_DFX && u->ns->dfx.mant_bits == DFX_MANT_BITS_SEED)
      return table[0][u->dims - 1];
   if (u->kind == TEX_NS_FLOAT)
      return table[1][u->dims - 1];
   return NULL;
}
