/*
 * Per-pixel event maps (FIXPIPE_EVENTS, docs/events.md): for each class of
 * range event, how many quads an event of that class was charged to, per
 * pixel of the target.  The model counts its events in rast_stats; this
 * instrument watches those counters from outside, around each quad the back
 * end takes, and charges what they moved to the quad's covered pixels.
 *
 * Attribution (the same for any number of threads):
 *  - a primitive's set-up (from its start to its edges loaded, before any
 *    quad row) is charged to every quad of the primitive, triangles, lines
 *    and points alike;
 *  - within a quad row, a quad is charged with what was counted since the
 *    row began or the previous quad of the row was finished, to the end of
 *    its own back-end processing (edge walk, span, division, shading,
 *    texture sampling);
 *  - what the row counts after its last quad (the perspective division's
 *    range events, moved to the counters when the row is done) is charged
 *    to every quad of the row;
 *  - events of a primitive that has no quad, or of a quad row without one,
 *    are charged to no pixel (they are in the counters all the same).
 * Each quad row is drawn by one thread, which counts its events alone, and
 * every thread that draws a primitive does its whole set-up: no charge
 * depends on which thread drew what.
 */
#ifndef RAST_EVENTS_H
#define RAST_EVENTS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

struct rast_context;
struct rast_stats;

enum rast_ev_class {
   RAST_EV_XY, RAST_EV_DXDY, RAST_EV_Z, RAST_EV_COLOR, RAST_EV_WEIGHT,
   RAST_EV_TEXSAT, RAST_EV_TEXFLUSH,
   RAST_EV_COUNT
};

/* "xy", "dxdy", "z", "color", "weight", "texsat", "texflush" */
const char *rast_ev_class_name(enum rast_ev_class c);
/* The count of class c in a rast_stats (saturations: high + low). */
uint64_t rast_ev_count(const struct rast_stats *st, enum rast_ev_class c);

struct rast_events;

/* Installs the recorder on rc and every thread context it has (call after
 * rast_set_threads, between flushes).  NULL when out of memory. */
struct rast_events *rast_events_attach(struct rast_context *rc);
/* Removes it from every context and frees it. */
void rast_events_detach(struct rast_context *rc, struct rast_events *ev);

/* What the next primitives map: a target of width x height (the maps are
 * made that size and cleared if it differs), or nothing (map false). */
bool rast_events_target(struct rast_events *ev, bool map, unsigned width, unsigned height);
/* The map of class c, width x height counts, row 0 first (the target's
 * rows), or NULL before any target was mapped.  Read after rast_flush. */
const uint16_t *rast_events_map(const struct rast_events *ev, enum rast_ev_class c,
                                unsigned *width, unsigned *height);
/* Every map back to zero. */
void rast_events_clear(struct rast_events *ev);
/* The maps with a marked pixel as DIR/frame-NNNNNN-CLASS.pgm (16-bit
 * binary PGM, row 0 first); false with a message if one cannot be written. */
bool rast_events_write(const struct rast_events *ev, const char *dir, unsigned long frame,
                       char *err, size_t errlen);

#endif
