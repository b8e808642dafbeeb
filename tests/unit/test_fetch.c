/*
 * Framebuffer fetch (rast_shader.fetch_mask): a shader that adds 1/255 to
 * the red its pixel holds, over scenes of overlapping random triangles.
 * Stencil counts the same hits (INCR, depth ALWAYS), so after a scene
 *
 *  - single-sampled: every pixel's red is its stencil count, which holds
 *    only if each quad read what every earlier triangle wrote (in order,
 *    also with groups of two and of four quads and on two threads);
 *  - four samples: every sample's red is that sample's stencil count: the
 *    shader ran once a covered sample, reading that sample's plane;
 *  - the green channel, which the shader copies from the fetch, keeps the
 *    clear value everywhere, and nothing outside the triangles changes.
 *
 *   test_fetch [--scenes N] [--seed S]
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tutil.h"

#define W 72
#define H 140                    /* more than two strips of msaa.c's cache */
#define NS RAST_MSAA_SAMPLES
#define PLANE ((size_t)W * H)

static uint64_t rng = 0x243f6a8885a308d3ull;

static uint8_t color[NS][PLANE * 4];
static uint64_t total_hits;
static uint32_t zs[NS][PLANE];

/* group: quads a call of shade_n (0: one at a time) */
static struct rast_context *target(unsigned samples, unsigned group, unsigned threads)
{
   char err[128];
   static struct rast_profile_buf prof;
   if (!rast_profile_parse("seed", &prof, err, sizeof err))
      exit(1);
   struct rast_context *rc = rast_create(&prof.p);
   t_bind_rgba8_z24s8_samples(rc, color[0], zs[0], W, H, samples);
   t_plain_state(rc);
   struct rast_shader fs;
   memset(&fs, 0, sizeof fs);
   fs.shade = t_shade_fetch_count;
   fs.shade_n = group ? t_shade_fetch_count_n : NULL;
   fs.group = group;
   fs.num_outputs = 1;
   fs.fetch_mask = 1;
   rast_set_shader(rc, &fs);
   t_depth_count_hits(rc, RAST_FUNC_ALWAYS);
   rast_set_threads(rc, threads);
   for (unsigned k = 0; k < NS; k++) {
      for (size_t i = 0; i < PLANE; i++) {
         color[k][4 * i + 0] = 0;
         color[k][4 * i + 1] = (uint8_t)(i * 7);
         color[k][4 * i + 2] = 0;
         color[k][4 * i + 3] = 0;
         zs[k][i] = 0x00ffffffu;      /* depth 1, stencil 0 */
      }
   }
   return rc;
}

static float coord(float lo, float hi) { return (float)(lo + (hi - lo) * t_rand()); }

static void scene(unsigned ntri, unsigned samples, unsigned group, unsigned threads)
{
   static float v[40][3][1][4];
   struct rast_context *rc = target(samples, group, threads);
   for (unsigned t = 0; t < ntri; t++) {
      const float cx = coord(-4, W + 4), cy = coord(-4, H + 4);
      const float r = t % 3 == 0 ? 60.0f : 12.0f;
      for (int i = 0; i < 3; i++) {
         v[t][i][0][0] = (float)(int)((cx + coord(-r, r)) * 4096.0f) / 4096.0f;
         v[t][i][0][1] = (float)(int)((cy + coord(-r, r)) * 4096.0f) / 4096.0f;
         v[t][i][0][2] = 0.5f;
         v[t][i][0][3] = 1.0f;
      }
      t_tri(rc, v[t][0], v[t][1], v[t][2]);
   }
   rast_flush(rc);

   unsigned bad_red = 0, bad_green = 0, bad_untouched = 0, hits = 0;
   for (unsigned k = 0; k < samples; k++) {
      for (size_t i = 0; i < PLANE; i++) {
         const unsigned n = zs[k][i] >> 24;
         hits += n;
         bad_red += color[k][4 * i + 0] != n;
         bad_green += color[k][4 * i + 1] != (uint8_t)(i * 7);
         bad_untouched += n == 0 && (color[k][4 * i + 2] || color[k][4 * i + 3]);
      }
   }
   total_hits += hits;
   CHECK(bad_red == 0, "%u sample(s) whose fetched count is not their hit count (%u samples, "
         "groups of %u, %u threads)", bad_red, samples, group, threads);
   CHECK(bad_green == 0, "%u sample(s) whose fetched green is not what they held", bad_green);
   CHECK(bad_untouched == 0, "%u sample(s) written that no triangle covers", bad_untouched);
   rast_destroy(rc);
}

int main(int argc, char **argv)
{
   unsigned scenes = 60;
   t_scene_args(argc, argv, "test_fetch", &scenes, &rng);
   t_seed(rng);
   for (unsigned n = 0; n < scenes; n++) {
      const unsigned ntri = 1 + n % 40;
      static const unsigned groups[3] = { 0, 2, 4 };
      scene(ntri, 1, groups[n % 3], 1);
      scene(ntri, NS, groups[n % 3], 1);
      if (n % 4 == 0) {
         scene(ntri, 1, groups[1 + n / 4 % 2], 2);
         scene(ntri, NS, 0, 2);
      }
   }
   CHECK(total_hits > 1000, "the scenes covered almost nothing (%llu hits)",
         (unsigned long long)total_hits);
   printf("fetch: %llu sample hits fetched and counted\n", (unsigned long long)total_hits);
   return t_summary("fetch");
}
