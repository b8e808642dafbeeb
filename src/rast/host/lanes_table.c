/*
 * One instruction set's table of lane functions (see lanes.h): this file
 * is compiled once per set, with LANES_SUFFIX naming it.
 */
#include "rast/host/lanes.h"
#include <stddef.h>
#include "rast/host/lanes_fns.h"

#define LANES_STR2(x) #x
#define LANES_STR(x) LANES_STR2(x)

const struct rast_lanes LANES_GLUE(rast_lanes, LANES_SUFFIX) = {
   .isa = &LANES_STR(LANES_SUFFIX)[1],     /* without the leading _ */
#if defined(DFXL_N) && DFXL_N == 8
   /* a lone quad fills half a vector: the 256-bit set's */
   .persp_dfx19 = persp_dfx19_lanes_avx2,
#else
   .persp_dfx19 = LANES_FN(persp_dfx19_lanes),
#endif
   .persp2_dfx19 = LANES_FN(persp2_dfx19_lanes),
   .persp_group_dfx19 = LANES_FN(persp_group_dfx19_lanes),
   .planes_dfx19 = LANES_FN(planes_dfx19_lanes),
#if defined(DFXL_N) && DFXL_N == 8
   .persp4_dfx19 = LANES_FN(persp4_dfx19_lanes),
   .persp3_dfx19 = LANES_FN(persp3_dfx19_lanes),
   .persp4_probe_dfx19 = LANES_FN(persp4_probe_dfx19_lanes),
   .tex_group = 4,
#else
   .tex_group = 2,
#endif
   .tex_dfx19_2d = LANES_FN(tex_dfx19_2d_lanes),
   .c8_group = LANES_FN(c8_group_lanes),
   .zgroup = LANES_FN(zgroup_lanes),
};
