/*
 * Across a cube map's edges: which texel of which face a bilinear tap
 * beyond a face's edge reads when cube maps are seamless (GL ES 3.0,
 * 3.8.9.1; ARB_seamless_cube_map).  Integer wiring only: the address unit
 * has already turned the coordinate into texel indices.
 *
 * A texel (x, y) of face f of an N-texel level is the direction whose
 * major component is +-N and whose two others are S = 2x + 1 - N and
 * T = 2y + 1 - N (half-texel units; GL's face table maps them to sc, tc).
 * For x = -1 or x = N, |S| = N + 1 exceeds the major component: the tap
 * lies beyond the edge.  The texel across it is on the face of that
 * component's axis: that component becomes the new major +-N, the old
 * major moves half a texel inwards to +-(N - 1) (the new face's first row),
 * and GL's table gives the new face's indices.  Every value stays an
 * integer of the parity of N + 1, so the mapping is exact.
 */
#include "rast/tex/tex_priv.h"

/* GL's table (tex_sample.c's cube_axes) as integer axes: for each face,
 * which component (0 x, 1 y, 2 z) and sign sc, tc and the major axis take. */
struct face_axes {
   int8_t sc_axis, sc_sign, tc_axis, tc_sign, ma_axis, ma_sign;
};

static const struct face_axes faces[6] = {
   { 2, -1, 1, -1, 0, +1 },   /* +X: sc = -rz, tc = -ry */
   { 2, +1, 1, -1, 0, -1 },   /* -X: sc = +rz, tc = -ry */
   { 0, +1, 2, +1, 1, +1 },   /* +Y: sc = +rx, tc = +rz */
   { 0, +1, 2, -1, 1, -1 },   /* -Y: sc = +rx, tc = -rz */
   { 0, +1, 1, -1, 2, +1 },   /* +Z: sc = +rx, tc = -ry */
   { 0, -1, 1, -1, 2, -1 },   /* -Z: sc = -rx, tc = -ry */
};

/* The texel across the edge from (x, y) on `face`, where exactly one of x
 * and y lies in {-1, size}.  False for a corner (both outside): GL leaves
 * the corner's texel to the implementation, and the filter takes the mean
 * of the three real taps there. */
bool tex_cube_across(unsigned face, int32_t size, int32_t x, int32_t y, unsigned *face_out,
                     int32_t *x_out, int32_t *y_out)
{
   const bool x_out_of = x < 0 || x >= size, y_out_of = y < 0 || y >= size;
   if (x_out_of == y_out_of)
      return false;
   const struct face_axes *f = &faces[face];
   int32_t r[3];
   r[f->sc_axis] = f->sc_sign * (2 * x + 1 - size);
   r[f->tc_axis] = f->tc_sign * (2 * y + 1 - size);
   r[f->ma_axis] = f->ma_sign * size;
   /* the overflowing component becomes the major one */
   const int axis = x_out_of ? f->sc_axis : f->tc_axis;
   const int sign = r[axis] < 0 ? -1 : 1;
   r[axis] = sign * size;
   r[f->ma_axis] = f->ma_sign * (size - 1);
   const unsigned nf = (unsigned)(2 * axis + (sign < 0));
   const struct face_axes *g = &faces[nf];
   *face_out = nf;
   *x_out = (g->sc_sign * r[g->sc_axis] + size - 1) / 2;
   *y_out = (g->tc_sign * r[g->tc_axis] + size - 1) / 2;
   return true;
}
