/*
 * The cycle model: how many clocks the modeled chip's units would take for
 * the work the model counted (docs/cycles.md).  The seeds give throughputs,
 * not a pipeline: the span processor of seed 000 draws one pixel a clock
 * with one ceil a span, seed 001's coordinate manager hands one pixel a
 * clock to each interpolation core, at 100 MHz.  What the seeds leave open
 * (a set-up's clocks, the texture unit's rate) is a parameter with a stated
 * default, set with FIXPIPE_CYCLES=KEY=VALUE,...
 *
 * Each unit's busy clocks are its counted work times its cost; the units
 * are taken as decoupled by FIFOs, so a frame takes as long as its busiest
 * unit.  No Mesa header: the standalone tests use it.
 */
#ifndef RAST_CYCLES_H
#define RAST_CYCLES_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

struct rast_stats;

struct rast_cycle_params {
   double clock_mhz;          /* clock: seed 001's 100 MHz */
   uint32_t setup;            /* clocks a triangle, line or point set up and drawn */
   uint32_t cull;             /* clocks a culled or dropped triangle (its determinant) */
   uint32_t span;             /* clocks a span beyond its pixels (seed 000: the ceil) */
   uint32_t pixel;            /* clocks a pixel in the span processor (seed 000: 1) */
   uint32_t cores;            /* interpolation cores, a pixel a clock each (seed 001) */
   uint32_t texels;           /* texels the texture unit reads a clock */
   uint32_t fragments;        /* pixels the back end writes a clock */
};

/* The units' busy clocks and the frame's (the largest). */
struct rast_cycles {
   uint64_t setup, scan, interp, texture, backend;
   uint64_t total;
};

void rast_cycle_params_default(struct rast_cycle_params *p);

/* "KEY=VALUE,..." over the defaults (NULL or "": the defaults).  Keys:
 * clock (MHz, > 0), setup, cull, span, pixel (clocks, 0..10^6), cores,
 * texels, fragments (1..4096).  On a bad setting, false with a message
 * naming it and the accepted values in err; p keeps the defaults. */
bool rast_cycle_params_parse(const char *spec, struct rast_cycle_params *p, char *err,
                             size_t errlen);

/* "clock=100,setup=24,...": every parameter, for printing. */
void rast_cycle_params_format(const struct rast_cycle_params *p, char *buf, size_t len);

void rast_cycles_estimate(const struct rast_cycle_params *p, const struct rast_stats *st,
                          struct rast_cycles *out);

/* b - a, field by field: the work between two readings of the counters
 * (every field is a count but interp_err_max, a largest value). */
void rast_stats_delta(const struct rast_stats *a, const struct rast_stats *b,
                      struct rast_stats *out);

#endif
