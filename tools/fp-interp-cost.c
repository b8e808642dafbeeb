/*
 * fp-interp-cost: the seeds' cost figures from the model's own counters
 * (docs/interp-modes.md).  No GL: random triangles of a given area, Z and
 * the colour's R, G, B as registers (the seed's four), through the model in
 * each FIXPIPE_INTERP mode (rast_set_interp).
 *
 *   fp-interp-cost OUTDIR [--tris N] [--setup CLOCKS]
 *
 * writes OUTDIR/cost.csv (seed 002's table: additions, multiplications and
 * divisions per covered pixel of each mode and of the scan-line walk made
 * per-pixel independent, for polygons of 410 to 38,646 pixels) and
 * OUTDIR/cores.csv (seed 001's figure: pixels per clock on N modeled cores:
 * a coordinate manager hands each core one pixel of the triangle's
 * bounding box per clock after CLOCKS of set-up; the scan-line unit of
 * seed 000 takes one clock per covered pixel and one per span), and prints
 * both as tables.
 */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rast/rast.h"
#include "fixed/fx.h"

#define TARGET 512
#define PI 3.14159265358979323846
#define MAX_ROWS TARGET

static const double sizes[] = { 410, 1000, 2500, 5000, 10000, 20000, 38646 };
#define NSIZES (sizeof(sizes) / sizeof(sizes[0]))
static const unsigned cores[] = { 1, 2, 4, 8, 16, 32, 64 };
#define NCORES (sizeof(cores) / sizeof(cores[0]))

static uint64_t state = 0x5eed0c0575ull;
static double rnd(void)
{
   state ^= state << 13;
   state ^= state >> 7;
   state ^= state << 17;
   return (double)(state >> 11) * (1.0 / 9007199254740992.0);
}

/* the scan lines with covered pixels of the triangle being drawn */
static bool row_hit[MAX_ROWS];

static unsigned shade(void *ctx, const struct rast_quad *q, struct rast_shaded_quad *out)
{
   (void)ctx;
   (void)out;
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
      if (q->mask & (1u << i))
         row_hit[q->y + (i >> 1)] = true;
   return 0;
}

/* A triangle of about `area` pixels, not thinner than 1:4, inside the target. */
static void make_triangle(double area, float v[3][2][4])
{
   for (;;) {
      const double a = rnd() * 2 * PI, s = 0.6 + rnd() * 0.8;
      double x[3], y[3];
      for (unsigned k = 0; k < 3; k++) {
         const double t = a + k * 2 * PI / 3 + (rnd() - 0.5) * 1.2;
         x[k] = cos(t) * (k == 0 ? s : 1.0);
         y[k] = sin(t) * (k == 0 ? 1.0 / s : 1.0);
      }
      const double d = fabs((x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0])) / 2;
      if (d < 0.3)
         continue;
      const double sc = sqrt(area / d);
      double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
      for (unsigned k = 0; k < 3; k++) {
         x[k] *= sc;
         y[k] *= sc;
         xmin = fmin(xmin, x[k]); xmax = fmax(xmax, x[k]);
         ymin = fmin(ymin, y[k]); ymax = fmax(ymax, y[k]);
      }
      if (xmax - xmin > TARGET - 2 || ymax - ymin > TARGET - 2)
         continue;
      const double ox = 1 - xmin + rnd() * (TARGET - 2 - (xmax - xmin));
      const double oy = 1 - ymin + rnd() * (TARGET - 2 - (ymax - ymin));
      for (unsigned k = 0; k < 3; k++) {
         v[k][0][0] = (float)(x[k] + ox);
         v[k][0][1] = (float)(y[k] + oy);
         v[k][0][2] = (float)rnd();
         v[k][0][3] = 1.0f;
         for (unsigned c = 0; c < 4; c++)
            v[k][1][c] = (float)rnd();
      }
      return;
   }
}

int main(int argc, char **argv)
{
   /* both take a number: val[] in the same order */
   static const struct option longopts[] = {
      { "tris", required_argument, NULL, 0 },
      { "setup", required_argument, NULL, 0 },
      { NULL, 0, NULL, 0 },
   };
   unsigned ntris = 200, setup_clocks = 16;
   unsigned *const val[] = { &ntris, &setup_clocks };
   int opt, li;
   while ((opt = getopt_long(argc, argv, "", longopts, &li)) == 0)
      *val[li] = (unsigned)atoi(optarg);
   if (opt != -1 || argc - optind != 1 || !ntris) {
      fprintf(stderr, "usage: fp-interp-cost OUTDIR [--tris N] [--setup CLOCKS]\n");
      return 2;
   }
   const char *outdir = argv[optind];
   char path[4096];
   snprintf(path, sizeof(path), "%s/cost.csv", outdir);
   FILE *cost = fopen(path, "w");
   snprintf(path, sizeof(path), "%s/cores.csv", outdir);
   FILE *cf = fopen(path, "w");
   if (!cost || !cf) {
      fprintf(stderr, "fp-interp-cost: cannot write in %s\n", outdir);
      return 1;
   }

   struct rast_context *rc = rast_create(rast_profile_by_name("seed"));
   struct rast_framebuffer fb;
   memset(&fb, 0, sizeof(fb));
   fb.width = fb.height = TARGET;
   rast_set_framebuffer(rc, &fb);
   struct rast_vertex_layout vl;
   memset(&vl, 0, sizeof(vl));
   vl.vertex_size = 2;
   vl.num_varyings = 1;
   vl.varying[0] = (struct rast_varying){ .slot = 1, .interp = RAST_INTERP_COLOR, .usage_mask = 0x7 };   /* R, G, B */
   rast_set_vertex_layout(rc, &vl);
   struct rast_shader fs;
   memset(&fs, 0, sizeof(fs));
   fs.shade = shade;
   rast_set_shader(rc, &fs);
   struct rast_raster_state rs;
   memset(&rs, 0, sizeof(rs));
   rs.half_pixel_center = true;
   rs.cull = RAST_CULL_NONE;
   rs.line_width = 1.0f;
   rast_set_raster_state(rc, &rs);

   fprintf(cost, "pixels,mode,add,mul,div\n");
   fprintf(cf, "pixels,unit,cores,pixels_per_clock\n");
   printf("operations per covered pixel (Z, R, G, B), %u random triangles a size\n", ntris);
   printf("%8s | %-29s | %-29s | %-29s | %-29s | vector/baseline\n", "pixels",
          "scan-line walk (000) +,*,/", "walk per pixel (002 base) +,*", "barycentric (001) +,*,/",
          "vector (002) +,*,/");
   double ppc_sum[NSIZES][NCORES + 1];
   for (unsigned si = 0; si < NSIZES; si++) {
      float (*tri)[3][2][4] = malloc(sizeof(*tri) * ntris);
      for (unsigned n = 0; n < ntris; n++)
         make_triangle(sizes[si], tri[n]);
      double ops[3][3], base[2] = { 0, 0 };
      uint64_t covered = 0, box = 0, spans = 0;
      for (unsigned m = 0; m < 3; m++) {
         rast_set_interp(rc, m);
         rast_reset_stats(rc);
         for (unsigned n = 0; n < ntris; n++) {
            memset(row_hit, 0, sizeof(row_hit));
            rast_triangle(rc, (const float (*)[4])tri[n][0], (const float (*)[4])tri[n][1],
                          (const float (*)[4])tri[n][2]);
            rast_flush(rc);
            if (m == 0)
               for (unsigned r = 0; r < MAX_ROWS; r++)
                  spans += row_hit[r];
         }
         const struct rast_stats *st = rast_get_stats(rc);
         const double px = (double)st->pixels_covered;
         ops[m][0] = (double)st->interp_add / px;
         ops[m][1] = (double)st->interp_mul / px;
         ops[m][2] = (double)st->interp_div / px;
         fprintf(cost, "%.0f,%s,%.4f,%.4f,%.4f\n", sizes[si], rast_interp_name(m), ops[m][0],
                 ops[m][1], ops[m][2]);
         if (m == 0) {
            base[0] = (double)st->interp_indep_add / px;
            base[1] = (double)st->interp_indep_mul / px;
            fprintf(cost, "%.0f,baseline,%.4f,%.4f,0\n", sizes[si], base[0], base[1]);
            covered = st->pixels_covered;
            box = st->interp_box_pixels;
         }
      }
      printf("%8.0f | %8.2f %8.2f %9.4f | %13.2f %14.2f | %8.2f %8.2f %9.4f | %8.2f %8.2f %9.4f "
             "| %5.1f%% +, %5.1f%% *\n", sizes[si], ops[0][0], ops[0][1], ops[0][2], base[0],
             base[1], ops[1][0], ops[1][1], ops[1][2], ops[2][0], ops[2][1], ops[2][2],
             100 * ops[2][0] / base[0], 100 * ops[2][1] / base[1]);
      /* clocks: N cores on the box after the set-up; the scan-line unit */
      for (unsigned c = 0; c < NCORES; c++) {
         const double clocks = (double)ntris * setup_clocks +
                               ceil((double)box / cores[c]);
         ppc_sum[si][c] = (double)covered / clocks;
      }
      ppc_sum[si][NCORES] = (double)covered / ((double)ntris * setup_clocks + (double)covered +
                                               (double)spans);
      free(tri);
   }
   printf("\npixels per clock: seed 001's cores (one box pixel each a clock, %u clocks of "
          "set-up a triangle) and seed 000's scan-line unit\n%8s", setup_clocks, "pixels");
   for (unsigned c = 0; c < NCORES; c++)
      printf(" %7u", cores[c]);
   printf("   scan-line\n");
   for (unsigned si = 0; si < NSIZES; si++) {
      printf("%8.0f", sizes[si]);
      for (unsigned c = 0; c < NCORES; c++) {
         printf(" %7.2f", ppc_sum[si][c]);
         fprintf(cf, "%.0f,barycentric,%u,%.4f\n", sizes[si], cores[c], ppc_sum[si][c]);
      }
      printf("   %7.2f\n", ppc_sum[si][NCORES]);
      fprintf(cf, "%.0f,scanline,1,%.4f\n", sizes[si], ppc_sum[si][NCORES]);
   }
   rast_destroy(rc);
   fclose(cost);
   fclose(cf);
   return 0;
}
