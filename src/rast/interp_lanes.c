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
 * when a lane had a range event.  `n`: the planes evaluated per pixel
 * (t->ln), a constant in the common cases so that the planes stay in
 * registers. */
static inline __attribute__((always_inline)) bool
persp(struct rast_front *fr, struct rast_quad *q, const dfxl_i *an, const dfxl_i *bn,
      const bool optimistic, const unsigned n)
{
   struct fr_tex *t = &fr->tex;
   struct dfxl_stats st = DFXL_STATS(optimistic);
   const dfxl_i nA = *an, nB = *bn;
   const struct dfxl rdet = splat(t->lrdet);
   const struct dfxl a = dfxl_mul(dfxl_from_fixed(nA, (int)t->k, &st), rdet, &st);
   const struct dfxl b = dfxl_mul(dfxl_from_fixed(nB, (int)t->k, &st), rdet, &st);

   struct dfxl v[1 + FR_MAX_COMP], u[1 + FR_MAX_COMP];
   for (unsigned i = 0; i < n; i++)
      v[i] = dfxl_mul(a, splat(t->lv[t->lidx[i]][1]), &st);
   for (unsigned i = 0; i < n; i++)
      u[i] = dfxl_mul(b, splat(t->lv[t->lidx[i]][2]), &st);
   for (unsigned i = 0; i < n; i++)
      v[i] = dfxl_add(splat(t->lv[t->lidx[i]][0]), v[i], &st);
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
   float *in = &q->in[0][0][0];
   for (unsigned i = first; i < n; i++) {
      if (!t->w_one)
         v[i] = dfxl_mul(v[i], w, &st);
      dfxl_to_float(v[i], in + t->lout[i]);
   }
   for (unsigned i = 0; i < t->n_const; i++) {
      float *o = in + t->cout[i];
      if (t->w_const) {
         for (unsigned p = 0; p < RAST_QUAD_SIZE; p++)
            o[p] = t->cval[i];
      } else {
         dfxl_to_float(dfxl_mul(splat(t->lv[t->cidx[i]][0]), w, &st), o);
      }
   }
   if (optimistic && dfxl_any(dfxl_trouble(&st)))
      return false;
   /* the events of the values computed once per primitive, for every pixel */
   if (t->w_const) {
      count(&t->dst, t->const_ev, RAST_QUAD_SIZE);
      t->n_const_w++;
   }
   t->n_const_comp += t->n_const;
   dfxl_stats_add(&t->dst, st);
   return true;
}

/* The optimistic quad for the common plane counts. */
#define PERSP_N(nn)                                                                           \
   static bool persp_##nn(struct rast_front *fr, struct rast_quad *q, const dfxl_i *an,      \
                          const dfxl_i *bn)                                                   \
   {                                                                                          \
      return persp(fr, q, an, bn, true, nn);                                                  \
   }
PERSP_N(1)
PERSP_N(2)
PERSP_N(3)
PERSP_N(4)

/* The quad's numerators are built here from the registers, as vectors:
 * written as four numbers and read as one vector they would wait on the
 * processor's store forwarding. */
void LANES_FN(persp_dfx19_lanes)(struct rast_front *fr, struct rast_quad *q)
{
   struct fr_tex *t = &fr->tex;
   const dfxl_i an = { t->an[0], t->an[0] + t->a_dx, t->an[1], t->an[1] + t->a_dx };
   const dfxl_i bn = { t->bn[0], t->bn[0] + t->b_dx, t->bn[1], t->bn[1] + t->b_dx };
   const unsigned n = t->ln;
   if (t->skip) {
      bool done;
      switch (n) {
      case 1: done = persp_1(fr, q, &an, &bn); break;
      case 2: done = persp_2(fr, q, &an, &bn); break;
      case 3: done = persp_3(fr, q, &an, &bn); break;
      case 4: done = persp_4(fr, q, &an, &bn); break;
      default: done = persp(fr, q, &an, &bn, true, n); break;
      }
      if (done)
         return;
   }
   persp(fr, q, &an, &bn, false, n);
}
