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
 * same exact jump as a scissored primitive.  A primitive wider than any
 * origin holds is clipped to a guard band around each tile first (below).
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
   /* fminf and fmaxf (a NaN operand gives the other), written out: the
    * threads' queue takes every primitive's extent on the main thread, and
    * the library calls were a measurable share of it */
#define MIN_OF(a, b) ((b) < (a) || (a) != (a) ? (b) : (a))
#define MAX_OF(a, b) ((b) > (a) || (a) != (a) ? (b) : (a))
   for (unsigned k = 1; k < nv; k++) {
      float x = v[k][ps][0], y = v[k][ps][1];
      x0 = MIN_OF(x0, x); x1 = MAX_OF(x1, x);
      y0 = MIN_OF(y0, y); y1 = MAX_OF(y1, y);
   }
#undef MIN_OF
#undef MAX_OF
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

/* ---- the guard band: primitives wider than the registers reach ----
 *
 * A primitive more than 2 * 2048 pixels across (seed) cannot be held from
 * any origin.  Such a primitive is drawn from each tile's centre, clipped
 * first, in float as the clip stage of seed 004 works, to the guard band:
 * halfway between the tile's edge and the registers' reach (512 pixels
 * outside the tile in seed, 4 times the widest line's half width), so the
 * new edges never cross the tile, a wide line's corners stay in reach, and
 * the original edges move only by the rounding of their new end points. */
#define TILE_MAX_SLOTS    80           /* draw's vertex: up to PIPE_MAX_SHADER_OUTPUTS */
#define TILE_MAX_POLY     7            /* a triangle clipped by four planes */

enum slot_mode { SLOT_LINEAR, SLOT_PERSPECTIVE, SLOT_CONSTANT };

struct guard {
   unsigned nslots, ps;
   uint8_t mode[TILE_MAX_SLOTS];
   const float (*provoking)[4];
   double lo[2], hi[2];                /* the band, in target pixels */
};

typedef float tile_vertex[TILE_MAX_SLOTS][4];

static void guard_modes(const struct rast_context *rc, struct guard *g,
                        const float (*provoking)[4])
{
   g->nslots = rc->vl.vertex_size;
   g->ps = rc->vl.pos_slot;
   g->provoking = provoking;
   for (unsigned s = 0; s < g->nslots; s++)
      g->mode[s] = SLOT_LINEAR;
   for (unsigned i = 0; i < rc->vl.num_varyings && i < RAST_MAX_VARYINGS; i++) {
      const struct rast_varying *vr = &rc->vl.varying[i];
      if (vr->slot >= g->nslots)
         continue;
      switch (vr->interp) {
      case RAST_INTERP_PERSPECTIVE:
         g->mode[vr->slot] = SLOT_PERSPECTIVE;
         break;
      case RAST_INTERP_COLOR:
         g->mode[vr->slot] = rc->rs.flatshade ? SLOT_CONSTANT :
                             rc->profile->color_perspective ? SLOT_PERSPECTIVE : SLOT_LINEAR;
         break;
      case RAST_INTERP_CONSTANT:
         g->mode[vr->slot] = SLOT_CONSTANT;
         break;
      default:
         break;
      }
   }
   g->mode[g->ps] = SLOT_LINEAR;       /* window x, y, z and 1/w: linear on the screen */
}

/* The point at t from a to b on the screen, each input as the pipeline
 * interpolates it. */
static void guard_lerp(const struct guard *g, const float (*a)[4], const float (*b)[4],
                       double t, float (*o)[4])
{
   const double qa = a[g->ps][3], qb = b[g->ps][3];
   const double q = qa + (qb - qa) * t;
   for (unsigned s = 0; s < g->nslots; s++) {
      for (unsigned c = 0; c < 4; c++) {
         const double va = a[s][c], vb = b[s][c];
         switch (g->mode[s]) {
         case SLOT_CONSTANT:
            o[s][c] = g->provoking[s][c];
            break;
         case SLOT_PERSPECTIVE:
            o[s][c] = q != 0.0 ? (float)((va * qa + (vb * qb - va * qa) * t) / q)
                               : (float)(va + (vb - va) * t);
            break;
         default:
            o[s][c] = (float)(va + (vb - va) * t);
            break;
         }
      }
   }
}

static void guard_copy(const struct guard *g, const float (*a)[4], float (*o)[4])
{
   for (unsigned s = 0; s < g->nslots; s++)
      for (unsigned c = 0; c < 4; c++)
         o[s][c] = g->mode[s] == SLOT_CONSTANT ? g->provoking[s][c] : a[s][c];
}

/* The crossing of the segment a-b with the line (axis) = edge, computed from
 * the end points in one order whichever way the edge is walked, so the two
 * polygons sharing it get the same point. */
static void guard_cross(const struct guard *g, const float (*a)[4], const float (*b)[4],
                        unsigned axis, double edge, float (*o)[4])
{
   const float (*p)[4] = a, (*r)[4] = b;
   if (a[g->ps][axis] > b[g->ps][axis] ||
       (a[g->ps][axis] == b[g->ps][axis] && a[g->ps][1 - axis] > b[g->ps][1 - axis])) {
      p = b;
      r = a;
   }
   const double t = (edge - p[g->ps][axis]) / ((double)r[g->ps][axis] - p[g->ps][axis]);
   guard_lerp(g, p, r, t, o);
   o[g->ps][axis] = (float)edge;
}

/* Sutherland-Hodgman against the band, from one buffer to the other: the
 * polygon's n vertices in *poly, which ends as the buffer holding the
 * result. */
static unsigned guard_clip_polygon(const struct guard *g, tile_vertex **poly, unsigned n,
                                   tile_vertex **tmp)
{
   for (unsigned plane = 0; plane < 4 && n; plane++) {
      const unsigned axis = plane & 1;
      const bool upper = plane >= 2;
      const double edge = upper ? g->hi[axis] : g->lo[axis];
      unsigned m = 0;
      tile_vertex *in = *poly;
      tile_vertex *out = *tmp;
      for (unsigned i = 0; i < n; i++) {
         const float (*a)[4] = (const float (*)[4])in[i];
         const float (*b)[4] = (const float (*)[4])in[(i + 1) % n];
         const double pa = a[g->ps][axis], pb = b[g->ps][axis];
         const bool ina = upper ? pa <= edge : pa >= edge;
         const bool inb = upper ? pb <= edge : pb >= edge;
         if (ina)
            guard_copy(g, a, out[m++]);
         if (ina != inb)
            guard_cross(g, a, b, axis, edge, out[m++]);
      }
      *tmp = *poly;
      *poly = out;
      n = m;
   }
   return n;
}

/* The primitive clipped to the band and drawn in the current pass; its
 * pieces' set-up is not counted (the primitive was, once). */
static void guard_draw(struct rast_context *rc, struct guard *g, enum rast_prim_kind kind,
                       const float (*v0)[4], const float (*v1)[4], const float (*v2)[4])
{
   tile_vertex buf[2][TILE_MAX_POLY];
   tile_vertex *poly = buf[0], *tmp = buf[1];
   if (kind == RAST_PRIM_LINE) {
      /* Liang-Barsky on the segment */
      double t0 = 0.0, t1 = 1.0;
      for (unsigned axis = 0; axis < 2; axis++) {
         const double p = v0[g->ps][axis], d = (double)v1[g->ps][axis] - p;
         if (d == 0.0) {
            if (p < g->lo[axis] || p > g->hi[axis])
               return;
            continue;
         }
         double ta = (g->lo[axis] - p) / d, tb = (g->hi[axis] - p) / d;
         if (ta > tb) { const double t = ta; ta = tb; tb = t; }
         if (ta > t0) t0 = ta;
         if (tb < t1) t1 = tb;
      }
      if (t0 > t1)
         return;
      guard_lerp(g, v0, v1, t0, poly[0]);
      guard_lerp(g, v0, v1, t1, poly[1]);
      rast_count_stretch(rc, false);
      rast_line_pass(rc, (const float (*)[4])poly[0], (const float (*)[4])poly[1]);
      return;
   }
   guard_copy(g, v0, poly[0]);
   guard_copy(g, v1, poly[1]);
   guard_copy(g, v2, poly[2]);
   unsigned n = guard_clip_polygon(g, &poly, 3, &tmp);
   for (unsigned i = 1; i + 1 < n; i++) {
      rast_count_stretch(rc, false);
      rast_triangle_pass(rc, (const float (*)[4])poly[0], (const float (*)[4])poly[i],
                         (const float (*)[4])poly[i + 1]);
   }
}

/* Counted once for a primitive drawn in pieces: what its own set-up would
 * count (a triangle by the sign of its determinant on the grid). */
static bool guard_count(struct rast_context *rc, enum rast_prim_kind kind, const float (*v0)[4],
                        const float (*v1)[4], const float (*v2)[4])
{
   const unsigned ps = rc->vl.pos_slot;
   if (kind == RAST_PRIM_LINE)
      return rast_line_counted(rc, v0[ps][0] - v1[ps][0], v0[ps][1] - v1[ps][1]);
   const float (*v[3])[4] = { v0, v1, v2 };
   int64_t X[3], Y[3];
   for (unsigned k = 0; k < 3; k++) {
      X[k] = rast_snap_xy(rc->profile->xy, v[k][ps][0]);
      Y[k] = rast_snap_xy(rc->profile->xy, v[k][ps][1]);
   }
   /* the box is finite and within 2^15 pixels: 2^28 grid steps, products in 2^57 */
   bool front;
   return rast_triangle_counted(rc, rast_det(X, Y), &front);
}

void rast_tiles_draw(struct rast_context *rc, enum rast_prim_kind kind, const float (*v0)[4],
                     const float (*v1)[4], const float (*v2)[4])
{
   const struct rast_scissor all = rc->clip_all;
   const int64_t T = rc->profile->tile_size;
   const int64_t R = INT64_C(1) << (rc->profile->xy.int_bits - 1);   /* the registers' reach */

   /* The pixels the primitive can reach; without a finite extent (NaN,
    * infinities) it is drawn in every tile from the origin, and saturates
    * there as it would untiled. */
   float box[4];
   int64_t bx0 = all.minx, by0 = all.miny, bx1 = all.maxx, by1 = all.maxy;
   int64_t ox = 0, oy = 0;
   bool guard = false;
   if (rast_prim_extent(rc, kind, v0, v1, v2, box)) {
      ox = even_middle(box[0], box[2]);
      oy = even_middle(box[1], box[3]);
      /* the vertices (the box less its 2-pixel snap margin) from the middle */
      /* (a point is at most 255 pixels across: it always fits) */
      guard = kind != RAST_PRIM_POINT &&
              !(box[0] + 2.0f >= (float)(ox - R) && box[2] - 2.0f < (float)(ox + R) &&
                box[1] + 2.0f >= (float)(oy - R) && box[3] - 2.0f < (float)(oy + R));
      int64_t fx0 = (int64_t)floorf(box[0]), fy0 = (int64_t)floorf(box[1]);
      int64_t fx1 = (int64_t)ceilf(box[2]), fy1 = (int64_t)ceilf(box[3]);
      if (fx0 > bx0) bx0 = fx0;
      if (fy0 > by0) by0 = fy0;
      if (fx1 < bx1) bx1 = fx1;
      if (fy1 < by1) by1 = fy1;
   }
   struct guard g;
   if (guard) {
      if (rc->vl.vertex_size > TILE_MAX_SLOTS || !guard_count(rc, kind, v0, v1, v2))
         return;
      const bool first_pv = rc->rs.flatshade_first;
      guard_modes(rc, &g, first_pv ? v0 : kind == RAST_PRIM_LINE ? v1 : v2);
   }

   const bool counting = rc->counting;
   bool first = true;
   uint64_t passes = 0;
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
         if (guard) {
            /* from the tile's centre, the band around it */
            const int64_t band = (T / 2 + R) / 2;
            ox = tx * T + T / 2;
            oy = ty * T + T / 2;
            g.lo[0] = (double)(ox - band);
            g.hi[0] = (double)(ox + band);
            g.lo[1] = (double)(oy - band);
            g.hi[1] = (double)(oy + band);
         }
         rc->clip = (struct rast_scissor){ (int)(c.minx - ox), (int)(c.miny - oy),
                                           (int)(c.maxx - ox), (int)(c.maxy - oy) };
         rc->org_x = ox;
         rc->org_y = oy;
         passes++;
         if (guard) {
            guard_draw(rc, &g, kind, v0, v1, v2);
            continue;
         }
         if (!first)
            rast_count_stretch(rc, false);
         first = false;
         draw_pass(rc, kind, v0, v1, v2);
      }
   }
   if (first && !guard) {
      /* in no tile: set up and counted as untiled, and nothing drawn */
      rc->clip = (struct rast_scissor){ 0, 0, 0, 0 };
      rc->org_x = ox;
      rc->org_y = oy;
      draw_pass(rc, kind, v0, v1, v2);
   }
   /* counted in the primitive's own stretch, once */
   rast_count_stretch(rc, counting);
   rc->stats.tile_passes += passes;
   rc->stats.tile_guard += guard;
   rc->clip = all;
   rc->org_x = rc->org_y = 0;
}
