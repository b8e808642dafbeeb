/*
 * The register formats.  `seed` is Table 1 of seed 000 as printed; `wide`
 * widens what GL ES needs beyond it (targets up to 8192, 24-bit depth,
 * perspective-correct colour) and keeps the fraction bits, so both profiles
 * snap vertices to the same 1/4096 pixel grid.
 */
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rast/host/settings.h"
#include "rast/rast.h"

static const struct rast_profile profile_seed = {
   .name = "seed",
   .summary = "seed 000 Table 1: X/Y 12.12, dx/dy 12.12, Z 20.12 (19-bit depth), "
              "colour 9.12, X_out 11 bits (tiles of 2048), linear colour",
   .xy = { 12, 12 },
   .dxdy = { 12, 12 },
   .z = { 20, 12 },
   .color = { 9, 12 },
   .z_bits = 19,
   .tile_size = 2048,
   .max_target = 8192,
   .color_perspective = false,
   .weight = { 8, 24 },
};

static const struct rast_profile profile_wide = {
   .name = "wide",
   .summary = "widened for GL ES: X/Y 16.12, dx/dy 16.12, Z 28.12 (24-bit depth), "
              "colour 9.12, targets up to 8192, perspective-correct colour",
   .xy = { 16, 12 },
   .dxdy = { 16, 12 },
   .z = { 28, 12 },
   .color = { 9, 12 },
   .z_bits = 24,
   .tile_size = 8192,
   .max_target = 8192,
   .color_perspective = true,
   .weight = { 8, 24 },
};

static const struct rast_profile *const profiles[] = {
   &profile_seed, &profile_wide, NULL
};

const struct rast_profile *rast_profile_by_name(const char *name)
{
   if (!name)
      return NULL;
   for (unsigned i = 0; profiles[i]; i++)
      if (strcmp(profiles[i]->name, name) == 0)
         return profiles[i];
   return NULL;
}

const char *rast_profile_names(void)
{
   return "seed, wide";
}

const struct rast_profile *const *rast_profile_list(void)
{
   return profiles;
}

/* ---- precision settings: NAME[:KEY=VALUE,...] ----
 *
 * Only fraction bits change: the integer bits give the registers' reach,
 * which the tiles, the GL limits and the depth scale are built on, so M
 * must be the named profile's.  The limits keep every product the model
 * forms in 64 bits (X: edge cross products of M+N-bit values) and every
 * conversion defined. */
struct frac_key {
   const char *key;
   size_t offset;                  /* of the struct fx_format in rast_profile */
   unsigned min_frac, max_total;   /* N >= min_frac, M + N <= max_total */
};

static const struct frac_key frac_keys[] = {
   { "xy", offsetof(struct rast_profile, xy), 1, 30 },
   { "dxdy", offsetof(struct rast_profile, dxdy), 1, 30 },
   { "z", offsetof(struct rast_profile, z), 0, 44 },
   { "color", offsetof(struct rast_profile, color), 0, 33 },
   { "weight", offsetof(struct rast_profile, weight), 4, 38 },
};
#define N_FRAC_KEYS (sizeof(frac_keys) / sizeof(frac_keys[0]))

static struct fx_format *key_format(struct rast_profile *p, const struct frac_key *k)
{
   return (struct fx_format *)((char *)p + k->offset);
}

static bool fail(char *err, size_t size, const char *fmt, ...)
{
   va_list ap;
   va_start(ap, fmt);
   if (size)
      vsnprintf(err, size, fmt, ap);
   va_end(ap);
   return false;
}

static void append(char *buf, size_t size, const char *fmt, ...)
{
   size_t used = strlen(buf);
   if (used + 1 >= size)
      return;
   va_list ap;
   va_start(ap, fmt);
   vsnprintf(buf + used, size - used, fmt, ap);
   va_end(ap);
}

/* "M.N" with M and N decimal */
static bool parse_mn(const char *v, unsigned *m, unsigned *n)
{
   char *end;
   if (*v < '0' || *v > '9')
      return false;
   unsigned long a = strtoul(v, &end, 10);
   if (*end != '.' || end[1] < '0' || end[1] > '9')
      return false;
   unsigned long b = strtoul(end + 1, &end, 10);
   if (*end || a > 64 || b > 64)
      return false;
   *m = (unsigned)a;
   *n = (unsigned)b;
   return true;
}

static const char profile_keys[] = "xy, dxdy, z, color, weight as M.N; walk=exact|literal";

/* The list being applied to a copy of its base profile. */
struct profile_edit {
   struct rast_profile *p;
   const struct rast_profile *base;
   bool dxdy_given;
};

static bool profile_setting(void *ctx, const char *key, const char *val, char *err, size_t size)
{
   struct profile_edit *e = ctx;
   if (!strcmp(key, "walk")) {
      if (!strcmp(val, "exact") || !strcmp(val, "literal")) {
         e->p->literal_walk = !strcmp(val, "literal");
         return true;
      }
      return fail(err, size, "walk=%s (accepted: exact, literal)", val);
   }
   for (unsigned i = 0; i < N_FRAC_KEYS; i++) {
      const struct frac_key *k = &frac_keys[i];
      const bool colour = !strcmp(key, "colour") && !strcmp(k->key, "color");
      if (!colour && strcmp(key, k->key))
         continue;
      const struct fx_format b = *key_format((struct rast_profile *)e->base, k);
      const unsigned hi = k->max_total - b.int_bits;
      unsigned m, n;
      if (!parse_mn(val, &m, &n) || m != b.int_bits || n < k->min_frac || n > hi)
         return fail(err, size, "%s=%s (accepted: %u.N with N from %u to %u: %s keeps its "
                     "%u integer bits)", k->key, val, b.int_bits, k->min_frac, hi, e->base->name,
                     b.int_bits);
      key_format(e->p, k)->frac_bits = (uint8_t)n;
      e->dxdy_given |= !strcmp(k->key, "dxdy");
      return true;
   }
   return fail(err, size, "unknown key '%s' (accepted: %s)", key, profile_keys);
}

bool rast_profile_parse(const char *spec, struct rast_profile_buf *out, char *err,
                        size_t err_size)
{
   if (err_size)
      err[0] = '\0';
   if (!spec || !*spec)
      return fail(err, err_size, "empty (accepted: %s, each optionally with "
                  ":KEY=VALUE,...)", rast_profile_names());
   const char *colon = strchr(spec, ':');
   const size_t nlen = colon ? (size_t)(colon - spec) : strlen(spec);
   char bname[32];
   if (nlen >= sizeof(bname))
      return fail(err, err_size, "unknown profile '%.*s' (accepted: %s)", (int)nlen, spec,
                  rast_profile_names());
   memcpy(bname, spec, nlen);
   bname[nlen] = '\0';
   const struct rast_profile *base = rast_profile_by_name(bname);
   if (!base)
      return fail(err, err_size, "unknown profile '%s' (accepted: %s)", bname,
                  rast_profile_names());

   struct rast_profile p = *base;
   struct profile_edit edit = { &p, base, false };
   if (colon && !colon[1])
      return fail(err, err_size, "nothing after ':' (keys: %s)", profile_keys);
   if (colon && !rast_settings_each(colon + 1, profile_keys, profile_setting, &edit, err, err_size))
      return false;
   const bool dxdy_given = edit.dxdy_given;
   /* The exact walk's slope register holds Δx/Δy on X's grid and the
    * remainder the rest, so its fraction is X's; only the literal walk
    * has a slope of its own precision. */
   if (!dxdy_given)
      p.dxdy.frac_bits = p.xy.frac_bits;
   else if (!p.literal_walk && p.dxdy.frac_bits != p.xy.frac_bits)
      return fail(err, err_size, "dxdy=%u.%u needs walk=literal (the exact walk's slope has X's "
                  "%u fraction bits and a remainder)", p.dxdy.int_bits, p.dxdy.frac_bits,
                  p.xy.frac_bits);

   memset(out, 0, sizeof(*out));
   snprintf(out->name, sizeof(out->name), "%s", base->name);
   snprintf(out->summary, sizeof(out->summary), "%s", base->summary);
   char sep = ':';
   for (unsigned i = 0; i < N_FRAC_KEYS; i++) {
      const struct frac_key *k = &frac_keys[i];
      const struct fx_format f = *key_format(&p, k);
      /* the exact walk's slope follows X: said once, by xy */
      if (f.frac_bits == key_format((struct rast_profile *)base, k)->frac_bits ||
          (!p.literal_walk && k->offset == offsetof(struct rast_profile, dxdy)))
         continue;
      append(out->name, sizeof(out->name), "%c%s=%u.%u", sep, k->key, f.int_bits, f.frac_bits);
      append(out->summary, sizeof(out->summary), "%s %s %u.%u", sep == ':' ? "; with" : ",",
             k->key, f.int_bits, f.frac_bits);
      sep = ',';
   }
   if (p.literal_walk != base->literal_walk) {
      append(out->name, sizeof(out->name), "%cwalk=%s", sep, p.literal_walk ? "literal" : "exact");
      append(out->summary, sizeof(out->summary), "%s the %s edge walk",
             sep == ':' ? "; with" : ",", p.literal_walk ? "literal (no remainder)" : "exact");
   }
   p.name = out->name;
   p.summary = out->summary;
   out->p = p;
   return true;
}
