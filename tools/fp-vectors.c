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
#include "verify/vectors_replay.h"

int main(int argc, char **argv)
{
   if (argc != 2 || argv[1][0] == '-') {
      fprintf(stderr, "usage: fp-vectors DIR   (the vectors FIXPIPE_VECTORS=DIR wrote)\n");
      return 2;
   }
   struct rast_vectors_counts n;
   long bad = rast_vectors_replay(argv[1], stderr, &n);
   if (bad < 0)
      return 2;
   if (n.triangles == 0 && n.tex_quads == 0) {
      fprintf(stderr, "fp-vectors: %s: nothing recorded\n", argv[1]);
      return 1;
   }
   printf("fp-vectors: %s: %" PRIu64 " triangles, %" PRIu64 " quads; texture unit: %" PRIu64
          " bindings, %" PRIu64 " quads; ", argv[1], n.triangles, n.quads, n.tex_bindings,
          n.tex_quads);
   if (bad) {
      printf("%ld differ\n", bad);
      return 1;
   }
   printf("every output bit equal\n");
   return 0;
}
