/*
 * Texel decoders of the formats the modeled unit reads itself (the common
 * GL ES texture formats); the driver's fetch function handles the rest.
 * One function per format, chosen at bind, so the tap loop never switches
 * on the format.
 */
#include <string.h>
#include "rast/tex/tex_priv.h"

static inline const uint8_t *texel_ptr(const struct tex_level *lv, int x, int y, int z,
                                       unsigned bytes)
{
   return lv->data + (size_t)z * lv->img_stride + (size_t)y * lv->row_stride +
          (size_t)x * bytes;
}


static inline unsigned rd16(const uint8_t *p)
{
   return (unsigned)p[0] | (unsigned)p[1] << 8;
}

static void f_rgba8(const struct tex_view_desc *v, const struct tex_level *lv, int x, int y,
                    int z, float o[4])
{
   const uint8_t *p = texel_ptr(lv, x, y, z, 4);
   (void)v;
   o[0] = tex_unorm8(p[0]); o[1] = tex_unorm8(p[1]); o[2] = tex_unorm8(p[2]); o[3] = tex_unorm8(p[3]);
}

static void f_rgbx8(const struct tex_view_desc *v, const struct tex_level *lv, int x, int y,
                    int z, float o[4])
{
   const uint8_t *p = texel_ptr(lv, x, y, z, 4);
   (void)v;
   o[0] = tex_unorm8(p[0]); o[1] = tex_unorm8(p[1]); o[2] = tex_unorm8(p[2]); o[3] = 1.0f;
}

static void f_bgra8(const struct tex_view_desc *v, const struct tex_level *lv, int x, int y,
                    int z, float o[4])
{
   const uint8_t *p = texel_ptr(lv, x, y, z, 4);
   (void)v;
   o[0] = tex_unorm8(p[2]); o[1] = tex_unorm8(p[1]); o[2] = tex_unorm8(p[0]); o[3] = tex_unorm8(p[3]);
}

static void f_bgrx8(const struct tex_view_desc *v, const struct tex_level *lv, int x, int y,
                    int z, float o[4])
{
   const uint8_t *p = texel_ptr(lv, x, y, z, 4);
   (void)v;
   o[0] = tex_unorm8(p[2]); o[1] = tex_unorm8(p[1]); o[2] = tex_unorm8(p[0]); o[3] = 1.0f;
}

static void f_l8(const struct tex_view_desc *v, const struct tex_level *lv, int x, int y,
                 int z, float o[4])
{
   (void)v;
   o[0] = o[1] = o[2] = tex_unorm8(*texel_ptr(lv, x, y, z, 1));
   o[3] = 1.0f;
}

static void f_a8(const struct tex_view_desc *v, const struct tex_level *lv, int x, int y,
                 int z, float o[4])
{
   (void)v;
   o[0] = o[1] = o[2] = 0.0f;
   o[3] = tex_unorm8(*texel_ptr(lv, x, y, z, 1));
}

static void f_i8(const struct tex_view_desc *v, const struct tex_level *lv, int x, int y,
                 int z, float o[4])
{
   (void)v;
   o[0] = o[1] = o[2] = o[3] = tex_unorm8(*texel_ptr(lv, x, y, z, 1));
}

static void f_r8(const struct tex_view_desc *v, const struct tex_level *lv, int x, int y,
                 int z, float o[4])
{
   (void)v;
   o[0] = tex_unorm8(*texel_ptr(lv, x, y, z, 1));
   o[1] = o[2] = 0.0f;
   o[3] = 1.0f;
}

static void f_la8(const struct tex_view_desc *v, const struct tex_level *lv, int x, int y,
                  int z, float o[4])
{
   const uint8_t *p = texel_ptr(lv, x, y, z, 2);
   (void)v;
   o[0] = o[1] = o[2] = tex_unorm8(p[0]);
   o[3] = tex_unorm8(p[1]);
}

/* A field of a packed 16-bit texel as unorm. */
#define UNF(px, shift, bits) ((float)(((px) >> (shift)) & ((1u << (bits)) - 1)) * \
                              (1.0f / (float)((1u << (bits)) - 1)))

static void f_b5g6r5(const struct tex_view_desc *v, const struct tex_level *lv, int x, int y,
                     int z, float o[4])
{
   unsigned p = rd16(texel_ptr(lv, x, y, z, 2));
   (void)v;
   o[0] = UNF(p, 11, 5); o[1] = UNF(p, 5, 6); o[2] = UNF(p, 0, 5); o[3] = 1.0f;
}

static void f_a4b4g4r4(const struct tex_view_desc *v, const struct tex_level *lv, int x,
                       int y, int z, float o[4])
{
   unsigned p = rd16(texel_ptr(lv, x, y, z, 2));
   (void)v;
   o[0] = UNF(p, 12, 4); o[1] = UNF(p, 8, 4); o[2] = UNF(p, 4, 4); o[3] = UNF(p, 0, 4);
}

static void f_b4g4r4a4(const struct tex_view_desc *v, const struct tex_level *lv, int x,
                       int y, int z, float o[4])
{
   unsigned p = rd16(texel_ptr(lv, x, y, z, 2));
   (void)v;
   o[0] = UNF(p, 8, 4); o[1] = UNF(p, 4, 4); o[2] = UNF(p, 0, 4); o[3] = UNF(p, 12, 4);
}

static void f_a1b5g5r5(const struct tex_view_desc *v, const struct tex_level *lv, int x,
                       int y, int z, float o[4])
{
   unsigned p = rd16(texel_ptr(lv, x, y, z, 2));
   (void)v;
   o[0] = UNF(p, 11, 5); o[1] = UNF(p, 6, 5); o[2] = UNF(p, 1, 5); o[3] = (float)(p & 1);
}

static void f_b5g5r5a1(const struct tex_view_desc *v, const struct tex_level *lv, int x,
                       int y, int z, float o[4])
{
   unsigned p = rd16(texel_ptr(lv, x, y, z, 2));
   (void)v;
   o[0] = UNF(p, 10, 5); o[1] = UNF(p, 5, 5); o[2] = UNF(p, 0, 5); o[3] = (float)(p >> 15);
}

static const struct {
   tex_fetch_fn fn;
   unsigned bytes;
} formats[TEX_FMT_COUNT] = {
   [TEX_FMT_CALLBACK] = { NULL, 0 },
   [TEX_FMT_RGBA8] = { f_rgba8, 4 },
   [TEX_FMT_RGBX8] = { f_rgbx8, 4 },
   [TEX_FMT_BGRA8] = { f_bgra8, 4 },
   [TEX_FMT_BGRX8] = { f_bgrx8, 4 },
   [TEX_FMT_L8] = { f_l8, 1 },
   [TEX_FMT_A8] = { f_a8, 1 },
   [TEX_FMT_I8] = { f_i8, 1 },
   [TEX_FMT_R8] = { f_r8, 1 },
   [TEX_FMT_LA8] = { f_la8, 2 },
   [TEX_FMT_B5G6R5] = { f_b5g6r5, 2 },
   [TEX_FMT_A4B4G4R4] = { f_a4b4g4r4, 2 },
   [TEX_FMT_B4G4R4A4] = { f_b4g4r4a4, 2 },
   [TEX_FMT_A1B5G5R5] = { f_a1b5g5r5, 2 },
   [TEX_FMT_B5G5R5A1] = { f_b5g5r5a1, 2 },
};

tex_fetch_fn tex_format_fetch(enum tex_format f)
{
   return f < TEX_FMT_COUNT ? formats[f].fn : NULL;
}

unsigned tex_format_bytes(enum tex_format f)
{
   return f < TEX_FMT_COUNT ? formats[f].bytes : 0;
}

void tex_view_texel(const struct tex_view_desc *v, const int x[TEX_QUAD], const int y[TEX_QUAD],
                    const int z[TEX_QUAD], const int level[TEX_QUAD], float rgba[4][TEX_QUAD])
{
   tex_fetch_fn fetch = tex_format_fetch(v->format);
   if (!fetch)
      fetch = v->fetch;
   for (unsigned p = 0; p < TEX_QUAD; p++) {
      float o[4] = { 0, 0, 0, 0 };
      if (fetch && level[p] >= 0 && (unsigned)level[p] < v->num_levels) {
         const struct tex_level *lv = &v->level[level[p]];
         int zmax = v->target == TEX_TARGET_3D ? lv->d
                    : (v->target == TEX_TARGET_1D_ARRAY || v->target == TEX_TARGET_2D_ARRAY ||
                       v->target == TEX_TARGET_CUBE_ARRAY)
                       ? v->layers : 1;
         int hmax = (v->target == TEX_TARGET_1D || v->target == TEX_TARGET_1D_ARRAY ||
                     v->target == TEX_TARGET_BUFFER) ? 1 : lv->h;
         if (x[p] >= 0 && x[p] < lv->w && y[p] >= 0 && y[p] < hmax && z[p] >= 0 && z[p] < zmax)
            fetch(v, lv, x[p], y[p], z[p], o);
      }
      for (unsigned c = 0; c < 4; c++) {
         unsigned s = v->swizzle[c];
         rgba[c][p] = s < 4 ? o[s] : s == TEX_SWZ_1 ? tex_one(v) : 0.0f;
      }
   }
}
