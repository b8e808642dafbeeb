/*
 * textureQueryLod (GL_EXT_texture_query_lod, GL ES 3.0): the modeled
 * unit's own LOD and level choice (--case linear|nearest|cube, 64x64
 * unless --size says).  A plane in perspective, its texture coordinate
 * stretched along the rows so that the LOD runs from below 0 to past the
 * last level, writes red = the levels the unit reads / 8 and green =
 * (the computed LOD + 2) / 12; blue is the texture sampled at the same
 * coordinate, so a level that the query and the sample disagree on shows.
 * linear: LINEAR_MIPMAP_LINEAR with a min LOD
 * of 1; nearest: NEAREST_MIPMAP_NEAREST; cube: a cube map, LINEAR mipmaps.
 *
 * Self-checks (errors fail the program on any driver): the extension is
 * exposed; red rises along the plane's rows by at least 3 levels (a
 * cube's 1); where the
 * LOD is below the min LOD (linear) red stays at 1 / 8.
 */
#include "e2e_common.h"

#include <GLES3/gl3.h>
#include <GLES2/gl2ext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define TEX 64   /* 7 levels */

static const char vs[] =
   "#version 300 es\n"
   "in vec4 a_pos;\n"
   "in vec2 a_uv;\n"
   "out vec2 v_uv;\n"
   "void main() { gl_Position = a_pos; v_uv = a_uv; }\n";

static const char fs_2d[] =
   "#version 300 es\n"
   "#extension GL_EXT_texture_query_lod : require\n"
   "precision highp float;\n"
   "uniform sampler2D u_tex;\n"
   "in vec2 v_uv;\n"
   "out vec4 o_color;\n"
   "void main() {\n"
   "   vec2 q = textureQueryLOD(u_tex, v_uv);\n"
   "   o_color = vec4(q.x / 8.0, (q.y + 2.0) / 12.0, texture(u_tex, v_uv).r, 1.0);\n"
   "}\n";

static const char fs_cube[] =
   "#version 300 es\n"
   "#extension GL_EXT_texture_query_lod : require\n"
   "precision highp float;\n"
   "uniform samplerCube u_tex;\n"
   "in vec2 v_uv;\n"
   "out vec4 o_color;\n"
   "void main() {\n"
   "   vec3 dir = vec3((v_uv.x * 2.0 - 1.0) * v_uv.y, 1.0, 0.5);\n"
   "   vec2 q = textureQueryLOD(u_tex, dir);\n"
   "   o_color = vec4(q.x / 8.0, (q.y + 2.0) / 12.0, texture(u_tex, dir).r, 1.0);\n"
   "}\n";

/* level l's texels: red 36 l (what blue shows) */
static void upload_levels(GLenum target)
{
   static unsigned char texels[TEX * TEX * 4];
   for (int l = 0, s = TEX; s >= 1; l++, s /= 2) {
      for (int i = 0; i < s * s * 4; i++)
         texels[i] = (unsigned char)(i % 4 == 0 ? 36 * l : 255);
      if (target == GL_TEXTURE_2D) {
         glTexImage2D(GL_TEXTURE_2D, l, GL_RGBA8, s, s, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
      } else {
         for (int f = 0; f < 6; f++)
            glTexImage2D((GLenum)(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), l, GL_RGBA8, s, s, 0,
                         GL_RGBA, GL_UNSIGNED_BYTE, texels);
      }
   }
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   struct fp_gl g;
   e2e_start(&g, &a, argc, argv, 64);
   const char *c = e2e_opt(&a, "case", "");
   const bool cube = !strcmp(c, "cube"), linear = !strcmp(c, "linear");
   if (!cube && !linear && strcmp(c, "nearest"))
      fp_die("--case: linear, nearest or cube");
   e2e_check(e2e_has_extension("GL_EXT_texture_query_lod"),
             "GL_EXT_texture_query_lod is not exposed");
   if (e2e_errors)
      return e2e_finish(&g, &a, NULL);

   const GLenum target = cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
   GLuint tex;
   glGenTextures(1, &tex);
   glBindTexture(target, tex);
   upload_levels(target);
   glTexParameteri(target, GL_TEXTURE_MIN_FILTER,
                   c[0] == 'n' ? GL_NEAREST_MIPMAP_NEAREST : GL_LINEAR_MIPMAP_LINEAR);
   glTexParameteri(target, GL_TEXTURE_MAG_FILTER, c[0] == 'n' ? GL_NEAREST : GL_LINEAR);
   if (linear)
      glTexParameterf(target, GL_TEXTURE_MIN_LOD, 1.0f);

   static const char *const attribs[] = { "a_pos", "a_uv", NULL };
   GLuint prog = fp_gl_program(vs, cube ? fs_cube : fs_2d, attribs);
   glUseProgram(prog);
   glUniform1i(glGetUniformLocation(prog, "u_tex"), 0);
   glClearColor(0, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   /* a plane receding along the rows: w from 1 at the bottom to 8 at the
    * top, the coordinate running 0..1 across and 0..12 along */
   const float pos[] = { -1, -1, 0, 1,   1, -1, 0, 1,   -8, 8, 0, 8,   8, 8, 0, 8 };
   const float uv[] = { 0, 0,   1, 0,   0, 12,   1, 12 };
   e2e_draw_uv(GL_TRIANGLE_STRIP, 4, pos, uv, 2);

   unsigned char *img = malloc((size_t)a.size * (size_t)a.size * 4);
   if (!img)
      fp_die("out of memory");
   glReadPixels(0, 0, a.size, a.size, GL_RGBA, GL_UNSIGNED_BYTE, img);
   const int mid = a.size / 2;
   const int lo = img[4 * (2 * a.size + mid)], hi = img[4 * ((a.size - 3) * a.size + mid)];
   printf("stat: level_bottom=%.2f,level_top=%.2f\n", lo * 8 / 255.0, hi * 8 / 255.0);
   e2e_check(hi - lo >= (cube ? 1 : 3) * 255 / 8,
             "the levels do not rise along the plane (by 3, a cube's by 1)");
   if (linear) {
      int below = 0;
      for (int x = 0; x < a.size; x++)
         below += abs(img[4 * x] - 32) > 1;   /* the bottom row: LOD under 1 */
      e2e_check(below == 0, "the bottom row's level is not the min LOD's 1");
   }
   free(img);
   glDeleteTextures(1, &tex);
   return e2e_finish(&g, &a, NULL);
}
