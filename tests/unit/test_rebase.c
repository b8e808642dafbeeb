/* The set-up's coordinate rebase (rast_varying.rebase_mask): a REPEAT
 * coordinate offset by an integer K (an even one under MIRRORED_REPEAT)
 * must reach the fragment stage as the same bits as without the offset,
 * at K = 2^17, 2^20 and 10^7, in both profiles and through every datapath
 * (lanes, noskip, scalar), for triangles and lines; and the test must be
 * able to fail: without the rebase, the offset coordinates differ.
 *
 * Random primitives with w from 0.5 to 2 and coordinates in [-2, 6) on the
 * grid that keeps u + K exact in binary32 (the float nearest, as a vertex
 * shader's output would be, is then the exact sum).  The offset
 * primitive's rebase is the unoffset one's plus K, so the planes are the
 * same bits.
 *
 * Second, which integer the rebase subtracts must not cost precision: on
 * ground-like triangles (1/w over a ratio of up to 6000, coordinates
 * growing with w to +-4096 as a receding plane's do) and on flat ones far
 * from 0, the interpolated coordinates' error against exact arithmetic is
 * no larger with the rebase than without it.  (Subtracting floor(min u)
 * failed this: it moved the near vertex, where the texture is magnified,
 * thousands of periods from 0, and the ground of fp-persp fell apart.) */
#include <math.h>
#include <string.h>
#include "tutil.h"

#define MAX_VALS (1u << 21)

static struct tctx t;
static float *rec[2];
static size_t nrec[2];
static int slot_rec;

static void hook(struct tctx *tc, const struct rast_quad *q)
{
   (void)tc;
   float *o = rec[slot_rec];
   size_t n = nrec[slot_rec];
   if (n + 3 + 2 * RAST_QUAD_SIZE > MAX_VALS)
      return;
   o[n++] = (float)q->x;
   o[n++] = (float)q->y;
   o[n++] = (float)q->mask;
   for (unsigned c = 0; c < 2; c++) {
      memcpy(&o[n], q->in[0][c], sizeof(q->in[0][c]));
      n += RAST_QUAD_SIZE;
   }
   nrec[slot_rec] = n;
}

static void layout(uint8_t mask, uint8_t even)
{
   struct rast_vertex_layout vl = t_layout_pos();
   struct rast_varying *v = t_layout_add(&vl, RAST_INTERP_PERSPECTIVE, 0x3);
   v->rebase_mask = mask;
   v->rebase_even = even;
   rast_set_vertex_layout(t.rc, &vl);
}

/* The grid of u in [-2, 6) whose sums with K are floats: ulp(K + 8). */
static double grid_of(double K)
{
   const float hi = (float)(K + 8.0);
   return (double)nextafterf(hi, INFINITY) - (double)hi;
}

struct prim {
   bool line;
   float v[3][2][4];
};

static void draw(const struct prim *p, double K)
{
   float v[3][2][4];
   memcpy(v, p->v, sizeof v);
   for (unsigned k = 0; k < 3; k++)
      for (unsigned c = 0; c < 2; c++) {
         const double u = (double)v[k][1][c] + K;
         CHECK((double)(float)u == u, "offset coordinate %.9g not exact", u);
         v[k][1][c] = (float)u;
      }
   t_begin(&t);
   if (p->line)
      t_line(t.rc, v[0], v[1]);
   else
      t_tri(t.rc, v[0], v[1], v[2]);
}

/* The primitive drawn at 0 into rec[0] and at K into rec[1]. */
static void draw_both(const struct prim *p, double K)
{
   nrec[0] = nrec[1] = 0;
   slot_rec = 0;
   draw(p, 0.0);
   slot_rec = 1;
   draw(p, K);
}

static void random_prim(struct prim *p, double grid)
{
   memset(p, 0, sizeof *p);
   p->line = t_rand() < 0.2;
   const double cx = 40 + 176 * t_rand(), cy = 40 + 176 * t_rand(), size = 4 + 60 * t_rand();
   for (unsigned k = 0; k < 3; k++) {
      const float w = (float)(0.5 + 1.5 * t_rand());
      p->v[k][0][0] = (float)(cx + size * (t_rand() - 0.5));
      p->v[k][0][1] = (float)(cy + size * (t_rand() - 0.5));
      p->v[k][0][2] = 0.5f;
      p->v[k][0][3] = 1.0f / w;
      for (unsigned c = 0; c < 2; c++)
         p->v[k][1][c] = (float)(grid * floor((-2 + 8 * t_rand()) / grid));
   }
}

/* The precision part: the hook sums |u - exact| over covered pixels,
 * modulo the period. */
static float prec_v[3][2][4];
static double prec_err[2], prec_max[2];
static uint64_t prec_pixels;
static int prec_slot;

static double exact_coord(unsigned c, double px, double py)
{
   float (*v)[2][4] = prec_v;
   double l[3];
   for (unsigned k = 0; k < 3; k++) {
      const unsigned a = (k + 1) % 3, b = (k + 2) % 3;
      l[k] = (v[b][0][0] - v[a][0][0]) * (py - v[a][0][1]) -
             (v[b][0][1] - v[a][0][1]) * (px - v[a][0][0]);
   }
   double num = 0, den = 0;
   for (unsigned k = 0; k < 3; k++) {
      num += l[k] * v[k][0][3] * v[k][1][c];
      den += l[k] * v[k][0][3];
   }
   return num / den;
}

static void prec_hook(struct tctx *tc, const struct rast_quad *q)
{
   (void)tc;
   for (unsigned p = 0; p < RAST_QUAD_SIZE; p++) {
      if (!(q->mask >> p & 1u))
         continue;
      const double px = q->x + (p & 1u) + 0.5, py = q->y + (p >> 1) + 0.5;
      for (unsigned c = 0; c < 2; c++) {
         /* the rebased coordinate is the exact one less a whole number */
         const double d = (double)q->in[0][c][p] - exact_coord(c, px, py);
         const double e = fabs(d - floor(d + 0.5));
         prec_err[prec_slot] += e;
         prec_max[prec_slot] = fmax(prec_max[prec_slot], e);
      }
      prec_pixels += prec_slot == 0;
   }
}

/* A triangle of a receding plane (ground) or a flat one far from 0. */
static void precision_prim(bool ground)
{
   const double cx = 40 + 176 * t_rand(), cy = 40 + 176 * t_rand(), size = 30 + 100 * t_rand();
   const double base = ground ? 0.0 : 500 + 3000 * t_rand();
   memset(prec_v, 0, sizeof prec_v);
   for (unsigned k = 0; k < 3; k++) {
      const double w = ground ? 0.6 * pow(6000.0, t_rand()) : 1.0;
      prec_v[k][0][0] = (float)(cx + size * (t_rand() - 0.5));
      prec_v[k][0][1] = (float)(cy + size * (t_rand() - 0.5));
      prec_v[k][0][2] = 0.5f;
      prec_v[k][0][3] = (float)(1.0 / w);
      for (unsigned c = 0; c < 2; c++)
         prec_v[k][1][c] = (float)(ground ? w * (2 * t_rand() - 1) : base + 40 * t_rand());
   }
}

static void precision(void)
{
   t_init(&t, "seed", 256, 256);
   t.hook = prec_hook;
   t_raster(&t, true, false);
   for (unsigned ground = 0; ground < 2; ground++) {
      prec_err[0] = prec_err[1] = prec_max[0] = prec_max[1] = 0;
      prec_pixels = 0;
      for (unsigned n = 0; n < 200; n++) {
         precision_prim(ground);
         for (prec_slot = 0; prec_slot < 2; prec_slot++) {
            layout(prec_slot ? 0x3 : 0x0, 0x0);
            float v[3][2][4];
            memcpy(v, prec_v, sizeof v);
            t_begin(&t);
            t_tri(t.rc, v[0], v[1], v[2]);
         }
      }
      const char *what = ground ? "ground" : "flat, far from 0";
      printf("rebase precision (%s): %llu pixels, mean |error| %.3g without the rebase, "
             "%.3g with it; max %.3g, %.3g\n", what, (unsigned long long)prec_pixels,
             prec_err[0] / (2.0 * (double)prec_pixels), prec_err[1] / (2.0 * (double)prec_pixels),
             prec_max[0], prec_max[1]);
      CHECK(prec_pixels > 50000, "%s: only %llu pixels", what, (unsigned long long)prec_pixels);
      CHECK(prec_err[1] <= prec_err[0] * 1.02, "%s: the rebase costs precision (%.6g against %.6g)",
            what, prec_err[1], prec_err[0]);
      CHECK(prec_max[1] <= prec_max[0] * 1.02, "%s: the rebase's worst error %.6g against %.6g",
            what, prec_max[1], prec_max[0]);
   }
   t_fini(&t);
}

int main(void)
{
   static const double offsets[] = { 131072.0, 1048576.0, 1e7 };
   static const char *const profiles[] = { "seed", "wide" };
   static const unsigned opts[] = { 0, RAST_OPT_NOSKIP, RAST_OPT_SCALAR };
   for (unsigned i = 0; i < 2; i++)
      rec[i] = malloc(MAX_VALS * sizeof(float));
   uint64_t prims = 0, quads_compared = 0, rebased = 0, differ_without = 0;
   t_seed(0x7265626173650001ull);
   for (unsigned pf = 0; pf < 2; pf++) {
      t_init(&t, profiles[pf], 256, 256);
      t.hook = hook;
      t_raster(&t, true, false);
      for (unsigned o = 0; o < 3; o++) {
         rast_set_options(t.rc, opts[o]);
         for (unsigned ki = 0; ki < 3; ki++) {
            const double K = offsets[ki];
            const double grid = grid_of(K);
            for (unsigned even = 0; even < 2; even++) {
               /* 10^7 is even; every K here is a whole number of mirror periods */
               layout(0x3, even ? 0x3 : 0x0);
               for (unsigned n = 0; n < 60; n++) {
                  struct prim p;
                  random_prim(&p, grid);
                  const uint64_t r0 = rast_get_stats(t.rc)->tex_rebased;
                  draw_both(&p, K);
                  /* the unoffset primitive's own rebase counted too */
                  rebased += rast_get_stats(t.rc)->tex_rebased - r0;
                  prims++;
                  CHECK(nrec[0] == nrec[1] &&
                           !memcmp(rec[0], rec[1], nrec[0] * sizeof(float)),
                        "%s opts %u K %.0f %s %s %u: the offset coordinates differ",
                        profiles[pf], opts[o], K, even ? "even" : "integer",
                        p.line ? "line" : "triangle", n);
                  quads_compared += nrec[0] / (3 + 2 * RAST_QUAD_SIZE);
               }
            }
            /* without the rebase the offset must show (the test's teeth) */
            layout(0, 0);
            for (unsigned n = 0; n < 20; n++) {
               struct prim p;
               random_prim(&p, grid);
               draw_both(&p, K);
               if (nrec[0] != nrec[1])
                  continue;
               bool d = false;
               for (size_t i = 0; i < nrec[0]; i += 3 + 2 * RAST_QUAD_SIZE)
                  for (unsigned j = 3; j < 3 + 2 * RAST_QUAD_SIZE; j++)
                     d |= fabs((double)rec[1][i + j] - K - rec[0][i + j]) > 1e-3;
               differ_without += d;
            }
         }
      }
      t_fini(&t);
   }
   CHECK(quads_compared > 20000, "only %llu quads compared", (unsigned long long)quads_compared);
   /* each offset primitive rebases both components (the unoffset ones
    * mostly by 0 or -2) */
   CHECK(rebased >= 2 * prims, "rebased %llu component-primitives of %llu primitives",
         (unsigned long long)rebased, (unsigned long long)prims);
   CHECK(differ_without > 100, "without the rebase only %llu primitives differ",
         (unsigned long long)differ_without);
   printf("rebase: %llu primitives, %llu quads the same bits with and without the offset; "
          "%llu primitives wrong without the rebase\n",
          (unsigned long long)prims, (unsigned long long)quads_compared,
          (unsigned long long)differ_without);
   for (unsigned i = 0; i < 2; i++)
      free(rec[i]);
   precision();
   return t_summary("rebase");
}
