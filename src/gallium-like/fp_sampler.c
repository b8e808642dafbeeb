/*
 * Glue between tgsi_exec's sampler interface and the modeled texture unit
 * (src/rast/tex*.c): gallium's sampler view and sampler state become the
 * unit's descriptors, bound once per (view, sampler) pair; every sample
 * request becomes a tex_quad.  Texels of the formats the unit does not
 * decode itself come back here through util_format (compressed, sRGB,
 * float, depth).
 *
 * Binding is checked on use: gallium may delete a state object and create
 * another at the same address, so the slot compares what its descriptors
 * were built from (a few dozen bytes) before each quad instead of trusting
 * pointers.
 */
#include <string.h>

#include "util/u_memory.h"
#include "util/u_math.h"
#include "util/format/u_format.h"
#include "tgsi/tgsi_exec.h"

#include "fp_context.h"
#include "fp_jit.h"
#include "fp_resource.h"
#include "fp_screen.h"
#include "rast/tex/tex.h"

/* What a slot's unit was bound from. */
struct fp_tex_key {
   const struct pipe_sampler_view *view;
   enum pipe_format format;
   enum pipe_texture_target target;
   unsigned swizzle, first_layer, last_layer, first_level, last_level;
   unsigned buf_offset, buf_size;      /* a texture buffer's range */
   const struct pipe_resource *res;
   const uint8_t *data;
   unsigned width0, height0, depth0, array_size, res_last_level;
   struct pipe_sampler_state ss;
};

#define FP_FOOTPRINTS 4

struct fp_tex_slot {
   bool valid;
   /* the same view and sampler objects, bound in the same epoch, over the
    * same storage: the unit is right without comparing the key.  Within
    * one epoch no view or sampler is bound, and a view holds its resource,
    * whose storage is fixed for its life: a request in the slot's epoch
    * for the same sampler index is answered by the unit without looking
    * anything up (fp_unit_of), as a compiled shader's every texture call,
    * four quads a call, asks. */
   uint64_t epoch;
   unsigned sampler_index;
   const struct fp_sampler_view *view;
   const void *sampler, *data;
   struct fp_tex_key key;
   struct tex_unit unit;
   /* The last gathers' footprints and the coordinates they were addressed
    * from: a gather of the same coordinates (the other channels of one
    * footprint, as a shader gathering colour asks for red, green and blue
    * in turn) reads its texels without addressing them again.  As many as
    * the quads compiled code hands over an instruction at a time (it
    * gathers each channel for all of them in turn), replaced in turn.
    * Valid for the unit they were addressed by and within one run of the
    * shader (fp_tgsi_sampler_begin): which quads one thread shades after
    * which depends on the thread count, and the counters must not.
    * Never under FIXPIPE_DEBUG=noskip. */
   unsigned footprints, footprint_next;
   uint64_t footprint_run;
   float footprint_key[FP_FOOTPRINTS][3][TGSI_QUAD_SIZE];
   struct tex_footprint footprint[FP_FOOTPRINTS];
   /* and, for the 4-byte layouts, every channel of their texels */
   float footprint_texels[FP_FOOTPRINTS][4][4][TGSI_QUAD_SIZE];
};

struct fp_tgsi_sampler {
   struct tgsi_sampler base;
   struct fp_context *fp;
   struct rast_context *rast;     /* the thread's: fp_tex_stats counts there */
   enum pipe_shader_type stage;
   const struct numsys *ns;
   struct ns_stats stats;
   uint64_t skip_lod;             /* quads sampled without their LOD */
   uint64_t lod_quads;            /* quads with an implicit or biased LOD */
   uint64_t quads;                /* every quad sampled */
   uint64_t skip_axes;            /* quads addressed per axis (tex_unit.axes_shared) */
   uint64_t skip_footprint;       /* gather quads that read the slot's footprint */
   uint64_t run;                  /* runs of the fragment shader begun (fp_tgsi_sampler_begin) */
   uint64_t texels;               /* texel reads of the filters (tex_unit.taps) */
   /* the units' registers for compiled gathers (fp_jit_gather.c), filled
    * before the compiled code's first call in a binding epoch; and the
    * quads compiled code gathered from them */
   struct fp_jit_gather gather[PIPE_MAX_SAMPLERS];
   uint64_t gathered_jit;
   /* made at the unit's first binding: about 6 KB each, 32 a stage, and most
    * programs sample from a few units of one or two stages */
   struct fp_tex_slot *slot[PIPE_MAX_SAMPLERS];
   bool rebind;                   /* FIXPIPE_DEBUG=noskip: every request binds */
};

struct tgsi_sampler *fp_tgsi_sampler_base(struct fp_tgsi_sampler *s)
{
   return &s->base;
}

void fp_tgsi_sampler_begin(struct fp_tgsi_sampler *s)
{
   s->run++;
}

void fp_init_sampler_view(struct fp_sampler_view *v)
{
   enum pipe_format f = v->base.format;
   const struct util_format_description *d = util_format_description(f);
   v->zs = d && d->colorspace == UTIL_FORMAT_COLORSPACE_ZS;
   v->fetch = v->zs ? NULL : (void *)util_format_fetch_rgba_func(f);
   /* A stencil view (GL ES 3.1 stencil texturing: X24S8, S8X24, X32_S8X24,
    * S8) gives the stencil index as an unsigned integer. */
   v->stencil = v->zs && !util_format_has_depth(d) && util_format_has_stencil(d);
   if (v->zs && !util_format_has_depth(d))
      v->zs = false;
   v->is_unorm = util_format_is_unorm(f);
   v->integer = util_format_is_pure_integer(f) || v->stencil;
   v->is_snorm = util_format_is_snorm(f);
   v->bw = d ? d->block.width : 1;
   v->bh = d ? d->block.height : 1;
   v->bsize = d ? MAX2(d->block.bits / 8, 1) : 1;
}

/* ---- texel fetch for the formats the unit leaves to the driver ---- */

static inline const uint8_t *fp_texel_ptr(const struct fp_sampler_view *v,
                                          const struct tex_level *lv, int x, int y, int z)
{
   return lv->data + (size_t)z * lv->img_stride + (size_t)(y / (int)v->bh) * lv->row_stride +
          (size_t)(x / (int)v->bw) * v->bsize;
}

static void fp_fetch_util(const struct tex_view_desc *d, const struct tex_level *lv, int x, int y,
                          int z, float out[4])
{
   const struct fp_sampler_view *v = d->fetch_ctx;
   ((util_format_fetch_rgba_func_ptr)v->fetch)(out, fp_texel_ptr(v, lv, x, y, z),
                                               x % v->bw, y % v->bh);
}

static void fp_fetch_depth(const struct tex_view_desc *d, const struct tex_level *lv, int x,
                           int y, int z, float out[4])
{
   const struct fp_sampler_view *v = d->fetch_ctx;
   util_format_unpack_z_float(v->base.format, &out[0], fp_texel_ptr(v, lv, x, y, z), 1);
   out[1] = out[2] = out[0];
   out[3] = 1.0f;
}

static void fp_fetch_stencil(const struct tex_view_desc *d, const struct tex_level *lv, int x,
                             int y, int z, float out[4])
{
   const struct fp_sampler_view *v = d->fetch_ctx;
   uint8_t s;
   util_format_unpack_s_8uint(v->base.format, &s, fp_texel_ptr(v, lv, x, y, z), 1);
   union { uint32_t u; float f; } c[2] = { { s }, { 1 } };
   out[0] = c[0].f;
   out[1] = out[2] = 0.0f;
   out[3] = c[1].f;
}

static void fp_fetch_none(const struct tex_view_desc *d, const struct tex_level *lv, int x, int y,
                          int z, float out[4])
{
   (void)d; (void)lv; (void)x; (void)y; (void)z;
   out[0] = out[1] = out[2] = 0.0f;
   out[3] = 1.0f;
}

static enum tex_format fp_tex_format(enum pipe_format f)
{
   switch (f) {
   case PIPE_FORMAT_R8G8B8A8_UNORM: return TEX_FMT_RGBA8;
   case PIPE_FORMAT_R8G8B8X8_UNORM: return TEX_FMT_RGBX8;
   case PIPE_FORMAT_B8G8R8A8_UNORM: return TEX_FMT_BGRA8;
   case PIPE_FORMAT_B8G8R8X8_UNORM: return TEX_FMT_BGRX8;
   case PIPE_FORMAT_L8_UNORM: return TEX_FMT_L8;
   case PIPE_FORMAT_A8_UNORM: return TEX_FMT_A8;
   case PIPE_FORMAT_I8_UNORM: return TEX_FMT_I8;
   case PIPE_FORMAT_R8_UNORM: return TEX_FMT_R8;
   case PIPE_FORMAT_L8A8_UNORM: return TEX_FMT_LA8;
   case PIPE_FORMAT_B5G6R5_UNORM: return TEX_FMT_B5G6R5;
   case PIPE_FORMAT_A4B4G4R4_UNORM: return TEX_FMT_A4B4G4R4;
   case PIPE_FORMAT_B4G4R4A4_UNORM: return TEX_FMT_B4G4R4A4;
   case PIPE_FORMAT_A1B5G5R5_UNORM: return TEX_FMT_A1B5G5R5;
   case PIPE_FORMAT_B5G5R5A1_UNORM: return TEX_FMT_B5G5R5A1;
   default: return TEX_FMT_CALLBACK;
   }
}

static enum tex_target fp_tex_target(enum pipe_texture_target t)
{
   switch (t) {
   case PIPE_TEXTURE_1D: return TEX_TARGET_1D;
   case PIPE_TEXTURE_3D: return TEX_TARGET_3D;
   case PIPE_TEXTURE_CUBE: return TEX_TARGET_CUBE;
   case PIPE_TEXTURE_1D_ARRAY: return TEX_TARGET_1D_ARRAY;
   case PIPE_TEXTURE_2D_ARRAY: return TEX_TARGET_2D_ARRAY;
   case PIPE_TEXTURE_RECT: return TEX_TARGET_RECT;
   case PIPE_BUFFER: return TEX_TARGET_BUFFER;
   case PIPE_TEXTURE_CUBE_ARRAY: return TEX_TARGET_CUBE_ARRAY;
   default: return TEX_TARGET_2D;
   }
}

static void fp_view_swizzle(const struct fp_sampler_view *fv, struct tex_view_desc *d)
{
   const struct pipe_sampler_view *v = &fv->base;
   const unsigned swz[4] = { v->swizzle_r, v->swizzle_g, v->swizzle_b, v->swizzle_a };
   for (unsigned c = 0; c < 4; c++)
      d->swizzle[c] = swz[c] <= PIPE_SWIZZLE_1 ? (uint8_t)swz[c] : TEX_SWZ_0;
   d->integer = fv->integer;
}

/* The view's descriptor: levels relative to first_level, layers from
 * first_layer (3D slices are addressed by the unit). */
static void fp_view_desc(const struct fp_sampler_view *fv, struct tex_view_desc *d)
{
   const struct pipe_sampler_view *v = &fv->base;
   const struct fp_resource *r = fp_resource(v->texture);
   const struct pipe_resource *t = &r->base;
   memset(d, 0, sizeof(*d));
   d->target = fp_tex_target(v->target);
   d->format = fv->zs ? TEX_FMT_CALLBACK : fp_tex_format(v->format);
   d->fetch = fv->zs ? fp_fetch_depth : fv->stencil ? fp_fetch_stencil
              : fv->fetch ? fp_fetch_util : fp_fetch_none;
   d->fetch_ctx = fv;
   d->depth = fv->zs;
   fp_view_swizzle(fv, d);
   if (v->target == PIPE_BUFFER) {
      /* a texture buffer: the range of the buffer the view gives, one row
       * of whole texels (GL clips the range to the buffer's size) */
      const unsigned offset = MIN2(v->u.buf.offset, t->width0);
      const unsigned bytes = MIN2(v->u.buf.size, t->width0 - offset);
      d->num_levels = 1;
      d->layers = 1;
      d->level[0].data = r->data + offset;
      d->level[0].row_stride = bytes;
      d->level[0].w = (int32_t)(bytes / fv->bsize);
      d->level[0].h = d->level[0].d = 1;
      return;
   }
   const unsigned first = v->u.tex.first_level;
   const unsigned last = MAX2(MIN2(v->u.tex.last_level, t->last_level), first);
   d->num_levels = MIN2(last - first + 1, TEX_MAX_LEVELS);
   /* a multisampled layer is its samples' planes */
   const unsigned layer0 = t->target == PIPE_TEXTURE_3D
                              ? 0 : v->u.tex.first_layer * fp_resource_samples(t);
   for (unsigned l = 0; l < d->num_levels; l++) {
      const unsigned lev = first + l;
      struct tex_level *lv = &d->level[l];
      lv->data = r->data + r->level_offset[lev] + layer0 * r->img_stride[lev];
      lv->row_stride = r->stride[lev];
      lv->img_stride = (uint32_t)r->img_stride[lev];
      lv->w = u_minify(t->width0, lev);
      lv->h = (t->target == PIPE_TEXTURE_1D || t->target == PIPE_TEXTURE_1D_ARRAY)
                 ? 1 : u_minify(t->height0, lev);
      lv->d = t->target == PIPE_TEXTURE_3D ? u_minify(t->depth0, lev) : 1;
   }
   d->layers = d->target == TEX_TARGET_CUBE ? 6
               : (int32_t)(v->u.tex.last_layer - v->u.tex.first_layer + 1);
}

static void fp_sampler_desc(const struct fp_sampler_view *fv, const struct pipe_sampler_state *ss,
                            struct tex_sampler_desc *d)
{
   memset(d, 0, sizeof(*d));
   d->wrap[0] = (enum tex_wrap)ss->wrap_s;
   d->wrap[1] = (enum tex_wrap)ss->wrap_t;
   d->wrap[2] = (enum tex_wrap)ss->wrap_r;
   d->min_filter = ss->min_img_filter == PIPE_TEX_FILTER_LINEAR ? TEX_FILTER_LINEAR
                                                                : TEX_FILTER_NEAREST;
   d->mag_filter = ss->mag_img_filter == PIPE_TEX_FILTER_LINEAR ? TEX_FILTER_LINEAR
                                                                : TEX_FILTER_NEAREST;
   d->mip = ss->min_mip_filter == PIPE_TEX_MIPFILTER_LINEAR    ? TEX_MIP_LINEAR
            : ss->min_mip_filter == PIPE_TEX_MIPFILTER_NEAREST ? TEX_MIP_NEAREST
                                                               : TEX_MIP_NONE;
   d->normalized = !ss->unnormalized_coords;
   d->seamless_cube = ss->seamless_cube_map;
   d->reduction = ss->reduction_mode == PIPE_TEX_REDUCTION_MIN   ? TEX_REDUCE_MIN
                  : ss->reduction_mode == PIPE_TEX_REDUCTION_MAX ? TEX_REDUCE_MAX
                                                                  : TEX_REDUCE_AVERAGE;
   d->compare = ss->compare_mode != PIPE_TEX_COMPARE_NONE && fv->zs;
   d->func = (enum tex_func)ss->compare_func;
   d->lod_bias = ss->lod_bias;
   d->min_lod = ss->min_lod;
   d->max_lod = ss->max_lod;
   for (unsigned c = 0; c < 4; c++) {
      float b = ss->border_color.f[c];   /* an integer format's: its bits */
      if (fv->integer)
         ;
      else if (fv->is_unorm || fv->zs)
         b = CLAMP(b, 0.0f, 1.0f);
      else if (fv->is_snorm)
         b = CLAMP(b, -1.0f, 1.0f);
      d->border[c] = b;
   }
}

static void fp_tex_key(struct fp_tex_key *k, const struct fp_sampler_view *fv,
                       const struct pipe_sampler_state *ss)
{
   const struct pipe_sampler_view *v = &fv->base;
   const struct fp_resource *r = fp_resource(v->texture);
   memset(k, 0, sizeof(*k));
   k->view = v;
   k->format = v->format;
   k->target = v->target;
   k->swizzle = v->swizzle_r | v->swizzle_g << 3 | v->swizzle_b << 6 | v->swizzle_a << 9;
   if (v->target == PIPE_BUFFER) {
      k->buf_offset = v->u.buf.offset;
      k->buf_size = v->u.buf.size;
   } else {
      k->first_layer = v->u.tex.first_layer;
      k->last_layer = v->u.tex.last_layer;
      k->first_level = v->u.tex.first_level;
      k->last_level = v->u.tex.last_level;
   }
   k->res = &r->base;
   k->data = r->data;
   k->width0 = r->base.width0;
   k->height0 = r->base.height0;
   k->depth0 = r->base.depth0;
   k->array_size = r->base.array_size;
   k->res_last_level = r->base.last_level;
   memcpy(&k->ss, ss, sizeof(*ss));
}

/* The slot's unit for (view, sampler), bound again when either changed. */
static const struct tex_unit *fp_tex_bind(struct fp_tgsi_sampler *ts, unsigned index,
                                          unsigned sampler_index,
                                          const struct fp_sampler_view *fv,
                                          const struct pipe_sampler_state *ss)
{
   struct fp_tex_slot *slot = ts->slot[index];
   if (unlikely(!slot)) {
      slot = ts->slot[index] = CALLOC_STRUCT(fp_tex_slot);
      if (!slot) {
         static bool reported;
         if (!reported)
            fprintf(stderr, "fixpipe: out of memory binding texture unit %u: its samples "
                    "read zero\n", index);
         reported = true;
         return NULL;
      }
   }
   const void *data = fp_resource(fv->base.texture)->data;
   slot->sampler_index = sampler_index;
   if (slot->valid && slot->epoch == ts->fp->tex_epoch && slot->view == fv &&
       slot->sampler == ss && slot->data == data && !ts->rebind)
      return &slot->unit;
   slot->epoch = ts->fp->tex_epoch;
   slot->view = fv;
   slot->sampler = ss;
   slot->data = data;
   struct fp_tex_key key;
   fp_tex_key(&key, fv, ss);
   if (slot->valid && !memcmp(&key, &slot->key, sizeof(key)))
      return &slot->unit;
   struct tex_view_desc vd;
   struct tex_sampler_desc sd;
   fp_view_desc(fv, &vd);
   fp_sampler_desc(fv, ss, &sd);
   tex_unit_bind(&slot->unit, ts->ns, &vd, &sd, &ts->stats);
   slot->footprints = 0;
   tex_unit_set_datapath(&slot->unit, ts->fp->opts->debug & FP_DEBUG_SCALAR,
                         ts->fp->opts->debug & FP_DEBUG_NOSKIP);
   slot->unit.axes_shared = &ts->skip_axes;
   memcpy(&slot->key, &key, sizeof(key));
   slot->valid = true;
   return &slot->unit;
}

static enum tex_lod_control fp_lod_control(enum tgsi_sampler_control c)
{
   switch (c) {
   case TGSI_SAMPLER_LOD_BIAS: return TEX_LOD_BIAS;
   case TGSI_SAMPLER_LOD_EXPLICIT: return TEX_LOD_EXPLICIT;
   case TGSI_SAMPLER_LOD_ZERO: return TEX_LOD_ZERO;
   case TGSI_SAMPLER_DERIVS_EXPLICIT: return TEX_LOD_DERIVS;
   default: return TEX_LOD_IMPLICIT;
   }
}

/* The sampler's counts into the model's counters (FIXPIPE_STATS). */
void fp_tgsi_sampler_jit_gathers(struct tgsi_sampler *s, const struct fp_jit_gather **gathers,
                                 const uint64_t **epoch, uint64_t **gathered)
{
   struct fp_tgsi_sampler *ts = (struct fp_tgsi_sampler *)s;
   *gathers = ts->gather;
   *epoch = &ts->fp->tex_epoch;
   *gathered = &ts->gathered_jit;
}

void fp_tgsi_sampler_flush_stats(struct fp_tgsi_sampler *ts, struct rast_context *rc)
{
   /* compiled gathers: the counts fp_gather_quad keeps, and none of its
    * range events (such calls take the glue) */
   ts->quads += ts->gathered_jit;
   ts->texels += 4 * 4 * ts->gathered_jit;
   tex_stats_jit_gathers(rc, ts->gathered_jit);
   ts->gathered_jit = 0;
   tex_stats_to_rast(rc, ts->stats.sat, ts->stats.flush, ts->skip_lod, ts->lod_quads,
                     ts->skip_axes, ts->skip_footprint, ts->quads, ts->texels);
   ts->stats.sat = ts->stats.flush = ts->skip_lod = ts->lod_quads = 0;
   ts->skip_axes = ts->skip_footprint = ts->quads = ts->texels = 0;
}

/* Range events at once (rare); the LOD counts, one per sample, in batches:
 * whoever prints the counters flushes the rest first. */
static inline void fp_tex_stats(struct fp_tgsi_sampler *ts)
{
   if (ts->stats.sat | ts->stats.flush || ts->quads >= 4096)
      fp_tgsi_sampler_flush_stats(ts, ts->rast);
}

/* The unit of a sample request's view and sampler (bound if need be), or
 * NULL when there is nothing to sample: the result is then zero. */
static const struct tex_unit *fp_unit_of(struct fp_tgsi_sampler *ts, unsigned sview_index,
                                         unsigned sampler_index,
                                         const struct fp_sampler_view **view)
{
   struct fp_context *fp = ts->fp;
   if (sview_index >= PIPE_MAX_SAMPLERS || sampler_index >= PIPE_MAX_SAMPLERS)
      return NULL;
   const struct fp_tex_slot *slot = ts->slot[sview_index];
   if (slot && slot->valid && slot->epoch == fp->tex_epoch &&
       slot->sampler_index == sampler_index && !ts->rebind) {
      *view = slot->view;
      return &slot->unit;
   }
   const struct fp_sampler_view *fv =
      (const struct fp_sampler_view *)fp->sampler_views[ts->stage][sview_index];
   const struct pipe_sampler_state *ss = fp->samplers[ts->stage][sampler_index];
   if (!fv || !ss || !fv->base.texture || !fp_resource(fv->base.texture)->data)
      return NULL;
   *view = fv;
   return fp_tex_bind(ts, sview_index, sampler_index, fv, ss);
}

/* A gather through the unit: its address stage, unless one of the slot's
 * last footprints was addressed from the same coordinates, then the texel
 * reads of the channel. */
static void fp_gather(struct fp_tgsi_sampler *ts, unsigned sview_index, const struct tex_unit *u,
                      const struct tex_quad *q, unsigned comp, float rgba[4][TGSI_QUAD_SIZE])
{
   struct fp_tex_slot *slot = ts->slot[sview_index];
   if (ts->rebind || !u->footprint || u != &slot->unit) {
      tex_unit_gather(u, q, comp, rgba);
      return;
   }
   if (slot->footprint_run != ts->run) {   /* another run of the shader: forget */
      slot->footprint_run = ts->run;
      slot->footprints = slot->footprint_next = 0;
   }
   float key[3][TGSI_QUAD_SIZE];
   memcpy(key[0], q->s, sizeof(key[0]));
   memcpy(key[1], q->t, sizeof(key[1]));
   memcpy(key[2], q->layer, sizeof(key[2]));
   /* the 4-byte layouts: every channel's texels kept with the footprint,
    * where a run is a fragment shader's (the texture does not change
    * within it; the other stages begin no runs); others read a channel */
   const bool words = ts->stage == PIPE_SHADER_FRAGMENT && tex_unit_gather_reads_words(u);
   for (unsigned i = 0; i < slot->footprints; i++) {
      if (!memcmp(key, slot->footprint_key[i], sizeof(key))) {
         ts->skip_footprint++;
         if (words) {
            memcpy(rgba, slot->footprint_texels[i][comp & 3], sizeof(float[4][TGSI_QUAD_SIZE]));
            tex_unit_gather_count(u, &slot->footprint[i]);
         } else {
            tex_unit_gather_read(u, &slot->footprint[i], q->ref, comp, rgba);
         }
         return;
      }
   }
   const unsigned i = slot->footprint_next;
   slot->footprint_next = (i + 1) % FP_FOOTPRINTS;
   if (slot->footprints < FP_FOOTPRINTS)
      slot->footprints++;
   tex_unit_gather_footprint(u, q, &slot->footprint[i]);
   memcpy(slot->footprint_key[i], key, sizeof(key));
   if (words) {
      tex_unit_gather_read_all(u, &slot->footprint[i], q->ref, slot->footprint_texels[i]);
      memcpy(rgba, slot->footprint_texels[i][comp & 3], sizeof(float[4][TGSI_QUAD_SIZE]));
      tex_unit_gather_count(u, &slot->footprint[i]);
   } else {
      tex_unit_gather_read(u, &slot->footprint[i], q->ref, comp, rgba);
   }
}

/* A gather reads the base level: its texel offsets as coordinate offsets
 * there, per axis; false where there are none. */
static bool fp_gather_offsets(const struct tex_unit *u, const int8_t offset[3], float k[3])
{
   if (!offset || !(offset[0] | offset[1] | offset[2]))
      return false;
   const int size[3] = { u->view.level[0].w, u->view.level[0].h, u->view.level[0].d };
   for (unsigned a = 0; a < 3; a++)
      k[a] = a >= u->dims ? 0.0f : u->samp.normalized ? (float)offset[a] / (float)size[a]
                                                      : offset[a];
   return true;
}

/* A gather of a quad whose operands are in place (fp_tgsi_get_samples, or
 * laid out by compiled code), its coordinates moved by `k` (NULL: no
 * offsets), and its counts. */
static void fp_gather_quad(struct fp_tgsi_sampler *ts, unsigned sview_index,
                           const struct tex_unit *u, struct tex_quad *q, const float *k,
                           unsigned comp, float rgba[4][TGSI_QUAD_SIZE])
{
   if (k) {
      /* a vector each: the memo's key reads the four coordinates as one,
       * which a store of four floats one by one would hold up */
      typedef float v4f __attribute__((vector_size(16)));
      float *co[3] = { q->s, q->t, q->r };
      for (unsigned a = 0; a < u->dims; a++) {
         v4f c;
         memcpy(&c, co[a], sizeof(c));
         c += k[a];
         memcpy(co[a], &c, sizeof(c));
      }
   }
   ts->quads++;
   ts->texels += 4 * 4;
   fp_gather(ts, sview_index, u, q, comp, rgba);
   fp_tex_stats(ts);
}

/* `n` quads through the unit (one, or up to four in one call), and their counts. */
static inline void fp_unit_sample(struct fp_tgsi_sampler *ts, const struct tex_unit *u,
                                  const struct tex_quad *q, unsigned n,
                                  enum tgsi_sampler_control control,
                                  float rgba[][TGSI_NUM_CHANNELS][TGSI_QUAD_SIZE])
{
   const enum tex_lod_control ctl = fp_lod_control(control);
   const bool lod_from_diffs = ctl == TEX_LOD_IMPLICIT || ctl == TEX_LOD_BIAS;
   ts->lod_quads += n * lod_from_diffs;
   ts->quads += n;
   ts->texels += n * 4 * u->taps;
   ts->skip_lod += n * (u->lod_skipped && lod_from_diffs);
   tex_unit_sample_quads(u, q, n, ctl, rgba);
   if (unlikely(ts->fp->vectors_on))
      rast_vectors_tex(ts->rast, u, q, n, ctl, (const float (*)[4][4])rgba);
   fp_tex_stats(ts);
}

/* The array layer among tgsi's operands of a sample or LOD query: a 1-D
 * array's in t, a cube map array's in c0, the others' in r. */
static inline float fp_tgsi_layer(enum pipe_texture_target target, float t, float r, float c0)
{
   return target == PIPE_TEXTURE_1D_ARRAY ? t : target == PIPE_TEXTURE_CUBE_ARRAY ? c0 : r;
}

static void fp_tgsi_get_samples(struct tgsi_sampler *tgsi_sampler, const unsigned sview_index,
                                const unsigned sampler_index, const float s[TGSI_QUAD_SIZE],
                                const float t[TGSI_QUAD_SIZE], const float r[TGSI_QUAD_SIZE],
                                const float c0[TGSI_QUAD_SIZE], const float c1[TGSI_QUAD_SIZE],
                                float derivs[3][2][TGSI_QUAD_SIZE], const int8_t offset[3],
                                enum tgsi_sampler_control control,
                                float rgba[TGSI_NUM_CHANNELS][TGSI_QUAD_SIZE])
{
   struct fp_tgsi_sampler *ts = (struct fp_tgsi_sampler *)tgsi_sampler;
   const struct fp_sampler_view *fv;

   memset(rgba, 0, sizeof(float) * TGSI_NUM_CHANNELS * TGSI_QUAD_SIZE);
   const struct tex_unit *u = fp_unit_of(ts, sview_index, sampler_index, &fv);
   if (!u)
      return;
   /* Outside the fragment stage tgsi's quad is four unrelated vertices, not
    * neighbouring pixels: the implicit level of detail is 0 there (GLSL ES
    * 1.00 8.7: the base level, with the magnification filter), and a bias
    * is added to 0.  A LOD from the vertices' differences would pick any
    * level. */
   if (ts->stage != PIPE_SHADER_FRAGMENT) {
      if (control == TGSI_SAMPLER_LOD_NONE)
         control = TGSI_SAMPLER_LOD_ZERO;
      else if (control == TGSI_SAMPLER_LOD_BIAS)
         control = TGSI_SAMPLER_LOD_EXPLICIT;
   }

   /* tgsi's operands per target: the array layer, the shadow reference
    * (a cube map array's layer in c0, its reference in c1, where no LOD
    * operand goes with it). */
   struct tex_quad q;
   const enum pipe_texture_target target = fv->base.target;
   const bool cube_array = target == PIPE_TEXTURE_CUBE_ARRAY;
   const bool ref_in_c0 = target == PIPE_TEXTURE_2D_ARRAY || target == PIPE_TEXTURE_CUBE;
   const bool clamp_ref = fv->zs && fv->base.format != PIPE_FORMAT_Z32_FLOAT &&
                          fv->base.format != PIPE_FORMAT_Z32_FLOAT_S8X24_UINT;
   for (unsigned p = 0; p < TGSI_QUAD_SIZE; p++) {
      q.s[p] = s[p];
      q.t[p] = t[p];
      q.r[p] = r[p];
      q.layer[p] = fp_tgsi_layer(target, t[p], r[p], c0[p]);
      q.ref[p] = ref_in_c0 ? c0[p] : cube_array ? c1[p] : r[p];
      if (clamp_ref)
         q.ref[p] = CLAMP(q.ref[p], 0.0f, 1.0f);
      q.lod[p] = c1[p];
   }
   if (control == TGSI_SAMPLER_DERIVS_EXPLICIT) {
      for (unsigned a = 0; a < 3; a++)
         for (unsigned p = 0; p < TGSI_QUAD_SIZE; p++) {
            q.ddx[a][p] = derivs[a][0][p];
            q.ddy[a][p] = derivs[a][1][p];
         }
   }
   const bool offsets = offset && (offset[0] | offset[1] | offset[2]);
   if (offsets && control != TGSI_SAMPLER_GATHER) {
      /* texel offsets (GLSL ES 3.00) at the level sampled: the unit's table
       * path, which moves the coordinate per level */
      const enum tex_lod_control ctl = fp_lod_control(control);
      ts->quads++;
      ts->lod_quads += ctl == TEX_LOD_IMPLICIT || ctl == TEX_LOD_BIAS;
      ts->texels += 4 * u->taps;
      tex_unit_sample_offset(u, &q, ctl, offset, rgba);
      fp_tex_stats(ts);
      return;
   }
   if (control == TGSI_SAMPLER_GATHER) {
      /* tgsi_exec passes the component in the LOD operand's bits */
      union { float f; uint32_t u; } comp = { c1[0] };
      float k[3];
      fp_gather_quad(ts, sview_index, u, &q, fp_gather_offsets(u, offset, k) ? k : NULL,
                     comp.u & 3, rgba);
      return;
   }
   fp_unit_sample(ts, u, &q, 1, control, (float(*)[TGSI_NUM_CHANNELS][TGSI_QUAD_SIZE])rgba);
}

/* The quads the compiled code laid out itself (fp_jit_sample.c: a plain
 * 2-D sample, the operands fp_tgsi_get_samples would have built), in one
 * call of the unit: `quads` of them real, `max` laid out.  The others
 * repeat the first (a quad shaded alone, the last of a primitive) and are
 * not sampled, their texels zero. */
void fp_tgsi_sample_quads(struct tgsi_sampler *tgsi_sampler, uint32_t sview_index,
                          uint32_t sampler_index, uint32_t control, uint32_t quads,
                          uint32_t max, const struct tex_quad *q,
                          float rgba[][4][TGSI_QUAD_SIZE])
{
   struct fp_tgsi_sampler *ts = (struct fp_tgsi_sampler *)tgsi_sampler;
   const struct fp_sampler_view *fv;
   const struct tex_unit *u = fp_unit_of(ts, sview_index, sampler_index, &fv);
   const unsigned n = quads < 1 ? 1 : quads > max ? max : quads;
   const unsigned sampled = u ? n : 0;     /* the others' texels are zero */
   if (sampled < max)
      memset(rgba[sampled], 0, sizeof(float) * (max - sampled) * TGSI_NUM_CHANNELS * TGSI_QUAD_SIZE);
   if (u)
      fp_unit_sample(ts, u, q, n, (enum tgsi_sampler_control)control, rgba);
}


/* The unit's registers for compiled gathers, once a binding epoch, before
 * the compiled code's first call in it (fp_tgsi_sampler_jit_prepare): not
 * valid under noskip (every request binds) or FIXPIPE_DEBUG=nojitgather,
 * nor for a unit the compiled copy does not cover (tex_unit_gather_regs). */
static void fp_jit_gather_fill(struct fp_tgsi_sampler *ts, unsigned sview_index,
                               unsigned sampler_index, const struct tex_unit *u)
{
   struct fp_jit_gather *g = &ts->gather[sview_index];
   const uint64_t epoch = ts->fp->tex_epoch;
   if (g->epoch == epoch && g->sampler == sampler_index)
      return;
   g->epoch = epoch;
   g->sampler = sampler_index;
   g->valid = !ts->rebind && !(ts->fp->opts->debug & FP_DEBUG_NOJITGATHER) &&
              ts->stage == PIPE_SHADER_FRAGMENT && tex_unit_gather_regs(u, &g->regs);
}

void fp_tgsi_sampler_jit_prepare(struct fp_tgsi_sampler *ts, const uint8_t (*units)[2],
                                 unsigned n)
{
   const uint64_t epoch = ts->fp->tex_epoch;
   for (unsigned i = 0; i < n; i++) {
      const unsigned t = units[i][0], smp = units[i][1];
      struct fp_jit_gather *g = &ts->gather[t];
      if (g->epoch == epoch && g->sampler == smp)
         continue;
      const struct fp_sampler_view *fv;
      const struct tex_unit *u = fp_unit_of(ts, t, smp, &fv);
      if (u) {
         fp_jit_gather_fill(ts, t, smp, u);
      } else {   /* nothing bound: the glue's zeros */
         g->epoch = epoch;
         g->sampler = smp;
         g->valid = 0;
      }
   }
}

/* Gathers of channel `comp` with constant offsets on the quads compiled
 * code laid out itself (fp_jit_sample.c: a non-shadow 2-D, 2-D array or
 * rectangle view, the operands fp_tgsi_get_samples would have built), in
 * one call: `quads` of them real, `max` laid out, the others' texels zero. */
void fp_tgsi_gather_quads(struct tgsi_sampler *tgsi_sampler, uint32_t sview_index,
                          uint32_t sampler_index, uint32_t comp, int32_t offset_s,
                          int32_t offset_t, uint32_t quads, uint32_t max,
                          const struct tex_quad *q, float rgba[][4][TGSI_QUAD_SIZE])
{
   struct fp_tgsi_sampler *ts = (struct fp_tgsi_sampler *)tgsi_sampler;
   const struct fp_sampler_view *fv;
   const struct tex_unit *u = fp_unit_of(ts, sview_index, sampler_index, &fv);
   const unsigned n = quads < 1 ? 1 : quads > max ? max : quads;
   const unsigned gathered = u ? n : 0;
   if (gathered < max)
      memset(rgba[gathered], 0, sizeof(float) * (max - gathered) * TGSI_NUM_CHANNELS * TGSI_QUAD_SIZE);
   const int8_t offset[3] = { (int8_t)offset_s, (int8_t)offset_t, 0 };
   float k[3];
   const bool moved = gathered && fp_gather_offsets(u, offset, k);
   for (unsigned i = 0; i < gathered; i++) {
      struct tex_quad qi;
      memcpy(qi.s, q[i].s, sizeof(qi.s));
      memcpy(qi.t, q[i].t, sizeof(qi.t));
      memcpy(qi.r, q[i].r, sizeof(qi.r));
      memcpy(qi.layer, q[i].layer, sizeof(qi.layer));
      memcpy(qi.ref, q[i].ref, sizeof(qi.ref));
      fp_gather_quad(ts, sview_index, u, &qi, moved ? k : NULL, comp & 3, rgba[i]);
   }
}

/* textureQueryLod: the unit's own LOD and level choice (tex_unit_query_lod)
 * for the quad tgsi gives, its operands as fp_tgsi_get_samples takes them. */
static void fp_tgsi_query_lod(const struct tgsi_sampler *tgsi_sampler, const unsigned sview_index,
                              const unsigned sampler_index, const float s[TGSI_QUAD_SIZE],
                              const float t[TGSI_QUAD_SIZE], const float p[TGSI_QUAD_SIZE],
                              const float c0[TGSI_QUAD_SIZE],
                              const enum tgsi_sampler_control control,
                              float mipmap[TGSI_QUAD_SIZE], float lod[TGSI_QUAD_SIZE])
{
   struct fp_tgsi_sampler *ts = (struct fp_tgsi_sampler *)tgsi_sampler;
   const struct fp_sampler_view *fv;
   memset(mipmap, 0, sizeof(float) * TGSI_QUAD_SIZE);
   memset(lod, 0, sizeof(float) * TGSI_QUAD_SIZE);
   const struct tex_unit *u = fp_unit_of(ts, sview_index, sampler_index, &fv);
   if (!u)
      return;
   struct tex_quad q;
   memset(&q, 0, sizeof(q));
   const enum pipe_texture_target target = fv->base.target;
   for (unsigned i = 0; i < TGSI_QUAD_SIZE; i++) {
      q.s[i] = s[i];
      q.t[i] = t[i];
      q.r[i] = p[i];
      q.layer[i] = fp_tgsi_layer(target, t[i], p[i], c0[i]);
   }
   /* the implicit LOD of a fragment quad; elsewhere tgsi's quad is four
    * unrelated vertices, whose LOD is 0 as their samples' (get_samples) */
   const enum tex_lod_control ctl =
      ts->stage == PIPE_SHADER_FRAGMENT ? fp_lod_control(control) : TEX_LOD_ZERO;
   tex_unit_query_lod(u, &q, ctl, mipmap, lod);
   fp_tex_stats(ts);
}

static void fp_tgsi_get_dims(struct tgsi_sampler *tgsi_sampler, const unsigned sview_index,
                             int level, int dims[4])
{
   struct fp_tgsi_sampler *ts = (struct fp_tgsi_sampler *)tgsi_sampler;
   const struct pipe_sampler_view *v =
      sview_index < PIPE_MAX_SHADER_SAMPLER_VIEWS ? ts->fp->sampler_views[ts->stage][sview_index]
                                                  : NULL;
   memset(dims, 0, 4 * sizeof(int));
   if (!v || !v->texture)
      return;
   const struct pipe_resource *t = v->texture;
   if (v->target == PIPE_BUFFER) {
      /* textureSize of a texture buffer: its texels (fp_view_desc) */
      const unsigned offset = MIN2(v->u.buf.offset, t->width0);
      dims[0] = (int)(MIN2(v->u.buf.size, t->width0 - offset) /
                      util_format_get_blocksize(v->format));
      return;
   }
   int lev = (int)v->u.tex.first_level + level;
   dims[3] = v->u.tex.last_level - v->u.tex.first_level + 1;
   if (level < 0 || lev > (int)v->u.tex.last_level)
      return;
   dims[0] = u_minify(t->width0, lev);
   switch (v->target) {
   case PIPE_TEXTURE_1D_ARRAY:
      dims[1] = v->u.tex.last_layer - v->u.tex.first_layer + 1;
      break;
   case PIPE_TEXTURE_2D_ARRAY:
      dims[1] = u_minify(t->height0, lev);
      dims[2] = v->u.tex.last_layer - v->u.tex.first_layer + 1;
      break;
   case PIPE_TEXTURE_CUBE_ARRAY:   /* textureSize: the cubes */
      dims[1] = u_minify(t->height0, lev);
      dims[2] = (v->u.tex.last_layer - v->u.tex.first_layer + 1) / 6;
      break;
   case PIPE_TEXTURE_3D:
      dims[1] = u_minify(t->height0, lev);
      dims[2] = u_minify(t->depth0, lev);
      break;
   case PIPE_TEXTURE_1D:
      break;
   default:
      dims[1] = u_minify(t->height0, lev);
      break;
   }
}

/* texelFetch of a multisampled view (sampler2DMS, sampler2DMSArray): the
 * LOD operand is the sample; sample s of layer l is plane l * samples + s
 * (fp_resource.h).  A sample out of range reads zero. */
static void fp_texel_ms(struct tex_view_desc *vd, unsigned samples, const int i[TGSI_QUAD_SIZE],
                        const int j[TGSI_QUAD_SIZE], const int k[TGSI_QUAD_SIZE],
                        const int sample[TGSI_QUAD_SIZE], const int8_t offset[3],
                        enum pipe_texture_target target, float rgba[TGSI_NUM_CHANNELS][TGSI_QUAD_SIZE])
{
   int x[TGSI_QUAD_SIZE], y[TGSI_QUAD_SIZE], z[TGSI_QUAD_SIZE], level[TGSI_QUAD_SIZE];
   const int layers = target == PIPE_TEXTURE_2D_ARRAY ? vd->layers : 1;
   vd->target = TEX_TARGET_2D_ARRAY;
   vd->layers = layers * (int)samples;
   vd->num_levels = 1;
   for (unsigned p = 0; p < TGSI_QUAD_SIZE; p++) {
      const int layer = target == PIPE_TEXTURE_2D_ARRAY ? k[p] : 0;
      x[p] = i[p] + offset[0];
      y[p] = j[p] + offset[1];
      z[p] = layer * (int)samples + sample[p];
      level[p] = sample[p] >= 0 && sample[p] < (int)samples && layer >= 0 && layer < layers
                    ? 0 : -1;
   }
   tex_view_texel(vd, x, y, z, level, rgba);
}

static void fp_tgsi_get_texel(struct tgsi_sampler *tgsi_sampler, const unsigned sview_index,
                              const int i[TGSI_QUAD_SIZE], const int j[TGSI_QUAD_SIZE],
                              const int k[TGSI_QUAD_SIZE], const int lod[TGSI_QUAD_SIZE],
                              const int8_t offset[3], float rgba[TGSI_NUM_CHANNELS][TGSI_QUAD_SIZE])
{
   struct fp_tgsi_sampler *ts = (struct fp_tgsi_sampler *)tgsi_sampler;
   memset(rgba, 0, sizeof(float) * TGSI_NUM_CHANNELS * TGSI_QUAD_SIZE);
   if (sview_index >= PIPE_MAX_SHADER_SAMPLER_VIEWS)
      return;
   const struct fp_sampler_view *fv =
      (const struct fp_sampler_view *)ts->fp->sampler_views[ts->stage][sview_index];
   if (!fv || !fv->base.texture || !fp_resource(fv->base.texture)->data)
      return;
   struct tex_view_desc vd;
   fp_view_desc(fv, &vd);
   int x[TGSI_QUAD_SIZE], y[TGSI_QUAD_SIZE], z[TGSI_QUAD_SIZE];
   if (fv->base.target == PIPE_BUFFER) {
      /* a texture buffer: the index alone (no level, no offset operand) */
      static const int zero[TGSI_QUAD_SIZE];
      tex_view_texel(&vd, i, zero, zero, zero, rgba);
      return;
   }
   const unsigned samples = fp_resource_samples(fv->base.texture);
   if (samples > 1) {
      fp_texel_ms(&vd, samples, i, j, k, lod, offset, fv->base.target, rgba);
      return;
   }
   for (unsigned p = 0; p < TGSI_QUAD_SIZE; p++) {
      x[p] = i[p] + offset[0];
      y[p] = j[p] + offset[1];
      z[p] = k[p] + offset[2];
      switch (fv->base.target) {
      case PIPE_TEXTURE_1D: y[p] = 0; z[p] = 0; break;
      case PIPE_TEXTURE_1D_ARRAY: z[p] = j[p]; y[p] = 0; break;
      case PIPE_TEXTURE_2D_ARRAY: z[p] = k[p]; break;
      case PIPE_TEXTURE_3D: break;
      default: z[p] = 0; break;
      }
   }
   tex_view_texel(&vd, x, y, z, lod, rgba);
}

void fp_tgsi_sampler_destroy(struct fp_tgsi_sampler *s)
{
   if (!s)
      return;
   for (unsigned i = 0; i < PIPE_MAX_SAMPLERS; i++)
      FREE(s->slot[i]);
   FREE(s);
}

struct fp_tgsi_sampler *fp_tgsi_sampler_create(struct fp_context *fp,
                                               enum pipe_shader_type stage,
                                               struct rast_context *rc)
{
   struct fp_tgsi_sampler *s = CALLOC_STRUCT(fp_tgsi_sampler);
   if (!s)
      return NULL;
   s->fp = fp;
   s->rast = rc;
   s->stage = stage;
   s->ns = fp->opts->texfmt;
   s->rebind = fp->opts->debug & FP_DEBUG_NOSKIP;
   s->base.get_samples = fp_tgsi_get_samples;
   s->base.get_dims = fp_tgsi_get_dims;
   s->base.get_texel = fp_tgsi_get_texel;
   s->base.query_lod = fp_tgsi_query_lod;
   return s;
}
