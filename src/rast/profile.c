/*
 * The register formats.  `seed` is Table 1 of seed 000 as printed; `wide`
 * widens what GL ES needs beyond it (targets up to 8192, 24-bit depth,
 * perspective-correct colour) and keeps the fraction bits, so both profiles
 * snap vertices to the same 1/4096 pixel grid.
 */
#include <stddef.h>
#include <string.h>
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
