/* fx.c: conversions, rounding, saturation at both ends of every profile
 * format (never a wrap-around), ceil, and the set-up multiply/divide. */
#include <math.h>
#include "tutil.h"
#include "fixed/fx_wide.h"
#include "fixed/fx.h"

static void check_format(const char *what, struct fx_format f)
{
   struct fx_sat s = { 0, 0 };
   double one = ldexp(1.0, -(int)f.frac_bits);          /* one ulp */
   double top = ldexp(1.0, f.int_bits - 1);             /* first value beyond max */

   /* exact values and rounding to nearest, ties away from zero */
   CHECK(fx_from_double(f, 1.0, &s) == fx_one(f), "%s 1.0", what);
   CHECK(fx_from_double(f, -2.5, &s) == -5 * fx_one(f) / 2, "%s -2.5", what);
   CHECK(fx_from_double(f, 0.4 * one, &s) == 0, "%s 0.4 ulp", what);
   CHECK(fx_from_double(f, 0.5 * one, &s) == 1, "%s +0.5 ulp ties away", what);
   CHECK(fx_from_double(f, -0.5 * one, &s) == -1, "%s -0.5 ulp ties away", what);
   CHECK(fx_from_double(f, 1.6 * one, &s) == 2, "%s 1.6 ulp", what);
   CHECK(fx_from_double(f, -1.4 * one, &s) == -1, "%s -1.4 ulp", what);
   CHECK(s.high == 0 && s.low == 0, "%s no saturation on in-range values", what);
   CHECK(fx_to_double(f, fx_from_double(f, 3.25, &s)) == 3.25, "%s round trip", what);

   /* the largest and smallest values, and one beyond each */
   CHECK(fx_from_double(f, top - one, &s) == fx_max(f), "%s max", what);
   CHECK(fx_from_double(f, -top, &s) == fx_min(f), "%s min", what);
   CHECK(s.high == 0 && s.low == 0, "%s max/min are in range", what);
   CHECK(fx_from_double(f, top - 0.5 * one, &s) == fx_max(f) && s.high == 1,
         "%s rounding up past max saturates", what);
   CHECK(fx_from_double(f, top * 1000, &s) == fx_max(f) && s.high == 2, "%s huge positive", what);
   CHECK(fx_from_double(f, INFINITY, &s) == fx_max(f) && s.high == 3, "%s +inf", what);
   CHECK(fx_from_double(f, -top - one, &s) == fx_min(f) && s.low == 1, "%s below min", what);
   CHECK(fx_from_double(f, -INFINITY, &s) == fx_min(f) && s.low == 2, "%s -inf", what);
   CHECK(fx_from_double(f, NAN, &s) == 0 && s.low == 3, "%s NaN -> 0, counted", what);
   CHECK(fx_max(f) > 0 && fx_min(f) < 0, "%s sign", what);

   /* the register update saturates instead of wrapping */
   s.high = s.low = 0;
   CHECK(fx_add(f, fx_max(f), 1, &s) == fx_max(f) && s.high == 1, "%s max + 1", what);
   CHECK(fx_add(f, fx_max(f), fx_max(f), &s) == fx_max(f) && s.high == 2, "%s max + max", what);
   CHECK(fx_sub(f, fx_min(f), 1, &s) == fx_min(f) && s.low == 1, "%s min - 1", what);
   CHECK(fx_add(f, fx_min(f), fx_min(f), &s) == fx_min(f) && s.low == 2, "%s min + min", what);
   CHECK(fx_add(f, fx_max(f), -1, &s) == fx_max(f) - 1 && s.high == 2, "%s in range", what);

   /* ceil circuit: integers stay, any fraction goes up, negatives too */
   int64_t o = fx_one(f);
   CHECK(fx_ceil_int(f, 5 * o) == 5, "%s ceil 5", what);
   CHECK(fx_ceil_int(f, 5 * o + 1) == 6, "%s ceil 5+ulp", what);
   CHECK(fx_ceil_int(f, 6 * o - 1) == 6, "%s ceil 6-ulp", what);
   CHECK(fx_ceil_int(f, -5 * o) == -5, "%s ceil -5", what);
   CHECK(fx_ceil_int(f, -5 * o + 1) == -4, "%s ceil -5+ulp", what);
   CHECK(fx_ceil_int(f, -5 * o - 1) == -5, "%s ceil -5-ulp", what);
   CHECK(fx_ceil_int(f, fx_max(f)) == ldexp(1.0, f.int_bits - 1), "%s ceil max", what);
   CHECK(fx_ceil_int(f, fx_min(f)) == -ldexp(1.0, f.int_bits - 1), "%s ceil min", what);
   CHECK(fx_floor_int(f, -1) == -1 && fx_floor_int(f, o - 1) == 0, "%s floor", what);

   /* multiply and divide: rounded, saturated */
   s.high = s.low = 0;
   int64_t a = fx_from_double(f, 1.5, &s), b = fx_from_double(f, -2.25, &s);
   CHECK(fx_mul(f, f, a, f, b, &s) == fx_from_double(f, -3.375, &s), "%s mul", what);
   CHECK(fx_div(f, f, b, f, a, &s) == fx_from_double(f, -1.5, &s), "%s div", what);
   CHECK(fx_div(f, f, o, f, 3 * o, &s) == (o + 1) / 3, "%s 1/3 rounds to nearest", what);
   CHECK(fx_div(f, f, 2 * o, f, 3 * o, &s) == (2 * o + 1) / 3, "%s 2/3 rounds to nearest", what);
   CHECK(s.high == 0 && s.low == 0, "%s mul/div in range", what);
   CHECK(fx_mul(f, f, fx_max(f), f, fx_max(f), &s) == fx_max(f) && s.high == 1, "%s mul sat", what);
   CHECK(fx_mul(f, f, fx_max(f), f, fx_min(f), &s) == fx_min(f) && s.low == 1, "%s mul sat low", what);
   CHECK(fx_div(f, f, o, f, 0, &s) == fx_max(f) && s.high == 2, "%s x/0", what);
   CHECK(fx_div(f, f, -o, f, 0, &s) == fx_min(f) && s.low == 2, "%s -x/0", what);
   CHECK(fx_div(f, f, fx_max(f), f, 1, &s) == fx_max(f) && s.high == 3, "%s div overflow", what);
}

/* fx_div_round_i128's 64-bit path against the 128-bit division it
 * replaces: random operands of every size, ties, signs, the ends. */
static fx_i128 div_round_ref(fx_i128 n, fx_i128 d)
{
   fx_i128 q = n / d, r = n % d;
   fx_i128 ar = r < 0 ? -r : r, ad = d < 0 ? -d : d;
   if (2 * ar >= ad)
      q += ((n < 0) != (d < 0)) ? -1 : 1;
   return q;
}

static void check_div_round(void)
{
   uint64_t st = 0x243f6a8885a308d3u;
   unsigned bad = 0;
   const int64_t ends[] = { INT64_MAX, -INT64_MAX, INT64_MAX - 1, 1, -1, 2, -2, 3, 7, -7 };
   for (unsigned i = 0; i < 2000000; i++) {
      fx_i128 n, d;
      if (i < 100) {
         n = ends[i % 10];
         d = ends[i / 10];
      } else {
         const unsigned bn = (unsigned)(t_xorshift(&st) % 64), bd = 1 + (unsigned)(t_xorshift(&st) % 63);
         n = (fx_i128)(t_xorshift(&st) >> (63 - bn)) - (fx_i128)(t_xorshift(&st) >> (63 - bn));
         d = (fx_i128)(t_xorshift(&st) >> (64 - bd)) | 1;
         if (i % 3 == 0)
            n = (n / d) * d + (d / 2) * (n < 0 ? -1 : 1);     /* a tie when d is even */
         if (i % 2)
            d = -d;
         if (i % 17 == 0)
            n *= (fx_i128)1 << 40;                          /* beyond 64 bits */
      }
      if (!d)
         continue;
      bad += fx_div_round_i128(n, d) != div_round_ref(n, d);
   }
   CHECK(bad == 0, "fx_div_round_i128: %u quotients differ from the 128-bit division", bad);
}

int main(void)
{
   check_div_round();
   for (const struct rast_profile *const *p = rast_profile_list(); *p; p++) {
      const struct rast_profile *pr = *p;
      char buf[64];
      snprintf(buf, sizeof buf, "%s.xy", pr->name);   check_format(buf, pr->xy);
      snprintf(buf, sizeof buf, "%s.dxdy", pr->name); check_format(buf, pr->dxdy);
      snprintf(buf, sizeof buf, "%s.z", pr->name);    check_format(buf, pr->z);
      snprintf(buf, sizeof buf, "%s.color", pr->name); check_format(buf, pr->color);
      CHECK(rast_profile_by_name(pr->name) == pr, "lookup %s", pr->name);
      /* the Z register holds (2^z_bits - 1) and colour 255 */
      CHECK(((INT64_C(1) << pr->z_bits) - 1) * fx_one(pr->z) <= fx_max(pr->z), "%s z fits", pr->name);
      CHECK(255 * fx_one(pr->color) <= fx_max(pr->color), "%s colour fits", pr->name);
      CHECK(pr->xy.frac_bits == pr->dxdy.frac_bits, "%s slopes step X in its own units", pr->name);
      /* X_out addresses no more than the XY register's positive range */
      CHECK(((int64_t)pr->tile_size << pr->xy.frac_bits) <= fx_max(pr->xy) + 1 &&
            pr->max_target >= pr->tile_size, "%s tiles", pr->name);
   }
   const struct rast_profile *seed = rast_profile_by_name("seed");
   CHECK(seed && seed->xy.int_bits == 12 && seed->xy.frac_bits == 12 && seed->z.int_bits == 20 &&
         seed->color.int_bits == 9 && seed->z_bits == 19 && seed->tile_size == 2048 &&
         !seed->color_perspective, "seed profile is Table 1");
   const struct rast_profile *wide = rast_profile_by_name("wide");
   CHECK(wide && wide->xy.int_bits == 16 && wide->z.int_bits == 28 && wide->z_bits == 24 &&
         wide->tile_size == 8192 && wide->color_perspective, "wide profile");
   CHECK(rast_profile_by_name("see") == NULL && rast_profile_by_name("seedx") == NULL &&
         rast_profile_by_name(NULL) == NULL, "unknown names");

   /* conversion between formats rounds to nearest when bits are dropped */
   struct fx_sat s = { 0, 0 };
   struct fx_format f12 = { 12, 12 }, f4 = { 20, 4 };
   CHECK(fx_convert(f4, f12, 0x1800, &s) == 0x18, "convert exact");
   CHECK(fx_convert(f4, f12, 0x1880, &s) == 0x19, "convert tie up");
   CHECK(fx_convert(f4, f12, -0x1880, &s) == -0x19, "convert tie away from zero");
   CHECK(fx_convert(f12, f4, 0x19, &s) == 0x1900, "convert widen");
   CHECK(s.high == 0 && s.low == 0, "convert in range");
   CHECK(fx_convert(f12, f4, INT64_C(1) << 20, &s) == fx_max(f12) && s.high == 1, "convert sat");
   return t_summary("fx");
}
