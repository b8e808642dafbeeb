/*
 * What set-up picks per primitive from its provoking vertex, over scenes
 * of random triangles, lines and points:
 *
 *  - the layer (gl_Layer: rast_vertex_layout.has_layer): drawn into a
 *    target of three layers (colour and depth/stencil), every layer must be
 *    byte for byte the same primitives drawn into a single-layer target of
 *    that layer alone; a layer beyond the last draws into the last;
 *  - the viewport index (gl_ViewportIndex: has_viewport_index): with four
 *    scissors and viewports (and the last of RAST_MAX_VIEWPORTS, which an
 *    index beyond takes), the target must be byte for byte the same
 *    primitives drawn one by one with rast_set_scissor and
 *    rast_set_viewport of their index before each, points clipped to their
 *    viewport (point_tri_clip).
 *
 * The shader adds 1/255 to the red it fetches and the stencil counts the
 * hits, so a quad that read or wrote another layer's pixels shows.
 * Single-sampled and with four samples, one quad at a time and in groups,
 * on one thread and on two.
 *
 *   test_layers [--scenes N] [--seed S]
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tutil.h"

#define W 40
#define H 72
#define NS RAST_MSAA_SAMPLES
#define PLANE ((size_t)W * H)
#define LAYERS 3
#define MAXPRIM 48
#define VIEWPORTS 4

static uint64_t rng = 0x6c61796572730a01ull;

/* a layer's samples one after the other, the layers one after the other */
static uint8_t color[LAYERS][NS][PLANE * 4], ref_color[LAYERS][NS][PLANE * 4];
static uint32_t zs[LAYERS][NS][PLANE], ref_zs[LAYERS][NS][PLANE];

/* A primitive: kind 0 triangle, 1 line, 2 point; two slots a vertex, the
 * position and the layer (an integer in x). */
struct prim {
   unsigned kind, layer;          /* layer: or the viewport index */
   float v[3][2][4];
};

/* The viewports' scissors and pixels: index 15 for those beyond. */
static struct rast_scissor scissor_of(unsigned i)
{
   if (i >= VIEWPORTS)
      return (struct rast_scissor){ 3, 5, W - 7, H / 2 };
   return (struct rast_scissor){ (int)i * 7, (int)i * 11, W - (int)i * 3, H - (int)i * 13 };
}

static struct rast_scissor viewport_of(unsigned i)
{
   if (i >= VIEWPORTS)
      return (struct rast_scissor){ 0, 0, W, H };
   return (struct rast_scissor){ (int)i * 5, 2, W - (int)i * 4, H - (int)i * 9 };
}
static struct prim prims[MAXPRIM];

static void clear(uint8_t (*c)[PLANE * 4], uint32_t (*z)[PLANE])
{
   for (unsigned k = 0; k < NS; k++)
      for (size_t i = 0; i < PLANE; i++) {
         c[k][4 * i + 0] = 0;
         c[k][4 * i + 1] = (uint8_t)(i * 5 + k);
         c[k][4 * i + 2] = 0;
         c[k][4 * i + 3] = 0;
         z[k][i] = 0x00ffffffu;      /* depth 1, stencil 0 */
      }
}

enum mode { LAYERED, FLAT, VIEWPORT_ARRAY, VIEWPORT_ONE };

static struct rast_context *context(unsigned samples, unsigned group, unsigned threads,
                                    uint8_t *c, uint32_t *z, enum mode mode)
{
   const bool layered = mode == LAYERED;
   char err[128];
   static struct rast_profile_buf prof;
   if (!rast_profile_parse("seed", &prof, err, sizeof err))
      exit(1);
   struct rast_context *rc = rast_create(&prof.p);
   struct rast_framebuffer fb;
   memset(&fb, 0, sizeof(fb));
   fb.width = W;
   fb.height = H;
   fb.samples = samples;
   fb.nr_cbufs = 1;
   fb.cbuf[0] = (struct rast_color_target){ .base = c, .stride = W * 4, .cpp = 4,
                                            .layout = RAST_CL_RGBA8, .load = t_load_rgba8,
                                            .store = t_store_rgba8, .clamp = true,
                                            .sample_stride = PLANE * 4,
                                            .layers = layered ? LAYERS : 0,
                                            .layer_stride = sizeof(color[0]) };
   fb.zs = (struct rast_zs_target){ .base = (uint8_t *)z, .stride = W * 4,
                                    .layout = RAST_ZS_Z24_S8, .sample_stride = PLANE * 4,
                                    .layers = layered ? LAYERS : 0,
                                    .layer_stride = sizeof(zs[0]) };
   rast_set_framebuffer(rc, &fb);
   t_plain_state(rc);
   struct rast_vertex_layout vl = t_layout_pos();
   vl.vertex_size = 2;
   vl.has_layer = layered;
   vl.layer_slot = 1;
   vl.has_viewport_index = mode == VIEWPORT_ARRAY;
   vl.viewport_slot = 1;
   if (mode == VIEWPORT_ARRAY || mode == VIEWPORT_ONE) {
      struct rast_raster_state rs;
      memset(&rs, 0, sizeof rs);
      rs.half_pixel_center = true;
      rs.line_width = 1.0f;
      rs.point_size = 3.0f;
      rs.point_tri_clip = true;
      rs.scissor = true;
      rast_set_raster_state(rc, &rs);
   }
   if (mode == VIEWPORT_ARRAY) {
      struct rast_scissor sc[RAST_MAX_VIEWPORTS], vp[RAST_MAX_VIEWPORTS];
      for (unsigned i = 0; i < RAST_MAX_VIEWPORTS; i++) {
         sc[i] = scissor_of(i);
         vp[i] = viewport_of(i);
      }
      rast_set_scissors(rc, 0, RAST_MAX_VIEWPORTS, sc);
      rast_set_viewports(rc, 0, RAST_MAX_VIEWPORTS, vp);
   }
   rast_set_vertex_layout(rc, &vl);
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
   return rc;
}

static void draw(struct rast_context *rc, const struct prim *p)
{
   switch (p->kind) {
   case 0: rast_triangle(rc, T_V(p->v[0]), T_V(p->v[1]), T_V(p->v[2])); break;
   case 1: rast_line(rc, T_V(p->v[0]), T_V(p->v[1])); break;
   default: rast_point(rc, T_V(p->v[0])); break;
   }
}

static float coord(float lo, float hi) { return (float)(lo + (hi - lo) * t_rand()); }

static uint64_t hits, beyond;

static void make_prims(unsigned n, unsigned count)
{
   for (unsigned t = 0; t < n; t++) {
      struct prim *p = &prims[t];
      p->kind = t % 5 == 3 ? 1 : t % 7 == 5 ? 2 : 0;
      /* now and then past the last layer, which draws into the last */
      p->layer = t % 11 == 4 ? count + (unsigned)(t_rand() * 100) : (unsigned)(t_rand() * count);
      const float cx = coord(-4, W + 4), cy = coord(-4, H + 4);
      const float r = t % 3 == 0 ? 40.0f : 10.0f;
      for (int i = 0; i < 3; i++) {
         p->v[i][0][0] = (float)(int)((cx + coord(-r, r)) * 4096.0f) / 4096.0f;
         p->v[i][0][1] = (float)(int)((cy + coord(-r, r)) * 4096.0f) / 4096.0f;
         p->v[i][0][2] = 0.5f;
         p->v[i][0][3] = 1.0f;
         /* the provoking vertex (the last) holds the layer; the others a
          * wrong one, which must not be taken */
         const uint32_t l = i == 2 || p->kind == 2 ? p->layer : p->layer + 1;
         memcpy(&p->v[i][1][0], &l, sizeof(l));
      }
      /* a line's provoking vertex is its second */
      if (p->kind == 1)
         memcpy(&p->v[1][1][0], &p->layer, sizeof(p->layer));
   }
   for (unsigned t = 0; t < n; t++)
      beyond += prims[t].layer >= count;
}

static void scene(unsigned n, unsigned samples, unsigned group, unsigned threads)
{
   make_prims(n, LAYERS);
   clear(color[0], zs[0]);
   clear(color[1], zs[1]);
   clear(color[2], zs[2]);
   struct rast_context *rc = context(samples, group, threads, color[0][0], zs[0][0], LAYERED);
   for (unsigned t = 0; t < n; t++)
      draw(rc, &prims[t]);
   rast_flush(rc);
   rast_destroy(rc);

   for (unsigned l = 0; l < LAYERS; l++) {
      clear(ref_color[l], ref_zs[l]);
      rc = context(samples, group, threads, ref_color[l][0], ref_zs[l][0], FLAT);
      for (unsigned t = 0; t < n; t++) {
         const unsigned pl = prims[t].layer < LAYERS ? prims[t].layer : LAYERS - 1;
         if (pl == l)
            draw(rc, &prims[t]);
      }
      rast_flush(rc);
      rast_destroy(rc);
   }

   unsigned bad_color = 0, bad_zs = 0, bad_fetch = 0;
   for (unsigned l = 0; l < LAYERS; l++)
      for (unsigned k = 0; k < samples; k++)
         for (size_t i = 0; i < PLANE; i++) {
            bad_color += memcmp(&color[l][k][4 * i], &ref_color[l][k][4 * i], 4) != 0;
            bad_zs += zs[l][k][i] != ref_zs[l][k][i];
            bad_fetch += color[l][k][4 * i] != zs[l][k][i] >> 24;
            hits += zs[l][k][i] >> 24;
         }
   CHECK(bad_color == 0 && bad_zs == 0,
         "%u colour and %u depth/stencil samples differ from the layers drawn alone (%u "
         "primitives, %u samples, groups of %u, %u threads)", bad_color, bad_zs, n, samples,
         group, threads);
   CHECK(bad_fetch == 0, "%u samples whose fetched count is not their layer's hit count",
         bad_fetch);
}

/* The same primitives with viewport indices, against each drawn with its
 * scissor and viewport set alone. */
static void scene_viewports(unsigned n, unsigned samples, unsigned group, unsigned threads)
{
   make_prims(n, VIEWPORTS);
   clear(color[0], zs[0]);
   clear(ref_color[0], ref_zs[0]);
   struct rast_context *rc = context(samples, group, threads, color[0][0], zs[0][0],
                                     VIEWPORT_ARRAY);
   for (unsigned t = 0; t < n; t++)
      draw(rc, &prims[t]);
   rast_flush(rc);
   rast_destroy(rc);

   rc = context(samples, group, threads, ref_color[0][0], ref_zs[0][0], VIEWPORT_ONE);
   for (unsigned t = 0; t < n; t++) {
      const struct rast_scissor sc = scissor_of(prims[t].layer), vp = viewport_of(prims[t].layer);
      rast_set_scissor(rc, &sc);
      rast_set_viewport(rc, &vp);
      draw(rc, &prims[t]);
   }
   rast_flush(rc);
   rast_destroy(rc);

   unsigned bad = 0, bad_fetch = 0;
   for (unsigned k = 0; k < samples; k++)
      for (size_t i = 0; i < PLANE; i++) {
         bad += memcmp(&color[0][k][4 * i], &ref_color[0][k][4 * i], 4) != 0 ||
                zs[0][k][i] != ref_zs[0][k][i];
         bad_fetch += color[0][k][4 * i] != zs[0][k][i] >> 24;
         hits += zs[0][k][i] >> 24;
      }
   CHECK(bad == 0, "%u samples differ from the primitives drawn with their viewport set alone "
         "(%u primitives, %u samples, groups of %u, %u threads)", bad, n, samples, group,
         threads);
   CHECK(bad_fetch == 0, "%u samples whose fetched count is not their hit count", bad_fetch);
}

int main(int argc, char **argv)
{
   unsigned scenes = 40;
   t_scene_args(argc, argv, "test_layers", &scenes, &rng);
   t_seed(rng);
   for (unsigned n = 0; n < scenes; n++) {
      static const unsigned groups[3] = { 0, 2, 4 };
      const unsigned np = 1 + n % MAXPRIM;
      scene(np, 1, groups[n % 3], 1);
      scene(np, NS, groups[n % 3], 1);
      scene_viewports(np, 1, groups[n % 3], 1);
      scene_viewports(np, NS, groups[n % 3], 1);
      if (n % 4 == 0) {
         scene(np, 1, groups[1 + n / 4 % 2], 2);
         scene(np, NS, 0, 2);
         scene_viewports(np, 1, groups[1 + n / 4 % 2], 2);
         scene_viewports(np, NS, 0, 2);
      }
   }
   CHECK(hits > 1000, "the scenes covered almost nothing (%llu hits)", (unsigned long long)hits);
   CHECK(beyond > 0, "no primitive went past the last layer");
   printf("layers: %llu sample hits on %d layers and %d viewports, %llu primitives past the "
          "last\n", (unsigned long long)hits, LAYERS, VIEWPORTS, (unsigned long long)beyond);
   return t_summary("layers");
}
