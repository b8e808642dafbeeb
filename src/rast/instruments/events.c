/*
 * Per-pixel event maps (events.h has the attribution rule, docs/events.md
 * the files).  An observer from outside the data path: it reads the
 * counters the model keeps anyway, at the hooks set-up and the scan
 * converter call when installed (rast_context.observe_prim, observe_scan)
 * and around the back end's quad function, which it wraps.  Nothing of it
 * runs, and no pixel pays a branch, when it is not installed.
 *
 * Threads: each thread context has its own state (rast_ev_thread), and
 * writes only the pixels of its own rows into the shared maps.  A thread
 * keeps the counts of its own stretches of work and undoes the rest
 * (rast_count_stretch): what it keeps is stats while counting, else mark,
 * a sum that only grows, and its growth between two points is exactly the
 * events this thread counts there.  Set-up is read from stats directly,
 * kept or not: every thread that draws a primitive sets it up in full, so
 * the events are the same on each.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "rast/rast_priv.h"
#include "rast/instruments/events.h"

struct ev_quad {
   int x;
   unsigned mask;
   unsigned cls;                    /* bit c: class c charged */
};

struct rast_events {
   bool map;                        /* the primitives now drawn are mapped */
   unsigned width, height;
   uint16_t *m[RAST_EV_COUNT];      /* width * height each, row 0 first */
};

struct rast_ev_thread {
   struct rast_events *ev;
   rast_quad_func next;             /* the back end's quad function */
   uint64_t prim0[RAST_EV_COUNT];   /* stats at the primitive's start */
   unsigned setup;                  /* the classes of its set-up */
   uint64_t last[RAST_EV_COUNT];    /* kept counts at the last charge point */
   bool row_open;
   int row_y;
   struct ev_quad *row;             /* the open row's quads, charged when it ends */
   unsigned nrow, caprow;
};

static const char *const class_names[RAST_EV_COUNT] = {
   "xy", "dxdy", "z", "color", "weight", "texsat", "texflush"
};

const char *rast_ev_class_name(enum rast_ev_class c)
{
   return c < RAST_EV_COUNT ? class_names[c] : NULL;
}

uint64_t rast_ev_count(const struct rast_stats *st, enum rast_ev_class c)
{
   switch (c) {
   case RAST_EV_TEXSAT: return st->tex_sat;
   case RAST_EV_TEXFLUSH: return st->tex_flush;
   default: return st->sat[c].high + st->sat[c].low;
   }
}

static void counts(const struct rast_stats *st, uint64_t v[RAST_EV_COUNT])
{
   for (unsigned c = 0; c < RAST_EV_COUNT; c++)
      v[c] = rast_ev_count(st, (enum rast_ev_class)c);
}

/* What this thread keeps (see above). */
static void kept(const struct rast_context *rc, uint64_t v[RAST_EV_COUNT])
{
   counts(rc->counting ? &rc->stats : &rc->mark, v);
}

static unsigned moved(const uint64_t now[RAST_EV_COUNT], const uint64_t then[RAST_EV_COUNT])
{
   unsigned cls = 0;
   for (unsigned c = 0; c < RAST_EV_COUNT; c++)
      cls |= (unsigned)(now[c] != then[c]) << c;
   return cls;
}

static void mark(struct rast_events *ev, int x, int y, unsigned mask, unsigned cls)
{
   if (!ev->map || !cls)
      return;
   for (unsigned i = 0; i < 4; i++) {
      const int px = x + (int)(i & 1), py = y + (int)(i >> 1);
      if (!(mask >> i & 1) || px < 0 || py < 0 || (unsigned)px >= ev->width ||
          (unsigned)py >= ev->height)
         continue;
      const size_t at = (size_t)py * ev->width + (size_t)px;
      for (unsigned c = 0; c < RAST_EV_COUNT; c++)
         if (cls >> c & 1 && ev->m[c][at] != UINT16_MAX)
            ev->m[c][at]++;
   }
}

/* The open row's end: what it counted after its last quad goes to each. */
static void row_close(struct rast_context *rc, struct rast_ev_thread *th)
{
   if (!th->row_open)
      return;
   uint64_t now[RAST_EV_COUNT];
   kept(rc, now);
   const unsigned tail = moved(now, th->last);
   for (unsigned i = 0; i < th->nrow; i++)
      mark(th->ev, th->row[i].x, th->row_y, th->row[i].mask, th->row[i].cls | tail);
   th->nrow = 0;
   th->row_open = false;
}

static void ev_prim(struct rast_context *rc)
{
   struct rast_ev_thread *th = rc->events;
   row_close(rc, th);
   counts(&rc->stats, th->prim0);
   th->setup = 0;
}

static void ev_scan(struct rast_context *rc, int what, int64_t row)
{
   struct rast_ev_thread *th = rc->events;
   uint64_t now[RAST_EV_COUNT];
   switch (what) {
   case RAST_SCAN_BEGIN:
      counts(&rc->stats, now);
      th->setup = moved(now, th->prim0);
      break;
   case RAST_SCAN_ROW:
      row_close(rc, th);
      th->row_open = true;
      th->row_y = (int)row;
      kept(rc, th->last);
      break;
   default:
      row_close(rc, th);
      break;
   }
}

static void ev_quad(struct rast_context *rc, struct rast_quad *q)
{
   struct rast_ev_thread *th = rc->events;
   th->next(rc, q);
   uint64_t now[RAST_EV_COUNT];
   kept(rc, now);
   const unsigned cls = th->setup | moved(now, th->last);
   memcpy(th->last, now, sizeof(now));
   if (th->row_open && q->y == th->row_y) {
      if (th->nrow == th->caprow) {
         const unsigned cap = th->caprow ? 2 * th->caprow : 64;
         struct ev_quad *r = realloc(th->row, cap * sizeof(*r));
         if (r) {
            th->row = r;
            th->caprow = cap;
         }
      }
      if (th->nrow < th->caprow) {
         th->row[th->nrow++] = (struct ev_quad){ q->x, q->mask, cls };
         return;
      }
   }
   /* outside a row of the walk (or no memory): charged now */
   mark(th->ev, q->x, q->y, q->mask, cls);
}

/* One quad at a time, as the unit emits them: a group's back-end events
 * could not be told apart. */
static void ev_wrap_backend(struct rast_context *rc)
{
   rc->events->next = rc->quad;
   rc->quad = ev_quad;
   rc->quads = NULL;
}

struct rast_events *rast_events_attach(struct rast_context *rc)
{
   const unsigned n = rast_get_threads(rc);
   for (unsigned t = 0; t < n; t++)
      if (rast_thread_context(rc, t)->observe_backend)
         return NULL;                /* another instrument holds the back end */
   struct rast_events *ev = calloc(1, sizeof(*ev));
   if (!ev)
      return NULL;
   for (unsigned t = 0; t < n; t++) {
      struct rast_context *c = rast_thread_context(rc, t);
      struct rast_ev_thread *th = calloc(1, sizeof(*th));
      if (!th) {
         rast_events_detach(rc, ev);
         return NULL;
      }
      th->ev = ev;
      c->events = th;
      c->observe_prim = ev_prim;
      c->observe_scan = ev_scan;
      c->observe_backend = ev_wrap_backend;
      c->dirty = true;
   }
   return ev;
}

void rast_events_detach(struct rast_context *rc, struct rast_events *ev)
{
   rast_flush(rc);
   const unsigned n = rast_get_threads(rc);
   for (unsigned t = 0; t < n; t++) {
      struct rast_context *c = rast_thread_context(rc, t);
      if (!c->events || c->events->ev != ev)
         continue;
      free(c->events->row);
      free(c->events);
      c->events = NULL;
      c->observe_prim = NULL;
      c->observe_scan = NULL;
      c->observe_backend = NULL;
      c->dirty = true;
   }
   for (unsigned c = 0; c < RAST_EV_COUNT; c++)
      free(ev->m[c]);
   free(ev);
}

bool rast_events_target(struct rast_events *ev, bool map, unsigned width, unsigned height)
{
   ev->map = false;
   if (!map)
      return true;
   if (width != ev->width || height != ev->height || !ev->m[0]) {
      const size_t n = (size_t)width * height;
      for (unsigned c = 0; c < RAST_EV_COUNT; c++) {
         free(ev->m[c]);
         ev->m[c] = calloc(n ? n : 1, sizeof(uint16_t));
      }
      for (unsigned c = 0; c < RAST_EV_COUNT; c++)
         if (!ev->m[c]) {
            for (unsigned k = 0; k < RAST_EV_COUNT; k++) {
               free(ev->m[k]);
               ev->m[k] = NULL;
            }
            ev->width = ev->height = 0;
            return false;
         }
      ev->width = width;
      ev->height = height;
   }
   ev->map = true;
   return true;
}

const uint16_t *rast_events_map(const struct rast_events *ev, enum rast_ev_class c,
                                unsigned *width, unsigned *height)
{
   *width = ev->width;
   *height = ev->height;
   return c < RAST_EV_COUNT ? ev->m[c] : NULL;
}

void rast_events_clear(struct rast_events *ev)
{
   for (unsigned c = 0; c < RAST_EV_COUNT; c++)
      if (ev->m[c])
         memset(ev->m[c], 0, (size_t)ev->width * ev->height * sizeof(uint16_t));
}

bool rast_events_write(const struct rast_events *ev, const char *dir, unsigned long frame,
                       char *err, size_t errlen)
{
   const size_t n = (size_t)ev->width * ev->height;
   for (unsigned c = 0; c < RAST_EV_COUNT; c++) {
      const uint16_t *m = ev->m[c];
      size_t i = 0;
      while (m && i < n && !m[i])
         i++;
      if (!m || i == n)
         continue;                   /* no event of the class: no file */
      char path[1024];
      snprintf(path, sizeof(path), "%s/frame-%06lu-%s.pgm", dir, frame, class_names[c]);
      FILE *f = fopen(path, "wb");
      if (!f) {
         snprintf(err, errlen, "cannot write %s: %s", path, strerror(errno));
         return false;
      }
      fprintf(f, "P5\n%u %u\n65535\n", ev->width, ev->height);
      /* big-endian, as PGM has its 16-bit samples */
      unsigned char row[2 * 4096];
      for (size_t k = 0; k < n;) {
         size_t len = 0;
         for (; k < n && len + 2 <= sizeof(row); k++) {
            row[len++] = (unsigned char)(m[k] >> 8);
            row[len++] = (unsigned char)(m[k] & 0xff);
         }
         fwrite(row, 1, len, f);
      }
      if (fclose(f) != 0) {
         snprintf(err, errlen, "cannot write %s: %s", path, strerror(errno));
         return false;
      }
   }
   return true;
}
