/*
 * Framebuffer fetch (EXT_shader_framebuffer_fetch): the fragment shader
 * reads the colour its target holds at the pixel.  Tile-based mobile GPUs
 * read it from the tile buffer; the model's back end reads it from the
 * target before shading the quad (rast_shader.fetch_mask, rast_quad.last).
 *
 * TGSI says it as `FBFETCH dst, OUT[k]`.  The compiled path gets it from
 * tgsi_to_nir and gallivm's fb_fetch hook (fp_jit_fs.c); tgsi_exec has no
 * FBFETCH, so the interpreter runs a copy of the tokens in which it is
 * `MOV dst, IN[fetch_first + k]`, those inputs filled from the quad's
 * `last` like any other (fp_fs.c).
 *
 * KHR_blend_equation_advanced comes the same way: Mesa writes the blend
 * into the shader with an FBFETCH, and marks the shader with the property
 * FS_BLEND_EQUATION_ADVANCED, which is for hardware that blends so itself.
 * tgsi_to_nir does not know the property (an unreachable() there), and
 * nothing in fixpipe reads it, so it is dropped from the shader's tokens.
 */
#include "util/u_memory.h"
#include "tgsi/tgsi_parse.h"
#include "tgsi/tgsi_scan.h"
#include "tgsi/tgsi_transform.h"

#include "fp_context.h"

struct fbfetch_rewrite {
   struct tgsi_transform_context base;
   const struct fp_fragment_shader *fs;
   unsigned fetch_mask;
};

/* The colour buffer output register `o` is written to, or -1. */
static int output_cbuf(const struct fp_fragment_shader *fs, unsigned o)
{
   for (unsigned cb = 0; cb < fs->num_color_outputs; cb++)
      if (fs->color_output[cb] == (int)o)
         return (int)cb;
   return -1;
}

static void fbfetch_instruction(struct tgsi_transform_context *tctx,
                                struct tgsi_full_instruction *inst)
{
   struct fbfetch_rewrite *rw = (struct fbfetch_rewrite *)tctx;
   if (inst->Instruction.Opcode == TGSI_OPCODE_FBFETCH &&
       inst->Src[0].Register.File == TGSI_FILE_OUTPUT) {
      const unsigned o = (unsigned)inst->Src[0].Register.Index;
      if (inst->Src[0].Register.Indirect) {
         for (unsigned cb = 0; cb < rw->fs->num_color_outputs; cb++)
            rw->fetch_mask |= 1u << cb;
      } else {
         const int cb = output_cbuf(rw->fs, o);
         if (cb >= 0)
            rw->fetch_mask |= 1u << cb;
      }
      inst->Instruction.Opcode = TGSI_OPCODE_MOV;
      inst->Src[0].Register.File = TGSI_FILE_INPUT;
      inst->Src[0].Register.Index = (int)(rw->fs->fetch_first + o);
   }
   tctx->emit_instruction(tctx, inst);
}

static void drop_advanced_property(struct tgsi_transform_context *tctx,
                                   struct tgsi_full_property *prop)
{
   if (prop->Property.PropertyName != TGSI_PROPERTY_FS_BLEND_EQUATION_ADVANCED)
      tctx->emit_property(tctx, prop);
}

bool fp_fbfetch_strip(struct fp_fragment_shader *fs)
{
   if (!fs->info.properties[TGSI_PROPERTY_FS_BLEND_EQUATION_ADVANCED])
      return true;
   struct tgsi_transform_context tc;
   memset(&tc, 0, sizeof(tc));
   tc.transform_property = drop_advanced_property;
   struct tgsi_token *t = tgsi_transform_shader(fs->tokens, tgsi_num_tokens(fs->tokens), &tc);
   if (!t)
      return false;
   FREE((void *)fs->tokens);
   fs->tokens = t;
   tgsi_scan_shader(fs->tokens, &fs->info);
   return true;
}

bool fp_fbfetch_prepare(struct fp_fragment_shader *fs)
{
   fs->exec_tokens = fs->tokens;
   fs->fetch_mask = 0;
   if (!fs->info.uses_fbfetch)
      return true;
   /* the fetched outputs follow the shader's own inputs */
   fs->fetch_first = fs->info.num_inputs;
   if (fs->fetch_first + fs->info.num_outputs > PIPE_MAX_SHADER_INPUTS)
      return false;

   struct fbfetch_rewrite rw;
   memset(&rw, 0, sizeof(rw));
   rw.base.transform_instruction = fbfetch_instruction;
   rw.fs = fs;
   const struct tgsi_token *t =
      tgsi_transform_shader(fs->tokens, tgsi_num_tokens(fs->tokens) + 16, &rw.base);
   if (!t)
      return false;
   fs->exec_tokens = t;
   fs->fetch_mask = rw.fetch_mask;
   return true;
}

void fp_fbfetch_release(struct fp_fragment_shader *fs)
{
   if (fs->exec_tokens && fs->exec_tokens != fs->tokens)
      FREE((void *)fs->exec_tokens);
   fs->exec_tokens = NULL;
}
