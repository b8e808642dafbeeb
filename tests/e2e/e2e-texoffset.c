/*
 * A NEAREST-filtered checkerboard of distinct texels whose coordinates are
 * offset by a whole number of repeats (--offset K, default 0): under REPEAT
 * and MIRRORED_REPEAT (K even) GL's image is the same for every K, and the
 * model's per-primitive coordinate rebase (docs/texture-unit.md) is what
 * lets a 24-bit coordinate path draw it so.  tests/e2e/texoffset.sh
 * compares the images of K = 2^17, 2^20 and 10^7 with K = 0.
 *
 * 256x256: the left half REPEAT, the right half MIRRORED_REPEAT (--wrap
 * repeat|mirror for one mode everywhere); each half a quad turned 20
 * degrees (two triangles), spanning 3 repeats of a 16x16 texture (one
 * colour per texel) each way, its corners' coordinates K + 0 and K + 3:
 * integers, so exact in binary32 up to 2^24 for every K.  No perspective
 * (w = 1) and nothing clipped: the vertex values reach the rasterizer as
 * they were given.
 */
#include "e2e_common.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static GLuint checker(GLenum wrap)
{
   enum { N = 16 };
   static unsigned char p[N * N * 4];
   for (int y = 0; y < N; y++)
      for (int x = 0; x < N; x++) {
         unsigned char *t = p + (y * N + x) * 4;
         const int dark = (x ^ y) & 1;
         t[0] = (unsigned char)(x * 16 + (dark ? 0 : 8));
         t[1] = (unsigned char)(y * 16 + (dark ? 0 : 8));
         t[2] = (unsigned char)(dark ? 40 : 220);
         t[3] = 255;
      }
   GLuint t;
   glGenTextures(1, &t);
   glBindTexture(GL_TEXTURE_2D, t);
   glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, N, N, 0, GL_RGBA, GL_UNSIGNED_BYTE, p);
   e2e_tex_params(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST, wrap, wrap);
   return t;
}

/* A square of side 90 pixels centred at (cx, cy), turned 20 degrees, its
 * corners' coordinates (K, K), (K + 3, K), (K, K + 3), (K + 3, K + 3). */
static void square(float cx, float cy, double K, int size)
{
   const double a = 20.0 * 3.14159265358979323846 / 180.0, h = 45.0;
   static const int cu[4] = { 0, 3, 0, 3 }, cv[4] = { 0, 0, 3, 3 };
   float pos[16], uv[8];
   for (int k = 0; k < 4; k++) {
      const double dx = cu[k] ? h : -h, dy = cv[k] ? h : -h;
      const double x = cx + dx * cos(a) - dy * sin(a), y = cy + dx * sin(a) + dy * cos(a);
      pos[k * 4 + 0] = e2e_ndc((int32_t)lround(x * E2E_SUB), size);
      pos[k * 4 + 1] = e2e_ndc((int32_t)lround(y * E2E_SUB), size);
      pos[k * 4 + 2] = 0;
      pos[k * 4 + 3] = 1;
      uv[k * 2 + 0] = (float)(K + cu[k]);
      uv[k * 2 + 1] = (float)(K + cv[k]);
      if ((double)uv[k * 2] != K + cu[k] || (double)uv[k * 2 + 1] != K + cv[k])
         fp_die("offset %.0f: the coordinates are not exact in binary32", K);
   }
   e2e_draw_uv(GL_TRIANGLE_STRIP, 4, pos, uv, 2);
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   e2e_parse(&a, argc, argv, 256);
   if (a.size != 256)
      fp_die("the texoffset test's layout is for --size 256");
   const double K = atof(e2e_opt(&a, "offset", "0"));
   const char *wrap = e2e_opt(&a, "wrap", "both");
   if (K != floor(K) || fabs(K) > 16777216.0 - 3)
      fp_die("--offset must be a whole number of repeats below 2^24 - 3");
   if (strcmp(wrap, "both") && strcmp(wrap, "repeat") && strcmp(wrap, "mirror"))
      fp_die("--wrap: both, repeat or mirror");

   struct fp_gl g;
   e2e_begin(&g, &a);
   GLuint prog = e2e_texture_program();
   glClearColor(0, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   glUseProgram(prog);
   glUniform1i(glGetUniformLocation(prog, "u_tex"), 0);
   glActiveTexture(GL_TEXTURE0);
   const GLenum left = strcmp(wrap, "mirror") ? GL_REPEAT : GL_MIRRORED_REPEAT;
   const GLenum right = strcmp(wrap, "repeat") ? GL_MIRRORED_REPEAT : GL_REPEAT;
   GLuint t0 = checker(left), t1 = checker(right);
   glBindTexture(GL_TEXTURE_2D, t0);
   square(64.5f, 128.25f, K, a.size);
   glBindTexture(GL_TEXTURE_2D, t1);
   square(192.25f, 127.75f, K, a.size);
   fp_gl_check("draw");
   /* distinct colours: a checkerboard of 256 texels, not a flat colour */
   unsigned char *px = malloc((size_t)a.size * a.size * 4);
   static unsigned char seen[1 << 21];      /* a bit per 24-bit colour */
   unsigned colours = 0;
   if (!px)
      fp_die("out of memory");
   fp_gl_read_rgba(&g, px);
   for (int i = 0; i < a.size * a.size; i++) {
      const unsigned c = px[i * 4] | px[i * 4 + 1] << 8 | (unsigned)px[i * 4 + 2] << 16;
      colours += !(seen[c >> 3] >> (c & 7) & 1);
      seen[c >> 3] |= (unsigned char)(1u << (c & 7));
   }
   free(px);
   printf("stat: offset=%.0f colours=%u\n", K, colours);
   glDeleteTextures(1, &t0);
   glDeleteTextures(1, &t1);
   glDeleteProgram(prog);
   e2e_end(&g, &a, NULL);
   return 0;
}
