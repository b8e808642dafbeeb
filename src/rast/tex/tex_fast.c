/*
 * The unit's quad for dfx24 and binary32, chosen at bind: the data path of
 * tex_sample.c, tex_lod.c, tex_addr.c and tex_filter.c in the same order of
 * operations, with the arithmetic inline (tex_fast.h), the wrap mode a
 * switch instead of a call, the common 8-bit RGBA layouts read in place and
 * level selection shared by pixels of equal LOD.  One instance per number
 * system and dimensionality.  Cube maps and explicit derivatives (rare,
 * and the longest paths) stay on the generic quad.
 */
#include "rast/tex/tex_fast_path.h"
#include "rast/host/lanes.h"

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

/* tex_gather.c's address stage of a 2-D or 2-D array view, the operations
 * inline: the same footprints and range events (test_tex_fast.c). */
TEX_FAST_INLINE void footprint(const struct tex_unit *u, const struct tex_quad *q,
                               struct tex_footprint *f, const enum tex_fk k)
{
   struct tex_fst x = { { 0, 0 }, { 0, 0 } };
   const bool array = u->view.target == TEX_TARGET_2D_ARRAY;
   /* tex_addr_mirrored is false but for the mirroring modes */
   const bool mirror0 = u->samp.wrap[0] >= TEX_WRAP_MIRROR_REPEAT;
   const bool mirror1 = u->samp.wrap[1] >= TEX_WRAP_MIRROR_REPEAT;
   for (unsigned p = 0; p < TEX_QUAD; p++) {
      const ns_val s = tex_fcoord(u, k, q->s[p], &x), t = tex_fcoord(u, k, q->t[p], &x);
      struct tex_addr A, B;
      addr(u, k, true, u->samp.wrap[0], &u->axis[0][0], s, &A, &x);
      addr(u, k, true, u->samp.wrap[1], &u->axis[0][1], t, &B, &x);
      const bool swap_x = mirror0 && tex_addr_mirrored(u, 0, s);
      const bool swap_y = mirror1 && tex_addr_mirrored(u, 1, t);
      f->x[0][p] = swap_x ? A.i1 : A.i0;
      f->x[1][p] = swap_x ? A.i0 : A.i1;
      f->y[0][p] = swap_y ? B.i1 : B.i0;
      f->y[1][p] = swap_y ? B.i0 : B.i1;
      f->layer[p] = array ? layer_of(u, q->layer[p]) : 0;
   }
   f->events.sat = x.d.sat + x.n.sat;
   f->events.flush = x.d.flush + x.n.flush;
}

static void footprint_dfx19(const struct tex_unit *u, const struct tex_quad *q,
                            struct tex_footprint *f)
{
   footprint(u, q, f, TEX_FK_DFX19);
}

static void footprint_float(const struct tex_unit *u, const struct tex_quad *q,
                            struct tex_footprint *f)
{
   footprint(u, q, f, TEX_FK_FLOAT);
}

/* The texel reads of a footprint (tex_gather.c's taps and GL's order),
 * whatever the number system: they read memory, not coordinates. */
static void read_taps(const struct tex_unit *u, const struct tex_footprint *f,
                      const float ref[TEX_QUAD], unsigned comp, float rgba[4][TEX_QUAD])
{
   const struct tex_level *lv = &u->view.level[0];
   /* a depth view's taps give the comparison in every colour channel */
   const unsigned sw = u->samp.compare ? 0 : u->view.swizzle[comp & 3];
   for (unsigned p = 0; p < TEX_QUAD; p++) {
      const int z = f->layer[p];
      /* GL's order: (i0, j1), (i1, j1), (i1, j0), (i0, j0) */
      const v4f t0 = tap(u, lv, f->x[0][p], f->y[1][p], z, ref[p]);
      const v4f t1 = tap(u, lv, f->x[1][p], f->y[1][p], z, ref[p]);
      const v4f t2 = tap(u, lv, f->x[1][p], f->y[0][p], z, ref[p]);
      const v4f t3 = tap(u, lv, f->x[0][p], f->y[0][p], z, ref[p]);
      if (sw < 4) {
         rgba[0][p] = t0[sw];
         rgba[1][p] = t1[sw];
         rgba[2][p] = t2[sw];
         rgba[3][p] = t3[sw];
      } else {
         const float c = sw == TEX_SWZ_1 ? tex_one(&u->view) : 0.0f;
         rgba[0][p] = rgba[1][p] = rgba[2][p] = rgba[3][p] = c;
      }
   }
}

/* The 4-byte layouts' sixteen texel words of a footprint, a tap of the
 * four pixels a vector, with no branch: a border tap (`in` 0) reads the
 * level's first texel instead. */
typedef int32_t v4i __attribute__((vector_size(16)));
typedef uint32_t v4u __attribute__((vector_size(16)));

static void read_words(const struct tex_unit *u, const struct tex_footprint *f, v4u w[4],
                       v4i in[4])
{
   const struct tex_level *lv = &u->view.level[0];
   v4i z;
   memcpy(&z, f->layer, sizeof(z));
   /* GL's order: (i0, j1), (i1, j1), (i1, j0), (i0, j0) */
   static const uint8_t xi[4] = { 0, 1, 1, 0 }, yi[4] = { 1, 1, 0, 0 };
   for (unsigned k = 0; k < 4; k++) {
      v4i x, y;
      memcpy(&x, f->x[xi[k]], sizeof(x));
      memcpy(&y, f->y[yi[k]], sizeof(y));
      in[k] = (x | y | z) >= 0;
      x &= in[k];
      y &= in[k];
      const v4i zz = z & in[k];
      for (unsigned p = 0; p < TEX_QUAD; p++) {
         uint32_t t;
         memcpy(&t, lv->data + (size_t)zz[p] * lv->img_stride + (size_t)y[p] * lv->row_stride +
                       (size_t)x[p] * 4, 4);
         w[k][p] = t;
      }
   }
}

/* A colour channel of those words, decoded as fetch decodes it
 * (tex_unorm8: the integer to binary32, times 1/255), the border colour's
 * where the tap is outside. */
static unsigned byte_shift(enum tex_format fmt, unsigned ch)
{
   const bool bgr = fmt == TEX_FMT_BGRA8 || fmt == TEX_FMT_BGRX8;
   return ch == 3 ? 24 : ch == 1 ? 8 : (ch == 0) != bgr ? 0 : 16;
}

static void decode_byte(const struct tex_unit *u, const v4u w[4], const v4i in[4], unsigned ch,
                        float rgba[4][TEX_QUAD])
{
   const unsigned shift = byte_shift(u->view.format, ch);
   const float bc = u->samp.border[ch];
   const v4f border = { bc, bc, bc, bc };
   for (unsigned k = 0; k < 4; k++) {
      const v4i b = (v4i)((w[k] >> shift) & 0xff);
      const v4f v = __builtin_convertvector(b, v4f) * (1.0f / 255.0f);
      const v4i o = ((v4i)v & in[k]) | ((v4i)border & ~in[k]);
      memcpy(rgba[k], &o, sizeof(o));
   }
}

/* The swizzled channel `comp` comes from a byte of the 4-byte layouts (no
 * comparison; not the 1 of an X layout's fourth): its byte, or none. */
static bool byte_channel(const struct tex_unit *u, unsigned comp, unsigned *ch)
{
   const enum tex_format fmt = u->view.format;
   const unsigned sw = u->view.swizzle[comp & 3];
   const bool x8 = fmt == TEX_FMT_RGBX8 || fmt == TEX_FMT_BGRX8;
   *ch = sw;
   return fmt >= TEX_FMT_RGBA8 && fmt <= TEX_FMT_BGRX8 && !u->samp.compare &&
          sw < (x8 ? 3u : 4u);
}

void tex_unit_gather_count(const struct tex_unit *u, const struct tex_footprint *f)
{
   u->stats->sat += f->events.sat;
   u->stats->flush += f->events.flush;
}

void tex_unit_gather_read(const struct tex_unit *u, const struct tex_footprint *f,
                          const float ref[TEX_QUAD], unsigned comp, float rgba[4][TEX_QUAD])
{
   unsigned ch;
   if (byte_channel(u, comp, &ch)) {
      v4u w[4];
      v4i in[4];
      read_words(u, f, w, in);
      decode_byte(u, w, in, ch, rgba);
   } else {
      read_taps(u, f, ref, comp, rgba);
   }
   tex_unit_gather_count(u, f);
}

bool tex_unit_gather_reads_words(const struct tex_unit *u)
{
   const enum tex_format fmt = u->view.format;
   return fmt >= TEX_FMT_RGBA8 && fmt <= TEX_FMT_BGRX8 && !u->samp.compare;
}

void tex_unit_gather_read_all(const struct tex_unit *u, const struct tex_footprint *f,
                              const float ref[TEX_QUAD], float rgba[4][4][TEX_QUAD])
{
   v4u w[4];
   v4i in[4];
   bool loaded = false;
   for (unsigned c = 0; c < 4; c++) {
      unsigned ch;
      if (byte_channel(u, c, &ch)) {
         if (!loaded)
            read_words(u, f, w, in);
         loaded = true;
         decode_byte(u, w, in, ch, rgba[c]);
      } else {
         read_taps(u, f, ref, c, rgba[c]);
      }
   }
}

static void dfx_words(ns_val v, int32_t w[3])
{
   w[0] = v.d.s;
   w[1] = v.d.l;
   w[2] = (int32_t)v.d.m;
}

/* tex_ns_cmp's order for normalized values: location, then mantissa. */
static int32_t dfx_key(ns_val v)
{
   const int32_t mag = (int32_t)((uint32_t)v.d.l << DFX_MANT_BITS_SEED | v.d.m);
   return !v.d.m ? 0 : v.d.s ? -mag : mag;
}

bool tex_unit_gather_regs(const struct tex_unit *u, struct tex_gather_regs *r)
{
   const struct tex_level *lv = &u->view.level[0];
   const enum tex_format fmt = u->view.format;
   if (u->footprint != footprint_dfx19 || !tex_unit_gather_reads_words(u) ||
       (u->view.target != TEX_TARGET_2D && u->view.target != TEX_TARGET_RECT) ||
       u->samp.wrap[0] != TEX_WRAP_CLAMP_TO_EDGE || u->samp.wrap[1] != TEX_WRAP_CLAMP_TO_EDGE ||
       lv->w < 2 || lv->h < 1 || lv->w > (1 << 20) || lv->h > (1 << 20) ||
       (uint64_t)lv->h * lv->row_stride > INT32_MAX)
      return false;
   memset(r, 0, sizeof(*r));
   r->data = lv->data;
   r->row_stride = (int32_t)lv->row_stride;
   const int32_t size[2] = { lv->w, lv->h };
   for (unsigned a = 0; a < 2; a++) {
      r->size[a] = u->axis[0][a].size;
      /* fp_gather_offsets: offsets move normalized coordinates by texels */
      r->offset_unit[a] = u->samp.normalized ? (float)size[a] : 1.0f;
      dfx_words(u->axis[0][a].scale, r->scale[a]);
      dfx_words(u->axis[0][a].lo, r->lo[a]);
      dfx_words(u->axis[0][a].hi, r->hi[a]);
      r->lo_key[a] = dfx_key(u->axis[0][a].lo);
      r->hi_key[a] = dfx_key(u->axis[0][a].hi);
   }
   dfx_words(u->k_texel_offset, r->neg_half);
   r->neg_half[0] ^= 1;
   const bool x8 = fmt == TEX_FMT_RGBX8 || fmt == TEX_FMT_BGRX8;
   for (unsigned c = 0; c < 4; c++) {
      unsigned ch;
      if (byte_channel(u, c, &ch)) {
         /* decode_byte's byte */
         r->shift[c] = (int32_t)byte_shift(fmt, ch);
         continue;
      }
      /* read_taps: the swizzle's constant, or an X layout's fourth (fetch's 1) */
      const unsigned sw = u->view.swizzle[c];
      r->shift[c] = -1;
      if (sw == TEX_SWZ_0)
         r->constant[c] = 0.0f;
      else if (sw == TEX_SWZ_1)
         r->constant[c] = tex_one(&u->view);
      else if (x8 && sw == 3)
         r->constant[c] = 1.0f;
      else
         return false;
   }
   return true;
}

tex_footprint_fn tex_fast_footprint_choose(const struct tex_unit *u, bool scalar)
{
   if (scalar || (u->view.target != TEX_TARGET_2D && u->view.target != TEX_TARGET_2D_ARRAY &&
                  u->view.target != TEX_TARGET_RECT))
      return NULL;
   if (u->kind == TEX_NS_DFX && u->ns->dfx.mant_bits == DFX_MANT_BITS_SEED)
      return footprint_dfx19;
   if (u->kind == TEX_NS_FLOAT)
      return footprint_float;
   return NULL;
}

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
   /* cube maps and the min/max reductions take the table path */
   if (tex_is_cube(u->view.target) || u->dims < 1 || u->dims > 3 ||
       u->samp.reduction != TEX_REDUCE_AVERAGE)
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
