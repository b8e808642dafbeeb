/*
 * Precision settings (FIXPIPE_PROFILE=NAME:KEY=VALUE,...; docs/profiles.md):
 *
 * - the parser takes what it documents, names the result canonically and
 *   refuses everything else with the accepted values in its message;
 * - the literal edge walk (walk=literal: Δx/Δy accumulated without the
 *   remainder) differs from the exact reference, by at most the drift its
 *   slope register allows on each scan line's two ends; it is the same
 *   walk wherever it starts (a scissor below a triangle's top sees the
 *   registers the walk from the top would hold); and a mesh drawn with it
 *   has no pixel covered twice and no hole away from its outline.
 *
 * Exact coverage with other X/Y fraction bits is test_scan_ref's and
 * test_watertight's (their profile lists include such settings).
 */
#include <math.h>
#include <string.h>
#include "tutil.h"
#include "fixed/fx.h"

#define TW 1024
#define TH 1024

static void parse_ok(const char *spec, const char *name, unsigned xy, unsigned dxdy, unsigned z,
                     unsigned color, unsigned weight, bool literal)
{
   struct rast_profile_buf b;
   char err[256];
   const bool ok = rast_profile_parse(spec, &b, err, sizeof(err));
   CHECK(ok, "'%s' refused: %s", spec, err);
   if (!ok)
      return;
   CHECK(!strcmp(b.p.name, name), "'%s' named '%s', not '%s'", spec, b.p.name, name);
   CHECK(b.p.xy.frac_bits == xy && b.p.dxdy.frac_bits == dxdy && b.p.z.frac_bits == z &&
            b.p.color.frac_bits == color && b.p.weight.frac_bits == weight &&
            b.p.literal_walk == literal,
         "'%s': xy %u dxdy %u z %u color %u weight %u literal %d", spec, b.p.xy.frac_bits,
         b.p.dxdy.frac_bits, b.p.z.frac_bits, b.p.color.frac_bits, b.p.weight.frac_bits,
         b.p.literal_walk);
   const struct rast_profile *base = rast_profile_by_name(strncmp(spec, "wide", 4) ? "seed" : "wide");
   CHECK(b.p.xy.int_bits == base->xy.int_bits && b.p.z.int_bits == base->z.int_bits &&
            b.p.tile_size == base->tile_size && b.p.z_bits == base->z_bits,
         "'%s': the integer bits and limits are not the named profile's", spec);
}

static void parse_bad(const char *spec, const char *must_say)
{
   struct rast_profile_buf b;
   char err[256];
   CHECK(!rast_profile_parse(spec, &b, err, sizeof(err)), "'%s' accepted", spec);
   CHECK(strstr(err, must_say) != NULL, "'%s': message '%s' does not say '%s'", spec, err,
         must_say);
}

static void parsing(void)
{
   parse_ok("seed", "seed", 12, 12, 12, 12, 24, false);
   parse_ok("wide", "wide", 12, 12, 12, 12, 24, false);
   parse_ok("seed:xy=12.12", "seed", 12, 12, 12, 12, 24, false);
   parse_ok("seed:xy=12.8,z=20.16", "seed:xy=12.8,z=20.16", 8, 8, 16, 12, 24, false);
   parse_ok("seed:z=20.16,xy=12.8", "seed:xy=12.8,z=20.16", 8, 8, 16, 12, 24, false);
   parse_ok("seed:colour=9.6,weight=8.16", "seed:color=9.6,weight=8.16", 12, 12, 12, 6, 16, false);
   parse_ok("seed:walk=literal", "seed:walk=literal", 12, 12, 12, 12, 24, true);
   parse_ok("seed:walk=literal,dxdy=12.8", "seed:dxdy=12.8,walk=literal", 12, 8, 12, 12, 24, true);
   parse_ok("wide:xy=16.14,z=28.0", "wide:xy=16.14,z=28.0", 14, 14, 0, 12, 24, false);
   parse_ok("seed:xy=12.18", "seed:xy=12.18", 18, 18, 12, 12, 24, false);

   parse_bad("", "accepted: seed, wide");
   parse_bad("tall", "accepted: seed, wide");
   parse_bad("seed:", "keys: xy");
   parse_bad("seed:xy", "KEY=VALUE");
   parse_bad("seed:depth=20.12", "accepted: xy, dxdy, z, color, weight");
   parse_bad("seed:xy=11.12", "accepted: 12.N with N from 1 to 18");
   parse_bad("seed:xy=12.0", "from 1 to 18");
   parse_bad("seed:xy=12.19", "from 1 to 18");
   parse_bad("wide:xy=16.15", "from 1 to 14");
   parse_bad("seed:z=20.x", "accepted: 20.N with N from 0 to 24");
   parse_bad("seed:xy=12.8,", "KEY=VALUE");
   parse_bad("seed:dxdy=12.8", "needs walk=literal");
   parse_bad("seed:walk=sideways", "accepted: exact, literal");
}

/* ---- the literal walk ---- */

struct cmp { struct tctx *t; uint64_t missing; int64_t row_lo, row_hi; unsigned *per_row; };

static void visit_ref(void *ctx, int x, int y)
{
   struct cmp *c = ctx;
   if (c->t->stamp[(size_t)y * TW + (size_t)x] != c->t->id) {
      c->missing++;
      c->per_row[y]++;
   }
}

/* One triangle through the model (t->stamp) and the reference: the pixels
 * that differ, and the most on one scan line that the model left out. */
static uint64_t compare(struct tctx *t, float v[3][2], unsigned *worst_row)
{
   struct fx_sat none = { 0, 0 };
   const int64_t S = fx_one(t->prof->xy);
   int64_t X[3], Y[3];
   for (int i = 0; i < 3; i++) {
      X[i] = fx_from_double(t->prof->xy, v[i][0], &none);
      Y[i] = fx_from_double(t->prof->xy, v[i][1], &none);
   }
   t_begin(t);
   t_tri_xy(t->rc, (const float (*)[2])v);
   static unsigned per_row[TH];
   memset(per_row, 0, sizeof(per_row));
   struct cmp c = { t, 0, 0, 0, per_row };
   struct rast_scissor clip = { 0, 0, TW, TH };
   const uint64_t ref = t_ref_triangle(X, Y, S, S / 2, false, clip, visit_ref, &c);
   /* the model's extra pixels: its count less the reference's it hit */
   const uint64_t extra = t->count - (ref - c.missing);
   *worst_row = 0;
   for (int y = 0; y < TH; y++)
      if (per_row[y] > *worst_row)
         *worst_row = per_row[y];
   return c.missing + extra;
}

static double coord(double lo, double hi) { return lo + (hi - lo) * t_rand(); }

static void random_triangle(float v[3][2], double size)
{
   const double cx = coord(size / 2, TW - size / 2), cy = coord(size / 2, TH - size / 2);
   for (int i = 0; i < 3; i++) {
      v[i][0] = (float)(cx + coord(-size / 2, size / 2));
      v[i][1] = (float)(cy + coord(-size / 2, size / 2));
   }
}

static void literal_against_exact(const char *spec, unsigned slope_frac, uint64_t *differ)
{
   struct tctx t;
   t_init(&t, spec, TW, TH);
   t_raster(&t, true, false);
   uint64_t pixels = 0, diff = 0, tris = 0;
   unsigned worst = 0;
   for (unsigned n = 0; n < 600; n++) {
      float v[3][2];
      const double size = n % 3 == 0 ? 900 : coord(20, 400);
      random_triangle(v, size);
      unsigned w;
      diff += compare(&t, v, &w);
      pixels += t.count;
      tris++;
      if (w > worst)
         worst = w;
      /* the drift after k scan lines is below k·2^-Nd pixels, so a row's
       * end is off by at most ceil(that) pixels, each end */
      const double rows = fabs((double)v[0][1] - v[1][1]) + fabs((double)v[1][1] - v[2][1]) +
                          fabs((double)v[0][1] - v[2][1]);
      const double drift = rows / 2 * ldexp(1.0, -(int)slope_frac);
      CHECK(w <= 2 * (unsigned)ceil(drift + 1e-9) + 2,
            "%s: %u pixels of one scan line missing, drift bound %.3f", spec, w, drift);
   }
   printf("precision: %s: %llu triangles, %llu pixels, %llu differ from the exact walk "
          "(%.4f%%), at most %u missing on one scan line\n",
          spec, (unsigned long long)tris, (unsigned long long)pixels, (unsigned long long)diff,
          100.0 * (double)diff / (double)pixels, worst);
   *differ = diff;
   t_fini(&t);
}

/* The same triangle with a scissor whose top is below the triangle's
 * must give the same pixels inside the scissor. */
static void literal_start_anywhere(void)
{
   struct tctx a, b;
   t_init(&a, "seed:walk=literal,dxdy=12.6", TW, TH);
   t_init(&b, "seed:walk=literal,dxdy=12.6", TW, TH);
   struct rast_raster_state rs;
   memset(&rs, 0, sizeof(rs));
   rs.half_pixel_center = true;
   rs.line_width = 1.0f;
   rast_set_raster_state(a.rc, &rs);
   rs.scissor = true;
   rast_set_raster_state(b.rc, &rs);
   uint64_t compared = 0, differ = 0;
   for (unsigned n = 0; n < 200; n++) {
      float v[3][2];
      random_triangle(v, coord(100, 900));
      const float top = fminf(v[0][1], fminf(v[1][1], v[2][1]));
      struct rast_scissor sc = { 0, (int)top + 1 + (int)coord(0, 200), TW, TH };
      if (sc.miny >= TH)
         continue;
      rast_set_scissor(b.rc, &sc);
      t_begin(&a);
      t_tri_xy(a.rc, (const float (*)[2])v);
      t_begin(&b);
      t_tri_xy(b.rc, (const float (*)[2])v);
      for (int y = sc.miny; y < TH; y++)
         for (int x = 0; x < TW; x++) {
            const size_t i = (size_t)y * TW + (size_t)x;
            const bool ia = a.stamp[i] == a.id, ib = b.stamp[i] == b.id;
            compared += ia;
            differ += ia != ib;
         }
   }
   CHECK(differ == 0 && compared > 100000,
         "literal walk under a scissor: %llu of %llu pixels differ",
         (unsigned long long)differ, (unsigned long long)compared);
   t_fini(&a);
   t_fini(&b);
}

int main(void)
{
   t_seed(0x707265636973696full);
   parsing();

   uint64_t differ_exact, differ_literal, differ_coarse;
   literal_against_exact("seed", 12, &differ_exact);
   CHECK(differ_exact == 0, "the exact walk differs from the reference on %llu pixels",
         (unsigned long long)differ_exact);
   literal_against_exact("seed:walk=literal", 12, &differ_literal);
   literal_against_exact("seed:walk=literal,dxdy=12.6", 6, &differ_coarse);
   CHECK(differ_literal > 0, "the literal walk is the exact one on every pixel");
   CHECK(differ_coarse > differ_literal,
         "a 6-bit slope (%llu pixels differ) is not worse than a 12-bit one (%llu)",
         (unsigned long long)differ_coarse, (unsigned long long)differ_literal);
   literal_start_anywhere();
   return t_summary("precision");
}
