/*
 * Images and shader storage buffers for tgsi_exec (compute and fragment
 * shaders): imageLoad, imageStore, imageAtomic*, imageSize and the SSBO
 * lookup, on the driver's linear resources (fp_resource.h).  Memory
 * operations only, like clears and copies: no stage of the model reads or
 * writes them (docs/compute.md).  Fragment shaders call them from every
 * thread of the model at once, so the atomics are atomic on the storage;
 * plain loads and stores of different fragments are unordered, as GL
 * leaves them within a draw.  A coordinate outside the view reads zero
 * (alpha 1) and writes nothing, as GL's robust behaviour and softpipe.
 */
#include "util/u_math.h"
#include "util/u_memory.h"
#include "util/format/u_format.h"
#include "tgsi/tgsi_exec.h"

#include "fp_context.h"
#include "fp_resource.h"

struct fp_tgsi_image {
   struct tgsi_image base;
   const struct pipe_image_view *views;      /* fp_context.images */
};

struct fp_tgsi_buffer {
   struct tgsi_buffer base;
   const struct pipe_shader_buffer *buffers; /* fp_context.ssbo */
};

/* Whether the instruction's target has a layer (or slice) coordinate, and
 * in which operand: t for 1-D arrays, r otherwise. */
static int layer_operand(unsigned tgsi_target)
{
   switch (tgsi_target) {
   case TGSI_TEXTURE_1D_ARRAY:
      return 1;
   case TGSI_TEXTURE_2D_ARRAY:
   case TGSI_TEXTURE_3D:
   case TGSI_TEXTURE_CUBE:
   case TGSI_TEXTURE_CUBE_ARRAY:
      return 2;
   default:
      return -1;
   }
}

/* The texel of lane p, or NULL outside the view (or no view). */
static uint8_t *image_texel(const struct pipe_image_view *iv, const struct tgsi_image_params *prm,
                            enum pipe_format format, const int s[TGSI_QUAD_SIZE],
                            const int t[TGSI_QUAD_SIZE], const int r[TGSI_QUAD_SIZE], unsigned p)
{
   struct pipe_resource *res = iv->resource;
   if (!res || !fp_resource(res)->data || format == PIPE_FORMAT_NONE)
      return NULL;
   const unsigned bs = util_format_get_blocksize(format);
   if (res->target == PIPE_BUFFER) {
      const unsigned n = MIN2(iv->u.buf.size, res->width0 - MIN2(iv->u.buf.offset, res->width0)) / bs;
      if (s[p] < 0 || (unsigned)s[p] >= n)
         return NULL;
      return fp_resource(res)->data + iv->u.buf.offset + (size_t)s[p] * bs;
   }
   if (bs > util_format_get_blocksize(res->format))
      return NULL;
   const unsigned level = iv->u.tex.level;
   const int w = u_minify(res->width0, level);
   const int h = res->target == PIPE_TEXTURE_1D || res->target == PIPE_TEXTURE_1D_ARRAY
                    ? 1 : u_minify(res->height0, level);
   const int op = layer_operand(prm->tgsi_tex_instr);
   /* a 1-D image's t is no coordinate (the register's y holds whatever
    * the shader left there), or its layer in a 1-D array */
   const bool one_d = prm->tgsi_tex_instr == TGSI_TEXTURE_1D ||
                      prm->tgsi_tex_instr == TGSI_TEXTURE_1D_ARRAY;
   const int y = one_d ? 0 : t[p];
   int layer = 0, layers = 1;
   if (op >= 0) {
      layer = op == 1 ? t[p] : r[p];
      layers = res->target == PIPE_TEXTURE_3D ? u_minify(res->depth0, level)
                                              : iv->u.tex.last_layer - iv->u.tex.first_layer + 1;
   }
   if (s[p] < 0 || s[p] >= w || y < 0 || y >= h || layer < 0 || layer >= layers)
      return NULL;
   const unsigned z = layer + (res->target == PIPE_TEXTURE_3D && op >= 0 ? 0 : iv->u.tex.first_layer);
   return fp_resource_image(res, level, z) + (size_t)y * fp_resource(res)->stride[level] +
          (size_t)s[p] * bs;
}

static const struct pipe_image_view *image_view(const struct tgsi_image *image,
                                                const struct tgsi_image_params *prm)
{
   const struct fp_tgsi_image *img = (const struct fp_tgsi_image *)image;
   return prm->unit < PIPE_MAX_SHADER_IMAGES ? &img->views[prm->unit] : NULL;
}

/* What a texel outside the view reads: zero, with alpha 1 when the format
 * has none. */
static void outside(enum pipe_format format, float rgba[TGSI_NUM_CHANNELS][TGSI_QUAD_SIZE],
                    unsigned p)
{
   union { float f; uint32_t u; } one = { 1.0f };
   if (format != PIPE_FORMAT_NONE && util_format_is_pure_integer(format))
      one.u = 1;
   const bool has_alpha = format != PIPE_FORMAT_NONE && util_format_get_nr_components(format) == 4;
   for (unsigned c = 0; c < 4; c++)
      rgba[c][p] = 0.0f;
   if (!has_alpha)
      rgba[3][p] = one.f;
}

static void fp_image_load(const struct tgsi_image *image, const struct tgsi_image_params *prm,
                          const int s[TGSI_QUAD_SIZE], const int t[TGSI_QUAD_SIZE],
                          const int r[TGSI_QUAD_SIZE], const int sample[TGSI_QUAD_SIZE],
                          float rgba[TGSI_NUM_CHANNELS][TGSI_QUAD_SIZE])
{
   const struct pipe_image_view *iv = image_view(image, prm);
   (void)sample;
   for (unsigned p = 0; p < TGSI_QUAD_SIZE; p++) {
      const uint8_t *texel = iv && (prm->execmask & (1u << p))
                                ? image_texel(iv, prm, prm->format, s, t, r, p) : NULL;
      if (!texel) {
         outside(prm->format, rgba, p);
         continue;
      }
      uint32_t v[4];
      util_format_unpack_rgba(prm->format, v, texel, 1);
      for (unsigned c = 0; c < 4; c++)
         ((uint32_t *)rgba[c])[p] = v[c];
   }
}

static void fp_image_store(const struct tgsi_image *image, const struct tgsi_image_params *prm,
                           const int s[TGSI_QUAD_SIZE], const int t[TGSI_QUAD_SIZE],
                           const int r[TGSI_QUAD_SIZE], const int sample[TGSI_QUAD_SIZE],
                           float rgba[TGSI_NUM_CHANNELS][TGSI_QUAD_SIZE])
{
   const struct pipe_image_view *iv = image_view(image, prm);
   (void)sample;
   if (!iv)
      return;
   /* writeonly images without a format qualifier store in the view's */
   const enum pipe_format format = prm->format != PIPE_FORMAT_NONE ? prm->format : iv->format;
   for (unsigned p = 0; p < TGSI_QUAD_SIZE; p++) {
      uint8_t *texel = (prm->execmask & (1u << p)) ? image_texel(iv, prm, format, s, t, r, p)
                                                   : NULL;
      if (!texel)
         continue;
      uint32_t v[4];
      for (unsigned c = 0; c < 4; c++)
         v[c] = ((const uint32_t *)rgba[c])[p];
      util_format_pack_rgba(format, texel, v, 1);
   }
}

/* The result of one atomic operation on a 32-bit texel (r32ui, r32i;
 * r32f exchange and add) holding `old`. */
static uint32_t atomic32_result(enum tgsi_opcode op, uint32_t old, uint32_t a, uint32_t b)
{
   union { uint32_t u; float f; } x = { old }, y = { a };
   switch (op) {
   case TGSI_OPCODE_ATOMUADD: return old + a;
   case TGSI_OPCODE_ATOMXCHG: return a;
   case TGSI_OPCODE_ATOMCAS: return old == a ? b : old;
   case TGSI_OPCODE_ATOMAND: return old & a;
   case TGSI_OPCODE_ATOMOR: return old | a;
   case TGSI_OPCODE_ATOMXOR: return old ^ a;
   case TGSI_OPCODE_ATOMUMIN: return MIN2(old, a);
   case TGSI_OPCODE_ATOMUMAX: return MAX2(old, a);
   case TGSI_OPCODE_ATOMIMIN: return (uint32_t)MIN2((int32_t)old, (int32_t)a);
   case TGSI_OPCODE_ATOMIMAX: return (uint32_t)MAX2((int32_t)old, (int32_t)a);
   case TGSI_OPCODE_ATOMFADD: x.f += y.f; return x.u;
   default: return old;
   }
}

/* The operation on the texel as one compare-and-swap: fragment shaders run
 * on the model's threads at once (docs/threads.md), and two fragments'
 * atomics on one texel must not lose either's update.  Returns the value
 * before it. */
static uint32_t atomic32(enum tgsi_opcode op, uint32_t *texel, uint32_t a, uint32_t b)
{
   uint32_t old = __atomic_load_n(texel, __ATOMIC_RELAXED);
   while (!__atomic_compare_exchange_n(texel, &old, atomic32_result(op, old, a, b), true,
                                       __ATOMIC_SEQ_CST, __ATOMIC_RELAXED))
      ;
   return old;
}

static void fp_image_op(const struct tgsi_image *image, const struct tgsi_image_params *prm,
                        enum tgsi_opcode op, const int s[TGSI_QUAD_SIZE],
                        const int t[TGSI_QUAD_SIZE], const int r[TGSI_QUAD_SIZE],
                        const int sample[TGSI_QUAD_SIZE],
                        float rgba[TGSI_NUM_CHANNELS][TGSI_QUAD_SIZE],
                        float rgba2[TGSI_NUM_CHANNELS][TGSI_QUAD_SIZE])
{
   const struct pipe_image_view *iv = image_view(image, prm);
   (void)sample;
   for (unsigned p = 0; p < TGSI_QUAD_SIZE; p++) {
      uint8_t *texel = iv && util_format_get_blocksize(prm->format) == 4
                          ? image_texel(iv, prm, prm->format, s, t, r, p) : NULL;
      if (!texel) {
         outside(prm->format, rgba, p);
         continue;
      }
      uint32_t *word = (uint32_t *)texel;
      if (!(prm->execmask & (1u << p))) {
         /* a lane that is off reads only */
         ((uint32_t *)rgba[0])[p] = __atomic_load_n(word, __ATOMIC_RELAXED);
         continue;
      }
      ((uint32_t *)rgba[0])[p] = atomic32(op, word, ((const uint32_t *)rgba[0])[p],
                                          ((const uint32_t *)rgba2[0])[p]);
   }
}

static void fp_image_dims(const struct tgsi_image *image, const struct tgsi_image_params *prm,
                          int dims[4])
{
   const struct pipe_image_view *iv = image_view(image, prm);
   memset(dims, 0, 4 * sizeof(int));
   if (!iv || !iv->resource)
      return;
   const struct pipe_resource *res = iv->resource;
   if (res->target == PIPE_BUFFER) {
      dims[0] = iv->u.buf.size / util_format_get_blocksize(iv->format);
      return;
   }
   const unsigned level = iv->u.tex.level;
   const int layers = iv->u.tex.last_layer - iv->u.tex.first_layer + 1;
   dims[0] = u_minify(res->width0, level);
   switch (prm->tgsi_tex_instr) {
   case TGSI_TEXTURE_1D:
      break;
   case TGSI_TEXTURE_1D_ARRAY:
      dims[1] = layers;
      break;
   case TGSI_TEXTURE_2D_ARRAY:
      dims[1] = u_minify(res->height0, level);
      dims[2] = layers;
      break;
   case TGSI_TEXTURE_3D:
      dims[1] = u_minify(res->height0, level);
      dims[2] = u_minify(res->depth0, level);
      break;
   case TGSI_TEXTURE_CUBE_ARRAY:
      dims[1] = u_minify(res->height0, level);
      dims[2] = layers / 6;
      break;
   default:
      dims[1] = u_minify(res->height0, level);
      break;
   }
}

static void *fp_buffer_lookup(const struct tgsi_buffer *buffer, uint32_t unit, uint32_t *size)
{
   const struct fp_tgsi_buffer *b = (const struct fp_tgsi_buffer *)buffer;
   *size = 0;
   if (unit >= PIPE_MAX_SHADER_BUFFERS)
      return NULL;
   const struct pipe_shader_buffer *sb = &b->buffers[unit];
   if (!sb->buffer || !fp_resource(sb->buffer)->data || sb->buffer_offset > sb->buffer->width0 ||
       sb->buffer_size > sb->buffer->width0 - sb->buffer_offset)
      return NULL;
   *size = sb->buffer_size;
   return fp_resource(sb->buffer)->data + sb->buffer_offset;
}

struct tgsi_image *fp_tgsi_image_create(const struct pipe_image_view *views)
{
   struct fp_tgsi_image *img = CALLOC_STRUCT(fp_tgsi_image);
   if (!img)
      return NULL;
   img->views = views;
   img->base.load = fp_image_load;
   img->base.store = fp_image_store;
   img->base.op = fp_image_op;
   img->base.get_dims = fp_image_dims;
   return &img->base;
}

struct tgsi_buffer *fp_tgsi_buffer_create(const struct pipe_shader_buffer *buffers)
{
   struct fp_tgsi_buffer *b = CALLOC_STRUCT(fp_tgsi_buffer);
   if (!b)
      return NULL;
   b->buffers = buffers;
   b->base.lookup = fp_buffer_lookup;
   return &b->base;
}
