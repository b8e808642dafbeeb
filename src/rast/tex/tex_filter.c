/*
 * Taps and filtering of one level: addresses from the per-axis functions,
 * texels from the bound fetch function (or the border colour), shadow
 * comparison per tap before filtering (as GL's percentage-closer rule
 * allows and llvmpipe does), bilinear blend with TEX_WEIGHT_BITS weights,
 * or the least or greatest tap (min/max reduction).  One function per
 * (dimensionality, filter, reduction), chosen at bind.
 */
#include <string.h>
#include "rast/tex/tex_priv.h"

static void tap_color(const struct tex_unit *u, const struct tex_level *lv, int x, int y, int z,
                      float ref, float out[4])
{
   (void)ref;
   if ((x | y | z) < 0) {
      memcpy(out, u->samp.border, 4 * sizeof(float));
      return;
   }
   u->fetch(&u->view, lv, x, y, z, out);
}

/* The border's depth goes through the comparison too. */
static void tap_shadow(const struct tex_unit *u, const struct tex_level *lv, int x, int y, int z,
                       float ref, float out[4])
{
   float d;
   if ((x | y | z) < 0) {
      d = u->samp.border[0];
   } else {
      u->fetch(&u->view, lv, x, y, z, out);
      d = out[0];
   }
   out[0] = out[1] = out[2] = tex_compare(u->samp.func, ref, d) ? 1.0f : 0.0f;
   out[3] = 1.0f;
}

tex_tap_fn tex_tap_choose(bool cmp)
{
   return cmp ? tap_shadow : tap_color;
}

static inline void lerp4(float o[4], const float a[4], const float b[4], uint32_t w)
{
   const float f = (float)w * (1.0f / TEX_WEIGHT_ONE);
   for (unsigned c = 0; c < 4; c++)
      o[c] = a[c] + f * (b[c] - a[c]);
}

/* Min/max reduction (ARB_texture_filter_minmax), in place of a lerp: the
 * second tap takes part where its weight is not zero, as llvmpipe's
 * lp_build_sample_min/max take it (a weight below 2^-TEX_WEIGHT_BITS is the
 * unit's zero); the first always does, its weight never being zero. */
static inline void min4(float o[4], const float a[4], const float b[4], uint32_t w)
{
   for (unsigned c = 0; c < 4; c++)
      o[c] = w && b[c] < a[c] ? b[c] : a[c];
}

static inline void max4(float o[4], const float a[4], const float b[4], uint32_t w)
{
   for (unsigned c = 0; c < 4; c++)
      o[c] = w && b[c] > a[c] ? b[c] : a[c];
}

static void level_1d_nearest(const struct tex_unit *u, unsigned level, const ns_val c[3],
                             int layer, float ref, float out[4])
{
   struct tex_addr A;
   u->addr[TEX_FILTER_NEAREST][0](u, &u->axis[level][0], c[0], &A);
   u->tap(u, &u->view.level[level], A.i0, 0, layer, ref, out);
}

static void level_2d_nearest(const struct tex_unit *u, unsigned level, const ns_val c[3],
                             int layer, float ref, float out[4])
{
   struct tex_addr A, B;
   u->addr[TEX_FILTER_NEAREST][0](u, &u->axis[level][0], c[0], &A);
   u->addr[TEX_FILTER_NEAREST][1](u, &u->axis[level][1], c[1], &B);
   u->tap(u, &u->view.level[level], A.i0, B.i0, layer, ref, out);
}

static void level_3d_nearest(const struct tex_unit *u, unsigned level, const ns_val c[3],
                             int layer, float ref, float out[4])
{
   struct tex_addr A, B, C;
   (void)layer;
   u->addr[TEX_FILTER_NEAREST][0](u, &u->axis[level][0], c[0], &A);
   u->addr[TEX_FILTER_NEAREST][1](u, &u->axis[level][1], c[1], &B);
   u->addr[TEX_FILTER_NEAREST][2](u, &u->axis[level][2], c[2], &C);
   u->tap(u, &u->view.level[level], A.i0, B.i0, C.i0, ref, out);
}

/* The LINEAR level functions, one set per way of combining taps
 * (lerp4: the weighted average; min4, max4: the reductions). */
#define LEVEL_LINEAR(suffix, combine)                                                    \
static void level_1d_##suffix(const struct tex_unit *u, unsigned level, const ns_val c[3], \
                              int layer, float ref, float out[4])                        \
{                                                                                        \
   const struct tex_level *lv = &u->view.level[level];                                   \
   struct tex_addr A;                                                                    \
   float t0[4], t1[4];                                                                   \
   u->addr[TEX_FILTER_LINEAR][0](u, &u->axis[level][0], c[0], &A);                       \
   u->tap(u, lv, A.i0, 0, layer, ref, t0);                                               \
   u->tap(u, lv, A.i1, 0, layer, ref, t1);                                               \
   combine(out, t0, t1, A.w);                                                            \
}                                                                                        \
                                                                                         \
static void level_2d_##suffix(const struct tex_unit *u, unsigned level, const ns_val c[3], \
                              int layer, float ref, float out[4])                        \
{                                                                                        \
   const struct tex_level *lv = &u->view.level[level];                                   \
   struct tex_addr A, B;                                                                 \
   float t[4][4], a[4], b[4];                                                            \
   u->addr[TEX_FILTER_LINEAR][0](u, &u->axis[level][0], c[0], &A);                       \
   u->addr[TEX_FILTER_LINEAR][1](u, &u->axis[level][1], c[1], &B);                       \
   u->tap(u, lv, A.i0, B.i0, layer, ref, t[0]);                                          \
   u->tap(u, lv, A.i1, B.i0, layer, ref, t[1]);                                          \
   u->tap(u, lv, A.i0, B.i1, layer, ref, t[2]);                                          \
   u->tap(u, lv, A.i1, B.i1, layer, ref, t[3]);                                          \
   combine(a, t[0], t[1], A.w);                                                          \
   combine(b, t[2], t[3], A.w);                                                          \
   combine(out, a, b, B.w);                                                              \
}                                                                                        \
                                                                                         \
static void level_3d_##suffix(const struct tex_unit *u, unsigned level, const ns_val c[3], \
                              int layer, float ref, float out[4])                        \
{                                                                                        \
   const struct tex_level *lv = &u->view.level[level];                                   \
   struct tex_addr A, B, C;                                                              \
   float t[8][4], a[4], b[4], e[4], f[4], g[4];                                          \
   (void)layer;                                                                          \
   u->addr[TEX_FILTER_LINEAR][0](u, &u->axis[level][0], c[0], &A);                       \
   u->addr[TEX_FILTER_LINEAR][1](u, &u->axis[level][1], c[1], &B);                       \
   u->addr[TEX_FILTER_LINEAR][2](u, &u->axis[level][2], c[2], &C);                       \
   for (unsigned k = 0; k < 8; k++)                                                      \
      u->tap(u, lv, k & 1 ? A.i1 : A.i0, k & 2 ? B.i1 : B.i0, k & 4 ? C.i1 : C.i0, ref,  \
             t[k]);                                                                      \
   combine(a, t[0], t[1], A.w);                                                          \
   combine(b, t[2], t[3], A.w);                                                          \
   combine(e, a, b, B.w);                                                                \
   combine(a, t[4], t[5], A.w);                                                          \
   combine(b, t[6], t[7], A.w);                                                          \
   combine(f, a, b, B.w);                                                                \
   combine(g, e, f, C.w);                                                                \
   memcpy(out, g, sizeof(g));                                                            \
}

LEVEL_LINEAR(linear, lerp4)
LEVEL_LINEAR(min, min4)
LEVEL_LINEAR(max, max4)

/* The four taps of a seamless cube face's bilinear footprint, in the
 * order (x0, y0), (x1, y0), (x0, y1), (x1, y1): those beyond an edge read
 * from the face across it (tex_cube_across); at a corner, where the fourth
 * tap has no texel, it is the mean of the three that have one, as llvmpipe
 * and the Khronos suite's reference take it (GL leaves it open).  The
 * address unit leaves the indices unclamped (tex_addr_cube_seamless).
 * `layer` is 6 L + face: a cube map array's faces cross to the faces of
 * their own cube. */
void tex_cube_taps(const struct tex_unit *u, unsigned level, const int32_t x[2],
                   const int32_t y[2], int layer, float ref, float t[4][4])
{
   const unsigned face = (unsigned)layer % 6u;
   const int base = layer - (int)face;
   const struct tex_level *lv = &u->view.level[level];
   const int32_t size = u->axis[level][0].size;
   int corner = -1;
   for (unsigned k = 0; k < 4; k++) {
      const int32_t tx = x[k & 1], ty = y[k >> 1];
      unsigned f;
      int32_t fx, fy;
      if (tx >= 0 && tx < size && ty >= 0 && ty < size)
         u->tap(u, lv, tx, ty, layer, ref, t[k]);
      else if (tex_cube_across(face, size, tx, ty, &f, &fx, &fy))
         u->tap(u, lv, fx, fy, base + (int)f, ref, t[k]);
      else
         corner = (int)k;
   }
   if (corner >= 0) {
      const unsigned c = (unsigned)corner;
      for (unsigned ch = 0; ch < 4; ch++)
         t[c][ch] = (t[c ^ 1][ch] + t[c ^ 2][ch] + t[c ^ 3][ch]) * (1.0f / 3.0f);
   }
}

/* A seamless cube face, LINEAR (GL ES 3.0 3.8.9.1); `layer` is the face,
 * 6 L + face in a cube map array. */
#define LEVEL_CUBE_SEAMLESS(suffix, combine)                                                \
static void level_cube_##suffix(const struct tex_unit *u, unsigned level, const ns_val c[3], \
                                int layer, float ref, float out[4])                        \
{                                                                                          \
   struct tex_addr A, B;                                                                   \
   float t[4][4], a[4], b[4];                                                              \
   u->addr[TEX_FILTER_LINEAR][0](u, &u->axis[level][0], c[0], &A);                         \
   u->addr[TEX_FILTER_LINEAR][1](u, &u->axis[level][1], c[1], &B);                         \
   const int32_t x[2] = { A.i0, A.i1 }, y[2] = { B.i0, B.i1 };                             \
   tex_cube_taps(u, level, x, y, layer, ref, t);                                           \
   combine(a, t[0], t[1], A.w);                                                            \
   combine(b, t[2], t[3], A.w);                                                            \
   combine(out, a, b, B.w);                                                                \
}

LEVEL_CUBE_SEAMLESS(seamless, lerp4)
LEVEL_CUBE_SEAMLESS(seamless_min, min4)
LEVEL_CUBE_SEAMLESS(seamless_max, max4)

tex_level_fn tex_level_cube_seamless(enum tex_reduction r)
{
   return r == TEX_REDUCE_MIN ? level_cube_seamless_min
          : r == TEX_REDUCE_MAX ? level_cube_seamless_max : level_cube_seamless;
}

tex_level_fn tex_level_choose(unsigned dims, enum tex_filter filter, enum tex_reduction r)
{
   static const tex_level_fn table[3][4] = {
      { level_1d_nearest, level_1d_linear, level_1d_min, level_1d_max },
      { level_2d_nearest, level_2d_linear, level_2d_min, level_2d_max },
      { level_3d_nearest, level_3d_linear, level_3d_min, level_3d_max },
   };
   const unsigned k = filter == TEX_FILTER_NEAREST ? 0
                      : r == TEX_REDUCE_MIN ? 2 : r == TEX_REDUCE_MAX ? 3 : 1;
   return table[(dims < 1 ? 1 : dims > 3 ? 3 : dims) - 1][k];
}

void tex_min4(float o[4], const float a[4], const float b[4], uint32_t w)
{
   min4(o, a, b, w);
}

void tex_max4(float o[4], const float a[4], const float b[4], uint32_t w)
{
   max4(o, a, b, w);
}

void tex_lerp4(float o[4], const float a[4], const float b[4], uint32_t w)
{
   lerp4(o, a, b, w);
}
