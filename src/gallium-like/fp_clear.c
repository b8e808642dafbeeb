/*
 * Clears and copies: plain memory fills and copies through util, outside
 * the model (a clear is no primitive in the modeled hardware).
 */
#include "util/u_surface.h"
#include "util/u_inlines.h"
#include "draw/draw_context.h"

#include "fp_context.h"

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
         util_clear_render_target(pipe, ps, color, x, y, w, h);
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
         util_clear_depth_stencil(pipe, zs, buffers & PIPE_CLEAR_DEPTHSTENCIL, depth,
                                  stencil, x, y, w, h);
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
   util_clear_render_target(pipe, dst, color, x, y, w, h);
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
   util_clear_depth_stencil(pipe, dst, flags, depth, stencil, x, y, w, h);
}

static void fp_resource_copy_region(struct pipe_context *pipe, struct pipe_resource *dst,
                                    unsigned dst_level, unsigned dstx, unsigned dsty,
                                    unsigned dstz, struct pipe_resource *src,
                                    unsigned src_level, const struct pipe_box *src_box)
{
   draw_flush(fp_context(pipe)->draw);
   util_resource_copy_region(pipe, dst, dst_level, dstx, dsty, dstz, src, src_level, src_box);
}

void fp_init_clear_functions(struct fp_context *fp)
{
   fp->pipe.clear = fp_clear;
   fp->pipe.clear_render_target = fp_clear_render_target;
   fp->pipe.clear_depth_stencil = fp_clear_depth_stencil;
   fp->pipe.resource_copy_region = fp_resource_copy_region;
}
