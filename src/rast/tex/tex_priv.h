/*
 * Inside the texture unit: what its files share.  Not for the driver.
 */
#ifndef FIXPIPE_TEX_PRIV_H
#define FIXPIPE_TEX_PRIV_H

#include <math.h>
#include "rast/tex/tex.h"
#include "rast/tex/tex_ns.h"

/* Small pieces the generic and the specialised (tex_fast.c) paths share. */
static inline int32_t tex_clampi(int64_t i, int32_t lo, int32_t hi)
{
   return i < lo ? lo : i > hi ? hi : (int32_t)i;
}

/* The texel index, or -1 (the border) outside [0, size). */
static inline int32_t tex_inside(int64_t i, int32_t size)
{
   return i >= 0 && i < size ? (int32_t)i : -1;
}

static inline float tex_unorm8(unsigned v) { return (float)v * (1.0f / 255.0f); }

/* The LOD register (fixed point, see tex_lod_fixed) with the sampler's bias
 * and clamps applied. */
static inline int32_t tex_clamp_lod(const struct tex_unit *u, int32_t l)
{
   l += u->lod_bias;
   if (l > u->max_lod)
      l = u->max_lod;
   if (l < u->min_lod)
      l = u->min_lod;
   return l;
}

/* Cube maps and cube map arrays: the faces, their LOD and seamless
 * filtering alike. */
static inline bool tex_is_cube(enum tex_target t)
{
   return t == TEX_TARGET_CUBE || t == TEX_TARGET_CUBE_ARRAY;
}

/* A float coordinate into the unit's number system (tex_ns_coord). */
static inline ns_val tex_nsf(const struct tex_unit *u, float v)
{
   return tex_ns_coord(u->ns, u->kind, v, u->stats);
}

/* The array layer of a coordinate: GL's clamp(floor(layer + 0.5), 0,
 * layers - 1), an integer path. */
static inline int32_t tex_layer_of(const struct tex_unit *u, float l)
{
   float f = floorf(l + 0.5f);
   if (!(f > 0.0f))
      return 0;
   return f >= (float)(u->view.layers - 1) ? u->view.layers - 1 : (int32_t)f;
}

/* The first layer of the cube a cube map array's coordinate picks, GL's
 * clamp(floor(layer + 0.5), 0, cubes - 1) times six; 0 for a cube map. */
static inline int32_t tex_cube_base_of(const struct tex_unit *u, float l)
{
   if (u->view.target != TEX_TARGET_CUBE_ARRAY)
      return 0;
   const int32_t cubes = u->view.layers / 6;
   float f = floorf(l + 0.5f);
   if (!(f > 0.0f) || cubes < 1)
      return 0;
   return 6 * (f >= (float)(cubes - 1) ? cubes - 1 : (int32_t)f);
}

/* Shadow comparison of the reference with a texel's depth. */
static inline bool tex_compare(enum tex_func func, float ref, float d)
{
   switch (func) {
   case TEX_FUNC_NEVER: return false;
   case TEX_FUNC_LESS: return ref < d;
   case TEX_FUNC_EQUAL: return ref == d;
   case TEX_FUNC_LEQUAL: return ref <= d;
   case TEX_FUNC_GREATER: return ref > d;
   case TEX_FUNC_NOTEQUAL: return ref != d;
   case TEX_FUNC_GEQUAL: return ref >= d;
   default: return true;
   }
}

/* An integer (a texel count, a floor) as a register of the number system.
 * Every such integer is exact in binary32, so the conversion is too. */
static inline ns_val tex_ns_int(const struct tex_unit *u, int64_t i)
{
   return u->ns->from_float(u->ns, (float)i, u->stats);
}

/* tex_addr.c */
tex_addr_fn tex_addr_choose(enum tex_wrap wrap, enum tex_filter filter);
bool tex_addr_mirrored(const struct tex_unit *u, unsigned axis, ns_val c);
void tex_addr_cube_seamless(const struct tex_unit *u, const struct tex_axis *ax, ns_val c,
                            struct tex_addr *a);


/* tex_lod.c */
int32_t tex_lod_diffs(const struct tex_unit *u, ns_val c[TEX_QUAD][3], unsigned dims);
int32_t tex_lod_derivs(const struct tex_unit *u, const float ddx[3], const float ddy[3],
                       unsigned dims, const ns_val scale[3]);
/* The same on derivatives already in the number system. */
int32_t tex_lod_grads(const struct tex_unit *u, const ns_val dx[3], const ns_val dy[3],
                      unsigned dims, const ns_val scale[3]);

/* tex_fast.c: the specialised address stage of a gather, or NULL. */
tex_footprint_fn tex_fast_footprint_choose(const struct tex_unit *u, bool scalar);
/* tex_fast.c: the specialised quad of the unit's number system, or NULL;
 * the lanes' (lanes.h) where there is one, unless scalar. */
tex_quad_fn tex_fast_choose(const struct tex_unit *u, bool scalar, bool noskip, bool *nolod,
                            tex_quad2_fn *pair, tex_quad4_fn *four);

/* tex_filter.c */
tex_level_fn tex_level_choose(unsigned dims, enum tex_filter filter, enum tex_reduction r);
tex_level_fn tex_level_cube_seamless(enum tex_reduction r);
void tex_cube_taps(const struct tex_unit *u, unsigned level, const int32_t x[2],
                   const int32_t y[2], int layer, float ref, float t[4][4]);
tex_tap_fn tex_tap_choose(bool compare);
void tex_lerp4(float o[4], const float a[4], const float b[4], uint32_t w);   /* w: 2^-8 */
/* the min/max reductions' combination of two taps or levels: b takes part
 * where its weight w is not zero */
void tex_min4(float o[4], const float a[4], const float b[4], uint32_t w);
void tex_max4(float o[4], const float a[4], const float b[4], uint32_t w);

/* A float LOD value (bias, clamp, explicit) as the LOD register. */
static inline int32_t tex_lod_fixed(float v)
{
   if (!(v > -1000.0f))
      v = -1000.0f;
   if (v > 1000.0f)
      v = 1000.0f;
   return (int32_t)(v * TEX_LOD_ONE + (v < 0 ? -0.5f : 0.5f));
}

#endif
