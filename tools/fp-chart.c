/*
 * fp-chart: a scatter/line chart as PNG for docs/texture-formats.md, so the
 * figure generator needs nothing beyond libpng (no matplotlib on a fresh
 * Debian).  A 5x7 bitmap font, drawn at twice its size; lower case is
 * drawn as upper case.
 *
 *   fp-chart DATA OUT.png [--size WxH]
 *
 * DATA, one directive a line ('#' starts a comment):
 *   title TEXT | xlabel TEXT | ylabel TEXT | logx | logy
 *   legend tl|tr|bl|br              (corner of the plot area; default tr)
 *   xrange LO HI | yrange LO HI     (default: the data's, padded)
 *   series R,G,B line|points NAME   (the following points belong to it)
 *   X Y [LABEL]                     (a point; on a log axis values are
 *                                    clamped to the range's low end)
 */
#include "fp_png.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_SERIES 16
#define MAX_POINTS 64
#define SCALE 2                 /* font pixels per glyph pixel */
#define GLYPH_W (6 * SCALE)     /* advance: 5 columns and a gap */
#define GLYPH_H (7 * SCALE)

struct glyph {
   char c;
   unsigned char rows[7];       /* bit 4 is the leftmost column */
};

static const struct glyph font[] = {
   { '0', { 0x0e, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0e } },
   { '1', { 0x04, 0x0c, 0x04, 0x04, 0x04, 0x04, 0x0e } },
   { '2', { 0x0e, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1f } },
   { '3', { 0x1e, 0x01, 0x01, 0x0e, 0x01, 0x01, 0x1e } },
   { '4', { 0x02, 0x06, 0x0a, 0x12, 0x1f, 0x02, 0x02 } },
   { '5', { 0x1f, 0x10, 0x1e, 0x01, 0x01, 0x11, 0x0e } },
   { '6', { 0x06, 0x08, 0x10, 0x1e, 0x11, 0x11, 0x0e } },
   { '7', { 0x1f, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08 } },
   { '8', { 0x0e, 0x11, 0x11, 0x0e, 0x11, 0x11, 0x0e } },
   { '9', { 0x0e, 0x11, 0x11, 0x0f, 0x01, 0x02, 0x0c } },
   { 'A', { 0x0e, 0x11, 0x11, 0x1f, 0x11, 0x11, 0x11 } },
   { 'B', { 0x1e, 0x11, 0x11, 0x1e, 0x11, 0x11, 0x1e } },
   { 'C', { 0x0e, 0x11, 0x10, 0x10, 0x10, 0x11, 0x0e } },
   { 'D', { 0x1c, 0x12, 0x11, 0x11, 0x11, 0x12, 0x1c } },
   { 'E', { 0x1f, 0x10, 0x10, 0x1e, 0x10, 0x10, 0x1f } },
   { 'F', { 0x1f, 0x10, 0x10, 0x1e, 0x10, 0x10, 0x10 } },
   { 'G', { 0x0e, 0x11, 0x10, 0x17, 0x11, 0x11, 0x0f } },
   { 'H', { 0x11, 0x11, 0x11, 0x1f, 0x11, 0x11, 0x11 } },
   { 'I', { 0x0e, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0e } },
   { 'J', { 0x07, 0x02, 0x02, 0x02, 0x02, 0x12, 0x0c } },
   { 'K', { 0x11, 0x12, 0x14, 0x18, 0x14, 0x12, 0x11 } },
   { 'L', { 0x10, 0x10, 0x10, 0x10, 0x10, 0x10, 0x1f } },
   { 'M', { 0x11, 0x1b, 0x15, 0x15, 0x11, 0x11, 0x11 } },
   { 'N', { 0x11, 0x11, 0x19, 0x15, 0x13, 0x11, 0x11 } },
   { 'O', { 0x0e, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0e } },
   { 'P', { 0x1e, 0x11, 0x11, 0x1e, 0x10, 0x10, 0x10 } },
   { 'Q', { 0x0e, 0x11, 0x11, 0x11, 0x15, 0x12, 0x0d } },
   { 'R', { 0x1e, 0x11, 0x11, 0x1e, 0x14, 0x12, 0x11 } },
   { 'S', { 0x0f, 0x10, 0x10, 0x0e, 0x01, 0x01, 0x1e } },
   { 'T', { 0x1f, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04 } },
   { 'U', { 0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0e } },
   { 'V', { 0x11, 0x11, 0x11, 0x11, 0x11, 0x0a, 0x04 } },
   { 'W', { 0x11, 0x11, 0x11, 0x15, 0x15, 0x15, 0x0a } },
   { 'X', { 0x11, 0x11, 0x0a, 0x04, 0x0a, 0x11, 0x11 } },
   { 'Y', { 0x11, 0x11, 0x0a, 0x04, 0x04, 0x04, 0x04 } },
   { 'Z', { 0x1f, 0x01, 0x02, 0x04, 0x08, 0x10, 0x1f } },
   { '.', { 0x00, 0x00, 0x00, 0x00, 0x00, 0x0c, 0x0c } },
   { ',', { 0x00, 0x00, 0x00, 0x00, 0x0c, 0x04, 0x08 } },
   { '-', { 0x00, 0x00, 0x00, 0x1f, 0x00, 0x00, 0x00 } },
   { '+', { 0x00, 0x04, 0x04, 0x1f, 0x04, 0x04, 0x00 } },
   { '/', { 0x01, 0x02, 0x02, 0x04, 0x08, 0x08, 0x10 } },
   { '(', { 0x02, 0x04, 0x08, 0x08, 0x08, 0x04, 0x02 } },
   { ')', { 0x08, 0x04, 0x02, 0x02, 0x02, 0x04, 0x08 } },
   { ':', { 0x00, 0x0c, 0x0c, 0x00, 0x0c, 0x0c, 0x00 } },
   { '=', { 0x00, 0x00, 0x1f, 0x00, 0x1f, 0x00, 0x00 } },
   { '%', { 0x18, 0x19, 0x02, 0x04, 0x08, 0x13, 0x03 } },
   { '_', { 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x1f } },
   { '^', { 0x04, 0x0a, 0x11, 0x00, 0x00, 0x00, 0x00 } },
   { '<', { 0x02, 0x04, 0x08, 0x10, 0x08, 0x04, 0x02 } },
   { '>', { 0x08, 0x04, 0x02, 0x01, 0x02, 0x04, 0x08 } },
   { '*', { 0x00, 0x04, 0x15, 0x0e, 0x15, 0x04, 0x00 } },
   { '#', { 0x0a, 0x0a, 0x1f, 0x0a, 0x1f, 0x0a, 0x0a } },
   { '\'', { 0x04, 0x04, 0x08, 0x00, 0x00, 0x00, 0x00 } },
};

struct point {
   double x, y;
   char label[32];
};

struct series {
   unsigned char rgb[3];
   int line;
   char name[128];
   struct point pt[MAX_POINTS];
   int n;
};

struct chart {
   char title[128], xlabel[128], ylabel[128];
   int logx, logy, have_xr, have_yr;
   char legend[4];
   double xr[2], yr[2];
   struct series s[MAX_SERIES];
   int ns;
};

struct canvas {
   int w, h;
   unsigned char *px;
};

static void put(struct canvas *c, int x, int y, const unsigned char rgb[3])
{
   if (x < 0 || y < 0 || x >= c->w || y >= c->h)
      return;
   unsigned char *p = c->px + ((size_t)y * (size_t)c->w + (size_t)x) * 4;
   p[0] = rgb[0];
   p[1] = rgb[1];
   p[2] = rgb[2];
   p[3] = 255;
}

static void rect(struct canvas *c, int x0, int y0, int x1, int y1, const unsigned char rgb[3])
{
   for (int y = y0; y <= y1; y++)
      for (int x = x0; x <= x1; x++)
         put(c, x, y, rgb);
}

static void line(struct canvas *c, int x0, int y0, int x1, int y1, int thick,
                 const unsigned char rgb[3])
{
   int dx = abs(x1 - x0), dy = -abs(y1 - y0);
   int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1, e = dx + dy;
   for (;;) {
      rect(c, x0 - thick / 2, y0 - thick / 2, x0 + (thick - 1) / 2, y0 + (thick - 1) / 2, rgb);
      if (x0 == x1 && y0 == y1)
         break;
      int e2 = 2 * e;
      if (e2 >= dy) {
         e += dy;
         x0 += sx;
      }
      if (e2 <= dx) {
         e += dx;
         y0 += sy;
      }
   }
}

static const struct glyph *find_glyph(char ch)
{
   ch = (char)toupper((unsigned char)ch);
   for (size_t i = 0; i < sizeof(font) / sizeof(font[0]); i++)
      if (font[i].c == ch)
         return &font[i];
   return NULL;                  /* space and anything unknown: blank */
}

/* vertical: reads bottom to top (the y axis label). */
static void text(struct canvas *c, int x, int y, const char *s, int vertical,
                 const unsigned char rgb[3])
{
   for (; *s; s++) {
      const struct glyph *g = find_glyph(*s);
      for (int r = 0; g && r < 7; r++)
         for (int col = 0; col < 5; col++) {
            if (!(g->rows[r] & (0x10 >> col)))
               continue;
            for (int j = 0; j < SCALE; j++)
               for (int i = 0; i < SCALE; i++) {
                  int gx = col * SCALE + i, gy = r * SCALE + j;
                  if (vertical)
                     put(c, x + gy, y - gx, rgb);
                  else
                     put(c, x + gx, y + gy, rgb);
               }
         }
      if (vertical)
         y -= GLYPH_W;
      else
         x += GLYPH_W;
   }
}

static int text_w(const char *s)
{
   return (int)strlen(s) * GLYPH_W;
}

static double tr(double v, int logscale, double lo)
{
   if (!logscale)
      return v;
   return log10(v > lo ? v : lo);
}

static void fmt_tick(char *buf, size_t n, double v)
{
   if (fabs(v) < 1e-12)
      v = 0;
   snprintf(buf, n, "%g", v);
}

/* Tick positions in data units: decades on a log axis, 1/2/5 steps else. */
static int ticks(double lo, double hi, int logscale, double *t, int max)
{
   int n = 0;
   if (logscale) {
      for (int k = (int)floor(log10(lo)); k <= (int)ceil(log10(hi)) && n < max; k++) {
         double v = pow(10, k);
         if (v >= lo * 0.999 && v <= hi * 1.001)
            t[n++] = v;
      }
      return n;
   }
   double span = hi - lo, raw = span / 6, mag = pow(10, floor(log10(raw)));
   double step = raw / mag < 1.5 ? mag : raw / mag < 3.5 ? 2 * mag : raw / mag < 7.5 ? 5 * mag
                                                                            : 10 * mag;
   for (double v = ceil(lo / step) * step; v <= hi + step * 1e-9 && n < max; v += step)
      t[n++] = v;
   return n;
}

static void die(const char *msg, const char *arg)
{
   fprintf(stderr, "fp-chart: %s%s\n", msg, arg ? arg : "");
   exit(2);
}

static void parse(struct chart *ch, const char *path)
{
   FILE *f = fopen(path, "r");
   if (!f)
      die("cannot open ", path);
   char buf[512];
   struct series *cur = NULL;
   while (fgets(buf, sizeof(buf), f)) {
      buf[strcspn(buf, "\r\n")] = 0;
      char *p = buf;
      while (isspace((unsigned char)*p))
         p++;
      if (!*p || *p == '#')
         continue;
      unsigned r, g, b;
      char kind[16], rest[128];
      if (!strncmp(p, "title ", 6)) {
         snprintf(ch->title, sizeof(ch->title), "%s", p + 6);
      } else if (!strncmp(p, "xlabel ", 7)) {
         snprintf(ch->xlabel, sizeof(ch->xlabel), "%s", p + 7);
      } else if (!strncmp(p, "ylabel ", 7)) {
         snprintf(ch->ylabel, sizeof(ch->ylabel), "%s", p + 7);
      } else if (sscanf(p, "legend %3s", ch->legend) == 1) {
         if (strcmp(ch->legend, "tl") && strcmp(ch->legend, "tr") &&
             strcmp(ch->legend, "bl") && strcmp(ch->legend, "br"))
            die("legend takes tl, tr, bl or br, not ", ch->legend);
      } else if (!strcmp(p, "logx")) {
         ch->logx = 1;
      } else if (!strcmp(p, "logy")) {
         ch->logy = 1;
      } else if (sscanf(p, "xrange %lf %lf", &ch->xr[0], &ch->xr[1]) == 2) {
         ch->have_xr = 1;
      } else if (sscanf(p, "yrange %lf %lf", &ch->yr[0], &ch->yr[1]) == 2) {
         ch->have_yr = 1;
      } else if (sscanf(p, "series %u,%u,%u %15s %127[^\n]", &r, &g, &b, kind, rest) == 5) {
         if (ch->ns == MAX_SERIES)
            die("too many series", NULL);
         cur = &ch->s[ch->ns++];
         cur->rgb[0] = (unsigned char)r;
         cur->rgb[1] = (unsigned char)g;
         cur->rgb[2] = (unsigned char)b;
         cur->line = !strcmp(kind, "line");
         snprintf(cur->name, sizeof(cur->name), "%s", rest);
      } else {
         struct point pt = { 0, 0, "" };
         if (sscanf(p, "%lf %lf %31s", &pt.x, &pt.y, pt.label) < 2)
            die("cannot read line: ", p);
         if (!cur || cur->n == MAX_POINTS)
            die("point outside a series or too many points: ", p);
         cur->pt[cur->n++] = pt;
      }
   }
   fclose(f);
}

int main(int argc, char **argv)
{
   int W = 900, H = 560;
   if (argc == 5 && !strcmp(argv[3], "--size")) {
      if (sscanf(argv[4], "%dx%d", &W, &H) != 2 || W < 300 || H < 200 || W > 4000 || H > 4000)
         die("bad --size ", argv[4]);
   } else if (argc != 3) {
      die("usage: fp-chart DATA OUT.png [--size WxH]", NULL);
   }
   static struct chart ch;
   parse(&ch, argv[1]);

   double lo[2] = { INFINITY, INFINITY }, hi[2] = { -INFINITY, -INFINITY };
   for (int i = 0; i < ch.ns; i++)
      for (int k = 0; k < ch.s[i].n; k++) {
         double v[2] = { ch.s[i].pt[k].x, ch.s[i].pt[k].y };
         int lg[2] = { ch.logx, ch.logy };
         for (int a = 0; a < 2; a++) {
            if (lg[a] && v[a] <= 0)
               continue;
            lo[a] = fmin(lo[a], v[a]);
            hi[a] = fmax(hi[a], v[a]);
         }
      }
   int logs[2] = { ch.logx, ch.logy };
   for (int a = 0; a < 2; a++) {
      if (!isfinite(lo[a])) {
         lo[a] = logs[a] ? 0.1 : 0;
         hi[a] = logs[a] ? 10 : 1;
      }
      if (logs[a]) {
         lo[a] /= 2;
         hi[a] *= 2;
      } else {
         double pad = (hi[a] - lo[a]) * 0.08 + (hi[a] == lo[a] ? 1 : 0);
         lo[a] = lo[a] - pad < 0 && lo[a] >= 0 ? 0 : lo[a] - pad;
         hi[a] += pad;
      }
   }
   if (ch.have_xr) {
      lo[0] = ch.xr[0];
      hi[0] = ch.xr[1];
   }
   if (ch.have_yr) {
      lo[1] = ch.yr[0];
      hi[1] = ch.yr[1];
   }
   if (!(hi[0] > lo[0]) || !(hi[1] > lo[1]) || (ch.logx && lo[0] <= 0) ||
       (ch.logy && lo[1] <= 0))
      die("empty or invalid range", NULL);

   struct canvas c = { W, H, calloc((size_t)W * (size_t)H, 4) };
   if (!c.px)
      die("out of memory", NULL);
   static const unsigned char white[3] = { 255, 255, 255 }, black[3] = { 0, 0, 0 },
                              grid[3] = { 222, 222, 222 }, grey[3] = { 90, 90, 90 };
   rect(&c, 0, 0, W - 1, H - 1, white);
   int L = 110, R = W - 24, T = 56, B = H - 70;   /* plot area */

   double tx0 = tr(lo[0], ch.logx, lo[0]), tx1 = tr(hi[0], ch.logx, lo[0]);
   double ty0 = tr(lo[1], ch.logy, lo[1]), ty1 = tr(hi[1], ch.logy, lo[1]);
#define PX(v) (L + (int)lround((tr((v), ch.logx, lo[0]) - tx0) / (tx1 - tx0) * (R - L)))
#define PY(v) (B - (int)lround((tr((v), ch.logy, lo[1]) - ty0) / (ty1 - ty0) * (B - T)))

   double t[32];
   char buf[64];
   int nt = ticks(lo[0], hi[0], ch.logx, t, 32);
   for (int i = 0; i < nt; i++) {
      int x = PX(t[i]);
      line(&c, x, T, x, B, 1, grid);
      fmt_tick(buf, sizeof(buf), t[i]);
      text(&c, x - text_w(buf) / 2, B + 8, buf, 0, grey);
   }
   nt = ticks(lo[1], hi[1], ch.logy, t, 32);
   for (int i = 0; i < nt; i++) {
      int y = PY(t[i]);
      line(&c, L, y, R, y, 1, grid);
      fmt_tick(buf, sizeof(buf), t[i]);
      text(&c, L - 8 - text_w(buf), y - GLYPH_H / 2, buf, 0, grey);
   }
   line(&c, L, B, R, B, 2, black);
   line(&c, L, T, L, B, 2, black);
   text(&c, (W - text_w(ch.title)) / 2, 16, ch.title, 0, black);
   text(&c, (L + R - text_w(ch.xlabel)) / 2, H - 30, ch.xlabel, 0, black);
   text(&c, 14, (T + B + text_w(ch.ylabel)) / 2, ch.ylabel, 1, black);

   int right = strcmp(ch.legend, "tl") && strcmp(ch.legend, "bl");
   int ly = ch.legend[0] == 'b' ? B - 8 - ch.ns * (GLYPH_H + 8) : T + 8;
   for (int i = 0; i < ch.ns; i++) {
      const struct series *s = &ch.s[i];
      int px = 0, py = 0;
      for (int k = 0; k < s->n; k++) {
         int x = PX(s->pt[k].x), y = PY(s->pt[k].y);
         if (s->line && k > 0)
            line(&c, px, py, x, y, 2, s->rgb);
         px = x;
         py = y;
      }
      for (int k = 0; k < s->n; k++) {
         int x = PX(s->pt[k].x), y = PY(s->pt[k].y);
         rect(&c, x - 5, y - 5, x + 5, y + 5, black);
         rect(&c, x - 4, y - 4, x + 4, y + 4, s->rgb);
         text(&c, x + 9, y - GLYPH_H - 2, s->pt[k].label, 0, s->rgb);
      }
      /* Legend, in the corner asked for. */
      int lx = right ? R - 12 - text_w(s->name) - 24 : L + 12;
      rect(&c, lx, ly + 2, lx + 12, ly + 12, s->rgb);
      text(&c, lx + 22, ly, s->name, 0, black);
      ly += GLYPH_H + 8;
   }

   char err[256];
   if (fp_png_write(argv[2], W, H, c.px, err, sizeof(err)))
      die(err, NULL);
   free(c.px);
   return 0;
}
