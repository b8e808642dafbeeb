/*
 * The framebuffer: gallium surfaces become the model's direct pointers and
 * layouts, chosen here once per set_framebuffer_state.
 */
#include "util/u_inlines.h"
#include "util/u_framebuffer.h"
#include "util/format/u_format.h"
#include "draw/draw_context.h"
#include "draw/draw_private.h"   /* draw->mrd: see fp_set_polygon_offset_unit */

#include "fp_context.h"
#include "fp_format.h"
#include "fp_resource.h"
#include "fp_screen.h"

static uint8_t *fp_surface_base(struct pipe_surface *ps, int *stride)
{
   struct fp_resource *r = fp_resource(ps->texture);
   if (!r->data)
      return NULL;
   if (ps->texture->target == PIPE_BUFFER) {
      *stride = 0;
      return r->data + ps->u.buf.first_element * util_format_get_blocksize(ps->format);
   }
   *stride = (int)r->stride[ps->u.tex.level];
   return fp_resource_image(ps->texture, ps->u.tex.level, ps->u.tex.first_layer);
}

static size_t fp_surface_sample_stride(struct pipe_surface *ps)
{
   if (ps->texture->target == PIPE_BUFFER)
      return 0;
   return fp_resource(ps->texture)->img_stride[ps->u.tex.level];
}

/* A surface of several layers (an array, cube map or 3-D texture attached
 * whole): the layers a geometry shader's gl_Layer picks among, each its
 * samples' planes apart (fp_resource_image). */
static unsigned fp_surface_layers(struct pipe_surface *ps, size_t *layer_stride)
{
   *layer_stride = 0;
   if (ps->texture->target == PIPE_BUFFER)
      return 0;
   *layer_stride = fp_surface_sample_stride(ps) * fp_resource_samples(ps->texture);
   return ps->u.tex.last_layer - ps->u.tex.first_layer + 1;
}

/* draw's polygon-offset stage adds offset_units * mrd to z.  The model
 * resolves depth to 1 / (2^z_bits - 1) whatever the buffer's width, so a
 * unit must be at least that, or an offset of one unit would vanish in the
 * model's Z register (piglit polygon-offset). */
static void fp_set_polygon_offset_unit(struct fp_context *fp, enum pipe_format zs_format)
{
   const struct rast_profile *prof = rast_get_profile(fp->rast);
   draw_set_zs_format(fp->draw, zs_format);
   if (!fp->draw->floating_point_depth) {
      double model_mrd = 1.0 / (double)((1u << prof->z_bits) - 1);
      if (fp->draw->mrd < model_mrd)
         fp->draw->mrd = model_mrd;
   }
}

static void fp_set_framebuffer_state(struct pipe_context *pipe,
                                     const struct pipe_framebuffer_state *fb)
{
   struct fp_context *fp = fp_context(pipe);
   const struct rast_profile *prof = rast_get_profile(fp->rast);
   struct rast_framebuffer rfb;

   draw_flush(fp->draw);
   util_copy_framebuffer_state(&fp->framebuffer, fb);
   /* drawing into a window's front after a swap draws over what it shows */
   for (unsigned i = 0; i < fb->nr_cbufs; i++)
      if (fb->cbufs[i])
         fp_resource_sync_front(fb->cbufs[i]->texture);

   memset(&rfb, 0, sizeof(rfb));
   /* Any size: beyond the profile's X_out range the model draws in tiles. */
   rfb.width = fb->width;
   rfb.height = fb->height;
   rfb.nr_cbufs = MIN2(fb->nr_cbufs, RAST_MAX_CBUFS);
   for (unsigned i = 0; i < rfb.nr_cbufs; i++) {
      struct pipe_surface *ps = fb->cbufs[i];
      struct rast_color_target *ct = &rfb.cbuf[i];
      if (!ps || !ps->texture || !fp_format_color_target(ps->format, ct)) {
         memset(ct, 0, sizeof(*ct));
         continue;
      }
      ct->base = fp_surface_base(ps, &ct->stride);
      ct->sample_stride = fp_surface_sample_stride(ps);
      ct->layers = fp_surface_layers(ps, &ct->layer_stride);
      rfb.samples = MAX2(rfb.samples, fp_resource_samples(ps->texture));
   }
   rfb.zs.layout = RAST_ZS_NONE;
   if (fb->zsbuf && fb->zsbuf->texture) {
      enum rast_zs_layout l = fp_format_zs_layout(fb->zsbuf->format);
      uint8_t *base = l != RAST_ZS_NONE ? fp_surface_base(fb->zsbuf, &rfb.zs.stride) : NULL;
      if (base) {
         rfb.zs.base = base;
         rfb.zs.layout = l;
         rfb.zs.sample_stride = fp_surface_sample_stride(fb->zsbuf);
         rfb.zs.layers = fp_surface_layers(fb->zsbuf, &rfb.zs.layer_stride);
         rfb.samples = MAX2(rfb.samples, fp_resource_samples(fb->zsbuf->texture));
      }
   }
   /* no attachments (GL ES 3.1): the framebuffer's own sample count */
   if (!rfb.samples && fb->samples > 1)
      rfb.samples = fb->samples == RAST_MSAA_SAMPLES ? RAST_MSAA_SAMPLES : 1;
   /* the shader's sample positions and masks follow the sample count */
   if (fp->fb_samples != MAX2(rfb.samples, 1))
      fp->fs_dirty = true;
   fp->fb_samples = MAX2(rfb.samples, 1);
   rast_set_framebuffer(fp->rast, &rfb);
   fp_set_polygon_offset_unit(fp, fb->zsbuf ? fb->zsbuf->format : PIPE_FORMAT_NONE);
}

void fp_init_fb_functions(struct fp_context *fp)
{
   fp->pipe.set_framebuffer_state = fp_set_framebuffer_state;
}
