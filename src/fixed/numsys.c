/*
 * The texture path's number systems (numsys.h).  Rounding, as tested in
 * tests/unit/test_numsys.c and stated in docs/dfx.md:
 *
 *   dfxNN     the dfx.c data paths (arithmetic truncates; from_float rounds
 *             to nearest); range events are dfx.c's saturation and flush.
 *   fxM.N     fx.h: from_float, mul and recip round to nearest (ties away
 *             from zero), add/sub are exact; every result saturates, counted
 *             as sat.  A non-zero value that rounds to 0 (from_float, mul,
 *             recip) is a flush: the underflow of seed 003's perspective
 *             division.
 *   float     IEEE binary32, round to nearest even.  A finite operation that
 *             overflows to inf (or 1/0) is sat; a subnormal result, or 0 from
 *             a mul of non-zero operands, is flush (the value is kept: the
 *             count says the precision is gone).
 */
#include <math.h>
#include <string.h>
#include "fixed/numsys.h"

/* ---- dynamic fixed point ---- */

static inline void dfx_count(struct ns_stats *st, struct dfx_stats d)
{
   st->sat += d.sat;
   st->flush += d.flush;
}

static ns_val d_from_float(const struct numsys *ns, float v, struct ns_stats *st)
{
   struct dfx_stats d = { 0, 0 };
   ns_val r;
   r.d = dfx_from_double(ns->dfx, v, &d);
   dfx_count(st, d);
   return r;
}

static ns_val d_from_scaled(const struct numsys *ns, int64_t n, unsigned k, struct ns_stats *st)
{
   struct dfx_stats d = { 0, 0 };
   struct fx_format f = { 0, (uint8_t)k };
   ns_val r;
   r.d = dfx_from_fixed(ns->dfx, f, n, &d);
   dfx_count(st, d);
   return r;
}

static float d_to_float(const struct numsys *ns, ns_val a)
{
   return (float)dfx_to_double(ns->dfx, a.d);
}

#define DFX_BINOP(name, op)                                                          \
   static ns_val name(const struct numsys *ns, ns_val a, ns_val b, struct ns_stats *st) \
   {                                                                                \
      struct dfx_stats d = { 0, 0 };                                                \
      ns_val r;                                                                     \
      r.d = op(ns->dfx, a.d, b.d, &d);                                              \
      dfx_count(st, d);                                                             \
      return r;                                                                     \
   }

DFX_BINOP(d_add, dfx_add)
DFX_BINOP(d_sub, dfx_sub)
DFX_BINOP(d_mul, dfx_mul)

static ns_val d_recip(const struct numsys *ns, ns_val a, struct ns_stats *st)
{
   struct dfx_stats d = { 0, 0 };
   ns_val r;
   r.d = dfx_recip(ns->dfx, a.d, &d);
   dfx_count(st, d);
   return r;
}

static inline int64_t sat_int32(int64_t v, struct ns_stats *st)
{
   if (v > INT32_MAX) { st->sat++; return INT32_MAX; }
   if (v < INT32_MIN) { st->sat++; return INT32_MIN; }
   return v;
}

static int64_t d_floor_frac(const struct numsys *ns, ns_val a, uint32_t *frac,
                            unsigned frac_bits, struct ns_stats *st)
{
   int64_t i = dfx_floor_int(ns->dfx, a.d, frac, frac_bits);
   int64_t c = sat_int32(i, st);
   if (c != i && frac)
      *frac = 0;
   return c;
}

/* ---- M.N fixed point ---- */

static inline void fx_count(struct ns_stats *st, struct fx_sat s)
{
   st->sat += s.high + s.low;
}

static ns_val x_from_float(const struct numsys *ns, float v, struct ns_stats *st)
{
   struct fx_sat s = { 0, 0 };
   ns_val r;
   r.x = fx_from_double(ns->fx, v, &s);
   fx_count(st, s);
   if (!r.x && v != 0 && !isnan(v))
      st->flush++;
   return r;
}

static ns_val x_from_scaled(const struct numsys *ns, int64_t n, unsigned k, struct ns_stats *st)
{
   struct fx_sat s = { 0, 0 };
   struct fx_format f = { 0, (uint8_t)k };
   ns_val r;
   r.x = fx_convert(ns->fx, f, n, &s);
   fx_count(st, s);
   if (!r.x && n)
      st->flush++;
   return r;
}

static float x_to_float(const struct numsys *ns, ns_val a)
{
   return (float)fx_to_double(ns->fx, a.x);
}

#define FX_BINOP(name, op)                                                           \
   static ns_val name(const struct numsys *ns, ns_val a, ns_val b, struct ns_stats *st) \
   {                                                                                \
      struct fx_sat s = { 0, 0 };                                                   \
      ns_val r;                                                                     \
      r.x = op(ns->fx, a.x, b.x, &s);                                               \
      fx_count(st, s);                                                              \
      return r;                                                                     \
   }

FX_BINOP(x_add, fx_add)
FX_BINOP(x_sub, fx_sub)

static ns_val x_mul(const struct numsys *ns, ns_val a, ns_val b, struct ns_stats *st)
{
   struct fx_sat s = { 0, 0 };
   ns_val r;
   r.x = fx_mul(ns->fx, ns->fx, a.x, ns->fx, b.x, &s);
   fx_count(st, s);
   if (!r.x && a.x && b.x)
      st->flush++;
   return r;
}

static ns_val x_recip(const struct numsys *ns, ns_val a, struct ns_stats *st)
{
   struct fx_sat s = { 0, 0 };
   ns_val r;
   r.x = fx_div(ns->fx, ns->fx, fx_one(ns->fx), ns->fx, a.x, &s);
   fx_count(st, s);
   if (!r.x)
      st->flush++;
   return r;
}

static int64_t x_floor_frac(const struct numsys *ns, ns_val a, uint32_t *frac,
                            unsigned frac_bits, struct ns_stats *st)
{
   unsigned n = ns->fx.frac_bits;
   if (frac) {
      uint64_t f = (uint64_t)a.x & ((UINT64_C(1) << n) - 1);
      *frac = (uint32_t)(frac_bits >= n ? f << (frac_bits - n) : f >> (n - frac_bits));
   }
   return sat_int32(a.x >> n, st);
}

/* ---- binary32 ---- */

static inline float f_count(float r, struct ns_stats *st)
{
   int c = fpclassify(r);
   if (c == FP_INFINITE)
      st->sat++;
   else if (c == FP_SUBNORMAL)
      st->flush++;
   return r;
}

static ns_val f_from_float(const struct numsys *ns, float v, struct ns_stats *st)
{
   (void)ns;
   (void)st;
   ns_val r;
   r.f = v;
   return r;
}

/* (float)n is correctly rounded; the power of two is exact unless the
 * result leaves the normal range. */
static ns_val f_from_scaled(const struct numsys *ns, int64_t n, unsigned k, struct ns_stats *st)
{
   (void)ns;
   ns_val r;
   r.f = f_count(ldexpf((float)n, -(int)k), st);
   return r;
}

static float f_to_float(const struct numsys *ns, ns_val a)
{
   (void)ns;
   return a.f;
}

/* Operands are finite here (they come from the walk); an inf operand would
 * count again, which is what a reader of the counters wants to see. */
static ns_val f_add(const struct numsys *ns, ns_val a, ns_val b, struct ns_stats *st)
{
   (void)ns;
   ns_val r;
   r.f = f_count(a.f + b.f, st);
   return r;
}

static ns_val f_sub(const struct numsys *ns, ns_val a, ns_val b, struct ns_stats *st)
{
   (void)ns;
   ns_val r;
   r.f = f_count(a.f - b.f, st);
   return r;
}

static ns_val f_mul(const struct numsys *ns, ns_val a, ns_val b, struct ns_stats *st)
{
   (void)ns;
   ns_val r;
   r.f = f_count(a.f * b.f, st);
   if (r.f == 0 && a.f != 0 && b.f != 0)
      st->flush++;
   return r;
}

static ns_val f_recip(const struct numsys *ns, ns_val a, struct ns_stats *st)
{
   (void)ns;
   ns_val r;
   r.f = f_count(1.0f / a.f, st);
   return r;
}

static int64_t f_floor_frac(const struct numsys *ns, ns_val a, uint32_t *frac,
                            unsigned frac_bits, struct ns_stats *st)
{
   (void)ns;
   if (isnan(a.f)) {
      st->sat++;
      if (frac)
         *frac = 0;
      return 0;
   }
   double fl = floor((double)a.f);
   if (fl > (double)INT32_MAX || fl < (double)INT32_MIN) {
      st->sat++;
      if (frac)
         *frac = 0;
      return fl > 0 ? INT32_MAX : INT32_MIN;
   }
   if (frac)   /* a - floor(a) is exact; truncated to frac_bits */
      *frac = (uint32_t)ldexp((double)a.f - fl, (int)frac_bits);
   return (int64_t)fl;
}

/* ---- the tables ---- */

#define NS_DFX(nm, w)                                                          \
   { .name = nm, .family = NUMSYS_DFX,                                        \
     .summary = "seed 003 dynamic fixed point, 1+4+" #w " bits",             \
     .dfx = { w }, .from_float = d_from_float, .from_scaled = d_from_scaled,  \
     .to_float = d_to_float,                                                  \
     .add = d_add, .sub = d_sub, .mul = d_mul, .recip = d_recip,              \
     .floor_frac = d_floor_frac }

#define NS_FX(nm, m, n, sum)                                                   \
   { .name = nm, .family = NUMSYS_FIXED, .summary = sum, .fx = { m, n },      \
     .from_float = x_from_float, .from_scaled = x_from_scaled,                \
     .to_float = x_to_float, .add = x_add,                                    \
     .sub = x_sub, .mul = x_mul, .recip = x_recip, .floor_frac = x_floor_frac }

static const struct numsys ns_main[] = {
   NS_DFX("dfx24", 19),
   NS_FX("fx16.16", 16, 16, "16.16 fixed point (the GL ES fixed type)"),
   NS_FX("fx8.24", 8, 24, "8.24 fixed point (seed 003: distorts under perspective)"),
   NS_FX("fx24.8", 24, 8, "24.8 fixed point"),
   { .name = "float", .family = NUMSYS_FLOAT, .summary = "IEEE binary32",
     .from_float = f_from_float, .from_scaled = f_from_scaled, .to_float = f_to_float,
     .add = f_add, .sub = f_sub,
     .mul = f_mul, .recip = f_recip, .floor_frac = f_floor_frac },
};

/* dfxNN: NN bits in all, mantissa NN - 5 (dfx24 is ns_main[0]). */
static const struct numsys ns_sweep[] = {
   NS_DFX("dfx17", 12), NS_DFX("dfx18", 13), NS_DFX("dfx19", 14), NS_DFX("dfx20", 15),
   NS_DFX("dfx21", 16), NS_DFX("dfx22", 17), NS_DFX("dfx23", 18), NS_DFX("dfx25", 20),
   NS_DFX("dfx26", 21), NS_DFX("dfx27", 22), NS_DFX("dfx28", 23), NS_DFX("dfx29", 24),
};

const struct numsys *numsys_by_name(const char *name)
{
   if (!name)
      return NULL;
   for (unsigned i = 0; i < sizeof(ns_main) / sizeof(ns_main[0]); i++)
      if (!strcmp(name, ns_main[i].name))
         return &ns_main[i];
   for (unsigned i = 0; i < sizeof(ns_sweep) / sizeof(ns_sweep[0]); i++)
      if (!strcmp(name, ns_sweep[i].name))
         return &ns_sweep[i];
   return NULL;
}

const char *numsys_names(void)
{
   return "dfx24, fx16.16, fx8.24, fx24.8, float (sweep: dfx17..dfx29)";
}

const struct numsys *numsys_default(void)
{
   return &ns_main[0];
}
