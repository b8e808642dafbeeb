/*
 * The cycle model (cycles.h, docs/cycles.md).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rast/host/settings.h"
#include "rast/instruments/cycles.h"
#include "rast/rast.h"

/* The defaults and why:
 *   clock 100 MHz: seed 001's FPGA figures (525 Mpixels/s at 100 MHz);
 *   setup 24: seed 000's set-up sorts three vertices and divides for the
 *     three edge slopes and the x and y gradients of Z and R, G, B: eight
 *     divisions, taken as an iterative divider of 3 clocks each;
 *   cull 2: the determinant and its sign;
 *   span 1, pixel 1: "nearly one pixel per clock (one ceil per span)";
 *   cores 6: 525 Mpixels/s at 100 MHz is 5.25 pixels a clock; with the
 *     coordinate manager's pixels of the bounding box outside the
 *     triangle, six cores;
 *   texels 4: one bilinear footprint a clock (four texel reads a clock);
 *   fragments 1: one pixel written a clock. */
void rast_cycle_params_default(struct rast_cycle_params *p)
{
   *p = (struct rast_cycle_params){
      .clock_mhz = 100.0, .setup = 24, .cull = 2, .span = 1, .pixel = 1,
      .cores = 6, .texels = 4, .fragments = 1,
   };
}

static const char accepted[] =
   "clock=MHZ (> 0, at most 100000), setup, cull, span, pixel (clocks, 0..1000000), "
   "cores, texels, fragments (1..4096)";

static bool cycle_param(void *ctx, const char *key, const char *val, char *err, size_t errlen)
{
   struct rast_cycle_params *q = ctx;
   char *end;
   if (!strcmp(key, "clock")) {
      const double d = strtod(val, &end);
      if (*end || !(d > 0.0 && d <= 100000.0)) {
         snprintf(err, errlen, "clock=%s (accepted: %s)", val, accepted);
         return false;
      }
      q->clock_mhz = d;
      return true;
   }
   const struct { const char *name; uint32_t *field; unsigned long lo, hi; } keys[] = {
      { "setup", &q->setup, 0, 1000000 },   { "cull", &q->cull, 0, 1000000 },
      { "span", &q->span, 0, 1000000 },     { "pixel", &q->pixel, 0, 1000000 },
      { "cores", &q->cores, 1, 4096 },      { "texels", &q->texels, 1, 4096 },
      { "fragments", &q->fragments, 1, 4096 },
   };
   for (size_t i = 0; i < sizeof(keys) / sizeof(keys[0]); i++) {
      if (strcmp(key, keys[i].name))
         continue;
      const unsigned long v = strtoul(val, &end, 10);
      if (*end || val[0] == '-' || v < keys[i].lo || v > keys[i].hi) {
         snprintf(err, errlen, "%s=%s (accepted: %s)", key, val, accepted);
         return false;
      }
      *keys[i].field = (uint32_t)v;
      return true;
   }
   snprintf(err, errlen, "unknown key '%s' (accepted: %s)", key, accepted);
   return false;
}

bool rast_cycle_params_parse(const char *spec, struct rast_cycle_params *p, char *err,
                             size_t errlen)
{
   struct rast_cycle_params q;
   rast_cycle_params_default(&q);
   rast_cycle_params_default(p);
   if (!spec || !*spec)
      return true;
   if (!rast_settings_each(spec, accepted, cycle_param, &q, err, errlen))
      return false;
   *p = q;
   return true;
}

void rast_cycle_params_format(const struct rast_cycle_params *p, char *buf, size_t len)
{
   snprintf(buf, len, "clock=%g,setup=%u,cull=%u,span=%u,pixel=%u,cores=%u,texels=%u,"
            "fragments=%u", p->clock_mhz, p->setup, p->cull, p->span, p->pixel, p->cores,
            p->texels, p->fragments);
}

static uint64_t ceil_div(uint64_t a, uint64_t b)
{
   return (a + b - 1) / b;
}

void rast_cycles_estimate(const struct rast_cycle_params *p, const struct rast_stats *st,
                          struct rast_cycles *c)
{
   const uint64_t drawn = st->triangles + st->lines + st->points;
   /* seed 000's unit: set-up, then its spans one pixel a clock */
   c->setup = drawn * p->setup + (st->culled + st->nonfinite) * p->cull;
   c->scan = st->spans * p->span + st->pixels_covered * p->pixel;
   /* the per-pixel independent interpolators (seeds 001, 002): every
    * covered pixel through one of the cores */
   c->interp = ceil_div(st->pixels_covered, p->cores);
   c->texture = ceil_div(st->texels, p->texels);
   c->backend = ceil_div(st->pixels_shaded, p->fragments);
   /* the set-up and the walk are one unit in seed 000 */
   const uint64_t units[] = { c->setup + c->scan, c->interp, c->texture, c->backend };
   c->total = 0;
   for (size_t i = 0; i < sizeof(units) / sizeof(units[0]); i++)
      if (units[i] > c->total)
         c->total = units[i];
}

void rast_stats_delta(const struct rast_stats *a, const struct rast_stats *b,
                      struct rast_stats *out)
{
   _Static_assert(sizeof(struct rast_stats) % sizeof(uint64_t) == 0, "counters only");
   uint64_t x[sizeof(struct rast_stats) / sizeof(uint64_t)];
   uint64_t y[sizeof(x) / sizeof(x[0])];
   memcpy(x, a, sizeof(x));
   memcpy(y, b, sizeof(y));
   for (size_t i = 0; i < sizeof(x) / sizeof(x[0]); i++)
      y[i] -= x[i];
   memcpy(out, y, sizeof(y));
}
