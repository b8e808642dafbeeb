/*
 * Texture paths of the modeled texture unit, one 64x64 cell each on a
 * 256x256 target (screen-aligned quads, w = 1: no perspective, no tie
 * pixels; the perspective case is e2e-texture's):
 *   row 0  NEAREST  REPEAT, MIRRORED_REPEAT, CLAMP_TO_EDGE (16x16, s,t in
 *          [-1.3, 2.7]), NPOT 13x7 CLAMP_TO_EDGE
 *   row 1  the same with LINEAR
 *   row 2  mipmaps (64x64 chain, distinct colour per level): minified 1.5x,
 *          3x, 6x with LINEAR_MIPMAP_LINEAR; 3x with NEAREST_MIPMAP_NEAREST
 *   row 3  cube map (8x8 faces, a colour ramp each): +Z and a corner view,
 *          NEAREST and LINEAR
 * --far N adds N to every 2D coordinate (REPEAT and MIRRORED_REPEAT cells
 * are periodic, so GL's image is the same): the register precision at
 * large coordinates, the number system's business.
 * --rows 0123 picks rows.
 */
#include "e2e_common.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void quad(int cx, int cy, const float *tc, int ncomp, int size)
{
   float pos[16];
   const int x0 = cx * 64, y0 = cy * 64;
   const int xs[4] = { x0, x0 + 64, x0, x0 + 64 }, ys[4] = { y0, y0, y0 + 64, y0 + 64 };
   for (int k = 0; k < 4; k++) {
      pos[k * 4 + 0] = e2e_ndc(xs[k] * E2E_SUB, size);
      pos[k * 4 + 1] = e2e_ndc(ys[k] * E2E_SUB, size);
      pos[k * 4 + 2] = 0;
      pos[k * 4 + 3] = 1;
   }
   e2e_draw_uv(GL_TRIANGLE_STRIP, 4, pos, tc, ncomp);
}

static void pattern(unsigned char *p, int w, int h, int seed)
{
   for (int y = 0; y < h; y++)
      for (int x = 0; x < w; x++) {
         unsigned char *t = p + (y * w + x) * 4;
         t[0] = (unsigned char)(x * 255 / (w > 1 ? w - 1 : 1));
         t[1] = (unsigned char)(y * 255 / (h > 1 ? h - 1 : 1));
         t[2] = (unsigned char)((((x ^ y) & 1) ? 200 : 30) + seed * 5);
         t[3] = 255;
      }
}

static GLuint tex2d(int w, int h, GLenum filter, GLenum wrap)
{
   GLuint t;
   unsigned char *p = malloc((size_t)w * h * 4);
   if (!p)
      fp_die("out of memory");
   pattern(p, w, h, 0);
   glGenTextures(1, &t);
   glBindTexture(GL_TEXTURE_2D, t);
   glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, p);
   e2e_tex_params(GL_TEXTURE_2D, filter, filter, wrap, wrap);
   free(p);
   return t;
}

static GLuint cubemap(GLenum filter)
{
   GLuint t;
   unsigned char p[8 * 8 * 4];
   glGenTextures(1, &t);
   glBindTexture(GL_TEXTURE_CUBE_MAP, t);
   for (int f = 0; f < 6; f++) {
      pattern(p, 8, 8, f * 8);
      glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, 0, GL_RGBA, 8, 8, 0, GL_RGBA,
                   GL_UNSIGNED_BYTE, p);
   }
   e2e_tex_params(GL_TEXTURE_CUBE_MAP, filter, filter, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
   return t;
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   e2e_parse(&a, argc, argv, 256);
   if (a.size != 256)
      fp_die("the texwrap test's layout is for --size 256");
   const int size = a.size;
   const char *rows = e2e_opt(&a, "rows", "0123");
   const float far = (float)atof(e2e_opt(&a, "far", "0"));

   struct fp_gl g;
   e2e_begin(&g, &a);
   static const char *vsc =
      "attribute vec4 a_pos;\nattribute vec3 a_uv;\nvarying vec3 v_dir;\n"
      "void main() { v_dir = a_uv; gl_Position = a_pos; }\n";
   static const char *fsc =
      "precision highp float;\nuniform samplerCube u_tex;\nvarying vec3 v_dir;\n"
      "void main() { gl_FragColor = textureCube(u_tex, v_dir); }\n";
   GLuint p2 = e2e_texture_program(), pc = e2e_program(vsc, fsc, "a_uv");
   glClearColor(0, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT);

   glUseProgram(p2);
   glUniform1i(glGetUniformLocation(p2, "u_tex"), 0);
   static const GLenum wraps[3] = { GL_REPEAT, GL_MIRRORED_REPEAT, GL_CLAMP_TO_EDGE };
   for (int r = 0; r < 2; r++) {
      if (!strchr(rows, '0' + r))
         continue;
      GLenum filter = r ? GL_LINEAR : GL_NEAREST;
      for (int c = 0; c < 3; c++) {
         /* periodic modes only: far shifts by whole periods (2 for mirror) */
         float off = c < 2 ? far : 0;
         float tc[8] = { -1.3f + off, -1.3f + off, 2.7f + off, -1.3f + off,
                         -1.3f + off, 2.7f + off, 2.7f + off, 2.7f + off };
         GLuint t = tex2d(16, 16, filter, wraps[c]);
         quad(c, 3 - r, tc, 2, size);
         glDeleteTextures(1, &t);
      }
      float tn[8] = { -0.3f, -0.2f, 1.3f, -0.2f, -0.3f, 1.25f, 1.3f, 1.25f };
      GLuint t = tex2d(13, 7, filter, GL_CLAMP_TO_EDGE);
      quad(3, 3 - r, tn, 2, size);
      glDeleteTextures(1, &t);
   }
   if (strchr(rows, '2')) {
      static const float span[4] = { 1.5f, 3.0f, 6.0f, 3.0f };
      for (int c = 0; c < 4; c++) {
         /* a distinct colour a level; REPEAT, GL's default */
         GLuint t = e2e_mip_texture(64, 36, 160, 60, c == 3 ? GL_NEAREST_MIPMAP_NEAREST
                                                           : GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
         /* 64 pixels across span * 64 texels: LOD log2(span) */
         float s1 = span[c] * 1.0f + 0.013f, s0 = 0.013f;
         float tc[8] = { s0, s0 * 0.7f, s1, s0 * 0.7f, s0, s1 * 0.9f, s1, s1 * 0.9f };
         quad(c, 1, tc, 2, size);
         glDeleteTextures(1, &t);
      }
   }
   if (strchr(rows, '3')) {
      glUseProgram(pc);
      glUniform1i(glGetUniformLocation(pc, "u_tex"), 0);
      for (int c = 0; c < 4; c++) {
         GLuint t = cubemap(c & 1 ? GL_LINEAR : GL_NEAREST);
         /* +Z face (cells 0, 1), a view across three faces (cells 2, 3) */
         float fz[12] = { -0.93f, -0.91f, 1, 0.95f, -0.91f, 1, -0.93f, 0.92f, 1, 0.95f, 0.92f, 1 };
         float corner[12] = { -0.2f, 1.7f, 0.4f, 1.9f, 1.3f, 0.9f, -0.6f, -0.3f, 1.1f,
                              1.1f, 0.3f, 1.6f };
         quad(c, 0, c < 2 ? fz : corner, 3, size);
         glDeleteTextures(1, &t);
      }
   }
   printf("stat: far=%g\n", far);
   e2e_end(&g, &a, NULL);
   return 0;
}
