/*
 * Texture sampling for tgsi_exec: a plain float sampler behind the
 * tgsi_sampler interface, kept in this one file so that the modeled
 * dynamic fixed-point texture unit (spec section 4) can replace it.
 *
 * Texels come from util_format's fetch (sRGB decoded, compressed blocks
 * included) or unpack_z_float for depth.  LOD comes from the quad's
 * coordinate differences (pixels 0, 1 and 2) times the level size.
 */
#include <math.h>
#include <string.h>

#include "util/u_memory.h"
#include "util/u_math.h"
#include "util/format/u_format.h"
#include "tgsi/tgsi_exec.h"

#include "fp_context.h"
#include "fp_resource.h"

struct fp_tgsi_sampler {
   struct tgsi_sampler base;
   struct fp_context *fp;
   enum pipe_shader_type stage;
};

struct tgsi_sampler *fp_tgsi_sampler_base(struct fp_tgsi_sampler *s)
{
   return &s->base;
}

void fp_init_sampler_view(struct fp_sampler_view *v)
{
   enum pipe_format f = v->base.format;
   const struct util_format_description *d = util_format_description(f);
   v->zs = d && d->colorspace == UTIL_FORMAT_COLORSPACE_ZS;
   v->fetch = v->zs ? NULL : (void *)util_format_fetch_rgba_func(f);
   if (v->zs && !util_format_has_depth(d))
      v->zs = false;   /* stencil-only sampling: not offered, reads zero */
   v->is_unorm = util_format_is_unorm(f);
   v->is_snorm = util_format_is_snorm(f);
   v->bw = d ? d->block.width : 1;
   v->bh = d ? d->block.height : 1;
   v->bsize = d ? MAX2(d->block.bits / 8, 1) : 1;
}

/* What one get_samples call works with. */
struct fp_samp {
   const struct fp_sampler_view *view;
   const struct pipe_sampler_state *ss;
   struct fp_resource *res;
   float border[4];
   bool compare;
};

/* Level dimensions (in texels) of the view's level `level` (absolute). */
static void fp_level_size(const struct fp_samp *S, unsigned level, int *w, int *h, int *d)
{
   const struct pipe_resource *t = &S->res->base;
   *w = u_minify(t->width0, level);
   *h = u_minify(t->height0, level);
   *d = t->target == PIPE_TEXTURE_3D ? (int)u_minify(t->depth0, level) : 1;
}

/* One texel, x/y/z already inside the level; z is the slice or layer. */
static void fp_texel(const struct fp_samp *S, unsigned level, int x, int y, int z,
                     float ref, float out[4])
{
   const struct fp_sampler_view *v = S->view;
   const struct fp_resource *r = S->res;
   const uint8_t *p;

   if (r->base.target == PIPE_TEXTURE_1D_ARRAY || r->base.target == PIPE_TEXTURE_1D) {
      if (r->base.target == PIPE_TEXTURE_1D_ARRAY)
         z = y;
      y = 0;
   }
   p = r->data + r->level_offset[level] + (size_t)z * r->img_stride[level] +
       (size_t)(y / (int)v->bh) * r->stride[level] + (size_t)(x / (int)v->bw) * v->bsize;

   if (v->zs) {
      float depth;
      util_format_unpack_z_float(v->base.format, &depth, p, 1);
      if (S->compare) {
         bool pass;
         switch (S->ss->compare_func) {
         case PIPE_FUNC_NEVER: pass = false; break;
         case PIPE_FUNC_LESS: pass = ref < depth; break;
         case PIPE_FUNC_EQUAL: pass = ref == depth; break;
         case PIPE_FUNC_LEQUAL: pass = ref <= depth; break;
         case PIPE_FUNC_GREATER: pass = ref > depth; break;
         case PIPE_FUNC_NOTEQUAL: pass = ref != depth; break;
         case PIPE_FUNC_GEQUAL: pass = ref >= depth; break;
         default: pass = true; break;
         }
         depth = pass ? 1.0f : 0.0f;
      }
      out[0] = out[1] = out[2] = depth;
      out[3] = 1.0f;
   } else if (v->fetch) {
      ((util_format_fetch_rgba_func_ptr)v->fetch)(out, p, x % v->bw, y % v->bh);
   } else {
      out[0] = out[1] = out[2] = 0.0f;
      out[3] = 1.0f;
   }
}

static int fp_mod(int a, int b)
{
   int m = a % b;
   return m < 0 ? m + b : m;
}

/* GL's mirror(): the coordinate folded into [0, 1]. */
static float fp_mirror(float s)
{
   float f = floorf(s);
   float fr = s - f;
   return ((int)f & 1) ? 1.0f - fr : fr;
}

/* Nearest texel index for coordinate u (in texels) along an axis of
 * `size`; -1 means the border colour. */
static int fp_wrap_nearest(unsigned wrap, float s, int size, bool unnorm)
{
   float u = unnorm ? s : s * size;
   switch (wrap) {
   case PIPE_TEX_WRAP_REPEAT:
      return fp_mod((int)floorf(u), size);
   case PIPE_TEX_WRAP_CLAMP_TO_BORDER: {
      int i = (int)floorf(u);
      return (i < 0 || i >= size) ? -1 : i;
   }
   case PIPE_TEX_WRAP_MIRROR_REPEAT:
      if (unnorm)
         return CLAMP((int)floorf(u), 0, size - 1);
      return MIN2((int)floorf(fp_mirror(s) * size), size - 1);
   case PIPE_TEX_WRAP_MIRROR_CLAMP:
   case PIPE_TEX_WRAP_MIRROR_CLAMP_TO_EDGE:
      return CLAMP((int)floorf(fabsf(u)), 0, size - 1);
   case PIPE_TEX_WRAP_MIRROR_CLAMP_TO_BORDER: {
      int i = (int)floorf(fabsf(u));
      return i >= size ? -1 : i;
   }
   case PIPE_TEX_WRAP_CLAMP:
   case PIPE_TEX_WRAP_CLAMP_TO_EDGE:
   default:
      return CLAMP((int)floorf(u), 0, size - 1);
   }
}

/* The two texels and the weight of the second for linear filtering. */
static void fp_wrap_linear(unsigned wrap, float s, int size, bool unnorm,
                           int *i0, int *i1, float *w)
{
   float u;
   switch (wrap) {
   case PIPE_TEX_WRAP_REPEAT:
      u = (unnorm ? s : s * size) - 0.5f;
      *i0 = (int)floorf(u);
      *w = u - *i0;
      *i1 = fp_mod(*i0 + 1, size);
      *i0 = fp_mod(*i0, size);
      return;
   case PIPE_TEX_WRAP_MIRROR_REPEAT:
      u = (unnorm ? s : fp_mirror(s) * size) - 0.5f;
      *i0 = (int)floorf(u);
      *w = u - *i0;
      *i1 = MIN2(*i0 + 1, size - 1);
      *i0 = MAX2(*i0, 0);
      return;
   case PIPE_TEX_WRAP_CLAMP:
      /* GL_CLAMP: clamp the coordinate, then blend with the border. */
      u = (unnorm ? CLAMP(s, 0.0f, (float)size) : CLAMP(s, 0.0f, 1.0f) * size) - 0.5f;
      *i0 = (int)floorf(u);
      *w = u - *i0;
      *i1 = *i0 + 1 >= size ? -1 : *i0 + 1;
      *i0 = *i0 < 0 ? -1 : *i0;
      return;
   case PIPE_TEX_WRAP_CLAMP_TO_BORDER:
      u = (unnorm ? s : s * size) - 0.5f;
      *i0 = (int)floorf(u);
      *w = u - *i0;
      *i1 = (*i0 + 1 < 0 || *i0 + 1 >= size) ? -1 : *i0 + 1;
      *i0 = (*i0 < 0 || *i0 >= size) ? -1 : *i0;
      return;
   case PIPE_TEX_WRAP_MIRROR_CLAMP:
   case PIPE_TEX_WRAP_MIRROR_CLAMP_TO_BORDER:
      /* Mirrored GL_CLAMP / CLAMP_TO_BORDER: taps outside the image,
       * at either end, take the border colour. */
      u = fabsf(unnorm ? s : s * size);
      if (wrap == PIPE_TEX_WRAP_MIRROR_CLAMP)
         u = MIN2(u, (float)size);
      u -= 0.5f;
      *i0 = (int)floorf(u);
      *w = u - *i0;
      *i1 = *i0 + 1 >= size ? -1 : *i0 + 1;
      *i0 = (*i0 < 0 || *i0 >= size) ? -1 : *i0;
      return;
   case PIPE_TEX_WRAP_MIRROR_CLAMP_TO_EDGE:
      u = fabsf(unnorm ? s : s * size) - 0.5f;
      break;
   case PIPE_TEX_WRAP_CLAMP_TO_EDGE:
   default:
      u = (unnorm ? s : s * size) - 0.5f;
      break;
   }
   *i0 = (int)floorf(u);
   *w = u - *i0;
   *i1 = CLAMP(*i0 + 1, 0, size - 1);
   *i0 = CLAMP(*i0, 0, size - 1);
}

static void fp_texel_or_border(const struct fp_samp *S, unsigned level, int x, int y, int z,
                               float ref, float out[4])
{
   if (x < 0 || y < 0 || z < 0) {
      if (S->compare) {
         /* The border's depth goes through the comparison too. */
         float d = S->border[0];
         bool pass;
         switch (S->ss->compare_func) {
         case PIPE_FUNC_NEVER: pass = false; break;
         case PIPE_FUNC_LESS: pass = ref < d; break;
         case PIPE_FUNC_EQUAL: pass = ref == d; break;
         case PIPE_FUNC_LEQUAL: pass = ref <= d; break;
         case PIPE_FUNC_GREATER: pass = ref > d; break;
         case PIPE_FUNC_NOTEQUAL: pass = ref != d; break;
         case PIPE_FUNC_GEQUAL: pass = ref >= d; break;
         default: pass = true; break;
         }
         out[0] = out[1] = out[2] = pass ? 1.0f : 0.0f;
         out[3] = 1.0f;
      } else {
         memcpy(out, S->border, 4 * sizeof(float));
      }
      return;
   }
   fp_texel(S, level, x, y, z, ref, out);
}

static void fp_lerp4(float out[4], const float a[4], const float b[4], float w)
{
   for (unsigned c = 0; c < 4; c++)
      out[c] = a[c] + w * (b[c] - a[c]);
}

/* Filter one level.  dims: 1, 2 or 3 filtered axes; `layer` is the array
 * layer or cube face image for non-3D targets. */
static void fp_sample_level(const struct fp_samp *S, unsigned level, unsigned filter,
                            unsigned dims, const float coord[3], int layer,
                            const int8_t offset[3], float ref, float out[4])
{
   const struct pipe_sampler_state *ss = S->ss;
   const bool unnorm = ss->unnormalized_coords;
   int w, h, d;
   fp_level_size(S, level, &w, &h, &d);
   const int size[3] = { w, h, d };
   const unsigned wrap[3] = { ss->wrap_s, ss->wrap_t, ss->wrap_r };
   float c[3];
   for (unsigned a = 0; a < dims; a++) {
      c[a] = coord[a];
      if (offset && offset[a])
         c[a] += unnorm ? offset[a] : (float)offset[a] / size[a];
   }

   if (filter == PIPE_TEX_FILTER_NEAREST) {
      int i[3] = { 0, 0, layer };
      for (unsigned a = 0; a < dims; a++)
         i[a] = fp_wrap_nearest(wrap[a], c[a], size[a], unnorm);
      fp_texel_or_border(S, level, i[0], i[1], i[2], ref, out);
      return;
   }

   int i0[3] = { 0, 0, layer }, i1[3] = { 0, 0, layer };
   float wt[3] = { 0, 0, 0 };
   for (unsigned a = 0; a < dims; a++)
      fp_wrap_linear(wrap[a], c[a], size[a], unnorm, &i0[a], &i1[a], &wt[a]);

   float t[8][4];
   unsigned n = 1u << dims;
   for (unsigned k = 0; k < n; k++) {
      int x = (k & 1) ? i1[0] : i0[0];
      int y = dims > 1 ? ((k & 2) ? i1[1] : i0[1]) : 0;
      int z = dims > 2 ? ((k & 4) ? i1[2] : i0[2]) : layer;
      fp_texel_or_border(S, level, x, y, z, ref, t[k]);
   }
   if (dims == 1) {
      fp_lerp4(out, t[0], t[1], wt[0]);
   } else {
      float a[4], b[4];
      fp_lerp4(a, t[0], t[1], wt[0]);
      fp_lerp4(b, t[2], t[3], wt[0]);
      fp_lerp4(out, a, b, wt[1]);
      if (dims == 3) {
         float e[4], f[4], g[4];
         fp_lerp4(e, t[4], t[5], wt[0]);
         fp_lerp4(f, t[6], t[7], wt[0]);
         fp_lerp4(g, e, f, wt[1]);
         fp_lerp4(out, out, g, wt[2]);
      }
   }
}

/* The [0,1] coordinates of direction r projected on cube face `face`
 * (GL table 8.19), whether or not that face is r's major axis. */
static void fp_cube_on_face(unsigned face, float rx, float ry, float rz, float *s, float *t)
{
   float sc, tc, ma;
   switch (face) {
   case 0: ma = rx; sc = -rz; tc = -ry; break;
   case 1: ma = -rx; sc = rz; tc = -ry; break;
   case 2: ma = ry; sc = rx; tc = rz; break;
   case 3: ma = -ry; sc = rx; tc = -rz; break;
   case 4: ma = rz; sc = rx; tc = -ry; break;
   default: ma = -rz; sc = -rx; tc = -ry; break;
   }
   ma = fabsf(ma);
   if (ma == 0.0f)
      ma = 1.0f;
   *s = 0.5f * (sc / ma + 1.0f);
   *t = 0.5f * (tc / ma + 1.0f);
}

/* Cube: the face of the major axis and the coordinates on it. */
static unsigned fp_cube_face(float rx, float ry, float rz, float *s, float *t)
{
   float ax = fabsf(rx), ay = fabsf(ry), az = fabsf(rz);
   unsigned face;
   if (ax >= ay && ax >= az)
      face = rx >= 0 ? 0 : 1;
   else if (ay >= az)
      face = ry >= 0 ? 2 : 3;
   else
      face = rz >= 0 ? 4 : 5;
   fp_cube_on_face(face, rx, ry, rz, s, t);
   return face;
}

static float fp_rho_to_lod(float rho)
{
   return rho > 0.0f ? log2f(rho) : -1000.0f;
}

/* rho from d(coord)/dx and d(coord)/dy in texels: GL's scale factor. */
static float fp_lod_from_derivs(const float ddx[3], const float ddy[3])
{
   float lx = sqrtf(ddx[0] * ddx[0] + ddx[1] * ddx[1] + ddx[2] * ddx[2]);
   float ly = sqrtf(ddy[0] * ddy[0] + ddy[1] * ddy[1] + ddy[2] * ddy[2]);
   return fp_rho_to_lod(MAX2(lx, ly));
}

/* The view's swizzle, from [pixel][chan] to tgsi's [chan][pixel]. */
static void fp_swizzle(const struct pipe_sampler_view *v, float out[TGSI_QUAD_SIZE][4],
                       float rgba[TGSI_NUM_CHANNELS][TGSI_QUAD_SIZE])
{
   const unsigned char swz[4] = { v->swizzle_r, v->swizzle_g, v->swizzle_b, v->swizzle_a };
   for (unsigned c = 0; c < 4; c++) {
      for (unsigned p = 0; p < TGSI_QUAD_SIZE; p++) {
         switch (swz[c]) {
         case PIPE_SWIZZLE_X: case PIPE_SWIZZLE_Y: case PIPE_SWIZZLE_Z: case PIPE_SWIZZLE_W:
            rgba[c][p] = out[p][swz[c]];
            break;
         case PIPE_SWIZZLE_1:
            rgba[c][p] = 1.0f;
            break;
         default:
            rgba[c][p] = 0.0f;
            break;
         }
      }
   }
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
   struct fp_context *fp = ts->fp;
   struct fp_samp S;
   float out[TGSI_QUAD_SIZE][4];

   memset(rgba, 0, sizeof(float) * TGSI_NUM_CHANNELS * TGSI_QUAD_SIZE);
   if (sview_index >= PIPE_MAX_SHADER_SAMPLER_VIEWS || sampler_index >= PIPE_MAX_SAMPLERS)
      return;
   S.view = (const struct fp_sampler_view *)fp->sampler_views[ts->stage][sview_index];
   S.ss = fp->samplers[ts->stage][sampler_index];
   if (!S.view || !S.ss || !S.view->base.texture || !fp_resource(S.view->base.texture)->data)
      return;
   S.res = fp_resource(S.view->base.texture);
   S.compare = S.ss->compare_mode != PIPE_TEX_COMPARE_NONE && S.view->zs;
   for (unsigned c = 0; c < 4; c++) {
      float b = S.ss->border_color.f[c];
      if (S.view->is_unorm || S.view->zs)
         b = CLAMP(b, 0.0f, 1.0f);
      else if (S.view->is_snorm)
         b = CLAMP(b, -1.0f, 1.0f);
      S.border[c] = b;
   }

   const struct pipe_sampler_view *v = &S.view->base;
   const enum pipe_texture_target target = v->target;
   const unsigned first = v->u.tex.first_level;
   const unsigned last = MAX2(v->u.tex.last_level, first);
   int bw, bh, bd;
   fp_level_size(&S, first, &bw, &bh, &bd);

   /* Per-pixel filtered coordinates, the layer, the compare value. */
   float coord[TGSI_QUAD_SIZE][3];
   int layer[TGSI_QUAD_SIZE];
   float ref[TGSI_QUAD_SIZE];
   unsigned dims;
   bool cube = target == PIPE_TEXTURE_CUBE;
   for (unsigned p = 0; p < TGSI_QUAD_SIZE; p++) {
      layer[p] = 0;
      coord[p][0] = s[p];
      coord[p][1] = t[p];
      coord[p][2] = r[p];
      ref[p] = r[p];
   }
   switch (target) {
   case PIPE_TEXTURE_1D:
      dims = 1;
      break;
   case PIPE_TEXTURE_1D_ARRAY:
      dims = 1;
      for (unsigned p = 0; p < TGSI_QUAD_SIZE; p++)
         layer[p] = CLAMP((int)lrintf(t[p]), 0, (int)(v->u.tex.last_layer - v->u.tex.first_layer));
      break;
   case PIPE_TEXTURE_2D_ARRAY:
      dims = 2;
      for (unsigned p = 0; p < TGSI_QUAD_SIZE; p++) {
         layer[p] = CLAMP((int)lrintf(r[p]), 0, (int)(v->u.tex.last_layer - v->u.tex.first_layer));
         ref[p] = c0[p];
      }
      break;
   case PIPE_TEXTURE_3D:
      dims = 3;
      break;
   case PIPE_TEXTURE_CUBE:
      dims = 2;
      for (unsigned p = 0; p < TGSI_QUAD_SIZE; p++) {
         float fs, ft;
         layer[p] = fp_cube_face(s[p], t[p], r[p], &fs, &ft);
         coord[p][0] = fs;
         coord[p][1] = ft;
         ref[p] = c0[p];
      }
      break;
   default:   /* 2D, RECT */
      dims = 2;
      break;
   }
   for (unsigned p = 0; p < TGSI_QUAD_SIZE; p++) {
      layer[p] += target == PIPE_TEXTURE_3D ? 0 : (int)v->u.tex.first_layer;
      if (S.compare && util_format_is_depth_or_stencil(v->format) &&
          v->format != PIPE_FORMAT_Z32_FLOAT && v->format != PIPE_FORMAT_Z32_FLOAT_S8X24_UINT)
         ref[p] = CLAMP(ref[p], 0.0f, 1.0f);
   }

   /* LOD, relative to the view's first level. */
   float lod[TGSI_QUAD_SIZE];
   const float size[3] = { (float)bw, (float)bh, (float)bd };
   const bool unnorm = S.ss->unnormalized_coords;
   if (control == TGSI_SAMPLER_LOD_NONE || control == TGSI_SAMPLER_LOD_BIAS) {
      float ddx[3] = { 0, 0, 0 }, ddy[3] = { 0, 0, 0 };
      if (cube) {
         /* Differences of all pixels projected on pixel 0's face, so that
          * a quad straddling a cube edge still gets one smooth LOD. */
         float cs[3], ct[3];
         for (unsigned p = 0; p < 3; p++)
            fp_cube_on_face((unsigned)(layer[0] - (int)v->u.tex.first_layer) % 6,
                            s[p], t[p], r[p], &cs[p], &ct[p]);
         ddx[0] = (cs[1] - cs[0]) * size[0];
         ddx[1] = (ct[1] - ct[0]) * size[1];
         ddy[0] = (cs[2] - cs[0]) * size[0];
         ddy[1] = (ct[2] - ct[0]) * size[1];
      } else {
         for (unsigned a = 0; a < dims; a++) {
            float sc = unnorm ? 1.0f : size[a];
            ddx[a] = (coord[1][a] - coord[0][a]) * sc;
            ddy[a] = (coord[2][a] - coord[0][a]) * sc;
         }
      }
      float l = fp_lod_from_derivs(ddx, ddy) + S.ss->lod_bias;
      for (unsigned p = 0; p < TGSI_QUAD_SIZE; p++)
         lod[p] = l + (control == TGSI_SAMPLER_LOD_BIAS ? c1[p] : 0.0f);
   } else if (control == TGSI_SAMPLER_DERIVS_EXPLICIT) {
      for (unsigned p = 0; p < TGSI_QUAD_SIZE; p++) {
         float ddx[3] = { 0, 0, 0 }, ddy[3] = { 0, 0, 0 };
         for (unsigned a = 0; a < (cube ? 3 : dims); a++) {
            float sc = cube ? size[0] * 0.5f : unnorm ? 1.0f : size[a];
            ddx[a] = derivs[a][0][p] * sc;
            ddy[a] = derivs[a][1][p] * sc;
         }
         lod[p] = fp_lod_from_derivs(ddx, ddy) + S.ss->lod_bias;
      }
   } else if (control == TGSI_SAMPLER_LOD_EXPLICIT) {
      for (unsigned p = 0; p < TGSI_QUAD_SIZE; p++)
         lod[p] = c1[p] + S.ss->lod_bias;
   } else {
      for (unsigned p = 0; p < TGSI_QUAD_SIZE; p++)
         lod[p] = S.ss->lod_bias;
   }

   const float max_rel = (float)(last - first);
   for (unsigned p = 0; p < TGSI_QUAD_SIZE; p++) {
      float l = CLAMP(lod[p], S.ss->min_lod, S.ss->max_lod);
      const bool minify = l > 0.0f;
      const unsigned filter = minify ? S.ss->min_img_filter : S.ss->mag_img_filter;
      const int8_t *offs = offset;
      if (!minify || S.ss->min_mip_filter == PIPE_TEX_MIPFILTER_NONE || unnorm) {
         fp_sample_level(&S, first, filter, dims, coord[p], layer[p], offs, ref[p], out[p]);
      } else if (S.ss->min_mip_filter == PIPE_TEX_MIPFILTER_NEAREST) {
         /* GL: level ceil(lod + 0.5) - 1, i.e. lod rounded half down. */
         int lev = (int)ceilf(l + 0.5f) - 1;
         lev = CLAMP(lev, 0, (int)max_rel);
         fp_sample_level(&S, first + lev, filter, dims, coord[p], layer[p], offs, ref[p],
                         out[p]);
      } else {
         float lc = CLAMP(l, 0.0f, max_rel);
         int l0 = (int)floorf(lc);
         float fr = lc - l0;
         fp_sample_level(&S, first + l0, filter, dims, coord[p], layer[p], offs, ref[p],
                         out[p]);
         if (fr > 0.0f && l0 + 1 <= (int)max_rel) {
            float b[4];
            fp_sample_level(&S, first + l0 + 1, filter, dims, coord[p], layer[p], offs,
                            ref[p], b);
            fp_lerp4(out[p], out[p], b, fr);
         }
      }
   }

   fp_swizzle(v, out, rgba);
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

static void fp_tgsi_get_texel(struct tgsi_sampler *tgsi_sampler, const unsigned sview_index,
                              const int i[TGSI_QUAD_SIZE], const int j[TGSI_QUAD_SIZE],
                              const int k[TGSI_QUAD_SIZE], const int lod[TGSI_QUAD_SIZE],
                              const int8_t offset[3], float rgba[TGSI_NUM_CHANNELS][TGSI_QUAD_SIZE])
{
   struct fp_tgsi_sampler *ts = (struct fp_tgsi_sampler *)tgsi_sampler;
   struct fp_samp S;
   memset(rgba, 0, sizeof(float) * TGSI_NUM_CHANNELS * TGSI_QUAD_SIZE);
   if (sview_index >= PIPE_MAX_SHADER_SAMPLER_VIEWS)
      return;
   S.view = (const struct fp_sampler_view *)ts->fp->sampler_views[ts->stage][sview_index];
   if (!S.view || !S.view->base.texture || !fp_resource(S.view->base.texture)->data)
      return;
   S.res = fp_resource(S.view->base.texture);
   S.ss = NULL;
   S.compare = false;
   const struct pipe_sampler_view *v = &S.view->base;
   float texels[TGSI_QUAD_SIZE][4];
   memset(texels, 0, sizeof(texels));

   for (unsigned p = 0; p < TGSI_QUAD_SIZE; p++) {
      int level = (int)v->u.tex.first_level + lod[p];
      if (lod[p] < 0 || level > (int)v->u.tex.last_level)
         continue;
      int w, h, d;
      fp_level_size(&S, level, &w, &h, &d);
      int x = i[p] + offset[0], y = j[p] + offset[1], z = k[p] + offset[2];
      int layers = v->u.tex.last_layer - v->u.tex.first_layer + 1;
      bool in;
      switch (v->target) {
      case PIPE_TEXTURE_1D:
         in = x >= 0 && x < w; y = 0; z = 0;
         break;
      case PIPE_TEXTURE_1D_ARRAY:
         in = x >= 0 && x < w && j[p] >= 0 && j[p] < layers;
         y = j[p] + v->u.tex.first_layer; z = 0;
         break;
      case PIPE_TEXTURE_2D_ARRAY:
         in = x >= 0 && x < w && y >= 0 && y < h && k[p] >= 0 && k[p] < layers;
         z = k[p] + v->u.tex.first_layer;
         break;
      case PIPE_TEXTURE_3D:
         in = x >= 0 && x < w && y >= 0 && y < h && z >= 0 && z < d;
         break;
      default:
         in = x >= 0 && x < w && y >= 0 && y < h;
         z = v->u.tex.first_layer;
         break;
      }
      if (!in)
         continue;
      fp_texel(&S, level, x, y, z, 0.0f, texels[p]);
   }
   fp_swizzle(v, texels, rgba);
}

struct fp_tgsi_sampler *fp_tgsi_sampler_create(struct fp_context *fp,
                                               enum pipe_shader_type stage)
{
   struct fp_tgsi_sampler *s = CALLOC_STRUCT(fp_tgsi_sampler);
   if (!s)
      return NULL;
   s->fp = fp;
   s->stage = stage;
   s->base.get_samples = fp_tgsi_get_samples;
   s->base.get_dims = fp_tgsi_get_dims;
   s->base.get_texel = fp_tgsi_get_texel;
   return s;
}
