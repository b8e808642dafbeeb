/* The texture unit's specialised quads (tex_fast.c, dfx24 and binary32;
 * dfx24's 2-D quad on lanes, tex_lanes.c, in every instruction set the CPU
 * runs, and its scalar quad) against its table path (tex_unit_sample_generic): the same bits out and
 * the same range-event counts, on random units (every target but cube,
 * every wrap mode, filters, mip modes, LOD controls, shadow compare,
 * swizzles, decoded and callback formats, 1 to 9 levels) and random
 * quads (smooth and scattered, coordinates from 2^-40 to 2^40, zeros,
 * subnormals, inf, NaN); the same for the specialised gather.  First the inline operations alone against the
 * numsys table on random operands. */
#include <math.h>
#include <string.h>
#include "tutil.h"
#include "rast/tex/tex.h"
#include "rast/tex/tex_fast.h"
#include "fixed/numsys.h"
#include "rast/host/lanes.h"

static uint64_t rng = 0x9e3779b97f4a7c15ull;
static uint32_t rnd32(void)
{
   return (uint32_t)(t_xorshift(&rng) >> 16);
}
static unsigned rndn(unsigned n) { return rnd32() % n; }
static float rndu(void) { return (float)rnd32() / 4294967296.0f; }

static float bits_float(uint32_t b)
{
   float f;
   memcpy(&f, &b, 4);
   return f;
}

/* Any float the unit may meet, weighted towards the interesting ones. */
static float rand_float(void)
{
   switch (rndn(10)) {
   case 0: {
      static const float special[] = { 0.0f, -0.0f, 1.0f, -1.0f, 0.5f, 1e-40f, -1e-40f,
                                       INFINITY, -INFINITY, NAN, 1e30f, -1e30f,
                                       2147483648.0f, -2147483648.0f, 4294967296.0f,
                                       65535.99f, -65536.0f, 3.0e-10f };
      return special[rndn(sizeof(special) / sizeof(special[0]))];
   }
   case 1:   /* any finite bit pattern */
      for (;;) {
         float f = bits_float(rnd32());
         if (isfinite(f))
            return f;
      }
   case 2:
   case 3:
      return ldexpf((rndu() + 1.0f) * (rndn(2) ? -1.0f : 1.0f), (int)rndn(81) - 40);
   case 4: {   /* near a texel boundary of a power-of-two or odd size */
      const float size = (float)(1u << rndn(11)) + (float)rndn(3);
      const float k = (float)((int)rndn(4 * (unsigned)size) - (int)size);
      return k / size + ldexpf((float)((int)rndn(9) - 4), -(int)rndn(24));
   }
   default:
      return 4.0f * rndu() - 2.0f;
   }
}

static bool same_val(int kind, ns_val a, ns_val b)
{
   if (kind == TEX_NS_FLOAT)
      return !memcmp(&a.f, &b.f, 4);
   return a.d.s == b.d.s && a.d.l == b.d.l && a.d.m == b.d.m;
}

static uint64_t op_checks;

/* Inline operation vs the table, and their range events. */
static void ops(const char *name, enum tex_fk k)
{
   const struct numsys *ns = numsys_by_name(name);
   const int kind = tex_fk_ns(k);
   struct tex_unit u;
   memset(&u, 0, sizeof(u));
   u.ns = ns;
   u.kind = kind;
   unsigned bad = 0;
   for (unsigned i = 0; i < 400000; i++) {
      struct ns_stats g = { 0, 0 };
      struct tex_fst x = { { 0, 0 }, { 0, 0 } };
      const float fa = rand_float(), fb = rand_float();
      /* operands: what the unit's input stage and its constants make */
      ns_val a = rndn(2) ? tex_ns_coord(ns, kind, fa, &g) : ns->from_float(ns, fa, &g);
      ns_val b = rndn(2) ? tex_ns_coord(ns, kind, fb, &g) : ns->from_float(ns, fb, &g);
      g.sat = g.flush = 0;
      /* the operation by the table (r0) and inline (r1); the floor's
       * integer and fraction are compared in its case */
      ns_val r0 = { .x = 0 }, r1 = { .x = 0 };
      bool ok = true, values = true;
      switch (i % 7) {
      case 0:
         r0 = ns->add(ns, a, b, &g);
         r1 = tex_fadd(k, a, b, &x);
         break;
      case 1:
         r0 = ns->sub(ns, a, b, &g);
         r1 = tex_fsub(k, a, b, &x);
         break;
      case 2:
         r0 = ns->mul(ns, a, b, &g);
         r1 = tex_fmul(k, a, b, &x);
         break;
      case 3:
         r0 = ns->recip(ns, a, &g);
         r1 = tex_frecip(k, a, &x);
         break;
      case 4: {
         const unsigned bits = rndn(2) ? TEX_WEIGHT_BITS : 0;
         uint32_t f0 = 0, f1 = 0;
         const int64_t i0 = ns->floor_frac(ns, a, &f0, bits, &g);
         const int64_t i1 = tex_ffloor(k, a, &f1, bits, &x);
         ok = i0 == i1 && f0 == f1;
         values = false;
         break;
      }
      case 5: {
         const int64_t n = (int64_t)(int32_t)rnd32() >> rndn(32);
         r0 = ns->from_float(ns, (float)n, &g);
         r1 = tex_fint(k, n, &x);
         break;
      }
      default:
         r0 = tex_ns_coord(ns, kind, fa, &g);
         r1 = tex_fcoord(&u, k, fa, &x);
         break;
      }
      if (values)
         ok = same_val(kind, r0, r1);
      struct ns_stats f = { 0, 0 };
      tex_fst_flush(&x, &f);
      ok = ok && f.sat == g.sat && f.flush == g.flush;
      if (!ok && bad++ < 5)
         CHECK(ok, "%s op %u: a %a b %a", name, i % 7, (double)fa, (double)fb);
      op_checks++;
   }
   CHECK(bad == 0, "%s: %u operations differ from the table", name, bad);
}

/* ---- whole quads ---- */

#define MAXL 9
static uint8_t texels[MAXL][64 * 64 * 8 * 4];

static void callback_fetch(const struct tex_view_desc *v, const struct tex_level *lv, int x,
                           int y, int z, float o[4])
{
   (void)v;
   const uint8_t *p = lv->data + (size_t)z * lv->img_stride + (size_t)y * lv->row_stride +
                      (size_t)x * 4;
   o[0] = (float)p[0] / 200.0f;   /* not a decoder of the unit's */
   o[1] = (float)p[1] / 255.0f;
   o[2] = -(float)p[2];
   o[3] = (float)p[3] * 0.01f;
}

static void rand_unit(struct tex_unit *u, const struct numsys *ns, struct ns_stats *st)
{
   static const enum tex_target targets[] = {
      TEX_TARGET_1D, TEX_TARGET_2D, TEX_TARGET_3D, TEX_TARGET_1D_ARRAY, TEX_TARGET_2D_ARRAY,
      TEX_TARGET_RECT, TEX_TARGET_2D, TEX_TARGET_2D,
   };
   static const enum tex_format formats[] = {
      TEX_FMT_RGBA8, TEX_FMT_BGRA8, TEX_FMT_RGBX8, TEX_FMT_BGRX8, TEX_FMT_L8,
      TEX_FMT_B5G6R5, TEX_FMT_LA8, TEX_FMT_CALLBACK, TEX_FMT_RGBA8, TEX_FMT_BGRA8,
   };
   struct tex_view_desc v;
   struct tex_sampler_desc s;
   memset(&v, 0, sizeof(v));
   memset(&s, 0, sizeof(s));
   v.target = targets[rndn(sizeof(targets) / sizeof(targets[0]))];
   v.format = formats[rndn(sizeof(formats) / sizeof(formats[0]))];
   v.depth = rndn(4) == 0;
   if (v.depth)
      v.format = TEX_FMT_CALLBACK;
   v.fetch = callback_fetch;
   const bool is3d = v.target == TEX_TARGET_3D;
   const bool arr = v.target == TEX_TARGET_1D_ARRAY || v.target == TEX_TARGET_2D_ARRAY;
   const bool is1d = v.target == TEX_TARGET_1D || v.target == TEX_TARGET_1D_ARRAY;
   int w = 1 + (int)rndn(64), h = is1d ? 1 : 1 + (int)rndn(64);
   int d = is3d ? 1 + (int)rndn(8) : 1;
   if (rndn(2)) {   /* power-of-two sizes */
      w = 1 << rndn(7);
      h = is1d ? 1 : 1 << rndn(7);
      d = is3d ? 1 << rndn(4) : 1;
   }
   v.layers = arr ? 1 + (int)rndn(8) : d;
   v.num_levels = 1 + rndn(MAXL);
   for (unsigned l = 0; l < v.num_levels; l++) {
      struct tex_level *lv = &v.level[l];
      lv->w = w;
      lv->h = h;
      lv->d = arr ? v.layers : d;
      lv->row_stride = (uint32_t)w * 4;
      lv->img_stride = lv->row_stride * (uint32_t)h;
      lv->data = texels[l];
      w = w > 1 ? w / 2 : 1;
      h = h > 1 ? h / 2 : 1;
      d = d > 1 ? d / 2 : 1;
   }
   for (unsigned c = 0; c < 4; c++)
      v.swizzle[c] = (uint8_t)(rndn(3) ? c : rndn(6));
   for (unsigned a = 0; a < 3; a++)
      s.wrap[a] = (enum tex_wrap)rndn(TEX_WRAP_COUNT);
   if (rndn(2))   /* one mode on every axis, as most samplers (the specialised lanes quads) */
      s.wrap[1] = s.wrap[2] = s.wrap[0];
   s.min_filter = (enum tex_filter)rndn(2);
   s.mag_filter = (enum tex_filter)rndn(2);
   s.mip = (enum tex_mip)rndn(3);
   s.normalized = v.target != TEX_TARGET_RECT || rndn(2);
   s.compare = rndn(2);
   s.func = (enum tex_func)rndn(8);
   s.lod_bias = rndn(2) ? 0.0f : 8.0f * rndu() - 4.0f;
   s.min_lod = rndn(2) ? -1000.0f : 4.0f * rndu() - 1.0f;
   s.max_lod = rndn(2) ? 1000.0f : 10.0f * rndu();
   for (unsigned c = 0; c < 4; c++)
      s.border[c] = rndu();
   tex_unit_bind(u, ns, &v, &s, st);
}

static void rand_quad(struct tex_quad *q, const struct tex_unit *u)
{
   const int mode = (int)rndn(4);
   float *co[3] = { q->s, q->t, q->r };
   for (unsigned a = 0; a < 3; a++) {
      /* smooth: a base and per-pixel steps of any scale, as a triangle gives */
      const float base = rand_float();
      const float scale = u->samp.normalized ? 1.0f : (float)u->view.level[0].w;
      const float dx = ldexpf(rndu() - 0.5f, -(int)rndn(14)) * (rndn(2) ? 1.0f : scale);
      const float dy = ldexpf(rndu() - 0.5f, -(int)rndn(14)) * (rndn(2) ? 1.0f : scale);
      for (unsigned p = 0; p < TEX_QUAD; p++) {
         co[a][p] = mode == 0 ? rand_float() : base * (mode == 1 ? scale : 1.0f) +
                                                  (float)(p & 1) * dx + (float)(p >> 1) * dy;
         q->ddx[a][p] = mode == 3 ? rand_float() : dx;
         q->ddy[a][p] = mode == 3 ? rand_float() : dy;
      }
   }
   const float lod = 12.0f * rndu() - 3.0f;
   for (unsigned p = 0; p < TEX_QUAD; p++) {
      q->layer[p] = rndn(8) ? 10.0f * rndu() - 1.0f : rand_float();
      q->ref[p] = rndn(8) ? rndu() : rand_float();
      q->lod[p] = rndn(2) ? lod : rndn(8) ? 12.0f * rndu() - 3.0f : rand_float();
   }
}

/* Two quads side by side whose coordinates follow the screen's axes, as a
 * 2-D window's texture (s per column, t per row, or one of the two): the
 * pair functions then address each column or row once (tex_lanes.c).  The columns' and rows'
 * values smooth, as a triangle gives, or any float. */
static void axis_pair(struct tex_quad two[2], const struct tex_unit *u)
{
   const float scale = u->samp.normalized ? 1.0f : (float)u->view.level[0].w;
   float col[4], row[2];
   const float s0 = rand_float(), t0 = rand_float();
   const float ds = ldexpf(rndu(), -(int)rndn(14)) * scale, dt = ldexpf(rndu(), -(int)rndn(14)) * scale;
   const bool any = rndn(4) == 0;
   for (unsigned c = 0; c < 4; c++)
      col[c] = any ? rand_float() : s0 * scale + (float)c * ds;
   for (unsigned r = 0; r < 2; r++)
      row[r] = any ? rand_float() : t0 * scale + (float)r * dt;
   /* both axes, or one (the other as it came) */
   const unsigned axes = rndn(3);
   for (unsigned i = 0; i < 2; i++)
      for (unsigned p = 0; p < TEX_QUAD; p++) {
         if (axes != 2)
            two[i].s[p] = col[2 * i + (p & 1)];
         if (axes != 1)
            two[i].t[p] = row[p >> 1];
      }
}

static uint64_t quads, fast_quads, lanes_quads, nolod_quads, pair_quads, axes_quads, four_calls;

/* LANES_BEST: the CPU's set (AVX-512 where it has it: lanes.h) */
enum mode { LANES_BEST, LANES_SSE2, SCALAR, LANES_AVX2 };

static void quads_vs_generic(const char *name, bool fast, unsigned units, unsigned per_unit,
                             enum mode mode)
{
   static const char *const mode_names[] = { "", " (SSE2 lanes)", " (scalar)",
                                             " (AVX2 lanes)" };
   __builtin_cpu_init();
   rast_lanes_set(mode == LANES_SSE2 || !__builtin_cpu_supports("avx2") ? &rast_lanes_sse2
                  : mode == LANES_BEST && rast_lanes_have_avx512()      ? &rast_lanes_avx512
                                                                       : &rast_lanes_avx2);
   const struct numsys *ns = numsys_by_name(name);
   unsigned bad = 0, fast_units = 0;
   for (unsigned i = 0; i < units; i++) {
      struct tex_unit u;
      struct ns_stats s_fast = { 0, 0 }, s_gen = { 0, 0 };
      rand_unit(&u, ns, &s_fast);
      if (mode == SCALAR)
         tex_unit_set_datapath(&u, true, false);
      s_gen = s_fast;
      CHECK(!!u.quad == (fast && u.view.target != TEX_TARGET_CUBE),
            "%s: specialised quad %s", name, u.quad ? "chosen" : "missing");
      fast_units += u.quad != NULL;
      for (unsigned j = 0; j < per_unit; j++) {
         /* the lanes with their skips and without (noskip) in turn */
         if (mode != SCALAR)
            tex_unit_set_datapath(&u, false, j & 1);
         struct tex_quad q;
         rand_quad(&q, &u);
         const enum tex_lod_control ctl = (enum tex_lod_control)rndn(5);
         float r0[4][TEX_QUAD], r1[4][TEX_QUAD];
         /* a LOD left out raises none of its range events: the reference
          * for the events is then the quad sampled at LOD 0, computing no
          * LOD; the bits are those of the quad with its LOD computed */
         const bool nolod = u.lod_skipped && (ctl == TEX_LOD_IMPLICIT || ctl == TEX_LOD_BIAS);
         struct ns_stats s_lod = { 0, 0 };
         u.stats = nolod ? &s_lod : &s_gen;
         tex_unit_sample_generic(&u, &q, ctl, r0);
         if (nolod) {
            float rz[4][TEX_QUAD];
            u.stats = &s_gen;
            tex_unit_sample_generic(&u, &q, TEX_LOD_ZERO, rz);
            CHECK(!memcmp(r0, rz, sizeof(r0)), "%s unit %u quad %u: LOD unused but it matters",
                  name, i, j);
            nolod_quads++;
         }
         u.stats = &s_fast;
         tex_unit_sample(&u, &q, ctl, r1);
         const bool ok = !memcmp(r0, r1, sizeof(r0)) && s_gen.sat == s_fast.sat &&
                         s_gen.flush == s_fast.flush;
         if (!ok && bad++ < 5)
            CHECK(ok, "%s unit %u quad %u: target %d fmt %d wrap %d/%d/%d filt %d/%d mip %d "
                  "ctl %d: r %a vs %a, sat %llu vs %llu, flush %llu vs %llu", name, i, j,
                  u.view.target, u.view.format, u.samp.wrap[0], u.samp.wrap[1],
                  u.samp.wrap[2], u.samp.min_filter, u.samp.mag_filter, u.samp.mip, ctl,
                  (double)r0[0][0], (double)r1[0][0], (unsigned long long)s_gen.sat,
                  (unsigned long long)s_fast.sat, (unsigned long long)s_gen.flush,
                  (unsigned long long)s_fast.flush);
         /* two quads in one call: the quad function's bits and range
          * events on each (the pair function where the unit has one) */
         struct tex_quad two[2] = { q, q };
         rand_quad(&two[1], &u);
         if (j % 3 == 2)
            axis_pair(two, &u);
         float one_by_one[2][4][TEX_QUAD], paired[2][4][TEX_QUAD];
         struct ns_stats s_one = { 0, 0 }, s_two = { 0, 0 };
         u.stats = &s_one;
         tex_unit_sample(&u, &two[0], ctl, one_by_one[0]);
         tex_unit_sample(&u, &two[1], ctl, one_by_one[1]);
         u.stats = &s_two;
         u.axes_shared = &axes_quads;
         tex_unit_sample2(&u, two, ctl, paired);
         u.axes_shared = NULL;
         const bool ok2 = !memcmp(one_by_one, paired, sizeof(paired)) &&
                          s_one.sat == s_two.sat && s_one.flush == s_two.flush;
         if (!ok2 && bad++ < 5)
            CHECK(ok2, "%s unit %u quad %u: two quads in one call (%s) differ from each alone "
                  "(wrap %d/%d filt %d/%d, ctl %d; sat %llu vs %llu, flush %llu vs %llu; "
                  "s %a t %a: %a vs %a)",
                  name, i, j, u.quad2 ? "pair function" : "quad twice", u.samp.wrap[0],
                  u.samp.wrap[1], u.samp.min_filter, u.samp.mag_filter, ctl,
                  (unsigned long long)s_one.sat, (unsigned long long)s_two.sat,
                  (unsigned long long)s_one.flush, (unsigned long long)s_two.flush,
                  (double)two[0].s[0], (double)two[0].t[0], (double)one_by_one[0][0][0],
                  (double)paired[0][0][0]);
         pair_quads += u.quad2 != NULL;
         /* four quads in one call (two of them the pair above, the quad
          * function's bits and range events on each; the quad-axes shared
          * as the two pairs alone count them), and three */
         struct tex_quad four[4] = { two[0], two[1], q, q };
         rand_quad(&four[3], &u);
         if (j % 3 != 1)
            axis_pair(&four[2], &u);
         float each[2][2][4][TEX_QUAD], together[4][4][TEX_QUAD];   /* each: two pairs */
         struct ns_stats s_each = { 0, 0 }, s_four = { 0, 0 };
         uint64_t axes_each = 0, axes_four = 0;
         const unsigned n4 = j % 5 == 4 ? 3 : 4;
         u.stats = &s_each;
         u.axes_shared = &axes_each;
         tex_unit_sample2(&u, &four[0], ctl, each[0]);
         if (n4 == 4)
            tex_unit_sample2(&u, &four[2], ctl, each[1]);
         else
            tex_unit_sample(&u, &four[2], ctl, each[1][0]);
         u.stats = &s_four;
         u.axes_shared = &axes_four;
         tex_unit_sample_quads(&u, four, n4, ctl, together);
         u.axes_shared = NULL;
         const bool ok4 = !memcmp(each, together, n4 * sizeof(together[0])) &&
                          s_each.sat == s_four.sat && s_each.flush == s_four.flush &&
                          axes_each == axes_four;
         if (!ok4 && bad++ < 5)
            CHECK(ok4, "%s unit %u quad %u: %u quads in one call (%s) differ from the pairs "
                  "(wrap %d/%d filt %d/%d, ctl %d; sat %llu vs %llu, flush %llu vs %llu, "
                  "axes %llu vs %llu)",
                  name, i, j, n4, u.quad4 ? "four-quad function" : "pairs", u.samp.wrap[0],
                  u.samp.wrap[1], u.samp.min_filter, u.samp.mag_filter, ctl,
                  (unsigned long long)s_each.sat, (unsigned long long)s_four.sat,
                  (unsigned long long)s_each.flush, (unsigned long long)s_four.flush,
                  (unsigned long long)axes_each, (unsigned long long)axes_four);
         four_calls += n4 == 4 && u.quad4 != NULL;
         quads++;
         fast_quads += u.quad != NULL;
         tex_quad2_fn pair;
         tex_quad4_fn four_fn;
         lanes_quads += u.quad && u.dims == 2 && u.kind == TEX_NS_DFX &&
                        u.quad == rast_lanes()->tex_dfx19_2d(&u, j & 1, u.lod_skipped, &pair,
                                                             &four_fn);
      }
   }
   CHECK(bad == 0, "%s: %u of %u quads differ", name, bad, units * per_unit);
   printf("  %-8s %u units (%u specialised) x %u quads%s: %u differ\n", name, units,
          fast_units, per_unit, mode_names[mode], bad);
}

/* Four quads side by side on the same two rows, as a 2-D window's quad
 * row gives them: s follows the eight columns from `s0`, moved by `ds_row`
 * on the second row (a coordinate interpolated across the rows: 0, or a
 * few last bits), t the two rows `row`. */
static void axis_four(struct tex_quad four[4], const struct tex_unit *u, float s0, float ds,
                      float ds_row, const float row[2])
{
   (void)u;
   for (unsigned i = 0; i < 4; i++)
      for (unsigned p = 0; p < TEX_QUAD; p++) {
         four[i].s[p] = s0 + (float)(2 * i + (p & 1)) * ds + (float)(p >> 1) * ds_row;
         four[i].t[p] = row[p >> 1];
      }
}

/* The four-quad function's rows memo: runs of calls along the rows of a
 * 2-D window, a row taken again, another between, the unit bound anew
 * (the memo cleared): every call's bits, range events and shared
 * quad-axes those of its two pairs, which never take the memo. */
static void rows_memo_runs(unsigned units, unsigned calls)
{
   __builtin_cpu_init();
   rast_lanes_set(rast_lanes_have_avx512()            ? &rast_lanes_avx512
                  : __builtin_cpu_supports("avx2") ? &rast_lanes_avx2
                                                   : &rast_lanes_sse2);
   const struct numsys *ns = numsys_by_name("dfx24");
   unsigned bad = 0;
   uint64_t taken = 0, taken_taps = 0, four = 0, loaded = 0, loaded_moved = 0, loaded_reduced = 0;
   for (unsigned i = 0; i < units; i++) {
      struct tex_unit u;
      struct ns_stats s_each = { 0, 0 }, s_four = { 0, 0 };
      /* a unit with a four-quad function (the others have no memo) */
      for (unsigned tries = 0; tries == 0 || (!u.quad4 && tries < 1000); tries++) {
         rand_unit(&u, ns, &s_four);
         tex_unit_set_datapath(&u, false, false);
      }
      const float scale = u.samp.normalized ? 1.0f : (float)u.view.level[0].w;
      /* a vertical blur's taps in a third of the units: each four quads
       * sampled on up to 24 pairs of rows in turn (more than the memo has
       * slots: some share one), the same rows for every four along them */
      const unsigned taps = rndn(3) ? 0 : 2 + rndn(23);
      float rows[24][2];
      for (unsigned r = 0; r < 24; r++) {
         const float t0 = rndn(8) ? rndu() * scale : rand_float();
         const float dt = ldexpf(rndu(), -(int)rndn(14)) * scale;
         rows[r][0] = t0;
         rows[r][1] = rndn(16) ? t0 + dt : rand_float();
      }
      /* rows that differ in the second only, or in the first only */
      const unsigned same = rndn(3);
      if (same < 2)
         rows[2][same] = rows[0][same];
      float s0 = rndu() * scale;
      /* s decreasing along the row in a quarter of the units (a mirrored
       * window: the leftmost texel column at the last quad) */
      const float ds = (rndn(4) ? 1.0f : -1.0f) * ldexpf(rndu(), -(int)rndn(14)) * scale;
      /* s the same down each column in half the units, and in the others
       * moved on the second row by a few of its last bits or more */
      const float ds_row = rndn(2) ? 0.0f : ldexpf(ds, -(int)(4 + rndn(20)));
      for (unsigned c = 0; c < calls; c++) {
         /* mostly the same rows, moving along them; now and then another */
         const unsigned r = taps ? c % taps : rndn(4) ? 0 : 1 + rndn(2);
         struct tex_quad q[4];
         memset(q, 0, sizeof(q));
         axis_four(q, &u, s0, ds, ds_row, rows[r]);
         if (!taps || r == taps - 1)
            s0 += 8 * ds;
         /* now and then the quads in another order on their rows (neither
          * end quad holds the leftmost column: rows_words then finds it by
          * the reduction) */
         if (!rndn(8)) {
            const unsigned a = rndn(4), b = rndn(4);
            const struct tex_quad tq = q[a];
            q[a] = q[b];
            q[b] = tq;
         }
         struct tex_rows_memo before[TEX_ROWS_MEMO];
         memcpy(before, u.rows_memo, sizeof(before));
         float each[2][2][4][TEX_QUAD], together[4][4][TEX_QUAD];
         uint64_t axes_each = 0, axes_four = 0;
         u.stats = &s_four;
         u.axes_shared = &axes_four;
         tex_unit_sample_quads(&u, q, 4, TEX_LOD_IMPLICIT, together);
         /* the memo held the rows before and still does: taken */
         bool held = false;
         for (unsigned k = 0; k < TEX_ROWS_MEMO; k++)
            held |= before[k].valid;
         const bool took = held && !memcmp(before, u.rows_memo, sizeof(before));
         taken += took;
         taken_taps += taps && took;
         u.stats = &s_each;
         u.axes_shared = &axes_each;
         tex_unit_sample2(&u, &q[0], TEX_LOD_IMPLICIT, each[0]);
         tex_unit_sample2(&u, &q[2], TEX_LOD_IMPLICIT, each[1]);
         u.axes_shared = NULL;
         four += u.quad4 != NULL;
         loaded += u.rows_loaded;
         loaded_moved += ds_row != 0.0f ? u.rows_loaded : 0;
         loaded_reduced += u.rows_reduced;
         u.rows_loaded = u.rows_reduced = 0;
         const bool ok = !memcmp(each, together, sizeof(together)) &&
                         s_each.sat == s_four.sat && s_each.flush == s_four.flush &&
                         axes_each == axes_four;
         if (!ok && bad++ < 5)
            CHECK(ok, "unit %u call %u (rows %u): four quads with the rows memo differ from "
                  "the pairs (wrap %d/%d filt %d/%d; sat %llu vs %llu, flush %llu vs %llu, "
                  "axes %llu vs %llu)", i, c, r, u.samp.wrap[0], u.samp.wrap[1],
                  u.samp.min_filter, u.samp.mag_filter, (unsigned long long)s_each.sat,
                  (unsigned long long)s_four.sat, (unsigned long long)s_each.flush,
                  (unsigned long long)s_four.flush, (unsigned long long)axes_each,
                  (unsigned long long)axes_four);
      }
   }
   CHECK(bad == 0, "rows memo: %u calls differ", bad);
   printf("  rows memo: %llu calls of four quads through a four-quad function, the rows' "
          "addresses taken from the memo in %llu (%llu of a blur's taps), the taps read from their texel rows in "
          "%llu (%llu of them with s moved on the second row, %llu with the leftmost column "
          "found by the reduction)\n", (unsigned long long)four, (unsigned long long)taken,
          (unsigned long long)taken_taps,
          (unsigned long long)loaded, (unsigned long long)loaded_moved,
          (unsigned long long)loaded_reduced);
   if (rast_lanes_have_avx512()) {
      CHECK(taken > 20000, "only %llu calls took the rows memo", (unsigned long long)taken);
      CHECK(taken_taps > 10000, "only %llu calls of a blur's taps took the rows memo",
            (unsigned long long)taken_taps);
      CHECK(loaded > 10000, "only %llu calls read their taps from the texel rows",
            (unsigned long long)loaded);
      CHECK(loaded_moved > 3000, "only %llu calls with s moved on the second row read their "
            "taps from the texel rows", (unsigned long long)loaded_moved);
      CHECK(loaded_reduced > 300 && loaded_reduced < loaded / 4,
            "%llu of %llu calls that read their taps from the texel rows found the leftmost "
            "column by the reduction", (unsigned long long)loaded_reduced,
            (unsigned long long)loaded);
   }
}

/* The specialised gather (u->footprint, then the texel reads) against the
 * table path: the same bits and range events on random units, every
 * channel; chosen exactly for the 2-D views of dfx24 and binary32, and not
 * with `scalar`.  One footprint read for all four channels (the driver's
 * memo), channel by channel and all at once, gives each channel's gather
 * and counts each gather's events. */
static void gathers_vs_generic(const char *name, bool fast, unsigned units, unsigned per_unit)
{
   const struct numsys *ns = numsys_by_name(name);
   unsigned bad = 0, fast_units = 0;
   for (unsigned i = 0; i < units; i++) {
      struct tex_unit u;
      struct ns_stats s_fast = { 0, 0 }, s_gen = { 0, 0 };
      rand_unit(&u, ns, &s_fast);
      const bool two_d = u.view.target == TEX_TARGET_2D || u.view.target == TEX_TARGET_2D_ARRAY ||
                         u.view.target == TEX_TARGET_RECT;
      CHECK(!!u.footprint == (fast && two_d), "%s: specialised gather %s for target %d", name,
            u.footprint ? "chosen" : "missing", u.view.target);
      tex_unit_set_datapath(&u, true, false);
      CHECK(!u.footprint, "%s: specialised gather chosen on the scalar datapath", name);
      tex_unit_set_datapath(&u, false, false);
      fast_units += u.footprint != NULL;
      for (unsigned j = 0; j < per_unit; j++) {
         struct tex_quad q;
         rand_quad(&q, &u);
         const unsigned comp = rndn(4);
         float r0[4][TEX_QUAD], r1[4][TEX_QUAD];
         u.stats = &s_gen;
         tex_unit_gather_generic(&u, &q, comp, r0);
         u.stats = &s_fast;
         tex_unit_gather(&u, &q, comp, r1);
         bool ok = !memcmp(r0, r1, sizeof(r0)) && s_gen.sat == s_fast.sat &&
                   s_gen.flush == s_fast.flush;
         struct tex_footprint f;
         if (ok && tex_unit_gather_footprint(&u, &q, &f)) {
            /* every channel of one footprint read channel by channel, and
             * all at once (with one gather's events counted a channel) */
            float all[4][4][TEX_QUAD];
            tex_unit_gather_read_all(&u, &f, q.ref, all);
            for (unsigned c = 0; c < 4; c++) {
               u.stats = &s_gen;
               tex_unit_gather_generic(&u, &q, c, r0);
               tex_unit_gather_generic(&u, &q, c, r0);
               u.stats = &s_fast;
               tex_unit_gather_read(&u, &f, q.ref, c, r1);
               ok &= !memcmp(r0, r1, sizeof(r0)) && !memcmp(r0, all[c], sizeof(r0));
               tex_unit_gather_count(&u, &f);
            }
            ok &= s_gen.sat == s_fast.sat && s_gen.flush == s_fast.flush;
         }
         if (!ok && bad++ < 5)
            CHECK(ok, "%s unit %u gather %u: target %d fmt %d wrap %d/%d comp %u compare %d: "
                  "r %a vs %a, sat %llu vs %llu, flush %llu vs %llu", name, i, j,
                  u.view.target, u.view.format, u.samp.wrap[0], u.samp.wrap[1], comp,
                  u.samp.compare, (double)r0[0][0], (double)r1[0][0],
                  (unsigned long long)s_gen.sat, (unsigned long long)s_fast.sat,
                  (unsigned long long)s_gen.flush, (unsigned long long)s_fast.flush);
      }
   }
   CHECK(bad == 0, "%s: %u of %u gathers differ", name, bad, units * per_unit);
   CHECK(!fast || fast_units > units / 4, "%s: only %u of %u units had the specialised gather",
         name, fast_units, units);
   printf("  %-8s %u units (%u specialised) x %u gathers: %u differ\n", name, units,
          fast_units, per_unit, bad);
}

/* The registers of the compiled gather (tex_unit_gather_regs): given
 * exactly to the units it covers, their clamp bounds' keys in
 * tex_ns_cmp's order, and each component's byte (or constant) what the
 * unit's texel reads give for a footprint of one texel. */
static void gather_regs(unsigned units)
{
   const struct numsys *ns = numsys_by_name("dfx24");
   unsigned bad = 0, covered = 0;
   for (unsigned i = 0; i < units; i++) {
      struct tex_unit u;
      struct ns_stats st = { 0, 0 };
      rand_unit(&u, ns, &st);
      if (rndn(2)) {   /* more of the covered kind than rand_unit makes */
         struct tex_view_desc v = u.view;
         struct tex_sampler_desc smp = u.samp;
         smp.wrap[0] = smp.wrap[1] = TEX_WRAP_CLAMP_TO_EDGE;
         smp.compare = false;
         v.depth = false;
         v.format = (enum tex_format)(TEX_FMT_RGBA8 + rndn(4));   /* the 4-byte layouts */
         tex_unit_bind(&u, ns, &v, &smp, &st);
      }
      struct tex_gather_regs r;
      const bool ok = tex_unit_gather_regs(&u, &r);
      const enum tex_format f = u.view.format;
      const bool want = u.footprint && !u.samp.compare && f >= TEX_FMT_RGBA8 &&
                        f <= TEX_FMT_BGRX8 &&
                        (u.view.target == TEX_TARGET_2D || u.view.target == TEX_TARGET_RECT) &&
                        u.samp.wrap[0] == TEX_WRAP_CLAMP_TO_EDGE &&
                        u.samp.wrap[1] == TEX_WRAP_CLAMP_TO_EDGE && u.view.level[0].w >= 2;
      if (ok != want && bad++ < 5)
         CHECK(0, "unit %u: registers %s (target %d fmt %d wrap %d/%d compare %d w %d)", i,
               ok ? "given" : "refused", u.view.target, f, u.samp.wrap[0], u.samp.wrap[1],
               u.samp.compare, u.view.level[0].w);
      if (!ok)
         continue;
      covered++;
      for (unsigned a = 0; a < 2; a++) {
         const int c = tex_ns_cmp(TEX_NS_DFX, u.axis[0][a].lo, u.axis[0][a].hi);
         if ((c > 0) != (r.lo_key[a] > r.hi_key[a]) || (c == 0) != (r.lo_key[a] == r.hi_key[a]))
            bad++;
      }
      /* a footprint of one texel, every tap on it */
      struct tex_footprint fp;
      memset(&fp, 0, sizeof(fp));
      const int x = (int)rndn((unsigned)u.view.level[0].w), y = (int)rndn((unsigned)u.view.level[0].h);
      for (unsigned p = 0; p < TEX_QUAD; p++) {
         fp.x[0][p] = fp.x[1][p] = x;
         fp.y[0][p] = fp.y[1][p] = y;
      }
      uint32_t word;
      memcpy(&word, u.view.level[0].data + (size_t)y * u.view.level[0].row_stride + (size_t)x * 4, 4);
      const float ref[TEX_QUAD] = { 0, 0, 0, 0 };
      for (unsigned c = 0; c < 4; c++) {
         float rgba[4][TEX_QUAD];
         tex_unit_gather_read(&u, &fp, ref, c, rgba);
         const float want_c = r.shift[c] < 0 ? r.constant[c]
                                             : (float)(int32_t)((word >> r.shift[c]) & 0xff) *
                                                  (1.0f / 255.0f);
         if (memcmp(&want_c, &rgba[0][0], sizeof(float)) && bad++ < 5)
            CHECK(0, "unit %u component %u (swizzle %u, fmt %d): %a from the registers, %a read",
                  i, c, u.view.swizzle[c], f, (double)want_c, (double)rgba[0][0]);
      }
   }
   CHECK(bad == 0, "compiled gather registers: %u of %u units wrong", bad, units);
   CHECK(covered > units / 10, "only %u of %u units covered by the compiled gather", covered,
         units);
   printf("  %u units, %u covered by the compiled gather: %u wrong\n", units, covered, bad);
}

int main(void)
{
   for (unsigned l = 0; l < MAXL; l++)
      for (size_t i = 0; i < sizeof(texels[l]); i++)
         texels[l][i] = (uint8_t)rnd32();
   printf("inline operations vs the numsys table:\n");
   ops("dfx24", TEX_FK_DFX19);
   ops("float", TEX_FK_FLOAT);
   printf("  %llu operations\n", (unsigned long long)op_checks);
   printf("specialised quad vs the table path (bits and range events):\n");
   quads_vs_generic("dfx24", true, 3000, 200, LANES_BEST);
   quads_vs_generic("dfx24", true, 3000, 200, LANES_SSE2);
   if (rast_lanes_have_avx512())
      quads_vs_generic("dfx24", true, 3000, 200, LANES_AVX2);
   else
      printf("  no AVX-512 on this CPU: the AVX2 lanes are the best set\n");
   quads_vs_generic("dfx24", true, 3000, 200, SCALAR);
   quads_vs_generic("float", true, 3000, 200, LANES_BEST);
   quads_vs_generic("fx16.16", false, 100, 50, LANES_BEST);   /* the table path */
   quads_vs_generic("dfx23", false, 100, 50, LANES_BEST);
   printf("specialised gather vs the table path (bits and range events):\n");
   gathers_vs_generic("dfx24", true, 2000, 200);
   gathers_vs_generic("float", true, 2000, 200);
   gathers_vs_generic("dfx23", false, 100, 50);
   printf("compiled gather's registers:\n");
   gather_regs(4000);
   printf("  %llu quads on lanes, %llu of them without a LOD\n", (unsigned long long)lanes_quads,
          (unsigned long long)nolod_quads);
   CHECK(nolod_quads > 10000, "only %llu quads left the LOD out", (unsigned long long)nolod_quads);
   CHECK(lanes_quads > 300000, "only %llu quads took the lanes", (unsigned long long)lanes_quads);
   printf("  %llu pairs of quads through a pair function\n", (unsigned long long)pair_quads);
   CHECK(pair_quads > 5000, "only %llu pairs took a pair function",
         (unsigned long long)pair_quads);
   printf("  %llu calls of four quads through a four-quad function\n",
          (unsigned long long)four_calls);
   if (rast_lanes_have_avx512())
      CHECK(four_calls > 2000, "only %llu calls took a four-quad function",
            (unsigned long long)four_calls);
   printf("  %llu quad-axes of pairs addressed once per column or row\n",
          (unsigned long long)axes_quads);
   CHECK(axes_quads > 4000, "only %llu quad-axes of pairs were addressed per column or row",
         (unsigned long long)axes_quads);
   CHECK(fast_quads > 1000000, "only %llu quads took the specialised path",
         (unsigned long long)fast_quads);
   rows_memo_runs(1000, 100);
   return t_summary("tex_fast");
}
