/*
 * Gather (GL ES 3.1 textureGather): one channel of each of the four texels
 * a bilinear tap of the view's base level reads, unfiltered.  The address
 * unit is the LINEAR filter's (the sampler's wrap modes, the number
 * system's coordinates and texel offset), so a gather returns exactly the
 * texels the filter would have blended, and a depth view compares each of
 * them with the reference as the filter's taps do.  A seamless cube map's
 * footprint crosses its face's edges as the filter's does (tex_cube_taps).
 * This is the table path; 2-D views take tex_fast.c's specialised copy,
 * its address stage (u->footprint) apart from its texel reads, unless
 * FIXPIPE_DEBUG=scalar.
 */
#include "rast/tex/tex_priv.h"

/* One channel of a texel as the swizzle gives it. */
static inline float channel(const struct tex_unit *u, const float t[4], unsigned comp)
{
   const unsigned s = u->view.swizzle[comp & 3];
   return s < 4 ? t[s] : s == TEX_SWZ_1 ? tex_one(&u->view) : 0.0f;
}

void tex_unit_gather(const struct tex_unit *u, const struct tex_quad *q, unsigned comp,
                     float rgba[4][TEX_QUAD])
{
   struct tex_footprint f;
   if (tex_unit_gather_footprint(u, q, &f))
      tex_unit_gather_read(u, &f, q->ref, comp, rgba);
   else
      tex_unit_gather_generic(u, q, comp, rgba);
}

bool tex_unit_gather_footprint(const struct tex_unit *u, const struct tex_quad *q,
                               struct tex_footprint *f)
{
   if (!u->footprint)
      return false;
   u->footprint(u, q, f);
   return true;
}

void tex_unit_gather_generic(const struct tex_unit *u, const struct tex_quad *q, unsigned comp,
                             float rgba[4][TEX_QUAD])
{
   const struct tex_level *lv = &u->view.level[0];
   const bool cube = tex_is_cube(u->view.target);
   const bool array = u->view.target == TEX_TARGET_2D_ARRAY;
   /* a depth view's taps give the comparison in every colour channel */
   if (u->samp.compare)
      comp = 0;
   for (unsigned p = 0; p < TEX_QUAD; p++) {
      ns_val s, t;
      int layer = 0;
      if (cube) {
         layer = (int)tex_cube_face(u, tex_nsf(u, q->s[p]), tex_nsf(u, q->t[p]), tex_nsf(u, q->r[p]), &s, &t) +
                 tex_cube_base_of(u, q->layer[p]);
      } else {
         s = tex_nsf(u, q->s[p]);
         t = tex_nsf(u, q->t[p]);
         if (array)
            layer = tex_layer_of(u, q->layer[p]);
      }
      struct tex_addr A, B;
      u->addr[TEX_FILTER_LINEAR][0](u, &u->axis[0][0], s, &A);
      u->addr[TEX_FILTER_LINEAR][1](u, &u->axis[0][1], t, &B);
      /* GL orders the footprint by the coordinate before the wrap */
      if (tex_addr_mirrored(u, 0, s)) {
         const int32_t i = A.i0;
         A.i0 = A.i1;
         A.i1 = i;
      }
      if (tex_addr_mirrored(u, 1, t)) {
         const int32_t j = B.i0;
         B.i0 = B.i1;
         B.i1 = j;
      }
      /* the footprint (x0, y0), (x1, y0), (x0, y1), (x1, y1), a seamless
       * cube's across its face's edges */
      float taps[4][4];
      const int32_t x[2] = { A.i0, A.i1 }, y[2] = { B.i0, B.i1 };
      if (cube && u->samp.seamless_cube) {
         tex_cube_taps(u, 0, x, y, layer, q->ref[p], taps);
      } else {
         for (unsigned k = 0; k < 4; k++)
            u->tap(u, lv, x[k & 1], y[k >> 1], layer, q->ref[p], taps[k]);
      }
      /* GL's order: (i0, j1), (i1, j1), (i1, j0), (i0, j0) */
      static const unsigned order[4] = { 2, 3, 1, 0 };
      for (unsigned k = 0; k < 4; k++)
         rgba[k][p] = u->samp.compare ? taps[order[k]][0] : channel(u, taps[order[k]], comp);
   }
}
