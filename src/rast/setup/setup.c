/*
 * Triangle setup (seed 000, section 2): fixed-point vertices, the culling
 * determinant, the plane slopes, the sort by y, the types 0/1/2 and the split
 * into halves A and B.  Validation of the front end lives here too: it picks
 * which attribute registers exist and the span processor that walks them.
 */
#include <math.h>
#include <stdlib.h>
#include "rast/setup/front.h"
#include "rast/setup/tri_regs.h"

static void add_comp(struct fr_comp *list, unsigned *n, unsigned var, unsigned chan,
                     unsigned slot)
{
   list[*n].var = (uint8_t)var;
   list[*n].chan = (uint8_t)chan;
   list[*n].slot = (uint8_t)slot;
   list[*n].rebase = FR_REBASE_NONE;
   (*n)++;
}

static enum fr_rebase rebase_of(const struct rast_varying *vr, unsigned c)
{
   if (!(vr->rebase_mask >> c & 1u))
      return FR_REBASE_NONE;
   return vr->rebase_even >> c & 1u ? FR_REBASE_EVEN : FR_REBASE_INT;
}

static void set_fix_class(struct rast_context *rc, struct rast_front *fr, unsigned k,
                          struct fx_format f, enum rast_reg_class cls)
{
   fr->fix_fmt[k] = f;
   fr->fix_min[k] = fx_min(f);
   fr->fix_max[k] = fx_max(f);
   fr->fix_sat[k] = &rc->stats.sat[cls];
}

void rast_compute_clip(struct rast_context *rc)
{
   struct rast_scissor c = { 0, 0, (int)rc->fb.width, (int)rc->fb.height };
   if (rc->rs.scissor) {
      if (rc->scissor.minx > c.minx) c.minx = rc->scissor.minx;
      if (rc->scissor.miny > c.miny) c.miny = rc->scissor.miny;
      if (rc->scissor.maxx < c.maxx) c.maxx = rc->scissor.maxx;
      if (rc->scissor.maxy < c.maxy) c.maxy = rc->scissor.maxy;
   }
   if (c.maxx < c.minx) c.maxx = c.minx;
   if (c.maxy < c.miny) c.maxy = c.miny;
   rc->clip_all = c;
   rc->clip = c;
   rc->org_x = rc->org_y = 0;
   /* X_out/Y_out address one tile: a larger target is drawn tile by tile. */
   rc->tiled = rc->fb.width > rc->profile->tile_size || rc->fb.height > rc->profile->tile_size;
}

void rast_front_validate(struct rast_context *rc)
{
   if (!rc->front_priv) {
      rc->front_priv = calloc(1, sizeof(struct rast_front));
      if (!rc->front_priv)
         abort();
   }
   struct rast_front *fr = rast_front(rc);
   const struct rast_profile *prof = rc->profile;

   fr->S = fx_one(prof->xy);
   fr->H = rc->rs.half_pixel_center ? fr->S / 2 : 0;
   fr->Hx = fr->Hy = fr->H;
   fr->row_bias = rc->rs.bottom_edge_rule ? 1 : 0;
   fr->inv_S = 1.0f / (float)fr->S;
   fr->z_scale = 1.0 / (((double)(INT64_C(1) << prof->z_bits) - 1.0) *
                        (double)fx_one(prof->z));
   fr->color_scale = (float)(1.0 / (255.0 * (double)fx_one(prof->color)));
   rast_front_classify(rc, fr, fr->points);
   rast_compute_clip(rc);
}

void rast_front_classify(struct rast_context *rc, struct rast_front *fr, bool points)
{
   const struct rast_profile *prof = rc->profile;
   fr->points = points;
   fr->ncolor = fr->nlin = fr->npersp = fr->nconst = 0;
   for (unsigned i = 0; i < rc->vl.num_varyings && i < RAST_MAX_VARYINGS; i++) {
      const struct rast_varying *vr = &rc->vl.varying[i];
      for (unsigned c = 0; c < 4; c++) {
         if (!(vr->usage_mask & (1u << c)))
            continue;
         if (points) {
            /* llvmpipe's point setup: constant planes, the sprite
             * coordinate's plane for the coordinate-replaced inputs. */
            if ((rc->vl.point_coord_mask >> i & 1u) && vr->interp != RAST_INTERP_CONSTANT)
               add_comp(fr->lin, &fr->nlin, i, c, vr->slot);
            else
               add_comp(fr->cnst, &fr->nconst, i, c, vr->slot);
            continue;
         }
         switch (vr->interp) {
         case RAST_INTERP_LINEAR:
            add_comp(fr->lin, &fr->nlin, i, c, vr->slot);
            break;
         case RAST_INTERP_PERSPECTIVE:
            add_comp(fr->persp, &fr->npersp, i, c, vr->slot);
            fr->persp[fr->npersp - 1].rebase = (uint8_t)rebase_of(vr, c);
            break;
         case RAST_INTERP_COLOR:
            if (rc->rs.flatshade)
               add_comp(fr->cnst, &fr->nconst, i, c, vr->slot);
            else if (prof->color_perspective)
               add_comp(fr->persp, &fr->npersp, i, c, vr->slot);
            else
               add_comp(fr->color, &fr->ncolor, i, c, vr->slot);
            break;
         default:
            add_comp(fr->cnst, &fr->nconst, i, c, vr->slot);
            break;
         }
      }
   }
   fr->nfix = 1 + fr->ncolor;
   fr->nflt = 1 + fr->nlin + fr->npersp;
   fr->nwalk = 1 + fr->nlin;
   set_fix_class(rc, fr, 0, prof->z, RAST_REG_Z);
   for (unsigned k = 1; k < fr->nfix; k++)
      set_fix_class(rc, fr, k, prof->color, RAST_REG_COLOR);

   /* Z feeds the depth test, gl_FragCoord.z and the RTL vectors only; the
    * per-pixel modes (FIXPIPE_INTERP) keep it, and so does a colour
    * register, which walks beside it. */
   const bool z_read = rc->dsa.depth_enabled || rc->fs.reads_fragcoord || rc->vec ||
                       fr->ncolor || rc->interp != RAST_INTERP_SCANLINE ||
                       (rc->opts & RAST_OPT_NOSKIP);
   fr->nfix_scan = z_read ? fr->nfix : 0;
   fr->nfix_walk = fr->nfix_scan;
   fr->pair = rast_interp_choose(rc, fr);
   rast_interp_perspective_choose(rc, fr);
}

void rast_front_destroy(struct rast_context *rc)
{
   free(rc->front_priv);
   rc->front_priv = NULL;
}

void rast_setup_attribs(struct rast_context *rc, struct rast_front *fr,
                        unsigned k, const float (*v)[4])
{
   const struct rast_profile *prof = rc->profile;
   const float *pos = v[rc->vl.pos_slot];
   double zfull = (double)(INT64_C(1) << prof->z_bits) - 1.0;

   fr->vfix[k][0] = fx_from_double(prof->z, (double)pos[2] * zfull,
                                   &rc->stats.sat[RAST_REG_Z]);
   for (unsigned i = 0; i < fr->ncolor; i++) {
      const struct fr_comp *c = &fr->color[i];
      fr->vfix[k][1 + i] = fx_from_double(prof->color, (double)v[c->slot][c->chan] * 255.0,
                                          &rc->stats.sat[RAST_REG_COLOR]);
   }
   float oow = pos[3];
   fr->vflt[k][0] = oow;
   for (unsigned i = 0; i < fr->nlin; i++)
      fr->vflt[k][1 + i] = v[fr->lin[i].slot][fr->lin[i].chan];
   for (unsigned i = 0; i < fr->npersp; i++) {
      const float a = v[fr->persp[i].slot][fr->persp[i].chan];
      fr->vflt[k][1 + fr->nlin + i] =
         fr->persp[i].rebase ? (float)((double)a - fr->rebase[i]) * oow : a * oow;
   }
}

/* The rebase of a REPEAT (or MIRRORED_REPEAT) coordinate: an integer R
 * (an even one for the mirror, whose period is 2) subtracted from every
 * vertex value, so that a coordinate offset by whole periods reaches the
 * planes as the same bits as without the offset.  Which integer matters
 * for precision: the planes carry (a - R)/w, whose registers lose bits in
 * proportion to their size, so R is the candidate that leaves the
 * smallest largest |a - R|/w over the vertices.  The candidates are the
 * integers nearest each vertex value and nearest the midpoint of the
 * smallest and largest: the nearest vertex (largest 1/w) under strong
 * perspective, where the texture is magnified and every bit shows; the
 * midpoint when the w are equal.  Every candidate and every |a - R| moves
 * with an offset by exactly the offset (they are exact in double), so the
 * choice does too.  The subtraction is exact when the vertex values lie
 * within a factor 2 of R (Sterbenz), which is the case it exists for;
 * elsewhere the difference rounds once, to the float nearest it. */
static double rebase_round(double a, bool even)
{
   return even ? 2.0 * floor(a / 2.0 + 0.5) : floor(a + 0.5);
}

static double rebase_cost(const double *a, const double *oow, unsigned n, double r)
{
   double worst = 0.0;
   for (unsigned k = 0; k < n; k++)
      worst = fmax(worst, fabs(a[k] - r) * oow[k]);
   return worst;
}

static double rebase_choose(const double *a, const double *oow, unsigned n, bool even)
{
   double lo = a[0], hi = a[0];
   for (unsigned k = 1; k < n; k++) {
      lo = fmin(lo, a[k]);
      hi = fmax(hi, a[k]);
   }
   double best = rebase_round(lo / 2.0 + hi / 2.0, even);
   double best_cost = rebase_cost(a, oow, n, best);
   for (unsigned k = 0; k < n; k++) {
      const double r = rebase_round(a[k], even);
      const double cost = rebase_cost(a, oow, n, r);
      if (cost < best_cost) {
         best = r;
         best_cost = cost;
      }
   }
   return best;
}

void rast_setup_rebase(struct rast_context *rc, struct rast_front *fr,
                       const float (*const *v)[4], unsigned n)
{
   double oow[3] = { 0.0, 0.0, 0.0 };
   bool finite_w = true;
   for (unsigned k = 0; k < n; k++) {
      oow[k] = fabs((double)v[k][rc->vl.pos_slot][3]);
      finite_w &= isfinite(oow[k]);
   }
   for (unsigned i = 0; i < fr->npersp; i++) {
      const struct fr_comp *c = &fr->persp[i];
      fr->rebase[i] = 0.0;
      if (!c->rebase || !finite_w)
         continue;
      double a[3] = { 0.0, 0.0, 0.0 };
      bool finite = true;
      for (unsigned k = 0; k < n; k++) {
         a[k] = (double)v[k][c->slot][c->chan];
         finite &= isfinite(a[k]);
      }
      if (!finite)
         continue;                          /* nothing to keep: left as it is */
      const double r = rebase_choose(a, oow, n, c->rebase == FR_REBASE_EVEN);
      if (r != 0.0) {
         fr->rebase[i] = r;
         rc->stats.tex_rebased++;
      }
   }
}

void rast_setup_constants(struct rast_front *fr, const float (*pv)[4])
{
   for (unsigned i = 0; i < fr->nconst; i++) {
      const struct fr_comp *c = &fr->cnst[i];
      float val = pv[c->slot][c->chan];
      for (unsigned g = 0; g < FR_AHEAD_MAX; g++)
         for (unsigned p = 0; p < RAST_QUAD_SIZE; p++)
            fr->quad[g].in[c->var][c->chan][p] = val;
   }
}

/* The plane of every attribute through the three fixed-point vertices:
 * ∂/∂x and ∂/∂y per pixel, once per triangle; the fix registers only for
 * the walk (a per-pixel FIXPIPE_INTERP mode has no use for them).  Fixed
 * registers get the exact quotient rounded once; floats are computed in
 * double. */
static void tri_gradients(struct rast_front *fr)
{
   int64_t ex = fr->X[1] - fr->X[0], ey = fr->Y[1] - fr->Y[0];
   int64_t gx = fr->X[2] - fr->X[0], gy = fr->Y[2] - fr->Y[0];
   int64_t D = ex * gy - ey * gx;
   fx_i128 DS = (fx_i128)D;

   for (unsigned k = 0; k < fr->nfix_walk; k++) {
      int64_t d1 = fr->vfix[1][k] - fr->vfix[0][k];
      int64_t d2 = fr->vfix[2][k] - fr->vfix[0][k];
      fx_i128 nx = ((fx_i128)d1 * gy - (fx_i128)d2 * ey) * fr->S;
      fx_i128 ny = ((fx_i128)d2 * ex - (fx_i128)d1 * gx) * fr->S;
      fr->fix_dx[k] = fr_fix_sat(fr, k, fx_div_round_i128(nx, DS));
      fr->fix_dy[k] = fr_fix_sat(fr, k, fx_div_round_i128(ny, DS));
   }
   double inv = (double)fr->S / (double)D;
   for (unsigned k = 0; k < fr->nwalk; k++) {
      double d1 = (double)fr->vflt[1][k] - fr->vflt[0][k];
      double d2 = (double)fr->vflt[2][k] - fr->vflt[0][k];
      fr->flt_dx[k] = (float)((d1 * (double)gy - d2 * (double)ey) * inv);
      fr->flt_dy[k] = (float)((d2 * (double)ex - d1 * (double)gx) * inv);
   }
}

static void set_edge(struct rast_front *fr, struct fr_edge *e, unsigned a, unsigned b, bool left)
{
   e->a = (uint8_t)a;
   e->b = (uint8_t)b;
   e->xa = fr->X[a]; e->ya = fr->Y[a];
   e->xb = fr->X[b]; e->yb = fr->Y[b];
   e->left = left;
}

/* Sort by y, classify and split (seed 000, Fig. 4).  The long edge top->bot
 * is one register set used by both halves: at the split it still holds the
 * long edge's x for the first scan line of B (the seed's X_next).  Returns
 * the type: 0 flat top or bottom, 1 middle vertex left, 2 right. */
static unsigned tri_sections(struct rast_front *fr)
{
   unsigned top = 0, mid = 1, bot = 2, t;
   if (fr->Y[mid] < fr->Y[top]) { t = top; top = mid; mid = t; }
   if (fr->Y[bot] < fr->Y[mid]) { t = mid; mid = bot; bot = t; }
   if (fr->Y[mid] < fr->Y[top]) { t = top; top = mid; mid = t; }

   /* > 0: the middle vertex lies left of the long edge (y grows down). */
   fx_i128 cross = (fx_i128)(fr->X[bot] - fr->X[top]) * (fr->Y[mid] - fr->Y[top]) -
                   (fx_i128)(fr->X[mid] - fr->X[top]) * (fr->Y[bot] - fr->Y[top]);
   bool mid_left = cross > 0;
   /* Type 0 (flat top or flat bottom) is the case where one half is empty;
    * types 1 and 2 (middle vertex left/right) differ only in mid_left. */

   struct fr_edge *lng = &fr->edge[0], *ea = &fr->edge[1], *eb = &fr->edge[2];
   set_edge(fr, lng, top, bot, !mid_left);
   set_edge(fr, ea, top, mid, mid_left);
   set_edge(fr, eb, mid, bot, mid_left);

   struct fr_section *A = &fr->sec[0], *B = &fr->sec[1];
   A->ytop = fr->Y[top]; A->ybot = fr->Y[mid];
   B->ytop = fr->Y[mid]; B->ybot = fr->Y[bot];
   A->l = mid_left ? ea : lng;  A->r = mid_left ? lng : ea;
   B->l = mid_left ? eb : lng;  B->r = mid_left ? lng : eb;
   fr->nsec = 2;
   if (fr->Y[top] == fr->Y[mid] || fr->Y[mid] == fr->Y[bot])
      return 0;
   return mid_left ? 1 : 2;
}

void rast_triangle(struct rast_context *rc, const float (*v0)[4],
                   const float (*v1)[4], const float (*v2)[4])
{
   if (!rast_position_finite(rc, v0) || !rast_position_finite(rc, v1) ||
       !rast_position_finite(rc, v2)) {
      rc->stats.nonfinite++;
      return;
   }
   if (!rast_queue(rc, RAST_PRIM_TRIANGLE, v0, v1, v2))
      rast_draw_triangle(rc, v0, v1, v2);
}

void rast_draw_triangle(struct rast_context *rc, const float (*v0)[4],
                        const float (*v1)[4], const float (*v2)[4])
{
   rast_validate(rc);
   if (rc->observe_prim)
      rc->observe_prim(rc);
   rast_primitive_viewport(rc, rc->rs.flatshade_first ? v0 : v2);
   rast_primitive_layer(rc, rc->rs.flatshade_first ? v0 : v2);
   if (rc->tiled)
      rast_tiles_draw(rc, RAST_PRIM_TRIANGLE, v0, v1, v2);
   else
      rast_triangle_pass(rc, v0, v1, v2);
}

/* A vertex coordinate into the XY register of the pass at origin `org`.
 * The snap to the register's grid rounds the position in the target (ties
 * away from zero, as fx_from_double) before the origin is taken off, so a
 * vertex lands on the same grid point whatever the pass. */
static int64_t vertex_xy(struct fx_format xy, double v, int64_t org, struct fx_sat *s)
{
   if (!(fabs(v) < 0x1p30))            /* NaN, or far off any target */
      return fx_from_double(xy, v - (double)org, s);
   return fx_sat(xy, rast_snap_xy(xy, v) - org * fx_one(xy), s);
}

bool rast_triangle_counted(struct rast_context *rc, int64_t det, bool *front)
{
   /* zero is a triangle seen edge-on */
   const unsigned facing = (unsigned)(det < 0) ^ (unsigned)rc->rs.front_ccw;   /* 0 = front */
   const unsigned face = facing ? RAST_CULL_BACK : RAST_CULL_FRONT;
   if (det == 0 || (face & (unsigned)rc->rs.cull)) {
      rc->stats.culled++;
      return false;
   }
   rc->stats.triangles++;
   *front = facing == 0;
   return true;
}

void rast_triangle_pass(struct rast_context *rc, const float (*v0)[4],
                        const float (*v1)[4], const float (*v2)[4])
{
   if (rast_multisampled(rc)) {
      rast_msaa_pass(rc, RAST_PRIM_TRIANGLE, v0, v1, v2);
      return;
   }
   struct rast_front *fr = rast_front_begin(rc, false);
   const struct rast_profile *prof = rc->profile;
   const float (*v[3])[4] = { v0, v1, v2 };
   unsigned ps = rc->vl.pos_slot;
   struct fx_sat *sxy = &rc->stats.sat[RAST_REG_XY];

   fr->nverts = 3;
   for (unsigned k = 0; k < 3; k++) {
      fr->X[k] = vertex_xy(prof->xy, v[k][ps][0], rc->org_x, sxy);
      fr->Y[k] = vertex_xy(prof->xy, v[k][ps][1], rc->org_y, sxy);
   }
   bool front;
   if (!rast_triangle_counted(rc, rast_det(fr->X, fr->Y), &front))
      return;
   /* A polygon drawn as lines or points, whose fragment shader reads its
    * face, gives its face in a slot of every vertex (as rast_line and
    * rast_point take it): smooth lines reach set-up as triangles of any
    * winding, and face the polygon's way, as its filled triangles do. */
   if (rc->vl.has_face)
      front = v0[rc->vl.face_slot][0] != 0.0f;
   fr_set_facing(fr, front);

   rast_setup_rebase(rc, fr, v, 3);
   for (unsigned k = 0; k < 3; k++)
      rast_setup_attribs(rc, fr, k, v[k]);
   rast_interp_modes_setup(rc, fr, 0, 1, 2);
   tri_gradients(fr);
   if (fr->npersp)
      rast_interp_perspective_setup(rc, fr, 0, 1, 2);
   rast_setup_constants(fr, rc->rs.flatshade_first ? v0 : v2);
   if (rc->observe_triangle)
      rc->observe_triangle(rc, fr, front);
   rc->stats.tri_type[tri_sections(fr)]++;
   rc->scanning_triangle = true;
   rast_scan_sections(rc, fr);
   rc->scanning_triangle = false;
}

void rast_setup_from_registers(struct rast_context *rc, const struct rast_tri_regs *t)
{
   struct rast_front *fr = rast_front_begin(rc, false);
   /* the recorded pass: its origin and clip (tiles), after validation */
   rc->org_x = t->org_x;
   rc->org_y = t->org_y;
   rc->clip = t->clip;
   fr->nverts = 3;
   for (unsigned k = 0; k < 3; k++) {
      fr->X[k] = t->X[k];
      fr->Y[k] = t->Y[k];
   }
   bool front;
   if (!rast_triangle_counted(rc, rast_det(fr->X, fr->Y), &front))
      return;
   fr_set_facing(fr, front);
   /* the layout (replay_state) has no LINEAR component: vflt[] is 1/w, then
    * the PERSPECTIVE components' A/w */
   for (unsigned k = 0; k < 3; k++) {
      fr->vfix[k][0] = t->Z[k];
      for (unsigned i = 0; i < fr->ncolor; i++)
         fr->vfix[k][1 + i] = t->color[i][k];
      fr->vflt[k][0] = t->oow[k];
      for (unsigned j = 0; j < fr->npersp; j++)
         fr->vflt[k][1 + j] = t->aw[j][k];
   }
   rc->scanning_triangle = true;
   rast_interp_modes_setup(rc, fr, 0, 1, 2);
   tri_gradients(fr);
   if (fr->npersp)
      rast_interp_perspective_setup(rc, fr, 0, 1, 2);
   rc->stats.tri_type[tri_sections(fr)]++;
   rast_scan_sections(rc, fr);
   rc->scanning_triangle = false;
}
