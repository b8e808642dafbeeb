/*
 * Recorded scan-converter vectors (FIXPIPE_VECTORS=DIR, docs/vectors.md)
 * against the exact reference, triangle by triangle: the pixels a
 * triangle's quads cover in scan.out.hex must be the pixels the reference
 * (tutil.c: 64-bit edge functions on the recorded XY registers, the
 * recorded pixel-centre convention and edge rule, inside the recorded
 * clip) covers, none twice, and each quad must face as its triangle.
 *
 *   test_vectors_ref DIR
 *
 * The replay (fp-vectors) shows the model still gives what it recorded;
 * this shows that what it recorded is the right coverage, by code that
 * shares nothing with the scan converter but the vertex registers.
 * Exits 0 with a summary line, 1 on a difference, 2 if DIR is unreadable.
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tutil.h"
#include "fixed/fx.h"
#include "rast/instruments/vectors.h"
#include "verify/vectors_replay.h"

/* A pixel relative to its pass's origin, packed for sorting. */
static uint64_t pix(int64_t x, int64_t y)
{
   return (uint64_t)(y + (1 << 30)) << 32 | (uint64_t)(x + (1 << 30));
}

static int cmp_u64(const void *a, const void *b)
{
   const uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
   return x < y ? -1 : x > y;
}

struct pixels { uint64_t *p; size_t n, cap; };

static void push(struct pixels *s, uint64_t v)
{
   if (s->n == s->cap) {
      s->cap = s->cap ? 2 * s->cap : 256;
      s->p = realloc(s->p, s->cap * sizeof(uint64_t));
      if (!s->p)
         exit(2);
   }
   s->p[s->n++] = v;
}

static void visit(void *ctx, int x, int y)
{
   push(ctx, pix(x, y));
}

/* The next triangle's quads from scan.out.hex (*next holds the record read
 * ahead), their pixels relative to the pass's origin into model; false if
 * a quad faces otherwise than the triangle. */
static bool quads_of(FILE *out, struct rast_vec_quad *next, bool *have, uint64_t t,
                     const struct rast_tri_regs *tri, struct pixels *model, uint64_t *nquad)
{
   bool facing_ok = true;
   for (; *have && next->tri == t; *have = rast_vectors_read_quad(out, next)) {
      facing_ok &= next->front == tri->front;
      const int64_t x = next->x - tri->org_x, y = next->y - tri->org_y;
      for (unsigned p = 0; p < 4; p++)
         if (next->mask >> p & 1)
            push(model, pix(x + (p & 1), y + (p >> 1)));
      (*nquad)++;
   }
   return facing_ok;
}

int main(int argc, char **argv)
{
   if (argc != 2 || argv[1][0] == '-') {
      fprintf(stderr, "usage: test_vectors_ref DIR   (the vectors FIXPIPE_VECTORS=DIR wrote)\n");
      return 2;
   }
   const char *dir = argv[1];
   static struct rast_vectors_header hd;
   if (!rast_vectors_read_header(dir, &hd, stderr))
      return 2;
   char path[4096];
   snprintf(path, sizeof(path), "%s/scan.in.hex", dir);
   FILE *in = fopen(path, "r");
   snprintf(path, sizeof(path), "%s/scan.out.hex", dir);
   FILE *out = in ? fopen(path, "r") : NULL;
   if (!out) {
      fprintf(stderr, "test_vectors_ref: cannot read the vectors in %s\n", dir);
      return 2;
   }
   const int64_t S = fx_one(hd.profile_buf.p.xy);

   struct pixels model = { 0 }, ref = { 0 };
   struct rast_tri_regs tri;
   struct rast_vec_quad next;
   bool have = rast_vectors_read_quad(out, &next);
   uint64_t ntri = 0, nquad = 0, covered = 0, bad = 0;
   for (; rast_vectors_read_triangle(in, &tri); ntri++) {
      ref.n = model.n = 0;
      t_ref_triangle(tri.X, tri.Y, S, tri.half_pixel ? S / 2 : 0, tri.bottom_rule, tri.clip,
                     visit, &ref);
      const bool facing_ok = quads_of(out, &next, &have, ntri, &tri, &model, &nquad);
      qsort(model.p, model.n, sizeof(uint64_t), cmp_u64);
      qsort(ref.p, ref.n, sizeof(uint64_t), cmp_u64);
      const bool same = model.n == ref.n && (!ref.n || !memcmp(model.p, ref.p, ref.n * 8));
      covered += ref.n;
      if ((!same || !facing_ok) && bad++ < 5)
         fprintf(stderr, "triangle %" PRIu64 ": the model covers %zu pixels, the reference %zu%s%s\n",
                 ntri, model.n, ref.n, same ? "" : " (not the same set)",
                 facing_ok ? "" : "; a quad faces otherwise than its triangle");
   }
   if (have) {
      fprintf(stderr, "quad of triangle %" PRIu32 ": not in recorded order\n", next.tri);
      bad++;
   }
   if (ntri == 0) {
      fprintf(stderr, "test_vectors_ref: %s: no triangle recorded\n", dir);
      bad++;
   }
   printf("test_vectors_ref: %s: %" PRIu64 " triangles, %" PRIu64 " quads, %" PRIu64
          " pixels; %" PRIu64 " against the exact reference's coverage differ\n", dir, ntri,
          nquad, covered, bad);
   fclose(in);
   fclose(out);
   free(model.p);
   free(ref.p);
   return bad ? 1 : 0;
}
