/* The lane functions of one instruction set (lanes_table.c's entries). */
#ifndef FIXPIPE_LANES_FNS_H
#define FIXPIPE_LANES_FNS_H

#include "rast/host/lanes.h"

void LANES_FN(persp_dfx19_lanes)(struct rast_front *fr, struct rast_quad *q);
void LANES_FN(persp2_dfx19_lanes)(struct rast_front *fr, float *in0, float *in1);
void LANES_FN(persp4_dfx19_lanes)(struct rast_front *fr, float *const in[4]);
bool LANES_FN(persp3_dfx19_lanes)(struct rast_front *fr, float *const in[3]);
bool LANES_FN(persp4_probe_dfx19_lanes)(struct rast_front *fr, float *const in[4],
                                        const int64_t (*num)[4]);
void LANES_FN(persp_group_dfx19_lanes)(struct rast_front *fr, float *const in[],
                                       const int64_t (*num)[4], unsigned n);
bool LANES_FN(planes_dfx19_lanes)(const float *const vtx[3], unsigned p0, unsigned n,
                                  int64_t det, unsigned k, double (*lv)[3], double *lrdet);
tex_quad_fn LANES_FN(tex_dfx19_2d_lanes)(const struct tex_unit *u, bool noskip, bool nolod,
                                        tex_quad2_fn *pair, tex_quad4_fn *four);
rast_c8_group_fn LANES_FN(c8_group_lanes)(enum rast_color_layout layout, bool blend);
rast_zgroup_fn LANES_FN(zgroup_lanes)(enum rast_func func, bool write);

/* The AVX2 set's, which the 512-bit one takes for a lone quad. */
void persp_dfx19_lanes_avx2(struct rast_front *fr, struct rast_quad *q);
void persp_group_dfx19_lanes_avx2(struct rast_front *fr, float *const in[],
                                  const int64_t (*num)[4], unsigned n);
tex_quad_fn tex_dfx19_2d_lanes_avx2(const struct tex_unit *u, bool noskip, bool nolod,
                                    tex_quad2_fn *pair, tex_quad4_fn *four);

#endif
