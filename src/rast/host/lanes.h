/*
 * The model's datapath on lanes: the quad's four pixels at once through
 * the same data paths as the scalar code (src/fixed/dfx_lanes.h).  The
 * functions are compiled once per instruction set (-DLANES_SUFFIX=_avx2
 * with -mavx2, _sse2 with the baseline, _avx512 with AVX-512 and two quads
 * a vector for the pair functions) and rast_lanes() picks one set per
 * process from the CPU.  The scalar functions stay the reference
 * (RAST_OPT_SCALAR); tests hold both sets to them bit for bit.
 */
#ifndef FIXPIPE_LANES_H
#define FIXPIPE_LANES_H

#include <stdint.h>
#include "rast/rast.h"
#include "rast/tex/tex.h"

struct rast_front;
struct rast_cbuf_plan;

/* The 8-bit colour stage of the quads of a group in `which` (bit i: q[i])
 * on one vector of sixteen lanes (backend_lanes.c): quad i at (q[i].x,
 * q[i].y), its pixels in bits 4i to 4i + 3 of `masks`, its colour
 * out[i].color[p->src].  Every quad in `which` has its four pixels in the
 * framebuffer (c8_lanes.h's c8_lanes_ok). */
typedef void (*rast_c8_group_fn)(const struct rast_cbuf_plan *p, const struct rast_quad *q,
                                 const struct rast_shaded_quad *out, unsigned which,
                                 unsigned masks);

/* The early depth test of a group's n quads (backend_lanes.c) where the
 * state is depth only, on a 24-bit buffer in the low bits of each word
 * (RAST_ZF_U24LO), with zconv_mul's conversion: each lane a pixel's clamp,
 * conversion, comparison and write as the per-quad functions do them.
 * `covered`: the quads' masks, bits 4i to 4i + 3 for q[i]; returns those
 * that pass.  The quads lie apart, each with its four pixels in the target
 * (backend.c's zgroup_ok). */
struct rast_backend;
typedef unsigned (*rast_zgroup_fn)(const struct rast_backend *be, const struct rast_quad *q,
                                   unsigned n, unsigned covered);

/* The PERSPECTIVE components a primitive can have (front.h's FR_MAX_COMP). */
#define RAST_PLANES_MAX (RAST_MAX_VARYINGS * 4)

struct rast_lanes {
   const char *isa;                       /* "avx512", "avx2", "sse2" */
   /* The perspective division of a quad in dfx24 (W = 19) from the
    * numerators' registers (fr->tex.an, bn: the quad's left pixels), which
    * the caller then moves on; the COLOR components of the wide profile
    * stay scalar. */
   void (*persp_dfx19)(struct rast_front *fr, struct rast_quad *q);
   /* The same, optimistic (the skips taken), for that quad and the next
    * one on the row together: their planes at the component offsets from
    * in0 and in1 (rast_quad.in's layout).  The caller moves the registers
    * on by one quad after each. */
   void (*persp2_dfx19)(struct rast_front *fr, float *in0, float *in1);
   /* The same for four quads of a row, two vectors of two (the 512-bit
    * set only; NULL elsewhere): their step-by-step operations overlap
    * where one vector leaves the processor waiting on the division's long
    * chain of dependent operations. */
   void (*persp4_dfx19)(struct rast_front *fr, float *const in[4]);
   /* The same for the last three quads of a row in one vector of binary32
    * lanes (the 512-bit set only, fixed/dfx_lanes32.h), where
    * RAST_OPT_NOF32 is not set; false, with nothing written, where the
    * caller must divide them another way (a range event, or not set). */
   bool (*persp3_dfx19)(struct rast_front *fr, float *const in[3]);
   /* Four quads from recorded numerators (as persp_group_dfx19's) on
    * binary32 lanes, for interp_axes.c's tables: false where a lane had a
    * range event or RAST_OPT_NOF32 is set; nothing counted either way (the
    * pixels count when they are drawn).  NULL but with the 512-bit set. */
   bool (*persp4_probe_dfx19)(struct rast_front *fr, float *const in[4],
                              const int64_t (*num)[4]);
   /* The same, optimistic, for n quads (1 to FR_AHEAD_MAX) of one
    * primitive wherever they lie on its rows, from the numerators the span
    * processor recorded for each (num[k]: a at the left pixels of both
    * scan lines, then b): a group of quads the shader takes together is
    * divided together, four to a call where the set has persp4. */
   void (*persp_group_dfx19)(struct rast_front *fr, float *const in[],
                             const int64_t (*num)[4], unsigned n);
   /* A primitive's n planes (plane 0 from the three vertices' value 0,
    * plane j from their value p0 + j - 1) as the registers' values, lv[j]:
    * v0, Δ1, Δ2; and recip(det·2^-k).  False, with nothing written, where
    * an operation had a range event or a value is not finite (the scalar
    * set-up then counts them). */
   bool (*planes_dfx19)(const float *const vtx[3], unsigned p0, unsigned n, int64_t det,
                        unsigned k, double (*lv)[3], double *lrdet);
   /* The texture unit's quad in dfx24 for a 2-D unit (2-D, 2-D array,
    * rectangle), specialised for the unit's state; `nolod`: the one that
    * leaves out the LOD (tex_unit_lod_unused); `noskip`: the one that
    * computes every quad with its range events handled at each operation
    * (not optimistically, dfx_lanes.h).
    * `pair`: the function for two quads of that unit in one call, their
    * operations side by side, or NULL where the state has none (then the
    * quad function twice); `four`: the function for four quads, two
    * vectors of pairs step by step (the 512-bit set), or NULL (then the
    * pair function twice). */
   tex_quad_fn (*tex_dfx19_2d)(const struct tex_unit *u, bool noskip, bool nolod,
                               tex_quad2_fn *pair, tex_quad4_fn *four);
   /* the most quads tex_dfx19_2d's functions take in one call: 4 where
    * it has four-quad functions, else 2 */
   unsigned tex_group;
   /* The colour stage of a group for an 8-bit layout: the affine blend
    * (`blend`, rast_cbuf_plan.affine) or the plain store of every channel;
    * NULL for other layouts, and outside the 512-bit set (sixteen lanes
    * there are as many vectors as the four quads' own). */
   rast_c8_group_fn (*c8_group)(enum rast_color_layout layout, bool blend);
   /* The early depth test of a group for a depth func, writing or not;
    * NULL outside the 512-bit set. */
   rast_zgroup_fn (*zgroup)(enum rast_func func, bool write);
};

#define LANES_GLUE2(a, b) a##b
#define LANES_GLUE(a, b) LANES_GLUE2(a, b)
#define LANES_FN(name) LANES_GLUE(name, LANES_SUFFIX)

extern const struct rast_lanes rast_lanes_avx512, rast_lanes_avx2, rast_lanes_sse2;

/* Whether this CPU runs the AVX-512 set. */
bool rast_lanes_have_avx512(void);
/* The set for this CPU: AVX-512 where it has it, else AVX2 where it has it. */
const struct rast_lanes *rast_lanes(void);
/* Another set from now on (tests: every set against the scalar path). */
void rast_lanes_set(const struct rast_lanes *set);

#endif
