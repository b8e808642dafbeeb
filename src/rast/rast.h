/*
 * The modeled rasterizer: what the pipe driver sees of it.
 *
 * Vertices arrive after Mesa's draw module has run the vertex shader,
 * clipping, the perspective divide and the viewport (spec section 1), as
 * arrays of float[4] slots.  The model converts them to its fixed-point
 * registers, culls by the sign of the 2-D determinant, scan-converts them
 * (seed 000: sorted vertices, types 0/1/2, halves A and B, X_next, edge and
 * span processors, top-left rule) and hands 2x2 quads to the fragment shader
 * callback, then runs the fragment back end (scissor, stencil, depth in the
 * profile's Z format, blend, colour mask) on what survives.
 *
 * Window coordinates are gallium's: x to the right, y down the rows of the
 * render target, pixel (i, j) covering [i, i+1) x [j, j+1).
 *
 * This header and everything under src/rast and src/fixed is plain C11 and
 * includes no Mesa header.
 */
#ifndef FIXPIPE_RAST_H
#define FIXPIPE_RAST_H

#include <stddef.h>
#include <stdint.h>
#include <stdbool.h>
#include <stdio.h>
#include "fixed/fx.h"

#define RAST_MAX_VARYINGS 32
#define RAST_MAX_CBUFS    8
#define RAST_MAX_THREADS  64
#define RAST_GROUP_MAX    4   /* quads a call of a shader's wide form (rast_shader.shade_n) */
#define RAST_QUAD_SIZE    4   /* pixel i of a quad: 0 (x,y) 1 (x+1,y) 2 (x,y+1) 3 (x+1,y+1) */

/* ------------------------------------------------------------------ */
/* Profiles: the register formats are a run-time choice.               */

/* Saturation counters, one per register class of Table 1. */
enum rast_reg_class {
   RAST_REG_XY,        /* vertex X, Y and X_left/X_right/X_next */
   RAST_REG_DXDY,      /* edge slopes dx/dy */
   RAST_REG_Z,         /* Z registers and their slopes */
   RAST_REG_COLOR,     /* R, G, B, A registers and their slopes */
   RAST_REG_WEIGHT,    /* the per-pixel weights of FIXPIPE_INTERP=barycentric|vector */
   RAST_REG_COUNT
};

struct rast_profile {
   const char *name;
   const char *summary;            /* one line for docs and error messages */
   struct fx_format xy;            /* seed: 12.12 */
   struct fx_format dxdy;          /* seed: 12.12 */
   struct fx_format z;             /* seed: 20.12 */
   struct fx_format color;         /* seed: 9.12, in units of 1/255 */
   unsigned z_bits;                /* Z full scale is (2^z_bits - 1): seed 19, wide 24 */
   /* X_out/Y_out, the scan converter's pixel address: seed 11 bits.  A
    * larger target is drawn in tiles of this side (tile.c). */
   unsigned tile_size;
   unsigned max_target;            /* largest target and texture side (the GL limits) */
   bool color_perspective;         /* seed: false, colour is the seed's linear Gouraud walk */
   /* The weights of the per-pixel independent interpolators (seeds 001,
    * 002; docs/interp-modes.md): 8.24 in both profiles. */
   struct fx_format weight;
   /* The seed's edge walk as Table 1 gives it: X_left, X_right step by the
    * Δx/Δy register alone, without the remainder that makes the walk
    * exact (docs/profiles.md, "Precision settings").  false in both. */
   bool literal_walk;
};

/* NULL when the name is unknown. */
const struct rast_profile *rast_profile_by_name(const char *name);
/* A profile with its own storage: a named one with some fraction bits
 * changed ("seed:xy=12.8,z=20.16,walk=literal"; docs/profiles.md). */
struct rast_profile_buf {
   struct rast_profile p;
   char name[96];                  /* the setting, normalised */
   char summary[256];
};
/* Parses NAME[:KEY=VALUE,...] into *out.  false on a bad setting, with one
 * line in err that names the accepted keys and ranges. */
bool rast_profile_parse(const char *spec, struct rast_profile_buf *out, char *err,
                        size_t err_size);
/* "seed, wide": for error messages and --help. */
const char *rast_profile_names(void);
/* The profiles in a NULL-terminated list, for docs and tests. */
const struct rast_profile *const *rast_profile_list(void);

/* ------------------------------------------------------------------ */
/* Per-fragment state.  Enumerations mean what their GL names say.     */

enum rast_func {        /* depth, stencil compare */
   RAST_FUNC_NEVER, RAST_FUNC_LESS, RAST_FUNC_EQUAL, RAST_FUNC_LEQUAL,
   RAST_FUNC_GREATER, RAST_FUNC_NOTEQUAL, RAST_FUNC_GEQUAL, RAST_FUNC_ALWAYS
};

enum rast_stencil_op {
   RAST_STENCIL_KEEP, RAST_STENCIL_ZERO, RAST_STENCIL_REPLACE,
   RAST_STENCIL_INCR, RAST_STENCIL_DECR, RAST_STENCIL_INCR_WRAP,
   RAST_STENCIL_DECR_WRAP, RAST_STENCIL_INVERT
};

enum rast_blend_eq {
   RAST_BLEND_ADD, RAST_BLEND_SUBTRACT, RAST_BLEND_REVERSE_SUBTRACT,
   RAST_BLEND_MIN, RAST_BLEND_MAX
};

enum rast_blend_factor {
   RAST_BF_ZERO, RAST_BF_ONE,
   RAST_BF_SRC_COLOR, RAST_BF_INV_SRC_COLOR,
   RAST_BF_SRC_ALPHA, RAST_BF_INV_SRC_ALPHA,
   RAST_BF_DST_COLOR, RAST_BF_INV_DST_COLOR,
   RAST_BF_DST_ALPHA, RAST_BF_INV_DST_ALPHA,
   RAST_BF_CONST_COLOR, RAST_BF_INV_CONST_COLOR,
   RAST_BF_CONST_ALPHA, RAST_BF_INV_CONST_ALPHA,
   RAST_BF_SRC_ALPHA_SATURATE,
   RAST_BF_SRC1_COLOR, RAST_BF_INV_SRC1_COLOR,
   RAST_BF_SRC1_ALPHA, RAST_BF_INV_SRC1_ALPHA
};

struct rast_stencil_face {
   bool enabled;
   enum rast_func func;
   enum rast_stencil_op fail_op, zfail_op, zpass_op;
   uint8_t valuemask, writemask;
};

struct rast_depth_stencil_state {
   bool depth_enabled;
   bool depth_writemask;
   enum rast_func depth_func;
   struct rast_stencil_face stencil[2];   /* [0] front, [1] back */
};

struct rast_blend_target {
   bool blend_enable;
   enum rast_blend_eq rgb_eq, alpha_eq;
   enum rast_blend_factor rgb_src, rgb_dst, alpha_src, alpha_dst;
   uint8_t colormask;                     /* bit 0 R, 1 G, 2 B, 3 A */
};

/* GL's order (GL_CLEAR .. GL_SET, gallium's PIPE_LOGICOP_*).  The value is
 * the op's truth table: bit (2*s + d) is the result for source bit s and
 * destination bit d. */
enum rast_logicop {
   RAST_LOGICOP_CLEAR, RAST_LOGICOP_NOR, RAST_LOGICOP_AND_INVERTED,
   RAST_LOGICOP_COPY_INVERTED, RAST_LOGICOP_AND_REVERSE, RAST_LOGICOP_INVERT,
   RAST_LOGICOP_XOR, RAST_LOGICOP_NAND, RAST_LOGICOP_AND, RAST_LOGICOP_EQUIV,
   RAST_LOGICOP_NOOP, RAST_LOGICOP_OR_INVERTED, RAST_LOGICOP_COPY,
   RAST_LOGICOP_OR_REVERSE, RAST_LOGICOP_OR, RAST_LOGICOP_SET
};

struct rast_blend_state {
   bool independent;                      /* else rt[0] applies to all */
   /* Replaces blending on every normalized (clamp) target: the op works on
    * the stored bits of the pixel.  Float targets get the source, unblended
    * (GL: no effect on floating-point buffers; llvmpipe, softpipe). */
   bool logicop_enable;
   enum rast_logicop logicop_func;
   /* Multisampled targets: sample k of a pixel is kept where the shader's
    * first colour output has alpha > k / 4 (llvmpipe's rule). */
   bool alpha_to_coverage;
   struct rast_blend_target rt[RAST_MAX_CBUFS];
};

/* ------------------------------------------------------------------ */
/* Render targets.  The back end reads and writes them directly; the     */
/* driver supplies pack/unpack for formats the model has no fast path for. */

enum rast_color_layout {
   RAST_CL_GENERIC,     /* use load/store */
   RAST_CL_RGBA8,       /* bytes R, G, B, A (unorm) */
   RAST_CL_BGRA8,       /* bytes B, G, R, A (unorm) */
   RAST_CL_BGRX8        /* bytes B, G, R, x (unorm, alpha reads 1) */
};

typedef void (*rast_load_func)(const uint8_t *src, unsigned n, float (*rgba)[4]);
typedef void (*rast_store_func)(uint8_t *dst, unsigned n, const float (*rgba)[4]);

struct rast_color_target {
   uint8_t *base;                 /* pixel (0, 0) of the bound level/layer */
   int stride;                    /* bytes between rows */
   unsigned cpp;                  /* bytes per pixel */
   enum rast_color_layout layout;
   rast_load_func load;           /* always set: RGBA float of n pixels */
   rast_store_func store;         /* always set */
   bool clamp;                    /* unorm/snorm: clamp blend inputs */
   bool snorm;                    /* with clamp: to [-1, 1], not [0, 1] */
   size_t sample_stride;          /* multisampled: bytes from one sample's plane to the next */
   unsigned layers;               /* layered (gl_Layer): layers bound from base on, 0 or 1: one */
   size_t layer_stride;           /* bytes from one layer (with its samples) to the next */
};

enum rast_zs_layout {
   RAST_ZS_NONE,
   RAST_ZS_Z16,                 /* uint16 z */
   RAST_ZS_Z32,                 /* uint32 z (unorm32) */
   RAST_ZS_Z24_S8,              /* uint32: z in bits 0..23, stencil 24..31 */
   RAST_ZS_Z24X8,               /* uint32: z in bits 0..23 */
   RAST_ZS_S8_Z24,              /* uint32: stencil 0..7, z in 8..31 */
   RAST_ZS_X8Z24,               /* uint32: z in 8..31 */
   RAST_ZS_Z32F,                /* float z */
   RAST_ZS_Z32F_S8X24,          /* float z, then uint32 with stencil in 0..7 */
   RAST_ZS_S8                   /* uint8 stencil only */
};

struct rast_zs_target {
   uint8_t *base;
   int stride;
   enum rast_zs_layout layout;
   size_t sample_stride;          /* multisampled: bytes from one sample's plane to the next */
   unsigned layers;               /* as rast_color_target's */
   size_t layer_stride;
};

/* Multisampling (msaa.c, docs/msaa.md): a target of RAST_MSAA_SAMPLES
 * samples a pixel stores each sample in a plane of its own, the
 * single-sampled layout, sample_stride bytes apart; sample k sits at
 * rast_sample_pos_4x[k] in its pixel (llvmpipe's and D3D's standard
 * pattern, multiples of 1/8: exact in the XY register). */
#define RAST_MSAA_SAMPLES 4
extern const float rast_sample_pos_4x[RAST_MSAA_SAMPLES][2];

struct rast_framebuffer {
   unsigned width, height;
   unsigned samples;              /* 0 or 1: one sample a pixel; else RAST_MSAA_SAMPLES */
   unsigned nr_cbufs;
   struct rast_color_target cbuf[RAST_MAX_CBUFS];   /* base NULL: unbound */
   struct rast_zs_target zs;
};

/* ------------------------------------------------------------------ */
/* Rasterizer state and the vertex layout.                              */

enum rast_cull { RAST_CULL_NONE = 0, RAST_CULL_FRONT = 1, RAST_CULL_BACK = 2,
                 RAST_CULL_BOTH = 3 };

struct rast_raster_state {
   bool front_ccw;               /* CCW in GL's sense (y up); see setup.c */
   enum rast_cull cull;
   bool scissor;
   bool half_pixel_center;       /* GL: true */
   bool bottom_edge_rule;        /* gallium: pixel centres on bottom edges are in */
   bool flatshade;               /* COLOR inputs are constant */
   bool flatshade_first;         /* provoking vertex is the first, else the last */
   float line_width;             /* rast_line: non-smooth lines of any width (llvmpipe's rule) */
   /* Points (rast_point), as llvmpipe draws them. */
   float point_size;             /* unless point_size_per_vertex and the vertex has a size */
   bool point_size_per_vertex;   /* the vertex layout's psize slot gives the size */
   bool point_quad_rasterization;   /* squares of any size on the 1/256 grid (GL ES, point
                                       sprites); else GL 2.1's whole-pixel point rule */
   bool sprite_coord_lower_left; /* the sprite coordinate t grows up the window (gallium's
                                    PIPE_SPRITE_COORD_LOWER_LEFT), else down */
   bool point_tri_clip;          /* points reach rast_point unclipped, whatever their centre
                                    (GL ES: a wide point by the viewport's edge keeps its
                                    pixels inside); each is scissored to the viewport
                                    (rast_set_viewport), as llvmpipe does */
   /* GL's depth clamp (ARB_depth_clamp, EXT_depth_clamp): draw no longer
    * clips z, and the back end clamps each fragment's depth, the Z
    * register's or the shader's, to the depth range of the primitive's
    * viewport (rast_set_depth_ranges) instead of [0, 1]. */
   bool depth_clamp;
   /* GL_MULTISAMPLE disabled (gallium's multisample false) on a
    * multisampled target: every sample takes the pixel centre's coverage,
    * depth and colour, as a single-sampled target's pixel would, and the
    * shader runs once a pixel with sample 0 (its per_sample and
    * writes_sample_mask do not apply: GL shades per sample and applies
    * gl_SampleMask only with multisampling on).  A framebuffer-fetch
    * shader still runs for each sample's colour, at the centre. */
   bool single_sample;
};

struct rast_scissor { int minx, miny, maxx, maxy; };   /* max exclusive */

enum rast_interp {
   RAST_INTERP_CONSTANT,        /* flat: the provoking vertex's value */
   RAST_INTERP_LINEAR,          /* noperspective: screen-linear, float incremental */
   RAST_INTERP_PERSPECTIVE,     /* A/w and 1/w incremental, divided per pixel */
   RAST_INTERP_COLOR            /* COLOR semantic: 9.12 Gouraud walk (or perspective,
                                   per profile), constant when flatshade */
};

struct rast_varying {
   uint8_t slot;                 /* float[4] slot of the vertex it comes from */
   uint8_t interp;               /* enum rast_interp */
   uint8_t usage_mask;           /* components the shader reads */
   /* PERSPECTIVE components that are only ever a REPEAT or
    * MIRRORED_REPEAT texture coordinate, read as they are: the set-up
    * subtracts an integer common to the primitive (an even one for those
    * in rebase_even) from their vertex values before the division by w,
    * which leaves every wrapped coordinate where it was and keeps the
    * registers' grid that of the primitive's extent, not of its distance
    * from 0 (docs/texture-unit.md, "Coordinate rebase"). */
   uint8_t rebase_mask, rebase_even;
   /* PERSPECTIVE components divided in binary32 whatever the texture
    * path's number system, as a non-float system divides COLOR ones: those
    * the shader reads as an array layer.  The layer is no address the unit
    * computes in its system but GL's integer choice clamp(RNE(r)) from the
    * shader's binary32 value, and a system's grid at a half-integer (dfx24:
    * 2^-15 at 1.5) or its adder's alignment rounds a layer crossing one to
    * the same side over the whole primitive (docs/texture-unit.md,
    * "Array layer"). */
   uint8_t float_mask;
};

struct rast_vertex_layout {
   unsigned vertex_size;         /* in float[4] slots */
   unsigned pos_slot;            /* window x, y, z in [0,1], and 1/w */
   unsigned num_varyings;        /* shader inputs, in shader input order */
   struct rast_varying varying[RAST_MAX_VARYINGS];
   bool has_psize;               /* the vertex carries a point size ... */
   unsigned psize_slot;          /* ... in this slot's x */
   /* Lines and points of a polygon drawn unfilled (desktop glPolygonMode)
    * carry the polygon's face: x is 1 for front, 0 for back (draw's
    * unfilled stage).  Without it they are front-facing. */
   bool has_face;
   unsigned face_slot;
   /* gl_Layer (a geometry shader's output): the layer of a layered target
    * the primitive draws into, its provoking vertex's, a 32-bit integer in
    * the slot's x; one past the targets' last layer draws into the last, as
    * llvmpipe does.  Without it, layer 0. */
   bool has_layer;
   unsigned layer_slot;
   /* gl_ViewportIndex (a geometry shader's output): the scissor and the
    * viewport the primitive is drawn with, its provoking vertex's, a 32-bit
    * integer in the slot's x; past the last, the last, as llvmpipe does.
    * Without it, index 0. */
   bool has_viewport_index;
   unsigned viewport_slot;
   /* Bit i: on points, varying i (unless CONSTANT) is the sprite coordinate
    * (s, t, 0, 1) generated across the square, not the vertex's value
    * (gl_PointCoord, GL_COORD_REPLACE).  Other primitives ignore it. */
   uint32_t point_coord_mask;
};

/* ------------------------------------------------------------------ */
/* The quad: what the scan converter hands the fragment shader.          */

struct rast_quad {
   int x, y;                         /* pixel 0; both even */
   unsigned mask;                    /* coverage, bit i = pixel i */
   bool front_facing;
   /* The sample whose walk made the quad on a multisampled target shaded
    * once a sample (rast_shader.per_sample, fetch_mask): gl_SampleID.  0
    * otherwise. */
   uint8_t sample;
   float frag_z[RAST_QUAD_SIZE];     /* Z register as window depth in [0,1] */
   float frag_w[RAST_QUAD_SIZE];     /* 1/w_clip, gl_FragCoord.w */
   int64_t z[RAST_QUAD_SIZE];        /* Z register, raw profile format */
   /* [varying][component][pixel]: the layout of tgsi_exec's input vectors */
   float in[RAST_MAX_VARYINGS][4][RAST_QUAD_SIZE];
   /* Framebuffer fetch: the colour buffers the shader reads (its
    * fetch_mask), as they are before this quad, in the layout of `in`;
    * the sample being drawn on a multisampled target. */
   float last[RAST_MAX_CBUFS][4][RAST_QUAD_SIZE];
};

struct rast_shaded_quad {
   float color[RAST_MAX_CBUFS][4][RAST_QUAD_SIZE];   /* [cbuf][chan][pixel] */
   float depth[RAST_QUAD_SIZE];      /* when the shader writes depth: [0,1] */
   /* gl_SampleMask, when the shader writes it (rast_shader.writes_sample_mask) */
   uint32_t sample_mask[RAST_QUAD_SIZE];
};

/* The fragment shader, bound once per state change.  shade() returns the
 * pixels that survive (discard clears bits); it must not write to `quad`. */
struct rast_shader {
   void *ctx;
   /* With threads (rast_set_threads): thread t >= 1 shades with
    * thread_ctx[t], its own copy of what shade() writes; NULL means ctx,
    * for a shade() that writes nothing but `out`. */
   void *thread_ctx[RAST_MAX_THREADS];
   unsigned (*shade)(void *ctx, const struct rast_quad *quad,
                     struct rast_shaded_quad *out);
   /* Up to `group` quads of one primitive in one call, where the shader
    * has a form eight or sixteen lanes wide (NULL: one quad at a time):
    * quad i from q[i], its outputs to out[i]; returns the pixels kept,
    * quad i's in bits 4i to 4i + 3.  n is 2 to `group`. */
   unsigned (*shade_n)(void *ctx, const struct rast_quad *const q[], struct rast_shaded_quad *const out[],
                       unsigned n);
   unsigned group;                   /* 2 or 4 with shade_n */
   unsigned num_outputs;             /* colour outputs written */
   bool writes_depth;
   bool color0_to_all;               /* gl_FragColor broadcast to every cbuf */
   bool may_discard;
   /* It writes memory (storage buffers, images, atomic counters): every
    * fragment that reaches it must run, so the back end shades before the
    * depth and stencil tests and skips no quad for want of a visible
    * effect.  early_tests (GL's early_fragment_tests) puts the tests
    * before it all the same, as GL then requires. */
   bool side_effects, early_tests;
   /* It reads gl_FragCoord: the span processor fills the quads' frag_z
    * and frag_w only then (a skip, counted in skip_fragcoord). */
   bool reads_fragcoord;
   /* Colour buffers the shader reads (framebuffer fetch): the back end
    * fills the quad's `last` with them before shading, and a multisampled
    * target is shaded once a sample (msaa.c). */
   unsigned fetch_mask;
   /* Shaded once a sample on a multisampled target, with the registers at
    * the sample's position and the sample in the quad (rast_quad.sample):
    * GL's sample shading, and a shader that reads gl_SampleID,
    * gl_SamplePosition or gl_SampleMaskIn.  Once a pixel otherwise. */
   bool per_sample;
   /* It writes gl_SampleMask (sample_mask of its outputs): a multisampled
    * target shades it once a sample, as per_sample, and keeps the sample
    * where the output has the sample's bit.  Single-sampled targets
    * ignore the output. */
   bool writes_sample_mask;
};

/* ------------------------------------------------------------------ */
/* Counters.                                                            */

struct rast_stats {
   struct fx_sat sat[RAST_REG_COUNT];
   uint64_t triangles, culled, lines, points;
   uint64_t nonfinite;               /* primitives dropped for a NaN or infinite position */
   /* triangles drawn by seed 000's type: 0 flat top or bottom, 1 the middle
    * vertex left of the long edge, 2 right of it; spans (a primitive's scan
    * lines with pixels) through the span processor */
   uint64_t tri_type[3], spans;
   /* texel reads of the texture unit's filters: 4 pixels a quad times the
    * taps of the minification filter (1, 2^dims; twice between mip levels) */
   uint64_t texels;
   uint64_t quads, pixels_covered, pixels_shaded;
   uint64_t samples_passed;          /* for occlusion queries */
   /* Range events of the texture path's number system (rast_set_texfmt):
    * saturation or overflow, and flush/underflow to zero. */
   uint64_t tex_sat, tex_flush;
   /* Work the model skipped (docs/datapath.md), 0 with RAST_OPT_NOSKIP:
    * quads whose 1/w is constant (one reciprocal per primitive), and
    * component-quads whose A/w is constant (no plane evaluated). */
   uint64_t skip_persp_w, skip_persp_comp;
   uint64_t skip_persp_terms;          /* plane terms with a zero difference left out, per quad */
   /* quads whose planes came from their primitive's tables per column and
    * scan line (interp_axes.c), not divided pixel by pixel */
   uint64_t skip_persp_axes;
   /* texture quads sampled without computing their LOD, which the sampler
    * cannot use (tex_unit_lod_unused) */
   uint64_t skip_tex_lod;
   /* texture quad-axes (a quad's s or t) addressed once per column or row
    * of a pair, where the coordinate follows the screen's axis (tex_lanes.c):
    * a share of twice tex_quads */
   uint64_t skip_tex_axes;
   /* gather quads whose footprint an earlier gather of the same
    * coordinates had addressed (the driver's memo): their texels read,
    * their addressing not done again; a share of tex_quads */
   uint64_t skip_tex_footprint;
   /* gather quads addressed and read by the unit's copy in compiled code
    * (src/gallium-like/fp_jit_gather.c), not its C functions: a share of
    * tex_quads */
   uint64_t tex_gather_jit;
   /* quads given to a shader that does not read gl_FragCoord, without its
    * z and w (the Z register as a float, the 1/w walk): a share of quads */
   uint64_t skip_fragcoord;
   /* quads without the Z walk, where nothing reads Z (no depth test, no
    * gl_FragCoord): neither the edges nor the spans walk it; its
    * saturations are then not counted (a share of quads) */
   uint64_t skip_z;
   /* the back end (backend.c): quads whose every covered pixel the early
    * depth/stencil test rejected, not shaded; quads that passed but were
    * not shaded because the shader has no visible effect (depth-only and
    * stencil-only passes, no colour written); shares of quads */
   uint64_t skip_early_quads, skip_shade_quads;
   /* PERSPECTIVE component-primitives whose vertex values were rebased by
    * a nonzero integer (rast_varying.rebase_mask) */
   uint64_t tex_rebased;
   /* what the skips are shares of: quads through the perspective division
    * and their PERSPECTIVE component-quads; texture quads whose LOD comes
    * from the coordinates' differences (implicit or biased); every texture
    * quad */
   uint64_t persp_quads, persp_comp_quads, tex_lod_quads, tex_quads;
   /* Tiles (tile.c): passes of primitives through the scan converter on a
    * target larger than X_out, and primitives clipped to the guard band
    * because no origin holds them in the XY registers. */
   uint64_t tile_passes, tile_guard;
   /* The interpolator of Z and colour (rast_set_interp): the operations
    * its registers took (docs/interp-modes.md says what each counts), the
    * additions and multiplications a scan-line walk made per-pixel
    * independent would take (seed 002's baseline; scanline mode only), and the pixels of the
    * primitives' bounding boxes (seed 001's coordinate manager).  With
    * RAST_INTERP_MEASURE, each covered pixel's registers against exact
    * arithmetic, per class (0 Z, 1 colour): how many, the sum of the
    * errors and the largest, in 2^-16 of the register's last bit. */
   uint64_t interp_add, interp_mul, interp_div, interp_indep_add, interp_indep_mul;
   uint64_t interp_box_pixels;
   uint64_t interp_err_n[2], interp_err_sum[2], interp_err_max[2];
};

/* ------------------------------------------------------------------ */
/* The rasterizer context.                                              */

struct rast_context;

struct rast_context *rast_create(const struct rast_profile *profile);
void rast_destroy(struct rast_context *rc);
const struct rast_profile *rast_get_profile(const struct rast_context *rc);

/* State: copied in; span and back-end functions are chosen again at the
 * next primitive after any of these. */
void rast_set_framebuffer(struct rast_context *rc, const struct rast_framebuffer *fb);
void rast_set_raster_state(struct rast_context *rc, const struct rast_raster_state *rs);
void rast_set_scissor(struct rast_context *rc, const struct rast_scissor *sc);
/* The viewport's pixels (llvmpipe's rounding of the viewport transform), for
 * point_tri_clip. */
void rast_set_viewport(struct rast_context *rc, const struct rast_scissor *vp);
/* Viewport arrays: scissors and viewports first to first + n - 1 of
 * RAST_MAX_VIEWPORTS, each primitive taking those of its viewport index
 * (rast_vertex_layout.has_viewport_index; else index 0, which
 * rast_set_scissor and rast_set_viewport set). */
#define RAST_MAX_VIEWPORTS 16
void rast_set_scissors(struct rast_context *rc, unsigned first, unsigned n,
                       const struct rast_scissor *sc);
void rast_set_viewports(struct rast_context *rc, unsigned first, unsigned n,
                        const struct rast_scissor *vp);
/* The depth ranges of viewports first to first + n - 1: glDepthRange's n
 * and f as window depths, for rs.depth_clamp, which clamps a fragment's
 * depth to [min(n, f), max(n, f)] of its primitive's viewport.  Each end is
 * taken into [0, 1] (NaN: 0), GL's range, then into the Z register as set-up
 * takes a vertex's depth.  [0, 1] until set. */
struct rast_depth_range { float n, f; };
void rast_set_depth_ranges(struct rast_context *rc, unsigned first, unsigned n,
                           const struct rast_depth_range *r);
void rast_set_depth_stencil(struct rast_context *rc, const struct rast_depth_stencil_state *dsa);
void rast_set_stencil_ref(struct rast_context *rc, uint8_t front, uint8_t back);
/* The samples drawn on a multisampled target (bit k: sample k; GL's sample
 * mask and sample coverage).  Single-sampled targets ignore it. */
void rast_set_sample_mask(struct rast_context *rc, unsigned mask);
void rast_set_blend(struct rast_context *rc, const struct rast_blend_state *blend);
void rast_set_blend_color(struct rast_context *rc, const float color[4]);
void rast_set_vertex_layout(struct rast_context *rc, const struct rast_vertex_layout *vl);
void rast_set_shader(struct rast_context *rc, const struct rast_shader *fs);

/* interpolateAt* (interp/interp_at.c): input `var` of quad q's pixels, its
 * four channels, at another point of each pixel, by the model's
 * interpolators in their formats.  OFFSET: arg0[i], arg1[i] are pixel i's
 * offset from its centre in pixels (rounded to the XY format's grid, within
 * the pixel); SAMPLE: arg0[i]'s bits are the sample index (the centre on a
 * single-sampled target); CENTROID: where the model shaded.  Called from
 * the shader while the model shades q, on the model context that shades
 * it. */
enum rast_interp_at_kind {
   RAST_INTERP_AT_CENTROID,
   RAST_INTERP_AT_SAMPLE,
   RAST_INTERP_AT_OFFSET,
};
void rast_interp_at(struct rast_context *rc, const struct rast_quad *q, unsigned var,
                    enum rast_interp_at_kind kind, const float arg0[RAST_QUAD_SIZE],
                    const float arg1[RAST_QUAD_SIZE], float out[4][RAST_QUAD_SIZE]);
/* The number system of the texture path (fixed/numsys.h: FIXPIPE_TEXFMT):
 * the perspective division of PERSPECTIVE varyings computes in it.  NULL
 * selects the default, dfx24. */
struct numsys;
void rast_set_texfmt(struct rast_context *rc, const struct numsys *ns);
/* The datapath (FIXPIPE_DEBUG=scalar,noskip,nof32,divideall): RAST_OPT_SCALAR
 * runs the scalar reference functions instead of the lanes (lanes.h),
 * RAST_OPT_NOSKIP computes what the skips leave out, RAST_OPT_NOF32 keeps
 * the division on binary64 lanes where the 512-bit set would take four
 * quads on binary32 lanes (fixed/dfx_lanes32.h), RAST_OPT_DIVIDE divides
 * every batch between the threads, however small (threads.c draws a batch
 * of fewer than 4096 pixels on the calling thread alone), so that a small
 * image proves the threads' identity too.  Every choice gives the same
 * bits. */
enum {
   RAST_OPT_SCALAR = 1u << 0, RAST_OPT_NOSKIP = 1u << 1, RAST_OPT_NOF32 = 1u << 2,
   RAST_OPT_DIVIDE = 1u << 3,
};
void rast_set_options(struct rast_context *rc, unsigned opts);
/* How Z and the colour registers get each pixel's value (FIXPIPE_INTERP,
 * docs/interp-modes.md): seed 000's incremental walk, seed 001's areas or
 * seed 002's edge vectors.  Coverage is the scan converter's in every mode.
 * RAST_INTERP_MEASURE also compares every covered pixel's registers with
 * exact arithmetic (rast_stats.interp_err_*). */
enum rast_interp_mode { RAST_INTERP_SCANLINE, RAST_INTERP_BARYCENTRIC, RAST_INTERP_VECTOR };
enum { RAST_INTERP_MEASURE = 1u << 4 };
void rast_set_interp(struct rast_context *rc, unsigned mode);
/* "scanline", "barycentric", "vector"; NULL for another value. */
const char *rast_interp_name(enum rast_interp_mode mode);

/* RTL test vectors of the scan-converter unit (docs/vectors.md): from now
 * on, every triangle the unit draws while frames_presented is in
 * [first, last] (rast_vectors_frame) is written to DIR/scan.in.hex, its
 * quads to DIR/scan.out.hex, the profile and counts to DIR/scan.txt.  One
 * thread: the records are in the unit's order.  false with a message if a
 * file cannot be written.  rast_destroy closes them. */
enum { RAST_VEC_SCAN = 1u << 0,      /* the scan converter and the division */
       RAST_VEC_TEX = 1u << 1 };      /* the texture unit */
bool rast_vectors_open(struct rast_context *rc, const char *dir, unsigned long first,
                       unsigned long last, unsigned units, char *err, size_t errlen);
void rast_vectors_frame(struct rast_context *rc, unsigned long frames_presented);
/* A new draw: the textures it samples are written again at their first use
 * (their texels may have changed: uploads, render to texture). */
void rast_vectors_draw(struct rast_context *rc);
bool rast_vectors_on(const struct rast_context *rc);
/* The texture unit's inputs and outputs of n quads (1 or 2) sampled with u
 * (tex.h) while vectors are on: DIR/tex.bind.hex, tex.in.hex, tex.out.hex. */
struct tex_unit;
struct tex_quad;
void rast_vectors_tex(struct rast_context *rc, const struct tex_unit *u,
                      const struct tex_quad *q, unsigned n, unsigned lod_control,
                      const float (*rgba)[4][4]);
void rast_vectors_close(struct rast_context *rc);
/* Their replay is verification, outside the model: src/verify. */

/* Primitives: each vertex is vertex_size float[4] slots. */
void rast_triangle(struct rast_context *rc, const float (*v0)[4],
                   const float (*v1)[4], const float (*v2)[4]);
/* A line of rs.line_width by GL's diamond-exit rule, as llvmpipe draws it
 * (smooth lines reach the model as triangles from draw's aaline stage). */
void rast_line(struct rast_context *rc, const float (*v0)[4], const float (*v1)[4]);
/* A point: the square (or, without point_quad_rasterization, GL 2.1's
 * whole-pixel point) of the vertex's or the state's size, as llvmpipe
 * builds it, every input constant except the point_coord_mask varyings.  Sizes
 * above RAST_MAX_POINT_SIZE draw at that size, below 1 (and NaN) at 1.
 * Primitives with a non-finite position (NaN, inf in x, y, z, 1/w) are dropped
 * and counted in rast_stats.nonfinite. */
#define RAST_MAX_POINT_SIZE 255.0f
void rast_point(struct rast_context *rc, const float (*v0)[4]);

/* ------------------------------------------------------------------ */
/* Threads (threads.c).  With n > 1 the primitives are queued and        */
/* rast_flush draws them on n threads, the caller's and n - 1 workers:   */
/* each thread draws one stretch of the target's rows per batch, cut at  */
/* multiples of RAST_BAND_ROWS scan lines where the batch's work divides */
/* evenly, every thread walking each primitive's edges from its top as   */
/* one thread does.  Per pixel, primitives land in submission order and  */
/* every register holds what one thread would compute: the frames are    */
/* byte-identical for every n, and so are the counters.                  */

#define RAST_BAND_ROWS 8
/* false with n out of [1, RAST_MAX_THREADS] or when a thread cannot start
 * (the context keeps drawing on one). */
bool rast_set_threads(struct rast_context *rc, unsigned n);
unsigned rast_get_threads(const struct rast_context *rc);
/* Thread t's context (t = 0: rc itself), for the shader's texture glue to
 * count its events into (tex_stats_to_rast) while it runs on that thread. */
struct rast_context *rast_thread_context(struct rast_context *rc, unsigned t);
/* Draws every queued primitive and returns when they are all in the
 * framebuffer.  Vertex memory given to rast_triangle/line/point must stay
 * valid until then; state setters flush first. */
void rast_flush(struct rast_context *rc);
/* Work outside the model that divides by rows (the driver's clears): the
 * queue drawn first, then job(arg, t, n) called once for each t in 0..n-1,
 * each on its own thread, returning when all have.  n is 1 (the caller
 * alone) unless the workers are already running: a job does not start
 * them, so a short program stays on one thread.  Returns n. */
typedef void (*rast_job_fn)(void *arg, unsigned t, unsigned n);
unsigned rast_run_on_threads(struct rast_context *rc, rast_job_fn job, void *arg);
/* Primitives drawn on one thread and on all of them since creation (for
 * docs and the threads test). */
void rast_get_flush_counts(const struct rast_context *rc, uint64_t *serial, uint64_t *parallel);
/* Jobs run by rast_run_on_threads on the caller alone and on all threads
 * (with one thread, no pool: both 0). */
void rast_get_job_counts(const struct rast_context *rc, uint64_t *serial, uint64_t *parallel);
/* Where the calling thread's time went since the pool was made, in
 * seconds, by the monotonic clock (all 0 with one thread).  What is not in
 * the model's batches (between) is the driver's, Mesa's and the program's
 * own work, which no worker can share: with the small batches drawn alone
 * it bounds what more threads can gain (docs/threads.md). */
struct rast_thread_times {
   double shares;          /* its share of the batches drawn on all threads */
   double waiting;         /* then waiting for the workers to finish theirs */
   double alone;           /* small batches, drawn on the calling thread alone */
   double jobs;            /* its part of the jobs run on all threads (clears) */
   double between;         /* from the end of one of the above to the next */
   double worker_shares;   /* the workers' shares of the batches, summed */
};
void rast_get_thread_times(const struct rast_context *rc, struct rast_thread_times *t);

/* Up to date after rast_flush: every thread's counters summed. */
const struct rast_stats *rast_get_stats(const struct rast_context *rc);
void rast_reset_stats(struct rast_context *rc);

#endif
