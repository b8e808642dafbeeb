/*
 * RTL test vectors of the scan-converter unit (vectors.c, docs/vectors.md):
 * the records as the model holds them, and the hooks of setup.c and the
 * back end.  Public entry points are in rast.h.
 */
#ifndef RAST_VECTORS_H
#define RAST_VECTORS_H

#include "rast/rast_priv.h"

struct rast_front;

#define VEC_MAX_COLOR 8        /* colour components a record holds */
#define VEC_MAX_PERSP 16       /* perspective components (the division's) */
/* 64-bit words a triangle: the scan converter's, then the division's (its
 * map, A/w at the vertices, then its set-up's registers: the reciprocal of
 * the determinant and the planes of 1/w and of each component) */
#define VEC_IN_SCAN (16 + 3 * VEC_MAX_COLOR)
#define VEC_IN_PLANES (VEC_IN_SCAN + 2 + 3 * VEC_MAX_PERSP)
#define VEC_IN_WORDS (VEC_IN_PLANES + 1 + 3 * (1 + VEC_MAX_PERSP))
/* and a quad: the scan converter's, the divided values as binary32, then
 * as the number system's words */
#define VEC_OUT_SCAN (8 + 2 * VEC_MAX_COLOR)
#define VEC_OUT_WORDS (VEC_OUT_SCAN + 4 * VEC_MAX_PERSP)

/* A triangle entering the unit: its flags, its pass's origin and clip, and
 * the registers of its three vertices. */
struct rast_vec_tri {
   bool half_pixel, bottom_rule, front_ccw;
   unsigned ncolor;
   int64_t org_x, org_y;
   struct rast_scissor clip;
   int64_t X[3], Y[3], Z[3];
   float oow[3];
   uint8_t var[VEC_MAX_COLOR], chan[VEC_MAX_COLOR];
   int64_t color[VEC_MAX_COLOR][3];
   /* the perspective division's: A/w of each component at each vertex */
   unsigned npersp;
   uint8_t pvar[VEC_MAX_PERSP], pchan[VEC_MAX_PERSP];
   bool pcolor[VEC_MAX_PERSP];        /* divided in binary32: COLOR (wide), array layer */
   float aw[VEC_MAX_PERSP][3];
};

/* A quad leaving it (compared byte for byte: built zeroed). */
struct rast_vec_quad {
   uint32_t tri;
   unsigned mask;
   bool front;
   int32_t x, y;
   int64_t z[RAST_QUAD_SIZE];
   uint32_t w[RAST_QUAD_SIZE];                       /* 1/w, binary32 bits */
   uint32_t color[VEC_MAX_COLOR][RAST_QUAD_SIZE];    /* as the shader gets them */
   uint32_t persp[VEC_MAX_PERSP][RAST_QUAD_SIZE];    /* divided, as the shader gets them */
   uint32_t pword[VEC_MAX_PERSP][RAST_QUAD_SIZE];    /* the same as dfx words (dfx systems) */
};

/* setup.c, in rast_triangle_pass: the triangle's input registers, once set
 * up (after the cull: front is its facing). */
void rast_vec_triangle(struct rast_context *rc, const struct rast_front *fr, bool front);
/* rast_backend_validate: the quad function wrapped while vectors are on. */
void rast_vec_wrap_backend(struct rast_context *rc);
/* setup.c: the unit from a record's registers on (the replay). */
void rast_vec_replay_triangle(struct rast_context *rc, const struct rast_vec_tri *t);

#endif
