/*
 * The fixpipe context: owns the model (rast_context), Mesa's draw module
 * (vertex shading, clipping, divide, viewport, smooth points and lines) and
 * the tgsi_exec machine that runs fragment shaders for the model's quads.
 */
#include <errno.h>
#include <stdatomic.h>
#include <stdio.h>
#include <string.h>
#include <inttypes.h>
#include <sys/stat.h>

#include "util/u_memory.h"
#include "util/u_inlines.h"
#include "util/u_upload_mgr.h"
#include "util/u_framebuffer.h"
#include "util/simple_mtx.h"
#include "draw/draw_context.h"
#include "draw/draw_vbuf.h"
#include "tgsi/tgsi_exec.h"
#include "gallivm/lp_bld_init.h"
#include <llvm-c/Core.h>

#include "fp_context.h"
#include "fixed/numsys.h"
#include "rast/cycles.h"
#include "rast/lanes.h"
#include "fp_resource.h"
#include "fp_screen.h"
#include "util/disk_cache.h"

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

LLVMContextRef fp_llvm_context(struct fp_context *fp)
{
   if (!fp->llvm_context && fp->jit && lp_build_init()) {
      fp->llvm_context = LLVMContextCreate();
#if LLVM_VERSION_MAJOR >= 15
      if (fp->llvm_context)
         LLVMContextSetOpaquePointers(fp->llvm_context, false);
#endif
   }
   return fp->llvm_context;
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

static void fp_print_stats(const struct fp_context *fp)
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
   fprintf(stderr, "  texture path (%s): range saturations %" PRIu64 " flushes %" PRIu64
           "; coordinates rebased (component-primitives) %" PRIu64 "\n",
           fp->opts->texfmt->name, st->tex_sat, st->tex_flush, st->tex_rebased);
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

static void fp_stats_track(struct fp_context *fp, bool live)
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

static void fp_destroy(struct pipe_context *pipe)
{
   struct fp_context *fp = fp_context(pipe);

   /* Compiled shaders still queued for the disk cache are written before
    * the context goes: a program that exits once its context is destroyed,
    * its screen never (OSMesa's), lost them with the cache's thread at
    * exit, and its next run compiled them again. */
   struct disk_cache *cache = fp_screen(pipe->screen)->disk_cache;
   if (cache)
      disk_cache_wait_for_idle(cache);

   if (fp->rast && fp->print_stats) {
      fp_stats_track(fp, false);
      fp_print_stats(fp);
   }
   if (fp->rast)
      rast_set_threads(fp->rast, 1);   /* the workers stop before what they shade with goes */

   util_unreference_framebuffer_state(&fp->framebuffer);
   for (unsigned sh = 0; sh < PIPE_SHADER_TYPES; sh++) {
      for (unsigned i = 0; i < PIPE_MAX_SHADER_SAMPLER_VIEWS; i++)
         pipe_sampler_view_reference(&fp->sampler_views[sh][i], NULL);
      for (unsigned i = 0; i < PIPE_MAX_CONSTANT_BUFFERS; i++)
         pipe_resource_reference(&fp->constants[sh][i].buffer, NULL);
   }
   for (unsigned i = 0; i < PIPE_MAX_ATTRIBS; i++)
      pipe_vertex_buffer_unreference(&fp->vertex_buffer[i]);
   fp_so_release(fp);
   fp_compute_release(fp);

   if (fp->draw)
      draw_destroy(fp->draw);
   if (fp->llvm_context)
      LLVMContextDispose(fp->llvm_context);
   for (unsigned t = 0; t < fp->num_threads; t++) {
      struct fp_fs_thread *th = &fp->fs_thread[t];
      if (th->mach)
         tgsi_exec_machine_destroy(th->mach);
      if (t > 0)
         fp_tgsi_sampler_destroy(th->sampler);
   }
   FREE(fp->fs_thread);
   for (unsigned sh = 0; sh < PIPE_SHADER_TYPES; sh++)
      fp_tgsi_sampler_destroy(fp->tgsi_sampler[sh]);
   if (fp->pipe.stream_uploader)
      u_upload_destroy(fp->pipe.stream_uploader);
   if (fp->rast)
      rast_destroy(fp->rast);
   FREE(fp);
}

static void fp_flush(struct pipe_context *pipe, struct pipe_fence_handle **fence,
                     unsigned flags)
{
   struct fp_context *fp = fp_context(pipe);
   (void)flags;
   draw_flush(fp->draw);
   if (fence)
      *fence = (struct pipe_fence_handle *)(uintptr_t)1;   /* already signalled */
}

static void fp_texture_barrier(struct pipe_context *pipe, unsigned flags)
{
   (void)pipe; (void)flags;
}

static void fp_memory_barrier(struct pipe_context *pipe, unsigned flags)
{
   (void)pipe; (void)flags;
}

/* EGLImage export (dri2_create_from_texture) calls this unconditionally; the
 * model keeps nothing cached outside the resource, so there is nothing to do. */
static void fp_flush_resource(struct pipe_context *pipe, struct pipe_resource *resource)
{
   (void)pipe; (void)resource;
}

static void fp_set_debug_callback(struct pipe_context *pipe,
                                  const struct util_debug_callback *cb)
{
   if (cb)
      pipe->debug = *cb;
   else
      memset(&pipe->debug, 0, sizeof(pipe->debug));
}

/* glGetMultisamplefv: the model's pattern (rast_sample_pos_4x). */
static void fp_get_sample_position(struct pipe_context *pipe, unsigned sample_count,
                                   unsigned sample_index, float *pos)
{
   (void)pipe;
   if (sample_count == RAST_MSAA_SAMPLES && sample_index < RAST_MSAA_SAMPLES) {
      pos[0] = rast_sample_pos_4x[sample_index][0];
      pos[1] = rast_sample_pos_4x[sample_index][1];
   } else {
      pos[0] = pos[1] = 0.5f;
   }
}

struct pipe_context *fp_create_context(struct pipe_screen *screen, void *priv,
                                       unsigned flags)
{
   struct fp_screen *s = fp_screen(screen);
   struct fp_context *fp = CALLOC_STRUCT(fp_context);
   (void)flags;
   if (!fp)
      return NULL;

   fp->pipe.screen = screen;
   fp->pipe.priv = priv;
   fp->pipe.destroy = fp_destroy;
   fp->pipe.flush = fp_flush;
   fp->pipe.texture_barrier = fp_texture_barrier;
   fp->pipe.memory_barrier = fp_memory_barrier;
   fp->pipe.set_debug_callback = fp_set_debug_callback;
   fp->pipe.get_sample_position = fp_get_sample_position;
   fp->pipe.flush_resource = fp_flush_resource;
   fp->sample_mask = ~0u;
   fp->fb_samples = 1;
   fp->fs_dirty = true;
   fp->opts = s->opts;
   fp->print_stats = fp->opts->stats;
   fp->stats_every = fp->opts->stats_frames;

   fp_init_context_resource_funcs(&fp->pipe);
   fp_init_state_functions(fp);
   fp_init_shader_functions(fp);
   fp_init_fb_functions(fp);
   fp_init_clear_functions(fp);
   fp_init_blit_functions(fp);
   fp_init_query_functions(fp);
   fp_init_draw_functions(fp);
   fp_init_so_functions(fp);
   if (!fp_init_compute_functions(fp))
      goto fail;

   fp->rast = rast_create(s->profile);
   if (!fp->rast)
      goto fail;
   rast_set_texfmt(fp->rast, fp->opts->texfmt);
   rast_set_options(fp->rast, fp_options_rast(fp->opts));
   rast_set_interp(fp->rast, fp->opts->interp);
   fp->vectors_pending = fp->opts->vectors.dir[0] != '\0';

   fp->pipe.stream_uploader = u_upload_create_default(&fp->pipe);
   if (!fp->pipe.stream_uploader)
      goto fail;
   fp->pipe.const_uploader = fp->pipe.stream_uploader;

   for (unsigned sh = 0; sh < PIPE_SHADER_TYPES; sh++) {
      fp->tgsi_sampler[sh] = fp_tgsi_sampler_create(fp, (enum pipe_shader_type)sh, fp->rast);
      if (!fp->tgsi_sampler[sh])
         goto fail;
   }

   /* The model's threads, each with what it shades with. */
   unsigned threads = fp_options_threads(fp->opts);
   if (!rast_set_threads(fp->rast, threads)) {
      fprintf(stderr, "fixpipe: cannot start %u threads; drawing on one\n", threads);
      threads = 1;
   }
   fp->fs_thread = CALLOC(threads, sizeof(*fp->fs_thread));
   if (!fp->fs_thread)
      goto fail;
   for (unsigned t = 0; t < threads; t++) {
      struct fp_fs_thread *th = &fp->fs_thread[t];
      fp->num_threads = t + 1;
      th->fp = fp;
      th->rast = rast_thread_context(fp->rast, t);
      th->sampler = t == 0 ? fp->tgsi_sampler[PIPE_SHADER_FRAGMENT]
                           : fp_tgsi_sampler_create(fp, PIPE_SHADER_FRAGMENT, th->rast);
      th->mach = tgsi_exec_machine_create(PIPE_SHADER_FRAGMENT);
      if (!th->sampler || !th->mach)
         goto fail;
   }

   /* Compiled shaders: draw's LLVM vertex path and fixpipe's fragment shaders.
    * Each makes its LLVM context with its first compiled shader (draw's own,
    * fp_llvm_context), so a process that never compiles one, as most of a
    * conformance run's do not, never initializes LLVM. */
   fp->jit = !(fp->opts->debug & FP_DEBUG_NOJIT);
   if (fp->jit) {
      fp->draw = draw_create(&fp->pipe);
   } else {
      fp->draw = draw_create_no_llvm(&fp->pipe);
   }
   if (!fp->draw)
      goto fail;
   draw_texture_sampler(fp->draw, PIPE_SHADER_VERTEX,
                        fp_tgsi_sampler_base(fp->tgsi_sampler[PIPE_SHADER_VERTEX]));

   fp->vbuf_render = fp_create_vbuf_render(fp);
   if (!fp->vbuf_render)
      goto fail;
   fp->vbuf_stage = draw_vbuf_stage(fp->draw, fp->vbuf_render);
   if (!fp->vbuf_stage) {
      fp->vbuf_render->destroy(fp->vbuf_render);
      goto fail;
   }
   draw_set_rasterize_stage(fp->draw, fp->vbuf_stage);
   draw_set_render(fp->draw, fp->vbuf_render);

   /* Points of any size, sprites and non-smooth lines of any width reach
    * the model (rast_point, rast_line draw them by llvmpipe's rules, as
    * llvmpipe configures draw).  draw's wide-point stage would shift every
    * square by (+1/8, -1/8) px, its wide-line quads are not llvmpipe's. */
   draw_wide_point_threshold(fp->draw, 10000.0f);
   draw_wide_point_sprites(fp->draw, FALSE);
   draw_enable_point_sprites(fp->draw, FALSE);
   draw_wide_line_threshold(fp->draw, 10000.0f);
   /* GL ES (rasterizer point_tri_clip): draw passes points whatever their
    * centre, and rast_point scissors them to the viewport, as llvmpipe
    * (lp_context.c) does; a wide point by the viewport's edge keeps its
    * pixels inside instead of vanishing with its centre.  Elsewhere draw
    * clips points by their centre, as GL 2.1 says. */
   draw_set_driver_clipping(fp->draw, FALSE, FALSE, FALSE, TRUE);

   /* GL 1.x extras done by draw with a modified fragment shader, as in
    * softpipe: smooth lines and points, polygon stipple. */
   draw_install_aaline_stage(fp->draw, &fp->pipe);
   draw_install_aapoint_stage(fp->draw, &fp->pipe);
   draw_install_pstipple_stage(fp->draw, &fp->pipe);

   if (fp->print_stats)
      fp_stats_track(fp, true);
   return &fp->pipe;

fail:
   fp_destroy(&fp->pipe);
   return NULL;
}
