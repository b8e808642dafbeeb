/*
 * The fragment back end: what happens to a 2x2 quad after scan conversion,
 * in GL ES order (stencil, depth, occlusion count, blend, colour mask).
 *
 * rast_backend_validate() turns the state into a quad function and a plan
 * (backend_priv.h) once per state change; the quad functions below only
 * follow the plan.  Depth and stencil run before the shader whenever the
 * shader can change neither (no depth output, no discard), so quads the
 * depth test rejects are never shaded; otherwise after it.
 *
 * Counters: stats.pixels_shaded counts the live pixels handed to the
 * shader; stats.samples_passed (occlusion queries) the pixels that survive
 * the shader and the depth/stencil test.
 */
#include <stdlib.h>
#include "rast/backend_priv.h"

static inline struct rast_backend *backend(struct rast_context *rc)
{
   return (struct rast_backend *)rc->back_priv;
}

typedef const float (*chan_quad)[RAST_QUAD_SIZE];

/* Runs the shader on the live pixels of q given by mask; returns the
 * pixels it keeps. */
static inline unsigned shade(struct rast_context *rc, struct rast_backend *be,
                             struct rast_quad *q, unsigned mask)
{
   const unsigned saved = q->mask;
   q->mask = mask;
   rc->stats.pixels_shaded += rast_popcount4(mask);
   const unsigned kept = rc->fs.shade(rc->fs.ctx, q, &be->out) & mask;
   q->mask = saved;
   return kept;
}

static inline void color_stage(const struct rast_backend *be, int x, int y, unsigned mask)
{
   for (unsigned k = 0; k < be->ncbufs; k++) {
      const struct rast_cbuf_plan *p = &be->cbuf[k];
      p->func(p, x, y, mask, (chan_quad)be->out.color[p->src], (chan_quad)be->out.color[1]);
   }
}

/* Nothing to draw: no shader. */
static void quad_nop(struct rast_context *rc, struct rast_quad *q)
{
   (void)rc;
   (void)q;
}

/* No depth/stencil, no visible colour, shader without effect: only the
 * occlusion count remains. */
static void quad_count(struct rast_context *rc, struct rast_quad *q)
{
   rc->stats.samples_passed += rast_popcount4(q->mask);
}

/* No depth/stencil. */
static void quad_color(struct rast_context *rc, struct rast_quad *q)
{
   struct rast_backend *be = backend(rc);
   const unsigned mask = shade(rc, be, q, q->mask);
   rc->stats.samples_passed += rast_popcount4(mask);
   if (mask)
      color_stage(be, q->x, q->y, mask);
}

/* No depth/stencil, no blend, all channels, one 8-bit target. */
#define QUAD_FAST8(NAME, R, G, B, A, X8) \
   static void quad_fast_##NAME(struct rast_context *rc, struct rast_quad *q) \
   { \
      struct rast_backend *be = backend(rc); \
      const unsigned mask = shade(rc, be, q, q->mask); \
      rc->stats.samples_passed += rast_popcount4(mask); \
      const struct rast_cbuf_plan *p = &be->cbuf[0]; \
      rast_store8_quad(p->base, p->stride, q->x, q->y, mask, \
                       (chan_quad)be->out.color[p->src], R, G, B, A, X8); \
   }

QUAD_FAST8(RGBA8, 0, 1, 2, 3, false)
QUAD_FAST8(BGRA8, 2, 1, 0, 3, false)
QUAD_FAST8(BGRX8, 2, 1, 0, 3, true)

/* Depth/stencil before the shader. */
static void quad_early(struct rast_context *rc, struct rast_quad *q)
{
   struct rast_backend *be = backend(rc);
   union rast_zq z;
   if (be->zconv)
      be->zconv(be, q, NULL, &z);
   unsigned mask = be->zs(be, q->x, q->y, q->mask, &z, q->front_facing);
   rc->stats.samples_passed += rast_popcount4(mask);
   if (!mask || !be->shade_needed)
      return;
   mask = shade(rc, be, q, mask);
   if (mask)
      color_stage(be, q->x, q->y, mask);
}

/* The shader first: it may discard or write depth. */
static void quad_late(struct rast_context *rc, struct rast_quad *q)
{
   struct rast_backend *be = backend(rc);
   union rast_zq z;
   unsigned mask = shade(rc, be, q, q->mask);
   if (!mask)
      return;
   if (be->zconv)
      be->zconv(be, q, &be->out, &z);
   mask = be->zs(be, q->x, q->y, mask, &z, q->front_facing);
   rc->stats.samples_passed += rast_popcount4(mask);
   if (mask)
      color_stage(be, q->x, q->y, mask);
}

void rast_backend_validate(struct rast_context *rc)
{
   struct rast_backend *be = backend(rc);
   if (!be) {
      be = calloc(1, sizeof *be);
      rc->back_priv = be;
      if (!be) {
         rc->quad = quad_nop;
         return;
      }
   }

   if (!rc->fs.shade) {
      rc->quad = quad_nop;
      return;
   }

   rast_zs_plan(be, rc);
   rast_color_plan(be, rc);
   be->shade_needed = be->ncbufs > 0 || rc->fs.writes_depth || rc->fs.may_discard;

   if (be->zs) {
      rc->quad = rc->fs.writes_depth || rc->fs.may_discard ? quad_late : quad_early;
   } else if (!be->shade_needed) {
      rc->quad = quad_count;
   } else if (be->ncbufs == 1 && be->cbuf[0].fast8 == RAST_CL_RGBA8) {
      rc->quad = quad_fast_RGBA8;
   } else if (be->ncbufs == 1 && be->cbuf[0].fast8 == RAST_CL_BGRA8) {
      rc->quad = quad_fast_BGRA8;
   } else if (be->ncbufs == 1 && be->cbuf[0].fast8 == RAST_CL_BGRX8) {
      rc->quad = quad_fast_BGRX8;
   } else {
      rc->quad = quad_color;
   }
}

void rast_backend_destroy(struct rast_context *rc)
{
   free(rc->back_priv);
   rc->back_priv = NULL;
   rc->quad = NULL;
}
