/*
 * Shaders that read the target, and blending with a second source, in
 * GL ES 3.0 (--case NAME, 64x64 unless --size says):
 *
 *   fetch        EXT_shader_framebuffer_fetch: random Gouraud triangles,
 *                each pixel becomes |last - colour| (a difference blend no
 *                fixed-function blend can do), so every triangle reads
 *                what the ones before it wrote
 *   fetch-msaa   the same with flat triangles into a 4x multisampled FBO,
 *                resolved by a blit: the shader reads and writes each
 *                sample, so edge pixels hold each sample's own history
 *   dualsrc      EXT_blend_func_extended: output 1 as the blend factor,
 *                src0 * src1 + dst * (1 - src1)
 *   advanced     KHR_blend_equation_advanced: multiply, screen, overlay and
 *                difference in turn, which Mesa builds from framebuffer
 *                fetch
 *
 * Self-checks (errors fail the program on any driver): the extension is
 * there, and a full-target draw of `last + (0.25, 0.5, 0, 0)` over a clear
 * to (0.5, 0.25, 0.2, 1) reads back (0.75, 0.75, 0.2, 1) within 2/255.
 */
#include "e2e_common.h"

#include <GLES3/gl3.h>
#include <GLES2/gl2ext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Pixels whose centre lies on a triangle's edge, where the fill rule alone
 * decides (left out of the comparison); NULL in the multisampled case,
 * whose samples are not at the centres. */
static unsigned char *ties;

static GLuint fetch_program(const char *body)
{
   char fs[1024];
   snprintf(fs, sizeof fs,
            "#version 300 es\n"
            "#extension GL_EXT_shader_framebuffer_fetch : require\n"
            "precision highp float;\n"
            "in vec4 v_color;\n"
            "inout vec4 o_color;\n"
            "void main() { %s }\n", body);
   return e2e_color_program_es3(fs);
}

/* The fetched colour reaches the shader: last + (0.25, 0.5, 0, 0). */
static void self_check_fetch(int size)
{
   glUseProgram(fetch_program("o_color = o_color + vec4(0.25, 0.5, 0.0, 0.0);"));
   glClearColor(0.5f, 0.25f, 0.2f, 1.0f);
   glClear(GL_COLOR_BUFFER_BIT);
   const float quad[] = { -1, -1, 0, 1, 1, -1, 0, 1, -1, 1, 0, 1, 1, 1, 0, 1 };
   const float white[4] = { 1, 1, 1, 1 };
   e2e_draw(GL_TRIANGLE_STRIP, 4, quad, NULL, white);
   unsigned char px[4];
   glReadPixels(size / 2, size / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
   printf("stat: fetch_check=%u,%u,%u,%u\n", px[0], px[1], px[2], px[3]);
   const int want[4] = { 191, 191, 51, 255 };
   bool ok = true;
   for (int c = 0; c < 4; c++)
      ok = ok && abs((int)px[c] - want[c]) <= 2;
   e2e_check(ok, "last + (0.25, 0.5, 0, 0) over (0.5, 0.25, 0.2, 1) is not (0.75, 0.75, 0.2, 1)");
}

/* n triangles with vertices on the sub-pixel grid inside the target (both
 * drivers hold them exactly, and neither clips), Gouraud or flat: a flat colour is the same wherever a driver
 * interpolates it, which leaves the multisampled case to coverage and the
 * fetch of each sample. */
static void random_triangles(uint32_t seed, int n, float alpha_lo, bool flat, int size)
{
   uint32_t rng = seed;
   /* inside the target: a clipped vertex would leave the grid */
   const int lo = 0, hi = size * E2E_SUB;
   for (int t = 0; t < n; t++) {
      float pos[12], col[12];
      struct e2e_tri tri;
      for (int k = 0; k < 3; k++) {
         tri.x[k] = e2e_rand_range(&rng, lo, hi);
         tri.y[k] = e2e_rand_range(&rng, lo, hi);
         pos[4 * k + 0] = e2e_ndc(tri.x[k], size);
         pos[4 * k + 1] = e2e_ndc(tri.y[k], size);
         pos[4 * k + 2] = 0.0f;
         pos[4 * k + 3] = 1.0f;
         for (int c = 0; c < 3; c++)
            col[4 * k + c] = (float)e2e_rand_range(&rng, 0, 255) / 255.0f;
         col[4 * k + 3] = alpha_lo + (1.0f - alpha_lo) *
                                        (float)e2e_rand_range(&rng, 0, 255) / 255.0f;
         if (flat && k > 0)
            memcpy(&col[4 * k], col, 4 * sizeof(float));
      }
      if (ties)
         e2e_tri_ties(&tri, size, ties);
      e2e_draw(GL_TRIANGLES, 3, pos, col, NULL);
   }
}

static void scene_fetch(bool flat, int size)
{
   glUseProgram(fetch_program("o_color = vec4(abs(o_color.rgb - v_color.rgb), 1.0);"));
   glClearColor(0.9f, 0.5f, 0.1f, 1.0f);
   glClear(GL_COLOR_BUFFER_BIT);
   random_triangles(0xfe7c4001u, 30, 1.0f, flat, size);
}

static void scene_dualsrc(int size)
{
   static const char *fs =
      "#version 300 es\n"
      "#extension GL_EXT_blend_func_extended : require\n"
      "precision highp float;\n"
      "in vec4 v_color;\n"
      "layout(location = 0, index = 0) out vec4 o_color;\n"
      "layout(location = 0, index = 1) out vec4 o_factor;\n"
      "void main() { o_color = v_color; o_factor = vec4(v_color.gbr * 0.8, 1.0); }\n";
   glUseProgram(e2e_color_program_es3(fs));
   glClearColor(0.2f, 0.4f, 0.6f, 1.0f);
   glClear(GL_COLOR_BUFFER_BIT);
   glEnable(GL_BLEND);
   glBlendFunc(GL_SRC1_COLOR_EXT, GL_ONE_MINUS_SRC1_COLOR_EXT);
   random_triangles(0xd0a15c01u, 30, 1.0f, false, size);
   glDisable(GL_BLEND);
}

static void scene_advanced(int size)
{
   static const char *fs =
      "#version 300 es\n"
      "#extension GL_KHR_blend_equation_advanced : require\n"
      "precision highp float;\n"
      "layout(blend_support_all_equations) out;\n"
      "in vec4 v_color;\n"
      "out vec4 o_color;\n"
      "void main() { o_color = v_color; }\n";
   static const GLenum eq[] = { GL_MULTIPLY_KHR, GL_SCREEN_KHR, GL_OVERLAY_KHR,
                                GL_DIFFERENCE_KHR };
   glUseProgram(e2e_color_program_es3(fs));
   glClearColor(0.6f, 0.3f, 0.5f, 1.0f);
   glClear(GL_COLOR_BUFFER_BIT);
   glEnable(GL_BLEND);
   for (int i = 0; i < 24; i++) {
      glBlendEquation(eq[i % 4]);
      random_triangles(0xadb1e000u + (uint32_t)i, 1, 0.4f, false, size);
   }
   glDisable(GL_BLEND);
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   struct fp_gl g;
   e2e_start(&g, &a, argc, argv, 64);
   const char *c = e2e_opt(&a, "case", "");
   if (strcmp(c, "fetch-msaa")) {
      ties = calloc((size_t)a.size * (size_t)a.size, 4);
      if (!ties)
         fp_die("out of memory");
   }

   if (!strcmp(c, "fetch") || !strcmp(c, "fetch-msaa")) {
      e2e_check(e2e_has_extension("GL_EXT_shader_framebuffer_fetch"),
                "GL_EXT_shader_framebuffer_fetch is not exposed");
      if (!e2e_errors)
         self_check_fetch(a.size);
      if (!e2e_errors && !strcmp(c, "fetch")) {
         scene_fetch(false, a.size);
      } else if (!e2e_errors) {
         struct e2e_msaa m;
         e2e_errors += e2e_msaa_create(&m, a.size);
         scene_fetch(true, a.size);
         e2e_msaa_resolve(&m, g.fbo);
      }
   } else if (!strcmp(c, "dualsrc")) {
      e2e_check(e2e_has_extension("GL_EXT_blend_func_extended"),
                "GL_EXT_blend_func_extended is not exposed");
      if (!e2e_errors)
         scene_dualsrc(a.size);
   } else if (!strcmp(c, "advanced")) {
      e2e_check(e2e_has_extension("GL_KHR_blend_equation_advanced"),
                "GL_KHR_blend_equation_advanced is not exposed");
      if (!e2e_errors)
         scene_advanced(a.size);
   } else {
      fp_die("--case: fetch, fetch-msaa, dualsrc or advanced");
   }
   const int status = e2e_finish(&g, &a, ties);
   free(ties);
   return status;
}
