/*
 * Points, as llvmpipe builds them (lp_setup_point.c), scanned through the
 * same edge and span processors as a triangle (a convex polygon of one
 * section).
 *
 * With point_quad_rasterization (GL ES, point sprites): the square of side
 * w = max(1, size snapped to 1/256 px) around the centre snapped to 1/256
 * px, with the triangle fill rule (left and top edges in; bottom instead of
 * top with the bottom-edge rule).  Without it, GL 2.1's rule: the size
 * rounded to whole pixels, and the w x w pixels around the centre's pixel
 * (odd w) or the pixel corner nearest the centre (even w).
 *
 * Every input is constant over the point (the vertex's value, no
 * perspective division: 1/w does not vary), except the point_coord_mask
 * varyings: the sprite coordinate s = 1/2 + (x - x_c)/w,
 * t = 1/2 ± (y - y_c)/w at the pixel centre (x, y), with the unsnapped
 * centre (x_c, y_c) and the snapped width, as llvmpipe's texcoord_coef;
 * its plane walks as a LINEAR input.
 */
#include <stddef.h>
#include "rast/setup/front.h"

#define POINT_SNAP_ONE 256              /* llvmpipe's FIXED_ONE: the 1/256 grid */

/* floor(v / 256) for the grid's integers (llvmpipe's >> FIXED_ORDER). */
static inline int64_t grid_floor(int64_t v)
{
   return v >= 0 ? v / POINT_SNAP_ONE : -((-v + POINT_SNAP_ONE - 1) / POINT_SNAP_ONE);
}

static inline int64_t grid_snap(float v)
{
   return rast_lp_iround(v * (float)POINT_SNAP_ONE);
}

/* A grid value (units of 1/256 px, pixel centres at multiples of 256) into
 * the XY register, where pixel centres are at i + h. */
static inline int64_t grid_to_xy(struct rast_context *rc, const struct rast_front *fr, int64_t g,
                                 int64_t org)
{
   struct fx_sat *sxy = &rc->stats.sat[RAST_REG_XY];
   int64_t r = fx_from_double(rc->profile->xy, (double)(g - org * POINT_SNAP_ONE) / POINT_SNAP_ONE,
                              sxy);
   return fx_add(rc->profile->xy, r, fr->H, sxy);
}

void rast_point(struct rast_context *rc, const float (*v)[4])
{
   if (!rast_position_finite(rc, v)) {
      rc->stats.nonfinite++;
      return;
   }
   if (!rast_queue(rc, RAST_PRIM_POINT, v, NULL, NULL))
      rast_draw_point(rc, v);
}

void rast_draw_point(struct rast_context *rc, const float (*v)[4])
{
   rast_validate(rc);
   if (rc->observe_prim)
      rc->observe_prim(rc);
   rast_primitive_viewport(rc, v);
   rast_primitive_layer(rc, v);
   if (rc->tiled)
      rast_tiles_draw(rc, RAST_PRIM_POINT, v, NULL, NULL);
   else
      rast_point_pass(rc, v);
}

/* point_tri_clip: the pass's clip narrowed to the viewport; false when the
 * point's square (size, its snap and the 2-pixel margin of
 * rast_prim_extent) cannot meet it, which also keeps a centre far outside
 * the target (draw passes any finite one) out of the XY registers. */
static bool point_viewport_clip(struct rast_context *rc, const float *pos, float size)
{
   const struct rast_scissor vp = rc->viewport;
   struct rast_scissor *c = &rc->clip;
   const int64_t minx = (int64_t)vp.minx - rc->org_x, maxx = (int64_t)vp.maxx - rc->org_x;
   const int64_t miny = (int64_t)vp.miny - rc->org_y, maxy = (int64_t)vp.maxy - rc->org_y;
   if (minx > c->minx) c->minx = (int)minx;
   if (miny > c->miny) c->miny = (int)miny;
   if (maxx < c->maxx) c->maxx = (int)maxx;
   if (maxy < c->maxy) c->maxy = (int)maxy;
   const double r = size * 0.5 + 2.0;
   return c->minx < c->maxx && c->miny < c->maxy &&
          pos[0] + r > (double)(c->minx + rc->org_x) && pos[0] - r < (double)(c->maxx + rc->org_x) &&
          pos[1] + r > (double)(c->miny + rc->org_y) && pos[1] - r < (double)(c->maxy + rc->org_y);
}

void rast_point_pass(struct rast_context *rc, const float (*v)[4])
{
   if (rast_multisampled(rc)) {
      rast_msaa_pass(rc, RAST_PRIM_POINT, v, NULL, NULL);
      return;
   }
   const struct rast_raster_state *rs = &rc->rs;
   const struct rast_profile *prof = rc->profile;
   const float *pos = v[rc->vl.pos_slot];

   float size = rs->point_size_per_vertex && rc->vl.has_psize ? v[rc->vl.psize_slot][0]
                                                              : rs->point_size;
   /* GL's range [1, max]; a NaN size (the shader's gl_PointSize) is the
    * smallest, as llvmpipe draws it, and +inf the largest */
   if (!(size >= 1.0f))
      size = 1.0f;
   else if (size > RAST_MAX_POINT_SIZE)
      size = RAST_MAX_POINT_SIZE;
   const struct rast_scissor clip = rc->clip;
   if (rs->point_tri_clip && !point_viewport_clip(rc, pos, size)) {
      rc->clip = clip;
      return;
   }
   struct rast_front *fr = rast_front_begin(rc, true);
   rc->stats.points++;

   /* The square's edges on the 1/256 grid, centres at multiples of 256. */
   int64_t x0, x1, y0, y1, width;
   if (rs->point_quad_rasterization) {
      const float po = rs->half_pixel_center ? 0.5f : 0.0f;
      width = grid_snap(size);
      if (width < POINT_SNAP_ONE)
         width = POINT_SNAP_ONE;
      x0 = grid_snap(pos[0] - po) - width / 2;
      y0 = grid_snap(pos[1] - po) - width / 2;
      x1 = x0 + width;
      y1 = y0 + width;
   } else {
      /* Whole pixels: the edges half a pixel from the outer pixel centres,
       * so no centre lies on an edge and the fill rule does not matter. */
      const int64_t adj = rs->bottom_edge_rule ? 1 : 0;
      const int64_t gx = grid_snap(pos[0]), gy = grid_snap(pos[1]) - adj;
      width = (grid_snap(size) + POINT_SNAP_ONE / 2 - 1) & ~(int64_t)(POINT_SNAP_ONE - 1);
      if (width < POINT_SNAP_ONE)
         width = POINT_SNAP_ONE;
      const int64_t n = width / POINT_SNAP_ONE;
      int64_t bx, by;
      if (n & 1) {
         bx = grid_floor(gx) - (n - 1) / 2;
         by = grid_floor(gy) - (n - 1) / 2;
      } else {
         bx = grid_floor(gx + POINT_SNAP_ONE / 2) - n / 2;
         by = grid_floor(gy + POINT_SNAP_ONE / 2) - n / 2;
      }
      x0 = bx * POINT_SNAP_ONE - POINT_SNAP_ONE / 2;
      y0 = by * POINT_SNAP_ONE - POINT_SNAP_ONE / 2;
      x1 = x0 + n * POINT_SNAP_ONE;
      y1 = y0 + n * POINT_SNAP_ONE;
   }

   fr->nverts = 4;
   fr->X[0] = fr->X[3] = grid_to_xy(rc, fr, x0, rc->org_x);
   fr->X[1] = fr->X[2] = grid_to_xy(rc, fr, x1, rc->org_x);
   fr->Y[0] = fr->Y[1] = grid_to_xy(rc, fr, y0, rc->org_y);
   fr->Y[2] = fr->Y[3] = grid_to_xy(rc, fr, y1, rc->org_y);

   /* Z and 1/w constant; the sprite coordinate's plane. */
   rast_setup_attribs(rc, fr, 0, v);
   fr->fix_dx[0] = fr->fix_dy[0] = 0;
   fr->flt_dx[0] = fr->flt_dy[0] = 0;
   const float ds = (float)POINT_SNAP_ONE / (float)width;   /* llvmpipe's dadx */
   const float dt = rs->sprite_coord_lower_left ? -ds : ds;
   for (unsigned i = 0; i < fr->nlin; i++) {
      const unsigned k = 1 + i, chan = fr->lin[i].chan;
      fr->flt_dx[k] = chan == 0 ? ds : 0.0f;
      fr->flt_dy[k] = chan == 1 ? dt : 0.0f;
   }
   for (unsigned c = 0; c < 4; c++) {
      fr->vfix[c][0] = fr->vfix[0][0];
      fr->vflt[c][0] = fr->vflt[0][0];
      const double cx = fx_to_double(prof->xy, fr->X[c]) + (double)rc->org_x - pos[0];
      const double cy = fx_to_double(prof->xy, fr->Y[c]) + (double)rc->org_y - pos[1];
      for (unsigned i = 0; i < fr->nlin; i++) {
         const unsigned chan = fr->lin[i].chan;
         fr->vflt[c][1 + i] = chan == 0 ? (float)(0.5 + cx * ds) :
                              chan == 1 ? (float)(0.5 + cy * dt) :
                              chan == 2 ? 0.0f : 1.0f;
      }
   }

   rast_interp_modes_off(fr);
   fr_set_facing(fr, !rc->vl.has_face || v[rc->vl.face_slot][0] != 0.0f);
   rast_setup_constants(fr, v);
   rast_scan_convex(rc, fr);
   rc->clip = clip;
}
