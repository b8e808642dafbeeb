/*
 * The number system of the texture path, chosen at run time
 * (FIXPIPE_TEXFMT): the seed's 24-bit dynamic fixed point, the fixed formats
 * the seed compares it with (16.16, 8.24, 24.8) and IEEE binary32.  The
 * perspective division of texture coordinates (src/rast/interp/persp.c) and the
 * texture unit's addressing (src/rast/tex*.c) compute in it, so one switch
 * shows what each format does to the same content.
 *
 * A table of functions, chosen once per state change, never per pixel.
 */
#ifndef FIXPIPE_NUMSYS_H
#define FIXPIPE_NUMSYS_H

#include <stdint.h>
#include "fixed/fx.h"
#include "fixed/dfx.h"

typedef union {
   struct dfx d;        /* dynamic fixed point */
   int64_t x;           /* M.N fixed point, units of 2^-N */
   float f;             /* binary32 */
} ns_val;

/* Range events of the chosen format: saturation (or overflow to inf) and
 * flush/underflow to zero.  Counted, never silent. */
struct ns_stats {
   uint64_t sat;
   uint64_t flush;
};

/* What a value of the system is made of: which ns_val member holds it. */
enum numsys_family { NUMSYS_DFX, NUMSYS_FIXED, NUMSYS_FLOAT };

struct numsys {
   const char *name;
   enum numsys_family family;                  /* "dfx24", "fx16.16", "fx8.24", "fx24.8", "float" */
   const char *summary;
   struct dfx_format dfx;             /* for dfx */
   struct fx_format fx;               /* for fixed */

   ns_val (*from_float)(const struct numsys *ns, float v, struct ns_stats *st);
   /* n * 2^-k for an exact integer n (k < 64), rounded as from_float: how
    * the rasterizer's exact integers (edge functions, the doubled area)
    * enter the system. */
   ns_val (*from_scaled)(const struct numsys *ns, int64_t n, unsigned k, struct ns_stats *st);
   float  (*to_float)(const struct numsys *ns, ns_val a);
   ns_val (*add)(const struct numsys *ns, ns_val a, ns_val b, struct ns_stats *st);
   ns_val (*sub)(const struct numsys *ns, ns_val a, ns_val b, struct ns_stats *st);
   ns_val (*mul)(const struct numsys *ns, ns_val a, ns_val b, struct ns_stats *st);
   ns_val (*recip)(const struct numsys *ns, ns_val a, struct ns_stats *st);
   /* floor(a) as an integer and the fraction in frac_bits bits (saturating
    * the integer to int32 range, counted). */
   int64_t (*floor_frac)(const struct numsys *ns, ns_val a, uint32_t *frac,
                         unsigned frac_bits, struct ns_stats *st);
};

/* NULL when unknown.  "dfx24" is the default; "dfxNN" (NN = 17..29, the
 * total width, mantissa NN-5 bits) selects the mantissa sweep. */
const struct numsys *numsys_by_name(const char *name);
const char *numsys_names(void);        /* "dfx24, fx16.16, fx8.24, fx24.8, float" */
const struct numsys *numsys_default(void);

#endif
