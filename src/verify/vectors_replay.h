/*
 * The replay of RTL test vectors (vectors_replay.c): verification that
 * tools and tests link, not part of the model or the driver.
 */
#ifndef VERIFY_VECTORS_REPLAY_H
#define VERIFY_VECTORS_REPLAY_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "rast/rast.h"

struct rast_tri_regs;
struct rast_vec_quad;

/* Replays DIR's vectors through a new context and texture units: every
 * quad's bits compared with the recorded ones; the first differences
 * described on log.  Returns the mismatches (0: every output bit equal), -1
 * if the vectors cannot be read; what was replayed in *counts. */
struct rast_vectors_counts {
   uint64_t triangles, quads, tex_bindings, tex_quads;
};
long rast_vectors_replay(const char *dir, FILE *log, struct rast_vectors_counts *counts);

/* The reading it is built of, for other checks of the same files: DIR's
 * scan.txt (its profile parsed; false, said on log, when it cannot be read
 * or its records are not the sizes this code reads), then one record of
 * scan.in.hex or scan.out.hex at a time (false at the end). */
struct rast_vectors_header {
   char profile[200], interp[32], texfmt[32];
   struct rast_profile_buf profile_buf;
};
bool rast_vectors_read_header(const char *dir, struct rast_vectors_header *h, FILE *log);
bool rast_vectors_read_triangle(FILE *f, struct rast_tri_regs *t);
bool rast_vectors_read_quad(FILE *f, struct rast_vec_quad *r);

#endif
