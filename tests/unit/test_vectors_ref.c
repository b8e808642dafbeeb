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

struct words { uint64_t *w; size_t n; };

/* A $readmemh file: one 64-bit word a line, "//" comment lines skipped. */
static bool read_words(const char *dir, const char *name, struct words *out)
{
   char path[4096];
   snprintf(path, sizeof(path), "%s/%s", dir, name);
   FILE *f = fopen(path, "r");
   if (!f) {
      fprintf(stderr, "test_vectors_ref: cannot read %s\n", path);
      return false;
   }
   size_t cap = 1024;
   out->w = malloc(cap * sizeof(uint64_t));
   out->n = 0;
   char line[256];
   while (out->w && fgets(line, sizeof(line), f)) {
      if (line[0] == '/' || line[0] == '\n')
         continue;
      if (out->n == cap)
         out->w = realloc(out->w, (cap *= 2) * sizeof(uint64_t));
      if (out->w)
         out->w[out->n++] = strtoull(line, NULL, 16);
   }
   fclose(f);
   return out->w != NULL;
}

/* scan.txt's "key value" lines */
static bool read_meta(const char *dir, char profile[128], unsigned *in_words,
                      unsigned *out_words)
{
   char path[4096], line[256], key[64], val[128];
   snprintf(path, sizeof(path), "%s/scan.txt", dir);
   FILE *f = fopen(path, "r");
   if (!f) {
      fprintf(stderr, "test_vectors_ref: cannot read %s\n", path);
      return false;
   }
   *in_words = *out_words = 0;
   profile[0] = 0;
   while (fgets(line, sizeof(line), f)) {
      if (sscanf(line, "%63s %127s", key, val) != 2)
         continue;
      if (!strcmp(key, "profile"))
         snprintf(profile, 128, "%s", val);
      else if (!strcmp(key, "in_words"))
         *in_words = (unsigned)atoi(val);
      else if (!strcmp(key, "out_words"))
         *out_words = (unsigned)atoi(val);
   }
   fclose(f);
   if (!profile[0] || !*in_words || !*out_words) {
      fprintf(stderr, "test_vectors_ref: %s lacks the profile or the record sizes\n", path);
      return false;
   }
   return true;
}

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

static int16_t half16(uint64_t w, int k) { return (int16_t)(uint16_t)(w >> (16 * k)); }

int main(int argc, char **argv)
{
   if (argc != 2 || argv[1][0] == '-') {
      fprintf(stderr, "usage: test_vectors_ref DIR   (the vectors FIXPIPE_VECTORS=DIR wrote)\n");
      return 2;
   }
   const char *dir = argv[1];
   char profile[128];
   unsigned in_words, out_words;
   struct words in, out;
   if (!read_meta(dir, profile, &in_words, &out_words) ||
       !read_words(dir, "scan.in.hex", &in) || !read_words(dir, "scan.out.hex", &out))
      return 2;
   char err[256];
   struct rast_profile_buf pb;
   if (!rast_profile_parse(profile, &pb, err, sizeof(err))) {
      fprintf(stderr, "test_vectors_ref: profile %s: %s\n", profile, err);
      return 2;
   }
   const int64_t S = fx_one(pb.p.xy);
   const size_t ntri = in.n / in_words, nquad = out.n / out_words;
   if (ntri == 0) {
      fprintf(stderr, "test_vectors_ref: %s: no triangle recorded\n", dir);
      return 1;
   }

   struct pixels model = { 0 }, ref = { 0 };
   size_t q = 0, bad = 0;
   uint64_t covered = 0;
   for (size_t t = 0; t < ntri; t++) {
      const uint64_t *r = in.w + t * in_words;
      const bool half = r[0] & 1, bottom = r[0] >> 1 & 1, front = r[0] >> 3 & 1;
      const int64_t ox = (int32_t)(uint32_t)r[1], oy = (int32_t)(uint32_t)(r[1] >> 32);
      const struct rast_scissor clip = { .minx = half16(r[2], 0), .maxx = half16(r[2], 1),
                                         .miny = half16(r[2], 2), .maxy = half16(r[2], 3) };
      const int64_t X[3] = { (int64_t)r[3], (int64_t)r[4], (int64_t)r[5] };
      const int64_t Y[3] = { (int64_t)r[6], (int64_t)r[7], (int64_t)r[8] };

      ref.n = model.n = 0;
      t_ref_triangle(X, Y, S, half ? S / 2 : 0, bottom, clip, visit, &ref);
      bool facing_ok = true;
      for (; q < nquad && (uint32_t)out.w[q * out_words] == t; q++) {
         const uint64_t *o = out.w + q * out_words;
         const unsigned cov = (unsigned)(o[0] >> 32) & 15;
         facing_ok &= (bool)(o[0] >> 36 & 1) == front;
         const int64_t x = (int32_t)(uint32_t)o[1] - ox, y = (int32_t)(uint32_t)(o[1] >> 32) - oy;
         for (unsigned p = 0; p < 4; p++)
            if (cov >> p & 1)
               push(&model, pix(x + (p & 1), y + (p >> 1)));
      }
      qsort(model.p, model.n, sizeof(uint64_t), cmp_u64);
      qsort(ref.p, ref.n, sizeof(uint64_t), cmp_u64);
      const bool same = model.n == ref.n && (!ref.n || !memcmp(model.p, ref.p, ref.n * 8));
      covered += ref.n;
      if (!same || !facing_ok) {
         if (bad++ < 5)
            fprintf(stderr, "triangle %zu: the model covers %zu pixels, the reference %zu%s%s\n",
                    t, model.n, ref.n, same ? "" : " (not the same set)",
                    facing_ok ? "" : "; a quad faces otherwise than its triangle");
      }
   }
   if (q != nquad) {
      fprintf(stderr, "quad %zu names triangle %" PRIu32 ", not in recorded order\n", q,
              (uint32_t)out.w[q * out_words]);
      bad++;
   }
   printf("test_vectors_ref: %s: %zu triangles, %zu quads, %" PRIu64 " pixels; %zu against the "
          "exact reference's coverage differ\n", dir, ntri, nquad, covered, bad);
   free(in.w);
   free(out.w);
   free(model.p);
   free(ref.p);
   return bad ? 1 : 0;
}
