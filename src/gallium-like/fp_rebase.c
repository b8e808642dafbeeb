/*
 * Which fragment-shader inputs the model may rebase (rast_varying's
 * rebase_mask, docs/texture-unit.md "Coordinate rebase").  Subtracting an
 * integer from a texture coordinate changes nothing under REPEAT, nor an
 * even one under MIRRORED_REPEAT, but only if the coordinate reaches the
 * sampler as it is: so an input component qualifies when every read of it
 * is a coordinate of a TEX, TXB, TXL or TXD on a 1D, 2D, 3D or array
 * target (not the layer), straight from the input register (no modifier,
 * no indirection), and every sampler it reaches wraps that axis with one of
 * the two modes.  The first half is the shader's (scanned once, here); the
 * second is the bound samplers' (at each vertex layout, fp_vbuf.c).
 */
#include <string.h>
#include "tgsi/tgsi_parse.h"
#include "tgsi/tgsi_util.h"
#include "util/u_math.h"

#include "fp_context.h"

/* The coordinate axes a target wraps (the layer of an array is not one). */
static unsigned wrapped_axes(enum tgsi_texture_type target)
{
   switch (target) {
   case TGSI_TEXTURE_1D:
   case TGSI_TEXTURE_1D_ARRAY:
      return 1;
   case TGSI_TEXTURE_2D:
   case TGSI_TEXTURE_2D_ARRAY:
      return 2;
   case TGSI_TEXTURE_3D:
      return 3;
   default:
      return 0;            /* RECT (unnormalised), cube, shadow, buffers, MSAA */
   }
}

static bool is_coord_sampling(enum tgsi_opcode op)
{
   return op == TGSI_OPCODE_TEX || op == TGSI_OPCODE_TXB || op == TGSI_OPCODE_TXL ||
          op == TGSI_OPCODE_TXD;
}

static void scan_instruction(struct fp_fragment_shader *fs, const struct tgsi_full_instruction *in)
{
   const enum tgsi_opcode op = in->Instruction.Opcode;
   int sampler = -1;
   for (unsigned s = 0; s < in->Instruction.NumSrcRegs; s++)
      if (in->Src[s].Register.File == TGSI_FILE_SAMPLER && !in->Src[s].Register.Indirect)
         sampler = in->Src[s].Register.Index;

   for (unsigned s = 0; s < in->Instruction.NumSrcRegs; s++) {
      const struct tgsi_full_src_register *src = &in->Src[s];
      if (src->Register.File != TGSI_FILE_INPUT)
         continue;
      const unsigned swz[4] = { src->Register.SwizzleX, src->Register.SwizzleY,
                                src->Register.SwizzleZ, src->Register.SwizzleW };
      /* the operand's channels the instruction reads, before the swizzle */
      const unsigned read = tgsi_util_get_src_usage_mask(op, s, in->Dst[0].Register.WriteMask,
                                                         0, 1, 2, 3, in->Texture.Texture,
                                                         in->Memory.Texture);
      const bool direct = !src->Register.Indirect && !src->Register.Absolute &&
                          !src->Register.Negate && !src->Register.Dimension;
      const unsigned axes =
         s == 0 && direct && sampler >= 0 && sampler < 32 && is_coord_sampling(op)
            ? wrapped_axes(in->Texture.Texture) : 0;
      for (unsigned c = 0; c < 4; c++) {
         if (!(read >> c & 1u))
            continue;
         if (src->Register.Indirect || src->Register.Index >= RAST_MAX_VARYINGS) {
            /* any input may be the one read */
            memset(fs->coord_other, 0xff, sizeof(fs->coord_other));
            continue;
         }
         struct fp_coord_use *u = &fs->coord_use[src->Register.Index][swz[c]];
         if (c < axes)
            u->samplers[c] |= 1u << sampler;
         else
            fs->coord_other[src->Register.Index] |= (uint8_t)(1u << swz[c]);
      }
   }
}

void fp_rebase_scan(struct fp_fragment_shader *fs)
{
   struct tgsi_parse_context p;
   memset(fs->coord_use, 0, sizeof(fs->coord_use));
   memset(fs->coord_other, 0, sizeof(fs->coord_other));
   if (tgsi_parse_init(&p, fs->tokens) != TGSI_PARSE_OK) {
      memset(fs->coord_other, 0xff, sizeof(fs->coord_other));
      return;
   }
   while (!tgsi_parse_end_of_tokens(&p)) {
      tgsi_parse_token(&p);
      if (p.FullToken.Token.Type == TGSI_TOKEN_TYPE_INSTRUCTION)
         scan_instruction(fs, &p.FullToken.FullInstruction);
   }
   tgsi_parse_free(&p);
}

/* 1: REPEAT, 2: MIRRORED_REPEAT, 0: another mode (or no sampler). */
static unsigned wrap_kind(unsigned wrap)
{
   return wrap == PIPE_TEX_WRAP_REPEAT ? 1u : wrap == PIPE_TEX_WRAP_MIRROR_REPEAT ? 2u : 0u;
}

/* How component c of an input may be rebased: 0 not, 1 by any integer,
 * 2 by an even one. */
static unsigned component_rebase(const struct fp_context *fp, unsigned input, unsigned c)
{
   const struct fp_fragment_shader *fs = fp->fs;
   const struct fp_coord_use *u = &fs->coord_use[input][c];
   unsigned kind = 0;
   if (fs->coord_other[input] >> c & 1u)
      return 0;
   for (unsigned a = 0; a < 3; a++) {
      uint32_t m = u->samplers[a];
      while (m) {
         const struct pipe_sampler_state *st =
            fp->samplers[PIPE_SHADER_FRAGMENT][u_bit_scan(&m)];
         const unsigned wrap = !st ? 0u : a == 0 ? st->wrap_s : a == 1 ? st->wrap_t : st->wrap_r;
         const unsigned k = st && !st->unnormalized_coords ? wrap_kind(wrap) : 0u;
         if (!k)
            return 0;
         kind = MAX2(kind, k);
      }
   }
   return kind;
}

void fp_rebase_modes(const struct fp_context *fp, unsigned input, uint8_t *mask, uint8_t *even)
{
   *mask = *even = 0;
   if (!fp->fs || input >= RAST_MAX_VARYINGS)
      return;
   for (unsigned c = 0; c < 4; c++) {
      const unsigned k = component_rebase(fp, input, c);
      *mask |= (uint8_t)((k != 0) << c);
      *even |= (uint8_t)((k == 2) << c);
   }
}
