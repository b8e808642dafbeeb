/*
 * The modeled screen's tiles.
 *
 * The scan converter addresses pixels with X_out and Y_out, 11 bits in the
 * seed profile, so one pass reaches a tile of 2048 x 2048 pixels at most.
 * A larger target is drawn the way such hardware draws it: tile by tile,
 * each primitive in one pass per tile it reaches, inside that tile.
 *
 * Every pass takes its vertices relative to an origin subtracted before
 * they enter the XY registers.  The origin is the centre of the primitive's
 * extent, not the tile's corner: the 12.12 registers span 4096 pixels
 * around it, so any primitive up to 4096 pixels across keeps every vertex
 * exact, whichever tile it is drawn in.  The origin is a whole, even
 * number of pixels, so the 1/4096 grid, the 2x2 quads and the threads'
 * bands land where they land without tiles: coverage is that of one big
 * register.  What does differ is where the edge walk starts: a pass starts
 * its edges and their attributes at the tile's first scan line, with the
 * same exact jump as a scissored primitive.
 *
 * Counters: a primitive is counted once, by its first pass; the later
 * passes' set-up (the same determinant, the same cull) is not counted, their
 * quad rows are (they are other pixels).
 */
#include <math.h>
#include "rast/rast_priv.h"

bool rast_prim_extent(const struct rast_context *rc, enum rast_prim_kind kind,
                      const float (*v0)[4], const float (*v1)[4], const float (*v2)[4],
                      float box[4])
{
   const unsigned ps = rc->vl.pos_slot;
   const float (*v[3])[4] = { v0, v1, v2 };
   unsigned nv = kind == RAST_PRIM_TRIANGLE ? 3 : kind == RAST_PRIM_LINE ? 2 : 1;
   float x0 = v[0][ps][0], x1 = x0, y0 = v[0][ps][1], y1 = y0;
   for (unsigned k = 1; k < nv; k++) {
      float x = v[k][ps][0], y = v[k][ps][1];
      x0 = fminf(x0, x); x1 = fmaxf(x1, x);
      y0 = fminf(y0, y); y1 = fmaxf(y1, y);
   }
   /* the snap moves a vertex by less than a pixel; lines and points grow
    * by their size */
   float m = 2.0f;
   if (kind == RAST_PRIM_LINE)
      m += rc->rs.line_width * 0.5f;
   else if (kind == RAST_PRIM_POINT)
      m += RAST_MAX_POINT_SIZE * 0.5f;
   box[0] = x0 - m; box[1] = y0 - m; box[2] = x1 + m; box[3] = y1 + m;
   return box[0] > -1e9f && box[2] < 1e9f && box[1] > -1e9f && box[3] < 1e9f;
}

/* An even whole number near the middle of [lo, hi]. */
static int64_t even_middle(float lo, float hi)
{
   return 2 * (int64_t)floor(((double)lo + (double)hi) * 0.25);
}

static void draw_pass(struct rast_context *rc, enum rast_prim_kind kind, const float (*v0)[4],
                      const float (*v1)[4], const float (*v2)[4])
{
   switch (kind) {
   case RAST_PRIM_TRIANGLE: rast_triangle_pass(rc, v0, v1, v2); break;
   case RAST_PRIM_LINE:     rast_line_pass(rc, v0, v1); break;
   case RAST_PRIM_POINT:    rast_point_pass(rc, v0); break;
   }
}

static inline int64_t floor_div_i(int64_t a, int64_t b)
{
   return a >= 0 ? a / b : -((-a + b - 1) / b);
}

void rast_tiles_draw(struct rast_context *rc, enum rast_prim_kind kind, const float (*v0)[4],
                     const float (*v1)[4], const float (*v2)[4])
{
   const struct rast_scissor all = rc->clip_all;
   const int64_t T = rc->profile->tile_size;

   /* The pixels the primitive can reach; without a finite extent (NaN,
    * infinities) it is drawn in every tile from the origin, and saturates
    * there as it would untiled. */
   float box[4];
   int64_t bx0 = all.minx, by0 = all.miny, bx1 = all.maxx, by1 = all.maxy;
   int64_t ox = 0, oy = 0;
   if (rast_prim_extent(rc, kind, v0, v1, v2, box)) {
      ox = even_middle(box[0], box[2]);
      oy = even_middle(box[1], box[3]);
      int64_t fx0 = (int64_t)floorf(box[0]), fy0 = (int64_t)floorf(box[1]);
      int64_t fx1 = (int64_t)ceilf(box[2]), fy1 = (int64_t)ceilf(box[3]);
      if (fx0 > bx0) bx0 = fx0;
      if (fy0 > by0) by0 = fy0;
      if (fx1 < bx1) bx1 = fx1;
      if (fy1 < by1) by1 = fy1;
   }

   const bool counting = rc->counting;
   bool first = true;
   for (int64_t ty = floor_div_i(by0, T); by0 < by1 && ty <= floor_div_i(by1 - 1, T); ty++) {
      for (int64_t tx = floor_div_i(bx0, T); bx0 < bx1 && tx <= floor_div_i(bx1 - 1, T); tx++) {
         struct rast_scissor c = { (int)(tx * T), (int)(ty * T),
                                   (int)(tx * T + T), (int)(ty * T + T) };
         if (c.minx < all.minx) c.minx = all.minx;
         if (c.miny < all.miny) c.miny = all.miny;
         if (c.maxx > all.maxx) c.maxx = all.maxx;
         if (c.maxy > all.maxy) c.maxy = all.maxy;
         if (c.minx >= c.maxx || c.miny >= c.maxy)
            continue;
         rc->clip = (struct rast_scissor){ (int)(c.minx - ox), (int)(c.miny - oy),
                                           (int)(c.maxx - ox), (int)(c.maxy - oy) };
         rc->org_x = ox;
         rc->org_y = oy;
         if (!first)
            rast_count_stretch(rc, false);
         first = false;
         draw_pass(rc, kind, v0, v1, v2);
      }
   }
   if (first) {
      /* in no tile: set up and counted as untiled, and nothing drawn */
      rc->clip = (struct rast_scissor){ 0, 0, 0, 0 };
      rc->org_x = ox;
      rc->org_y = oy;
      draw_pass(rc, kind, v0, v1, v2);
   }
   rast_count_stretch(rc, counting);
   rc->clip = all;
   rc->org_x = rc->org_y = 0;
}
