/*
 * The modeled texture unit (spec section 4): coordinates in the texture
 * path's number system (struct numsys, dfx24 by default), wrap modes,
 * texel addresses, bilinear weights, LOD and mip selection as the unit
 * computes them; texels come through a fetch function chosen when the
 * unit is bound.  No Mesa header: the driver's glue (fp_sampler.c)
 * translates gallium state into the descriptors below.
 *
 * Precisions (docs/texture-unit.md):
 *   bilinear weights     TEX_WEIGHT_BITS fraction bits, rounded to nearest
 *   LOD                  signed fixed point, TEX_LOD_FRAC_BITS fraction bits
 *   log2                 leading one + a 256-entry ROM of log2(1 + i/256)
 *   filtering of texels  binary32 (the colour data path is not modelled)
 */
#ifndef FIXPIPE_TEX_H
#define FIXPIPE_TEX_H

#include <stdint.h>
#include <stdbool.h>
#include "fixed/numsys.h"

#define TEX_QUAD 4
#define TEX_MAX_LEVELS 16
#define TEX_WEIGHT_BITS 8
#define TEX_WEIGHT_ONE (1u << TEX_WEIGHT_BITS)
#define TEX_LOD_FRAC_BITS 8
#define TEX_LOD_ONE (1 << TEX_LOD_FRAC_BITS)
#define TEX_LOD_NONE (-(1 << 24))   /* log2(0): below any min_lod clamp */

/* TEX_TARGET_BUFFER: a buffer's texels (GL's texture buffers), one row
 * of level 0 read by texelFetch alone (GLSL samples no buffer).
 * TEX_TARGET_CUBE_ARRAY: cube map arrays, face f of cube L being layer
 * 6 L + f of the view (its layers a multiple of six); a quad's `layer`
 * is L, unrounded. */
enum tex_target {
   TEX_TARGET_1D, TEX_TARGET_2D, TEX_TARGET_3D, TEX_TARGET_CUBE,
   TEX_TARGET_1D_ARRAY, TEX_TARGET_2D_ARRAY, TEX_TARGET_RECT, TEX_TARGET_BUFFER,
   TEX_TARGET_CUBE_ARRAY,
};

/* Same order as gallium's and GL's lists. */
enum tex_wrap {
   TEX_WRAP_REPEAT, TEX_WRAP_CLAMP, TEX_WRAP_CLAMP_TO_EDGE, TEX_WRAP_CLAMP_TO_BORDER,
   TEX_WRAP_MIRROR_REPEAT, TEX_WRAP_MIRROR_CLAMP, TEX_WRAP_MIRROR_CLAMP_TO_EDGE,
   TEX_WRAP_MIRROR_CLAMP_TO_BORDER,
   TEX_WRAP_COUNT
};

enum tex_filter { TEX_FILTER_NEAREST, TEX_FILTER_LINEAR };
/* How LINEAR combines a level's taps (GL's TEXTURE_REDUCTION_MODE, gallium's
 * order): the weighted average, or the least or greatest of the taps whose
 * weight is not zero (ARB/EXT_texture_filter_minmax). */
enum tex_reduction { TEX_REDUCE_AVERAGE, TEX_REDUCE_MIN, TEX_REDUCE_MAX };
enum tex_mip { TEX_MIP_NONE, TEX_MIP_NEAREST, TEX_MIP_LINEAR };

/* Comparison functions in GL's order. */
enum tex_func {
   TEX_FUNC_NEVER, TEX_FUNC_LESS, TEX_FUNC_EQUAL, TEX_FUNC_LEQUAL,
   TEX_FUNC_GREATER, TEX_FUNC_NOTEQUAL, TEX_FUNC_GEQUAL, TEX_FUNC_ALWAYS,
};

/* Texel layouts decoded inside the model; anything else is TEX_FMT_CALLBACK
 * and decoded by the driver.  Packed 16-bit names list the fields from the
 * least significant bit (gallium's convention). */
enum tex_format {
   TEX_FMT_CALLBACK,
   TEX_FMT_RGBA8, TEX_FMT_RGBX8, TEX_FMT_BGRA8, TEX_FMT_BGRX8,
   TEX_FMT_L8, TEX_FMT_A8, TEX_FMT_I8, TEX_FMT_R8, TEX_FMT_LA8,
   TEX_FMT_B5G6R5, TEX_FMT_A4B4G4R4, TEX_FMT_B4G4R4A4, TEX_FMT_A1B5G5R5, TEX_FMT_B5G5R5A1,
   TEX_FMT_COUNT
};

/* Swizzle sources: channels 0..3, then the constants 0 and 1. */
enum { TEX_SWZ_0 = 4, TEX_SWZ_1 = 5 };

/* The slots of the texture unit's rows memo (a power of two). */
#define TEX_ROWS_MEMO 16

/* One mip level.  Layer or slice z, row y and texel x are at
 * data + z * img_stride + y * row_stride + x * texel size. */
struct tex_level {
   const uint8_t *data;
   uint32_t row_stride, img_stride;
   int32_t w, h, d;
};

struct tex_view_desc;
/* A texel, coordinates inside the level; a depth view returns the depth in
 * out[0]. */
typedef void (*tex_fetch_fn)(const struct tex_view_desc *v, const struct tex_level *lv,
                             int x, int y, int z, float out[4]);

struct tex_view_desc {
   enum tex_target target;
   enum tex_format format;
   tex_fetch_fn fetch;          /* the driver's, for TEX_FMT_CALLBACK */
   const void *fetch_ctx;       /* the driver's, for its fetch */
   bool depth;                  /* texels are depths: shadow compare applies */
   unsigned num_levels;         /* the view's levels, level[0] its base */
   struct tex_level level[TEX_MAX_LEVELS];
   int32_t layers;              /* array layers; 6 for a cube */
   uint8_t swizzle[4];
   /* Integer texels (GL ES 3.0's integer formats): the driver's fetch
    * gives their bits, which the unit returns as they are (GL samples them
    * NEAREST), and TEX_SWZ_1 is the integer 1 (tex_one). */
   bool integer;
};

/* The value TEX_SWZ_1 gives. */
static inline float tex_one(const struct tex_view_desc *v)
{
   union { uint32_t u; float f; } one = { 1u };
   return v->integer ? one.f : 1.0f;
}

struct tex_sampler_desc {
   enum tex_wrap wrap[3];
   enum tex_filter min_filter, mag_filter;
   enum tex_mip mip;
   bool normalized;             /* false: texel coordinates (RECT) */
   bool seamless_cube;          /* cube maps filtered across face edges (GL ES 3.0) */
   enum tex_reduction reduction;
   bool compare;
   enum tex_func func;
   float lod_bias, min_lod, max_lod;
   float border[4];             /* already clamped to the format's range */
};

enum tex_lod_control {
   TEX_LOD_IMPLICIT,            /* from the quad's coordinate differences */
   TEX_LOD_BIAS,                /* implicit + quad.lod */
   TEX_LOD_EXPLICIT,            /* quad.lod */
   TEX_LOD_ZERO,
   TEX_LOD_DERIVS,              /* from quad.ddx / quad.ddy */
};

/* One 2x2 quad of requests (pixel order of rast: 0 1 / 2 3). */
struct tex_quad {
   float s[TEX_QUAD], t[TEX_QUAD], r[TEX_QUAD];   /* r: 3D coordinate or cube z */
   float layer[TEX_QUAD];                         /* array layer, unrounded */
   float ref[TEX_QUAD];                           /* shadow reference */
   float lod[TEX_QUAD];                           /* bias or explicit LOD */
   float ddx[3][TEX_QUAD], ddy[3][TEX_QUAD];      /* explicit derivatives */
};

/* What address computation gives for one axis: two texel indices (-1: the
 * border colour) and the weight of i1 in units of 2^-TEX_WEIGHT_BITS. */
struct tex_addr {
   int32_t i0, i1;
   uint32_t w;
};

/* Per level and axis, in the number system: the scale from the coordinate
 * to texels and the clamp bounds of the clamp modes. */
struct tex_axis {
   int32_t size;
   ns_val scale;
   ns_val lo, hi;
};

struct tex_unit;
typedef void (*tex_addr_fn)(const struct tex_unit *u, const struct tex_axis *ax, ns_val c,
                            struct tex_addr *a);
typedef void (*tex_tap_fn)(const struct tex_unit *u, const struct tex_level *lv,
                           int x, int y, int z, float ref, float out[4]);
typedef void (*tex_level_fn)(const struct tex_unit *u, unsigned level, const ns_val c[3],
                             int layer, float ref, float out[4]);
typedef void (*tex_quad_fn)(const struct tex_unit *u, const struct tex_quad *q,
                            enum tex_lod_control ctl, float rgba[4][TEX_QUAD]);
typedef void (*tex_quad2_fn)(const struct tex_unit *u, const struct tex_quad q[2],
                             enum tex_lod_control ctl, float rgba[2][4][TEX_QUAD]);
typedef void (*tex_quad4_fn)(const struct tex_unit *u, const struct tex_quad q[4],
                             enum tex_lod_control ctl, float rgba[4][4][TEX_QUAD]);
/* A gather's footprint, what the address unit hands the texel reads: per
 * pixel the two columns and two rows of the base level's bilinear
 * footprint (-1: the border) after a mirroring wrap's exchange, so that
 * GL's four texels are (x[0], y[1]), (x[1], y[1]), (x[1], y[0]),
 * (x[0], y[0]); the layer; and the range events the addressing raised,
 * counted by every gather that reads the footprint. */
struct tex_footprint {
   int32_t x[2][TEX_QUAD], y[2][TEX_QUAD], layer[TEX_QUAD];
   struct ns_stats events;
};
typedef void (*tex_footprint_fn)(const struct tex_unit *u, const struct tex_quad *q,
                                 struct tex_footprint *f);

struct tex_unit {
   const struct numsys *ns;
   struct ns_stats *stats;        /* range events of the number system */
   struct tex_view_desc view;
   struct tex_sampler_desc samp;

   /* Chosen at bind: filter x wrap per axis, target, tap kind. */
   unsigned dims;                 /* filtered axes */
   tex_addr_fn addr[2][3];        /* [filter][axis] */
   tex_level_fn sample_level[2];   /* [filter] */
   tex_tap_fn tap;
   /* how LINEAR mipmapping combines the two levels' results, the upper's
    * weight in 2^-TEX_WEIGHT_BITS: their lerp, or their min or max under a
    * min/max reduction, which takes every texel with a nonzero weight */
   void (*mix_levels)(float o[4], const float a[4], const float b[4], uint32_t w);
   tex_fetch_fn fetch;
   /* dfx24 and binary32: the whole quad specialised (tex_fast.c), NULL for
    * the table path above. */
   tex_quad_fn quad;
   /* two quads in one call, their operations side by side (the lanes'
    * specialised quads); NULL: quad twice */
   tex_quad2_fn quad2;
   /* four quads in one call, two pairs step by step; NULL: quad2 twice */
   tex_quad4_fn quad4;
   /* textureGather's address stage specialised (tex_fast.c: 2-D views,
    * dfx24 and binary32), the texel reads then tex_unit_gather_read;
    * NULL: tex_unit_gather_generic */
   tex_footprint_fn footprint;
   bool lod_skipped;              /* quad leaves out the LOD (tex_unit_lod_unused) */
   uint32_t bind_serial;          /* which binding: RTL vectors dump a binding once */
   /* texel reads a pixel, for the counters: the minification filter's taps
    * (1 or 2^dims), twice when it blends two mip levels */
   unsigned taps;
   /* quad-axes of pairs addressed once per column or row (the lanes' pair
    * functions: s that follows the screen's x, t that follows y), counted
    * here when not NULL; NULL after bind */
   uint64_t *axes_shared;
   struct tex_axis axis[TEX_MAX_LEVELS][3];
   int32_t lod_bias, min_lod, max_lod;   /* units of 2^-TEX_LOD_FRAC_BITS */
   int kind;                      /* the number system's family (tex_ns.h) */
   ns_val k_zero, k_one, k_half, k_two, k_minus_one;
   ns_val k_texel_offset;        /* linear filtering: 1/2 - 2^-(TEX_WEIGHT_BITS+1) */
   /* dfx24 on lanes (tex_lanes.c): the registers above as the lanes hold
    * them, their values in doubles (the texel offset is a constant there,
    * DFXL_TEXEL_OFFSET); [l][a]: scale, lo, hi of axis[l][a] */
   double lk_one;
   bool lanes_soa;                /* the filter one channel per vector (tex_bind.c) */
   /* with lanes_soa, each result channel (after the swizzle) from the
    * texel word: ((word >> shift) & mask) / 255 + add, the border's where
    * outside; a constant channel (swizzle 0 or 1, X formats' alpha) has
    * mask 0.  `pick`: the same byte as a byte shuffle's control (each
    * word's byte shift / 8 to its low byte, the others zero; all zero for
    * mask 0). */
   struct tex_lanes_channel {
      int32_t shift, mask;
      float add, border;
      uint8_t pick[16];
   } lanes_ch[4];
   uint8_t lanes_const;           /* bit ch: lanes_ch[ch] is a constant (mask 0) */
   double laxis[TEX_MAX_LEVELS][3][3];
   /* level 0's s and t constants side by side, as the address unit takes
    * both axes in one vector (tex_lanes.c's pair_addr): [0] scale, [1] lo,
    * [2] hi, lanes 0-3 of s, 4-7 of t; and the two sizes */
   double laxis_st[3][8];
   int32_t lsize_st[8];
   /* The rows' addresses of four quads whose t followed the rows
    * (tex_lanes.c's pairs4), by the rows' t: later four quads on the same
    * rows take them instead of the address unit.  Several rows at once, a
    * slot by a hash of the t registers: a vertical blur's taps each have
    * their own rows, the same for every four quads along them.  The unit's
    * one part written while sampling (a unit is a thread's own), cleared
    * by binding. */
   struct tex_rows_memo {
      bool valid;
      double t[2];
      int32_t i0[8], i1[8], w[8];
   } rows_memo[TEX_ROWS_MEMO];
   /* Four-quad calls whose taps were read from their texel rows instead of
    * gathered (tex_lanes.c's rows_words): the tests' proof that the path
    * ran.  Written while sampling, as the memo. */
   uint64_t rows_loaded;
   /* Of those, the calls whose leftmost texel column was not at either end
    * quad (found by the reduction): the tests' proof of that way. */
   uint64_t rows_reduced;
};

/* Bind: copies the descriptors, converts constants into the number system
 * and chooses the functions.  The view's level data must stay valid.
 * `stats` counts the range events of sampling; the constants' conversions
 * are register loads, not counted. */
void tex_unit_bind(struct tex_unit *u, const struct numsys *ns, const struct tex_view_desc *v,
                   const struct tex_sampler_desc *s, struct ns_stats *stats);
/* The datapath (FIXPIPE_DEBUG=scalar,noskip): `scalar` takes the scalar
 * reference quads instead of the lanes' (the same bits); `noskip` computes
 * the LOD even where the sampler cannot use it (the same bits; the range
 * events of a LOD left out are not counted, the modeled unit not clocking
 * it).  tex_unit_bind chooses as with both false. */
void tex_unit_set_datapath(struct tex_unit *u, bool scalar, bool noskip);
/* Whether no LOD can change what the unit samples: it only ever reads one
 * level (no mip filter, one level, or texel coordinates) and minifies and
 * magnifies alike. */
bool tex_unit_lod_unused(const struct tex_unit *u);

/* Sample a quad; rgba[channel][pixel], swizzled. */
void tex_unit_sample(const struct tex_unit *u, const struct tex_quad *q,
                     enum tex_lod_control ctl, float rgba[4][TEX_QUAD]);
/* Two quads: the same bits and range events as tex_unit_sample on each. */
void tex_unit_sample2(const struct tex_unit *u, const struct tex_quad q[2],
                      enum tex_lod_control ctl, float rgba[2][4][TEX_QUAD]);

/* `n` quads (up to four; four in one call where the unit has quad4): the
 * same bits and range events as tex_unit_sample on each. */
void tex_unit_sample_quads(const struct tex_unit *u, const struct tex_quad *q, unsigned n,
                           enum tex_lod_control ctl, float rgba[][4][TEX_QUAD]);

/* The table path (struct numsys calls, the functions above) whatever the
 * number system: what tex_unit_sample does without u->quad, for tests
 * holding the specialised quad to it. */
void tex_unit_sample_generic(const struct tex_unit *u, const struct tex_quad *q,
                             enum tex_lod_control ctl, float rgba[4][TEX_QUAD]);

/* textureQueryLod (tex_sample.c): per pixel the LOD register the unit
 * computes with the sampler's bias, before its clamps (-infinity for
 * log2 0), in lod; and in level the mip levels it then reads: the level
 * (NEAREST mip filter), the lower level plus the weight of the upper
 * (LINEAR), 0 without mipmapping.  The table path's stages, as
 * tex_unit_sample_generic takes them. */
void tex_unit_query_lod(const struct tex_unit *u, const struct tex_quad *q,
                        enum tex_lod_control ctl, float level[TEX_QUAD], float lod[TEX_QUAD]);

/* textureOffset and its kin: `offset` texels (per axis, GLSL's constant
 * offsets) added at the level sampled, not at the base level: the
 * coordinate moves by offset / size of each level the filter reads, before
 * the wrap (GL ES 3.0 3.8.10).  The table path. */
void tex_unit_sample_offset(const struct tex_unit *u, const struct tex_quad *q,
                            enum tex_lod_control ctl, const int8_t offset[3],
                            float rgba[4][TEX_QUAD]);

/* textureGather (tex_gather.c): channel `comp` (after the swizzle; for a
 * depth view with comparison, the comparison) of the four texels of the
 * base level's bilinear footprint, in GL's order: rgba[0] = (i0, j1),
 * [1] = (i1, j1), [2] = (i1, j0), [3] = (i0, j0).  2-D, 2-D array and
 * cube views. */
void tex_unit_gather(const struct tex_unit *u, const struct tex_quad *q, unsigned comp,
                     float rgba[4][TEX_QUAD]);
/* The table path of it: the reference the specialised gather
 * (u->footprint, then tex_unit_gather_read) must match bit for bit. */
void tex_unit_gather_generic(const struct tex_unit *u, const struct tex_quad *q, unsigned comp,
                             float rgba[4][TEX_QUAD]);
/* The two stages of a specialised gather, for a caller that gathers
 * several channels of one footprint (the driver's memo, docs/datapath.md):
 * the address stage, false where the unit has none (cube maps, the table
 * path: tex_unit_gather then), and the texel reads of channel `comp`,
 * which count the footprint's range events as tex_unit_gather does. */
bool tex_unit_gather_footprint(const struct tex_unit *u, const struct tex_quad *q,
                               struct tex_footprint *f);
void tex_unit_gather_read(const struct tex_unit *u, const struct tex_footprint *f,
                          const float ref[TEX_QUAD], unsigned comp, float rgba[4][TEX_QUAD]);
/* Every channel of a footprint at once, rgba[c] what tex_unit_gather_read
 * gives for channel c, counting no event: the 4-byte layouts' sixteen
 * words read once for all their channels (where tex_unit_gather_reads_words,
 * the unit's layout is one of them with no comparison), for a caller
 * that keeps them for the run's other gathers of the footprint; and the
 * events one gather of the footprint counts. */
bool tex_unit_gather_reads_words(const struct tex_unit *u);
void tex_unit_gather_read_all(const struct tex_unit *u, const struct tex_footprint *f,
                              const float ref[TEX_QUAD], float rgba[4][4][TEX_QUAD]);
void tex_unit_gather_count(const struct tex_unit *u, const struct tex_footprint *f);

/* The registers a compiled copy of the specialised gather reads
 * (src/gallium-like/fp_jit_gather.c): the dfx24 address stage of a 2-D or
 * rectangle view clamped to its edges on both axes and the texel reads of
 * the 4-byte layouts, for the gathers that raise no range event (the copy
 * hands every other call to u->footprint and tex_unit_gather_read, which
 * count them).  A dfx24 value is three words: sign, location, mantissa. */
struct tex_gather_regs {
   const uint8_t *data;            /* the base level's first texel */
   int32_t row_stride;             /* bytes */
   int32_t size[2];                /* texels per axis */
   float offset_unit[2];           /* a texel offset in coordinate units is offset / this */
   int32_t scale[2][3];            /* the coordinate's scale to texels */
   int32_t lo[2][3], hi[2][3];     /* the clamp's bounds */
   /* and their order as one signed word: +-(L << W | M), 0 for zero */
   int32_t lo_key[2], hi_key[2];
   int32_t neg_half[3];            /* -k_texel_offset: the footprint's corner */
   /* per gathered component, after the swizzle: the byte's shift in the
    * texel word, or -1 for the constant */
   int32_t shift[4];
   float constant[4];
};
/* Fills `r` and returns true where the unit's gathers can take the
 * compiled copy: dfx24 at the seed's width, a 2-D or rectangle view of a
 * 4-byte layout without comparison, CLAMP_TO_EDGE on both axes, 2 to 2^20
 * columns (the copy reads a row's two texels as one 8-byte word) and up
 * to 2^20 rows, every texel within 2^31 bytes of the first. */
bool tex_unit_gather_regs(const struct tex_unit *u, struct tex_gather_regs *r);

/* texelFetch: integer coordinates, level relative to the view; outside
 * the level gives (0, 0, 0, 0) before swizzle.  z is the layer or slice. */
void tex_view_texel(const struct tex_view_desc *v, const int x[TEX_QUAD], const int y[TEX_QUAD],
                    const int z[TEX_QUAD], const int level[TEX_QUAD], float rgba[4][TEX_QUAD]);

/* The fetch function of a format decoded by the model, NULL for
 * TEX_FMT_CALLBACK; bytes per texel of those formats. */
tex_fetch_fn tex_format_fetch(enum tex_format f);
unsigned tex_format_bytes(enum tex_format f);

/* Adds the unit's range events to the model's counters (rast_stats
 * tex_sat / tex_flush, printed by FIXPIPE_STATS), and its quads without a
 * LOD among those with an implicit or biased one (skip_tex_lod,
 * tex_lod_quads), and its quad-axes addressed once per column or row among
 * the two axes of all quads it sampled (skip_tex_axes, tex_quads), and its
 * gather quads that read a footprint addressed before (skip_tex_footprint). */
struct rast_context;
void tex_stats_to_rast(struct rast_context *rc, uint64_t sat, uint64_t flush, uint64_t skip_lod,
                       uint64_t lod_quads, uint64_t skip_axes, uint64_t skip_footprint,
                       uint64_t quads, uint64_t texels);

/* Adds gather quads the unit's copy in compiled code did (tex_gather_jit). */
void tex_stats_jit_gathers(struct rast_context *rc, uint64_t quads);

/* Pieces of the data path, for tests. */
int32_t tex_lod_from_rho(const struct tex_unit *u, ns_val rho);       /* log2 */
int32_t tex_lod_quad(const struct tex_unit *u, const struct tex_quad *q);
unsigned tex_cube_face(const struct tex_unit *u, ns_val rx, ns_val ry, ns_val rz,
                       ns_val *s, ns_val *t);
/* Seamless cube maps (tex_cube.c): the texel across a face's edge from the
 * tap (x, y), one of them in {-1, size}; false at a corner. */
bool tex_cube_across(unsigned face, int32_t size, int32_t x, int32_t y, unsigned *face_out,
                     int32_t *x_out, int32_t *y_out);
void tex_cube_on_face(const struct tex_unit *u, unsigned face, ns_val rx, ns_val ry, ns_val rz,
                      ns_val *s, ns_val *t);
void tex_unit_select(const struct tex_unit *u, int32_t lod, unsigned *level0, unsigned *level1,
                     uint32_t *frac, enum tex_filter *filter);

#endif
