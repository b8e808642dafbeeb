/*
 * Edge processing (seed 000, section 2): walk the left and right edges one
 * scan line at a time, two scan lines per quad row, and hand each pair of
 * spans to the span processor (span.c).
 *
 * Fill rule, with c = (i + h, j + h) the pixel centre (h = 1/2 for GL):
 *   rows     top-left rule:    y_top <= c_y <  y_bottom
 *            bottom-edge rule: y_top <  c_y <= y_bottom
 *   columns  always:           X_left <= c_x < X_right
 * evaluated with the seed's ceil circuit on exact values:
 *   y_min = ceil(y_top - h [+ 1 ulp]), y_max = ceil(y_bottom - h [+ 1 ulp]) - 1
 *   x_init = ceil(X_left - h), x_end = ceil(X_right - h) - 1
 * where X_left, X_right are exact (register + remainder, see fr_edge), so a
 * non-zero remainder is the "+ 1 ulp" that makes ceil() of the rational value
 * exact.  This is llvmpipe's tie rule: left edges include pixel centres on
 * them, right edges exclude them; horizontal top edges are in with the
 * top-left rule, horizontal bottom edges with the bottom-edge rule.
 */
#include <stddef.h>
#include "rast/setup/front.h"

static inline int64_t ceil_row(const struct rast_front *fr, struct fx_format xy, int64_t y)
{
   return fx_ceil_int(xy, y - fr->Hy + fr->row_bias);
}

/* floor(n / d) for d > 0, with the remainder in [0, d). */
static inline int64_t floor_div(int64_t n, int64_t d, int64_t *rem)
{
   int64_t q = n / d, r = n % d;
   if (r < 0) { q--; r += d; }
   *rem = r;
   return q;
}

/* The seed's walk as Table 1 has it (profile setting walk=literal): the
 * Δx/Δy register is floor(Δx·2^Nd/Δy) in its own format (Nd fraction
 * bits, saturating), added to X on X's grid (the adder drops what X
 * cannot hold), and nothing carries the rest.  X starts at the edge's
 * first scan line j0 with the exact intersection floored (the set-up's
 * multiply-divide) and then only adds: at scan line j it holds
 * start + (j - j0) slopes, which is what the walk from j0 would hold, so
 * a clip, a tile or a thread that starts lower sees the same register. */
static void literal_start(struct rast_context *rc, struct rast_front *fr, struct fr_edge *e,
                          int64_t j, int64_t dx, bool steps)
{
   const struct rast_profile *prof = rc->profile;
   const unsigned nxy = prof->xy.frac_bits, nd = prof->dxdy.frac_bits;
   int64_t rem;
   int64_t q = floor_div(dx * (INT64_C(1) << nd), e->dy, &rem);
   const int64_t j0 = ceil_row(fr, prof->xy, e->ya);
   if (q > fx_max(prof->dxdy) || q < fx_min(prof->dxdy)) {
      struct fx_sat none = { 0, 0 };
      /* counted where the slope is used, as the exact walk counts it */
      q = fx_sat(prof->dxdy, q, steps || j > j0 ? &rc->stats.sat[RAST_REG_DXDY] : &none);
   }
   e->step = nd >= nxy ? q >> (nd - nxy) : q * (INT64_C(1) << (nxy - nd));
   e->step_rem = 0;
   const int64_t t0 = j0 * fr->S + fr->Hy - e->ya;
   const int64_t x0 = e->xa + floor_div(dx * t0, e->dy, &rem);
   e->x = fx_sat(prof->xy, x0 + (j - j0) * e->step, &rc->stats.sat[RAST_REG_XY]);
   e->rem = 0;
}

/* Load an edge's registers at scan line j: the subpixel start (one exact
 * multiply-divide, also used to jump over clipped scan lines), the slope
 * registers if the edge will be stepped, and for a left edge the attribute
 * registers and their Δ/Δy along the edge. */
static void edge_start(struct rast_context *rc, struct rast_front *fr,
                       struct fr_edge *e, int64_t j)
{
   const struct rast_profile *prof = rc->profile;
   int64_t S = fr->S;
   int64_t t = j * S + fr->Hy - e->ya;         /* 0 <= t <= dy */
   int64_t dx = e->xb - e->xa;
   int64_t rem;

   e->dy = e->yb - e->ya;
   bool steps = e->j_end > j;
   if (prof->literal_walk) {
      literal_start(rc, fr, e, j, dx, steps);
   } else {
      e->x = fx_add(prof->xy, e->xa, floor_div(dx * t, e->dy, &rem), &rc->stats.sat[RAST_REG_XY]);
      e->rem = rem;
      e->step = e->step_rem = 0;
   }
   if (steps && !prof->literal_walk) {
      int64_t q = floor_div(dx * S, e->dy, &rem);
      /* The dx/dy register; a clamped slope loses the exact walk. */
      if (q > fx_max(prof->dxdy) || q < fx_min(prof->dxdy)) {
         q = fx_sat(prof->dxdy, q, &rc->stats.sat[RAST_REG_DXDY]);
         rem = 0;
      }
      e->step = q;
      e->step_rem = rem;
   }

   if (!e->left)
      return;
   const unsigned nfix = fr->nfix_walk;
   rc->stats.interp_add += 2 * nfix;
   rc->stats.interp_mul += (steps ? 2 : 1) * nfix;
   rc->stats.interp_div += (steps ? 2 : 1) * nfix;
   for (unsigned k = 0; k < nfix; k++) {
      int64_t va = fr->vfix[e->a][k], d = fr->vfix[e->b][k] - va;
      e->fix[k] = fr_fix_sat(fr, k, (fx_i128)va + fx_div_round_i128((fx_i128)d * t, e->dy));
      e->fix_step[k] = steps ? fr_fix_sat(fr, k, fx_div_round_i128((fx_i128)d * S, e->dy)) : 0;
   }
   double ft = (double)t / (double)e->dy, fs = (double)S / (double)e->dy;
   for (unsigned k = 0; k < fr->nwalk; k++) {
      double va = fr->vflt[e->a][k], d = (double)fr->vflt[e->b][k] - va;
      e->flt[k] = (float)(va + d * ft);
      e->flt_step[k] = (float)(d * fs);
   }
}

static inline void edge_step(struct rast_context *rc, struct rast_front *fr, struct fr_edge *e)
{
   struct fx_format xy = rc->profile->xy;
   struct fx_sat *s = &rc->stats.sat[RAST_REG_XY];
   e->x = fx_add(xy, e->x, e->step, s);
   e->rem += e->step_rem;
   if (e->rem >= e->dy) {
      e->rem -= e->dy;
      e->x = fx_add(xy, e->x, 1, s);
   }
   if (!e->left)
      return;
   rc->stats.interp_add += fr->nfix_walk;
   for (unsigned k = 0; k < fr->nfix_walk; k++)
      e->fix[k] = fr_fix_add(fr, k, e->fix[k], e->fix_step[k]);
   for (unsigned k = 0; k < fr->nwalk; k++)
      e->flt[k] += e->flt_step[k];
}

static inline void record_row(struct rast_context *rc, struct rast_front *fr, struct fr_row *row,
                              const struct fr_edge *L, const struct fr_edge *R)
{
   struct fx_format xy = rc->profile->xy;
   int64_t xs = fx_ceil_int(xy, L->x - fr->Hx + (L->rem != 0));
   int64_t xe = fx_ceil_int(xy, R->x - fr->Hx + (R->rem != 0)) - 1;
   if (xs < rc->clip.minx) xs = rc->clip.minx;
   if (xe > rc->clip.maxx - 1) xe = rc->clip.maxx - 1;
   row->valid = true;
   row->xs = xs;
   row->xe = xe;
   row->xl = L->x;
   row->xl_frac = (float)L->rem / (float)L->dy;
   for (unsigned k = 0; k < fr->nfix_walk; k++)
      row->fix[k] = L->fix[k];
   for (unsigned k = 0; k < fr->nwalk; k++)
      row->flt[k] = L->flt[k];
}

void rast_scan_sections(struct rast_context *rc, struct rast_front *fr)
{
   struct fx_format xy = rc->profile->xy;
   int64_t jtop = INT64_MAX, jbot = INT64_MIN;

   for (unsigned s = 0; s < fr->nsec; s++) {
      struct fr_section *sec = &fr->sec[s];
      sec->j0 = ceil_row(fr, xy, sec->ytop);
      sec->j1 = ceil_row(fr, xy, sec->ybot) - 1;
      if (sec->j0 > sec->j1)
         continue;
      if (sec->j0 < jtop) jtop = sec->j0;
      if (sec->j1 > jbot) jbot = sec->j1;
   }
   /* Scan lines outside the clip are never walked: the first visible one
    * is reached by edge_start's jump. */
   int64_t jlo = jtop > rc->clip.miny ? jtop : rc->clip.miny;
   int64_t jhi = jbot < rc->clip.maxy - 1 ? jbot : rc->clip.maxy - 1;
   if (jlo > jhi)
      return;
   /* Below the thread's stretch every row is another thread's, which walks
    * there itself: the walk stops at the stretch's last scan line.  The
    * edges' extents stay the primitive's (edge_start counts by them). */
   int64_t jstop = jhi;
   if (rc->band_count > 1 && rc->band_hi != INT64_MAX && rc->band_hi - 1 - rc->org_y < jhi)
      jstop = rc->band_hi - 1 - rc->org_y;

   for (unsigned s = 0; s < fr->nsec; s++) {
      fr->sec[s].l->j_end = INT64_MIN;
      fr->sec[s].r->j_end = INT64_MIN;
   }
   unsigned cur = fr->nsec;
   for (unsigned s = 0; s < fr->nsec; s++) {
      struct fr_section *sec = &fr->sec[s];
      int64_t a = sec->j0 > jlo ? sec->j0 : jlo;
      int64_t b = sec->j1 < jhi ? sec->j1 : jhi;
      if (a > b)
         continue;
      if (cur == fr->nsec)
         cur = s;
      if (b > sec->l->j_end) sec->l->j_end = b;
      if (b > sec->r->j_end) sec->r->j_end = b;
   }

   struct fr_edge *L = fr->sec[cur].l, *R = fr->sec[cur].r;
   edge_start(rc, fr, L, jlo);
   edge_start(rc, fr, R, jlo);
   /* the set-up ends with the edges loaded: every thread that draws the
    * primitive has done the same work to here */
   if (rc->observe_scan)
      rc->observe_scan(rc, RAST_SCAN_BEGIN, 0);

   for (int64_t p = jlo & ~(int64_t)1; p <= jstop; p += 2) {
      /* Every thread walks the edges over every scan line (the registers
       * are the walk's, not recomputed); the spans are drawn, and the
       * walk's events counted, by the quad row's thread. */
      const bool mine = rast_band_mine(rc, p);
      rast_count_stretch(rc, mine);
      if (mine && rc->observe_scan)
         rc->observe_scan(rc, RAST_SCAN_ROW, p + rc->org_y);
      for (unsigned r = 0; r < 2; r++) {
         int64_t j = p + r;
         struct fr_row *row = &fr->row[r];
         if (j < jlo || j > jhi) {
            row->valid = false;
            row->xs = 1;
            row->xe = 0;
            continue;
         }
         if (j > fr->sec[cur].j1) {
            /* Into half B (or the next section of a line): the edge that
             * continues keeps its registers (X_next), the new one is loaded. */
            while (j > fr->sec[cur].j1)
               cur++;
            if (fr->sec[cur].l != L) { L = fr->sec[cur].l; edge_start(rc, fr, L, j); }
            if (fr->sec[cur].r != R) { R = fr->sec[cur].r; edge_start(rc, fr, R, j); }
         }
         /* another thread's rows: only the walk, which reaches this
          * thread's rows with the registers one thread would hold */
         if (mine) {
            record_row(rc, fr, row, L, R);
            rc->stats.spans += row->xs <= row->xe;
         }
         if (j < L->j_end) edge_step(rc, fr, L);
         if (j < R->j_end) edge_step(rc, fr, R);
      }
      if (mine)
         fr->pair(rc, fr, p);
   }
   fr_quads_flush(rc, fr);
   if (rc->observe_scan)
      rc->observe_scan(rc, RAST_SCAN_END, 0);
}

void rast_scan_convex(struct rast_context *rc, struct rast_front *fr)
{
   unsigned n = fr->nverts;
   fx_i128 area2 = 0;
   for (unsigned i = 0; i < n; i++) {
      unsigned k = (i + 1) % n;
      area2 += (fx_i128)fr->X[i] * fr->Y[k] - (fx_i128)fr->X[k] * fr->Y[i];
   }
   if (area2 == 0)
      return;
   /* With y down, a negative area means the forward order runs down the
    * left side. */
   bool fwd_left = area2 < 0;

   unsigned ne = 0;
   for (unsigned i = 0; i < n; i++) {
      unsigned k = (i + 1) % n;
      if (fr->Y[i] == fr->Y[k])
         continue;
      struct fr_edge *e = &fr->edge[ne++];
      bool down = fr->Y[i] < fr->Y[k];
      unsigned a = down ? i : k, b = down ? k : i;
      e->a = (uint8_t)a; e->b = (uint8_t)b;
      e->xa = fr->X[a]; e->ya = fr->Y[a];
      e->xb = fr->X[b]; e->yb = fr->Y[b];
      e->left = down ? fwd_left : !fwd_left;
   }

   /* The distinct vertex y values, sorted: section boundaries. */
   int64_t ys[FR_MAX_VERTS];
   unsigned ny = 0;
   for (unsigned i = 0; i < n; i++) {
      unsigned p = 0;
      while (p < ny && ys[p] < fr->Y[i]) p++;
      if (p < ny && ys[p] == fr->Y[i]) continue;
      for (unsigned q = ny; q > p; q--) ys[q] = ys[q - 1];
      ys[p] = fr->Y[i];
      ny++;
   }

   fr->nsec = 0;
   for (unsigned s = 0; s + 1 < ny; s++) {
      struct fr_section *sec = &fr->sec[fr->nsec];
      sec->ytop = ys[s];
      sec->ybot = ys[s + 1];
      sec->l = sec->r = NULL;
      for (unsigned i = 0; i < ne; i++) {
         struct fr_edge *e = &fr->edge[i];
         if (e->ya <= sec->ytop && e->yb >= sec->ybot) {
            if (e->left) sec->l = e; else sec->r = e;
         }
      }
      if (sec->l && sec->r)
         fr->nsec++;
   }
   if (fr->nsec)
      rast_scan_sections(rc, fr);
}
