/*
 * The instruction set of the lanes, chosen once per process from the CPU.
 */
#include "rast/lanes.h"

static const struct rast_lanes *chosen;

const struct rast_lanes *rast_lanes(void)
{
   if (!chosen) {
      __builtin_cpu_init();
      chosen = rast_lanes_have_avx512()         ? &rast_lanes_avx512
               : __builtin_cpu_supports("avx2") ? &rast_lanes_avx2
                                                : &rast_lanes_sse2;
   }
   return chosen;
}

bool rast_lanes_have_avx512(void)
{
   __builtin_cpu_init();
   return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
          __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512bw") &&
          __builtin_cpu_supports("avx2");
}

void rast_lanes_set(const struct rast_lanes *set)
{
   chosen = set;
}
