/*
 * Level of detail, in the number system up to the log2 unit:
 *
 *   rho = max over axes a and directions x, y of |dc_a/dx| * size_a
 *
 * (the largest scaled derivative component, as llvmpipe's default; GL's
 * Euclidean length is up to sqrt(2) larger, i.e. up to 0.5 LOD), then
 *
 *   lod = log2(rho) = e + ROM[f]       leading one e, next 8 bits f
 *
 * with ROM[i] = round(256 * log2(1 + i/256)), so lod is a fixed-point
 * register with TEX_LOD_FRAC_BITS fraction bits; the error of log2 is below
 * 2^-8 + log2(e) / 256 < 0.01.  Bias, min and max clamps and level
 * selection are integer operations on that register.
 */
#include "rast/tex/tex_priv.h"

static const uint8_t log2_rom[256] = {
     0,   1,   3,   4,   6,   7,   9,  10,  11,  13,  14,  16,  17,  18,  20,  21,
    22,  24,  25,  26,  28,  29,  30,  32,  33,  34,  36,  37,  38,  40,  41,  42,
    44,  45,  46,  47,  49,  50,  51,  52,  54,  55,  56,  57,  59,  60,  61,  62,
    63,  65,  66,  67,  68,  69,  71,  72,  73,  74,  75,  77,  78,  79,  80,  81,
    82,  84,  85,  86,  87,  88,  89,  90,  92,  93,  94,  95,  96,  97,  98,  99,
   100, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111, 112, 113, 114, 116, 117,
   118, 119, 120, 121, 122, 123, 124, 125, 126, 127, 128, 129, 130, 131, 132, 133,
   134, 135, 136, 137, 138, 139, 140, 141, 142, 143, 144, 145, 146, 147, 148, 149,
   150, 151, 152, 153, 154, 155, 155, 156, 157, 158, 159, 160, 161, 162, 163, 164,
   165, 166, 167, 168, 169, 169, 170, 171, 172, 173, 174, 175, 176, 177, 178, 178,
   179, 180, 181, 182, 183, 184, 185, 185, 186, 187, 188, 189, 190, 191, 192, 192,
   193, 194, 195, 196, 197, 198, 198, 199, 200, 201, 202, 203, 203, 204, 205, 206,
   207, 208, 208, 209, 210, 211, 212, 212, 213, 214, 215, 216, 216, 217, 218, 219,
   220, 220, 221, 222, 223, 224, 224, 225, 226, 227, 228, 228, 229, 230, 231, 231,
   232, 233, 234, 234, 235, 236, 237, 238, 238, 239, 240, 241, 241, 242, 243, 244,
   244, 245, 246, 247, 247, 248, 249, 249, 250, 251, 252, 252, 253, 254, 255, 255,
};

int32_t tex_lod_from_rho(const struct tex_unit *u, ns_val rho)
{
   int e;
   unsigned f;
   if (!tex_ns_lead(u->ns, u->kind, rho, &e, &f))
      return TEX_LOD_NONE;
   return e * TEX_LOD_ONE + log2_rom[f];
}

static inline ns_val scaled_abs(const struct tex_unit *u, ns_val d, ns_val scale)
{
   return tex_ns_abs(u->kind, u->ns->mul(u->ns, d, scale, u->stats));
}

/* The quad's differences on the pixels of the shader's coarse derivatives
 * (tgsi_exec's, softpipe's): x from pixel 2 to 3 (the quad's lower scan
 * line), y from pixel 2 to 0 (its left column), as the cube LOD takes
 * them; so textureGrad(c, dFdx(c), dFdy(c)) is texture(c)'s LOD.  Taken
 * from pixel 0's neighbours instead (the upper scan line), a projected
 * quad whose LOD grew fast towards its upper right gave its lower-left
 * pixel a level coarser than the LOD of any of that pixel's neighbours
 * allows (dEQP-GLES2 texture.mipmap.2d.projected.*, 3 pixels a case). */
int32_t tex_lod_diffs(const struct tex_unit *u, ns_val c[TEX_QUAD][3], unsigned dims)
{
   ns_val rho = u->k_zero;
   for (unsigned a = 0; a < dims; a++) {
      ns_val dx = u->ns->sub(u->ns, c[3][a], c[2][a], u->stats);
      ns_val dy = u->ns->sub(u->ns, c[0][a], c[2][a], u->stats);
      rho = tex_ns_max(u->kind, rho, scaled_abs(u, dx, u->axis[0][a].scale));
      rho = tex_ns_max(u->kind, rho, scaled_abs(u, dy, u->axis[0][a].scale));
   }
   return tex_lod_from_rho(u, rho);
}

int32_t tex_lod_grads(const struct tex_unit *u, const ns_val dx[3], const ns_val dy[3],
                      unsigned dims, const ns_val scale[3])
{
   ns_val rho = u->k_zero;
   for (unsigned a = 0; a < dims; a++) {
      rho = tex_ns_max(u->kind, rho, scaled_abs(u, dx[a], scale[a]));
      rho = tex_ns_max(u->kind, rho, scaled_abs(u, dy[a], scale[a]));
   }
   return tex_lod_from_rho(u, rho);
}

int32_t tex_lod_derivs(const struct tex_unit *u, const float ddx[3], const float ddy[3],
                       unsigned dims, const ns_val scale[3])
{
   ns_val dx[3], dy[3];
   for (unsigned a = 0; a < dims; a++) {
      dx[a] = tex_ns_coord(u->ns, u->kind, ddx[a], u->stats);
      dy[a] = tex_ns_coord(u->ns, u->kind, ddy[a], u->stats);
   }
   return tex_lod_grads(u, dx, dy, dims, scale);
}

/* tex_unit_select then gives level 0, no fraction and the one filter for
 * every LOD. */
bool tex_unit_lod_unused(const struct tex_unit *u)
{
   return (u->samp.mip == TEX_MIP_NONE || u->view.num_levels == 1 || !u->samp.normalized) &&
          u->samp.min_filter == u->samp.mag_filter;
}

/* GL's level choice on the LOD register (already biased and clamped):
 * magnification below or at 0; NEAREST takes ceil(lod + 1/2) - 1 (ties
 * toward the finer level); LINEAR the two levels around lod with its 8
 * fraction bits as the weight. */
void tex_unit_select(const struct tex_unit *u, int32_t lod, unsigned *level0, unsigned *level1,
                     uint32_t *frac, enum tex_filter *filter)
{
   const int32_t last = (int32_t)u->view.num_levels - 1;
   *frac = 0;
   *level0 = *level1 = 0;
   if (lod <= 0 || !u->samp.normalized) {
      *filter = lod <= 0 ? u->samp.mag_filter : u->samp.min_filter;
      return;
   }
   *filter = u->samp.min_filter;
   switch (u->samp.mip) {
   case TEX_MIP_NONE:
      return;
   case TEX_MIP_NEAREST: {
      int32_t l = (lod + TEX_LOD_ONE / 2 - 1) >> TEX_LOD_FRAC_BITS;
      *level0 = *level1 = (unsigned)(l > last ? last : l);
      return;
   }
   case TEX_MIP_LINEAR: {
      int32_t l = lod >> TEX_LOD_FRAC_BITS;
      if (l >= last) {
         *level0 = *level1 = (unsigned)last;
         return;
      }
      *level0 = (unsigned)l;
      *level1 = (unsigned)l + 1;
      *frac = (uint32_t)lod & (TEX_LOD_ONE - 1);
      return;
   }
   }
}
