/*
 * A rasterizer on every core.
 *
 * The modeled hardware's cores each draw their own pixels (seeds 001 and
 * 002 make a pixel's values independent of its neighbours'); here a core
 * is a thread with its own context, and its pixels are the quad rows of
 * every n-th band of RAST_BAND_ROWS scan lines.
 *
 * With more than one thread the main context queues the primitives the
 * driver gives it (their vertices stay where the driver keeps them), and
 * rast_flush hands the queue to every thread at once.  Each thread sets up
 * every primitive that can reach its bands and walks its edges over every
 * scan line, exactly as one thread would: the edge and attribute registers
 * at a scan line are the walk's, so nothing about a pixel depends on which
 * thread draws it.  A thread draws the spans of its own quad rows only, so
 * per pixel the primitives still land in submission order, and no two
 * threads touch the same pixel of any buffer.
 *
 * Counters: each event belongs to one stretch of work, a quad row (its
 * band's thread) or a primitive's set-up (the thread of the band holding
 * its top); a thread undoes what it counted in stretches not its own
 * (rast_count_stretch), and the flush adds every worker's counters to the
 * main context's.  The sums are the one-thread counts.
 *
 * Small batches, where waking the workers costs more than it saves, are
 * drawn on the calling thread alone, which owns every band for them.  The
 * workers start with the first batch that is not small: a short program
 * (a conformance test draws a few small images) never starts them.
 */
#include <fenv.h>
#include <math.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include <pthread.h>

#include "rast/rast_priv.h"

/* Below this many pixels of bounding boxes a batch is drawn on one
 * thread (docs/threads.md). */
#define RAST_PARALLEL_MIN_PIXELS 4096
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
   uint64_t drawn_serial, drawn_parallel;

   /* The flushing thread's floating-point environment, which the workers
    * take for the batch: Mesa's draw module sets denormals to zero around a
    * draw, and a subnormal input must read the same on every thread. */
   fenv_t fenv;

   pthread_mutex_t mtx;
   pthread_cond_t go, done;
   atomic_ulong batch;         /* batches started; a worker runs each once */
   atomic_uint pending;        /* workers still drawing the current batch */
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
                      int64_t *lo, int64_t *hi, double *area)
{
   float b[4];
   if (!rast_prim_extent(rc, p->kind, p->v[0], p->v[1], p->v[2], b))
      return false;
   *lo = (int64_t)floorf(b[1]);
   *hi = (int64_t)ceilf(b[3]);
   if (*lo < 0)
      *lo = 0;
   double w = fmin(b[2], (double)rc->fb.width) - fmax(b[0], 0.0);
   double h = fmin(b[3], (double)rc->fb.height) - fmax(b[1], 0.0);
   *area = w > 0 && h > 0 ? w * h : 0.0;
   return true;
}

static inline unsigned band_of(const struct rast_context *rc, int64_t row)
{
   return (unsigned)((uint64_t)row / RAST_BAND_ROWS % rc->band_count);
}

static bool bands_meet(const struct rast_context *rc, int64_t lo, int64_t hi)
{
   if (lo > hi)
      return false;
   uint64_t b0 = (uint64_t)lo / RAST_BAND_ROWS, b1 = (uint64_t)hi / RAST_BAND_ROWS;
   if (b1 - b0 + 1 >= rc->band_count)
      return true;
   for (uint64_t b = b0; b <= b1; b++)
      if (b % rc->band_count == rc->band_index)
         return true;
   return false;
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
         /* the set-up is counted by the thread of the top band */
         mine_setup = band_of(rc, p->lo) == rc->band_index;
         if (!mine_setup && !bands_meet(rc, p->lo, p->hi))
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

      fesetenv(&pool->fenv);
      draw_share(pool->ctx[t], pool);

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

void rast_flush(struct rast_context *rc)
{
   struct rast_pool *pool = rc->pool;
   if (!pool || !pool->nprim)
      return;

   if (pool->pixels < RAST_PARALLEL_MIN_PIXELS || !pool_start(pool)) {
      draw_share(rc, pool);
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
   rc->band_count = pool->n;
   fegetenv(&pool->fenv);
   atomic_store_explicit(&pool->pending, pool->n - 1, memory_order_relaxed);
   pthread_mutex_lock(&pool->mtx);
   atomic_fetch_add_explicit(&pool->batch, 1, memory_order_release);
   pthread_cond_broadcast(&pool->go);
   pthread_mutex_unlock(&pool->mtx);

   draw_share(rc, pool);

   for (unsigned i = 0; i < RAST_SPIN_POLLS &&
        atomic_load_explicit(&pool->pending, memory_order_acquire); i++)
      cpu_relax();
   if (atomic_load_explicit(&pool->pending, memory_order_acquire)) {
      pthread_mutex_lock(&pool->mtx);
      while (atomic_load_explicit(&pool->pending, memory_order_acquire))
         pthread_cond_wait(&pool->done, &pool->mtx);
      pthread_mutex_unlock(&pool->mtx);
   }
   rc->band_count = 1;
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
   p->rows_known = prim_rows(rc, p, &p->lo, &p->hi, &area);
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
