/*
 * Inside the model: the context shared by setup/scan (the front end) and the
 * fragment back end.  Not for the driver.
 */
#ifndef FIXPIPE_RAST_PRIV_H
#define FIXPIPE_RAST_PRIV_H

#include "rast/rast.h"

struct rast_context;

/* The back end's entry, chosen by rast_backend_validate(): the quad's mask is
 * already clipped to the scissor and the framebuffer. */
typedef void (*rast_quad_func)(struct rast_context *rc, struct rast_quad *q);

struct rast_context {
   const struct rast_profile *profile;
   struct rast_stats stats;

   /* State as the driver set it. */
   struct rast_framebuffer fb;
   struct rast_raster_state rs;
   struct rast_scissor scissor;
   struct rast_depth_stencil_state dsa;
   uint8_t stencil_ref[2];
   struct rast_blend_state blend;
   float blend_color[4];
   struct rast_vertex_layout vl;
   struct rast_shader fs;
   unsigned opts;                   /* RAST_OPT_* */
   const struct numsys *texfmt;     /* never NULL after rast_create */

   bool dirty;                      /* re-validate before the next primitive */

   /* Chosen at validation. */
   struct rast_scissor clip;        /* scissor & framebuffer, max exclusive */
   rast_quad_func quad;             /* back end */
   void *front_priv;                /* setup/scan's own specialised state */
   void *back_priv;                 /* back end's own specialised state */
};

/* Called by rast_validate() (context.c) when rc->dirty is set. */
void rast_front_validate(struct rast_context *rc);
void rast_backend_validate(struct rast_context *rc);
void rast_backend_destroy(struct rast_context *rc);
void rast_front_destroy(struct rast_context *rc);

static inline void rast_validate(struct rast_context *rc)
{
   if (rc->dirty) {
      rast_front_validate(rc);
      rast_backend_validate(rc);
      rc->dirty = false;
   }
}

#endif
