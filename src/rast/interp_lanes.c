/*
 * The perspective division of interp.c (seeds 002, 003) for dfx24 on
 * lanes: the quad's four pixels through dfx_lanes.h, each lane the scalar
 * tex_quad_impl's operations in its order:
 *
 *    a = (n_a in the system) · recip(det)     b likewise
 *    w = recip(v0 + a·Δ1 + b·Δ2)              the plane of 1/w
 *    A = (v0 + a·Δ1 + b·Δ2) · w               every PERSPECTIVE component
 *
 * The components go step by step over all of them (every product a·Δ1,
 * then every sum, ...): each step's operations are independent, so the
 * processor overlaps them; one component after the other would wait on
 * each operation's latency.
 *
 * The skips of rast_interp_perspective_setup (docs/datapath.md): a plane
 * whose differences are both zero is its v0 (the multiplier gives zero,
 * the adder returns v0 unchanged, neither with an event), so a constant
 * 1/w takes its reciprocal once per primitive, and a constant component
 * with a constant w is one value; the events those operations would have
 * raised are counted per pixel all the same.  Each quad is first computed
 * optimistically (dfx_lanes.h), and again with its range events handled
 * where one happened; not with noskip.
 */
#include "rast/front.h"
#include "rast/lanes_fns.h"
#include "fixed/dfx_lanes.h"

static inline __attribute__((always_inline)) struct dfxl splat(double v)
{
   struct dfxl r = { { v, v, v, v } };
   return r;
}

static inline void count(struct dfx_stats *to, struct dfx_stats ev, unsigned times)
{
   to->sat += ev.sat * times;
   to->flush += ev.flush * times;
}

/* The quad; `optimistic` (dfx_lanes.h): false, leaving nothing counted,
 * when a lane had a range event. */
static inline __attribute__((always_inline)) bool
persp(struct rast_front *fr, struct rast_quad *q, const int64_t an[RAST_QUAD_SIZE],
      const int64_t bn[RAST_QUAD_SIZE], const bool optimistic)
{
   struct fr_tex *t = &fr->tex;
   struct dfxl_stats st = DFXL_STATS(optimistic);
   const dfxl_i nA = { an[0], an[1], an[2], an[3] }, nB = { bn[0], bn[1], bn[2], bn[3] };
   const struct dfxl rdet = splat(t->lrdet);
   const struct dfxl a = dfxl_mul(dfxl_from_fixed(nA, (int)t->k, &st), rdet, &st);
   const struct dfxl b = dfxl_mul(dfxl_from_fixed(nB, (int)t->k, &st), rdet, &st);

   /* the planes evaluated per pixel: 1/w unless constant, and the
    * components that are not */
   unsigned idx[1 + FR_MAX_COMP], n = 0;
   if (!t->w_const)
      idx[n++] = 0;
   for (unsigned j = 0; j < fr->npersp; j++)
      if (!t->comp_const[j])
         idx[n++] = 1 + j;
   struct dfxl v[1 + FR_MAX_COMP], u[1 + FR_MAX_COMP];
   for (unsigned i = 0; i < n; i++)
      v[i] = dfxl_mul(a, splat(t->lv[idx[i]][1]), &st);
   for (unsigned i = 0; i < n; i++)
      u[i] = dfxl_mul(b, splat(t->lv[idx[i]][2]), &st);
   for (unsigned i = 0; i < n; i++)
      v[i] = dfxl_add(splat(t->lv[idx[i]][0]), v[i], &st);
   for (unsigned i = 0; i < n; i++)
      v[i] = dfxl_add(v[i], u[i], &st);

   struct dfxl w;
   unsigned first = 0;
   if (t->w_const) {
      w = splat(t->lw);
   } else {
      w = dfxl_recip(v[0], &st);
      first = 1;
   }
   for (unsigned i = first; i < n; i++) {
      if (!t->w_one)
         v[i] = dfxl_mul(v[i], w, &st);
      const unsigned j = idx[i] - 1;
      dfxl_to_float(v[i], q->in[fr->persp[j].var][fr->persp[j].chan]);
   }
   unsigned n_const = 0;
   for (unsigned j = 0; j < fr->npersp; j++) {
      if (!t->comp_const[j])
         continue;
      float *o = q->in[fr->persp[j].var][fr->persp[j].chan];
      n_const++;
      if (t->w_const) {
         for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
            o[i] = t->comp_val[j];
      } else {
         dfxl_to_float(dfxl_mul(splat(t->lv[1 + j][0]), w, &st), o);
      }
   }
   if (optimistic && dfxl_any(st.trouble))
      return false;
   /* the events of the values computed once per primitive, for every pixel */
   if (t->w_const) {
      count(&t->dst, t->w_ev, RAST_QUAD_SIZE);
      t->n_const_w++;
      for (unsigned j = 0; j < fr->npersp; j++)
         if (t->comp_const[j])
            count(&t->dst, t->comp_ev[j], RAST_QUAD_SIZE);
   }
   t->n_const_comp += n_const;
   dfxl_stats_add(&t->dst, st);
   return true;
}

void LANES_FN(persp_dfx19_lanes)(struct rast_front *fr, struct rast_quad *q,
                                 const int64_t an[RAST_QUAD_SIZE],
                                 const int64_t bn[RAST_QUAD_SIZE])
{
   if (!fr->tex.skip || !persp(fr, q, an, bn, true))
      persp(fr, q, an, bn, false);
}
