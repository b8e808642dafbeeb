/*
 * The per-pixel error bound of the perspective division (src/rast/interp/persp.c,
 * the vector method), derived from each number system's per-operation
 * bounds (docs/dfx.md, tested in test_dfx.c and test_numsys.c) by first-
 * order propagation through the fixed sequence of operations every pixel
 * makes.  Nothing depends on the pixel's position in a span: no error is
 * carried from one pixel to the next.
 *
 *   a  = from_scaled(a_num, k) · recip(from_scaled(det, k))   (b the same)
 *   Δ  = from_float(v_i) − from_float(v_0)                      (per primitive)
 *   s  = (v_0 + a·Δ1) + b·Δ2                                    (1/w and A/w)
 *   A  = s_A · recip(s_w)
 *
 * An operation with exact result x is off by at most rel·|x| + abs:
 *
 *   system   conversions (nearest)     mul, recip           add, sub
 *   dfxNN    2^-(W-3) |x|              2^-(W-4) |x| (trunc) max(17/16·2^-(W-4), 2^-16) |x|
 *   float    2^-24 |x|                 2^-24 |x|            2^-24 |x|
 *   fxM.N    2^-(N+1)                  2^-(N+1)             exact
 *
 * (dfx: a normalized mantissa has at least W-3 significant bits, so an ulp
 * is at most 2^-(W-4) of the value; the add's 17/16 ulp is its guard digit's
 * bound, 2^-16 the 5-way alignment's for W > 20.)  The vertex values A/w are
 * the float product A·(1/w) of the set-up, 2^-24 off the exact one.  The
 * division is bounded without linearizing it: with s_w off by E_w < |s_w|/2,
 * |s_A'/s_w' − s_A/s_w| <= (E_A + |P|·E_w) / (|s_w| − E_w).  Where E_w is
 * larger (a helper far outside, where 1/w extrapolates through zero) the
 * quotient has no bound and pb_bound returns INFINITY; so it does where a
 * value (a, b, 1/w's reciprocal or the result) lies beyond the system's
 * range, which saturates (counted as tex_sat).
 */
#ifndef FIXPIPE_PERSP_BOUND_H
#define FIXPIPE_PERSP_BOUND_H

#include <math.h>
#include <string.h>
#include "fixed/numsys.h"

struct pb_sys {
   double relc, relo, rela;    /* conversions, mul/recip, add/sub: relative */
   double absc, abso;          /* conversions, mul/recip: absolute */
   double max;                 /* the largest magnitude the system holds */
};

static inline struct pb_sys pb_sys_of(const struct numsys *ns)
{
   struct pb_sys p;
   memset(&p, 0, sizeof p);
   if (ns->dfx.mant_bits) {
      int w = ns->dfx.mant_bits;
      p.relc = ldexp(1, -(w - 3));
      p.relo = ldexp(1, -(w - 4));
      p.rela = fmax(17.0 / 16 * ldexp(1, -(w - 4)), ldexp(1, -16) * 1.001);
      p.absc = p.abso = ldexp(1, -32);          /* flush below 2^-32 */
      p.max = ldexp(1, 32);
   } else if (!strcmp(ns->name, "float")) {
      p.relc = p.relo = p.rela = ldexp(1, -24);
      p.absc = p.abso = 1e-37;                  /* the normal range's end */
      p.max = 3.4e38;
   } else {
      p.absc = p.abso = ldexp(1, -(ns->fx.frac_bits + 1));
      p.max = ldexp(1, ns->fx.int_bits - 1);
   }
   return p;
}

struct pb_plane {
   double s, e;                /* exact value at the pixel, error bound */
};

/* One plane v0 + a·Δ1 + b·Δ2 with exact vertex values v[3]; a, b exact,
 * ea, eb their error bounds. */
static inline struct pb_plane pb_plane(const struct pb_sys *p, const double v[3], double a,
                                       double b, double ea, double eb)
{
   const double fl = ldexp(1, -24);
   double ev[3];
   for (int i = 0; i < 3; i++)
      ev[i] = (p->relc + fl) * fabs(v[i]) + p->absc;
   double d1 = v[1] - v[0], d2 = v[2] - v[0];
   double ed1 = ev[1] + ev[0] + p->rela * fabs(d1);
   double ed2 = ev[2] + ev[0] + p->rela * fabs(d2);
   double t1 = a * d1, t2 = b * d2;
   double et1 = fabs(d1) * ea + fabs(a) * ed1 + p->relo * fabs(t1) + p->abso;
   double et2 = fabs(d2) * eb + fabs(b) * ed2 + p->relo * fabs(t2) + p->abso;
   double s1 = v[0] + t1, s = s1 + t2;
   struct pb_plane r;
   r.s = s;
   r.e = ev[0] + et1 + p->rela * fabs(s1) + et2 + p->rela * fabs(s);
   return r;
}

/* The bound on |A − exact| at a pixel: a, b its exact edge-vector
 * coefficients, delta = det·2^-k (in [1/2, 1) in magnitude), ow[3] and
 * aw[3] the exact vertex values of 1/w and A/w. */
/* How far the computed 1/w and result may lie beyond the exact ones. */
static inline double q_slack(struct pb_plane w, struct pb_plane s, double P)
{
   return (s.e + fabs(P) * w.e) / (fabs(w.s) - w.e) + w.e / (w.s * w.s) * 2;
}

static inline double pb_bound(const struct pb_sys *p, double a, double b, double delta,
                              const double ow[3], const double aw[3])
{
   double r = 1 / delta;
   double ed = p->relc * fabs(delta) + p->absc;
   double er = r * r * ed + p->relo * fabs(r) + p->abso;
   double al = a * delta, be = b * delta;
   double ea = fabs(r) * (p->relc * fabs(al) + p->absc) + fabs(al) * er + p->relo * fabs(a) + p->abso;
   double eb = fabs(r) * (p->relc * fabs(be) + p->absc) + fabs(be) * er + p->relo * fabs(b) + p->abso;
   struct pb_plane w = pb_plane(p, ow, a, b, ea, eb);
   struct pb_plane s = pb_plane(p, aw, a, b, ea, eb);
   if (w.e >= fabs(w.s) / 2)
      return INFINITY;
   double P = s.s / w.s;
   /* a value the system cannot hold saturates (counted): no bound */
   double big = fmax(fmax(fabs(1 / w.s), fabs(P)), fmax(fabs(a), fabs(b)));
   if (big + q_slack(w, s, P) >= p->max)
      return INFINITY;
   double q = (s.e + fabs(P) * w.e) / (fabs(w.s) - w.e);
   double m = fabs(P) + q;
   /* recip and mul round; the output is a binary32 */
   double e = q + 2 * p->relo * m + p->abso * (fabs(s.s) + s.e) + p->abso + ldexp(m, -24);
   return e * 1.01 + 1e-12;
}

#endif
