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
#include <stddef.h>
#include <stdlib.h>
#include "rast/backend_priv.h"
#include "rast/vectors.h"

static inline struct rast_backend *backend(struct rast_context *rc)
{
   return (struct rast_backend *)rc->back_priv;
}

typedef const float (*chan_quad)[RAST_QUAD_SIZE];

/* Framebuffer fetch: the colour buffers the shader reads, as they are now,
 * into the quad's `last`.  Every pixel of the quad inside the target is
 * read, covered or not, so derivatives of the fetched colour are those of
 * the picture (a quad starts inside it; its right column or lower row may
 * not be, and reads 0).  The quad's rows are this thread's, and primitives
 * reach the back end in order, so what is read is every earlier
 * primitive's result (coherent fetch). */
static void fetch_targets(const struct rast_context *rc, const struct rast_backend *be,
                          struct rast_quad *q)
{
   const unsigned w = q->x + 1 < (int)rc->fb.width ? 2 : 1;
   const unsigned h = q->y + 1 < (int)rc->fb.height ? 2 : 1;
   for (unsigned cb = 0; cb < RAST_MAX_CBUFS; cb++) {
      if (!(rc->fs.fetch_mask >> cb & 1u))
         continue;
      const struct rast_color_target *t = &rc->fb.cbuf[cb];
      float rgba[RAST_QUAD_SIZE][4] = { { 0 } };   /* pixel i at [i] */
      if (cb < rc->fb.nr_cbufs && t->base) {
         const uint8_t *row = t->base + be->sample * t->sample_stride +
                              (ptrdiff_t)q->y * t->stride + (ptrdiff_t)q->x * (ptrdiff_t)t->cpp;
         for (unsigned r = 0; r < h; r++)
            t->load(row + (ptrdiff_t)r * t->stride, w, &rgba[2 * r]);
      }
      for (unsigned c = 0; c < 4; c++)
         for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
            q->last[cb][c][i] = rgba[i][c];
   }
}

/* Runs the shader on the live pixels of q given by mask, its outputs to
 * `out`; returns the pixels it keeps. */
static inline unsigned shade(struct rast_context *rc, struct rast_quad *q, unsigned mask,
                             struct rast_shaded_quad *out)
{
   const unsigned saved = q->mask;
   q->mask = mask;
   if (rc->fs.fetch_mask)
      fetch_targets(rc, backend(rc), q);
   rc->stats.pixels_shaded += rast_popcount4(mask);
   const unsigned kept = rc->fs.shade(rc->fs.ctx, q, out) & mask;
   q->mask = saved;
   return kept;
}

/* The same on two quads, in one call of the shader where both have live
 * pixels (m0, m1), their outputs to be->out and be->out2; returns the
 * pixels kept, q0's in bits 0-3 and q1's in bits 4-7. */
static inline unsigned shade_pair(struct rast_context *rc, struct rast_backend *be,
                                  struct rast_quad *q0, unsigned m0, struct rast_quad *q1,
                                  unsigned m1)
{
   if (!m0 || !m1)
      return (m0 ? shade(rc, q0, m0, &be->out) : 0) |
             (m1 ? shade(rc, q1, m1, &be->out2) << 4 : 0);
   const unsigned saved0 = q0->mask, saved1 = q1->mask;
   q0->mask = m0;
   q1->mask = m1;
   if (rc->fs.fetch_mask) {
      fetch_targets(rc, be, q0);
      fetch_targets(rc, be, q1);
   }
   rc->stats.pixels_shaded += rast_popcount4(m0) + rast_popcount4(m1);
   const unsigned kept = rc->fs.shade2(rc->fs.ctx, q0, q1, &be->out, &be->out2) &
                         (m0 | m1 << 4);
   q0->mask = saved0;
   q1->mask = saved1;
   return kept;
}

static inline void color_stage(const struct rast_backend *be, const struct rast_shaded_quad *out,
                               int x, int y, unsigned mask)
{
   for (unsigned k = 0; k < be->ncbufs; k++) {
      const struct rast_cbuf_plan *p = &be->cbuf[k];
      p->func(p, x, y, mask, (chan_quad)out->color[p->src], (chan_quad)out->color[1]);
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
   const unsigned mask = shade(rc, q, q->mask, &be->out);
   rc->stats.samples_passed += rast_popcount4(mask);
   if (mask)
      color_stage(be, &be->out, q->x, q->y, mask);
}

/* color_stage for a pair, `kept` as shade_pair returns it. */
static inline void color_stage_pair(const struct rast_backend *be, const struct rast_quad *q0,
                                    const struct rast_quad *q1, unsigned kept)
{
   if (kept & 15)
      color_stage(be, &be->out, q0->x, q0->y, kept & 15);
   if (kept >> 4)
      color_stage(be, &be->out2, q1->x, q1->y, kept >> 4);
}

static void pair_color(struct rast_context *rc, struct rast_quad *q0, struct rast_quad *q1)
{
   struct rast_backend *be = backend(rc);
   const unsigned kept = shade_pair(rc, be, q0, q0->mask, q1, q1->mask);
   rc->stats.samples_passed += rast_popcount4(kept & 15) + rast_popcount4(kept >> 4);
   color_stage_pair(be, q0, q1, kept);
}

/* No depth/stencil, no blend, all channels, one 8-bit target. */
#define QUAD_FAST8(NAME, R, G, B, A, X8) \
   static void quad_fast_##NAME(struct rast_context *rc, struct rast_quad *q) \
   { \
      struct rast_backend *be = backend(rc); \
      const unsigned mask = shade(rc, q, q->mask, &be->out); \
      rc->stats.samples_passed += rast_popcount4(mask); \
      const struct rast_cbuf_plan *p = &be->cbuf[0]; \
      rast_store8_quad(p->base, p->stride, q->x, q->y, mask, \
                       (chan_quad)be->out.color[p->src], R, G, B, A, X8); \
   } \
   static void pair_fast_##NAME(struct rast_context *rc, struct rast_quad *q0, \
                                struct rast_quad *q1) \
   { \
      struct rast_backend *be = backend(rc); \
      const unsigned kept = shade_pair(rc, be, q0, q0->mask, q1, q1->mask); \
      const unsigned k0 = kept & 15, k1 = kept >> 4; \
      rc->stats.samples_passed += rast_popcount4(k0) + rast_popcount4(k1); \
      const struct rast_cbuf_plan *p = &be->cbuf[0]; \
      rast_store8_quad(p->base, p->stride, q0->x, q0->y, k0, \
                       (chan_quad)be->out.color[p->src], R, G, B, A, X8); \
      rast_store8_quad(p->base, p->stride, q1->x, q1->y, k1, \
                       (chan_quad)be->out2.color[p->src], R, G, B, A, X8); \
   }

QUAD_FAST8(RGBA8, 0, 1, 2, 3, false)
QUAD_FAST8(BGRA8, 2, 1, 0, 3, false)
QUAD_FAST8(BGRX8, 2, 1, 0, 3, true)

/* Depth/stencil before the shader. */
static inline unsigned early_zs(struct rast_context *rc, struct rast_backend *be,
                                struct rast_quad *q)
{
   union rast_zq z;
   if (be->zconv)
      be->zconv(be, q, NULL, &z);
   const unsigned mask = be->zs(be, q->x, q->y, q->mask, &z, q->front_facing);
   rc->stats.samples_passed += rast_popcount4(mask);
   return mask;
}

static void quad_early(struct rast_context *rc, struct rast_quad *q)
{
   struct rast_backend *be = backend(rc);
   unsigned mask = early_zs(rc, be, q);
   if (!mask || !be->shade_needed)
      return;
   mask = shade(rc, q, mask, &be->out);
   if (mask)
      color_stage(be, &be->out, q->x, q->y, mask);
}

static void pair_early(struct rast_context *rc, struct rast_quad *q0, struct rast_quad *q1)
{
   struct rast_backend *be = backend(rc);
   const unsigned m0 = early_zs(rc, be, q0), m1 = early_zs(rc, be, q1);
   if (!(m0 | m1) || !be->shade_needed)
      return;
   color_stage_pair(be, q0, q1, shade_pair(rc, be, q0, m0, q1, m1));
}

/* The shader first: it may discard or write depth. */
static inline void late_zs_color(struct rast_context *rc, struct rast_backend *be,
                                 struct rast_quad *q, const struct rast_shaded_quad *out,
                                 unsigned mask)
{
   union rast_zq z;
   if (be->zconv)
      be->zconv(be, q, out, &z);
   mask = be->zs(be, q->x, q->y, mask, &z, q->front_facing);
   rc->stats.samples_passed += rast_popcount4(mask);
   if (mask)
      color_stage(be, out, q->x, q->y, mask);
}

static void quad_late(struct rast_context *rc, struct rast_quad *q)
{
   struct rast_backend *be = backend(rc);
   const unsigned mask = shade(rc, q, q->mask, &be->out);
   if (mask)
      late_zs_color(rc, be, q, &be->out, mask);
}

static void pair_late(struct rast_context *rc, struct rast_quad *q0, struct rast_quad *q1)
{
   struct rast_backend *be = backend(rc);
   const unsigned kept = shade_pair(rc, be, q0, q0->mask, q1, q1->mask);
   if (kept & 15)
      late_zs_color(rc, be, q0, &be->out, kept & 15);
   if (kept >> 4)
      late_zs_color(rc, be, q1, &be->out2, kept >> 4);
}

static void backend_choose(struct rast_context *rc);

void rast_backend_validate(struct rast_context *rc)
{
   backend_choose(rc);
   if (rc->vec)
      rast_vec_wrap_backend(rc);
}

static void backend_choose(struct rast_context *rc)
{
   struct rast_backend *be = backend(rc);
   rc->quad2 = NULL;
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
   /* Alpha to coverage takes samples away as a discard does. */
   const bool a2c = rc->blend.alpha_to_coverage && rc->fb.samples > 1;
   be->shade_needed = be->ncbufs > 0 || rc->fs.writes_depth || rc->fs.may_discard || a2c;

   rast_quad2_func pair = NULL;
   if (be->zs) {
      const bool late = rc->fs.writes_depth || rc->fs.may_discard || a2c;
      rc->quad = late ? quad_late : quad_early;
      pair = late ? pair_late : pair_early;
   } else if (!be->shade_needed) {
      rc->quad = quad_count;
   } else if (be->ncbufs == 1 && be->cbuf[0].fast8 == RAST_CL_RGBA8) {
      rc->quad = quad_fast_RGBA8;
      pair = pair_fast_RGBA8;
   } else if (be->ncbufs == 1 && be->cbuf[0].fast8 == RAST_CL_BGRA8) {
      rc->quad = quad_fast_BGRA8;
      pair = pair_fast_BGRA8;
   } else if (be->ncbufs == 1 && be->cbuf[0].fast8 == RAST_CL_BGRX8) {
      rc->quad = quad_fast_BGRX8;
      pair = pair_fast_BGRX8;
   } else {
      rc->quad = quad_color;
      pair = pair_color;
   }
   /* pairs only where the shader has its eight-lane form; noskip: one by one */
   if (rc->fs.shade2 && !(rc->opts & RAST_OPT_NOSKIP))
      rc->quad2 = pair;
}

void rast_backend_sample(struct rast_context *rc, unsigned s)
{
   struct rast_backend *be = backend(rc);
   if (!be)
      return;
   be->sample = s;
   if (be->zs_base0)
      be->zs_base = be->zs_base0 + s * be->zs_sample_stride;
   for (unsigned k = 0; k < be->ncbufs; k++)
      be->cbuf[k].base = be->cbuf[k].base0 + s * be->cbuf[k].sample_stride;
}

bool rast_backend_shades(const struct rast_context *rc)
{
   const struct rast_backend *be = backend((struct rast_context *)rc);
   return be && be->shade_needed;
}

void rast_backend_destroy(struct rast_context *rc)
{
   free(rc->back_priv);
   rc->back_priv = NULL;
   rc->quad = NULL;
   rc->quad2 = NULL;
}
