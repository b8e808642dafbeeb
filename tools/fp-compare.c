/*
 * fp-compare: how far apart two renderings are.
 *
 *   fp-compare A.png B.png [--heatmap out.png] [--threshold T] [--mask M.png]
 *              [--format=text|kv] [--max-diff-pixels N] [--max-diff-percent P]
 *              [--max-error E] [--max-mean M] [--min-psnr DB]
 *
 * A pixel differs when any of its R, G, B, A errors exceeds T (default 0).
 * Max errors are per channel and over all four; mean error and PSNR are per
 * channel and over R, G, B ("overall"): alpha is 255 in both images of an
 * opaque rendering and would only flatter the figures.  Pixels whose mask
 * value is non-zero are left out of every figure but counted apart.
 * Exit: 0 within the limits, 1 over a --max-... or --min-psnr limit, 2 bad input.
 */
#include "fp_heatmap.h"
#include "fp_png.h"

#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

struct limits {
   double diff_pixels, diff_percent, error, mean, psnr;   /* < 0 (psnr: NAN) = none */
};

struct stats {
   long pixels, masked, masked_diff, diff;
   int max_err[4], max_all;
   double sum[4], sumsq[4];
   int bbox[4];   /* x0 y0 x1 y1 of differing pixels, inclusive */
};

static int usage(FILE *f)
{
   fprintf(f,
      "usage: fp-compare A.png B.png [--heatmap out.png] [--threshold T] [--mask M.png]\n"
      "                  [--format=text|kv] [--max-diff-pixels N] [--max-diff-percent P]\n"
      "                  [--max-error E] [--max-mean M] [--min-psnr DB]\n");
   return f == stdout ? 0 : 2;
}

static int bad(const char *msg)
{
   fprintf(stderr, "fp-compare: %s\n", msg);
   return 2;
}

static double psnr_of(double sumsq, double n)
{
   if (sumsq == 0.0 || n == 0.0)
      return INFINITY;
   return 10.0 * log10(255.0 * 255.0 / (sumsq / n));
}

static void fmt_psnr(char *buf, size_t len, double p)
{
   if (isinf(p))
      snprintf(buf, len, "inf");
   else
      snprintf(buf, len, "%.2f", p);
}

static int parse_num(const char *opt, const char *v, double *out)
{
   char *end;
   *out = strtod(v, &end);
   if (end == v || *end != '\0') {
      fprintf(stderr, "fp-compare: --%s needs a number, got '%s'\n", opt, v);
      return -1;
   }
   return 0;
}

int main(int argc, char **argv)
{
   const char *heatmap = NULL, *mask_path = NULL;
   int kv = 0;
   double threshold = 0;
   struct limits lim = { -1, -1, -1, -1, NAN };
   /* the numbers first, in the order of num[] */
   static const struct option longopts[] = {
      { "threshold", required_argument, NULL, 'n' },
      { "max-diff-pixels", required_argument, NULL, 'n' },
      { "max-diff-percent", required_argument, NULL, 'n' },
      { "max-error", required_argument, NULL, 'n' },
      { "max-mean", required_argument, NULL, 'n' },
      { "min-psnr", required_argument, NULL, 'n' },
      { "format", required_argument, NULL, 'f' },
      { "heatmap", required_argument, NULL, 'H' },
      { "mask", required_argument, NULL, 'm' },
      { "help", no_argument, NULL, 'h' },
      { NULL, 0, NULL, 0 },
   };
   double *const num[] = { &threshold, &lim.diff_pixels, &lim.diff_percent, &lim.error,
                           &lim.mean, &lim.psnr };

   for (int c, li; (c = getopt_long(argc, argv, "h", longopts, &li)) != -1;) {
      switch (c) {
      case 'n':
         if (parse_num(longopts[li].name, optarg, num[li]) != 0)
            return 2;
         break;
      case 'f':
         if (strcmp(optarg, "text") && strcmp(optarg, "kv")) {
            fprintf(stderr, "fp-compare: bad --format '%s' (text or kv)\n", optarg);
            return 2;
         }
         kv = !strcmp(optarg, "kv");
         break;
      case 'H': heatmap = optarg; break;
      case 'm': mask_path = optarg; break;
      case 'h': return usage(stdout);
      default: return usage(stderr);
      }
   }
   if (argc - optind != 2) {
      usage(stderr);
      return bad(argc - optind > 2 ? "more than two images given" : "two images are needed");
   }
   const char *const files[2] = { argv[optind], argv[optind + 1] };

   char err[512];
   int w[3], h[3];
   unsigned char *img[3] = { NULL, NULL, NULL };
   for (int k = 0; k < 3; k++) {
      const char *path = k < 2 ? files[k] : mask_path;
      if (!path)
         continue;
      if (fp_png_read(path, &w[k], &h[k], &img[k], err, sizeof(err)) != 0)
         return bad(err);
   }
   if (w[0] != w[1] || h[0] != h[1]) {
      fprintf(stderr, "fp-compare: size mismatch: %s is %dx%d, %s is %dx%d\n",
              files[0], w[0], h[0], files[1], w[1], h[1]);
      return 2;
   }
   if (img[2] && (w[2] != w[0] || h[2] != h[0])) {
      fprintf(stderr, "fp-compare: size mismatch: mask %s is %dx%d, images are %dx%d\n",
              mask_path, w[2], h[2], w[0], h[0]);
      return 2;
   }

   int W = w[0], H = h[0];
   size_t n = (size_t)W * (size_t)H;
   int *perr = malloc(sizeof(int) * n);
   if (!perr)
      return bad("out of memory");
   struct stats s;
   memset(&s, 0, sizeof(s));
   s.bbox[0] = W;
   s.bbox[1] = H;
   s.bbox[2] = s.bbox[3] = -1;
   for (size_t i = 0; i < n; i++) {
      const unsigned char *a = img[0] + i * 4, *b = img[1] + i * 4;
      int e = 0, d[4];
      for (int c = 0; c < 4; c++) {
         d[c] = abs((int)a[c] - (int)b[c]);
         if (d[c] > e)
            e = d[c];
      }
      if (img[2]) {
         const unsigned char *m = img[2] + i * 4;
         if (m[0] | m[1] | m[2]) {
            s.masked++;
            if (e > threshold)
               s.masked_diff++;
            perr[i] = -1;
            continue;
         }
      }
      perr[i] = e;
      s.pixels++;
      for (int c = 0; c < 4; c++) {
         if (d[c] > s.max_err[c])
            s.max_err[c] = d[c];
         s.sum[c] += d[c];
         s.sumsq[c] += (double)d[c] * d[c];
      }
      if (e > s.max_all)
         s.max_all = e;
      if (e > threshold) {
         int x = (int)(i % (size_t)W), y = (int)(i / (size_t)W);
         s.diff++;
         if (x < s.bbox[0]) s.bbox[0] = x;
         if (y < s.bbox[1]) s.bbox[1] = y;
         if (x > s.bbox[2]) s.bbox[2] = x;
         if (y > s.bbox[3]) s.bbox[3] = y;
      }
   }

   double np = s.pixels ? (double)s.pixels : 1.0;
   double pct = 100.0 * (double)s.diff / np;
   double mean[4], psnr[4];
   for (int c = 0; c < 4; c++) {
      mean[c] = s.sum[c] / np;
      psnr[c] = psnr_of(s.sumsq[c], (double)s.pixels);
   }
   double mean_all = (s.sum[0] + s.sum[1] + s.sum[2]) / (3.0 * np);
   double psnr_all = psnr_of(s.sumsq[0] + s.sumsq[1] + s.sumsq[2], 3.0 * (double)s.pixels);

   /* Limits, in the order they are reported. */
   char failed[256] = "";
   char tmp[96];
#define CHECK(cond, what)                                                   \
   do {                                                                     \
      if (cond) {                                                           \
         snprintf(tmp, sizeof(tmp), "%s%s", failed[0] ? "," : "", what);   \
         strncat(failed, tmp, sizeof(failed) - strlen(failed) - 1);         \
      }                                                                     \
   } while (0)
   CHECK(lim.diff_pixels >= 0 && (double)s.diff > lim.diff_pixels, "max_diff_pixels");
   CHECK(lim.diff_percent >= 0 && pct > lim.diff_percent, "max_diff_percent");
   CHECK(lim.error >= 0 && s.max_all > lim.error, "max_error");
   CHECK(lim.mean >= 0 && mean_all > lim.mean, "max_mean");
   CHECK(!isnan(lim.psnr) && psnr_all < lim.psnr, "min_psnr");
#undef CHECK

   static const char ch[4] = { 'r', 'g', 'b', 'a' };
   char pbuf[32];
   fmt_psnr(pbuf, sizeof(pbuf), psnr_all);
   if (kv) {
      printf("width=%d\nheight=%d\npixels=%ld\nmasked_pixels=%ld\nmasked_diff_pixels=%ld\n",
             W, H, s.pixels, s.masked, s.masked_diff);
      printf("threshold=%g\ndiff_pixels=%ld\ndiff_percent=%.4f\n", threshold, s.diff, pct);
      if (s.diff)
         printf("diff_bbox=%d,%d,%d,%d\n", s.bbox[0], s.bbox[1], s.bbox[2], s.bbox[3]);
      for (int c = 0; c < 4; c++) {
         char pc[32];
         fmt_psnr(pc, sizeof(pc), psnr[c]);
         printf("max_err_%c=%d\nmean_err_%c=%.4f\npsnr_%c=%s\n", ch[c], s.max_err[c],
                ch[c], mean[c], ch[c], pc);
      }
      printf("max_err=%d\nmean_err=%.4f\npsnr=%s\n", s.max_all, mean_all, pbuf);
      printf("result=%s\n", failed[0] ? "fail" : "pass");
      if (failed[0])
         printf("failed=%s\n", failed);
   } else {
      printf("images:       %s vs %s (%dx%d)\n", files[0], files[1], W, H);
      if (img[2])
         printf("masked:       %ld pixels left out (%ld of them differ)\n", s.masked,
                s.masked_diff);
      printf("differing:    %ld of %ld pixels (%.4f%%), error > %g\n", s.diff, s.pixels,
             pct, threshold);
      if (s.diff)
         printf("diff box:     x %d..%d, y %d..%d (rows from the top)\n", s.bbox[0],
                s.bbox[2], s.bbox[1], s.bbox[3]);
      printf("max error:    R %d  G %d  B %d  A %d  overall %d (of 255)\n", s.max_err[0],
             s.max_err[1], s.max_err[2], s.max_err[3], s.max_all);
      printf("mean error:   R %.4f  G %.4f  B %.4f  A %.4f  overall(RGB) %.4f\n", mean[0],
             mean[1], mean[2], mean[3], mean_all);
      printf("PSNR:         %s dB (RGB)\n", pbuf);
      if (failed[0])
         printf("FAIL:         over limit: %s\n", failed);
   }

   if (heatmap) {
      int lh = fp_heatmap_legend_height(W);
      unsigned char *hm = malloc((size_t)W * (size_t)(H + lh) * 4);
      if (!hm)
         return bad("out of memory");
      fp_heatmap_render(perr, W, H, hm);
      if (fp_png_write(heatmap, W, H + lh, hm, err, sizeof(err)) != 0)
         return bad(err);
      if (!kv)
         printf("heat map:     %s\n", heatmap);
      free(hm);
   }
   free(perr);
   for (int k = 0; k < 3; k++)
      free(img[k]);
   return failed[0] ? 1 : 0;
}
