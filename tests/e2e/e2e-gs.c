/*
 * Geometry shaders (GL_OES_geometry_shader, GLSL ES 3.10; --case NAME,
 * 64x64 unless --size says):
 *
 *   layered   random triangles, each sent by the geometry shader into the
 *             four layers of a 2-D array texture (gl_Layer), a colour of
 *             its own in each and depth tested per layer; the fragment
 *             shader reads gl_Layer too.  The picture is the four layers
 *             side by side, each a quarter of the target.
 *   amplify   points grown into squares by the geometry shader, their
 *             colour fetched there from a texture (texelFetch: the texture
 *             unit, from a geometry shader), their primitive ID passed on
 *             to the fragment shader, which shades by it.
 *   points    each point made three by the geometry shader, each of its
 *             own size (gl_PointSize, GL_OES_geometry_point_size).
 *   viewports random triangles sent by the geometry shader into four
 *             viewports, the target's quarters (gl_ViewportIndex,
 *             GL_OES_viewport_array), each with a scissor of its own; the
 *             fragment shader reads gl_ViewportIndex into blue.
 *
 * Self-checks (errors fail the program on any driver): the context is GL ES
 * 3.1 with the extension; in layered, one triangle covering the centre,
 * read back from each layer, has that layer's colour; in amplify, the
 * centre square's colour is its texel's.
 */
#include "e2e_common.h"

#include <EGL/egl.h>
#include <GLES3/gl31.h>
#include <GLES2/gl2ext.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef GL_FRAMEBUFFER_ATTACHMENT_LAYERED_OES
#define GL_FRAMEBUFFER_ATTACHMENT_LAYERED_OES 0x8DA7
#endif

#define LAYERS 4

static unsigned char *ties;

/* vs, gs and fs linked, a_pos at location 0 and a_color at 1. */
static GLuint program3(const char *vs, const char *gs, const char *fs)
{
   static const char *const attribs[] = { "a_pos", "a_color", NULL };
   return fp_gl_program_gs(vs, gs, fs, attribs);
}

static const char vs_pass[] =
   "#version 310 es\n"
   "in vec4 a_pos;\n"
   "in vec4 a_color;\n"
   "out vec4 g_color;\n"
   "void main() { gl_Position = a_pos; g_color = a_color; }\n";

/* ---- layered ---- */

static const char gs_layers[] =
   "#version 310 es\n"
   "#extension GL_OES_geometry_shader : require\n"
   "layout(triangles) in;\n"
   "layout(triangle_strip, max_vertices = 12) out;\n"
   "in vec4 g_color[];\n"
   "out vec4 v_color;\n"
   "void main() {\n"
   "   for (int l = 0; l < 4; l++) {\n"
   "      for (int i = 0; i < 3; i++) {\n"
   "         gl_Layer = l;\n"
   "         gl_Position = gl_in[i].gl_Position;\n"
   "         v_color = vec4(g_color[i].rgb * (1.0 - 0.2 * float(l)), g_color[i].a);\n"
   "         EmitVertex();\n"
   "      }\n"
   "      EndPrimitive();\n"
   "   }\n"
   "}\n";

static const char fs_layers[] =
   "#version 310 es\n"
   "#extension GL_OES_geometry_shader : require\n"
   "precision highp float;\n"
   "in vec4 v_color;\n"
   "out vec4 o_color;\n"
   "void main() { o_color = vec4(v_color.rg, float(gl_Layer) / 3.0, 1.0); }\n";

/* The four layers side by side: quarter q of the target shows layer q. */
static const char fs_show[] =
   "#version 310 es\n"
   "precision highp float;\n"
   "precision highp sampler2DArray;\n"
   "uniform sampler2DArray u_layers;\n"
   "uniform int u_size;\n"
   "out vec4 o_color;\n"
   "void main() {\n"
   "   ivec2 p = ivec2(gl_FragCoord.xy);\n"
   "   int h = u_size / 2;\n"
   "   int q = (p.x >= h ? 1 : 0) + (p.y >= h ? 2 : 0);\n"
   "   o_color = texelFetch(u_layers, ivec3((p.x % h) * 2, (p.y % h) * 2, q), 0);\n"
   "}\n";

static void layered_target(int size, GLuint *fbo, GLuint *tex)
{
   void (*framebuffer_texture)(GLenum, GLenum, GLuint, GLint) =
      (void (*)(GLenum, GLenum, GLuint, GLint))eglGetProcAddress("glFramebufferTextureOES");
   if (!framebuffer_texture)
      fp_die("no glFramebufferTextureOES");
   GLuint ds;
   glGenTextures(1, tex);
   glBindTexture(GL_TEXTURE_2D_ARRAY, *tex);
   glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_RGBA8, size, size, LAYERS);
   glGenTextures(1, &ds);
   glBindTexture(GL_TEXTURE_2D_ARRAY, ds);
   glTexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_DEPTH24_STENCIL8, size, size, LAYERS);
   glGenFramebuffers(1, fbo);
   glBindFramebuffer(GL_FRAMEBUFFER, *fbo);
   framebuffer_texture(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, *tex, 0);
   framebuffer_texture(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, ds, 0);
   e2e_check(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE,
             "the layered framebuffer is not complete");
   GLint layered = 0;
   glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                         GL_FRAMEBUFFER_ATTACHMENT_LAYERED_OES, &layered);
   e2e_check(layered == GL_TRUE, "the colour attachment is not layered");
   glViewport(0, 0, size, size);
   glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
   glClearDepthf(1.0f);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

/* Layer l's pixel at the centre, read through a framebuffer of that layer. */
static void read_layer(GLuint tex, int l, int size, unsigned char px[4])
{
   GLuint f;
   glGenFramebuffers(1, &f);
   glBindFramebuffer(GL_READ_FRAMEBUFFER, f);
   glFramebufferTextureLayer(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, tex, 0, l);
   glReadPixels(size / 2, size / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
   glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
   glDeleteFramebuffers(1, &f);
}

static void scene_layered(struct fp_gl *g, int size)
{
   GLuint fbo, tex;
   const int big = 2 * size;          /* each layer shown at half its size */
   layered_target(big, &fbo, &tex);
   glUseProgram(program3(vs_pass, gs_layers, fs_layers));
   glEnable(GL_DEPTH_TEST);

   /* the self-check's triangle first: over the centre, at the back */
   const float check_pos[] = { -0.5f, -0.5f, 0.9f, 1, 0.5f, -0.5f, 0.9f, 1, 0, 0.5f, 0.9f, 1 };
   const float check_col[4] = { 1.0f, 0.5f, 0.0f, 1.0f };
   e2e_draw(GL_TRIANGLES, 3, check_pos, NULL, check_col);
   for (int l = 0; l < LAYERS && !e2e_errors; l++) {
      unsigned char px[4];
      read_layer(tex, l, big, px);
      const int want[3] = { (int)(255 * (1.0f - 0.2f * l) + 0.5f),
                            (int)(127.5f * (1.0f - 0.2f * l) + 0.5f), (int)(255 * l / 3.0f + 0.5f) };
      printf("stat: layer%d=%u,%u,%u\n", l, px[0], px[1], px[2]);
      char what[96];
      snprintf(what, sizeof what, "layer %d's centre is not its colour", l);
      e2e_check(abs(px[0] - want[0]) <= 2 && abs(px[1] - want[1]) <= 2 &&
                   abs(px[2] - want[2]) <= 2, what);
   }

   /* random triangles on the 1/256 grid, nearer than the first */
   uint32_t seed = 0x67656f6du;
   for (int t = 0; t < 24; t++) {
      float pos[12], col[12];
      for (int i = 0; i < 3; i++) {
         pos[4 * i + 0] = e2e_ndc(e2e_rand_range(&seed, -8, big + 8) * E2E_SUB, big);
         pos[4 * i + 1] = e2e_ndc(e2e_rand_range(&seed, -8, big + 8) * E2E_SUB, big);
         pos[4 * i + 2] = (float)e2e_rand_range(&seed, -80, 80) / 100.0f;
         pos[4 * i + 3] = 1.0f;
         col[4 * i + 0] = (float)e2e_rand_range(&seed, 0, 255) / 255.0f;
         col[4 * i + 1] = (float)e2e_rand_range(&seed, 0, 255) / 255.0f;
         col[4 * i + 2] = 0.0f;
         col[4 * i + 3] = 1.0f;
      }
      e2e_draw(GL_TRIANGLES, 3, pos, col, NULL);
   }
   glDisable(GL_DEPTH_TEST);

   /* the layers into the picture */
   glBindFramebuffer(GL_FRAMEBUFFER, g->fbo);
   glViewport(0, 0, size, size);
   const char vs_quad[] = "#version 310 es\nin vec4 a_pos;\nvoid main() { gl_Position = a_pos; }\n";
   GLuint show = e2e_program(vs_quad, fs_show, NULL);
   glUseProgram(show);
   glBindTexture(GL_TEXTURE_2D_ARRAY, tex);
   glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
   glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
   glUniform1i(glGetUniformLocation(show, "u_size"), size);
   const float quad[] = { -1, -1, 0, 1, 1, -1, 0, 1, -1, 1, 0, 1, 1, 1, 0, 1 };
   const float white[4] = { 1, 1, 1, 1 };
   e2e_draw(GL_TRIANGLE_STRIP, 4, quad, NULL, white);
}

/* ---- amplify ---- */

static const char gs_squares[] =
   "#version 310 es\n"
   "#extension GL_OES_geometry_shader : require\n"
   "precision highp float;\n"
   "layout(points) in;\n"
   "layout(triangle_strip, max_vertices = 4) out;\n"
   "uniform highp sampler2D u_tex;\n"
   "uniform float u_half;\n"
   "in vec4 g_color[];\n"
   "out vec4 v_color;\n"
   "void main() {\n"
   "   vec4 c = texelFetch(u_tex, ivec2(g_color[0].xy * 7.0 + 0.5), 0);\n"
   "   for (int i = 0; i < 4; i++) {\n"
   "      vec2 d = vec2(i % 2 == 0 ? -u_half : u_half, i < 2 ? -u_half : u_half);\n"
   "      gl_Position = gl_in[0].gl_Position + vec4(d, 0.0, 0.0);\n"
   "      gl_PrimitiveID = gl_PrimitiveIDIn;\n"
   "      v_color = c;\n"
   "      EmitVertex();\n"
   "   }\n"
   "   EndPrimitive();\n"
   "}\n";

static const char fs_squares[] =
   "#version 310 es\n"
   "#extension GL_OES_geometry_shader : require\n"
   "precision highp float;\n"
   "in vec4 v_color;\n"
   "out vec4 o_color;\n"
   "void main() { o_color = vec4(v_color.rgb, 1.0) * (1.0 - float(gl_PrimitiveID % 4) * 0.1); }\n";

static void scene_amplify(int size)
{
   /* an 8x8 texture of distinct colours */
   unsigned char texels[8 * 8 * 4];
   for (int i = 0; i < 64; i++) {
      texels[4 * i + 0] = (unsigned char)(i * 4);
      texels[4 * i + 1] = (unsigned char)(255 - i * 3);
      texels[4 * i + 2] = (unsigned char)((i * 37) & 255);
      texels[4 * i + 3] = 255;
   }
   GLuint tex;
   glGenTextures(1, &tex);
   glBindTexture(GL_TEXTURE_2D, tex);
   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
   e2e_tex_params(GL_TEXTURE_2D, GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_EDGE);
   GLuint p = program3(vs_pass, gs_squares, fs_squares);
   glUseProgram(p);
   /* squares of 6 pixels on the grid's centres */
   glUniform1f(glGetUniformLocation(p, "u_half"), 3.0f / (float)size);
   glClearColor(0, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT);

   /* point 0 at the centre, texel (3, 5) */
   enum { N = 49 };
   float pos[4 * N], col[4 * N];
   uint32_t seed = 0x616d706cu;
   for (int i = 0; i < N; i++) {
      const int px = i == 0 ? size / 2 : e2e_rand_range(&seed, 2, size - 3);
      const int py = i == 0 ? size / 2 : e2e_rand_range(&seed, 2, size - 3);
      pos[4 * i + 0] = e2e_ndc(px * E2E_SUB, size);
      pos[4 * i + 1] = e2e_ndc(py * E2E_SUB, size);
      pos[4 * i + 2] = 0.0f;
      pos[4 * i + 3] = 1.0f;
      col[4 * i + 0] = i == 0 ? 3.0f / 7.0f : (float)e2e_rand_range(&seed, 0, 7) / 7.0f;
      col[4 * i + 1] = i == 0 ? 5.0f / 7.0f : (float)e2e_rand_range(&seed, 0, 7) / 7.0f;
      col[4 * i + 2] = 0.0f;
      col[4 * i + 3] = 1.0f;
   }
   /* the centre's square drawn alone first: its colour is texel (3, 5)'s */
   e2e_draw(GL_POINTS, 1, pos, col, NULL);
   unsigned char px[4];
   glReadPixels(size / 2, size / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
   const unsigned char *want = &texels[4 * (5 * 8 + 3)];
   printf("stat: centre=%u,%u,%u\n", px[0], px[1], px[2]);
   e2e_check(abs(px[0] - want[0]) <= 1 && abs(px[1] - want[1]) <= 1 && abs(px[2] - want[2]) <= 1,
             "the centre square's colour is not its texel's");
   e2e_draw(GL_POINTS, N, pos, col, NULL);
}

/* ---- points ---- */

static const char gs_points[] =
   "#version 310 es\n"
   "#extension GL_OES_geometry_shader : require\n"
   "#extension GL_OES_geometry_point_size : require\n"
   "layout(points) in;\n"
   "layout(points, max_vertices = 3) out;\n"
   "uniform float u_step;\n"
   "in vec4 g_color[];\n"
   "out vec4 v_color;\n"
   "void main() {\n"
   "   for (int i = 0; i < 3; i++) {\n"
   "      gl_Position = gl_in[0].gl_Position + vec4(float(i) * u_step, 0.0, 0.0, 0.0);\n"
   "      gl_PointSize = 1.0 + float(i + gl_PrimitiveIDIn % 3) * 2.0;\n"
   "      v_color = g_color[0] * (1.0 - 0.25 * float(i));\n"
   "      EmitVertex();\n"
   "      EndPrimitive();\n"
   "   }\n"
   "}\n";

static const char fs_points[] =
   "#version 310 es\n"
   "precision highp float;\n"
   "in vec4 v_color;\n"
   "out vec4 o_color;\n"
   "void main() { o_color = vec4(v_color.rgb, 1.0); }\n";

static void scene_points(int size)
{
   e2e_check(e2e_has_extension("GL_OES_geometry_point_size"),
             "GL_OES_geometry_point_size is not exposed");
   if (e2e_errors)
      return;
   GLuint p = program3(vs_pass, gs_points, fs_points);
   glUseProgram(p);
   glUniform1f(glGetUniformLocation(p, "u_step"), 12.0f * 2.0f / (float)size);
   glClearColor(0, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   enum { N = 30 };
   float pos[4 * N], col[4 * N];
   uint32_t seed = 0x706f696eu;
   for (int i = 0; i < N; i++) {
      /* pixel centres: a point's square is the same on any rule */
      const int px = i == 0 ? 8 : e2e_rand_range(&seed, 0, size - 30);
      const int py = i == 0 ? size / 2 : e2e_rand_range(&seed, 0, size - 1);
      pos[4 * i + 0] = e2e_ndc(px * E2E_SUB + E2E_SUB / 2, size);
      pos[4 * i + 1] = e2e_ndc(py * E2E_SUB + E2E_SUB / 2, size);
      pos[4 * i + 2] = 0.0f;
      pos[4 * i + 3] = 1.0f;
      col[4 * i + 0] = (float)e2e_rand_range(&seed, 64, 255) / 255.0f;
      col[4 * i + 1] = (float)e2e_rand_range(&seed, 64, 255) / 255.0f;
      col[4 * i + 2] = (float)e2e_rand_range(&seed, 0, 255) / 255.0f;
      col[4 * i + 3] = 1.0f;
   }
   e2e_draw(GL_POINTS, N, pos, col, NULL);
   /* point 0's copies are 1, 3 and 5 pixels wide, 12 pixels apart: the
    * third lights 5 pixels of its row, the first only its own */
   const int x0 = 8, y0 = size / 2;
   unsigned char row[64 * 4];
   if (size == 64) {
      glReadPixels(0, y0, size, 1, GL_RGBA, GL_UNSIGNED_BYTE, row);
      int lit_first = 0, lit_third = 0;
      for (int x = x0 - 2; x <= x0 + 2; x++)
         lit_first += row[4 * x] || row[4 * x + 1];
      for (int x = x0 + 24 - 2; x <= x0 + 24 + 2; x++)
         lit_third += row[4 * x] || row[4 * x + 1];
      printf("stat: point0=%d,%d\n", lit_first, lit_third);
      e2e_check(lit_third == 5, "point 0's third copy is not 5 pixels wide");
   }
}

/* ---- viewports ---- */

static const char gs_viewports[] =
   "#version 310 es\n"
   "#extension GL_OES_geometry_shader : require\n"
   "#extension GL_OES_viewport_array : require\n"
   "layout(triangles) in;\n"
   "layout(triangle_strip, max_vertices = 12) out;\n"
   "in vec4 g_color[];\n"
   "out vec4 v_color;\n"
   "void main() {\n"
   "   for (int v = 0; v < 4; v++) {\n"
   "      for (int i = 0; i < 3; i++) {\n"
   "         gl_ViewportIndex = v;\n"
   "         gl_Position = gl_in[i].gl_Position;\n"
   "         v_color = g_color[i];\n"
   "         EmitVertex();\n"
   "      }\n"
   "      EndPrimitive();\n"
   "   }\n"
   "}\n";

/* gl_ViewportIndex read in the fragment shader too */
static const char fs_viewports[] =
   "#version 310 es\n"
   "#extension GL_OES_viewport_array : require\n"
   "precision highp float;\n"
   "in vec4 v_color;\n"
   "out vec4 o_color;\n"
   "void main() { o_color = vec4(v_color.rg, float(gl_ViewportIndex) / 3.0, 1.0); }\n";

static void scene_viewports(int size)
{
   e2e_check(e2e_has_extension("GL_OES_viewport_array"), "GL_OES_viewport_array is not exposed");
   if (e2e_errors)
      return;
   void (*viewports)(GLuint, GLsizei, const GLfloat *) =
      (void (*)(GLuint, GLsizei, const GLfloat *))eglGetProcAddress("glViewportArrayvOES");
   void (*scissors)(GLuint, GLsizei, const GLint *) =
      (void (*)(GLuint, GLsizei, const GLint *))eglGetProcAddress("glScissorArrayvOES");
   if (!viewports || !scissors)
      fp_die("no glViewportArrayvOES or glScissorArrayvOES");
   const int h = size / 2;
   GLfloat vp[16];
   GLint sc[16];
   for (int v = 0; v < 4; v++) {
      const int x = (v & 1) * h, y = (v >> 1) * h;
      vp[4 * v + 0] = (float)x;
      vp[4 * v + 1] = (float)y;
      vp[4 * v + 2] = (float)h;
      vp[4 * v + 3] = (float)h;
      /* each scissor cuts its quarter differently: inset v + 1 pixels on
       * the left, 2v on the top */
      sc[4 * v + 0] = x + v + 1;
      sc[4 * v + 1] = y;
      sc[4 * v + 2] = h - v - 1;
      sc[4 * v + 3] = h - 2 * v;
   }
   viewports(0, 4, vp);
   scissors(0, 4, sc);
   glEnable(GL_SCISSOR_TEST);
   GLuint p = program3(vs_pass, gs_viewports, fs_viewports);
   glUseProgram(p);
   glClearColor(0, 0, 0, 1);
   glDisable(GL_SCISSOR_TEST);
   glClear(GL_COLOR_BUFFER_BIT);
   glEnable(GL_SCISSOR_TEST);

   /* the self-check: a triangle over all of clip space lights each quarter
    * up to its scissor and no further */
   const float all[] = { -1, -1, 0, 1, 3, -1, 0, 1, -1, 3, 0, 1 };
   const float white[4] = { 1, 1, 1, 1 };
   e2e_draw(GL_TRIANGLES, 3, all, NULL, white);
   for (int v = 0; v < 4; v++) {
      unsigned char in[4], out[4];
      const int y = (v >> 1) * h + 1;
      glReadPixels(sc[4 * v + 0], y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, in);
      glReadPixels(sc[4 * v + 0] - 1, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
      char what[80];
      snprintf(what, sizeof what, "viewport %d is not lit up to its scissor and no further", v);
      e2e_check(in[0] == 255 && out[0] == 0, what);
   }
   glClear(GL_COLOR_BUFFER_BIT);
   uint32_t seed = 0x76696577u;
   for (int t = 0; t < 16; t++) {
      float pos[12], col[12];
      for (int i = 0; i < 3; i++) {
         pos[4 * i + 0] = e2e_ndc(e2e_rand_range(&seed, -4, h + 4) * E2E_SUB, h);
         pos[4 * i + 1] = e2e_ndc(e2e_rand_range(&seed, -4, h + 4) * E2E_SUB, h);
         pos[4 * i + 2] = 0.0f;
         pos[4 * i + 3] = 1.0f;
         col[4 * i + 0] = (float)e2e_rand_range(&seed, 0, 255) / 255.0f;
         col[4 * i + 1] = (float)e2e_rand_range(&seed, 0, 255) / 255.0f;
         col[4 * i + 2] = 0.0f;
         col[4 * i + 3] = 1.0f;
      }
      e2e_draw(GL_TRIANGLES, 3, pos, col, NULL);
      /* pixels where the fill rule alone decides, in each quarter */
      struct e2e_tri tri;
      for (int i = 0; i < 3; i++) {
         tri.x[i] = (int32_t)lroundf((pos[4 * i + 0] + 1.0f) * 0.5f * (float)(h * E2E_SUB));
         tri.y[i] = (int32_t)lroundf((pos[4 * i + 1] + 1.0f) * 0.5f * (float)(h * E2E_SUB));
      }
      unsigned char quarter[32 * 32 * 4];
      if (ties && h <= 32) {
         memset(quarter, 0, sizeof quarter);
         e2e_tri_ties(&tri, h, quarter);
         for (int v = 0; v < 4; v++) {
            const int x0 = (v & 1) * h, top = size - (v >> 1) * h - h;
            for (int r = 0; r < h; r++)
               for (int c = 0; c < h; c++)
                  ties[4 * ((size_t)(top + r) * (size_t)size + (size_t)(x0 + c))] |=
                     quarter[4 * (r * h + c)];
         }
      }
   }
   glDisable(GL_SCISSOR_TEST);
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   struct fp_gl g;
   e2e_start(&g, &a, argc, argv, 64);
   const char *c = e2e_opt(&a, "case", "");
   if (!strcmp(c, "viewports")) {
      ties = calloc((size_t)a.size * (size_t)a.size, 4);
      if (!ties)
         fp_die("out of memory");
   }
   e2e_check(e2e_check_es31(), "the context is not GL ES 3.1");
   e2e_check(e2e_has_extension("GL_OES_geometry_shader"), "GL_OES_geometry_shader is not exposed");
   if (!strcmp(c, "layered")) {
      if (!e2e_errors)
         scene_layered(&g, a.size);
   } else if (!strcmp(c, "amplify")) {
      if (!e2e_errors)
         scene_amplify(a.size);
   } else if (!strcmp(c, "points")) {
      if (!e2e_errors)
         scene_points(a.size);
   } else if (!strcmp(c, "viewports")) {
      if (!e2e_errors)
         scene_viewports(a.size);
   } else {
      fp_die("--case: layered, amplify, points or viewports");
   }
   const int status = e2e_finish(&g, &a, ties);
   free(ties);
   return status;
}
