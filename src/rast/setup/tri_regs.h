/*
 * A triangle's registers as set-up holds them after the snap to the
 * sub-pixel grid (seed 000): its flags, its pass's origin and clip, the
 * fixed-point X, Y, Z and colours of its vertices, 1/w and the perspective
 * components' A/w.  rast_setup_from_registers runs the unit from them on,
 * as from a triangle the model snapped itself: the verification library
 * (src/verify) replays recorded RTL vectors through it.
 */
#ifndef RAST_TRI_REGS_H
#define RAST_TRI_REGS_H

#include "rast/rast_priv.h"

#define RAST_REGS_MAX_COLOR 8        /* colour components */
#define RAST_REGS_MAX_PERSP 16       /* perspective components (the division's) */

struct rast_tri_regs {
   bool half_pixel, bottom_rule, front_ccw;
   bool front;                        /* the cull's result: facing front */
   unsigned ncolor;
   int64_t org_x, org_y;
   struct rast_scissor clip;
   int64_t X[3], Y[3], Z[3];
   float oow[3];
   uint8_t var[RAST_REGS_MAX_COLOR], chan[RAST_REGS_MAX_COLOR];
   int64_t color[RAST_REGS_MAX_COLOR][3];
   /* the perspective division's: A/w of each component at each vertex */
   unsigned npersp;
   uint8_t pvar[RAST_REGS_MAX_PERSP], pchan[RAST_REGS_MAX_PERSP];
   bool pcolor[RAST_REGS_MAX_PERSP];        /* divided in binary32: COLOR (wide), array layer */
   float aw[RAST_REGS_MAX_PERSP][3];
};

/* Set-up, the perspective division's set-up and the scan conversion of
 * one triangle from its registers. */
void rast_setup_from_registers(struct rast_context *rc, const struct rast_tri_regs *t);

#endif
