/* The float (double) reference sampler of the texture-unit tests: GL's
 * formulas written out independently of the unit (GL 4.6 section 8.14:
 * wrap on texel indices, mirror(), floor(u - 1/2) for linear). */
#ifndef TEST_TEX_REF_H
#define TEST_TEX_REF_H

#include <math.h>
#include <stdbool.h>
#include "rast/tex/tex.h"

/* Texels and their weights for one axis (index -1: border). */
struct ref_taps {
   int n;
   int i[2];
   double w[2];
   double u;          /* the texel-space coordinate the decision was made on */
};

static inline int ref_mod(long long a, int b)
{
   long long m = a % b;
   return (int)(m < 0 ? m + b : m);
}

static inline long long ref_mirror(long long a) { return a >= 0 ? a : -(1 + a); }

static inline int ref_wrap_index(enum tex_wrap w, long long i, int size)
{
   switch (w) {
   case TEX_WRAP_REPEAT: return ref_mod(i, size);
   case TEX_WRAP_CLAMP_TO_EDGE: return i < 0 ? 0 : i >= size ? size - 1 : (int)i;
   case TEX_WRAP_CLAMP:
   case TEX_WRAP_CLAMP_TO_BORDER: return i < 0 || i >= size ? -1 : (int)i;
   case TEX_WRAP_MIRROR_REPEAT:
      return (size - 1) - (int)ref_mirror((long long)ref_mod(i, 2 * size) - size);
   case TEX_WRAP_MIRROR_CLAMP_TO_EDGE: {
      long long m = ref_mirror(i);
      return m >= size ? size - 1 : (int)m;
   }
   case TEX_WRAP_MIRROR_CLAMP:
   case TEX_WRAP_MIRROR_CLAMP_TO_BORDER: {
      long long m = ref_mirror(i);
      return m >= size ? -1 : (int)m;
   }
   default: return -2;
   }
}

static inline struct ref_taps ref_axis(enum tex_wrap w, bool linear, double c, int size,
                                       bool normalized)
{
   struct ref_taps r;
   double u;
   if (w == TEX_WRAP_MIRROR_CLAMP_TO_BORDER) {
      /* EXT_texture_mirror_clamp (as softpipe and llvmpipe): |s|, then
       * CLAMP_TO_BORDER; the index -1 next to 0 is the border */
      c = fabs(c);
      w = TEX_WRAP_CLAMP_TO_BORDER;
   }
   if (w == TEX_WRAP_CLAMP || w == TEX_WRAP_MIRROR_CLAMP) {
      /* GL_CLAMP: the coordinate is clamped to [0, 1] first */
      double lim = normalized ? 1.0 : size;
      double cc = w == TEX_WRAP_MIRROR_CLAMP ? fabs(c) : c;
      cc = cc < 0 ? 0 : cc > lim ? lim : cc;
      u = normalized ? cc * size : cc;
      if (w == TEX_WRAP_MIRROR_CLAMP)
         w = TEX_WRAP_CLAMP;
   } else {
      u = normalized ? c * size : c;
   }
   if (!linear) {
      r.n = 1;
      r.u = u;
      long long i = (long long)floor(u);
      if (w == TEX_WRAP_CLAMP)
         i = i >= size ? size - 1 : i;   /* GL_CLAMP nearest: like the edge */
      r.i[0] = ref_wrap_index(w, i, size);
      r.w[0] = 1.0;
      return r;
   }
   u -= 0.5;
   r.u = u;
   long long i = (long long)floor(u);
   double f = u - floor(u);
   r.n = 2;
   r.i[0] = ref_wrap_index(w, i, size);
   r.i[1] = ref_wrap_index(w, i + 1, size);
   r.w[0] = 1.0 - f;
   r.w[1] = f;
   return r;
}

/* Largest difference of the texel->weight maps of two tap sets. */
static inline double ref_taps_diff(struct ref_taps a, struct ref_taps b)
{
   int keys[4];
   int nk = 0;
   for (int k = 0; k < a.n; k++) keys[nk++] = a.i[k];
   for (int k = 0; k < b.n; k++) keys[nk++] = b.i[k];
   double worst = 0;
   for (int k = 0; k < nk; k++) {
      double wa = 0, wb = 0;
      for (int j = 0; j < a.n; j++) if (a.i[j] == keys[k]) wa += a.w[j];
      for (int j = 0; j < b.n; j++) if (b.i[j] == keys[k]) wb += b.w[j];
      if (fabs(wa - wb) > worst)
         worst = fabs(wa - wb);
   }
   return worst;
}

/* GL's cube face table (major axis ties: x, then y). */
static inline unsigned ref_cube(double rx, double ry, double rz, double *s, double *t)
{
   double ax = fabs(rx), ay = fabs(ry), az = fabs(rz), sc, tc, ma;
   unsigned f;
   if (ax >= ay && ax >= az) { f = rx >= 0 ? 0 : 1; ma = ax; sc = rx >= 0 ? -rz : rz; tc = -ry; }
   else if (ay >= az) { f = ry >= 0 ? 2 : 3; ma = ay; sc = rx; tc = ry >= 0 ? rz : -rz; }
   else { f = rz >= 0 ? 4 : 5; ma = az; sc = rz >= 0 ? rx : -rx; tc = -ry; }
   *s = 0.5 * (sc / ma + 1.0);
   *t = 0.5 * (tc / ma + 1.0);
   return f;
}

#endif
