/*
 * fp-bench-persp: what the model alone costs for perspective-correct
 * varyings, per number system of the texture path.  The seed profile draws
 * N random triangles (up to 1024 px across, 1 <= w <= 21) with two
 * PERSPECTIVE texture coordinates into a 1024x1024 RGBA8 target through a
 * trivial shader, and prints the CPU time and covered pixels per second.
 * No GL, no Mesa: rast.h only (docs/dfx.md, "Speed").
 *
 *   fp-bench-persp [--triangles N] [--components C] [--scalar] [--nof32] [SYSTEM ...]
 *                                          (default: float dfx24 fx8.24 fx16.16)
 *
 * --components C: C PERSPECTIVE components (1 to 16, default 2) in vec4
 * varyings, as a shader with many varyings has (jellyfish reads 12).
 *
 * --scalar: the scalar reference datapath, nothing skipped (RAST_OPT_SCALAR,
 * RAST_OPT_NOSKIP; docs/datapath.md) instead of dfx24's lanes.
 *
 * --nof32: dfx24's division on binary64 lanes only (RAST_OPT_NOF32), where
 * the AVX-512 set takes three or four quads on binary32 lanes.
 */
#define _POSIX_C_SOURCE 199309L
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "rast/rast.h"
#include "fixed/numsys.h"

static unsigned shade(void *ctx, const struct rast_quad *q, struct rast_shaded_quad *o)
{
   (void)ctx;
   for (int i = 0; i < 4; i++) {
      o->color[0][0][i] = q->in[0][0][i];
      o->color[0][1][i] = q->in[0][1][i];
      o->color[0][2][i] = 0.5f;
      o->color[0][3][i] = 1;
   }
   return q->mask;
}

static void load(const uint8_t *s, unsigned n, float (*c)[4])
{
   (void)s;
   memset(c, 0, n * sizeof(*c));
}

static void store(uint8_t *d, unsigned n, const float (*c)[4])
{
   (void)d;
   (void)n;
   (void)c;
}

static double cpu_seconds(void)
{
   struct timespec t;
   clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
   return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static unsigned opts;
static int ncomp = 2;

static int run(const char *sys, int ntri)
{
   const int W = 1024, H = 1024;
   const struct numsys *ns = numsys_by_name(sys);
   if (!ns) {
      fprintf(stderr, "fp-bench-persp: unknown system '%s' (%s)\n", sys, numsys_names());
      return 2;
   }
   struct rast_context *rc = rast_create(rast_profile_by_name("seed"));
   rast_set_texfmt(rc, ns);
   rast_set_options(rc, opts);
   uint8_t *fbm = calloc((size_t)W * H, 4);
   if (!rc || !fbm) {
      fprintf(stderr, "fp-bench-persp: out of memory\n");
      return 1;
   }
   struct rast_framebuffer fb;
   memset(&fb, 0, sizeof fb);
   fb.width = W;
   fb.height = H;
   fb.nr_cbufs = 1;
   fb.cbuf[0] = (struct rast_color_target){ .base = fbm, .stride = W * 4, .cpp = 4,
                                            .layout = RAST_CL_RGBA8, .load = load,
                                            .store = store, .clamp = true };
   rast_set_framebuffer(rc, &fb);
   struct rast_raster_state rs;
   memset(&rs, 0, sizeof rs);
   rs.half_pixel_center = true;
   rs.line_width = 1;
   rast_set_raster_state(rc, &rs);
   struct rast_blend_state bs;
   memset(&bs, 0, sizeof bs);
   bs.rt[0].colormask = 15;
   rast_set_blend(rc, &bs);
   struct rast_vertex_layout vl;
   memset(&vl, 0, sizeof vl);
   const int nvar = (ncomp + 3) / 4;
   vl.vertex_size = 1 + nvar;
   vl.num_varyings = nvar;
   for (int i = 0; i < nvar; i++) {
      const int c = ncomp - 4 * i < 4 ? ncomp - 4 * i : 4;
      vl.varying[i] = (struct rast_varying){ .slot = 1 + i, .interp = RAST_INTERP_PERSPECTIVE,
                                             .usage_mask = (1u << c) - 1 };
   }
   rast_set_vertex_layout(rc, &vl);
   struct rast_shader fs = { .shade = shade, .num_outputs = 1 };
   rast_set_shader(rc, &fs);

   srand(1);          /* the same triangles for every system */
   double t0 = cpu_seconds();
   for (int n = 0; n < ntri; n++) {
      float v[3][5][4];
      for (int k = 0; k < 3; k++) {
         v[k][0][0] = (float)(rand() % W);
         v[k][0][1] = (float)(rand() % H);
         v[k][0][2] = 0.5f;
         v[k][0][3] = 1 / (1 + 20.0f * (float)rand() / (float)RAND_MAX);
         for (int c = 0; c < 16; c++)
            v[k][1 + c / 4][c % 4] = c < ncomp ? (float)rand() / (float)RAND_MAX : 0;
      }
      rast_triangle(rc, (const float (*)[4])v[0], (const float (*)[4])v[1],
                    (const float (*)[4])v[2]);
   }
   double s = cpu_seconds() - t0;
   const struct rast_stats *st = rast_get_stats(rc);
   printf("%-8s %.3f s CPU, %llu px covered, %.1f Mpx/s, tex_sat %llu, tex_flush %llu\n", sys,
          s, (unsigned long long)st->pixels_covered, (double)st->pixels_covered / s * 1e-6,
          (unsigned long long)st->tex_sat, (unsigned long long)st->tex_flush);
   rast_destroy(rc);
   free(fbm);
   return 0;
}

static int usage(FILE *f)
{
   fprintf(f, "usage: fp-bench-persp [--triangles N] [--components C] [--scalar] [--nof32] "
              "[SYSTEM ...]  (%s)\n", numsys_names());
   return f == stdout ? 0 : 2;
}

int main(int argc, char **argv)
{
   static const struct option longopts[] = {
      { "triangles", required_argument, NULL, 't' },
      { "components", required_argument, NULL, 'c' },
      { "scalar", no_argument, NULL, 's' },
      { "nof32", no_argument, NULL, 'n' },
      { "help", no_argument, NULL, 'h' },
      { NULL, 0, NULL, 0 },
   };
   int ntri = 800, rc = 0;
   for (int c; (c = getopt_long(argc, argv, "h", longopts, NULL)) != -1;) {
      switch (c) {
      case 't': ntri = atoi(optarg); break;
      case 'c': ncomp = atoi(optarg); break;
      case 's': opts |= RAST_OPT_SCALAR | RAST_OPT_NOSKIP; break;
      case 'n': opts |= RAST_OPT_NOF32; break;
      case 'h': return usage(stdout);
      default: return usage(stderr);
      }
   }
   if (ncomp < 1 || ncomp > 16) {
      fprintf(stderr, "fp-bench-persp: bad --components (1 to 16)\n");
      return 2;
   }
   if (ntri < 1) {
      fprintf(stderr, "fp-bench-persp: bad --triangles (1 or more)\n");
      return 2;
   }
   static const char *const def[] = { "float", "dfx24", "fx8.24", "fx16.16" };
   if (optind >= argc)
      for (unsigned i = 0; i < sizeof(def) / sizeof(def[0]); i++)
         rc |= run(def[i], ntri);
   for (int i = optind; i < argc; i++)
      rc |= run(argv[i], ntri);
   return rc;
}
