/*
 * Sample shading (GL ES 3.1 with GL_OES_sample_shading and
 * GL_OES_sample_variables; docs/msaa.md): a scene drawn into a 4-sample
 * texture of half the target's side, then each sample shown in a quarter
 * of the target (sample k in column k & 1, row k >> 1) by texelFetch, so
 * that each sample's own value is compared, not the resolve's mean
 * (--case NAME, 64x64 unless --size says):
 *
 *   shading      random Gouraud triangles of steep colour with
 *                glMinSampleShadingOES(1.0): each sample's colour at its
 *                position
 *   variables    gl_SampleID, gl_SamplePosition and gl_SampleMaskIn as the
 *                colour, on random triangles
 *   mask         gl_SampleMask from the pixel's position, on random
 *                triangles of flat colours
 *
 * Self-checks (errors fail the program on any driver): the extensions are
 * there, the texture has 4 samples; shading: the samples of covered
 * pixels differ (shaded once a pixel they would be equal); variables: each
 * covered sample holds its own id and position; mask: samples the mask
 * leaves out keep the background.
 */
#include "e2e_common.h"

#include <EGL/egl.h>
#include <GLES3/gl31.h>
#include <GLES2/gl2ext.h>
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

static GLuint program(const char *fs)
{
   return e2e_program(vs, fs, "a_color");
}

/* A triangle with vertices on the sub-pixel grid of a side-`size` target,
 * some beyond its edges. */
static void random_triangle(uint32_t *rng, int size, float pos[12])
{
   for (int k = 0; k < 3; k++) {
      pos[4 * k + 0] = e2e_ndc(e2e_rand_range(rng, -size * E2E_SUB / 4, size * E2E_SUB * 5 / 4),
                               size);
      pos[4 * k + 1] = e2e_ndc(e2e_rand_range(rng, -size * E2E_SUB / 4, size * E2E_SUB * 5 / 4),
                               size);
      pos[4 * k + 2] = 0.0f;
      pos[4 * k + 3] = 1.0f;
   }
}

/* Steep colours: each channel 0 or 1 at random at each vertex. */
static void random_colors(uint32_t *rng, float col[12])
{
   for (int k = 0; k < 3; k++) {
      for (int c = 0; c < 3; c++)
         col[4 * k + c] = (float)e2e_rand_range(rng, 0, 1);
      col[4 * k + 3] = 1.0f;
   }
}

static void scene_shading(int half)
{
   PFNGLMINSAMPLESHADINGOESPROC min_sample_shading =
      (PFNGLMINSAMPLESHADINGOESPROC)eglGetProcAddress("glMinSampleShadingOES");
   e2e_check(min_sample_shading != NULL, "no glMinSampleShadingOES");
   if (!min_sample_shading)
      return;
   glUseProgram(program("#version 310 es\n"
                        "precision highp float;\n"
                        "in vec4 v_color;\n"
                        "out vec4 o_color;\n"
                        "void main() { o_color = v_color; }\n"));
   glEnable(GL_SAMPLE_SHADING_OES);
   min_sample_shading(1.0f);
   uint32_t rng = 0x5a3b1e01u;
   for (int t = 0; t < 12; t++) {
      float pos[12], col[12];
      random_triangle(&rng, half, pos);
      random_colors(&rng, col);
      e2e_draw(GL_TRIANGLES, 3, pos, col, NULL);
   }
   glDisable(GL_SAMPLE_SHADING_OES);
}

static void scene_variables(int half)
{
   glUseProgram(program("#version 310 es\n"
                        "#extension GL_OES_sample_variables : require\n"
                        "precision highp float;\n"
                        "in vec4 v_color;\n"
                        "out vec4 o_color;\n"
                        "void main() {\n"
                        "   o_color = vec4(gl_SamplePosition, float(gl_SampleID) / 3.0,\n"
                        "                  float(gl_SampleMaskIn[0]) / 15.0);\n"
                        "}\n"));
   uint32_t rng = 0x7a11e5edu;
   for (int t = 0; t < 6; t++) {
      float pos[12];
      random_triangle(&rng, half, pos);
      const float white[4] = { 1, 1, 1, 1 };
      e2e_draw(GL_TRIANGLES, 3, pos, NULL, white);
   }
}

static void scene_mask(int half)
{
   glUseProgram(program("#version 310 es\n"
                        "#extension GL_OES_sample_variables : require\n"
                        "precision highp float;\n"
                        "in vec4 v_color;\n"
                        "out vec4 o_color;\n"
                        "void main() {\n"
                        "   ivec2 p = ivec2(gl_FragCoord.xy);\n"
                        "   gl_SampleMask[0] = (p.x * 7 + p.y * 3) & 15;\n"
                        "   o_color = v_color;\n"
                        "}\n"));
   /* flat colours: the mask and coverage alone decide each sample (where
    * a plain varying is evaluated is the implementation's choice) */
   uint32_t rng = 0x3a5c0de5u;
   for (int t = 0; t < 8; t++) {
      float pos[12], col[12];
      random_triangle(&rng, half, pos);
      random_colors(&rng, col);
      e2e_draw(GL_TRIANGLES, 3, pos, NULL, col);
   }
}

/* The shown samples, read back: pixel (x, y) of sample k. */
static const unsigned char *sample_px(const unsigned char *img, int size, int k, int x, int y)
{
   const int half = size / 2;
   return img + 4 * ((size_t)(y + half * (k >> 1)) * (size_t)size + (size_t)(x + half * (k & 1)));
}

static bool is_background(const unsigned char *p)
{
   return p[0] == 0 && p[1] == 0 && p[2] == 0 && p[3] == 0;
}

static void self_check(const char *c, int size)
{
   const int half = size / 2;
   unsigned char *img = malloc((size_t)size * (size_t)size * 4);
   if (!img)
      fp_die("out of memory");
   glReadPixels(0, 0, size, size, GL_RGBA, GL_UNSIGNED_BYTE, img);
   int differ = 0, bad_vars = 0, covered = 0, masked_in = 0;
   for (int y = 0; y < half; y++)
      for (int x = 0; x < half; x++) {
         const unsigned char *s0 = sample_px(img, size, 0, x, y);
         bool all = true;
         for (int k = 0; k < NS; k++)
            all &= !is_background(sample_px(img, size, k, x, y));
         for (int k = 1; k < NS && all; k++)
            differ += memcmp(s0, sample_px(img, size, k, x, y), 4) != 0;
         for (int k = 0; k < NS; k++) {
            const unsigned char *s = sample_px(img, size, k, x, y);
            if (is_background(s))
               continue;
            covered++;
            const int mask = (x * 7 + y * 3) & 15;
            masked_in += !(mask >> k & 1);
            if (!strcmp(c, "variables")) {
               /* the standard pattern (docs/msaa.md) times 255 */
               static const int pos[NS][2] = { { 96, 32 }, { 223, 96 }, { 32, 159 }, { 159, 223 } };
               const int m = (int)((double)s[3] * 15.0 / 255.0 + 0.5);
               bad_vars += abs(s[0] - pos[k][0]) > 1 || abs(s[1] - pos[k][1]) > 1 ||
                           abs(s[2] - k * 85) > 1 || !(m >> k & 1);
            }
         }
      }
   printf("stat: covered=%d differ=%d\n", covered, differ);
   e2e_check(covered > half * half / 2, "less than half of the samples covered");
   if (!strcmp(c, "shading"))
      e2e_check(differ > half * half,
                "the samples of covered pixels are alike: not shaded once a sample");
   if (!strcmp(c, "variables"))
      e2e_check(bad_vars == 0, "a sample without its own gl_SampleID, gl_SamplePosition or "
                               "gl_SampleMaskIn bit");
   if (!strcmp(c, "mask"))
      e2e_check(masked_in == 0, "a sample gl_SampleMask leaves out was written");
   free(img);
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   struct fp_gl g;
   e2e_start(&g, &a, argc, argv, 64);
   const char *c = e2e_opt(&a, "case", "");
   e2e_check(e2e_check_es31(), "not GL ES 3.1");
   e2e_check(e2e_has_extension("GL_OES_sample_shading"), "no GL_OES_sample_shading");
   e2e_check(e2e_has_extension("GL_OES_sample_variables"), "no GL_OES_sample_variables");
   const int half = a.size / 2;

   GLuint tex, fbo;
   glGenTextures(1, &tex);
   glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, tex);
   glTexStorage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, NS, GL_RGBA8, half, half, GL_TRUE);
   GLint samples = 0;
   glGetTexLevelParameteriv(GL_TEXTURE_2D_MULTISAMPLE, 0, GL_TEXTURE_SAMPLES, &samples);
   e2e_check(samples == NS, "the texture does not have 4 samples");
   glGenFramebuffers(1, &fbo);
   glBindFramebuffer(GL_FRAMEBUFFER, fbo);
   glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D_MULTISAMPLE, tex, 0);
   e2e_check(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE,
             "the 4-sample texture FBO is not complete");
   glViewport(0, 0, half, half);
   glClearColor(0, 0, 0, 0);
   glClear(GL_COLOR_BUFFER_BIT);

   if (!strcmp(c, "shading"))
      scene_shading(half);
   else if (!strcmp(c, "variables"))
      scene_variables(half);
   else if (!strcmp(c, "mask"))
      scene_mask(half);
   else
      fp_die("--case: shading, variables or mask");

   e2e_show_samples(tex, g.fbo, a.size);
   self_check(c, a.size);
   glDeleteFramebuffers(1, &fbo);
   glDeleteTextures(1, &tex);
   return e2e_finish(&g, &a, NULL);
}
