/*
 * Per-sample shading (rast_shader.per_sample, msaa.c), on random triangles
 * with a COLOR, a PERSPECTIVE and a LINEAR varying:
 *
 *  - the shader runs once for each covered sample, with the sample in the
 *    quad (gl_SampleID): sample k's calls are exactly the pixels the exact
 *    reference (tutil.c) finds covered at k's position, and no others;
 *  - its inputs are the interpolators' at the sample: every component, bit
 *    for bit, is what the single-sampled model gives the pixel centre of
 *    the triangle moved by (1/2 - sx, 1/2 - sy), on 1 and 2 threads;
 *  - the colour register of seed 002's vector method (FIXPIPE_INTERP=vector)
 *    lies within that method's bound, (|ΔA1| + |ΔA2|)·2^-24 + 1/2 of a last
 *    bit, of the exact plane through the vertices' registers evaluated at
 *    the sample's position in rational arithmetic; the centre's value
 *    misses it by the gradient times the sample's offset;
 *  - gl_SampleMask (writes_sample_mask) alone shades once a sample, and a
 *    sample is written where the output has its bit;
 *  - GL_MULTISAMPLE disabled (rs.single_sample): the same shader runs once
 *    a pixel, sample 0, with the centre's inputs, and every sample of a
 *    pixel whose centre is covered is written, whatever the mask.
 *
 *   test_sample_shading [--scenes N] [--seed S]
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tutil.h"

#define W 64
#define H 80
#define NS RAST_MSAA_SAMPLES
#define PLANE ((size_t)W * H)
#define NCOMP 8                  /* colour r, g, b, a; perspective s, t; linear u, v */
#define SLOTS 4                  /* position, perspective, colour, linear */

static uint64_t rng = 0x2545f4914f6cdd1dull;

/* What the shader saw at each sample of each pixel (a single-sampled
 * target: plane 0). */
struct record {
   bool white_masked;            /* write white and gl_SampleMask = mask_of(x, y) */
   uint8_t calls[NS][PLANE];
   float v[NS][PLANE][NCOMP];
};

static void keep(struct record *r, const struct rast_quad *q, unsigned i)
{
   const size_t p = (size_t)(q->y + (int)(i >> 1)) * W + (size_t)(q->x + (int)(i & 1));
   r->calls[q->sample][p]++;
   float *v = r->v[q->sample][p];
   for (unsigned c = 0; c < 4; c++)
      v[c] = q->in[1][c][i];
   for (unsigned c = 0; c < 2; c++) {
      v[4 + c] = q->in[0][c][i];
      v[6 + c] = q->in[2][c][i];
   }
}

/* A gl_SampleMask that differs from pixel to pixel, every pattern. */
static uint32_t mask_of(int x, int y)
{
   return (uint32_t)(x * 7 + y * 3) & 15u;
}

static unsigned shade(void *ctx, const struct rast_quad *q, struct rast_shaded_quad *out)
{
   const struct record *r = ctx;
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      if (q->mask >> i & 1u)
         keep(ctx, q, i);
      for (unsigned c = 0; c < 4; c++)
         out->color[0][c][i] = r->white_masked ? 1.0f : q->in[1][c][i];
      out->sample_mask[i] = mask_of(q->x + (int)(i & 1), q->y + (int)(i >> 1));
   }
   return q->mask;
}

struct target {
   struct rast_context *rc;
   uint8_t color[NS][PLANE * 4];
   uint32_t zs[NS][PLANE];
};

static void target_init(struct target *t, struct record *r, unsigned samples, unsigned interp,
                        unsigned threads, bool white_masked)
{
   char err[128];
   static struct rast_profile_buf prof;
   if (!rast_profile_parse("seed", &prof, err, sizeof err))
      exit(1);
   t->rc = rast_create(&prof.p);
   t_bind_rgba8_z24s8_samples(t->rc, t->color[0], t->zs[0], W, H, samples);
   t_plain_state(t->rc);
   struct rast_vertex_layout vl = t_layout_pos();
   t_layout_add(&vl, RAST_INTERP_PERSPECTIVE, 0x3);
   t_layout_add(&vl, RAST_INTERP_COLOR, 0xf);
   t_layout_add(&vl, RAST_INTERP_LINEAR, 0x3);
   rast_set_vertex_layout(t->rc, &vl);
   rast_set_interp(t->rc, interp);
   rast_set_threads(t->rc, threads);
   struct rast_shader fs;
   memset(&fs, 0, sizeof fs);
   fs.ctx = r;
   fs.shade = shade;
   fs.num_outputs = 1;
   fs.per_sample = !white_masked;     /* the mask alone asks for it */
   fs.writes_sample_mask = white_masked;
   rast_set_shader(t->rc, &fs);
   memset(r, 0, sizeof *r);
   memset(t->color, 0, sizeof t->color);
   r->white_masked = white_masked;
}

static void random_tri(struct t_slot_tri *tr)
{
   t_random_slot_tri(tr, W, H);
}

static void draw(struct target *t, const struct t_slot_tri *tr, float dx, float dy)
{
   static float v[3][SLOTS][4];
   memcpy(v, tr->v, sizeof v);
   for (int i = 0; i < 3; i++) {
      v[i][0][0] += dx;               /* exact: both on the 1/4096 grid, |v| < 2^11 */
      v[i][0][1] += dy;
   }
   t_tri(t->rc, v[0], v[1], v[2]);
   rast_flush(t->rc);
}

static float sdx(unsigned k) { return 0.5f - rast_sample_pos_4x[k][0]; }
static float sdy(unsigned k) { return 0.5f - rast_sample_pos_4x[k][1]; }

struct refmark { uint8_t *in; };
static void mark(void *ctx, int x, int y)
{
   ((struct refmark *)ctx)->in[(size_t)y * W + (size_t)x] = 1;
}

static void one_tri(unsigned threads)
{
   static struct target ms, ss;
   static struct record rm, rs;
   struct t_slot_tri tr;
   random_tri(&tr);

   target_init(&ms, &rm, NS, RAST_INTERP_SCANLINE, threads, false);
   draw(&ms, &tr, 0, 0);
   unsigned bad_calls = 0, bad_values = 0;
   for (unsigned k = 0; k < NS; k++) {
      uint8_t in[PLANE];
      memset(in, 0, sizeof in);
      int64_t X[3], Y[3];
      for (int i = 0; i < 3; i++) {
         X[i] = (int64_t)llroundf((tr.v[i][0][0] + sdx(k)) * 4096.0f);
         Y[i] = (int64_t)llroundf((tr.v[i][0][1] + sdy(k)) * 4096.0f);
      }
      struct refmark r = { in };
      t_ref_triangle(X, Y, 4096, 2048, false, (struct rast_scissor){ 0, 0, W, H }, mark, &r);

      target_init(&ss, &rs, 1, RAST_INTERP_SCANLINE, 1, false);
      draw(&ss, &tr, sdx(k), sdy(k));
      for (size_t p = 0; p < PLANE; p++) {
         bad_calls += rm.calls[k][p] != in[p];
         if (in[p] && rs.calls[0][p] == 1)
            bad_values += memcmp(rm.v[k][p], rs.v[0][p], sizeof rm.v[k][p]) != 0;
      }
      rast_destroy(ss.rc);
   }
   CHECK(bad_calls == 0, "%u sample(s) shaded otherwise than once where covered (%u threads)",
         bad_calls, threads);
   CHECK(bad_values == 0, "%u sample(s) whose inputs differ from the moved centre's (%u threads)",
         bad_values, threads);
   rast_destroy(ms.rc);
}

/* Seed 002's colour registers against the exact plane at the samples; the
 * largest error in last bits over the bound, and the same measure for the
 * pixel centre's plane value (which must miss). */
static void one_tri_exact(double *worst, double *centre_worst)
{
   static struct target ms;
   static struct record rm;
   struct t_slot_tri tr;
   random_tri(&tr);
   target_init(&ms, &rm, NS, RAST_INTERP_VECTOR, 1, false);
   draw(&ms, &tr, 0, 0);
   /* the register holds colour·255 in 12 fraction bits; the shader reads
    * it scaled back to [0, 1] */
   const long double unit = 255.0L * 4096.0L;
   int64_t X[3], Y[3];
   for (int i = 0; i < 3; i++) {
      X[i] = (int64_t)llroundf(tr.v[i][0][0] * 4096.0f);
      Y[i] = (int64_t)llroundf(tr.v[i][0][1] * 4096.0f);
   }
   unsigned bad = 0;
   for (unsigned c = 0; c < 4; c++) {
      int64_t ra[3];
      for (int i = 0; i < 3; i++)
         ra[i] = (int64_t)llroundl((long double)tr.v[i][2][c] * unit);
      const double bound = (double)(llabs(ra[1] - ra[0]) + llabs(ra[2] - ra[0])) / 16777216.0 +
                           0.5 + 0.5;   /* and half a bit of the vertex's own rounding */
      for (unsigned k = 0; k < NS; k++)
         for (size_t p = 0; p < PLANE; p++) {
            if (!rm.calls[k][p])
               continue;
            const int64_t x = (int64_t)(p % W), y = (int64_t)(p / W);
            const int64_t sx = (int64_t)(rast_sample_pos_4x[k][0] * 4096.0f);
            const int64_t sy = (int64_t)(rast_sample_pos_4x[k][1] * 4096.0f);
            const long double got = (long double)rm.v[k][p][c] * unit;
            const double err = (double)fabsl(got - t_exact_plane(X, Y, ra, x * 4096 + sx,
                                                              y * 4096 + sy)) / bound;
            const double cerr = (double)fabsl(got - t_exact_plane(X, Y, ra, x * 4096 + 2048,
                                                               y * 4096 + 2048)) / bound;
            bad += err > 1.0;
            if (err > *worst)
               *worst = err;
            if (cerr > *centre_worst)
               *centre_worst = cerr;
         }
   }
   CHECK(bad == 0, "%u colour register(s) outside seed 002's bound of the exact plane at the "
         "sample", bad);
   rast_destroy(ms.rc);
}

/* gl_SampleMask: each covered sample shaded once, and written where the
 * output has its bit, whatever the shader's other state asks. */
static void one_tri_masked(void)
{
   static struct target ms;
   static struct record rm;
   struct t_slot_tri tr;
   random_tri(&tr);
   target_init(&ms, &rm, NS, RAST_INTERP_SCANLINE, 1, true);
   draw(&ms, &tr, 0, 0);
   unsigned bad_calls = 0, bad_written = 0;
   for (unsigned k = 0; k < NS; k++) {
      uint8_t in[PLANE];
      memset(in, 0, sizeof in);
      int64_t X[3], Y[3];
      for (int i = 0; i < 3; i++) {
         X[i] = (int64_t)llroundf((tr.v[i][0][0] + sdx(k)) * 4096.0f);
         Y[i] = (int64_t)llroundf((tr.v[i][0][1] + sdy(k)) * 4096.0f);
      }
      struct refmark r = { in };
      t_ref_triangle(X, Y, 4096, 2048, false, (struct rast_scissor){ 0, 0, W, H }, mark, &r);
      for (size_t p = 0; p < PLANE; p++) {
         const bool want = in[p] && (mask_of((int)(p % W), (int)(p / W)) >> k & 1u);
         bad_calls += rm.calls[k][p] != in[p];
         bad_written += (ms.color[k][p * 4] == 255) != want;
      }
   }
   CHECK(bad_calls == 0, "gl_SampleMask: %u sample(s) shaded otherwise than once where covered",
         bad_calls);
   CHECK(bad_written == 0, "gl_SampleMask: %u sample(s) written otherwise than the mask says",
         bad_written);
   rast_destroy(ms.rc);
}

/* GL_MULTISAMPLE disabled: per_sample and gl_SampleMask do not apply;
 * each sample plane is the single-sampled model's image. */
static void one_tri_single_sample(void)
{
   static struct target ms, ss;
   static struct record rm, rs;
   struct t_slot_tri tr;
   random_tri(&tr);
   target_init(&ms, &rm, NS, RAST_INTERP_SCANLINE, 1, true);
   struct rast_raster_state st;
   memset(&st, 0, sizeof st);
   st.half_pixel_center = true;
   st.line_width = 1.0f;
   st.point_size = 1.0f;
   st.single_sample = true;
   rast_set_raster_state(ms.rc, &st);
   struct rast_shader fs;
   memset(&fs, 0, sizeof fs);
   fs.ctx = &rm;
   fs.shade = shade;
   fs.num_outputs = 1;
   fs.per_sample = true;
   fs.writes_sample_mask = true;
   rast_set_shader(ms.rc, &fs);
   rm.white_masked = false;
   draw(&ms, &tr, 0, 0);
   target_init(&ss, &rs, 1, RAST_INTERP_SCANLINE, 1, false);
   draw(&ss, &tr, 0, 0);
   unsigned bad_calls = 0, bad_values = 0, bad_planes = 0;
   for (size_t p = 0; p < PLANE; p++) {
      bad_calls += rm.calls[0][p] != rs.calls[0][p];
      for (unsigned k = 1; k < NS; k++)
         bad_calls += rm.calls[k][p] != 0;
      if (rs.calls[0][p])
         bad_values += memcmp(rm.v[0][p], rs.v[0][p], sizeof rm.v[0][p]) != 0;
      for (unsigned k = 0; k < NS; k++)
         bad_planes += memcmp(&ms.color[k][p * 4], &ss.color[0][p * 4], 4) != 0;
   }
   CHECK(bad_calls == 0, "multisampling off: %u pixel(s) shaded otherwise than once at the "
         "centre, as sample 0", bad_calls);
   CHECK(bad_values == 0, "multisampling off: %u pixel(s) with other inputs than the centre's",
         bad_values);
   CHECK(bad_planes == 0, "multisampling off: %u sample(s) unlike the single-sampled image",
         bad_planes);
   rast_destroy(ms.rc);
   rast_destroy(ss.rc);
}

int main(int argc, char **argv)
{
   unsigned scenes = 200;
   t_scene_args(argc, argv, "test_sample_shading", &scenes, &rng);
   t_seed(rng);
   double worst = 0, centre_worst = 0;
   for (unsigned n = 0; n < scenes; n++) {
      one_tri(1);
      if (n % 8 == 0)
         one_tri(2);
      one_tri_exact(&worst, &centre_worst);
      one_tri_masked();
      one_tri_single_sample();
   }
   printf("sample shading: largest colour error %.3f of the bound at the samples, %.1f at the "
          "pixel centres\n", worst, centre_worst);
   CHECK(centre_worst > 1.0, "the pixel centre's value is within the bound too: the test "
         "cannot tell the sample from the centre");
   return t_summary("sample_shading");
}
