/*
 * Texture instructions of compiled fragment shaders reach the modeled
 * texture unit.  gallivm asks a lp_build_sampler_soa to emit code for each
 * texture instruction; ours emits no sampling of its own, only a call into
 * C with the quad's operands in memory.  The C side puts them where
 * tgsi_exec puts them (exec_tex, exec_txd, exec_txf, exec_txq) and calls the
 * same tgsi_sampler the interpreter calls, so the unit sees bit for bit the
 * operands it would see from tgsi_exec for the same shader values.
 *
 * gallivm's operand layout differs from tgsi's in three places, undone
 * here: a 1D array's layer is moved to coords[2], the shadow reference is
 * always coords[4], and coordinates a target does not use are undefined
 * (tgsi passes zeros).
 */
#include <string.h>

#include "compiler/nir/nir.h"
#include "gallivm/lp_bld_const.h"
#include "gallivm/lp_bld_flow.h"
#include "gallivm/lp_bld_init.h"
#include "gallivm/lp_bld_pack.h"
#include "gallivm/lp_bld_sample.h"
#include "gallivm/lp_bld_tgsi.h"
#include "gallivm/lp_bld_type.h"
#include "tgsi/tgsi_exec.h"
#include "tgsi/tgsi_util.h"
#include "util/u_memory.h"
#include "util/u_pointer.h"

#include "fp_context.h"
#include "fp_jit.h"
#include "fp_screen.h"
#include "rast/tex/tex.h"

/* the TGSI target of a texture instruction, carried above the gallivm sample key */
#define FP_KEY_TARGET_SHIFT 16

/* What compiled gathers have computed, for the gathers after them (a
 * shader gathering colour asks for red, green and blue of one footprint
 * in turn; a filter gathers blocks side by side from one coordinate and
 * constant offsets, which share their columns and rows): per texture and
 * sampler the decision to gather in the code (registers valid, every lane
 * of its axes within the copy), per axis its coordinate's two texels, per
 * footprint its texel words (undefined where the decision was not to). */
enum fp_jit_memo_kind { FP_MEMO_VALID, FP_MEMO_AXIS, FP_MEMO_FOOTPRINT };
struct fp_jit_memo {
   enum fp_jit_memo_kind kind;
   unsigned texture, sampler, axis;
   LLVMValueRef coord[2];
   int offset[2];
   LLVMValueRef v[4];     /* valid: v[0]; axis: i0, i1, the lanes' ok; footprint: its words */
   LLVMValueRef fast, xy[2][2];   /* footprint: the decision, its columns and rows */
};
#define FP_JIT_MEMOS 32

struct fp_jit_sampler {
   struct lp_build_sampler_soa base;
   /* A stage draw compiles (fp_jit_draw.c): its glue, the tgsi_sampler
    * tgsi_exec calls for that stage, and the C functions, constants in the
    * code, for draw's jit context has no place for them; NULL for a
    * fragment shader, which reads them from fp_jit_context. */
   struct tgsi_sampler *stage_sampler;
   /* per texture index, from the shader's texture instructions */
   uint8_t tgsi_target[PIPE_MAX_SHADER_SAMPLER_VIEWS];
   /* the memo of the last gathers, valid in block `memo_block` alone: the
    * merge block of the last gather, which every block its values were
    * computed in dominates (gathers one after the other, nothing branching
    * between them) */
   LLVMBasicBlockRef memo_block;
   /* the (texture, sampler) pairs of the gathers done in the code */
   uint8_t units[FP_JIT_GATHER_UNITS][2];
   unsigned num_units;
   unsigned memos, memo_next;
   struct fp_jit_memo memo[FP_JIT_MEMOS];
};

static enum tgsi_texture_type fp_tgsi_target(const nir_tex_instr *tex)
{
   const bool a = tex->is_array, s = tex->is_shadow;
   switch (tex->sampler_dim) {
   case GLSL_SAMPLER_DIM_1D:
      return a ? (s ? TGSI_TEXTURE_SHADOW1D_ARRAY : TGSI_TEXTURE_1D_ARRAY)
               : (s ? TGSI_TEXTURE_SHADOW1D : TGSI_TEXTURE_1D);
   case GLSL_SAMPLER_DIM_3D:
      return TGSI_TEXTURE_3D;
   case GLSL_SAMPLER_DIM_CUBE:
      return a ? (s ? TGSI_TEXTURE_SHADOWCUBE_ARRAY : TGSI_TEXTURE_CUBE_ARRAY)
               : (s ? TGSI_TEXTURE_SHADOWCUBE : TGSI_TEXTURE_CUBE);
   case GLSL_SAMPLER_DIM_RECT:
      return s ? TGSI_TEXTURE_SHADOWRECT : TGSI_TEXTURE_RECT;
   case GLSL_SAMPLER_DIM_BUF:
      return TGSI_TEXTURE_BUFFER;
   case GLSL_SAMPLER_DIM_MS:
      return a ? TGSI_TEXTURE_2D_ARRAY_MSAA : TGSI_TEXTURE_2D_MSAA;
   default:
      return a ? (s ? TGSI_TEXTURE_SHADOW2D_ARRAY : TGSI_TEXTURE_2D_ARRAY)
               : (s ? TGSI_TEXTURE_SHADOW2D : TGSI_TEXTURE_2D);
   }
}

/* ---------------------------------------------------------------- C side */

/* tgsi_exec's control of a sample's LOD operand, from gallivm's key. */
static enum tgsi_sampler_control fp_control(unsigned key)
{
   switch ((key & LP_SAMPLER_LOD_CONTROL_MASK) >> LP_SAMPLER_LOD_CONTROL_SHIFT) {
   case LP_SAMPLER_LOD_BIAS: return TGSI_SAMPLER_LOD_BIAS;
   case LP_SAMPLER_LOD_EXPLICIT: return TGSI_SAMPLER_LOD_EXPLICIT;
   case LP_SAMPLER_LOD_DERIVATIVES: return TGSI_SAMPLER_DERIVS_EXPLICIT;
   default: return TGSI_SAMPLER_LOD_NONE;
   }
}

static void fp_jit_sample(struct tgsi_sampler *s, uint32_t texture, uint32_t sampler,
                          uint32_t key, const float coords[5][RAST_QUAD_SIZE],
                          const float lod[RAST_QUAD_SIZE], float derivs[3][2][RAST_QUAD_SIZE],
                          const int32_t offsets[3][RAST_QUAD_SIZE],
                          float rgba[4][RAST_QUAD_SIZE])
{
   const enum tgsi_texture_type target = key >> FP_KEY_TARGET_SHIFT;
   const unsigned op = (key & LP_SAMPLER_OP_TYPE_MASK) >> LP_SAMPLER_OP_TYPE_SHIFT;
   const unsigned lod_control = (key & LP_SAMPLER_LOD_CONTROL_MASK) >> LP_SAMPLER_LOD_CONTROL_SHIFT;
   const bool array_1d = target == TGSI_TEXTURE_1D_ARRAY || target == TGSI_TEXTURE_SHADOW1D_ARRAY;
   static const float zero[RAST_QUAD_SIZE];
   int8_t offset[3] = { 0, 0, 0 };
   if (key & LP_SAMPLER_OFFSETS)
      for (unsigned a = 0; a < 3; a++)
         offset[a] = (int8_t)offsets[a][0];

   /* tgsi's operand slots: coordinates, then the reference, the LOD last */
   const float *arg[5] = { zero, zero, zero, zero, zero };
   const int dim = tgsi_util_get_texture_coord_dim(target);
   for (int i = 0; i < dim && i < 4; i++)
      arg[i] = coords[i];
   if (array_1d)
      arg[1] = coords[2];
   if (key & LP_SAMPLER_SHADOW) {
      const int ref = tgsi_util_get_shadow_ref_src_index(target);
      if (ref >= 0 && ref < 5)
         arg[ref] = coords[4];
   }

   if (op == LP_SAMPLER_OP_FETCH) {
      /* exec_txf: integer coordinates and level, as int bit patterns */
      const int32_t(*ic)[RAST_QUAD_SIZE] = (const int32_t(*)[RAST_QUAD_SIZE])arg[0];
      int32_t x[RAST_QUAD_SIZE] = { 0 }, y[RAST_QUAD_SIZE] = { 0 }, z[RAST_QUAD_SIZE] = { 0 };
      int32_t level[RAST_QUAD_SIZE] = { 0 };
      const int32_t *ilod = (const int32_t *)lod;
      memcpy(x, ic, sizeof(x));
      if (dim > 1 || array_1d)
         memcpy(y, arg[1], sizeof(y));
      if (dim > 2)
         memcpy(z, arg[2], sizeof(z));
      /* the level, or of a multisampled texture the sample (exec_txf
       * takes either from the coordinate's w) */
      if (lod_control == LP_SAMPLER_LOD_EXPLICIT || (key & LP_SAMPLER_FETCH_MS))
         memcpy(level, ilod, sizeof(level));
      s->get_texel(s, texture, x, y, z, level, offset, rgba);
      return;
   }

   if (op == LP_SAMPLER_OP_LODQ) {
      /* textureQueryLod: the unit's levels in x, its LOD in y, as gallivm
       * returns them; exec_lodq takes the implicit LOD */
      memset(rgba, 0, sizeof(float[4][RAST_QUAD_SIZE]));
      s->query_lod(s, texture, sampler, arg[0], arg[1], arg[2], arg[3], TGSI_SAMPLER_LOD_NONE,
                   rgba[0], rgba[1]);
      return;
   }

   if (op == LP_SAMPLER_OP_GATHER) {
      /* exec_tex's TG4: the component in the last operand's bits */
      union { uint32_t u; float f; } comp = {
         (key & LP_SAMPLER_GATHER_COMP_MASK) >> LP_SAMPLER_GATHER_COMP_SHIFT
      };
      const float c1[RAST_QUAD_SIZE] = { comp.f, comp.f, comp.f, comp.f };
      s->get_samples(s, texture, sampler, arg[0], arg[1], arg[2], arg[3], c1, NULL, offset,
                     TGSI_SAMPLER_GATHER, rgba);
      /* textureGatherOffset's offset may differ between lanes
       * (ARB_gpu_shader5): a lane whose offset is not lane 0's gathers
       * again with its own, as tgsi_exec does (mesa/patches/0019) */
      for (unsigned p = 1; (key & LP_SAMPLER_OFFSETS) && p < RAST_QUAD_SIZE; p++) {
         const int8_t o[3] = { (int8_t)offsets[0][p], (int8_t)offsets[1][p],
                               (int8_t)offsets[2][p] };
         if (!memcmp(o, offset, sizeof(o)))
            continue;
         float t[4][RAST_QUAD_SIZE];
         s->get_samples(s, texture, sampler, arg[0], arg[1], arg[2], arg[3], c1, NULL, o,
                        TGSI_SAMPLER_GATHER, t);
         for (unsigned c = 0; c < 4; c++)
            rgba[c][p] = t[c][p];
      }
      return;
   }
   const enum tgsi_sampler_control control = fp_control(key);
   if (control == TGSI_SAMPLER_LOD_BIAS || control == TGSI_SAMPLER_LOD_EXPLICIT)
      arg[4] = lod;
   s->get_samples(s, texture, sampler, arg[0], arg[1], arg[2], arg[3], arg[4],
                  control == TGSI_SAMPLER_DERIVS_EXPLICIT ? derivs : NULL, offset, control, rgba);
}

static void fp_jit_size(struct tgsi_sampler *s, uint32_t texture, int32_t lod, int32_t dims[4])
{
   s->get_dims(s, texture, lod, dims);
}

void fp_jit_context_init_sampler(struct fp_jit_context *ctx, struct tgsi_sampler *s)
{
   fp_tgsi_sampler_jit_gathers(s, &ctx->gathers, &ctx->tex_epoch, &ctx->gathered);
   ctx->sampler = s;
   ctx->sample = fp_jit_sample;
   ctx->size = fp_jit_size;
   ctx->sample_quads = fp_tgsi_sample_quads;
   ctx->gather_quads = fp_tgsi_gather_quads;
   ctx->quads = 2;
}

/* ---------------------------------------------------------------- code */

LLVMValueRef fp_jit_load(struct gallivm_state *gallivm, LLVMValueRef base, size_t offset,
                         LLVMTypeRef type)
{
   LLVMBuilderRef b = gallivm->builder;
   LLVMTypeRef i8 = LLVMInt8TypeInContext(gallivm->context);
   LLVMValueRef off = lp_build_const_int32(gallivm, (int)offset);
   LLVMValueRef p = LLVMBuildBitCast(b, base, LLVMPointerType(i8, 0), "");
   p = LLVMBuildGEP2(b, i8, p, &off, 1, "");
   p = LLVMBuildBitCast(b, p, LLVMPointerType(type, 0), "");
   return LLVMBuildLoad2(b, type, p, "");
}

/* The texture unit an instruction names: its index plus a dynamic offset
 * (sampler arrays), whose first lane is taken, as tgsi_exec takes it. */
static LLVMValueRef fp_texture_unit(struct gallivm_state *gallivm, unsigned unit,
                                    LLVMValueRef offset)
{
   LLVMValueRef texture = lp_build_const_int32(gallivm, unit);
   if (!offset)
      return texture;
   if (LLVMGetTypeKind(LLVMTypeOf(offset)) == LLVMVectorTypeKind)
      offset = LLVMBuildExtractElement(gallivm->builder, offset,
                                       lp_build_const_int32(gallivm, 0), "");
   return LLVMBuildAdd(gallivm->builder, texture, offset, "");
}

/* An array of n vectors in the entry block; returns its first element. */
static LLVMValueRef fp_vec_array(struct gallivm_state *gallivm, LLVMTypeRef vec, unsigned n,
                                 const char *name)
{
   return lp_build_array_alloca(gallivm, vec, lp_build_const_int32(gallivm, n), name);
}

static void fp_store_vec(struct gallivm_state *gallivm, LLVMValueRef array, LLVMTypeRef vec,
                         unsigned i, LLVMValueRef v)
{
   LLVMBuilderRef b = gallivm->builder;
   LLVMValueRef idx = lp_build_const_int32(gallivm, i);
   LLVMValueRef p = LLVMBuildGEP2(b, vec, array, &idx, 1, "");
   if (!v || LLVMIsUndef(v))
      v = LLVMConstNull(vec);
   else if (LLVMTypeOf(v) != vec)
      v = LLVMBuildBitCast(b, v, vec, "");
   LLVMBuildStore(b, v, p);
}

/* A call of the C function at `fn_offset` in fp_jit_context, with the
 * context's sampler glue as its first argument (args[0] is set here); in a
 * stage draw compiles, of `stage_fn` with the stage's glue, both constants. */
static void fp_emit_ctx_call(struct gallivm_state *gallivm, const struct fp_jit_sampler *js,
                             LLVMValueRef context_ptr, size_t fn_offset, func_pointer stage_fn,
                             LLVMTypeRef *arg_types, LLVMValueRef *args, unsigned n)
{
   LLVMBuilderRef b = gallivm->builder;
   LLVMTypeRef fn_type = LLVMFunctionType(LLVMVoidTypeInContext(gallivm->context), arg_types,
                                          n, 0);
   LLVMValueRef fn;
   if (js->stage_sampler) {
      fn = lp_build_const_func_pointer_from_type(gallivm, func_to_pointer(stage_fn), fn_type,
                                                 "fp_stage_fn");
      args[0] = LLVMBuildBitCast(b, lp_build_const_int_pointer(gallivm, js->stage_sampler),
                                 arg_types[0], "");
   } else {
      fn = fp_jit_load(gallivm, context_ptr, fn_offset, LLVMPointerType(fn_type, 0));
      args[0] = fp_jit_load(gallivm, context_ptr, offsetof(struct fp_jit_context, sampler),
                            arg_types[0]);
   }
   LLVMBuildCall2(b, fn_type, fn, args, n, "");
}

/* The quads of a call (fp_jit_fs.c). */
static unsigned fp_quads(const struct lp_sampler_params *params)
{
   return params->type.length / RAST_QUAD_SIZE;
}

LLVMValueRef fp_jit_quad_part(struct gallivm_state *gallivm, LLVMValueRef v, unsigned k,
                              unsigned nq)
{
   if (!v || nq == 1)
      return v;
   return lp_build_extract_range(gallivm, v, k * RAST_QUAD_SIZE, RAST_QUAD_SIZE);
}

LLVMValueRef fp_jit_join_quads(struct gallivm_state *gallivm, LLVMValueRef v[],
                               struct lp_type type4, unsigned nq)
{
   return nq == 1 ? v[0] : lp_build_concat(gallivm, v, type4, nq);
}

/* The texel vectors of nq quads' result arrays, each 4 vectors. */
static void fp_load_texels(struct gallivm_state *gallivm, struct lp_type type4,
                           LLVMValueRef rgba, unsigned nq, LLVMValueRef texel[4])
{
   LLVMTypeRef fvec = lp_build_vec_type(gallivm, type4);
   for (unsigned c = 0; c < 4; c++) {
      LLVMValueRef v[FP_JIT_MAX_QUADS];
      for (unsigned k = 0; k < nq; k++) {
         LLVMValueRef idx = lp_build_const_int32(gallivm, k * 4 + c);
         v[k] = LLVMBuildLoad2(gallivm->builder, fvec,
                               LLVMBuildGEP2(gallivm->builder, fvec, rgba, &idx, 1, ""), "");
      }
      texel[c] = fp_jit_join_quads(gallivm, v, type4, nq);
   }
}

/* Whether an instruction is a plain 2-D sample (no shadow, offsets,
 * derivatives, gather): the one most shaders are made of, whose quad the
 * code lays out itself.  tgsi_exec's operands for it are s and t, zeros for
 * r and the reference (whatever the view's target), and the bias or LOD. */
static bool fp_plain_2d(enum tgsi_texture_type target, unsigned key)
{
   const unsigned op = (key & LP_SAMPLER_OP_TYPE_MASK) >> LP_SAMPLER_OP_TYPE_SHIFT;
   return target == TGSI_TEXTURE_2D && op == LP_SAMPLER_OP_TEXTURE &&
          !(key & (LP_SAMPLER_SHADOW | LP_SAMPLER_OFFSETS)) &&
          fp_control(key) != TGSI_SAMPLER_DERIVS_EXPLICIT;
}

/* The operands' types of a call from the code into the unit's glue: the
 * quads of the call, a quad's vector of floats and pointers to it, the
 * 32-bit integers, the context. */
struct fp_call_types {
   unsigned nq;
   struct lp_type type4;
   LLVMTypeRef fvec, i32, vp, voidp;
};

static struct fp_call_types fp_call_types(struct gallivm_state *gallivm,
                                          const struct lp_sampler_params *params)
{
   LLVMContextRef lc = gallivm->context;
   struct fp_call_types ct = { .nq = fp_quads(params), .type4 = params->type };
   ct.type4.length = RAST_QUAD_SIZE;
   ct.fvec = lp_build_vec_type(gallivm, ct.type4);
   ct.i32 = LLVMInt32TypeInContext(lc);
   ct.vp = LLVMPointerType(ct.fvec, 0);
   ct.voidp = LLVMPointerType(LLVMInt8TypeInContext(lc), 0);
   return ct;
}

/* The quads of a call laid out by the code as struct tex_quad, the operands
 * fp_tgsi_get_samples would build: s and t; `layer` (NULL: zero) in r and
 * the layer; the reference zero; `lod` (NULL: zero). */
#define FP_Q(member) (unsigned)(offsetof(struct tex_quad, member) / sizeof(float[RAST_QUAD_SIZE]))
static LLVMValueRef fp_emit_tex_quads(struct gallivm_state *gallivm,
                                      const struct lp_sampler_params *params, LLVMTypeRef fvec,
                                      LLVMValueRef layer, LLVMValueRef lod, const char *name)
{
   const unsigned nq = fp_quads(params);
   const unsigned per = sizeof(struct tex_quad) / sizeof(float[RAST_QUAD_SIZE]);
   LLVMValueRef q = fp_vec_array(gallivm, fvec, per * nq, name);
   for (unsigned k = 0; k < nq; k++) {
      LLVMValueRef l = fp_jit_quad_part(gallivm, layer, k, nq);
      fp_store_vec(gallivm, q, fvec, k * per + FP_Q(s), fp_jit_quad_part(gallivm, params->coords[0], k, nq));
      fp_store_vec(gallivm, q, fvec, k * per + FP_Q(t), fp_jit_quad_part(gallivm, params->coords[1], k, nq));
      fp_store_vec(gallivm, q, fvec, k * per + FP_Q(r), l);
      fp_store_vec(gallivm, q, fvec, k * per + FP_Q(layer), l);
      fp_store_vec(gallivm, q, fvec, k * per + FP_Q(ref), NULL);
      fp_store_vec(gallivm, q, fvec, k * per + FP_Q(lod), fp_jit_quad_part(gallivm, lod, k, nq));
   }
   return q;
}
#undef FP_Q

/* A plain 2-D sample on the quads of a call: the struct tex_quad
 * fp_tgsi_get_samples would build, one a quad, stored by the code, and one
 * call into the unit's glue. */
static void fp_emit_tex_quad(const struct fp_jit_sampler *js, struct gallivm_state *gallivm,
                             const struct lp_sampler_params *params)
{
   const struct fp_call_types ct = fp_call_types(gallivm, params);
   const unsigned nq = ct.nq;
   LLVMTypeRef fvec = ct.fvec, i32 = ct.i32, vp = ct.vp, voidp = ct.voidp;
   const enum tgsi_sampler_control control = fp_control(params->sample_key);
   LLVMValueRef q = fp_emit_tex_quads(gallivm, params, fvec, NULL,
                                      control == TGSI_SAMPLER_LOD_NONE ? NULL : params->lod,
                                      "tex_quad");
   LLVMValueRef rgba = fp_vec_array(gallivm, fvec, 4 * nq, "texel");
   LLVMValueRef texture = lp_build_const_int32(gallivm, params->texture_index);
   LLVMValueRef sampler = lp_build_const_int32(gallivm, params->sampler_index);
   LLVMValueRef ctl = lp_build_const_int32(gallivm, control);
   LLVMValueRef quads = fp_jit_load(gallivm, params->context_ptr,
                                    offsetof(struct fp_jit_context, quads), i32);
   LLVMTypeRef arg_types[] = { voidp, i32, i32, i32, i32, i32, vp, vp };
   LLVMValueRef args[] = { NULL, texture, sampler, ctl, quads, lp_build_const_int32(gallivm, nq),
                           q, rgba };
   fp_emit_ctx_call(gallivm, js, params->context_ptr,
                    offsetof(struct fp_jit_context, sample_quads), NULL, arg_types, args,
                    ARRAY_SIZE(args));
   fp_load_texels(gallivm, ct.type4, rgba, nq, params->texel);
}

/* Whether an instruction is a gather the code can lay out itself: a
 * non-shadow 2-D, 2-D array or rectangle view named by a constant index,
 * with no offsets or constant ones (the same in every lane, as
 * fp_jit_sample takes each quad's first).  tgsi_exec's operands for it are
 * s, t, and for an array the layer in r and the layer operand, the
 * reference zero. */
static bool fp_gather_2d(enum tgsi_texture_type target, const struct lp_sampler_params *params)
{
   const unsigned key = params->sample_key;
   const unsigned op = (key & LP_SAMPLER_OP_TYPE_MASK) >> LP_SAMPLER_OP_TYPE_SHIFT;
   if (op != LP_SAMPLER_OP_GATHER || (key & LP_SAMPLER_SHADOW) || params->texture_index_offset)
      return false;
   if (target != TGSI_TEXTURE_2D && target != TGSI_TEXTURE_2D_ARRAY &&
       target != TGSI_TEXTURE_RECT)
      return false;
   if (key & LP_SAMPLER_OFFSETS)
      for (unsigned a = 0; a < 2; a++)
         if (!params->offsets[a] || !LLVMIsConstant(params->offsets[a]))
            return false;
   return true;
}

/* Such a gather on the quads of a call: their struct tex_quad stored by
 * the code, and one call into the unit's glue; the texels to texel[4]. */
static void fp_emit_gather_call(const struct fp_jit_sampler *js, struct gallivm_state *gallivm,
                                const struct lp_sampler_params *params,
                                enum tgsi_texture_type target, LLVMValueRef texel[4])
{
   LLVMBuilderRef b = gallivm->builder;
   const struct fp_call_types ct = fp_call_types(gallivm, params);
   const unsigned nq = ct.nq;
   LLVMTypeRef fvec = ct.fvec, i32 = ct.i32, vp = ct.vp, voidp = ct.voidp;
   const bool array = target == TGSI_TEXTURE_2D_ARRAY;
   LLVMValueRef q = fp_emit_tex_quads(gallivm, params, fvec,
                                      array ? params->coords[2] : NULL, NULL, "gather_quad");
   LLVMValueRef off[2] = { lp_build_const_int32(gallivm, 0), lp_build_const_int32(gallivm, 0) };
   if (params->sample_key & LP_SAMPLER_OFFSETS)
      for (unsigned a = 0; a < 2; a++)
         off[a] = LLVMGetTypeKind(LLVMTypeOf(params->offsets[a])) == LLVMVectorTypeKind
                     ? LLVMBuildExtractElement(b, params->offsets[a],
                                               lp_build_const_int32(gallivm, 0), "")
                     : params->offsets[a];
   const unsigned comp =
      (params->sample_key & LP_SAMPLER_GATHER_COMP_MASK) >> LP_SAMPLER_GATHER_COMP_SHIFT;
   LLVMValueRef rgba = fp_vec_array(gallivm, fvec, 4 * nq, "texel");
   LLVMValueRef quads = fp_jit_load(gallivm, params->context_ptr,
                                    offsetof(struct fp_jit_context, quads), i32);
   LLVMTypeRef arg_types[] = { voidp, i32, i32, i32, i32, i32, i32, i32, vp, vp };
   LLVMValueRef args[] = { NULL, lp_build_const_int32(gallivm, params->texture_index),
                           lp_build_const_int32(gallivm, params->sampler_index),
                           lp_build_const_int32(gallivm, comp), off[0], off[1], quads,
                           lp_build_const_int32(gallivm, nq), q, rgba };
   fp_emit_ctx_call(gallivm, js, params->context_ptr,
                    offsetof(struct fp_jit_context, gather_quads), NULL, arg_types, args,
                    ARRAY_SIZE(args));
   fp_load_texels(gallivm, ct.type4, rgba, nq, texel);
}

/* The same value: one, or elements taken from one aggregate alike (gallivm
 * takes a NIR value's channel anew for each instruction that reads it). */
static bool fp_same_value(LLVMValueRef a, LLVMValueRef b)
{
   if (a == b)
      return true;
   if (!a || !b || !LLVMIsAExtractValueInst(a) || !LLVMIsAExtractValueInst(b) ||
       LLVMGetOperand(a, 0) != LLVMGetOperand(b, 0) || LLVMGetNumIndices(a) != LLVMGetNumIndices(b))
      return false;
   return !memcmp(LLVMGetIndices(a), LLVMGetIndices(b), LLVMGetNumIndices(a) * sizeof(unsigned));
}

/* The memo's entry of a kind for these operands: the one there, or a new
 * one, empty (its values NULL), in place of the oldest. */
static struct fp_jit_memo *fp_jit_memo(struct fp_jit_sampler *js, enum fp_jit_memo_kind kind,
                                       const struct lp_sampler_params *params, unsigned axis,
                                       const LLVMValueRef coord[2], const int offset[2])
{
   for (unsigned i = 0; i < js->memos; i++) {
      struct fp_jit_memo *e = &js->memo[i];
      if (e->kind == kind && e->texture == params->texture_index &&
          e->sampler == params->sampler_index && e->axis == axis &&
          fp_same_value(e->coord[0], coord[0]) && fp_same_value(e->coord[1], coord[1]) &&
          e->offset[0] == offset[0] && e->offset[1] == offset[1])
         return e;
   }
   struct fp_jit_memo *e = &js->memo[js->memo_next];
   js->memo_next = (js->memo_next + 1) % FP_JIT_MEMOS;
   if (js->memos < FP_JIT_MEMOS)
      js->memos++;
   memset(e, 0, sizeof(*e));
   e->kind = kind;
   e->texture = params->texture_index;
   e->sampler = params->sampler_index;
   e->axis = axis;
   e->coord[0] = coord[0];
   e->coord[1] = coord[1];
   e->offset[0] = offset[0];
   e->offset[1] = offset[1];
   return e;
}

/* A 2-D or rectangle gather: in the code (fp_jit_gather.c) where the
 * unit's registers are valid and no lane needs the C glue, else the call
 * of fp_emit_gather_call; one branch on a value common to the call and a
 * phi of the texels.  A gather of the footprint a gather just before it
 * addressed takes its decision, addressing and texel words. */
static void fp_emit_gather_quads(struct fp_jit_sampler *js, struct gallivm_state *gallivm,
                                 const struct lp_sampler_params *params,
                                 enum tgsi_texture_type target)
{
   LLVMBuilderRef b = gallivm->builder;
   LLVMContextRef lc = gallivm->context;
   int offset[2] = { 0, 0 };
   bool compiled = target != TGSI_TEXTURE_2D_ARRAY;
   if (compiled && (params->sample_key & LP_SAMPLER_OFFSETS))
      for (unsigned a = 0; a < 2; a++) {
         LLVMValueRef o = params->offsets[a];
         if (LLVMGetTypeKind(LLVMTypeOf(o)) == LLVMVectorTypeKind)
            o = LLVMBuildExtractElement(b, o, lp_build_const_int32(gallivm, 0), "");
         if (!LLVMIsAConstantInt(o))
            compiled = false;
         else
            offset[a] = (int)LLVMConstIntGetSExtValue(o);
      }
   /* the pair among the variant's (its registers filled before a call) */
   unsigned u = 0;
   while (compiled && u < js->num_units &&
          (js->units[u][0] != params->texture_index || js->units[u][1] != params->sampler_index))
      u++;
   if (compiled && u == js->num_units) {
      if (u == FP_JIT_GATHER_UNITS || params->texture_index >= PIPE_MAX_SAMPLERS ||
          params->sampler_index >= PIPE_MAX_SAMPLERS) {
         compiled = false;
      } else {
         js->units[u][0] = (uint8_t)params->texture_index;
         js->units[u][1] = (uint8_t)params->sampler_index;
         js->num_units++;
      }
   }
   if (!compiled) {
      fp_emit_gather_call(js, gallivm, params, target, params->texel);
      return;
   }
   LLVMTypeRef i8 = LLVMInt8TypeInContext(lc), i32 = LLVMInt32TypeInContext(lc);
   LLVMTypeRef i64 = LLVMInt64TypeInContext(lc);
   LLVMTypeRef i8p = LLVMPointerType(i8, 0);
   const unsigned n = params->type.length, nq = fp_quads(params);
   const unsigned comp =
      (params->sample_key & LP_SAMPLER_GATHER_COMP_MASK) >> LP_SAMPLER_GATHER_COMP_SHIFT;

   /* the registers of this texture's entry */
   LLVMValueRef gathers = fp_jit_load(gallivm, params->context_ptr,
                                      offsetof(struct fp_jit_context, gathers), i8p);
   LLVMValueRef at = lp_build_const_int32(gallivm, (int)(params->texture_index *
                                                         sizeof(struct fp_jit_gather)));
   LLVMValueRef entry = LLVMBuildGEP2(b, i8, gathers, &at, 1, "");
   at = lp_build_const_int32(gallivm, (int)offsetof(struct fp_jit_gather, regs));
   LLVMValueRef regs = LLVMBuildGEP2(b, i8, entry, &at, 1, "");

   if (LLVMGetInsertBlock(b) != js->memo_block)
      js->memos = js->memo_next = 0;
   const LLVMValueRef none[2] = { NULL, NULL };
   const int zero[2] = { 0, 0 };
   struct fp_jit_memo *f = fp_jit_memo(js, FP_MEMO_FOOTPRINT, params, 0, params->coords, offset);
   const bool again = f->fast != NULL;
   if (!again) {
      struct fp_jit_memo *v = fp_jit_memo(js, FP_MEMO_VALID, params, 0, none, zero);
      if (!v->v[0]) {
         /* this texture's registers valid in this epoch for this sampler */
         LLVMValueRef epoch_p = fp_jit_load(gallivm, params->context_ptr,
                                            offsetof(struct fp_jit_context, tex_epoch),
                                            LLVMPointerType(i64, 0));
         LLVMValueRef epoch = LLVMBuildLoad2(b, i64, epoch_p, "");
#define FIELD(type, member) \
   fp_jit_load(gallivm, entry, offsetof(struct fp_jit_gather, member), type)
         v->v[0] = LLVMBuildAnd(b,
            LLVMBuildICmp(b, LLVMIntEQ, FIELD(i64, epoch), epoch, ""),
            LLVMBuildAnd(b, LLVMBuildICmp(b, LLVMIntEQ, FIELD(i32, sampler),
                                          lp_build_const_int32(gallivm, params->sampler_index), ""),
                         LLVMBuildICmp(b, LLVMIntNE, FIELD(i32, valid),
                                       lp_build_const_int32(gallivm, 0), ""), ""), "");
#undef FIELD
      }
      /* the addressing does not wait for the decision: it reads no texel,
       * and where the registers are not valid its values are unused */
      LLVMValueRef ok[2];
      for (unsigned a = 0; a < 2; a++) {
         const LLVMValueRef co[2] = { params->coords[a], NULL };
         const int off[2] = { offset[a], 0 };
         struct fp_jit_memo *x = fp_jit_memo(js, FP_MEMO_AXIS, params, a, co, off);
         if (!x->v[2])
            x->v[2] = fp_jit_gather_axis(gallivm, regs, n, a, params->coords[a], offset[a], x->v);
         f->xy[a][0] = x->v[0];
         f->xy[a][1] = x->v[1];
         ok[a] = x->v[2];
      }
      f->fast = LLVMBuildAnd(b, v->v[0], fp_jit_gather_all(gallivm, n, ok[0], ok[1]), "");
   }
   LLVMValueRef func = LLVMGetBasicBlockParent(LLVMGetInsertBlock(b));
   LLVMBasicBlockRef read_bb = LLVMAppendBasicBlockInContext(lc, func, "gather_read");
   LLVMBasicBlockRef call_bb = LLVMAppendBasicBlockInContext(lc, func, "gather_call");
   LLVMBasicBlockRef merge_bb = LLVMAppendBasicBlockInContext(lc, func, "gather_merge");
   LLVMBuildCondBr(b, f->fast, read_bb, call_bb);

   LLVMPositionBuilderAtEnd(b, read_bb);
   LLVMValueRef fast[4], words[4];
   fp_jit_gather_read(gallivm, regs, n, comp, f->xy, again ? f->v : NULL, words, fast);
   /* the quads counted as the glue counts them: the real ones */
   LLVMValueRef quads = fp_jit_load(gallivm, params->context_ptr,
                                    offsetof(struct fp_jit_context, quads), i32);
   LLVMValueRef one = lp_build_const_int32(gallivm, 1), max = lp_build_const_int32(gallivm, nq);
   quads = LLVMBuildSelect(b, LLVMBuildICmp(b, LLVMIntULT, quads, one, ""), one, quads, "");
   quads = LLVMBuildSelect(b, LLVMBuildICmp(b, LLVMIntUGT, quads, max, ""), max, quads, "");
   LLVMValueRef count_p = fp_jit_load(gallivm, params->context_ptr,
                                      offsetof(struct fp_jit_context, gathered),
                                      LLVMPointerType(i64, 0));
   LLVMBuildStore(b, LLVMBuildAdd(b, LLVMBuildLoad2(b, i64, count_p, ""),
                                  LLVMBuildZExt(b, quads, i64, ""), ""), count_p);
   LLVMBasicBlockRef read_end = LLVMGetInsertBlock(b);
   LLVMBuildBr(b, merge_bb);

   LLVMPositionBuilderAtEnd(b, call_bb);
   LLVMValueRef slow[4];
   fp_emit_gather_call(js, gallivm, params, target, slow);
   LLVMBasicBlockRef call_end = LLVMGetInsertBlock(b);
   LLVMBuildBr(b, merge_bb);

   LLVMPositionBuilderAtEnd(b, merge_bb);
   LLVMBasicBlockRef from[2] = { read_end, call_end };
   for (unsigned c = 0; c < 4; c++) {
      LLVMValueRef phi = LLVMBuildPhi(b, LLVMTypeOf(fast[c]), "");
      LLVMValueRef in[2] = { fast[c], slow[c] };
      LLVMAddIncoming(phi, in, from, 2);
      params->texel[c] = phi;
      /* the words for the gathers after it, which read them only where
       * this one read them (the same decision) */
      if (!again) {
         LLVMValueRef w = LLVMBuildPhi(b, LLVMTypeOf(words[c]), "");
         LLVMValueRef win[2] = { words[c], LLVMGetUndef(LLVMTypeOf(words[c])) };
         LLVMAddIncoming(w, win, from, 2);
         f->v[c] = w;
      }
   }
   js->memo_block = merge_bb;
}

/* Any other texture instruction, quad k of nq: its operands where tgsi_exec
 * has them (fp_jit_sample()), the texels to `rgba` (4 vectors). */
static void fp_emit_tex_general(const struct fp_jit_sampler *js, struct gallivm_state *gallivm,
                                const struct lp_sampler_params *params, unsigned key,
                                unsigned k, unsigned nq, LLVMValueRef rgba)
{
   LLVMContextRef lc = gallivm->context;
   struct lp_type type4 = params->type;
   type4.length = RAST_QUAD_SIZE;
   LLVMTypeRef fvec = lp_build_vec_type(gallivm, type4);
   LLVMTypeRef ivec = lp_build_int_vec_type(gallivm, type4);
   LLVMTypeRef i32 = LLVMInt32TypeInContext(lc);
   LLVMTypeRef vp = LLVMPointerType(fvec, 0);
   LLVMTypeRef voidp = LLVMPointerType(LLVMInt8TypeInContext(lc), 0);
   const unsigned unit = params->texture_index;
   const enum tgsi_texture_type target =
      unit < PIPE_MAX_SHADER_SAMPLER_VIEWS ? js->tgsi_target[unit] : TGSI_TEXTURE_2D;

   LLVMValueRef coords = fp_vec_array(gallivm, fvec, 5, "tex_coords");
   for (unsigned i = 0; i < 5; i++)
      fp_store_vec(gallivm, coords, fvec, i, fp_jit_quad_part(gallivm, params->coords[i], k, nq));

   LLVMValueRef lod = fp_vec_array(gallivm, fvec, 1, "tex_lod");
   fp_store_vec(gallivm, lod, fvec, 0,
                fp_jit_quad_part(gallivm,
                                 (params->sample_key & LP_SAMPLER_FETCH_MS) ? params->ms_index
                                                                            : params->lod,
                                 k, nq));

   /* Only the derivatives the target has are set (visit_tex leaves the
    * rest of lp_derivatives uninitialised). */
   LLVMValueRef derivs = fp_vec_array(gallivm, fvec, 6, "tex_derivs");
   int nderiv = 0;
   if (params->derivs) {
      nderiv = tgsi_util_get_texture_coord_dim(target);
      if (target == TGSI_TEXTURE_1D_ARRAY || target == TGSI_TEXTURE_SHADOW1D_ARRAY ||
          target == TGSI_TEXTURE_2D_ARRAY || target == TGSI_TEXTURE_SHADOW2D_ARRAY ||
          target == TGSI_TEXTURE_CUBE_ARRAY || target == TGSI_TEXTURE_SHADOWCUBE_ARRAY)
         nderiv--;
      nderiv = MIN2(nderiv, 3);
   }
   for (int a = 0; a < 3; a++) {
      fp_store_vec(gallivm, derivs, fvec, a * 2,
                   a < nderiv ? fp_jit_quad_part(gallivm, params->derivs->ddx[a], k, nq) : NULL);
      fp_store_vec(gallivm, derivs, fvec, a * 2 + 1,
                   a < nderiv ? fp_jit_quad_part(gallivm, params->derivs->ddy[a], k, nq) : NULL);
   }

   LLVMValueRef offsets = fp_vec_array(gallivm, ivec, 3, "tex_offsets");
   for (unsigned a = 0; a < 3; a++)
      fp_store_vec(gallivm, offsets, ivec, a,
                   (params->sample_key & LP_SAMPLER_OFFSETS)
                      ? fp_jit_quad_part(gallivm, params->offsets[a], k, nq) : NULL);

   LLVMValueRef texture = fp_texture_unit(gallivm, unit,
                                          fp_jit_quad_part(gallivm, params->texture_index_offset, k, nq));

   LLVMTypeRef arg_types[] = { voidp, i32, i32, i32, vp, vp, vp, LLVMPointerType(ivec, 0), vp };
   LLVMValueRef args[] = {
      NULL, texture, lp_build_const_int32(gallivm, params->sampler_index),
      lp_build_const_int32(gallivm, key), coords, lod, derivs, offsets, rgba,
   };
   fp_emit_ctx_call(gallivm, js, params->context_ptr, offsetof(struct fp_jit_context, sample),
                    (func_pointer)fp_jit_sample, arg_types, args, ARRAY_SIZE(args));
}

/* An instruction of a stage draw compiles: its lanes are unrelated vertices,
 * patches or primitives (4, 8 or 16), which tgsi_exec hands the glue four at
 * a time; so does the code, every instruction through fp_jit_sample(), whose
 * glue takes the stage's LOD rule (fp_tgsi_get_samples: no implicit LOD
 * outside the fragment stage).  Every lane is real: a lane past the last
 * vertex is sampled as tgsi_exec samples the stale lanes of its last quad,
 * its texels unused. */
static void fp_emit_tex_stage(const struct fp_jit_sampler *js, struct gallivm_state *gallivm,
                              const struct lp_sampler_params *params, unsigned key)
{
   if (params->type.length % RAST_QUAD_SIZE) {
      /* draw's lanes come in fours (lp_native_vector_width / 32, or 4) */
      for (unsigned c = 0; c < 4; c++)
         params->texel[c] = LLVMConstNull(lp_build_vec_type(gallivm, params->type));
      return;
   }
   const struct fp_call_types ct = fp_call_types(gallivm, params);
   LLVMValueRef rgba = fp_vec_array(gallivm, ct.fvec, 4 * ct.nq, "texel");
   for (unsigned k = 0; k < ct.nq; k++) {
      LLVMValueRef idx = lp_build_const_int32(gallivm, 4 * k);
      fp_emit_tex_general(js, gallivm, params, key, k, ct.nq,
                          LLVMBuildGEP2(gallivm->builder, ct.fvec, rgba, &idx, 1, ""));
   }
   fp_load_texels(gallivm, ct.type4, rgba, ct.nq, params->texel);
}

static void fp_emit_tex_sample(const struct lp_build_sampler_soa *base,
                               struct gallivm_state *gallivm,
                               const struct lp_sampler_params *params)
{
   const struct fp_jit_sampler *js = (const struct fp_jit_sampler *)base;
   const unsigned unit = params->texture_index;
   const enum tgsi_texture_type target =
      unit < PIPE_MAX_SHADER_SAMPLER_VIEWS ? js->tgsi_target[unit] : TGSI_TEXTURE_2D;
   const unsigned key = params->sample_key | (unsigned)target << FP_KEY_TARGET_SHIFT;
   if (js->stage_sampler) {
      fp_emit_tex_stage(js, gallivm, params, key);
      return;
   }
   const unsigned nq = fp_quads(params);
   /* noskip compiles one quad a call and sends every instruction through
    * get_samples; a dynamic unit index, which may differ between the two
    * quads, takes the call per quad below */
   if (nq >= 2 && fp_plain_2d(target, params->sample_key) && !params->texture_index_offset) {
      fp_emit_tex_quad(js, gallivm, params);
      return;
   }
   if (nq >= 2 && fp_gather_2d(target, params)) {
      fp_emit_gather_quads((struct fp_jit_sampler *)js, gallivm, params, target);
      return;
   }

   /* quad by quad; the later ones only where they are real (not the first
    * again: fp_jit_context.quads), their texels zero otherwise */
   const struct fp_call_types ct = fp_call_types(gallivm, params);
   LLVMTypeRef fvec = ct.fvec;
   LLVMValueRef rgba = fp_vec_array(gallivm, fvec, 4 * nq, "texel");
   fp_emit_tex_general(js, gallivm, params, key, 0, nq, rgba);
   if (nq > 1) {
      LLVMBuilderRef b = gallivm->builder;
      LLVMTypeRef i32 = ct.i32;
      for (unsigned i = 4; i < 4 * nq; i++)
         fp_store_vec(gallivm, rgba, fvec, i, NULL);
      LLVMValueRef quads = fp_jit_load(gallivm, params->context_ptr,
                                       offsetof(struct fp_jit_context, quads), i32);
      for (unsigned k = 1; k < nq; k++) {
         struct lp_build_if_state ifs;
         lp_build_if(&ifs, gallivm, LLVMBuildICmp(b, LLVMIntUGT, quads,
                                                  lp_build_const_int32(gallivm, k), ""));
         LLVMValueRef idx = lp_build_const_int32(gallivm, 4 * k);
         fp_emit_tex_general(js, gallivm, params, key, k, nq,
                             LLVMBuildGEP2(b, fvec, rgba, &idx, 1, ""));
         lp_build_endif(&ifs);
      }
   }
   fp_load_texels(gallivm, ct.type4, rgba, nq, params->texel);
}

static void fp_emit_size_query(const struct lp_build_sampler_soa *base,
                               struct gallivm_state *gallivm,
                               const struct lp_sampler_size_query_params *params)
{
   LLVMBuilderRef b = gallivm->builder;
   LLVMContextRef lc = gallivm->context;
   LLVMTypeRef i32 = LLVMInt32TypeInContext(lc);
   LLVMTypeRef voidp = LLVMPointerType(LLVMInt8TypeInContext(lc), 0);
   struct lp_build_context int_bld;
   lp_build_context_init(&int_bld, gallivm, params->int_type);

   if (params->samples_only) {
      /* no multisampled textures: one sample */
      params->sizes_out[0] = lp_build_const_int_vec(gallivm, params->int_type, 1);
      return;
   }

   /* tgsi_exec's TXQ takes the level of the first pixel: so do we. */
   LLVMValueRef lod = lp_build_const_int32(gallivm, 0);
   if (params->explicit_lod) {
      lod = params->explicit_lod;
      if (LLVMGetTypeKind(LLVMTypeOf(lod)) == LLVMVectorTypeKind)
         lod = LLVMBuildExtractElement(b, lod, lp_build_const_int32(gallivm, 0), "");
   }
   LLVMValueRef texture = fp_texture_unit(gallivm, params->texture_unit,
                                          params->texture_unit_offset);
   LLVMValueRef dims = lp_build_array_alloca(gallivm, i32, lp_build_const_int32(gallivm, 4),
                                             "dims");
   LLVMTypeRef arg_types[] = { voidp, i32, i32, LLVMPointerType(i32, 0) };
   LLVMValueRef args[] = { NULL, texture, lod, dims };
   fp_emit_ctx_call(gallivm, (const struct fp_jit_sampler *)base, params->context_ptr,
                    offsetof(struct fp_jit_context, size), (func_pointer)fp_jit_size, arg_types,
                    args, ARRAY_SIZE(args));
   for (unsigned c = 0; c < 4; c++) {
      LLVMValueRef idx = lp_build_const_int32(gallivm, c);
      LLVMValueRef v = LLVMBuildLoad2(b, i32, LLVMBuildGEP2(b, i32, dims, &idx, 1, ""), "");
      params->sizes_out[c] = lp_build_broadcast_scalar(&int_bld, v);
   }
}

unsigned fp_jit_sampler_gather_units(const struct lp_build_sampler_soa *sampler,
                                     uint8_t units[FP_JIT_GATHER_UNITS][2])
{
   const struct fp_jit_sampler *js = (const struct fp_jit_sampler *)sampler;
   memcpy(units, js->units, sizeof(js->units));
   return js->num_units;
}

struct lp_build_sampler_soa *fp_jit_sampler_create(const struct tgsi_shader_info *info,
                                                  void *shader)
{
   return fp_jit_sampler_create_stage(info, shader, NULL);
}

struct lp_build_sampler_soa *fp_jit_sampler_create_stage(const struct tgsi_shader_info *info,
                                                        void *shader,
                                                        struct tgsi_sampler *stage_sampler)
{
   struct fp_jit_sampler *js = CALLOC_STRUCT(fp_jit_sampler);
   if (!js)
      return NULL;
   js->base.emit_tex_sample = fp_emit_tex_sample;
   js->base.emit_size_query = fp_emit_size_query;
   js->stage_sampler = stage_sampler;
   for (unsigned i = 0; i < PIPE_MAX_SHADER_SAMPLER_VIEWS; i++)
      js->tgsi_target[i] = info->sampler_targets[i] ? info->sampler_targets[i]
                                                    : TGSI_TEXTURE_2D;
   nir_shader *nir = shader;   /* NULL: TGSI, whose views declare their targets */
   if (!nir)
      return &js->base;
   nir_foreach_function(func, nir) {
      if (!func->impl)
         continue;
      nir_foreach_block(block, func->impl) {
         nir_foreach_instr(instr, block) {
            if (instr->type != nir_instr_type_tex)
               continue;
            const nir_tex_instr *tex = nir_instr_as_tex(instr);
            if (tex->texture_index < PIPE_MAX_SHADER_SAMPLER_VIEWS &&
                tex->op != nir_texop_txs && tex->op != nir_texop_query_levels &&
                tex->op != nir_texop_texture_samples)
               js->tgsi_target[tex->texture_index] = fp_tgsi_target(tex);
         }
      }
   }
   return &js->base;
}
