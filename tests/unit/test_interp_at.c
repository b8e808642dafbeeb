/*
 * interpolateAt* in the model (rast_interp_at, interp/interp_at.c), on
 * random triangles with a PERSPECTIVE, a COLOR and a LINEAR varying, for
 * each Z/colour interpolator (FIXPIPE_INTERP), each number system of the
 * division and both datapaths (lanes, scalar):
 *
 *  - at the pixel's own point (offset 0, a sample on a single-sampled
 *    target) every component is the walk's, bit for bit, and at the
 *    centroid so is it on a multisampled target too (where the model
 *    shades a pixel whose centre is uncovered at its first covered sample);
 *  - at sample k of a multisampled target, from a shader run once a
 *    sample: every component is bit for bit what the walk at sample k gave the
 *    pixel, and so are the scan-line walk's colour and noperspective
 *    registers, taken where the walk is;
 *  - from the pixel centre to sample k: the perspective components and
 *    the per-pixel modes' colour registers are sample k's walk's bits;
 *    the scan-line colour register misses the exact plane through the
 *    vertices' registers by at most one last bit more than the centre's
 *    register does (the walk's steps round, and the subpixel correction
 *    rounds once more), and the noperspective one is sample k's walk's
 *    within binary32's rounding of the two walks;
 *  - an offset of sample k's position gives what sample k gives, and an
 *    offset beyond the pixel is clamped to its edge.
 *
 *   test_interp_at [--scenes N] [--seed S]
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tutil.h"
#include "fixed/numsys.h"

#define W 48
#define H 40
#define NS RAST_MSAA_SAMPLES
#define SLOTS 4                  /* position, perspective, colour, linear */
#define NVAR 3                   /* in[0] perspective, in[1] colour, in[2] linear */

static uint64_t rng = 0x9e3779b97f4a7c15ull;

/* Two binary32 walks of a noperspective plane, each a row start and up to
 * W steps of ∂/∂x, then one subpixel correction: each addition rounds by
 * half a last bit of values below 8 (2^-21); measured 1.2e-6 over the
 * scenes of the default seed. */
#define LINEAR_TOLERANCE 4e-6

struct probe {
   struct rast_context *rc;
   bool per_sample;             /* the run shades once a sample */
   bool centre;                 /* single-sampled: every quad is shaded at the centres */
   bool scanline;               /* the colour registers walk seed 000's way */
   unsigned quads;
   unsigned bad_exact;          /* a component that must be the walk's bits, and is not */
   unsigned bad_color;          /* scan-line colour: the correction off by more than a bit */
   unsigned bad_linear;         /* noperspective off by more than the rounding */
   unsigned bad_offset;         /* an offset unlike the sample at its point */
   unsigned bad_clamp;          /* an offset beyond the pixel unlike its edge */
   double worst_color;          /* in last bits beyond the centre's own error */
   double worst_color_walk;     /* in last bits from the sample's walk */
   int64_t X[3], Y[3];          /* the vertices, 1/4096 pixel */
   int64_t ra[4][3];            /* their colour registers */
   bool color_steep[4];         /* the component's exact slope beyond the register */
   unsigned steep;              /* pixel-samples skipped for it */
   double worst_linear;         /* relative to 1 + |v| */
};

static bool same(const float *a, const float *b)
{
   return memcmp(a, b, sizeof(float) * RAST_QUAD_SIZE) == 0;
}

static void splat(float v[RAST_QUAD_SIZE], float f)
{
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
      v[i] = f;
}

static void at(struct probe *p, const struct rast_quad *q, unsigned var,
               enum rast_interp_at_kind kind, float a0, float a1, float out[4][RAST_QUAD_SIZE])
{
   float x[RAST_QUAD_SIZE], y[RAST_QUAD_SIZE];
   splat(x, a0);
   splat(y, a1);
   rast_interp_at(p->rc, q, var, kind, x, y, out);
}

static float bits_f(unsigned u)
{
   union { unsigned u; float f; } v = { u };
   return v.f;
}

/* The colour register's unit: colour·255 in 12 fraction bits. */
#define UNIT (255.0L * 4096.0L)

/* What the walk at each sample gave each covered pixel (the run shaded
 * once a sample), for the centre run's offsets to compare with. */
static float walked[NS][W * H][NVAR][4];
static uint8_t has_walked[NS][W * H];

static unsigned shade(void *ctx, const struct rast_quad *q, struct rast_shaded_quad *out)
{
   struct probe *p = ctx;
   p->quads++;
   float v[4][RAST_QUAD_SIZE], w[4][RAST_QUAD_SIZE];
   if (!p->per_sample) {
      /* where the model shaded: the centre, or (multisampled, the centre
       * uncovered) the first covered sample */
      for (unsigned var = 0; var < NVAR; var++) {
         at(p, q, var, RAST_INTERP_AT_CENTROID, 0.0f, 0.0f, v);
         for (unsigned c = 0; c < 4; c++)
            p->bad_exact += !same(v[c], q->in[var][c]);
      }
   }
   if (p->per_sample) {
      /* at sample k, the sample's own walk: every family's bits; an offset
       * to the sample's position the same */
      const unsigned k = q->sample;
      const float ox = rast_sample_pos_4x[k][0] - 0.5f, oy = rast_sample_pos_4x[k][1] - 0.5f;
      for (unsigned var = 0; var < NVAR; var++) {
         at(p, q, var, RAST_INTERP_AT_SAMPLE, bits_f(k), 0.0f, v);
         at(p, q, var, RAST_INTERP_AT_OFFSET, ox, oy, w);
         for (unsigned c = 0; c < 4; c++) {
            p->bad_exact += !same(v[c], q->in[var][c]);
            p->bad_offset += !same(v[c], w[c]);
         }
      }
      for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
         if (!(q->mask >> i & 1u))
            continue;
         const size_t px = (size_t)(q->y + (int)(i >> 1)) * W + (size_t)(q->x + (int)(i & 1));
         has_walked[k][px] = 1;
         for (unsigned var = 0; var < NVAR; var++)
            for (unsigned c = 0; c < 4; c++)
               walked[k][px][var][c] = q->in[var][c][i];
      }
   }
   if (p->centre) {
      /* the pixel's own point, two more ways */
      for (unsigned var = 0; var < NVAR; var++) {
         at(p, q, var, RAST_INTERP_AT_OFFSET, 0.0f, 0.0f, v);
         for (unsigned c = 0; c < 4; c++)
            p->bad_exact += !same(v[c], q->in[var][c]);
         at(p, q, var, RAST_INTERP_AT_SAMPLE, bits_f(2), 0.0f, v);
         for (unsigned c = 0; c < 4; c++)
            p->bad_exact += !same(v[c], q->in[var][c]);
      }
      /* from the centre to each sample: what the sample's walk gave */
      for (unsigned k = 0; k < NS; k++) {
         const float ox = rast_sample_pos_4x[k][0] - 0.5f, oy = rast_sample_pos_4x[k][1] - 0.5f;
         for (unsigned var = 0; var < NVAR; var++) {
            at(p, q, var, RAST_INTERP_AT_OFFSET, ox, oy, v);
            for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
               const size_t px =
                  (size_t)(q->y + (int)(i >> 1)) * W + (size_t)(q->x + (int)(i & 1));
               if (!(q->mask >> i & 1u) || !has_walked[k][px])
                  continue;
               for (unsigned c = 0; c < 4; c++) {
                  const float got = v[c][i], want = walked[k][px][var][c];
                  if (var == 0 || (var == 1 && !p->scanline)) {
                     p->bad_exact += memcmp(&got, &want, sizeof got) != 0;
                  } else if (var == 1) {
                     /* the scan-line walk rounds its steps: the centre and
                      * the sample each miss the exact plane by their own
                      * walk's error, so the correction is held to the
                      * centre's error and the one rounding it adds */
                     const int64_t x = (int64_t)(px % W), y = (int64_t)(px / W);
                     const int64_t sx = (int64_t)(rast_sample_pos_4x[k][0] * 4096.0f);
                     const int64_t sy = (int64_t)(rast_sample_pos_4x[k][1] * 4096.0f);
                     const long double e_centre =
                        fabsl((long double)q->in[1][c][i] * UNIT -
                              t_exact_plane(p->X, p->Y, p->ra[c], x * 4096 + 2048, y * 4096 + 2048));
                     const long double e_at =
                        fabsl((long double)got * UNIT -
                              t_exact_plane(p->X, p->Y, p->ra[c], x * 4096 + sx, y * 4096 + sy));
                     const double d = (double)(e_at - e_centre);
                     if (p->color_steep[c]) {
                        /* ∂/∂x or ∂/∂y beyond the register: it saturated
                         * (counted), and the correction with it */
                        p->steep++;
                        continue;
                     }
                     p->bad_color += d > 1.0 + 1e-6;
                     if (d > p->worst_color)
                        p->worst_color = d;
                     const double dw = fabs((double)got - (double)want) * (double)UNIT;
                     if (dw > p->worst_color_walk)
                        p->worst_color_walk = dw;
                  } else {
                     const double d = fabs((double)got - (double)want) /
                                      (1.0 + fabs((double)want));
                     p->bad_linear += d > LINEAR_TOLERANCE;
                     if (d > p->worst_linear)
                        p->worst_linear = d;
                  }
               }
            }
         }
      }
   }
   /* beyond the pixel: its edge, one grid step inside on the right */
   at(p, q, 0, RAST_INTERP_AT_OFFSET, 3.0f, -7.0f, v);
   at(p, q, 0, RAST_INTERP_AT_OFFSET, 0.5f - 1.0f / 4096.0f, -0.5f, w);
   for (unsigned c = 0; c < 4; c++)
      p->bad_clamp += !same(v[c], w[c]);
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
      for (unsigned c = 0; c < 4; c++)
         out->color[0][c][i] = q->in[1][c][i];
   return q->mask;
}

static void random_tri(struct t_slot_tri *tr)
{
   t_random_slot_tri(tr, W, H);
}

static uint8_t color[NS][W * H * 4];
static uint32_t zs[NS][W * H];

static void run(struct probe *p, struct t_slot_tri *tr, unsigned samples, unsigned interp,
                const char *texfmt, unsigned opts)
{
   char err[128];
   static struct rast_profile_buf prof;
   if (!rast_profile_parse("seed", &prof, err, sizeof err))
      exit(1);
   p->rc = rast_create(&prof.p);
   t_bind_rgba8_z24s8_samples(p->rc, color[0], zs[0], W, H, samples);
   t_plain_state(p->rc);
   struct rast_vertex_layout vl = t_layout_pos();
   t_layout_add(&vl, RAST_INTERP_PERSPECTIVE, 0xf);
   t_layout_add(&vl, RAST_INTERP_COLOR, 0xf);
   t_layout_add(&vl, RAST_INTERP_LINEAR, 0xf);
   rast_set_vertex_layout(p->rc, &vl);
   rast_set_interp(p->rc, interp);
   rast_set_texfmt(p->rc, numsys_by_name(texfmt));
   rast_set_options(p->rc, opts);
   struct rast_shader fs;
   memset(&fs, 0, sizeof fs);
   fs.ctx = p;
   fs.shade = shade;
   fs.num_outputs = 1;
   fs.per_sample = p->per_sample;
   rast_set_shader(p->rc, &fs);
   p->scanline = interp == RAST_INTERP_SCANLINE;
   for (int v = 0; v < 3; v++) {
      p->X[v] = (int64_t)llroundf(tr->v[v][0][0] * 4096.0f);
      p->Y[v] = (int64_t)llroundf(tr->v[v][0][1] * 4096.0f);
      for (int c = 0; c < 4; c++)
         p->ra[c][v] = (int64_t)llroundl((long double)tr->v[v][2][c] * UNIT);
   }
   const int64_t e1x = p->X[1] - p->X[0], e1y = p->Y[1] - p->Y[0];
   const int64_t e2x = p->X[2] - p->X[0], e2y = p->Y[2] - p->Y[0];
   const long double det = (long double)e1x * e2y - (long double)e1y * e2x;
   const long double reg_max = (long double)fx_max(prof.p.color);
   for (int c = 0; c < 4; c++) {
      const long double d1 = (long double)(p->ra[c][1] - p->ra[c][0]);
      const long double d2 = (long double)(p->ra[c][2] - p->ra[c][0]);
      const long double gx = (d1 * e2y - d2 * e1y) * 4096.0L / det;
      const long double gy = (d2 * e1x - d1 * e2x) * 4096.0L / det;
      p->color_steep[c] = det == 0 || fabsl(gx) >= reg_max || fabsl(gy) >= reg_max;
   }
   p->centre = samples == 1;
   t_tri(p->rc, tr->v[0], tr->v[1], tr->v[2]);
   rast_flush(p->rc);
   rast_destroy(p->rc);
}

int main(int argc, char **argv)
{
   unsigned scenes = 300;
   t_scene_args(argc, argv, "test_interp_at", &scenes, &rng);
   t_seed(rng);
   static const char *const texfmts[] = { "dfx24", "float", "fx8.24", "dfx20" };
   static const unsigned interps[] = { RAST_INTERP_SCANLINE, RAST_INTERP_BARYCENTRIC,
                                       RAST_INTERP_VECTOR };
   struct probe p;
   memset(&p, 0, sizeof p);
   for (unsigned n = 0; n < scenes; n++) {
      struct t_slot_tri tr;
      random_tri(&tr);
      const char *texfmt = texfmts[n % 4];
      const unsigned interp = interps[(n / 4) % 3];
      const unsigned opts = n % 2 ? RAST_OPT_SCALAR : 0;
      memset(has_walked, 0, sizeof has_walked);
      p.per_sample = true;
      run(&p, &tr, NS, interp, texfmt, opts);
      p.per_sample = false;
      run(&p, &tr, 1, interp, texfmt, opts);
      run(&p, &tr, NS, interp, texfmt, opts);
   }
   printf("interpolateAt: %u quads probed; from the centre to a sample, scan-line colour at "
          "most %.3f last bits further from the exact plane than the centre (%.1f from the "
          "sample's walk; %u pixel-samples of slopes beyond the register left out), "
          "noperspective %.2g relative from the sample's walk\n",
          p.quads, p.worst_color, p.worst_color_walk, p.steep, p.worst_linear);
   CHECK(p.quads > scenes, "only %u quads shaded: the triangles draw nothing", p.quads);
   CHECK(p.bad_exact == 0, "%u component-quads unlike the walk's bits at the same point",
         p.bad_exact);
   CHECK(p.bad_color == 0, "%u scan-line colour registers offset from the centre to a sample "
         "more than one last bit further from the exact plane than the centre's", p.bad_color);
   CHECK(p.bad_linear == 0, "%u noperspective values beyond binary32's rounding of the "
         "sample's walk", p.bad_linear);
   CHECK(p.bad_offset == 0, "%u component-quads where an offset to a sample's position gives "
         "other bits than the sample", p.bad_offset);
   CHECK(p.bad_clamp == 0, "%u component-quads where an offset beyond the pixel is not its "
         "edge", p.bad_clamp);
   return t_summary("interp_at");
}
