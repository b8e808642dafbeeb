/*
 * Four samples a pixel (msaa.c), on random scenes of triangles:
 *
 *  - coverage: sample k's stencil plane counts exactly the hits the exact
 *    reference (tutil.c) finds at the sample's position;
 *  - depth and stencil: after a scene of overlapping triangles with depth,
 *    each sample's planes are byte for byte those of the single-sampled
 *    model drawing the scene moved by (1/2 - sx, 1/2 - sy): a sample is the
 *    walk at its point, so the registers are that walk's;
 *  - the shader once a pixel: each pixel with a covered sample is shaded
 *    once, no other pixel is, and every covered sample holds its colour;
 *  - the sample mask and alpha to coverage touch exactly their samples;
 *  - two threads give the planes of one.
 *
 *   test_msaa [--scenes N] [--seed S]
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tutil.h"
#include "fixed/fx.h"

#define W 64
#define H 150                    /* three strips of msaa.c's cache */
#define NS RAST_MSAA_SAMPLES
#define PLANE ((size_t)W * H)

static uint64_t rng = 0x9e3779b97f4a7c15ull;

/* The shader: a colour that names the pixel and the primitive, alpha as
 * set; every call counted per pixel. */
struct shader {
   uint8_t calls[PLANE];
   uint32_t prim;
   float alpha;
   bool discard_odd;             /* discard pixels with odd x */
};

static unsigned shade(void *ctx, const struct rast_quad *q, struct rast_shaded_quad *out)
{
   struct shader *s = ctx;
   unsigned kept = q->mask;
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      const int x = q->x + (int)(i & 1), y = q->y + (int)(i >> 1);
      if (!(q->mask >> i & 1u))
         continue;
      s->calls[(size_t)y * W + (size_t)x]++;
      out->color[0][0][i] = (float)x / 255.0f;
      out->color[0][1][i] = (float)y / 255.0f;
      out->color[0][2][i] = (float)(s->prim & 0xff) / 255.0f;
      out->color[0][3][i] = s->alpha;
      if (s->discard_odd && (x & 1))
         kept &= ~(1u << i);
   }
   return kept;
}

struct target {
   struct rast_context *rc;
   uint8_t color[NS][PLANE * 4];
   uint32_t zs[NS][PLANE];
   unsigned samples;
};

static void target_init(struct target *t, struct shader *s, unsigned samples, bool discard)
{
   memset(t, 0, sizeof *t);
   char err[128];
   static struct rast_profile_buf prof;
   if (!rast_profile_parse("seed", &prof, err, sizeof err))
      exit(1);
   t->rc = rast_create(&prof.p);
   t->samples = samples;
   t_bind_rgba8_z24s8_samples(t->rc, t->color[0], t->zs[0], W, H, samples);
   t_plain_state(t->rc);
   struct rast_shader fs;
   memset(&fs, 0, sizeof fs);
   fs.ctx = s;
   fs.shade = shade;
   fs.num_outputs = 1;
   fs.may_discard = discard;
   rast_set_shader(t->rc, &fs);
}

static void clear(struct target *t)
{
   memset(t->color, 0, sizeof t->color);
   for (unsigned k = 0; k < NS; k++)
      for (size_t i = 0; i < PLANE; i++)
         t->zs[k][i] = 0x00ffffffu;      /* depth 1, stencil 0 */
}

/* A coordinate on the XY grid (1/4096), some off the target. */
static float coord(float lo, float hi)
{
   return (float)(lo + (hi - lo) * t_rand());
}
static float snap(float v) { return roundf(v * 4096.0f) / 4096.0f; }

struct tri { float v[3][4]; };

static void random_tri(struct tri *tr)
{
   const double pick = t_rand();
   const float cx = coord(-4, W + 4), cy = coord(-4, H + 4);
   const float r = pick < 0.5 ? 3.0f : pick < 0.9 ? 40.0f : 150.0f;
   for (int i = 0; i < 3; i++) {
      tr->v[i][0] = snap(cx + coord(-r, r));
      tr->v[i][1] = snap(cy + coord(-r, r));
      tr->v[i][2] = (float)t_rand();
      tr->v[i][3] = 1.0f;
   }
}

/* Triangle i of the scene; its vertices stay where they are until the
 * flush, as the queue of the threads needs them. */
static void draw(struct target *t, unsigned i_tri, const struct tri *tr, float dx, float dy)
{
   static float verts[32][3][1][4];
   float (*v)[1][4] = verts[i_tri];
   for (int i = 0; i < 3; i++) {
      memcpy(v[i][0], tr->v[i], sizeof v[i][0]);
      v[i][0][0] += dx;               /* exact: both on the 1/4096 grid, |v| < 2^11 */
      v[i][0][1] += dy;
   }
   t_tri(t->rc, v[0], v[1], v[2]);
}

/* Sample k's offset from the centre. */
static float sdx(unsigned k) { return 0.5f - rast_sample_pos_4x[k][0]; }
static float sdy(unsigned k) { return 0.5f - rast_sample_pos_4x[k][1]; }

static void set_depth(struct target *t, bool on)
{
   t_depth_count_hits(t->rc, on ? RAST_FUNC_LESS : RAST_FUNC_ALWAYS);
}

/* Depth and stencil of every sample against the single-sampled model on the
 * moved scene. */
static void scene_zs(struct shader *s, unsigned ntri, unsigned threads)
{
   static struct target ms, ss;
   struct tri tris[24];
   for (unsigned i = 0; i < ntri; i++)
      random_tri(&tris[i]);
   target_init(&ms, s, NS, false);
   rast_set_threads(ms.rc, threads);
   set_depth(&ms, true);
   clear(&ms);
   for (unsigned i = 0; i < ntri; i++)
      draw(&ms, i, &tris[i], 0, 0);
   rast_flush(ms.rc);
   for (unsigned k = 0; k < NS; k++) {
      target_init(&ss, s, 1, false);
      set_depth(&ss, true);
      clear(&ss);
      for (unsigned i = 0; i < ntri; i++)
         draw(&ss, i, &tris[i], sdx(k), sdy(k));
      rast_flush(ss.rc);
      CHECK(memcmp(ms.zs[k], ss.zs[0], sizeof ss.zs[0]) == 0,
            "sample %u: depth/stencil differ from the moved single-sampled scene (%u threads)",
            k, threads);
      rast_destroy(ss.rc);
   }
   rast_destroy(ms.rc);
}

struct refmark { uint8_t *in; };
static void mark(void *ctx, int x, int y)
{
   ((struct refmark *)ctx)->in[(size_t)y * W + (size_t)x] = 1;
}

/* One triangle: coverage per sample against the reference, the shader once
 * a pixel, the colour of each covered sample; with a sample mask, alpha to
 * coverage and discard as given. */
static void one_tri(struct shader *s, unsigned mask, bool a2c, bool discard)
{
   static struct target t;
   struct tri tr;
   random_tri(&tr);
   target_init(&t, s, NS, discard);
   set_depth(&t, false);
   rast_set_sample_mask(t.rc, mask);
   if (a2c) {
      struct rast_blend_state b;
      memset(&b, 0, sizeof b);
      b.rt[0].colormask = 0xf;
      b.alpha_to_coverage = true;
      rast_set_blend(t.rc, &b);
   }
   s->alpha = a2c ? (float)t_rand() : 1.0f;
   s->prim++;
   s->discard_odd = discard;
   memset(s->calls, 0, sizeof s->calls);
   clear(&t);
   draw(&t, 0, &tr, 0, 0);
   rast_flush(t.rc);

   const int64_t S = 4096;
   uint8_t in[NS][PLANE], any[PLANE];
   memset(in, 0, sizeof in);
   memset(any, 0, sizeof any);
   for (unsigned k = 0; k < NS; k++) {
      int64_t X[3], Y[3];
      for (int i = 0; i < 3; i++) {
         X[i] = (int64_t)llroundf((tr.v[i][0] + sdx(k)) * (float)S);
         Y[i] = (int64_t)llroundf((tr.v[i][1] + sdy(k)) * (float)S);
      }
      struct refmark r = { in[k] };
      t_ref_triangle(X, Y, S, S / 2, false, (struct rast_scissor){ 0, 0, W, H }, mark, &r);
      for (size_t p = 0; p < PLANE; p++)
         any[p] |= in[k][p] & (mask >> k & 1u);
   }
   /* the centre's walk shades the pixels whose centre is covered, whatever
    * the sample mask (unless it is empty: then nothing runs) */
   uint8_t centre[PLANE];
   memset(centre, 0, sizeof centre);
   {
      int64_t X[3], Y[3];
      for (int i = 0; i < 3; i++) {
         X[i] = (int64_t)llroundf(tr.v[i][0] * (float)S);
         Y[i] = (int64_t)llroundf(tr.v[i][1] * (float)S);
      }
      struct refmark r = { centre };
      t_ref_triangle(X, Y, S, S / 2, false, (struct rast_scissor){ 0, 0, W, H }, mark, &r);
   }
   unsigned bad_cov = 0, bad_calls = 0, bad_color = 0;
   for (size_t p = 0; p < PLANE; p++) {
      const int x = (int)(p % W), y = (int)(p / W);
      bad_calls += s->calls[p] != (any[p] | (centre[p] & (mask != 0)));
      for (unsigned k = 0; k < NS; k++) {
         const bool drawn = in[k][p] && (mask >> k & 1u);
         const bool kept = drawn && !(discard && (x & 1)) &&
                           (!a2c || s->alpha > (float)k * 0.25f);
         /* the stencil counts the sample's hits: covered and in the mask,
          * kept by the shader (discard, alpha to coverage) */
         bad_cov += (t.zs[k][p] >> 24) != (uint32_t)kept;
         const uint8_t *c = &t.color[k][p * 4];
         const uint8_t want[4] = { (uint8_t)(kept ? x : 0), (uint8_t)(kept ? y : 0),
                                   (uint8_t)(kept ? s->prim & 0xff : 0),
                                   (uint8_t)(kept ? (uint8_t)lroundf(s->alpha * 255.0f) : 0) };
         bad_color += memcmp(c, want, 4) != 0;
      }
   }
   CHECK(bad_cov == 0, "%u sample(s) covered otherwise than the reference says (mask %x%s%s)",
         bad_cov, mask, a2c ? ", alpha to coverage" : "", discard ? ", discard" : "");
   CHECK(bad_calls == 0, "%u pixel(s) not shaded exactly once where the centre or a sample "
         "is covered",
         bad_calls);
   CHECK(bad_color == 0, "%u sample(s) with another colour than their pixel's", bad_color);
   rast_destroy(t.rc);
}

int main(int argc, char **argv)
{
   unsigned scenes = 300;
   t_scene_args(argc, argv, "test_msaa", &scenes, &rng);
   t_seed(rng);
   static struct shader s;
   for (unsigned n = 0; n < scenes; n++) {
      scene_zs(&s, 1 + n % 24, 1);
      if (n % 10 == 0)
         scene_zs(&s, 24, 2);
      one_tri(&s, 0xf, false, false);
      one_tri(&s, (unsigned)(t_rand() * 16), false, false);
      one_tri(&s, 0xf, true, false);
      one_tri(&s, 0xf, false, true);
   }
   return t_summary("msaa");
}
