/*
 * Watertightness: meshes that tile a region must cover every pixel whose
 * centre is strictly inside exactly once and nothing strictly outside, with
 * both edge rules and both pixel-centre conventions.  Meshes: jittered grids
 * (each cell split along a random diagonal, random winding), fans around a
 * centre (often exactly on a pixel centre), and strips between two random
 * polylines.  Vertices are snapped to coarse subpixel grids so that many
 * pixel centres lie exactly on shared edges and vertices.
 */
#include <getopt.h>
#include <math.h>
#include <string.h>
#include "tutil.h"
#include "fixed/fx.h"

#define W 512
#define H 512

static struct tctx t;
static unsigned meshes;

static void tri(float ax, float ay, float bx, float by, float cx, float cy)
{
   float v[3][1][4] = { { { ax, ay, 0.5f, 1 } }, { { bx, by, 0.5f, 1 } }, { { cx, cy, 0.5f, 1 } } };
   t_begin(&t);
   if (t_rand() < 0.5)
      t_tri(t.rc, v[0], v[1], v[2]);
   else
      t_tri(t.rc, v[0], v[2], v[1]);
   CHECK(t.dups == 0 && t.badquad == 0, "a triangle emitted a pixel twice or a bad quad");
}

static float snap(double v, double grid) { return (float)(floor(v / grid + 0.5) * grid); }

/* inside(x, y): +1 strictly inside, -1 strictly outside, 0 on the boundary */
typedef int (*region_fn)(double x, double y, const void *ctx);

/* Pixels within `margin` of the outline are not judged inside or outside:
 * the literal walk (walk=literal) moves the outline by its drift.  Its
 * holes and overlaps inside are counted and printed, not required to be
 * zero: that is what the setting exists to measure. */
static double margin;
static bool measured, measure_only;
static uint64_t literal_holes, literal_twice, literal_inside;

static int region_with_margin(region_fn region, const void *ctx, double x, double y)
{
   const int r = region(x, y, ctx);
   if (margin == 0 || r == 0)
      return r;
   for (int dy = -1; dy <= 1; dy++)
      for (int dx = -1; dx <= 1; dx++)
         if (region(x + dx * margin, y + dy * margin, ctx) != r)
            return 0;
   return r;
}

static void verify(const char *what, region_fn region, const void *ctx, double hc)
{
   uint64_t bad_in = 0, bad_out = 0, multi = 0, inside = 0;
   for (int j = 0; j < H; j++)
      for (int i = 0; i < W; i++) {
         uint8_t h = t.hits[(size_t)j * W + (size_t)i];
         int r = region_with_margin(region, ctx, i + hc, j + hc);
         if (h > 1) multi++;
         if (r > 0) { inside++; if (h != 1) bad_in++; }
         if (r < 0 && h != 0) bad_out++;
      }
   if (measured) {
      /* not required: drifted edges cross near the vertices they
       * converge on (docs/profiles.md) */
      literal_holes += bad_in + bad_out;
      literal_twice += multi;
      literal_inside += inside;
      memset(t.hits, 0, (size_t)W * H);
      meshes++;
      return;
   }
   CHECK(bad_in == 0 && bad_out == 0 && multi == 0 && inside > 0,
         "%s %s: %llu inside pixels, %llu not covered once, %llu covered outside, %llu covered twice",
         t.prof->name, what, (unsigned long long)inside, (unsigned long long)bad_in,
         (unsigned long long)bad_out, (unsigned long long)multi);
   memset(t.hits, 0, (size_t)W * H);
   meshes++;
}

struct rect { double x0, y0, x1, y1; };
static int in_rect(double x, double y, const void *c)
{
   const struct rect *r = c;
   if (x > r->x0 && x < r->x1 && y > r->y0 && y < r->y1) return 1;
   if (x < r->x0 || x > r->x1 || y < r->y0 || y > r->y1) return -1;
   return 0;
}

static void grid_mesh(double grid, double hc)
{
   enum { N = 12 };
   float px[N + 1][N + 1], py[N + 1][N + 1];
   struct rect r;
   r.x0 = snap(20 + 10 * t_rand(), grid);
   r.y0 = snap(20 + 10 * t_rand(), grid);
   double cw = 25 + 10 * t_rand(), ch = 25 + 10 * t_rand();
   r.x1 = snap(r.x0 + N * cw, grid);
   r.y1 = snap(r.y0 + N * ch, grid);
   for (int j = 0; j <= N; j++)
      for (int i = 0; i <= N; i++) {
         double x = r.x0 + (r.x1 - r.x0) * i / N, y = r.y0 + (r.y1 - r.y0) * j / N;
         if (i > 0 && i < N) x += (t_rand() - 0.5) * cw * 0.4;
         if (j > 0 && j < N) y += (t_rand() - 0.5) * ch * 0.4;
         px[j][i] = (i == 0 || i == N) ? (float)x : snap(x, grid);
         py[j][i] = (j == 0 || j == N) ? (float)y : snap(y, grid);
      }
   for (int j = 0; j < N; j++)
      for (int i = 0; i < N; i++) {
         if (t_rand() < 0.5) {
            tri(px[j][i], py[j][i], px[j][i + 1], py[j][i + 1], px[j + 1][i + 1], py[j + 1][i + 1]);
            tri(px[j][i], py[j][i], px[j + 1][i + 1], py[j + 1][i + 1], px[j + 1][i], py[j + 1][i]);
         } else {
            tri(px[j][i], py[j][i], px[j][i + 1], py[j][i + 1], px[j + 1][i], py[j + 1][i]);
            tri(px[j][i + 1], py[j][i + 1], px[j + 1][i + 1], py[j + 1][i + 1], px[j + 1][i], py[j + 1][i]);
         }
      }
   verify("jittered grid", in_rect, &r, hc);
}

/* A convex polygon (counter-clockwise on screen, y down). */
struct poly { int n; double x[64], y[64]; };
static int in_poly(double x, double y, const void *c)
{
   const struct poly *p = c;
   int on = 0;
   for (int i = 0; i < p->n; i++) {
      int k = (i + 1) % p->n;
      double e = (p->x[k] - p->x[i]) * (y - p->y[i]) - (p->y[k] - p->y[i]) * (x - p->x[i]);
      if (e < 0) return -1;
      if (e == 0) on = 1;
   }
   return on ? 0 : 1;
}

static void fan_mesh(double grid, double hc)
{
   struct poly p;
   p.n = 8 + (int)(t_rand() * 40);
   double cx = floor(150 + 200 * t_rand()) + hc, cy = floor(150 + 200 * t_rand()) + hc;
   if (t_rand() < 0.3) { cx = snap(cx + t_rand(), grid); cy = snap(cy + t_rand(), grid); }
   double rad = 20 + 120 * t_rand(), a0 = t_rand();
   for (int i = 0; i < p.n; i++) {
      double a = a0 + 6.283185307179586 * i / p.n;
      p.x[i] = snap(cx + rad * cos(a), grid);
      p.y[i] = snap(cy + rad * sin(a), grid);
   }
   /* snapping keeps it convex for these radii and counts */
   for (int i = 0; i < p.n; i++) {
      int k = (i + 1) % p.n;
      tri((float)cx, (float)cy, (float)p.x[i], (float)p.y[i], (float)p.x[k], (float)p.y[k]);
   }
   verify("fan", in_poly, &p, hc);
}

/* A strip between two random monotone polylines y = top(x), bottom(x). */
struct strip { int n; double x[40], yt[40], yb[40]; };
static int in_strip(double x, double y, const void *c)
{
   const struct strip *s = c;
   if (x <= s->x[0] || x >= s->x[s->n - 1]) return x < s->x[0] || x > s->x[s->n - 1] ? -1 : 0;
   int i = 0;
   while (x > s->x[i + 1]) i++;
   double f = (x - s->x[i]) / (s->x[i + 1] - s->x[i]);
   double yt = s->yt[i] + f * (s->yt[i + 1] - s->yt[i]);
   double yb = s->yb[i] + f * (s->yb[i + 1] - s->yb[i]);
   if (y > yt + 1e-9 && y < yb - 1e-9) return 1;
   if (y < yt - 1e-9 || y > yb + 1e-9) return -1;
   return 0;
}

static void strip_mesh(double grid, double hc)
{
   struct strip s;
   s.n = 6 + (int)(t_rand() * 30);
   double x = snap(10 + 20 * t_rand(), grid);
   for (int i = 0; i < s.n; i++) {
      s.x[i] = x;
      double mid = 250 + 60 * sin(x / 40.0);
      s.yt[i] = snap(mid - 20 - 80 * t_rand(), grid);
      s.yb[i] = snap(mid + 20 + 80 * t_rand(), grid);
      x = snap(x + 2 + 30 * t_rand(), grid);
   }
   for (int i = 0; i + 1 < s.n; i++) {
      tri((float)s.x[i], (float)s.yt[i], (float)s.x[i + 1], (float)s.yt[i + 1], (float)s.x[i], (float)s.yb[i]);
      tri((float)s.x[i + 1], (float)s.yt[i + 1], (float)s.x[i + 1], (float)s.yb[i + 1], (float)s.x[i], (float)s.yb[i]);
   }
   verify("strip", in_strip, &s, hc);
}

/* Every mesh kind on every grid the profile's X/Y holds, in both edge rules
 * and pixel-centre conventions. */
static void run_meshes(const char *spec)
{
   t_init(&t, spec, W, H);
   t.counting = true;
   const double finest = ldexp(1.0, -(int)t.prof->xy.frac_bits);
   /* measured: the literal walk's drift over the meshes' 500 scan lines
    * at most, and the snapping of a coarse grid, kept off the outline */
   measured = measure_only || t.prof->literal_walk || finest > 1.0 / 64;
   margin = !measured ? 0
            : 1.0 + (t.prof->literal_walk ? 500.0 * ldexp(1.0, -(int)t.prof->dxdy.frac_bits) : 0);
   for (int cfg = 0; cfg < 4; cfg++) {
      bool half = cfg & 1, bottom = cfg >> 1;
      t_raster(&t, half, bottom);
      double hc = half ? 0.5 : 0.0;
      const double grids[4] = { 0.5, 0.25, 1.0 / 64, 1.0 / 4096 };
      for (int rep = 0; rep < 24; rep++) {
         double g = fmax(grids[rep % 4], finest);
         grid_mesh(g, hc);
         fan_mesh(g, hc);
         strip_mesh(g, hc);
      }
   }
}

/* With arguments (--measure SPEC...): each setting's holes and double hits
 * as key=value, for ./fixpipe sweep; nothing checked. */
int main(int argc, char **argv)
{
   static const struct option opts[] = {
      { "measure", no_argument, NULL, 'm' },
      { NULL, 0, NULL, 0 },
   };
   int c;
   while ((c = getopt_long(argc, argv, "", opts, NULL)) == 'm')
      measure_only = true;
   if (c != -1 || measure_only != (optind < argc)) {
      fprintf(stderr, "usage: test_watertight [--measure SPEC...]\n");
      return 2;
   }
   t_seed(777);
   if (measure_only) {
      for (int i = optind; i < argc; i++) {
         run_meshes(argv[i]);
         printf("profile=%s inside=%llu holes=%llu twice=%llu\n", t.prof->name,
                (unsigned long long)literal_inside, (unsigned long long)literal_holes,
                (unsigned long long)literal_twice);
         literal_holes = literal_twice = literal_inside = 0;
         t_fini(&t);
      }
      return 0;
   }
   /* the named profiles and X/Y on a 1/64 grid: watertight; the literal
    * walk with the seed's slope and with a 6-bit one: measured
    * (docs/profiles.md) */
   const char *profiles[] = { "seed", "wide", "seed:xy=12.6", "seed:walk=literal",
                              "seed:walk=literal,dxdy=12.6" };
   for (int pi = 0; pi < (int)(sizeof(profiles) / sizeof(profiles[0])); pi++) {
      run_meshes(profiles[pi]);
      if (measured) {
         printf("watertight: %s: %llu pixels inside, %llu not covered once, %llu covered twice\n",
                t.prof->name, (unsigned long long)literal_inside,
                (unsigned long long)literal_holes, (unsigned long long)literal_twice);
         if (t.prof->dxdy.frac_bits < 8)
            CHECK(literal_holes > 0 && literal_twice > 0,
                  "%s: the drift left no hole or overlap to measure", t.prof->name);
         literal_holes = literal_twice = literal_inside = 0;
      }
      t_fini(&t);
   }
   printf("watertight: %u meshes checked\n", meshes);
   return t_summary("watertight");
}
