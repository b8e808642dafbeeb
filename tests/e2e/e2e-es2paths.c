/*
 * GL ES 2 paths a wider conformance suite found wrong in fixpipe and right
 * in llvmpipe, one scene each (--case NAME), 64x64 unless --size says:
 *
 *   vs-cube        a mipmapped cube map sampled in the vertex shader: one
 *                  1-pixel point per pixel, coloured by textureCube (six
 *                  filter and wrap states) and textureCubeLod (LOD 0 to
 *                  3.5) at directions over every face
 *   proj-mip       texture2DProj (vec3, vec4) and texture2DProjLod in the
 *                  vertex shader, NEAREST_MIPMAP_NEAREST and
 *                  LINEAR_MIPMAP_NEAREST, q from 0.25 to 4
 *   points-viewport wide points (sizes 3 to 15) whose centres lie inside,
 *                  on and outside a viewport smaller than the target: GL ES
 *                  draws their pixels inside the viewport (llvmpipe's
 *                  d3d-style point clipping), not nothing
 *   half-float-rgb  an RGB half-float (OES_texture_half_float) texture as
 *                  the colour attachment, complete with
 *                  EXT_color_buffer_half_float (self-checked): a Gouraud
 *                  triangle with colours beyond [0, 1] drawn into it, then
 *                  the texture drawn into the target
 *   clip-control   GL_EXT_clip_control: must be exposed (self-checked), and
 *                  triangles drawn with the upper-left origin and the
 *                  [0, 1] depth range against a depth buffer
 */
#include "e2e_common.h"

#include <GLES2/gl2ext.h>
#include <EGL/egl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static bool has_ext(const char *name)
{
   const char *e = (const char *)glGetString(GL_EXTENSIONS);
   size_t n = strlen(name);
   for (const char *p = e; p && (p = strstr(p, name)); p += n)
      if ((p == e || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
         return true;
   return false;
}

/* A face's texels: a ramp, a checker and a face colour, so that a wrong
 * face, texel or weight shows. */
static void face_texels(unsigned char *p, int s, int face, int level)
{
   for (int y = 0; y < s; y++)
      for (int x = 0; x < s; x++) {
         unsigned char *t = p + (y * s + x) * 4;
         t[0] = (unsigned char)(s > 1 ? x * 255 / (s - 1) : 128);
         t[1] = (unsigned char)(s > 1 ? y * 255 / (s - 1) : 128);
         t[2] = (unsigned char)(face * 40 + (((x ^ y) & 1) ? 30 : 0));
         t[3] = (unsigned char)(255 - level * 60);
      }
}

static GLuint cube_texture(GLenum min, GLenum mag, GLenum wrap, bool mips)
{
   GLuint t;
   unsigned char p[16 * 16 * 4];
   glGenTextures(1, &t);
   glBindTexture(GL_TEXTURE_CUBE_MAP, t);
   for (int f = 0; f < 6; f++)
      for (int l = 0, s = 16; s >= 1 && (l == 0 || mips); l++, s /= 2) {
         face_texels(p, s, f, l);
         glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)f, l, GL_RGBA, s, s, 0, GL_RGBA,
                      GL_UNSIGNED_BYTE, p);
      }
   e2e_tex_params(GL_TEXTURE_CUBE_MAP, min, mag, wrap, wrap);
   return t;
}

/* The position of pixel (x, y)'s centre in clip space. */
static void pixel_pos(float *p, int x, int y, int size)
{
   p[0] = ((float)x + 0.5f) * 2.0f / (float)size - 1.0f;
   p[1] = ((float)y + 0.5f) * 2.0f / (float)size - 1.0f;
   p[2] = 0.0f;
   p[3] = 1.0f;
}

/* A program whose vertex shader `vs` (attributes a_pos and `attr1`) writes
 * v_col from a texture on unit 0, drawn as 1-pixel points; 0 (an error
 * counted) without vertex texture units. */
static GLuint vertex_texture_program(const char *vs, const char *attr1)
{
   static const char *fs =
      "precision mediump float;\nvarying vec4 v_col;\n"
      "void main() { gl_FragColor = v_col; }\n";
   GLint units = 0;
   glGetIntegerv(GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS, &units);
   e2e_check(units >= 1, "no vertex texture units");
   if (units < 1)
      return 0;
   GLuint prog = e2e_program(vs, fs, attr1);
   glUseProgram(prog);
   glUniform1i(glGetUniformLocation(prog, "u_tex"), 0);
   return prog;
}

/* n points from client arrays: attribute 0 and 1, four floats each. */
static void draw_points(const float *a0, const float *a1, int n)
{
   glEnableVertexAttribArray(0);
   glEnableVertexAttribArray(1);
   glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 0, a0);
   glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, 0, a1);
   glDrawArrays(GL_POINTS, 0, n);
}

static void vs_cube(int size)
{
   static const char *vs =
      "attribute vec4 a_pos;\nattribute vec4 a_dir;\n"
      "uniform samplerCube u_tex;\nuniform float u_explicit;\nvarying vec4 v_col;\n"
      "void main() {\n"
      "   v_col = u_explicit > 0.5 ? textureCubeLod(u_tex, a_dir.xyz, a_dir.w)\n"
      "                            : textureCube(u_tex, a_dir.xyz);\n"
      "   gl_Position = a_pos; gl_PointSize = 1.0;\n}\n";
   const GLuint prog = vertex_texture_program(vs, "a_dir");
   if (!prog)
      return;
   const GLint explicit_loc = glGetUniformLocation(prog, "u_explicit");

   /* eight bands of size/8 rows: six sampler states of textureCube, whose
    * level of detail in a vertex shader is 0 (GLSL ES 1.00: the base level
    * with the magnification filter; min and mag differ, so a LOD from the
    * four vertices of tgsi's quad would show), then textureCubeLod */
   static const struct { GLenum min, mag, wrap; bool lod; } band[8] = {
      { GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR, GL_CLAMP_TO_EDGE, false },
      { GL_LINEAR_MIPMAP_LINEAR, GL_NEAREST, GL_REPEAT, false },
      { GL_LINEAR, GL_NEAREST, GL_MIRRORED_REPEAT, false },
      { GL_NEAREST, GL_LINEAR, GL_CLAMP_TO_EDGE, false },
      { GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, GL_REPEAT, false },
      { GL_NEAREST_MIPMAP_LINEAR, GL_NEAREST, GL_CLAMP_TO_EDGE, false },
      { GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE, true },
      { GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE, true },
   };
   const int rows = size / 8;
   float *pos = malloc(sizeof(float) * 4 * (size_t)(size * rows));
   float *dir = malloc(sizeof(float) * 4 * (size_t)(size * rows));
   if (!pos || !dir)
      fp_die("out of memory");
   uint32_t rng = 12345;
   for (int b = 0; b < 8; b++) {
      GLuint t = cube_texture(band[b].min, band[b].mag, band[b].wrap, true);
      glUniform1f(explicit_loc, band[b].lod ? 1.0f : 0.0f);
      int n = 0;
      for (int y = b * rows; y < (b + 1) * rows; y++)
         for (int x = 0; x < size; x++, n++) {
            pixel_pos(pos + 4 * n, x, y, size);
            /* a major axis and two minor ones, the minor ones clear of
             * the face's edges: GL ES 2 filters a face on its own (clamped
             * at its edges), GL ES 3 across its edges (llvmpipe's context
             * is ES 3.2), so texels by an edge are not compared */
            float d[3];
            const int major = e2e_rand_range(&rng, 0, 2);
            const float sign = e2e_rand(&rng) & 1 ? 1.0f : -1.0f;
            for (int k = 0; k < 3; k++)
               d[k] = (float)e2e_rand_range(&rng, -600, 600) / 1000.0f;
            d[major] = sign;
            const float len = 0.5f + (float)e2e_rand_range(&rng, 0, 1000) / 500.0f;
            for (int k = 0; k < 3; k++)
               dir[4 * n + k] = d[k] * len;
            /* clear of the half-way LODs, where NEAREST_MIPMAP_NEAREST's
             * choice of level is the implementation's, and of the 2x2
             * level, where every bilinear tap is by an edge */
            dir[4 * n + 3] = (float)e2e_rand_range(&rng, 0, 18) / 10.0f + 0.03f;
         }
      draw_points(pos, dir, n);
      glDeleteTextures(1, &t);
   }
   free(pos);
   free(dir);
}

static void proj_mip(int size)
{
   /* in the vertex shader, one 1-pixel point per pixel: the implicit level
    * of detail is 0 there, texture2DProjLod's is the operand */
   static const char *vs =
      "attribute vec4 a_pos;\nattribute vec4 a_tc;\n"
      "uniform sampler2D u_tex;\nuniform int u_form;\nvarying vec4 v_col;\n"
      "void main() {\n"
      "   if (u_form == 0) v_col = texture2DProj(u_tex, a_tc.xyw);\n"
      "   else if (u_form == 1) v_col = texture2DProj(u_tex, a_tc);\n"
      "   else v_col = texture2DProjLod(u_tex, a_tc, a_tc.z);\n"
      "   gl_Position = a_pos; gl_PointSize = 1.0;\n}\n";
   const GLuint prog = vertex_texture_program(vs, "a_tc");
   if (!prog)
      return;
   const GLint form = glGetUniformLocation(prog, "u_form");
   /* six bands: the three forms with NEAREST_MIPMAP_NEAREST, then with
    * LINEAR_MIPMAP_NEAREST (magnification NEAREST: level 0 unfiltered) */
   const int rows = size / 8;
   float *pos = malloc(sizeof(float) * 4 * (size_t)(size * rows));
   float *tc = malloc(sizeof(float) * 4 * (size_t)(size * rows));
   if (!pos || !tc)
      fp_die("out of memory");
   uint32_t rng = 999;
   for (int b = 0; b < 6; b++) {
      GLuint t = e2e_mip_texture(32, 40, 200, 40, b < 3 ? GL_NEAREST_MIPMAP_NEAREST
                                                        : GL_LINEAR_MIPMAP_NEAREST, GL_NEAREST);
      glUniform1i(form, b % 3);
      int n = 0;
      for (int y = b * rows; y < (b + 1) * rows; y++)
         for (int x = 0; x < size; x++, n++) {
            pixel_pos(pos + 4 * n, x, y, size);
            /* s, t in (0.01, 0.99) once divided, clear of texel edges of
             * level 0 (32 texels: a quarter texel inside); q from 0.25 to 4 */
            const float q = (float)e2e_rand_range(&rng, 25, 400) / 100.0f;
            for (int k = 0; k < 2; k++) {
               const float texel = (float)e2e_rand_range(&rng, 0, 31);
               const float frac = (float)e2e_rand_range(&rng, 25, 75) / 100.0f;
               tc[4 * n + k] = (texel + frac) / 32.0f * q;
            }
            /* texture2DProjLod's LOD, clear of the half-way ones */
            tc[4 * n + 2] = (float)e2e_rand_range(&rng, 0, 4) + 0.2f;
            tc[4 * n + 3] = q;
         }
      draw_points(pos, tc, n);
      glDeleteTextures(1, &t);
   }
   free(pos);
   free(tc);
}

static void points_viewport(int size)
{
   static const char *vs =
      "attribute vec4 a_pos;\nattribute vec4 a_col;\nvarying vec4 v_col;\n"
      "void main() { v_col = a_col; gl_Position = vec4(a_pos.xy, 0.0, 1.0);\n"
      "              gl_PointSize = a_pos.z; }\n";
   static const char *fs =
      "precision mediump float;\nvarying vec4 v_col;\n"
      "void main() { gl_FragColor = v_col; }\n";
   GLuint prog = e2e_program(vs, fs, "a_col");
   glUseProgram(prog);
   /* a viewport in the middle, a quarter of the target's area, and one
    * at the target's corner; points along the viewport's edges */
   const int q = size / 4;
   const int vps[2][4] = { { q, q, 2 * q, 2 * q }, { 0, 0, q, q } };
   uint32_t rng = 777;
   for (int v = 0; v < 2; v++) {
      glViewport(vps[v][0], vps[v][1], vps[v][2], vps[v][3]);
      float pos[64 * 4], col[64 * 4];
      int n = 0;
      for (int side = 0; side < 4; side++)
         for (int i = 0; i < 16; i++, n++) {
            /* a coordinate along the side, and one across it: the centre
             * from a little inside to well outside (up to 8 px) */
            const float along = -1.0f + 2.0f * ((float)i + 0.5f) / 16.0f;
            const float px = 2.0f / (float)vps[v][2];
            const float across = 1.0f + px * ((float)e2e_rand_range(&rng, -6, 16) * 0.5f + 0.25f);
            const float sgn = side & 1 ? -1.0f : 1.0f;
            pos[4 * n + 0] = side < 2 ? sgn * across : along;
            pos[4 * n + 1] = side < 2 ? along : sgn * across;
            pos[4 * n + 2] = (float)(3 + 2 * e2e_rand_range(&rng, 0, 6));
            pos[4 * n + 3] = 1.0f;
            col[4 * n + 0] = (float)(side & 1);
            col[4 * n + 1] = (float)(side >> 1);
            col[4 * n + 2] = (float)i / 15.0f;
            col[4 * n + 3] = 1.0f;
         }
      draw_points(pos, col, n);
   }
   glViewport(0, 0, size, size);
}

static void half_float_rgb(struct fp_gl *g, int size)
{
   if (!has_ext("GL_OES_texture_half_float") || !has_ext("GL_EXT_color_buffer_half_float")) {
      printf("stat: half_float=absent\n");
      return;
   }
   GLuint t, fbo;
   glGenTextures(1, &t);
   glBindTexture(GL_TEXTURE_2D, t);
   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, size, size, 0, GL_RGB, GL_HALF_FLOAT_OES, NULL);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
   glGenFramebuffers(1, &fbo);
   glBindFramebuffer(GL_FRAMEBUFFER, fbo);
   glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t, 0);
   /* EXT_color_buffer_half_float: RGB16F is colour-renderable (Mesa's
    * rule for every driver), so the framebuffer is complete and must draw */
   const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
   e2e_check(status == GL_FRAMEBUFFER_COMPLETE, "RGB half-float framebuffer incomplete");
   if (status == GL_FRAMEBUFFER_COMPLETE) {
      glViewport(0, 0, size, size);
      glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
      glClear(GL_COLOR_BUFFER_BIT);
      glUseProgram(e2e_color_program());
      /* colours beyond [0, 1] stay unclamped in a float target until the
       * texture is drawn into the RGBA8 target */
      static const float pos[12] = { -0.9f, -0.8f, 0, 1, 0.85f, -0.6f, 0, 1, -0.3f, 0.9f, 0, 1 };
      static const float col[12] = { 1.5f, 0, 0.2f, 1, 0, 0.6f, -0.5f, 1, 0.1f, 0.3f, 1, 1 };
      e2e_draw(GL_TRIANGLES, 3, pos, col, NULL);
   }
   glBindFramebuffer(GL_FRAMEBUFFER, g->fbo);
   glClearColor(0, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   glUseProgram(e2e_texture_program());
   e2e_draw_rect(-1, -1, 1, 1, 0, 0, 1, 1);
   glDeleteFramebuffers(1, &fbo);
   glDeleteTextures(1, &t);
   printf("stat: rgb16f_status=0x%x\n", status);
}

static void clip_control(int size)
{
   e2e_check(has_ext("GL_EXT_clip_control"), "GL_EXT_clip_control is not exposed");
   PFNGLCLIPCONTROLEXTPROC clip = (PFNGLCLIPCONTROLEXTPROC)eglGetProcAddress("glClipControlEXT");
   if (!has_ext("GL_EXT_clip_control") || !clip)
      return;
   clip(GL_UPPER_LEFT_EXT, GL_ZERO_TO_ONE_EXT);
   fp_gl_check("glClipControlEXT");
   GLuint prog = e2e_color_program();
   glUseProgram(prog);
   glEnable(GL_DEPTH_TEST);
   glDepthFunc(GL_LESS);
   glClearDepthf(1.0f);
   glClear(GL_DEPTH_BUFFER_BIT);
   /* two triangles crossing in depth; with [0, 1] clip depth, z from -0.5
    * (clipped away near) to 1.5 (clipped far) */
   uint32_t rng = 4242;
   for (int i = 0; i < 12; i++) {
      float pos[12], col[12];
      for (int k = 0; k < 3; k++) {
         pos[4 * k + 0] = (float)e2e_rand_range(&rng, -1100, 1100) / 1000.0f;
         pos[4 * k + 1] = (float)e2e_rand_range(&rng, -1100, 1100) / 1000.0f;
         pos[4 * k + 2] = (float)e2e_rand_range(&rng, -500, 1500) / 1000.0f;
         pos[4 * k + 3] = 1.0f;
         col[4 * k + 0] = (float)(i % 3) / 2.0f;
         col[4 * k + 1] = (float)k / 2.0f;
         col[4 * k + 2] = (float)(i % 4) / 3.0f;
      }
      float c4[12];
      for (int k = 0; k < 3; k++) {
         c4[4 * k + 0] = col[4 * k + 0];
         c4[4 * k + 1] = col[4 * k + 1];
         c4[4 * k + 2] = col[4 * k + 2];
         c4[4 * k + 3] = 1.0f;
      }
      e2e_draw(GL_TRIANGLES, 3, pos, c4, NULL);
   }
   glDisable(GL_DEPTH_TEST);
   clip(GL_LOWER_LEFT_EXT, GL_NEGATIVE_ONE_TO_ONE_EXT);
   (void)size;
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   e2e_parse(&a, argc, argv, 64);
   const char *c = e2e_opt(&a, "case", "");
   if (a.size < 16 || a.size % 8)
      fp_die("--size must be a multiple of 8, at least 16");

   struct fp_gl g;
   e2e_begin(&g, &a);
   glClearColor(0, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
   if (!strcmp(c, "vs-cube"))
      vs_cube(a.size);
   else if (!strcmp(c, "proj-mip"))
      proj_mip(a.size);
   else if (!strcmp(c, "points-viewport"))
      points_viewport(a.size);
   else if (!strcmp(c, "half-float-rgb"))
      half_float_rgb(&g, a.size);
   else if (!strcmp(c, "clip-control"))
      clip_control(a.size);
   else
      fp_die("--case: vs-cube, proj-mip, points-viewport, half-float-rgb or clip-control");
   fp_gl_check(c);
   printf("stat: case=%s self_check_errors=%d\n", c, e2e_errors);
   e2e_end(&g, &a, NULL);
   return 0;
}
