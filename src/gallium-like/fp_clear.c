/*
 * Clears and copies: plain memory fills and copies through util, outside
 * the model (a clear is no primitive in the modeled hardware).
 */
#include "util/u_surface.h"
#include "util/u_inlines.h"
#include "util/u_pack_color.h"
#include "util/format/u_format.h"
#include "draw/draw_context.h"

#include "fp_context.h"
#include "fp_resource.h"
#include "fp_screen.h"

/* A clear as large as this divides its rows between the model's threads
 * where they already run (rast_run_on_threads), in equal stretches from the
 * top as the batches' stretches go: each thread writes about the rows it
 * will draw, into its own cache, and the fill of a full-window target no
 * longer waits on one core.  Smaller ones are not worth waking the
 * workers. */
#define FP_CLEAR_THREADED_PIXELS (64 * 1024)

/* A mapped box filled by rows, as util_clear_render_target and
 * util_clear_depth_stencil fill it (the same util functions, the same
 * bytes), thread t of n taking the t-th stretch of rows. */
struct fill_job {
   ubyte *map;
   enum pipe_format format;
   unsigned stride, layer_stride, width, height, layers;
   bool zs, need_rmw;
   unsigned zs_flags;
   uint64_t zstencil;
   union util_color color;
};

static void fill_rows(void *arg, unsigned t, unsigned n)
{
   struct fill_job *j = arg;
   const unsigned y0 = (unsigned)((uint64_t)j->height * t / n);
   const unsigned y1 = (unsigned)((uint64_t)j->height * (t + 1) / n);
   if (y1 == y0)
      return;
   if (j->zs)
      util_fill_zs_box(j->map + (size_t)y0 * j->stride, j->format, j->need_rmw, j->zs_flags,
                       j->stride, j->layer_stride, j->width, y1 - y0, j->layers, j->zstencil);
   else
      util_fill_box(j->map, j->format, j->stride, j->layer_stride, 0, y0, 0, j->width, y1 - y0,
                    j->layers, &j->color);
}

/* Whether a clear of ps's w x h box goes to the threads: a plain texture
 * (not a buffer, one sample) of one-pixel blocks, large enough. */
static bool clear_threaded(const struct fp_context *fp, const struct pipe_surface *ps,
                           unsigned w, unsigned h)
{
   return rast_get_threads(fp->rast) > 1 && !(fp->opts->debug & FP_DEBUG_SERIALCLEAR) &&
          ps->texture->target != PIPE_BUFFER &&
          fp_resource_samples(ps->texture) == 1 &&
          util_format_get_blockwidth(ps->format) == 1 &&
          util_format_get_blockheight(ps->format) == 1 &&
          (uint64_t)w * h >= FP_CLEAR_THREADED_PIXELS;
}

/* The box mapped as util maps it, filled on the threads. */
static void clear_on_threads(struct pipe_context *pipe, struct pipe_surface *ps,
                             struct fill_job *j, unsigned x, unsigned y, unsigned w, unsigned h)
{
   struct pipe_transfer *trans;
   const unsigned layers = ps->u.tex.last_layer - ps->u.tex.first_layer + 1;
   j->map = pipe_texture_map_3d(pipe, ps->texture, ps->u.tex.level,
                                j->need_rmw ? PIPE_MAP_READ_WRITE : PIPE_MAP_WRITE, x, y,
                                ps->u.tex.first_layer, w, h, layers, &trans);
   if (!j->map)
      return;
   j->format = ps->format;
   j->stride = trans->stride;
   j->layer_stride = (unsigned)trans->layer_stride;
   j->width = w;
   j->height = h;
   j->layers = layers;
   rast_run_on_threads(fp_context(pipe)->rast, fill_rows, j);
   pipe->texture_unmap(pipe, trans);
}

/* util's clears reach a surface's layers: a multisampled surface is
 * cleared plane by plane, each plane as the layer it is stored as. */
static void clear_color_planes(struct pipe_context *pipe, struct pipe_surface *ps,
                               const union pipe_color_union *color, unsigned x, unsigned y,
                               unsigned w, unsigned h)
{
   const unsigned n = fp_resource_samples(ps->texture);
   if (clear_threaded(fp_context(pipe), ps, w, h)) {
      struct fill_job j = { .zs = false };
      util_pack_color_union(ps->format, &j.color, color);
      clear_on_threads(pipe, ps, &j, x, y, w, h);
      return;
   }
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
   if (clear_threaded(fp_context(pipe), ps, w, h)) {
      /* util_clear_depth_stencil_texture's read-modify-write rule */
      const bool rmw = (flags & PIPE_CLEAR_DEPTHSTENCIL) &&
                       (flags & PIPE_CLEAR_DEPTHSTENCIL) != PIPE_CLEAR_DEPTHSTENCIL &&
                       util_format_is_depth_and_stencil(ps->format);
      struct fill_job j = { .zs = true, .need_rmw = rmw, .zs_flags = flags,
                            .zstencil = util_pack64_z_stencil(ps->format, depth, stencil) };
      clear_on_threads(pipe, ps, &j, x, y, w, h);
      return;
   }
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

/* The rectangle of a surface a clear covers: all of it, or its part inside
 * the scissor; false when that is empty. */
static bool clear_rect(const struct pipe_surface *ps, const struct pipe_scissor_state *scissor,
                       unsigned *x, unsigned *y, unsigned *w, unsigned *h)
{
   *x = *y = 0;
   *w = ps->width;
   *h = ps->height;
   if (scissor) {
      *x = MIN2(scissor->minx, *w);
      *y = MIN2(scissor->miny, *h);
      *w = MIN2(scissor->maxx, *w) > *x ? MIN2(scissor->maxx, *w) - *x : 0;
      *h = MIN2(scissor->maxy, *h) > *y ? MIN2(scissor->maxy, *h) - *y : 0;
   }
   return *w && *h;
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
      unsigned x, y, w, h;
      if (clear_rect(ps, scissor, &x, &y, &w, &h))
         clear_color_planes(pipe, ps, color, x, y, w, h);
   }

   struct pipe_surface *zs = fb->zsbuf;
   if (zs && (buffers & PIPE_CLEAR_DEPTHSTENCIL)) {
      unsigned x, y, w, h;
      if (clear_rect(zs, scissor, &x, &y, &w, &h))
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
