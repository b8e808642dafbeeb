/*
 * Min/max reduction filtering (GL_EXT_texture_filter_minmax, GL ES 3.1)
 * through the modeled unit (--case min|max, 64x64 unless --size says):
 * a random 16x16 RGBA8 texture with its mipmaps on two quads, the left one
 * magnified and turned (LINEAR: the least or greatest of the footprint's
 * taps with a nonzero weight), the right one minified in perspective
 * (LINEAR_MIPMAP_LINEAR: each level reduced, then the two levels: every
 * texel with a nonzero weight takes part, as in D3D and llvmpipe).
 *
 * Self-checks (errors fail the program on any driver): the extension is
 * exposed; on the magnified quad, min never exceeds and max never falls
 * below the weighted average drawn by the same texture (a second pass,
 * WEIGHTED_AVERAGE, read back first).
 */
#include "e2e_common.h"

#include <GLES3/gl31.h>
#include <GLES2/gl2ext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef GL_TEXTURE_REDUCTION_MODE_EXT
#define GL_TEXTURE_REDUCTION_MODE_EXT 0x9366
#define GL_WEIGHTED_AVERAGE_EXT 0x9367
#endif

#define TEX 16

static const char vs[] =
   "#version 310 es\n"
   "in vec4 a_pos;\n"
   "in vec2 a_uv;\n"
   "out vec2 v_uv;\n"
   "void main() { gl_Position = a_pos; v_uv = a_uv; }\n";

static const char fs[] =
   "#version 310 es\n"
   "precision highp float;\n"
   "uniform sampler2D u_tex;\n"
   "in vec2 v_uv;\n"
   "out vec4 o_color;\n"
   "void main() { o_color = texture(u_tex, v_uv); }\n";

static void draw_scene(void)
{
   glClearColor(0, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   /* left: magnified 4x, turned by about 20 degrees */
   const float mag[] = { -0.95f, -0.55f, 0, 1,  -0.1f, -0.85f, 0, 1,
                         -0.65f, 0.3f, 0, 1,    0.2f, 0.0f, 0, 1 };
   const float mag_uv[] = { 0.1f, 0.1f, 0.6f, 0.1f, 0.1f, 0.6f, 0.6f, 0.6f };
   e2e_draw_uv(GL_TRIANGLE_STRIP, 4, mag, mag_uv, 2);
   /* right: minified, receding (w 1 to 4) */
   const float min_pos[] = { 0.05f, -1, 0, 1,   1, -1, 0, 1,   0.2f, 4, 0, 4,   4, 4, 0, 4 };
   const float min_uv[] = { 0, 0, 3, 0, 0, 9, 3, 9 };
   e2e_draw_uv(GL_TRIANGLE_STRIP, 4, min_pos, min_uv, 2);
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   struct fp_gl g;
   e2e_start(&g, &a, argc, argv, 64);
   const char *c = e2e_opt(&a, "case", "");
   const bool is_min = !strcmp(c, "min");
   if (!is_min && strcmp(c, "max"))
      fp_die("--case: min or max");
   e2e_check(e2e_has_extension("GL_EXT_texture_filter_minmax"),
             "GL_EXT_texture_filter_minmax is not exposed");
   if (e2e_errors)
      return e2e_finish(&g, &a, NULL);

   uint32_t seed = 4242;
   static unsigned char texels[TEX * TEX * 4];
   for (int i = 0; i < TEX * TEX * 4; i++)
      texels[i] = (unsigned char)e2e_rand_range(&seed, 0, 255);
   GLuint tex;
   glGenTextures(1, &tex);
   glBindTexture(GL_TEXTURE_2D, tex);
   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, TEX, TEX, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
   glGenerateMipmap(GL_TEXTURE_2D);
   e2e_tex_params(GL_TEXTURE_2D, GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT, GL_REPEAT);

   static const char *const attribs[] = { "a_pos", "a_uv", NULL };
   glUseProgram(fp_gl_program(vs, fs, attribs));

   /* the weighted average first, for the self-check */
   const size_t n = (size_t)a.size * (size_t)a.size * 4;
   unsigned char *avg = malloc(n), *img = malloc(n);
   if (!avg || !img)
      fp_die("out of memory");
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_REDUCTION_MODE_EXT, GL_WEIGHTED_AVERAGE_EXT);
   draw_scene();
   glReadPixels(0, 0, a.size, a.size, GL_RGBA, GL_UNSIGNED_BYTE, avg);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_REDUCTION_MODE_EXT, is_min ? GL_MIN : GL_MAX);
   draw_scene();
   glReadPixels(0, 0, a.size, a.size, GL_RGBA, GL_UNSIGNED_BYTE, img);

   /* the magnified quad's pixels: the left half */
   int wrong = 0, differ = 0;
   for (int y = 0; y < a.size; y++)
      for (int x = 0; x < a.size / 2; x++)
         for (int ch = 0; ch < 3; ch++) {
            const size_t k = 4 * ((size_t)y * (size_t)a.size + (size_t)x) + (size_t)ch;
            wrong += is_min ? img[k] > avg[k] + 1 : img[k] + 1 < avg[k];
            differ += img[k] != avg[k];
         }
   printf("stat: beyond_average=%d,differ_from_average=%d\n", wrong, differ);
   e2e_check(wrong == 0, is_min ? "min exceeds the weighted average" :
                                  "max falls below the weighted average");
   e2e_check(differ > 100, "the reduction draws what the weighted average draws");
   free(avg);
   free(img);
   glDeleteTextures(1, &tex);
   return e2e_finish(&g, &a, NULL);
}
