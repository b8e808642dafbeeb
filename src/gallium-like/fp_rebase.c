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
 *
 * The same scan finds the components read as an array layer (directly or
 * through a temporary holding the input times a constant): the model
 * divides those in binary32 (rast_varying's float_mask).
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

/* The channel of the coordinate operand that holds the array layer, or -1. */
static int layer_channel(enum tgsi_texture_type target)
{
   switch (target) {
   case TGSI_TEXTURE_1D_ARRAY:
   case TGSI_TEXTURE_SHADOW1D_ARRAY:
      return 1;
   case TGSI_TEXTURE_2D_ARRAY:
   case TGSI_TEXTURE_SHADOW2D_ARRAY:
      return 2;
   case TGSI_TEXTURE_CUBE_ARRAY:
   case TGSI_TEXTURE_SHADOWCUBE_ARRAY:
      return 3;
   default:
      return -1;           /* no layer, or an integer one (TXF on MSAA arrays) */
   }
}

/* The instructions that take a layer from a float coordinate in Src[0]. */
static bool is_layer_sampling(enum tgsi_opcode op)
{
   switch (op) {
   case TGSI_OPCODE_TEX: case TGSI_OPCODE_TEX_LZ: case TGSI_OPCODE_TXB:
   case TGSI_OPCODE_TXL: case TGSI_OPCODE_TXD: case TGSI_OPCODE_TG4:
   case TGSI_OPCODE_TEX2: case TGSI_OPCODE_TXB2: case TGSI_OPCODE_TXL2:
      return true;
   default:
      return false;
   }
}

static bool is_coord_sampling(enum tgsi_opcode op)
{
   return op == TGSI_OPCODE_TEX || op == TGSI_OPCODE_TXB || op == TGSI_OPCODE_TXL ||
          op == TGSI_OPCODE_TXD;
}

/* The derivative of a coordinate less a constant is the coordinate's, and
 * so is the derivative of a constant times it: such a derivative neither
 * qualifies nor spoils a rebase.  Without this, a shader passing dFdx and
 * dFdy of its coordinate to textureGrad saw the coordinate unrebased while
 * texture() of it in another shader saw it rebased, and the two sampled
 * different bits (piglit arb_shader_texture_lod-texgrad compares exactly
 * those; st computes dFdy of the coordinate times the window's y flip).
 * So the scan follows, in straight-line code, each temporary component
 * that holds an input component times a constant (a MOV or a MUL by a
 * constant or immediate): a derivative of it is harmless, any other read
 * is a read of the input. */
#define SCAN_TEMPS 64

struct rebase_scan {
   struct fp_fragment_shader *fs;
   bool flow;                       /* branches or loops: nothing followed */
   int16_t scaled[SCAN_TEMPS][4];   /* input * 4 + component, or -1 */
};

static bool is_derivative(enum tgsi_opcode op)
{
   return op == TGSI_OPCODE_DDX || op == TGSI_OPCODE_DDY || op == TGSI_OPCODE_DDX_FINE ||
          op == TGSI_OPCODE_DDY_FINE;
}

static bool is_flow(enum tgsi_opcode op)
{
   switch (op) {
   case TGSI_OPCODE_IF: case TGSI_OPCODE_UIF: case TGSI_OPCODE_ELSE: case TGSI_OPCODE_ENDIF:
   case TGSI_OPCODE_BGNLOOP: case TGSI_OPCODE_ENDLOOP: case TGSI_OPCODE_BRK:
   case TGSI_OPCODE_CONT: case TGSI_OPCODE_CAL: case TGSI_OPCODE_RET:
   case TGSI_OPCODE_BGNSUB: case TGSI_OPCODE_ENDSUB: case TGSI_OPCODE_SWITCH:
   case TGSI_OPCODE_CASE: case TGSI_OPCODE_DEFAULT: case TGSI_OPCODE_ENDSWITCH:
      return true;
   default:
      return false;
   }
}

static bool plain(const struct tgsi_full_src_register *src)
{
   return !src->Register.Indirect && !src->Register.Absolute && !src->Register.Dimension;
}

/* Whether `in` writes a temporary an input times a constant: a MOV of the
 * input, or a MUL of it by a constant or an immediate, unsaturated. */
static int scaled_input(const struct rebase_scan *sc, const struct tgsi_full_instruction *in)
{
   const enum tgsi_opcode op = in->Instruction.Opcode;
   if (sc->flow || in->Instruction.Saturate || in->Dst[0].Register.File != TGSI_FILE_TEMPORARY ||
       in->Dst[0].Register.Indirect || in->Dst[0].Register.Index >= SCAN_TEMPS)
      return -1;
   if (op == TGSI_OPCODE_MOV)
      return in->Src[0].Register.File == TGSI_FILE_INPUT && plain(&in->Src[0]) ? 0 : -1;
   if (op != TGSI_OPCODE_MUL)
      return -1;
   for (int s = 0; s < 2; s++) {
      const struct tgsi_full_src_register *k = &in->Src[1 - s];
      if (in->Src[s].Register.File == TGSI_FILE_INPUT && plain(&in->Src[s]) &&
          (k->Register.File == TGSI_FILE_CONSTANT || k->Register.File == TGSI_FILE_IMMEDIATE) &&
          !k->Register.Indirect)
         return s;
   }
   return -1;
}

static void scan_instruction(struct rebase_scan *sc, const struct tgsi_full_instruction *in)
{
   struct fp_fragment_shader *fs = sc->fs;
   const enum tgsi_opcode op = in->Instruction.Opcode;
   int sampler = -1;
   for (unsigned s = 0; s < in->Instruction.NumSrcRegs; s++)
      if (in->Src[s].Register.File == TGSI_FILE_SAMPLER && !in->Src[s].Register.Indirect)
         sampler = in->Src[s].Register.Index;
   const int copy = scaled_input(sc, in);
   const unsigned wmask = in->Dst[0].Register.WriteMask;
   /* the channel of Src[0] read as an array layer, or -1 */
   const int layer = is_layer_sampling(op) ? layer_channel(in->Texture.Texture) : -1;
   int16_t written[4] = { -1, -1, -1, -1 };

   for (unsigned s = 0; s < in->Instruction.NumSrcRegs; s++) {
      const struct tgsi_full_src_register *src = &in->Src[s];
      const unsigned swz[4] = { src->Register.SwizzleX, src->Register.SwizzleY,
                                src->Register.SwizzleZ, src->Register.SwizzleW };
      /* the operand's channels the instruction reads, before the swizzle */
      const unsigned read = tgsi_util_get_src_usage_mask(op, s, wmask, 0, 1, 2, 3,
                                                         in->Texture.Texture,
                                                         in->Memory.Texture);
      if (src->Register.File == TGSI_FILE_TEMPORARY) {
         /* a temporary holding a scaled input: harmless under a derivative */
         for (unsigned c = 0; c < 4; c++) {
            if (!(read >> c & 1u))
               continue;
            if (src->Register.Indirect) {
               for (unsigned t = 0; t < SCAN_TEMPS; t++)
                  for (unsigned k = 0; k < 4; k++)
                     if (sc->scaled[t][k] >= 0)
                        fs->coord_other[sc->scaled[t][k] / 4] |= (uint8_t)(1u << sc->scaled[t][k] % 4);
               continue;
            }
            const int16_t v = src->Register.Index < SCAN_TEMPS
                                 ? sc->scaled[src->Register.Index][swz[c]] : -1;
            if (v >= 0 && s == 0 && (int)c == layer)
               fs->layer_read[v / 4] |= (uint8_t)(1u << v % 4);
            if (v >= 0 && !(is_derivative(op) && plain(src)))
               fs->coord_other[v / 4] |= (uint8_t)(1u << v % 4);
         }
         continue;
      }
      if (src->Register.File != TGSI_FILE_INPUT)
         continue;
      const bool direct = plain(src) && !src->Register.Negate;
      if (direct && is_derivative(op))
         continue;
      if ((int)s == copy && src->Register.Index < RAST_MAX_VARYINGS) {
         for (unsigned c = 0; c < 4; c++)
            if (wmask >> c & 1u)
               written[c] = (int16_t)(src->Register.Index * 4 + swz[c]);
         continue;
      }
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
         if (s == 0 && (int)c == layer)
            fs->layer_read[src->Register.Index] |= (uint8_t)(1u << swz[c]);
         struct fp_coord_use *u = &fs->coord_use[src->Register.Index][swz[c]];
         if (c < axes)
            u->samplers[c] |= 1u << sampler;
         else
            fs->coord_other[src->Register.Index] |= (uint8_t)(1u << swz[c]);
      }
   }
   /* what the instruction leaves in a temporary it writes */
   for (unsigned d = 0; d < in->Instruction.NumDstRegs; d++) {
      const struct tgsi_full_dst_register *dst = &in->Dst[d];
      if (dst->Register.File != TGSI_FILE_TEMPORARY)
         continue;
      if (dst->Register.Indirect) {
         memset(sc->scaled, 0xff, sizeof(sc->scaled));
         continue;
      }
      if (dst->Register.Index >= SCAN_TEMPS)
         continue;
      for (unsigned c = 0; c < 4; c++)
         if (dst->Register.WriteMask >> c & 1u)
            sc->scaled[dst->Register.Index][c] = d == 0 ? written[c] : -1;
   }
}

void fp_rebase_scan(struct fp_fragment_shader *fs)
{
   struct tgsi_parse_context p;
   struct rebase_scan sc = { .fs = fs, .flow = false };
   memset(sc.scaled, 0xff, sizeof(sc.scaled));
   memset(fs->coord_use, 0, sizeof(fs->coord_use));
   memset(fs->coord_other, 0, sizeof(fs->coord_other));
   memset(fs->layer_read, 0, sizeof(fs->layer_read));
   if (tgsi_parse_init(&p, fs->tokens) != TGSI_PARSE_OK) {
      memset(fs->coord_other, 0xff, sizeof(fs->coord_other));
      return;
   }
   while (!tgsi_parse_end_of_tokens(&p)) {
      tgsi_parse_token(&p);
      if (p.FullToken.Token.Type == TGSI_TOKEN_TYPE_INSTRUCTION &&
          is_flow(p.FullToken.FullInstruction.Instruction.Opcode))
         sc.flow = true;
   }
   tgsi_parse_free(&p);
   if (tgsi_parse_init(&p, fs->tokens) != TGSI_PARSE_OK) {
      memset(fs->coord_other, 0xff, sizeof(fs->coord_other));
      return;
   }
   while (!tgsi_parse_end_of_tokens(&p)) {
      tgsi_parse_token(&p);
      if (p.FullToken.Token.Type == TGSI_TOKEN_TYPE_INSTRUCTION)
         scan_instruction(&sc, &p.FullToken.FullInstruction);
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
