/* Heat map colours and the legend with its tiny built-in digit font. */
#include "fp_heatmap.h"

#include <math.h>
#include <string.h>

#define LEGEND_H 20
#define RAMP_H 10

/* Error is mapped on a log2 scale: 1 LSB must already be visible, and the
 * step from 1 to 2 matters as much as the one from 128 to 255. */
static double ramp_pos(int err)
{
   return log2((double)err) / log2(255.0);
}

void fp_heatmap_ramp(int err, unsigned char rgb[3])
{
   static const double stop_t[] = { 0.0, 0.25, 0.5, 0.75, 0.9, 1.0 };
   static const unsigned char stop_c[][3] = {
      { 0, 60, 255 }, { 0, 220, 255 }, { 0, 255, 0 },
      { 255, 255, 0 }, { 255, 0, 0 }, { 255, 255, 255 },
   };
   double t = err <= 1 ? 0.0 : err >= 255 ? 1.0 : ramp_pos(err);
   int k = 0;
   while (k < 4 && t > stop_t[k + 1])
      k++;
   double f = (t - stop_t[k]) / (stop_t[k + 1] - stop_t[k]);
   for (int c = 0; c < 3; c++)
      rgb[c] = (unsigned char)lround(stop_c[k][c] + f * (stop_c[k + 1][c] - stop_c[k][c]));
}

int fp_heatmap_legend_height(int w)
{
   return w >= 96 ? LEGEND_H : 0;
}

/* 3x5 digits, one row per nibble (bit 2 = left column). */
static const unsigned char digit_font[10][5] = {
   {7, 5, 5, 5, 7}, {2, 6, 2, 2, 7}, {7, 1, 7, 4, 7}, {7, 1, 7, 1, 7}, {5, 5, 7, 1, 1},
   {7, 4, 7, 1, 7}, {7, 4, 7, 5, 7}, {7, 1, 1, 1, 1}, {7, 5, 7, 5, 7}, {7, 5, 7, 1, 7},
};

static void put(unsigned char *img, int w, int x, int y, const unsigned char rgb[3])
{
   unsigned char *p = img + ((size_t)y * (size_t)w + (size_t)x) * 4;
   p[0] = rgb[0];
   p[1] = rgb[1];
   p[2] = rgb[2];
   p[3] = 255;
}

static void draw_number(unsigned char *img, int w, int x, int y, int value)
{
   static const unsigned char white[3] = { 255, 255, 255 };
   char s[8];
   int n = 0;
   do {
      s[n++] = (char)('0' + value % 10);
      value /= 10;
   } while (value && n < 7);
   for (int i = 0; i < n; i++) {
      const unsigned char *g = digit_font[s[n - 1 - i] - '0'];
      for (int r = 0; r < 5; r++)
         for (int c = 0; c < 3; c++)
            if (g[r] & (4 >> c) && x + i * 4 + c < w)
               put(img, w, x + i * 4 + c, y + r, white);
   }
}

void fp_heatmap_render(const int *err, int w, int h, unsigned char *out)
{
   static const unsigned char black[3] = { 0, 0, 0 };
   static const unsigned char masked[3] = { 48, 48, 72 };
   for (int y = 0; y < h; y++)
      for (int x = 0; x < w; x++) {
         int e = err[(size_t)y * (size_t)w + (size_t)x];
         unsigned char rgb[3];
         if (e < 0)
            memcpy(rgb, masked, 3);
         else if (e == 0)
            memcpy(rgb, black, 3);
         else
            fp_heatmap_ramp(e, rgb);
         put(out, w, x, y, rgb);
      }

   int lh = fp_heatmap_legend_height(w);
   for (int y = h; y < h + lh; y++)
      for (int x = 0; x < w; x++)
         put(out, w, x, y, black);
   if (!lh)
      return;
   /* Ramp from error 1 (left) to 255 (right), labelled at the powers of 2. */
   for (int x = 0; x < w; x++) {
      int e = (int)lround(pow(255.0, (double)x / (w - 1)));
      unsigned char rgb[3];
      fp_heatmap_ramp(e < 1 ? 1 : e, rgb);
      for (int y = h + 1; y < h + 1 + RAMP_H; y++)
         put(out, w, x, y, rgb);
   }
   static const int labels[] = { 1, 2, 4, 8, 16, 32, 64, 128, 255 };
   int next_free = 0;
   for (int i = 0; i < 9; i++) {
      int x = (int)lround(ramp_pos(labels[i] < 2 ? 1 : labels[i]) * (w - 1));
      int digits = labels[i] >= 100 ? 3 : labels[i] >= 10 ? 2 : 1, tw = digits * 4 - 1;
      int tx = x - tw / 2;
      if (tx < 0)
         tx = 0;
      if (tx + tw > w)
         tx = w - tw;
      if (tx < next_free)
         continue;   /* no room on a narrow map: skip rather than overlap */
      static const unsigned char white[3] = { 255, 255, 255 };
      put(out, w, x, h + 1 + RAMP_H, white);
      draw_number(out, w, tx, h + RAMP_H + 3, labels[i]);
      next_free = tx + tw + 2;
   }
}
