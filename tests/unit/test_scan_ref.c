/*
 * The scan-line converter against an exact reference (tutil.c: 64-bit edge
 * functions on the same fixed-point vertices with llvmpipe's tie rule), on
 * random triangles of many kinds, for both profiles, both edge rules and
 * both pixel-centre conventions, with and without scissor.  The covered
 * pixel sets must be identical, and no pixel may be emitted twice.
 *
 *   test_scan_ref [--triangles N] [--seed S]
 * N triangles in all (at least; default 22/16 UNIT_TRIANGLES), 16/22 of
 * them in the named profiles, 6/22 in three precision settings;
 * ./fixpipe stress runs 10^7 in several processes with their own seeds.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tutil.h"
#include "fixed/fx.h"

#ifndef UNIT_TRIANGLES
#define UNIT_TRIANGLES 120000
#endif

#define TW 2048
#define TH 2048

enum kind { K_SMALL, K_MEDIUM, K_SLIVER, K_HUGE, K_CENTRES, K_HALVES, K_DEGEN, K_GUARD, K_COUNT };
#ifndef FUZZ_TARGET
static const char *kind_name[K_COUNT] = {
   "small", "medium", "sliver", "huge", "on-centres", "on-half-pixels", "degenerate", "guard-band"
};
#endif

struct cmp { struct tctx *t; uint64_t missing; };

static void visit_ref(void *ctx, int x, int y)
{
   struct cmp *c = ctx;
   if (c->t->stamp[(size_t)y * TW + (size_t)x] != c->t->id)
      c->missing++;
}

/* What one triangle did against the reference. */
struct outcome {
   int64_t X[3], Y[3];          /* its vertices in the XY format */
   uint64_t ref, missing;       /* the reference's pixels; those the model left out */
   bool same;                   /* the same pixel set, none twice, none outside */
   bool sat, dsat;              /* a counted saturation; one of a dx/dy slope (not compared) */
};

/* The triangle v through the model and through the exact reference. */
static struct outcome draw_and_compare(struct tctx *t, float v[3][2], bool half,
                                       bool bottom, struct rast_scissor clip)
{
   struct outcome o;
   struct fx_sat dummy = { 0, 0 };
   const int64_t S = fx_one(t->prof->xy);
   for (int i = 0; i < 3; i++) {
      o.X[i] = fx_from_double(t->prof->xy, v[i][0], &dummy);
      o.Y[i] = fx_from_double(t->prof->xy, v[i][1], &dummy);
   }
   struct rast_stats before = *rast_get_stats(t->rc);
   t_begin(t);
   t_tri_xy(t->rc, (const float (*)[2])v);
   const struct rast_stats *after = rast_get_stats(t->rc);
   o.sat = t_sat_total(after) != t_sat_total(&before);
   o.dsat = t_sat_class(after, RAST_REG_DXDY) != t_sat_class(&before, RAST_REG_DXDY);
   struct cmp c = { t, 0 };
   o.ref = t_ref_triangle(o.X, o.Y, S, half ? S / 2 : 0, bottom, clip, visit_ref, &c);
   o.missing = c.missing;
   o.same = c.missing == 0 && o.ref == t->count && t->dups == 0 && t->outside == 0 &&
            t->badquad == 0;
   return o;
}

#ifndef FUZZ_TARGET  /* the random triangles of the unit test */
static double coord(double lo, double hi) { return lo + (hi - lo) * t_rand(); }

/* Random float vertices of the given kind. */
static void gen(enum kind k, bool half, float v[3][2], bool wide)
{
   double cx = coord(-20, TW + 20), cy = coord(-20, TH + 20);
   double size;
   switch (k) {
   case K_SMALL: size = coord(0.1, 24); break;
   case K_MEDIUM: size = coord(24, 300); break;
   default: size = 64; break;
   }
   for (int i = 0; i < 3; i++) {
      v[i][0] = (float)(cx + coord(-size, size));
      v[i][1] = (float)(cy + coord(-size, size));
   }
   if (k == K_SLIVER) {
      /* Nearly collinear: the third vertex a few subpixel units off the
       * line through the first two, which may be far apart. */
      double len = coord(2, 900), ang = coord(0, 6.283185307179586);
      double x0 = cx, y0 = cy, x1 = cx + len * cos(ang), y1 = cy + len * sin(ang);
      double s = t_rand(), off = coord(-4, 4) / 4096.0 * (t_rand() < 0.5 ? 1 : 64);
      v[0][0] = (float)x0; v[0][1] = (float)y0;
      v[1][0] = (float)x1; v[1][1] = (float)y1;
      v[2][0] = (float)(x0 + s * (x1 - x0) - off * sin(ang));
      v[2][1] = (float)(y0 + s * (y1 - y0) + off * cos(ang));
   } else if (k == K_HUGE) {
      for (int i = 0; i < 3; i++) {
         v[i][0] = (float)coord(-30, TW + 30);
         v[i][1] = (float)coord(-30, TH + 30);
      }
      /* one of them always spans the whole target */
      if (t_rand() < 0.5) {
         v[0][0] = -1.25f; v[0][1] = -3.5f;
         v[1][0] = TW - 0.25f; v[1][1] = (float)coord(-10, TH + 10);
         v[2][0] = (float)coord(-10, TW + 10); v[2][1] = TH - 0.125f;
      }
   } else if (k == K_CENTRES || k == K_HALVES) {
      double step = k == K_CENTRES ? 1.0 : 0.5;
      double off = (k == K_CENTRES && half) ? 0.5 : 0.0;
      double sz = coord(1, 40);
      for (int i = 0; i < 3; i++) {
         v[i][0] = (float)(floor((cx + coord(-sz, sz)) / step) * step + off);
         v[i][1] = (float)(floor((cy + coord(-sz, sz)) / step) * step + off);
      }
   } else if (k == K_DEGEN) {
      /* exactly collinear on the fixed grid, or two equal vertices */
      double q = 1.0 / 64;
      double ax = floor(cx / q) * q, ay = floor(cy / q) * q;
      double dx = floor(coord(-50, 50)) * q * 4, dy = floor(coord(-50, 50)) * q * 4;
      v[0][0] = (float)ax; v[0][1] = (float)ay;
      v[1][0] = (float)(ax + 2 * dx); v[1][1] = (float)(ay + 2 * dy);
      if (t_rand() < 0.5) {
         v[2][0] = (float)(ax + dx); v[2][1] = (float)(ay + dy);
      } else {
         v[2][0] = v[1][0]; v[2][1] = v[1][1];
      }
   } else if (k == K_GUARD) {
      /* around and beyond the target's edges: the wide profile holds
       * coordinates far outside, the seed one up to its 12-bit range */
      double r = wide ? 3000 : 1500, sz = coord(10, 600);
      double gx = coord(-r, TW + r), gy = coord(-r, TH + r);
      for (int i = 0; i < 3; i++) {
         v[i][0] = (float)(gx + coord(-sz, sz));
         v[i][1] = (float)(gy + coord(-sz, sz));
      }
   }
   /* The seed's X/Y format ends just below 2048: stay inside it (the
    * saturation test covers what happens beyond). */
   double lim = wide ? 30000 : 2047.5;
   for (int i = 0; i < 3; i++)
      for (int c = 0; c < 2; c++) {
         if (v[i][c] > lim) v[i][c] = (float)lim;
         if (v[i][c] < -lim) v[i][c] = (float)-lim;
      }
}
#endif

#ifdef FUZZ_TARGET
/* libFuzzer (tests/fuzz, ./fixpipe fuzz): one triangle from the input's
 * bytes, through the model and through the exact reference.  Byte 0: the
 * profile, the pixel-centre convention, the edge rule, whether vertices 1
 * and 2 are near vertex 0 (within 64 pixels: slivers and small triangles)
 * or anywhere, and whether anywhere is the whole 2048x2048 target or its
 * first 128x128; then six int32, each a coordinate on the 1/4096 grid of
 * the XY registers, from 32 pixels before that.  On the whole target,
 * unless bit 5 of byte 0 is set, the scan converter and the reference see
 * a 64x64 window of it (a scissor placed by the next two bytes, or by
 * bytes 1 and 5): triangles anywhere at the cost of 4,096 pixels, and the
 * edge walk's jump to the window's first scan line checked; the unit suite
 * draws whole large triangles.  A difference aborts. */
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
   static struct tctx t[2];
   static bool ready;
   if (!ready) {
      t_init(&t[0], "seed", TW, TH);
      t_init(&t[1], "wide", TW, TH);
      ready = true;
   }
   if (size < 1 + 6 * 4)
      return 0;
   const uint8_t flags = data[0];
   struct tctx *tc = &t[flags & 1];
   const bool half = flags & 2, bottom = flags & 4, near = flags & 8, whole = flags & 16;
   const int64_t far = whole ? TW + 64 : 128 + 64;     /* most triangles stay quick */
   float v[3][2];
   for (unsigned i = 0; i < 6; i++) {
      int32_t r;
      memcpy(&r, data + 1 + 4 * i, 4);
      const int64_t span = (i < 2 || !near ? far : 128) * INT64_C(4096);
      const int64_t off = i < 2 || !near ? -32 * INT64_C(4096) : -64 * INT64_C(4096);
      const int64_t g = ((int64_t)r % span + span) % span + off;
      v[i / 2][i % 2] = (float)((double)g / 4096.0 + (i >= 2 && near ? v[0][i % 2] : 0.0));
   }
   struct rast_raster_state rs;
   memset(&rs, 0, sizeof(rs));
   rs.half_pixel_center = half;
   rs.bottom_edge_rule = bottom;
   rs.line_width = 1;
   struct rast_scissor clip = { 0, 0, TW, TH };
   if (whole && !(flags & 32)) {
      const bool placed = size >= 1 + 6 * 4 + 2;
      const int wx = (placed ? data[1 + 6 * 4] : data[1]) * (TW - 64) / 255;
      const int wy = (placed ? data[2 + 6 * 4] : data[5]) * (TH - 64) / 255;
      clip = (struct rast_scissor){ wx, wy, wx + 64, wy + 64 };
      rs.scissor = true;
   }
   rast_set_raster_state(tc->rc, &rs);
   rast_set_scissor(tc->rc, &clip);
   struct outcome o = draw_and_compare(tc, v, half, bottom, clip);
   if (!o.same && !o.dsat) {
      fprintf(stderr, "scan_ref fuzz: %s half=%d bottom=%d: model %llu px, reference %llu, "
              "missing %llu, twice %llu, outside %llu; v=(%.9g,%.9g) (%.9g,%.9g) (%.9g,%.9g)\n",
              tc->prof->name, half, bottom, (unsigned long long)tc->count,
              (unsigned long long)o.ref, (unsigned long long)o.missing,
              (unsigned long long)tc->dups, (unsigned long long)tc->outside, v[0][0], v[0][1],
              v[1][0], v[1][1], v[2][0], v[2][1]);
      abort();
   }
   return 0;
}
#else

int main(int argc, char **argv)
{
   uint64_t n_total = (uint64_t)UNIT_TRIANGLES * 22 / 16, seed = 12345;
   t_count_seed_args(argc, argv, "test_scan_ref", "triangles", UINT64_MAX, &n_total, &seed);
   if (n_total == 0 || seed == 0) {
      fprintf(stderr, "test_scan_ref: --triangles and --seed take positive integers\n");
      return 2;
   }
   /* the named profiles and precision settings of X/Y (docs/profiles.md):
    * the exact walk is exact on any grid */
   const char *profiles[] = { "seed", "wide", "seed:xy=12.4", "seed:xy=12.18", "wide:xy=16.8" };
   const unsigned nprof = sizeof(profiles) / sizeof(profiles[0]);
   uint64_t total = 0, total_px = 0, sat_tris = 0, dxdy_sat_tris = 0, mismatches = 0;
   uint64_t per_kind[K_COUNT] = { 0 }, degen_culled_ok = 0, sat_class[RAST_REG_COUNT] = { 0 };
   /* 8 raster configurations of 2 named profiles, and of 3 settings at a quarter */
   uint64_t per_cfg = (n_total + 21) / 22;
   t_seed(seed);
   printf("scan_ref: seed %llu\n", (unsigned long long)seed);

   for (unsigned pi = 0; pi < nprof; pi++) {
      struct tctx t;
      t_init(&t, profiles[pi], TW, TH);
      const bool wide = t.prof->xy.int_bits > 12;
      const uint64_t n_tris = pi < 2 ? per_cfg : (per_cfg + 3) / 4;
      for (unsigned cfg = 0; cfg < 8; cfg++) {
         bool half = cfg & 1, bottom = (cfg >> 1) & 1, scissor = (cfg >> 2) & 1;
         t_raster_scissor(&t, half, bottom, scissor);
         struct rast_scissor clip = { 0, 0, TW, TH };
         for (uint64_t n = 0; n < n_tris; n++) {
            if (scissor && n % 64 == 0) {
               struct rast_scissor sc;
               sc.minx = (int)coord(0, TW); sc.maxx = sc.minx + (int)coord(0, TW);
               sc.miny = (int)coord(0, TH); sc.maxy = sc.miny + (int)coord(0, TH);
               if (sc.maxx > TW) sc.maxx = TW;
               if (sc.maxy > TH) sc.maxy = TH;
               rast_set_scissor(t.rc, &sc);
               clip = sc;
            }
            enum kind k;
            double r = t_rand();
            if (n % 1024 == 0) k = K_HUGE;
            else if (r < 0.35) k = K_SMALL;
            else if (r < 0.50) k = K_MEDIUM;
            else if (r < 0.65) k = K_SLIVER;
            else if (r < 0.77) k = K_CENTRES;
            else if (r < 0.89) k = K_HALVES;
            else if (r < 0.94) k = K_DEGEN;
            else k = K_GUARD;
            float v[3][2];
            gen(k, half, v, wide);
            struct rast_stats before = *rast_get_stats(t.rc);
            struct outcome o = draw_and_compare(&t, v, half, bottom, clip);
            const struct rast_stats *after = rast_get_stats(t.rc);
            const int64_t *X = o.X, *Y = o.Y;
            uint64_t ref = o.ref;
            bool same = o.same;
            if (o.sat) {
               sat_tris++;
               for (unsigned c = 0; c < RAST_REG_COUNT; c++)
                  sat_class[c] += t_sat_class(after, (enum rast_reg_class)c) !=
                                  t_sat_class(&before, (enum rast_reg_class)c);
            }
            if (o.dsat) dxdy_sat_tris++;
            if (k == K_DEGEN && (X[0] - X[2]) * (Y[1] - Y[2]) == (Y[0] - Y[2]) * (X[1] - X[2])) {
               CHECK(after->culled == before.culled + 1 && t.count == 0,
                     "degenerate triangle not dropped");
               degen_culled_ok++;
            }
            if (!same && !o.dsat) {
               mismatches++;
               CHECK(same, "%s %s half=%d bottom=%d scissor=%d kind=%s: model %llu px, ref %llu, "
                     "missing %llu, dups %llu, outside %llu, badquad %llu; v=(%.9g,%.9g) (%.9g,%.9g) (%.9g,%.9g)",
                     profiles[pi], "", half, bottom, scissor, kind_name[k],
                     (unsigned long long)t.count, (unsigned long long)ref,
                     (unsigned long long)o.missing, (unsigned long long)t.dups,
                     (unsigned long long)t.outside, (unsigned long long)t.badquad,
                     v[0][0], v[0][1], v[1][0], v[1][1], v[2][0], v[2][1]);
            }
            total++;
            total_px += ref;
            per_kind[k]++;
         }
      }
      t_fini(&t);
   }
   printf("scan_ref: %llu triangles, %llu reference pixels, %llu mismatches\n",
          (unsigned long long)total, (unsigned long long)total_px,
          (unsigned long long)mismatches);
   for (int k = 0; k < K_COUNT; k++)
      printf("  %-15s %llu\n", kind_name[k], (unsigned long long)per_kind[k]);
   printf("  degenerate triangles dropped: %llu\n", (unsigned long long)degen_culled_ok);
   printf("  triangles with a counted saturation: %llu (dx/dy slope saturations: %llu; "
          "those are excluded from the comparison)\n",
          (unsigned long long)sat_tris, (unsigned long long)dxdy_sat_tris);
   printf("  by register class: XY %llu, dx/dy %llu, Z %llu, colour %llu\n",
          (unsigned long long)sat_class[RAST_REG_XY], (unsigned long long)sat_class[RAST_REG_DXDY],
          (unsigned long long)sat_class[RAST_REG_Z], (unsigned long long)sat_class[RAST_REG_COLOR]);
   /* what was asked was run, with its share of the degenerate kind (5%) */
   CHECK(total >= n_total, "only %llu triangles", (unsigned long long)total);
   CHECK(degen_culled_ok > total / 200, "too few degenerate cases: %llu",
         (unsigned long long)degen_culled_ok);
   return t_summary("scan_ref");
}
#endif
