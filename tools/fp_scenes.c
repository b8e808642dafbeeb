/* Geometry, shaders and textures of the three demo scenes. */
#include "fp_scenes.h"
#include "fp_gl.h"
#include "fp_math.h"

#include <stdlib.h>

#define FAN_SEGMENTS 16
#define STRIP_PAIRS 24
#define SLIVERS 12
#define TORUS_U 64
#define TORUS_V 32
#define TEX_SIZE 256

static const char *color_vs =
   "uniform vec2 u_scale;\n"
   "attribute vec2 a_pos;\n"
   "attribute vec3 a_color;\n"
   "varying vec3 v_color;\n"
   "void main() {\n"
   "   v_color = a_color;\n"
   "   gl_Position = vec4(a_pos * u_scale, 0.0, 1.0);\n"
   "}\n";
static const char *color_fs =
   "precision mediump float;\n"
   "varying vec3 v_color;\n"
   "void main() { gl_FragColor = vec4(v_color, 1.0); }\n";

/* Per-vertex (Gouraud) lighting: the colours the rasterizer interpolates
 * are the ones the lighting made, which is what the model's colour walk is
 * about. */
static const char *lit_vs =
   "uniform mat4 u_mvp, u_model;\n"
   "attribute vec3 a_pos;\n"
   "attribute vec3 a_normal;\n"
   "attribute vec3 a_color;\n"
   "varying vec3 v_color;\n"
   "void main() {\n"
   "   vec3 n = normalize((u_model * vec4(a_normal, 0.0)).xyz);\n"
   "   vec3 p = (u_model * vec4(a_pos, 1.0)).xyz;\n"
   "   vec3 l = normalize(vec3(0.5, 0.7, 0.6));\n"
   "   vec3 h = normalize(l + normalize(-p));\n"
   "   float d = max(dot(n, l), 0.0);\n"
   "   float s = pow(max(dot(n, h), 0.0), 32.0);\n"
   "   v_color = a_color * (0.15 + 0.85 * d) + vec3(0.6) * s;\n"
   "   gl_Position = u_mvp * vec4(a_pos, 1.0);\n"
   "}\n";

static const char *tex_vs =
   "uniform mat4 u_mvp;\n"
   "attribute vec3 a_pos;\n"
   "attribute vec2 a_uv;\n"
   "varying vec2 v_uv;\n"
   "void main() {\n"
   "   v_uv = a_uv;\n"
   "   gl_Position = u_mvp * vec4(a_pos, 1.0);\n"
   "}\n";
static const char *tex_fs =
   "precision mediump float;\n"
   "uniform sampler2D u_tex;\n"
   "varying vec2 v_uv;\n"
   "void main() { gl_FragColor = texture2D(u_tex, v_uv); }\n";

static void hue(float h, float *rgb)
{
   /* h in [0, 1): a plain six-sector hue wheel at full saturation. */
   float x = h * 6.0f;
   int sector = (int)x % 6;
   float f = x - (float)(int)x;
   float v[6][3] = { {1, f, 0}, {1 - f, 1, 0}, {0, 1, f},
                     {0, 1 - f, 1}, {f, 0, 1}, {1, 0, 1 - f} };
   rgb[0] = v[sector][0];
   rgb[1] = v[sector][1];
   rgb[2] = v[sector][2];
}

static GLuint upload(const void *data, size_t bytes, GLenum target)
{
   GLuint b;
   glGenBuffers(1, &b);
   glBindBuffer(target, b);
   glBufferData(target, (GLsizeiptr)bytes, data, GL_STATIC_DRAW);
   return b;
}

static void init_gouraud(struct fp_scenes *s)
{
   /* Fan then strip in one buffer: x, y, r, g, b. */
   float fan[(FAN_SEGMENTS + 2 + 2 * STRIP_PAIRS) * 5], *p = fan;
   *p++ = -0.45f; *p++ = 0.35f; *p++ = 1; *p++ = 1; *p++ = 1;
   for (int i = 0; i <= FAN_SEGMENTS; i++) {
      float a = 2.0f * FP_PI * (float)i / FAN_SEGMENTS;
      *p++ = -0.45f + 0.5f * cosf(a);
      *p++ = 0.35f + 0.5f * sinf(a);
      hue((float)(i % FAN_SEGMENTS) / FAN_SEGMENTS, p);
      p += 3;
   }
   for (int i = 0; i < STRIP_PAIRS; i++) {
      float x = -0.95f + 1.9f * (float)i / (STRIP_PAIRS - 1);
      float y = -0.65f + 0.12f * sinf(x * 5.0f);
      float t = (float)i / (STRIP_PAIRS - 1);
      for (int k = 0; k < 2; k++) {
         *p++ = x;
         *p++ = y + (k ? 0.18f : -0.18f);
         *p++ = k ? 1.0f - t : 0.1f;
         *p++ = k ? 0.2f : t;
         *p++ = k ? t : 0.9f - 0.5f * t;
      }
   }
   s->fan_verts = FAN_SEGMENTS + 2;
   s->fan_vbo = upload(fan, sizeof(fan), GL_ARRAY_BUFFER);

   /* Two big overlapping triangles and a row of slivers. */
   float tris[(2 + SLIVERS) * 3 * 5], *q = tris;
   const float big[2][3][5] = {
      { {0.05f, 0.92f, 1, 0, 0}, {0.95f, 0.80f, 0, 1, 0}, {0.45f, -0.10f, 0, 0, 1} },
      { {0.25f, 0.10f, 0, 1, 1}, {0.97f, 0.20f, 1, 0, 1}, {0.70f, 0.70f, 1, 1, 0} },
   };
   for (int t = 0; t < 2; t++)
      for (int v = 0; v < 3; v++)
         for (int c = 0; c < 5; c++)
            *q++ = big[t][v][c];
   for (int i = 0; i < SLIVERS; i++) {
      float x = -0.95f + 0.16f * (float)i, col[3];
      hue((float)i / SLIVERS, col);
      const float v[3][2] = { {x, -0.30f}, {x + 0.03f + 0.005f * (float)i, -0.05f},
                              {x + 0.12f, -0.28f} };
      for (int k = 0; k < 3; k++) {
         *q++ = v[k][0];
         *q++ = v[k][1];
         *q++ = k == 1 ? 1.0f : col[0];
         *q++ = k == 1 ? 1.0f : col[1];
         *q++ = k == 1 ? 1.0f : col[2];
      }
   }
   s->tris_verts = (2 + SLIVERS) * 3;
   s->tris_vbo = upload(tris, sizeof(tris), GL_ARRAY_BUFFER);
}

static void init_torus(struct fp_scenes *s)
{
   enum { NV = (TORUS_U + 1) * (TORUS_V + 1) };
   float *v = malloc(sizeof(float) * 9 * NV);
   GLushort *idx = malloc(sizeof(GLushort) * 6 * TORUS_U * TORUS_V);
   if (!v || !idx)
      fp_die("out of memory");
   const float R = 1.0f, r = 0.42f;
   float *p = v;
   for (int i = 0; i <= TORUS_U; i++) {
      float u = 2.0f * FP_PI * (float)i / TORUS_U, cu = cosf(u), su = sinf(u);
      for (int j = 0; j <= TORUS_V; j++) {
         float w = 2.0f * FP_PI * (float)j / TORUS_V, cw = cosf(w), sw = sinf(w);
         *p++ = (R + r * cw) * cu;
         *p++ = (R + r * cw) * su;
         *p++ = r * sw;
         *p++ = cw * cu;
         *p++ = cw * su;
         *p++ = sw;
         hue((float)(i % TORUS_U) / TORUS_U, p);
         p += 3;
      }
   }
   GLushort *q = idx;
   for (int i = 0; i < TORUS_U; i++)
      for (int j = 0; j < TORUS_V; j++) {
         GLushort a = (GLushort)(i * (TORUS_V + 1) + j), b = (GLushort)(a + TORUS_V + 1);
         *q++ = a; *q++ = b; *q++ = (GLushort)(a + 1);
         *q++ = (GLushort)(a + 1); *q++ = b; *q++ = (GLushort)(b + 1);
      }
   s->torus_indices = 6 * TORUS_U * TORUS_V;
   s->torus_vbo = upload(v, sizeof(float) * 9 * NV, GL_ARRAY_BUFFER);
   s->torus_ibo = upload(idx, sizeof(GLushort) * (size_t)s->torus_indices, GL_ELEMENT_ARRAY_BUFFER);
   free(v);
   free(idx);
}

static void init_textured(struct fp_scenes *s)
{
   /* A floor receding to the horizon (minification across all mip levels)
    * and an upright quad turned away from the eye; x, y, z, u, v. */
   const float quads[2][4][5] = {
      { {-4, -1, -1.5f, 0, 0}, {4, -1, -1.5f, 8, 0}, {-4, -1, -40, 0, 40}, {4, -1, -40, 8, 40} },
      { {-0.2f, -1, -5, 0, 0}, {1.8f, -1, -7, 2, 0}, {-0.2f, 1.2f, -5, 0, 2}, {1.8f, 1.2f, -7, 2, 2} },
   };
   s->floor_vbo = upload(quads, sizeof(quads), GL_ARRAY_BUFFER);

   unsigned char *t = malloc(TEX_SIZE * TEX_SIZE * 4);
   if (!t)
      fp_die("out of memory");
   for (int y = 0; y < TEX_SIZE; y++)
      for (int x = 0; x < TEX_SIZE; x++) {
         unsigned char *px = t + (y * TEX_SIZE + x) * 4;
         int light = ((x >> 5) ^ (y >> 5)) & 1;
         px[0] = (unsigned char)(light ? x : 40 + x / 8);
         px[1] = (unsigned char)(light ? y : 30 + y / 8);
         px[2] = (unsigned char)(light ? 255 - (x + y) / 2 : 60);
         px[3] = 255;
      }
   glGenTextures(1, &s->tex);
   glBindTexture(GL_TEXTURE_2D, s->tex);
   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, TEX_SIZE, TEX_SIZE, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
   glGenerateMipmap(GL_TEXTURE_2D);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
   free(t);
}

void fp_scenes_init(struct fp_scenes *s)
{
   static const char *const color_attr[] = { "a_pos", "a_color", NULL };
   static const char *const lit_attr[] = { "a_pos", "a_normal", "a_color", NULL };
   static const char *const tex_attr[] = { "a_pos", "a_uv", NULL };
   s->prog_color = fp_gl_program(color_vs, color_fs, color_attr);
   s->prog_lit = fp_gl_program(lit_vs, color_fs, lit_attr);
   s->prog_tex = fp_gl_program(tex_vs, tex_fs, tex_attr);
   s->color_scale = glGetUniformLocation(s->prog_color, "u_scale");
   s->lit_mvp = glGetUniformLocation(s->prog_lit, "u_mvp");
   s->lit_model = glGetUniformLocation(s->prog_lit, "u_model");
   s->tex_mvp = glGetUniformLocation(s->prog_tex, "u_mvp");
   s->tex_sampler = glGetUniformLocation(s->prog_tex, "u_tex");
   init_gouraud(s);
   init_torus(s);
   init_textured(s);
   fp_gl_check("scene set-up");
}

void fp_scenes_fini(struct fp_scenes *s)
{
   GLuint bufs[] = { s->fan_vbo, s->tris_vbo, s->torus_vbo, s->torus_ibo, s->floor_vbo };
   glDeleteBuffers(5, bufs);
   glDeleteTextures(1, &s->tex);
   glDeleteProgram(s->prog_color);
   glDeleteProgram(s->prog_lit);
   glDeleteProgram(s->prog_tex);
}

static void attrib(GLuint loc, int n, int stride, int offset)
{
   glEnableVertexAttribArray(loc);
   glVertexAttribPointer(loc, n, GL_FLOAT, GL_FALSE, stride * (int)sizeof(float),
                         (const void *)(sizeof(float) * (size_t)offset));
}

static void disable_attribs(void)
{
   for (GLuint i = 0; i < 3; i++)
      glDisableVertexAttribArray(i);
}

void fp_scene_gouraud(const struct fp_scenes *s, float aspect)
{
   glUseProgram(s->prog_color);
   /* Keep the square design square in any viewport. */
   glUniform2f(s->color_scale, aspect > 1 ? 1 / aspect : 1, aspect > 1 ? 1 : aspect);
   glBindBuffer(GL_ARRAY_BUFFER, s->tris_vbo);
   attrib(0, 2, 5, 0);
   attrib(1, 3, 5, 2);
   glDrawArrays(GL_TRIANGLES, 0, s->tris_verts);
   glBindBuffer(GL_ARRAY_BUFFER, s->fan_vbo);
   attrib(0, 2, 5, 0);
   attrib(1, 3, 5, 2);
   glDrawArrays(GL_TRIANGLE_FAN, 0, s->fan_verts);
   glDrawArrays(GL_TRIANGLE_STRIP, s->fan_verts, 2 * STRIP_PAIRS);
   disable_attribs();
}

void fp_scene_mesh(const struct fp_scenes *s, float aspect)
{
   fp_mat4 model = fp_mat4_mul(fp_mat4_translate(0, 0, -4.3f),
                               fp_mat4_mul(fp_mat4_rotate(35, 1, 0, 0),
                                           fp_mat4_rotate(-25, 0, 0.6f, 0.8f)));
   fp_mat4 mvp = fp_mat4_mul(fp_mat4_perspective(45, aspect, 1.0f, 10.0f), model);
   glEnable(GL_DEPTH_TEST);
   glDepthFunc(GL_LESS);
   glEnable(GL_CULL_FACE);
   glUseProgram(s->prog_lit);
   glUniformMatrix4fv(s->lit_mvp, 1, GL_FALSE, mvp.m);
   glUniformMatrix4fv(s->lit_model, 1, GL_FALSE, model.m);
   glBindBuffer(GL_ARRAY_BUFFER, s->torus_vbo);
   glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, s->torus_ibo);
   attrib(0, 3, 9, 0);
   attrib(1, 3, 9, 3);
   attrib(2, 3, 9, 6);
   glDrawElements(GL_TRIANGLES, s->torus_indices, GL_UNSIGNED_SHORT, 0);
   disable_attribs();
   glDisable(GL_CULL_FACE);
   glDisable(GL_DEPTH_TEST);
}

void fp_scene_textured(const struct fp_scenes *s, float aspect)
{
   fp_mat4 view = fp_mat4_rotate(8, 1, 0, 0);
   fp_mat4 mvp = fp_mat4_mul(fp_mat4_perspective(60, aspect, 0.5f, 50.0f), view);
   glEnable(GL_DEPTH_TEST);
   glDepthFunc(GL_LESS);
   glUseProgram(s->prog_tex);
   glUniformMatrix4fv(s->tex_mvp, 1, GL_FALSE, mvp.m);
   glUniform1i(s->tex_sampler, 0);
   glActiveTexture(GL_TEXTURE0);
   glBindTexture(GL_TEXTURE_2D, s->tex);
   glBindBuffer(GL_ARRAY_BUFFER, s->floor_vbo);
   attrib(0, 3, 5, 0);
   attrib(1, 2, 5, 3);
   glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
   glDrawArrays(GL_TRIANGLE_STRIP, 4, 4);
   disable_attribs();
   glDisable(GL_DEPTH_TEST);
}
