/*
 * The scan-converter unit's RTL test vectors (vectors.c, docs/vectors.md):
 * random triangles with Z and four colour registers (and a perspective
 * varying, which is not the unit's) recorded on a target of 4096 x 4096,
 * which the seed profile draws in tiles; the replay must reproduce every
 * output bit, and must fail once one bit of the outputs is flipped.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "tutil.h"

#define W 4096
#define H 4096

static void draw_some(struct tctx *t, int n)
{
   for (int i = 0; i < n; i++) {
      float v[3][3][4];
      /* every fifth across the tiles' borders at 2048 */
      const bool across = i % 5 == 0;
      const double cx = across ? 2048.0 + (t_rand() - 0.5) * 100.0 : t_rand() * W;
      const double cy = across ? 2048.0 + (t_rand() - 0.5) * 100.0 : t_rand() * H;
      const double r = across ? 300.0 : 40.0;
      for (int k = 0; k < 3; k++) {
         v[k][0][0] = (float)(cx + (t_rand() - 0.5) * r);
         v[k][0][1] = (float)(cy + (t_rand() - 0.5) * r);
         v[k][0][2] = (float)t_rand();
         v[k][0][3] = (float)(0.25 + t_rand());
         for (int c = 0; c < 4; c++) {
            v[k][1][c] = (float)t_rand();
            v[k][2][c] = (float)(t_rand() * 8.0);
         }
      }
      t_begin(t);
      rast_triangle(t->rc, T_V(v[0]), T_V(v[1]), T_V(v[2]));
   }
}

/* Flips bit 0 of the first Z word of the n-th quad record. */
static bool flip_one_bit(const char *path, int n)
{
   FILE *f = fopen(path, "r+");
   if (!f)
      return false;
   char line[64], tag[32];
   snprintf(tag, sizeof(tag), "// quad %d\n", n);
   bool done = false;
   for (long pos = 0; fgets(line, sizeof(line), f); pos = ftell(f)) {
      if (strcmp(line, tag))
         continue;
      /* the record's words: 0 (triangle, mask), 1 (x, y), 2 (Z of pixel 0) */
      for (int w = 0; w < 3; w++) {
         pos = ftell(f);
         if (!fgets(line, sizeof(line), f))
            break;
      }
      unsigned long long z = strtoull(line, NULL, 16) ^ 1u;
      fseek(f, pos, SEEK_SET);
      fprintf(f, "%016llx", z);
      done = true;
      break;
   }
   fclose(f);
   return done;
}

int main(void)
{
   char dir[] = "/tmp/fixpipe-vectors-XXXXXX";
   CHECK(mkdtemp(dir) != NULL, "cannot make a temporary directory");
   struct tctx t;
   t_init(&t, "seed", W, H);
   struct rast_vertex_layout vl;
   memset(&vl, 0, sizeof vl);
   vl.vertex_size = 3;
   vl.pos_slot = 0;
   vl.num_varyings = 2;
   vl.varying[0] = (struct rast_varying){ .slot = 1, .interp = RAST_INTERP_COLOR,
                                          .usage_mask = 0xf };
   vl.varying[1] = (struct rast_varying){ .slot = 2, .interp = RAST_INTERP_PERSPECTIVE,
                                          .usage_mask = 0x3 };
   rast_set_vertex_layout(t.rc, &vl);
   char err[256];
   CHECK(rast_vectors_open(t.rc, dir, 0, ~0ul, err, sizeof(err)), "open: %s", err);
   t_seed(99);
   draw_some(&t, 300);
   const uint64_t drawn = rast_get_stats(t.rc)->triangles;
   const uint64_t passes = rast_get_stats(t.rc)->tile_passes;
   rast_vectors_close(t.rc);
   t_fini(&t);

   uint64_t tris = 0, quads = 0;
   long bad = rast_vectors_replay(dir, stderr, &tris, &quads);
   printf("vectors: %llu triangles drawn in %llu tile passes, %llu recorded, %llu quads; "
          "replay: %ld differ\n", (unsigned long long)drawn, (unsigned long long)passes,
          (unsigned long long)tris, (unsigned long long)quads, bad);
   CHECK(bad == 0, "the replay differs in %ld quads", bad);
   CHECK(drawn > 250 && quads > 5000, "too little drawn: %llu triangles, %llu quads",
         (unsigned long long)drawn, (unsigned long long)quads);
   /* a record a pass: the triangles across tiles count once a tile */
   CHECK(tris >= drawn && passes > 0 && tris > drawn, "records %llu for %llu triangles",
         (unsigned long long)tris, (unsigned long long)drawn);
   /* the colour registers are in the records */
   char path[512];
   snprintf(path, sizeof(path), "%s/scan.in.hex", dir);
   FILE *f = fopen(path, "r");
   char line[64] = "";
   if (f) {
      while (fgets(line, sizeof(line), f) && strcmp(line, "// triangle 0\n"))
         ;
      if (!fgets(line, sizeof(line), f))
         line[0] = '\0';
      fclose(f);
   }
   CHECK(((strtoull(line, NULL, 16) >> 8) & 0xff) == 4, "triangle 0 records %llu colour "
         "components, not 4", (strtoull(line, NULL, 16) >> 8) & 0xff);

   snprintf(path, sizeof(path), "%s/scan.out.hex", dir);
   CHECK(flip_one_bit(path, 1234), "cannot flip a bit of quad 1234");
   fprintf(stderr, "vectors: the replay with bit 0 of quad 1234's first Z flipped:\n");
   bad = rast_vectors_replay(dir, stderr, &tris, &quads);
   CHECK(bad == 1, "with one output bit flipped the replay finds %ld differences", bad);

   for (const char *n = "scan.in.hex\0scan.out.hex\0scan.txt\0"; *n; n += strlen(n) + 1) {
      snprintf(path, sizeof(path), "%s/%s", dir, n);
      unlink(path);
   }
   rmdir(dir);
   return t_summary("vectors");
}
