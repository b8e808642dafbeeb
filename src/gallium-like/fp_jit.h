/*
 * Compiled fragment shaders: gallivm (LLVM) code for one shader, run on the
 * model's 2x2 quads in place of tgsi_exec.  The shader ALU is not modeled
 * hardware, so it runs as fast as the host allows; everything the seeds
 * model stays the model's: the quad's inputs are the model's interpolated
 * registers, and every texture instruction calls the modeled texture unit
 * (fp_jit_sample.c) with the same operands tgsi_exec would give it.
 *
 * The compiled code depends on the shader alone: constants, samplers and
 * views are read through fp_jit_context at run time, so there is one
 * variant per shader and no state key.
 */
#ifndef FP_JIT_H
#define FP_JIT_H

#include <stdbool.h>
#include <stdint.h>

#include "gallivm/lp_bld.h"
struct gallivm_state;   /* lp_bld_jit_types.h does not declare it */
#include "gallivm/lp_bld_jit_types.h"
#include "gallivm/lp_bld_limits.h"
#include "rast/rast.h"
#include "rast/tex/tex.h"

struct tgsi_sampler;
struct lp_type;
struct tex_quad;
struct tgsi_shader_info;
struct tgsi_token;
struct gallivm_state;
struct fp_context;

/* What compiled code reads at run time; filled by fp_fs_validate. */
struct fp_jit_context {
   struct lp_jit_buffer constants[LP_MAX_TGSI_CONST_BUFFERS];
   struct tgsi_sampler *sampler;            /* the fragment stage's texture unit glue */
   /* called from compiled code: fp_jit_sample.c */
   void (*sample)(struct tgsi_sampler *s, uint32_t texture, uint32_t sampler, uint32_t key,
                  const float coords[5][RAST_QUAD_SIZE], const float lod[RAST_QUAD_SIZE],
                  float derivs[3][2][RAST_QUAD_SIZE], const int32_t offsets[3][RAST_QUAD_SIZE],
                  float rgba[4][RAST_QUAD_SIZE]);
   void (*size)(struct tgsi_sampler *s, uint32_t texture, int32_t lod, int32_t dims[4]);
   /* plain 2-D samples: the quads laid out by the code, in one call
    * (fp_tgsi_sample_quads: `quads` of them real) */
   void (*sample_quads)(struct tgsi_sampler *s, uint32_t texture, uint32_t sampler,
                        uint32_t control, uint32_t quads, uint32_t max,
                        const struct tex_quad *q, float rgba[][4][RAST_QUAD_SIZE]);
   /* gathers of a 2-D view with constant offsets, the same way
    * (fp_tgsi_gather_quads) */
   void (*gather_quads)(struct tgsi_sampler *s, uint32_t texture, uint32_t sampler,
                        uint32_t comp, int32_t offset_s, int32_t offset_t, uint32_t quads,
                        uint32_t max, const struct tex_quad *q, float rgba[][4][RAST_QUAD_SIZE]);
   /* gathers in the code itself (fp_jit_gather.c): the units' registers
    * by texture index, valid in the binding epoch the context is in; and
    * the quads gathered so, counted with the unit's (fp_sampler.c) */
   const struct fp_jit_gather *gathers;
   const uint64_t *tex_epoch;
   uint64_t *gathered;
   /* the quads a call of the function shades: up to its quads a call, the
    * lanes of the others repeating the first quad's (a quad alone, the
    * last of a primitive) */
   uint32_t quads;
   /* gl_SamplePosition and gl_SampleMaskIn of each sample a quad may be
    * shaded for (rast_quad.sample): the pattern and 1 << k on a
    * multisampled target, the centre and 1 on a single-sampled one */
   float sample_pos[RAST_MSAA_SAMPLES][2];
   uint32_t sample_mask_in[RAST_MSAA_SAMPLES];
};

/* A texture unit's registers for compiled gathers, filled before the
 * compiled code's first call in a binding epoch (fp_tgsi_sampler_jit_prepare):
 * valid where `valid` is set, `epoch` is the context's and `sampler` the
 * instruction's sampler index; the C glue gathers otherwise. */
struct fp_jit_gather {
   uint64_t epoch;
   uint32_t sampler;
   uint32_t valid;
   struct tex_gather_regs regs;
};

/* Quads a call of the compiled code at most: sixteen lanes. */
#define FP_JIT_MAX_QUADS 4
/* (texture, sampler) pairs of gathers in the code a shader at most; a
 * gather beyond them goes through the C glue */
#define FP_JIT_GATHER_UNITS 8

/* The compiled function on its quads a call (their lanes one after the
 * other, quad i from q[i], its outputs to out[i]).  mask: in, the covered
 * pixels (lane = ~0); out, those that survive discard. */
typedef void (*fp_jit_fs_func)(const struct fp_jit_context *ctx, const struct rast_quad *const *q,
                               struct rast_shaded_quad *const *out, int32_t *mask);

struct fp_jit_variant {
   struct gallivm_state *gallivm;
   fp_jit_fs_func func;
   /* the texture and sampler indices of the gathers the code does itself:
    * their registers are filled before a call (fp_fs_shade_n_jit), so that
    * which calls gather in the code depends on the coordinates alone, not
    * on which thread shades a call first */
   uint8_t gather_units[FP_JIT_GATHER_UNITS][2];
   unsigned num_gather_units;
   /* quads a call: 4 (sixteen lanes) for a shader that samples a texture
    * where the texture unit has its four-quad functions, else 2; 1 with
    * noskip */
   unsigned quads;
   double compile_ms;
   bool cache_hit;                  /* code from Mesa's on-disk shader cache */
};

/* Compiles the fragment shader: st's NIR where it came so (nir, with
 * `tokens` the TGSI nir_to_tgsi made of it, whose input registers the code
 * reads), else its TGSI; NULL when gallivm cannot (the caller keeps
 * interpreting it). */
struct nir_shader;
struct fp_jit_variant *fp_jit_fs_compile(struct fp_context *fp, const struct tgsi_token *tokens,
                                         const struct nir_shader *nir,
                                         const struct tgsi_shader_info *info,
                                         int depth_output, const int *color_output,
                                         unsigned num_color_outputs);
void fp_jit_fs_destroy(struct fp_jit_variant *v);
/* st's NIR (made with the screen's options, for nir_to_tgsi) made ready for
 * lp_build_nir_soa, in place: gallivm's options and llvmpipe's finalisation. */
void fp_jit_prepare_nir(struct nir_shader *nir);

/* fp_jit_sample.c: the sampler gallivm calls for every texture instruction,
 * and the C functions its code calls. */
struct lp_build_sampler_soa;
struct lp_build_sampler_soa *fp_jit_sampler_create(const struct tgsi_shader_info *info,
                                                  void *nir_shader);
/* The same for a stage draw compiles (fp_jit_draw.c): every texture
 * instruction calls `stage_sampler`, that stage's glue, through
 * fp_jit_sample(); nir_shader NULL for TGSI. */
struct lp_build_sampler_soa *fp_jit_sampler_create_stage(const struct tgsi_shader_info *info,
                                                        void *nir_shader,
                                                        struct tgsi_sampler *stage_sampler);
/* fp_jit_draw.c: draw builds its compiled shaders' samplers so
 * (mesa/patches/0016) */
struct draw_context;
void fp_jit_draw_samplers(struct draw_context *draw, struct fp_context *fp);
void fp_jit_context_init_sampler(struct fp_jit_context *ctx, struct tgsi_sampler *s);
/* A member at byte `offset` of the struct `base` points to, loaded in
 * compiled code as `type` (fp_jit_context's, a unit's registers). */
LLVMValueRef fp_jit_load(struct gallivm_state *gallivm, LLVMValueRef base, size_t offset,
                         LLVMTypeRef type);
/* The (texture, sampler) pairs the code built so far gathers from itself. */
unsigned fp_jit_sampler_gather_units(const struct lp_build_sampler_soa *sampler,
                                     uint8_t units[FP_JIT_GATHER_UNITS][2]);
/* Quad k's four lanes of a vector of nq quads' lanes (NULL stays NULL),
 * and the vector of nq quads' lanes from each quad's four. */
LLVMValueRef fp_jit_quad_part(struct gallivm_state *gallivm, LLVMValueRef v, unsigned k,
                              unsigned nq);
/* fp_jit_gather.c: the unit's gather on n lanes from the registers at
 * `regs` (an i8 pointer to struct tex_gather_regs): axis a's two texels
 * (the footprint's columns, or rows) from its coordinate moved by a
 * constant texel offset, returning the lanes that raised no range event
 * nor need the C path; whether every lane of both axes did; then channel
 * comp's four texels from the columns xy[0] and rows xy[1], reading their
 * four texel words (to words[4]) unless an earlier gather read them
 * (words_in). */
LLVMValueRef fp_jit_gather_axis(struct gallivm_state *gallivm, LLVMValueRef regs, unsigned n,
                                unsigned a, LLVMValueRef coord, int offset, LLVMValueRef i[2]);
LLVMValueRef fp_jit_gather_all(struct gallivm_state *gallivm, unsigned n, LLVMValueRef a,
                               LLVMValueRef b);
void fp_jit_gather_read(struct gallivm_state *gallivm, LLVMValueRef regs, unsigned n,
                        unsigned comp, LLVMValueRef xy[2][2], const LLVMValueRef *words_in,
                        LLVMValueRef words[4], LLVMValueRef texel[4]);
LLVMValueRef fp_jit_join_quads(struct gallivm_state *gallivm, LLVMValueRef v[],
                               struct lp_type type4, unsigned nq);

/* Quads a fragment shader, vertices a vertex shader, is interpreted for
 * before it is compiled (see docs/jit.md); and, once the process has
 * presented a frame (a real-time program, drawing the same shaders frame
 * after frame), the fewer it is interpreted for then: fp_jit_hot_loop. */
#define FP_JIT_HOT_QUADS 16384
#define FP_JIT_HOT_VERTICES 16384
#define FP_JIT_LOOP_QUADS 1024
#define FP_JIT_LOOP_VERTICES 1024
struct fp_context;
bool fp_jit_hot_loop(const struct fp_context *fp);

#endif
