/*
 * Shader CSOs and constant buffers.  Vertex and geometry shaders belong to
 * draw, which runs each interpreted or compiled (fp_bind_draw_stages);
 * fragment shaders keep their TGSI for tgsi_exec plus draw's copy (which
 * draw's wide-point stage reads to find sprite-coordinate inputs).
 * Tessellation's shaders are fp_state_tess.c's.
 */
#include "util/u_memory.h"
#include "util/u_inlines.h"
#include "draw/draw_context.h"
#include "draw/draw_vs.h"
#include "tgsi/tgsi_parse.h"
#include "tgsi/tgsi_scan.h"
#include "tgsi/tgsi_exec.h"
#include "compiler/nir/nir.h"
#include "nir/nir_to_tgsi.h"
#include "util/ralloc.h"

#include "fp_context.h"
#include "fp_resource.h"
#include "fp_screen.h"

static void fp_fs_free(struct fp_fragment_shader *fs)
{
   ralloc_free(fs->nir);
   FREE((void *)fs->tokens);
   FREE(fs);
}

/* What makes the shader run once a sample (docs/msaa.md): gl_SampleID,
 * gl_SamplePosition, gl_SampleMaskIn (each invocation has its sample's
 * bit alone, which GL allows, so the model need not know a pixel's
 * coverage before shading it), `sample` inputs, gl_SampleMask. */
static void fp_fs_scan_samples(struct fp_fragment_shader *fs)
{
   const struct tgsi_shader_info *info = &fs->info;
   fs->sv_sample_id = fs->sv_sample_pos = fs->sv_sample_mask = fs->sample_mask_output = -1;
   for (unsigned i = 0; i < info->num_system_values; i++) {
      switch (info->system_value_semantic_name[i]) {
      case TGSI_SEMANTIC_SAMPLEID:   fs->sv_sample_id = (int)i; break;
      case TGSI_SEMANTIC_SAMPLEPOS:  fs->sv_sample_pos = (int)i; break;
      case TGSI_SEMANTIC_SAMPLEMASK: fs->sv_sample_mask = (int)i; break;
      default: break;
      }
   }
   for (unsigned i = 0; i < info->num_outputs; i++)
      if (info->output_semantic_name[i] == TGSI_SEMANTIC_SAMPLEMASK)
         fs->sample_mask_output = (int)i;
   fs->per_sample = fs->sv_sample_id >= 0 || fs->sv_sample_pos >= 0 || fs->sv_sample_mask >= 0 ||
                    fs->sample_mask_output >= 0;
   for (unsigned i = 0; i < info->num_inputs; i++)
      fs->per_sample |= info->input_interpolate_loc[i] == TGSI_INTERPOLATE_LOC_SAMPLE;
}

static void *fp_create_fs_state(struct pipe_context *pipe, const struct pipe_shader_state *templ)
{
   struct fp_context *fp = fp_context(pipe);
   struct fp_fragment_shader *fs;

   if (templ->type == PIPE_SHADER_IR_TGSI ? !templ->tokens
                                          : templ->type != PIPE_SHADER_IR_NIR || !templ->ir.nir)
      return NULL;
   fs = CALLOC_STRUCT(fp_fragment_shader);
   if (!fs)
      return NULL;
   if (templ->type == PIPE_SHADER_IR_NIR) {
      /* st's NIR, ours to free: the compiled path keeps a copy; the rest of
       * the driver (tgsi_exec, draw, the scans) takes the TGSI nir_to_tgsi
       * makes of it, which frees it, the tokens st makes for a driver that
       * prefers TGSI.  Their input registers are the NIR inputs'
       * driver_location, which the compiled code reads them by. */
      fs->nir = nir_shader_clone(NULL, templ->ir.nir);
      fs->tokens = nir_to_tgsi(templ->ir.nir, pipe->screen);
   } else {
      fs->tokens = tgsi_dup_tokens(templ->tokens);
   }
   if (!fs->tokens) {
      ralloc_free(fs->nir);
      FREE(fs);
      return NULL;
   }
   tgsi_scan_shader(fs->tokens, &fs->info);
   if (!fp_fbfetch_strip(fs)) {
      fp_fs_free(fs);
      return NULL;
   }
   fp_rebase_scan(fs);

   struct pipe_shader_state dstate = *templ;
   dstate.type = PIPE_SHADER_IR_TGSI;
   dstate.tokens = fs->tokens;
   fs->draw_fs = draw_create_fragment_shader(fp->draw, &dstate);
   if (!fs->draw_fs) {
      fp_fs_free(fs);
      return NULL;
   }

   const struct tgsi_shader_info *info = &fs->info;
   fs->pixel_center_integer =
      info->properties[TGSI_PROPERTY_FS_COORD_PIXEL_CENTER] == TGSI_FS_COORD_PIXEL_CENTER_INTEGER;
   fs->color0_to_all = info->properties[TGSI_PROPERTY_FS_COLOR0_WRITES_ALL_CBUFS] != 0;
   fs->may_discard = info->uses_kill;
   fs->side_effects = info->writes_memory;
   fs->early_tests = info->properties[TGSI_PROPERTY_FS_EARLY_DEPTH_STENCIL] != 0;
   fs->reads_fragcoord = info->reads_position;
   fp_fs_scan_samples(fs);
   fs->depth_output = -1;
   for (unsigned i = 0; i < RAST_MAX_CBUFS; i++)
      fs->color_output[i] = -1;
   for (unsigned i = 0; i < info->num_outputs; i++) {
      unsigned idx = info->output_semantic_index[i];
      switch (info->output_semantic_name[i]) {
      case TGSI_SEMANTIC_COLOR:
         if (idx < RAST_MAX_CBUFS) {
            fs->color_output[idx] = i;
            fs->num_color_outputs = MAX2(fs->num_color_outputs, idx + 1);
         }
         break;
      case TGSI_SEMANTIC_POSITION:
         fs->depth_output = i;
         fs->writes_depth = true;
         break;
      default:
         break;
      }
   }
   if (!fp_fbfetch_prepare(fs)) {
      draw_delete_fragment_shader(fp->draw, fs->draw_fs);
      fp_fs_free(fs);
      return NULL;
   }
   return fs;
}

static void fp_bind_fs_state(struct pipe_context *pipe, void *cso)
{
   struct fp_context *fp = fp_context(pipe);
   struct fp_fragment_shader *fs = cso;
   draw_bind_fragment_shader(fp->draw, fs ? fs->draw_fs : NULL);
   fp->fs = fs;
   fp->fs_dirty = true;
   fp->vl_valid = false;
}

static void fp_delete_fs_state(struct pipe_context *pipe, void *cso)
{
   struct fp_context *fp = fp_context(pipe);
   struct fp_fragment_shader *fs = cso;
   for (unsigned t = 0; t < fp->num_threads; t++) {
      struct tgsi_exec_machine *mach = fp->fs_thread[t].mach;
      if (mach && mach->Tokens == fs->exec_tokens)
         tgsi_exec_machine_bind_shader(mach, NULL, NULL, NULL, NULL);
   }
   if (fp->fs == fs)
      fp->fs = NULL;
   draw_delete_fragment_shader(fp->draw, fs->draw_fs);
   fp_jit_fs_destroy(fs->jit);
   fp_fbfetch_release(fs);
   fp_fs_free(fs);
}

static void *fp_create_vs_state(struct pipe_context *pipe, const struct pipe_shader_state *templ)
{
   struct fp_context *fp = fp_context(pipe);
   struct fp_vertex_shader *vs = CALLOC_STRUCT(fp_vertex_shader);
   if (!vs)
      return NULL;
   vs->state = *templ;
   if (templ->type == PIPE_SHADER_IR_TGSI && templ->tokens)
      vs->state.tokens = tgsi_dup_tokens(templ->tokens);
   /* interpreted until hot (fp_vs_count), or until tessellation needs it
    * compiled (fp_tess_validate) */
   vs->draw_vs = draw_create_vertex_shader_exec(fp->draw, &vs->state);
   if (!vs->draw_vs) {
      FREE((void *)vs->state.tokens);
      FREE(vs);
      return NULL;
   }
   return vs;
}

bool fp_vs_compile(struct fp_context *fp, struct fp_vertex_shader *vs)
{
   if (vs->draw_vs_llvm)
      return true;
   if (vs->llvm_failed || !vs->state.tokens)
      return false;
   vs->draw_vs_llvm = draw_create_vertex_shader(fp->draw, &vs->state);
   /* draw falls back on tgsi_exec itself when gallivm refuses */
   if (!vs->draw_vs_llvm || vs->draw_vs_llvm->interpreted) {
      if (vs->draw_vs_llvm)
         draw_delete_vertex_shader(fp->draw, vs->draw_vs_llvm);
      vs->draw_vs_llvm = NULL;
      vs->llvm_failed = true;   /* stays interpreted */
      fp->jit_stats.vs_failed++;
      return false;
   }
   fp->jit_stats.vs_compiled++;
   return true;
}

/* Called before each draw of `vertices` vertices: compiles the bound vertex
 * shader once it is hot (at once with FIXPIPE_DEBUG=jitall). */
void fp_vs_count(struct fp_context *fp, uint64_t vertices)
{
   struct fp_vertex_shader *vs = fp->vs;
   vs->vertices += vertices;
   if (vs->draw_vs_llvm || vs->llvm_failed || !fp->jit ||
       !vs->state.tokens)
      return;
   /* hot as a fragment shader is (fp_fs_hot): past the threshold, or past
    * the loop threshold once the process presents frames */
   const bool loop = vs->vertices >= FP_JIT_LOOP_VERTICES && fp_jit_hot_loop(fp);
   /* signed normalized vertex data: draw's compiled fetch at once, the one
    * that reads it as GL does (fp_velems.snorm) */
   const bool snorm = fp->velems && fp->velems->snorm;
   if (vs->vertices < FP_JIT_HOT_VERTICES && !loop && !snorm &&
       !(fp->opts->debug & FP_DEBUG_JITALL))
      return;
   if (fp_vs_compile(fp, vs))
      fp_bind_draw_stages(fp);
}

/* Without tessellation: the vertex shader's compiled copy once there is
 * one, unless a geometry shader follows it, which runs interpreted (draw's
 * general middle end runs both).  With it, which only draw's LLVM middle
 * end runs: both compiled, the copies fp_tess_validate makes. */
void fp_bind_draw_stages(struct fp_context *fp)
{
   struct fp_vertex_shader *vs = fp->vs;
   struct fp_geometry_shader *gs = fp->gs;
   const bool tess = fp->tes != NULL;
   draw_bind_geometry_shader(fp->draw, !gs ? NULL
                                       : tess && gs->draw_gs_llvm ? gs->draw_gs_llvm
                                                                  : gs->draw_gs);
   draw_bind_vertex_shader(fp->draw, !vs ? NULL
                                     : vs->draw_vs_llvm && (!gs || tess) ? vs->draw_vs_llvm
                                                                        : vs->draw_vs);
}

static void fp_bind_vs_state(struct pipe_context *pipe, void *cso)
{
   struct fp_context *fp = fp_context(pipe);
   fp->vs = cso;
   fp_bind_draw_stages(fp);
   fp->vl_valid = false;
}

static void *fp_create_gs_state(struct pipe_context *pipe, const struct pipe_shader_state *templ)
{
   struct fp_context *fp = fp_context(pipe);
   if (templ->type != PIPE_SHADER_IR_TGSI || !templ->tokens)
      return NULL;
   struct fp_geometry_shader *gs = CALLOC_STRUCT(fp_geometry_shader);
   if (!gs)
      return NULL;
   gs->state = *templ;
   gs->state.tokens = tgsi_dup_tokens(templ->tokens);
   gs->draw_gs = gs->state.tokens ? draw_create_geometry_shader_exec(fp->draw, &gs->state)
                                  : NULL;
   if (!gs->draw_gs) {
      FREE((void *)gs->state.tokens);
      FREE(gs);
      return NULL;
   }
   return gs;
}

static void fp_bind_gs_state(struct pipe_context *pipe, void *cso)
{
   struct fp_context *fp = fp_context(pipe);
   fp->gs = cso;
   fp_bind_draw_stages(fp);
   fp->vl_valid = false;
}

static void fp_delete_gs_state(struct pipe_context *pipe, void *cso)
{
   struct fp_context *fp = fp_context(pipe);
   struct fp_geometry_shader *gs = cso;
   draw_delete_geometry_shader(fp->draw, gs->draw_gs);
   if (gs->draw_gs_llvm)
      draw_delete_geometry_shader(fp->draw, gs->draw_gs_llvm);
   FREE((void *)gs->state.tokens);
   FREE(gs);
}

static void fp_delete_vs_state(struct pipe_context *pipe, void *cso)
{
   struct fp_context *fp = fp_context(pipe);
   struct fp_vertex_shader *vs = cso;
   draw_delete_vertex_shader(fp->draw, vs->draw_vs);
   if (vs->draw_vs_llvm)
      draw_delete_vertex_shader(fp->draw, vs->draw_vs_llvm);
   FREE((void *)vs->state.tokens);
   FREE(vs);
}

static void fp_set_constant_buffer(struct pipe_context *pipe, enum pipe_shader_type shader,
                                   uint index, bool take_ownership,
                                   const struct pipe_constant_buffer *cb)
{
   struct fp_context *fp = fp_context(pipe);
   if (shader >= PIPE_SHADER_TYPES || index >= PIPE_MAX_CONSTANT_BUFFERS)
      return;
   draw_flush(fp->draw);
   util_copy_constant_buffer(&fp->constants[shader][index], cb, take_ownership);

   const struct pipe_constant_buffer *c = &fp->constants[shader][index];
   const void *data = NULL;
   unsigned size = 0;
   if (c->user_buffer) {
      data = (const uint8_t *)c->user_buffer + c->buffer_offset;
      size = c->buffer_size;
   } else if (c->buffer) {
      data = fp_resource(c->buffer)->data + c->buffer_offset;
      size = c->buffer_size;
   }
   /* draw counts every stage's constants in one unit, its stride: a vec4,
    * the unit the TGSI of vertex and geometry shaders reads; the compiled
    * tessellation stages are NIR, whose code bounds a buffer in dwords (as
    * llvmpipe's draw, whose stride is a float): their sizes go in four times
    * over, so that draw's count is their dwords */
   if (shader == PIPE_SHADER_TESS_CTRL || shader == PIPE_SHADER_TESS_EVAL)
      size *= 4;
   if (shader != PIPE_SHADER_FRAGMENT && shader != PIPE_SHADER_COMPUTE)
      draw_set_mapped_constant_buffer(fp->draw, shader, index, data, size);
   if (shader == PIPE_SHADER_FRAGMENT)
      fp->fs_dirty = true;
}

void fp_init_shader_functions(struct fp_context *fp)
{
   struct pipe_context *p = &fp->pipe;
   p->create_fs_state = fp_create_fs_state;
   p->bind_fs_state = fp_bind_fs_state;
   p->delete_fs_state = fp_delete_fs_state;
   p->create_vs_state = fp_create_vs_state;
   p->bind_vs_state = fp_bind_vs_state;
   p->delete_vs_state = fp_delete_vs_state;
   p->create_gs_state = fp_create_gs_state;
   p->bind_gs_state = fp_bind_gs_state;
   p->delete_gs_state = fp_delete_gs_state;
   p->set_constant_buffer = fp_set_constant_buffer;
}
