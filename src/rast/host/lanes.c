/*
 * The instruction set of the lanes, chosen once per process from the CPU.
 */
#include <stdatomic.h>

#include "rast/host/lanes.h"

/* Atomic: the first validation may run on several threads at once (a
 * context's first batch drawn on all of them); each finds the same set. */
static const struct rast_lanes *_Atomic chosen;

const struct rast_lanes *rast_lanes(void)
{
   const struct rast_lanes *set = atomic_load_explicit(&chosen, memory_order_acquire);
   if (!set) {
      __builtin_cpu_init();
      set = rast_lanes_have_avx512()         ? &rast_lanes_avx512
            : __builtin_cpu_supports("avx2") ? &rast_lanes_avx2
                                             : &rast_lanes_sse2;
      atomic_store_explicit(&chosen, set, memory_order_release);
   }
   return set;
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
   atomic_store_explicit(&chosen, set, memory_order_release);
}
