/*
 * The texture unit's data path for one pixel with the number system fixed
 * at compile time (tex_fast.h): addressing per wrap mode, texel fetch,
 * filtering and the quad's LOD from its differences.  The quads of
 * tex_fast.c and the lanes' quad (tex_lanes.c, which takes these for the
 * pixels it does not address on lanes) share them.
 */
#ifndef FIXPIPE_TEX_FAST_PATH_H
#define FIXPIPE_TEX_FAST_PATH_H

#include "rast/tex/tex_fast.h"

/* c - floor(c) and the parity of floor(c); c itself in [-1, 0), with
 * *below set (tex_addr.c's frac_of). */
TEX_FAST_INLINE ns_val frac_of(const enum tex_fk k, ns_val c, bool *odd, bool *below,
                               struct tex_fst *x)
{
   uint32_t unused;
   const int64_t fl = tex_ffloor(k, c, &unused, 0, x);
   *odd = fl & 1;
   *below = fl == -1;
   return *below ? c : tex_fsub(k, c, tex_fint(k, fl, x), x);
}

/* The clamping wrap modes (all but the two repeats): whether the
 * coordinate is mirrored (|c|) before the clamp, and whether linear taps
 * outside the texture read the border.  Invalid modes clamp to the edge,
 * as tex_addr_choose. */
TEX_FAST_INLINE void clamp_mode(unsigned wrap, bool linear, bool *mirror, bool *border)
{
   *mirror = wrap == TEX_WRAP_MIRROR_CLAMP || wrap == TEX_WRAP_MIRROR_CLAMP_TO_EDGE ||
             wrap == TEX_WRAP_MIRROR_CLAMP_TO_BORDER;
   *border = wrap == TEX_WRAP_CLAMP_TO_BORDER || wrap == TEX_WRAP_MIRROR_CLAMP_TO_BORDER ||
             ((wrap == TEX_WRAP_CLAMP || wrap == TEX_WRAP_MIRROR_CLAMP) && linear);
}

/* tex_addr.c's functions, the wrap mode a switch (invalid modes as
 * CLAMP_TO_EDGE, as tex_addr_choose). */
TEX_FAST_INLINE void addr(const struct tex_unit *u, const enum tex_fk k, const bool linear,
                          unsigned wrap, const struct tex_axis *ax, ns_val c,
                          struct tex_addr *a, struct tex_fst *x)
{
   const int nk = tex_fk_ns(k);
   bool border = false;
   bool odd, below;
   uint32_t w;
   switch (wrap) {
   case TEX_WRAP_REPEAT: {
      const ns_val s = tex_fmul(k, frac_of(k, c, &odd, &below, x), ax->scale, x);
      const int64_t period = below ? ax->size : 0;
      if (!linear) {
         a->i0 = a->i1 = tex_clampi(tex_ffloor(k, s, &w, TEX_WEIGHT_BITS, x) + period, 0,
                                    ax->size - 1);
         a->w = 0;
         return;
      }
      int64_t i = tex_ffloor(k, tex_fsub(k, s, u->k_texel_offset, x), &a->w,
                             TEX_WEIGHT_BITS, x) + period;
      i = tex_clampi(i, -1, ax->size - 1);
      a->i0 = i < 0 ? ax->size - 1 : (int32_t)i;
      a->i1 = i + 1 >= ax->size ? 0 : (int32_t)i + 1;
      return;
   }
   case TEX_WRAP_MIRROR_REPEAT: {
      const ns_val f = frac_of(k, c, &odd, &below, x);
      c = below ? tex_ns_abs(nk, c) : odd ? tex_fsub(k, u->k_one, f, x) : f;
      break;
   }
   default: {
      bool mirror;
      clamp_mode(wrap, linear, &mirror, &border);
      c = tex_ns_clamp(nk, mirror ? tex_ns_abs(nk, c) : c, ax->lo, ax->hi);
      break;
   }
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
      /* tex_unorm8 on the four bytes at once: the same float operations */
      typedef int32_t v4i __attribute__((vector_size(16)));
      const uint8_t *p = lv->data + (size_t)z * lv->img_stride + (size_t)y * lv->row_stride +
                         (size_t)x * 4;
      uint32_t w;
      memcpy(&w, p, 4);
      const bool bgr = f == TEX_FMT_BGRA8 || f == TEX_FMT_BGRX8;
      const v4i sh = { bgr ? 16 : 0, 8, bgr ? 0 : 16, 24 };
      const v4i b = ((v4i){ (int32_t)w, (int32_t)w, (int32_t)w, (int32_t)w } >> sh) & 0xff;
      v4f o = __builtin_convertvector(b, v4f) * (1.0f / 255.0f);
      if (f == TEX_FMT_RGBX8 || f == TEX_FMT_BGRX8)
         o[3] = 1.0f;
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

TEX_FAST_INLINE int32_t layer_of(const struct tex_unit *u, float l)
{
   float f = floorf(l + 0.5f);
   if (!(f > 0.0f))
      return 0;
   return f >= (float)(u->view.layers - 1) ? u->view.layers - 1 : (int32_t)f;
}

/* Whether the LOD comes from the quad's coordinate differences. */
TEX_FAST_INLINE bool tex_lod_from_diffs(enum tex_lod_control ctl)
{
   return ctl == TEX_LOD_IMPLICIT || ctl == TEX_LOD_BIAS;
}

/* Each pixel's LOD register before the sampler's clamps: `l` from the
 * differences (implicit, bias), the explicit LOD, or 0. */
TEX_FAST_INLINE void lods(enum tex_lod_control ctl, int32_t l, const struct tex_quad *q,
                          int32_t lod[TEX_QUAD])
{
   for (unsigned p = 0; p < TEX_QUAD; p++) {
      switch (ctl) {
      case TEX_LOD_IMPLICIT:
         lod[p] = l;
         break;
      case TEX_LOD_BIAS:
         lod[p] = l != TEX_LOD_NONE ? l + tex_lod_fixed(q->lod[p]) : l;
         break;
      case TEX_LOD_EXPLICIT:
         lod[p] = tex_lod_fixed(q->lod[p]);
         break;
      default:
         lod[p] = 0;
         break;
      }
   }
}

/* tex_lod_diffs. */
TEX_FAST_INLINE int32_t lod_diffs(const struct tex_unit *u, const enum tex_fk k,
                                  const unsigned dims, ns_val c[TEX_QUAD][3], struct tex_fst *x)
{
   const int nk = tex_fk_ns(k);
   ns_val rho = u->k_zero;
   for (unsigned a = 0; a < dims; a++) {
      const ns_val dx = tex_fsub(k, c[3][a], c[2][a], x);
      const ns_val dy = tex_fsub(k, c[0][a], c[2][a], x);
      rho = tex_ns_max(nk, rho, tex_ns_abs(nk, tex_fmul(k, dx, u->axis[0][a].scale, x)));
      rho = tex_ns_max(nk, rho, tex_ns_abs(nk, tex_fmul(k, dy, u->axis[0][a].scale, x)));
   }
   return tex_lod_from_rho(u, rho);
}

#endif
