/*
 * The replay of RTL test vectors (vectors_replay.c): verification that
 * tools and tests link, not part of the model or the driver.
 */
#ifndef VERIFY_VECTORS_REPLAY_H
#define VERIFY_VECTORS_REPLAY_H

#include <stdint.h>
#include <stdio.h>

/* Replays DIR's vectors through a new context and texture units: every
 * quad's bits compared with the recorded ones; the first differences
 * described on log.  Returns the mismatches (0: every output bit equal), -1
 * if the vectors cannot be read; what was replayed in *counts. */
struct rast_vectors_counts {
   uint64_t triangles, quads, tex_bindings, tex_quads;
};
long rast_vectors_replay(const char *dir, FILE *log, struct rast_vectors_counts *counts);

#endif
