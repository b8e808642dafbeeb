/*
 * Saturation: coordinates, slopes, Z and colour beyond their formats clamp
 * to the format's ends, the counters of the right register class go up, and
 * nothing wraps around (a huge positive X never turns into a small or
 * negative one, a Z above full scale never reads as a small depth).
 */
#include <math.h>
#include <string.h>
#include "tutil.h"
#include "fixed/fx.h"

static float zmin, zmax, cmin, cmax;

/* The depth and colour ranges seen; the box of the pixels is tctx's. */
static void reset_ranges(void)
{
   zmin = cmin = 1e30f; zmax = cmax = -1e30f;
}

static void hook(struct tctx *t, const struct rast_quad *q)
{
   (void)t;
   for (unsigned i = 0; i < 4; i++) {
      if (!(q->mask & (1u << i)))
         continue;
      if (q->frag_z[i] < zmin) zmin = q->frag_z[i];
      if (q->frag_z[i] > zmax) zmax = q->frag_z[i];
      if (q->in[0][0][i] < cmin) cmin = q->in[0][0][i];
      if (q->in[0][0][i] > cmax) cmax = q->in[0][0][i];
   }
}

static struct tctx t;

static void tri(float x0, float y0, float x1, float y1, float x2, float y2, float z, float c)
{
   float v[3][2][4] = {
      { { x0, y0, z, 1 }, { c, c, c, 1 } },
      { { x1, y1, z, 1 }, { c, c, c, 1 } },
      { { x2, y2, z, 1 }, { c, c, c, 1 } },
   };
   reset_ranges();
   t_begin(&t);
   t_tri(t.rc, v[0], v[1], v[2]);
}

static uint64_t hi(enum rast_reg_class c) { return rast_get_stats(t.rc)->sat[c].high; }
static uint64_t lo(enum rast_reg_class c) { return rast_get_stats(t.rc)->sat[c].low; }

int main(void)
{
   t_init(&t, "seed", 2048, 2048);
   t.hook = hook;
   struct rast_vertex_layout vl = t_layout_pos();
   t_layout_add(&vl, RAST_INTERP_COLOR, 0xf);
   rast_set_vertex_layout(t.rc, &vl);

   /* in range: no counter moves */
   tri(100, 10, 400, 10, 100, 60, 0.5f, 0.5f);
   CHECK(t_sat_total(rast_get_stats(t.rc)) == 0, "in-range triangle counted a saturation");
   CHECK(t.count > 0 && t.maxx >= 390 && t.maxx <= 399, "in-range triangle: maxx %d", t.maxx);

   /* X far beyond +2048: clamps to the largest X, the triangle reaches the
    * right edge of the target and never wraps to the left */
   uint64_t h0 = hi(RAST_REG_XY);
   tri(100, 10, 5000, 10, 100, 60, 0.5f, 0.5f);
   CHECK(hi(RAST_REG_XY) == h0 + 1, "X high not counted");
   CHECK(t.count > 0 && t.minx >= 100 && t.maxx >= 2000 && t.maxx <= 2047,
         "X high: x range %d..%d", t.minx, t.maxx);

   /* X and Y far below -2048: clamp low */
   uint64_t l0 = lo(RAST_REG_XY);
   tri(-1e6f, -1e6f, 300, 20, 20, 300, 0.5f, 0.5f);
   CHECK(lo(RAST_REG_XY) == l0 + 2, "X/Y low not counted");
   CHECK(t.count > 0 && t.minx == 0 && t.miny == 0 && t.maxx <= 300 && t.maxy <= 300,
         "X low: box %d..%d x %d..%d", t.minx, t.maxx, t.miny, t.maxy);

   /* Y far beyond: the triangle ends at the bottom of the target */
   h0 = hi(RAST_REG_XY);
   tri(10, 1000, 60, 1000, 30, 1e9f, 0.5f, 0.5f);
   CHECK(hi(RAST_REG_XY) == h0 + 1 && t.maxy >= 2000 && t.maxy <= 2047 && t.miny == 1000,
         "Y high: %d..%d", t.miny, t.maxy);

   /* an edge too flat for the dx/dy register (slope beyond 2048 pixels per
    * scan line, walked over two scan lines) */
   uint64_t d0 = hi(RAST_REG_DXDY) + lo(RAST_REG_DXDY);
   tri(-2000, 100.2f, 2000, 101.9f, -2000, 103, 0.5f, 0.5f);
   CHECK(hi(RAST_REG_DXDY) + lo(RAST_REG_DXDY) > d0, "slope saturation not counted");
   CHECK(t.dups == 0 && t.badquad == 0 && t.miny >= 100 && t.maxy <= 102,
         "slope saturation: rows %d..%d", t.miny, t.maxy);

   /* Z above full scale: the register holds its largest value, read as a
    * depth just above 1, never as a small or negative depth */
   h0 = hi(RAST_REG_Z);
   tri(10, 10, 200, 10, 10, 200, 3.0f, 0.5f);
   double zmax_fmt = fx_to_double(t.prof->z, fx_max(t.prof->z)) / ((1 << 19) - 1);
   CHECK(hi(RAST_REG_Z) >= 3, "Z high not counted");
   CHECK(t.count > 0 && zmin > 1.0f && zmax <= (float)zmax_fmt + 1e-6f, "Z high: %g..%g", zmin, zmax);
   l0 = lo(RAST_REG_Z);
   tri(10, 10, 200, 10, 10, 200, -3.0f, 0.5f);
   CHECK(lo(RAST_REG_Z) >= 3 && zmax < -1.0f && zmin >= -1.00001f, "Z low: %g..%g", zmin, zmax);

   /* colour beyond 9.12 (2.0 = 510/255): clamps just below 256/255 */
   h0 = hi(RAST_REG_COLOR);
   tri(10, 10, 200, 10, 10, 200, 0.5f, 2.0f);
   CHECK(hi(RAST_REG_COLOR) - h0 >= 9, "colour high not counted (%llu)", (unsigned long long)(hi(RAST_REG_COLOR) - h0));
   CHECK(cmin > 1.0f && cmax < 256.0f / 255.0f + 1e-5f, "colour high: %g..%g", cmin, cmax);
   l0 = lo(RAST_REG_COLOR);
   tri(10, 10, 200, 10, 10, 200, 0.5f, -2.0f);
   CHECK(lo(RAST_REG_COLOR) - l0 >= 9 && cmax < -1.0f && cmin >= -256.0f / 255.0f - 1e-5f,
         "colour low: %g..%g", cmin, cmax);

   /* a steep colour gradient inside the format walks without clamping */
   {
      float v[3][2][4] = {
         { { 10, 10, 0.5f, 1 }, { 1.0f, 1, 1, 1 } },
         { { 11, 10, 0.5f, 1 }, { 1.0f, 1, 1, 1 } },
         { { 10, 400, 0.5f, 1 }, { -1.0f, 1, 1, 1 } },
      };
      reset_ranges();
      t_begin(&t);
      t_tri(t.rc, v[0], v[1], v[2]);
      /* inside, colour runs from 1 down to -1: no saturation needed */
      CHECK(cmax <= 1.0f + 1e-5f && cmin >= -1.0f - 1e-5f, "colour walk %g..%g", cmin, cmax);
   }

   /* A position that is not finite (NaN, an infinity in x, y, z or 1/w) is
    * no overflow to saturate but a primitive to drop, counted apart from
    * the saturations: triangles, lines and points (rast_position_finite). */
   {
      const float bad[] = { NAN, INFINITY, -INFINITY };
      uint64_t dropped = 0;
      for (unsigned b = 0; b < 3; b++)
         for (unsigned k = 0; k < 3; k++)
            for (unsigned c = 0; c < 4; c++) {
               float v[3][2][4] = {
                  { { 10, 10, 0.5f, 1 }, { 0.5f, 0.5f, 0.5f, 1 } },
                  { { 300, 20, 0.5f, 1 }, { 0.5f, 0.5f, 0.5f, 1 } },
                  { { 40, 250, 0.5f, 1 }, { 0.5f, 0.5f, 0.5f, 1 } },
               };
               v[k][0][c] = bad[b];
               const uint64_t n0 = rast_get_stats(t.rc)->nonfinite;
               const uint64_t s0 = t_sat_total(rast_get_stats(t.rc));
               reset_ranges();
               t_begin(&t);
               t_tri(t.rc, v[0], v[1], v[2]);
               t_line(t.rc, v[k], v[(k + 1) % 3]);
               rast_point(t.rc, T_V(v[k]));
               CHECK(t.count == 0, "%g in coordinate %u of vertex %u: %llu pixels drawn",
                     (double)bad[b], c, k, (unsigned long long)t.count);
               CHECK(rast_get_stats(t.rc)->nonfinite == n0 + 3 &&
                     t_sat_total(rast_get_stats(t.rc)) == s0,
                     "%g in coordinate %u of vertex %u: dropped %llu of 3, saturations %llu",
                     (double)bad[b], c, k,
                     (unsigned long long)(rast_get_stats(t.rc)->nonfinite - n0),
                     (unsigned long long)(t_sat_total(rast_get_stats(t.rc)) - s0));
               dropped += rast_get_stats(t.rc)->nonfinite - n0;
            }
      CHECK(dropped == 3 * 3 * 4 * 3, "non-finite primitives dropped: %llu",
            (unsigned long long)dropped);
   }
   t_fini(&t);

   /* the wide profile holds what the seed one clamps */
   t_init(&t, "wide", 2048, 2048);
   t.hook = hook;
   rast_set_vertex_layout(t.rc, &vl);
   tri(100, 10, 5000, 10, 100, 60, 0.5f, 0.5f);
   CHECK(t_sat_total(rast_get_stats(t.rc)) == 0 && t.maxx == 2047,
         "wide: 5000 in range, clipped by the target");
   tri(100, 10, 40000, 10, 100, 60, 0.5f, 0.5f);
   CHECK(hi(RAST_REG_XY) == 1 && t.maxx == 2047 && t.minx >= 100, "wide: 40000 clamps");
   t_fini(&t);
   return t_summary("saturation");
}
