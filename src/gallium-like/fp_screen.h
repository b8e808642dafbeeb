#ifndef FP_SCREEN_H
#define FP_SCREEN_H

#include "pipe/p_screen.h"
#include "util/u_call_once.h"
#include "util/simple_mtx.h"
#include "rast/rast.h"
#include "rast/instruments/cycles.h"

struct sw_winsys;
struct disk_cache;

#define FP_MAX_FRONTS 16
struct fp_screen {
   struct pipe_screen base;
   struct sw_winsys *winsys;
   /* compiled fragment shaders (fp_jit_fs.c), opened at the first
    * compilation: fp_screen_disk_cache(); NULL: none */
   struct disk_cache *disk_cache;
   util_once_flag disk_cache_once;
   const struct fp_options *opts;
   const struct rast_profile *profile;   /* opts->profile */
   char name[128];
   /* frames presented by any context (flush_frontbuffer): a process that
    * presents is a real-time program, whose shaders are hot sooner
    * (fp_jit_hot_loop) */
   uint64_t frames_presented;
   /* the windows' front buffers (fp_resource_presented) */
   simple_mtx_t fronts_lock;
   struct fp_resource *fronts[FP_MAX_FRONTS];
};

static inline struct fp_screen *fp_screen(struct pipe_screen *s)
{
   return (struct fp_screen *)s;
}

/* The on-disk shader cache, opened at the first call (NULL: none). */
struct disk_cache *fp_screen_disk_cache(struct fp_screen *s);

/* FIXPIPE_DEBUG: flags in Mesa's style (FIXPIPE_DEBUG=help lists them) */
#define FP_DEBUG_NOJIT   (1u << 0)   /* interpret every shader: tgsi_exec, draw without LLVM */
#define FP_DEBUG_JITALL  (1u << 1)   /* compile shaders at first use, not once hot */
#define FP_DEBUG_SCALAR  (1u << 2)   /* the model's scalar reference datapath, no lanes */
#define FP_DEBUG_NOSKIP  (1u << 3)   /* compute what the model's skips leave out */
#define FP_DEBUG_NOTHREADS (1u << 4) /* the model on one thread, whatever FIXPIPE_THREADS says */
#define FP_DEBUG_NOREBASE (1u << 5)  /* no coordinate rebase in the set-up (docs/texture-unit.md) */
#define FP_DEBUG_NOAVX512 (1u << 6)  /* the 256-bit lanes where the CPU has 512-bit ones */
#define FP_DEBUG_SERIALCLEAR (1u << 7) /* large clears filled by the calling thread alone */
#define FP_DEBUG_NOF32   (1u << 8)   /* the division's four quads on binary64 lanes, not binary32 */
#define FP_DEBUG_NOJITGATHER (1u << 9) /* compiled gathers call the texture unit's C functions */
#define FP_DEBUG_DIVIDEALL (1u << 10)  /* every batch divided between the threads */

struct numsys;
struct fp_vectors_option {
   char dir[480];                 /* "" when unset or bad */
   unsigned long first, last;     /* frames presented before, inclusive */
   unsigned units;                /* RAST_VEC_* */
};

/* FIXPIPE_EVENTS=DIR[,frames=A-B] (docs/events.md) */
struct fp_events_option {
   char dir[480];                 /* "" when unset or bad */
   unsigned long first, last;     /* frames presented before, inclusive */
};

/* The FIXPIPE_* variables (README.md, docs/), parsed once per process by
 * fp_options_from_env, the one reader of the environment, at the first
 * screen's creation; bad values are reported there, once, with the
 * accepted values.  The screen and every context hold a pointer. */
struct fp_options {
   const struct rast_profile *profile;   /* FIXPIPE_PROFILE */
   bool stats;                           /* FIXPIPE_STATS */
   unsigned long stats_frames;           /* FIXPIPE_STATS=frames:N, else 0 */
   unsigned debug;                       /* FIXPIPE_DEBUG: FP_DEBUG_* */
   unsigned threads;                     /* FIXPIPE_THREADS: 1..RAST_MAX_THREADS */
   unsigned interp;                      /* FIXPIPE_INTERP: rast_set_interp's mode */
   const struct numsys *texfmt;          /* FIXPIPE_TEXFMT: the texture unit */
   /* FIXPIPE_PERSPFMT: the perspective division's, FIXPIPE_TEXFMT's unless
    * set, so that a report can tell the two units' precision apart */
   const struct numsys *perspfmt;
   struct rast_cycle_params cycles;      /* FIXPIPE_CYCLES */
   struct fp_vectors_option vectors;     /* FIXPIPE_VECTORS */
   struct fp_events_option events;       /* FIXPIPE_EVENTS */
};
const struct fp_options *fp_options_from_env(void);
/* The model's RAST_OPT_* the debug flags select. */
unsigned fp_options_rast(const struct fp_options *o);
/* The model's threads: one under nothreads, or while vectors are recorded
 * (in the unit's order). */
unsigned fp_options_threads(const struct fp_options *o);

/* Render-target formats the driver can pack from float (fp_format.c). */
bool fp_format_renderable(enum pipe_format format);
bool fp_format_depth_supported(enum pipe_format format);
bool fp_format_samplable(enum pipe_format format);

#endif
