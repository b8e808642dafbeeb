/*
 * RTL test vectors of the scan-converter unit (vectors.c, docs/vectors.md):
 * the records as the model holds them (a triangle's are set-up's registers,
 * setup/tri_regs.h), and what the replay (src/verify) shares with the recorder.  Public entry
 * points are in rast.h.
 */
#ifndef RAST_VECTORS_H
#define RAST_VECTORS_H

#include "rast/rast_priv.h"
#include "rast/setup/tri_regs.h"

struct rast_front;

#define VEC_MAX_COLOR RAST_REGS_MAX_COLOR
#define VEC_MAX_PERSP RAST_REGS_MAX_PERSP
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

/* The replay's side (src/verify): every quad's record handed to check, the
 * triangle index set before each triangle; rast_vectors_close ends it. */
typedef void (*rast_vec_check_fn)(void *ctx, const struct rast_vec_quad *r);
bool rast_vectors_check_open(struct rast_context *rc, rast_vec_check_fn check, void *ctx);
void rast_vectors_check_triangle(struct rast_context *rc, uint64_t index);

/* The files' words, shared by the recorder and the replay. */
/* binding and control, 48 binary32 inputs, then s, t, r as the unit's
 * coordinate registers hold them */
#define VEC_TEX_IN_WORDS 31
#define VEC_TEX_OUT_WORDS 8     /* 16 binary32 outputs */
struct tex_unit;
uint32_t rast_vec_fbits(float f);
float rast_vec_bitsf(uint32_t u);
uint64_t rast_vec_two(float a, float b);
void rast_vec_words_to_quad(const uint64_t w[VEC_OUT_WORDS], struct rast_vec_quad *r);
/* pixels 0, 1 (a) and 2, 3 (b) of a coordinate as the unit's register */
void rast_vec_coord_words(const struct tex_unit *u, const float c[4], uint64_t *a, uint64_t *b);

#endif
