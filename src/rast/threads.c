/*
 * A rasterizer on every core.
 *
 * The modeled hardware's cores each draw their own pixels (seeds 001 and
 * 002 make a pixel's values independent of its neighbours'); here a core
 * is a thread with its own context, and its pixels are one stretch of
 * the target's rows per batch (split_rows, below).
 *
 * With more than one thread the main context queues the primitives the
 * driver gives it (their vertices stay where the driver keeps them), and
 * rast_flush hands the queue to every thread at once.  Each thread sets up
 * every primitive that can reach its rows and walks its edges from the
 * primitive's first scan line, exactly as one thread would: the edge and
 * attribute registers at a scan line are the walk's, so nothing about a
 * pixel depends on which thread draws it.  A thread draws the spans of its own quad rows only, so
 * per pixel the primitives still land in submission order, and no two
 * threads touch the same pixel of any buffer.
 *
 * Counters: each event belongs to one stretch of work, a quad row (its
 * thread) or a primitive's set-up (the thread of the row holding its
 * top); a thread undoes what it counted in stretches not its own
 * (rast_count_stretch), and the flush adds every worker's counters to the
 * main context's.  The sums are the one-thread counts.
 *
 * rast_run_on_threads gives every thread a part of work outside the model
 * that divides by rows (the driver's large clears), so that each thread
 * finds the rows it is about to draw in its own cache.
 *
 * Small batches, where waking the workers costs more than it saves, are
 * drawn on the calling thread alone, which owns every row for them.  The
 * workers start with the first batch that is not small: a short program
 * (a conformance test draws a few small images) never starts them.
 */
#define _POSIX_C_SOURCE 200809L        /* clock_gettime */
#include <fenv.h>
#include <math.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <pthread.h>
#include <time.h>

#include "rast/rast_priv.h"

/* Below this many pixels of bounding boxes a batch is drawn on one
 * thread (docs/threads.md). */
#define RAST_PARALLEL_MIN_PIXELS 4096
/* What a primitive's set-up and edge walk cost against a pixel it covers,
 * for dividing a batch between the threads (split_rows), and a culled
 * triangle's: fitted to the benchmark's replay (docs/threads.md). */
#define RAST_PRIM_SETUP_PIXELS 24
#define RAST_CULLED_PIXELS 1
/* Batches by size (log2 of their primitives), each with its own learned
 * speeds of the threads. */
#define RAST_BATCH_SIZES 16
/* How long a worker that has just drawn a batch polls for the next one
 * before it sleeps: a draw's next batch usually follows within
 * microseconds. */
#define RAST_SPIN_POLLS 20000

struct rast_prim {
   enum rast_prim_kind kind;
   const float (*v[3])[4];
   /* the scan lines it can cover (prim_rows), found once when queued;
    * rows_known false: every thread takes it */
   bool rows_known;
   int64_t lo, hi;
   double width;        /* what it covers on a row of its box, for the split */
   bool culled;         /* a triangle the cull stage drops (likely: for the split) */
};

/* The state a worker draws a batch with: what the setters set on the main
 * context, copied where it changed since the last batch.  The copy is the
 * batch's own, so the main context may change while the workers still
 * draw (scenes, below). */
struct rast_state_copy {
   unsigned long serial;                /* from 1; the workers compare it */
   struct rast_state_copy *next;        /* the pool's list, freed when drained */
   struct rast_framebuffer fb;
   struct rast_raster_state rs;
   struct rast_scissor scissor, viewport;
   struct rast_depth_stencil_state dsa;
   uint8_t stencil_ref[2];
   unsigned sample_mask;
   struct rast_blend_state blend;
   float blend_color[4];
   struct rast_vertex_layout vl;
   struct rast_shader fs;
   unsigned opts, interp;
   const struct numsys *texfmt;
};

/* What the workers do next, in order: a batch (its primitives, the state
 * it is drawn with, each thread's rows) or a job. */
struct rast_event {
   struct rast_prim *prim;
   size_t nprim, cap;
   const struct rast_state_copy *state;
   int64_t band_lo[RAST_MAX_THREADS], band_hi[RAST_MAX_THREADS];
   rast_job_fn job;
   void *job_arg;
   /* the submitting thread's floating-point environment: Mesa's draw
    * module sets denormals to zero around a draw, and a subnormal input
    * must read the same on every thread */
   fenv_t fenv;
};
/* Events the workers may be behind the calling thread. */
#define RAST_RING 64
/* Targets whose work per band the scenes remember. */
#define RAST_SCENE_HIST 32

/* What the last scene on a target said (a target: its size and where its
 * first colour buffer or its depth buffer is, as a program renders each
 * pass of a frame to a target of its own): the work of each of its bands,
 * and the calling thread's share of the work that balanced it. */
struct rast_scene_hist {
   unsigned width, height;
   const void *where;
   /* and how it began: a program may draw two passes to one target in a
    * frame (a background, then windows), each its own scene */
   size_t first_nprim;
   unsigned first_pixels;           /* 4 log2 of the first batch's boxes */
   int64_t first_row;               /* its first primitive's top, in 64 rows */
   size_t batches;                  /* the scene's batches */
   double *work;
   size_t nb;
   double main_share;
};

struct rast_pool {
   unsigned n;
   /* the workers' threads: started with the first batch drawn on all
    * (pool_start); if one cannot be, every batch is drawn on the caller */
   bool started, serial_only;
   struct rast_context *ctx[RAST_MAX_THREADS];   /* [0]: the main context */
   pthread_t thread[RAST_MAX_THREADS];
   bool thread_live[RAST_MAX_THREADS];

   /* the queue being filled */
   struct rast_prim *prim;
   size_t nprim, cap;
   double pixels;                                 /* the queue's bounding boxes */
   /* event e (from 1) is ring[(e - 1) % RAST_RING]; published: the last */
   struct rast_event ring[RAST_RING];
   unsigned long published;
   /* the state copies alive, the newest first, and its serial */
   struct rast_state_copy *copies;
   unsigned long copied_serial, copies_made;
   /* split_rows: the work per band of the target's rows */
   double *band_w;
   size_t band_cap;
   /* Per size of batch, each thread's time for a unit of that work, as a
    * multiple of the main thread's (learned from the batches drawn), and
    * the current batch's size. */
   float slowness[RAST_BATCH_SIZES][RAST_MAX_THREADS];
   unsigned size_class;
   /* Each thread's share of the batch: its work and its time; and a
    * worker's time drawing in the scene.  Written by that thread only, a
    * cache line apart. */
   struct {
      double work, seconds, scene_seconds;
      char apart[64 - 3 * sizeof(double)];
   } share[RAST_MAX_THREADS];
   uint64_t drawn_serial, drawn_parallel;
   uint64_t jobs_serial, jobs_parallel;           /* rast_run_on_threads */
   /* rast_get_thread_times; last_end: when the calling thread last
    * returned from the model's work (0: not yet) */
   struct rast_thread_times times;
   double last_end;

   /* Scenes (rast_set_overlap): from the first batch after a drain to the
    * next drain, every batch is cut at the same rows, so that a worker may
    * draw batches behind the calling thread without changing the order on
    * any row; the calling thread draws its rows as it submits. */
   bool overlap;
   bool scene;                        /* one is open */
   /* The calling thread draws its rows of a scene's batches one batch
    * behind, with this context and the state each batch was submitted
    * with, so that a worker done with a batch finds the next one waiting:
    * main_next is the first event whose rows it has not drawn. */
   struct rast_context *behind;
   unsigned long main_next, behind_applied;
   int64_t scene_lo[RAST_MAX_THREADS], scene_hi[RAST_MAX_THREADS];
   unsigned scene_width, scene_height;
   const void *scene_where;
   size_t scene_first_nprim;
   unsigned scene_first_pixels;
   int64_t scene_first_row;
   size_t scene_batches;
   /* its start; the calling thread's time drawing its rows, and waiting
    * for a free event (the workers RAST_RING behind) */
   double scene_t0, scene_main_seconds, scene_wait;
   double *scene_work;                /* its work per band so far */
   size_t scene_nb, scene_cap;
   struct rast_scene_hist hist[RAST_SCENE_HIST];
   unsigned hist_next;

   pthread_mutex_t mtx;
   pthread_cond_t go, done;
   atomic_ulong batch;         /* events published; a worker runs each once, in order */
   atomic_uint pending;        /* events not yet run, summed over the workers */
   atomic_bool main_sleeping;  /* the calling thread waits on `done` */
   atomic_bool quit;
};

struct rast_worker_arg {
   struct rast_pool *pool;
   unsigned t;
};

static inline void cpu_relax(void)
{
#if defined(__x86_64__) || defined(__i386__)
   __builtin_ia32_pause();
#endif
}

/* ---- which primitives a thread must look at ---- */

/* The scan lines a primitive can cover (rast_prim_extent).  false: no
 * finite extent, so every thread takes it and the set-up decides. */
static bool prim_rows(const struct rast_context *rc, const struct rast_prim *p,
                      int64_t *lo, int64_t *hi, double *width, bool *culled, double *area)
{
   float b[4];
   if (!rast_prim_extent(rc, p->kind, p->v[0], p->v[1], p->v[2], b))
      return false;
   /* floor and ceil of values inside +-1e9 (rast_prim_extent), and the
    * box clipped to the target, without library calls: this runs on the
    * main thread for every primitive queued */
   *lo = (int64_t)b[1] - ((float)(int64_t)b[1] > b[1]);
   *hi = (int64_t)b[3] + ((float)(int64_t)b[3] < b[3]);
   if (*lo < 0)
      *lo = 0;
   const double fw = (double)rc->fb.width, fh = (double)rc->fb.height;
   const double w = (b[2] < fw ? b[2] : fw) - (b[0] > 0 ? b[0] : 0.0);
   const double h = (b[3] < fh ? b[3] : fh) - (b[1] > 0 ? b[1] : 0.0);
   *area = w > 0 && h > 0 ? w * h : 0.0;
   *width = w > 0 && h > 0 ? w : 0.0;
   *culled = false;
   if (p->kind == RAST_PRIM_TRIANGLE && *width > 0) {
      /* for the split, what it covers: none where it is culled (as
       * rast_triangle_counted decides on the registers), else its area
       * spread over its box's rows */
      const unsigned ps = rc->vl.pos_slot;
      const double x0 = p->v[0][ps][0], y0 = p->v[0][ps][1], x1 = p->v[1][ps][0],
                   y1 = p->v[1][ps][1], x2 = p->v[2][ps][0], y2 = p->v[2][ps][1];
      const double det = (x0 - x2) * (y1 - y2) - (y0 - y2) * (x1 - x2);
      const unsigned facing = (unsigned)(det < 0) ^ (unsigned)rc->rs.front_ccw;
      const unsigned face = facing ? RAST_CULL_BACK : RAST_CULL_FRONT;
      *culled = (face & (unsigned)rc->rs.cull) != 0;
      const double covered = 0.5 * (det < 0 ? -det : det) / ((double)b[3] - b[1]);
      *width = *culled ? 0.0 : covered < *width ? covered : *width;
   }
   return true;
}

static inline bool owns_row(const struct rast_context *rc, int64_t row)
{
   return row >= rc->band_lo && row < rc->band_hi;
}

/* ---- which rows a thread draws ----
 *
 * Each thread draws one stretch of the target's rows per batch, cut at
 * band boundaries (RAST_BAND_ROWS) where the batch's work is divided in
 * proportion to the threads' speeds.  A primitive inside one stretch is
 * set up and walked by one thread only; dealing small bands round-robin
 * made every primitive taller than a few bands the work of every thread
 * (docs/threads.md).  Which thread draws a row changes nothing in it: one
 * thread per row, and that thread draws the batch in order.
 *
 * The work of a band: the area its primitives cover over its rows (a
 * batch has one state, so about one cost a pixel), and each primitive's
 * set-up in the band of its top row.  The speeds are learned per size of
 * batch: a worker reads the vertices and the rows the main thread has just
 * written, and for a batch of many small primitives that makes it
 * measurably slower. */
static inline double seconds_now(void)
{
   struct timespec t;
   clock_gettime(CLOCK_MONOTONIC, &t);
   return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* The calling thread enters the model's work at now: what it did since it
 * last left it is between batches. */
static double work_begins(struct rast_pool *pool)
{
   const double now = seconds_now();
   if (pool->last_end > 0)
      pool->times.between += now - pool->last_end;
   return now;
}

static unsigned size_class(size_t nprim)
{
   unsigned c = 0;
   while (nprim > 1 && c + 1 < RAST_BATCH_SIZES) {
      nprim >>= 1;
      c++;
   }
   return c;
}

/* The work of each band of rows of the batch prim[0..n) into
 * pool->band_w; its sum, 0 when the array cannot be had. */
static double band_work(struct rast_pool *pool, const struct rast_prim *prim, size_t n,
                        int64_t height, size_t nb)
{
   if (pool->band_cap < nb + 1) {
      double *w = realloc(pool->band_w, (nb + 1) * sizeof(*w));
      if (!w)
         return 0;
      pool->band_w = w;
      pool->band_cap = nb + 1;
   }
   double *bw = pool->band_w;
   memset(bw, 0, (nb + 1) * sizeof(*bw));
   /* a primitive's width on each of its rows as differences: a band's sum
    * over its rows added where the primitive begins, taken off where it
    * ends, summed below; the set-up's in the band of the top row */
   for (size_t i = 0; i < n; i++) {
      const struct rast_prim *p = &prim[i];
      if (!p->rows_known || p->lo >= height || p->hi < 0)
         continue;
      const int64_t lo = p->lo, hi = p->hi < height ? p->hi : height - 1;
      const size_t b0 = (size_t)(lo / RAST_BAND_ROWS), b1 = (size_t)(hi / RAST_BAND_ROWS);
      const double w = p->width;
      const double setup = p->culled ? RAST_CULLED_PIXELS : RAST_PRIM_SETUP_PIXELS;
      bw[b0] += setup;
      bw[b0 + 1] -= setup;
      if (b0 == b1) {
         bw[b0] += w * (double)(hi + 1 - lo);
         bw[b0 + 1] -= w * (double)(hi + 1 - lo);
         continue;
      }
      const double first = (double)((int64_t)(b0 + 1) * RAST_BAND_ROWS - lo);
      const double last = (double)(hi + 1 - (int64_t)b1 * RAST_BAND_ROWS);
      bw[b0] += w * first;
      bw[b0 + 1] += w * (RAST_BAND_ROWS - first);
      bw[b1] += w * (last - RAST_BAND_ROWS);
      bw[b1 + 1] -= w * last;
   }
   double run = 0, total = 0;
   for (size_t b = 0; b < nb; b++) {
      run += bw[b];
      bw[b] = run;
      total += run;
   }
   return total;
}

/* Thread t's rows, [lo, hi), from the cuts before each thread (in bands). */
static void rows_of_cuts(const size_t *cut, unsigned n, int64_t *lo, int64_t *hi)
{
   for (unsigned t = 0; t < n; t++) {
      lo[t] = t == 0 ? INT64_MIN : (int64_t)cut[t] * RAST_BAND_ROWS;
      hi[t] = t + 1 == n ? INT64_MAX : (int64_t)cut[t + 1] * RAST_BAND_ROWS;
   }
}

/* The cuts where work w[0..nb) divides as share[t] (summing to 1): the
 * cut before thread t where the work before it is that of the threads
 * before it, a band to whichever side holds more of it. */
static void cut_work(const double *w, size_t nb, double total, const double *share, unsigned n,
                     size_t *cut)
{
   cut[0] = 0;
   cut[n] = nb;
   if (!(total > 0)) {
      for (unsigned t = 1; t < n; t++)
         cut[t] = nb * t / n;
      return;
   }
   double acc = 0, ahead = 0;
   size_t b = 0;
   for (unsigned t = 1; t < n; t++) {
      ahead += share[t - 1];
      const double want = total * ahead;
      while (b < nb && acc + w[b] * 0.5 < want)
         acc += w[b++];
      cut[t] = b;
   }
}

/* A scene's rows for each thread, where work w[0..nb) divides as share[t]:
 * within a band at a quad row's edge, the band's work taken as even over
 * its rows.  A scene keeps its cut for all its batches, so a band's worth
 * of error would be its error throughout. */
static void cut_rows_fine(const double *w, size_t nb, double total, const double *share,
                          unsigned n, int64_t *lo, int64_t *hi)
{
   double acc = 0, ahead = 0;
   size_t b = 0;
   int64_t row = 0;
   for (unsigned t = 1; t < n; t++) {
      ahead += share[t - 1];
      const double want = total * ahead;
      while (b < nb && acc + w[b] < want)
         acc += w[b++];
      const double frac = b < nb && w[b] > 0 ? (want - acc) / w[b] : 0.0;
      const int64_t quads = (int64_t)(frac * (RAST_BAND_ROWS / 2) + 0.5);
      int64_t r = (int64_t)b * RAST_BAND_ROWS + 2 * quads;
      row = r > row ? r : row;
      hi[t - 1] = row;
      lo[t] = row;
   }
   lo[0] = INT64_MIN;
   hi[n - 1] = INT64_MAX;
}

/* The batch ev divided where its work divides in proportion to the
 * threads' learned speeds. */
static void split_rows(struct rast_pool *pool, const struct rast_context *rc,
                       struct rast_event *ev)
{
   const unsigned n = pool->n;
   const int64_t height = rc->fb.height > 0 ? rc->fb.height : 1;
   const size_t nb = (size_t)((height + RAST_BAND_ROWS - 1) / RAST_BAND_ROWS);
   const double total = band_work(pool, ev->prim, ev->nprim, height, nb);
   const float *slow = pool->slowness[pool->size_class = size_class(ev->nprim)];
   double share[RAST_MAX_THREADS] = { 0 }, speed = 0;
   size_t cut[RAST_MAX_THREADS + 1];            /* thread t: bands [cut[t], cut[t + 1]) */
   for (unsigned t = 0; t < n; t++)
      speed += 1.0 / slow[t];
   for (unsigned t = 0; t < n; t++)
      share[t] = 1.0 / slow[t] / speed;
   cut_work(pool->band_w, nb, total, share, n, cut);
   rows_of_cuts(cut, n, ev->band_lo, ev->band_hi);
   for (unsigned t = 0; t < n; t++) {
      double w = 0;
      for (size_t k = cut[t]; total > 0 && k < cut[t + 1]; k++)
         w += pool->band_w[k];
      pool->share[t].work = w;
   }
}

/* What the batch just drawn says of the threads' speeds: each thread's
 * time per unit of work against the main thread's, averaged over the
 * batches of its size.  Shares too short to time well say nothing. */
static void learn_speeds(struct rast_pool *pool)
{
   const double min_seconds = 50e-6;
   float *slow = pool->slowness[pool->size_class];
   if (pool->share[0].work <= 0 || pool->share[0].seconds < min_seconds)
      return;
   const double main_rate = pool->share[0].seconds / pool->share[0].work;
   for (unsigned t = 1; t < pool->n; t++) {
      if (pool->share[t].work <= 0 || pool->share[t].seconds < min_seconds)
         continue;
      double r = pool->share[t].seconds / pool->share[t].work / main_rate;
      r = r < 0.25 ? 0.25 : r > 4.0 ? 4.0 : r;
      slow[t] += 0.25f * ((float)r - slow[t]);
   }
}

static void draw_prim(struct rast_context *rc, const struct rast_prim *p)
{
   switch (p->kind) {
   case RAST_PRIM_TRIANGLE: rast_draw_triangle(rc, p->v[0], p->v[1], p->v[2]); break;
   case RAST_PRIM_LINE:     rast_draw_line(rc, p->v[0], p->v[1]); break;
   case RAST_PRIM_POINT:    rast_draw_point(rc, p->v[0]); break;
   }
}

/* Thread rc's share of the batch prim[0..n). */
static void draw_share(struct rast_context *rc, const struct rast_prim *prim, size_t n)
{
   for (size_t i = 0; i < n; i++) {
      const struct rast_prim *p = &prim[i];
      bool mine_setup;
      if (rc->band_count == 1) {
         mine_setup = true;
      } else if (p->rows_known) {
         /* the set-up is counted by the thread of the top row */
         mine_setup = owns_row(rc, p->lo);
         if (!mine_setup && (p->hi < rc->band_lo || p->lo >= rc->band_hi))
            continue;
      } else {
         mine_setup = rc->band_index == 0;
      }
      rast_count_stretch(rc, mine_setup);
      draw_prim(rc, p);
   }
   rast_count_stretch(rc, true);
}

/* ---- the state the workers draw with ---- */

/* The main context's state as the batches from now on draw it: the last
 * copy, or a new one where a setter changed it since.  NULL: no memory. */
static const struct rast_state_copy *state_now(struct rast_pool *pool,
                                               const struct rast_context *rc)
{
   if (pool->copies && pool->copied_serial == rc->state_serial)
      return pool->copies;
   struct rast_state_copy *c = malloc(sizeof(*c));
   if (!c)
      return NULL;
   c->serial = ++pool->copies_made;
   c->fb = rc->fb;
   c->rs = rc->rs;
   c->scissor = rc->scissor;
   c->viewport = rc->viewport;
   c->dsa = rc->dsa;
   memcpy(c->stencil_ref, rc->stencil_ref, sizeof(c->stencil_ref));
   c->sample_mask = rc->sample_mask;
   c->blend = rc->blend;
   memcpy(c->blend_color, rc->blend_color, sizeof(c->blend_color));
   c->vl = rc->vl;
   c->fs = rc->fs;
   c->opts = rc->opts;
   c->interp = rc->interp;
   c->texfmt = rc->texfmt;
   c->next = pool->copies;
   pool->copies = c;
   pool->copied_serial = rc->state_serial;
   return c;
}

/* Every copy but the newest, once no event names them. */
static void free_old_copies(struct rast_pool *pool)
{
   if (!pool->copies)
      return;
   for (struct rast_state_copy *c = pool->copies->next, *next; c; c = next) {
      next = c->next;
      free(c);
   }
   pool->copies->next = NULL;
}

/* The copy as worker t's state: the same everything but the shader's
 * context, which is the thread's own, brought up to the batch's shader
 * state by the shader's sync. */
static void apply_state(struct rast_context *w, const struct rast_state_copy *c, unsigned t)
{
   w->fb = c->fb;
   w->rs = c->rs;
   w->scissor = c->scissor;
   w->viewport = c->viewport;
   w->dsa = c->dsa;
   memcpy(w->stencil_ref, c->stencil_ref, sizeof(w->stencil_ref));
   w->sample_mask = c->sample_mask;
   w->blend = c->blend;
   memcpy(w->blend_color, c->blend_color, sizeof(w->blend_color));
   w->vl = c->vl;
   w->fs = c->fs;
   if (c->fs.thread_ctx[t])
      w->fs.ctx = c->fs.thread_ctx[t];
   w->opts = c->opts;
   w->interp = c->interp;
   w->texfmt = c->texfmt;
   w->dirty = true;
   if (w->fs.sync)
      w->fs.sync(w->fs.ctx, w->fs.sync_data);
}

/* ---- the workers ---- */

static void *worker_main(void *data)
{
   struct rast_worker_arg *arg = data;
   struct rast_pool *pool = arg->pool;
   const unsigned t = arg->t;
   free(arg);
   unsigned long seen = 0, applied = 0;
   unsigned polls = 0;          /* none before the first batch */

   for (;;) {
      unsigned long b = atomic_load_explicit(&pool->batch, memory_order_acquire);
      for (unsigned i = 0; b == seen && i < polls &&
           !atomic_load_explicit(&pool->quit, memory_order_relaxed); i++) {
         cpu_relax();
         b = atomic_load_explicit(&pool->batch, memory_order_acquire);
      }
      if (b == seen) {
         pthread_mutex_lock(&pool->mtx);
         while ((b = atomic_load_explicit(&pool->batch, memory_order_acquire)) == seen &&
                !atomic_load(&pool->quit))
            pthread_cond_wait(&pool->go, &pool->mtx);
         pthread_mutex_unlock(&pool->mtx);
      }
      if (atomic_load(&pool->quit))
         return NULL;
      polls = RAST_SPIN_POLLS;

      while (seen < b) {
         const struct rast_event *ev = &pool->ring[seen % RAST_RING];
         seen++;
         if (ev->job) {
            ev->job(ev->job_arg, t, pool->n);
         } else {
            struct rast_context *w = pool->ctx[t];
            const double t0 = seconds_now();
            if (ev->state->serial != applied) {
               apply_state(w, ev->state, t);
               applied = ev->state->serial;
            }
            w->band_lo = ev->band_lo[t];
            w->band_hi = ev->band_hi[t];
            fesetenv(&ev->fenv);
            draw_share(w, ev->prim, ev->nprim);
            const double s = seconds_now() - t0;
            pool->share[t].seconds = s;
            pool->share[t].scene_seconds += s;
         }
         atomic_fetch_sub(&pool->pending, 1);
         if (atomic_load(&pool->main_sleeping)) {
            pthread_mutex_lock(&pool->mtx);
            pthread_cond_broadcast(&pool->done);
            pthread_mutex_unlock(&pool->mtx);
         }
      }
   }
}

/* rast_stats holds uint64_t counters only (fx_sat is two of them), and
 * two largest values, which merge by their maximum. */
static void stats_add(struct rast_stats *to, struct rast_stats *from)
{
   _Static_assert(sizeof(struct rast_stats) % sizeof(uint64_t) == 0, "counters only");
   uint64_t a[sizeof(struct rast_stats) / sizeof(uint64_t)], b[sizeof(a) / sizeof(a[0])];
   uint64_t max[2];
   for (unsigned c = 0; c < 2; c++)
      max[c] = to->interp_err_max[c] > from->interp_err_max[c] ? to->interp_err_max[c]
                                                                : from->interp_err_max[c];
   memcpy(a, to, sizeof(a));
   memcpy(b, from, sizeof(b));
   for (size_t i = 0; i < sizeof(a) / sizeof(a[0]); i++)
      a[i] += b[i];
   memcpy(to, a, sizeof(a));
   memcpy(to->interp_err_max, max, sizeof(max));
   memset(from, 0, sizeof(*from));
}

/* The workers' threads stopped and joined. */
static void pool_stop(struct rast_pool *pool)
{
   pthread_mutex_lock(&pool->mtx);
   atomic_store(&pool->quit, true);
   pthread_cond_broadcast(&pool->go);
   pthread_mutex_unlock(&pool->mtx);
   for (unsigned t = 1; t < pool->n; t++)
      if (pool->thread_live[t])
         pthread_join(pool->thread[t], NULL);
   memset(pool->thread_live, 0, sizeof(pool->thread_live));
   atomic_store(&pool->quit, false);
   pool->started = false;
}

/* Whether the workers run, started now if need be. */
static bool pool_start(struct rast_pool *pool)
{
   if (pool->started || pool->serial_only)
      return pool->started;
   for (unsigned t = 1; t < pool->n; t++) {
      struct rast_worker_arg *arg = malloc(sizeof(*arg));
      if (arg)
         *arg = (struct rast_worker_arg){ pool, t };
      if (!arg || pthread_create(&pool->thread[t], NULL, worker_main, arg) != 0) {
         free(arg);
         pool_stop(pool);
         pool->serial_only = true;
         return false;
      }
      pool->thread_live[t] = true;
   }
   pool->started = true;
   return true;
}

/* The calling thread waits until at most `left` events are still to be run
 * (summed over the workers). */
static void wait_pending(struct rast_pool *pool, unsigned left)
{
   for (unsigned i = 0; i < RAST_SPIN_POLLS && atomic_load(&pool->pending) > left; i++)
      cpu_relax();
   if (atomic_load(&pool->pending) <= left)
      return;
   pthread_mutex_lock(&pool->mtx);
   atomic_store(&pool->main_sleeping, true);
   while (atomic_load(&pool->pending) > left)
      pthread_cond_wait(&pool->done, &pool->mtx);
   atomic_store(&pool->main_sleeping, false);
   pthread_mutex_unlock(&pool->mtx);
}

/* The next event's slot, free: every worker has run the event that held
 * it.  The caller fills it and publishes it. */
static struct rast_event *next_event(struct rast_pool *pool)
{
   wait_pending(pool, RAST_RING - 1);
   return &pool->ring[pool->published % RAST_RING];
}

/* The workers on to the event just filled. */
static void publish(struct rast_pool *pool)
{
   pool->published++;
   atomic_fetch_add(&pool->pending, pool->n - 1);
   pthread_mutex_lock(&pool->mtx);
   atomic_store_explicit(&pool->batch, pool->published, memory_order_release);
   pthread_cond_broadcast(&pool->go);
   pthread_mutex_unlock(&pool->mtx);
}

/* The queue into event ev (which gives the queue its array back). */
static void take_queue(struct rast_pool *pool, struct rast_event *ev)
{
   struct rast_prim *p = ev->prim;
   const size_t cap = ev->cap;
   ev->prim = pool->prim;
   ev->cap = pool->cap;
   ev->nprim = pool->nprim;
   ev->job = NULL;
   pool->prim = p;
   pool->cap = cap;
   pool->nprim = 0;
   pool->pixels = 0;
}

/* ---- scenes ---- */

static const void *target_where(const struct rast_framebuffer *fb)
{
   return fb->nr_cbufs && fb->cbuf[0].base ? (const void *)fb->cbuf[0].base
                                           : (const void *)fb->zs.base;
}

static struct rast_scene_hist *scene_hist(struct rast_pool *pool)
{
   for (unsigned i = 0; i < RAST_SCENE_HIST; i++) {
      const struct rast_scene_hist *h = &pool->hist[i];
      if (h->work && h->width == pool->scene_width && h->height == pool->scene_height &&
          h->where == pool->scene_where && h->first_nprim == pool->scene_first_nprim &&
          h->first_pixels == pool->scene_first_pixels && h->first_row == pool->scene_first_row)
         return &pool->hist[i];
   }
   return NULL;
}

/* A scene's cut: the work per band of the last scene on its target, the
 * calling thread's share as learned there; else its first batch's work
 * (the queue), or the rows, evenly. */
static void scene_open(struct rast_pool *pool, const struct rast_context *rc)
{
   const unsigned n = pool->n;
   const int64_t height = rc->fb.height > 0 ? rc->fb.height : 1;
   const size_t nb = (size_t)((height + RAST_BAND_ROWS - 1) / RAST_BAND_ROWS);
   pool->scene_width = rc->fb.width;
   pool->scene_height = (unsigned)height;
   pool->scene_where = target_where(&rc->fb);
   pool->scene_first_nprim = pool->nprim;
   pool->scene_first_pixels = (unsigned)(4.0 * log2(pool->pixels + 1.0));
   pool->scene_first_row = pool->nprim && pool->prim[0].rows_known ? pool->prim[0].lo / 64 : -1;
   pool->scene_batches = 0;
   const struct rast_scene_hist *h = scene_hist(pool);
   double share[RAST_MAX_THREADS] = { 0 };
   /* the calling thread's share as learned for the scene, else as the
    * threads' speeds for its first batch give it */
   const float *slow = pool->slowness[size_class(pool->nprim)];
   double speed = 0;
   for (unsigned t = 0; t < n; t++)
      speed += 1.0 / slow[t];
   share[0] = h ? h->main_share : 1.0 / speed;
   for (unsigned t = 1; t < n; t++)
      share[t] = h ? (1.0 - share[0]) / (n - 1) : 1.0 / slow[t] / speed;
   double total = 0;
   if (h && h->batches > 1 && h->nb == nb)
      for (size_t b = 0; b < nb; b++)
         total += h->work[b];
   if (total > 0) {
      cut_rows_fine(h->work, nb, total, share, n, pool->scene_lo, pool->scene_hi);
   } else if ((total = band_work(pool, pool->prim, pool->nprim, height, nb)) > 0) {
      /* a scene of one batch last time, or not seen yet: as its first
       * batch divides */
      cut_rows_fine(pool->band_w, nb, total, share, n, pool->scene_lo, pool->scene_hi);
   } else {
      /* rows in proportion to the shares */
      size_t cut[RAST_MAX_THREADS + 1];
      cut[0] = 0;
      cut[n] = nb;
      double ahead = 0;
      for (unsigned t = 1; t < n; t++) {
         ahead += share[t - 1];
         cut[t] = (size_t)(ahead * (double)nb + 0.5);
      }
      rows_of_cuts(cut, n, pool->scene_lo, pool->scene_hi);
   }
   pool->scene = true;
   pool->scene_nb = pool->scene_cap >= nb ? nb : 0;
   if (pool->scene_cap < nb) {
      double *w = realloc(pool->scene_work, nb * sizeof(*w));
      if (w) {
         pool->scene_work = w;
         pool->scene_cap = nb;
         pool->scene_nb = nb;
      }
   }
   if (pool->scene_nb)
      memset(pool->scene_work, 0, nb * sizeof(*pool->scene_work));
   pool->scene_t0 = seconds_now();
   pool->main_next = pool->published + 1;
   pool->scene_main_seconds = 0;
   pool->scene_wait = 0;
   for (unsigned t = 1; t < n; t++)
      pool->share[t].scene_seconds = 0;
}

/* The scene drawn (every event run): what it says of the next one on a
 * target of its size.  The calling thread's share is the one with which it
 * would have ended with the workers: its time per unit of work, plus its
 * own time outside its shares (the driver's, Mesa's, the program's), equal
 * to theirs.  t_end: when the calling thread began to wait for them. */
static void scene_close(struct rast_pool *pool, double t_end)
{
   const unsigned n = pool->n;
   pool->scene = false;
   if (!pool->scene_nb)
      return;
   struct rast_scene_hist *h = scene_hist(pool);
   if (!h) {
      h = &pool->hist[pool->hist_next];
      pool->hist_next = (pool->hist_next + 1) % RAST_SCENE_HIST;
      free(h->work);
      *h = (struct rast_scene_hist){ pool->scene_width, pool->scene_height, pool->scene_where,
                                     pool->scene_first_nprim, pool->scene_first_pixels,
                                     pool->scene_first_row, 0, NULL, 0, 1.0 / n };
   }
   h->batches = pool->scene_batches;
   if (h->nb != pool->scene_nb) {
      double *w = realloc(h->work, pool->scene_nb * sizeof(*w));
      if (!w)
         return;
      h->work = w;
      h->nb = pool->scene_nb;
   }
   memcpy(h->work, pool->scene_work, h->nb * sizeof(*h->work));

   double main_work = 0, work = 0, workers_seconds = 0;
   for (size_t b = 0; b < h->nb; b++) {
      work += h->work[b];
      /* the part of the band above the calling thread's last row */
      const double rows = (double)(pool->scene_hi[0] - (int64_t)b * RAST_BAND_ROWS);
      main_work += h->work[b] * (rows <= 0 ? 0.0 : rows >= RAST_BAND_ROWS ? 1.0
                                                                           : rows / RAST_BAND_ROWS);
   }
   for (unsigned t = 1; t < n; t++)
      workers_seconds += pool->share[t].scene_seconds;
   const double min_seconds = 200e-6;
   if (!(work > 0) || main_work <= 0 || main_work >= work ||
       pool->scene_main_seconds < min_seconds || workers_seconds < min_seconds)
      return;
   const double main_rate = pool->scene_main_seconds / main_work;
   const double worker_rate = workers_seconds / (work - main_work);   /* all workers together */
   const double own = t_end - pool->scene_t0 - pool->scene_main_seconds - pool->scene_wait;
   /* w0 * main_rate + own = (work - w0) * worker_rate / (n - 1) */
   const double per = worker_rate / (n - 1);
   double share = (work * per - (own > 0 ? own : 0)) / (main_rate + per) / work;
   share = share < 0.02 ? 0.02 : share > 0.98 ? 0.98 : share;
   h->main_share += 0.5 * (share - h->main_share);
}

/* ---- batches ---- */

/* The calling thread's rows of the scene's events up to `upto`, each with
 * the state and floating-point environment it was submitted with. */
static void draw_main_parts(struct rast_pool *pool, unsigned long upto)
{
   if (pool->main_next > upto)
      return;
   fenv_t env;
   fegetenv(&env);
   struct rast_context *w = pool->behind;
   const double t0 = seconds_now();
   for (; pool->main_next <= upto; pool->main_next++) {
      const struct rast_event *ev = &pool->ring[(pool->main_next - 1) % RAST_RING];
      if (ev->job)
         continue;
      if (ev->state->serial != pool->behind_applied) {
         apply_state(w, ev->state, 0);
         pool->behind_applied = ev->state->serial;
      }
      w->band_lo = ev->band_lo[0];
      w->band_hi = ev->band_hi[0];
      fesetenv(&ev->fenv);
      draw_share(w, ev->prim, ev->nprim);
   }
   fesetenv(&env);
   pool->scene_main_seconds += seconds_now() - t0;
}

unsigned rast_run_on_threads(struct rast_context *rc, rast_job_fn job, void *arg)
{
   struct rast_pool *pool = rc->pool;
   rast_flush(rc);
   /* only where the workers already run: a job alone does not start them */
   if (!pool || !pool->started) {
      job(arg, 0, 1);
      if (pool)
         pool->jobs_serial++;
      return 1;
   }
   pool->jobs_parallel++;
   const double t0 = work_begins(pool);
   struct rast_event *ev = next_event(pool);
   ev->job = job;
   ev->job_arg = arg;
   publish(pool);
   job(arg, 0, pool->n);
   wait_pending(pool, 0);
   pool->last_end = seconds_now();
   pool->times.jobs += pool->last_end - t0;
   return pool->n;
}

/* Every event run; the workers' counters into the main context's, and
 * what a scene or a batch says of the threads' speeds. */
void rast_wait(struct rast_context *rc)
{
   struct rast_pool *pool = rc->pool;
   if (!pool || !pool->scene)
      return;
   double t0 = work_begins(pool);
   draw_main_parts(pool, pool->published);
   const double t1 = seconds_now();
   pool->times.shares += t1 - t0;
   wait_pending(pool, 0);
   pool->last_end = seconds_now();
   pool->times.waiting += pool->last_end - t1;
   for (unsigned t = 1; t < pool->n; t++)
      pool->times.worker_shares += pool->share[t].scene_seconds;
   scene_close(pool, t1);
   for (unsigned t = 1; t < pool->n; t++)
      stats_add(&rc->stats, &pool->ctx[t]->stats);
   stats_add(&rc->stats, &pool->behind->stats);
   free_old_copies(pool);
}

void rast_submit(struct rast_context *rc)
{
   struct rast_pool *pool = rc->pool;
   if (!pool || !pool->nprim)
      return;

   double t0 = work_begins(pool);
   if (!pool->scene && (pool->pixels < RAST_PARALLEL_MIN_PIXELS || !pool_start(pool))) {
      /* small, or no worker: on the calling thread, every row its own */
      const size_t n = pool->nprim;
      pool->nprim = 0;
      pool->pixels = 0;
      draw_share(rc, pool->prim, n);
      pool->last_end = seconds_now();
      pool->times.alone += pool->last_end - t0;
      pool->drawn_serial += n;
      return;
   }
   const struct rast_state_copy *state = state_now(pool, rc);
   if (!state) {
      /* no memory for the copy: drawn when every thread has finished */
      rast_wait(rc);
      t0 = work_begins(pool);
      const size_t n = pool->nprim;
      pool->nprim = 0;
      pool->pixels = 0;
      draw_share(rc, pool->prim, n);
      pool->last_end = seconds_now();
      pool->times.alone += pool->last_end - t0;
      pool->drawn_serial += n;
      return;
   }

   if (pool->overlap && !pool->scene)
      scene_open(pool, rc);
   const double tw = seconds_now();
   struct rast_event *ev = next_event(pool);
   const double waited = seconds_now() - tw;
   pool->scene_wait += waited;
   pool->times.waiting += waited;
   take_queue(pool, ev);
   ev->state = state;
   fegetenv(&ev->fenv);
   if (pool->scene) {
      pool->scene_batches++;
      memcpy(ev->band_lo, pool->scene_lo, sizeof(ev->band_lo));
      memcpy(ev->band_hi, pool->scene_hi, sizeof(ev->band_hi));
      if (pool->scene_nb) {
         const double total = band_work(pool, ev->prim, ev->nprim, pool->scene_height,
                                        pool->scene_nb);
         for (size_t b = 0; total > 0 && b < pool->scene_nb; b++)
            pool->scene_work[b] += pool->band_w[b];
      }
   } else {
      split_rows(pool, rc, ev);
   }
   publish(pool);
   if (pool->scene) {
      /* Its own rows of the batches before, while the workers have more
       * than the one they draw: else it goes on to the next batch first, so
       * that they do not wait for it (at most half the ring behind). */
      while (pool->main_next < pool->published &&
             (atomic_load(&pool->pending) >= 2 * (pool->n - 1) ||
              pool->published - pool->main_next >= RAST_RING / 2))
         draw_main_parts(pool, pool->main_next);
      pool->drawn_parallel += ev->nprim;
      const double t2 = seconds_now();
      pool->times.shares += t2 - t0 - waited;
      pool->last_end = t2;
      return;
   }

   /* the calling thread's own rows */
   rc->band_count = pool->n;
   rc->band_lo = ev->band_lo[0];
   rc->band_hi = ev->band_hi[0];
   const double t1 = seconds_now();
   draw_share(rc, ev->prim, ev->nprim);
   const double t2 = seconds_now();
   rc->band_count = 1;
   rc->band_lo = INT64_MIN;
   rc->band_hi = INT64_MAX;
   pool->share[0].seconds = t2 - t1;
   pool->drawn_parallel += ev->nprim;
   pool->times.shares += t2 - t0 - waited;
   pool->last_end = t2;

   /* without scenes, the batch ends here */
   wait_pending(pool, 0);
   pool->last_end = seconds_now();
   pool->times.waiting += pool->last_end - t2;
   for (unsigned t = 1; t < pool->n; t++)
      pool->times.worker_shares += pool->share[t].seconds;
   learn_speeds(pool);
   for (unsigned t = 1; t < pool->n; t++)
      stats_add(&rc->stats, &pool->ctx[t]->stats);
   free_old_copies(pool);
}

void rast_flush(struct rast_context *rc)
{
   rast_submit(rc);
   rast_wait(rc);
}

bool rast_busy(const struct rast_context *rc)
{
   return rc->pool && rc->pool->scene;
}

void rast_set_overlap(struct rast_context *rc, bool on)
{
   if (!rc->pool)
      return;
   rast_flush(rc);
   rc->pool->overlap = on;
}

void rast_flush_state(struct rast_context *rc)
{
   if (rc->pool && rc->pool->scene)
      rast_submit(rc);
   else
      rast_flush(rc);
}

bool rast_queue(struct rast_context *rc, enum rast_prim_kind kind, const float (*v0)[4],
                const float (*v1)[4], const float (*v2)[4])
{
   struct rast_pool *pool = rc->pool;
   if (!pool)
      return false;
   if (pool->nprim == pool->cap) {
      size_t cap = pool->cap ? pool->cap * 2 : 1024;
      struct rast_prim *p = realloc(pool->prim, cap * sizeof(*p));
      if (!p) {
         /* drawn now, in order after what is queued */
         rast_flush(rc);
         return false;
      }
      pool->prim = p;
      pool->cap = cap;
   }
   struct rast_prim *p = &pool->prim[pool->nprim++];
   p->kind = kind;
   p->v[0] = v0;
   p->v[1] = v1;
   p->v[2] = v2;
   double area;
   p->rows_known = prim_rows(rc, p, &p->lo, &p->hi, &p->width, &p->culled, &area);
   pool->pixels += p->rows_known ? area : RAST_PARALLEL_MIN_PIXELS;
   return true;
}

/* ---- the pool's life ---- */

static void pool_destroy(struct rast_context *rc)
{
   struct rast_pool *pool = rc->pool;
   if (!pool)
      return;
   rast_flush(rc);
   pool_stop(pool);
   for (unsigned t = 1; t < pool->n; t++)
      rast_destroy(pool->ctx[t]);
   if (pool->behind)
      rast_destroy(pool->behind);
   pthread_mutex_destroy(&pool->mtx);
   pthread_cond_destroy(&pool->go);
   pthread_cond_destroy(&pool->done);
   free(pool->prim);
   for (unsigned i = 0; i < RAST_RING; i++)
      free(pool->ring[i].prim);
   for (struct rast_state_copy *c = pool->copies, *next; c; c = next) {
      next = c->next;
      free(c);
   }
   for (unsigned i = 0; i < RAST_SCENE_HIST; i++)
      free(pool->hist[i].work);
   free(pool->scene_work);
   free(pool->band_w);
   free(pool);
   rc->pool = NULL;
   rc->band_index = 0;
   rc->band_count = 1;
}

bool rast_set_threads(struct rast_context *rc, unsigned n)
{
   if (n < 1 || n > RAST_MAX_THREADS)
      return false;
   if (n == rast_get_threads(rc))
      return true;
   pool_destroy(rc);
   if (n == 1)
      return true;

   struct rast_pool *pool = calloc(1, sizeof(*pool));
   if (!pool)
      return false;
   pthread_mutex_init(&pool->mtx, NULL);
   pthread_cond_init(&pool->go, NULL);
   pthread_cond_init(&pool->done, NULL);
   for (unsigned c = 0; c < RAST_BATCH_SIZES; c++)
      for (unsigned t = 0; t < RAST_MAX_THREADS; t++)
         pool->slowness[c][t] = 1.0f;
   pool->ctx[0] = rc;
   pool->n = 1;
   rc->pool = pool;
   pool->behind = rast_create(rc->profile);
   if (!pool->behind) {
      pool_destroy(rc);
      return false;
   }
   pool->behind->band_count = n;
   for (unsigned t = 1; t < n; t++) {
      struct rast_context *w = rast_create(rc->profile);
      if (!w) {
         pool_destroy(rc);
         return false;
      }
      w->band_index = t;
      w->band_count = n;
      pool->ctx[t] = w;
      pool->n = t + 1;
   }
   rc->band_index = 0;
   return true;
}

unsigned rast_get_threads(const struct rast_context *rc)
{
   return rc->pool ? rc->pool->n : 1;
}

struct rast_context *rast_behind_context(struct rast_context *rc)
{
   return rc->pool ? rc->pool->behind : rc;
}

struct rast_context *rast_thread_context(struct rast_context *rc, unsigned t)
{
   if (t == 0 || !rc->pool || t >= rc->pool->n)
      return rc;
   return rc->pool->ctx[t];
}

void rast_get_flush_counts(const struct rast_context *rc, uint64_t *serial, uint64_t *parallel)
{
   *serial = rc->pool ? rc->pool->drawn_serial : 0;
   *parallel = rc->pool ? rc->pool->drawn_parallel : 0;
}

void rast_get_job_counts(const struct rast_context *rc, uint64_t *serial, uint64_t *parallel)
{
   *serial = rc->pool ? rc->pool->jobs_serial : 0;
   *parallel = rc->pool ? rc->pool->jobs_parallel : 0;
}

void rast_get_thread_times(const struct rast_context *rc, struct rast_thread_times *t)
{
   if (rc->pool)
      *t = rc->pool->times;
   else
      memset(t, 0, sizeof(*t));
}
