/* The perspective division's specialised quads and lanes (persp.c: tex_quad_dfx19
 * with W = 19 a constant, tex_quad_float on float vectors) against the
 * generic quad (rast_interp_perspective_reference: tex_quad_impl with the
 * width read at run time for dfx24, with the scalar binary32 operations
 * for float): every random primitive is drawn through both, and every
 * quad's used inputs must be the same bits, with the same tex_sat and
 * tex_flush counts.  Random layouts (1 to 8 varyings, PERSPECTIVE with
 * some COLOR and LINEAR, random usage masks), w ratios up to 4000, both
 * edge rules, seed and wide profiles (wide: perspective COLOR in
 * binary32 beside the system), lines as well as triangles; helpers are
 * part of each quad's inputs.  The same primitives go through the lanes
 * (lanes.h: dfx24 on the default path, every instruction set the CPU
 * runs), with and without the skips, and through RAST_OPT_SCALAR; some
 * primitives have a constant 1/w (sometimes 1) and constant components,
 * and some a 1/w or components equal at two vertices (one difference of
 * the plane zero where V0 is one of them), so that the skips are taken.  Some passes shade groups of two or four
 * quads (rast_shader.shade_n), where the lanes divide a group's quads
 * together wherever they lie on the primitive's rows. */
#include <math.h>
#include <string.h>
#include "tutil.h"
#include "rast/setup/front.h"
#include "fixed/numsys.h"
#include "rast/host/lanes.h"

#define MAX_VALS (1u << 22)

static struct tctx t;
static struct rast_vertex_layout vl;
/* pass 0: the generic reference; then each mode below (isa: lanes.h's
 * sets, each where the CPU runs it, else the next one down) */
enum { ISA_AVX2, ISA_SSE2, ISA_AVX512 };
static const struct { unsigned opts; int isa; unsigned group; } modes[] = {
   { 0, ISA_AVX2, 0 },   { RAST_OPT_NOSKIP, ISA_AVX2, 0 },   { 0, ISA_SSE2, 0 },
   { RAST_OPT_NOSKIP, ISA_SSE2, 0 }, { RAST_OPT_SCALAR, ISA_AVX2, 0 },
   { 0, ISA_AVX512, 0 }, { RAST_OPT_NOSKIP, ISA_AVX512, 0 },
   { 0, ISA_AVX512, 4 }, { 0, ISA_AVX512, 2 }, { 0, ISA_AVX2, 4 }, { 0, ISA_AVX2, 2 },
   { 0, ISA_SSE2, 4 }, { RAST_OPT_NOSKIP, ISA_AVX512, 4 },
   { RAST_OPT_NOF32, ISA_AVX512, 0 }, { RAST_OPT_NOF32, ISA_AVX512, 4 },
};
#define NPASS (1 + (int)(sizeof(modes) / sizeof(modes[0])))
static float *rec[NPASS];
static size_t nrec[NPASS];
static uint64_t skipped_w, skipped_comp, skipped_terms, skipped_axes;
static int pass;
static bool avx2, avx512;
static uint64_t quads, helpers, values;
static uint64_t group_calls;   /* shade_n calls of more than one quad */

/* tutil's shader, a group of quads at a time: each quad in turn. */
static unsigned shade_group(void *ctx, const struct rast_quad *const q[],
                            struct rast_shaded_quad *const out[], unsigned n)
{
   unsigned kept = 0;
   group_calls += n > 1;
   for (unsigned i = 0; i < n; i++)
      kept |= t_shade_record(ctx, q[i], out[i]) << 4 * i;
   return kept;
}

static void set_group(unsigned group)
{
   struct rast_shader fs;
   memset(&fs, 0, sizeof(fs));
   fs.ctx = &t;
   fs.shade = t_shade_record;
   fs.shade_n = group ? shade_group : NULL;
   fs.group = group;
   fs.may_discard = true;
   fs.reads_fragcoord = true;
   rast_set_shader(t.rc, &fs);
}

/* The used components of every quad, in order, with its position. */
static void hook(struct tctx *tc, const struct rast_quad *q)
{
   (void)tc;
   float *o = rec[pass];
   size_t n = nrec[pass];
   if (n + 4 + RAST_MAX_VARYINGS * 4 * RAST_QUAD_SIZE > MAX_VALS)
      return;                   /* the primitive is compared up to here */
   o[n++] = (float)q->x;
   o[n++] = (float)q->y;
   o[n++] = (float)q->mask;
   for (unsigned v = 0; v < vl.num_varyings; v++)
      for (unsigned c = 0; c < 4; c++)
         if (vl.varying[v].usage_mask & (1u << c)) {
            memcpy(&o[n], q->in[v][c], sizeof(q->in[v][c]));
            n += RAST_QUAD_SIZE;
         }
   nrec[pass] = n;
   if (pass == 1) {
      quads++;
      helpers += 4 - (unsigned)__builtin_popcount(q->mask);
   }
}

static float rnd_attr(void)
{
   switch ((int)(t_rand() * 7)) {
   case 0: return t_rand() < 0.5 ? 0.0f : -0.0f;
   case 1: return (float)ldexp(t_rand() - 0.5, (int)(t_rand() * 40) - 20);
   /* around 2^32, where the planes' set-up saturates (the lanes' fall-back) */
   case 2: return (float)ldexp(t_rand() - 0.5, 30 + (int)(t_rand() * 5));
   default: return (float)(8 * t_rand() - 4);
   }
}

static void run(const char *profile, const char *texfmt, unsigned nprim, uint64_t *ev)
{
   t_init(&t, profile, 1024, 1024);
   rast_set_texfmt(t.rc, numsys_by_name(texfmt));
   t.hook = hook;
   uint64_t events = 0, bad = 0;
   for (unsigned n = 0; n < nprim; n++) {
      if (n % 16 == 0) {
         memset(&vl, 0, sizeof vl);
         vl.num_varyings = 1 + (unsigned)(t_rand() * 8);
         vl.vertex_size = 1 + vl.num_varyings;
         vl.pos_slot = 0;
         for (unsigned v = 0; v < vl.num_varyings; v++) {
            double r = t_rand();
            uint8_t interp = r < 0.7 ? RAST_INTERP_PERSPECTIVE
                           : r < 0.85 ? RAST_INTERP_COLOR : RAST_INTERP_LINEAR;
            vl.varying[v] = (struct rast_varying){
               .slot = (uint8_t)(1 + v), .interp = interp,
               .usage_mask = (uint8_t)(1 + t_rand() * 15),
               /* rebased components: the set-up's, the same on every path */
               .rebase_mask = (uint8_t)(t_rand() * 16), .rebase_even = (uint8_t)(t_rand() * 16) };
         }
         /* now and then an array layer: components divided in binary32 */
         if (t_rand() < 0.15) {
            struct rast_varying *vr = &vl.varying[(unsigned)(t_rand() * vl.num_varyings)];
            vr->float_mask = (uint8_t)(t_rand() * 16);
         }
         rast_set_vertex_layout(t.rc, &vl);
      }
      struct rast_raster_state rs;
      memset(&rs, 0, sizeof rs);
      rs.half_pixel_center = true;
      rs.front_ccw = n & 1;
      rs.bottom_edge_rule = t_rand() < 0.5;
      rs.line_width = 1 + (float)(t_rand() * 3);
      rast_set_raster_state(t.rc, &rs);

      double size = 1 + 300 * t_rand() * t_rand();
      double cx = 50 + 900 * t_rand(), cy = 50 + 900 * t_rand();
      /* w from 1/2 up to 4000 times that: the far end's 1/w is tiny */
      double wmax = pow(8000.0, t_rand());
      const double shape = t_rand();       /* 2-D content: one w, maybe 1 */
      float v[3][1 + 8][4];
      memset(v, 0, sizeof v);
      for (int k = 0; k < 3; k++) {
         v[k][0][0] = (float)(cx + size * (t_rand() - 0.5));
         v[k][0][1] = (float)(cy + size * (t_rand() - 0.5));
         v[k][0][2] = (float)t_rand();
         v[k][0][3] = (float)(1.0 / (0.5 * pow(wmax, t_rand())));
         if (shape < 0.3)
            v[k][0][3] = shape < 0.15 ? 1.0f : v[0][0][3];
         /* 2-D content along one edge: two vertices share a value (1/w
          * here, components 2 and 3 below), so that one of a plane's
          * differences is zero wherever V0 is one of the two */
         else if (shape < 0.4 && k == 1)
            v[k][0][3] = v[0][0][3];
         for (unsigned s = 1; s <= vl.num_varyings; s++)
            for (int c = 0; c < 4; c++)
               v[k][s][c] = shape < 0.5 && c == 1                ? v[0][s][c]
                            : shape < 0.7 && c == 2 && k == 1     ? v[0][s][c]
                            : shape < 0.7 && c == 3 && k == 2     ? v[1][s][c]
                                                                  : rnd_attr();
      }
      /* 2-D content's rectangles: a right triangle with legs along the
       * axes, one w, each component following one axis (the same at the
       * right angle and at the end of the other leg), the vertices in any
       * order: where the set-up's V0 is at the right angle, the planes
       * follow the axes (interp_axes.c) */
      if (t_rand() < 0.15) {
         const double w = t_rand() < 0.5 ? 1.0 : 1.0 / (0.5 * pow(wmax, t_rand()));
         const double lx = (t_rand() < 0.5 ? -1 : 1) * (10 + 290 * t_rand());
         const double ly = (t_rand() < 0.5 ? -1 : 1) * (10 + 290 * t_rand());
         const double px[3] = { cx, cx + lx, cx }, py[3] = { cy, cy, cy + ly };
         const unsigned rot = (unsigned)(t_rand() * 3);
         for (int k = 0; k < 3; k++) {
            const unsigned c = (unsigned)(k + rot) % 3;
            v[k][0][0] = (float)px[c];
            v[k][0][1] = (float)py[c];
            v[k][0][3] = (float)w;
         }
         for (unsigned s = 1; s <= vl.num_varyings; s++)
            for (int c = 0; c < 4; c++) {
               /* the corners' values: right angle, x leg's end, y leg's end */
               const double kind = t_rand();
               float at[3];
               for (int k = 0; k < 3; k++)
                  at[k] = t_rand() < 0.5 ? rnd_attr() : (float)(8 * t_rand() - 4);
               if (kind < 0.4)
                  at[2] = at[0];          /* follows x */
               else if (kind < 0.8)
                  at[1] = at[0];          /* follows y */
               else                       /* constant: A·w once a primitive, */
                  at[1] = at[2] = at[0] = /* at times past the range */
                     t_rand() < 0.5 ? (float)ldexp(t_rand() + 0.5, 20 + (int)(t_rand() * 16))
                                    : rnd_attr();
               for (int k = 0; k < 3; k++)
                  v[k][s][c] = at[(unsigned)(k + rot) % 3];
            }
      }
      bool line = t_rand() < 0.1;
      uint64_t e[NPASS];
      for (pass = 0; pass < NPASS; pass++) {
         if (pass) {
            const int isa = modes[pass - 1].isa;
            rast_lanes_set(isa == ISA_AVX512 && avx512 ? &rast_lanes_avx512
                           : isa != ISA_SSE2 && avx2   ? &rast_lanes_avx2
                                                       : &rast_lanes_sse2);
            rast_set_options(t.rc, modes[pass - 1].opts);
         }
         set_group(pass ? modes[pass - 1].group : 0);
         rast_interp_perspective_reference(t.rc, pass == 0);
         nrec[pass] = 0;
         const struct rast_stats *st = rast_get_stats(t.rc);
         uint64_t e0 = st->tex_sat + st->tex_flush * 0x100000000ull;
         t_begin(&t);
         if (line)
            t_line(t.rc, v[0], v[1]);
         else
            t_tri(t.rc, v[0], v[1], v[2]);
         st = rast_get_stats(t.rc);
         e[pass] = st->tex_sat + st->tex_flush * 0x100000000ull - e0;
      }
      events += e[1];
      values += nrec[1];
      for (int p = 1; p < NPASS; p++) {
         if (nrec[0] != nrec[p] || memcmp(rec[0], rec[p], nrec[0] * sizeof(float)) ||
             e[0] != e[p]) {
            if (bad++ < 5)
               CHECK(false, "%s %s primitive %u (%s, %u varyings), mode %d: %zu/%zu values, "
                     "events 0x%llx/0x%llx, %s", profile, texfmt, n,
                     line ? "line" : "triangle", vl.num_varyings, p - 1, nrec[0], nrec[p],
                     (unsigned long long)e[0], (unsigned long long)e[p],
                     nrec[0] == nrec[p] && memcmp(rec[0], rec[p], nrec[0] * sizeof(float))
                        ? "values differ" : "");
         }
      }
   }
   skipped_w += rast_get_stats(t.rc)->skip_persp_w;
   skipped_comp += rast_get_stats(t.rc)->skip_persp_comp;
   skipped_terms += rast_get_stats(t.rc)->skip_persp_terms;
   skipped_axes += rast_get_stats(t.rc)->skip_persp_axes;
   t_fini(&t);
   printf("%-5s %-6s %u primitives: %llu differ; range events %llu sat, %llu flush\n",
          profile, texfmt, nprim, (unsigned long long)bad,
          (unsigned long long)(events & 0xffffffffu), (unsigned long long)(events >> 32));
   *ev += events;
}

/* The array layer (rast_varying.float_mask): dEQP-GLES3's
 * texture.filtering.2d_array "level rounding" quad, layers 1.50001 at one
 * corner, 1.49999 at the opposite one and their mean (1.5) at the other two:
 * the reference samples layer 2 over one triangle and layer 1 over the other,
 * where the layer lies up to 1e-5 below 1.5.  A texture path's system does
 * not hold that (dfx24 rounds all three to 1.5, dfx26 and dfx29 lose the
 * plane's terms in the adder's alignment, fx16.16 and fx24.8 have too few
 * fraction bits), so the layer is divided in binary32: its bits must be the
 * binary32 system's in every system, profile and data path, and the second
 * triangle's pixels off the diagonal must choose layer 1. */
static float layer_rec[2][64 * 64];
static int layer_tri;
static unsigned layer_hits[2];

static void layer_hook(struct tctx *tc, const struct rast_quad *q)
{
   (void)tc;
   for (unsigned p = 0; p < RAST_QUAD_SIZE; p++) {
      const int x = q->x + (int)(p & 1) - 8, y = q->y + (int)(p >> 1) - 8;
      if ((q->mask >> p & 1u) && x >= 0 && x < 64 && y >= 0 && y < 64) {
         layer_rec[layer_tri][y * 64 + x] = q->in[0][2][p];
         layer_hits[layer_tri]++;
      }
   }
}

static void layer_draw(const char *profile, const char *texfmt, unsigned opts, bool mask)
{
   t_init(&t, profile, 128, 128);
   rast_set_texfmt(t.rc, numsys_by_name(texfmt));
   rast_set_options(t.rc, opts);
   t.hook = layer_hook;
   t_raster(&t, true, false);
   struct rast_vertex_layout l = t_layout_pos();
   t_layout_add(&l, RAST_INTERP_PERSPECTIVE, 0x7)->float_mask = (uint8_t)(mask ? 0x4 : 0);
   rast_set_vertex_layout(t.rc, &l);
   const float l0 = 1.50001f, l1 = 1.49999f, lm = l0 * 0.5f + l1 * 0.5f;
   /* the quad's four corners (s, t, layer), as dEQP's renderQuad */
   float v[4][2][4] = { { { 8, 8, 0.5f, 1 }, { -2.0f, -1.5f, l0, 1 } },
                        { { 8, 72, 0.5f, 1 }, { -2.0f, -0.6f, lm, 1 } },
                        { { 72, 8, 0.5f, 1 }, { -1.1f, -1.5f, lm, 1 } },
                        { { 72, 72, 0.5f, 1 }, { -1.1f, -0.6f, l1, 1 } } };
   memset(layer_rec, 0, sizeof layer_rec);
   layer_hits[0] = layer_hits[1] = 0;
   layer_tri = 0;
   t_begin(&t);
   t_tri(t.rc, v[0], v[1], v[2]);
   layer_tri = 1;
   t_begin(&t);
   t_tri(t.rc, v[2], v[1], v[3]);
   t_fini(&t);
}

static void layer_rounding(void)
{
   static const char *const systems[] = { "dfx24", "dfx17", "dfx26", "dfx29", "fx16.16",
                                          "fx8.24", "fx24.8" };
   static const unsigned opts[] = { 0, RAST_OPT_NOSKIP, RAST_OPT_SCALAR | RAST_OPT_NOSKIP,
                                    RAST_OPT_NOF32 };
   static float ref[2][64 * 64];
   static const char *const profiles[] = { "seed", "wide" };
   for (unsigned pf = 0; pf < 2; pf++) {
      layer_draw(profiles[pf], "float", 0, true);
      memcpy(ref, layer_rec, sizeof ref);
      unsigned n = 0, layer1 = 0;
      for (unsigned i = 0; i < 64 * 64; i++)
         if (ref[1][i] != 0.0f) {
            n++;
            layer1 += floorf(ref[1][i] + 0.5f) == 1.0f;
         }
      CHECK(layer_hits[1] == 2080 && n == layer_hits[1] && layer1 + 64 >= n,
            "%s: binary32 chose layer 1 at %u of %u pixels of the second triangle",
            profiles[pf], layer1, n);
      for (unsigned s = 0; s < sizeof systems / sizeof systems[0]; s++)
         for (unsigned o = 0; o < sizeof opts / sizeof opts[0]; o++) {
            layer_draw(profiles[pf], systems[s], opts[o], true);
            CHECK(!memcmp(layer_rec, ref, sizeof ref),
                  "%s %s opts %u: the array layer is not binary32's", profiles[pf],
                  systems[s], opts[o]);
         }
      layer_draw(profiles[pf], "dfx24", 0, false);
      unsigned same = 0;
      for (unsigned i = 0; i < 64 * 64; i++)
         same += layer_rec[1][i] != 0.0f &&
                 floorf(layer_rec[1][i] + 0.5f) == floorf(ref[1][i] + 0.5f);
      printf("array layer (%s): layer 1 at %u of %u pixels of the second triangle in binary32, "
             "the same layer at %u of them in dfx24 when not divided in binary32\n",
             profiles[pf], layer1, n, same);
   }
}

int main(void)
{
   for (int p = 0; p < NPASS; p++)
      if (!(rec[p] = malloc(MAX_VALS * sizeof(float))))
         return 1;
   __builtin_cpu_init();
   avx2 = __builtin_cpu_supports("avx2");
   avx512 = rast_lanes_have_avx512();
   if (!avx2)
      printf("no AVX2 on this CPU: the SSE2 lanes only\n");
   else if (!avx512)
      printf("no AVX-512 on this CPU: its passes take the AVX2 lanes\n");
   layer_rounding();
   t_seed(12345);
   uint64_t ev = 0;
   const unsigned nprim = 3000;
   static const char *const profiles[] = { "seed", "wide" };
   static const char *const systems[] = { "dfx24", "float" };
   for (int p = 0; p < 2; p++)
      for (int s = 0; s < 2; s++)
         run(profiles[p], systems[s], nprim, &ev);
   printf("%llu quads (%llu helper pixels), %llu values compared\n", (unsigned long long)quads,
          (unsigned long long)helpers, (unsigned long long)values);
   CHECK(quads > 10000 && helpers > 1000, "the primitives covered quads with helpers");
   CHECK((ev & 0xffffffffu) > 0 || (ev >> 32) > 0, "range events were exercised");
   printf("skips taken: %llu quads with a constant 1/w, %llu constant component-quads, "
          "%llu plane terms with a zero difference (per quad)\n",
          (unsigned long long)skipped_w, (unsigned long long)skipped_comp,
          (unsigned long long)skipped_terms);
   CHECK(skipped_w > 1000 && skipped_comp > 1000 && skipped_terms > 1000,
         "the skips were exercised");
   printf("%llu quads divided per column and scan line (interp_axes.c)\n",
          (unsigned long long)skipped_axes);
   if (avx512)
      CHECK(skipped_axes > 5000, "primitives' planes were divided per column and scan line");
   printf("%llu calls of a group of quads\n", (unsigned long long)group_calls);
   CHECK(group_calls > 10000, "groups of quads were shaded");
   for (int p = 0; p < NPASS; p++)
      free(rec[p]);
   return t_summary("persp_fast");
}
