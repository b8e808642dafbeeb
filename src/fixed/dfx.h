/*
 * The 24-bit dynamic fixed-point format of the texture unit (seed 003).
 *
 *    [23] sign   [22:19] location L (0..15)   [18:0] mantissa M (19 bits)
 *
 * The format addresses a virtual 32.32 fixed-point word as 16 hexadecimal
 * digits; L names the digit holding the mantissa's most significant bit, so
 * with a W-bit mantissa (W = 19 in the seed)
 *
 *    value = (-1)^s * M * 2^(4L + 4 - W - 32)        (W = 19: 2^(4L - 47))
 *
 * A value is normalized when its top digit M[W-1:W-4] is non-zero; the
 * exponent moves in whole digits, so a normalized mantissa keeps W-3 to W
 * significant bits.  Results beyond L = 15 saturate to the largest
 * magnitude, results below the smallest normalized value flush to zero;
 * both are counted, never silent.
 *
 * The mantissa width is a parameter (12..24) for precision sweeps; the
 * register is modelled as its three fields, not as packed bits, so that a
 * reader sees the hardware's registers.
 */
#ifndef FIXPIPE_DFX_H
#define FIXPIPE_DFX_H

#include <stdint.h>
#include <stdbool.h>
#include "fixed/fx.h"

#define DFX_MANT_BITS_SEED 19
#define DFX_MANT_BITS_MIN  12
#define DFX_MANT_BITS_MAX  24
#define DFX_L_MAX          15

struct dfx_format {
   uint8_t mant_bits;            /* W */
};

/* One register: zero is m == 0 (l and s then 0). */
struct dfx {
   uint8_t s;                    /* sign */
   uint8_t l;                    /* location, 0..15 */
   uint32_t m;                   /* mantissa, W bits, normalized unless zero */
};

struct dfx_stats {
   uint64_t sat;                 /* clamped above L = 15 */
   uint64_t flush;               /* flushed to zero below the smallest value */
};

static inline bool dfx_is_zero(struct dfx a) { return a.m == 0; }
static inline struct dfx dfx_zero(void) { struct dfx z = {0, 0, 0}; return z; }
static inline struct dfx dfx_neg(struct dfx a) { if (a.m) a.s ^= 1; return a; }

/* Conversions.  Rounding of every operation is stated where it is defined
 * (dfx.c) and tested (tests/unit/test_dfx.c). */
struct dfx dfx_from_double(struct dfx_format f, double d, struct dfx_stats *st);
double     dfx_to_double(struct dfx_format f, struct dfx a);
struct dfx dfx_from_fixed(struct dfx_format f, struct fx_format fx, int64_t v, struct dfx_stats *st);
/* To M.N fixed point, saturating in that format (counted in *s). */
int64_t    dfx_to_fixed(struct dfx_format f, struct dfx a, struct fx_format fx, struct fx_sat *s);
/* The integer part (floor) and the fraction in `frac_bits` bits: what the
 * texture unit's addressing takes from a scaled coordinate. */
int64_t    dfx_floor_int(struct dfx_format f, struct dfx a, uint32_t *frac, unsigned frac_bits);

/* Arithmetic as the paper's data paths: add/sub align by whole digits (a
 * 5-way multiplexer: shifts of 0..4 digits; 5 or more leave nothing of the
 * smaller operand), add the mantissas, renormalize by whole digits;
 * multiply keeps the top W bits of the 2W-bit product (Fig. 9); reciprocal
 * and divide as dfx.c states. */
struct dfx dfx_add(struct dfx_format f, struct dfx a, struct dfx b, struct dfx_stats *st);
struct dfx dfx_sub(struct dfx_format f, struct dfx a, struct dfx b, struct dfx_stats *st);
struct dfx dfx_mul(struct dfx_format f, struct dfx a, struct dfx b, struct dfx_stats *st);
struct dfx dfx_recip(struct dfx_format f, struct dfx a, struct dfx_stats *st);
struct dfx dfx_div(struct dfx_format f, struct dfx a, struct dfx b, struct dfx_stats *st);

/* Packed 24-bit (W = 19) register image, for test vectors. */
uint32_t   dfx_pack(struct dfx_format f, struct dfx a);
struct dfx dfx_unpack(struct dfx_format f, uint32_t bits);

#endif
