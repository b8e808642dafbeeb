/*
 * What the perspective division (persp.c) and the span processor
 * (span.c) share: the division's numerator registers, which the span
 * processor steps quad by quad, and the quad row's range events, which
 * it hands to the context's counters when the row is done.
 */
#ifndef RAST_INTERP_PERSP_H
#define RAST_INTERP_PERSP_H

#include "rast/setup/front.h"

/* The numerators' registers moved on to the next quad. */
static inline void tex_numerators_next(struct fr_tex *t)
{
   for (unsigned r = 0; r < 2; r++) {
      t->an[r] += 2 * t->a_dx;
      t->bn[r] += 2 * t->b_dx;
   }
}

/* The quad row's range events into the context's counters. */
static inline void tex_end(struct rast_context *rc, struct rast_front *fr)
{
   struct fr_tex *t = &fr->tex;
   rc->stats.tex_sat += t->st.sat + t->dst.sat;
   rc->stats.tex_flush += t->st.flush + t->dst.flush;
   t->st.sat = t->st.flush = t->dst.sat = t->dst.flush = 0;
   rc->stats.skip_persp_w += t->n_const_w;
   rc->stats.skip_persp_comp += t->n_const_comp;
   rc->stats.skip_persp_terms += t->n_zero_terms_quads;
   rc->stats.persp_quads += t->n_divided;
   rc->stats.persp_comp_quads += t->n_divided * fr->npersp;
   t->n_const_w = t->n_const_comp = t->n_zero_terms_quads = t->n_divided = 0;
}

#endif
