/*
 * One-pixel lines by GL's diamond-exit rule, as llvmpipe builds them
 * (lp_setup_line.c, the non-rectangular path): the line becomes a
 * parallelogram one pixel across the minor axis, its ends shifted by half a
 * pixel where the diamond rule wants the end pixel drawn or not, and the
 * parallelogram goes through the same edge and span processors as a
 * triangle (as a convex polygon of up to three sections).  Attributes vary
 * along the major axis only (llvmpipe's "preferred wide-lines formula").
 */
#include <math.h>
#include <stddef.h>
#include "rast/setup/front.h"

static inline bool sign_of(float x)
{
   return x >= 0;
}

static inline float fracf_pos(float f)
{
   return f - floorf(f);
}

/* llvmpipe's subpixel_snap: util_iround on the 1/256 grid, then into the XY
 * register (exact: 12 fraction bits hold the grid).  The diamond-exit
 * offsets put corners off the grid (y_offset = x_offset * dy/dx); snapping
 * them at the register's 1/4096 instead tilts the long edges differently,
 * and pixel centres on them (lines through a pixel boundary) fall on the
 * other side: 48 of 2,700 short centre-to-centre lines differed from
 * llvmpipe by one pixel that way, and 7 of 1,500 long ones where the offset
 * is an exact half of 1/256 (round to even instead of llvmpipe's away from
 * zero). */
#define LINE_SNAP_ONE 256

static int64_t line_snap(const struct rast_profile *prof, float v, int64_t org,
                         struct fx_sat *sxy)
{
   const int64_t k = rast_lp_iround(v * (float)LINE_SNAP_ONE) - org * LINE_SNAP_ONE;
   return fx_from_double(prof->xy, (double)k / LINE_SNAP_ONE, sxy);
}

bool rast_line_counted(struct rast_context *rc, float dx, float dy)
{
   if (dx * dx + dy * dy == 0) {
      rc->stats.culled++;
      return false;
   }
   rc->stats.lines++;
   return true;
}

void rast_line(struct rast_context *rc, const float (*v1)[4], const float (*v2)[4])
{
   if (!rast_position_finite(rc, v1) || !rast_position_finite(rc, v2)) {
      rc->stats.nonfinite++;
      return;
   }
   if (!rast_queue(rc, RAST_PRIM_LINE, v1, v2, NULL))
      rast_draw_line(rc, v1, v2);
}

void rast_draw_line(struct rast_context *rc, const float (*v1)[4], const float (*v2)[4])
{
   rast_validate(rc);
   if (rc->observe_prim)
      rc->observe_prim(rc);
   rast_primitive_viewport(rc, rc->rs.flatshade_first ? v1 : v2);
   rast_primitive_layer(rc, rc->rs.flatshade_first ? v1 : v2);
   if (rc->tiled)
      rast_tiles_draw(rc, RAST_PRIM_LINE, v1, v2, NULL);
   else
      rast_line_pass(rc, v1, v2);
}

void rast_line_pass(struct rast_context *rc, const float (*v1)[4], const float (*v2)[4])
{
   if (rast_multisampled(rc)) {
      rast_msaa_pass(rc, RAST_PRIM_LINE, v1, v2, NULL);
      return;
   }
   struct rast_front *fr = rast_front_begin(rc, false);
   const struct rast_profile *prof = rc->profile;
   unsigned ps = rc->vl.pos_slot;
   const float (*o1)[4] = v1, (*o2)[4] = v2;   /* original order, for attributes */

   float width = rc->rs.line_width > 1.0f ? rc->rs.line_width : 1.0f;
   float dx = v1[ps][0] - v2[ps][0];
   float dy = v1[ps][1] - v2[ps][1];
   if (!rast_line_counted(rc, dx, dy))
      return;

   float x_offset = 0, y_offset = 0, x_offset_end = 0, y_offset_end = 0;
   float x1diff = v1[ps][0] - floorf(v1[ps][0]) - 0.5f;
   float y1diff = v1[ps][1] - floorf(v1[ps][1]) - 0.5f;
   float x2diff = v2[ps][0] - floorf(v2[ps][0]) - 0.5f;
   float y2diff = v2[ps][1] - floorf(v2[ps][1]) - 0.5f;
   bool draw_start, draw_end;
   bool xmajor = fabsf(dx) >= fabsf(dy);
   /* Half the width across the minor axis, in the XY format. */
   int64_t half = rast_lp_iround(width) * fr->S / 2;

   if (xmajor) {
      float dydx = dy / dx;
      if (y2diff == -0.5f && dy < 0)
         y2diff = 0.5f;
      if (fabsf(x1diff) + fabsf(y1diff) < 0.5f)
         draw_start = true;
      else if (sign_of(x1diff) == sign_of(-dx))
         draw_start = false;
      else if (sign_of(-y1diff) != sign_of(dy))
         draw_start = true;
      else {
         float yi = fracf_pos(v1[ps][1]) + x1diff * dydx;
         draw_start = yi < 1.0f && yi > 0.0f;
      }
      if (fabsf(x2diff) + fabsf(y2diff) < 0.5f)
         draw_end = false;
      else if (sign_of(x2diff) != sign_of(-dx))
         draw_end = false;
      else if (sign_of(-y2diff) == sign_of(dy))
         draw_end = true;
      else {
         float yi = fracf_pos(v2[ps][1]) + x2diff * dydx;
         draw_end = yi < 1.0f && yi > 0.0f;
      }
      bool will_draw_start = sign_of(-x1diff) != sign_of(dx);
      bool will_draw_end = (sign_of(x2diff) == sign_of(-dx)) || x2diff == 0;
      if (dx < 0) {
         const float (*t)[4] = v1; v1 = v2; v2 = t;
         dx = -dx; dy = -dy;
         if (will_draw_start != draw_start) {
            x_offset_end = -x1diff - 0.5f;
            y_offset_end = x_offset_end * dydx;
         }
         if (will_draw_end != draw_end) {
            x_offset = -x2diff - 0.5f;
            y_offset = x_offset * dydx;
         }
      } else {
         if (will_draw_start != draw_start) {
            x_offset = -x1diff + 0.5f;
            y_offset = x_offset * dydx;
         }
         if (will_draw_end != draw_end) {
            x_offset_end = -x2diff + 0.5f;
            y_offset_end = x_offset_end * dydx;
         }
      }
   } else {
      float dxdy = dx / dy;
      if (x2diff == -0.5f && dx < 0)
         x2diff = 0.5f;
      if (fabsf(x1diff) + fabsf(y1diff) < 0.5f)
         draw_start = true;
      else if (sign_of(-y1diff) == sign_of(dy))
         draw_start = false;
      else if (sign_of(x1diff) != sign_of(-dx))
         draw_start = true;
      else {
         float xi = fracf_pos(v1[ps][0]) + y1diff * dxdy;
         draw_start = xi < 1.0f && xi > 0.0f;
      }
      if (fabsf(x2diff) + fabsf(y2diff) < 0.5f)
         draw_end = false;
      else if (sign_of(-y2diff) != sign_of(dy))
         draw_end = false;
      else if (sign_of(x2diff) == sign_of(-dx))
         draw_end = true;
      else {
         float xi = fracf_pos(v2[ps][0]) + y2diff * dxdy;
         draw_end = xi < 1.0f && xi >= 0.0f;
      }
      bool will_draw_start = sign_of(y1diff) == sign_of(dy);
      bool will_draw_end = (sign_of(-y2diff) == sign_of(dy)) || y2diff == 0;
      if (dy > 0) {
         const float (*t)[4] = v1; v1 = v2; v2 = t;
         dx = -dx; dy = -dy;
         if (will_draw_start != draw_start) {
            y_offset_end = -y1diff + 0.5f;
            x_offset_end = y_offset_end * dxdy;
         }
         if (will_draw_end != draw_end) {
            y_offset = -y2diff + 0.5f;
            x_offset = y_offset * dxdy;
         }
      } else {
         if (will_draw_start != draw_start) {
            y_offset = -y1diff - 0.5f;
            x_offset = y_offset * dxdy;
         }
         if (will_draw_end != draw_end) {
            y_offset_end = -y2diff - 0.5f;
            x_offset_end = y_offset_end * dxdy;
         }
      }
   }

   /* Snap like llvmpipe's subpixel_snap(v + offset - pixel_offset) and add
    * the pixel-centre offset back: scan.c evaluates at centres (i + h, j + h). */
   struct fx_sat *sxy = &rc->stats.sat[RAST_REG_XY];
   float po = rc->rs.half_pixel_center ? 0.5f : 0.0f;
   const int64_t gx = rc->org_x, gy = rc->org_y;
   int64_t sx1 = fx_add(prof->xy, line_snap(prof, v1[ps][0] + x_offset - po, gx, sxy), fr->H, sxy);
   int64_t sy1 = fx_add(prof->xy, line_snap(prof, v1[ps][1] + y_offset - po, gy, sxy), fr->H, sxy);
   int64_t sx2 = fx_add(prof->xy, line_snap(prof, v2[ps][0] + x_offset_end - po, gx, sxy), fr->H,
                        sxy);
   int64_t sy2 = fx_add(prof->xy, line_snap(prof, v2[ps][1] + y_offset_end - po, gy, sxy), fr->H,
                        sxy);
   int64_t ox = xmajor ? 0 : half, oy = xmajor ? half : 0;
   fr->nverts = 4;
   fr->X[0] = sx1 - ox; fr->Y[0] = sy1 - oy;
   fr->X[1] = sx2 - ox; fr->Y[1] = sy2 - oy;
   fr->X[2] = sx2 + ox; fr->Y[2] = sy2 + oy;
   fr->X[3] = sx1 + ox; fr->Y[3] = sy1 + oy;
   for (unsigned k = 0; k < 4; k++) {
      fr->X[k] = fx_sat(prof->xy, fr->X[k], sxy);
      fr->Y[k] = fx_sat(prof->xy, fr->Y[k], sxy);
   }

   /* Attribute planes through the original end points, varying along the
    * major axis only; the corners take the plane's values. */
   const float (*const ends[2])[4] = { o1, o2 };
   rast_setup_rebase(rc, fr, ends, 2);
   rast_setup_attribs(rc, fr, 0, o1);
   rast_setup_attribs(rc, fr, 1, o2);
   /* the corners' offsets from the first end point, in pixels (exact) */
   double ax = (double)o1[ps][0] - (double)gx, ay = (double)o1[ps][1] - (double)gy;
   double major = xmajor ? (double)o1[ps][0] - o2[ps][0] : (double)o1[ps][1] - o2[ps][1];
   double cx[4], cy[4];
   for (unsigned k = 0; k < 4; k++) {
      cx[k] = fx_to_double(prof->xy, fr->X[k]) - ax;
      cy[k] = fx_to_double(prof->xy, fr->Y[k]) - ay;
   }
   for (unsigned k = 0; k < fr->nfix_scan; k++) {
      double a1 = (double)fr->vfix[0][k];
      double g = (a1 - (double)fr->vfix[1][k]) / major;
      fr->fix_dx[k] = fr_fix_sat(fr, k, (fx_i128)llround(xmajor ? g : 0));
      fr->fix_dy[k] = fr_fix_sat(fr, k, (fx_i128)llround(xmajor ? 0 : g));
      for (unsigned c = 0; c < 4; c++)
         fr->vfix[c][k] = fr_fix_sat(fr, k, (fx_i128)llround(a1 + g * (xmajor ? cx[c] : cy[c])));
   }
   for (unsigned k = 0; k < fr->nflt; k++) {
      double a1 = fr->vflt[0][k];
      double g = (a1 - fr->vflt[1][k]) / major;
      fr->flt_dx[k] = (float)(xmajor ? g : 0);
      fr->flt_dy[k] = (float)(xmajor ? 0 : g);
      for (unsigned c = 0; c < 4; c++)
         fr->vflt[c][k] = (float)(a1 + g * (xmajor ? cx[c] : cy[c]));
   }

   /* The perspective division's vector form on corners 0, 1 (along the
    * line) and 3 (across it, where nothing varies: Δ2 = 0). */
   rast_interp_modes_setup(rc, fr, 0, 1, 3);
   if (fr->npersp)
      rast_interp_perspective_setup(rc, fr, 0, 1, 3);
   fr_set_facing(fr, !rc->vl.has_face || o1[rc->vl.face_slot][0] != 0.0f);
   rast_setup_constants(fr, rc->rs.flatshade_first ? o1 : o2);
   rast_scan_convex(rc, fr);
}
