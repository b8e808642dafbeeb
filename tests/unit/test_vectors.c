/*
 * The scan-converter unit's RTL test vectors (vectors.c, docs/vectors.md):
 * random triangles with Z and four colour registers (and a perspective
 * varying, which is not the unit's) recorded on a target of 4096 x 4096,
 * which the seed profile draws in tiles, and quads through two texture
 * units (REPEAT and LINEAR; MIRRORED_REPEAT and two mip levels); the replay
 * must reproduce every output bit, and must fail once one bit of the outputs
 * is flipped.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "tutil.h"
#include "fixed/numsys.h"
#include "rast/tex/tex.h"
#include "verify/vectors_replay.h"

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

/* 500 quads through each of two texture units, recorded as the driver does
 * after sampling. */
static void sample_some(struct rast_context *rc)
{
   static uint8_t level0[64 * 64 * 4], level1[32 * 32 * 4];
   for (size_t i = 0; i < sizeof(level0); i++)
      level0[i] = (uint8_t)(t_rand() * 256.0);
   for (size_t i = 0; i < sizeof(level1); i++)
      level1[i] = (uint8_t)(t_rand() * 256.0);
   for (int b = 0; b < 2; b++) {
      struct tex_view_desc d;
      struct tex_sampler_desc s;
      memset(&d, 0, sizeof(d));
      memset(&s, 0, sizeof(s));
      d.target = TEX_TARGET_2D;
      d.format = TEX_FMT_RGBA8;
      d.num_levels = b ? 2 : 1;
      d.level[0] = (struct tex_level){ level0, 64 * 4, 64 * 64 * 4, 64, 64, 1 };
      d.level[1] = (struct tex_level){ level1, 32 * 4, 32 * 32 * 4, 32, 32, 1 };
      d.layers = 1;
      for (int c = 0; c < 4; c++)
         d.swizzle[c] = (uint8_t)c;
      s.wrap[0] = s.wrap[1] = s.wrap[2] = b ? TEX_WRAP_MIRROR_REPEAT : TEX_WRAP_REPEAT;
      s.min_filter = s.mag_filter = TEX_FILTER_LINEAR;
      s.mip = b ? TEX_MIP_LINEAR : TEX_MIP_NONE;
      s.normalized = true;
      s.max_lod = 1000.0f;
      struct tex_unit u;
      struct ns_stats st = { 0, 0 };
      tex_unit_bind(&u, numsys_default(), &d, &s, &st);
      for (int n = 0; n < 500; n++) {
         struct tex_quad q;
         memset(&q, 0, sizeof(q));
         const float s0 = (float)(t_rand() * 6.0 - 3.0), t0 = (float)(t_rand() * 6.0 - 3.0);
         const float ds = (float)(t_rand() * 0.05), dt = (float)(t_rand() * 0.05);
         for (int i = 0; i < 4; i++) {
            q.s[i] = s0 + (float)(i & 1) * ds;
            q.t[i] = t0 + (float)(i >> 1) * dt;
         }
         float rgba[4][TEX_QUAD];
         tex_unit_sample(&u, &q, TEX_LOD_IMPLICIT, rgba);
         rast_vectors_tex(rc, &u, &q, 1, TEX_LOD_IMPLICIT, (const float (*)[4][4])rgba);
      }
   }
}

/* Flips bit 0 of word `word` of the n-th quad record. */
static bool flip_one_bit(const char *path, int n, int word)
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
      for (int w = 0; w <= word; w++) {
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
   struct rast_vertex_layout vl = t_layout_pos();
   t_layout_add(&vl, RAST_INTERP_COLOR, 0xf);
   t_layout_add(&vl, RAST_INTERP_PERSPECTIVE, 0x3);
   rast_set_vertex_layout(t.rc, &vl);
   char err[256];
   CHECK(rast_vectors_open(t.rc, dir, 0, ~0ul, RAST_VEC_SCAN | RAST_VEC_TEX, err, sizeof(err)),
         "open: %s", err);
   t_seed(99);
   draw_some(&t, 300);
   sample_some(t.rc);
   const uint64_t drawn = rast_get_stats(t.rc)->triangles;
   const uint64_t passes = rast_get_stats(t.rc)->tile_passes;
   rast_vectors_close(t.rc);
   t_fini(&t);

   struct rast_vectors_counts n;
   long bad = rast_vectors_replay(dir, stderr, &n);
   const uint64_t tris = n.triangles, quads = n.quads;
   printf("vectors: %llu triangles drawn in %llu tile passes, %llu recorded, %llu quads; "
          "replay: %ld differ\n", (unsigned long long)drawn, (unsigned long long)passes,
          (unsigned long long)tris, (unsigned long long)quads, bad);
   CHECK(bad == 0, "the replay differs in %ld quads", bad);
   CHECK(n.tex_bindings == 2 && n.tex_quads == 1000, "texture unit: %llu bindings, %llu quads "
         "replayed, not 2 and 1000", (unsigned long long)n.tex_bindings,
         (unsigned long long)n.tex_quads);
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
   CHECK(((strtoull(line, NULL, 16) >> 16) & 0xff) == 2, "triangle 0 records %llu "
         "perspective components, not 2", (strtoull(line, NULL, 16) >> 16) & 0xff);

   /* one bit of the scan converter's output (Z, word 2), of the division's
    * (its first component at pixel 0, word 24, and the same as a dfx word,
    * word 56), of the texture unit's (red at pixel 0 of quad 700, word 0),
    * and of the coordinate registers it records beside its inputs (s at
    * pixels 0, 1 of quad 800, word 25) */
   const char *files[5] = { "scan.out.hex", "scan.out.hex", "scan.out.hex", "tex.out.hex",
                            "tex.in.hex" };
   const int words[5] = { 2, 24, 56, 0, 25 }, quad[5] = { 1234, 1235, 1236, 700, 800 };
   for (int i = 0; i < 5; i++) {
      snprintf(path, sizeof(path), "%s/%s", dir, files[i]);
      CHECK(flip_one_bit(path, quad[i], words[i]), "cannot flip a bit of quad %d", quad[i]);
      fprintf(stderr, "vectors: the replay with bit 0 of word %d of %s's quad %d flipped:\n",
              words[i], files[i], quad[i]);
      bad = rast_vectors_replay(dir, stderr, &n);
      CHECK(bad == i + 1, "with %d output bits flipped the replay finds %ld differences",
            i + 1, bad);
   }

   for (const char *name = "scan.in.hex\0scan.out.hex\0scan.txt\0tex.bind.hex\0tex.in.hex\0"
                        "tex.out.hex\0"; *name; name += strlen(name) + 1) {
      snprintf(path, sizeof(path), "%s/%s", dir, name);
      unlink(path);
   }
   rmdir(dir);
   return t_summary("vectors");
}
