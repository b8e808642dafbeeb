/*
 * The unit's quad: coordinates into the number system, cube face
 * selection, LOD per quad (implicit) or per pixel (explicit), level
 * selection, filtering, swizzle.
 */
#include <math.h>
#include <string.h>
#include "rast/tex/tex_priv.h"

static inline ns_val neg(const struct tex_unit *u, ns_val a)
{
   return u->ns->sub(u->ns, u->k_zero, a, u->stats);
}

/* GL's table: the face's (sc, tc, ma) of a vector, signed.  Linear, so it
 * maps a direction's derivatives as well as the direction. */
static void cube_axes(const struct tex_unit *u, unsigned face, ns_val rx, ns_val ry, ns_val rz,
                      ns_val *sc, ns_val *tc, ns_val *ma)
{
   switch (face) {
   case 0: *ma = rx; *sc = neg(u, rz); *tc = neg(u, ry); break;
   case 1: *ma = rx; *sc = rz; *tc = neg(u, ry); break;
   case 2: *ma = ry; *sc = rx; *tc = rz; break;
   case 3: *ma = ry; *sc = rx; *tc = neg(u, rz); break;
   case 4: *ma = rz; *sc = rx; *tc = neg(u, ry); break;
   default: *ma = rz; *sc = neg(u, rx); *tc = neg(u, ry); break;
   }
}

/* s = (sc / |ma| + 1) / 2. */
void tex_cube_on_face(const struct tex_unit *u, unsigned face, ns_val rx, ns_val ry, ns_val rz,
                      ns_val *s, ns_val *t)
{
   ns_val sc, tc, ma;
   cube_axes(u, face, rx, ry, rz, &sc, &tc, &ma);
   ma = tex_ns_abs(u->kind, ma);
   if (tex_ns_cmp(u->kind, ma, u->k_zero) == 0) {
      *s = *t = u->k_half;
      return;
   }
   const struct numsys *ns = u->ns;
   ns_val k = ns->mul(ns, ns->recip(ns, ma, u->stats), u->k_half, u->stats);
   *s = ns->add(ns, ns->mul(ns, sc, k, u->stats), u->k_half, u->stats);
   *t = ns->add(ns, ns->mul(ns, tc, k, u->stats), u->k_half, u->stats);
}

/* Cube LOD of one pixel: the direction's derivatives gx, gy projected onto
 * the pixel's face by differentiating s = (sc/|ma| + 1)/2,
 *
 *   ds = (dsc - sc * d|ma| / |ma|) / (2 |ma|)      (dt likewise with tc)
 *
 * as llvmpipe does (lp_build_cube_lookup), then the 2D LOD on the face's
 * size.  softpipe's "derivative times size/2" is this for |ma| = 1 and
 * d|ma| = 0 only: a level off wherever the direction is not unit length or
 * moves along the major axis.  A zero direction samples the face centre:
 * no LOD. */
static int32_t cube_lod_grads(const struct tex_unit *u, unsigned face, const ns_val dir[3],
                              const ns_val gx[3], const ns_val gy[3])
{
   const struct numsys *ns = u->ns;
   ns_val sc, tc, ma;
   cube_axes(u, face, dir[0], dir[1], dir[2], &sc, &tc, &ma);
   const bool flip = tex_ns_neg(u->kind, ma);   /* d|ma| = -dma */
   ma = tex_ns_abs(u->kind, ma);
   if (tex_ns_cmp(u->kind, ma, u->k_zero) == 0)
      return TEX_LOD_NONE;
   const ns_val r = ns->recip(ns, ma, u->stats);
   const ns_val k = ns->mul(ns, r, u->k_half, u->stats);
   ns_val d[2][3];   /* [x, y][s, t] */
   for (unsigned xy = 0; xy < 2; xy++) {
      const ns_val *g = xy ? gy : gx;
      ns_val dsc, dtc, dma;
      cube_axes(u, face, g[0], g[1], g[2], &dsc, &dtc, &dma);
      if (flip)
         dma = neg(u, dma);
      const ns_val q = ns->mul(ns, dma, r, u->stats);   /* d|ma| / |ma| */
      d[xy][0] = ns->mul(ns, ns->sub(ns, dsc, ns->mul(ns, sc, q, u->stats), u->stats), k,
                         u->stats);
      d[xy][1] = ns->mul(ns, ns->sub(ns, dtc, ns->mul(ns, tc, q, u->stats), u->stats), k,
                         u->stats);
      d[xy][2] = u->k_zero;
   }
   const ns_val scale[3] = { u->axis[0][0].scale, u->axis[0][1].scale, u->k_zero };
   return tex_lod_grads(u, d[0], d[1], 2, scale);
}

/* The major axis; ties go to x, then y (GL leaves them open). */
unsigned tex_cube_face(const struct tex_unit *u, ns_val rx, ns_val ry, ns_val rz,
                       ns_val *s, ns_val *t)
{
   const int k = u->kind;
   ns_val ax = tex_ns_abs(k, rx), ay = tex_ns_abs(k, ry), az = tex_ns_abs(k, rz);
   unsigned face;
   if (tex_ns_cmp(k, ax, ay) >= 0 && tex_ns_cmp(k, ax, az) >= 0)
      face = tex_ns_neg(k, rx) ? 1 : 0;
   else if (tex_ns_cmp(k, ay, az) >= 0)
      face = tex_ns_neg(k, ry) ? 3 : 2;
   else
      face = tex_ns_neg(k, rz) ? 5 : 4;
   tex_cube_on_face(u, face, rx, ry, rz, s, t);
   return face;
}


/* Implicit LOD of a cube quad, per pixel: the quad's direction differences
 * (numsys sub) projected onto each pixel's own face, exactly as explicit
 * derivatives are (cube_lod_grads).  Direction differences are smooth
 * across cube edges, unlike differences of face coordinates, so a quad on a
 * face's edge needs no special case (piglit cubemap npot).  The pixel pairs
 * are those of the shader's coarse derivatives (tgsi_exec: x from pixel 2
 * to 3, y from 0 to 2), so that textureCube and textureCubeGrad(dFdx, dFdy)
 * choose the same level (piglit arb_shader_texture_lod-texgradcube: quads
 * astride the horizon differ by a level between the two rows). */
static void cube_lod(const struct tex_unit *u, const int face[TEX_QUAD],
                     ns_val dir[TEX_QUAD][3], int32_t lod[TEX_QUAD])
{
   ns_val gx[3], gy[3];
   for (unsigned a = 0; a < 3; a++) {
      gx[a] = u->ns->sub(u->ns, dir[3][a], dir[2][a], u->stats);
      gy[a] = u->ns->sub(u->ns, dir[2][a], dir[0][a], u->stats);
   }
   for (unsigned p = 0; p < TEX_QUAD; p++)
      lod[p] = cube_lod_grads(u, (unsigned)face[p], dir[p], gx, gy);
}

/* A cube quad's LOD is per pixel: pixel 0's here. */
int32_t tex_lod_quad(const struct tex_unit *u, const struct tex_quad *q)
{
   ns_val c[TEX_QUAD][3];
   for (unsigned p = 0; p < TEX_QUAD; p++) {
      c[p][0] = tex_nsf(u, q->s[p]);
      c[p][1] = tex_nsf(u, q->t[p]);
      c[p][2] = tex_nsf(u, q->r[p]);
   }
   if (tex_is_cube(u->view.target)) {
      int face[TEX_QUAD];
      int32_t lod[TEX_QUAD];
      for (unsigned p = 0; p < TEX_QUAD; p++) {
         ns_val s, t;
         face[p] = (int)tex_cube_face(u, c[p][0], c[p][1], c[p][2], &s, &t);
      }
      cube_lod(u, face, c, lod);
      return lod[0];
   }
   return tex_lod_diffs(u, c, u->dims);
}

void tex_unit_sample(const struct tex_unit *u, const struct tex_quad *q,
                     enum tex_lod_control ctl, float rgba[4][TEX_QUAD])
{
   if (u->quad)
      u->quad(u, q, ctl, rgba);
   else
      tex_unit_sample_generic(u, q, ctl, rgba);
}

void tex_unit_sample2(const struct tex_unit *u, const struct tex_quad q[2],
                      enum tex_lod_control ctl, float rgba[2][4][TEX_QUAD])
{
   if (u->quad2) {
      u->quad2(u, q, ctl, rgba);
      return;
   }
   tex_unit_sample(u, &q[0], ctl, rgba[0]);
   tex_unit_sample(u, &q[1], ctl, rgba[1]);
}

void tex_unit_sample_quads(const struct tex_unit *u, const struct tex_quad *q, unsigned n,
                           enum tex_lod_control ctl, float rgba[][4][TEX_QUAD])
{
   if (n == 4 && u->quad4) {
      u->quad4(u, q, ctl, rgba);
      return;
   }
   unsigned i = 0;
   for (; i + 2 <= n; i += 2)
      tex_unit_sample2(u, &q[i], ctl, &rgba[i]);
   if (i < n)
      tex_unit_sample(u, &q[i], ctl, rgba[i]);
}

/* The coordinate registers at `level` moved by `offset` texels of that
 * level: offset / size, a constant the number system holds exactly for
 * every power-of-two size (loaded, not computed: no range event). */
static void offset_at(const struct tex_unit *u, unsigned level, const int8_t offset[3],
                      const ns_val c[3], ns_val out[3])
{
   struct ns_stats loads = { 0, 0 };
   for (unsigned a = 0; a < 3; a++) {
      out[a] = c[a];
      if (a >= u->dims || !offset[a])
         continue;
      const float k = u->samp.normalized ? (float)offset[a] / (float)u->axis[level][a].size
                                         : (float)offset[a];
      out[a] = u->ns->add(u->ns, c[a], u->ns->from_float(u->ns, k, &loads), u->stats);
   }
}

static void sample_generic(const struct tex_unit *u, const struct tex_quad *q,
                           enum tex_lod_control ctl, const int8_t *offset,
                           float rgba[4][TEX_QUAD]);

void tex_unit_sample_generic(const struct tex_unit *u, const struct tex_quad *q,
                             enum tex_lod_control ctl, float rgba[4][TEX_QUAD])
{
   sample_generic(u, q, ctl, NULL, rgba);
}

void tex_unit_sample_offset(const struct tex_unit *u, const struct tex_quad *q,
                            enum tex_lod_control ctl, const int8_t offset[3],
                            float rgba[4][TEX_QUAD])
{
   sample_generic(u, q, ctl, offset, rgba);
}

/* The table path's first stages, which a sample and a LOD query share:
 * the quad's coordinates into the number system (a cube's direction and
 * its face coordinates, the layer), then each pixel's LOD as the
 * requests' control asks, before the sampler's bias and clamps. */
struct generic_quad {
   ns_val c[TEX_QUAD][3], dir[TEX_QUAD][3];
   int layer[TEX_QUAD], face[TEX_QUAD];
   int32_t lod[TEX_QUAD];
};

static void generic_coords_lod(const struct tex_unit *u, const struct tex_quad *q,
                               enum tex_lod_control ctl, struct generic_quad *g)
{
   const bool cube = tex_is_cube(u->view.target);
   ns_val (*c)[3] = g->c, (*dir)[3] = g->dir;
   int *layer = g->layer, *face = g->face;
   int32_t *lod = g->lod;

   for (unsigned p = 0; p < TEX_QUAD; p++) {
      layer[p] = face[p] = 0;
      if (cube) {
         dir[p][0] = tex_nsf(u, q->s[p]);
         dir[p][1] = tex_nsf(u, q->t[p]);
         dir[p][2] = tex_nsf(u, q->r[p]);
         face[p] = (int)tex_cube_face(u, dir[p][0], dir[p][1], dir[p][2], &c[p][0], &c[p][1]);
         layer[p] = face[p] + tex_cube_base_of(u, q->layer[p]);
         continue;
      }
      c[p][0] = tex_nsf(u, q->s[p]);
      if (u->dims > 1)
         c[p][1] = tex_nsf(u, q->t[p]);
      if (u->dims > 2)
         c[p][2] = tex_nsf(u, q->r[p]);
      if (u->view.target == TEX_TARGET_1D_ARRAY || u->view.target == TEX_TARGET_2D_ARRAY)
         layer[p] = tex_layer_of(u, q->layer[p]);
   }

   switch (ctl) {
   case TEX_LOD_IMPLICIT:
   case TEX_LOD_BIAS: {
      if (cube) {
         cube_lod(u, face, dir, lod);
      } else {
         const int32_t l = tex_lod_diffs(u, c, u->dims);
         for (unsigned p = 0; p < TEX_QUAD; p++)
            lod[p] = l;
      }
      for (unsigned p = 0; p < TEX_QUAD; p++)
         if (ctl == TEX_LOD_BIAS && lod[p] != TEX_LOD_NONE)
            lod[p] += tex_lod_fixed(q->lod[p]);
      break;
   }
   case TEX_LOD_EXPLICIT:
      for (unsigned p = 0; p < TEX_QUAD; p++)
         lod[p] = tex_lod_fixed(q->lod[p]);
      break;
   case TEX_LOD_DERIVS:
      for (unsigned p = 0; p < TEX_QUAD; p++) {
         float dx[3], dy[3];
         ns_val gx[3], gy[3], scale[3];
         const unsigned n = cube ? 3 : u->dims;
         for (unsigned a = 0; a < n; a++) {
            dx[a] = q->ddx[a][p];
            dy[a] = q->ddy[a][p];
            gx[a] = tex_nsf(u, dx[a]);
            gy[a] = tex_nsf(u, dy[a]);
            scale[a] = u->axis[0][a].scale;
         }
         lod[p] = cube ? cube_lod_grads(u, (unsigned)face[p], dir[p], gx, gy)
                       : tex_lod_derivs(u, dx, dy, n, scale);
      }
      break;
   default:
      for (unsigned p = 0; p < TEX_QUAD; p++)
         lod[p] = 0;
      break;
   }
}

static void sample_generic(const struct tex_unit *u, const struct tex_quad *q,
                           enum tex_lod_control ctl, const int8_t *offset,
                           float rgba[4][TEX_QUAD])
{
   struct generic_quad g;
   float out[TEX_QUAD][4];
   generic_coords_lod(u, q, ctl, &g);
   const ns_val (*c)[3] = (const ns_val (*)[3])g.c;
   const int *layer = g.layer;
   const int32_t *lod = g.lod;

   for (unsigned p = 0; p < TEX_QUAD; p++) {
      unsigned l0, l1;
      uint32_t frac;
      enum tex_filter f;
      tex_unit_select(u, tex_clamp_lod(u, lod[p]), &l0, &l1, &frac, &f);
      ns_val co[3];
      if (offset)
         offset_at(u, l0, offset, c[p], co);
      u->sample_level[f](u, l0, offset ? co : c[p], layer[p], q->ref[p], out[p]);
      if (frac) {
         float b[4];
         if (offset)
            offset_at(u, l1, offset, c[p], co);
         u->sample_level[f](u, l1, offset ? co : c[p], layer[p], q->ref[p], b);
         u->mix_levels(out[p], out[p], b, frac);
      }
   }

   for (unsigned ch = 0; ch < 4; ch++) {
      const unsigned s = u->view.swizzle[ch];
      for (unsigned p = 0; p < TEX_QUAD; p++)
         rgba[ch][p] = s < 4 ? out[p][s] : s == TEX_SWZ_1 ? tex_one(&u->view) : 0.0f;
   }
}

void tex_unit_query_lod(const struct tex_unit *u, const struct tex_quad *q,
                        enum tex_lod_control ctl, float level[TEX_QUAD], float lod[TEX_QUAD])
{
   struct generic_quad g;
   generic_coords_lod(u, q, ctl, &g);
   for (unsigned p = 0; p < TEX_QUAD; p++) {
      /* the LOD register with the sampler's bias; log2(0) stays below any
       * value, as the unit's clamp treats it */
      lod[p] = g.lod[p] == TEX_LOD_NONE ? -INFINITY
                                       : (float)(g.lod[p] + u->lod_bias) / (float)TEX_LOD_ONE;
      unsigned l0, l1;
      uint32_t frac;
      enum tex_filter f;
      tex_unit_select(u, tex_clamp_lod(u, g.lod[p]), &l0, &l1, &frac, &f);
      level[p] = u->samp.mip == TEX_MIP_NONE ? 0.0f
                 : u->samp.mip == TEX_MIP_NEAREST
                    ? (float)l0
                    : (float)l0 + (float)frac / (float)TEX_LOD_ONE;
   }
}
