/*
 * Counters by name through GL_AMD_performance_monitor: Mesa exposes a
 * driver's queries there (fixpipe's: docs/cycles.md).  For fp-demo's
 * modeled-chip time and the e2e test of the queries.
 */
#ifndef FP_PERFMON_H
#define FP_PERFMON_H

#include <stdbool.h>

struct fp_perfmon;

/* A monitor of the n counters named (in any group); NULL, with the reason
 * in why, when the extension or a counter is missing (other drivers). */
struct fp_perfmon *fp_perfmon_open(const char *const *names, unsigned n, const char **why);
void fp_perfmon_begin(struct fp_perfmon *m);
/* Ends the monitor and reads every counter (after glFinish), in the order
 * of the names; false when a result is missing. */
bool fp_perfmon_end(struct fp_perfmon *m, double *values);
void fp_perfmon_close(struct fp_perfmon *m);

#endif
