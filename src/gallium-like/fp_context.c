/*
 * The fixpipe context: owns the model (rast_context), Mesa's draw module
 * (vertex shading, clipping, divide, viewport, smooth points and lines) and
 * the tgsi_exec machine that runs fragment shaders for the model's quads.
 * What it prints of them (FIXPIPE_STATS) is fp_instruments.c's.
 */
#include <stdio.h>
#include <string.h>

#include "util/u_memory.h"
#include "util/u_inlines.h"
#include "util/u_upload_mgr.h"
#include "util/u_framebuffer.h"
#include "draw/draw_context.h"
#include "draw/draw_vbuf.h"
#include "tgsi/tgsi_exec.h"
#include "gallivm/lp_bld_init.h"
#include <llvm-c/Core.h>

#include "fp_context.h"
#include "fp_resource.h"
#include "fp_screen.h"
#include "util/disk_cache.h"

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
   if (fp->rast) {
      fp_events_stop(fp);              /* its state is on every thread's context */
      rast_set_threads(fp->rast, 1);   /* the workers stop before what they shade with goes */
   }

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

/* A draw's fragments (their colours, and their stores to storage buffers
 * and images) are complete when draw_vbo returns: it flushes draw, whose
 * back end ends the batch with rast_flush, which returns once every model
 * thread has drawn its share (docs/threads.md).  The barriers flush all
 * the same, so that nothing draw might hold stays unseen by what follows
 * (a later draw, a map, a dispatch). */
static void fp_texture_barrier(struct pipe_context *pipe, unsigned flags)
{
   (void)flags;
   draw_flush(fp_context(pipe)->draw);
}

static void fp_memory_barrier(struct pipe_context *pipe, unsigned flags)
{
   (void)flags;
   draw_flush(fp_context(pipe)->draw);
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

/* GL_KHR_robustness: the model runs in the process; nothing resets it
 * but the process ending, so no reset is ever seen. */
static enum pipe_reset_status fp_get_device_reset_status(struct pipe_context *pipe)
{
   (void)pipe;
   return PIPE_NO_RESET;
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
   fp->pipe.get_device_reset_status = fp_get_device_reset_status;
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
   fp_init_tess_functions(fp);
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
   rast_set_texfmt(fp->rast, fp->opts->perspfmt);
   rast_set_options(fp->rast, fp_options_rast(fp->opts));
   rast_set_interp(fp->rast, fp->opts->interp);
   /* GL's default depth range, [0, 1], which the model starts with */
   for (unsigned i = 0; i < PIPE_MAX_VIEWPORTS; i++) {
      fp->viewports[i].scale[2] = fp->viewports[i].translate[2] = 0.5f;
      fp->depth_ranges[i] = (struct rast_depth_range){ 0.0f, 1.0f };
   }
   fp->vectors_pending = fp->opts->vectors.dir[0] != '\0';
   fp->events_pending = fp->opts->events.dir[0] != '\0';

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

   /* Compiled shaders: draw's LLVM path and fixpipe's fragment shaders.
    * Each makes its LLVM context with its first compiled shader (draw's own,
    * fp_llvm_context), so a process that never compiles one, as most of a
    * conformance run's do not, never initializes LLVM.  draw has its LLVM
    * path under FIXPIPE_DEBUG=nojit too, for tessellation, which has no
    * other (fp_state_tess.c); the vertex and geometry shaders draw creates
    * interpreted stay so there. */
   fp->jit = !(fp->opts->debug & FP_DEBUG_NOJIT);
   fp->draw = draw_create(&fp->pipe);
   if (!fp->draw)
      goto fail;
   /* the texture instructions of draw's compiled shaders call the same
    * per-stage glue as its interpreted ones (fp_jit_draw.c) */
   fp_jit_draw_samplers(fp->draw, fp);
   draw_texture_sampler(fp->draw, PIPE_SHADER_VERTEX,
                        fp_tgsi_sampler_base(fp->tgsi_sampler[PIPE_SHADER_VERTEX]));
   draw_texture_sampler(fp->draw, PIPE_SHADER_GEOMETRY,
                        fp_tgsi_sampler_base(fp->tgsi_sampler[PIPE_SHADER_GEOMETRY]));

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
