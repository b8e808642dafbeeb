/*
 * Attributes at pixel centres against the exact plane through the
 * fixed-point vertices (barycentrics in double):
 *   Z (raw register):  |err| <= 2 + (rows + columns walked)/2 + |dZ/dx|/4096 ulps
 *                      (each Δ/Δy and ∂/∂x step rounds by at most 1/2 ulp;
 *                      the subpixel correction starts from X_left's floor)
 *   colour (seed, 9.12 walk): the same bound in colour ulps
 *   linear varyings, 1/w: relative error <= 1e-4 of the largest vertex
 *                      magnitude (float walk over <= 256 px)
 *   perspective varyings, in each number system of the texture path
 *                      (rast_set_texfmt: dfx24, dfx29, float, fx8.24, fx16.16,
 *                      fx24.8): the per-pixel bound of the vector method
 *                      (persp_bound.h), from the system's per-operation
 *                      bounds; it does not depend on where the pixel lies in
 *                      its span.  Pixels where the bound on 1/w reaches half
 *                      of it (helpers where 1/w extrapolates through zero)
 *                      have no bound and are counted, not checked.
 * for covered pixels and for helpers (extrapolated values, also on scan
 * lines outside the triangle).  Also: flat inputs take the provoking vertex,
 * COLOR is flat under flatshade, front_facing follows softpipe's rule.
 */
#include <math.h>
#include <string.h>
#include "tutil.h"
#include "fixed/fx.h"
#include "fixed/numsys.h"
#include "persp_bound.h"

static struct tctx t;
static int64_t X[3], Y[3];
static double Zr[3], Cr[3], P[3], L[3], OW[3], flatv;
static bool wide;
static double worst_z, worst_c, worst_p, worst_l, worst_w;
static uint64_t helpers_checked, covered_checked, bad_face;
static bool expect_front;
static double zbound, cbound;
static struct pb_sys psys;
static double worst_pcov, worst_pratio, delta;
static uint64_t p_unbounded;
static struct rast_stats tex_events;
static unsigned sat_tris;

static void bary(double px, double py, double l[3])
{
   double D = (double)(X[1] - X[0]) * (double)(Y[2] - Y[0]) - (double)(X[2] - X[0]) * (double)(Y[1] - Y[0]);
   l[1] = ((px - X[0]) * (double)(Y[2] - Y[0]) - (double)(X[2] - X[0]) * (py - Y[0])) / D;
   l[2] = ((double)(X[1] - X[0]) * (py - Y[0]) - (px - X[0]) * (double)(Y[1] - Y[0])) / D;
   l[0] = 1 - l[1] - l[2];
}

static double clampd(double v, struct fx_format f)
{
   if (v > (double)fx_max(f)) return (double)fx_max(f);
   if (v < (double)fx_min(f)) return (double)fx_min(f);
   return v;
}

static void hook(struct tctx *tc, const struct rast_quad *q)
{
   double S = (double)fx_one(tc->prof->xy), H = S / 2;
   if (q->front_facing != expect_front)
      bad_face++;
   for (unsigned i = 0; i < 4; i++) {
      bool cov = q->mask & (1u << i);
      double px = (q->x + (int)(i & 1)) * S + H, py = (q->y + (int)(i >> 1)) * S + H;
      double l[3];
      bary(px, py, l);
      /* the register clamps at the format's ends (helpers far out) */
      double z = clampd(l[0] * Zr[0] + l[1] * Zr[1] + l[2] * Zr[2], tc->prof->z);
      double ez = fabs((double)q->z[i] - z);
      if (ez > worst_z) worst_z = ez;
      CHECK(ez <= zbound, "Z at (%d,%d) %s: %lld vs %.2f", q->x + (int)(i & 1),
            q->y + (int)(i >> 1), cov ? "covered" : "helper", (long long)q->z[i], z);
      double ow = l[0] * OW[0] + l[1] * OW[1] + l[2] * OW[2];
      double ew = fabs(q->frag_w[i] - ow) / 2.0;
      if (ew > worst_w) worst_w = ew;
      CHECK(ew <= 1e-4, "1/w: %g vs %g", q->frag_w[i], ow);
      double pw = l[0] * P[0] * OW[0] + l[1] * P[1] * OW[1] + l[2] * P[2] * OW[2];
      double pe = fabs(q->in[1][0][i] - pw / ow) / (fabs(pw / ow) > 1 ? fabs(pw / ow) : 1);
      if (pe > worst_p) worst_p = pe;
      if (cov && pe > worst_pcov) worst_pcov = pe;
      double awv[3] = { P[0] * OW[0], P[1] * OW[1], P[2] * OW[2] };
      double pbound = pb_bound(&psys, l[1], l[2], delta, OW, awv);
      double perr = fabs(q->in[1][0][i] - pw / ow);
      if (isinf(pbound)) {
         p_unbounded++;
      } else {
         if (perr / pbound > worst_pratio) worst_pratio = perr / pbound;
         CHECK(perr <= pbound, "perspective at (%d,%d) %s: %.9g vs %.9g, 1/w %g, bound %g",
               q->x + (int)(i & 1), q->y + (int)(i >> 1), cov ? "covered" : "helper",
               q->in[1][0][i], pw / ow, ow, pbound);
      }
      double lv = l[0] * L[0] + l[1] * L[1] + l[2] * L[2];
      double le = fabs(q->in[2][1][i] - lv);
      if (le > worst_l) worst_l = le;
      CHECK(le <= 1e-4, "linear: %g vs %g", q->in[2][1][i], lv);
      CHECK(q->in[3][2][i] == (float)flatv, "flat: %g vs %g", q->in[3][2][i], flatv);
      if (!wide) {
         double c = clampd(l[0] * Cr[0] + l[1] * Cr[1] + l[2] * Cr[2], tc->prof->color);
         double got = q->in[0][0][i] * 255.0 * 4096.0;
         double ec = fabs(got - c);
         if (ec > worst_c) worst_c = ec;
         CHECK(ec <= cbound, "colour at (%d,%d) %s: %g vs %g ulps, bound %g", q->x + (int)(i & 1), q->y + (int)(i >> 1), cov ? "covered" : "helper", got, c, cbound);
      } else {
         /* wide: colour is perspective-correct */
         double cw = l[0] * Cr[0] * OW[0] + l[1] * Cr[1] * OW[1] + l[2] * Cr[2] * OW[2];
         double ce = fabs(q->in[0][0][i] - cw / ow) / (fabs(cw / ow) > 1 ? fabs(cw / ow) : 1);
         if (ce > worst_c) worst_c = ce;
         CHECK(ce <= 1e-4, "wide colour: %g vs %g", q->in[0][0][i], cw / ow);
      }
      if (cov) covered_checked++; else helpers_checked++;
   }
}

static void run(const char *profile, const char *texfmt)
{
   t_init(&t, profile, 1024, 1024);
   rast_set_texfmt(t.rc, numsys_by_name(texfmt));
   psys = pb_sys_of(numsys_by_name(texfmt));
   wide = strcmp(profile, "wide") == 0;
   t.hook = hook;
   struct rast_vertex_layout vl = t_layout_pos();
   t_layout_add(&vl, RAST_INTERP_COLOR, 0x1);
   t_layout_add(&vl, RAST_INTERP_PERSPECTIVE, 0x1);
   t_layout_add(&vl, RAST_INTERP_LINEAR, 0x2);
   t_layout_add(&vl, RAST_INTERP_CONSTANT, 0x4);
   rast_set_vertex_layout(t.rc, &vl);
   struct fx_sat s = { 0, 0 };
   double zfull = (double)((1 << t.prof->z_bits) - 1);

   for (int n = 0; n < 3000; n++) {
      struct rast_raster_state rs;
      memset(&rs, 0, sizeof rs);
      rs.half_pixel_center = true;
      rs.front_ccw = n & 1;
      rs.flatshade_first = (n >> 1) & 1;
      rs.bottom_edge_rule = (n >> 2) & 1;
      rs.line_width = 1;
      rast_set_raster_state(t.rc, &rs);
      double size = 2 + 250 * t_rand() * t_rand();
      double cx = 100 + 800 * t_rand(), cy = 100 + 800 * t_rand();
      float v[3][5][4];
      memset(v, 0, sizeof v);
      /* well-shaped triangles: slivers have gradients beyond the formats
       * (test_saturation covers those) */
      double area;
      do {
         for (int k = 0; k < 3; k++) {
            v[k][0][0] = (float)(cx + size * (t_rand() - 0.5));
            v[k][0][1] = (float)(cy + size * (t_rand() - 0.5));
         }
         area = fabs((double)(v[1][0][0] - v[0][0][0]) * (v[2][0][1] - v[0][0][1]) -
                     (double)(v[2][0][0] - v[0][0][0]) * (v[1][0][1] - v[0][0][1]));
      } while (area < 0.1 * size * size);
      /* depth and colour ranges a triangle of this size can hold in the
       * slope formats (full-scale change within a pixel saturates ∂/∂x) */
      double span = size / 8 < 1 ? size / 8 : 1;
      double zc = span / 2 + (1 - span) * t_rand(), cc = span / 2 + (1 - span) * t_rand();
      for (int k = 0; k < 3; k++) {
         v[k][0][2] = (float)(zc + span * (t_rand() - 0.5));
         float w = (float)(0.5 + 1.5 * t_rand());
         v[k][0][3] = 1.0f / w;
         v[k][1][0] = (float)(cc + span * (t_rand() - 0.5));
         v[k][2][0] = (float)(2 * t_rand() - 1);
         v[k][3][1] = (float)(2 * t_rand() - 1);
         v[k][4][2] = (float)(10 * t_rand());
         X[k] = fx_from_double(t.prof->xy, v[k][0][0], &s);
         Y[k] = fx_from_double(t.prof->xy, v[k][0][1], &s);
         Zr[k] = (double)fx_from_double(t.prof->z, v[k][0][2] * zfull, &s);
         Cr[k] = wide ? v[k][1][0] : (double)fx_from_double(t.prof->color, v[k][1][0] * 255.0, &s);
         P[k] = v[k][2][0];
         L[k] = v[k][3][1];
         OW[k] = v[k][0][3];
      }
      flatv = rs.flatshade_first ? v[0][4][2] : v[2][4][2];
      int64_t det = (X[0] - X[2]) * (Y[1] - Y[2]) - (Y[0] - Y[2]) * (X[1] - X[2]);
      expect_front = ((det < 0) ^ rs.front_ccw) == 0;
      /* bounds from the walk lengths (rows + columns + a quad and a row of helpers) */
      double D = (double)(X[1] - X[0]) * (double)(Y[2] - Y[0]) - (double)(X[2] - X[0]) * (double)(Y[1] - Y[0]);
      double S = (double)fx_one(t.prof->xy);
      double dzdx = fabs(((Zr[1] - Zr[0]) * (double)(Y[2] - Y[0]) - (Zr[2] - Zr[0]) * (double)(Y[1] - Y[0])) / D * S);
      double dcdx = fabs(((Cr[1] - Cr[0]) * (double)(Y[2] - Y[0]) - (Cr[2] - Cr[0]) * (double)(Y[1] - Y[0])) / D * S);
      double walk = 2 * size + 8;
      zbound = 2 + walk / 2 + dzdx / S + 1;
      cbound = 2 + walk / 2 + dcdx / S + 1;
      {
         int e;
         delta = frexp(D, &e);       /* det·2^-k, k = bitlen(|det|) */
      }
      uint64_t sat0 = t_sat_total(rast_get_stats(t.rc));
      t_begin(&t);
      t_tri(t.rc, v[0], v[1], v[2]);
      if (t_sat_total(rast_get_stats(t.rc)) != sat0)
         sat_tris++;
   }

   tex_events = *rast_get_stats(t.rc);
   t_fini(&t);
}

/* Flat COLOR and culling, checked through a separate hook. */
static float seen_color = -1;
static unsigned seen_quads;
static void flat_hook(struct tctx *tc, const struct rast_quad *q)
{
   (void)tc;
   seen_quads++;
   for (unsigned i = 0; i < 4; i++)
      if (q->mask & (1u << i))
         seen_color = q->in[0][0][i];
}

static void flat_and_cull(void)
{
   t_init(&t, "seed", 256, 256);
   t.hook = flat_hook;
   struct rast_vertex_layout vl = t_layout_pos();
   t_layout_add(&vl, RAST_INTERP_COLOR, 0x1);
   rast_set_vertex_layout(t.rc, &vl);
   float v[3][2][4] = {
      { { 10, 10, 0.5f, 1 }, { 0.1f, 0, 0, 0 } },
      { { 10, 90, 0.5f, 1 }, { 0.2f, 0, 0, 0 } },
      { { 90, 10, 0.5f, 1 }, { 0.3f, 0, 0, 0 } },
   };
   /* det = (v0-v2)x(v1-v2) = -6400 < 0 for this order, so softpipe's
    * facing = (det < 0) ^ front_ccw: front with front_ccw, back without. */
   struct rast_raster_state rs;
   memset(&rs, 0, sizeof rs);
   rs.half_pixel_center = true;
   rs.flatshade = true;
   rs.flatshade_first = true;
   rs.cull = RAST_CULL_BACK;
   rs.front_ccw = true;
   rast_set_raster_state(t.rc, &rs);
   seen_quads = 0;
   t_tri(t.rc, v[0], v[1], v[2]);
   CHECK(seen_quads > 0 && seen_color == 0.1f, "flat COLOR, first: %g", seen_color);
   rs.flatshade_first = false;
   rast_set_raster_state(t.rc, &rs);
   t_tri(t.rc, v[0], v[1], v[2]);
   CHECK(seen_color == 0.3f, "flat COLOR, last: %g", seen_color);
   rs.front_ccw = false;
   rast_set_raster_state(t.rc, &rs);
   seen_quads = 0;
   uint64_t culled = rast_get_stats(t.rc)->culled;
   t_tri(t.rc, v[0], v[1], v[2]);
   CHECK(seen_quads == 0 && rast_get_stats(t.rc)->culled == culled + 1, "back face not culled");
   t_tri(t.rc, v[0], v[2], v[1]);
   CHECK(seen_quads > 0, "front face culled");
   t_fini(&t);
}

/* gl_FragCoord's z and w are left out of the quads of a shader that does
 * not read them (a skip, counted per quad): everything else the same, and
 * under RAST_OPT_NOSKIP the same z and w as for a shader that reads them. */
#define FC_MAX 4096
static struct fc_quad { int x, y; unsigned mask; int64_t z[4]; float fz[4], fw[4]; } fc[FC_MAX];
static unsigned fc_n;
static void fc_hook(struct tctx *tc, const struct rast_quad *q)
{
   (void)tc;
   if (fc_n < FC_MAX) {
      struct fc_quad *r = &fc[fc_n];
      r->x = q->x; r->y = q->y; r->mask = q->mask;
      memcpy(r->z, q->z, sizeof(r->z));
      memcpy(r->fz, q->frag_z, sizeof(r->fz));
      memcpy(r->fw, q->frag_w, sizeof(r->fw));
   }
   fc_n++;
}

/* The depth test on, with no depth buffer (it then passes): Z is walked. */
static void set_depth_test(bool on)
{
   struct rast_depth_stencil_state dsa;
   memset(&dsa, 0, sizeof(dsa));
   dsa.depth_enabled = on;
   dsa.depth_func = RAST_FUNC_ALWAYS;
   rast_set_depth_stencil(t.rc, &dsa);
}

static void fragcoord_pass(bool reads, unsigned opts, uint64_t *quads, uint64_t *skipped)
{
   struct rast_shader fs;
   memset(&fs, 0, sizeof(fs));
   fs.ctx = &t;
   fs.shade = t_shade_record;
   fs.may_discard = true;
   fs.reads_fragcoord = reads;
   rast_set_shader(t.rc, &fs);
   rast_set_options(t.rc, opts);
   const struct rast_stats s0 = *rast_get_stats(t.rc);
   fc_n = 0;
   float v[3][1][4] = { { { 10.3f, 7.1f, 0.2f, 1.0f } }, { { 90.6f, 30.2f, 0.7f, 0.25f } },
                        { { 40.2f, 100.9f, 0.9f, 0.5f } } };
   t_tri(t.rc, v[0], v[1], v[2]);
   *quads = rast_get_stats(t.rc)->quads - s0.quads;
   *skipped = rast_get_stats(t.rc)->skip_fragcoord - s0.skip_fragcoord;
}

static void fragcoord_skip(void)
{
   t_init(&t, "seed", 128, 128);
   t.hook = fc_hook;
   set_depth_test(true);   /* Z walked in every pass: only z and w skipped */
   static struct fc_quad want[FC_MAX];
   uint64_t q, sk;
   fragcoord_pass(true, 0, &q, &sk);
   const unsigned n = fc_n;
   CHECK(n > 0 && n <= FC_MAX && q == n && sk == 0, "read: %u quads, %llu skipped", n,
         (unsigned long long)sk);
   memcpy(want, fc, sizeof(want));
   fragcoord_pass(false, 0, &q, &sk);
   CHECK(fc_n == n && sk == q && q == n, "not read: %u quads, %llu skipped", fc_n,
         (unsigned long long)sk);
   for (unsigned i = 0; i < n && i < fc_n; i++)
      CHECK(fc[i].x == want[i].x && fc[i].y == want[i].y && fc[i].mask == want[i].mask &&
               !memcmp(fc[i].z, want[i].z, sizeof(fc[i].z)), "quad %u differs", i);
   fragcoord_pass(false, RAST_OPT_NOSKIP, &q, &sk);
   CHECK(fc_n == n && sk == 0, "noskip: %llu skipped", (unsigned long long)sk);
   CHECK(!memcmp(fc, want, n * sizeof(fc[0])), "noskip: gl_FragCoord's z or w differ");
   t_fini(&t);
}

/* Without a depth test and gl_FragCoord nothing reads Z: neither the edges
 * nor the spans walk it (a skip, counted per quad).  The same quads, masks
 * and inputs; with the depth test, or under RAST_OPT_NOSKIP, the Z walk is
 * back with the same registers; Z's saturation counts only where walked. */
static void z_walk_skip(void)
{
   t_init(&t, "seed", 128, 128);
   t.hook = fc_hook;
   static struct fc_quad want[FC_MAX];
   uint64_t q, sk;
   set_depth_test(true);
   const uint64_t z0 = rast_get_stats(t.rc)->skip_z;
   fragcoord_pass(false, 0, &q, &sk);
   const unsigned n = fc_n;
   CHECK(n > 0 && n <= FC_MAX && rast_get_stats(t.rc)->skip_z == z0, "depth test: Z skipped");
   memcpy(want, fc, sizeof(want));
   set_depth_test(false);
   const uint64_t z1 = rast_get_stats(t.rc)->skip_z;
   fragcoord_pass(false, 0, &q, &sk);
   CHECK(fc_n == n && rast_get_stats(t.rc)->skip_z - z1 == q, "no depth test: %llu of %llu "
         "quads without Z", (unsigned long long)(rast_get_stats(t.rc)->skip_z - z1),
         (unsigned long long)q);
   for (unsigned i = 0; i < n && i < fc_n; i++)
      CHECK(fc[i].x == want[i].x && fc[i].y == want[i].y && fc[i].mask == want[i].mask,
            "quad %u differs", i);
   const uint64_t z2 = rast_get_stats(t.rc)->skip_z;
   fragcoord_pass(false, RAST_OPT_NOSKIP, &q, &sk);
   CHECK(fc_n == n && rast_get_stats(t.rc)->skip_z == z2, "noskip: Z skipped");
   for (unsigned i = 0; i < n && i < fc_n; i++)
      CHECK(!memcmp(fc[i].z, want[i].z, sizeof(fc[i].z)), "noskip: quad %u's Z differs", i);
   /* the interpolators' additions (the cycle model's count) without Z's */
   rast_set_options(t.rc, 0);
   float v[3][1][4] = { { { 10.3f, 7.1f, 0.2f, 1.0f } }, { { 90.6f, 30.2f, 0.7f, 1.0f } },
                        { { 40.2f, 100.9f, 0.9f, 1.0f } } };
   const uint64_t a0 = rast_get_stats(t.rc)->interp_add;
   t_tri(t.rc, v[0], v[1], v[2]);
   const uint64_t a1 = rast_get_stats(t.rc)->interp_add;
   set_depth_test(true);
   t_tri(t.rc, v[0], v[1], v[2]);
   const uint64_t a2 = rast_get_stats(t.rc)->interp_add;
   CHECK(a2 - a1 > a1 - a0, "Z walk's additions: %llu without it, %llu with",
         (unsigned long long)(a1 - a0), (unsigned long long)(a2 - a1));
   t_fini(&t);
}

/* Lines: the vector form on two corners along the line and one across it
 * (Δ2 = 0).  The attribute varies along the major axis only, linearly in
 * A/w and 1/w between the end points, so at a pixel centre c the exact
 * value is (A1w + t·(A2w − A1w)) / (ow1 + t·(ow2 − ow1)), t the major-axis
 * parameter of c.  The tolerance is the triangle bound's order: 64 ulps of
 * the system's mul (values and 1/w within [1/2, 2]). */
static double line_worst;
static double line_ep[2][2], line_ow[2], line_aw[2];
static bool line_xmajor;
static double line_tol;

static void line_hook(struct tctx *tc, const struct rast_quad *q)
{
   (void)tc;
   for (unsigned i = 0; i < 4; i++) {
      if (!(q->mask & (1u << i)))
         continue;
      double c[2] = { q->x + (int)(i & 1) + 0.5, q->y + (int)(i >> 1) + 0.5 };
      unsigned m = line_xmajor ? 0 : 1;
      double tt = (c[m] - line_ep[0][m]) / (line_ep[1][m] - line_ep[0][m]);
      double ow = line_ow[0] + tt * (line_ow[1] - line_ow[0]);
      double p = (line_aw[0] + tt * (line_aw[1] - line_aw[0])) / ow;
      double e = fabs(q->in[1][0][i] - p);
      if (e > line_worst)
         line_worst = e;
      CHECK(e <= line_tol, "line pixel (%g, %g): %.9g vs %.9g", c[0], c[1], q->in[1][0][i], p);
   }
}

static void lines_persp(const char *texfmt)
{
   t_init(&t, "seed", 512, 512);
   rast_set_texfmt(t.rc, numsys_by_name(texfmt));
   struct pb_sys ps = pb_sys_of(numsys_by_name(texfmt));
   line_tol = 64 * ps.relo + 64 * ps.abso;
   t.hook = line_hook;
   struct rast_vertex_layout vl = t_layout_pos();
   t_layout_add(&vl, RAST_INTERP_LINEAR, 0x1);
   t_layout_add(&vl, RAST_INTERP_PERSPECTIVE, 0x1);
   rast_set_vertex_layout(t.rc, &vl);
   struct rast_raster_state rs;
   memset(&rs, 0, sizeof rs);
   rs.half_pixel_center = true;
   rs.line_width = 1;
   rast_set_raster_state(t.rc, &rs);
   line_worst = 0;
   uint64_t px0 = rast_get_stats(t.rc)->pixels_covered;
   for (int n = 0; n < 400; n++) {
      float v[2][3][4];
      memset(v, 0, sizeof v);
      for (int k = 0; k < 2; k++) {
         v[k][0][0] = (float)(20 + 470 * t_rand());
         v[k][0][1] = (float)(20 + 470 * t_rand());
         v[k][0][2] = 0.5f;
         v[k][0][3] = (float)(1 / (0.5 + 1.5 * t_rand()));
         v[k][2][0] = (float)(2 * t_rand() - 1);
         line_ep[k][0] = v[k][0][0];
         line_ep[k][1] = v[k][0][1];
         line_ow[k] = v[k][0][3];
         line_aw[k] = (double)v[k][2][0] * v[k][0][3];
      }
      line_xmajor = fabs(line_ep[1][0] - line_ep[0][0]) >= fabs(line_ep[1][1] - line_ep[0][1]);
      t_begin(&t);
      t_line(t.rc, v[0], v[1]);
   }
   uint64_t px = rast_get_stats(t.rc)->pixels_covered - px0;
   printf("lines, texfmt %-7s perspective: worst %.2e (tolerance %.2e) over %llu pixels\n",
          texfmt, line_worst, line_tol, (unsigned long long)px);
   CHECK(px > 10000, "lines drawn");
   t_fini(&t);
}

static void reset_worst(void)
{
   worst_z = worst_c = worst_p = worst_l = worst_w = 0;
   worst_pcov = worst_pratio = 0;
   p_unbounded = 0;
}

/* The perspective varying in one more number system, on the seed run's
 * triangles: the derived bound where the values fit the system (helpers
 * where 1/w extrapolates to near zero saturate fx8.24's 1/w at 128). */
static void run_system(const char *texfmt)
{
   reset_worst();
   t_seed(4242);
   run("seed", texfmt);
   printf("seed, texfmt %-7s perspective: worst covered %.2e, all %.2e; error/bound %.3f; "
          "%llu helpers unbounded or out of range; sat %llu, flush %llu\n", texfmt, worst_pcov, worst_p,
          worst_pratio, (unsigned long long)p_unbounded,
          (unsigned long long)tex_events.tex_sat, (unsigned long long)tex_events.tex_flush);
   CHECK(worst_pratio > 0, "%s: the perspective varying was checked", texfmt);
}

int main(void)
{
   t_seed(4242);
   run("seed", "dfx24");
   printf("seed: worst Z %.2f ulps, colour %.2f ulps, perspective %.2e (covered %.2e, "
          "error/bound %.3f), linear %.2e, 1/w %.2e\n",
          worst_z, worst_c, worst_p, worst_pcov, worst_pratio, worst_l, worst_w);
   /* dfx24 near its format's precision: a covered pixel's value is a few
    * roundings of terms up to 4 (|A/w| <= 2), 16 to 19 significant bits */
   CHECK(worst_pcov < 4e-4, "dfx24: covered pixels' worst error %g", worst_pcov);
   reset_worst();
   run("wide", "dfx24");
   printf("wide: worst Z %.2f ulps, colour %.2e, perspective %.2e (covered %.2e, "
          "error/bound %.3f), linear %.2e, 1/w %.2e\n",
          worst_z, worst_c, worst_p, worst_pcov, worst_pratio, worst_l, worst_w);
   CHECK(tex_events.tex_sat == 0 && tex_events.tex_flush == 0, "dfx24: a range event");
   const char *systems[] = { "float", "dfx29", "fx8.24", "fx16.16", "fx24.8" };
   for (unsigned i = 0; i < sizeof(systems) / sizeof(systems[0]); i++)
      run_system(systems[i]);
   fragcoord_skip();
   z_walk_skip();
   lines_persp("dfx24");
   lines_persp("float");
   lines_persp("fx8.24");
   printf("triangles with a counted saturation (helpers beyond the format): %u\n", sat_tris);
   printf("pixels checked: %llu covered, %llu helpers\n",
          (unsigned long long)covered_checked, (unsigned long long)helpers_checked);
   CHECK(helpers_checked > 1000, "too few helper pixels checked");
   CHECK(bad_face == 0, "%llu quads with the wrong front_facing", (unsigned long long)bad_face);
   flat_and_cull();
   return t_summary("attrib");
}
