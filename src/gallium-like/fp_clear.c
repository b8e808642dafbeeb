/*
 * Clears and copies: plain memory fills and copies through util, outside
 * the model (a clear is no primitive in the modeled hardware).
 */
#include "util/u_surface.h"
#include "util/u_inlines.h"
#include "draw/draw_context.h"

#include "fp_context.h"
#include "fp_resource.h"

/* util's clears reach a surface's layers: a multisampled surface is
 * cleared plane by plane, each plane as the layer it is stored as. */
static void clear_color_planes(struct pipe_context *pipe, struct pipe_surface *ps,
                               const union pipe_color_union *color, unsigned x, unsigned y,
                               unsigned w, unsigned h)
{
   const unsigned n = fp_resource_samples(ps->texture);
   if (n == 1) {
      util_clear_render_target(pipe, ps, color, x, y, w, h);
      return;
   }
   struct pipe_surface plane = *ps;
   for (unsigned l = ps->u.tex.first_layer; l <= ps->u.tex.last_layer; l++)
      for (unsigned s = 0; s < n; s++) {
         plane.u.tex.first_layer = plane.u.tex.last_layer = l * n + s;
         util_clear_render_target(pipe, &plane, color, x, y, w, h);
      }
}

static void clear_zs_planes(struct pipe_context *pipe, struct pipe_surface *ps, unsigned flags,
                            double depth, unsigned stencil, unsigned x, unsigned y,
                            unsigned w, unsigned h)
{
   const unsigned n = fp_resource_samples(ps->texture);
   if (n == 1) {
      util_clear_depth_stencil(pipe, ps, flags, depth, stencil, x, y, w, h);
      return;
   }
   struct pipe_surface plane = *ps;
   for (unsigned l = ps->u.tex.first_layer; l <= ps->u.tex.last_layer; l++)
      for (unsigned s = 0; s < n; s++) {
         plane.u.tex.first_layer = plane.u.tex.last_layer = l * n + s;
         util_clear_depth_stencil(pipe, &plane, flags, depth, stencil, x, y, w, h);
      }
}

static void fp_clear(struct pipe_context *pipe, unsigned buffers,
                     const struct pipe_scissor_state *scissor,
                     const union pipe_color_union *color, double depth, unsigned stencil)
{
   struct fp_context *fp = fp_context(pipe);
   const struct pipe_framebuffer_state *fb = &fp->framebuffer;

   if (!fp_check_render_cond(fp))
      return;
   draw_flush(fp->draw);

   for (unsigned i = 0; i < fb->nr_cbufs; i++) {
      struct pipe_surface *ps = fb->cbufs[i];
      if (!ps || !(buffers & (PIPE_CLEAR_COLOR0 << i)))
         continue;
      unsigned x = 0, y = 0, w = ps->width, h = ps->height;
      if (scissor) {
         x = MIN2(scissor->minx, w);
         y = MIN2(scissor->miny, h);
         w = MIN2(scissor->maxx, w) > x ? MIN2(scissor->maxx, w) - x : 0;
         h = MIN2(scissor->maxy, h) > y ? MIN2(scissor->maxy, h) - y : 0;
      }
      if (w && h)
         clear_color_planes(pipe, ps, color, x, y, w, h);
   }

   struct pipe_surface *zs = fb->zsbuf;
   if (zs && (buffers & PIPE_CLEAR_DEPTHSTENCIL)) {
      unsigned x = 0, y = 0, w = zs->width, h = zs->height;
      if (scissor) {
         x = MIN2(scissor->minx, w);
         y = MIN2(scissor->miny, h);
         w = MIN2(scissor->maxx, w) > x ? MIN2(scissor->maxx, w) - x : 0;
         h = MIN2(scissor->maxy, h) > y ? MIN2(scissor->maxy, h) - y : 0;
      }
      if (w && h)
         clear_zs_planes(pipe, zs, buffers & PIPE_CLEAR_DEPTHSTENCIL, depth, stencil, x, y, w,
                         h);
   }
}

static void fp_clear_render_target(struct pipe_context *pipe, struct pipe_surface *dst,
                                   const union pipe_color_union *color, unsigned x, unsigned y,
                                   unsigned w, unsigned h, bool render_condition_enabled)
{
   struct fp_context *fp = fp_context(pipe);
   if (render_condition_enabled && !fp_check_render_cond(fp))
      return;
   draw_flush(fp->draw);
   clear_color_planes(pipe, dst, color, x, y, w, h);
}

static void fp_clear_depth_stencil(struct pipe_context *pipe, struct pipe_surface *dst,
                                   unsigned flags, double depth, unsigned stencil,
                                   unsigned x, unsigned y, unsigned w, unsigned h,
                                   bool render_condition_enabled)
{
   struct fp_context *fp = fp_context(pipe);
   if (render_condition_enabled && !fp_check_render_cond(fp))
      return;
   draw_flush(fp->draw);
   clear_zs_planes(pipe, dst, flags, depth, stencil, x, y, w, h);
}

static void fp_resource_copy_region(struct pipe_context *pipe, struct pipe_resource *dst,
                                    unsigned dst_level, unsigned dstx, unsigned dsty,
                                    unsigned dstz, struct pipe_resource *src,
                                    unsigned src_level, const struct pipe_box *src_box)
{
   draw_flush(fp_context(pipe)->draw);
   const unsigned n = fp_resource_samples(src);
   if (n == 1 || fp_resource_samples(dst) != n || src_box->depth != 1) {
      util_resource_copy_region(pipe, dst, dst_level, dstx, dsty, dstz, src, src_level,
                                src_box);
      return;
   }
   /* multisampled: plane by plane, each plane as the layer it is stored as */
   for (unsigned s = 0; s < n; s++) {
      struct pipe_box box = *src_box;
      box.z = src_box->z * (int)n + (int)s;
      util_resource_copy_region(pipe, dst, dst_level, dstx, dsty, dstz * n + s, src,
                                src_level, &box);
   }
}

/* glClearTexImage: a multisampled layer is its samples' planes, one after
 * the other (fp_resource.h), so the box covers them all. */
static void fp_clear_texture(struct pipe_context *pipe, struct pipe_resource *res, unsigned level,
                             const struct pipe_box *box, const void *data)
{
   struct pipe_box b = *box;
   const unsigned samples = fp_resource_samples(res);
   b.z *= (int)samples;
   b.depth *= (int)samples;
   util_clear_texture(pipe, res, level, &b, data);
}

void fp_init_clear_functions(struct fp_context *fp)
{
   fp->pipe.clear_texture = fp_clear_texture;
   fp->pipe.clear = fp_clear;
   fp->pipe.clear_render_target = fp_clear_render_target;
   fp->pipe.clear_depth_stencil = fp_clear_depth_stencil;
   fp->pipe.resource_copy_region = fp_resource_copy_region;
}
