/*
 * The unit's quad for dfx24 and binary32, chosen at bind: the data path of
 * tex_sample.c, tex_lod.c, tex_addr.c and tex_filter.c in the same order of
 * operations, with the arithmetic inline (tex_fast.h), the wrap mode a
 * switch instead of a call, the common 8-bit RGBA layouts read in place and
 * level selection shared by pixels of equal LOD.  One instance per number
 * system and dimensionality.  Cube maps and explicit derivatives (rare,
 * and the longest paths) stay on the generic quad.
 */
#include "rast/tex_fast_path.h"
#include "rast/lanes.h"

TEX_FAST_INLINE void quad(const struct tex_unit *u, const struct tex_quad *q,
                          enum tex_lod_control ctl, float rgba[4][TEX_QUAD],
                          const enum tex_fk k, const unsigned dims)
{
   if (ctl == TEX_LOD_DERIVS) {
      tex_unit_sample_generic(u, q, ctl, rgba);
      return;
   }
   struct tex_fst x = { { 0, 0 }, { 0, 0 } };
   const bool array = u->view.target == TEX_TARGET_1D_ARRAY ||
                      u->view.target == TEX_TARGET_2D_ARRAY;
   ns_val c[TEX_QUAD][3];
   int layer[TEX_QUAD];
   int32_t lod[TEX_QUAD];
   v4f out[TEX_QUAD];

   for (unsigned p = 0; p < TEX_QUAD; p++) {
      c[p][0] = tex_fcoord(u, k, q->s[p], &x);
      if (dims > 1)
         c[p][1] = tex_fcoord(u, k, q->t[p], &x);
      if (dims > 2)
         c[p][2] = tex_fcoord(u, k, q->r[p], &x);
      layer[p] = array ? layer_of(u, q->layer[p]) : 0;
   }

   lods(ctl, tex_lod_from_diffs(ctl) ? lod_diffs(u, k, dims, c, &x) : 0, q, lod);

   unsigned l0 = 0, l1 = 0;
   uint32_t frac = 0;
   enum tex_filter f = TEX_FILTER_NEAREST;
   int32_t prev = 0;
   for (unsigned p = 0; p < TEX_QUAD; p++) {
      const int32_t cl = tex_clamp_lod(u, lod[p]);
      if (!p || cl != prev)   /* selection depends on the LOD alone */
         tex_unit_select(u, cl, &l0, &l1, &frac, &f);
      prev = cl;
      out[p] = level_f(u, k, dims, f, l0, c[p], layer[p], q->ref[p], &x);
      if (frac)
         out[p] = lerp4(out[p], level_f(u, k, dims, f, l1, c[p], layer[p], q->ref[p], &x), frac);
   }

   for (unsigned ch = 0; ch < 4; ch++) {
      const unsigned s = u->view.swizzle[ch];
      for (unsigned p = 0; p < TEX_QUAD; p++)
         rgba[ch][p] = s < 4 ? out[p][s] : s == TEX_SWZ_1 ? tex_one(&u->view) : 0.0f;
   }
   tex_fst_flush(&x, u->stats);
}

#define QUAD_FN(name, k, dims)                                                              \
   static void name(const struct tex_unit *u, const struct tex_quad *q,                     \
                    enum tex_lod_control ctl, float rgba[4][TEX_QUAD])                      \
   {                                                                                        \
      quad(u, q, ctl, rgba, k, dims);                                                       \
   }

QUAD_FN(quad_dfx19_1d, TEX_FK_DFX19, 1)
QUAD_FN(quad_dfx19_2d, TEX_FK_DFX19, 2)
QUAD_FN(quad_dfx19_3d, TEX_FK_DFX19, 3)
QUAD_FN(quad_float_1d, TEX_FK_FLOAT, 1)
QUAD_FN(quad_float_2d, TEX_FK_FLOAT, 2)
QUAD_FN(quad_float_3d, TEX_FK_FLOAT, 3)

tex_quad_fn tex_fast_choose(const struct tex_unit *u, bool scalar, bool noskip, bool *nolod,
                            tex_quad2_fn *pair, tex_quad4_fn *four)
{
   *nolod = false;
   *pair = NULL;
   *four = NULL;
   static const tex_quad_fn table[2][3] = {
      { quad_dfx19_1d, quad_dfx19_2d, quad_dfx19_3d },
      { quad_float_1d, quad_float_2d, quad_float_3d },
   };
   if (u->view.target == TEX_TARGET_CUBE || u->dims < 1 || u->dims > 3)
      return NULL;
   if (u->kind == TEX_NS_DFX && u->ns->dfx.mant_bits == DFX_MANT_BITS_SEED) {
      if (!scalar && u->dims == 2 && rast_lanes()->tex_dfx19_2d) {
         *nolod = !noskip && tex_unit_lod_unused(u);
         return rast_lanes()->tex_dfx19_2d(u, noskip, *nolod, pair, four);
      }
      return table[0][u->dims - 1];
   }
   if (u->kind == TEX_NS_FLOAT)
      return table[1][u->dims - 1];
   return NULL;
}
