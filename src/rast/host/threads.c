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

struct rast_pool {
   unsigned n;
   /* the workers' threads: started with the first batch drawn on all
    * (pool_start); if one cannot be, every batch is drawn on the caller */
   bool started, serial_only;
   struct rast_context *ctx[RAST_MAX_THREADS];   /* [0]: the main context */
   unsigned long synced[RAST_MAX_THREADS];       /* state_serial last copied */
   pthread_t thread[RAST_MAX_THREADS];
   bool thread_live[RAST_MAX_THREADS];

   struct rast_prim *prim;
   size_t nprim, cap;
   double pixels;                                 /* the queue's bounding boxes */
   /* split_rows: the work per band of the target's rows */
   double *band_w;
   size_t band_cap;
   /* Per size of batch, each thread's time for a unit of that work, as a
    * multiple of the main thread's (learned from the batches drawn), and
    * the current batch's size. */
   float slowness[RAST_BATCH_SIZES][RAST_MAX_THREADS];
   unsigned size_class;
   /* Each thread's share of the batch: its work and its time, written by
    * that thread only, a cache line apart. */
   struct {
      double work, seconds;
      char apart[64 - 2 * sizeof(double)];
   } share[RAST_MAX_THREADS];
   uint64_t drawn_serial, drawn_parallel;
   uint64_t jobs_serial, jobs_parallel;           /* rast_run_on_threads */
   /* rast_get_thread_times; last_end: when the calling thread last
    * returned from a batch or a job on all threads (0: not yet) */
   struct rast_thread_times times;
   double last_end;

   /* The flushing thread's floating-point environment, which the workers
    * take for the batch: Mesa's draw module sets denormals to zero around a
    * draw, and a subnormal input must read the same on every thread. */
   fenv_t fenv;

   pthread_mutex_t mtx;
   pthread_cond_t go, done;
   atomic_ulong batch;         /* batches started; a worker runs each once */
   atomic_uint pending;        /* workers still drawing the current batch */
   atomic_bool quit;

   /* rast_run_on_threads: the batch is this job instead of the queue */
   rast_job_fn job;
   void *job_arg;
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

/* It leaves it now, after the work begun at t0, which goes to *figure. */
static void work_ends(struct rast_pool *pool, double t0, double *figure)
{
   pool->last_end = seconds_now();
   *figure += pool->last_end - t0;
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

/* The work of each band of rows into pool->band_w; its sum, 0 when the
 * array cannot be had. */
static double band_work(struct rast_pool *pool, int64_t height, size_t nb)
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
   for (size_t i = 0; i < pool->nprim; i++) {
      const struct rast_prim *p = &pool->prim[i];
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

static void split_rows(struct rast_pool *pool, const struct rast_context *rc)
{
   const unsigned n = pool->n;
   const int64_t height = rc->fb.height > 0 ? rc->fb.height : 1;
   const size_t nb = (size_t)((height + RAST_BAND_ROWS - 1) / RAST_BAND_ROWS);
   const double total = band_work(pool, height, nb);
   const float *slow = pool->slowness[pool->size_class = size_class(pool->nprim)];
   size_t cut[RAST_MAX_THREADS + 1];            /* thread t: bands [cut[t], cut[t + 1]) */
   double speed = 0;
   for (unsigned t = 0; t < n; t++)
      speed += 1.0 / slow[t];
   cut[0] = 0;
   cut[n] = nb;
   if (total > 0) {
      /* the cut before thread t where the work before it is that of the
       * threads before it (a band to whichever side holds more of it) */
      double acc = 0, ahead = 0;
      size_t b = 0;
      for (unsigned t = 1; t < n; t++) {
         ahead += 1.0 / slow[t - 1];
         const double want = total * ahead / speed;
         while (b < nb && acc + pool->band_w[b] * 0.5 < want)
            acc += pool->band_w[b++];
         cut[t] = b;
      }
   } else {
      for (unsigned t = 1; t < n; t++)
         cut[t] = nb * t / n;
   }
   for (unsigned t = 0; t < n; t++) {
      struct rast_context *c = pool->ctx[t];
      c->band_lo = t == 0 ? INT64_MIN : (int64_t)cut[t] * RAST_BAND_ROWS;
      c->band_hi = t + 1 == n ? INT64_MAX : (int64_t)cut[t + 1] * RAST_BAND_ROWS;
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

/* Thread rc's share of the queue. */
static void draw_share(struct rast_context *rc, const struct rast_pool *pool)
{
   for (size_t i = 0; i < pool->nprim; i++) {
      const struct rast_prim *p = &pool->prim[i];
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

/* ---- the workers ---- */

static void *worker_main(void *data)
{
   struct rast_worker_arg *arg = data;
   struct rast_pool *pool = arg->pool;
   const unsigned t = arg->t;
   free(arg);
   unsigned long seen = 0;
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
      seen = b;
      polls = RAST_SPIN_POLLS;

      if (pool->job) {
         pool->job(pool->job_arg, t, pool->n);
      } else {
         fesetenv(&pool->fenv);
         const double t0 = seconds_now();
         draw_share(pool->ctx[t], pool);
         pool->share[t].seconds = seconds_now() - t0;
      }

      if (atomic_fetch_sub_explicit(&pool->pending, 1, memory_order_acq_rel) == 1) {
         pthread_mutex_lock(&pool->mtx);
         pthread_cond_signal(&pool->done);
         pthread_mutex_unlock(&pool->mtx);
      }
   }
}

/* The main context's state, as a worker's own: the same everything but
 * the shader's context, which is the worker's. */
static void sync_state(struct rast_context *w, const struct rast_context *rc, unsigned t)
{
   w->fb = rc->fb;
   w->rs = rc->rs;
   memcpy(w->scissors, rc->scissors, sizeof(w->scissors));
   memcpy(w->viewports, rc->viewports, sizeof(w->viewports));
   memcpy(w->depth_ranges, rc->depth_ranges, sizeof(w->depth_ranges));
   w->vp_index = rc->vp_index;
   w->scissor = rc->scissor;
   w->viewport = rc->viewport;
   w->dsa = rc->dsa;
   memcpy(w->stencil_ref, rc->stencil_ref, sizeof(w->stencil_ref));
   w->sample_mask = rc->sample_mask;
   w->blend = rc->blend;
   memcpy(w->blend_color, rc->blend_color, sizeof(w->blend_color));
   w->vl = rc->vl;
   w->fs = rc->fs;
   if (rc->fs.thread_ctx[t])
      w->fs.ctx = rc->fs.thread_ctx[t];
   w->opts = rc->opts;
   w->interp = rc->interp;
   w->texfmt = rc->texfmt;
   w->dirty = true;
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

/* The workers on to the next batch (the queue, or pool->job). */
static void wake_workers(struct rast_pool *pool)
{
   atomic_store_explicit(&pool->pending, pool->n - 1, memory_order_relaxed);
   pthread_mutex_lock(&pool->mtx);
   atomic_fetch_add_explicit(&pool->batch, 1, memory_order_release);
   pthread_cond_broadcast(&pool->go);
   pthread_mutex_unlock(&pool->mtx);
}

/* Returns when every worker has finished the batch. */
static void wait_workers(struct rast_pool *pool)
{
   for (unsigned i = 0; i < RAST_SPIN_POLLS &&
        atomic_load_explicit(&pool->pending, memory_order_acquire); i++)
      cpu_relax();
   if (atomic_load_explicit(&pool->pending, memory_order_acquire)) {
      pthread_mutex_lock(&pool->mtx);
      while (atomic_load_explicit(&pool->pending, memory_order_acquire))
         pthread_cond_wait(&pool->done, &pool->mtx);
      pthread_mutex_unlock(&pool->mtx);
   }
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
   pool->job = job;
   pool->job_arg = arg;
   wake_workers(pool);
   job(arg, 0, pool->n);
   wait_workers(pool);
   pool->job = NULL;
   pool->job_arg = NULL;
   work_ends(pool, t0, &pool->times.jobs);
   return pool->n;
}

void rast_flush(struct rast_context *rc)
{
   struct rast_pool *pool = rc->pool;
   if (!pool || !pool->nprim)
      return;

   const double t0 = work_begins(pool);
   const bool small = pool->pixels < RAST_PARALLEL_MIN_PIXELS && !(rc->opts & RAST_OPT_DIVIDE);
   if (small || !pool_start(pool)) {
      draw_share(rc, pool);
      work_ends(pool, t0, &pool->times.alone);
      pool->drawn_serial += pool->nprim;
      pool->nprim = 0;
      pool->pixels = 0;
      return;
   }

   for (unsigned t = 1; t < pool->n; t++) {
      if (pool->synced[t] != rc->state_serial) {
         sync_state(pool->ctx[t], rc, t);
         pool->synced[t] = rc->state_serial;
      }
   }
   split_rows(pool, rc);
   rc->band_count = pool->n;
   fegetenv(&pool->fenv);
   wake_workers(pool);

   const double t1 = seconds_now();
   draw_share(rc, pool);
   const double t2 = seconds_now();
   pool->share[0].seconds = t2 - t1;

   wait_workers(pool);
   pool->times.shares += t2 - t0;
   work_ends(pool, t2, &pool->times.waiting);
   for (unsigned t = 1; t < pool->n; t++)
      pool->times.worker_shares += pool->share[t].seconds;
   rc->band_count = 1;
   rc->band_lo = INT64_MIN;
   rc->band_hi = INT64_MAX;
   learn_speeds(pool);
   for (unsigned t = 1; t < pool->n; t++)
      stats_add(&rc->stats, &pool->ctx[t]->stats);
   pool->drawn_parallel += pool->nprim;
   pool->nprim = 0;
   pool->pixels = 0;
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
   pthread_mutex_destroy(&pool->mtx);
   pthread_cond_destroy(&pool->go);
   pthread_cond_destroy(&pool->done);
   free(pool->prim);
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
   for (unsigned t = 1; t < n; t++) {
      struct rast_context *w = rast_create(rc->profile);
      if (!w) {
         pool_destroy(rc);
         return false;
      }
      w->band_index = t;
      w->band_count = n;
      pool->ctx[t] = w;
      pool->synced[t] = rc->state_serial - 1;
      pool->n = t + 1;
   }
   rc->band_index = 0;
   return true;
}

unsigned rast_get_threads(const struct rast_context *rc)
{
   return rc->pool ? rc->pool->n : 1;
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
