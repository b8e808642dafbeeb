/*
 * The instruction set of the lanes, chosen once per process from the CPU.
 */
#include "rast/lanes.h"

static const struct rast_lanes *chosen;

const struct rast_lanes *rast_lanes(void)
{
   if (!chosen) {
      __builtin_cpu_init();
      chosen = __builtin_cpu_supports("avx2") ? &rast_lanes_avx2 : &rast_lanes_sse2;
   }
   return chosen;
}

void rast_lanes_set(const struct rast_lanes *set)
{
   chosen = set;
}
