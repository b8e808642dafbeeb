/*
 * Conversions and the set-up arithmetic of the M.N formats (fx.h).  Exact
 * intermediates in 128 bits, one rounding at the end, so a result depends
 * only on the operands and the formats, never on the host's float unit.
 */
#include <math.h>
#include "fixed/fx.h"
#include "fixed/fx_wide.h"

static int64_t sat128(struct fx_format f, fx_i128 v, struct fx_sat *s)
{
   return fx_sat_i128(v, fx_min(f), fx_max(f), &s->high, &s->low);
}

int64_t fx_from_double(struct fx_format f, double d, struct fx_sat *s)
{
   if (isnan(d)) {
      s->low++;
      return 0;
   }
   /* d * 2^N is exact (a power of two at most 2^63 scales a double
    * exactly, or to inf, as ldexp would) */
   double r = round(d * fx_pow2(f.frac_bits));  /* ties away from zero */
   /* fx_max/fx_min need at most 63 bits; the double compare is exact at
    * the boundary because 2^(M+N-1) is a power of two. */
   const double top = fx_pow2(f.int_bits + f.frac_bits - 1);
   if (r >= top) {
      s->high++;
      return fx_max(f);
   }
   if (r < -top) {
      s->low++;
      return fx_min(f);
   }
   return (int64_t)r;
}

double fx_to_double(struct fx_format f, int64_t v)
{
   return (double)v * fx_pow2(-(int)f.frac_bits);
}

/* v in units of 2^-from_frac -> units of 2^-to_frac, rounded. */
static fx_i128 rescale(fx_i128 v, int from_frac, int to_frac)
{
   if (to_frac >= from_frac)
      return v * ((fx_i128)1 << (to_frac - from_frac));
   return fx_shr_round_i128(v, (unsigned)(from_frac - to_frac));
}

int64_t fx_convert(struct fx_format to, struct fx_format from, int64_t v, struct fx_sat *s)
{
   return sat128(to, rescale(v, from.frac_bits, to.frac_bits), s);
}

int64_t fx_mul(struct fx_format fr, struct fx_format fa, int64_t a,
               struct fx_format fb, int64_t b, struct fx_sat *s)
{
   fx_i128 p = (fx_i128)a * b;                  /* units 2^-(Na+Nb) */
   return sat128(fr, rescale(p, fa.frac_bits + fb.frac_bits, fr.frac_bits), s);
}

int64_t fx_div(struct fx_format fr, struct fx_format fa, int64_t a,
               struct fx_format fb, int64_t b, struct fx_sat *s)
{
   if (b == 0) {
      /* 0/0 is taken as +0/0: it saturates high like any non-negative. */
      if (a >= 0) { s->high++; return fx_max(fr); }
      s->low++;
      return fx_min(fr);
   }
   /* raw = a * 2^(Nr - Na + Nb) / b */
   int e = fr.frac_bits - fa.frac_bits + fb.frac_bits;
   fx_i128 n = a, d = b;
   if (e >= 0)
      n *= (fx_i128)1 << e;
   else
      d *= (fx_i128)1 << -e;
   return sat128(fr, fx_div_round_i128(n, d), s);
}
