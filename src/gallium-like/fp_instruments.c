/*
 * The context's instruments, outside the drawing: FIXPIPE_STATS (the counters
 * printed at a context's end, at exit for the contexts a program leaves, and
 * every N frames), the cycle model's line, FIXPIPE_VECTORS' start, and the
 * counters the queries read.  The model counts; this prints.
 */
#include <errno.h>
#include <inttypes.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "util/simple_mtx.h"
#include "fp_context.h"
#include "fp_screen.h"
#include "fixed/numsys.h"
#include "rast/instruments/cycles.h"
#include "rast/host/lanes.h"

/* FIXPIPE_STATS=frames:N: the work counters so far, one line every N frames
 * presented (tools/replay-bench.sh takes each scene's shares of skipped
 * work from their differences). */
/* The counters as printed: the samplers' batches flushed into the model's. */
static const struct rast_stats *fp_stats(const struct fp_context *fp)
{
   for (unsigned sh = 0; sh < PIPE_SHADER_TYPES; sh++)
      if (fp->tgsi_sampler[sh])
         fp_tgsi_sampler_flush_stats(fp->tgsi_sampler[sh], fp->rast);
   for (unsigned t = 1; t < fp->num_threads; t++)
      fp_tgsi_sampler_flush_stats(fp->fs_thread[t].sampler, fp->rast);
   return rast_get_stats(fp->rast);
}

/* FIXPIPE_VECTORS=DIR: the first context of the process to draw writes the
 * scan-converter unit's vectors (docs/vectors.md; programs often make a
 * context only to ask it questions); DIR is made if missing. */
void fp_vectors_start(struct fp_context *fp)
{
   static atomic_flag taken = ATOMIC_FLAG_INIT;
   const struct fp_vectors_option *v = &fp->opts->vectors;
   fp->vectors_pending = false;
   if (!v->dir[0] || atomic_flag_test_and_set(&taken))
      return;
   char err[640];
   if (mkdir(v->dir, 0777) != 0 && errno != EEXIST)
      fprintf(stderr, "fixpipe: FIXPIPE_VECTORS: cannot make %s: %s\n", v->dir, strerror(errno));
   else if (!rast_vectors_open(fp->rast, v->dir, v->first, v->last, v->units, err,
                               sizeof(err)))
      fprintf(stderr, "fixpipe: FIXPIPE_VECTORS: %s; no vectors written\n", err);
   else {
      rast_vectors_frame(fp->rast, fp->frames);
      fp->vectors_on = true;
   }
}

const struct rast_stats *fp_context_stats(struct fp_context *fp)
{
   return fp_stats(fp);
}

/* FIXPIPE_INTERP=MODE:error: the registers against exact arithmetic. */
static void fp_print_interp_error(const struct rast_stats *st, const char *indent)
{
   for (unsigned c = 0; c < 2; c++)
      fprintf(stderr, "%sinterpolator error, %s: %" PRIu64 " values, mean %.4f, max %.4f "
              "(last bits of the register, against exact arithmetic)\n", indent,
              c ? "colour" : "z", st->interp_err_n[c],
              st->interp_err_n[c] ? (double)st->interp_err_sum[c] / 65536.0 /
                                    (double)st->interp_err_n[c] : 0.0,
              (double)st->interp_err_max[c] / 65536.0);
}

void fp_context_frame_presented(struct fp_context *fp)
{
   fp->frames++;
   rast_vectors_frame(fp->rast, fp->frames);
   fp_events_frame(fp, fp->frames - 1);
   if (!fp->stats_every || fp->frames % fp->stats_every || !fp->rast)
      return;
   const struct rast_stats *st = fp_stats(fp);
   fprintf(stderr, "fixpipe work at frame %lu: quads %" PRIu64 " divided %" PRIu64
           " skip_w %" PRIu64 " comp_quads %" PRIu64 " skip_comp %" PRIu64 " lod_quads %" PRIu64
           " skip_lod %" PRIu64 " tex_quads %" PRIu64 " skip_axes %" PRIu64
           " skip_fragcoord %" PRIu64 " skip_z %" PRIu64 " skip_early %" PRIu64
           " skip_shade %" PRIu64 " skip_terms %" PRIu64 " skip_footprint %" PRIu64 "\n",
           fp->frames,
           st->quads, st->persp_quads, st->skip_persp_w, st->persp_comp_quads,
           st->skip_persp_comp, st->tex_lod_quads, st->skip_tex_lod, st->tex_quads,
           st->skip_tex_axes, st->skip_fragcoord, st->skip_z, st->skip_early_quads,
           st->skip_shade_quads, st->skip_persp_terms, st->skip_tex_footprint);
}

/* The cycle model's estimate of the work so far (docs/cycles.md): the line
 * ./fixpipe demo shows beside the host's time. */
static void fp_print_cycles(const struct fp_context *fp, const struct rast_stats *st)
{
   const struct rast_cycle_params *p = &fp->opts->cycles;
   struct rast_cycles c;
   char params[160];
   rast_cycles_estimate(p, st, &c);
   rast_cycle_params_format(p, params, sizeof(params));
   fprintf(stderr, "  cycles (%s): set-up and scan %" PRIu64 ", interpolators %" PRIu64
           ", texture %" PRIu64 ", back end %" PRIu64 "\n", params, c.setup + c.scan, c.interp,
           c.texture, c.backend);
   const double secs = (double)c.total / (p->clock_mhz * 1e6);
   if (fp->frames)
      fprintf(stderr, "  modeled chip: %" PRIu64 " cycles over %lu frames, %.0f a frame: "
              "%.1f frames/s at %g MHz\n", c.total, fp->frames,
              (double)c.total / (double)fp->frames,
              c.total ? (double)fp->frames / secs : 0.0, p->clock_mhz);
   else
      fprintf(stderr, "  modeled chip: %" PRIu64 " cycles, %.3f ms at %g MHz\n", c.total,
              secs * 1e3, p->clock_mhz);
}

void fp_print_stats(const struct fp_context *fp)
{
   static const char *const class_names[RAST_REG_COUNT] = { "xy", "dxdy", "z", "color",
                                                                  "weight" };
   const struct rast_stats *st = fp_stats(fp);
   uint64_t quads_jit = 0, quads_interp = 0, serial, parallel, jobs_serial, jobs_parallel;
   for (unsigned t = 0; t < fp->num_threads; t++) {
      quads_jit += fp->fs_thread[t].quads_jit;
      quads_interp += fp->fs_thread[t].quads_interp;
   }
   rast_get_flush_counts(fp->rast, &serial, &parallel);
   rast_get_job_counts(fp->rast, &jobs_serial, &jobs_parallel);
   fprintf(stderr, "fixpipe stats (profile %s):\n", rast_get_profile(fp->rast)->name);
   for (unsigned i = 0; i < RAST_REG_COUNT; i++)
      fprintf(stderr, "  saturation %-5s high %" PRIu64 " low %" PRIu64 "\n",
              class_names[i], st->sat[i].high, st->sat[i].low);
   fprintf(stderr, "  triangles %" PRIu64 " culled %" PRIu64 " lines %" PRIu64
           " points %" PRIu64 " dropped for a non-finite position %" PRIu64 "\n",
           st->triangles, st->culled, st->lines, st->points, st->nonfinite);
   fprintf(stderr, "  triangles of type 0 %" PRIu64 ", type 1 %" PRIu64 ", type 2 %" PRIu64
           "; spans %" PRIu64 "; texels read %" PRIu64 "\n", st->tri_type[0], st->tri_type[1],
           st->tri_type[2], st->spans, st->texels);
   fprintf(stderr, "  quads %" PRIu64 " pixels covered %" PRIu64 " shaded %" PRIu64
           " samples passed %" PRIu64 "\n", st->quads, st->pixels_covered,
           st->pixels_shaded, st->samples_passed);
   fp_print_cycles(fp, st);
   fprintf(stderr, "  texture path (%s, division %s): range saturations %" PRIu64
           " flushes %" PRIu64 "; coordinates rebased (component-primitives) %" PRIu64 "\n",
           fp->opts->texfmt->name, fp->opts->perspfmt->name, st->tex_sat, st->tex_flush,
           st->tex_rebased);
   fprintf(stderr, "  datapath: %s; skipped: quads with a constant 1/w %" PRIu64
           ", constant component-quads %" PRIu64 ", texture quads without a LOD %" PRIu64
           ", texture quad-axes addressed per column or row %" PRIu64
           ", quads without gl_FragCoord %" PRIu64 ", quads without a Z walk %" PRIu64
           ", quads rejected whole before shading %" PRIu64
           ", quads not shaded (no visible effect) %" PRIu64
           ", plane terms with a zero difference (per quad) %" PRIu64
           ", quads divided per column and scan line %" PRIu64
           ", gather quads whose footprint was addressed before %" PRIu64 "\n",
           fp->opts->debug & FP_DEBUG_SCALAR ? "scalar" : rast_lanes()->isa,
           st->skip_persp_w, st->skip_persp_comp, st->skip_tex_lod, st->skip_tex_axes,
           st->skip_fragcoord, st->skip_z, st->skip_early_quads, st->skip_shade_quads,
           st->skip_persp_terms, st->skip_persp_axes, st->skip_tex_footprint);
   fprintf(stderr, "  datapath work: quads divided %" PRIu64 ", component-quads %" PRIu64
           ", texture quads with a LOD from differences %" PRIu64 ", texture quads %" PRIu64
           ", quads %" PRIu64 "\n", st->persp_quads, st->persp_comp_quads, st->tex_lod_quads,
           st->tex_quads, st->quads);
   {
      const unsigned im = fp->opts->interp;
      const double px = st->pixels_covered ? (double)st->pixels_covered : 1.0;
      fprintf(stderr, "  interpolator %s: per covered pixel %.2f additions, %.2f "
              "multiplications, %.3f divisions; pixels in the primitives' boxes %" PRIu64 "\n",
              rast_interp_name((enum rast_interp_mode)(im & 3u)), (double)st->interp_add / px,
              (double)st->interp_mul / px, (double)st->interp_div / px, st->interp_box_pixels);
      if (im & RAST_INTERP_MEASURE)
         fp_print_interp_error(st, "  ");
   }
   fprintf(stderr, "  tiles of %u: passes %" PRIu64 ", primitives clipped to the guard band %"
           PRIu64 "\n", rast_get_profile(fp->rast)->tile_size, st->tile_passes, st->tile_guard);
   fprintf(stderr, "  fragment shaders: %s, compiled %" PRIu64 " (%.1f ms) failed %" PRIu64
           " (from the disk cache %" PRIu64 "), quads compiled %" PRIu64 " interpreted %" PRIu64
           "; vertex shaders compiled %" PRIu64 " failed %" PRIu64 "; hot before a batch %" PRIu64
           ", hot after a present %" PRIu64 "\n",
           fp->jit ? "tiered" : "interpreted (nojit)", fp->jit_stats.compiled,
           fp->jit_stats.compile_ms, fp->jit_stats.failed, fp->jit_stats.cache_hits,
           quads_jit, quads_interp, fp->jit_stats.vs_compiled, fp->jit_stats.vs_failed,
           fp->jit_stats.hot_ahead,
           fp->jit_stats.hot_loop);
   fprintf(stderr, "  gathers in compiled code: quads %" PRIu64 " addressed and read there, the "
           "rest through the texture unit's C functions\n", st->tex_gather_jit);
   fprintf(stderr, "  threads %u: primitives drawn on one thread %" PRIu64 ", on all %" PRIu64
           "; large clears filled by one thread %" PRIu64 ", divided %" PRIu64,
           rast_get_threads(fp->rast), serial, parallel, jobs_serial, jobs_parallel);
   /* on the same line: seconds differ from run to run, and the threads
    * line is the one the thread-count identity test leaves out */
   if (rast_get_threads(fp->rast) > 1) {
      struct rast_thread_times tt;
      rast_get_thread_times(fp->rast, &tt);
      fprintf(stderr, "; the calling thread's seconds: its shares %.3f, waiting for the workers %.3f, "
              "batches alone %.3f, clears divided %.3f, between batches %.3f; the workers' "
              "shares %.3f", tt.shares, tt.waiting, tt.alone, tt.jobs, tt.between,
              tt.worker_shares);
   }
   fprintf(stderr, "\n");
}

/* FIXPIPE_STATS=1 prints a context's statistics when it is destroyed.  A
 * program may exit without destroying its contexts (eglretrace does): the
 * contexts still alive, listed in creation order through stats_next, print
 * theirs at exit. */
static simple_mtx_t stats_mtx = SIMPLE_MTX_INITIALIZER;
static struct fp_context *stats_live;
static bool stats_atexit;

static void fp_stats_at_exit(void)
{
   simple_mtx_lock(&stats_mtx);
   for (struct fp_context *fp = stats_live; fp; fp = fp->stats_next) {
      rast_flush(fp->rast);      /* what the threads still hold */
      fp_print_stats(fp);
   }
   stats_live = NULL;
   simple_mtx_unlock(&stats_mtx);
}

void fp_stats_track(struct fp_context *fp, bool live)
{
   simple_mtx_lock(&stats_mtx);
   if (live && !stats_atexit)
      stats_atexit = atexit(fp_stats_at_exit) == 0;
   struct fp_context **p = &stats_live;
   while (*p && *p != fp)
      p = &(*p)->stats_next;
   if (live) {
      fp->stats_next = NULL;
      *p = fp;                   /* the end of the list */
   } else if (*p) {
      *p = fp->stats_next;
   }
   simple_mtx_unlock(&stats_mtx);
}
