/*
 * The rasterizer context: state is copied in and marks the context dirty;
 * the front and back ends choose their specialised functions at the next
 * primitive (rast_validate), never per pixel.
 */
#include <stdlib.h>
#include <string.h>
#include "rast/rast_priv.h"
#include "fixed/numsys.h"

/* Every setter flushes the queued primitives first (they were submitted
 * under the old state) and ends here: validate again, and workers copy. */
static void state_changed(struct rast_context *rc)
{
   rc->dirty = true;
   rc->state_serial++;
}

struct rast_context *rast_create(const struct rast_profile *profile)
{
   if (!profile)
      return NULL;
   struct rast_context *rc = calloc(1, sizeof(*rc));
   if (!rc)
      return NULL;
   rc->profile = profile;
   rc->rs.half_pixel_center = true;
   rc->rs.line_width = 1.0f;
   rc->rs.point_size = 1.0f;
   rc->rs.point_quad_rasterization = true;
   for (unsigned i = 0; i < RAST_MAX_VIEWPORTS; i++)
      rc->viewports[i] = (struct rast_scissor){ -(1 << 30), -(1 << 30), 1 << 30, 1 << 30 };
   rc->viewport = rc->viewports[0];
   for (unsigned i = 0; i < RAST_MAX_VIEWPORTS; i++)
      rc->depth_ranges[i] = (struct rast_depth_range){ 0.0f, 1.0f };
   rc->vl.vertex_size = 1;
   rc->texfmt = numsys_default();
   rc->dirty = true;
   rc->band_count = 1;
   rc->band_lo = INT64_MIN;
   rc->band_hi = INT64_MAX;
   rc->counting = true;
   rc->sample_mask = ~0u;
   rc->rows_lo = INT64_MIN;
   rc->rows_hi = INT64_MAX;
   return rc;
}

void rast_destroy(struct rast_context *rc)
{
   if (!rc)
      return;
   rast_set_threads(rc, 1);
   rast_vectors_close(rc);
   rast_front_destroy(rc);
   rast_backend_destroy(rc);
   rast_msaa_destroy(rc);
   free(rc);
}

const struct rast_profile *rast_get_profile(const struct rast_context *rc)
{
   return rc->profile;
}

/* A setter's change starts the next primitives at viewport 0 again. */
static void select_viewport_0(struct rast_context *rc)
{
   rc->vp_index = 0;
   rc->scissor = rc->scissors[0];
   rc->viewport = rc->viewports[0];
}

void rast_set_framebuffer(struct rast_context *rc, const struct rast_framebuffer *fb)
{
   rast_flush(rc);
   rc->fb = *fb;
   state_changed(rc);
}

void rast_set_raster_state(struct rast_context *rc, const struct rast_raster_state *rs)
{
   rast_flush(rc);
   rc->rs = *rs;
   state_changed(rc);
}


void rast_set_scissors(struct rast_context *rc, unsigned first, unsigned n,
                       const struct rast_scissor *sc)
{
   rast_flush(rc);
   for (unsigned i = 0; i < n && first + i < RAST_MAX_VIEWPORTS; i++)
      rc->scissors[first + i] = sc[i];
   select_viewport_0(rc);
   state_changed(rc);
}

void rast_set_scissor(struct rast_context *rc, const struct rast_scissor *sc)
{
   rast_set_scissors(rc, 0, 1, sc);
}

void rast_set_sample_mask(struct rast_context *rc, unsigned mask)
{
   rast_flush(rc);
   rc->sample_mask = mask;
   state_changed(rc);
}

void rast_set_viewports(struct rast_context *rc, unsigned first, unsigned n,
                        const struct rast_scissor *vp)
{
   rast_flush(rc);
   for (unsigned i = 0; i < n && first + i < RAST_MAX_VIEWPORTS; i++)
      rc->viewports[first + i] = vp[i];
   select_viewport_0(rc);
   state_changed(rc);
}

void rast_set_depth_ranges(struct rast_context *rc, unsigned first, unsigned n,
                           const struct rast_depth_range *r)
{
   rast_flush(rc);
   for (unsigned i = 0; i < n && first + i < RAST_MAX_VIEWPORTS; i++)
      rc->depth_ranges[first + i] = r[i];
   select_viewport_0(rc);
   state_changed(rc);
}

void rast_set_viewport(struct rast_context *rc, const struct rast_scissor *vp)
{
   rast_set_viewports(rc, 0, 1, vp);
}

void rast_set_depth_stencil(struct rast_context *rc, const struct rast_depth_stencil_state *dsa)
{
   rast_flush(rc);
   rc->dsa = *dsa;
   state_changed(rc);
}

void rast_set_stencil_ref(struct rast_context *rc, uint8_t front, uint8_t back)
{
   rast_flush(rc);
   rc->stencil_ref[0] = front;
   rc->stencil_ref[1] = back;
   state_changed(rc);
}

void rast_set_blend(struct rast_context *rc, const struct rast_blend_state *blend)
{
   rast_flush(rc);
   rc->blend = *blend;
   state_changed(rc);
}

void rast_set_blend_color(struct rast_context *rc, const float color[4])
{
   rast_flush(rc);
   memcpy(rc->blend_color, color, sizeof(rc->blend_color));
   state_changed(rc);
}

void rast_set_vertex_layout(struct rast_context *rc, const struct rast_vertex_layout *vl)
{
   rast_flush(rc);
   rc->vl = *vl;
   /* Set-up picks a primitive's viewport only from an index in its vertex:
    * a layout without one draws with viewport 0 (GL's, unless a geometry
    * shader writes gl_ViewportIndex), not with the last index seen. */
   select_viewport_0(rc);
   state_changed(rc);
}

void rast_set_shader(struct rast_context *rc, const struct rast_shader *fs)
{
   rast_flush(rc);
   rc->fs = *fs;
   state_changed(rc);
}

void rast_set_options(struct rast_context *rc, unsigned opts)
{
   rast_flush(rc);
   rc->opts = opts;
   state_changed(rc);
}

void rast_set_interp(struct rast_context *rc, unsigned mode)
{
   rast_flush(rc);
   rc->interp = mode;
   state_changed(rc);
}

const char *rast_interp_name(enum rast_interp_mode mode)
{
   switch (mode) {
   case RAST_INTERP_SCANLINE: return "scanline";
   case RAST_INTERP_BARYCENTRIC: return "barycentric";
   case RAST_INTERP_VECTOR: return "vector";
   }
   return NULL;
}

void rast_set_texfmt(struct rast_context *rc, const struct numsys *ns)
{
   rast_flush(rc);
   rc->texfmt = ns ? ns : numsys_default();
   state_changed(rc);
}

const struct rast_stats *rast_get_stats(const struct rast_context *rc)
{
   return &rc->stats;
}

void rast_reset_stats(struct rast_context *rc)
{
   memset(&rc->stats, 0, sizeof(rc->stats));
}
