/*
 * The modeled screen's tiles (tile.c): targets larger than X_out reaches.
 *
 * 1. Small tiles against none: the seed profile with 32-pixel tiles on a
 *    203 x 150 target (seven by five tiles, primitives across every kind of
 *    boundary) against the seed profile drawing it in one pass.  Coverage
 *    must be identical (the stencil counts every hit of every pixel, so a
 *    pixel lost or drawn twice at a tile boundary shows), and so must the
 *    primitive and pixel counters; depth and colour may differ only by
 *    where the edge walk starts (a tile's first scan line), a unit at most.
 *    The tiled picture must be byte-identical on random thread counts.
 * 2. A 3000 x 2000 target in the seed profile (tiles of 2048, vertices up
 *    to 3000 px from the origin) against the wide profile, which needs no
 *    tiles: identical coverage, and no XY register saturated.
 * 3. The guard band: registers of 8.12 (a reach of 128 pixels) with tiles
 *    of 64 on 300 x 200, so that most large primitives are clipped to the
 *    band, against 12.12 in one pass.  The clip's new vertices are rounded
 *    to the grid, so an edge may move by a fraction of 1/4096 pixel and a
 *    pixel centre that close to it may change sides: at most 1 in 10,000
 *    hit pixels, by one hit.  No XY register saturates; 1 = N threads.
 * Run under ThreadSanitizer by `./fixpipe check` (build/tsan), like
 * test_threads.
 */
#include <math.h>
#include <string.h>
#include "tutil.h"

#define MAX_PRIMS 400
#define SLOTS T_PERSP_COLOR_SLOTS

static unsigned shade(void *ctx, const struct rast_quad *q, struct rast_shaded_quad *out)
{
   (void)ctx;
   for (unsigned p = 0; p < RAST_QUAD_SIZE; p++) {
      out->color[0][0][p] = q->in[0][0][p];
      out->color[0][1][p] = q->in[0][1][p];
      out->color[0][2][p] = q->in[1][2][p];
      out->color[0][3][p] = q->in[1][3][p];
   }
   return q->mask;
}

struct scene {
   int w, h;
   unsigned nprim;
   unsigned kind[MAX_PRIMS];        /* 0 triangle, 1 line, 2 point */
   float v[MAX_PRIMS][3][SLOTS][4];
   float line_width, point_size;
   bool cull;
};

static uint64_t rng;

static float frnd(float lo, float hi)
{
   return lo + (hi - lo) * (float)(t_xorshift(&rng) >> 11) * (1.0f / 9007199254740992.0f);
}

static void make_vertex(float (*v)[4], float x, float y)
{
   float w = frnd(0.3f, 3.0f);
   v[0][0] = x; v[0][1] = y; v[0][2] = frnd(0.0f, 1.0f); v[0][3] = 1.0f / w;
   v[1][0] = frnd(0, 1) / w; v[1][1] = frnd(0, 1) / w; v[1][2] = 0; v[1][3] = 0;
   for (unsigned c = 0; c < 4; c++)
      v[2][c] = frnd(0, 1);
}

/* Mostly small primitives near a multiple of `grid` (the tiles' edges),
 * `big` of them across most of the target, a few partly off it. */
static void make_scene(struct scene *s, int w, int h, unsigned nprim, int grid, float medium,
                       unsigned big)
{
   s->w = w;
   s->h = h;
   s->nprim = nprim;
   s->line_width = frnd(1.0f, 6.0f);
   s->point_size = frnd(1.0f, 40.0f);
   s->cull = t_xorshift(&rng) % 3 == 0;
   for (unsigned i = 0; i < nprim; i++) {
      unsigned r = (unsigned)(t_xorshift(&rng) % 10);
      s->kind[i] = r < 7 ? 0 : r < 9 ? 1 : 2;
      float cx = (float)(grid * (int)(t_xorshift(&rng) % (unsigned)(w / grid + 1))) + frnd(-4, 4);
      float cy = (float)(grid * (int)(t_xorshift(&rng) % (unsigned)(h / grid + 1))) + frnd(-4, 4);
      float size = i < big ? frnd(0.4f, 0.5f) * (float)(w > h ? w : h)
                 : t_xorshift(&rng) % 8 == 0 ? frnd(10, medium) : frnd(0.5f, 12);
      if (i < big) {
         cx = frnd(0.3f, 0.7f) * (float)w;
         cy = frnd(0.3f, 0.7f) * (float)h;
      }
      for (unsigned k = 0; k < 3; k++)
         make_vertex(s->v[i][k], cx + frnd(-size, size), cy + frnd(-size, size));
   }
}

struct result {
   uint8_t *color;
   uint32_t *zs;
   struct rast_stats stats;
};

static void draw_scene(const struct scene *s, const struct rast_profile *prof, unsigned threads,
                       struct result *res)
{
   const size_t n = (size_t)s->w * (size_t)s->h;
   struct rast_context *rc = rast_create(prof);
   CHECK(rast_set_threads(rc, threads), "%u threads", threads);
   memset(res->color, 0x40, n * 4);
   for (size_t i = 0; i < n; i++)
      res->zs[i] = 0x00ffffffu;        /* depth far, stencil 0 */

   t_bind_rgba8_z24s8(rc, res->color, res->zs, s->w, s->h);
   t_layout_persp_color(rc);

   struct rast_shader fs;
   memset(&fs, 0, sizeof(fs));
   fs.shade = shade;
   fs.num_outputs = 1;
   rast_set_shader(rc, &fs);

   /* Depth ALWAYS, written: the last primitive's Z and colour are the
    * pixel's, whatever a unit of Z; the stencil counts every hit. */
   t_depth_count_hits(rc, RAST_FUNC_ALWAYS);

   struct rast_blend_state bs;
   memset(&bs, 0, sizeof(bs));
   bs.rt[0].colormask = 0xf;
   rast_set_blend(rc, &bs);
   struct rast_raster_state rs;
   memset(&rs, 0, sizeof(rs));
   rs.half_pixel_center = true;
   rs.line_width = s->line_width;
   rs.point_size = s->point_size;
   rs.point_quad_rasterization = true;
   rs.cull = s->cull ? RAST_CULL_BACK : RAST_CULL_NONE;
   rast_set_raster_state(rc, &rs);
   for (unsigned i = 0; i < s->nprim; i++) {
      const float (*v0)[4] = T_V(s->v[i][0]);
      const float (*v1)[4] = T_V(s->v[i][1]);
      const float (*v2)[4] = T_V(s->v[i][2]);
      switch (s->kind[i]) {
      case 0: rast_triangle(rc, v0, v1, v2); break;
      case 1: rast_line(rc, v0, v1); break;
      default: rast_point(rc, v0); break;
      }
   }
   rast_flush(rc);
   res->stats = *rast_get_stats(rc);
   rast_destroy(rc);
}

static void result_alloc(struct result *r, int w, int h)
{
   r->color = malloc((size_t)w * (size_t)h * 4);
   r->zs = malloc((size_t)w * (size_t)h * 4);
   if (!r->color || !r->zs)
      abort();
}

static void result_free(struct result *r)
{
   free(r->color);
   free(r->zs);
}

/* The scene on `ref` in one pass (one), and on `prof` in tiles on one
 * thread (tiled) and on `threads` (many), which must be the same bytes,
 * counters included. */
static void draw_tiled(const struct scene *s, const struct rast_profile *ref,
                       const struct rast_profile *prof, unsigned threads, struct result *one,
                       struct result *tiled, struct result *many, const char *what, unsigned n)
{
   const size_t bytes = (size_t)s->w * (size_t)s->h * 4;
   draw_scene(s, ref, 1, one);
   draw_scene(s, prof, 1, tiled);
   draw_scene(s, prof, threads, many);
   CHECK(!memcmp(tiled->color, many->color, bytes) && !memcmp(tiled->zs, many->zs, bytes),
         "%s scene %u: tiles differ with %u threads", what, n, threads);
   CHECK(!memcmp(&tiled->stats, &many->stats, sizeof(tiled->stats)),
         "%s scene %u: tiles' counters differ with %u threads", what, n, threads);
}

/* The counters that depend on coverage alone, not on the registers. */
static bool same_coverage_counts(const struct rast_stats *a, const struct rast_stats *b)
{
   return a->triangles == b->triangles && a->lines == b->lines && a->points == b->points &&
          a->culled == b->culled && a->quads == b->quads &&
          a->pixels_covered == b->pixels_covered;
}

/* Pixels whose stencil (hit count) differs; the largest depth and colour
 * differences over the rest. */
static size_t compare(const struct scene *s, const struct result *a, const struct result *b,
                      unsigned *max_z, unsigned *max_c, size_t *hit)
{
   const size_t n = (size_t)s->w * (size_t)s->h;
   size_t bad = 0;
   *max_z = *max_c = 0;
   *hit = 0;
   for (size_t i = 0; i < n; i++) {
      if (a->zs[i] >> 24 != b->zs[i] >> 24) {
         bad++;
         continue;
      }
      *hit += (a->zs[i] >> 24) != 0;
      unsigned za = a->zs[i] & 0xffffff, zb = b->zs[i] & 0xffffff;
      unsigned dz = za > zb ? za - zb : zb - za;
      if (dz > *max_z) *max_z = dz;
      for (unsigned c = 0; c < 4; c++) {
         int d = (int)a->color[4 * i + c] - (int)b->color[4 * i + c];
         if ((unsigned)abs(d) > *max_c) *max_c = (unsigned)abs(d);
      }
   }
   return bad;
}

int main(void)
{
   const struct rast_profile *seed = rast_profile_by_name("seed");
   const struct rast_profile *wide = rast_profile_by_name("wide");
   struct rast_profile small = *seed;
   small.tile_size = 32;
   static struct scene scene;
   struct result one, tiled, many;
   rng = 0x711e5eed0042ull;

   /* 1. small tiles */
   const int W = 203, H = 150;
   result_alloc(&one, W, H);
   result_alloc(&tiled, W, H);
   result_alloc(&many, W, H);
   unsigned worst_z = 0, worst_c = 0;
   size_t hits = 0;
   for (unsigned n = 0; n < 40; n++) {
      make_scene(&scene, W, H, 1 + (unsigned)(t_xorshift(&rng) % MAX_PRIMS), 32, 128, n % 4);
      draw_tiled(&scene, seed, &small, 2 + (unsigned)(t_xorshift(&rng) % 7), &one, &tiled,
                 &many, "small", n);
      unsigned mz, mc;
      size_t h;
      size_t bad = compare(&scene, &one, &tiled, &mz, &mc, &h);
      hits += h;
      CHECK(bad == 0, "scene %u: %zu pixels hit another number of times in tiles", n, bad);
      CHECK(same_coverage_counts(&one.stats, &tiled.stats),
            "scene %u: counters differ in tiles: triangles %llu/%llu, culled %llu/%llu, "
            "quads %llu/%llu", n,
            (unsigned long long)one.stats.triangles, (unsigned long long)tiled.stats.triangles,
            (unsigned long long)one.stats.culled, (unsigned long long)tiled.stats.culled,
            (unsigned long long)one.stats.quads, (unsigned long long)tiled.stats.quads);
      if (mz > worst_z) worst_z = mz;
      if (mc > worst_c) worst_c = mc;
   }
   /* Where the walk starts moves a register by its last bit (2^-12 of a Z
    * unit, 2^-7 of the 24-bit buffer's): the buffer's rounding by one. */
   CHECK(worst_z <= 1, "depth differs by %u (24-bit units) in tiles", worst_z);
   CHECK(worst_c <= 1, "colour differs by %u in tiles", worst_c);
   CHECK(hits > 20000, "only %zu pixels hit: the scenes prove little", hits);
   printf("small tiles: 40 scenes, %zu pixels hit, depth within %u, colour within %u\n", hits,
          worst_z, worst_c);
   result_free(&one);
   result_free(&tiled);
   result_free(&many);

   /* 2. a target beyond X_out: seed in tiles against wide in one pass */
   const int W2 = 3000, H2 = 2000;
   result_alloc(&one, W2, H2);
   result_alloc(&tiled, W2, H2);
   for (unsigned n = 0; n < 3; n++) {
      make_scene(&scene, W2, H2, MAX_PRIMS, 2048, 1000, 4);
      draw_scene(&scene, wide, 1, &one);
      draw_scene(&scene, seed, 1 + n, &tiled);
      unsigned mz, mc;
      size_t h;
      size_t bad = compare(&scene, &one, &tiled, &mz, &mc, &h);
      CHECK(bad == 0, "%dx%d scene %u: %zu pixels hit another number of times than wide",
            W2, H2, n, bad);
      CHECK(same_coverage_counts(&one.stats, &tiled.stats),
            "%dx%d scene %u: counters differ from wide", W2, H2, n);
      CHECK(t_sat_class(&tiled.stats, RAST_REG_XY) == 0, "%dx%d scene %u: %llu XY saturations",
            W2, H2, n, (unsigned long long)t_sat_class(&tiled.stats, RAST_REG_XY));
      CHECK(h > (size_t)W2 * H2 / 20, "%dx%d scene %u: only %zu pixels hit", W2, H2, n, h);
      printf("%dx%d scene %u (%u threads): %zu pixels hit, coverage as wide's\n", W2, H2, n,
             1 + n, h);
   }
   result_free(&one);
   result_free(&tiled);

   /* 3. the guard band */
   const int W3 = 300, H3 = 200;
   struct rast_profile narrow = *seed;
   narrow.xy = (struct fx_format){ 8, 12 };
   narrow.tile_size = 64;
   result_alloc(&one, W3, H3);
   result_alloc(&tiled, W3, H3);
   result_alloc(&many, W3, H3);
   size_t moved = 0, hit3 = 0;
   uint64_t guarded = 0;
   for (unsigned n = 0; n < 20; n++) {
      make_scene(&scene, W3, H3, 1 + (unsigned)(t_xorshift(&rng) % 100), 64, 300, 6);
      draw_tiled(&scene, seed, &narrow, 2 + (unsigned)(t_xorshift(&rng) % 7), &one, &tiled,
                 &many, "guard", n);
      for (size_t i = 0; i < (size_t)W3 * H3; i++) {
         int a = (int)(one.zs[i] >> 24), b = (int)(tiled.zs[i] >> 24);
         hit3 += a != 0;
         moved += a != b;
         CHECK(abs(a - b) <= 1, "guard scene %u: pixel %zu hit %d times, %d in one pass", n, i,
               b, a);
      }
      guarded += tiled.stats.tile_guard;
      CHECK(t_sat_class(&tiled.stats, RAST_REG_XY) == 0, "guard scene %u: %llu XY saturations",
            n, (unsigned long long)t_sat_class(&tiled.stats, RAST_REG_XY));
      CHECK(tiled.stats.triangles == one.stats.triangles && tiled.stats.lines == one.stats.lines &&
            tiled.stats.culled == one.stats.culled,
            "guard scene %u: primitives counted %llu/%llu, %llu/%llu culled", n,
            (unsigned long long)tiled.stats.triangles, (unsigned long long)one.stats.triangles,
            (unsigned long long)tiled.stats.culled, (unsigned long long)one.stats.culled);
   }
   CHECK(guarded > 20, "only %llu primitives clipped to the guard band", (unsigned long long)guarded);
   CHECK(moved * 10000 <= hit3, "%zu of %zu hit pixels moved by the guard band's clip", moved, hit3);
   printf("guard band: 20 scenes, %llu primitives clipped, %zu pixels hit, %zu moved\n",
          (unsigned long long)guarded, hit3, moved);
   result_free(&one);
   result_free(&tiled);
   result_free(&many);
   return t_summary("tiles");
}
