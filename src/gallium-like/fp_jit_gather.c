/*
 * The texture unit's gather in compiled code: tex_fast.c's footprint
 * (dfx24 at the seed's width) and its texel reads of the 4-byte layouts,
 * emitted as vector code on every lane of a call, so that a shader that
 * gathers (a polar EWA upscaler: 27 gathers a pixel) does not call into C
 * for each.  One lane reads like footprint() and decode_byte() for one
 * pixel: the same integer operations on the register's sign, location and
 * mantissa (dfx_ops.h), in the same order.
 *
 * The copy covers what such content uses: 2-D and rectangle views clamped
 * to their edges, gathers that raise no range event.  Everything else, and
 * any call in which one lane would raise an event (a coordinate outside
 * the register's range, a product flushed to zero, NaN), goes to the C
 * glue (fp_tgsi_gather_quads), which gives the same bits and counts the
 * events.  The unit's registers (tex_unit_gather_regs) are filled before
 * a call by the driver (fp_tgsi_sampler_jit_prepare), so which calls take
 * the C glue depends on their coordinates alone.  FIXPIPE_DEBUG=nojitgather
 * sends every call there; tests/e2e/jit-identity.sh holds the two to the
 * same bytes and the same counts.
 *
 * The texel reads take a row's two texels as one 8-byte word at column
 * min(x0, w - 2) (x1 is x0 + 1, or x0 at an edge), half the elements of
 * the instruction set's gathers.  The emitter (fp_jit_sample.c) keeps what
 * it has computed for the gathers after it: the columns of one coordinate
 * and offset, the rows likewise, the texel words of one footprint.
 */
#include <stddef.h>
#include <stdio.h>

#include "gallivm/lp_bld_const.h"
#include "gallivm/lp_bld_gather.h"
#include "gallivm/lp_bld_init.h"
#include "gallivm/lp_bld_intr.h"
#include "gallivm/lp_bld_pack.h"
#include "gallivm/lp_bld_swizzle.h"
#include "gallivm/lp_bld_type.h"

#include "fp_jit.h"
#include "rast/tex/tex.h"

/* The lanes of a call and the registers' address. */
struct fpg {
   struct gallivm_state *g;
   LLVMBuilderRef b;
   unsigned n;                 /* lanes */
   struct lp_type it;          /* n x i32 */
   LLVMTypeRef i32, ivec;
   LLVMValueRef regs;          /* i8 *: the unit's struct tex_gather_regs */
};

/* A dfx24 value on every lane. */
struct dfxv {
   LLVMValueRef s, l, m;
};

static LLVMValueRef K(const struct fpg *c, int64_t v)
{
   return lp_build_const_int_vec(c->g, c->it, v);
}

static LLVMValueRef splat(const struct fpg *c, LLVMValueRef scalar)
{
   return lp_build_broadcast(c->g, LLVMVectorType(LLVMTypeOf(scalar), c->n), scalar);
}

/* A word of the registers, at byte `off`, as a scalar. */
static LLVMValueRef word(const struct fpg *c, size_t off, LLVMTypeRef type)
{
   return fp_jit_load(c->g, c->regs, off, type);
}

static LLVMValueRef reg(const struct fpg *c, size_t off)
{
   return splat(c, word(c, off, c->i32));
}

static struct dfxv reg_dfx(const struct fpg *c, size_t off)
{
   struct dfxv r = { reg(c, off), reg(c, off + 4), reg(c, off + 8) };
   return r;
}

#define R(member) offsetof(struct tex_gather_regs, member)

static LLVMValueRef sel(const struct fpg *c, LLVMValueRef cond, LLVMValueRef a, LLVMValueRef b)
{
   return LLVMBuildSelect(c->b, cond, a, b, "");
}

static struct dfxv sel_dfx(const struct fpg *c, LLVMValueRef cond, struct dfxv a, struct dfxv b)
{
   struct dfxv r = { sel(c, cond, a.s, b.s), sel(c, cond, a.l, b.l), sel(c, cond, a.m, b.m) };
   return r;
}

static LLVMValueRef cmp(const struct fpg *c, LLVMIntPredicate p, LLVMValueRef a, LLVMValueRef b)
{
   return LLVMBuildICmp(c->b, p, a, b, "");
}

static LLVMValueRef zext(const struct fpg *c, LLVMValueRef cond)
{
   return LLVMBuildZExt(c->b, cond, c->ivec, "");
}

/* tex_fcoord: binary32 to the register, toward -inf, for a normal number
 * whose leading digit is a register digit; zero to zero.  *ok is false on
 * the lanes that take tex_ns_coord in C (tiny, huge, inf, NaN). */
static struct dfxv coord(const struct fpg *c, LLVMValueRef v, LLVMValueRef *ok)
{
   LLVMBuilderRef b = c->b;
   LLVMValueRef bits = LLVMBuildBitCast(b, v, c->ivec, "");
   LLVMValueRef be = LLVMBuildAnd(b, LLVMBuildLShr(b, bits, K(c, 23), ""), K(c, 0xff), "");
   LLVMValueRef l = LLVMBuildAShr(b, LLVMBuildSub(b, be, K(c, 95), ""), K(c, 2), "");
   LLVMValueRef m24 = LLVMBuildOr(b, LLVMBuildAnd(b, bits, K(c, 0x7fffff), ""), K(c, 0x800000), "");
   /* the mantissa's last bit is 2^(4L - 47): drop 5 to 8 bits (masked to
    * a defined shift on the lanes that fall back) */
   LLVMValueRef sh = LLVMBuildSub(b, LLVMBuildAdd(b, LLVMBuildShl(b, l, K(c, 2), ""), K(c, 103), ""),
                                  be, "");
   sh = LLVMBuildAnd(b, sh, K(c, 31), "");
   LLVMValueRef neg = LLVMBuildLShr(b, bits, K(c, 31), "");
   LLVMValueRef m = LLVMBuildLShr(b, m24, sh, "");
   LLVMValueRef rest = LLVMBuildAnd(b, m24, LLVMBuildSub(b, LLVMBuildShl(b, K(c, 1), sh, ""), K(c, 1), ""), "");
   LLVMValueRef up = LLVMBuildAnd(b, neg, zext(c, cmp(c, LLVMIntNE, rest, K(c, 0))), "");
   m = LLVMBuildAdd(b, m, up, "");
   LLVMValueRef carry = cmp(c, LLVMIntNE, LLVMBuildLShr(b, m, K(c, DFX_MANT_BITS_SEED), ""), K(c, 0));
   m = sel(c, carry, LLVMBuildLShr(b, m, K(c, 4), ""), m);
   l = LLVMBuildAdd(b, l, zext(c, carry), "");
   LLVMValueRef zero = cmp(c, LLVMIntEQ, LLVMBuildAnd(b, bits, K(c, 0x7fffffff), ""), K(c, 0));
   *ok = LLVMBuildOr(b, zero,
                     LLVMBuildAnd(b, LLVMBuildAnd(b, cmp(c, LLVMIntSGE, be, K(c, 95)),
                                                  cmp(c, LLVMIntSLE, l, K(c, DFX_L_MAX)), ""),
                                  cmp(c, LLVMIntNE, be, K(c, 0xff)), ""), "");
   struct dfxv r = { sel(c, zero, K(c, 0), neg), sel(c, zero, K(c, 0), l), sel(c, zero, K(c, 0), m) };
   return r;
}

/* tex_ns_cmp's order as one signed word: normalized values order by
 * location, then mantissa; zero of either sign is 0. */
static LLVMValueRef key(const struct fpg *c, struct dfxv a)
{
   LLVMBuilderRef b = c->b;
   LLVMValueRef mag = LLVMBuildOr(b, LLVMBuildShl(b, a.l, K(c, DFX_MANT_BITS_SEED), ""), a.m, "");
   LLVMValueRef v = sel(c, cmp(c, LLVMIntNE, a.s, K(c, 0)), LLVMBuildNeg(b, mag, ""), mag);
   return sel(c, cmp(c, LLVMIntEQ, a.m, K(c, 0)), K(c, 0), v);
}

/* tex_ns_clamp, the bounds' keys from the registers. */
static struct dfxv clamp(const struct fpg *c, struct dfxv a, struct dfxv lo, LLVMValueRef lo_key,
                         struct dfxv hi, LLVMValueRef hi_key)
{
   LLVMValueRef k = key(c, a);
   struct dfxv r = sel_dfx(c, cmp(c, LLVMIntSGT, k, hi_key), hi, a);
   return sel_dfx(c, cmp(c, LLVMIntSLT, k, lo_key), lo, r);
}

/* dfx_mul_i (Fig. 9); *ok false where dfx_finish_i counts an event.
 * The 38-bit product P of two 19-bit mantissas in 32-bit lanes: with the
 * scale's mantissa split at bit 10, T = a*hi + (a*lo >> 10) is P >> 10
 * exactly (the bits dropped lie below every bit kept), so P >> 15, P >> 19
 * and P >> 34 are T >> 5, T >> 9 and T >> 24. */
static struct dfxv mul(const struct fpg *c, struct dfxv a, struct dfxv s, LLVMValueRef *ok)
{
   LLVMBuilderRef b = c->b;
   const unsigned w = DFX_MANT_BITS_SEED;
   _Static_assert(DFX_MANT_BITS_SEED == 19, "the split product is for 19-bit mantissas");
   LLVMValueRef hi = LLVMBuildLShr(b, s.m, K(c, 10), "");
   LLVMValueRef lo = LLVMBuildAnd(b, s.m, K(c, 0x3ff), "");
   LLVMValueRef T = LLVMBuildAdd(b, LLVMBuildMul(b, a.m, hi, ""),
                                 LLVMBuildLShr(b, LLVMBuildMul(b, a.m, lo, ""), K(c, 10), ""), "");
   LLVMValueRef top0 = cmp(c, LLVMIntEQ, LLVMBuildLShr(b, T, K(c, 2 * w - 4 - 10), ""), K(c, 0));
   LLVMValueRef m = sel(c, top0, LLVMBuildLShr(b, T, K(c, w - 4 - 10), ""),
                        LLVMBuildLShr(b, T, K(c, w - 10), ""));
   LLVMValueRef l = LLVMBuildSub(b, LLVMBuildSub(b, LLVMBuildAdd(b, a.l, s.l, ""), K(c, 7), ""),
                                 zext(c, top0), "");
   LLVMValueRef zero = LLVMBuildOr(b, cmp(c, LLVMIntEQ, a.m, K(c, 0)), cmp(c, LLVMIntEQ, s.m, K(c, 0)), "");
   LLVMValueRef in = LLVMBuildAnd(b, cmp(c, LLVMIntSGE, l, K(c, 0)), cmp(c, LLVMIntSLE, l, K(c, DFX_L_MAX)), "");
   *ok = LLVMBuildAnd(b, *ok, LLVMBuildOr(b, zero, in, ""), "");
   struct dfxv r = { sel(c, zero, K(c, 0), LLVMBuildXor(b, a.s, s.s, "")), sel(c, zero, K(c, 0), l),
                     sel(c, zero, K(c, 0), m) };
   return r;
}

/* dfx_add_i with a nonzero second operand; *ok as mul's. */
static struct dfxv add(const struct fpg *c, struct dfxv a, struct dfxv o, LLVMValueRef *ok)
{
   LLVMBuilderRef b = c->b;
   const unsigned w = DFX_MANT_BITS_SEED;
   /* order by magnitude */
   LLVMValueRef swap = LLVMBuildOr(b, cmp(c, LLVMIntSGT, o.l, a.l),
                                   LLVMBuildAnd(b, cmp(c, LLVMIntEQ, o.l, a.l),
                                                cmp(c, LLVMIntUGT, o.m, a.m), ""), "");
   struct dfxv big = sel_dfx(c, swap, o, a), small = sel_dfx(c, swap, a, o);
   LLVMValueRef d = LLVMBuildSub(b, big.l, small.l, "");
   LLVMValueRef far = cmp(c, LLVMIntSGE, d, K(c, 5));
   /* align by whole digits, one guard digit below the mantissa */
   LLVMValueRef dsh = LLVMBuildShl(b, sel(c, far, K(c, 4), d), K(c, 2), "");
   LLVMValueRef A = LLVMBuildShl(b, big.m, K(c, 4), "");
   LLVMValueRef B = LLVMBuildLShr(b, LLVMBuildShl(b, small.m, K(c, 4), ""), dsh, "");
   LLVMValueRef S = sel(c, cmp(c, LLVMIntEQ, big.s, small.s), LLVMBuildAdd(b, A, B, ""),
                        LLVMBuildSub(b, A, B, ""));
   LLVMValueRef cancel = cmp(c, LLVMIntEQ, S, K(c, 0));
   LLVMValueRef carry = cmp(c, LLVMIntNE, LLVMBuildLShr(b, S, K(c, w + 4), ""), K(c, 0));
   S = sel(c, carry, LLVMBuildLShr(b, S, K(c, 4), ""), S);
   LLVMValueRef l = LLVMBuildAdd(b, big.l, zext(c, carry), "");
   /* renormalize by the leading-zero digits at once */
   /* S's bit length from its binary32 exponent (S < 2^24 converts
    * exactly; S = 0 has "length" -126 and is the cancellation above) */
   LLVMTypeRef fvec = LLVMVectorType(LLVMFloatTypeInContext(c->g->context), c->n);
   LLVMValueRef bl = LLVMBuildSub(b, LLVMBuildLShr(b, LLVMBuildBitCast(b, LLVMBuildSIToFP(b, S, fvec, ""),
                                                                       c->ivec, ""), K(c, 23), ""),
                                  K(c, 126), "");
   LLVMValueRef small_s = cmp(c, LLVMIntSLE, bl, K(c, w));
   LLVMValueRef z = sel(c, LLVMBuildAnd(b, small_s, LLVMBuildNot(b, cancel, ""), ""),
                        LLVMBuildLShr(b, LLVMBuildSub(b, K(c, w + 4), bl, ""), K(c, 2), ""), K(c, 0));
   S = LLVMBuildShl(b, S, LLVMBuildShl(b, z, K(c, 2), ""), "");
   l = LLVMBuildSub(b, l, z, "");
   LLVMValueRef in = LLVMBuildAnd(b, cmp(c, LLVMIntSGE, l, K(c, 0)), cmp(c, LLVMIntSLE, l, K(c, DFX_L_MAX)), "");
   struct dfxv sum = { big.s, l, LLVMBuildLShr(b, S, K(c, 4), "") };
   const struct dfxv zero = { K(c, 0), K(c, 0), K(c, 0) };
   struct dfxv r = sel_dfx(c, cancel, zero, sum);
   r = sel_dfx(c, far, big, r);
   LLVMValueRef a0 = cmp(c, LLVMIntEQ, a.m, K(c, 0));
   r = sel_dfx(c, a0, o, r);
   *ok = LLVMBuildAnd(b, *ok, LLVMBuildOr(b, LLVMBuildOr(b, a0, far, ""), LLVMBuildOr(b, cancel, in, ""), ""), "");
   return r;
}

/* tex_ffloor's integer part with TEX_WEIGHT_BITS of fraction (the weight
 * a gather does not use).  The clamp before it keeps the value within
 * [0, 2^20] (tex_unit_gather_regs): the shifts stay inside 32 bits and the
 * integer never saturates. */
static LLVMValueRef floor_int(const struct fpg *c, struct dfxv a)
{
   LLVMBuilderRef b = c->b;
   /* dfx_exp_i + the fraction's bits */
   LLVMValueRef sh = LLVMBuildAdd(b, LLVMBuildShl(b, a.l, K(c, 2), ""),
                                  K(c, 4 - DFX_MANT_BITS_SEED - 32 + TEX_WEIGHT_BITS), "");
   LLVMValueRef left = cmp(c, LLVMIntSGE, sh, K(c, 0));
   LLVMValueRef ls = sel(c, left, sh, K(c, 0));
   LLVMValueRef rs = sel(c, left, K(c, 0), LLVMBuildNeg(b, sh, ""));
   rs = sel(c, cmp(c, LLVMIntSGT, rs, K(c, 31)), K(c, 31), rs);   /* m >> 31 is m >> 39: 0 */
   LLVMValueRef down = LLVMBuildLShr(b, a.m, rs, "");
   LLVMValueRef up = LLVMBuildLShr(b, LLVMBuildAdd(b, a.m,
                                                   LLVMBuildSub(b, LLVMBuildShl(b, K(c, 1), rs, ""), K(c, 1), ""),
                                                   ""), rs, "");
   LLVMValueRef neg = cmp(c, LLVMIntNE, a.s, K(c, 0));
   LLVMValueRef mag = sel(c, left, LLVMBuildShl(b, a.m, ls, ""), sel(c, neg, up, down));
   LLVMValueRef t = sel(c, neg, LLVMBuildNeg(b, mag, ""), mag);
   return LLVMBuildAShr(b, t, K(c, TEX_WEIGHT_BITS), "");
}

static LLVMValueRef clampi(const struct fpg *c, LLVMValueRef i, LLVMValueRef hi)
{
   i = sel(c, cmp(c, LLVMIntSLT, i, K(c, 0)), K(c, 0), i);
   return sel(c, cmp(c, LLVMIntSGT, i, hi), hi, i);
}

/* One axis of footprint() on CLAMP_TO_EDGE: its two texels. */
static void axis(const struct fpg *c, unsigned a, LLVMValueRef coordv, LLVMValueRef *i0,
                 LLVMValueRef *i1, LLVMValueRef *ok)
{
   LLVMValueRef lane_ok;
   struct dfxv v = coord(c, coordv, &lane_ok);
   v = clamp(c, v, reg_dfx(c, R(lo[a])), reg(c, R(lo_key[a])), reg_dfx(c, R(hi[a])),
             reg(c, R(hi_key[a])));
   v = mul(c, v, reg_dfx(c, R(scale[a])), &lane_ok);
   v = add(c, v, reg_dfx(c, R(neg_half)), &lane_ok);
   LLVMValueRef i = floor_int(c, v);
   LLVMValueRef last = LLVMBuildSub(c->b, reg(c, R(size[a])), K(c, 1), "");
   *i0 = clampi(c, i, last);
   *i1 = clampi(c, LLVMBuildAdd(c->b, i, K(c, 1), ""), last);
   *ok = *ok ? LLVMBuildAnd(c->b, *ok, lane_ok, "") : lane_ok;
}

/* All lanes of an i1 vector set. */
static LLVMValueRef all(const struct fpg *c, LLVMValueRef v)
{
   LLVMTypeRef iN = LLVMIntTypeInContext(c->g->context, c->n);
   LLVMValueRef bits = LLVMBuildBitCast(c->b, v, iN, "");
   return LLVMBuildICmp(c->b, LLVMIntEQ, bits, LLVMConstAllOnes(iN), "");
}

static void init(struct fpg *c, struct gallivm_state *gallivm, unsigned n, LLVMValueRef regs)
{
   c->g = gallivm;
   c->b = gallivm->builder;
   c->n = n;
   c->it = lp_type_int_vec(32, 32 * n);
   c->i32 = LLVMInt32TypeInContext(gallivm->context);
   c->ivec = lp_build_vec_type(gallivm, c->it);
   c->regs = regs;
}

LLVMValueRef fp_jit_gather_axis(struct gallivm_state *gallivm, LLVMValueRef regs, unsigned n,
                                unsigned a, LLVMValueRef coord, int offset, LLVMValueRef i[2])
{
   struct fpg c;
   init(&c, gallivm, n, regs);
   if (offset) {
      /* fp_gather_offsets: the offset in coordinate units, added in
       * binary32 (the glue adds 0 to the other axis: the same register) */
      LLVMTypeRef f32 = LLVMFloatTypeInContext(gallivm->context);
      LLVMValueRef k = LLVMBuildFDiv(c.b, LLVMConstReal(f32, (double)offset),
                                     word(&c, R(offset_unit[a]), f32), "");
      coord = LLVMBuildFAdd(c.b, coord, splat(&c, k), "");
   }
   LLVMValueRef ok = NULL;
   axis(&c, a, coord, &i[0], &i[1], &ok);
   return ok;
}

LLVMValueRef fp_jit_gather_all(struct gallivm_state *gallivm, unsigned n, LLVMValueRef a,
                               LLVMValueRef b)
{
   struct fpg c;
   init(&c, gallivm, n, NULL);
   return all(&c, LLVMBuildAnd(c.b, a, b, ""));
}

/* The two texel words at byte offsets `off` from `data` as one 64-bit
 * word a lane (the first in its low half), through LLVM's gather of
 * eight lanes at a time (the instruction set's). */
static LLVMValueRef gather_pairs(const struct fpg *c, LLVMValueRef data, LLVMValueRef off)
{
   LLVMBuilderRef b = c->b;
   LLVMContextRef lc = c->g->context;
   LLVMTypeRef i8 = LLVMInt8TypeInContext(lc), i64 = LLVMInt64TypeInContext(lc);
   const unsigned per = c->n < 8 ? c->n : 8, parts = c->n / per;
   LLVMTypeRef v64 = LLVMVectorType(i64, per);
   LLVMTypeRef pv = LLVMVectorType(LLVMPointerType(i64, 0), per);
   char name[64];
   snprintf(name, sizeof(name), "llvm.masked.gather.v%ui64.v%up0i64", per, per);
   LLVMValueRef part[LP_MAX_VECTOR_LENGTH / 4];
   for (unsigned i = 0; i < parts; i++) {
      LLVMValueRef o = parts > 1 ? lp_build_extract_range(c->g, off, per * i, per) : off;
      LLVMValueRef p = LLVMBuildGEP2(b, i8, data, &o, 1, "");
      p = LLVMBuildBitCast(b, p, pv, "");
      LLVMValueRef mask = LLVMConstAllOnes(LLVMVectorType(LLVMInt1TypeInContext(lc), per));
      LLVMValueRef args[4] = { p, lp_build_const_int32(c->g, 4), mask, LLVMGetUndef(v64) };
      part[i] = lp_build_intrinsic(b, name, v64, args, 4, 0);
   }
   return parts > 1 ? lp_build_concat(c->g, part, lp_type_int_vec(64, 64 * per), parts) : part[0];
}

void fp_jit_gather_read(struct gallivm_state *gallivm, LLVMValueRef regs, unsigned n,
                        unsigned comp, LLVMValueRef xy[2][2], const LLVMValueRef *words_in,
                        LLVMValueRef words[4], LLVMValueRef texel[4])
{
   struct fpg c;
   init(&c, gallivm, n, regs);
   LLVMBuilderRef b = c.b;
   LLVMTypeRef f32 = LLVMFloatTypeInContext(gallivm->context);
   LLVMTypeRef fvec = LLVMVectorType(f32, n);
   LLVMValueRef data = word(&c, R(data), LLVMPointerType(LLVMInt8TypeInContext(gallivm->context), 0));
   LLVMValueRef stride = reg(&c, R(row_stride));
   LLVMValueRef shift = word(&c, R(shift[0]) + 4 * (comp & 3), c.i32);
   LLVMValueRef constant = word(&c, R(constant[0]) + 4 * (comp & 3), f32);
   LLVMValueRef is_const = LLVMBuildICmp(b, LLVMIntSLT, shift, lp_build_const_int32(gallivm, 0), "");
   LLVMValueRef shv = splat(&c, LLVMBuildAnd(b, shift, lp_build_const_int32(gallivm, 31), ""));
   LLVMValueRef kv = splat(&c, constant);
   /* GL's order: (i0, j1), (i1, j1), (i1, j0), (i0, j0).  Each row's two
    * texels are the two words at the column xl = min(x0, w - 2) (views of
    * two columns or more, tex_unit_gather_regs): x0 and x1 are xl or the
    * next column, x1 = x0 at the edges */
   static const unsigned xi[4] = { 0, 1, 1, 0 }, yi[4] = { 1, 1, 0, 0 };
   LLVMValueRef xl = xy[0][0], pair[2] = { NULL, NULL };
   if (!words_in) {
      LLVMValueRef w2 = LLVMBuildSub(b, reg(&c, R(size[0])), K(&c, 2), "");
      xl = LLVMBuildSelect(b, LLVMBuildICmp(b, LLVMIntSGT, xl, w2, ""), w2, xl, "");
      for (unsigned r = 0; r < 2; r++) {
         LLVMValueRef off = LLVMBuildAdd(b, LLVMBuildMul(b, xy[1][r], stride, ""),
                                         LLVMBuildShl(b, xl, K(&c, 2), ""), "");
         pair[r] = gather_pairs(&c, data, off);
      }
   }
   for (unsigned k = 0; k < 4; k++) {
      LLVMValueRef w = words_in ? words_in[k] : NULL;
      if (!w) {
         LLVMValueRef lo = LLVMBuildTrunc(b, pair[yi[k]], c.ivec, "");
         LLVMValueRef hi = LLVMBuildTrunc(b, LLVMBuildLShr(b, pair[yi[k]],
                                                           lp_build_const_int_vec(gallivm, lp_type_int_vec(64, 64 * n), 32), ""),
                                          c.ivec, "");
         w = LLVMBuildSelect(b, LLVMBuildICmp(b, LLVMIntEQ, xy[0][xi[k]], xl, ""), lo, hi, "");
      }
      words[k] = w;
      /* decode_byte: the byte to binary32, times 1/255 */
      LLVMValueRef v = LLVMBuildAnd(b, LLVMBuildLShr(b, w, shv, ""), K(&c, 0xff), "");
      v = LLVMBuildFMul(b, LLVMBuildSIToFP(b, v, fvec, ""),
                        lp_build_const_vec(gallivm, lp_type_float_vec(32, 32 * n), 1.0f / 255.0f), "");
      texel[k] = LLVMBuildSelect(b, is_const, kv, v, "");
   }
}
