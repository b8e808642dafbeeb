/*
 * GL ES 3.0 with a 4x multisampled framebuffer: the scene is drawn into a
 * renderbuffer FBO of 4 samples (colour RGBA8, depth24/stencil8) with
 * GLSL ES 3.00 shaders, resolved by glBlitFramebuffer into the target and
 * read back (--case NAME, 64x64 unless --size says):
 *
 *   edges      random Gouraud triangles with the depth test: every edge
 *              pixel a mean of its four samples
 *   coverage   alpha to coverage on alpha ramps, and glSampleCoverage (0.5,
 *              inverted and not), over a background
 *   blend      translucent Gouraud triangles blended (SRC_ALPHA,
 *              ONE_MINUS_SRC_ALPHA) into each sample
 *
 * Self-checks (errors fail the program on any driver): the FBO is complete
 * with GL_SAMPLES = 4, and the resolved image has pixels strictly between
 * a white triangle and the black background (more than one sample a pixel
 * reached the target).
 */
#include "e2e_common.h"

#include <GLES3/gl3.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The colour as it arrives. */
static GLuint program(void)
{
   static const char *fs =
      "#version 300 es\n"
      "precision mediump float;\n"
      "in vec4 v_color;\n"
      "out vec4 o_color;\n"
      "void main() { o_color = v_color; }\n";
   return e2e_color_program_es3(fs);
}

/* A white triangle on black: the resolve must hold partly covered pixels. */
static void self_check(GLuint target, int size)
{
   struct e2e_msaa m;
   e2e_errors += e2e_msaa_create(&m, size);
   glClearColor(0, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   const float pos[] = { -0.9f, -0.8f, 0, 1, 0.85f, -0.3f, 0, 1, -0.2f, 0.9f, 0, 1 };
   const float white[4] = { 1, 1, 1, 1 };
   e2e_draw(GL_TRIANGLES, 3, pos, NULL, white);
   e2e_msaa_resolve(&m, target);
   unsigned char *px = malloc((size_t)size * (size_t)size * 4);
   if (!px)
      fp_die("out of memory");
   glReadPixels(0, 0, size, size, GL_RGBA, GL_UNSIGNED_BYTE, px);
   int partial = 0;
   for (int i = 0; i < size * size; i++)
      partial += px[4 * i] > 8 && px[4 * i] < 247;
   free(px);
   printf("stat: partial=%d\n", partial);
   e2e_check(partial > size / 2, "no partly covered pixels in the resolve: not multisampled");
   e2e_msaa_delete(&m);
   glBindFramebuffer(GL_FRAMEBUFFER, target);
}

static void scene_edges(int size)
{
   uint32_t rng = 0x5eed1234u;
   glEnable(GL_DEPTH_TEST);
   glDepthFunc(GL_LESS);
   glClearColor(0.1f, 0.15f, 0.2f, 1);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
   for (int t = 0; t < 40; t++) {
      float pos[12], col[12];
      for (int k = 0; k < 3; k++) {
         pos[4 * k + 0] = (float)e2e_rand_range(&rng, -1100, 1100) / 1000.0f;
         pos[4 * k + 1] = (float)e2e_rand_range(&rng, -1100, 1100) / 1000.0f;
         pos[4 * k + 2] = (float)e2e_rand_range(&rng, -900, 900) / 1000.0f;
         pos[4 * k + 3] = 1.0f;
         for (int c = 0; c < 3; c++)
            col[4 * k + c] = (float)e2e_rand_range(&rng, 0, 255) / 255.0f;
         col[4 * k + 3] = 1.0f;
      }
      e2e_draw(GL_TRIANGLES, 3, pos, col, NULL);
   }
   glDisable(GL_DEPTH_TEST);
   (void)size;
}

static void scene_coverage(int size)
{
   glClearColor(0.0f, 0.0f, 0.3f, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   /* alpha to coverage: a horizontal quad whose alpha runs 0 to 1 */
   glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
   const float quad[] = { -0.9f, 0.1f, 0, 1, 0.9f, 0.1f, 0, 1, -0.9f, 0.9f, 0, 1,
                          0.9f, 0.9f, 0, 1 };
   const float ramp[] = { 1, 1, 0, 0, 1, 1, 0, 1, 1, 1, 0, 0, 1, 1, 0, 1 };
   e2e_draw(GL_TRIANGLE_STRIP, 4, quad, ramp, NULL);
   glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
   /* sample coverage 0.5, then inverted, in two colours over one rectangle */
   glEnable(GL_SAMPLE_COVERAGE);
   const float rect[] = { -0.7f, -0.9f, 0, 1, 0.7f, -0.9f, 0, 1, -0.7f, -0.1f, 0, 1,
                          0.7f, -0.1f, 0, 1 };
   const float red[4] = { 1, 0, 0, 1 }, green[4] = { 0, 1, 0, 1 };
   glSampleCoverage(0.5f, GL_FALSE);
   e2e_draw(GL_TRIANGLE_STRIP, 4, rect, NULL, red);
   glSampleCoverage(0.5f, GL_TRUE);
   e2e_draw(GL_TRIANGLE_STRIP, 4, rect, NULL, green);
   glDisable(GL_SAMPLE_COVERAGE);
   (void)size;
}

static void scene_blend(int size)
{
   uint32_t rng = 0xb1e4d00du;
   glClearColor(0.2f, 0.1f, 0.05f, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   glEnable(GL_BLEND);
   glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
   for (int t = 0; t < 30; t++) {
      float pos[12], col[12];
      for (int k = 0; k < 3; k++) {
         pos[4 * k + 0] = (float)e2e_rand_range(&rng, -1100, 1100) / 1000.0f;
         pos[4 * k + 1] = (float)e2e_rand_range(&rng, -1100, 1100) / 1000.0f;
         pos[4 * k + 2] = 0.0f;
         pos[4 * k + 3] = 1.0f;
         for (int c = 0; c < 4; c++)
            col[4 * k + c] = (float)e2e_rand_range(&rng, 0, 255) / 255.0f;
      }
      e2e_draw(GL_TRIANGLES, 3, pos, col, NULL);
   }
   glDisable(GL_BLEND);
   (void)size;
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   struct fp_gl g;
   e2e_start(&g, &a, argc, argv, 64);
   const char *c = e2e_opt(&a, "case", "");
   glUseProgram(program());
   self_check(g.fbo, a.size);

   struct e2e_msaa m;
   e2e_errors += e2e_msaa_create(&m, a.size);
   if (!strcmp(c, "edges"))
      scene_edges(a.size);
   else if (!strcmp(c, "coverage"))
      scene_coverage(a.size);
   else if (!strcmp(c, "blend"))
      scene_blend(a.size);
   else
      fp_die("--case: edges, coverage or blend");
   e2e_msaa_resolve(&m, g.fbo);
   return e2e_finish(&g, &a, NULL);
}
