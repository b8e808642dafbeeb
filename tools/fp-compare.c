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

static void usage(FILE *f)
{
   fprintf(f,
      "usage: fp-compare A.png B.png [--heatmap out.png] [--threshold T] [--mask M.png]\n"
      "                  [--format=text|kv] [--max-diff-pixels N] [--max-diff-percent P]\n"
      "                  [--max-error E] [--max-mean M] [--min-psnr DB]\n");
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
   if (!v)
      return -1;
   *out = strtod(v, &end);
   if (end == v || *end != '\0') {
      fprintf(stderr, "fp-compare: %s needs a number, got '%s'\n", opt, v);
      return -1;
   }
   return 0;
}

int main(int argc, char **argv)
{
   const char *files[2] = { NULL, NULL }, *heatmap = NULL, *mask_path = NULL;
   int nfiles = 0, kv = 0;
   double threshold = 0;
   struct limits lim = { -1, -1, -1, -1, NAN };

   for (int i = 1; i < argc; i++) {
      const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
      double *num = NULL;
      if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
         usage(stdout);
         return 0;
      } else if (!strcmp(a, "--format=kv")) {
         kv = 1;
         continue;
      } else if (!strcmp(a, "--format=text")) {
         kv = 0;
         continue;
      } else if (!strcmp(a, "--heatmap") && v) {
         heatmap = argv[++i];
         continue;
      } else if (!strcmp(a, "--mask") && v) {
         mask_path = argv[++i];
         continue;
      }
      /* --opt=value and --opt value both work for the numeric options. */
      char name[64];
      const char *eq = strchr(a, '=');
      size_t nlen = eq ? (size_t)(eq - a) : strlen(a);
      if (nlen >= sizeof(name))
         nlen = sizeof(name) - 1;
      memcpy(name, a, nlen);
      name[nlen] = '\0';
      if (!strcmp(name, "--threshold")) num = &threshold;
      else if (!strcmp(name, "--max-diff-pixels")) num = &lim.diff_pixels;
      else if (!strcmp(name, "--max-diff-percent")) num = &lim.diff_percent;
      else if (!strcmp(name, "--max-error")) num = &lim.error;
      else if (!strcmp(name, "--max-mean")) num = &lim.mean;
      else if (!strcmp(name, "--min-psnr")) num = &lim.psnr;
      if (num) {
         const char *val = eq ? eq + 1 : v;
         if (!eq)
            i++;
         if (parse_num(name, val, num) != 0)
            return 2;
      } else if (a[0] == '-' && a[1] != '\0') {
         usage(stderr);
         return bad("unknown option");
      } else if (nfiles < 2) {
         files[nfiles++] = a;
      } else {
         usage(stderr);
         return bad("more than two images given");
      }
   }
   if (nfiles != 2) {
      usage(stderr);
      return bad("two images are needed");
   }

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
