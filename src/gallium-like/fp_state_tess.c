/*
 * Tessellation: control and evaluation shaders, their default levels and
 * the vertices of a patch, all draw's.  draw runs tessellation in its LLVM
 * middle end alone, the shaders compiled from st's NIR (draw_tess.c), so a
 * draw with an evaluation shader bound runs the vertex shader, and the
 * geometry shader if any, compiled too, whether hot or not, under
 * FIXPIPE_DEBUG=nojit as well: their interpreted copies run in draw's
 * general middle end, which has no tessellation.  Every texture
 * instruction of these compiled stages reaches the modeled unit through
 * the stage's glue (fp_jit_draw.c); the primitives tessellation makes reach
 * the model as any other draw's.
 */
#include <stdio.h>

#include "compiler/nir/nir.h"
#include "draw/draw_context.h"
#include "util/ralloc.h"

#include "fp_context.h"
#include "fp_jit.h"

/* st's NIR, ours (a driver that takes NIR owns it): made ready for gallivm
 * as a compiled fragment shader's is, then draw's, which frees it with the
 * shader. */
static void *fp_create_tess_state(struct fp_context *fp, const struct pipe_shader_state *templ,
                                  bool control)
{
   if (templ->type != PIPE_SHADER_IR_NIR || !templ->ir.nir)
      return NULL;
   struct pipe_shader_state state = *templ;
   fp_jit_prepare_nir(state.ir.nir);
   void *shader = control ? (void *)draw_create_tess_ctrl_shader(fp->draw, &state)
                          : (void *)draw_create_tess_eval_shader(fp->draw, &state);
   if (!shader)
      ralloc_free(state.ir.nir);
   return shader;
}

static void *fp_create_tcs_state(struct pipe_context *pipe, const struct pipe_shader_state *templ)
{
   return fp_create_tess_state(fp_context(pipe), templ, true);
}

static void fp_bind_tcs_state(struct pipe_context *pipe, void *cso)
{
   struct fp_context *fp = fp_context(pipe);
   fp->tcs = cso;
   draw_bind_tess_ctrl_shader(fp->draw, fp->tcs);
}

static void fp_delete_tcs_state(struct pipe_context *pipe, void *cso)
{
   struct fp_context *fp = fp_context(pipe);
   if (fp->tcs == cso)
      fp_bind_tcs_state(pipe, NULL);
   draw_delete_tess_ctrl_shader(fp->draw, cso);
}

static void *fp_create_tes_state(struct pipe_context *pipe, const struct pipe_shader_state *templ)
{
   return fp_create_tess_state(fp_context(pipe), templ, false);
}

/* The evaluation shader decides whether draw tessellates: the stages before
 * it are bound again, compiled or interpreted, and the vertex layout follows
 * the last stage. */
static void fp_bind_tes_state(struct pipe_context *pipe, void *cso)
{
   struct fp_context *fp = fp_context(pipe);
   fp->tes = cso;
   draw_bind_tess_eval_shader(fp->draw, fp->tes);
   fp_bind_draw_stages(fp);
   fp->vl_valid = false;
}

static void fp_delete_tes_state(struct pipe_context *pipe, void *cso)
{
   struct fp_context *fp = fp_context(pipe);
   if (fp->tes == cso)
      fp_bind_tes_state(pipe, NULL);
   draw_delete_tess_eval_shader(fp->draw, cso);
}

/* The levels of a draw without a control shader (desktop GL). */
static void fp_set_tess_state(struct pipe_context *pipe, const float default_outer_level[4],
                              const float default_inner_level[2])
{
   draw_set_tess_state(fp_context(pipe)->draw, default_outer_level, default_inner_level);
}

static void fp_set_patch_vertices(struct pipe_context *pipe, uint8_t patch_vertices)
{
   fp_context(pipe)->patch_vertices = patch_vertices;
}

bool fp_tess_validate(struct fp_context *fp)
{
   if (!fp->tes)
      return true;
   struct fp_vertex_shader *vs = fp->vs;
   struct fp_geometry_shader *gs = fp->gs;
   const bool bind = !vs->draw_vs_llvm || (gs && !gs->draw_gs_llvm);
   if (!fp_vs_compile(fp, vs)) {
      static bool reported;
      if (!reported)
         fprintf(stderr, "fixpipe: a vertex shader gallivm cannot compile: draws with "
                 "tessellation skipped\n");
      reported = true;
      return false;
   }
   if (gs && !gs->draw_gs_llvm) {
      gs->draw_gs_llvm = draw_create_geometry_shader(fp->draw, &gs->state);
      if (!gs->draw_gs_llvm)
         return false;
   }
   if (bind)
      fp_bind_draw_stages(fp);
   return true;
}

void fp_init_tess_functions(struct fp_context *fp)
{
   struct pipe_context *p = &fp->pipe;
   p->create_tcs_state = fp_create_tcs_state;
   p->bind_tcs_state = fp_bind_tcs_state;
   p->delete_tcs_state = fp_delete_tcs_state;
   p->create_tes_state = fp_create_tes_state;
   p->bind_tes_state = fp_bind_tes_state;
   p->delete_tes_state = fp_delete_tes_state;
   p->set_tess_state = fp_set_tess_state;
   p->set_patch_vertices = fp_set_patch_vertices;
}
