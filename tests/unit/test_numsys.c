/*
 * numsys.c against double, with the bounds docs/dfx.md states:
 *   dfxNN (W = NN - 5)  from_float |err| <= 2^-(W-3) |v|; add/sub
 *                       |err| <= max(2^-(W-6), 2^-16) max(|a|, |b|) (the
 *                       5-way alignment's 2^-16 matters for W > 22); mul, recip
 *                       |err| <= 2^-(W-4) |exact|
 *   fxM.N               from_float, mul, recip |err| <= 2^-(N+1); add/sub
 *                       exact; all saturating
 *   float               from_float exact; ops correctly rounded binary32
 * and the range events each counts.  Then the perspective division on
 * rendered triangles (rast_set_texfmt): a wall receding to the right with a
 * w ratio of 100 and 1000 along a 1000-pixel span, where fx8.24 cannot hold
 * w = 1000 (saturates, counted), fx16.16 flushes the small products near
 * the texture's origin, and dfx24 counts no event; every system stays
 * within the per-pixel bound of the vector method (persp_bound.h) wherever
 * its values fit.
 */
#include <math.h>
#include <string.h>
#include "tutil.h"
#include "fixed/numsys.h"
#include "persp_bound.h"

static double rnd_val(double lo_exp, double hi_exp)
{
   double e = lo_exp + (hi_exp - lo_exp) * t_rand();
   return (t_rand() < 0.5 ? -1 : 1) * exp2(e);
}

/* The exact value a register holds (to_float rounds it to binary32). */
static double val(const struct numsys *ns, ns_val v)
{
   if (ns->dfx.mant_bits)
      return dfx_to_double(ns->dfx, v.d);
   if (ns->fx.frac_bits)
      return fx_to_double(ns->fx, v.x);
   return v.f;
}

static void check_system(const struct numsys *ns)
{
   bool dfx = ns->dfx.mant_bits != 0, flt = !strcmp(ns->name, "float");
   unsigned w = ns->dfx.mant_bits, n = ns->fx.frac_bits;
   /* magnitudes whose products and reciprocals stay inside the format */
   double mi = ns->fx.int_bits;
   double lo = dfx ? -14 : flt ? -60 : fmax(-(double)n / 2 + 1, -(mi - 2));
   double hi = dfx ? 14 : flt ? 60 : fmin((mi - 2) / 2, (double)n / 2 - 1);
   double q = ldexp(1, -(int)n - 1);
   for (unsigned i = 0; i < 200000; i++) {
      struct ns_stats st = { 0, 0 };
      float fa = (float)rnd_val(lo, hi), fb = (float)rnd_val(lo, hi);
      ns_val a = ns->from_float(ns, fa, &st), b = ns->from_float(ns, fb, &st);
      double da = val(ns, a), db = val(ns, b);
      CHECK(ns->to_float(ns, a) == (float)da, "%s to_float", ns->name);
      double e1 = fabs(da - fa), e2 = fabs(db - fb);
      if (dfx)
         CHECK(e1 <= ldexp(fabs(fa), -(int)w + 3) && e2 <= ldexp(fabs(fb), -(int)w + 3),
               "%s from_float %g", ns->name, fa);
      else if (flt)
         CHECK(e1 == 0 && e2 == 0, "%s from_float", ns->name);
      else
         CHECK(e1 <= q && e2 <= q, "%s from_float %g: %g", ns->name, fa, da);
      /* operations on the values the system holds */
      double s = val(ns, ns->add(ns, a, b, &st)), d = val(ns, ns->sub(ns, a, b, &st));
      double m = val(ns, ns->mul(ns, a, b, &st));
      double r = val(ns, ns->recip(ns, a, &st));
      double mx = fabs(da) > fabs(db) ? fabs(da) : fabs(db);
      double es = fabs(s - (da + db)), ed = fabs(d - (da - db)), em = fabs(m - da * db), er = fabs(r - 1 / da);
      if (dfx) {
         /* the 5-way alignment drops an operand below 2^-16 of the other */
         double ab = fmax(ldexp(mx, -(int)w + 6), ldexp(mx, -16));
         CHECK(es <= ab && ed <= ab, "%s add/sub", ns->name);
         CHECK(em <= ldexp(fabs(da * db), -(int)w + 4) + 0 && er <= ldexp(fabs(1 / da), -(int)w + 4),
               "%s mul/recip %g %g", ns->name, da, db);
      } else if (flt) {
         /* binary32 rounding of the double result, which is exact for +,-,* of floats */
         CHECK(s == (float)(da + db) && d == (float)(da - db) && m == (float)(da * db) &&
               r == (float)(1 / da), "%s ops", ns->name);
      } else {
         CHECK(es == 0 && ed == 0, "%s add/sub exact", ns->name);
         CHECK(em <= q && er <= q, "%s mul %g*%g=%g recip %g", ns->name, da, db, m, r);
      }
      CHECK(st.sat == 0 && st.flush == 0, "%s: no range events inside the range (%g, %g)", ns->name, da, db);
      /* from_scaled: an exact integer n (up to 2^59, the edge functions'
       * size) times 2^-k, rounded as from_float (long double holds n and
       * the difference exactly) */
      {
         int64_t nn = (int64_t)(t_rand() * ldexp(1, 59)) >> (int)(t_rand() * 58);
         if (t_rand() < 0.5)
            nn = -nn;
         if (nn == 0)
            nn = 1;
         int bl = 64 - __builtin_clzll((uint64_t)(nn < 0 ? -nn : nn));
         int k = bl - (int)floor(lo + (hi - lo) * t_rand());   /* |n·2^-k| in [2^lo, 2^hi] */
         if (k < 0) k = 0;
         if (k > 63) k = 63;
         struct ns_stats st2 = { 0, 0 };
         ns_val v = ns->from_scaled(ns, nn, (unsigned)k, &st2);
         CHECK(st2.sat == 0 && st2.flush == 0, "%s from_scaled: a range event", ns->name);
         long double ex = ldexpl((long double)nn, -k);
         double ev = (double)fabsl((long double)val(ns, v) - ex);
         double bound = dfx ? (double)ldexpl(fabsl(ex), -(int)w + 3)
                      : flt ? (double)ldexpl(fabsl(ex), -24) : q;
         CHECK(ev <= bound, "%s from_scaled(%lld, %d): %g off", ns->name, (long long)nn, k, ev);
      }
      /* floor_frac: the integer part and the fraction bits */
      uint32_t frac;
      int64_t ip = ns->floor_frac(ns, a, &frac, 8, &st);
      CHECK(fabs(da) >= 2e9 || ((double)ip == floor(da) && frac == (uint32_t)floor((da - floor(da)) * 256)),
            "%s floor_frac %g: %lld %u", ns->name, da, (long long)ip, frac);
   }
   /* range events */
   struct ns_stats st = { 0, 0 };
   float huge = flt ? 3e38f : dfx ? 1e10f : (float)ldexp(1, ns->fx.int_bits);
   ns_val h = ns->from_float(ns, huge, &st);
   if (!flt)
      CHECK(st.sat == 1, "%s: %g beyond the range is counted", ns->name, huge);
   st.sat = 0;
   ns->mul(ns, h, ns->from_float(ns, 4, &st), &st);
   CHECK(st.sat == 1, "%s: overflowing mul counted (%llu)", ns->name, (unsigned long long)st.sat);
   st.sat = 0;
   ns->recip(ns, ns->from_float(ns, 0, &st), &st);
   CHECK(st.sat == 1, "%s: 1/0 counted", ns->name);
   float tiny = flt ? 1e-40f : dfx ? 1e-11f : (float)ldexp(1, -(int)n - 2);
   ns_val t = ns->from_float(ns, tiny, &st);
   if (!flt)
      CHECK(st.flush == 1 && val(ns, t) == 0, "%s: %g below the range flushes, counted", ns->name, tiny);
   st.flush = 0;
   float small = flt ? 1e-30f : dfx ? 1e-6f : (float)ldexp(1, -(int)n / 2 - 1);
   ns_val sm = ns->from_float(ns, small, &st);
   ns->mul(ns, sm, sm, &st);
   CHECK(st.flush == 1, "%s: underflowing mul counted", ns->name);
}

/* ---- the perspective division on a rendered triangle ---- */

static struct tctx tc;
static double X[3], Y[3], S3[3], OW[3], worst, worst_ratio;
static struct pb_sys psys;

static void hook(struct tctx *t, const struct rast_quad *q)
{
   (void)t;
   double D = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
   int e;
   double delta = frexp(D, &e);          /* det·2^-k, as the model scales it */
   double aw[3] = { S3[0] * OW[0], S3[1] * OW[1], S3[2] * OW[2] };
   for (unsigned i = 0; i < 4; i++) {
      if (!(q->mask & (1u << i)))
         continue;
      double px = q->x + (int)(i & 1) + 0.5, py = q->y + (int)(i >> 1) + 0.5;
      double l1 = ((px - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (py - Y[0])) / D;
      double l2 = ((X[1] - X[0]) * (py - Y[0]) - (px - X[0]) * (Y[1] - Y[0])) / D, l0 = 1 - l1 - l2;
      double ow = l0 * OW[0] + l1 * OW[1] + l2 * OW[2];
      double s = (l0 * aw[0] + l1 * aw[1] + l2 * aw[2]) / ow;
      double err = fabs(q->in[0][0][i] - s);
      if (err > worst)
         worst = err;
      double b = pb_bound(&psys, l1, l2, delta, OW, aw);
      if (isinf(b))
         continue;                       /* beyond the system's range */
      if (err / b > worst_ratio)
         worst_ratio = err / b;
      CHECK(err <= b, "%g at (%g, %g): %g vs %g, bound %g", 1 / OW[2], px, py,
            q->in[0][0][i], s, b);
   }
}

static void wall(const char *fmt, double wr, double *err, struct rast_stats *out)
{
   t_init(&tc, "seed", 1024, 256);
   rast_set_texfmt(tc.rc, numsys_by_name(fmt));
   tc.hook = hook;
   struct rast_vertex_layout vl = t_layout_pos();
   t_layout_add(&vl, RAST_INTERP_PERSPECTIVE, 0x1);
   rast_set_vertex_layout(tc.rc, &vl);
   float v[3][2][4];
   memset(v, 0, sizeof v);
   const double xs[3] = { 10, 10, 1010 }, ys[3] = { 10, 200, 100 }, ws[3] = { 1, 1, wr };
   const double ss[3] = { 0, 0, 1 };
   for (int k = 0; k < 3; k++) {
      v[k][0][0] = (float)xs[k];
      v[k][0][1] = (float)ys[k];
      v[k][0][2] = 0.5f;
      v[k][0][3] = (float)(1 / ws[k]);
      v[k][1][0] = (float)ss[k];
      X[k] = v[k][0][0]; Y[k] = v[k][0][1]; OW[k] = v[k][0][3]; S3[k] = v[k][1][0];
   }
   worst = 0;
   psys = pb_sys_of(numsys_by_name(fmt));
   t_tri(tc.rc, v[0], v[1], v[2]);
   *err = worst;
   *out = *rast_get_stats(tc.rc);
   t_fini(&tc);
}

static void perspective(void)
{
   const char *fmts[] = { "float", "dfx24", "fx8.24", "fx16.16" };
   const double ratios[] = { 100, 1000 };
   double err[2][4];
   struct rast_stats st[2][4];
   for (unsigned r = 0; r < 2; r++)
      for (unsigned f = 0; f < 4; f++) {
         worst_ratio = 0;
         wall(fmts[f], ratios[r], &err[r][f], &st[r][f]);
         printf("w ratio %5g %-8s worst texcoord error %.2e (%6.2f texels of 256), sat %llu, "
                "flush %llu; error/bound where it fits %.3f\n",
                ratios[r], fmts[f], err[r][f], err[r][f] * 256,
                (unsigned long long)st[r][f].tex_sat, (unsigned long long)st[r][f].tex_flush,
                worst_ratio);
         CHECK(st[r][f].pixels_covered > 90000, "the wall is drawn");
         CHECK(worst_ratio > 0, "%s: the bound was checked", fmts[f]);
      }
   for (unsigned r = 0; r < 2; r++)
      CHECK(st[r][1].tex_sat == 0 && st[r][1].tex_flush == 0, "dfx24 counts no range event");
   /* w = 1000 does not fit 8.24 (max 128): saturation, counted, and a
    * larger error than dfx24's */
   CHECK(st[1][2].tex_sat > 0, "fx8.24 must saturate at w ratio 1000");
   CHECK(err[1][2] > err[1][1], "fx8.24 (%g) should be worse than dfx24 (%g)", err[1][2], err[1][1]);
   /* 16.16 flushes b·Δ near the texture's origin (b·0.01 < 2^-17 at ratio
    * 100), and its 16 fraction bits of 1/w lose to dfx24 */
   for (unsigned r = 0; r < 2; r++)
      CHECK(st[r][3].tex_flush > 0 && err[r][3] > err[r][1],
            "fx16.16 must flush and lose to dfx24 at w ratio %g", ratios[r]);
   CHECK(st[0][0].tex_sat == 0 && st[0][0].tex_flush == 0, "float counts no range event");
}

int main(void)
{
   t_seed(77);
   const char *names[] = { "dfx24", "fx16.16", "fx8.24", "fx24.8", "float",
                           "dfx17", "dfx20", "dfx23", "dfx25", "dfx29" };
   for (unsigned i = 0; i < sizeof(names) / sizeof(names[0]); i++) {
      const struct numsys *ns = numsys_by_name(names[i]);
      CHECK(ns && !strcmp(ns->name, names[i]), "numsys_by_name(%s)", names[i]);
      if (ns)
         check_system(ns);
   }
   for (unsigned nn = 17; nn <= 29; nn++) {
      char nm[8];
      snprintf(nm, sizeof nm, "dfx%u", nn);
      const struct numsys *ns = numsys_by_name(nm);
      CHECK(ns && ns->dfx.mant_bits == nn - 5, "%s has a %u-bit mantissa", nm, nn - 5);
   }
   CHECK(numsys_default() == numsys_by_name("dfx24"), "default is dfx24");
   CHECK(!numsys_by_name("dfx30") && !numsys_by_name("fx8.8") && !numsys_by_name(NULL), "unknown names");
   CHECK(strstr(numsys_names(), "fx8.24") != NULL, "names list");
   perspective();
   return t_summary("numsys");
}
