/*
 * Inside the texture unit: what its files share.  Not for the driver.
 */
#ifndef FIXPIPE_TEX_PRIV_H
#define FIXPIPE_TEX_PRIV_H

#include "rast/tex.h"
#include "rast/tex_ns.h"

/* An integer (a texel count, a floor) as a register of the number system.
 * Every such integer is exact in binary32, so the conversion is too. */
static inline ns_val tex_ns_int(const struct tex_unit *u, int64_t i)
{
   return u->ns->from_float(u->ns, (float)i, u->stats);
}

/* tex_addr.c */
tex_addr_fn tex_addr_choose(enum tex_wrap wrap, enum tex_filter filter);

/* tex_lod.c */
int32_t tex_lod_diffs(const struct tex_unit *u, ns_val c[TEX_QUAD][3], unsigned dims);
int32_t tex_lod_derivs(const struct tex_unit *u, const float ddx[3], const float ddy[3],
                       unsigned dims, const ns_val scale[3]);
/* The same on derivatives already in the number system. */
int32_t tex_lod_grads(const struct tex_unit *u, const ns_val dx[3], const ns_val dy[3],
                      unsigned dims, const ns_val scale[3]);

/* tex_fast.c: the specialised quad of the unit's number system, or NULL. */
tex_quad_fn tex_fast_choose(const struct tex_unit *u);

/* tex_filter.c */
tex_level_fn tex_level_choose(unsigned dims, enum tex_filter filter);
tex_tap_fn tex_tap_choose(bool compare);
void tex_lerp4(float o[4], const float a[4], const float b[4], uint32_t w);   /* w: 2^-8 */

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
