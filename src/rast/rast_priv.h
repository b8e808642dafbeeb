/*
 * Inside the model: the context shared by setup/scan (the front end) and the
 * fragment back end.  Not for the driver.
 */
#ifndef FIXPIPE_RAST_PRIV_H
#define FIXPIPE_RAST_PRIV_H

#include <math.h>
#include <string.h>
#include "rast/rast.h"

struct rast_context;

/* The back end's entry, chosen by rast_backend_validate(): the quad's mask is
 * already clipped to the scissor and the framebuffer. */
typedef void (*rast_quad_func)(struct rast_context *rc, struct rast_quad *q);
/* n quads of a primitive, one after another in q, each at a place of its own. */
typedef void (*rast_quads_func)(struct rast_context *rc, struct rast_quad *q, unsigned n);

struct rast_front;

struct rast_context {
   const struct rast_profile *profile;
   struct rast_stats stats;

   /* State as the driver set it. */
   struct rast_framebuffer fb;
   struct rast_raster_state rs;
   struct rast_scissor scissors[RAST_MAX_VIEWPORTS];
   struct rast_scissor viewports[RAST_MAX_VIEWPORTS];
   struct rast_depth_range depth_ranges[RAST_MAX_VIEWPORTS];
   struct rast_depth_stencil_state dsa;
   uint8_t stencil_ref[2];
   unsigned sample_mask;
   struct rast_blend_state blend;
   float blend_color[4];
   struct rast_vertex_layout vl;
   struct rast_shader fs;
   unsigned opts;                   /* RAST_OPT_* */
   unsigned interp;                 /* enum rast_interp_mode | RAST_INTERP_MEASURE */
   const struct numsys *texfmt;     /* never NULL after rast_create */

   bool dirty;                      /* re-validate before the next primitive */
   unsigned long state_serial;      /* bumped by every setter: workers copy state */

   /* Threads (threads.c).  The main context owns the pool; every context,
    * the main one included, draws the quad rows of its bands. */
   struct rast_pool *pool;
   unsigned band_index, band_count;    /* thread t of n; count 1: every row */
   int64_t band_lo, band_hi;           /* its target rows in the batch: [lo, hi) */
   /* Counters of the current stretch of work are kept (its band, or the
    * primitive's set-up on the thread that owns it), else undone back to
    * mark: each event is counted on exactly one thread. */
   bool counting;
   struct rast_stats mark;

   /* Chosen per primitive (set-up, rast_primitive_viewport): its viewport
    * index and that viewport's scissor and pixels (and, in the back end,
    * its depth range: rast_backend_viewport). */
   unsigned vp_index;
   struct rast_scissor scissor;
   struct rast_scissor viewport;

   /* Chosen at validation. */
   struct rast_scissor clip_all;    /* scissor & framebuffer, max exclusive */
   bool tiled;                      /* the target is larger than a tile (tile.c) */
   /* The pass being drawn: the scan converter's clip and the origin the
    * vertices are taken from, in pixels (even, so quads and bands stay
    * where they are).  Untiled: clip_all and 0. */
   struct rast_scissor clip;
   int64_t org_x, org_y;
   rast_quad_func quad;             /* back end */
   /* the same on 2 to fs.group quads of a primitive; NULL: one by one */
   rast_quads_func quads;
   /* RTL test vectors (vectors.c): recording or replaying; the quads of the
    * triangle being scanned go through the wrapper to vec_next_quad */
   struct rast_vectors *vec;
   /* Instruments installed from outside (instruments/vectors.c), NULL when
    * none: set-up hands each triangle's registers over, the back end's
    * validation lets its quad function be wrapped. */
   void (*observe_triangle)(struct rast_context *rc, const struct rast_front *fr, bool front);
   void (*observe_backend)(struct rast_context *rc);
   bool scanning_triangle;          /* set-up's: the quads under way are a triangle's */
   /* The event maps (instruments/events.c), NULL when off: a primitive
    * begins (before its set-up), and the scan converter's walk begins
    * (set-up done: RAST_SCAN_BEGIN), enters a quad row of this thread's
    * (RAST_SCAN_ROW, its first target row) and ends (RAST_SCAN_END).  Per
    * primitive and per quad row, never per pixel. */
   void (*observe_prim)(struct rast_context *rc);
   void (*observe_scan)(struct rast_context *rc, int what, int64_t row);
   struct rast_ev_thread *events;   /* that instrument's state for this thread */
   rast_quad_func vec_next_quad;
   struct rast_msaa *msaa;          /* a multisampled target's passes (msaa.c) */
   bool msaa_busy;                  /* inside them: a pass is one walk */
   /* The quad rows a walk draws (pass-local scan lines, [lo, hi)): the
    * walk runs from the primitive's top whatever they are, so that its
    * registers are the whole walk's (msaa.c's strips). */
   int64_t rows_lo, rows_hi;
   void *front_priv;                /* setup/scan's own specialised state */
   void *back_priv;                 /* back end's own specialised state */
};

enum { RAST_SCAN_BEGIN, RAST_SCAN_ROW, RAST_SCAN_END };

/* Called by rast_validate() (context.c) when rc->dirty is set. */
void rast_front_validate(struct rast_context *rc);
void rast_backend_validate(struct rast_context *rc);
void rast_backend_destroy(struct rast_context *rc);
void rast_front_destroy(struct rast_context *rc);

/* The primitives proper, past the queue (setup.c, line.c, point.c). */
void rast_draw_triangle(struct rast_context *rc, const float (*v0)[4],
                        const float (*v1)[4], const float (*v2)[4]);
void rast_draw_line(struct rast_context *rc, const float (*v0)[4], const float (*v1)[4]);
void rast_draw_point(struct rast_context *rc, const float (*v0)[4]);

/* The XY register's grid point of a window coordinate, unsaturated (ties
 * away from zero, as fx_from_double): |v| < 2^30. */
static inline int64_t rast_snap_xy(struct fx_format xy, double v)
{
   return (int64_t)round(v * (double)fx_one(xy));   /* exact: a power of two */
}

/* softpipe's det = (v0 - v2) x (v1 - v2) of three grid points. */
static inline int64_t rast_det(const int64_t *X, const int64_t *Y)
{
   return (X[0] - X[2]) * (Y[1] - Y[2]) - (Y[0] - Y[2]) * (X[1] - X[2]);
}

/* Seed 004 leaves input that is not a number open; the model's rule, as D3D's
 * clipper has it: a primitive with a vertex whose position after the divide
 * (window x, y, z or 1/w) is NaN or infinite is dropped before the cull stage
 * and counted in rast_stats.nonfinite.  Past the divide an infinity is no
 * longer a limit but an overflow, and a NaN has no place on the grid: any
 * picture drawn from either would be the conversion's, not the primitive's.
 * (A clip-space w of +inf divides to a finite 0 and is drawn.) */
static inline bool rast_position_finite(const struct rast_context *rc, const float (*v)[4])
{
   const float *p = v[rc->vl.pos_slot];
   return isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]) && isfinite(p[3]);
}

/* A primitive's counters: culled (edge-on, zero length, or its face
 * culled) or drawn; false when culled.  setup.c, line.c. */
bool rast_triangle_counted(struct rast_context *rc, int64_t det, bool *front);
bool rast_line_counted(struct rast_context *rc, float dx, float dy);

/* One pass of each through the scan converter, at rc->org_x/org_y and
 * inside rc->clip (setup.c, line.c, point.c). */
void rast_triangle_pass(struct rast_context *rc, const float (*v0)[4],
                        const float (*v1)[4], const float (*v2)[4]);
void rast_line_pass(struct rast_context *rc, const float (*v0)[4], const float (*v1)[4]);
void rast_point_pass(struct rast_context *rc, const float (*v0)[4]);

/* threads.c: true when the primitive went to the queue (threads > 1). */
enum rast_prim_kind { RAST_PRIM_TRIANGLE, RAST_PRIM_LINE, RAST_PRIM_POINT };

/* msaa.c: one pass of a primitive on a multisampled target, as the passes
 * above are on others: the pixels' shading once, then each sample's
 * coverage, depth, stencil and colour. */
static inline bool rast_multisampled(const struct rast_context *rc)
{
   return rc->fb.samples > 1 && !rc->msaa_busy;
}
void rast_msaa_pass(struct rast_context *rc, enum rast_prim_kind kind, const float (*v0)[4],
                    const float (*v1)[4], const float (*v2)[4]);
void rast_msaa_destroy(struct rast_context *rc);
/* backend.c: the back end on sample s's planes of the framebuffer. */
void rast_backend_sample(struct rast_context *rc, unsigned s);
/* The layer of a layered target the next primitives draw into (set-up:
 * gl_Layer, rast_vertex_layout.has_layer), and a target's address of a
 * layer and sample. */
void rast_backend_layer(struct rast_context *rc, unsigned layer);
/* The viewport whose depth range the next primitives' depths are clamped
 * to (rs.depth_clamp; backend_zs.c), after validation, which plans
 * rc->vp_index's. */
void rast_backend_viewport(struct rast_context *rc, unsigned vp);
uint8_t *rast_target_place(uint8_t *base0, unsigned layers, size_t layer_stride,
                           unsigned layer, unsigned s, size_t sample_stride);
/* The clip of the scissor and framebuffer (setup.c): at validation, and
 * when a primitive's viewport index changes the scissor. */
void rast_compute_clip(struct rast_context *rc);

/* Set-up's: the primitive's viewport index, from its provoking vertex: the
 * scissor and viewport it is drawn with. */
static inline void rast_primitive_viewport(struct rast_context *rc, const float (*pv)[4])
{
   if (rc->vl.has_viewport_index) {
      uint32_t i;
      memcpy(&i, &pv[rc->vl.viewport_slot][0], sizeof(i));
      if (i >= RAST_MAX_VIEWPORTS)
         i = RAST_MAX_VIEWPORTS - 1;
      if (i != rc->vp_index) {
         rc->vp_index = i;
         rc->scissor = rc->scissors[i];
         rc->viewport = rc->viewports[i];
         rast_compute_clip(rc);
         rast_backend_viewport(rc, i);
      }
   }
}

/* Set-up's: the primitive's layer, from its provoking vertex, to the back
 * end (after validation, which plans layer 0). */
static inline void rast_primitive_layer(struct rast_context *rc, const float (*pv)[4])
{
   if (rc->vl.has_layer) {
      uint32_t layer;
      memcpy(&layer, &pv[rc->vl.layer_slot][0], sizeof(layer));
      rast_backend_layer(rc, layer);
   }
}
/* backend.c: whether the back end runs the shader at all (a colour it
 * writes, a depth output or a discard). */
bool rast_backend_shades(const struct rast_context *rc);
bool rast_queue(struct rast_context *rc, enum rast_prim_kind kind, const float (*v0)[4],
                const float (*v1)[4], const float (*v2)[4]);

/* tile.c: the pixels a primitive can reach, conservatively, from its float
 * vertices: box = x0, y0, x1, y1.  false: no finite extent. */
bool rast_prim_extent(const struct rast_context *rc, enum rast_prim_kind kind,
                      const float (*v0)[4], const float (*v1)[4], const float (*v2)[4],
                      float box[4]);
/* tile.c: the primitive in a pass per tile it reaches (rc->tiled). */
void rast_tiles_draw(struct rast_context *rc, enum rast_prim_kind kind, const float (*v0)[4],
                     const float (*v1)[4], const float (*v2)[4]);

/* Whether the quad row starting at scan line p (even, >= 0) is this
 * context's: the thread's rows of the batch (threads.c). */
static inline bool rast_band_mine(const struct rast_context *rc, int64_t p)
{
   if (p < rc->rows_lo || p >= rc->rows_hi)
      return false;
   return rc->band_count == 1 || (p + rc->org_y >= rc->band_lo && p + rc->org_y < rc->band_hi);
}

/* Entering work that is (mine) or is not this context's to count. */
static inline void rast_count_stretch(struct rast_context *rc, bool mine)
{
   if (mine == rc->counting)
      return;
   if (mine)
      rc->stats = rc->mark;
   else
      rc->mark = rc->stats;
   rc->counting = mine;
}

static inline void rast_validate(struct rast_context *rc)
{
   if (rc->dirty) {
      rast_front_validate(rc);
      rast_backend_validate(rc);
      rc->dirty = false;
   }
}

#endif
