/*
 * A fragment shader compiled by gallivm for the model's quads.
 *
 * st/mesa's NIR (the screen prefers NIR for fragment shaders) ->
 * lp_build_opt_nir (llvmpipe's NIR preparation) -> lp_build_nir_soa
 * (llvmpipe's code generator) -> one LLVM function per shader; a shader
 * that comes as TGSI (u_blitter's) goes through tgsi_to_nir first:
 *
 *    void fs(const struct fp_jit_context *ctx, const struct rast_quad *q,
 *            struct rast_shaded_quad *out, int32_t mask[4])
 *
 * It reads the quad exactly as fp_fs_shade (the interpreter) does: the
 * model's interpolated inputs in q->in, gl_FragCoord from the quad's
 * position and its Z and 1/w registers, gl_FrontFacing; it writes the colour
 * outputs and depth to `out` and the surviving lanes to `mask`.  The lanes
 * are the quad's pixels in the model's order (x, then y), which is the
 * order gallivm's derivatives assume.
 */
#include <stddef.h>
#include <stdio.h>

#include "compiler/nir/nir.h"
#include "compiler/nir/nir_serialize.h"
#include "util/blob.h"
#include "gallivm/lp_bld_const.h"
#include "gallivm/lp_bld_flow.h"
#include "gallivm/lp_bld_init.h"
#include "gallivm/lp_bld_intr.h"
#include "gallivm/lp_bld_nir.h"
#include "gallivm/lp_bld_struct.h"
#include "gallivm/lp_bld_tgsi.h"
#include "gallivm/lp_bld_type.h"
#include "nir/tgsi_to_nir.h"
#include "pipe/p_shader_tokens.h"
#include "tgsi/tgsi_info.h"
#include "tgsi/tgsi_scan.h"
#include "util/os_time.h"
#include "util/disk_cache.h"
#include "util/mesa-sha1.h"
#include "gallivm/lp_bld_misc.h"
#include "tgsi/tgsi_parse.h"
#include "util/u_memory.h"
#include "util/ralloc.h"

#include "fp_context.h"
#include "fp_jit.h"
#include "fp_screen.h"
#include "rast/host/lanes.h"

/* llvmpipe's NIR options (lp_screen.c, gallivm_nir_options): what
 * lp_build_nir_soa expects to see lowered. */
static const struct nir_shader_compiler_options fp_jit_nir_options = {
   .lower_scmp = true,
   .lower_flrp32 = true,
   .lower_flrp64 = true,
   .lower_fsat = true,
   .lower_bitfield_insert_to_shifts = true,
   .lower_bitfield_extract_to_shifts = true,
   .lower_fdot = true,
   .lower_fdph = true,
   .lower_ffma16 = true,
   .lower_ffma32 = true,
   .lower_ffma64 = true,
   .lower_flrp16 = true,
   .lower_fmod = true,
   .lower_hadd = true,
   .lower_uadd_sat = true,
   .lower_usub_sat = true,
   .lower_iadd_sat = true,
   .lower_ldexp = true,
   .lower_pack_snorm_2x16 = true,
   .lower_pack_snorm_4x8 = true,
   .lower_pack_unorm_2x16 = true,
   .lower_pack_unorm_4x8 = true,
   .lower_pack_half_2x16 = true,
   .lower_pack_split = true,
   .lower_unpack_snorm_2x16 = true,
   .lower_unpack_snorm_4x8 = true,
   .lower_unpack_unorm_2x16 = true,
   .lower_unpack_unorm_4x8 = true,
   .lower_unpack_half_2x16 = true,
   .lower_extract_byte = true,
   .lower_extract_word = true,
   .lower_insert_byte = true,
   .lower_insert_word = true,
   .lower_rotate = true,
   .lower_uadd_carry = true,
   .lower_usub_borrow = true,
   .lower_mul_2x32_64 = true,
   .lower_ifind_msb = true,
   .lower_int64_options = nir_lower_imul_2x32_64,
   .max_unroll_iterations = 32,
   .use_interpolated_input_intrinsics = true,
   .lower_to_scalar = true,
   .lower_uniforms_to_ubo = true,
   .lower_vector_cmp = true,
   .lower_device_index_to_zero = true,
   .support_16bit_alu = true,
   .lower_fisnormal = true,
   .use_scoped_barrier = true,
};

static const void *fp_jit_compiler_options(struct pipe_screen *screen, enum pipe_shader_ir ir,
                                           enum pipe_shader_type shader)
{
   return &fp_jit_nir_options;
}

/* NIR's clean-up loop before llvmpipe's finalisation (lp_build_opt_nir);
 * with `lower`, nir_opt_algebraic in the loop lowers what the shader's
 * options ask to be lowered. */
static void fp_jit_opt_nir(nir_shader *nir, bool lower)
{
   bool progress;
   do {
      progress = false;
      NIR_PASS(progress, nir, nir_copy_prop);
      NIR_PASS(progress, nir, nir_opt_dce);
      NIR_PASS(progress, nir, nir_opt_cse);
      NIR_PASS(progress, nir, nir_opt_dead_cf);
      if (lower) {
         NIR_PASS(progress, nir, nir_opt_constant_folding);
         NIR_PASS(progress, nir, nir_opt_algebraic);
      }
   } while (progress);
   lp_build_opt_nir(nir);
}

/* llvmpipe_finalize_nir, after tgsi_to_nir's own clean-up */
static char *fp_jit_finalize_nir(struct pipe_screen *screen, void *shader)
{
   fp_jit_opt_nir(shader, false);
   return NULL;
}

/* st's NIR, made with the screen's options for nir_to_tgsi, under gallivm's:
 * nir_opt_algebraic lowers what they lower that the screen's did not
 * (ldexp, the packing built-ins, fsat ...), lp_build_opt_nir the rest, as
 * llvmpipe's finalize does for its own NIR. */
void fp_jit_prepare_nir(nir_shader *nir)
{
   nir->options = &fp_jit_nir_options;
   NIR_PASS_V(nir, nir_lower_int64);
   fp_jit_opt_nir(nir, true);
}

/* The output slots gallivm gives a NIR shader's colours, depth and
 * gl_SampleMask: the outputs' driver_location (lp_build_nir_soa indexes its
 * outputs so), by the colour buffer their location names.  False for an
 * output the back end has no place for (stencil export). */
static bool fp_jit_nir_outputs(const nir_shader *nir, int *depth_output,
                               int color_output[RAST_MAX_CBUFS], int *sample_mask_output)
{
   *depth_output = -1;
   *sample_mask_output = -1;
   for (unsigned cb = 0; cb < RAST_MAX_CBUFS; cb++)
      color_output[cb] = -1;
   nir_foreach_shader_out_variable(var, nir) {
      const int loc = var->data.location, base = (int)var->data.driver_location;
      if (var->data.location_frac != 0 || var->data.index > 1 ||
          (var->data.index == 1 && loc != FRAG_RESULT_DATA0))
         return false;
      if (var->data.index == 1) {
         /* dual-source blending's second colour: the back end's colour 1,
          * as TGSI's COLOR[1] */
         color_output[1] = base;
      } else if (loc == FRAG_RESULT_DEPTH) {
         *depth_output = base;
      } else if (loc == FRAG_RESULT_SAMPLE_MASK) {
         *sample_mask_output = base;
      } else if (loc == FRAG_RESULT_COLOR) {
         color_output[0] = base;
      } else if (loc >= FRAG_RESULT_DATA0) {
         const int slots = (int)glsl_count_attribute_slots(var->type, false);
         for (int k = 0; k < slots; k++)
            if (loc - FRAG_RESULT_DATA0 + k < RAST_MAX_CBUFS)
               color_output[loc - FRAG_RESULT_DATA0 + k] = base + k;
      } else {
         return false;
      }
   }
   return true;
}

static LLVMValueRef fp_byte_ptr(struct gallivm_state *gallivm, LLVMValueRef base, size_t offset,
                                LLVMTypeRef pointee)
{
   LLVMBuilderRef b = gallivm->builder;
   LLVMTypeRef i8 = LLVMInt8TypeInContext(gallivm->context);
   LLVMValueRef off = lp_build_const_int32(gallivm, (int)offset);
   LLVMValueRef p = LLVMBuildGEP2(b, i8, base, &off, 1, "");
   return LLVMBuildBitCast(b, p, LLVMPointerType(pointee, 0), "");
}

/* The model's quads are float arrays, aligned to 4 bytes, not to a vector. */
static LLVMValueRef fp_load_vec(struct gallivm_state *gallivm, LLVMValueRef base, size_t offset,
                                LLVMTypeRef vec)
{
   LLVMValueRef v = LLVMBuildLoad2(gallivm->builder, vec,
                                   fp_byte_ptr(gallivm, base, offset, vec), "");
   LLVMSetAlignment(v, 4);
   return v;
}

static void fp_store(struct gallivm_state *gallivm, LLVMValueRef base, size_t offset,
                     LLVMValueRef v)
{
   LLVMValueRef s = LLVMBuildStore(gallivm->builder, v,
                                   fp_byte_ptr(gallivm, base, offset, LLVMTypeOf(v)));
   LLVMSetAlignment(s, 4);
}

/* A vector of the quads' lanes, quad after quad, each quad's four from
 * `offset` in it. */
static LLVMValueRef fp_load_quads(struct gallivm_state *gallivm, const LLVMValueRef *quads,
                                  unsigned nq, size_t offset, struct lp_type type4)
{
   LLVMValueRef v[FP_JIT_MAX_QUADS];
   for (unsigned k = 0; k < nq; k++)
      v[k] = fp_load_vec(gallivm, quads[k], offset, lp_build_vec_type(gallivm, type4));
   return fp_jit_join_quads(gallivm, v, type4, nq);
}

/* gl_FragCoord.xy of the quad's four pixels: (x + (p & 1), y + (p >> 1)) + centre. */
static LLVMValueRef fp_quad_coord(struct gallivm_state *gallivm, struct lp_type type,
                                  LLVMValueRef quad, size_t offset, const float step[4],
                                  float centre)
{
   LLVMBuilderRef b = gallivm->builder;
   LLVMTypeRef i32 = LLVMInt32TypeInContext(gallivm->context);
   struct lp_build_context fbld;
   lp_build_context_init(&fbld, gallivm, type);
   LLVMValueRef v = LLVMBuildLoad2(b, i32, fp_byte_ptr(gallivm, quad, offset, i32), "");
   v = LLVMBuildSIToFP(b, v, fbld.elem_type, "");
   v = lp_build_broadcast_scalar(&fbld, v);
   LLVMValueRef steps[4];
   for (unsigned p = 0; p < 4; p++)
      steps[p] = lp_build_const_float(gallivm, step[p] + centre);
   return LLVMBuildFAdd(b, v, LLVMConstVector(steps, 4), "");
}

/* gl_FragCoord.xy of the quads' lanes. */
static LLVMValueRef fp_quads_coord(struct gallivm_state *gallivm, struct lp_type type4,
                                   const LLVMValueRef *quads, unsigned nq, size_t offset,
                                   const float step[4], float centre)
{
   LLVMValueRef v[FP_JIT_MAX_QUADS];
   for (unsigned k = 0; k < nq; k++)
      v[k] = fp_quad_coord(gallivm, type4, quads[k], offset, step, centre);
   return fp_jit_join_quads(gallivm, v, type4, nq);
}

/* Framebuffer fetch: gallivm asks for the output at `location`; the back
 * end has put that colour buffer's contents in the quads' `last`. */
struct fp_fs_iface {
   struct lp_build_fs_iface base;
   const LLVMValueRef *quads;
   unsigned nq;
   struct lp_type type4;
};

static void fp_fb_fetch(const struct lp_build_fs_iface *iface, struct lp_build_context *bld,
                        int location, LLVMValueRef result[4])
{
   const struct fp_fs_iface *f = (const struct fp_fs_iface *)iface;
   unsigned cb = location >= FRAG_RESULT_DATA0 ? (unsigned)(location - FRAG_RESULT_DATA0) : 0;
   if (cb >= RAST_MAX_CBUFS)
      cb = 0;
   for (unsigned c = 0; c < 4; c++)
      result[c] = fp_load_quads(bld->gallivm, f->quads, f->nq,
                                offsetof(struct rast_quad, last) +
                                   ((size_t)cb * 4 + c) * RAST_QUAD_SIZE * sizeof(float),
                                f->type4);
}

/* The shader on `nq` quads: 4 lanes a quad, gallivm's quad operations
 * (derivatives) within each quad's four. */
static LLVMValueRef fp_build_fs(struct gallivm_state *gallivm, nir_shader *nir,
                                const struct tgsi_shader_info *info,
                                const struct lp_build_sampler_soa *sampler, int depth_output,
                                const int *color_output, unsigned num_color_outputs,
                                int sample_mask_output, unsigned nq)
{
   LLVMContextRef lc = gallivm->context;
   LLVMBuilderRef b = gallivm->builder;
   const struct lp_type type = lp_type_float_vec(32, 32 * RAST_QUAD_SIZE * nq);
   const struct lp_type type4 = lp_type_float_vec(32, 32 * RAST_QUAD_SIZE);
   LLVMTypeRef fvec = lp_build_vec_type(gallivm, type);
   LLVMTypeRef ivec = lp_build_int_vec_type(gallivm, type);
   LLVMTypeRef i8p = LLVMPointerType(LLVMInt8TypeInContext(lc), 0);
   LLVMTypeRef i8pp = LLVMPointerType(i8p, 0);
   LLVMTypeRef args[4] = { i8p, i8pp, i8pp, LLVMPointerType(ivec, 0) };
   LLVMTypeRef func_type = LLVMFunctionType(LLVMVoidTypeInContext(lc), args, 4, 0);
   LLVMValueRef func = LLVMAddFunction(gallivm->module, "fp_fs", func_type);
   LLVMSetFunctionCallConv(func, LLVMCCallConv);
   LLVMValueRef ctx = LLVMGetParam(func, 0);
   LLVMValueRef mask_ptr = LLVMGetParam(func, 3);
   lp_add_function_attr(func, 1, LP_FUNC_ATTR_NOALIAS);
   lp_add_function_attr(func, 4, LP_FUNC_ATTR_NOALIAS);

   LLVMBasicBlockRef block = LLVMAppendBasicBlockInContext(lc, func, "entry");
   LLVMPositionBuilderAtEnd(b, block);

   /* the quads and their outputs: q[k], out[k] (the quads repeat the first
    * where fewer are real: read-only, they may alias) */
   LLVMValueRef quads[FP_JIT_MAX_QUADS], outs[FP_JIT_MAX_QUADS];
   for (unsigned k = 0; k < nq; k++) {
      LLVMValueRef idx = lp_build_const_int32(gallivm, (int)k);
      quads[k] = LLVMBuildLoad2(b, i8p, LLVMBuildGEP2(b, i8p, LLVMGetParam(func, 1), &idx, 1, ""),
                                "");
      outs[k] = LLVMBuildLoad2(b, i8p, LLVMBuildGEP2(b, i8p, LLVMGetParam(func, 2), &idx, 1, ""),
                               "");
   }

   /* Each quad's four lanes loaded alone: the caller has just stored them
    * quad by quad (fp_fs_shade_n_jit), and one load over the four stores
    * would wait for them to reach the cache (docs/datapath.md, "Coordinates
    * read as they were stored"). */
   struct lp_build_mask_context mask;
   const struct lp_type itype4 = lp_int_type(type4);
   LLVMValueRef mask_bytes = LLVMBuildBitCast(b, mask_ptr, i8p, "");
   LLVMValueRef mask_q[FP_JIT_MAX_QUADS];
   for (unsigned k = 0; k < nq; k++)
      mask_q[k] = fp_load_vec(gallivm, mask_bytes, k * RAST_QUAD_SIZE * sizeof(int32_t),
                              lp_build_vec_type(gallivm, itype4));
   LLVMValueRef mask_in = fp_jit_join_quads(gallivm, mask_q, itype4, nq);
   lp_build_mask_begin(&mask, gallivm, type, mask_in);

   /* Inputs, as fp_fs_shade fills tgsi_exec's. */
   const bool integer_centre =
      info->properties[TGSI_PROPERTY_FS_COORD_PIXEL_CENTER] == TGSI_FS_COORD_PIXEL_CENTER_INTEGER;
   const float centre = integer_centre ? 0.0f : 0.5f;
   static const float step_x[4] = { 0, 1, 0, 1 }, step_y[4] = { 0, 0, 1, 1 };
   LLVMValueRef inputs[PIPE_MAX_SHADER_INPUTS][4];
   memset(inputs, 0, sizeof(inputs));
   for (unsigned i = 0; i < info->num_inputs && i < RAST_MAX_VARYINGS; i++) {
      switch (info->input_semantic_name[i]) {
      case TGSI_SEMANTIC_POSITION:
         inputs[i][0] = fp_quads_coord(gallivm, type4, quads, nq, offsetof(struct rast_quad, x),
                                       step_x, centre);
         inputs[i][1] = fp_quads_coord(gallivm, type4, quads, nq, offsetof(struct rast_quad, y),
                                       step_y, centre);
         inputs[i][2] = fp_load_quads(gallivm, quads, nq, offsetof(struct rast_quad, frag_z), type4);
         inputs[i][3] = fp_load_quads(gallivm, quads, nq, offsetof(struct rast_quad, frag_w), type4);
         break;
      case TGSI_SEMANTIC_FACE: {
         /* tgsi_to_nir reads FACE as a boolean input: lanes of ~0 or 0.
          * The quads of a call are of one primitive: q0's facing is theirs. */
         LLVMTypeRef i8 = LLVMInt8TypeInContext(lc);
         LLVMValueRef ff = LLVMBuildLoad2(
            b, i8, fp_byte_ptr(gallivm, quads[0], offsetof(struct rast_quad, front_facing), i8),
            "");
         ff = LLVMBuildICmp(b, LLVMIntNE, ff, LLVMConstInt(i8, 0, 0), "");
         ff = LLVMBuildSExt(b, ff, LLVMInt32TypeInContext(lc), "");
         struct lp_build_context ibld;
         lp_build_context_init(&ibld, gallivm, lp_int_type(type));
         ff = LLVMBuildBitCast(b, lp_build_broadcast_scalar(&ibld, ff), fvec, "");
         inputs[i][0] = ff;
         inputs[i][1] = inputs[i][2] = lp_build_const_vec(gallivm, type, 0.0);
         inputs[i][3] = lp_build_const_vec(gallivm, type, 1.0);
         break;
      }
      default:
         for (unsigned c = 0; c < 4; c++)
            inputs[i][c] = fp_load_quads(gallivm, quads, nq,
                                         offsetof(struct rast_quad, in) +
                                            ((size_t)i * 4 + c) * RAST_QUAD_SIZE * sizeof(float),
                                         type4);
         break;
      }
   }
   for (unsigned i = 0; i < PIPE_MAX_SHADER_INPUTS; i++)
      for (unsigned c = 0; c < 4; c++)
         if (!inputs[i][c])
            inputs[i][c] = lp_build_const_vec(gallivm, type, 0.0);

   /* System values (the screen has FACE, POSITION and PCOORD as inputs):
    * the sample's, of sample shading.  The quads of a call are of one walk
    * of the model: q0's sample is theirs; its position and mask come from
    * the context's tables (fp_fs_sample_tables), as the interpreter's. */
   struct lp_bld_tgsi_system_values system_values;
   memset(&system_values, 0, sizeof(system_values));
   {
      LLVMTypeRef i8 = LLVMInt8TypeInContext(lc), i32 = LLVMInt32TypeInContext(lc);
      LLVMValueRef sid = LLVMBuildLoad2(
         b, i8, fp_byte_ptr(gallivm, quads[0], offsetof(struct rast_quad, sample), i8), "");
      sid = LLVMBuildZExt(b, sid, i32, "");
      system_values.sample_id = sid;
      system_values.sample_pos_type =
         LLVMArrayType(LLVMFloatTypeInContext(lc), RAST_MSAA_SAMPLES * 2);
      system_values.sample_pos = fp_byte_ptr(gallivm, ctx, offsetof(struct fp_jit_context, sample_pos),
                                             system_values.sample_pos_type);
      LLVMTypeRef masks_type = LLVMArrayType(i32, RAST_MSAA_SAMPLES);
      LLVMValueRef masks = fp_byte_ptr(gallivm, ctx, offsetof(struct fp_jit_context, sample_mask_in),
                                       masks_type);
      struct lp_build_context ibld;
      lp_build_context_init(&ibld, gallivm, lp_int_type(type));
      system_values.sample_mask_in =
         lp_build_broadcast_scalar(&ibld, lp_build_array_get2(gallivm, masks_type, masks, sid));
   }

   LLVMTypeRef buffers_type = LLVMArrayType(lp_build_create_jit_buffer_type(gallivm),
                                            LP_MAX_TGSI_CONST_BUFFERS);
   LLVMValueRef consts = fp_byte_ptr(gallivm, ctx, offsetof(struct fp_jit_context, constants),
                                     buffers_type);

   LLVMValueRef outputs[PIPE_MAX_SHADER_OUTPUTS][4];
   memset(outputs, 0, sizeof(outputs));

   struct lp_build_tgsi_params params;
   memset(&params, 0, sizeof(params));
   params.type = type;
   params.mask = &mask;
   params.consts_ptr = consts;
   params.system_values = &system_values;
   params.inputs = (const LLVMValueRef(*)[4])inputs;
   params.context_ptr = ctx;
   params.sampler = sampler;
   params.info = info;
   /* Derivatives as tgsi_exec takes them (mesa/patches/0005): one per quad,
    * dFdx from the bottom row, dFdy from the left column, the convention the
    * model's implicit LOD shares, so textureGrad(dFdx(c), dFdy(c)) samples the
    * same LOD compiled as interpreted. */
   params.tgsi_exec_derivatives = true;
   struct fp_fs_iface fs_iface = { { NULL, fp_fb_fetch }, quads, nq, type4 };
   if (info->uses_fbfetch)
      params.fs_iface = &fs_iface.base;
   lp_build_nir_soa(gallivm, nir, &params, outputs);

   /* Outputs: what fp_fs_shade copies out of tgsi_exec's registers. */
   LLVMValueRef zero = lp_build_const_vec(gallivm, type, 0.0);
   for (unsigned cb = 0; cb < MAX2(num_color_outputs, 1); cb++) {
      const int o = cb < num_color_outputs ? color_output[cb] : -1;
      for (unsigned c = 0; c < 4; c++) {
         LLVMValueRef v = zero;
         if (o >= 0 && outputs[o][c])
            v = LLVMBuildLoad2(b, fvec, outputs[o][c], "");
         for (unsigned k = 0; k < nq; k++)
            fp_store(gallivm, outs[k],
                     offsetof(struct rast_shaded_quad, color) +
                        ((size_t)cb * 4 + c) * RAST_QUAD_SIZE * sizeof(float),
                     fp_jit_quad_part(gallivm, v, k, nq));
      }
   }
   if (depth_output >= 0) {
      /* gallivm stores FRAG_RESULT_DEPTH in .z, where TGSI has it */
      LLVMValueRef v = zero;
      if (outputs[depth_output][2])
         v = LLVMBuildLoad2(b, fvec, outputs[depth_output][2], "");
      for (unsigned k = 0; k < nq; k++)
         fp_store(gallivm, outs[k], offsetof(struct rast_shaded_quad, depth),
                  fp_jit_quad_part(gallivm, v, k, nq));
   }

   if (sample_mask_output >= 0 && outputs[sample_mask_output][0]) {
      /* gl_SampleMask: an integer in the float output's bits */
      LLVMValueRef v = LLVMBuildLoad2(b, fvec, outputs[sample_mask_output][0], "");
      v = LLVMBuildBitCast(b, v, ivec, "");
      for (unsigned k = 0; k < nq; k++)
         fp_store(gallivm, outs[k], offsetof(struct rast_shaded_quad, sample_mask),
                  fp_jit_quad_part(gallivm, v, k, nq));
   }

   LLVMSetAlignment(LLVMBuildStore(b, lp_build_mask_end(&mask), mask_ptr), 4);
   LLVMBuildRetVoid(b);
   gallivm_verify_function(gallivm, func);
   return func;
}

/* What the compiled path takes from TGSI alone (the driver's own and
 * u_blitter's shaders; st's come as NIR); any other shader stays
 * interpreted.  tgsi_to_nir aborts on a varying semantic it has no NIR slot for (nir_to_tgsi
 * gives packed varyings TGSI_SEMANTIC_PATCH, say); the slot names the
 * variable only, the compiled code reads inputs by TGSI index. */
static bool fp_jit_shader_ok(const struct tgsi_shader_info *info)
{
   for (unsigned i = 0; i < info->num_inputs; i++) {
      const unsigned idx = info->input_semantic_index[i];
      switch (info->input_semantic_name[i]) {
      case TGSI_SEMANTIC_POSITION:
      case TGSI_SEMANTIC_COLOR:
      case TGSI_SEMANTIC_BCOLOR:
      case TGSI_SEMANTIC_FOG:
      case TGSI_SEMANTIC_PSIZE:
      case TGSI_SEMANTIC_FACE:
      case TGSI_SEMANTIC_EDGEFLAG:
      case TGSI_SEMANTIC_PRIMID:
      case TGSI_SEMANTIC_CLIPDIST:
      case TGSI_SEMANTIC_CLIPVERTEX:
      case TGSI_SEMANTIC_PCOORD:
      case TGSI_SEMANTIC_VIEWPORT_INDEX:
      case TGSI_SEMANTIC_LAYER:
         break;
      case TGSI_SEMANTIC_GENERIC:
         if (idx >= 32)
            return false;
         break;
      case TGSI_SEMANTIC_TEXCOORD:
         if (idx >= 8)
            return false;
         break;
      default:
         return false;
      }
   }
   /* textureGather: tgsi_to_nir has no TG4 (it aborts) */
   if (info->opcode_count[TGSI_OPCODE_TG4])
      return false;
   /* Opcodes Mesa 22.3.6's tgsi_to_nir has no translation for: it aborts
    * the process ("unknown TGSI opcode"), and a GL program must not die
    * through valid GL (ldexp() is LDEXP).  A shader with one stays on
    * tgsi_exec, which has them.  The list is tgsi_to_nir.c's op_trans[]
    * entries of 0 that ttn_emit_instruction has no case for. */
   static const uint8_t ttn_missing[] = {
      TGSI_OPCODE_LDEXP, TGSI_OPCODE_FMA, TGSI_OPCODE_DEMOTE, TGSI_OPCODE_READ_HELPER,
      TGSI_OPCODE_CLOCK, TGSI_OPCODE_PK2H, TGSI_OPCODE_PK2US, TGSI_OPCODE_PK4B,
      TGSI_OPCODE_PK4UB, TGSI_OPCODE_UP2H, TGSI_OPCODE_UP2US, TGSI_OPCODE_UP4B,
      TGSI_OPCODE_UP4UB, TGSI_OPCODE_CAL, TGSI_OPCODE_RET, TGSI_OPCODE_BGNSUB,
      TGSI_OPCODE_ENDSUB, TGSI_OPCODE_SWITCH, TGSI_OPCODE_CASE, TGSI_OPCODE_DEFAULT,
      TGSI_OPCODE_ENDSWITCH, TGSI_OPCODE_MEMBAR, TGSI_OPCODE_RESQ, TGSI_OPCODE_TXQS,
      TGSI_OPCODE_LOD, TGSI_OPCODE_ATOMUADD, TGSI_OPCODE_ATOMXCHG, TGSI_OPCODE_ATOMCAS,
      TGSI_OPCODE_ATOMAND, TGSI_OPCODE_ATOMOR, TGSI_OPCODE_ATOMXOR, TGSI_OPCODE_ATOMUMIN,
      TGSI_OPCODE_ATOMUMAX, TGSI_OPCODE_ATOMIMIN, TGSI_OPCODE_ATOMIMAX, TGSI_OPCODE_ATOMFADD,
      TGSI_OPCODE_ATOMINC_WRAP, TGSI_OPCODE_ATOMDEC_WRAP, TGSI_OPCODE_INTERP_CENTROID,
      TGSI_OPCODE_INTERP_SAMPLE, TGSI_OPCODE_INTERP_OFFSET, TGSI_OPCODE_READ_FIRST,
      TGSI_OPCODE_READ_INVOC, TGSI_OPCODE_BALLOT, TGSI_OPCODE_VOTE_ANY, TGSI_OPCODE_VOTE_ALL,
      TGSI_OPCODE_VOTE_EQ, TGSI_OPCODE_SAMPLE_POS, TGSI_OPCODE_SAMPLE_INFO,
      TGSI_OPCODE_IMG2HND, TGSI_OPCODE_SAMP2HND,
   };
   for (unsigned i = 0; i < sizeof(ttn_missing); i++)
      if (info->opcode_count[ttn_missing[i]])
         return false;
   /* and no double or 64-bit integer arithmetic (GL ES has none) */
   for (unsigned op = 0; op < TGSI_OPCODE_LAST; op++) {
      if (!info->opcode_count[op])
         continue;
      if (tgsi_type_is_64bit(tgsi_opcode_infer_dst_type((enum tgsi_opcode)op, 0)) ||
          tgsi_type_is_64bit(tgsi_opcode_infer_src_type((enum tgsi_opcode)op, 0)))
         return false;
   }
   /* texelFetch from multisampled textures: interpreted (the compiled
    * code's fetch has no sample operand) */
   for (unsigned i = 0; i < PIPE_MAX_SHADER_SAMPLER_VIEWS; i++)
      if (info->sampler_targets[i] == TGSI_TEXTURE_2D_MSAA ||
          info->sampler_targets[i] == TGSI_TEXTURE_2D_ARRAY_MSAA)
         return false;
   for (unsigned i = 0; i < info->num_outputs; i++) {
      switch (info->output_semantic_name[i]) {
      case TGSI_SEMANTIC_COLOR:
      case TGSI_SEMANTIC_POSITION:
         break;
      default:
         return false;   /* stencil export, sample mask: not from TGSI alone (st's come as NIR) */
      }
   }
   return true;
}

/* Quads a call (docs/jit.md): four (sixteen lanes) where the datapath's
 * lanes are the 512-bit set, whose texture unit takes four quads in one
 * call (two vectors of pairs overlap a sample's long chain of latencies)
 * and whose perspective division takes four quads in one vector of
 * binary32 lanes, the group the shader is called with being the group the
 * division takes (persp.c); two otherwise; one with noskip. */
static unsigned fp_jit_quads_a_call(const struct fp_context *fp)
{
   const unsigned debug = fp->opts->debug;
   if (debug & FP_DEBUG_NOSKIP)
      return 1;
   if (!(debug & FP_DEBUG_SCALAR) && rast_lanes()->tex_group == 4)
      return 4;
   return 2;
}

/* The shader's key in the on-disk cache: what the generated code depends on.
 * The driver's own layout (rast_quad, fp_jit_context) is in the cache's id. */
static void fp_jit_cache_key(const struct tgsi_token *tokens, const nir_shader *nir,
                             int depth_output, const int *color_output,
                             unsigned num_color_outputs, unsigned quads,
                             unsigned char key[CACHE_KEY_SIZE], struct disk_cache *cache)
{
   struct mesa_sha1 ctx;
   unsigned char sha1[20];
   /* 2: tgsi_exec derivatives; 3: plain 2-D samples lay out their quad;
    * 4: two quads a call; 5: the quads by pointer arrays, four a call for
    * texturing shaders; 6: st's NIR, gathers and multisample fetches;
    * 7: gathers of 2-D views in the code; 8: the sample's system values */
   static const char version[] = "fixpipe fs quad 8";
   /* the quads a call (noskip: one, which also leaves the quads laid out
    * by the code out: fp_jit_sample.c) */
   _mesa_sha1_init(&ctx);
   _mesa_sha1_update(&ctx, version, sizeof(version));
   _mesa_sha1_update(&ctx, &quads, sizeof(quads));
   /* the shader compiled, and the TGSI its inputs are laid out by */
   _mesa_sha1_update(&ctx, tokens, tgsi_num_tokens(tokens) * sizeof(struct tgsi_token));
   if (nir) {
      struct blob blob;
      blob_init(&blob);
      nir_serialize(&blob, nir, true);
      _mesa_sha1_update(&ctx, blob.data, blob.size);
      blob_finish(&blob);
   }
   _mesa_sha1_update(&ctx, &depth_output, sizeof(depth_output));
   _mesa_sha1_update(&ctx, &num_color_outputs, sizeof(num_color_outputs));
   _mesa_sha1_update(&ctx, color_output, num_color_outputs * sizeof(*color_output));
   _mesa_sha1_final(&ctx, sha1);
   disk_cache_compute_key(cache, sha1, sizeof(sha1), key);
}

struct fp_jit_variant *fp_jit_fs_compile(struct fp_context *fp, const struct tgsi_token *tokens,
                                         const nir_shader *src_nir,
                                         const struct tgsi_shader_info *info,
                                         int depth_output, const int *color_output,
                                         unsigned num_color_outputs)
{
   const int64_t start = os_time_get_nano();
   if (info->num_inputs > RAST_MAX_VARYINGS || num_color_outputs > RAST_MAX_CBUFS)
      return NULL;
   /* input arrays (gl_TexCoord[i], an array varying): gallivm reads one at
    * a run-time index from an array of the inputs the compiled code does not
    * lay out, and its code generation crashed there; tgsi_exec has them */
   if (info->indirect_files & (1u << TGSI_FILE_INPUT))
      return NULL;
   if (src_nir) {
      nir_foreach_shader_in_variable(var, src_nir)
         if (glsl_type_is_array(var->type))
            return NULL;
   }
   /* interpolateAt*: the model evaluates the input at the point
    * (rast_interp_at, through tgsi_exec's INTERP_* hook, mesa/patches/0018);
    * gallivm's code would evaluate its own planes, which the compiled code
    * does not have, and crashed building them */
   if (info->opcode_count[TGSI_OPCODE_INTERP_CENTROID] ||
       info->opcode_count[TGSI_OPCODE_INTERP_SAMPLE] ||
       info->opcode_count[TGSI_OPCODE_INTERP_OFFSET])
      return NULL;
   /* st's NIR: every operation gallivm has, its outputs by their NIR slots;
    * TGSI alone: what tgsi_to_nir can read */
   int nir_color_output[RAST_MAX_CBUFS];
   int sample_mask_output = -1;
   /* Storage buffers, images and atomic counters (st's storage buffers)
    * stay interpreted: the compiled code has none of gallivm's image and
    * buffer hooks, and tgsi_exec's atomics are atomic on the storage
    * across the model's threads (fp_image.c, mesa/patches/0017) */
   if (info->file_max[TGSI_FILE_BUFFER] >= 0 || info->file_max[TGSI_FILE_IMAGE] >= 0 ||
       info->file_max[TGSI_FILE_HW_ATOMIC] >= 0 || info->writes_memory)
      return NULL;
   if (src_nir) {
      if (!fp_jit_nir_outputs(src_nir, &depth_output, nir_color_output, &sample_mask_output))
         return NULL;
      color_output = nir_color_output;
   } else if (!fp_jit_shader_ok(info)) {
      return NULL;
   }
   /* gallivm (and LLVM) initialized here, at the process's first compilation */
   LLVMContextRef llvm_context = fp_llvm_context(fp);
   if (!llvm_context)
      return NULL;
   struct fp_jit_variant *v = CALLOC_STRUCT(fp_jit_variant);
   if (!v)
      return NULL;
   v->quads = fp_jit_quads_a_call(fp);

   /* tgsi_to_nir takes the NIR options and the final passes from the
    * screen: give it gallivm's (the screen's own are for st's NIR-to-TGSI
    * and must not change), on a copy so every cap it reads is ours. */
   nir_shader *nir;
   if (src_nir) {
      nir = nir_shader_clone(NULL, src_nir);
      fp_jit_prepare_nir(nir);
   } else {
      struct fp_screen jit_screen = *fp_screen(fp->pipe.screen);
      jit_screen.base.get_compiler_options = fp_jit_compiler_options;
      jit_screen.base.finalize_nir = fp_jit_finalize_nir;
      nir = tgsi_to_nir(tokens, &jit_screen.base, false);
   }
   if (!nir) {
      FREE(v);
      return NULL;
   }

   /* Mesa's on-disk cache: a hit skips LLVM's code generation (the IR is
    * still built, as in llvmpipe); gallivm frees the cached data. */
   struct disk_cache *cache = fp_screen_disk_cache(fp_screen(fp->pipe.screen));
   struct lp_cached_code cached = { 0 };
   unsigned char key[CACHE_KEY_SIZE];
   if (cache) {
      fp_jit_cache_key(tokens, src_nir, depth_output, color_output, num_color_outputs,
                       v->quads, key, cache);
      size_t size = 0;
      cached.data = disk_cache_get(cache, key, &size);
      cached.data_size = cached.data ? size : 0;
      v->cache_hit = cached.data != NULL;
   }

   struct lp_build_sampler_soa *sampler = fp_jit_sampler_create(info, nir);
   v->gallivm = sampler ? gallivm_create("fixpipe_fs", llvm_context, &cached) : NULL;
   if (!v->gallivm) {
      free(cached.data);
      FREE(sampler);
      ralloc_free(nir);
      FREE(v);
      return NULL;
   }
   LLVMValueRef func = fp_build_fs(v->gallivm, nir, info, sampler, depth_output, color_output,
                                   num_color_outputs, sample_mask_output, v->quads);
   v->num_gather_units = fp_jit_sampler_gather_units(sampler, v->gather_units);
   gallivm_compile_module(v->gallivm);
   v->func = (fp_jit_fs_func)gallivm_jit_function(v->gallivm, func);
   if (cache && v->func && !v->cache_hit && cached.data_size && !cached.dont_cache)
      disk_cache_put(cache, key, cached.data, cached.data_size, NULL);
   gallivm_free_ir(v->gallivm);
   FREE(sampler);
   ralloc_free(nir);
   v->compile_ms = (double)(os_time_get_nano() - start) / 1e6;
   if (!v->func) {
      fp_jit_fs_destroy(v);
      return NULL;
   }
   return v;
}

void fp_jit_fs_destroy(struct fp_jit_variant *v)
{
   if (!v)
      return;
   if (v->gallivm)
      gallivm_destroy(v->gallivm);
   FREE(v);
}
