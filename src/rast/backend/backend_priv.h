/*
 * The fragment back end's own state (rc->back_priv): everything that
 * rast_backend_validate() decides once per state change, so that the quad
 * functions only follow pointers and never look at the gallium-level state
 * again.
 */
#ifndef FIXPIPE_BACKEND_PRIV_H
#define FIXPIPE_BACKEND_PRIV_H

#include <stddef.h>
#include <string.h>
#include "rast/rast_priv.h"
#include "rast/host/lanes.h"

/* A quad's depth in the depth buffer's own units: unorm for the integer
 * layouts, IEEE float for Z32F.  The same value serves the test and the
 * write, so early and late depth agree bit for bit. */
union rast_zq {
   uint32_t u[RAST_QUAD_SIZE];
   float f[RAST_QUAD_SIZE];
};

struct rast_backend;

/* Rasterizer Z (or shader depth) of a quad -> buffer units. */
typedef void (*rast_zconv_func)(const struct rast_backend *be,
                                const struct rast_quad *q,
                                const struct rast_shaded_quad *out,
                                union rast_zq *z);

/* Depth/stencil test and update of a quad; returns the pixels that pass. */
typedef unsigned (*rast_zs_func)(const struct rast_backend *be, int x, int y,
                                 unsigned mask, const union rast_zq *z,
                                 bool front_facing);

struct rast_cbuf_plan;

/* A logic op on n bytes: r = op(s, d), bit for bit. */
typedef void (*rast_lop_func)(const uint8_t *s, const uint8_t *d, uint8_t *r, unsigned n);

/* Largest pixel the logic op handles (RGBA32: float, which it leaves alone). */
#define RAST_LOP_MAX_CPP 16

/* Blend, colour mask and store of one colour buffer.  src and src1 are
 * [chan][pixel], the layout of rast_shaded_quad. */
typedef void (*rast_color_func)(const struct rast_cbuf_plan *p, int x, int y,
                                unsigned mask, const float (*src)[RAST_QUAD_SIZE],
                                const float (*src1)[RAST_QUAD_SIZE]);

struct rast_cbuf_plan {
   rast_color_func func;
   /* func for the quads of a group on one vector (lanes.h), or NULL */
   rast_c8_group_fn group;
   uint8_t *base;                 /* the layer and sample drawn (rast_backend_place) */
   uint8_t *base0;                /* layer 0, sample 0 */
   size_t sample_stride;
   unsigned layers;               /* rast_color_target's */
   size_t layer_stride;
   int stride;
   unsigned cpp;
   rast_load_func load;
   rast_store_func store;
   bool clamp;
   float clamp_lo;                /* clamp's lower bound: 0, or -1 for snorm targets */
   uint8_t colormask;
   bool clamp_dst;                /* generic target that clamps: dst and result can
                                     leave [0, 1] */
   bool uses_src1;                /* a SRC1 factor: clamp the second output too */
   struct rast_blend_target bt;
   /* ADD with factors k0 + k1 * As (ZERO, ONE, SRC_ALPHA, INV_SRC_ALPHA):
    * rgb src, rgb dst, alpha src, alpha dst, as {k0, k1}. */
   float affine[4][2];
   bool quad4;                    /* quads on four lanes (not RAST_OPT_SCALAR) */
   int fb_w, fb_h;                /* the framebuffer: a quad inside has four pixels */
   float konst[4];                /* blend colour, clamped if the target clamps */
   unsigned src;                  /* index into rast_shaded_quad.color */
   enum rast_color_layout fast8;  /* no blend, full mask, 8-bit: the quad's fast store;
                                     RAST_CL_GENERIC otherwise */
   /* Logic op: the stored pixel becomes ((op(s, d) | lop_set) & lop_wmask) |
    * (d & ~lop_wmask), byte k of a pixel with mask byte k.  lop_wmask holds
    * the bits of the channels the colour mask writes; lop_set the X byte of
    * BGRX8, which every store fills with 255. */
   rast_lop_func lop;
   uint8_t lop_wmask[RAST_LOP_MAX_CPP];
   uint8_t lop_set[RAST_LOP_MAX_CPP];
};

/* Where the depth and stencil of the bound zs buffer live. */
enum rast_zfamily {
   RAST_ZF_NONE,
   RAST_ZF_U16,        /* Z16 */
   RAST_ZF_U24LO,      /* Z24_S8, Z24X8: z in bits 0..23 */
   RAST_ZF_U24HI,      /* S8_Z24, X8Z24: z in bits 8..31 */
   RAST_ZF_U32,        /* Z32 */
   RAST_ZF_F32,        /* Z32F */
   RAST_ZF_F32S8,      /* Z32F_S8X24: 8-byte pixel, float first */
   RAST_ZF_COUNT
};

/* floor(n / (2^s · B)) for n up to the rule's numerator, B odd:
 * (⌊n / 2^s⌋ · m) >> k with m = ⌈2^k / B⌉ (backend_zs.c). */
struct rast_zdiv {
   uint64_t m;
   unsigned s, k;
};

/* The bounds a fragment's depth is clamped to: the Z registers lo and hi
 * (Zc = clamp(Z, lo, hi)), and the same bounds in the buffer's units,
 * which clamp a depth the shader wrote (backend_zs.c).  Without the depth
 * clamp, 0 and FULL: [0, 1]. */
struct rast_zrange {
   uint64_t lo, hi;
   union { uint32_t u; float f; } code_lo, code_hi;
};

struct rast_backend {
   /* Depth/stencil. */
   rast_zconv_func zconv;
   rast_zs_func zs;               /* NULL: no depth or stencil work */
   uint8_t *zs_base;              /* the layer and sample drawn, as cbuf's base */
   uint8_t *zs_base0;
   size_t zs_sample_stride;
   unsigned zs_layers;
   size_t zs_layer_stride;
   int zs_stride;
   enum rast_zs_layout zs_layout;
   enum rast_zfamily zfamily;
   bool depth_test, depth_write;
   enum rast_func depth_func;
   bool stencil_test;
   bool two_sided;
   struct rast_stencil_face stencil[2];
   uint8_t stencil_ref[2];

   /* Rasterizer Z -> unorm: see backend_zs.c for the exact rule. */
   uint64_t z_full;               /* (2^z_bits - 1) << frac_bits */
   uint64_t z_max;                /* 2^N - 1 of the buffer */
   unsigned z_frac;               /* frac_bits of the profile */
   unsigned z_nbits;              /* N */
   struct rast_zdiv zdiv;         /* the rule's division as a multiply */
   /* The depth range of each viewport (rs.depth_clamp), and that of the
    * viewport being drawn (rast_backend_viewport): what every conversion
    * of a Z register or shader depth clamps to. */
   struct rast_zrange zranges[RAST_MAX_VIEWPORTS];
   struct rast_zrange zr;
   /* A group's early depth test on lanes (lanes.h), or NULL; zgroup_b is
    * the rule's divisor (2 z_full >> zdiv.s) as a double, and the target's
    * size says which quads have all four pixels in it. */
   rast_zgroup_fn zgroup;
   double zgroup_b;
   int fb_w, fb_h;

   /* Colour. */
   bool shade_needed;             /* false: no visible effect of the shader */
   /* 1 where the early tests' quads left unshaded are skips (counted):
    * single-sampled targets; on a multisampled one the order is the
    * model's (msaa.c), not a skip */
   unsigned skips_counted;
   unsigned ncbufs;
   struct rast_cbuf_plan cbuf[RAST_MAX_CBUFS];
   unsigned sample;               /* the sample plane drawn (rast_backend_sample) */
   unsigned layer;                /* the layer drawn (rast_backend_layer) */

   /* Scratch for the shader's output: not on the stack of every quad. */
   struct rast_shaded_quad out[RAST_GROUP_MAX];   /* [i]: the i-th quad of a group */
};

/* backend_zs.c */
void rast_zs_plan(struct rast_backend *be, const struct rast_context *rc);
uint32_t rast_z_to_unorm(uint64_t z, uint64_t full, uint64_t max);
/* The same, the division by 2·full as a multiply by its reciprocal, exact
 * where rast_zdiv_init says so. */
bool rast_zdiv_init(struct rast_zdiv *d, uint64_t full, uint64_t max);
uint32_t rast_zdiv_to_unorm(const struct rast_zdiv *d, uint64_t z, uint64_t full, uint64_t max);
uint32_t rast_float_to_unorm(float d, unsigned nbits);

/* backend_color.c */
void rast_color_plan(struct rast_backend *be, const struct rast_context *rc);
uint8_t rast_float_to_ubyte(float f);

/* backend_logicop.c: sets p->func and the lop fields for `op` on a target of
 * `layout` (p's cpp, store and colormask already set); false when the pixel
 * is too large, and p is left alone. */
bool rast_logicop_plan(struct rast_cbuf_plan *p, enum rast_color_layout layout,
                       enum rast_logicop op);

/* Whether a quad's four pixels are all in a w x h target: a quad whose
 * four are covered has them there (coverage is clipped to the target), and
 * a partly covered one must not be at the last column or row.  The lanes
 * read and write a quad's two rows of two pixels whole. */
static inline bool rast_quad_whole(int x, int y, unsigned mask, int w, int h)
{
   return mask == 0xf || (x + 1 < w && y + 1 < h);
}

static inline unsigned rast_popcount4(unsigned mask)
{
   return (mask & 1) + ((mask >> 1) & 1) + ((mask >> 2) & 1) + ((mask >> 3) & 1);
}

/* The pixels kept of a group (16 bits): the baseline instruction set has
 * no popcnt, and __builtin_popcount is then a call into libgcc. */
static inline unsigned rast_popcount16(unsigned mask)
{
   mask -= (mask >> 1) & 0x5555u;
   mask = (mask & 0x3333u) + ((mask >> 2) & 0x3333u);
   mask = (mask + (mask >> 4)) & 0x0f0fu;
   return (mask + (mask >> 8)) & 0x1fu;
}

/* Pixel i of the quad at (x, y). */
static inline int rast_qx(int x, unsigned i) { return x + (int)(i & 1); }
static inline int rast_qy(int y, unsigned i) { return y + (int)(i >> 1); }

/* Mesa's float_to_ubyte (util/u_math.h), bit for bit: NaN and <= 0 give 0,
 * >= 1 gives 255, else round(f * 255) to nearest even, done by the float
 * adder: f * 255/256 + 2^15 leaves round(f * 255) in the low mantissa bits. */
static inline float rast_clamp01(float v)
{
   v = v > 0.0f ? v : 0.0f;          /* NaN -> 0; compiles to maxss/minss */
   return v < 1.0f ? v : 1.0f;
}

/* A clamping target's clamp: [lo, 1], lo 0 (unorm) or -1 (snorm), a
 * constant of the plan; NaN gives 0, as util's packing of either. */
static inline float rast_clamp_lo(float v, float lo)
{
   v = v == v ? v : 0.0f;
   v = v > lo ? v : lo;
   return v < 1.0f ? v : 1.0f;
}

/* Clamping first gives Mesa's results without its branches: 0 and 1 go
 * through the adder exactly (32768 and 32768 + 255/256). */
static inline uint8_t rast_f2ub(float f)
{
   union { float f; uint32_t u; } t;
   t.f = rast_clamp01(f) * (255.0f / 256.0f) + 32768.0f;
   return (uint8_t)t.u;
}

/* Mesa's ubyte_to_float. */
static inline float rast_ub2f(uint8_t v)
{
   return (float)v * (1.0f / 255.0f);
}

/* No blend, all four channels: the fast store of the 8-bit layouts.  r, g,
 * b, a are byte offsets; x8 writes 255 into the unused byte. */
static inline void rast_store8_quad(uint8_t *base, int stride, int x, int y, unsigned mask,
                                    const float (*src)[RAST_QUAD_SIZE],
                                    unsigned r, unsigned g, unsigned b, unsigned a, bool x8)
{
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      if (!(mask & (1u << i)))
         continue;
      uint8_t px[4];
      px[r] = rast_f2ub(src[0][i]);
      px[g] = rast_f2ub(src[1][i]);
      px[b] = rast_f2ub(src[2][i]);
      px[a] = x8 ? 255 : rast_f2ub(src[3][i]);
      memcpy(base + (ptrdiff_t)rast_qy(y, i) * stride + (ptrdiff_t)rast_qx(x, i) * 4, px, 4);
   }
}

#endif
