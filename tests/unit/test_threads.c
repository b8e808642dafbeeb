/*
 * The model on many threads (threads.c) against one: random batches of
 * triangles, lines and points, many of them small and across the bands'
 * boundaries, with depth, stencil and order-dependent blending, drawn with
 * random thread counts.  Colour, depth and stencil bytes and every counter
 * must be those of one thread, in each FIXPIPE_INTERP mode (whose coverage
 * must be scanline's); each thread must shade with its own shader context.
 * rast_run_on_threads must run its job once on each thread, after the queue
 * is drawn (on the caller alone before the workers start).  Run under
 * ThreadSanitizer by `./fixpipe check` (build/tsan).
 */
#include <math.h>
#if defined(__x86_64__) || defined(__i386__)
#include <xmmintrin.h>
#endif
#include <string.h>
#include "tutil.h"

#define W 203
#define H 150
#define MAX_PRIMS 600
#define SLOTS T_PERSP_COLOR_SLOTS

struct shade_ctx {
   uint64_t quads;                  /* written by this thread only */
   unsigned thread;
};

static unsigned shade(void *ctx, const struct rast_quad *q, struct rast_shaded_quad *out)
{
   struct shade_ctx *s = ctx;
   s->quads++;
   for (unsigned p = 0; p < RAST_QUAD_SIZE; p++) {
      out->color[0][0][p] = q->in[0][0][p];
      out->color[0][1][p] = q->in[0][1][p];
      out->color[0][2][p] = q->in[1][2][p];
      out->color[0][3][p] = 0.25f + 0.5f * q->in[1][3][p];
   }
   return q->mask;
}

struct scene {
   unsigned nbatch;
   unsigned nprim[8];
   unsigned kind[8][MAX_PRIMS];     /* 0 triangle, 1 line, 2 point */
   float v[8][MAX_PRIMS][3][SLOTS][4];
   bool blend[8];
   float line_width[8], point_size[8];
};

static uint64_t rng;

static float frnd(float lo, float hi)
{
   return lo + (hi - lo) * (float)(t_xorshift(&rng) >> 11) * (1.0f / 9007199254740992.0f);
}

static void make_vertex(float (*v)[4], float x, float y)
{
   /* now and then a w or a value far from 1: the texture path's range
    * events (saturation, flush to zero) must be counted once too */
   bool far = t_xorshift(&rng) % 4 == 0;
   float w = far ? ldexpf(1.0f, (int)(t_xorshift(&rng) % 40) - 20) : frnd(0.3f, 3.0f);
   float a = far ? ldexpf(1.0f, -(int)(t_xorshift(&rng) % 150)) : 1.0f;   /* to subnormals */
   v[0][0] = x; v[0][1] = y; v[0][2] = frnd(0.0f, 1.0f); v[0][3] = 1.0f / w;
   /* A/w, as draw hands PERSPECTIVE inputs over */
   v[1][0] = a * frnd(0, 1) / w; v[1][1] = frnd(0, 1) / w; v[1][2] = 0; v[1][3] = 0;
   for (unsigned c = 0; c < 4; c++)
      v[2][c] = frnd(0, 1);
}

static void make_scene(struct scene *s)
{
   s->nbatch = 1 + (unsigned)(t_xorshift(&rng) % 8);
   for (unsigned b = 0; b < s->nbatch; b++) {
      /* a third of the batches few and large, as a window or a full-screen
       * pass: each crosses the cuts, and the walk stops at its stretch */
      const bool few = t_xorshift(&rng) % 3 == 0;
      s->nprim[b] = 1 + (unsigned)(t_xorshift(&rng) % (few ? 8 : MAX_PRIMS));
      s->blend[b] = t_xorshift(&rng) & 1;
      s->line_width[b] = frnd(1.0f, 6.0f);
      s->point_size[b] = frnd(1.0f, 40.0f);
      for (unsigned i = 0; i < s->nprim[b]; i++) {
         unsigned r = (unsigned)(t_xorshift(&rng) % 10);
         s->kind[b][i] = r < 7 ? 0 : r < 9 ? 1 : 2;
         /* mostly small, near a band boundary; some large; some off the target */
         float cy = (float)(RAST_BAND_ROWS * (t_xorshift(&rng) % (H / RAST_BAND_ROWS + 2))) - 4;
         float cx = frnd(-10, W + 10);
         float size = few || (t_xorshift(&rng) % 8) == 0 ? frnd(20, 300) : frnd(0.5f, 12);
         for (unsigned k = 0; k < 3; k++)
            make_vertex(s->v[b][i][k], cx + frnd(-size, size), cy + frnd(-size, size));
      }
   }
}

struct result {
   uint8_t color[W * H * 4];
   uint32_t zs[W * H];
   struct rast_stats stats;
   uint64_t quads_shaded;
   unsigned threads_shading;
};

/* `shade` on every thread, each with its own context sctx[t]. */
static void bind_shader(struct rast_context *rc, struct shade_ctx *sctx, unsigned threads)
{
   struct rast_shader fs;
   memset(&fs, 0, sizeof(fs));
   fs.ctx = &sctx[0];
   fs.shade = shade;
   fs.num_outputs = 1;
   for (unsigned t = 1; t < threads; t++) {
      sctx[t].thread = t;
      fs.thread_ctx[t] = &sctx[t];
   }
   rast_set_shader(rc, &fs);
}

static void draw_scene(const struct scene *s, unsigned threads, bool daz, unsigned interp,
                       struct result *res)
{
   static struct shade_ctx sctx[RAST_MAX_THREADS];
   struct rast_context *rc = rast_create(rast_profile_by_name("seed"));
   CHECK(rast_set_threads(rc, threads), "%u threads", threads);
   rast_set_interp(rc, interp);
#if defined(__x86_64__) || defined(__i386__)
   /* With daz, drawn as Mesa's draw module leaves the thread around a draw:
    * denormals flushed to zero (FTZ) and read as zero (DAZ), set after the
    * workers started.  They must compute in the same mode. */
   const unsigned csr = _mm_getcsr();
   if (daz)
      _mm_setcsr(csr | 0x8040);
#else
   (void)daz;
#endif
   CHECK(rast_get_threads(rc) == threads, "threads %u", rast_get_threads(rc));
   memset(sctx, 0, sizeof(sctx));
   memset(res->color, 0x40, sizeof(res->color));
   for (unsigned i = 0; i < W * H; i++)
      res->zs[i] = 0x00ffffffu;        /* depth far, stencil 0 */

   t_bind_rgba8_z24s8(rc, res->color, res->zs, W, H);
   t_layout_persp_color(rc);

   bind_shader(rc, sctx, threads);

   t_depth_count_hits(rc, RAST_FUNC_LEQUAL);

   for (unsigned b = 0; b < s->nbatch; b++) {
      struct rast_blend_state bs;
      memset(&bs, 0, sizeof(bs));
      bs.rt[0] = (struct rast_blend_target){ s->blend[b], RAST_BLEND_ADD, RAST_BLEND_ADD,
                                             RAST_BF_SRC_ALPHA, RAST_BF_INV_SRC_ALPHA,
                                             RAST_BF_ONE, RAST_BF_INV_SRC_ALPHA, 0xf };
      rast_set_blend(rc, &bs);
      struct rast_raster_state rs;
      memset(&rs, 0, sizeof(rs));
      rs.half_pixel_center = true;
      rs.line_width = s->line_width[b];
      rs.point_size = s->point_size[b];
      rs.point_quad_rasterization = true;
      rs.cull = b % 3 == 2 ? RAST_CULL_BACK : RAST_CULL_NONE;
      rast_set_raster_state(rc, &rs);
      for (unsigned i = 0; i < s->nprim[b]; i++) {
         const float (*v0)[4] = T_V(s->v[b][i][0]);
         const float (*v1)[4] = T_V(s->v[b][i][1]);
         const float (*v2)[4] = T_V(s->v[b][i][2]);
         switch (s->kind[b][i]) {
         case 0: rast_triangle(rc, v0, v1, v2); break;
         case 1: rast_line(rc, v0, v1); break;
         default: rast_point(rc, v0); break;
         }
      }
      rast_flush(rc);
   }
   res->stats = *rast_get_stats(rc);
   res->quads_shaded = 0;
   res->threads_shading = 0;
   for (unsigned t = 0; t < threads; t++) {
      CHECK(sctx[t].thread == t, "thread %u shaded with context %u", t, sctx[t].thread);
      res->quads_shaded += sctx[t].quads;
      res->threads_shading += sctx[t].quads != 0;
   }
#if defined(__x86_64__) || defined(__i386__)
   _mm_setcsr(csr);
#endif
   rast_destroy(rc);
}

/* rast_run_on_threads: the job runs once on each thread, after the queue
 * is drawn; on the caller alone (n = 1) while the workers have not started. */
struct job_log {
   _Atomic unsigned calls[RAST_MAX_THREADS];
   _Atomic unsigned wrong_n;
   unsigned n;
   const uint8_t *color;           /* the pixel the queued triangle covers */
   _Atomic unsigned saw_clear_value;
};

static void job_record(void *arg, unsigned t, unsigned n)
{
   struct job_log *l = arg;
   if (n != l->n || t >= n)
      l->wrong_n++;
   else
      l->calls[t]++;
   if (l->color && l->color[0] == 0x40 && l->color[1] == 0x40)
      l->saw_clear_value++;
}

static void test_jobs(void)
{
   enum { threads = 4 };
   static uint8_t color[W * H * 4];
   static uint32_t zs[W * H];
   static struct shade_ctx sctx[threads];
   static float v[3][SLOTS][4];
   struct rast_context *rc = rast_create(rast_profile_by_name("seed"));
   CHECK(rast_set_threads(rc, threads), "%u threads", threads);
   memset(color, 0x40, sizeof(color));
   memset(zs, 0xff, sizeof(zs));
   t_bind_rgba8_z24s8(rc, color, zs, W, H);
   t_layout_persp_color(rc);
   bind_shader(rc, sctx, threads);
   struct rast_blend_state bs;
   memset(&bs, 0, sizeof(bs));
   bs.rt[0] = (struct rast_blend_target){ false, RAST_BLEND_ADD, RAST_BLEND_ADD, RAST_BF_ONE,
                                          RAST_BF_ZERO, RAST_BF_ONE, RAST_BF_ZERO, 0xf };
   rast_set_blend(rc, &bs);
   /* a triangle over the whole target, w = 1, its colour (the shader's
    * red and green from slot 1) 1.0: never the 0x40 the target is set to */
   const float xy[3][2] = { { -50, -50 }, { 2 * W + 50, -50 }, { -50, 2 * H + 50 } };
   for (unsigned k = 0; k < 3; k++) {
      const float vert[SLOTS][4] = { { xy[k][0], xy[k][1], 0.5f, 1.0f },
                                     { 1.0f, 1.0f, 0.0f, 0.0f },
                                     { 1.0f, 1.0f, 1.0f, 1.0f } };
      memcpy(v[k], vert, sizeof(vert));
   }

   for (unsigned round = 0; round < 3; round++) {
      /* round 0: nothing drawn yet, the workers asleep: the caller alone;
       * 1 and 2: after a large batch started them, every thread, with a
       * triangle still queued that the job must find drawn */
      struct job_log log = { .n = round == 0 ? 1 : threads };
      if (round > 0) {
         memset(color, 0x40, sizeof(color));
         memset(zs, 0xff, sizeof(zs));
         rast_triangle(rc, T_V(v[0]), T_V(v[1]), T_V(v[2]));
         log.color = &color[((H / 2) * W + W / 2) * 4];
      }
      const unsigned n = rast_run_on_threads(rc, job_record, &log);
      CHECK(n == log.n, "round %u: the job ran on %u threads, expected %u", round, n, log.n);
      CHECK(log.wrong_n == 0, "round %u: %u calls with a wrong thread or count", round,
            (unsigned)log.wrong_n);
      for (unsigned t = 0; t < log.n; t++)
         CHECK(log.calls[t] == 1, "round %u: thread %u ran the job %u times", round, t,
               (unsigned)log.calls[t]);
      CHECK(log.saw_clear_value == 0, "round %u: the job ran before the queued triangle", round);
   }
   uint64_t serial, parallel;
   rast_get_job_counts(rc, &serial, &parallel);
   CHECK(serial == 1 && parallel == 2, "job counts %llu on one thread, %llu on all",
         (unsigned long long)serial, (unsigned long long)parallel);

   /* where the calling thread's time went: two batches on all threads and
    * two jobs so far, none alone; then a small triangle, drawn alone */
   struct rast_thread_times tt;
   rast_get_thread_times(rc, &tt);
   CHECK(tt.shares > 0 && tt.worker_shares > 0 && tt.jobs > 0 && tt.between > 0 &&
         tt.waiting >= 0 && tt.alone == 0,
         "times after two batches and jobs: shares %g, workers %g, jobs %g, between %g, "
         "waiting %g, alone %g", tt.shares, tt.worker_shares, tt.jobs, tt.between, tt.waiting,
         tt.alone);
   for (unsigned k = 0; k < 3; k++) {
      v[k][0][0] = 8.0f + 4.0f * (float)(k == 1);
      v[k][0][1] = 8.0f + 4.0f * (float)(k == 2);
   }
   const struct rast_thread_times before = tt;
   rast_triangle(rc, T_V(v[0]), T_V(v[1]), T_V(v[2]));
   rast_flush(rc);
   rast_get_thread_times(rc, &tt);
   CHECK(tt.alone > 0 && tt.shares == before.shares && tt.jobs == before.jobs &&
         tt.between > before.between,
         "a small batch: alone %g, shares %g (before %g), between %g (before %g)", tt.alone,
         tt.shares, before.shares, tt.between, before.between);
   rast_destroy(rc);

   /* one thread: no pool, nothing timed */
   rc = rast_create(rast_profile_by_name("seed"));
   rast_get_thread_times(rc, &tt);
   CHECK(tt.shares == 0 && tt.between == 0 && tt.alone == 0, "one thread has times");
   rast_destroy(rc);
}

int main(void)
{
   static struct scene scene;
   static struct result one, many;
   unsigned scenes = 0, parallel_scenes = 0;
   uint64_t range_events = 0;
   rng = 0x7e1f00d5eed5ull;
   test_jobs();

   for (unsigned n = 0; n < 60; n++) {
      make_scene(&scene);
      unsigned threads = 2 + (unsigned)(t_xorshift(&rng) % 7);
      if (n % 10 == 9)
         threads = RAST_MAX_THREADS;
      /* every FIXPIPE_INTERP mode, measured or not, in turn */
      const unsigned interp = n % 3 | (n % 6 >= 3 ? RAST_INTERP_MEASURE : 0u);
      draw_scene(&scene, 1, n & 1, interp, &one);
      draw_scene(&scene, threads, n & 1, interp, &many);
      if (interp != RAST_INTERP_SCANLINE) {
         /* the scan converter's coverage, whatever the interpolator */
         static struct result walk;
         draw_scene(&scene, 1, n & 1, RAST_INTERP_SCANLINE, &walk);
         CHECK(walk.stats.quads == one.stats.quads &&
               walk.stats.pixels_covered == one.stats.pixels_covered &&
               walk.stats.triangles == one.stats.triangles,
               "scene %u: %s covers %llu pixels in %llu quads, scanline %llu in %llu", n,
               rast_interp_name(interp & 3u), (unsigned long long)one.stats.pixels_covered,
               (unsigned long long)one.stats.quads, (unsigned long long)walk.stats.pixels_covered,
               (unsigned long long)walk.stats.quads);
      }
      if (interp & RAST_INTERP_MEASURE)
         /* points are not measured: their registers are the vertex's */
         CHECK(one.stats.interp_err_n[0] > 0 &&
               one.stats.interp_err_n[0] <= one.stats.pixels_covered,
               "scene %u: %llu Z values measured of %llu pixels covered", n,
               (unsigned long long)one.stats.interp_err_n[0],
               (unsigned long long)one.stats.pixels_covered);
      scenes++;
      parallel_scenes += many.threads_shading > 1;
      range_events += one.stats.tex_sat + one.stats.tex_flush;
      CHECK(!memcmp(one.color, many.color, sizeof(one.color)),
            "scene %u: colour differs with %u threads", n, threads);
      CHECK(!memcmp(one.zs, many.zs, sizeof(one.zs)),
            "scene %u: depth/stencil differs with %u threads", n, threads);
      CHECK(!memcmp(&one.stats, &many.stats, sizeof(one.stats)),
            "scene %u: counters differ with %u threads (quads %llu vs %llu, triangles %llu vs "
            "%llu, xy sat %llu vs %llu)", n, threads,
            (unsigned long long)one.stats.quads, (unsigned long long)many.stats.quads,
            (unsigned long long)one.stats.triangles, (unsigned long long)many.stats.triangles,
            (unsigned long long)one.stats.sat[RAST_REG_XY].high,
            (unsigned long long)many.stats.sat[RAST_REG_XY].high);
      CHECK(one.quads_shaded == many.quads_shaded && one.quads_shaded > 0,
            "scene %u: quads shaded %llu on one thread, %llu on %u", n,
            (unsigned long long)one.quads_shaded, (unsigned long long)many.quads_shaded,
            threads);
   }
   /* The comparison means something only if the threads shared the work. */
   CHECK(parallel_scenes * 2 > scenes, "only %u of %u scenes shaded on more than one thread",
         parallel_scenes, scenes);
   CHECK(range_events > 0, "no range events in the texture path: nothing proven about their counts");
   printf("%u scenes, %u shaded on several threads, %llu texture-path range events\n", scenes,
          parallel_scenes, (unsigned long long)range_events);
   return t_summary("threads");
}
