/*
 * Texture instructions of the shaders draw compiles (vertex, geometry,
 * tessellation control and evaluation) reach the modeled texture unit.
 * draw builds each such shader with the lp_build_sampler_soa the driver's
 * factory makes (mesa/patches/0016): fixpipe's (fp_jit_sample.c), calling
 * the stage's tgsi_sampler, the glue tgsi_exec calls for that stage
 * (fp_sampler.c).  Its pointer is a constant in the code: draw's jit
 * contexts have no slot for it, and draw's shaders belong to one context
 * (PIPE_CAP_SHAREABLE_SHADERS is 0) and are never cached on disk.
 */
#include "draw/draw_context.h"
#include "pipe/p_state.h"
#include "util/u_memory.h"

#include "fp_context.h"
#include "fp_jit.h"

static struct lp_build_sampler_soa *fp_jit_draw_sampler_create(void *data,
                                                              enum pipe_shader_type stage,
                                                              const struct pipe_shader_state *state,
                                                              const struct tgsi_shader_info *info)
{
   struct fp_context *fp = data;
   if (stage >= PIPE_SHADER_TYPES || stage == PIPE_SHADER_FRAGMENT || !fp->tgsi_sampler[stage])
      return NULL;
   return fp_jit_sampler_create_stage(info,
                                      state->type == PIPE_SHADER_IR_NIR ? state->ir.nir : NULL,
                                      fp_tgsi_sampler_base(fp->tgsi_sampler[stage]));
}

static void fp_jit_draw_sampler_destroy(void *data, struct lp_build_sampler_soa *sampler)
{
   (void)data;
   FREE(sampler);
}

void fp_jit_draw_samplers(struct draw_context *draw, struct fp_context *fp)
{
   const struct draw_llvm_sampler_factory factory = {
      .create = fp_jit_draw_sampler_create,
      .destroy = fp_jit_draw_sampler_destroy,
      .data = fp,
   };
   draw_set_llvm_sampler_factory(draw, &factory);
}
