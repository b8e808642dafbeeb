/*
 * Fragment shading for the model's quads: compiled code (fp_jit_fs.c) or
 * tgsi_exec.  The model interpolates; the shader only runs instructions.
 *
 * Tiered: a shader is interpreted for its first FP_JIT_HOT_QUADS quads and
 * compiled at the first draw after that (FIXPIPE_DEBUG=jitall: at its first
 * draw; nojit: never).  Conformance tests draw a few small images with each
 * of thousands of shaders, where compiling costs more than it saves; real
 * content shades the same few shaders for millions of quads.
 *
 * tgsi_exec: exec_declaration() in
 * tgsi_exec.c would re-interpolate every FS INPUT from InterpCoefs on each
 * run, so after binding, the INPUT declarations are dropped from the
 * machine and Inputs[] are filled from rast_quad.in per quad.
 */
#include <string.h>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include "util/u_memory.h"
#include "util/u_atomic.h"
#include "util/u_math.h"
#include "tgsi/tgsi_exec.h"
#include "tgsi/tgsi_parse.h"

#include "fp_context.h"
#include "fp_jit.h"
#include "fp_resource.h"
#include "fp_screen.h"

static void fp_fs_drop_input_decls(struct tgsi_exec_machine *mach)
{
   unsigned n = 0;
   for (unsigned i = 0; i < mach->NumDeclarations; i++) {
      if (mach->Declarations[i].Declaration.File == TGSI_FILE_INPUT)
         continue;
      mach->Declarations[n++] = mach->Declarations[i];
   }
   mach->NumDeclarations = n;
}

/* interpolateAt* (TGSI INTERP_*, mesa/patches/0018): the model evaluates
 * the input at the point, on the quad being shaded (rast_interp_at).
 * gl_FragCoord and the facing are not interpolants; they answer as read. */
static void fp_fs_interp_at(struct tgsi_exec_machine *mach, unsigned opcode,
                            const union tgsi_exec_channel *attrib,
                            const union tgsi_exec_channel *arg0,
                            const union tgsi_exec_channel *arg1,
                            union tgsi_exec_channel out[4])
{
   struct fp_fs_thread *th = mach->InterpAtData;
   const struct tgsi_shader_info *info = &th->fp->fs->info;
   const enum rast_interp_at_kind kind =
      opcode == TGSI_OPCODE_INTERP_OFFSET   ? RAST_INTERP_AT_OFFSET
      : opcode == TGSI_OPCODE_INTERP_SAMPLE ? RAST_INTERP_AT_SAMPLE
                                            : RAST_INTERP_AT_CENTROID;
   float v[4][RAST_QUAD_SIZE];
   unsigned done = ~0u;
   for (unsigned p = 0; p < RAST_QUAD_SIZE; p++) {
      const unsigned var = attrib->u[p];
      if (var != done) {        /* an input array's lanes may read different ones */
         const unsigned sem =
            var < info->num_inputs ? info->input_semantic_name[var] : TGSI_SEMANTIC_COUNT;
         if (sem == TGSI_SEMANTIC_POSITION || sem == TGSI_SEMANTIC_FACE ||
             var >= RAST_MAX_VARYINGS) {
            for (unsigned c = 0; c < 4; c++)
               memcpy(v[c], mach->Inputs[var < TGSI_EXEC_MAX_INPUT_ATTRIBS ? var : 0].xyzw[c].f,
                      sizeof(v[c]));
         } else {
            rast_interp_at(th->rast, th->quad, var, kind, arg0->f, arg1->f, v);
         }
         done = var;
      }
      for (unsigned c = 0; c < 4; c++)
         out[c].f[p] = v[c][p];
   }
}

static unsigned fp_fs_shade(void *ctx, const struct rast_quad *q, struct rast_shaded_quad *out)
{
   struct fp_fs_thread *th = ctx;
   struct fp_fragment_shader *fs = th->fp->fs;
   struct tgsi_exec_machine *mach = th->mach;

   th->quads_interp++;   /* counted to the shader after the batch: fp_fs_batch_done */
   fp_tgsi_sampler_begin(th->sampler);
   const struct tgsi_shader_info *info = &fs->info;
   const float c = fs->pixel_center_integer ? 0.0f : 0.5f;

   for (unsigned p = 0; p < RAST_QUAD_SIZE; p++) {
      mach->QuadPos.xyzw[0].f[p] = (float)(q->x + (p & 1)) + c;
      mach->QuadPos.xyzw[1].f[p] = (float)(q->y + (p >> 1)) + c;
      mach->QuadPos.xyzw[2].f[p] = q->frag_z[p];
      mach->QuadPos.xyzw[3].f[p] = q->frag_w[p];
   }
   mach->Face = q->front_facing ? 1.0f : -1.0f;

   for (unsigned i = 0; i < info->num_inputs && i < RAST_MAX_VARYINGS; i++) {
      struct tgsi_exec_vector *in = &mach->Inputs[i];
      switch (info->input_semantic_name[i]) {
      case TGSI_SEMANTIC_POSITION:
         *in = mach->QuadPos;
         break;
      case TGSI_SEMANTIC_FACE:
         for (unsigned p = 0; p < RAST_QUAD_SIZE; p++) {
            in->xyzw[0].f[p] = mach->Face;
            in->xyzw[1].f[p] = 0.0f;
            in->xyzw[2].f[p] = 0.0f;
            in->xyzw[3].f[p] = 1.0f;
         }
         break;
      default:
         memcpy(in, q->in[i], sizeof(*in));
         break;
      }
   }
   for (unsigned cb = 0; cb < fs->num_color_outputs; cb++)
      if (fs->fetch_mask >> cb & 1u)
         memcpy(&mach->Inputs[fs->fetch_first + (unsigned)fs->color_output[cb]], q->last[cb],
                sizeof(q->last[cb]));

   mach->NonHelperMask = q->mask;
   th->quad = q;
   unsigned mask = q->mask & tgsi_exec_machine_run(mach, 0) & 0xf;
   if (!mask)
      return 0;

   for (unsigned i = 0; i < fs->num_color_outputs; i++) {
      if (fs->color_output[i] >= 0)
         memcpy(out->color[i], &mach->Outputs[fs->color_output[i]], sizeof(out->color[i]));
      else
         memset(out->color[i], 0, sizeof(out->color[i]));
   }
   if (fs->num_color_outputs == 0)
      memset(out->color[0], 0, sizeof(out->color[0]));
   if (fs->depth_output >= 0) {
      for (unsigned p = 0; p < RAST_QUAD_SIZE; p++)
         out->depth[p] = mach->Outputs[fs->depth_output].xyzw[2].f[p];
   }
   return mask;
}

/* A system value the same on a quad's four pixels: channel c is v[c]
 * (bit patterns: integers go through uif). */
static void fp_fs_splat(struct tgsi_exec_vector *sv, const float v[4])
{
   for (unsigned c = 0; c < 4; c++)
      for (unsigned p = 0; p < RAST_QUAD_SIZE; p++)
         sv->xyzw[c].f[p] = v[c];
}

/* A shader shaded once a sample (docs/msaa.md): its sample's system values
 * from the thread's tables (fp_fs_sample_tables) before it runs, its
 * gl_SampleMask into the model's output after.  The quad's lanes share the
 * sample: one walk of the model made them. */
static unsigned fp_fs_shade_sample(void *ctx, const struct rast_quad *q,
                                   struct rast_shaded_quad *out)
{
   struct fp_fs_thread *th = ctx;
   const struct fp_fragment_shader *fs = th->fp->fs;
   struct tgsi_exec_machine *mach = th->mach;
   const unsigned k = q->sample;
   if (fs->sv_sample_id >= 0)
      fp_fs_splat(&mach->SystemValue[fs->sv_sample_id], (float[4]){ uif(k), 0, 0, 0 });
   if (fs->sv_sample_pos >= 0)
      fp_fs_splat(&mach->SystemValue[fs->sv_sample_pos],
                  (float[4]){ th->jit_ctx.sample_pos[k][0], th->jit_ctx.sample_pos[k][1], 0, 0 });
   if (fs->sv_sample_mask >= 0)
      fp_fs_splat(&mach->SystemValue[fs->sv_sample_mask],
                  (float[4]){ uif(th->jit_ctx.sample_mask_in[k]), 0, 0, 0 });
   const unsigned kept = fp_fs_shade(ctx, q, out);
   if (fs->sample_mask_output >= 0)
      for (unsigned p = 0; p < RAST_QUAD_SIZE; p++)
         out->sample_mask[p] = mach->Outputs[fs->sample_mask_output].xyzw[0].u[p];
   return kept;
}

/* The values fp_fs_shade_sample and the compiled code give a shader for
 * the sample a quad is shaded for, by the framebuffer's samples and
 * GL_MULTISAMPLE (off: the model shades at the centre as sample 0). */
static void fp_fs_sample_tables(struct fp_context *fp)
{
   const bool ms = fp->fb_samples > 1 && fp->rasterizer && fp->rasterizer->base.multisample;
   for (unsigned t = 0; t < fp->num_threads; t++) {
      struct fp_jit_context *jc = &fp->fs_thread[t].jit_ctx;
      for (unsigned k = 0; k < RAST_MSAA_SAMPLES; k++) {
         jc->sample_pos[k][0] = ms ? rast_sample_pos_4x[k][0] : 0.5f;
         jc->sample_pos[k][1] = ms ? rast_sample_pos_4x[k][1] : 0.5f;
         jc->sample_mask_in[k] = ms ? 1u << k : 1u;
      }
   }
}

/* A quad's four lanes from its mask (lane = ~0 where the pixel is live). */
#define FP_LANES(m) { -((m) & 1), -((m) >> 1 & 1), -((m) >> 2 & 1), -((m) >> 3 & 1) }
static const int32_t fp_quad_lanes[16][RAST_QUAD_SIZE] = {
   FP_LANES(0),  FP_LANES(1),  FP_LANES(2),  FP_LANES(3),  FP_LANES(4),  FP_LANES(5),
   FP_LANES(6),  FP_LANES(7),  FP_LANES(8),  FP_LANES(9),  FP_LANES(10), FP_LANES(11),
   FP_LANES(12), FP_LANES(13), FP_LANES(14), FP_LANES(15),
};
#undef FP_LANES

/* The pixels a quad's lanes keep (a lane is nonzero where kept): one
 * vector compare, where per-lane loads would each wait for the compiled
 * code's vector store of the lanes to be forwarded. */
static inline unsigned fp_lanes_mask(const int32_t lanes[RAST_QUAD_SIZE])
{
#ifdef __SSE2__
   const __m128i v = _mm_loadu_si128((const __m128i *)lanes);
   return ~(unsigned)_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(v, _mm_setzero_si128()))) &
          15u;
#else
   unsigned m = 0;
   for (unsigned p = 0; p < RAST_QUAD_SIZE; p++)
      m |= (unsigned)(lanes[p] != 0) << p;
   return m;
#endif
}

/* The compiled function on the n quads q[i] of a primitive, their outputs
 * to out[i] (n up to the variant's quads a call: one call of the eight- or
 * sixteen-lane code).  The code's other quads are q[0] again with every
 * lane off, their outputs to `spare`, and not sampled
 * (fp_jit_context.quads).  Returns the pixels kept, quad i's in bits 4i
 * to 4i + 3. */
static unsigned fp_fs_shade_n_jit(void *ctx, const struct rast_quad *const q[],
                                  struct rast_shaded_quad *const out[], unsigned n)
{
   struct fp_fs_thread *th = ctx;
   const struct fp_jit_variant *v = th->fp->fs->jit;
   const struct rast_quad *qs[FP_JIT_MAX_QUADS];
   struct rast_shaded_quad *outs[FP_JIT_MAX_QUADS];
   int32_t lanes[FP_JIT_MAX_QUADS][RAST_QUAD_SIZE];
   /* all of them: the code reads its quads a call, at most these */
   for (unsigned k = 0; k < FP_JIT_MAX_QUADS; k++) {
      qs[k] = k < n ? q[k] : q[0];
      outs[k] = k < n ? out[k] : &th->spare;
      memcpy(lanes[k], fp_quad_lanes[k < n ? q[k]->mask & 15 : 0], sizeof(lanes[k]));
   }
   th->jit_ctx.quads = n;
   fp_tgsi_sampler_begin(th->sampler);
   if (v->num_gather_units)
      fp_tgsi_sampler_jit_prepare(th->sampler, v->gather_units, v->num_gather_units);
   v->func(&th->jit_ctx, qs, outs, &lanes[0][0]);
   th->quads_jit += n;
   unsigned kept = 0;
   for (unsigned k = 0; k < n; k++)
      kept |= (fp_lanes_mask(lanes[k]) & q[k]->mask) << 4 * k;
   return kept;
}

static unsigned fp_fs_shade_jit(void *ctx, const struct rast_quad *q, struct rast_shaded_quad *out)
{
   return fp_fs_shade_n_jit(ctx, &q, &out, 1);
}

/* Whether the process has presented a frame.  A program that presents is
 * a real-time one (a game, a benchmark, a demo, a replay): it draws its
 * shaders frame after frame, so a shader it has drawn a little is likely
 * to be drawn for long, and each frame it stays interpreted costs more
 * than compiling it (a fraction of a millisecond from the disk cache, a
 * few without).  A conformance test, which presents its one image at the
 * end if at all, and a program that presents nothing (surfaceless, an
 * FBO) keep the threshold's tiering.  Frames are presented between
 * batches, so the decision is the same on every thread count. */
bool fp_jit_hot_loop(const struct fp_context *fp)
{
   return p_atomic_read(&fp_screen(fp->pipe.screen)->frames_presented) > 0;
}

/* Hot with `more` quads interpreted besides: past the threshold, or past
 * the loop threshold once the process presents frames. */
enum fp_fs_heat { FP_FS_COLD, FP_FS_HOT, FP_FS_HOT_LOOP };
static enum fp_fs_heat fp_fs_hot(const struct fp_context *fp,
                                 const struct fp_fragment_shader *fs, double more)
{
   const double quads = (double)fs->quads_interpreted + more;
   if (quads >= FP_JIT_HOT_QUADS)
      return FP_FS_HOT;
   if (quads >= FP_JIT_LOOP_QUADS && fp_jit_hot_loop(fp))
      return FP_FS_HOT_LOOP;
   return FP_FS_COLD;
}

/* Compiles the bound shader when it is due; false leaves it interpreted. */
static bool fp_fs_compiled(struct fp_context *fp)
{
   struct fp_fragment_shader *fs = fp->fs;
   if (fs->jit)
      return true;
   if (!fp->jit || fs->jit_failed)
      return false;
   if (fp_fs_hot(fp, fs, 0) == FP_FS_COLD && !fs->hot_ahead &&
       !(fp->opts->debug & FP_DEBUG_JITALL))
      return false;
   fs->jit = fp_jit_fs_compile(fp, fs->tokens, fs->nir, &fs->info, fs->depth_output, fs->color_output,
                               fs->num_color_outputs);
   if (!fs->jit) {
      fs->jit_failed = true;
      fp->jit_stats.failed++;
      return false;
   }
   fp->jit_stats.compiled++;
   fp->jit_stats.hot_loop += fs->hot_loop && !(fp->opts->debug & FP_DEBUG_JITALL);
   fp->jit_stats.cache_hits += fs->jit->cache_hit;
   fp->jit_stats.compile_ms += fs->jit->compile_ms;
   return true;
}

/* A GL program never draws without a fragment shader, but the driver must
 * not crash if asked to: colour 0, nothing discarded. */
static unsigned fp_fs_shade_none(void *ctx, const struct rast_quad *q,
                                 struct rast_shaded_quad *out)
{
   (void)ctx;
   memset(out->color[0], 0, sizeof(out->color[0]));
   return q->mask;
}

bool fp_fs_batch_may_compile(const struct fp_context *fp)
{
   const struct fp_fragment_shader *fs = fp->fs;
   return fs && !fs->jit && !fs->hot_ahead && fp->jit && !fs->jit_failed;
}

/* A batch that alone takes the shader past FP_JIT_HOT_QUADS would cost more
 * interpreted than compiling it costs (the threshold's rent-or-buy
 * argument, docs/jit.md), so the shader is hot before it: a full-screen
 * pass, one batch of two triangles, is otherwise interpreted whole.  The
 * estimate is the triangles' area, from the batch's own vertices, so the
 * decision depends on the program alone, never on the threads. */
void fp_fs_batch_ahead(struct fp_context *fp, double quads)
{
   struct fp_fragment_shader *fs = fp->fs;
   const enum fp_fs_heat heat = fp_fs_hot(fp, fs, quads);
   if (heat != FP_FS_COLD) {
      fs->hot_ahead = true;
      fs->hot_loop = heat == FP_FS_HOT_LOOP;
      fp->fs_dirty = true;
      fp->jit_stats.hot_ahead += heat == FP_FS_HOT;
   }
}

/* Hot: compiled at the next validation (the next draw, or the next batch of
 * primitives of this one). */
void fp_fs_batch_done(struct fp_context *fp)
{
   struct fp_fragment_shader *fs = fp->fs;
   uint64_t n = 0;
   for (unsigned t = 0; t < fp->num_threads; t++) {
      struct fp_fs_thread *th = &fp->fs_thread[t];
      n += th->quads_interp - th->quads_interp_seen;
      th->quads_interp_seen = th->quads_interp;
   }
   if (!fs || !n)
      return;
   fs->quads_interpreted += n;
   const enum fp_fs_heat heat = fp_fs_hot(fp, fs, 0);
   if (heat != FP_FS_COLD && !fs->jit && fp->jit && !fs->jit_failed) {
      fs->hot_loop = heat == FP_FS_HOT_LOOP;
      fp->fs_dirty = true;
   }
}

void fp_fs_validate(struct fp_context *fp)
{
   struct rast_shader rs;
   memset(&rs, 0, sizeof(rs));
   rs.ctx = &fp->fs_thread[0];
   for (unsigned t = 1; t < fp->num_threads; t++)
      rs.thread_ctx[t] = &fp->fs_thread[t];

   if (!fp->fs) {
      rs.shade = fp_fs_shade_none;
      rs.num_outputs = 1;
      rast_set_shader(fp->rast, &rs);
      fp->fs_dirty = false;
      return;
   }

   const void *bufs[PIPE_MAX_CONSTANT_BUFFERS];
   unsigned sizes[PIPE_MAX_CONSTANT_BUFFERS];
   for (unsigned i = 0; i < PIPE_MAX_CONSTANT_BUFFERS; i++) {
      const struct pipe_constant_buffer *c = &fp->constants[PIPE_SHADER_FRAGMENT][i];
      bufs[i] = NULL;
      sizes[i] = 0;
      if (c->user_buffer)
         bufs[i] = (const uint8_t *)c->user_buffer + c->buffer_offset;
      else if (c->buffer)
         bufs[i] = fp_resource(c->buffer)->data + c->buffer_offset;
      if (bufs[i])
         sizes[i] = c->buffer_size;
   }
   rs.num_outputs = fp->fs->num_color_outputs;
   rs.writes_depth = fp->fs->writes_depth;
   rs.color0_to_all = fp->fs->color0_to_all;
   rs.may_discard = fp->fs->may_discard;
   rs.side_effects = fp->fs->side_effects;
   rs.early_tests = fp->fs->early_tests;
   rs.reads_fragcoord = fp->fs->reads_fragcoord;
   rs.fetch_mask = fp->fs->fetch_mask;
   rs.per_sample = fp->fs->per_sample || fp->min_samples > 1;
   rs.writes_sample_mask = fp->fs->sample_mask_output >= 0;
   fp_fs_sample_tables(fp);

   if (fp_fs_compiled(fp)) {
      for (unsigned t = 0; t < fp->num_threads; t++) {
         struct fp_fs_thread *th = &fp->fs_thread[t];
         for (unsigned i = 0; i < PIPE_MAX_CONSTANT_BUFFERS && i < LP_MAX_TGSI_CONST_BUFFERS; i++) {
            th->jit_ctx.constants[i].f = bufs[i];
            th->jit_ctx.constants[i].num_elements = sizes[i] / 4;
         }
         fp_jit_context_init_sampler(&th->jit_ctx, fp_tgsi_sampler_base(th->sampler));
      }
      rs.shade = fp_fs_shade_jit;
      if (fp->fs->jit->quads >= 2) {
         rs.shade_n = fp_fs_shade_n_jit;
         rs.group = fp->fs->jit->quads;
      }
      rast_set_shader(fp->rast, &rs);
      fp->fs_dirty = false;
      return;
   }

   for (unsigned t = 0; t < fp->num_threads; t++) {
      struct fp_fs_thread *th = &fp->fs_thread[t];
      tgsi_exec_set_constant_buffers(th->mach, PIPE_MAX_CONSTANT_BUFFERS, bufs, sizes);
      tgsi_exec_machine_bind_shader(th->mach, fp->fs->exec_tokens,
                                    fp_tgsi_sampler_base(th->sampler),
                                    fp->tgsi_image[FP_MEM_FRAGMENT],
                                    fp->tgsi_buffer[FP_MEM_FRAGMENT]);
      fp_fs_drop_input_decls(th->mach);
      th->mach->InterpAt = fp_fs_interp_at;
      th->mach->InterpAtData = th;
   }

   rs.shade = fp->fs->per_sample ? fp_fs_shade_sample : fp_fs_shade;
   rast_set_shader(fp->rast, &rs);
   fp->fs_dirty = false;
}
