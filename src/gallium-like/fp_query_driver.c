/*
 * The model's counters as gallium driver queries (docs/cycles.md): Mesa's
 * HUD draws them (GALLIUM_HUD=fp-triangles,fp-cycles; GALLIUM_HUD=help lists
 * them) and GL_AMD_performance_monitor reads them.  A query's result is the
 * work between its begin and its end: every counter of the model read at
 * both (after the model has drawn what was queued), subtracted, and the
 * query's figure taken from the difference; the cycle figures through the
 * cycle model (rast/cycles.h) with FIXPIPE_CYCLES's parameters.
 */
#include <stddef.h>
#include <string.h>

#include "util/u_memory.h"
#include "draw/draw_context.h"

#include "fp_context.h"
#include "fp_screen.h"
#include "rast/instruments/cycles.h"

enum fp_query_group {
   FP_GROUP_PRIMITIVES,
   FP_GROUP_PIXELS,
   FP_GROUP_RANGE,
   FP_GROUP_SKIPS,
   FP_GROUP_TEXTURE,
   FP_GROUP_CYCLES,
   FP_GROUP_COUNT
};

static const char *const group_names[FP_GROUP_COUNT] = {
   "fixpipe primitives", "fixpipe pixels", "fixpipe range events",
   "fixpipe skipped work", "fixpipe texture unit", "fixpipe modeled cycles",
};

/* A counter of the model, or a figure of the cycle model. */
enum fp_figure {
   FIG_FIELD,        /* a rast_stats field (offset) */
   FIG_SAT,          /* both saturations of a register class (index) */
   FIG_CYCLES,       /* the frame's cycles: the busiest unit */
   FIG_CYCLES_SCAN, FIG_CYCLES_INTERP, FIG_CYCLES_TEXTURE, FIG_CYCLES_BACKEND,
   FIG_MODELED_US,   /* the cycles as time at the clock */
   FIG_MODELED_FPS,  /* a frame a query: frames a second at the clock */
};

struct fp_driver_query {
   const char *name;
   enum fp_query_group group;
   enum fp_figure figure;
   size_t arg;       /* FIG_FIELD: offset in rast_stats; FIG_SAT: the class */
};

#define FIELD(name, group, field) { name, group, FIG_FIELD, offsetof(struct rast_stats, field) }

static const struct fp_driver_query queries[] = {
   FIELD("fp-triangles", FP_GROUP_PRIMITIVES, triangles),
   FIELD("fp-triangles-type0", FP_GROUP_PRIMITIVES, tri_type[0]),
   FIELD("fp-triangles-type1", FP_GROUP_PRIMITIVES, tri_type[1]),
   FIELD("fp-triangles-type2", FP_GROUP_PRIMITIVES, tri_type[2]),
   FIELD("fp-culled", FP_GROUP_PRIMITIVES, culled),
   FIELD("fp-nonfinite", FP_GROUP_PRIMITIVES, nonfinite),
   FIELD("fp-lines", FP_GROUP_PRIMITIVES, lines),
   FIELD("fp-points", FP_GROUP_PRIMITIVES, points),
   FIELD("fp-spans", FP_GROUP_PIXELS, spans),
   FIELD("fp-quads", FP_GROUP_PIXELS, quads),
   FIELD("fp-pixels-covered", FP_GROUP_PIXELS, pixels_covered),
   FIELD("fp-pixels-shaded", FP_GROUP_PIXELS, pixels_shaded),
   { "fp-sat-xy", FP_GROUP_RANGE, FIG_SAT, RAST_REG_XY },
   { "fp-sat-dxdy", FP_GROUP_RANGE, FIG_SAT, RAST_REG_DXDY },
   { "fp-sat-z", FP_GROUP_RANGE, FIG_SAT, RAST_REG_Z },
   { "fp-sat-color", FP_GROUP_RANGE, FIG_SAT, RAST_REG_COLOR },
   { "fp-sat-weight", FP_GROUP_RANGE, FIG_SAT, RAST_REG_WEIGHT },
   FIELD("fp-dfx-saturations", FP_GROUP_RANGE, tex_sat),
   FIELD("fp-dfx-flushes", FP_GROUP_RANGE, tex_flush),
   FIELD("fp-skip-constant-w", FP_GROUP_SKIPS, skip_persp_w),
   FIELD("fp-skip-constant-components", FP_GROUP_SKIPS, skip_persp_comp),
   FIELD("fp-skip-zero-terms", FP_GROUP_SKIPS, skip_persp_terms),
   FIELD("fp-skip-axes-planes", FP_GROUP_SKIPS, skip_persp_axes),
   FIELD("fp-skip-texture-lod", FP_GROUP_SKIPS, skip_tex_lod),
   FIELD("fp-skip-texture-axes", FP_GROUP_SKIPS, skip_tex_axes),
   FIELD("fp-skip-gather-footprints", FP_GROUP_SKIPS, skip_tex_footprint),
   FIELD("fp-skip-fragcoord", FP_GROUP_SKIPS, skip_fragcoord),
   FIELD("fp-skip-z", FP_GROUP_SKIPS, skip_z),
   FIELD("fp-skip-early-quads", FP_GROUP_SKIPS, skip_early_quads),
   FIELD("fp-skip-shade-quads", FP_GROUP_SKIPS, skip_shade_quads),
   FIELD("fp-texture-quads", FP_GROUP_TEXTURE, tex_quads),
   FIELD("fp-texels", FP_GROUP_TEXTURE, texels),
   { "fp-cycles", FP_GROUP_CYCLES, FIG_CYCLES, 0 },
   { "fp-cycles-setup-scan", FP_GROUP_CYCLES, FIG_CYCLES_SCAN, 0 },
   { "fp-cycles-interpolators", FP_GROUP_CYCLES, FIG_CYCLES_INTERP, 0 },
   { "fp-cycles-texture", FP_GROUP_CYCLES, FIG_CYCLES_TEXTURE, 0 },
   { "fp-cycles-backend", FP_GROUP_CYCLES, FIG_CYCLES_BACKEND, 0 },
   { "fp-modeled-us", FP_GROUP_CYCLES, FIG_MODELED_US, 0 },
   { "fp-modeled-fps", FP_GROUP_CYCLES, FIG_MODELED_FPS, 0 },
};

#define NUM_QUERIES (sizeof(queries) / sizeof(queries[0]))

static bool is_float(const struct fp_driver_query *q)
{
   return q->figure == FIG_MODELED_US || q->figure == FIG_MODELED_FPS;
}

static int fp_get_driver_query_info(struct pipe_screen *screen, unsigned index,
                                    struct pipe_driver_query_info *info)
{
   (void)screen;
   if (!info)
      return (int)NUM_QUERIES;
   if (index >= NUM_QUERIES)
      return 0;
   const struct fp_driver_query *q = &queries[index];
   *info = (struct pipe_driver_query_info){
      .name = q->name,
      .query_type = PIPE_QUERY_DRIVER_SPECIFIC + index,
      .type = is_float(q) ? PIPE_DRIVER_QUERY_TYPE_FLOAT : PIPE_DRIVER_QUERY_TYPE_UINT64,
      /* the HUD shows the figure per frame, averaged over its period */
      .result_type = PIPE_DRIVER_QUERY_RESULT_TYPE_AVERAGE,
      .group_id = q->group,
   };
   return 1;
}

static int fp_get_driver_query_group_info(struct pipe_screen *screen, unsigned index,
                                          struct pipe_driver_query_group_info *info)
{
   (void)screen;
   if (!info)
      return FP_GROUP_COUNT;
   if (index >= FP_GROUP_COUNT)
      return 0;
   unsigned n = 0;
   for (unsigned i = 0; i < NUM_QUERIES; i++)
      n += queries[i].group == index;
   *info = (struct pipe_driver_query_group_info){
      .name = group_names[index], .max_active_queries = n, .num_queries = n,
   };
   return 1;
}

void fp_init_screen_query_functions(struct pipe_screen *screen)
{
   screen->get_driver_query_info = fp_get_driver_query_info;
   screen->get_driver_query_group_info = fp_get_driver_query_group_info;
}

/* ---- the queries of a context ---- */

struct fp_counter_query {
   unsigned index;
   struct rast_stats start, end;
   const struct rast_cycle_params *cycles;   /* the context's FIXPIPE_CYCLES */
};

bool fp_is_driver_query(unsigned type)
{
   return type >= PIPE_QUERY_DRIVER_SPECIFIC && type < PIPE_QUERY_DRIVER_SPECIFIC + NUM_QUERIES;
}

struct fp_counter_query *fp_counter_query_create(unsigned type)
{
   struct fp_counter_query *q = CALLOC_STRUCT(fp_counter_query);
   if (q)
      q->index = type - PIPE_QUERY_DRIVER_SPECIFIC;
   return q;
}

/* The counters up to now: what draw holds drawn first. */
static void read_counters(struct fp_context *fp, struct rast_stats *out)
{
   draw_flush(fp->draw);
   *out = *fp_context_stats(fp);
}

void fp_counter_query_begin(struct fp_context *fp, struct fp_counter_query *q)
{
   q->cycles = &fp->opts->cycles;
   read_counters(fp, &q->start);
   q->end = q->start;
}

void fp_counter_query_end(struct fp_context *fp, struct fp_counter_query *q)
{
   read_counters(fp, &q->end);
}

void fp_counter_query_result(const struct fp_counter_query *q, union pipe_query_result *result)
{
   const struct fp_driver_query *d = &queries[q->index];
   struct rast_stats w;
   rast_stats_delta(&q->start, &q->end, &w);
   const struct rast_cycle_params *p = q->cycles;
   struct rast_cycles c;
   rast_cycles_estimate(p, &w, &c);
   switch (d->figure) {
   case FIG_FIELD: {
      uint64_t v;
      memcpy(&v, (const char *)&w + d->arg, sizeof(v));
      result->u64 = v;
      break;
   }
   case FIG_SAT:
      result->u64 = w.sat[d->arg].high + w.sat[d->arg].low;
      break;
   case FIG_CYCLES: result->u64 = c.total; break;
   case FIG_CYCLES_SCAN: result->u64 = c.setup + c.scan; break;
   case FIG_CYCLES_INTERP: result->u64 = c.interp; break;
   case FIG_CYCLES_TEXTURE: result->u64 = c.texture; break;
   case FIG_CYCLES_BACKEND: result->u64 = c.backend; break;
   case FIG_MODELED_US:
      result->f = (float)((double)c.total / p->clock_mhz);
      break;
   case FIG_MODELED_FPS:
      result->f = c.total ? (float)(p->clock_mhz * 1e6 / (double)c.total) : 0.0f;
      break;
   }
}
