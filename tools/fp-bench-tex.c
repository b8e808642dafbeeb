/*
 * fp-bench-tex: what the texture unit alone costs per quad, for the
 * sampler states the replays spend their time in.  A 300x200 RGBA8
 * texture (one level, CLAMP_TO_EDGE or REPEAT, LINEAR or NEAREST) is
 * sampled in pairs of quads and in fours, the ways the compiled shader
 * calls the unit (docs/jit.md), over a run of quads whose coordinates come from a plane: an
 * axis-aligned one (each coordinate follows one screen axis, as a 2-D
 * window's texture does), a sheared one (s follows x, t does not) or a
 * rotated one.  Prints the CPU time per quad, in pairs and in fours (where
 * the unit has no four-quad function, a four is two pairs).
 * No GL, no Mesa: the model's texture unit only.
 *
 *   fp-bench-tex [--quads N] [--runs N] [--case N] [--scalar] [--noskip]
 *   fp-bench-tex --window [--taps N] [--rows N] [--vertical] [--hot] [--fresh] [--runs N] [--scalar] [--noskip]
 *
 * --window samples a 640x480 texture one texel a pixel over the first N
 * quad rows (--rows, default all 240) of a 640x480 screen, each four
 * quads' taps (--taps, default 1) one after the other, a texel apart along
 * the rows or, with --vertical, down the columns (a blur's two passes, as
 * glmark2's desktop draws them): the texels come from memory as they do in
 * a replay, where the 300x200 cases stay in the caches.  --hot samples the
 * first quad row over and over instead, the same calls on texels in the
 * caches: the difference is what memory costs.  --fresh writes each call's
 * four quads just before the call, s and t as one 16-byte store each, as
 * the compiled shader does (docs/jit.md), where otherwise the rows are
 * written long before: the difference is what reading freshly stored
 * coordinates costs.  --quads and --case are the other cases' and are
 * refused with --window.
 *
 * --case N runs only the N-th case of the list (from 1), for a profile or
 * an instruction count of one sampler state.
 *
 * Each case runs N times (5); the fastest run is the figure, the mean shows
 * the noise.
 */
#define _POSIX_C_SOURCE 199309L
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "rast/tex/tex.h"
#include "fixed/numsys.h"

static double cpu_seconds(void)
{
   struct timespec t;
   clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
   return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

enum { TW = 300, TH = 200, ROW_QUADS = 320 };   /* a 640-pixel row of quads */

static uint8_t texels[TW * TH * 4];

enum { WW = 640, WH = 480 };
static uint8_t window_texels[WW * WH * 4];

static void bind_level(struct tex_unit *u, struct ns_stats *st, enum tex_wrap wrap,
                       enum tex_filter f, uint8_t *data, unsigned w, unsigned h)
{
   struct tex_view_desc v;
   struct tex_sampler_desc s;
   memset(&v, 0, sizeof(v));
   memset(&s, 0, sizeof(s));
   v.target = TEX_TARGET_2D;
   v.format = TEX_FMT_RGBA8;
   v.num_levels = 1;
   v.layers = 1;
   v.level[0] = (struct tex_level){ data, w * 4, w * h * 4, w, h, 1 };
   for (unsigned c = 0; c < 4; c++)
      v.swizzle[c] = (uint8_t)c;
   s.wrap[0] = s.wrap[1] = s.wrap[2] = wrap;
   s.min_filter = s.mag_filter = f;
   s.mip = TEX_MIP_NONE;
   s.normalized = true;
   s.min_lod = -1000;
   s.max_lod = 1000;
   tex_unit_bind(u, numsys_by_name("dfx24"), &v, &s, st);
}

static void bind(struct tex_unit *u, struct ns_stats *st, enum tex_wrap wrap, enum tex_filter f)
{
   bind_level(u, st, wrap, f, texels, TW, TH);
}

/* Texels that vary from one to the next (no filter takes a shortcut). */
static void fill_texels(uint8_t *t, size_t n)
{
   for (size_t i = 0; i < n; i++)
      t[i] = (uint8_t)(i * 2654435761u >> 24);
}

/* The quads of quad row qy, tap k of n: one texel a pixel, the tap k - n/2
 * texels along the row (or down the column: `vertical`), a quarter texel
 * off the centres (the filter blends). */
static void window_row(struct tex_quad *q, int qy, int k, int n, bool vertical)
{
   const float d = (float)(k - n / 2);
   const float dx = (vertical ? 0.0f : d) + 0.25f, dy = (vertical ? d : 0.0f) + 0.25f;
   for (int qx = 0; qx < WW / 2; qx++) {
      for (int p = 0; p < TEX_QUAD; p++) {
         const float x = (float)(2 * qx + (p & 1)) + 0.5f, y = (float)(2 * qy + (p >> 1)) + 0.5f;
         q[qx].s[p] = (x + dx) * (1.0f / WW);
         q[qx].t[p] = (y + dy) * (1.0f / WH);
      }
   }
}

enum { MAX_TAPS = 64 };

/* --window: ns a quad-sample, the whole screen or its first row (`hot`),
 * the taps of four quads one after the other, as a blur's shader calls
 * the unit. */
static int window_bench(int taps, int nrows, bool vertical, bool hot, bool fresh, int runs,
                        bool scalar, bool noskip)
{
   fill_texels(window_texels, sizeof(window_texels));
   struct tex_unit u;
   struct ns_stats st;
   memset(&st, 0, sizeof(st));
   bind_level(&u, &st, TEX_WRAP_CLAMP_TO_EDGE, TEX_FILTER_LINEAR, window_texels, WW, WH);
   tex_unit_set_datapath(&u, scalar, noskip);
   static struct tex_quad q[MAX_TAPS][WW / 2];
   struct tex_quad staged[4];
   memset(staged, 0, sizeof(staged));
   float rgba[4][4][TEX_QUAD], check = 0;
   double best = 1e30, total = 0, rows_best = 1e30;
   for (int r = 0; r < runs; r++) {
      double t0 = cpu_seconds(), gen = 0;
      for (int qy = 0; qy < nrows; qy++) {
         const double g0 = cpu_seconds();
         for (int k = 0; k < taps; k++)
            window_row(q[k], hot ? 0 : qy, k, taps, vertical);
         gen += cpu_seconds() - g0;
         for (int qx = 0; qx < WW / 2; qx += 4)
            for (int k = 0; k < taps; k++) {
               const struct tex_quad *in = &q[k][qx];
               if (fresh) {
                  for (int j = 0; j < 4; j++) {
                     memcpy(staged[j].s, q[k][qx + j].s, sizeof(staged[j].s));
                     memcpy(staged[j].t, q[k][qx + j].t, sizeof(staged[j].t));
                  }
                  in = staged;
               }
               tex_unit_sample_quads(&u, in, 4, TEX_LOD_IMPLICIT, rgba);
               check += rgba[3][0][3];
            }
      }
      const double t = cpu_seconds() - t0 - gen;
      best = t < best ? t : best;
      rows_best = gen < rows_best ? gen : rows_best;
      total += t;
   }
   const double n = (double)(WW / 2) * nrows * taps;
   printf("window %dx%d, %d tap%s %s, %s%s: fours %5.1f ns a quad (the fastest of %d runs of %.0f "
          "quads; mean %.1f; making the coordinates %.1f more), range events %llu\n",
          WW, WH, taps, taps == 1 ? "" : "s", vertical ? "down the columns" : "along the rows",
          hot ? "first row over and over" : "whole screen",
          fresh ? ", stored before each call" : "", 1e9 * best / n, runs, n,
          1e9 * total / runs / n, 1e9 * rows_best / n, (unsigned long long)(st.sat + st.flush));
   return check == -1.0f;
}

/* Quad (qx, qy) of the screen: pixel (x, y) at s = s0 + x·ds_dx + y·ds_dy;
 * `turn`: 0 axis-aligned, 1 sheared (t also follows x), 2 rotated. */
static void plane_quad(struct tex_quad *q, int qx, int qy, int turn)
{
   const float sx = 1.0f / 640, sy = 1.0f / 480;
   const float rx = turn == 2 ? 0.3f * sy : 0.0f, ry = turn ? -0.3f * sx : 0.0f;
   memset(q, 0, sizeof(*q));
   for (int p = 0; p < TEX_QUAD; p++) {
      const float x = (float)(2 * qx + (p & 1)) + 0.5f, y = (float)(2 * qy + (p >> 1)) + 0.5f;
      q->s[p] = 0.01f + x * sx + y * rx;
      q->t[p] = 0.02f + y * sy + x * ry;
   }
}

static int usage(void)
{
   fprintf(stderr, "usage: fp-bench-tex [--quads N] [--runs N] [--case N] [--scalar] [--noskip]\n"
                   "       fp-bench-tex --window [--taps N] [--rows N] [--vertical] [--hot] "
                   "[--fresh] [--runs N] [--scalar] [--noskip]\n");
   return 2;
}

int main(int argc, char **argv)
{
   long nquads = 2000000;
   int runs = 5, only = 0, taps = 1, nrows = WH / 2;
   int scalar = 0, noskip = 0, window = 0, hot = 0, vertical = 0, fresh = 0;
   bool quads_set = false;
   const struct option longopts[] = {
      { "quads", required_argument, NULL, 'q' },
      { "runs", required_argument, NULL, 'r' },
      { "case", required_argument, NULL, 'c' },
      { "taps", required_argument, NULL, 't' },
      { "rows", required_argument, NULL, 'R' },
      { "window", no_argument, &window, 1 },
      { "hot", no_argument, &hot, 1 },
      { "vertical", no_argument, &vertical, 1 },
      { "fresh", no_argument, &fresh, 1 },
      { "scalar", no_argument, &scalar, 1 },
      { "noskip", no_argument, &noskip, 1 },
      { NULL, 0, NULL, 0 },
   };
   for (int c; (c = getopt_long(argc, argv, "", longopts, NULL)) != -1;) {
      switch (c) {
      case 0: break;
      case 'q': nquads = atol(optarg); quads_set = true; break;
      case 'r': runs = atoi(optarg); break;
      case 'c': only = atoi(optarg); break;
      case 't': taps = atoi(optarg); break;
      case 'R': nrows = atoi(optarg); break;
      default: return usage();
      }
   }
   if (optind < argc)
      return usage();
   nquads &= ~3L;
   if (nquads < 4 || nquads > 1000000000 || runs < 1 || runs > 1000) {
      fprintf(stderr, "fp-bench-tex: --quads takes 4 to 10^9, --runs 1 to 1000\n");
      return 2;
   }
   if (window) {
      if (quads_set || only) {
         fprintf(stderr, "fp-bench-tex: --window takes --taps, --rows, --vertical, --hot, --fresh, "
                         "--runs, --scalar and --noskip, not --quads or --case\n");
         return 2;
      }
      if (taps < 1 || taps > MAX_TAPS || nrows < 1 || nrows > WH / 2) {
         fprintf(stderr, "fp-bench-tex: --taps takes 1 to %d, --rows 1 to %d\n", MAX_TAPS, WH / 2);
         return 2;
      }
      return window_bench(taps, nrows, vertical, hot, fresh, runs, scalar, noskip);
   }
   if (fresh || hot || vertical) {
      fprintf(stderr, "fp-bench-tex: --fresh, --hot and --vertical are --window's\n");
      return 2;
   }
   fill_texels(texels, sizeof(texels));

   static const struct {
      const char *name;
      enum tex_wrap wrap;
      enum tex_filter filter;
      int turn;
   } cases[] = {
      { "edge linear, axis-aligned", TEX_WRAP_CLAMP_TO_EDGE, TEX_FILTER_LINEAR, 0 },
      { "edge linear, sheared", TEX_WRAP_CLAMP_TO_EDGE, TEX_FILTER_LINEAR, 1 },
      { "edge linear, rotated", TEX_WRAP_CLAMP_TO_EDGE, TEX_FILTER_LINEAR, 2 },
      { "edge nearest, axis-aligned", TEX_WRAP_CLAMP_TO_EDGE, TEX_FILTER_NEAREST, 0 },
      { "repeat linear, axis-aligned", TEX_WRAP_REPEAT, TEX_FILTER_LINEAR, 0 },
      { "repeat linear, rotated", TEX_WRAP_REPEAT, TEX_FILTER_LINEAR, 2 },
   };
   /* four rows of quads of a 640-pixel screen, sampled over and over: the
    * coordinates stay in the caches, as a shader's would */
   enum { SCREEN = ROW_QUADS * 4 };
   static struct tex_quad q[SCREEN];
   float check = 0;
   const int ncases = (int)(sizeof(cases) / sizeof(cases[0]));
   if (only < 0 || only > ncases) {
      fprintf(stderr, "fp-bench-tex: --case takes 1 to %d (0: all)\n", ncases);
      return 2;
   }
   for (unsigned c = 0; c < (unsigned)ncases; c++) {
      if (only && c + 1 != (unsigned)only)
         continue;
      struct tex_unit u;
      struct ns_stats st;
      memset(&st, 0, sizeof(st));
      bind(&u, &st, cases[c].wrap, cases[c].filter);
      tex_unit_set_datapath(&u, scalar, noskip);
      for (int i = 0; i < SCREEN; i += 2) {
         plane_quad(&q[i], i % ROW_QUADS, i / ROW_QUADS, cases[c].turn);
         plane_quad(&q[i + 1], (i + 1) % ROW_QUADS, (i + 1) / ROW_QUADS, cases[c].turn);
      }
      float rgba[4][4][TEX_QUAD];
      double best[2] = { 1e30, 1e30 }, total[2] = { 0, 0 };
      for (int r = 0; r < runs; r++) {
         for (unsigned g = 0; g < 2; g++) {
            const double t0 = cpu_seconds();
            if (g == 0)
               for (long n = 0; n < nquads; n += 2) {
                  tex_unit_sample2(&u, &q[n % SCREEN], TEX_LOD_IMPLICIT, rgba);
                  check += rgba[1][0][3];
               }
            else
               for (long n = 0; n < nquads; n += 4) {
                  tex_unit_sample_quads(&u, &q[n % SCREEN], 4, TEX_LOD_IMPLICIT, rgba);
                  check += rgba[3][0][3];
               }
            const double t = cpu_seconds() - t0;
            best[g] = t < best[g] ? t : best[g];
            total[g] += t;
         }
      }
      printf("%-28s pairs %5.1f, fours %5.1f ns a quad (the fastest of %d runs of %ld quads; "
             "means %.1f, %.1f), range events %llu\n",
             cases[c].name, 1e9 * best[0] / (double)nquads, 1e9 * best[1] / (double)nquads, runs,
             nquads, 1e9 * total[0] / runs / (double)nquads,
             1e9 * total[1] / runs / (double)nquads, (unsigned long long)(st.sat + st.flush));
   }
   return check == -1.0f;   /* keeps the samples */
}
