/*
 * interpolateAt* and gather offsets of each pixel (GL ES 3.1 with
 * GL_OES_shader_multisample_interpolation and GL_EXT_gpu_shader5; the
 * model's interpolators at another point of the pixel, docs/msaa.md):
 * random perspective triangles of steep Gouraud colour (--case NAME, 64x64
 * unless --size says):
 *
 *   offset     single-sampled: the colour at an offset from the pixel's
 *              centre that differs from pixel to pixel (inside a quad
 *              too), on GL's 1/16 grid
 *   sample     a 4-sample texture of half the target's side shaded once a
 *              pixel, the colour at a sample chosen per pixel; each sample
 *              of the texture shown in a quarter of the target
 *   centroid   the same texture, the colour at the centroid
 *   gather     textureGatherOffset with an offset that differs from pixel
 *              to pixel (GL_EXT_gpu_shader5), on a texture of random texels
 *
 * Self-checks (errors fail the program on any driver): the extensions are
 * there; offset and sample: in a pass of their own, the input moved
 * (interpolateAt unlike the plain input) over most drawn pixels; gather:
 * the lanes' offsets differ, so the alpha (gathered at the pixel's offset
 * unlike at offset 0) is set over most pixels.
 */
#include "e2e_common.h"

#include <GLES3/gl31.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NS 4

static const char *vs =
   "#version 310 es\n"
   "in vec4 a_pos;\n"
   "in vec4 a_color;\n"
   "out vec4 v_color;\n"
   "void main() { v_color = a_color; gl_Position = a_pos; }\n";

/* A triangle with vertices on the sub-pixel grid of a side-`size` target,
 * some beyond its edges, each with its own w (perspective). */
static void random_triangle(uint32_t *rng, int size, float pos[12])
{
   for (int k = 0; k < 3; k++) {
      const float w = 1.0f + (float)e2e_rand_range(rng, 0, 3);
      pos[4 * k + 0] = w * e2e_ndc(e2e_rand_range(rng, -size * E2E_SUB / 4,
                                                  size * E2E_SUB * 5 / 4), size);
      pos[4 * k + 1] = w * e2e_ndc(e2e_rand_range(rng, -size * E2E_SUB / 4,
                                                  size * E2E_SUB * 5 / 4), size);
      pos[4 * k + 2] = 0.0f;
      pos[4 * k + 3] = w;
   }
}

static void random_colors(uint32_t *rng, float col[12])
{
   for (int k = 0; k < 3; k++) {
      for (int c = 0; c < 3; c++)
         col[4 * k + c] = (float)e2e_rand_range(rng, 0, 1);
      col[4 * k + 3] = 1.0f;
   }
}

static void triangles(uint32_t seed, int size, int n)
{
   uint32_t rng = seed;
   for (int t = 0; t < n; t++) {
      float pos[12], col[12];
      random_triangle(&rng, size, pos);
      random_colors(&rng, col);
      e2e_draw(GL_TRIANGLES, 3, pos, col, NULL);
   }
}

/* The colour at the pixel's offset; alpha: how far it moved. */
static const char *fs_offset =
   "#version 310 es\n"
   "#extension GL_OES_shader_multisample_interpolation : require\n"
   "precision highp float;\n"
   "in vec4 v_color;\n"
   "out vec4 o_color;\n"
   "void main() {\n"
   "   ivec2 p = ivec2(gl_FragCoord.xy);\n"
   "   /* every lane of a quad its own offset, on the 1/16 grid of\n"
   "    * FRAGMENT_INTERPOLATION_OFFSET_BITS, within [-0.5, 0.5) */\n"
   "   vec2 off = vec2((p.x * 5 + p.y * 3) & 15, (p.y * 7 + p.x) & 15) / 16.0 - 0.5;\n"
   "   vec4 c = interpolateAtOffset(v_color, off);\n"
   "   o_color = vec4(c.rgb, MOVED);\n"
   "}\n";

static const char *fs_sample =
   "#version 310 es\n"
   "#extension GL_OES_shader_multisample_interpolation : require\n"
   "precision highp float;\n"
   "in vec4 v_color;\n"
   "out vec4 o_color;\n"
   "void main() {\n"
   "   ivec2 p = ivec2(gl_FragCoord.xy);\n"
   "   vec4 c = interpolateAtSample(v_color, (p.x + 3 * p.y) & 3);\n"
   "   o_color = vec4(c.rgb, MOVED);\n"
   "}\n";

static const char *fs_centroid =
   "#version 310 es\n"
   "#extension GL_OES_shader_multisample_interpolation : require\n"
   "precision highp float;\n"
   "in vec4 v_color;\n"
   "out vec4 o_color;\n"
   "void main() { o_color = vec4(interpolateAtCentroid(v_color).rgb, 1.0); }\n";

static const char *fs_gather =
   "#version 310 es\n"
   "#extension GL_EXT_gpu_shader5 : require\n"
   "precision highp float;\n"
   "uniform highp sampler2D u_tex;\n"
   "in vec2 v_uv;\n"
   "out vec4 o_color;\n"
   "void main() {\n"
   "   ivec2 p = ivec2(gl_FragCoord.xy);\n"
   "   ivec2 off = ivec2((p.x & 3) - 2, (p.y % 3) - 1);\n"
   "   vec4 g = textureGatherOffset(u_tex, v_uv, off, 1);\n"
   "   vec4 g0 = textureGatherOffset(u_tex, v_uv, ivec2(0), 1);\n"
   "   o_color = vec4(g.xyz, any(notEqual(g, g0)) ? 1.0 : 0.0);\n"
   "}\n";

/* fs with MOVED defined: 1 (the image compared), or whether the input
 * moved (the self-check's pass: where the input is evaluated without
 * interpolateAt is each implementation's choice on a multisampled target,
 * so it stays out of the image). */
static GLuint moved_program(const char *fs, bool check)
{
   const char *v = strchr(fs, '\n') + 1;
   char src[2048];
   snprintf(src, sizeof src, "%.*s#define MOVED %s\n%s", (int)(v - fs), fs,
            check ? "(length(c.rgb - v_color.rgb) > 0.004 ? 1.0 : 0.0)" : "1.0", v);
   return e2e_program(vs, src, "a_color");
}

/* Of the target's pixels: how many were drawn (not the clear's (0, 0, 0,
 * 0)), and how many have alpha above 0. */
static void count_alpha(int size, int *drawn, int *moved)
{
   unsigned char *img = malloc((size_t)size * (size_t)size * 4);
   if (!img)
      fp_die("out of memory");
   glReadPixels(0, 0, size, size, GL_RGBA, GL_UNSIGNED_BYTE, img);
   *drawn = *moved = 0;
   for (int i = 0; i < size * size; i++) {
      const unsigned char *p = img + 4 * i;
      *drawn += p[0] || p[1] || p[2] || p[3];
      *moved += p[3] > 0;
   }
   free(img);
}

static void multisampled(const char *c, struct fp_gl *g, int size)
{
   const int half = size / 2;
   GLuint tex, fbo;
   glGenTextures(1, &tex);
   glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, tex);
   glTexStorage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, NS, GL_RGBA8, half, half, GL_TRUE);
   glGenFramebuffers(1, &fbo);
   glBindFramebuffer(GL_FRAMEBUFFER, fbo);
   glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D_MULTISAMPLE, tex, 0);
   e2e_check(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE,
             "the 4-sample texture FBO is not complete");
   glViewport(0, 0, half, half);
   glClearColor(0, 0, 0, 0);
   glClear(GL_COLOR_BUFFER_BIT);
   const bool sample = !strcmp(c, "sample");
   int drawn = 0, moved = 0;
   for (int pass = sample ? 0 : 1; pass < 2; pass++) {
      glBindFramebuffer(GL_FRAMEBUFFER, fbo);
      glViewport(0, 0, half, half);
      glClear(GL_COLOR_BUFFER_BIT);
      glUseProgram(sample ? moved_program(fs_sample, pass == 0)
                          : e2e_program(vs, fs_centroid, "a_color"));
      triangles(sample ? 0x1a7e5a3bu : 0x5ce7401du, half, 10);
      e2e_show_samples(tex, g->fbo, size);
      int d, m;
      count_alpha(size, &d, &m);
      if (pass == 0)
         moved = m;
      else
         drawn = d;
   }
   printf("stat: drawn=%d moved=%d\n", drawn, moved);
   e2e_check(drawn > size * size / 2, "less than half of the samples drawn");
   if (sample)
      e2e_check(moved > drawn / 2, "interpolateAtSample left most colours where they were");
   glDeleteFramebuffers(1, &fbo);
   glDeleteTextures(1, &tex);
}

static void offset(struct fp_gl *g, int size)
{
   int drawn = 0, moved = 0;
   for (int pass = 0; pass < 2; pass++) {
      glBindFramebuffer(GL_FRAMEBUFFER, g->fbo);
      glClear(GL_COLOR_BUFFER_BIT);
      glUseProgram(moved_program(fs_offset, pass == 0));
      triangles(0x0ff5e7a1u, size, 10);
      int d, m;
      count_alpha(size, &d, &m);
      if (pass == 0)
         moved = m;
      else
         drawn = d;
   }
   printf("stat: drawn=%d moved=%d\n", drawn, moved);
   e2e_check(drawn > size * size / 2, "less than half of the pixels drawn");
   e2e_check(moved > drawn / 2, "interpolateAtOffset left most colours where they were");
}

static void gather(int size)
{
   enum { T = 16 };
   unsigned char texels[T * T * 4];
   uint32_t rng = 0x6a7e0ff5u;
   for (int i = 0; i < T * T * 4; i++)
      texels[i] = (unsigned char)e2e_rand_range(&rng, 0, 255);
   GLuint tex;
   glGenTextures(1, &tex);
   glActiveTexture(GL_TEXTURE0);
   glBindTexture(GL_TEXTURE_2D, tex);
   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, T, T, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
   e2e_tex_params(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST, GL_REPEAT, GL_REPEAT);
   glUseProgram(e2e_uv_program_es31(fs_gather));
   /* texel corners between pixels: each gather's footprint is decided */
   e2e_draw_rect(-1, -1, 1, 1, 0.013f, 0.021f, 1.7f, 1.3f);
   int drawn, moved;
   count_alpha(size, &drawn, &moved);
   printf("stat: drawn=%d moved=%d\n", drawn, moved);
   e2e_check(moved > size * size / 2,
             "the gathers at each pixel's offset are mostly those at offset 0");
   glDeleteTextures(1, &tex);
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   struct fp_gl g;
   e2e_start(&g, &a, argc, argv, 64);
   const char *c = e2e_opt(&a, "case", "");
   e2e_check(e2e_check_es31(), "not GL ES 3.1");
   e2e_check(e2e_has_extension("GL_OES_shader_multisample_interpolation"),
             "no GL_OES_shader_multisample_interpolation");
   e2e_check(e2e_has_extension("GL_EXT_gpu_shader5"), "no GL_EXT_gpu_shader5");
   glClearColor(0, 0, 0, 0);
   glClear(GL_COLOR_BUFFER_BIT);
   if (!strcmp(c, "offset"))
      offset(&g, a.size);
   else if (!strcmp(c, "sample") || !strcmp(c, "centroid"))
      multisampled(c, &g, a.size);
   else if (!strcmp(c, "gather"))
      gather(a.size);
   else
      fp_die("--case: offset, sample, centroid or gather");
   return e2e_finish(&g, &a, NULL);
}
