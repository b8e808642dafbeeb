/*
 * fp-thumb: crops and shrinks a PNG for the documentation, so the figures
 * in docs/ stay small.  Shrinking averages each NxN block, or with --max
 * keeps the block's brightest pixel: a heat map must not lose a single bad
 * pixel to averaging.
 *
 *   fp-thumb IN.png OUT.png [--crop X,Y,W,H] [--shrink N] [--max]
 */
#include "fp_png.h"

#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int usage(void)
{
   fprintf(stderr, "usage: fp-thumb IN.png OUT.png [--crop X,Y,W,H] [--shrink N] [--max]\n"
                   "  --crop    rectangle to keep, rows from the top (default: all)\n"
                   "  --shrink  divide width and height by N, averaging NxN blocks\n"
                   "  --max     shrink by keeping each block's brightest pixel\n");
   return 2;
}

static int bad(const char *option, const char *v)
{
   fprintf(stderr, "fp-thumb: bad %s '%s'\n", option, v);
   return usage();
}

int main(int argc, char **argv)
{
   static const struct option longopts[] = {
      { "crop", required_argument, NULL, 'c' },
      { "shrink", required_argument, NULL, 's' },
      { "max", no_argument, NULL, 'm' },
      { NULL, 0, NULL, 0 },
   };
   int cx = 0, cy = 0, cw = -1, ch = -1, n = 1, use_max = 0;
   for (int c; (c = getopt_long(argc, argv, "", longopts, NULL)) != -1;) {
      switch (c) {
      case 'c':
         if (sscanf(optarg, "%d,%d,%d,%d", &cx, &cy, &cw, &ch) != 4 || cx < 0 || cy < 0 ||
             cw < 1 || ch < 1)
            return bad("--crop", optarg);
         break;
      case 's':
         if ((n = atoi(optarg)) < 1)
            return bad("--shrink", optarg);
         break;
      case 'm': use_max = 1; break;
      default: return usage();
      }
   }
   if (argc - optind != 2)
      return usage();
   const char *const files[2] = { argv[optind], argv[optind + 1] };

   char err[512];
   int w, h;
   unsigned char *in;
   if (fp_png_read(files[0], &w, &h, &in, err, sizeof(err))) {
      fprintf(stderr, "fp-thumb: %s\n", err);
      return 2;
   }
   if (cw < 0) {
      cw = w;
      ch = h;
   }
   if (cx + cw > w || cy + ch > h) {
      fprintf(stderr, "fp-thumb: crop %d,%d,%d,%d outside the %dx%d image\n", cx, cy, cw, ch,
              w, h);
      return 2;
   }
   int ow = cw / n, oh = ch / n;
   if (ow < 1 || oh < 1) {
      fprintf(stderr, "fp-thumb: nothing left after shrinking by %d\n", n);
      return 2;
   }
   unsigned char *out = malloc((size_t)ow * (size_t)oh * 4);
   if (!out) {
      fprintf(stderr, "fp-thumb: out of memory\n");
      return 2;
   }
   for (int y = 0; y < oh; y++)
      for (int x = 0; x < ow; x++) {
         unsigned sum[4] = { 0, 0, 0, 0 };
         int best = -1;
         unsigned char *o = out + ((size_t)y * (size_t)ow + (size_t)x) * 4;
         for (int j = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
               const unsigned char *p =
                  in + ((size_t)(cy + y * n + j) * (size_t)w + (size_t)(cx + x * n + i)) * 4;
               int lum = p[0] + p[1] + p[2];
               if (lum > best) {
                  best = lum;
                  if (use_max)
                     memcpy(o, p, 4);
               }
               for (int c = 0; c < 4; c++)
                  sum[c] += p[c];
            }
         if (!use_max)
            for (int c = 0; c < 4; c++)
               o[c] = (unsigned char)((sum[c] + (unsigned)(n * n) / 2) / (unsigned)(n * n));
      }
   int rc = fp_png_write(files[1], ow, oh, out, err, sizeof(err));
   if (rc)
      fprintf(stderr, "fp-thumb: %s\n", err);
   free(in);
   free(out);
   return rc ? 2 : 0;
}
