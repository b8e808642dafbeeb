/*
 * Texture sampling under perspective: four quads, each with its own filter
 * and wrap mode, over a 64x64 texture whose mip levels are made on the CPU
 * (a 2x2 box) so the test measures sampling, not glGenerateMipmap.
 *   lower left   LINEAR_MIPMAP_LINEAR, REPEAT, floor receding to w = 8
 *   upper left   LINEAR (magnified), CLAMP_TO_EDGE, mild perspective
 *   lower right  NEAREST_MIPMAP_NEAREST, MIRRORED_REPEAT, turned 12 deg, w = 1
 *   upper right  LINEAR_MIPMAP_NEAREST, REPEAT, wall receding to w = 4
 * Vertex w are powers of two and window positions lie on the 1/256 grid, so
 * the projected triangles are exact and their tie pixels are known: they
 * form the mask (coverage is the coverage test's business).
 * --quads 0123: which quads to draw (0 lower left .. 3 upper right), so the
 * filtered and the NEAREST quads can get tolerances of their own.
 */
#include "e2e_common.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TEX 64

struct quad {
   float x[4], y[4], w[4], s[4], t[4];   /* window pixels, corners in strip order */
   GLenum min, mag, wrap;
};

static const struct quad quads[4] = {
   { { 3.2f, 124.7f, 40.1f, 88.9f }, { 4.3f, 4.3f, 120.6f, 120.6f }, { 1, 1, 8, 8 },
     { 0, 4, 0, 4 }, { 0, 0, 16, 16 }, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT },
   { { 5.3f, 122.7f, 5.3f, 122.7f }, { 133.4f, 140.1f, 250.6f, 244.9f }, { 1, 2, 1, 2 },
     { -0.25f, 1.25f, -0.25f, 1.25f }, { -0.25f, -0.25f, 1.25f, 1.25f },
     GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE },
   /* Turned by only 12 degrees at 2 texels a pixel (LOD 1): at 45 degrees
    * the GL-permitted approximations of rho (llvmpipe's) pick another mip
    * level than the exact length (softpipe's) and half the quad differs. */
   { { 153.49f, 251.30f, 132.70f, 230.51f }, { 4.70f, 25.49f, 102.51f, 123.30f }, { 1, 1, 1, 1 },
     { -1, 2.125f, -1, 2.125f }, { -1, -1, 2.125f, 2.125f }, GL_NEAREST_MIPMAP_NEAREST,
     GL_NEAREST, GL_MIRRORED_REPEAT },
   { { 131.1f, 250.2f, 131.1f, 250.2f }, { 131.7f, 170.3f, 251.2f, 215.8f }, { 1, 4, 1, 4 },
     { 0, 8, 0, 8 }, { 0, 0, 2, 2 }, GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, GL_REPEAT },
};

static void make_texture(unsigned char *level0)
{
   for (int y = 0; y < TEX; y++)
      for (int x = 0; x < TEX; x++) {
         unsigned char *p = level0 + (y * TEX + x) * 4;
         int on = ((x >> 3) ^ (y >> 3)) & 1, line = (x % 16 == 0) || (y % 16 == 5);
         p[0] = (unsigned char)(line ? 255 : on ? 40 + 3 * x : 20);
         p[1] = (unsigned char)(line ? 255 : on ? 40 + 3 * y : 60 + x);
         p[2] = (unsigned char)(line ? 0 : on ? 230 - 2 * (x + y) / 2 : 90);
         p[3] = 255;
      }
}

static void upload_levels(const unsigned char *level0)
{
   unsigned char *cur = malloc(TEX * TEX * 4), *next = malloc(TEX * TEX * 4);
   if (!cur || !next)
      fp_die("out of memory");
   for (int i = 0; i < TEX * TEX * 4; i++)
      cur[i] = level0[i];
   for (int level = 0, s = TEX; s >= 1; level++, s /= 2) {
      glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, s, s, 0, GL_RGBA, GL_UNSIGNED_BYTE, cur);
      int h = s / 2;
      for (int y = 0; y < h; y++)
         for (int x = 0; x < h; x++)
            for (int c = 0; c < 4; c++) {
               int sum = cur[((2 * y) * s + 2 * x) * 4 + c] + cur[((2 * y) * s + 2 * x + 1) * 4 + c] +
                         cur[((2 * y + 1) * s + 2 * x) * 4 + c] +
                         cur[((2 * y + 1) * s + 2 * x + 1) * 4 + c];
               next[(y * h + x) * 4 + c] = (unsigned char)((sum + 2) / 4);
            }
      unsigned char *t = cur;
      cur = next;
      next = t;
   }
   free(cur);
   free(next);
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   e2e_parse(&a, argc, argv, 256);
   if (a.size != 256)
      fp_die("the texture test's layout is for --size 256");
   int size = a.size;
   const char *which = e2e_opt(&a, "quads", "0123");
   unsigned char *mask = calloc((size_t)size * size * 4, 1), *tex0 = malloc(TEX * TEX * 4);
   if (!mask || !tex0)
      fp_die("out of memory");
   make_texture(tex0);

   struct fp_gl g;
   e2e_begin(&g, &a);
   static const char *vs =
      "attribute vec4 a_pos;\n"
      "attribute vec2 a_uv;\n"
      "varying vec2 v_uv;\n"
      "void main() { v_uv = a_uv; gl_Position = a_pos; }\n";
   static const char *fs =
      "precision mediump float;\n"
      "uniform sampler2D u_tex;\n"
      "varying vec2 v_uv;\n"
      "void main() { gl_FragColor = texture2D(u_tex, v_uv); }\n";
   GLuint prog = e2e_program(vs, fs, "a_uv");
   glUseProgram(prog);
   glUniform1i(glGetUniformLocation(prog, "u_tex"), 0);
   glClearColor(0, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT);

   long ties = 0;
   int drawn = 0;
   for (int q = 0; q < 4; q++) {
      const struct quad *Q = &quads[q];
      if (!strchr(which, '0' + q))
         continue;
      drawn++;
      GLuint tex;
      glGenTextures(1, &tex);
      glBindTexture(GL_TEXTURE_2D, tex);
      upload_levels(tex0);
      e2e_tex_params(GL_TEXTURE_2D, Q->min, Q->mag, Q->wrap, Q->wrap);

      float pos[16], uv[8];
      int32_t gx[4], gy[4];
      for (int k = 0; k < 4; k++) {
         gx[k] = (int32_t)lroundf(Q->x[k] * E2E_SUB);
         gy[k] = (int32_t)lroundf(Q->y[k] * E2E_SUB);
         /* clip = ndc * w with w a power of two: the divide is exact. */
         pos[k * 4 + 0] = e2e_ndc(gx[k], size) * Q->w[k];
         pos[k * 4 + 1] = e2e_ndc(gy[k], size) * Q->w[k];
         pos[k * 4 + 2] = 0.0f;
         pos[k * 4 + 3] = Q->w[k];
         uv[k * 2 + 0] = Q->s[k];
         uv[k * 2 + 1] = Q->t[k];
      }
      for (int tri = 0; tri < 2; tri++) {
         struct e2e_tri t = { { gx[tri], gx[tri + 1], gx[tri + 2] },
                              { gy[tri], gy[tri + 1], gy[tri + 2] } };
         ties += e2e_tri_ties(&t, size, mask);
      }
      e2e_draw_uv(GL_TRIANGLE_STRIP, 4, pos, uv, 2);
      glDeleteTextures(1, &tex);
   }
   printf("stat: quads=%d tie_pixels=%ld\n", drawn, ties);
   e2e_end(&g, &a, mask);
   free(mask);
   free(tex0);
   return 0;
}
