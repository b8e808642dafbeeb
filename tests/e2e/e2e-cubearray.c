/*
 * Cube map arrays (GL_OES_texture_cube_map_array, GL ES 3.1) through the
 * modeled unit (--case nearest|linear|shadow, 64x64 unless --size says):
 * three cubes of 8x8 faces, every texel random but green, which is the
 * cube's (80 L + a little); every pixel samples the direction of an
 * equirectangular map of the sphere at its column and row, from the cube
 * its band of rows picks (layers -0.6, 0.4, 1.4, 2.4: cube 0 clamped,
 * 0, 1, 2), at LOD 0: NEAREST, LINEAR (GL ES filters cube maps across
 * their faces' edges), or a depth cube map array compared with a
 * reference (samplerCubeArrayShadow, LINEAR).
 *
 * Self-checks (errors fail the program on any driver): the extension is
 * exposed; textureSize gives (8, 8, 3); in nearest and linear, every
 * pixel's green is its band's cube's.
 */
#include "e2e_common.h"

#include <GLES3/gl31.h>
#include <GLES2/gl2ext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef GL_TEXTURE_CUBE_MAP_ARRAY_OES
#define GL_TEXTURE_CUBE_MAP_ARRAY_OES 0x9009
#endif

#define FACE 8
#define CUBES 3

static const char vs_quad[] =
   "#version 310 es\n"
   "in vec4 a_pos;\n"
   "void main() { gl_Position = a_pos; }\n";

/* the direction of column u, row v of an equirectangular map; the layer
 * of v's band of four */
#define FS_COMMON \
   "#version 310 es\n" \
   "#extension GL_OES_texture_cube_map_array : require\n" \
   "precision highp float;\n" \
   "uniform float u_size;\n" \
   "out vec4 o_color;\n" \
   "vec4 coord() {\n" \
   "   vec2 uv = gl_FragCoord.xy / u_size;\n" \
   "   float lon = 6.2831853 * uv.x, lat = 3.1415927 * (fract(uv.y * 4.0) - 0.5);\n" \
   "   vec3 dir = vec3(sin(lon) * cos(lat), sin(lat), cos(lon) * cos(lat));\n" \
   "   return vec4(dir, floor(uv.y * 4.0) - 0.6);\n" \
   "}\n"

static const char fs_color[] =
   FS_COMMON
   "uniform highp samplerCubeArray u_tex;\n"
   "void main() {\n"
   "   bool size = textureSize(u_tex, 0) == ivec3(8, 8, 3);\n"
   "   vec4 c = textureLod(u_tex, coord(), 0.0);\n"
   "   o_color = vec4(c.rgb, size ? 1.0 : 0.0);\n"
   "}\n";

static const char fs_shadow[] =
   FS_COMMON
   "uniform highp samplerCubeArrayShadow u_tex;\n"
   "void main() {\n"
   "   vec2 uv = gl_FragCoord.xy / u_size;\n"
   "   float r = texture(u_tex, coord(), fract(uv.x * 5.0));\n"
   "   o_color = vec4(r, 0.0, 0.0, 1.0);\n"
   "}\n";

static uint32_t seed = 777;

static void upload_color(void)
{
   static unsigned char texels[CUBES * 6][FACE * FACE * 4];
   for (int layer = 0; layer < CUBES * 6; layer++)
      for (int i = 0; i < FACE * FACE; i++) {
         unsigned char *t = &texels[layer][4 * i];
         t[0] = (unsigned char)e2e_rand_range(&seed, 0, 255);
         t[1] = (unsigned char)(80 * (layer / 6) + e2e_rand_range(&seed, 0, 15));
         t[2] = (unsigned char)e2e_rand_range(&seed, 0, 255);
         t[3] = 255;
      }
   glTexImage3D(GL_TEXTURE_CUBE_MAP_ARRAY_OES, 0, GL_RGBA8, FACE, FACE, CUBES * 6, 0, GL_RGBA,
                GL_UNSIGNED_BYTE, texels);
}

static void upload_depth(void)
{
   static float depths[CUBES * 6][FACE * FACE];
   for (int layer = 0; layer < CUBES * 6; layer++)
      for (int i = 0; i < FACE * FACE; i++)
         depths[layer][i] = (float)e2e_rand_range(&seed, 0, 1000) / 1000.0f;
   glTexImage3D(GL_TEXTURE_CUBE_MAP_ARRAY_OES, 0, GL_DEPTH_COMPONENT32F, FACE, FACE, CUBES * 6, 0,
                GL_DEPTH_COMPONENT, GL_FLOAT, depths);
   glTexParameteri(GL_TEXTURE_CUBE_MAP_ARRAY_OES, GL_TEXTURE_COMPARE_MODE,
                   GL_COMPARE_REF_TO_TEXTURE);
   glTexParameteri(GL_TEXTURE_CUBE_MAP_ARRAY_OES, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   struct fp_gl g;
   e2e_start(&g, &a, argc, argv, 64);
   const char *c = e2e_opt(&a, "case", "");
   const bool shadow = !strcmp(c, "shadow");
   if (!shadow && strcmp(c, "nearest") && strcmp(c, "linear"))
      fp_die("--case: nearest, linear or shadow");
   if (!e2e_check_es31())
      return e2e_finish(&g, &a, NULL);
   e2e_check(e2e_has_extension("GL_OES_texture_cube_map_array"),
             "GL_OES_texture_cube_map_array is not exposed");
   if (e2e_errors)
      return e2e_finish(&g, &a, NULL);

   GLuint tex;
   glGenTextures(1, &tex);
   glBindTexture(GL_TEXTURE_CUBE_MAP_ARRAY_OES, tex);
   if (shadow)
      upload_depth();
   else
      upload_color();
   const GLenum filter = !strcmp(c, "nearest") ? GL_NEAREST : GL_LINEAR;
   glTexParameteri(GL_TEXTURE_CUBE_MAP_ARRAY_OES, GL_TEXTURE_MIN_FILTER, filter);
   glTexParameteri(GL_TEXTURE_CUBE_MAP_ARRAY_OES, GL_TEXTURE_MAG_FILTER, filter);
   glTexParameteri(GL_TEXTURE_CUBE_MAP_ARRAY_OES, GL_TEXTURE_MAX_LEVEL, 0);

   static const char *const attribs[] = { "a_pos", NULL };
   GLuint prog = fp_gl_program(vs_quad, shadow ? fs_shadow : fs_color, attribs);
   glUseProgram(prog);
   glUniform1i(glGetUniformLocation(prog, "u_tex"), 0);
   glUniform1f(glGetUniformLocation(prog, "u_size"), (float)a.size);
   glClearColor(0, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   const float quad[] = { -1, -1, 0, 1, 1, -1, 0, 1, -1, 1, 0, 1, 1, 1, 0, 1 };
   const float unused[4] = { 0, 0, 0, 0 };
   e2e_draw(GL_TRIANGLE_STRIP, 4, quad, NULL, unused);

   if (!shadow) {
      /* band b of rows samples cube max(b - 1, 0): green 80 L to 80 L + 15 */
      unsigned char *img = malloc((size_t)a.size * (size_t)a.size * 4);
      if (!img)
         fp_die("out of memory");
      glReadPixels(0, 0, a.size, a.size, GL_RGBA, GL_UNSIGNED_BYTE, img);
      int wrong = 0, nosize = 0;
      for (int y = 0; y < a.size; y++)
         for (int x = 0; x < a.size; x++) {
            const unsigned char *p = img + 4 * ((size_t)y * (size_t)a.size + (size_t)x);
            const int band = y * 4 / a.size, cube = band > 0 ? band - 1 : 0;
            wrong += p[1] < 80 * cube || p[1] > 80 * cube + 15;
            nosize += p[3] != 255;
         }
      free(img);
      printf("stat: wrong_cube=%d,wrong_size=%d\n", wrong, nosize);
      e2e_check(nosize == 0, "textureSize is not (8, 8, 3)");
      e2e_check(wrong == 0, "pixels sample another cube than their layer's");
   }
   glDeleteTextures(1, &tex);
   return e2e_finish(&g, &a, NULL);
}
