/*
 * Shadow lookups with an explicit LOD, bias or offset
 * (GL_EXT_texture_shadow_lod, GL ES 3.0) through the modeled unit
 * (--case array|cube, 64x64 unless --size says): a 2-D array or cube depth
 * texture of 8 levels whose depths step per level (and per layer), compared
 * with a reference that sweeps across the target, at an LOD that sweeps
 * along it: textureLod and textureLodOffset (array), textureLod and
 * texture with a bias (cube); LINEAR_MIPMAP_LINEAR with
 * COMPARE_REF_TO_TEXTURE LEQUAL.
 *
 * Self-checks (errors fail the program on any driver): the extension is
 * exposed; where the reference lies below every level's depth the result
 * is 1 and above every level's 0.
 */
#include "e2e_common.h"

#include <GLES3/gl3.h>
#include <GLES2/gl2ext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define SIZE 128   /* 8 levels */

static const char vs[] =
   "#version 300 es\n"
   "in vec4 a_pos;\n"
   "in vec2 a_uv;\n"
   "out vec2 v_uv;\n"
   "void main() { gl_Position = a_pos; v_uv = a_uv; }\n";

/* u: the reference, 0.05 to 0.95 across; v: the LOD, -1 to 8 along */
static const char fs_array[] =
   "#version 300 es\n"
   "#extension GL_EXT_texture_shadow_lod : require\n"
   "precision highp float;\n"
   "uniform highp sampler2DArrayShadow u_tex;\n"
   "in vec2 v_uv;\n"
   "out vec4 o_color;\n"
   "void main() {\n"
   "   float ref = 0.05 + 0.9 * v_uv.x, lod = -1.0 + 9.0 * v_uv.y;\n"
   "   vec4 c = vec4(0.3, 0.6, 1.0, ref);\n"
   "   o_color = vec4(textureLod(u_tex, c, lod),\n"
   "                  textureLodOffset(u_tex, c, lod, ivec2(1, -2)), 0.0, 1.0);\n"
   "}\n";

static const char fs_cube[] =
   "#version 300 es\n"
   "#extension GL_EXT_texture_shadow_lod : require\n"
   "precision highp float;\n"
   "uniform highp samplerCubeShadow u_tex;\n"
   "in vec2 v_uv;\n"
   "out vec4 o_color;\n"
   "void main() {\n"
   "   float ref = 0.05 + 0.9 * v_uv.x, lod = -1.0 + 9.0 * v_uv.y;\n"
   "   vec4 c = vec4(0.4, -0.7, 1.0, ref);\n"
   "   o_color = vec4(textureLod(u_tex, c, lod), texture(u_tex, c, lod), 0.0, 1.0);\n"
   "}\n";

/* level l, layer k: depth 0.1 + 0.1 l + 0.02 k, a ramp of +-0.04 across x */
static void upload(GLenum target, bool cube)
{
   static float d[SIZE * SIZE * 6];
   for (int l = 0, s = SIZE; s >= 1; l++, s /= 2) {
      const int layers = cube ? 6 : 2;
      for (int k = 0; k < layers; k++)
         for (int y = 0; y < s; y++)
            for (int x = 0; x < s; x++)
               d[(k * s + y) * s + x] = 0.1f + 0.1f * (float)l + 0.02f * (float)k +
                                        0.08f * ((float)x / (float)s - 0.5f);
      if (cube) {
         for (int k = 0; k < 6; k++)
            glTexImage2D((GLenum)(GL_TEXTURE_CUBE_MAP_POSITIVE_X + k), l, GL_DEPTH_COMPONENT32F, s,
                         s, 0, GL_DEPTH_COMPONENT, GL_FLOAT, d + (size_t)k * s * s);
      } else {
         glTexImage3D(target, l, GL_DEPTH_COMPONENT32F, s, s, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                      d);
      }
   }
   glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
   glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
   glTexParameteri(target, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
   glTexParameteri(target, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   struct fp_gl g;
   e2e_start(&g, &a, argc, argv, 64);
   const char *c = e2e_opt(&a, "case", "");
   const bool cube = !strcmp(c, "cube");
   if (!cube && strcmp(c, "array"))
      fp_die("--case: array or cube");
   e2e_check(e2e_has_extension("GL_EXT_texture_shadow_lod"),
             "GL_EXT_texture_shadow_lod is not exposed");
   if (e2e_errors)
      return e2e_finish(&g, &a, NULL);
   const GLenum target = cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D_ARRAY;
   GLuint tex;
   glGenTextures(1, &tex);
   glBindTexture(target, tex);
   upload(target, cube);

   static const char *const attribs[] = { "a_pos", "a_uv", NULL };
   glUseProgram(fp_gl_program(vs, cube ? fs_cube : fs_array, attribs));
   glClearColor(0, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   const float pos[] = { -1, -1, 0, 1, 1, -1, 0, 1, -1, 1, 0, 1, 1, 1, 0, 1 };
   const float uv[] = { 0, 0, 1, 0, 0, 1, 1, 1 };
   e2e_draw_uv(GL_TRIANGLE_STRIP, 4, pos, uv, 2);

   unsigned char *img = malloc((size_t)a.size * (size_t)a.size * 4);
   if (!img)
      fp_die("out of memory");
   glReadPixels(0, 0, a.size, a.size, GL_RGBA, GL_UNSIGNED_BYTE, img);
   /* the reference below every depth (left column, 0.05): 1; above every
    * depth (right column, 0.95): 0 */
   int wrong = 0;
   for (int y = 0; y < a.size; y++) {
      const unsigned char *l = img + 4 * (size_t)y * (size_t)a.size;
      const unsigned char *r = l + 4 * (size_t)(a.size - 1);
      wrong += l[0] != 255 || l[1] != 255 || r[0] != 0 || r[1] != 0;
   }
   /* the LOD moves the edge: its column at the bottom and the top rows */
   int edge[2] = { -1, -1 };
   for (int k = 0; k < 2; k++) {
      const unsigned char *row = img + 4 * (size_t)(k ? a.size - 2 : 1) * (size_t)a.size;
      for (int x = 0; x < a.size && edge[k] < 0; x++)
         if (row[4 * x] < 128)
            edge[k] = x;
   }
   printf("stat: wrong_ends=%d,edge_bottom=%d,edge_top=%d\n", wrong, edge[0], edge[1]);
   free(img);
   e2e_check(wrong == 0, "a reference below or above every level's depth compares wrongly");
   e2e_check(edge[1] - edge[0] > a.size / 2, "the LOD does not move the comparison's edge");
   glDeleteTextures(1, &tex);
   return e2e_finish(&g, &a, NULL);
}
