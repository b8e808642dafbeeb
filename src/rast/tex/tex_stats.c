/*
 * The texture unit's range events join the model's counters, next to those
 * of the perspective division (same number system, same rast_stats fields).
 */
#include "rast/rast_priv.h"
#include "rast/tex/tex.h"

void tex_stats_to_rast(struct rast_context *rc, uint64_t sat, uint64_t flush, uint64_t skip_lod,
                       uint64_t lod_quads, uint64_t skip_axes, uint64_t skip_footprint,
                       uint64_t quads, uint64_t texels)
{
   rc->stats.skip_tex_footprint += skip_footprint;
   rc->stats.texels += texels;
   rc->stats.skip_tex_axes += skip_axes;
   rc->stats.tex_quads += quads;
   rc->stats.tex_sat += sat;
   rc->stats.tex_flush += flush;
   rc->stats.skip_tex_lod += skip_lod;
   rc->stats.tex_lod_quads += lod_quads;
}

void tex_stats_jit_gathers(struct rast_context *rc, uint64_t quads)
{
   rc->stats.tex_gather_jit += quads;
}
