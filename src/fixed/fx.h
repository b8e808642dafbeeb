/*
 * M.N two's-complement fixed point with saturation: the number formats of the
 * scan converter's registers (seed 000, Table 1).
 *
 * A value is held in an int64_t in units of 2^-N.  Every operation that can
 * leave the M.N range clamps to the format's largest or smallest value and
 * counts the event in the fx_sat counter it is given, so an overflow in the
 * model is never silent.
 */
#ifndef FIXPIPE_FX_H
#define FIXPIPE_FX_H

#include <stdint.h>
#include <stdbool.h>

struct fx_format {
   uint8_t int_bits;    /* M: integer bits, sign included */
   uint8_t frac_bits;   /* N: fraction bits */
};

/* Saturation events of one register class (X, Z, colour, ...). */
struct fx_sat {
   uint64_t high;       /* clamped to the largest value */
   uint64_t low;        /* clamped to the smallest value */
};

/* The bits of n: the position of its leading one, plus one (0 for 0). */
static inline unsigned fx_bitlen64(uint64_t n)
{
   return n ? 64 - (unsigned)__builtin_clzll(n) : 0;
}

static inline int64_t fx_max(struct fx_format f)
{
   return (INT64_C(1) << (f.int_bits + f.frac_bits - 1)) - 1;
}

static inline int64_t fx_min(struct fx_format f)
{
   return -(INT64_C(1) << (f.int_bits + f.frac_bits - 1));
}

static inline int64_t fx_one(struct fx_format f)
{
   return INT64_C(1) << f.frac_bits;
}

/* 2^e exactly, for e in -1022..1023: the bits of the double.  ldexp is a
 * library call with errno handling; the set-up converts every vertex and
 * the data paths every value with this, so it is two instructions (the one
 * copy for fx, dfx and the lanes). */
static inline double fx_pow2(int e)
{
   union { uint64_t u; double d; } b = { (uint64_t)(e + 1023) << 52 };
   return b.d;
}

/* Clamp an exact intermediate into the format, counting a clamp. */
static inline int64_t fx_sat(struct fx_format f, int64_t v, struct fx_sat *s)
{
   if (v > fx_max(f)) { s->high++; return fx_max(f); }
   if (v < fx_min(f)) { s->low++;  return fx_min(f); }
   return v;
}

/* The register update of the edge and span processors: a + b, saturated.
 * Operands are already in range, so the int64 sum cannot overflow. */
static inline int64_t fx_add(struct fx_format f, int64_t a, int64_t b, struct fx_sat *s)
{
   return fx_sat(f, a + b, s);
}

static inline int64_t fx_sub(struct fx_format f, int64_t a, int64_t b, struct fx_sat *s)
{
   return fx_sat(f, a - b, s);
}

/* ceil() as the seed's Fig. 7 circuit: add 2^N - 1 and clear the fraction.
 * Returns an integer (not a fixed-point value). */
static inline int64_t fx_ceil_int(struct fx_format f, int64_t v)
{
   return (v + fx_one(f) - 1) >> f.frac_bits;   /* arithmetic shift: floor */
}

static inline int64_t fx_floor_int(struct fx_format f, int64_t v)
{
   return v >> f.frac_bits;
}

/* Conversions.  Rounding to nearest, ties away from zero; NaN counts as a
 * low saturation and becomes 0 so that garbage never reaches the walkers. */
int64_t fx_from_double(struct fx_format f, double d, struct fx_sat *s);
double  fx_to_double(struct fx_format f, int64_t v);

/* Re-express a value of format `from` in format `to` (rounding to nearest
 * when fraction bits are dropped), saturating. */
int64_t fx_convert(struct fx_format to, struct fx_format from, int64_t v, struct fx_sat *s);

/* a * b where a is in format fa, b in fb; the result in format fr, rounded
 * to nearest and saturated.  Used by setup (slopes) and the subpixel
 * corrections, never inside a span. */
int64_t fx_mul(struct fx_format fr, struct fx_format fa, int64_t a,
               struct fx_format fb, int64_t b, struct fx_sat *s);

/* a / b (formats as fx_mul), rounded to nearest, saturated; b == 0
 * saturates to the sign of a and counts. */
int64_t fx_div(struct fx_format fr, struct fx_format fa, int64_t a,
               struct fx_format fb, int64_t b, struct fx_sat *s);

#endif
