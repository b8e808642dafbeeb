/*
 * Planes that follow one screen axis (docs/datapath.md).
 *
 * Seed 002's numerators at a pixel's centre (px, py from V0) are
 * a = e2y·px - e2x·py and b = e1x·py - e1y·px.  Where e2x = e1y = 0 (V0V2
 * vertical, V0V1 horizontal: one of the two triangles of an axis-aligned
 * rectangle, as 2-D content draws them) a depends on the pixel's column
 * alone and b on its scan line alone; where e2y = e1x = 0, the other way
 * round.  With w constant, a plane with one term (interp_lanes.c's lterm:
 * FR_TERM_A or FR_TERM_B alone) is a function of one numerator, so every
 * pixel of a column, or of a scan line, goes through the same operations
 * on the same registers: the same value, the same range events.
 *
 * Such a primitive's planes are divided once per column and once per
 * scan line of its bounding box instead of once per pixel.  The division
 * is the lanes' own, on quads along the box's diagonal (quad j: columns
 * x0 + 2j and the next, scan lines y0 + 2j and the next), and each pixel
 * then takes its column's and its scan line's values.  Where a lane of
 * those divisions has a range event the tables are not made, and the
 * primitive's pixels are divided one by one as before: a pixel's events
 * are counted when it is drawn.  Taken with the skips and the binary32
 * lanes (FIXPIPE_DEBUG=noskip and nof32 leave it out); the quads that
 * took it are counted in skip_persp_axes.
 */
#include "rast/setup/front.h"
#include "rast/host/lanes.h"
#include "rast/rast_priv.h"

void rast_interp_axes_setup(struct rast_front *fr)
{
   struct fr_tex *t = &fr->tex;
   t->axes = 0;
   if (!t->lanes || !t->skip || !t->f32 || !t->w_const || t->ln > FR_AXES_PLANES ||
       !rast_lanes()->persp4_probe_dfx19)
      return;
   const bool a_by_x = t->e2x == 0 && t->e1y == 0, a_by_y = t->e2y == 0 && t->e1x == 0;
   if (a_by_x == a_by_y)
      return;
   for (unsigned i = 0; i < t->ln; i++) {
      if (t->lterm[i] == (FR_TERM_A | FR_TERM_B))
         return;
      /* a plane without a term is its v0: either axis holds it */
      t->by_x[i] = t->lterm[i] & FR_TERM_B ? !a_by_x : a_by_x;
   }
   t->axes = -1;
}

/* The numerators of the quad whose left column is c and top scan line r
 * (persp.c's tex_begin), as the span processor records them. */
static void axes_numerators(const struct rast_front *fr, int64_t c, int64_t r, int64_t num[4])
{
   const struct fr_tex *t = &fr->tex;
   const int64_t px = c * fr->S + fr->Hx - t->x0, py = r * fr->S + fr->Hy - t->y0;
   num[0] = px * t->e2y - py * t->e2x;
   num[1] = num[0] + t->a_dy;
   num[2] = t->e1x * py - t->e1y * px;
   num[3] = num[2] + t->b_dy;
}

/* The box's columns and scan lines, two more on each side than the
 * vertices' extent (a quad's helper pixels), from an even one. */
static bool axes_box(struct rast_front *fr)
{
   struct fr_tex *t = &fr->tex;
   int64_t lo[2] = { t->x0, t->y0 }, hi[2] = { t->x0, t->y0 };
   const int64_t ex[2] = { t->e1x, t->e2x }, ey[2] = { t->e1y, t->e2y };
   for (unsigned v = 0; v < 2; v++) {
      const int64_t x = t->x0 + ex[v], y = t->y0 + ey[v];
      lo[0] = x < lo[0] ? x : lo[0];
      hi[0] = x > hi[0] ? x : hi[0];
      lo[1] = y < lo[1] ? y : lo[1];
      hi[1] = y > hi[1] ? y : hi[1];
   }
   int64_t first[2], n[2];
   for (unsigned a = 0; a < 2; a++) {
      /* floor division: the XY format's coordinates may be negative */
      const int64_t f = lo[a] >= 0 ? lo[a] / fr->S : -((-lo[a] + fr->S - 1) / fr->S);
      const int64_t l = hi[a] >= 0 ? hi[a] / fr->S : -((-hi[a] + fr->S - 1) / fr->S);
      first[a] = (f - 2) & ~(int64_t)1;
      n[a] = ((l + 3 - first[a]) | 1) + 1;
   }
   /* a box too narrow saves less than its diagonal costs */
   if (n[0] < 16 || n[1] < 16 || n[0] > FR_AXES_MAX || n[1] > FR_AXES_MAX)
      return false;
   t->col_x0 = first[0];
   t->row_y0 = first[1];
   t->ncols = (unsigned)n[0];
   t->nrows = (unsigned)n[1];
   return true;
}

/* The tables, from the lanes' division of the quads along the diagonal,
 * four a call; false where a lane had a range event. */
static bool axes_tables(struct rast_front *fr)
{
   struct fr_tex *t = &fr->tex;
   if (!axes_box(fr))
      return false;
   const unsigned span = t->ncols > t->nrows ? t->ncols : t->nrows;
   const unsigned nq = span / 2;
   struct rast_quad scratch[4];
   float *const in[4] = { &scratch[0].in[0][0][0], &scratch[1].in[0][0][0],
                          &scratch[2].in[0][0][0], &scratch[3].in[0][0][0] };
   for (unsigned j0 = 0; j0 < nq; j0 += 4) {
      int64_t num[4][4];
      unsigned dc[4], dr[4];
      for (unsigned k = 0; k < 4; k++) {
         const unsigned j = j0 + k < nq ? j0 + k : nq - 1;
         dc[k] = 2 * j < t->ncols - 2 ? 2 * j : t->ncols - 2;
         dr[k] = 2 * j < t->nrows - 2 ? 2 * j : t->nrows - 2;
         axes_numerators(fr, t->col_x0 + dc[k], t->row_y0 + dr[k], num[k]);
      }
      if (!rast_lanes()->persp4_probe_dfx19(fr, in, (const int64_t (*)[4])num))
         return false;
      for (unsigned k = 0; k < 4; k++)
         for (unsigned i = 0; i < t->ln; i++) {
            const float *v = in[k] + t->lout[i];
            if (t->by_x[i]) {
               t->col[i][dc[k]] = v[0];
               t->col[i][dc[k] + 1] = v[1];
            } else {
               t->row[i][dr[k]] = v[0];
               t->row[i][dr[k] + 1] = v[2];
            }
         }
   }
   return true;
}

bool rast_interp_axes_fill(struct rast_context *rc, struct rast_front *fr)
{
   struct fr_tex *t = &fr->tex;
   if (!t->axes)
      return false;
   if (t->axes < 0) {
      t->axes = axes_tables(fr) ? 1 : 0;
      if (!t->axes)
         return false;
      t->axes_hx = fr->Hx;
      t->axes_hy = fr->Hy;
   }
   /* a multisampled target's other samples: other numerators */
   if (fr->Hx != t->axes_hx || fr->Hy != t->axes_hy)
      return false;
   const unsigned nq = t->nrec;
   int64_t dc[FR_AHEAD_MAX], dr[FR_AHEAD_MAX];
   for (unsigned k = 0; k < nq; k++) {
      dc[k] = fr->quad[k].x - rc->org_x - t->col_x0;
      dr[k] = fr->quad[k].y - rc->org_y - t->row_y0;
      if (dc[k] < 0 || dc[k] > (int64_t)t->ncols - 2 || dr[k] < 0 ||
          dr[k] > (int64_t)t->nrows - 2)
         return false;
   }
   for (unsigned k = 0; k < nq; k++) {
      float *in = &fr->quad[k].in[0][0][0];
      for (unsigned i = 0; i < t->ln; i++) {
         float *o = in + t->lout[i];
         if (t->by_x[i]) {
            const float *c = &t->col[i][dc[k]];
            o[0] = c[0]; o[1] = c[1]; o[2] = c[0]; o[3] = c[1];
         } else {
            const float *r = &t->row[i][dr[k]];
            o[0] = r[0]; o[1] = r[0]; o[2] = r[1]; o[3] = r[1];
         }
      }
      /* the constant components, as the division writes them */
      for (unsigned i = 0; i < t->n_const; i++)
         for (unsigned p = 0; p < RAST_QUAD_SIZE; p++)
            in[t->cout[i] + p] = t->cval[i];
   }
   fr_tex_counted(t, nq);
   rc->stats.skip_persp_axes += nq;
   return true;
}
