/*
 * fp-es32: a GL ES 3.2 scene offscreen, for a trace of a GL ES 3.2 program
 * (traces/list.txt, docs/traces.md): what GL ES 3.2 has and GL ES 3.1 has
 * not, drawn into a 4-sample target and resolved each frame, every shader
 * `#version 320 es` with no extension:
 *
 *   - a patch tessellated (quads, levels from the frame) into a height field
 *     whose evaluation shader samples a texture (the modeled unit from a
 *     compiled stage);
 *   - a geometry shader that emits each triangle with its flat normal and
 *     a shrunk copy of it on another layer of depth;
 *   - a fragment shader with interpolateAtOffset at an offset of each pixel,
 *     interpolateAtSample under sample shading and textureGatherOffset with
 *     an offset of each pixel.
 *
 * Deterministic: frame k is a function of k alone.  One glFinish a frame.
 *
 *   fp-es32 [--size WxH] [--frames N] [-o out.png]
 */
#define _POSIX_C_SOURCE 200809L
#include "fp_gl.h"

#include <GLES3/gl32.h>
#include <stdio.h>
#include <stdlib.h>

static void usage(FILE *f)
{
   fprintf(f, "usage: fp-es32 [--size WxH] [--frames N] [-o out.png]\n"
              "  a GL ES 3.2 scene (tessellation, geometry, interpolateAt*, gather\n"
              "  offsets, sample shading) into a 4-sample target, one glFinish a frame\n");
}

static const char *vs =
   "#version 320 es\n"
   "in vec2 a_pos;\n"
   "out vec2 v_pos;\n"
   "void main() { v_pos = a_pos; }\n";

static const char *tcs =
   "#version 320 es\n"
   "layout(vertices = 4) out;\n"
   "uniform float u_level;\n"
   "in vec2 v_pos[];\n"
   "out vec2 c_pos[];\n"
   "void main() {\n"
   "   c_pos[gl_InvocationID] = v_pos[gl_InvocationID];\n"
   "   gl_TessLevelOuter[0] = u_level; gl_TessLevelOuter[1] = u_level + 1.0;\n"
   "   gl_TessLevelOuter[2] = u_level + 2.0; gl_TessLevelOuter[3] = u_level;\n"
   "   gl_TessLevelInner[0] = u_level; gl_TessLevelInner[1] = u_level + 1.0;\n"
   "}\n";

static const char *tes =
   "#version 320 es\n"
   "layout(quads, fractional_odd_spacing, ccw) in;\n"
   "uniform highp sampler2D u_height;\n"
   "uniform float u_time;\n"
   "in vec2 c_pos[];\n"
   "out vec3 e_world;\n"
   "out vec2 e_uv;\n"
   "void main() {\n"
   "   vec2 uv = gl_TessCoord.xy;\n"
   "   vec2 p = mix(mix(c_pos[0], c_pos[1], uv.x), mix(c_pos[3], c_pos[2], uv.x), uv.y);\n"
   "   float h = textureLod(u_height, uv * 1.5 + vec2(u_time * 0.1, 0.0), 0.0).r;\n"
   "   e_world = vec3(p, h * 0.6);\n"
   "   e_uv = uv;\n"
   "}\n";

static const char *gs =
   "#version 320 es\n"
   "layout(triangles) in;\n"
   "layout(triangle_strip, max_vertices = 6) out;\n"
   "uniform float u_time;\n"
   "in vec3 e_world[];\n"
   "in vec2 e_uv[];\n"
   "out vec2 g_uv;\n"
   "out vec3 g_shade;\n"
   "flat out float g_copy;\n"
   "vec4 project(vec3 w) {\n"
   "   float c = cos(u_time * 0.3), s = sin(u_time * 0.3);\n"
   "   vec3 r = vec3(c * w.x - s * w.z, w.y * 0.9 - w.z * 0.3, s * w.x + c * w.z);\n"
   "   return vec4(r.xy, r.z * 0.3, 1.0 + 0.5 * r.y);\n"
   "}\n"
   "void main() {\n"
   "   vec3 n = normalize(cross(e_world[1] - e_world[0], e_world[2] - e_world[0]));\n"
   "   vec3 m = (e_world[0] + e_world[1] + e_world[2]) / 3.0;\n"
   "   for (int copy = 0; copy < 2; copy++) {\n"
   "      for (int i = 0; i < 3; i++) {\n"
   "         vec3 w = copy == 0 ? e_world[i] : mix(m, e_world[i], 0.5) + vec3(0.0, 0.0, 0.2);\n"
   "         gl_Position = project(w);\n"
   "         g_uv = e_uv[i];\n"
   "         g_shade = abs(n) * (copy == 0 ? 1.0 : 0.5);\n"
   "         g_copy = float(copy);\n"
   "         EmitVertex();\n"
   "      }\n"
   "      EndPrimitive();\n"
   "   }\n"
   "}\n";

static const char *fs =
   "#version 320 es\n"
   "precision highp float;\n"
   "uniform highp sampler2D u_tex;\n"
   "in vec2 g_uv;\n"
   "in vec3 g_shade;\n"
   "flat in float g_copy;\n"
   "out vec4 o_color;\n"
   "void main() {\n"
   "   ivec2 p = ivec2(gl_FragCoord.xy);\n"
   "   vec2 off = vec2((p.x * 3 + p.y) & 15, (p.y * 5 + p.x) & 15) / 16.0 - 0.5;\n"
   "   vec2 uv = interpolateAtOffset(g_uv, off);\n"
   "   vec3 shade = interpolateAtSample(g_shade, gl_SampleID);\n"
   "   vec4 g = textureGatherOffset(u_tex, uv * 4.0, ivec2((p.x & 3) - 2, (p.y & 1) - 1), 1);\n"
   "   float t = dot(g, vec4(0.25));\n"
   "   o_color = vec4(mix(shade, vec3(t), 0.5) + vec3(0.0, 0.0, 0.3 * g_copy), 1.0);\n"
   "}\n";

struct scene {
   GLuint prog, vao, vbo, height, tex, ms_fbo, ms_rb;
   int w, h, frame;
};

static GLuint texture_of(int size, unsigned seed, bool smooth)
{
   unsigned char *t = malloc((size_t)size * (size_t)size * 4);
   if (!t) {
      fprintf(stderr, "fp-es32: out of memory\n");
      exit(2);
   }
   for (int i = 0; i < size * size * 4; i++) {
      seed = seed * 1103515245u + 12345u;
      t[i] = (unsigned char)(seed >> 16);
   }
   /* smooth: a height field in red; else soft bands in every channel, as a
    * photograph's texels are (noise would make every rounding a large error) */
   for (int y = 0; y < size; y++)
      for (int x = 0; x < size; x++) {
         unsigned char *p = t + 4 * (y * size + x);
         if (smooth)
            p[0] = (unsigned char)(128 + 100 * ((x * 7 + y * 3) % size) / size -
                                   50 * ((x + y) % 16) / 16);
         else
            for (int c = 0; c < 3; c++)
               p[c] = (unsigned char)(128 + 120 * ((x * (c + 1) + y * (3 - c)) % size) / size -
                                      60);
      }
   GLuint tex;
   glGenTextures(1, &tex);
   glBindTexture(GL_TEXTURE_2D, tex);
   glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, smooth ? GL_LINEAR : GL_NEAREST);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_MIRRORED_REPEAT);
   free(t);
   return tex;
}

static void scene_init(struct scene *s, int w, int h)
{
   static const char *const attribs[] = { "a_pos", NULL };
   s->w = w;
   s->h = h;
   s->frame = 0;
   s->prog = fp_gl_program_stages(vs, tcs, tes, gs, fs, attribs);
   static const float quad[] = { -0.8f, -0.8f, 0.8f, -0.8f, 0.8f, 0.8f, -0.8f, 0.8f };
   glGenVertexArrays(1, &s->vao);
   glBindVertexArray(s->vao);
   glGenBuffers(1, &s->vbo);
   glBindBuffer(GL_ARRAY_BUFFER, s->vbo);
   glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STATIC_DRAW);
   glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, NULL);
   glEnableVertexAttribArray(0);
   glActiveTexture(GL_TEXTURE0);
   s->height = texture_of(64, 7u, true);
   glActiveTexture(GL_TEXTURE1);
   s->tex = texture_of(32, 11u, false);
   glUseProgram(s->prog);
   glUniform1i(glGetUniformLocation(s->prog, "u_height"), 0);
   glUniform1i(glGetUniformLocation(s->prog, "u_tex"), 1);
   glPatchParameteri(GL_PATCH_VERTICES, 4);
   glGenRenderbuffers(1, &s->ms_rb);
   glBindRenderbuffer(GL_RENDERBUFFER, s->ms_rb);
   glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_RGBA8, w, h);
   glGenFramebuffers(1, &s->ms_fbo);
   glBindFramebuffer(GL_FRAMEBUFFER, s->ms_fbo);
   glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, s->ms_rb);
   if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      fprintf(stderr, "fp-es32: the 4-sample framebuffer is not complete\n");
      exit(2);
   }
}

/* Frame s->frame into the 4-sample target. */
static void draw_frame(struct scene *s)
{
   const float t = (float)s->frame++;
   glBindFramebuffer(GL_FRAMEBUFFER, s->ms_fbo);
   glViewport(0, 0, s->w, s->h);
   glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
   glClear(GL_COLOR_BUFFER_BIT);
   glUseProgram(s->prog);
   glUniform1f(glGetUniformLocation(s->prog, "u_time"), t);
   glUniform1f(glGetUniformLocation(s->prog, "u_level"), 5.0f + 2.0f * t);
   glEnable(GL_SAMPLE_SHADING);
   glMinSampleShading(1.0f);
   glDrawArrays(GL_PATCHES, 0, 4);
   glDisable(GL_SAMPLE_SHADING);
}

int main(int argc, char **argv)
{
   static const struct option opts[] = { FP_GL_OPTIONS, { NULL, 0, NULL, 0 } };
   struct fp_gl_args a = { .w = 320, .h = 240, .frames = 3 };
   for (int c; (c = fp_gl_getopt(argc, argv, opts, "fp-es32", 16, &a, usage)) != -1;)
      ;
   struct fp_gl g;
   fp_gl_init(&g, a.w, a.h);
   printf("renderer: %s\n", fp_gl_renderer());
   printf("version: %s\n", (const char *)glGetString(GL_VERSION));
   struct scene s;
   scene_init(&s, a.w, a.h);
   for (int f = 0; f < a.frames; f++) {
      draw_frame(&s);
      /* resolved into fp_gl's single-sampled FBO, which the PNG reads */
      glBindFramebuffer(GL_READ_FRAMEBUFFER, s.ms_fbo);
      glBindFramebuffer(GL_DRAW_FRAMEBUFFER, g.fbo);
      glBlitFramebuffer(0, 0, a.w, a.h, 0, 0, a.w, a.h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
      glBindFramebuffer(GL_FRAMEBUFFER, g.fbo);
      glFinish();
   }
   fp_gl_check("drawing");
   if (a.out) {
      fp_gl_write_png(&g, a.out);
      printf("wrote: %s\n", a.out);
   }
   fp_gl_fini(&g);
   return 0;
}
