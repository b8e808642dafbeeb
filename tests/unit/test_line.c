/*
 * One-pixel lines (diamond exit, as llvmpipe): known pixel sets for lines
 * between pixel centres, one pixel per major-axis step for random lines,
 * no pixel twice, attributes along the line, front_facing.
 */
#include <math.h>
#include <string.h>
#include "tutil.h"

static struct tctx t;
static unsigned colcount[1024], rowcount[1024];
static int colrow[1024];          /* the row of the last pixel seen in a column */
static double worst_attr;
static double la1, la2, lx1, lx2, ly1, ly2;
static bool lxmajor, bad_face;

static void hook(struct tctx *tc, const struct rast_quad *q)
{
   (void)tc;
   if (!q->front_facing)
      bad_face = true;
   for (unsigned i = 0; i < 4; i++) {
      if (!(q->mask & (1u << i)))
         continue;
      int x = q->x + (int)(i & 1), y = q->y + (int)(i >> 1);
      colcount[x]++;
      rowcount[y]++;
      colrow[x] = y;
      /* the attribute follows the major axis */
      double f = lxmajor ? (x + 0.5 - lx1) / (lx2 - lx1) : (y + 0.5 - ly1) / (ly2 - ly1);
      double e = fabs(q->in[0][0][i] - (la1 + f * (la2 - la1)));
      if (e > worst_attr) worst_attr = e;
   }
}

static void line(float x1, float y1, float x2, float y2)
{
   float v[2][2][4] = { { { x1, y1, 0.5f, 1 }, { 0.2f, 0, 0, 0 } },
                        { { x2, y2, 0.5f, 1 }, { 0.9f, 0, 0, 0 } } };
   la1 = 0.2; la2 = 0.9; lx1 = x1; lx2 = x2; ly1 = y1; ly2 = y2;
   lxmajor = fabsf(x2 - x1) >= fabsf(y2 - y1);
   memset(colcount, 0, sizeof colcount);
   memset(rowcount, 0, sizeof rowcount);
   t_begin(&t);
   t_line(t.rc, v[0], v[1]);
}

int main(void)
{
   t_seed(99);
   t_init(&t, "seed", 1024, 1024);
   t.hook = hook;
   struct rast_vertex_layout vl = t_layout_pos();
   t_layout_add(&vl, RAST_INTERP_LINEAR, 0x1);
   rast_set_vertex_layout(t.rc, &vl);

   /* between pixel centres: the start pixel is drawn, the end one not */
   line(10.5f, 10.5f, 20.5f, 10.5f);
   CHECK(t.count == 10 && t.minx == 10 && t.maxx == 19 && t.miny == 10 && t.maxy == 10,
         "horizontal: %llu px, x %d..%d, y %d..%d", (unsigned long long)t.count, t.minx, t.maxx,
         t.miny, t.maxy);
   line(20.5f, 10.5f, 10.5f, 10.5f);
   CHECK(t.count == 10 && t.minx == 11 && t.maxx == 20 && t.miny == 10 && t.maxy == 10,
         "horizontal reversed: %llu px, x %d..%d", (unsigned long long)t.count, t.minx, t.maxx);
   line(30.5f, 5.5f, 30.5f, 45.5f);
   CHECK(t.count == 40 && t.minx == 30 && t.maxx == 30 && t.miny == 5 && t.maxy == 44,
         "vertical: %llu px, y %d..%d", (unsigned long long)t.count, t.miny, t.maxy);
   line(100.5f, 100.5f, 110.5f, 110.5f);
   CHECK(t.count == 10 && t.minx == 100 && t.maxx == 109 && t.miny == 100 && t.maxy == 109,
         "diagonal: %llu px, x %d..%d, y %d..%d", (unsigned long long)t.count, t.minx, t.maxx,
         t.miny, t.maxy);
   CHECK(rast_get_stats(t.rc)->lines == 4, "lines counted");
   line(7.5f, 7.5f, 7.5f, 7.5f);
   CHECK(t.count == 0, "zero-length line drew %llu px", (unsigned long long)t.count);

   /* Corners snapped to llvmpipe's 1/256 (util_iround: halves away from
    * zero), not to the XY register's 1/4096: both lines pass exactly through
    * a pixel boundary at a pixel centre's column, so the snapped diamond
    * offset alone picks the row.  Pixels as llvmpipe draws them. */
   line(110.5f, 85.5f, 72.5f, 84.5f);        /* y_offset 0.5/38: 3/256, not 54/4096 */
   CHECK(t.count == 38 && colcount[91] == 1 && colrow[91] == 84,
         "snapped offset: %llu px, column 91 at row %d", (unsigned long long)t.count, colrow[91]);
   line(1014.5f, 523.5f, 246.5f, 460.5f);    /* y_offset 10.5/256 exactly: rounds to 11 */
   CHECK(colcount[374] == 1 && colrow[374] == 471,
         "half-step offset: column 374 at row %d", colrow[374]);

   /* random lines: one pixel per major-axis step, none twice, attribute
    * linear along the major axis */
   unsigned checked = 0;
   for (int n = 0; n < 4000; n++) {
      float x1 = (float)(20 + 980 * t_rand()), y1 = (float)(20 + 980 * t_rand());
      float len = (float)(1 + 200 * t_rand()), a = (float)(6.283185307179586 * t_rand());
      float x2 = x1 + len * cosf(a), y2 = y1 + len * sinf(a);
      if (x2 < 2 || y2 < 2 || x2 > 1020 || y2 > 1020)
         continue;
      line(x1, y1, x2, y2);
      CHECK(t.dups == 0 && t.badquad == 0, "line emitted a pixel twice");
      bool xm = fabsf(x2 - x1) >= fabsf(y2 - y1);
      unsigned *cnt = xm ? colcount : rowcount;
      int lo = xm ? t.minx : t.miny, hi = xm ? t.maxx : t.maxy;
      for (int i = lo; t.count && i <= hi; i++)
         CHECK(cnt[i] == 1, "line (%g,%g)-(%g,%g): %u pixels at major position %d", x1, y1, x2, y2, cnt[i], i);
      /* the number of pixel centres the major extent passes, within 2: the
       * diamond rule may add or drop a pixel at each end */
      double ext = xm ? fabs(x2 - x1) : fabs(y2 - y1);
      CHECK(fabs((double)t.count - ext) <= 2.0, "line (%g,%g)-(%g,%g): %llu px for extent %g",
            x1, y1, x2, y2, (unsigned long long)t.count, ext);
      checked++;
   }
   printf("line: %u random lines, worst attribute error %.2e\n", checked, worst_attr);
   CHECK(worst_attr < 1e-4, "attribute along the line off by %g", worst_attr);
   CHECK(!bad_face, "a line quad was not front-facing");
   t_fini(&t);
   return t_summary("line");
}
