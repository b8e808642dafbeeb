/*
 * Points (rast_point): coverage against an exact reference of llvmpipe's
 * point (lp_setup_point.c: the square on the 1/256 grid and its four
 * planes, or GL 2.1's whole-pixel rectangle), sizes 1..8 and fractional
 * ones at random positions, both edge rules, both pixel-centre conventions,
 * both profiles, clipped at the target's border; then the inputs: sprite
 * coordinates (both origins), constant varyings, Z, the size from the
 * vertex or the state, and triangles after points still interpolating.
 */
#include <math.h>
#include <string.h>
#include "tutil.h"

#define W 96
#define H 80

static struct tctx t;

/* Per quad: the worst sprite-coordinate error, constant checks. */
static double pc_x, pc_y, pc_w;      /* unsnapped centre, snapped width (px) */
static bool pc_lower_left;
static double worst_s, worst_t;
static unsigned bad_const, bad_face, bad_zw;
static float want_const[4], want_z, want_w;

static void hook(struct tctx *tc, const struct rast_quad *q)
{
   const float c = 0.5f;    /* half_pixel_center in the input checks */
   (void)tc;
   if (!q->front_facing)
      bad_face++;
   for (unsigned i = 0; i < 4; i++) {
      if (!(q->mask & (1u << i)))
         continue;
      double cx = q->x + (int)(i & 1) + c, cy = q->y + (int)(i >> 1) + c;
      double s = 0.5 + (cx - pc_x) / pc_w;
      double tt = pc_lower_left ? 0.5 - (cy - pc_y) / pc_w : 0.5 + (cy - pc_y) / pc_w;
      double es = fabs(q->in[0][0][i] - s), et = fabs(q->in[0][1][i] - tt);
      if (es > worst_s) worst_s = es;
      if (et > worst_t) worst_t = et;
      if (q->in[0][2][i] != 0.0f || q->in[0][3][i] != 1.0f)
         bad_const++;
      for (unsigned k = 0; k < 4; k++)
         if (q->in[1][k][i] != want_const[k])
            bad_const++;
      if (fabsf(q->frag_z[i] - want_z) > 1e-5f || q->frag_w[i] != want_w)
         bad_zw++;
   }
}

/* llvmpipe's util_iround (x86-64 generic branch) and subpixel_snap. */
static int64_t ref_snap(float v)
{
   float f = v * 256.0f;
   return f >= 0.0f ? (int64_t)(f + 0.5f) : (int64_t)(f - 0.5f);
}

static int64_t ref_shr8(int64_t v)   /* arithmetic >> 8 */
{
   return v >= 0 ? v / 256 : -((-v + 255) / 256);
}

/* The reference pixel set: llvmpipe's planes evaluated at every pixel. */
static bool ref_covered(int i, int j, float x, float y, float size, bool quad, bool half,
                        bool bottom)
{
   if (i < 0 || j < 0 || i >= W || j >= H)
      return false;
   if (size > 255.0f)
      size = 255.0f;
   if (quad) {
      float po = half ? 0.5f : 0.0f;
      int64_t fw = ref_snap(size);
      if (fw < 256) fw = 256;
      int64_t x0 = ref_snap(x - po) - fw / 2, y0 = ref_snap(y - po) - fw / 2;
      int64_t px = (int64_t)i * 256, py = (int64_t)j * 256;
      bool inx = px >= x0 && px < x0 + fw;
      bool iny = bottom ? (py > y0 && py <= y0 + fw) : (py >= y0 && py < y0 + fw);
      return inx && iny;
   }
   int64_t gx = ref_snap(x), gy = ref_snap(y) - (bottom ? 1 : 0);
   int64_t fw = (ref_snap(size) + 127) & ~(int64_t)255;
   if (fw < 256) fw = 256;
   int64_t n = fw >> 8, bx, by;
   if (n == 1) {
      bx = ref_shr8(gx);
      by = ref_shr8(gy);
   } else if (n & 1) {
      bx = ref_shr8(gx) - (n - 1) / 2;
      by = ref_shr8(gy) - (n - 1) / 2;
   } else {
      bx = ref_shr8(gx + 128) - n / 2;
      by = ref_shr8(gy + 128) - n / 2;
   }
   return i >= bx && i < bx + n && j >= by && j < by + n;
}

static float vert[4][4];
static struct rast_raster_state rs;
/* point_tri_clip: the reference's pixels inside this viewport only */
static bool ref_vp_on;
static struct rast_scissor ref_vp;

static void set_raster(bool quad, bool half, bool bottom, bool lower_left, float state_size,
                       bool per_vertex)
{
   memset(&rs, 0, sizeof rs);
   rs.half_pixel_center = half;
   rs.bottom_edge_rule = bottom;
   rs.cull = RAST_CULL_NONE;
   rs.line_width = 1.0f;
   rs.point_quad_rasterization = quad;
   rs.sprite_coord_lower_left = lower_left;
   rs.point_size = state_size;
   rs.point_size_per_vertex = per_vertex;
   rast_set_raster_state(t.rc, &rs);
}

static void point(float x, float y, float size)
{
   vert[0][0] = x; vert[0][1] = y; vert[0][2] = 0.25f; vert[0][3] = 0.5f;
   vert[1][0] = size;
   t_begin(&t);
   rast_point(t.rc, T_V(vert));
}

/* Coverage of one point of the given size against the reference's point
 * of ref_size; returns the mismatches. */
static unsigned check_cover_as(float x, float y, float size, float ref_size)
{
   unsigned bad = 0;
   uint64_t n = 0;
   point(x, y, size);
   for (int j = (int)y - 140; j <= (int)y + 140; j++) {
      for (int i = (int)x - 140; i <= (int)x + 140; i++) {
         bool ref = ref_covered(i, j, x, y, rs.point_size_per_vertex ? ref_size : rs.point_size,
                                rs.point_quad_rasterization, rs.half_pixel_center,
                                rs.bottom_edge_rule) &&
                    (!ref_vp_on || (i >= ref_vp.minx && i < ref_vp.maxx && j >= ref_vp.miny &&
                                    j < ref_vp.maxy));
         bool got = i >= 0 && j >= 0 && i < W && j < H &&
                    t.stamp[(size_t)j * W + (size_t)i] == t.id;
         n += ref;
         bad += ref != got;
      }
   }
   bad += t.count != n;
   CHECK(t.dups == 0 && t.badquad == 0 && t.outside == 0, "point emitted a bad quad");
   return bad;
}

static unsigned check_cover(float x, float y, float size)
{
   return check_cover_as(x, y, size, size);
}

static void layout(void)
{
   struct rast_vertex_layout vl = t_layout_pos();
   vl.has_psize = true;
   vl.psize_slot = vl.vertex_size++;        /* slot 1 */
   t_layout_add(&vl, RAST_INTERP_PERSPECTIVE, 0xf);
   t_layout_add(&vl, RAST_INTERP_COLOR, 0xf);
   vl.point_coord_mask = 1u << 0;
   rast_set_vertex_layout(t.rc, &vl);
}

static unsigned coverage_run(const char *profile)
{
   static const float fsizes[] = { 0.0f, 0.3f, 1.5f, 2.25f, 2.5f, 3.49f, 6.7f, 300.0f };
   unsigned bad = 0, points = 0;
   t_init(&t, profile, W, H);
   layout();
   for (unsigned cfg = 0; cfg < 8; cfg++) {
      const bool quad = !(cfg & 4), half = !(cfg & 2), bottom = cfg & 1;
      if (!quad && !half)
         continue;   /* llvmpipe asserts half-pixel centres for GL 2.1 points */
      set_raster(quad, half, bottom, false, 1.0f, true);
      for (int n = 0; n < 4000; n++) {
         float size = n % 10 < 8 ? (float)(1 + n % 8)
                                 : fsizes[(unsigned)(t_rand() * 8) & 7];
         float x, y;
         if (n % 3 == 0) {
            /* on the 1/256 grid, often on pixel centres and edges */
            x = (float)((int)(t_rand() * (W + 8) * 4) - 16) / 4.0f;
            y = (float)((int)(t_rand() * (H + 8) * 4) - 16) / 4.0f;
         } else {
            x = (float)(t_rand() * (W + 16) - 8);
            y = (float)(t_rand() * (H + 16) - 8);
         }
         unsigned b = check_cover(x, y, size);
         if (b && bad < 10)
            fprintf(stderr, "%s cfg %u point (%.9g, %.9g) size %g: %u pixels differ\n",
                    profile, cfg, x, y, size, b);
         bad += b;
         points++;
      }
   }
   /* sizes outside GL's range [1, max] (gl_PointSize is the shader's): NaN
    * and below 1 drawn as 1, +inf and beyond as the largest */
   static const float odd[] = { NAN, -INFINITY, -1.0f, 1e-30f, INFINITY, 1e30f };
   for (unsigned cfg = 0; cfg < 2; cfg++) {
      set_raster(cfg == 0, true, false, false, 1.0f, true);
      for (unsigned i = 0; i < 6; i++) {
         float x = (float)(t_rand() * W), y = (float)(t_rand() * H);
         float as = isnan(odd[i]) || odd[i] < 1.0f ? 1.0f : (float)RAST_MAX_POINT_SIZE;
         unsigned b = check_cover_as(x, y, odd[i], as);
         CHECK(b == 0, "%s point of size %g: %u pixels differ from one of size %g", profile,
               (double)odd[i], b, (double)as);
         points++;
      }
   }
   /* the state's size when the vertex has none, or per-vertex size is off */
   set_raster(true, true, false, false, 3.0f, false);
   for (int n = 0; n < 500; n++) {
      float x = (float)(t_rand() * W), y = (float)(t_rand() * H);
      bad += check_cover(x, y, 7.0f);   /* vertex size ignored */
      points++;
   }
   CHECK(rast_get_stats(t.rc)->points == points, "points counted: %llu of %u",
         (unsigned long long)rast_get_stats(t.rc)->points, points);

   /* point_tri_clip (GL ES: draw passes points whatever their centre): the
    * square scissored to the viewport, as llvmpipe does; a centre far
    * outside draws nothing and reaches no register (no XY saturation) */
   unsigned vp_bad = 0;
   for (int n = 0; n < 2000; n++) {
      set_raster(true, true, n & 1, false, 1.0f, true);
      rs.point_tri_clip = true;
      rast_set_raster_state(t.rc, &rs);
      const int x0 = (int)(t_rand() * W / 2), y0 = (int)(t_rand() * H / 2);
      ref_vp = (struct rast_scissor){ x0, y0, x0 + 4 + (int)(t_rand() * W / 2),
                                      y0 + 4 + (int)(t_rand() * H / 2) };
      rast_set_viewport(t.rc, &ref_vp);
      ref_vp_on = true;
      const float size = (float)(1 + n % 31);
      /* the centre within 20 px of an edge of the viewport, either side */
      float x = (float)(ref_vp.minx + t_rand() * (ref_vp.maxx - ref_vp.minx));
      float y = (float)(ref_vp.miny + t_rand() * (ref_vp.maxy - ref_vp.miny));
      const float off = (float)(t_rand() * 40 - 20);
      switch (n % 4) {
      case 0: x = (float)ref_vp.minx + off; break;
      case 1: x = (float)ref_vp.maxx + off; break;
      case 2: y = (float)ref_vp.miny + off; break;
      default: y = (float)ref_vp.maxy + off; break;
      }
      unsigned b = check_cover(x, y, size);
      if (b && vp_bad < 10)
         fprintf(stderr, "%s viewport (%d,%d)-(%d,%d) point (%.9g, %.9g) size %g: %u differ\n",
                 profile, ref_vp.minx, ref_vp.miny, ref_vp.maxx, ref_vp.maxy, x, y, size, b);
      vp_bad += b;
   }
   const struct fx_sat xy = rast_get_stats(t.rc)->sat[RAST_REG_XY];
   static const float far[] = { -1e30f, -3e6f, 5e5f, 1e30f };
   for (unsigned i = 0; i < 4; i++) {
      point(far[i], 40.0f, 200.0f);
      vp_bad += t.count != 0;
      point(40.0f, far[i], 200.0f);
      vp_bad += t.count != 0;
   }
   CHECK(rast_get_stats(t.rc)->sat[RAST_REG_XY].high == xy.high &&
         rast_get_stats(t.rc)->sat[RAST_REG_XY].low == xy.low,
         "a point far outside the viewport saturated the XY registers");
   ref_vp_on = false;
   CHECK(vp_bad == 0, "%s: %u pixels differ with the point scissored to the viewport", profile,
         vp_bad);
   printf("point (%s): %u points, %u pixels differ from the reference\n", profile, points, bad);
   t_fini(&t);
   return bad;
}

struct tri_probe { float s_max, col_max; };

static void probe_hook(struct tctx *tc, const struct rast_quad *q)
{
   struct tri_probe *p = tc->user;
   for (unsigned i = 0; i < 4; i++) {
      if (!(q->mask & (1u << i)))
         continue;
      if (q->in[0][0][i] > p->s_max) p->s_max = q->in[0][0][i];
      if (q->in[1][0][i] > p->col_max) p->col_max = q->in[1][0][i];
   }
}

static void inputs_run(void)
{
   t_init(&t, "seed", W, H);
   t.hook = hook;
   layout();
   want_const[0] = 0.1f; want_const[1] = 0.7f; want_const[2] = 0.3f; want_const[3] = 1.0f;
   memcpy(vert[3], want_const, sizeof want_const);
   vert[2][0] = 5; vert[2][1] = 6; vert[2][2] = 7; vert[2][3] = 8;   /* replaced */
   want_z = 0.25f;
   want_w = 0.5f;
   unsigned pixels = 0;
   for (unsigned ll = 0; ll < 2; ll++) {
      set_raster(true, true, ll, ll, 1.0f, true);
      pc_lower_left = ll;
      for (int n = 0; n < 3000; n++) {
         float size = n % 2 ? (float)(1 + n % 8) : (float)(1 + 40 * t_rand());
         float x = (float)(t_rand() * W), y = (float)(t_rand() * H);
         int64_t fw = ref_snap(size);
         pc_x = x; pc_y = y; pc_w = (double)(fw < 256 ? 256 : fw) / 256.0;
         point(x, y, size);
         pixels += (unsigned)t.count;
      }
   }
   printf("point: %u sprite pixels, worst s error %.2e, t error %.2e\n", pixels, worst_s,
          worst_t);
   CHECK(pixels > 100000, "only %u pixels", pixels);
   CHECK(worst_s < 2e-5 && worst_t < 2e-5, "sprite coordinate off by %g, %g", worst_s, worst_t);
   CHECK(bad_const == 0, "%u constant inputs differ from the vertex", bad_const);
   CHECK(bad_zw == 0, "%u pixels with Z or 1/w not the vertex's", bad_zw);
   CHECK(bad_face == 0, "%u point quads not front-facing", bad_face);

   /* A triangle after points interpolates its inputs again. */
   static float tv[3][4][4];
   for (unsigned k = 0; k < 3; k++) {
      tv[k][0][0] = k == 1 ? 60.0f : 10.0f;
      tv[k][0][1] = k == 2 ? 60.0f : 10.0f;
      tv[k][0][2] = 0.5f;
      tv[k][0][3] = 1.0f;
      for (unsigned c = 0; c < 4; c++) {
         tv[k][2][c] = k == 1 ? 1.0f : 0.0f;
         tv[k][3][c] = k == 2 ? 1.0f : 0.0f;
      }
   }
   struct tri_probe probe = { 0, 0 };
   t.user = &probe;
   t.hook = probe_hook;
   t_begin(&t);
   t_tri(t.rc, tv[0], tv[1], tv[2]);
   CHECK(t.count > 1000, "triangle drew %llu px", (unsigned long long)t.count);
   CHECK(probe.s_max > 0.5f && probe.col_max > 0.5f,
         "triangle inputs not interpolated after points: max %g %g", probe.s_max,
         probe.col_max);
   t_fini(&t);
}

int main(void)
{
   t_seed(4242);
   unsigned bad = coverage_run("seed");
   bad += coverage_run("wide");
   CHECK(bad == 0, "%u pixels differ from llvmpipe's point rule", bad);
   inputs_run();
   return t_summary("point");
}
