/*
 * The FIXPIPE_* environment variables into struct fp_options: the driver's
 * one reader of the environment.  Read once per process: a screen is
 * created for every display, and a bad value should be reported once.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/u_call_once.h"
#include "util/u_debug.h"
#include "util/u_cpu_detect.h"
#include "pipe/p_format.h"
#include "fp_screen.h"
#include "fixed/numsys.h"
#include "rast/host/settings.h"
#include "rast/instruments/cycles.h"

static struct fp_options env;

static const struct debug_named_value fp_debug_flags[] = {
   { "nojit", FP_DEBUG_NOJIT,
     "interpret every shader (tgsi_exec; draw's vertex shaders without LLVM)" },
   { "jitall", FP_DEBUG_JITALL,
     "compile every shader at its first draw instead of once it is hot" },
   { "scalar", FP_DEBUG_SCALAR,
     "the model's scalar reference datapath instead of its lanes, gathers on the texture unit's table path (same bits)" },
   { "noskip", FP_DEBUG_NOSKIP,
     "compute everything the model's skips leave out (same bits)" },
   { "nothreads", FP_DEBUG_NOTHREADS,
     "the model on one thread whatever FIXPIPE_THREADS says (same bits)" },
   { "norebase", FP_DEBUG_NOREBASE,
     "no per-primitive rebase of REPEAT texture coordinates (large ones lose bits)" },
   { "noavx512", FP_DEBUG_NOAVX512,
     "the lanes' 256-bit instruction set where the CPU has AVX-512 (same bits)" },
   { "serialclear", FP_DEBUG_SERIALCLEAR,
     "large clears filled by the calling thread alone, not divided between the threads" },
   { "nof32", FP_DEBUG_NOF32,
     "the perspective division on binary64 lanes only, not four quads on binary32 lanes (same bits)" },
   { "divideall", FP_DEBUG_DIVIDEALL,
     "every batch of primitives divided between the threads, however small (same bits; the thread identity test)" },
   { "nojitgather", FP_DEBUG_NOJITGATHER,
     "compiled shaders' gathers call the texture unit's C functions, not its copy in the compiled code (same bits)" },
   DEBUG_NAMED_VALUE_END
};

/* debug_get_flags_option ignores names it does not know: say so, once. */
static void fp_env_check_flags(const char *var, const char *value,
                               const struct debug_named_value *flags)
{
   if (!value || !strcmp(value, "help"))
      return;
   char buf[256];
   snprintf(buf, sizeof(buf), "%s", value);
   for (char *save = NULL, *tok = strtok_r(buf, ", ", &save); tok;
        tok = strtok_r(NULL, ", ", &save)) {
      bool known = false;
      for (const struct debug_named_value *f = flags; f->name; f++)
         known |= !strcmp(tok, f->name);
      if (known)
         continue;
      fprintf(stderr, "fixpipe: unknown %s flag '%s' (accepted:", var, tok);
      for (const struct debug_named_value *f = flags; f->name; f++)
         fprintf(stderr, " %s", f->name);
      fprintf(stderr, ", help); ignored\n");
   }
}

static const char vectors_keys[] =
   "frames=A-B with A <= B, frames counted from 0 by presents, and units=scan, tex or scan+tex";

static bool vectors_option(void *ctx, const char *key, const char *val, char *err, size_t errlen)
{
   struct fp_vectors_option *v = ctx;
   char *end;
   if (!strcmp(key, "frames")) {
      v->first = strtoul(val, &end, 10);
      if (end != val && *end == '-') {
         const char *b = end + 1;
         v->last = strtoul(b, &end, 10);
         if (end != b && !*end && v->first <= v->last)
            return true;
      }
   } else if (!strcmp(key, "units")) {
      v->units = 0;
      for (const char *u = val; *u;) {
         const size_t n = strcspn(u, "+");
         if (n == 4 && !strncmp(u, "scan", 4))
            v->units |= RAST_VEC_SCAN;
         else if (n == 3 && !strncmp(u, "tex", 3))
            v->units |= RAST_VEC_TEX;
         else
            break;
         u += n;
         if (*u == '+' && *++u == '\0')
            break;
         if (!*u)
            return true;
      }
   } else {
      snprintf(err, errlen, "unknown key '%s' (accepted: %s)", key, vectors_keys);
      return false;
   }
   snprintf(err, errlen, "%s=%s (accepted: %s)", key, val, vectors_keys);
   return false;
}

/* A number system named by the variable `var`, `fallback` when it is unset or
 * unknown (reported once, with the accepted names). */
static const struct numsys *numsys_from_env(const char *var, const struct numsys *fallback)
{
   const char *v = getenv(var);
   if (!v || !*v)
      return fallback;
   const struct numsys *ns = numsys_by_name(v);
   if (!ns)
      fprintf(stderr, "fixpipe: unknown %s '%s' (accepted: %s); using %s\n", var, v,
              numsys_names(), fallback->name);
   return ns ? ns : fallback;
}

/* DIR[,KEY=VALUE,...], the form of FIXPIPE_VECTORS and FIXPIPE_EVENTS: the
 * directory into dir (1 to dir_size - 1 characters), then each key through
 * fn; false with the reason in err. */
static bool parse_dir_setting(const char *value, char *dir, size_t dir_size,
                              const char *keys, rast_setting_fn fn, void *ctx,
                              char *err, size_t errlen)
{
   const char *comma = strchr(value, ',');
   const size_t dlen = comma ? (size_t)(comma - value) : strlen(value);
   snprintf(err, errlen, "a directory of 1 to %zu characters first, then optionally %s",
            dir_size - 1, keys);
   if (dlen == 0 || dlen >= dir_size)
      return false;
   memcpy(dir, value, dlen);
   dir[dlen] = '\0';
   return !comma || rast_settings_each(comma + 1, keys, fn, ctx, err, errlen);
}

static const char events_keys[] = "frames=A-B with A <= B, frames counted from 0 by presents";

static bool events_option(void *ctx, const char *key, const char *val, char *err, size_t errlen)
{
   struct fp_events_option *e = ctx;
   char *end;
   if (!strcmp(key, "frames")) {
      e->first = strtoul(val, &end, 10);
      if (end != val && *end == '-' && val[0] >= '0' && val[0] <= '9') {
         const char *b = end + 1;
         e->last = strtoul(b, &end, 10);
         if (end != b && !*end && b[0] >= '0' && b[0] <= '9' && e->first <= e->last)
            return true;
      }
      snprintf(err, errlen, "%s=%s (accepted: %s)", key, val, events_keys);
      return false;
   }
   snprintf(err, errlen, "unknown key '%s' (accepted: %s)", key, events_keys);
   return false;
}

static void fp_env_parse(void)
{
   /* FIXPIPE_PROFILE=NAME[:KEY=VALUE,...] (docs/profiles.md) */
   const char *p = getenv("FIXPIPE_PROFILE");
   env.profile = rast_profile_by_name("seed");
   if (p && *p) {
      static struct rast_profile_buf custom;
      char err[256];
      if (rast_profile_parse(p, &custom, err, sizeof(err)))
         env.profile = &custom.p;
      else
         fprintf(stderr, "fixpipe: bad FIXPIPE_PROFILE '%s': %s; using seed\n", p, err);
   }

   const char *s = getenv("FIXPIPE_STATS");
   if (s && *s) {
      char *end;
      if (!strcmp(s, "1")) {
         env.stats = true;
      } else if (!strncmp(s, "frames:", 7) && s[7] >= '1' && s[7] <= '9' &&
                 (env.stats_frames = strtoul(s + 7, &end, 10), !*end)) {
         env.stats = true;
      } else if (strcmp(s, "0")) {
         env.stats_frames = 0;
         fprintf(stderr, "fixpipe: bad FIXPIPE_STATS '%s' (accepted: 0, 1, frames:N with N >= 1); "
                 "using 0\n", s);
      }
   }

   const char *d = getenv("FIXPIPE_DEBUG");
   env.debug = (unsigned)debug_get_flags_option("FIXPIPE_DEBUG", fp_debug_flags, 0);
   fp_env_check_flags("FIXPIPE_DEBUG", d, fp_debug_flags);

   /* FIXPIPE_THREADS, like LP_NUM_THREADS: the cores by default */
   unsigned cores = util_get_cpu_caps()->nr_cpus;
   env.threads = cores < 1 ? 1 : cores > RAST_MAX_THREADS ? RAST_MAX_THREADS : cores;
   const char *n = getenv("FIXPIPE_THREADS");
   if (n && *n) {
      char *end;
      unsigned long v = strtoul(n, &end, 10);
      if (*end || n[0] < '0' || n[0] > '9' || v < 1 || v > RAST_MAX_THREADS)
         fprintf(stderr, "fixpipe: bad FIXPIPE_THREADS '%s' (accepted: 1 to %u); using %u\n",
                 n, RAST_MAX_THREADS, env.threads);
      else
         env.threads = (unsigned)v;
   }

   /* FIXPIPE_INTERP=MODE[:error] (docs/interp-modes.md) */
   const char *im = getenv("FIXPIPE_INTERP");
   env.interp = RAST_INTERP_SCANLINE;
   if (im && *im) {
      char mode[32];
      const char *colon = strchr(im, ':');
      const size_t len = colon ? (size_t)(colon - im) : strlen(im);
      bool ok = len < sizeof(mode) && (!colon || !strcmp(colon, ":error"));
      unsigned m = 0;
      if (ok) {
         memcpy(mode, im, len);
         mode[len] = '\0';
         for (m = 0; rast_interp_name((enum rast_interp_mode)m); m++)
            if (!strcmp(mode, rast_interp_name((enum rast_interp_mode)m)))
               break;
         ok = rast_interp_name((enum rast_interp_mode)m) != NULL;
      }
      if (ok)
         env.interp = m | (colon ? RAST_INTERP_MEASURE : 0u);
      else
         fprintf(stderr, "fixpipe: bad FIXPIPE_INTERP '%s' (accepted: scanline, barycentric, "
                 "vector, each optionally with :error); using scanline\n", im);
   }

   /* FIXPIPE_VECTORS=DIR[,frames=A-B][,units=scan+tex] (docs/vectors.md) */
   const char *vec = getenv("FIXPIPE_VECTORS");
   if (vec && *vec) {
      struct fp_vectors_option v = { .first = 0, .last = ~0ul,
                                      .units = RAST_VEC_SCAN | RAST_VEC_TEX };
      char verr[384];
      bool ok = parse_dir_setting(vec, v.dir, sizeof(v.dir), vectors_keys, vectors_option, &v,
                                  verr, sizeof(verr));
      if (ok)
         env.vectors = v;
      else
         fprintf(stderr, "fixpipe: bad FIXPIPE_VECTORS '%s': %s; no vectors written\n", vec,
                 verr);
   }

   /* FIXPIPE_EVENTS=DIR[,frames=A-B] (docs/events.md) */
   const char *ev = getenv("FIXPIPE_EVENTS");
   if (ev && *ev) {
      struct fp_events_option e = { .first = 0, .last = ~0ul };
      char eerr[384];
      bool ok = parse_dir_setting(ev, e.dir, sizeof(e.dir), events_keys, events_option, &e,
                                  eerr, sizeof(eerr));
      if (ok && env.vectors.dir[0]) {
         ok = false;
         snprintf(eerr, sizeof(eerr), "not with FIXPIPE_VECTORS, which records alone");
      }
      if (ok)
         env.events = e;
      else
         fprintf(stderr, "fixpipe: bad FIXPIPE_EVENTS '%s': %s; nothing recorded\n", ev, eerr);
   }

   /* FIXPIPE_CYCLES=KEY=VALUE,... over the cycle model's defaults (docs/cycles.md) */
   const char *cy = getenv("FIXPIPE_CYCLES");
   char cerr[256];
   if (!rast_cycle_params_parse(cy, &env.cycles, cerr, sizeof(cerr)))
      fprintf(stderr, "fixpipe: bad FIXPIPE_CYCLES '%s': %s; using the defaults\n", cy, cerr);

   env.texfmt = numsys_from_env("FIXPIPE_TEXFMT", numsys_default());
   env.perspfmt = numsys_from_env("FIXPIPE_PERSPFMT", env.texfmt);
}

static util_once_flag env_once = UTIL_ONCE_FLAG_INIT;

const struct fp_options *fp_options_from_env(void)
{
   util_call_once(&env_once, fp_env_parse);
   return &env;
}

unsigned fp_options_threads(const struct fp_options *o)
{
   return o->debug & FP_DEBUG_NOTHREADS || o->vectors.dir[0] ? 1 : o->threads;
}

unsigned fp_options_rast(const struct fp_options *o)
{
   const unsigned d = o->debug;
   return (d & FP_DEBUG_SCALAR ? RAST_OPT_SCALAR : 0u) | (d & FP_DEBUG_NOSKIP ? RAST_OPT_NOSKIP : 0u) |
          (d & FP_DEBUG_NOF32 ? RAST_OPT_NOF32 : 0u) |
          (d & FP_DEBUG_DIVIDEALL ? RAST_OPT_DIVIDE : 0u);
}
