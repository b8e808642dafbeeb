/*
 * Texture buffers (GL_OES_texture_buffer, GL ES 3.1): texelFetch of a
 * buffer through the modeled unit's fetch (--case NAME, 64x64 unless
 * --size says):
 *
 *   fragment  every pixel fetches three buffers by an index made of its
 *             position: random RGBA8 texels, R32F texels of a range of a
 *             larger buffer (glTexBufferRangeOES at an offset), RGBA32UI
 *             texels; a band of indices past each buffer's end reads zero
 *   vertex    a grid of squares whose colours and offsets the vertex
 *             shader fetches from a buffer by gl_InstanceID; the squares'
 *             edges lie on pixel edges, so no pixel is a tie
 *
 * Self-checks (errors fail the program on any driver): the extension is
 * exposed; textureSize gives each buffer's texels; in fragment, pixels
 * read back hold the texels computed here and zero past the end; in
 * vertex, every square's centre holds its texel.
 */
#include "e2e_common.h"

#include <GLES3/gl31.h>
#include <GLES2/gl2ext.h>
#include <EGL/egl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef GL_TEXTURE_BUFFER_OES
#define GL_TEXTURE_BUFFER_OES 0x8C2A
#endif

typedef void (*tex_buffer_fn)(GLenum, GLenum, GLuint);
typedef void (*tex_buffer_range_fn)(GLenum, GLenum, GLuint, GLintptr, GLsizeiptr);

#define N_RGBA8 200     /* texels of each buffer */
#define N_R32F 150
#define N_UINT 170
#define R32F_OFFSET 64  /* bytes into the larger buffer the range starts */

static const char vs_quad[] =
   "#version 310 es\n"
   "in vec4 a_pos;\n"
   "void main() { gl_Position = a_pos; }\n";

/* index = x + y * size, wrapped past each buffer's end by a margin of 16
 * texels, so a band of pixels reads beyond every buffer */
static const char fs_fragment[] =
   "#version 310 es\n"
   "#extension GL_OES_texture_buffer : require\n"
   "precision highp float;\n"
   "precision highp int;\n"
   "uniform highp samplerBuffer u_rgba8;\n"
   "uniform highp samplerBuffer u_r32f;\n"
   "uniform highp usamplerBuffer u_uint;\n"
   "uniform int u_size;\n"
   "out vec4 o_color;\n"
   "void main() {\n"
   "   int i = int(gl_FragCoord.x) + int(gl_FragCoord.y) * u_size;\n"
   "   vec4 a = texelFetch(u_rgba8, i % (textureSize(u_rgba8) + 16));\n"
   "   float b = texelFetch(u_r32f, i % (textureSize(u_r32f) + 16)).r;\n"
   "   uvec4 c = texelFetch(u_uint, i % (textureSize(u_uint) + 16));\n"
   "   bool sizes = textureSize(u_rgba8) == 200 && textureSize(u_r32f) == 150 &&\n"
   "                textureSize(u_uint) == 170;\n"
   "   o_color = vec4(a.r, a.g * 0.5 + b * 0.5, float(c.b & 255u) / 255.0,\n"
   "                  sizes ? a.a : 0.0);\n"
   "}\n";

static uint32_t seed = 12345;

static GLuint make_buffer(GLsizeiptr bytes, const void *data)
{
   GLuint b;
   glGenBuffers(1, &b);
   glBindBuffer(GL_TEXTURE_BUFFER_OES, b);
   glBufferData(GL_TEXTURE_BUFFER_OES, bytes, data, GL_STATIC_DRAW);
   return b;
}

static GLuint make_texture(GLenum unit)
{
   GLuint t;
   glGenTextures(1, &t);
   glActiveTexture(unit);
   glBindTexture(GL_TEXTURE_BUFFER_OES, t);
   return t;
}

static void pixel(int x, int y, unsigned char px[4])
{
   glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
}

static unsigned char unorm8(float f)
{
   return (unsigned char)(f <= 0.0f ? 0 : f >= 1.0f ? 255 : (int)(f * 255.0f + 0.5f));
}

static void scene_fragment(int size, tex_buffer_fn tex_buffer, tex_buffer_range_fn range)
{
   unsigned char rgba8[N_RGBA8 * 4];
   float r32f[R32F_OFFSET / 4 + N_R32F + 8];
   uint32_t uints[N_UINT * 4];
   for (int i = 0; i < N_RGBA8 * 4; i++)
      rgba8[i] = (unsigned char)e2e_rand_range(&seed, 0, 255);
   for (size_t i = 0; i < sizeof(r32f) / sizeof(r32f[0]); i++)
      r32f[i] = (float)e2e_rand_range(&seed, 0, 255) / 255.0f;
   for (int i = 0; i < N_UINT * 4; i++)
      uints[i] = e2e_rand(&seed);

   GLuint b8 = make_buffer(sizeof(rgba8), rgba8);
   GLuint bf = make_buffer(sizeof(r32f), r32f);
   GLuint bu = make_buffer(sizeof(uints), uints);
   GLuint t8 = make_texture(GL_TEXTURE0);
   tex_buffer(GL_TEXTURE_BUFFER_OES, GL_RGBA8, b8);
   GLuint tf = make_texture(GL_TEXTURE1);
   range(GL_TEXTURE_BUFFER_OES, GL_R32F, bf, R32F_OFFSET, N_R32F * 4);
   GLuint tu = make_texture(GL_TEXTURE2);
   tex_buffer(GL_TEXTURE_BUFFER_OES, GL_RGBA32UI, bu);

   static const char *const attribs[] = { "a_pos", NULL };
   GLuint prog = fp_gl_program(vs_quad, fs_fragment, attribs);
   glUseProgram(prog);
   glUniform1i(glGetUniformLocation(prog, "u_rgba8"), 0);
   glUniform1i(glGetUniformLocation(prog, "u_r32f"), 1);
   glUniform1i(glGetUniformLocation(prog, "u_uint"), 2);
   glUniform1i(glGetUniformLocation(prog, "u_size"), size);
   glClearColor(0, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   const float quad[] = { -1, -1, 0, 1, 1, -1, 0, 1, -1, 1, 0, 1, 1, 1, 0, 1 };
   const float unused[4] = { 0, 0, 0, 0 };
   e2e_draw(GL_TRIANGLE_STRIP, 4, quad, NULL, unused);

   /* what the shader computes, for every pixel */
   unsigned char *img = malloc((size_t)size * (size_t)size * 4);
   if (!img)
      fp_die("out of memory");
   glReadPixels(0, 0, size, size, GL_RGBA, GL_UNSIGNED_BYTE, img);
   int bad = 0, checked = 0, zeros = 0;
   for (int y = 0; y < size; y++)
      for (int x = 0; x < size; x++) {
         const int i = x + y * size;
         const int ia = i % (N_RGBA8 + 16), ib = i % (N_R32F + 16), ic = i % (N_UINT + 16);
         const float a[4] = {
            ia < N_RGBA8 ? rgba8[4 * ia] / 255.0f : 0, ia < N_RGBA8 ? rgba8[4 * ia + 1] / 255.0f : 0,
            0, ia < N_RGBA8 ? rgba8[4 * ia + 3] / 255.0f : 0 };
         const float b = ib < N_R32F ? r32f[R32F_OFFSET / 4 + ib] : 0;
         const uint32_t c = ic < N_UINT ? uints[4 * ic + 2] : 0;
         unsigned char want[4] = { unorm8(a[0]), unorm8(a[1] * 0.5f + b * 0.5f),
                                   (unsigned char)(c & 255), unorm8(a[3]) };
         const unsigned char *got = img + 4 * ((size_t)y * (size_t)size + (size_t)x);
         checked++;
         zeros += ia >= N_RGBA8;
         for (int ch = 0; ch < 4; ch++)
            if (abs((int)got[ch] - (int)want[ch]) > 1)
               bad++;
      }
   free(img);
   printf("stat: checked=%d,past_end=%d,wrong=%d\n", checked, zeros, bad);
   e2e_check(zeros > 0, "no checked pixel reads past a buffer's end");
   e2e_check(bad == 0, "pixels differ from the buffers' texels (or textureSize is wrong)");
   glDeleteTextures(1, &t8);
   glDeleteTextures(1, &tf);
   glDeleteTextures(1, &tu);
   glDeleteBuffers(1, &b8);
   glDeleteBuffers(1, &bf);
   glDeleteBuffers(1, &bu);
}

/* GRID x GRID squares; instance k's texels 2k (colour) and 2k + 1 (the
 * square's corner in pixels, as integers in RGBA32I: x, y, side) */
#define GRID 6

static const char vs_vertex[] =
   "#version 310 es\n"
   "#extension GL_OES_texture_buffer : require\n"
   "precision highp float;\n"
   "uniform highp samplerBuffer u_color;\n"
   "uniform highp isamplerBuffer u_place;\n"
   "uniform float u_size;\n"
   "in vec4 a_pos;\n"
   "flat out vec4 v_color;\n"
   "void main() {\n"
   "   ivec4 p = texelFetch(u_place, gl_InstanceID);\n"
   "   vec2 corner = vec2(p.xy) + a_pos.xy * float(p.z);\n"
   "   gl_Position = vec4(corner / u_size * 2.0 - 1.0, 0.0, 1.0);\n"
   "   v_color = texelFetch(u_color, gl_InstanceID);\n"
   "}\n";

static const char fs_vertex[] =
   "#version 310 es\n"
   "precision highp float;\n"
   "flat in vec4 v_color;\n"
   "out vec4 o_color;\n"
   "void main() { o_color = v_color; }\n";

static void scene_vertex(int size, tex_buffer_fn tex_buffer)
{
   const int n = GRID * GRID, cell = size / GRID, side = cell - 2;
   unsigned char colors[GRID * GRID * 4];
   int32_t place[GRID * GRID * 4];
   for (int k = 0; k < n; k++) {
      for (int c = 0; c < 3; c++)
         colors[4 * k + c] = (unsigned char)e2e_rand_range(&seed, 0, 255);
      colors[4 * k + 3] = 255;
      place[4 * k] = (k % GRID) * cell + 1;
      place[4 * k + 1] = (k / GRID) * cell + 1;
      place[4 * k + 2] = side;
      place[4 * k + 3] = 0;
   }
   GLuint bc = make_buffer(sizeof(colors), colors);
   GLuint bp = make_buffer(sizeof(place), place);
   GLuint tc = make_texture(GL_TEXTURE0);
   tex_buffer(GL_TEXTURE_BUFFER_OES, GL_RGBA8, bc);
   GLuint tp = make_texture(GL_TEXTURE1);
   tex_buffer(GL_TEXTURE_BUFFER_OES, GL_RGBA32I, bp);

   static const char *const attribs[] = { "a_pos", NULL };
   GLuint prog = fp_gl_program(vs_vertex, fs_vertex, attribs);
   glUseProgram(prog);
   glUniform1i(glGetUniformLocation(prog, "u_color"), 0);
   glUniform1i(glGetUniformLocation(prog, "u_place"), 1);
   glUniform1f(glGetUniformLocation(prog, "u_size"), (float)size);
   glClearColor(0, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   const float unit[] = { 0, 0, 0, 1, 1, 0, 0, 1, 0, 1, 0, 1, 1, 1, 0, 1 };
   glBindBuffer(GL_ARRAY_BUFFER, 0);
   glEnableVertexAttribArray(0);
   glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 0, unit);
   glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, n);
   glDisableVertexAttribArray(0);

   int bad = 0;
   for (int k = 0; k < n; k++) {
      unsigned char got[4];
      pixel(place[4 * k] + side / 2, place[4 * k + 1] + side / 2, got);
      for (int c = 0; c < 4; c++)
         bad += got[c] != colors[4 * k + c];
   }
   printf("stat: squares=%d,wrong=%d\n", n, bad);
   e2e_check(bad == 0, "a square's centre differs from its texel");
   glDeleteTextures(1, &tc);
   glDeleteTextures(1, &tp);
   glDeleteBuffers(1, &bc);
   glDeleteBuffers(1, &bp);
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   struct fp_gl g;
   e2e_start(&g, &a, argc, argv, 64);
   const char *c = e2e_opt(&a, "case", "");
   if (!e2e_check_es31())
      return e2e_finish(&g, &a, NULL);
   e2e_check(e2e_has_extension("GL_OES_texture_buffer"), "GL_OES_texture_buffer is not exposed");
   tex_buffer_fn tex_buffer = (tex_buffer_fn)eglGetProcAddress("glTexBufferOES");
   tex_buffer_range_fn range = (tex_buffer_range_fn)eglGetProcAddress("glTexBufferRangeOES");
   if (!tex_buffer || !range)
      fp_die("no glTexBufferOES or glTexBufferRangeOES");
   if (e2e_errors)
      ;
   else if (!strcmp(c, "fragment"))
      scene_fragment(a.size, tex_buffer, range);
   else if (!strcmp(c, "vertex"))
      scene_vertex(a.size, tex_buffer);
   else
      fp_die("--case: fragment or vertex");
   return e2e_finish(&g, &a, NULL);
}
