/*
 * Binding: the unit's constants in the number system and its functions,
 * chosen once per (view, sampler) pair so that sampling never branches on
 * state.
 */
#include <stdatomic.h>
#include <string.h>
#include "rast/tex/tex_priv.h"
#include "fixed/dfx_lanes.h"

static unsigned target_dims(enum tex_target t)
{
   switch (t) {
   case TEX_TARGET_1D: case TEX_TARGET_1D_ARRAY: case TEX_TARGET_BUFFER: return 1;
   case TEX_TARGET_3D: return 3;
   default: return 2;
   }
}

/* Clamp bounds of a mode, in coordinate units: normalized [0,1]-based, or
 * texels for unnormalized coordinates.  Border modes keep one period
 * beyond the edge, enough for both taps to be outside; nothing further
 * changes the result, and nothing larger can saturate the scaled value. */
static void axis_bounds(const struct tex_unit *u, enum tex_wrap w, int32_t size,
                        struct tex_axis *ax)
{
   const float span = u->samp.normalized ? 1.0f : (float)size;
   float lo = 0.0f, hi = span;
   switch (w) {
   case TEX_WRAP_CLAMP_TO_BORDER:
      lo = -1.0f;
      hi = u->samp.normalized ? 2.0f : span + 1.0f;
      break;
   case TEX_WRAP_MIRROR_CLAMP_TO_BORDER:
      hi = u->samp.normalized ? 2.0f : span + 1.0f;
      break;
   default:
      break;
   }
   ax->lo = u->ns->from_float(u->ns, lo, u->stats);
   ax->hi = u->ns->from_float(u->ns, hi, u->stats);
}

/* The unit's constants as the dfx24 lanes hold them (tex_lanes.c). */
static double lanes_value(const struct tex_unit *u, ns_val v)
{
   return u->kind == TEX_NS_DFX ? dfxl_value(v.d) : 0.0;
}

/* Whether the lanes' filter takes the unit one channel per vector: 4-byte
 * texels without a shadow compare, every tap's byte offset in int32. */
static bool lanes_soa(const struct tex_unit *u)
{
   const enum tex_format f = u->view.format;
   if (f < TEX_FMT_RGBA8 || f > TEX_FMT_BGRX8 || (u->samp.compare && u->view.depth))
      return false;
   const uint64_t layers = u->view.layers > 1 ? (uint64_t)u->view.layers : 1;
   for (unsigned l = 0; l < u->view.num_levels; l++) {
      const struct tex_level *lv = &u->view.level[l];
      const uint64_t w = lv->w > 1 ? (uint64_t)lv->w : 1, h = lv->h > 1 ? (uint64_t)lv->h : 1;
      if ((layers - 1) * lv->img_stride + (h - 1) * lv->row_stride + w * 4 > INT32_MAX)
         return false;
   }
   return true;
}

/* The result channels of a lanes_soa unit from its texel words: the
 * swizzle taken into the decoding, which filters constants exactly
 * (a + f (a - a) is a). */
static void lanes_channels(struct tex_unit *u)
{
   const enum tex_format f = u->view.format;
   const bool bgr = f == TEX_FMT_BGRA8 || f == TEX_FMT_BGRX8;
   const bool x = f == TEX_FMT_RGBX8 || f == TEX_FMT_BGRX8;
   static const int32_t shift_rgba[4] = { 0, 8, 16, 24 }, shift_bgra[4] = { 16, 8, 0, 24 };
   for (unsigned ch = 0; ch < 4; ch++) {
      struct tex_lanes_channel *c = &u->lanes_ch[ch];
      const unsigned s = u->view.swizzle[ch];
      if (s < 4 && !(s == 3 && x)) {
         *c = (struct tex_lanes_channel){ bgr ? shift_bgra[s] : shift_rgba[s], 0xff, 0.0f,
                                          u->samp.border[s], { 0 } };
      } else {
         const float k = s == 3 || s == TEX_SWZ_1 ? tex_one(&u->view) : 0.0f;
         *c = (struct tex_lanes_channel){ 0, 0, k, s < 4 ? u->samp.border[s] : k, { 0 } };
      }
      for (unsigned b = 0; b < 16; b++)
         c->pick[b] = b % 4 == 0 && c->mask ? (uint8_t)(b + c->shift / 8) : 0x80;
      if (!c->mask)
         u->lanes_const |= (uint8_t)(1u << ch);
   }
}

static void lanes_constants(struct tex_unit *u)
{
   u->lanes_soa = lanes_soa(u);
   u->lanes_const = 0;
   if (u->lanes_soa)
      lanes_channels(u);
   u->lk_one = lanes_value(u, u->k_one);
   for (unsigned l = 0; l < u->view.num_levels; l++)
      for (unsigned a = 0; a < 3; a++) {
         u->laxis[l][a][0] = lanes_value(u, u->axis[l][a].scale);
         u->laxis[l][a][1] = lanes_value(u, u->axis[l][a].lo);
         u->laxis[l][a][2] = lanes_value(u, u->axis[l][a].hi);
      }
   for (unsigned k = 0; k < 3; k++)
      for (unsigned i = 0; i < 8; i++)
         u->laxis_st[k][i] = u->laxis[0][i / 4][k];
   for (unsigned i = 0; i < 8; i++)
      u->lsize_st[i] = (int32_t)u->axis[0][i / 4].size;
}

void tex_unit_bind(struct tex_unit *u, const struct numsys *ns, const struct tex_view_desc *v,
                   const struct tex_sampler_desc *s, struct ns_stats *stats)
{
   /* The constants are loaded once per binding, not computed per pixel:
    * their conversions are not range events of the datapath (and a unit is
    * bound again per thread and whenever its state comes back, which would
    * make such counts depend on the threads and the binding order). */
   struct ns_stats loads = { 0, 0 };
   static _Atomic uint32_t serials;
   memset(u, 0, sizeof(*u));
   u->bind_serial = atomic_fetch_add(&serials, 1) + 1;
   u->ns = ns;
   u->stats = &loads;
   u->view = *v;
   u->samp = *s;
   u->kind = tex_ns_kind(ns);
   if (u->view.num_levels < 1)
      u->view.num_levels = 1;
   if (u->view.num_levels > TEX_MAX_LEVELS)
      u->view.num_levels = TEX_MAX_LEVELS;

   u->k_zero = ns->from_float(ns, 0.0f, &loads);
   u->k_one = ns->from_float(ns, 1.0f, &loads);
   u->k_half = ns->from_float(ns, 0.5f, &loads);
   /* Linear filtering's half-texel offset, less half a weight LSB: the
    * weight, the fraction's top TEX_WEIGHT_BITS bits, is then rounded to
    * nearest rather than truncated, so a coordinate that interpolation puts
    * a hair below a texel centre still takes that texel alone (piglit
    * 1-1-linear-texture; llvmpipe rounds its 8-bit weights too). */
   u->k_texel_offset = ns->from_float(ns, 0.5f - 1.0f / (float)(2u * TEX_WEIGHT_ONE), &loads);
   u->k_two = ns->from_float(ns, 2.0f, &loads);
   u->k_minus_one = ns->from_float(ns, -1.0f, &loads);

   /* Targets without coordinates to wrap on some axis, and the rules GL
    * and llvmpipe apply: cube faces clamp to their edge; rectangles
    * (texel coordinates) know no periodic modes. */
   if (tex_is_cube(v->target))
      u->samp.wrap[0] = u->samp.wrap[1] = TEX_WRAP_CLAMP_TO_EDGE;
   if (v->target == TEX_TARGET_RECT)
      u->samp.normalized = false;
   if (!u->samp.normalized) {
      u->samp.mip = TEX_MIP_NONE;
      for (unsigned a = 0; a < 3; a++)
         if (u->samp.wrap[a] == TEX_WRAP_REPEAT || u->samp.wrap[a] == TEX_WRAP_MIRROR_REPEAT)
            u->samp.wrap[a] = TEX_WRAP_CLAMP_TO_EDGE;
   }
   u->dims = target_dims(v->target);
   u->taps = (s->min_filter == TEX_FILTER_LINEAR ? 1u << u->dims : 1u) *
             (s->mip == TEX_MIP_LINEAR ? 2u : 1u);

   for (unsigned f = 0; f < 2; f++) {
      for (unsigned a = 0; a < 3; a++)
         u->addr[f][a] = tex_addr_choose(u->samp.wrap[a], (enum tex_filter)f);
      u->sample_level[f] = tex_level_choose(u->dims, (enum tex_filter)f, s->reduction);
   }
   /* Seamless cube maps: LINEAR reads across the face's edges; NEAREST
    * never leaves the face, so its CLAMP_TO_EDGE above is already right. */
   if (tex_is_cube(v->target) && s->seamless_cube) {
      u->addr[TEX_FILTER_LINEAR][0] = u->addr[TEX_FILTER_LINEAR][1] = tex_addr_cube_seamless;
      u->sample_level[TEX_FILTER_LINEAR] = tex_level_cube_seamless(s->reduction);
   }
   u->tap = tex_tap_choose(u->samp.compare && v->depth);
   u->mix_levels = s->reduction == TEX_REDUCE_MIN   ? tex_min4
                   : s->reduction == TEX_REDUCE_MAX ? tex_max4 : tex_lerp4;
   u->fetch = tex_format_fetch(v->format);
   if (!u->fetch)
      u->fetch = v->fetch;

   for (unsigned l = 0; l < u->view.num_levels; l++) {
      const struct tex_level *lv = &u->view.level[l];
      const int32_t size[3] = { lv->w, lv->h, lv->d };
      for (unsigned a = 0; a < 3; a++) {
         struct tex_axis *ax = &u->axis[l][a];
         ax->size = size[a] > 0 ? size[a] : 1;
         ax->scale = u->samp.normalized ? ns->from_float(ns, (float)ax->size, &loads) : u->k_one;
         axis_bounds(u, u->samp.wrap[a], ax->size, ax);
      }
   }

   u->lod_bias = tex_lod_fixed(s->lod_bias);
   u->min_lod = tex_lod_fixed(s->min_lod);
   u->max_lod = tex_lod_fixed(s->max_lod);
   if (u->kind == TEX_NS_DFX && ns->dfx.mant_bits == DFX_MANT_BITS_SEED)
      lanes_constants(u);
   tex_unit_set_datapath(u, false, false);
   u->stats = stats;
}

void tex_unit_set_datapath(struct tex_unit *u, bool scalar, bool noskip)
{
   u->quad = tex_fast_choose(u, scalar, noskip, &u->lod_skipped, &u->quad2, &u->quad4);
   u->footprint = tex_fast_footprint_choose(u, scalar);
}
