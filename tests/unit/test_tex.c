/* The texture unit (src/rast/tex*.c) against the float reference sampler of
 * test_tex_ref.h: texel choice, bilinear weights, every wrap mode on
 * coordinates from -2^20 to 2^20, LOD and level selection, cube faces,
 * shadow compare, border colour, texel formats, texelFetch.  The same
 * address sweep is reported for the fixed-point number systems. */
#include <math.h>
#include <string.h>
#include "tutil.h"
#include "test_tex_ref.h"
#include "rast/tex/tex.h"
#include "rast/tex/tex_ns.h"
#include "fixed/numsys.h"

#ifdef FUZZ_TARGET
/* the fuzz build keeps the checks; the unit test's own drivers go unused */
#pragma GCC diagnostic ignored "-Wunused-function"
#endif

static struct ns_stats st;

static const char *wrap_name[TEX_WRAP_COUNT] = {
   "REPEAT", "CLAMP", "CLAMP_TO_EDGE", "CLAMP_TO_BORDER", "MIRRORED_REPEAT",
   "MIRROR_CLAMP", "MIRROR_CLAMP_TO_EDGE", "MIRROR_CLAMP_TO_BORDER",
};

static void view_1level(struct tex_view_desc *v, enum tex_target t, enum tex_format f,
                        const void *data, int w, int h, int d)
{
   memset(v, 0, sizeof(*v));
   v->target = t;
   v->format = f;
   v->num_levels = 1;
   v->layers = t == TEX_TARGET_CUBE ? 6 : d;
   v->level[0].data = data;
   v->level[0].w = w;
   v->level[0].h = h;
   v->level[0].d = d;
   v->level[0].row_stride = (uint32_t)w * (tex_format_bytes(f) ? tex_format_bytes(f) : 4);
   v->level[0].img_stride = v->level[0].row_stride * (uint32_t)h;
   for (unsigned c = 0; c < 4; c++)
      v->swizzle[c] = (uint8_t)c;
}

static void samp_init(struct tex_sampler_desc *s, enum tex_wrap w, enum tex_filter f)
{
   memset(s, 0, sizeof(*s));
   s->wrap[0] = s->wrap[1] = s->wrap[2] = w;
   s->min_filter = s->mag_filter = f;
   s->mip = TEX_MIP_NONE;
   s->normalized = true;
   s->min_lod = -1000;
   s->max_lod = 1000;
}

/* A coordinate spread over [-2^20, 2^20] on a log scale, or near [-2, 2]. */
static double rand_coord(void)
{
   double r = t_rand();
   double sign = t_rand() < 0.5 ? -1.0 : 1.0;
   if (r < 0.4)
      return 4.0 * t_rand() - 2.0;
   return sign * ldexp(1.0 + t_rand(), (int)(t_rand() * 20.0));
}

static struct ref_taps unit_taps(const struct tex_unit *u, enum tex_filter f, ns_val c)
{
   struct tex_addr a;
   struct ref_taps r;
   u->addr[f][0](u, &u->axis[0][0], c, &a);
   if (f == TEX_FILTER_NEAREST) {
      r.n = 1; r.i[0] = a.i0; r.w[0] = 1.0;
   } else {
      r.n = 2; r.i[0] = a.i0; r.i[1] = a.i1;
      r.w[1] = a.w / 256.0; r.w[0] = 1.0 - r.w[1];
   }
   return r;
}

/* The unit's weight precision at texel coordinate u: 8 bits, or the
 * register's own ulp when coarser (a dfx24 mantissa's leading one may sit
 * 3 bits above u's, leaving W - 4 = 15 bits below it). */
static double weight_tol(const struct numsys *ns, int size)
{
   /* the unit's scaled register stays below 2 * size in every mode */
   double lead = floor(log2(2.0 * size));
   if (!strncmp(ns->name, "dfx", 3))
      return 1.0 / 256 + ldexp(1.0, (int)lead + 3 - (ns->dfx.mant_bits - 1)) + 1e-9;
   return 1.0 / 256 + ldexp(1.0, (int)lead - 22) + 1e-9;
}

static bool nearest_tie(double u)
{
   double m = fabs(u) > 1 ? fabs(u) : 1;
   return fabs(u - floor(u + 0.5)) <= m * ldexp(1.0, -14);
}

/* One coordinate c through unit u (wrap w, filter f, one axis of `size`
 * texels in system ns) against the reference on the value the register
 * holds: whether they agree (a disagreement is a failure for `strict`
 * systems); *wrong_orig: whether the unit misses the reference on the
 * application's own coordinate. */
static bool address_matches(const struct tex_unit *u, const struct numsys *ns, enum tex_wrap w,
                            unsigned f, int size, float c, bool strict, bool *wrong_orig)
{
   ns_val h = tex_ns_coord(ns, tex_ns_kind(ns), c, &st);
   double held = ns->to_float(ns, h);
   struct ref_taps got = unit_taps(u, (enum tex_filter)f, h);
   struct ref_taps want = ref_axis(w, f, held, size, true);
   struct ref_taps orig = ref_axis(w, f, c, size, true);
   double tol = f ? weight_tol(ns, size) : 0.0;
   bool tie = !f && nearest_tie(want.u);
   double d = ref_taps_diff(got, want);
   *wrong_orig = !(!f && nearest_tie(orig.u)) && ref_taps_diff(got, orig) > (f ? 2.0 / 256 : 0);
   if (tie || d <= tol)
      return true;
   if (strict)
      CHECK(0, "%s %s %s size %d c %.9g (held %.9g): diff %.5f tol %.5f "
            "got %d,%d w %.4f want %d,%d w %.4f", ns->name, wrap_name[w],
            f ? "LINEAR" : "NEAREST", size, (double)c, held, d, tol,
            got.i[0], got.n > 1 ? got.i[1] : -9, got.n > 1 ? got.w[1] : 0,
            want.i[0], want.n > 1 ? want.i[1] : -9, want.n > 1 ? want.w[1] : 0);
   return false;
}

/* A unit on one 1D RGBA8 level of `size` texels, wrap w, filter f. */
static void bind_1d(struct tex_unit *u, const struct numsys *ns, int size, enum tex_wrap w,
                    enum tex_filter f)
{
   struct tex_view_desc v;
   struct tex_sampler_desc s;
   view_1level(&v, TEX_TARGET_1D, TEX_FMT_RGBA8, NULL, size, 1, 1);
   samp_init(&s, w, f);
   tex_unit_bind(u, ns, &v, &s, &st);
}

/* Every wrap mode x filter x size on coordinates up to 2^20.  On the value
 * the register holds, the unit must agree with the reference (asserted for
 * `strict` systems); against the coordinate the application gave, the
 * mismatches are counted per magnitude bucket and reported. */
static void wrap_sweep(const char *name, bool strict, unsigned n)
{
   const struct numsys *ns = numsys_by_name(name);
   static const int sizes[] = { 1, 2, 3, 5, 16, 100, 256, 1000 };
   unsigned long bad_held = 0, bad_orig[4] = { 0, 0, 0, 0 }, tot[4] = { 0, 0, 0, 0 };
   CHECK(ns != NULL, "%s", name);
   if (!ns)
      return;
   t_seed(7);
   for (unsigned w = 0; w < TEX_WRAP_COUNT; w++)
      for (unsigned f = 0; f < 2; f++)
         for (unsigned si = 0; si < sizeof(sizes) / sizeof(sizes[0]); si++) {
            struct tex_unit u;
            bind_1d(&u, ns, sizes[si], (enum tex_wrap)w, (enum tex_filter)f);
            for (unsigned k = 0; k < n; k++) {
               const float c = (float)rand_coord();
               bool wrong_orig;
               bad_held += !address_matches(&u, ns, (enum tex_wrap)w, f, sizes[si], c, strict,
                                            &wrong_orig);
               double ac = fabs(c);
               unsigned b = ac < 128 ? 0 : ac < 32768 ? 1 : ac < 8388608 ? 2 : 3;
               tot[b]++;
               bad_orig[b] += wrong_orig;
            }
         }
   printf("  %-8s wrong vs held value %6lu | vs app coordinate, |c|<2^7: %lu/%lu  "
          "2^7..2^15: %lu/%lu  2^15..2^20: %lu/%lu\n", name, bad_held, bad_orig[0], tot[0],
          bad_orig[1], tot[1], bad_orig[2] + bad_orig[3], tot[2] + tot[3]);
}

/* Exactly representable coordinates: the unit must match the reference on
 * the application's own value, all the way to 2^20. */
static void wrap_exact_dfx24(void)
{
   const struct numsys *ns = numsys_default();
   static const int sizes[] = { 1, 3, 64, 100, 256 };
   unsigned checked = 0;
   t_seed(11);
   for (unsigned w = 0; w < TEX_WRAP_COUNT; w++)
      for (unsigned f = 0; f < 2; f++)
         for (unsigned si = 0; si < 5; si++) {
            struct tex_unit u;
            bind_1d(&u, ns, sizes[si], (enum tex_wrap)w, (enum tex_filter)f);
            for (int e = -8; e <= 20; e++)
               for (unsigned k = 0; k < 40; k++) {
                  /* 15 significant bits fit any digit alignment of a
                   * 19-bit mantissa */
                  double m = (double)((1 << 14) + (int)(t_rand() * (1 << 14)));
                  double c = ldexp(m, e - 14) * (k & 1 ? -1 : 1);
                  ns_val h = tex_ns_coord(ns, tex_ns_kind(ns), (float)c, &st);
                  CHECK(ns->to_float(ns, h) == c, "representable %.9g", c);
                  struct ref_taps got = unit_taps(&u, (enum tex_filter)f, h);
                  struct ref_taps want = ref_axis((enum tex_wrap)w, f, c, sizes[si], true);
                  if (!f && nearest_tie(want.u))
                     continue;
                  checked++;
                  CHECK(ref_taps_diff(got, want) <= (f ? weight_tol(ns, sizes[si]) : 0.0),
                        "exact %s %s size %d c %.9g", wrap_name[w], f ? "LINEAR" : "NEAREST",
                        sizes[si], c);
               }
         }
   CHECK(checked > 10000, "enough exact cases: %u", checked);
}

/* Weights are the fraction rounded to 8 bits: a coordinate 0.4 of a
 * weight LSB past a step keeps the step's weight, 0.6 past takes the next
 * (carrying into the next texel after 255). */
static void weight_bits(const char *name)
{
   const struct numsys *ns = numsys_by_name(name);
   struct tex_view_desc v;
   struct tex_sampler_desc s;
   struct tex_unit u;
   view_1level(&v, TEX_TARGET_1D, TEX_FMT_RGBA8, NULL, 64, 1, 1);
   samp_init(&s, TEX_WRAP_REPEAT, TEX_FILTER_LINEAR);
   tex_unit_bind(&u, ns, &v, &s, &st);
   static const double extra_lsb[3] = { 0.0, 0.4, 0.6 };
   for (int k = 0; k < 62; k += 7)
      for (int j = 0; j < 256; j++)
         for (int e = 0; e < 3; e++) {
            double uu = k + 0.5 + (j + extra_lsb[e]) / 256.0;
            int want_w = j + (extra_lsb[e] > 0.5), want_i = k;
            if (want_w == 256) { want_w = 0; want_i++; }
            struct tex_addr a;
            u.addr[1][0](&u, &u.axis[0][0], tex_ns_coord(ns, u.kind, (float)(uu / 64), &st), &a);
            CHECK(a.w == (uint32_t)want_w && a.i0 == want_i, "%s u %.6f: w %u want %d, i0 %d want %d",
                  name, uu, a.w, want_w, a.i0, want_i);
         }
}

/* 2D RGBA8 sampling of an NPOT texture vs the reference blend. */
static void sample_2d(void)
{
   enum { W = 37, H = 23 };
   static uint8_t tex[W * H * 4];
   const struct numsys *ns = numsys_default();
   t_seed(3);
   for (unsigned i = 0; i < sizeof(tex); i++)
      tex[i] = (uint8_t)(t_rand() * 256);
   const float border[4] = { 0.25f, 0.5f, 0.75f, 1.0f };
   for (unsigned w = 0; w < TEX_WRAP_COUNT; w++)
      for (unsigned f = 0; f < 2; f++) {
         struct tex_view_desc v;
         struct tex_sampler_desc s;
         struct tex_unit u;
         view_1level(&v, TEX_TARGET_2D, TEX_FMT_RGBA8, tex, W, H, 1);
         samp_init(&s, (enum tex_wrap)w, (enum tex_filter)f);
         memcpy(s.border, border, sizeof(border));
         tex_unit_bind(&u, ns, &v, &s, &st);
         for (unsigned k = 0; k < 400; k++) {
            struct tex_quad q;
            float rgba[4][TEX_QUAD];
            memset(&q, 0, sizeof(q));
            for (unsigned p = 0; p < 4; p++) {
               q.s[p] = (float)(6 * t_rand() - 3);
               q.t[p] = (float)(6 * t_rand() - 3);
            }
            tex_unit_sample(&u, &q, TEX_LOD_ZERO, rgba);
            for (unsigned p = 0; p < 4; p++) {
               struct ref_taps a = ref_axis((enum tex_wrap)w, f, q.s[p], W, true);
               struct ref_taps b = ref_axis((enum tex_wrap)w, f, q.t[p], H, true);
               if (!f && (nearest_tie(a.u) || nearest_tie(b.u)))
                  continue;
               for (unsigned c = 0; c < 4; c++) {
                  double want = 0;
                  for (int i = 0; i < a.n; i++)
                     for (int j = 0; j < b.n; j++) {
                        double texel = (a.i[i] < 0 || b.i[j] < 0) ? border[c]
                                       : tex[(b.i[j] * W + a.i[i]) * 4 + c] / 255.0;
                        want += a.w[i] * b.w[j] * texel;
                     }
                  CHECK(fabs(rgba[c][p] - want) <= (f ? 2.5 / 256 : 1e-6),
                        "2D %s %s (%g,%g) ch %u: %g want %g", wrap_name[w],
                        f ? "LINEAR" : "NEAREST", q.s[p], q.t[p], c, rgba[c][p], want);
               }
            }
         }
      }
}

/* LOD: log2 of the largest scaled derivative within 0.02; level choice. */
/* A 256x256 texture of 9 levels, mipmapped nearest, in system ns. */
static void lod_unit(struct tex_unit *u, const struct numsys *ns)
{
   static uint8_t tex[4];
   struct tex_view_desc v;
   struct tex_sampler_desc s;
   view_1level(&v, TEX_TARGET_2D, TEX_FMT_RGBA8, tex, 256, 256, 1);
   v.num_levels = 9;
   for (unsigned l = 0; l < 9; l++) {
      v.level[l] = v.level[0];
      v.level[l].w = v.level[l].h = 256 >> l;
   }
   samp_init(&s, TEX_WRAP_REPEAT, TEX_FILTER_LINEAR);
   s.mip = TEX_MIP_NEAREST;
   tex_unit_bind(u, ns, &v, &s, &st);
}

/* The quad from s0, t0 and three differences d[] (pixel 3 completes the
 * parallelogram, as the interpolators make it). */
static void lod_quad(struct tex_quad *q, double s0, double t0, const double d[4])
{
   memset(q, 0, sizeof(*q));
   q->s[0] = (float)s0; q->t[0] = (float)t0;
   q->s[1] = (float)(s0 + d[0]); q->t[1] = (float)(t0 + d[1]);
   q->s[2] = (float)(s0 + d[2]); q->t[2] = (float)(t0 + d[3]);
   q->s[3] = q->s[1] + q->s[2] - q->s[0]; q->t[3] = q->t[1] + q->t[2] - q->t[0];
}

/* The unit's LOD of quad q against log2 of the largest scaled difference
 * of the held coordinates on the pixels of the shader's coarse
 * derivatives (x from pixel 2 to 3, y from 2 to 0: tgsi_exec's dFdx and
 * dFdy), within 0.02, and GL's nearest level where the LOD is not within
 * 0.02 of a choice (counted in *levels); returns the error. */
static double lod_check(const struct tex_unit *u, const struct numsys *ns,
                        const struct tex_quad *q, unsigned *levels)
{
   double h[4][2];
   for (unsigned p = 0; p < 4; p++) {
      h[p][0] = ns->to_float(ns, tex_ns_coord(ns, u->kind, q->s[p], &st));
      h[p][1] = ns->to_float(ns, tex_ns_coord(ns, u->kind, q->t[p], &st));
   }
   double rho = 0;
   for (unsigned a = 0; a < 2; a++) {
      rho = fmax(rho, fabs(h[3][a] - h[2][a]) * 256);
      rho = fmax(rho, fabs(h[0][a] - h[2][a]) * 256);
   }
   double ref = log2(rho);
   int32_t lod = tex_lod_quad(u, q);
   double err = fabs(lod / 256.0 - ref);
   CHECK(err <= 0.02, "lod %.4f want %.4f (rho %g)", lod / 256.0, ref, rho);
   /* GL's nearest level: ceil(lod + 1/2) - 1, clamped */
   if (fabs(ref - floor(ref) - 0.5) > 0.02 && fabs(ref - floor(ref + 0.5)) > 0.02) {
      int want = ref <= 0.5 ? 0 : (int)ceil(ref + 0.5) - 1;
      want = want > 8 ? 8 : want;
      unsigned l0, l1;
      uint32_t fr;
      enum tex_filter flt;
      tex_unit_select(u, lod, &l0, &l1, &fr, &flt);
      CHECK((int)l0 == want && l1 == l0, "level %u want %d (lod %.3f)", l0, want, ref);
      (*levels)++;
   }
   return err;
}

static void lod_select(void)
{
   const struct numsys *ns = numsys_default();
   struct tex_unit u;
   lod_unit(&u, ns);
   double worst = 0;
   unsigned lvl_checked = 0;
   t_seed(5);
   for (unsigned k = 0; k < 20000; k++) {
      struct tex_quad q;
      double s0 = t_rand(), t0 = t_rand();
      double d[4];
      for (unsigned i = 0; i < 4; i++)
         d[i] = ldexp((t_rand() < 0.5 ? -1 : 1) * (0.5 + t_rand()), (int)(t_rand() * 16) - 14);
      lod_quad(&q, s0, t0, d);
      if (k & 1) {
         /* not a parallelogram, as a projection makes quads: pixel 3
          * away from where 0, 1 and 2 put it (the LOD is then not the
          * same from every pixel's neighbours) */
         q.s[3] += (float)(d[0] * (t_rand() - 0.5));
         q.t[3] += (float)(d[3] * (t_rand() - 0.5));
      }
      worst = fmax(worst, lod_check(&u, ns, &q, &lvl_checked));
   }
   CHECK(lvl_checked > 10000, "levels checked %u", lvl_checked);
   printf("  LOD: worst |lod - log2(rho)| %.4f over 20000 quads\n", worst);
}

/* Mip selection with explicit LOD, bias and clamps on solid levels. */
static void mip_levels(void)
{
   static uint8_t lv[4][8 * 8 * 4];
   const struct numsys *ns = numsys_default();
   struct tex_view_desc v;
   struct tex_sampler_desc s;
   struct tex_unit u;
   for (unsigned l = 0; l < 4; l++)
      memset(lv[l], 40 + 60 * l, sizeof(lv[l]));
   view_1level(&v, TEX_TARGET_2D, TEX_FMT_RGBA8, lv[0], 8, 8, 1);
   v.num_levels = 4;
   for (unsigned l = 0; l < 4; l++) {
      v.level[l].data = lv[l];
      v.level[l].w = v.level[l].h = 8 >> l;
      v.level[l].row_stride = 4u * (8 >> l);
   }
   struct { enum tex_mip mip; float bias, minl, maxl, lod; double want; } cases[] = {
      { TEX_MIP_LINEAR, 0, -1000, 1000, 1.25f, 0.75 * 100 + 0.25 * 160 },
      { TEX_MIP_LINEAR, 0, -1000, 1000, 7.0f, 220 },
      { TEX_MIP_LINEAR, 0, -1000, 1000, -3.0f, 40 },
      { TEX_MIP_NEAREST, 0, -1000, 1000, 1.5f, 100 },
      { TEX_MIP_NEAREST, 0, -1000, 1000, 1.5f + 1.0f / 256, 160 },
      { TEX_MIP_NEAREST, 0, -1000, 1000, 0.5f, 40 },
      { TEX_MIP_NEAREST, 1.0f, -1000, 1000, 0.75f, 160 },
      { TEX_MIP_NEAREST, 0, 2.0f, 1000, 0.0f, 160 },
      { TEX_MIP_LINEAR, 0, -1000, 1.5f, 3.0f, 0.5 * 100 + 0.5 * 160 },
      { TEX_MIP_NONE, 0, -1000, 1000, 3.0f, 40 },
   };
   for (unsigned k = 0; k < sizeof(cases) / sizeof(cases[0]); k++) {
      samp_init(&s, TEX_WRAP_REPEAT, TEX_FILTER_LINEAR);
      s.mip = cases[k].mip;
      s.lod_bias = cases[k].bias;
      s.min_lod = cases[k].minl;
      s.max_lod = cases[k].maxl;
      tex_unit_bind(&u, ns, &v, &s, &st);
      struct tex_quad q;
      float rgba[4][TEX_QUAD];
      memset(&q, 0, sizeof(q));
      for (unsigned p = 0; p < 4; p++) {
         q.s[p] = 0.3f; q.t[p] = 0.6f; q.lod[p] = cases[k].lod;
      }
      tex_unit_sample(&u, &q, TEX_LOD_EXPLICIT, rgba);
      CHECK(fabs(rgba[0][0] * 255 - cases[k].want) < 1.0, "mip case %u: %g want %g", k,
            rgba[0][0] * 255, cases[k].want);
      /* textureQueryLod: the levels the sample read (level l is 40 + 60 l),
       * and the LOD with the sampler's bias, unclamped */
      float level[TEX_QUAD], lod[TEX_QUAD];
      tex_unit_query_lod(&u, &q, TEX_LOD_EXPLICIT, level, lod);
      CHECK(fabs(40 + 60 * level[0] - cases[k].want) < 1.0, "query lod case %u: level %g, the "
            "sample read %g", k, level[0], cases[k].want);
      CHECK(lod[0] == cases[k].lod + cases[k].bias, "query lod case %u: lod %g, want %g", k,
            lod[0], cases[k].lod + cases[k].bias);
   }
   /* the implicit LOD: the unit's own (2 texels a pixel: 1), biased */
   samp_init(&s, TEX_WRAP_REPEAT, TEX_FILTER_LINEAR);
   s.mip = TEX_MIP_LINEAR;
   s.lod_bias = 0.5f;
   tex_unit_bind(&u, ns, &v, &s, &st);
   struct tex_quad q;
   memset(&q, 0, sizeof(q));
   const float qs[4] = { 0.1f, 0.35f, 0.1f, 0.35f }, qt[4] = { 0.2f, 0.2f, 0.45f, 0.45f };
   memcpy(q.s, qs, sizeof(qs));
   memcpy(q.t, qt, sizeof(qt));
   float level[TEX_QUAD], lod[TEX_QUAD];
   tex_unit_query_lod(&u, &q, TEX_LOD_IMPLICIT, level, lod);
   const float want = (float)tex_lod_quad(&u, &q) / TEX_LOD_ONE + 0.5f;
   for (unsigned p = 0; p < TEX_QUAD; p++)
      CHECK(lod[p] == want && fabs(want - 1.5f) < 0.02f && level[p] == want,
            "query lod implicit pixel %u: lod %g level %g, want %g (about 1.5)", p, lod[p],
            level[p], want);
}

/* textureOffset at the level sampled: on level 1 (4x4) an offset of one
 * texel is a quarter of the coordinate, not the base level's eighth; it
 * wraps as the coordinate does; trilinear moves each level by its own. */
static void offsets_per_level(void)
{
   static uint8_t lv[2][8 * 8 * 4];
   const struct numsys *ns = numsys_default();
   struct tex_view_desc v;
   struct tex_sampler_desc s;
   struct tex_unit u;
   /* red = 16 * x + y on every level: which texel was read */
   for (unsigned l = 0; l < 2; l++)
      for (unsigned y = 0; y < (8u >> l); y++)
         for (unsigned x = 0; x < (8u >> l); x++) {
            uint8_t *t = &lv[l][4 * (y * (8u >> l) + x)];
            t[0] = (uint8_t)(16 * x + y + 128 * l);
            t[1] = t[2] = 0;
            t[3] = 255;
         }
   view_1level(&v, TEX_TARGET_2D, TEX_FMT_RGBA8, lv[0], 8, 8, 1);
   v.num_levels = 2;
   for (unsigned l = 0; l < 2; l++) {
      v.level[l].data = lv[l];
      v.level[l].w = v.level[l].h = 8 >> l;
      v.level[l].row_stride = 4u * (8 >> l);
   }
   samp_init(&s, TEX_WRAP_REPEAT, TEX_FILTER_NEAREST);
   s.mip = TEX_MIP_NEAREST;
   tex_unit_bind(&u, ns, &v, &s, &st);
   struct { float s, t, lod; int8_t off[3]; unsigned want; } cases[] = {
      { 0.3f, 0.6f, 1.0f, { 1, -1, 0 }, 128 + 16 * 2 + 1 },   /* (1, 2) + (1, -1) */
      { 0.9f, 0.1f, 1.0f, { 1, -1, 0 }, 128 + 16 * 0 + 3 },   /* (3, 0) wraps to (0, 3) */
      { 0.3f, 0.6f, 0.0f, { 1, -1, 0 }, 16 * 3 + 3 },         /* base: (2, 4) + (1, -1) */
   };
   for (unsigned k = 0; k < sizeof(cases) / sizeof(cases[0]); k++) {
      struct tex_quad q;
      float rgba[4][TEX_QUAD];
      memset(&q, 0, sizeof(q));
      for (unsigned p = 0; p < 4; p++) {
         q.s[p] = cases[k].s; q.t[p] = cases[k].t; q.lod[p] = cases[k].lod;
      }
      tex_unit_sample_offset(&u, &q, TEX_LOD_EXPLICIT, cases[k].off, rgba);
      CHECK(lroundf(rgba[0][0] * 255) == (long)cases[k].want, "offset case %u: texel %ld want %u",
            k, lroundf(rgba[0][0] * 255), cases[k].want);
   }
   /* no offset: the same bits as the plain sample */
   static const int8_t none[3] = { 0, 0, 0 };
   struct tex_quad q;
   float a[4][TEX_QUAD], b[4][TEX_QUAD];
   memset(&q, 0, sizeof(q));
   for (unsigned p = 0; p < 4; p++) {
      q.s[p] = 0.11f * (float)p; q.t[p] = 0.7f; q.lod[p] = 0.6f;
   }
   tex_unit_sample_offset(&u, &q, TEX_LOD_EXPLICIT, none, a);
   tex_unit_sample(&u, &q, TEX_LOD_EXPLICIT, b);
   CHECK(!memcmp(a, b, sizeof(a)), "a zero offset changes the result");
}

static void cube_faces(void)
{
   const struct numsys *ns = numsys_default();
   struct tex_view_desc v;
   struct tex_sampler_desc s;
   struct tex_unit u;
   view_1level(&v, TEX_TARGET_CUBE, TEX_FMT_RGBA8, NULL, 16, 16, 1);
   samp_init(&s, TEX_WRAP_REPEAT, TEX_FILTER_NEAREST);
   tex_unit_bind(&u, ns, &v, &s, &st);
   unsigned checked = 0;
   t_seed(9);
   for (unsigned k = 0; k < 100000; k++) {
      double r[3];
      for (unsigned a = 0; a < 3; a++)
         r[a] = ldexp(2 * t_rand() - 1, (int)(t_rand() * 20) - 10);
      if (k % 4 == 0)   /* near the cube's edges and corners */
         r[1] = r[0] * (1 + ldexp(2 * t_rand() - 1, -10));
      ns_val h[3], ss, tt;
      double hd[3], rs, rt;
      for (unsigned a = 0; a < 3; a++) {
         h[a] = ns->from_float(ns, (float)r[a], &st);
         hd[a] = ns->to_float(ns, h[a]);
      }
      unsigned want = ref_cube(hd[0], hd[1], hd[2], &rs, &rt);
      unsigned got = tex_cube_face(&u, h[0], h[1], h[2], &ss, &tt);
      double m[3] = { fabs(hd[0]), fabs(hd[1]), fabs(hd[2]) };
      bool tie = (m[0] == m[1] && m[0] >= m[2]) || (m[0] == m[2] && m[0] >= m[1]) ||
                 (m[1] == m[2] && m[1] >= m[0]);
      if (fmax(fmax(m[0], m[1]), m[2]) == 0)
         continue;
      CHECK(got == want || tie, "face %u want %u (%g %g %g)", got, want, hd[0], hd[1], hd[2]);
      if (got == want) {
         checked++;
         CHECK(fabs(ns->to_float(ns, ss) - rs) <= ldexp(1, -13) &&
               fabs(ns->to_float(ns, tt) - rt) <= ldexp(1, -13),
               "face %u coords (%g %g) want (%g %g)", got, ns->to_float(ns, ss),
               ns->to_float(ns, tt), rs, rt);
      }
   }
   CHECK(checked > 90000, "cube cases %u", checked);
}

/* Seamless cube maps: the texel across each edge against GL's face table
 * in floating point (the direction of the tap's centre projected on the
 * cube), and the LINEAR filter on an edge and at a corner of faces of one
 * colour each: half of each face on an edge, a third of each at a corner,
 * where the filter without seams keeps one face's colour. */
static void cube_seamless(void)
{
   static const int32_t sizes[] = { 1, 2, 3, 4, 5, 8, 16 };
   unsigned crossed = 0;
   for (unsigned n = 0; n < sizeof(sizes) / sizeof(sizes[0]); n++) {
      const int32_t N = sizes[n];
      for (unsigned f = 0; f < 6; f++)
         for (int32_t k = -1; k <= N; k++)
            for (unsigned e = 0; e < 4; e++) {
               const int32_t x = e == 0 ? -1 : e == 1 ? N : k;
               const int32_t y = e == 2 ? -1 : e == 3 ? N : k;
               unsigned g;
               int32_t gx, gy;
               const bool corner = (x < 0 || x >= N) && (y < 0 || y >= N);
               const bool got = tex_cube_across(f, N, x, y, &g, &gx, &gy);
               if (corner || (x >= 0 && x < N && y >= 0 && y < N)) {
                  CHECK(!got, "size %d face %u (%d, %d): no texel across", N, f, x, y);
                  continue;
               }
               /* the tap's centre as a direction: GL's table inverted */
               const double S = 2 * x + 1 - N, T = 2 * y + 1 - N, M = N;
               double r[3];
               switch (f) {
               case 0: r[0] = M; r[2] = -S; r[1] = -T; break;
               case 1: r[0] = -M; r[2] = S; r[1] = -T; break;
               case 2: r[1] = M; r[0] = S; r[2] = T; break;
               case 3: r[1] = -M; r[0] = S; r[2] = -T; break;
               case 4: r[2] = M; r[0] = S; r[1] = -T; break;
               default: r[2] = -M; r[0] = -S; r[1] = -T; break;
               }
               double rs, rt;
               const unsigned want = ref_cube(r[0], r[1], r[2], &rs, &rt);
               const int32_t wx = (int32_t)floor(rs * N), wy = (int32_t)floor(rt * N);
               CHECK(got && g == want && g != f && gx == wx && gy == wy,
                     "size %d face %u (%d, %d): face %u (%d, %d), want face %u (%d, %d)", N, f, x,
                     y, g, gx, gy, want, wx, wy);
               crossed++;
            }
   }
   CHECK(crossed == 6 * 4 * (1 + 2 + 3 + 4 + 5 + 8 + 16), "edge taps checked %u", crossed);

   /* faces of one colour each: red channel 40 * face */
   const int32_t N = 4;
   static uint8_t texels[6 * 4 * 4 * 4];
   for (unsigned i = 0; i < sizeof(texels) / 4; i++) {
      texels[4 * i + 0] = (uint8_t)(40 * (i / (N * N)));
      texels[4 * i + 1] = texels[4 * i + 2] = 0;
      texels[4 * i + 3] = 255;
   }
   const struct numsys *ns = numsys_default();
   for (unsigned seamless = 0; seamless < 2; seamless++) {
      struct tex_view_desc v;
      struct tex_sampler_desc s;
      struct tex_unit u;
      view_1level(&v, TEX_TARGET_CUBE, TEX_FMT_RGBA8, texels, N, N, 1);
      samp_init(&s, TEX_WRAP_REPEAT, TEX_FILTER_LINEAR);
      s.seamless_cube = seamless;
      tex_unit_bind(&u, ns, &v, &s, &st);
      struct tex_quad q;
      float rgba[4][TEX_QUAD];
      memset(&q, 0, sizeof(q));
      /* pixel 0 on the edge of +X (face 0) and +Z (4), inside +X by a hair;
       * pixel 1 on the corner of +X, +Y and +Z (faces 0, 2, 4) */
      q.s[0] = 1.0f; q.t[0] = 0.25f; q.r[0] = 0.9999f;
      q.s[1] = q.t[1] = q.r[1] = 1.0f;
      q.s[2] = q.s[3] = 1.0f;
      tex_unit_sample(&u, &q, TEX_LOD_ZERO, rgba);
      const double edge = rgba[0][0] * 255, corner = rgba[0][1] * 255;
      if (seamless) {
         CHECK(fabs(edge - (0 + 160) / 2.0) < 1.5, "seamless edge: red %g, want 80", edge);
         CHECK(fabs(corner - (0 + 80 + 160) / 3.0) < 1.5, "seamless corner: red %g, want 80",
               corner);
      } else {
         CHECK(edge == 0 && corner == 0, "face by face: red %g and %g, want 0 (+X's own)", edge,
               corner);
      }
   }
}

/* Cube map arrays: cube L of the array samples as a cube map made of its
 * six faces does, bit for bit (directions on faces, edges and a corner,
 * seamless and not, NEAREST and LINEAR), the layer coordinate rounded and
 * clamped to the cubes as GL says; a seamless footprint crosses to the
 * faces of its own cube (green is the cube's, 80 L, on every tap). */
static void cube_array(void)
{
   enum { N = 4, CUBES = 3 };
   static uint8_t texels[CUBES * 6 * N * N * 4];
   for (unsigned i = 0; i < sizeof(texels) / 4; i++) {
      const unsigned layer = i / (N * N);
      texels[4 * i + 0] = (uint8_t)(40 * (layer % 6) + (i % 7));
      texels[4 * i + 1] = (uint8_t)(80 * (layer / 6));
      texels[4 * i + 2] = (uint8_t)(i * 13);
      texels[4 * i + 3] = 255;
   }
   const struct numsys *ns = numsys_default();
   static const float layers[] = { -0.7f, 0.4f, 0.5f, 1.2f, 1.49f, 1.5f, 7.0f };
   static const int want_cube[] = { 0, 0, 1, 1, 1, 2, 2 };
   for (unsigned mode = 0; mode < 4; mode++) {
      const bool seamless = mode & 1;
      const enum tex_filter f = mode & 2 ? TEX_FILTER_LINEAR : TEX_FILTER_NEAREST;
      struct tex_sampler_desc s;
      samp_init(&s, TEX_WRAP_REPEAT, f);
      s.seamless_cube = seamless;
      struct tex_view_desc va;
      struct tex_unit ua;
      view_1level(&va, TEX_TARGET_CUBE_ARRAY, TEX_FMT_RGBA8, texels, N, N, 1);
      va.layers = 6 * CUBES;
      tex_unit_bind(&ua, ns, &va, &s, &st);
      for (unsigned k = 0; k < sizeof(layers) / sizeof(layers[0]); k++) {
         const int L = want_cube[k];
         struct tex_view_desc vc;
         struct tex_unit uc;
         view_1level(&vc, TEX_TARGET_CUBE, TEX_FMT_RGBA8, texels + (size_t)L * 6 * N * N * 4, N,
                     N, 1);
         tex_unit_bind(&uc, ns, &vc, &s, &st);
         struct tex_quad q;
         memset(&q, 0, sizeof(q));
         /* an edge of +X and +Z, the corner of +X, +Y, +Z, inside -Y, -Z */
         q.s[0] = 1.0f; q.t[0] = 0.25f; q.r[0] = 0.9999f;
         q.s[1] = q.t[1] = q.r[1] = 1.0f;
         q.s[2] = 0.3f; q.t[2] = -1.0f; q.r[2] = 0.6f;
         q.s[3] = -0.2f; q.t[3] = 0.45f; q.r[3] = -1.0f;
         for (unsigned p = 0; p < TEX_QUAD; p++)
            q.layer[p] = layers[k];
         float ra[4][TEX_QUAD], rc[4][TEX_QUAD];
         tex_unit_sample(&ua, &q, TEX_LOD_ZERO, ra);
         tex_unit_sample(&uc, &q, TEX_LOD_ZERO, rc);
         CHECK(!memcmp(ra, rc, sizeof(ra)), "cube array mode %u layer %g: differs from cube %d "
               "alone", mode, (double)layers[k], L);
         for (unsigned p = 0; p < TEX_QUAD; p++)
            CHECK(fabs(ra[1][p] * 255 - 80 * L) < 0.01, "cube array mode %u layer %g pixel %u: "
                  "green %g, want cube %d's %d", mode, (double)layers[k], p, ra[1][p] * 255, L,
                  80 * L);
      }
   }
}

/* Cube LOD from derivatives (textureCubeGrad, and the implicit LOD, which
 * projects the quad's direction differences the same way): against GL's
 * s = (sc/|ma| + 1)/2 differentiated in double, on directions whose major
 * axis is far from 1 and derivatives along the major axis (where "derivative
 * times size/2" is levels off); and implicit == explicit on the shader's
 * coarse derivatives (pixel 3 - 2, pixel 2 - 0). */
#define CUBE_LEVELS 7
static uint8_t cube_lv[CUBE_LEVELS][64 * 64 * 4 * 6];

static void cube_mip_unit(struct tex_unit *u, const struct numsys *ns)
{
   struct tex_view_desc v;
   struct tex_sampler_desc s;
   view_1level(&v, TEX_TARGET_CUBE, TEX_FMT_RGBA8, cube_lv[0], 64, 64, 1);
   v.num_levels = CUBE_LEVELS;
   for (unsigned l = 0; l < CUBE_LEVELS; l++) {
      memset(cube_lv[l], (int)(30 * l), sizeof(cube_lv[l]));
      v.level[l].data = cube_lv[l];
      v.level[l].w = v.level[l].h = 64 >> l;
      v.level[l].row_stride = 4u * (uint32_t)(64 >> l);
      v.level[l].img_stride = v.level[l].row_stride * (uint32_t)(64 >> l);
   }
   samp_init(&s, TEX_WRAP_CLAMP_TO_EDGE, TEX_FILTER_LINEAR);
   s.mip = TEX_MIP_LINEAR;
   tex_unit_bind(u, ns, &v, &s, &st);
}

/* LOD of each pixel read back from LINEAR_MIPMAP_LINEAR on levels 30 * l. */
static void cube_sampled_lod(const struct tex_unit *u, const struct tex_quad *q,
                             enum tex_lod_control ctl, double lod[TEX_QUAD])
{
   float rgba[4][TEX_QUAD];
   tex_unit_sample(u, q, ctl, rgba);
   for (unsigned p = 0; p < TEX_QUAD; p++)
      lod[p] = rgba[0][p] * 255.0 / 30.0;
}

static double ref_cube_lod(const double r[3], const double gx[3], const double gy[3], int size)
{
   double ax = fabs(r[0]), ay = fabs(r[1]), az = fabs(r[2]);
   unsigned m = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
   double rho = 0;
   for (unsigned k = 0; k < 3; k++) {
      const double *v = k == 0 ? r : k == 1 ? gx : gy;
      double sc, tc, ma;   /* GL's table, applied to v with the face of r */
      switch (m) {
      case 0: ma = v[0]; sc = r[0] >= 0 ? -v[2] : v[2]; tc = -v[1]; break;
      case 1: ma = v[1]; sc = v[0]; tc = r[1] >= 0 ? v[2] : -v[2]; break;
      default: ma = v[2]; sc = r[2] >= 0 ? v[0] : -v[0]; tc = -v[1]; break;
      }
      static double s0, t0, m0;
      if (k == 0) {
         s0 = sc; t0 = tc; m0 = ma;
         continue;
      }
      double dm = m0 < 0 ? -ma : ma, am = fabs(m0);   /* d|ma|, |ma| */
      rho = fmax(rho, fabs((sc - s0 * dm / am) / (2 * am)) * size);
      rho = fmax(rho, fabs((tc - t0 * dm / am) / (2 * am)) * size);
   }
   return log2(rho);
}

static void cube_lod_grads(void)
{
   const char *names[] = { "dfx24", "float" };
   for (unsigned n = 0; n < 2; n++) {
      const struct numsys *ns = numsys_by_name(names[n]);
      struct tex_unit u;
      cube_mip_unit(&u, ns);
      unsigned checked = 0, same = 0, total = 0;
      double worst = 0, worst_ie = 0;
      t_seed(21);
      for (unsigned k = 0; k < 20000; k++) {
         struct tex_quad q;
         memset(&q, 0, sizeof(q));
         double r[3], gx[3], gy[3];
         const double len = ldexp(1.0 + t_rand(), (int)(t_rand() * 8) - 4);
         for (unsigned a = 0; a < 3; a++) {
            r[a] = len * (2 * t_rand() - 1);
            gx[a] = len * ldexp(2 * t_rand() - 1, -(int)(t_rand() * 6) - 2);
            gy[a] = len * ldexp(2 * t_rand() - 1, -(int)(t_rand() * 6) - 2);
         }
         /* explicit: the application's derivatives at each pixel */
         for (unsigned p = 0; p < TEX_QUAD; p++) {
            q.s[p] = (float)r[0]; q.t[p] = (float)r[1]; q.r[p] = (float)r[2];
            for (unsigned a = 0; a < 3; a++) {
               q.ddx[a][p] = (float)gx[a];
               q.ddy[a][p] = (float)gy[a];
            }
         }
         double h[3], hx[3], hy[3];   /* what the registers hold */
         for (unsigned a = 0; a < 3; a++) {
            h[a] = ns->to_float(ns, tex_ns_coord(ns, u.kind, (float)r[a], &st));
            hx[a] = ns->to_float(ns, tex_ns_coord(ns, u.kind, (float)gx[a], &st));
            hy[a] = ns->to_float(ns, tex_ns_coord(ns, u.kind, (float)gy[a], &st));
         }
         double m[3] = { fabs(h[0]), fabs(h[1]), fabs(h[2]) };
         double mx = fmax(fmax(m[0], m[1]), m[2]), mid = m[0] + m[1] + m[2] - mx -
                     fmin(fmin(m[0], m[1]), m[2]);
         const double want = ref_cube_lod(h, hx, hy, 64);
         double lod[TEX_QUAD];
         cube_sampled_lod(&u, &q, TEX_LOD_DERIVS, lod);
         if (mx - mid > 1e-3 * mx && want > 0.1 && want < CUBE_LEVELS - 1.1) {
            double err = fabs(lod[0] - want);
            worst = fmax(worst, err);
            CHECK(err <= 0.02, "%s: cube grad lod %.4f want %.4f", names[n], lod[0], want);
            checked++;
         }

         /* implicit on a quad spanned by the same derivatives (with a
          * perspective-like bend) vs explicit on its coarse differences */
         for (unsigned p = 0; p < TEX_QUAD; p++) {
            const double i = p & 1, j = p >> 1, bend = 1 + 0.05 * i * j;
            q.s[p] = (float)((r[0] + i * gx[0] + j * gy[0]) * bend);
            q.t[p] = (float)((r[1] + i * gx[1] + j * gy[1]) * bend);
            q.r[p] = (float)((r[2] + i * gx[2] + j * gy[2]) * bend);
         }
         const float *co[3] = { q.s, q.t, q.r };
         for (unsigned a = 0; a < 3; a++)
            for (unsigned p = 0; p < TEX_QUAD; p++) {
               q.ddx[a][p] = co[a][3] - co[a][2];
               q.ddy[a][p] = co[a][2] - co[a][0];
            }
         double li[TEX_QUAD], le[TEX_QUAD];
         cube_sampled_lod(&u, &q, TEX_LOD_IMPLICIT, li);
         cube_sampled_lod(&u, &q, TEX_LOD_DERIVS, le);
         for (unsigned p = 0; p < TEX_QUAD; p++) {
            total++;
            same += li[p] == le[p];
            worst_ie = fmax(worst_ie, fabs(li[p] - le[p]));
         }
      }
      CHECK(checked > 10000, "%s: cube grad cases %u", names[n], checked);
      /* float: the same arithmetic on the same values.  dfx24 subtracts
       * registers (each rounded down on input) where the shader subtracted
       * binary32 values: a LOD register LSB or two (1/256) apart, where the
       * other row of the quad would be 0.07 apart (the bend). */
      if (n == 1)
         CHECK(same == total, "float: implicit != explicit on %u of %u pixels", total - same,
               total);
      CHECK(worst_ie <= 2.5 / 256, "%s: implicit vs explicit cube lod %.5f apart", names[n],
            worst_ie);
      printf("  cube LOD from derivatives (%s): worst %.4f over %u; implicit == explicit on "
             "%u of %u pixels, worst %.4f\n", names[n], worst, checked, same, total, worst_ie);
   }
}

/* Depth texels through the driver-style fetch callback. */
static float depth_tex[8 * 8];
static void depth_fetch(const struct tex_view_desc *v, const struct tex_level *lv, int x, int y,
                        int z, float out[4])
{
   (void)v; (void)lv; (void)z;
   out[0] = out[1] = out[2] = depth_tex[y * 8 + x];
   out[3] = 1.0f;
}

/* A w x h depth view of depth_tex (at most 8 x 8). */
static void depth_view(struct tex_view_desc *v, int w, int h)
{
   view_1level(v, TEX_TARGET_2D, TEX_FMT_CALLBACK, NULL, w, h, 1);
   v->fetch = depth_fetch;
   v->depth = true;
}

static bool ref_cmp(enum tex_func f, double r, double d)
{
   switch (f) {
   case TEX_FUNC_NEVER: return false;
   case TEX_FUNC_LESS: return r < d;
   case TEX_FUNC_EQUAL: return r == d;
   case TEX_FUNC_LEQUAL: return r <= d;
   case TEX_FUNC_GREATER: return r > d;
   case TEX_FUNC_NOTEQUAL: return r != d;
   case TEX_FUNC_GEQUAL: return r >= d;
   default: return true;
   }
}

static void shadow(void)
{
   const struct numsys *ns = numsys_default();
   t_seed(13);
   for (unsigned i = 0; i < 64; i++)
      depth_tex[i] = (float)((int)(t_rand() * 8) / 8.0);
   for (unsigned fn = 0; fn < 8; fn++)
      for (unsigned f = 0; f < 2; f++) {
         struct tex_view_desc v;
         struct tex_sampler_desc s;
         struct tex_unit u;
         depth_view(&v, 8, 8);
         samp_init(&s, TEX_WRAP_CLAMP_TO_BORDER, (enum tex_filter)f);
         s.compare = true;
         s.func = (enum tex_func)fn;
         s.border[0] = 0.5f;
         tex_unit_bind(&u, ns, &v, &s, &st);
         for (unsigned k = 0; k < 500; k++) {
            struct tex_quad q;
            float rgba[4][TEX_QUAD];
            memset(&q, 0, sizeof(q));
            for (unsigned p = 0; p < 4; p++) {
               q.s[p] = (float)(1.4 * t_rand() - 0.2);
               q.t[p] = (float)(1.4 * t_rand() - 0.2);
               q.ref[p] = (float)((int)(t_rand() * 9) / 8.0);
            }
            tex_unit_sample(&u, &q, TEX_LOD_ZERO, rgba);
            for (unsigned p = 0; p < 4; p++) {
               struct ref_taps a = ref_axis(TEX_WRAP_CLAMP_TO_BORDER, f, q.s[p], 8, true);
               struct ref_taps b = ref_axis(TEX_WRAP_CLAMP_TO_BORDER, f, q.t[p], 8, true);
               if (!f && (nearest_tie(a.u) || nearest_tie(b.u)))
                  continue;
               double want = 0;
               for (int i = 0; i < a.n; i++)
                  for (int j = 0; j < b.n; j++) {
                     double d = (a.i[i] < 0 || b.i[j] < 0) ? 0.5 : depth_tex[b.i[j] * 8 + a.i[i]];
                     want += a.w[i] * b.w[j] * (ref_cmp((enum tex_func)fn, q.ref[p], d) ? 1 : 0);
                  }
               CHECK(fabs(rgba[0][p] - want) <= (f ? 2.5 / 256 : 0) && rgba[3][p] == 1.0f,
                     "shadow func %u %s (%g,%g) ref %g: %g want %g", fn, f ? "LINEAR" : "NEAREST",
                     q.s[p], q.t[p], q.ref[p], rgba[0][p], want);
            }
         }
      }
}

static void border_colour(void)
{
   static uint8_t tex[4 * 4 * 4];
   const float border[4] = { 0.1f, 0.2f, 0.3f, 0.4f };
   memset(tex, 255, sizeof(tex));
   for (unsigned f = 0; f < 2; f++) {
      struct tex_view_desc v;
      struct tex_sampler_desc s;
      struct tex_unit u;
      view_1level(&v, TEX_TARGET_2D, TEX_FMT_RGBA8, tex, 4, 4, 1);
      samp_init(&s, TEX_WRAP_CLAMP_TO_BORDER, (enum tex_filter)f);
      memcpy(s.border, border, sizeof(border));
      tex_unit_bind(&u, numsys_default(), &v, &s, &st);
      struct tex_quad q;
      float rgba[4][TEX_QUAD];
      memset(&q, 0, sizeof(q));
      q.s[0] = -0.5f; q.t[0] = 0.5f;          /* outside: the border */
      q.s[1] = 0.5f; q.t[1] = 1.75f;
      q.s[2] = 0.0f; q.t[2] = 0.5f;           /* on the edge: half border (linear) */
      q.s[3] = 0.5f; q.t[3] = 0.5f;           /* inside */
      tex_unit_sample(&u, &q, TEX_LOD_ZERO, rgba);
      for (unsigned c = 0; c < 4; c++) {
         CHECK(rgba[c][0] == border[c] && rgba[c][1] == border[c], "border ch %u", c);
         double edge = f ? 0.5 * border[c] + 0.5 : 1.0;
         CHECK(fabs(rgba[c][2] - edge) < 1e-6, "edge ch %u %s: %g want %g", c,
               f ? "LINEAR" : "NEAREST", rgba[c][2], edge);
         CHECK(rgba[c][3] == 1.0f, "inside ch %u", c);
      }
   }
}

static void formats(void)
{
   static const struct { enum tex_format f; uint8_t b[4]; float want[4]; } cases[] = {
      { TEX_FMT_RGBA8, { 255, 0, 51, 102 }, { 1, 0, 0.2f, 0.4f } },
      { TEX_FMT_RGBX8, { 255, 0, 51, 102 }, { 1, 0, 0.2f, 1 } },
      { TEX_FMT_BGRA8, { 255, 0, 51, 102 }, { 0.2f, 0, 1, 0.4f } },
      { TEX_FMT_BGRX8, { 255, 0, 51, 102 }, { 0.2f, 0, 1, 1 } },
      { TEX_FMT_L8, { 51 }, { 0.2f, 0.2f, 0.2f, 1 } },
      { TEX_FMT_A8, { 51 }, { 0, 0, 0, 0.2f } },
      { TEX_FMT_I8, { 51 }, { 0.2f, 0.2f, 0.2f, 0.2f } },
      { TEX_FMT_R8, { 51 }, { 0.2f, 0, 0, 1 } },
      { TEX_FMT_LA8, { 51, 102 }, { 0.2f, 0.2f, 0.2f, 0.4f } },
      /* 0xF800 little endian: R = 31 */
      { TEX_FMT_B5G6R5, { 0x00, 0xF8 }, { 1, 0, 0, 1 } },
      { TEX_FMT_B5G6R5, { 0x1F, 0x00 }, { 0, 0, 1, 1 } },
      { TEX_FMT_A4B4G4R4, { 0x0F, 0xF0 }, { 1, 0, 0, 1 } },
      { TEX_FMT_B4G4R4A4, { 0x0F, 0xF0 }, { 0, 0, 1, 1 } },
      { TEX_FMT_A1B5G5R5, { 0x01, 0xF8 }, { 1, 0, 0, 1 } },
      { TEX_FMT_B5G5R5A1, { 0x00, 0x80 }, { 0, 0, 0, 1 } },
      { TEX_FMT_B5G5R5A1, { 0xE0, 0x03 }, { 0, 1, 0, 0 } },
   };
   for (unsigned k = 0; k < sizeof(cases) / sizeof(cases[0]); k++) {
      struct tex_view_desc v;
      float out[4];
      view_1level(&v, TEX_TARGET_2D, cases[k].f, cases[k].b, 1, 1, 1);
      tex_format_fetch(cases[k].f)(&v, &v.level[0], 0, 0, 0, out);
      for (unsigned c = 0; c < 4; c++)
         CHECK(fabs(out[c] - cases[k].want[c]) < 1e-6, "format case %u ch %u: %g want %g", k, c,
               out[c], cases[k].want[c]);
   }
}

static void texel_fetch_and_swizzle(void)
{
   static uint8_t tex[3 * 2 * 4];
   struct tex_view_desc v;
   float rgba[4][TEX_QUAD];
   for (unsigned i = 0; i < sizeof(tex); i++)
      tex[i] = (uint8_t)(i * 10);
   view_1level(&v, TEX_TARGET_2D, TEX_FMT_RGBA8, tex, 3, 2, 1);
   v.swizzle[0] = 2; v.swizzle[1] = TEX_SWZ_1; v.swizzle[2] = TEX_SWZ_0; v.swizzle[3] = 0;
   const int x[4] = { 2, 3, 0, 1 }, y[4] = { 1, 0, -1, 0 }, z[4] = { 0, 0, 0, 0 };
   const int l[4] = { 0, 0, 0, 1 };
   tex_view_texel(&v, x, y, z, l, rgba);
   /* texel (2,1) = bytes 20..23 -> 200, 210, 220, 230 */
   CHECK(fabs(rgba[0][0] - 220 / 255.0) < 1e-6 && rgba[1][0] == 1 && rgba[2][0] == 0 &&
         fabs(rgba[3][0] - 200 / 255.0) < 1e-6, "texelFetch + swizzle");
   for (unsigned p = 1; p < 4; p++)
      CHECK(rgba[0][p] == 0 && rgba[3][p] == 0 && rgba[1][p] == 1, "out of range %u", p);
}

/* Min/max reduction (ARB_texture_filter_minmax): LINEAR on a level gives
 * the least or greatest tap among those with a nonzero weight, per
 * channel, against a reference that lists the footprint's texels itself;
 * coordinates a quarter texel apart (weights 0, 64, 128, 192 exactly),
 * 2-D and 3-D; and with two mip levels, the least or greatest of the two
 * levels' results, as the reduction takes every texel with a nonzero
 * weight (D3D's and llvmpipe's reading; the LOD's fraction is not 0). */
static void reduction_minmax(void)
{
   enum { N = 8 };
   static uint8_t texels[N * N * N * 4], lv1[(N / 2) * (N / 2) * 4];
   for (unsigned i = 0; i < sizeof(texels); i++)
      texels[i] = (uint8_t)(t_rand() * 256);
   for (unsigned i = 0; i < sizeof(lv1); i++)
      lv1[i] = (uint8_t)(t_rand() * 256);
   const struct numsys *ns = numsys_default();
   unsigned checked = 0;
   for (unsigned dims = 2; dims <= 3; dims++)
      for (unsigned r = TEX_REDUCE_MIN; r <= TEX_REDUCE_MAX; r++) {
         struct tex_view_desc v;
         struct tex_sampler_desc sd;
         struct tex_unit u;
         view_1level(&v, dims == 3 ? TEX_TARGET_3D : TEX_TARGET_2D, TEX_FMT_RGBA8, texels, N, N,
                     dims == 3 ? N : 1);
         samp_init(&sd, TEX_WRAP_CLAMP_TO_EDGE, TEX_FILTER_LINEAR);
         sd.reduction = (enum tex_reduction)r;
         tex_unit_bind(&u, ns, &v, &sd, &st);
         for (unsigned k = 0; k < 200; k++) {
            int i[3], q[3];
            struct tex_quad quad;
            memset(&quad, 0, sizeof(quad));
            for (unsigned a = 0; a < 3; a++) {
               i[a] = (int)(t_rand() * (N - 1));
               q[a] = (int)(t_rand() * 4);
            }
            /* texel space i + q/4 is coordinate (i + 1/2 + q/4) / N */
            quad.s[0] = (i[0] + 0.5f + q[0] * 0.25f) / N;
            quad.t[0] = (i[1] + 0.5f + q[1] * 0.25f) / N;
            quad.r[0] = (i[2] + 0.5f + q[2] * 0.25f) / N;
            for (unsigned p = 1; p < TEX_QUAD; p++) {
               quad.s[p] = quad.s[0];
               quad.t[p] = quad.t[0];
               quad.r[p] = quad.r[0];
            }
            float rgba[4][TEX_QUAD];
            tex_unit_sample(&u, &quad, TEX_LOD_ZERO, rgba);
            for (unsigned c = 0; c < 4; c++) {
               int want = r == TEX_REDUCE_MIN ? 256 : -1;
               for (int dz = 0; dz <= (dims == 3 && q[2] ? 1 : 0); dz++)
                  for (int dy = 0; dy <= (q[1] ? 1 : 0); dy++)
                     for (int dx = 0; dx <= (q[0] ? 1 : 0); dx++) {
                        const int z = dims == 3 ? i[2] + dz : 0;
                        const int t = texels[4 * ((z * N + i[1] + dy) * N + i[0] + dx) + c];
                        want = r == TEX_REDUCE_MIN ? (t < want ? t : want) : (t > want ? t : want);
                     }
               CHECK(fabs(rgba[c][0] * 255 - want) < 1e-3, "%s %uD at %d+%d/4 %d+%d/4: ch %u %g, "
                     "want %d", r == TEX_REDUCE_MIN ? "min" : "max", dims, i[0], q[0], i[1], q[1],
                     c, rgba[c][0] * 255, want);
               checked++;
            }
         }
         if (dims != 2)
            continue;
         /* two levels: each level reduced, then the two reduced again */
         v.num_levels = 2;
         v.level[1].data = lv1;
         v.level[1].w = v.level[1].h = N / 2;
         v.level[1].row_stride = 4 * (N / 2);
         sd.mip = TEX_MIP_LINEAR;
         struct tex_unit um, u0, u1;
         tex_unit_bind(&um, ns, &v, &sd, &st);
         sd.min_lod = sd.max_lod = 0.0f;
         tex_unit_bind(&u0, ns, &v, &sd, &st);
         sd.min_lod = sd.max_lod = 1.0f;
         tex_unit_bind(&u1, ns, &v, &sd, &st);
         struct tex_quad quad;
         memset(&quad, 0, sizeof(quad));
         for (unsigned p = 0; p < TEX_QUAD; p++) {
            quad.s[p] = 0.37f + 0.05f * (float)p;
            quad.t[p] = 0.61f - 0.03f * (float)p;
            quad.lod[p] = 0.25f + 0.125f * (float)p;
         }
         float m[4][TEX_QUAD], a0[4][TEX_QUAD], a1[4][TEX_QUAD];
         tex_unit_sample(&um, &quad, TEX_LOD_EXPLICIT, m);
         tex_unit_sample(&u0, &quad, TEX_LOD_EXPLICIT, a0);
         tex_unit_sample(&u1, &quad, TEX_LOD_EXPLICIT, a1);
         for (unsigned p = 0; p < TEX_QUAD; p++)
            for (unsigned c = 0; c < 4; c++) {
               const float want = r == TEX_REDUCE_MIN ? fminf(a0[c][p], a1[c][p])
                                                      : fmaxf(a0[c][p], a1[c][p]);
               CHECK(fabsf(m[c][p] - want) < 1e-5f, "%s mip pixel %u ch %u: %g, want %g",
                     r == TEX_REDUCE_MIN ? "min" : "max", p, c, m[c][p], want);
            }
      }
   CHECK(checked == 2 * 2 * 200 * 4, "reduction checks %u", checked);
}

/* A texture buffer: one row of texels, by index alone; the row and the
 * layer must be zero (the glue passes zero), indices outside the row read
 * zero before the swizzle. */
static void texel_fetch_buffer(void)
{
   static uint8_t buf[5 * 4 * 4];   /* room for the rows the level claims */
   struct tex_view_desc v;
   float rgba[4][TEX_QUAD];
   for (unsigned i = 0; i < sizeof(buf); i++)
      buf[i] = (uint8_t)(i * 12 + 3);
   view_1level(&v, TEX_TARGET_BUFFER, TEX_FMT_RGBA8, buf, 5, 1, 1);
   v.level[0].h = 4;   /* a row whatever the level says: y past 0 reads zero */
   const int x[4] = { 4, 5, -1, 1 }, y[4] = { 0, 0, 0, 1 }, z[4] = { 0, 0, 0, 0 };
   const int l[4] = { 0, 0, 0, 0 };
   tex_view_texel(&v, x, y, z, l, rgba);
   for (unsigned c = 0; c < 4; c++)
      CHECK(fabs(rgba[c][0] - ((16 + c) * 12 + 3) / 255.0) < 1e-6, "buffer texel 4 ch %u: %g",
            c, rgba[c][0]);
   for (unsigned p = 1; p < 4; p++)
      for (unsigned c = 0; c < 4; c++)
         CHECK(rgba[c][p] == 0, "buffer fetch %u outside the row reads %g", p, rgba[c][p]);
}

#ifdef FUZZ_TARGET
/* libFuzzer (tests/fuzz, ./fixpipe fuzz): the unit's addressing and LOD on
 * the input's bytes, in the systems the unit test holds to the reference
 * (dfx24, float).  Byte 0: the system and what to check; addressing: a
 * wrap mode, a filter, a size of 1 to 4096 texels and any finite binary32
 * coordinate below 2^24; LOD: a quad at s0, t0 in [0, 1) with differences
 * of 2^-14 to 2^2 (the range the unit test's bound is stated for).  A
 * failed check aborts. */
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
   if (size < 4 + 6 * 4)
      return 0;
   const struct numsys *ns = numsys_by_name(data[0] & 1 ? "float" : "dfx24");
   uint32_t word[6];
   memcpy(word, data + 4, sizeof(word));
   if (data[0] & 2) {
      struct tex_unit u;
      lod_unit(&u, ns);
      double d[4];
      for (unsigned i = 0; i < 4; i++)
         d[i] = ldexp((word[i] & 1 ? -1 : 1) * (0.5 + (word[i] >> 1) * 0x1p-31),
                      (int)(word[i] >> 28) - 14);
      struct tex_quad q;
      lod_quad(&q, word[4] * 0x1p-32, word[5] * 0x1p-32, d);
      unsigned levels = 0;
      lod_check(&u, ns, &q, &levels);
   } else {
      const enum tex_wrap w = (enum tex_wrap)(data[1] % TEX_WRAP_COUNT);
      const unsigned f = data[2] & 1;
      const int texels = 1 + (int)((data[3] | (unsigned)data[2] << 7) % 4096);
      float c;
      memcpy(&c, &word[0], sizeof(c));
      if (!isfinite(c) || fabsf(c) >= 0x1p24f)
         return 0;
      struct tex_unit u;
      bind_1d(&u, ns, texels, w, (enum tex_filter)f);
      bool wrong_orig;
      address_matches(&u, ns, w, f, texels, c, true, &wrong_orig);
   }
   if (t_failures)
      abort();
   return 0;
}
#else
/* Coordinates in [-1, 0) a hair below and above each texel boundary, under
 * REPEAT and MIRRORED_REPEAT: the fraction 1 + c would round to the
 * register's coarser grid near 1 and cross the boundary (a libFuzzer
 * finding: dfx24, 64 texels, c = -0.0156265628 sampled texel 63, not 62;
 * tests/fuzz/corpus/tex/repeat-negative-fraction).  Both number systems
 * must agree with the reference on every one. */
static void negative_fractions(void)
{
   static const int sizes[] = { 3, 64, 100, 4096 };
   static const enum tex_wrap wraps[] = { TEX_WRAP_REPEAT, TEX_WRAP_MIRROR_REPEAT };
   static const char *const systems[] = { "dfx24", "float" };
   unsigned long checked = 0, bad = 0;
   for (unsigned n = 0; n < 2; n++) {
      const struct numsys *ns = numsys_by_name(systems[n]);
      for (unsigned w = 0; w < 2; w++)
         for (unsigned f = 0; f < 2; f++)
            for (unsigned si = 0; si < sizeof(sizes) / sizeof(sizes[0]); si++) {
               struct tex_unit u;
               bind_1d(&u, ns, sizes[si], wraps[w], (enum tex_filter)f);
               for (int k = 1; k <= sizes[si]; k++) {
                  const float b = (float)(-(double)k / sizes[si]) - (f ? 0.5f / sizes[si] : 0);
                  /* below the boundary by 0.55 to 0.95 of dfx24's grid near 1 (2^-19):
                   * beyond the reference's tie allowance (2^-14 texel) where the
                   * texture has more than about 60 texels */
                  float near[6];
                  for (unsigned j = 0; j < 5; j++)
                     near[j] = (float)(b - (0.55 + 0.1 * j) * 0x1p-19);
                  near[5] = nextafterf(b, 0);
                  for (unsigned j = 0; j < 6; j++) {
                     if (!(near[j] >= -1 && near[j] < 0))
                        continue;
                     bool wrong_orig;
                     bad += !address_matches(&u, ns, wraps[w], f, sizes[si], near[j], true,
                                             &wrong_orig);
                     checked++;
                  }
               }
            }
   }
   printf("  coordinates in [-1, 0) beside texel boundaries: %lu checked, %lu wrong\n",
          checked, bad);
   CHECK(checked > 30000, "only %lu checked", checked);
}

/* textureGather: on a texture whose texel (x, y) holds x in red and y in
 * green, gathering red and green gives the footprint's indices, which must
 * be the reference LINEAR taps of each axis in GL's order, (i0, j1),
 * (i1, j1), (i1, j0), (i0, j0), with i0 = wrap(floor(u - 1/2)) before the
 * wrap reorders them (mirrored periods), and the border where the taps
 * leave a border mode's texture.  Coordinates within a weight step of a
 * texel boundary, where the unit rounds to the nearer footprint (its
 * weight 0 there for the filter), are left out.  A depth view
 * gathers the comparison of each tap. */
static void gather(void)
{
   static const enum tex_wrap wraps[] = { TEX_WRAP_REPEAT, TEX_WRAP_CLAMP_TO_EDGE,
                                          TEX_WRAP_CLAMP_TO_BORDER, TEX_WRAP_MIRROR_REPEAT,
                                          TEX_WRAP_MIRROR_CLAMP_TO_EDGE };
   static const int sizes[][2] = { { 8, 8 }, { 13, 7 }, { 1, 5 }, { 64, 3 } };
   static uint8_t tex[64 * 8 * 4];
   const struct numsys *ns = numsys_by_name("dfx24");
   unsigned checked = 0, swapped = 0;
   for (unsigned wi = 0; wi < sizeof(wraps) / sizeof(wraps[0]); wi++)
      for (unsigned si = 0; si < sizeof(sizes) / sizeof(sizes[0]); si++) {
         const int W = sizes[si][0], H = sizes[si][1];
         for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
               uint8_t *t = &tex[(y * W + x) * 4];
               t[0] = (uint8_t)x; t[1] = (uint8_t)y; t[2] = 7; t[3] = 255;
            }
         struct tex_view_desc v;
         struct tex_sampler_desc sd;
         struct tex_unit u;
         view_1level(&v, TEX_TARGET_2D, TEX_FMT_RGBA8, tex, W, H, 1);
         samp_init(&sd, wraps[wi], TEX_FILTER_NEAREST);   /* gather ignores the filter */
         sd.border[0] = sd.border[1] = 200.0f / 255.0f;
         tex_unit_bind(&u, ns, &v, &sd, &st);
         for (int n = 0; n < 400; n++) {
            struct tex_quad q;
            memset(&q, 0, sizeof(q));
            for (unsigned p = 0; p < TEX_QUAD; p++) {
               q.s[p] = (float)(t_rand() * 5.0 - 2.0);
               q.t[p] = (float)(t_rand() * 5.0 - 2.0);
            }
            float r[4][TEX_QUAD], g[4][TEX_QUAD];
            tex_unit_gather(&u, &q, 0, r);
            tex_unit_gather(&u, &q, 1, g);
            for (unsigned p = 0; p < TEX_QUAD; p++) {
               struct ref_taps a = ref_axis(wraps[wi], true, q.s[p], W, true);
               struct ref_taps b = ref_axis(wraps[wi], true, q.t[p], H, true);
               /* the footprint is the filter's: decided on the weight
                * grid (2^-TEX_WEIGHT_BITS texel), rounded to nearest */
               const double near = 1.0 / TEX_WEIGHT_ONE + 1e-4;
               if (fabs(a.u - floor(a.u + 0.5)) < near || fabs(b.u - floor(b.u + 0.5)) < near)
                  continue;
               const int ix[4] = { a.i[0], a.i[1], a.i[1], a.i[0] };
               const int iy[4] = { b.i[1], b.i[1], b.i[0], b.i[0] };
               swapped += a.i[0] > a.i[1] || b.i[0] > b.i[1];
               for (unsigned k = 0; k < 4; k++) {
                  const bool border = ix[k] < 0 || iy[k] < 0;
                  const int want_x = border ? 200 : ix[k], want_y = border ? 200 : iy[k];
                  const int got_x = (int)lrintf(r[k][p] * 255.0f);
                  const int got_y = (int)lrintf(g[k][p] * 255.0f);
                  CHECK(got_x == want_x && got_y == want_y,
                        "gather %s %dx%d (s, t) = (%.6f, %.6f) texel %u: got (%d, %d) want (%d, %d)",
                        wrap_name[wraps[wi]], W, H, (double)q.s[p], (double)q.t[p], k, got_x,
                        got_y, want_x, want_y);
               }
               checked++;
            }
         }
      }
   /* a depth view: each tap compared, 1 where ref <= depth */
   for (int i = 0; i < 16; i++)
      depth_tex[i / 4 * 8 + i % 4] = (float)i / 16.0f;
   struct tex_view_desc v;
   struct tex_sampler_desc sd;
   struct tex_unit u;
   depth_view(&v, 4, 4);
   samp_init(&sd, TEX_WRAP_CLAMP_TO_EDGE, TEX_FILTER_NEAREST);
   sd.compare = true;
   sd.func = TEX_FUNC_LEQUAL;
   tex_unit_bind(&u, ns, &v, &sd, &st);
   struct tex_quad q;
   memset(&q, 0, sizeof(q));
   for (unsigned p = 0; p < TEX_QUAD; p++) {
      q.s[p] = 0.5f;     /* u = 2: taps x 1 and 2 */
      q.t[p] = 0.5f;     /* rows 1 and 2 */
      q.ref[p] = (float)(4 + 2 * p) / 16.0f;
   }
   float c[4][TEX_QUAD];
   tex_unit_gather(&u, &q, 2, c);
   for (unsigned p = 0; p < TEX_QUAD; p++) {
      const int tx[4] = { 1, 2, 2, 1 }, ty[4] = { 2, 2, 1, 1 };
      for (unsigned k = 0; k < 4; k++) {
         const float d = depth_tex[ty[k] * 8 + tx[k]];
         CHECK(c[k][p] == (q.ref[p] <= d ? 1.0f : 0.0f), "shadow gather pixel %u texel %u", p, k);
      }
   }
   printf("  gather: %u footprints against the reference (%u with a mirrored axis)\n", checked,
          swapped);
   CHECK(checked > 10000 && swapped > 500, "gather: too few footprints checked");
}

int main(void)
{
   wrap_exact_dfx24();
   negative_fractions();
   printf("address sweep, 8 wraps x 2 filters x 8 sizes x 2000 coordinates in [-2^20, 2^20]:\n");
   wrap_sweep("dfx24", true, 2000);
   wrap_sweep("float", true, 2000);
   wrap_sweep("fx16.16", false, 2000);
   wrap_sweep("fx8.24", false, 2000);
   wrap_sweep("fx24.8", false, 2000);
   weight_bits("dfx24");
   weight_bits("float");
   sample_2d();
   lod_select();
   mip_levels();
   offsets_per_level();
   cube_faces();
   cube_seamless();
   cube_array();
   cube_lod_grads();
   shadow();
   border_colour();
   formats();
   texel_fetch_and_swizzle();
   texel_fetch_buffer();
   reduction_minmax();
   gather();
   printf("  range events counted: sat %llu flush %llu\n", (unsigned long long)st.sat,
          (unsigned long long)st.flush);
   return t_summary("tex");
}
#endif
