/*
 * pipe->blit on the CPU: scaled nearest/linear, format conversion through
 * float unpack/pack, Z and S masks, scissor.  (util_blitter would draw
 * through the model, turning copies into modeled primitives.)
 *
 * Multisampled images: a blit between two of them copies sample to sample,
 * a blit into one writes every sample, and a blit from one into a
 * single-sampled image resolves it: colour the mean of the samples (as
 * util_blitter's resolve shader averages them), depth and stencil sample 0.
 */
#include <math.h>
#include <string.h>

#include "util/u_math.h"
#include "util/u_surface.h"
#include "util/u_inlines.h"
#include "util/format/u_format.h"
#include "draw/draw_context.h"

#include "fp_context.h"
#include "fp_resource.h"

struct fp_blit_image {
   struct pipe_resource *res;
   enum pipe_format format;
   unsigned level, width, height, depth;   /* depth: slices or layers */
   const struct util_format_description *desc;
   util_format_fetch_rgba_func_ptr fetch;
   unsigned samples;                       /* planes a layer (fp_resource_samples) */
   unsigned sample;                        /* the plane read or written */
   bool resolve;                           /* colour fetches average every sample */
};

static void fp_blit_image_init(struct fp_blit_image *im, struct pipe_resource *res,
                               unsigned level, enum pipe_format format)
{
   im->res = res;
   im->format = format;
   im->level = level;
   im->width = u_minify(res->width0, level);
   im->height = res->target == PIPE_TEXTURE_1D_ARRAY ? res->array_size
                                                     : u_minify(res->height0, level);
   im->depth = res->target == PIPE_TEXTURE_3D ? u_minify(res->depth0, level)
             : res->target == PIPE_TEXTURE_1D_ARRAY ? 1 : res->array_size;
   im->desc = util_format_description(format);
   im->fetch = util_format_fetch_rgba_func(format);
   im->samples = fp_resource_samples(res);
   im->sample = 0;
   im->resolve = false;
}

static uint8_t *fp_blit_texel_ptr(const struct fp_blit_image *im, int x, int y, int z)
{
   struct fp_resource *r = fp_resource(im->res);
   const struct util_format_description *d = im->desc;
   if (im->res->target == PIPE_TEXTURE_1D_ARRAY) {
      z = y;
      y = 0;
   }
   z = z * (int)im->samples + (int)im->sample;
   return r->data + r->level_offset[im->level] + (size_t)z * r->img_stride[im->level] +
          (size_t)(y / d->block.height) * r->stride[im->level] +
          (size_t)(x / d->block.width) * (d->block.bits / 8);
}

static void fp_blit_fetch_one(const struct fp_blit_image *im, int x, int y, int z,
                              float rgba[4])
{
   const uint8_t *p = fp_blit_texel_ptr(im, x, y, z);
   if (im->fetch)
      im->fetch(rgba, p, x % im->desc->block.width, y % im->desc->block.height);
   else
      util_format_unpack_rgba(im->format, rgba, p, 1);
}

static void fp_blit_fetch(const struct fp_blit_image *im, int x, int y, int z, float rgba[4])
{
   x = CLAMP(x, 0, (int)im->width - 1);
   y = CLAMP(y, 0, (int)im->height - 1);
   z = CLAMP(z, 0, (int)im->depth - 1);
   if (!im->resolve) {
      fp_blit_fetch_one(im, x, y, z, rgba);
      return;
   }
   struct fp_blit_image one = *im;
   float sum[4] = { 0, 0, 0, 0 }, c[4];
   for (one.sample = 0; one.sample < im->samples; one.sample++) {
      fp_blit_fetch_one(&one, x, y, z, c);
      for (unsigned ch = 0; ch < 4; ch++)
         sum[ch] += c[ch];
   }
   for (unsigned ch = 0; ch < 4; ch++)
      rgba[ch] = sum[ch] / (float)im->samples;
}

static float fp_blit_fetch_z(const struct fp_blit_image *im, int x, int y, int z)
{
   x = CLAMP(x, 0, (int)im->width - 1);
   y = CLAMP(y, 0, (int)im->height - 1);
   z = CLAMP(z, 0, (int)im->depth - 1);
   float d;
   util_format_unpack_z_float(im->format, &d, fp_blit_texel_ptr(im, x, y, z), 1);
   return d;
}

/*
 * Bilinear at (sx, sy), and trilinear through the slices of a 3D source, as
 * util_blitter's linear sampler does: mipmap generation of a 3D texture must
 * average pairs of slices, not pick one (piglit fbo-generatemipmap-3d).
 * Layers of arrays and cube faces are never filtered across.  depth_only
 * filters the Z value of a depth format instead of colour.
 */
static void fp_blit_linear(const struct fp_blit_image *src, float sx, float sy, float sz,
                           bool depth_only, float c[4])
{
   float u = sx - 0.5f, v = sy - 0.5f;
   int x0 = (int)floorf(u), y0 = (int)floorf(v), z0 = (int)floorf(sz);
   float fu = u - x0, fv = v - y0, fw = 0.0f;
   unsigned slices = 1;
   if (src->res->target == PIPE_TEXTURE_3D) {
      float w = sz - 0.5f;
      z0 = (int)floorf(w);
      fw = w - z0;
      slices = 2;
   }
   float s[2][4];
   for (unsigned k = 0; k < slices; k++) {
      float t[4][4];
      for (unsigned i = 0; i < 4; i++) {
         int x = x0 + (int)(i & 1), y = y0 + (int)(i >> 1);
         if (depth_only)
            t[i][0] = t[i][1] = t[i][2] = t[i][3] = fp_blit_fetch_z(src, x, y, z0 + (int)k);
         else
            fp_blit_fetch(src, x, y, z0 + (int)k, t[i]);
      }
      for (unsigned ch = 0; ch < 4; ch++) {
         float a = t[0][ch] + fu * (t[1][ch] - t[0][ch]);
         float b = t[2][ch] + fu * (t[3][ch] - t[2][ch]);
         s[k][ch] = a + fv * (b - a);
      }
   }
   for (unsigned ch = 0; ch < 4; ch++)
      c[ch] = slices == 1 ? s[0][ch] : s[0][ch] + fw * (s[1][ch] - s[0][ch]);
}

/* sz: the source's z coordinate in slices (centre of slice k is k + 0.5). */
static void fp_blit_color(const struct fp_blit_image *src, const struct fp_blit_image *dst,
                          const struct pipe_blit_info *info, float sx, float sy, float sz,
                          int dx, int dy, int dz)
{
   float c[4];
   if (info->filter == PIPE_TEX_FILTER_LINEAR && src->fetch)
      fp_blit_linear(src, sx, sy, sz, false, c);
   else
      fp_blit_fetch(src, (int)floorf(sx), (int)floorf(sy), (int)floorf(sz), c);

   uint8_t *p = fp_blit_texel_ptr(dst, dx, dy, dz);
   unsigned mask = info->mask & PIPE_MASK_RGBA;
   if (mask != PIPE_MASK_RGBA || info->alpha_blend) {
      float old[4];
      util_format_unpack_rgba(dst->format, old, p, 1);
      if (info->alpha_blend) {
         for (unsigned ch = 0; ch < 3; ch++)
            c[ch] = c[ch] * c[3] + old[ch] * (1.0f - c[3]);
      }
      for (unsigned ch = 0; ch < 4; ch++)
         if (!(mask & (1u << ch)))
            c[ch] = old[ch];
   }
   util_format_pack_rgba(dst->format, p, c, 1);
}

/*
 * LINEAR filters depth as util_blitter does for a scaled blit of a source
 * without stencil (mipmap generation of depth textures averages 2x2, piglit
 * fbo-generatemipmap-formats GL_ARB_depth_texture); stencil is never filtered.
 */
static void fp_blit_zs(const struct fp_blit_image *src, const struct fp_blit_image *dst,
                       const struct pipe_blit_info *info, float sx, float sy, float sz,
                       int dx, int dy, int dz)
{
   int ix = CLAMP((int)floorf(sx), 0, (int)src->width - 1);
   int iy = CLAMP((int)floorf(sy), 0, (int)src->height - 1);
   int iz = CLAMP((int)floorf(sz), 0, (int)src->depth - 1);
   const uint8_t *s = fp_blit_texel_ptr(src, ix, iy, iz);
   uint8_t *d = fp_blit_texel_ptr(dst, dx, dy, dz);
   unsigned mask = info->mask;
   /* util's Z and S packers keep the other component of combined formats. */
   if ((mask & PIPE_MASK_Z) && util_format_has_depth(src->desc) &&
       util_format_has_depth(dst->desc)) {
      float z;
      if (info->filter == PIPE_TEX_FILTER_LINEAR && !util_format_has_stencil(src->desc)) {
         float c[4];
         fp_blit_linear(src, sx, sy, sz, true, c);
         z = c[0];
      } else {
         util_format_unpack_z_float(src->format, &z, s, 1);
      }
      util_format_pack_z_float(dst->format, d, &z, 1);
   }
   if ((mask & PIPE_MASK_S) && util_format_has_stencil(src->desc) &&
       util_format_has_stencil(dst->desc)) {
      uint8_t st;
      util_format_unpack_s_8uint(src->format, &st, s, 1);
      util_format_pack_s_8uint(dst->format, d, &st, 1);
   }
}

static bool fp_blit_is_copy(const struct pipe_blit_info *info)
{
   const struct util_format_description *d = util_format_description(info->dst.format);
   unsigned full = util_format_is_depth_or_stencil(info->dst.format)
      ? ((util_format_has_depth(d) ? PIPE_MASK_Z : 0) | (util_format_has_stencil(d) ? PIPE_MASK_S : 0))
      : PIPE_MASK_RGBA;
   return info->src.format == info->dst.format &&
          info->src.resource->format == info->dst.resource->format &&
          info->src.format == info->src.resource->format &&
          fp_resource_samples(info->src.resource) == 1 &&
          fp_resource_samples(info->dst.resource) == 1 &&
          info->src.box.width == info->dst.box.width &&
          info->src.box.height == info->dst.box.height &&
          info->src.box.depth == info->dst.box.depth &&
          (info->mask & full) == full && !info->scissor_enable && !info->alpha_blend;
}

static void fp_blit(struct pipe_context *pipe, const struct pipe_blit_info *info)
{
   struct fp_context *fp = fp_context(pipe);
   struct fp_blit_image src, dst;

   if (info->render_condition_enable && !fp_check_render_cond(fp))
      return;
   draw_flush(fp->draw);
   if (!info->src.resource || !info->dst.resource ||
       !fp_resource(info->src.resource)->data || !fp_resource(info->dst.resource)->data)
      return;
   fp_resource_sync_front(info->src.resource);
   fp_resource_sync_front(info->dst.resource);

   if (fp_blit_is_copy(info)) {
      util_resource_copy_region(pipe, info->dst.resource, info->dst.level, info->dst.box.x,
                                info->dst.box.y, info->dst.box.z, info->src.resource,
                                info->src.level, &info->src.box);
      return;
   }

   fp_blit_image_init(&src, info->src.resource, info->src.level, info->src.format);
   fp_blit_image_init(&dst, info->dst.resource, info->dst.level, info->dst.format);
   if (dst.desc->block.width != 1 || dst.desc->block.height != 1)
      return;   /* never a render target: the screen does not offer it */

   bool zs = util_format_is_depth_or_stencil(info->dst.format);
   const struct pipe_box *db = &info->dst.box, *sb = &info->src.box;
   int x0 = db->x, y0 = db->y, x1 = db->x + db->width, y1 = db->y + db->height;
   if (info->scissor_enable) {
      x0 = MAX2(x0, (int)info->scissor.minx);
      y0 = MAX2(y0, (int)info->scissor.miny);
      x1 = MIN2(x1, (int)info->scissor.maxx);
      y1 = MIN2(y1, (int)info->scissor.maxy);
   }
   x0 = MAX2(x0, 0);
   y0 = MAX2(y0, 0);
   x1 = MIN2(x1, (int)dst.width);
   y1 = MIN2(y1, (int)dst.height);
   if (db->width <= 0 || db->height <= 0 || db->depth <= 0)
      return;

   const float scale_x = (float)sb->width / db->width;
   const float scale_y = (float)sb->height / db->height;
   const float scale_z = (float)sb->depth / db->depth;

   /* an integer image's samples are not averaged: sample 0, as GL allows */
   src.resolve = src.samples > 1 && dst.samples == 1 && !zs &&
                 !util_format_is_pure_integer(src.format);
   for (dst.sample = 0; dst.sample < dst.samples; dst.sample++) {
      src.sample = src.samples > 1 && dst.samples > 1 ? dst.sample : 0;
      for (int z = db->z; z < db->z + db->depth; z++) {
         if (z < 0 || z >= (int)dst.depth)
            continue;
         float sz = sb->z + (z - db->z + 0.5f) * scale_z;
         for (int y = y0; y < y1; y++) {
            float sy = sb->y + (y - db->y + 0.5f) * scale_y;
            for (int x = x0; x < x1; x++) {
               float sx = sb->x + (x - db->x + 0.5f) * scale_x;
               if (zs)
                  fp_blit_zs(&src, &dst, info, sx, sy, sz, x, y, z);
               else if (info->mask & PIPE_MASK_RGBA)
                  fp_blit_color(&src, &dst, info, sx, sy, sz, x, y, z);
            }
         }
      }
   }
}

void fp_init_blit_functions(struct fp_context *fp)
{
   fp->pipe.blit = fp_blit;
}
