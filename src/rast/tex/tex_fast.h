/*
 * The texture unit's arithmetic with the number system fixed at compile
 * time: dfx24 (W = 19) through dfx_ops.h's inline data paths, binary32 as
 * plain float operations.  Each function gives the bits and the range
 * events of what the generic path computes through struct numsys
 * (numsys.c) and tex_ns.h, so the fast quad (tex_fast.c) changes no
 * result; tests/unit/test_tex_fast.c holds both paths to that.
 *
 * Range events gather in a struct tex_fst for the quad and join the
 * unit's counters once at its end: the totals are what the table path
 * counts, only added later.
 */
#ifndef FIXPIPE_TEX_FAST_H
#define FIXPIPE_TEX_FAST_H

#include <float.h>
#include <math.h>
#include <string.h>
#include "fixed/dfx_ops.h"
#include "rast/tex/tex_priv.h"

#define TEX_FAST_INLINE static inline __attribute__((always_inline))

enum tex_fk { TEX_FK_DFX19, TEX_FK_FLOAT };

#define TEX_F19 ((struct dfx_format){ DFX_MANT_BITS_SEED })

struct tex_fst {
   struct dfx_stats d;   /* dfx_ops.h's counters */
   struct ns_stats n;    /* float and the generic fall-backs */
};

TEX_FAST_INLINE int tex_fk_ns(const enum tex_fk k)
{
   return k == TEX_FK_DFX19 ? TEX_NS_DFX : TEX_NS_FLOAT;
}

TEX_FAST_INLINE void tex_fst_flush(const struct tex_fst *x, struct ns_stats *st)
{
   st->sat += x->d.sat + x->n.sat;
   st->flush += x->d.flush + x->n.flush;
}

/* numsys.c's f_count without a branch: inf is sat, subnormal is flush. */
TEX_FAST_INLINE float tex_fcount(float r, struct tex_fst *x)
{
   const float a = fabsf(r);
   x->n.sat += a > FLT_MAX;
   x->n.flush += (a < FLT_MIN) & (a != 0.0f);
   return r;
}

TEX_FAST_INLINE ns_val tex_fadd(const enum tex_fk k, ns_val a, ns_val b, struct tex_fst *x)
{
   ns_val r = { .x = 0 };   /* whole union defined: copies stay clean */
   if (k == TEX_FK_DFX19)
      r.d = dfx_add_i(TEX_F19, a.d, b.d, &x->d);
   else
      r.f = tex_fcount(a.f + b.f, x);
   return r;
}

/* dfx.c's dfx_sub is the adder on the negated operand. */
TEX_FAST_INLINE ns_val tex_fsub(const enum tex_fk k, ns_val a, ns_val b, struct tex_fst *x)
{
   ns_val r = { .x = 0 };   /* whole union defined: copies stay clean */
   if (k == TEX_FK_DFX19)
      r.d = dfx_add_i(TEX_F19, a.d, dfx_neg(b.d), &x->d);
   else
      r.f = tex_fcount(a.f - b.f, x);
   return r;
}

TEX_FAST_INLINE ns_val tex_fmul(const enum tex_fk k, ns_val a, ns_val b, struct tex_fst *x)
{
   ns_val r = { .x = 0 };   /* whole union defined: copies stay clean */
   if (k == TEX_FK_DFX19) {
      r.d = dfx_mul_i(TEX_F19, a.d, b.d, &x->d);
   } else {
      r.f = tex_fcount(a.f * b.f, x);
      x->n.flush += (r.f == 0.0f) & (a.f != 0.0f) & (b.f != 0.0f);
   }
   return r;
}

TEX_FAST_INLINE ns_val tex_frecip(const enum tex_fk k, ns_val a, struct tex_fst *x)
{
   ns_val r = { .x = 0 };   /* whole union defined: copies stay clean */
   if (k == TEX_FK_DFX19)
      r.d = dfx_recip_i(TEX_F19, a.d, &x->d);
   else
      r.f = tex_fcount(1.0f / a.f, x);
   return r;
}

/* numsys.c's floor_frac for frac_bits <= TEX_WEIGHT_BITS: floor(a) saturated
 * to int32 (counted, fraction 0 then), the fraction truncated.  dfx24's
 * register shifted by at most 47 + 8 bits fits 64 bits (dfx.c needs 128 for
 * every width and fraction length); binary32's floor is a truncation
 * corrected by one wherever |a| < 2^31 (every integer there is a float). */
TEX_FAST_INLINE int64_t tex_ffloor(const enum tex_fk k, ns_val a, uint32_t *frac,
                                   const unsigned frac_bits, struct tex_fst *x)
{
   if (k == TEX_FK_DFX19) {
      const int sh = dfx_exp_i(TEX_F19, a.d.l) + (int)frac_bits;
      const uint64_t m = a.d.m;
      int64_t t;
      if (!m)
         t = 0;
      else if (sh >= 0)
         t = a.d.s ? -(int64_t)(m << sh) : (int64_t)(m << sh);
      else if (a.d.s)
         t = -(int64_t)((m + ((UINT64_C(1) << -sh) - 1)) >> -sh);
      else
         t = (int64_t)(m >> -sh);
      int64_t ip = t >> frac_bits;   /* arithmetic: floor */
      uint32_t fr = (uint32_t)(t & ((INT64_C(1) << frac_bits) - 1));
      if (ip > INT32_MAX || ip < INT32_MIN) {
         x->n.sat++;
         ip = ip > 0 ? INT32_MAX : INT32_MIN;
         fr = 0;
      }
      *frac = fr;
      return ip;
   }
   const float v = a.f;
   if (fabsf(v) < 2147483648.0f) {
      int64_t i = (int64_t)v;
      if ((float)i > v)
         i--;
      *frac = (uint32_t)(((double)v - (double)i) * (double)(1u << frac_bits));
      return i;
   }
   if (isnan(v)) {
      x->n.sat++;
      *frac = 0;
      return 0;
   }
   const double fl = floor((double)v);
   if (fl > (double)INT32_MAX || fl < (double)INT32_MIN) {
      x->n.sat++;
      *frac = 0;
      return fl > 0 ? INT32_MAX : INT32_MIN;
   }
   *frac = (uint32_t)ldexp((double)v - fl, (int)frac_bits);
   return (int64_t)fl;
}

/* tex_ns_int: the integer through binary32, then into the register; the
 * float's value is an integer below 2^32, so the exact fixed-point input
 * of dfx_ops.h rounds it as dfx_from_double does. */
TEX_FAST_INLINE ns_val tex_fint(const enum tex_fk k, int64_t i, struct tex_fst *x)
{
   ns_val r = { .x = 0 };   /* whole union defined: copies stay clean */
   const float f = (float)i;
   if (k == TEX_FK_DFX19)
      r.d = dfx_from_fixed_i(TEX_F19, (struct fx_format){ 0, 0 }, (int64_t)f, &x->d);
   else
      r.f = f;
   return r;
}

/* tex_ns_coord (round toward -inf) from the float's fields for a normal
 * binary32 whose leading digit is a register digit (L = 0..15): the
 * mantissa drops 5 to 8 bits.  Everything else (zero, subnormal, inf,
 * NaN, out of range, rounding up past L = 15) takes tex_ns_coord itself. */
TEX_FAST_INLINE ns_val tex_fcoord(const struct tex_unit *u, const enum tex_fk k, float v,
                                  struct tex_fst *x)
{
   ns_val r = { .x = 0 };   /* whole union defined: copies stay clean */
   if (k == TEX_FK_FLOAT) {
      r.f = v;
      return r;
   }
   uint32_t bits;
   memcpy(&bits, &v, 4);
   const int be = (int)((bits >> 23) & 0xff);
   const int l = (be - 95) >> 2;          /* frexp's e = be - 126; L = (e + 31) / 4 */
   if (be >= 95 && l <= DFX_L_MAX && be != 0xff) {
      const uint32_t m24 = (bits & 0x7fffff) | 0x800000;
      const int sh = 4 * l + 103 - be;     /* the mantissa's last bit: 2^(4L - 47) */
      const bool neg = bits >> 31;
      uint32_t m = m24 >> sh;
      if (neg && (m24 & ((1u << sh) - 1)))
         m++;                              /* toward -inf */
      int ll = l;
      if (m >> DFX_MANT_BITS_SEED) {
         m >>= 4;
         ll++;
      }
      if (ll <= DFX_L_MAX) {
         r.d.s = neg;
         r.d.l = (uint8_t)ll;
         r.d.m = m;
         return r;
      }
   }
   return tex_ns_coord(u->ns, TEX_NS_DFX, v, &x->n);
}

#endif
