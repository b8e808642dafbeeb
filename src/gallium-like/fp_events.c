/*
 * FIXPIPE_EVENTS=DIR[,frames=A-B] (docs/events.md): per draw_vbo, the range
 * events the model counted (DIR/draws.tsv), and per frame presented, where
 * on the window's picture they were (DIR/frame-NNNNNN-CLASS.pgm, made by
 * the model's instrument, rast/instruments/events.c).
 *
 * A row is a draw's difference of the counters from the end of the
 * previous draw_vbo to its own end, after the model has drawn everything
 * the draw queued (rast_flush): the rows of a run add up to the totals
 * FIXPIPE_STATS prints.  Only draws whose colour buffer 0 is a display
 * target (the window's buffer that is presented) are mapped: a texture
 * rendered to has no place on the picture.
 */
#include <errno.h>
#include <inttypes.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "fp_context.h"
#include "fp_resource.h"
#include "fp_screen.h"
#include "util/simple_mtx.h"
#include "rast/instruments/events.h"

/* the columns after frame, draw, target, width, height */
enum { EV_TRIANGLES = RAST_EV_COUNT, EV_QUADS, EV_PIXELS_SHADED, EV_COLUMNS };

struct fp_events {
   struct rast_events *rec;
   FILE *tsv;
   unsigned long draw;            /* draw_vbo calls in the frame so far */
   unsigned depth;                /* draw_vbo inside draw_vbo (multi-draw, indirect) */
   bool recording;                /* the current frame is in the range */
   bool mapped;                   /* a draw of the frame was mapped */
   uint64_t base[EV_COLUMNS];     /* the counters at the previous draw's end */
};

static void columns(struct fp_context *fp, uint64_t v[EV_COLUMNS])
{
   const struct rast_stats *st = fp_context_stats(fp);
   for (unsigned c = 0; c < RAST_EV_COUNT; c++)
      v[c] = rast_ev_count(st, (enum rast_ev_class)c);
   v[EV_TRIANGLES] = st->triangles;
   v[EV_QUADS] = st->quads;
   v[EV_PIXELS_SHADED] = st->pixels_shaded;
}

static bool in_range(const struct fp_context *fp)
{
   const struct fp_events_option *o = &fp->opts->events;
   return fp->frames >= o->first && fp->frames <= o->last;
}

/* A frame drawn but never presented (a replay that ends at its last
 * snapshot, before the trace's last swap) keeps its maps: written under its
 * number when the context ends, or at exit if the program never destroys
 * it (eglretrace does not). */
static void write_unpresented(struct fp_context *fp)
{
   struct fp_events *e = fp->events;
   if (e->recording && e->mapped) {
      char err[1100];
      rast_flush(fp->rast);
      if (!rast_events_write(e->rec, fp->opts->events.dir, fp->frames, err, sizeof(err)))
         fprintf(stderr, "fixpipe: FIXPIPE_EVENTS: %s\n", err);
   }
   e->mapped = false;
}

static simple_mtx_t live_mtx = SIMPLE_MTX_INITIALIZER;
static struct fp_context *live;   /* the recording context, until it ends */

static void at_exit(void)
{
   simple_mtx_lock(&live_mtx);
   if (live)
      write_unpresented(live);
   live = NULL;
   simple_mtx_unlock(&live_mtx);
}

/* The first context of the process to draw records (as FIXPIPE_VECTORS):
 * programs often make a context only to ask it questions. */
void fp_events_start(struct fp_context *fp)
{
   static atomic_flag taken = ATOMIC_FLAG_INIT;
   const struct fp_events_option *o = &fp->opts->events;
   fp->events_pending = false;
   if (!o->dir[0] || atomic_flag_test_and_set(&taken))
      return;
   if (mkdir(o->dir, 0777) != 0 && errno != EEXIST) {
      fprintf(stderr, "fixpipe: FIXPIPE_EVENTS: cannot make %s: %s; nothing recorded\n",
              o->dir, strerror(errno));
      return;
   }
   struct fp_events *e = calloc(1, sizeof(*e));
   char path[600];
   snprintf(path, sizeof(path), "%s/draws.tsv", o->dir);
   if (e)
      e->tsv = fopen(path, "w");
   if (e && e->tsv) {
      rast_flush(fp->rast);
      e->rec = rast_events_attach(fp->rast);
   }
   if (!e || !e->tsv || !e->rec) {
      fprintf(stderr, "fixpipe: FIXPIPE_EVENTS: cannot record in %s: %s; nothing recorded\n",
              o->dir, e && !e->tsv ? strerror(errno) : "out of memory");
      if (e && e->tsv)
         fclose(e->tsv);
      free(e);
      return;
   }
   fprintf(e->tsv, "frame\tdraw\ttarget\twidth\theight\tsat_xy\tsat_dxdy\tsat_z\tsat_color\t"
           "sat_weight\ttex_sat\ttex_flush\ttriangles\tquads\tpixels_shaded\n");
   fflush(e->tsv);
   columns(fp, e->base);
   e->recording = in_range(fp);
   fp->events = e;
   simple_mtx_lock(&live_mtx);
   live = fp;
   simple_mtx_unlock(&live_mtx);
   atexit(at_exit);
}

static const char *target_of(const struct fp_context *fp)
{
   const struct pipe_surface *cb = fp->framebuffer.nr_cbufs ? fp->framebuffer.cbufs[0] : NULL;
   if (!cb || !cb->texture)
      return "none";
   return fp_resource(cb->texture)->dt ? "display" : "offscreen";
}

void fp_events_draw_begin(struct fp_context *fp)
{
   struct fp_events *e = fp->events;
   if (e->depth++)
      return;
   const bool display = !strcmp(target_of(fp), "display");
   const bool map = e->recording && display;
   rast_flush(fp->rast);           /* the previous primitives under the previous setting */
   if (map && !rast_events_target(e->rec, true, fp->framebuffer.width, fp->framebuffer.height))
      fprintf(stderr, "fixpipe: FIXPIPE_EVENTS: out of memory for the maps\n");
   else if (!map)
      rast_events_target(e->rec, false, 0, 0);
   e->mapped |= map;
}

void fp_events_draw_end(struct fp_context *fp)
{
   struct fp_events *e = fp->events;
   if (--e->depth)
      return;
   rast_flush(fp->rast);           /* the draw's row is complete: every thread has drawn it */
   uint64_t now[EV_COLUMNS];
   columns(fp, now);
   if (e->recording) {
      fprintf(e->tsv, "%lu\t%lu\t%s\t%u\t%u", fp->frames, e->draw, target_of(fp),
              fp->framebuffer.width, fp->framebuffer.height);
      for (unsigned c = 0; c < EV_COLUMNS; c++)
         fprintf(e->tsv, "\t%" PRIu64, now[c] - e->base[c]);
      fprintf(e->tsv, "\n");
      fflush(e->tsv);
   }
   memcpy(e->base, now, sizeof(now));
   e->draw++;
}

/* Frame `frame` was presented: its maps written, the next frame's begun. */
void fp_events_frame(struct fp_context *fp, unsigned long frame)
{
   struct fp_events *e = fp->events;
   if (!e)
      return;
   rast_flush(fp->rast);
   if (e->recording && e->mapped) {
      char err[1100];
      if (!rast_events_write(e->rec, fp->opts->events.dir, frame, err, sizeof(err)))
         fprintf(stderr, "fixpipe: FIXPIPE_EVENTS: %s\n", err);
   }
   rast_events_clear(e->rec);
   e->mapped = false;
   e->draw = 0;
   e->recording = in_range(fp);
}

void fp_events_stop(struct fp_context *fp)
{
   struct fp_events *e = fp->events;
   if (!e)
      return;
   simple_mtx_lock(&live_mtx);
   write_unpresented(fp);
   live = NULL;
   simple_mtx_unlock(&live_mtx);
   rast_events_detach(fp->rast, e->rec);
   fclose(e->tsv);
   free(e);
   fp->events = NULL;
}
