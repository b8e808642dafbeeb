/*
 * fp-vectors: replays the scan-converter unit's RTL test vectors
 * (FIXPIPE_VECTORS=DIR, docs/vectors.md) through the model and checks every
 * output bit.
 *
 *   fp-vectors DIR
 *
 * Prints "fp-vectors: DIR: N triangles, M quads, every output bit equal" and
 * exits 0; on a difference, the first ones and exit 1; 2 if DIR cannot be
 * read.
 */
#include <inttypes.h>
#include <stdio.h>

#include "rast/rast.h"

int main(int argc, char **argv)
{
   if (argc != 2 || argv[1][0] == '-') {
      fprintf(stderr, "usage: fp-vectors DIR   (the vectors FIXPIPE_VECTORS=DIR wrote)\n");
      return 2;
   }
   uint64_t tris = 0, quads = 0;
   long bad = rast_vectors_replay(argv[1], stderr, &tris, &quads);
   if (bad < 0)
      return 2;
   if (tris == 0) {
      fprintf(stderr, "fp-vectors: %s: no triangle recorded\n", argv[1]);
      return 1;
   }
   if (bad) {
      printf("fp-vectors: %s: %" PRIu64 " triangles, %" PRIu64 " quads, %ld differ\n", argv[1],
             tris, quads, bad);
      return 1;
   }
   printf("fp-vectors: %s: %" PRIu64 " triangles, %" PRIu64 " quads, every output bit equal\n",
          argv[1], tris, quads);
   return 0;
}
