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
#include "rast/backend/backend_priv.h"
#include "rast/backend/c8_lanes.h"

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
         const uint8_t *row = rast_target_place(t->base, t->layers, t->layer_stride, be->layer,
                                                be->sample, t->sample_stride) +
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

/* The same on n quads of a primitive, in one call of the shader for those
 * with live pixels (quad i's in bits 4i to 4i + 3 of `masks`), quad i's
 * outputs to be->out[i]; returns the pixels kept, in the same bits.  A
 * quad left without live pixels (the early tests) is not shaded. */
static inline unsigned shade_group(struct rast_context *rc, struct rast_backend *be,
                                   struct rast_quad *q, unsigned n, unsigned masks)
{
   struct rast_quad *live[RAST_GROUP_MAX];
   struct rast_shaded_quad *out[RAST_GROUP_MAX];
   unsigned saved[RAST_GROUP_MAX], at[RAST_GROUP_MAX], nl = 0;
   for (unsigned i = 0; i < n; i++) {
      const unsigned m = masks >> 4 * i & 15;
      if (!m)
         continue;
      saved[nl] = q[i].mask;
      q[i].mask = m;
      at[nl] = i;
      live[nl] = &q[i];
      out[nl++] = &be->out[i];
      if (rc->fs.fetch_mask)
         fetch_targets(rc, be, &q[i]);
      rc->stats.pixels_shaded += rast_popcount4(m);
      /* the colour stage's rows, on their way while the shader runs */
      for (unsigned k = 0; k < be->ncbufs; k++) {
         const struct rast_cbuf_plan *p = &be->cbuf[k];
         const uint8_t *row = p->base + (ptrdiff_t)q[i].y * p->stride +
                              (ptrdiff_t)q[i].x * (ptrdiff_t)p->cpp;
         __builtin_prefetch(row, 1);
         __builtin_prefetch(row + p->stride, 1);
      }
   }
   unsigned got;
   if (nl >= 2)
      got = rc->fs.shade_n(rc->fs.ctx, (const struct rast_quad *const *)live, out, nl);
   else if (nl == 1)
      got = rc->fs.shade(rc->fs.ctx, live[0], out[0]);
   else
      return 0;
   unsigned kept = 0;
   for (unsigned j = 0; j < nl; j++) {
      kept |= (got >> 4 * j & live[j]->mask) << 4 * at[j];
      live[j]->mask = saved[j];
   }
   return kept;
}

/* The masks of a group's quads, quad i's in bits 4i to 4i + 3. */
static inline unsigned group_masks(const struct rast_quad *q, unsigned n)
{
   unsigned m = 0;
   for (unsigned i = 0; i < n; i++)
      m |= q[i].mask << 4 * i;
   return m;
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
 * occlusion count remains (not shaded: counted). */
static void quad_count(struct rast_context *rc, struct rast_quad *q)
{
   rc->stats.samples_passed += rast_popcount4(q->mask);
   rc->stats.skip_shade_quads += backend(rc)->skips_counted;
}

/* No depth/stencil. */
static void quad_color(struct rast_context *rc, struct rast_quad *q)
{
   struct rast_backend *be = backend(rc);
   const unsigned mask = shade(rc, q, q->mask, &be->out[0]);
   rc->stats.samples_passed += rast_popcount4(mask);
   if (mask)
      color_stage(be, &be->out[0], q->x, q->y, mask);
}

/* One colour buffer's stage for a group, `kept` as shade_group returns it:
 * the quads with four pixels in the framebuffer on one vector where the
 * plan has the group's function and two or more of them are drawn, the
 * others each alone (a group's quads are of one primitive: no two share a
 * pixel, so their order does not matter). */
static inline void cbuf_stage_group(const struct rast_backend *be,
                                    const struct rast_cbuf_plan *p, const struct rast_quad *q,
                                    unsigned n, unsigned kept)
{
   unsigned which = 0;
   if (p->group) {
      for (unsigned i = 0; i < n; i++) {
         const unsigned m = kept >> 4 * i & 15;
         which |= (unsigned)(m && c8_lanes_ok(p, q[i].x, q[i].y, m)) << i;
      }
      if (which & (which - 1))
         p->group(p, q, be->out, which, kept);
      else
         which = 0;
   }
   for (unsigned i = 0; i < n; i++) {
      const unsigned m = kept >> 4 * i & 15;
      if (m && !(which >> i & 1))
         p->func(p, q[i].x, q[i].y, m, (chan_quad)be->out[i].color[p->src],
                 (chan_quad)be->out[i].color[1]);
   }
}

static inline void color_stage_group(const struct rast_backend *be, const struct rast_quad *q,
                                     unsigned n, unsigned kept)
{
   for (unsigned k = 0; k < be->ncbufs; k++)
      cbuf_stage_group(be, &be->cbuf[k], q, n, kept);
}

static void group_color(struct rast_context *rc, struct rast_quad *q, unsigned n)
{
   struct rast_backend *be = backend(rc);
   const unsigned kept = shade_group(rc, be, q, n, group_masks(q, n));
   rc->stats.samples_passed += rast_popcount16(kept);
   color_stage_group(be, q, n, kept);
}

/* No depth/stencil, no blend, all channels, one 8-bit target. */
#define QUAD_FAST8(NAME, R, G, B, A, X8) \
   static void quad_fast_##NAME(struct rast_context *rc, struct rast_quad *q) \
   { \
      struct rast_backend *be = backend(rc); \
      const unsigned mask = shade(rc, q, q->mask, &be->out[0]); \
      rc->stats.samples_passed += rast_popcount4(mask); \
      const struct rast_cbuf_plan *p = &be->cbuf[0]; \
      c8_store_quad(p, q->x, q->y, mask, \
                       (chan_quad)be->out[0].color[p->src], R, G, B, A, X8); \
   } \
   static void group_fast_##NAME(struct rast_context *rc, struct rast_quad *q, unsigned n) \
   { \
      struct rast_backend *be = backend(rc); \
      const unsigned kept = shade_group(rc, be, q, n, group_masks(q, n)); \
      rc->stats.samples_passed += rast_popcount16(kept); \
      const struct rast_cbuf_plan *p = &be->cbuf[0]; \
      if (p->group) { \
         cbuf_stage_group(be, p, q, n, kept); \
         return; \
      } \
      for (unsigned i = 0; i < n; i++) \
         c8_store_quad(p, q[i].x, q[i].y, kept >> 4 * i & 15, \
                          (chan_quad)be->out[i].color[p->src], R, G, B, A, X8); \
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

/* The early tests' skips (counted): a quad they reject whole is not
 * shaded, nor one the shader would draw nothing for. */
static void quad_early(struct rast_context *rc, struct rast_quad *q)
{
   struct rast_backend *be = backend(rc);
   unsigned mask = early_zs(rc, be, q);
   if (!mask || !be->shade_needed) {
      rc->stats.skip_early_quads += be->skips_counted & !mask;
      rc->stats.skip_shade_quads += be->skips_counted & (mask != 0);
      return;
   }
   mask = shade(rc, q, mask, &be->out[0]);
   if (mask)
      color_stage(be, &be->out[0], q->x, q->y, mask);
}

/* Whether a group's quads can take the early depth test on lanes
 * (lanes.h's rast_zgroup_fn): each with its four pixels in the target.  No
 * two are at one place (rast_quads_func), so reading every quad's depth
 * before writing any is what one quad after the other would read. */
static inline bool zgroup_ok(const struct rast_backend *be, const struct rast_quad *q,
                             unsigned n)
{
   for (unsigned i = 0; i < n; i++)
      if (!rast_quad_whole(q[i].x, q[i].y, q[i].mask, be->fb_w, be->fb_h))
         return false;
   return true;
}

/* The same for a block of quads: one the tests reject whole is left out of
 * the shader's call, and a block they reject whole makes no call. */
static void group_early(struct rast_context *rc, struct rast_quad *q, unsigned n)
{
   struct rast_backend *be = backend(rc);
   unsigned masks = 0, live = 0;
   if (be->zgroup && zgroup_ok(be, q, n)) {
      masks = be->zgroup(be, q, n, group_masks(q, n));
      for (unsigned i = 0; i < n; i++)
         live += (masks >> 4 * i & 15) != 0;
      rc->stats.samples_passed += rast_popcount16(masks);
   } else {
      for (unsigned i = 0; i < n; i++) {
         const unsigned m = early_zs(rc, be, &q[i]);
         masks |= m << 4 * i;
         live += m != 0;
      }
   }
   rc->stats.skip_early_quads += be->skips_counted * (n - live);
   if (!masks || !be->shade_needed) {
      rc->stats.skip_shade_quads += be->skips_counted * live;
      return;
   }
   color_stage_group(be, q, n, shade_group(rc, be, q, n, masks));
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
   const unsigned mask = shade(rc, q, q->mask, &be->out[0]);
   if (mask)
      late_zs_color(rc, be, q, &be->out[0], mask);
}

static void group_late(struct rast_context *rc, struct rast_quad *q, unsigned n)
{
   struct rast_backend *be = backend(rc);
   const unsigned kept = shade_group(rc, be, q, n, group_masks(q, n));
   for (unsigned i = 0; i < n; i++)
      if (kept >> 4 * i & 15)
         late_zs_color(rc, be, &q[i], &be->out[i], kept >> 4 * i & 15);
}

static void backend_choose(struct rast_context *rc);

void rast_backend_validate(struct rast_context *rc)
{
   backend_choose(rc);
   if (rc->observe_backend)
      rc->observe_backend(rc);
}

static void backend_choose(struct rast_context *rc)
{
   struct rast_backend *be = backend(rc);
   rc->quads = NULL;
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
   be->layer = 0;                 /* the plans' bases: layer 0 */
   /* Alpha to coverage takes samples away as a discard does. */
   const bool a2c = rc->blend.alpha_to_coverage && rc->fb.samples > 1;
   be->shade_needed = be->ncbufs > 0 || rc->fs.writes_depth || rc->fs.may_discard || a2c ||
                      rc->fs.side_effects;

   /* noskip: every covered quad is shaded, the tests after it (the same
    * bits: an early test is only taken where the shader cannot change
    * what it decides).  Not on a multisampled target, where the order
    * decides which sample's position shades an edge pixel (msaa.c: the
    * first sample that reaches the shader). */
   const bool single = rc->fb.samples <= 1, asked = rc->opts & RAST_OPT_NOSKIP;
   const bool noskip = asked && single;
   be->skips_counted = !asked && single;
   rast_quads_func group = NULL;
   if (be->zs) {
      /* A shader with side effects sees every covered fragment, unless
       * it asks for the tests first (then even noskip keeps them first:
       * shading the fragments they reject would write memory) */
      const bool late = !rc->fs.early_tests &&
                        (rc->fs.writes_depth || rc->fs.may_discard || a2c || noskip ||
                         rc->fs.side_effects);
      rc->quad = late ? quad_late : quad_early;
      group = late ? group_late : group_early;
   } else if (!be->shade_needed && !noskip) {
      rc->quad = quad_count;
   } else if (be->ncbufs == 1 && be->cbuf[0].fast8 == RAST_CL_RGBA8) {
      rc->quad = quad_fast_RGBA8;
      group = group_fast_RGBA8;
   } else if (be->ncbufs == 1 && be->cbuf[0].fast8 == RAST_CL_BGRA8) {
      rc->quad = quad_fast_BGRA8;
      group = group_fast_BGRA8;
   } else if (be->ncbufs == 1 && be->cbuf[0].fast8 == RAST_CL_BGRX8) {
      rc->quad = quad_fast_BGRX8;
      group = group_fast_BGRX8;
   } else {
      rc->quad = quad_color;
      group = group_color;
   }
   /* groups only where the shader has its wide form; noskip: one by one */
   if (rc->fs.shade_n && !(rc->opts & RAST_OPT_NOSKIP))
      rc->quads = group;
}

/* A target's layer and sample from its layer 0, sample 0: a layer beyond
 * the target's last is its last (the layer an overflowing gl_Layer draws
 * into, rast_vertex_layout.has_layer). */
uint8_t *rast_target_place(uint8_t *base0, unsigned layers, size_t layer_stride,
                           unsigned layer, unsigned s, size_t sample_stride)
{
   const unsigned l = layers > 1 ? (layer < layers ? layer : layers - 1) : 0;
   return base0 + (size_t)l * layer_stride + (size_t)s * sample_stride;
}

static void place(struct rast_backend *be)
{
   if (be->zs_base0)
      be->zs_base = rast_target_place(be->zs_base0, be->zs_layers, be->zs_layer_stride,
                                      be->layer, be->sample, be->zs_sample_stride);
   for (unsigned k = 0; k < be->ncbufs; k++) {
      struct rast_cbuf_plan *p = &be->cbuf[k];
      p->base = rast_target_place(p->base0, p->layers, p->layer_stride, be->layer, be->sample,
                                  p->sample_stride);
   }
}

void rast_backend_sample(struct rast_context *rc, unsigned s)
{
   struct rast_backend *be = backend(rc);
   if (!be)
      return;
   be->sample = s;
   place(be);
}

void rast_backend_layer(struct rast_context *rc, unsigned layer)
{
   struct rast_backend *be = backend(rc);
   if (!be || be->layer == layer)
      return;
   be->layer = layer;
   place(be);
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
   rc->quads = NULL;
}
