/*
 * Tessellation shaders (GL_OES_tessellation_shader, GLSL ES 3.10; --case
 * NAME, 64x64 unless --size says):
 *
 *   quad       two quad patches, fractional odd spacing on the left,
 *              fractional even on the right, their levels fractional; the
 *              evaluation shader displaces each vertex by a texel of a
 *              4x4 texture (NEAREST) and colours it by a bilinear sample
 *              of an 8x8 one, both through textureLod: the texture unit,
 *              from a stage draw runs compiled.
 *   triangles  random triangle patches, each with levels of its own
 *              (equal spacing); the control shader writes per-patch
 *              outputs, a tint fetched there from a texture (texelFetch
 *              by gl_PrimitiveID) and a lift from its vertices' colours,
 *              which the evaluation shader mixes into every vertex.
 *   geometry   the triangles' tessellation followed by a geometry shader
 *              that shades each triangle by a texel it fetches: every stage
 *              draw compiles, each sampling through the unit.
 *
 * Self-checks (errors fail the program on any driver): the context is GL ES
 * 3.1 with the extension; in quad, the corner whose texel displaces it
 * inwards leaves the patch's corner pixel unlit and lights one inside; in
 * triangles and geometry, a patch drawn alone over the centre has its
 * tint times its colour there.
 */
#include "e2e_common.h"

#include <EGL/egl.h>
#include <GLES3/gl31.h>
#include <GLES2/gl2ext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef GL_PATCHES_OES
#define GL_PATCHES_OES 0x000E
#endif
#ifndef GL_PATCH_VERTICES_OES
#define GL_PATCH_VERTICES_OES 0x8E72
#endif

static void (*patch_parameteri)(GLenum, GLint);

static GLuint program(const char *vs, const char *tcs, const char *tes, const char *gs,
                      const char *fs)
{
   static const char *const attribs[] = { "a_pos", "a_color", NULL };
   return fp_gl_program_stages(vs, tcs, tes, gs, fs, attribs);
}

static const char vs_pass[] =
   "#version 310 es\n"
   "in vec4 a_pos;\n"
   "in vec4 a_color;\n"
   "out vec4 c_color;\n"
   "void main() { gl_Position = a_pos; c_color = a_color; }\n";

static const char fs_color[] =
   "#version 310 es\n"
   "precision highp float;\n"
   "in vec4 v_color;\n"
   "out vec4 o_color;\n"
   "void main() { o_color = vec4(v_color.rgb, 1.0); }\n";

static GLuint texture_rgba(int w, int h, const unsigned char *texels, GLenum filter)
{
   GLuint tex;
   glGenTextures(1, &tex);
   glBindTexture(GL_TEXTURE_2D, tex);
   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
   e2e_tex_params(GL_TEXTURE_2D, filter, filter, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
   return tex;
}

static void draw_patches(int vertices, int n, const float *pos, const float *col,
                         const float rgba[4])
{
   patch_parameteri(GL_PATCH_VERTICES_OES, vertices);
   e2e_draw(GL_PATCHES_OES, n, pos, col, rgba);
}

/* ---- quad ---- */

static const char tcs_quad[] =
   "#version 310 es\n"
   "#extension GL_OES_tessellation_shader : require\n"
   "layout(vertices = 4) out;\n"
   "uniform vec4 u_outer;\n"
   "uniform vec2 u_inner;\n"
   "in vec4 c_color[];\n"
   "out vec4 e_color[];\n"
   "void main() {\n"
   "   gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;\n"
   "   e_color[gl_InvocationID] = c_color[gl_InvocationID];\n"
   "   if (gl_InvocationID == 0) {\n"
   "      for (int i = 0; i < 4; i++) gl_TessLevelOuter[i] = u_outer[i];\n"
   "      gl_TessLevelInner[0] = u_inner.x;\n"
   "      gl_TessLevelInner[1] = u_inner.y;\n"
   "   }\n"
   "}\n";

/* control points 0..3: bottom left, bottom right, top right, top left */
#define TES_QUAD(SPACING)                                                                 \
   "#version 310 es\n"                                                                    \
   "#extension GL_OES_tessellation_shader : require\n"                                    \
   "layout(quads, " SPACING ", ccw) in;\n"                                                \
   "precision highp float;\n"                                                             \
   "uniform highp sampler2D u_disp;\n"                                                    \
   "uniform highp sampler2D u_color;\n"                                                   \
   "uniform float u_amp;\n"                                                               \
   "in vec4 e_color[];\n"                                                                 \
   "out vec4 v_color;\n"                                                                  \
   "void main() {\n"                                                                      \
   "   vec2 uv = gl_TessCoord.xy;\n"                                                      \
   "   vec4 b = mix(gl_in[0].gl_Position, gl_in[1].gl_Position, uv.x);\n"                \
   "   vec4 t = mix(gl_in[3].gl_Position, gl_in[2].gl_Position, uv.x);\n"                \
   "   vec4 p = mix(b, t, uv.y);\n"                                                       \
   "   vec4 d = textureLod(u_disp, uv, 0.0);\n"                                           \
   "   p.xy += (d.rg - 0.5) * u_amp;\n"                                                   \
   "   gl_Position = p;\n"                                                                \
   "   v_color = textureLod(u_color, uv, 0.0) * (0.6 + 0.4 * e_color[0]);\n"              \
   "}\n"

static const char tes_quad_odd[] = TES_QUAD("fractional_odd_spacing");
static const char tes_quad_even[] = TES_QUAD("fractional_even_spacing");

static void scene_quad(int size)
{
   /* displacement: every texel in place (0.5) but the first, which moves
    * its corner of the patch inwards on both axes (1.0); 4x4, NEAREST */
   unsigned char disp[4 * 4 * 4];
   uint32_t seed = 0x74657373u;
   for (int i = 0; i < 16; i++) {
      disp[4 * i + 0] = (unsigned char)(i == 0 ? 255 : e2e_rand_range(&seed, 96, 160));
      disp[4 * i + 1] = (unsigned char)(i == 0 ? 255 : e2e_rand_range(&seed, 96, 160));
      disp[4 * i + 2] = 0;
      disp[4 * i + 3] = 255;
   }
   unsigned char colors[8 * 8 * 4];
   for (int i = 0; i < 64; i++) {
      colors[4 * i + 0] = (unsigned char)e2e_rand_range(&seed, 0, 255);
      colors[4 * i + 1] = (unsigned char)e2e_rand_range(&seed, 0, 255);
      colors[4 * i + 2] = (unsigned char)e2e_rand_range(&seed, 0, 255);
      colors[4 * i + 3] = 255;
   }
   glActiveTexture(GL_TEXTURE0);
   texture_rgba(4, 4, disp, GL_NEAREST);
   glActiveTexture(GL_TEXTURE1);
   texture_rgba(8, 8, colors, GL_LINEAR);
   glActiveTexture(GL_TEXTURE0);

   glClearColor(0, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   /* the amplitude: a full texel (1.0) moves its vertices 6 pixels */
   const float amp = 2.0f * 12.0f / (float)size;
   const float outer[4] = { 3.3f, 5.7f, 2.4f, 4.9f }, inner[2] = { 4.6f, 3.2f };
   for (int half = 0; half < 2; half++) {
      GLuint p = program(vs_pass, tcs_quad, half ? tes_quad_even : tes_quad_odd, NULL, fs_color);
      glUseProgram(p);
      glUniform1i(glGetUniformLocation(p, "u_disp"), 0);
      glUniform1i(glGetUniformLocation(p, "u_color"), 1);
      glUniform1f(glGetUniformLocation(p, "u_amp"), amp);
      glUniform4fv(glGetUniformLocation(p, "u_outer"), 1, outer);
      glUniform2fv(glGetUniformLocation(p, "u_inner"), 1, inner);
      /* the half's patch, 4 pixels in from its edges, off the pixel grid */
      const int x0 = half * size / 2 + 4, x1 = (half + 1) * size / 2 - 4;
      const int y0 = 4, y1 = size - 4;
      const int32_t sx0 = x0 * E2E_SUB + 37, sx1 = x1 * E2E_SUB - 21;
      const int32_t sy0 = y0 * E2E_SUB + 53, sy1 = y1 * E2E_SUB - 90;
      const float pos[16] = {
         e2e_ndc(sx0, size), e2e_ndc(sy0, size), 0, 1, e2e_ndc(sx1, size), e2e_ndc(sy0, size), 0, 1,
         e2e_ndc(sx1, size), e2e_ndc(sy1, size), 0, 1, e2e_ndc(sx0, size), e2e_ndc(sy1, size), 0, 1,
      };
      const float col[4] = { half ? 0.3f : 1.0f, 0.6f, half ? 1.0f : 0.2f, 1.0f };
      draw_patches(4, 4, pos, NULL, col);
      /* the first texel's corner, moved 6 pixels inwards: the patch's
       * corner pixel stays dark, one 9 pixels inside is lit */
      unsigned char out[4], in[4];
      glReadPixels(x0, y0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
      glReadPixels(x0 + 9, y0 + 9, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, in);
      printf("stat: corner%d=%u,%u inside%d=%u,%u\n", half, out[0], out[1], half, in[0], in[1]);
      e2e_check(!out[0] && !out[1] && !out[2], "the displaced corner's pixel is lit");
      e2e_check(in[0] || in[1] || in[2], "the pixel inside the displaced corner is dark");
   }
}

/* ---- triangles ---- */

static const char tcs_tri[] =
   "#version 310 es\n"
   "#extension GL_OES_tessellation_shader : require\n"
   "layout(vertices = 3) out;\n"
   "precision highp float;\n"
   "uniform highp sampler2D u_tint;\n"
   "in vec4 c_color[];\n"
   "out vec4 e_color[];\n"
   "patch out vec4 p_tint;\n"
   "patch out float p_lift;\n"
   "void main() {\n"
   "   gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;\n"
   "   e_color[gl_InvocationID] = c_color[gl_InvocationID];\n"
   "   if (gl_InvocationID == 0) {\n"
   "      int id = gl_PrimitiveID;\n"
   "      p_tint = texelFetch(u_tint, ivec2(id % 4, id / 4 % 4), 0);\n"
   "      vec3 sum = c_color[0].rgb + c_color[1].rgb + c_color[2].rgb;\n"
   "      p_lift = (sum.r + sum.g + sum.b) / 9.0 * 0.25;\n"
   "      for (int i = 0; i < 3; i++) gl_TessLevelOuter[i] = float(1 + (id + i) % 4);\n"
   "      gl_TessLevelInner[0] = float(1 + id % 3);\n"
   "   }\n"
   "}\n";

static const char tes_tri[] =
   "#version 310 es\n"
   "#extension GL_OES_tessellation_shader : require\n"
   "layout(triangles, equal_spacing, cw) in;\n"
   "precision highp float;\n"
   "in vec4 e_color[];\n"
   "patch in vec4 p_tint;\n"
   "patch in float p_lift;\n"
   "out vec4 v_color;\n"
   "void main() {\n"
   "   vec3 w = gl_TessCoord;\n"
   "   gl_Position = w.x * gl_in[0].gl_Position + w.y * gl_in[1].gl_Position +\n"
   "                 w.z * gl_in[2].gl_Position;\n"
   "   vec4 c = w.x * e_color[0] + w.y * e_color[1] + w.z * e_color[2];\n"
   /* each vertex its own shade: the tessellation shows in the colours */
   "   float k = fract(dot(w, vec3(3.0, 5.0, 7.0)));\n"
   "   v_color = c * p_tint + p_lift + 0.1 * k;\n"
   "}\n";

/* tessellated triangles, each shaded by a grey texel fetched here */
static const char gs_shade[] =
   "#version 310 es\n"
   "#extension GL_OES_geometry_shader : require\n"
   "layout(triangles) in;\n"
   "layout(triangle_strip, max_vertices = 3) out;\n"
   "precision highp float;\n"
   "uniform highp sampler2D u_shade;\n"
   "in vec4 g_color[];\n"
   "out vec4 v_color;\n"
   "void main() {\n"
   "   vec4 s = texelFetch(u_shade, ivec2(gl_PrimitiveIDIn % 4, 0), 0);\n"
   "   for (int i = 0; i < 3; i++) {\n"
   "      gl_Position = gl_in[i].gl_Position;\n"
   "      v_color = g_color[i] * s;\n"
   "      EmitVertex();\n"
   "   }\n"
   "   EndPrimitive();\n"
   "}\n";

static void scene_triangles(int size, bool geometry)
{
   if (geometry) {
      e2e_check(e2e_has_extension("GL_OES_geometry_shader"),
                "GL_OES_geometry_shader is not exposed");
      if (e2e_errors)
         return;
   }
   /* tints: a 4x4 texture, texel 0 white; shades: 4x1, greys of 0.8 and
    * more, which keep a colour of 1.25 white (the self-check) */
   unsigned char tint[4 * 4 * 4], shade[4 * 4];
   uint32_t seed = 0x74726973u;
   for (int i = 0; i < 16; i++)
      for (int c = 0; c < 4; c++)
         tint[4 * i + c] = (unsigned char)(i == 0 || c == 3 ? 255 : e2e_rand_range(&seed, 64, 255));
   for (int i = 0; i < 4; i++) {
      const int grey = e2e_rand_range(&seed, 208, 255);
      for (int c = 0; c < 4; c++)
         shade[4 * i + c] = (unsigned char)(c == 3 ? 255 : grey);
   }
   glActiveTexture(GL_TEXTURE0);
   texture_rgba(4, 4, tint, GL_NEAREST);
   glActiveTexture(GL_TEXTURE1);
   texture_rgba(4, 1, shade, GL_NEAREST);
   glActiveTexture(GL_TEXTURE0);
   const char *tes = tes_tri;
   char tes_gs[sizeof tes_tri + 64];
   if (geometry) {
      /* the evaluation shader's colour goes to the geometry shader */
      const char *at = strstr(tes_tri, "out vec4 v_color;");
      snprintf(tes_gs, sizeof tes_gs, "%.*sout vec4 g_color;%s", (int)(at - tes_tri), tes_tri,
               at + strlen("out vec4 v_color;"));
      char *v = strstr(tes_gs, "   v_color = c");
      if (!v)
         fp_die("no colour in the evaluation shader");
      memcpy(v, "   g_color", strlen("   g_color"));
      tes = tes_gs;
   }
   GLuint p = program(vs_pass, tcs_tri, tes, geometry ? gs_shade : NULL, fs_color);
   glUseProgram(p);
   glUniform1i(glGetUniformLocation(p, "u_tint"), 0);
   if (geometry)
      glUniform1i(glGetUniformLocation(p, "u_shade"), 1);
   glClearColor(0, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT);

   /* the self-check's patch first, alone (gl_PrimitiveID 0: the white
    * tint): black vertices, so the centre is the lift, 0, plus 0.1 times a
    * fraction, grey */
   const float big[] = { -1, -1, 0, 1, 3, -1, 0, 1, -1, 3, 0, 1 };
   const float black[4] = { 0, 0, 0, 1 };
   draw_patches(3, 3, big, NULL, black);
   unsigned char px[4];
   glReadPixels(size / 2, size / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
   printf("stat: centre=%u,%u,%u\n", px[0], px[1], px[2]);
   e2e_check(px[0] == px[1] && px[1] == px[2] && px[0] <= 26 && px[3] == 255,
             "the lone patch's centre is not grey within 0.1");
   /* white vertices: the tint (white) plus the lift (0.25) saturate */
   const float white[4] = { 1, 1, 1, 1 };
   draw_patches(3, 3, big, NULL, white);
   glReadPixels(size / 2, size / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
   e2e_check(px[0] == 255 && px[1] == 255 && px[2] == 255,
             "the lone white patch's centre is not white");
   glClear(GL_COLOR_BUFFER_BIT);

   /* random patches on the 1/256 grid, one draw */
   enum { N = 12 };
   float pos[4 * 3 * N], col[4 * 3 * N];
   for (int i = 0; i < 3 * N; i++) {
      pos[4 * i + 0] = e2e_ndc(e2e_rand_range(&seed, -8 * E2E_SUB, (size + 8) * E2E_SUB), size);
      pos[4 * i + 1] = e2e_ndc(e2e_rand_range(&seed, -8 * E2E_SUB, (size + 8) * E2E_SUB), size);
      pos[4 * i + 2] = 0.0f;
      pos[4 * i + 3] = 1.0f;
      for (int c = 0; c < 3; c++)
         col[4 * i + c] = (float)e2e_rand_range(&seed, 0, 255) / 255.0f * 0.7f;
      col[4 * i + 3] = 1.0f;
   }
   draw_patches(3, 3 * N, pos, col, NULL);
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   struct fp_gl g;
   e2e_start(&g, &a, argc, argv, 64);
   const char *c = e2e_opt(&a, "case", "");
   e2e_check(e2e_check_es31(), "the context is not GL ES 3.1");
   e2e_check(e2e_has_extension("GL_OES_tessellation_shader"),
             "GL_OES_tessellation_shader is not exposed");
   patch_parameteri = (void (*)(GLenum, GLint))eglGetProcAddress("glPatchParameteriOES");
   if (!patch_parameteri)
      fp_die("no glPatchParameteriOES");
   if (!strcmp(c, "quad")) {
      if (!e2e_errors)
         scene_quad(a.size);
   } else if (!strcmp(c, "triangles")) {
      if (!e2e_errors)
         scene_triangles(a.size, false);
   } else if (!strcmp(c, "geometry")) {
      if (!e2e_errors)
         scene_triangles(a.size, true);
   } else {
      fp_die("--case: quad, triangles or geometry");
   }
   return e2e_finish(&g, &a, NULL);
}
