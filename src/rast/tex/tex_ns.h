/*
 * What the texture unit needs from a number system beyond struct numsys's
 * arithmetic: sign, magnitude comparison and the leading-one position with
 * the bits after it.  These are wiring (a comparator, a priority encoder),
 * not arithmetic, so they read the register fields of each family directly
 * instead of going through the function table.
 */
#ifndef FIXPIPE_TEX_NS_H
#define FIXPIPE_TEX_NS_H

#include <math.h>
#include <string.h>
#include "rast/tex/tex.h"

enum { TEX_NS_DFX = NUMSYS_DFX, TEX_NS_FIXED = NUMSYS_FIXED, TEX_NS_FLOAT = NUMSYS_FLOAT };

static inline int tex_ns_kind(const struct numsys *ns)
{
   return (int)ns->family;
}

static inline bool tex_ns_neg(int kind, ns_val a)
{
   switch (kind) {
   case TEX_NS_DFX: return a.d.s && a.d.m;
   case TEX_NS_FIXED: return a.x < 0;
   default: return a.f < 0.0f;
   }
}

/* -1, 0, 1 as a < b, a == b, a > b. */
static inline int tex_ns_cmp(int kind, ns_val a, ns_val b)
{
   switch (kind) {
   case TEX_NS_DFX: {
      bool na = a.d.s && a.d.m, nb = b.d.s && b.d.m;
      if (na != nb)
         return na ? -1 : 1;
      int c;
      if (!a.d.m || !b.d.m)
         c = (a.d.m != 0) - (b.d.m != 0);
      else if (a.d.l != b.d.l)   /* normalized: a higher digit is larger */
         c = a.d.l < b.d.l ? -1 : 1;
      else
         c = (a.d.m > b.d.m) - (a.d.m < b.d.m);
      return na ? -c : c;
   }
   case TEX_NS_FIXED:
      return (a.x > b.x) - (a.x < b.x);
   default:
      return (a.f > b.f) - (a.f < b.f);
   }
}

static inline ns_val tex_ns_abs(int kind, ns_val a)
{
   switch (kind) {
   case TEX_NS_DFX: a.d.s = 0; return a;
   case TEX_NS_FIXED: if (a.x < 0) a.x = -a.x; return a;
   default: if (a.f < 0.0f) a.f = -a.f; return a;
   }
}

static inline ns_val tex_ns_max(int kind, ns_val a, ns_val b)
{
   return tex_ns_cmp(kind, a, b) >= 0 ? a : b;
}

static inline ns_val tex_ns_clamp(int kind, ns_val a, ns_val lo, ns_val hi)
{
   if (tex_ns_cmp(kind, a, lo) < 0)
      return lo;
   if (tex_ns_cmp(kind, a, hi) > 0)
      return hi;
   return a;
}

/* The unit's coordinate input: binary32 to the register, rounding toward
 * -inf (the numsys conversion rounds to nearest).  Rounding down keeps
 * every decision "floor(c * size) >= k" of the float reference wherever the
 * boundary k / size lies on the register's grid (every power-of-two size):
 * a coordinate just below a texel boundary stays below it.  Out of range
 * saturates, below the smallest value flushes, both counted. */
static inline ns_val tex_ns_coord(const struct numsys *ns, int kind, float v, struct ns_stats *st)
{
   ns_val r;
   memset(&r, 0, sizeof(r));
   if (kind == TEX_NS_FLOAT) {
      r.f = v;
      return r;
   }
   if (isnan(v)) {
      st->sat++;
      return r;
   }
   if (kind == TEX_NS_FIXED) {
      const double top = ldexp(1.0, ns->fx.int_bits + ns->fx.frac_bits - 1);
      double x = floor(ldexp((double)v, ns->fx.frac_bits));
      if (x >= top) { st->sat++; x = top - 1; }
      if (x < -top) { st->sat++; x = -top; }
      if (x == 0 && v > 0)
         st->flush++;
      r.x = (int64_t)x;
      return r;
   }
   if (v == 0.0f)
      return r;
   const unsigned w = ns->dfx.mant_bits;
   const bool neg = v < 0;
   int e;
   (void)frexp(fabs((double)v), &e);   /* 2^(e-1) <= |v| < 2^e */
   int l = (e - 1 + 32) >> 2;           /* the digit of the leading one */
   if (e - 1 + 32 < 0) {
      st->flush++;
      if (neg) {   /* toward -inf: the smallest negative value */
         r.d.s = 1; r.d.l = 0; r.d.m = 1u << (w - 4);
      }
      return r;
   }
   if (l > DFX_L_MAX || isinf(v))
      goto saturate;
   {
      double mag = ldexp(fabs((double)v), -(4 * l + 4 - (int)w - 32));
      uint64_t m = (uint64_t)(neg ? ceil(mag) : floor(mag));
      if (m >> w) {   /* rounded up past the mantissa: next digit */
         m >>= 4;
         if (++l > DFX_L_MAX)
            goto saturate;
      }
      r.d.s = neg;
      r.d.l = (uint8_t)l;
      r.d.m = (uint32_t)m;
      return r;
   }
saturate:
   st->sat++;
   r.d.s = neg;
   r.d.l = DFX_L_MAX;
   r.d.m = (1u << w) - 1;
   return r;
}

/* The priority encoder of the log2 unit: for |a| > 0, the power of two of
 * its leading one (e) and the 8 bits that follow it (f), so that
 * |a| = 2^e * (1 + f/256 + less).  False for zero. */
static inline bool tex_ns_lead(const struct numsys *ns, int kind, ns_val a, int *e, unsigned *f)
{
   uint64_t m;
   int lsb;   /* power of two of m's bit 0 */
   switch (kind) {
   case TEX_NS_DFX:
      m = a.d.m;
      lsb = 4 * a.d.l + 4 - ns->dfx.mant_bits - 32;
      break;
   case TEX_NS_FIXED:
      m = a.x < 0 ? (uint64_t)-a.x : (uint64_t)a.x;
      lsb = -(int)ns->fx.frac_bits;
      break;
   default: {
      float v = a.f < 0.0f ? -a.f : a.f;
      uint32_t bits;
      memcpy(&bits, &v, 4);
      if (!(v > 0.0f) || (bits >> 23) == 0xff)
         return false;   /* zero, NaN, inf: no meaningful rho */
      if ((bits >> 23) == 0)
         return false;   /* denormal: LOD far below any clamp */
      *e = (int)(bits >> 23) - 127;
      *f = (bits >> 15) & 0xff;
      return true;
   }
   }
   if (!m)
      return false;
   int p = 63 - __builtin_clzll(m);
   *e = p + lsb;
   *f = p >= 8 ? (unsigned)(m >> (p - 8)) & 0xff : (unsigned)(m << (8 - p)) & 0xff;
   return true;
}

#endif
