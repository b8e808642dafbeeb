/* Shared plumbing of the e2e test programs. */
#include "e2e_common.h"
#include "fp_png.h"
#include <GLES3/gl31.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static _Noreturn void usage(const char *prog)
{
   fprintf(stderr, "usage: %s -o out.png [--mask mask.png] [--size N] [--name value ...]\n",
           prog);
   exit(2);
}

void e2e_parse(struct e2e_args *a, int argc, char **argv, int default_size)
{
   memset(a, 0, sizeof(*a));
   a->size = default_size;
   for (int i = 1; i < argc; i++) {
      if (i + 1 >= argc || strncmp(argv[i], "-", 1) != 0)
         usage(argv[0]);
      const char *k = argv[i], *v = argv[++i];
      if (!strcmp(k, "-o"))
         a->out = v;
      else if (!strcmp(k, "--mask"))
         a->mask = v;
      else if (!strcmp(k, "--size"))
         a->size = atoi(v);
      else if (!strncmp(k, "--", 2) && a->nopt < 8) {
         a->opt[a->nopt][0] = k + 2;
         a->opt[a->nopt][1] = v;
         a->nopt++;
      } else
         usage(argv[0]);
   }
   if (!a->out || a->size < 16 || a->size > 4096)
      usage(argv[0]);
}

const char *e2e_opt(const struct e2e_args *a, const char *name, const char *def)
{
   for (int i = 0; i < a->nopt; i++)
      if (!strcmp(a->opt[i][0], name))
         return a->opt[i][1];
   return def;
}

void e2e_begin(struct fp_gl *g, const struct e2e_args *a)
{
   fp_gl_init(g, a->size, a->size);
   printf("renderer: %s\n", fp_gl_renderer());
}

void e2e_start(struct fp_gl *g, struct e2e_args *a, int argc, char **argv, int default_size)
{
   e2e_parse(a, argc, argv, default_size);
   e2e_begin(g, a);
}

int e2e_errors;

void e2e_check(bool ok, const char *what)
{
   if (!ok) {
      printf("error: %s\n", what);
      e2e_errors++;
   }
}

bool e2e_check_es31(void)
{
   GLint major = 0, minor = 0;
   glGetIntegerv(GL_MAJOR_VERSION, &major);
   glGetIntegerv(GL_MINOR_VERSION, &minor);
   e2e_check(major * 10 + minor >= 31, "the context is not GL ES 3.1 or later");
   return major * 10 + minor >= 31;
}

int e2e_finish(struct fp_gl *g, const struct e2e_args *a, const unsigned char *mask)
{
   e2e_check(glGetError() == GL_NO_ERROR, "a GL error");
   e2e_end(g, a, mask);
   return e2e_errors ? 1 : 0;
}

void e2e_end(struct fp_gl *g, const struct e2e_args *a, const unsigned char *mask)
{
   size_t bytes = (size_t)g->w * (size_t)g->h * 4;
   unsigned char *px = malloc(bytes);
   char err[512];
   if (!px)
      fp_die("out of memory");
   fp_gl_check("the test's drawing");
   fp_gl_read_rgba(g, px);
   if (fp_png_write(a->out, g->w, g->h, px, err, sizeof(err)) != 0)
      fp_die("%s", err);
   if (a->mask) {
      unsigned char *m = NULL;
      if (!mask) {
         m = calloc(bytes, 1);
         if (!m)
            fp_die("out of memory");
         for (size_t i = 3; i < bytes; i += 4)
            m[i] = 255;
      }
      if (fp_png_write(a->mask, g->w, g->h, mask ? mask : m, err, sizeof(err)) != 0)
         fp_die("%s", err);
      free(m);
   }
   free(px);
   fp_gl_fini(g);
}

GLuint e2e_program(const char *vs, const char *fs, const char *attr1)
{
   const char *const attr[] = { "a_pos", attr1, NULL };
   return fp_gl_program(vs, fs, attr);
}

GLuint e2e_color_program(void)
{
   static const char *vs =
      "attribute vec4 a_pos;\n"
      "attribute vec4 a_color;\n"
      "varying vec4 v_color;\n"
      "void main() { v_color = a_color; gl_Position = a_pos; }\n";
   static const char *fs =
      "precision mediump float;\n"
      "varying vec4 v_color;\n"
      "void main() { gl_FragColor = v_color; }\n";
   return e2e_program(vs, fs, "a_color");
}

GLuint e2e_texture_program(void)
{
   static const char *vs =
      "attribute vec4 a_pos;\nattribute vec2 a_uv;\nvarying vec2 v_uv;\n"
      "void main() { v_uv = a_uv; gl_Position = a_pos; }\n";
   static const char *fs =
      "precision highp float;\nuniform sampler2D u_tex;\nvarying vec2 v_uv;\n"
      "void main() { gl_FragColor = texture2D(u_tex, v_uv); }\n";
   return e2e_program(vs, fs, "a_uv");
}

void e2e_draw_uv(GLenum mode, int n, const float *pos, const float *uv, int ncomp)
{
   glBindBuffer(GL_ARRAY_BUFFER, 0);
   glEnableVertexAttribArray(0);
   glEnableVertexAttribArray(1);
   glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 0, pos);
   glVertexAttribPointer(1, ncomp, GL_FLOAT, GL_FALSE, 0, uv);
   glDrawArrays(mode, 0, n);
   glDisableVertexAttribArray(0);
   glDisableVertexAttribArray(1);
}

void e2e_draw_rect(float x0, float y0, float x1, float y1, float u0, float v0, float u1,
                   float v1)
{
   const float pos[] = { x0, y0, 0, 1, x1, y0, 0, 1, x0, y1, 0, 1, x1, y1, 0, 1 };
   const float uv[] = { u0, v0, u1, v0, u0, v1, u1, v1 };
   e2e_draw_uv(GL_TRIANGLE_STRIP, 4, pos, uv, 2);
}

/* A GLSL ES `version` program: its vertex shader passes a_pos on as the
 * position and a_NAME (of `type`) on as v_NAME; fragment shader fs. */
static GLuint passthrough_program(const char *version, const char *type, const char *name,
                                  const char *fs)
{
   char vs[256], attr1[32];
   snprintf(vs, sizeof vs,
            "#version %s\n"
            "in vec4 a_pos;\n"
            "in %s a_%s;\n"
            "out %s v_%s;\n"
            "void main() { v_%s = a_%s; gl_Position = a_pos; }\n",
            version, type, name, type, name, name, name);
   snprintf(attr1, sizeof attr1, "a_%s", name);
   return e2e_program(vs, fs, attr1);
}

GLuint e2e_color_program_es3(const char *fs)
{
   return passthrough_program("300 es", "vec4", "color", fs);
}

GLuint e2e_uv_program_es31(const char *fs)
{
   return passthrough_program("310 es", "vec2", "uv", fs);
}

void e2e_show_samples(GLuint tex, GLuint target, int size)
{
   glBindFramebuffer(GL_FRAMEBUFFER, target);
   glViewport(0, 0, size, size);
   char fs[512];
   snprintf(fs, sizeof fs,
            "#version 310 es\n"
            "precision highp float;\n"
            "uniform highp sampler2DMS u_ms;\n"
            "out vec4 o_color;\n"
            "void main() {\n"
            "   ivec2 p = ivec2(gl_FragCoord.xy);\n"
            "   int k = p.x / %d + 2 * (p.y / %d);\n"
            "   o_color = texelFetch(u_ms, p %% %d, k);\n"
            "}\n",
            size / 2, size / 2, size / 2);
   glUseProgram(e2e_uv_program_es31(fs));
   glActiveTexture(GL_TEXTURE0);
   glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, tex);
   e2e_draw_rect(-1, -1, 1, 1, 0, 0, 1, 1);
}

void e2e_tex_params(GLenum target, GLenum min, GLenum mag, GLenum wrap_s, GLenum wrap_t)
{
   glTexParameteri(target, GL_TEXTURE_MIN_FILTER, (GLint)min);
   glTexParameteri(target, GL_TEXTURE_MAG_FILTER, (GLint)mag);
   glTexParameteri(target, GL_TEXTURE_WRAP_S, (GLint)wrap_s);
   glTexParameteri(target, GL_TEXTURE_WRAP_T, (GLint)wrap_t);
}

GLuint e2e_mip_texture(int size, int step, int hi, int lo, GLenum min, GLenum mag)
{
   GLuint t;
   unsigned char *p = malloc((size_t)size * (size_t)size * 4);
   if (!p)
      fp_die("out of memory");
   glGenTextures(1, &t);
   glBindTexture(GL_TEXTURE_2D, t);
   for (int l = 0, s = size; s >= 1; l++, s /= 2) {
      for (int i = 0; i < s * s; i++) {
         const int x = i % s, y = i / s;
         p[i * 4 + 0] = (unsigned char)(l * step);
         p[i * 4 + 1] = (unsigned char)(255 - l * step);
         p[i * 4 + 2] = (unsigned char)(((x ^ y) & 1) ? hi : lo);
         p[i * 4 + 3] = 255;
      }
      glTexImage2D(GL_TEXTURE_2D, l, GL_RGBA, s, s, 0, GL_RGBA, GL_UNSIGNED_BYTE, p);
   }
   free(p);
   e2e_tex_params(GL_TEXTURE_2D, min, mag, GL_REPEAT, GL_REPEAT);
   return t;
}

void e2e_draw(GLenum mode, int n, const float *pos, const float *color, const float rgba[4])
{
   glBindBuffer(GL_ARRAY_BUFFER, 0);
   glEnableVertexAttribArray(0);
   glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 0, pos);
   if (color) {
      glEnableVertexAttribArray(1);
      glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, 0, color);
   } else {
      glDisableVertexAttribArray(1);
      glVertexAttrib4fv(1, rgba);
   }
   glDrawArrays(mode, 0, n);
   glDisableVertexAttribArray(0);
   glDisableVertexAttribArray(1);
}

float e2e_ndc(int32_t sub, int size)
{
   /* x_w = (x_ndc + 1) * size / 2 and x_w = sub / 256. */
   return (float)((double)sub * 2.0 / ((double)size * E2E_SUB) - 1.0);
}

uint32_t e2e_rand(uint32_t *s)
{
   uint32_t x = *s;
   x ^= x << 13;
   x ^= x >> 17;
   x ^= x << 5;
   return *s = x;
}

int e2e_rand_range(uint32_t *s, int lo, int hi)
{
   return lo + (int)(e2e_rand(s) % (uint32_t)(hi - lo + 1));
}

int64_t e2e_tri_area2(const struct e2e_tri *t)
{
   return (int64_t)(t->x[1] - t->x[0]) * (t->y[2] - t->y[0]) -
          (int64_t)(t->x[2] - t->x[0]) * (t->y[1] - t->y[0]);
}

long e2e_tri_ties(const struct e2e_tri *t, int size, unsigned char *mask)
{
   int32_t minx = t->x[0], maxx = t->x[0], miny = t->y[0], maxy = t->y[0];
   for (int k = 1; k < 3; k++) {
      if (t->x[k] < minx) minx = t->x[k];
      if (t->x[k] > maxx) maxx = t->x[k];
      if (t->y[k] < miny) miny = t->y[k];
      if (t->y[k] > maxy) maxy = t->y[k];
   }
   int i0 = minx / E2E_SUB - 1, i1 = maxx / E2E_SUB + 1;
   int j0 = miny / E2E_SUB - 1, j1 = maxy / E2E_SUB + 1;
   if (i0 < 0) i0 = 0;
   if (j0 < 0) j0 = 0;
   if (i1 > size - 1) i1 = size - 1;
   if (j1 > size - 1) j1 = size - 1;
   int64_t area = e2e_tri_area2(t);
   long ties = 0;
   for (int j = j0; j <= j1; j++)
      for (int i = i0; i <= i1; i++) {
         int64_t px = (int64_t)i * E2E_SUB + E2E_SUB / 2, py = (int64_t)j * E2E_SUB + E2E_SUB / 2;
         int on_edge = 0, outside = 0;
         for (int k = 0; k < 3; k++) {
            int a = k, b = (k + 1) % 3;
            /* Edge function, oriented so that the inside is positive. */
            int64_t e = (int64_t)(t->x[b] - t->x[a]) * (py - t->y[a]) -
                        (int64_t)(t->y[b] - t->y[a]) * (px - t->x[a]);
            if (area < 0)
               e = -e;
            if (e == 0)
               on_edge = 1;
            else if (e < 0)
               outside = 1;
         }
         if (on_edge && !outside) {
            ties++;
            if (mask) {
               unsigned char *m = mask + ((size_t)(size - 1 - j) * (size_t)size + (size_t)i) * 4;
               m[0] = m[1] = m[2] = m[3] = 255;
            }
         }
      }
   return ties;
}

int e2e_msaa_create(struct e2e_msaa *m, int size)
{
   int problems = 0;
   m->size = size;
   glGenRenderbuffers(1, &m->color);
   glBindRenderbuffer(GL_RENDERBUFFER, m->color);
   glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_RGBA8, size, size);
   glGenRenderbuffers(1, &m->ds);
   glBindRenderbuffer(GL_RENDERBUFFER, m->ds);
   glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_DEPTH24_STENCIL8, size, size);
   glGenFramebuffers(1, &m->fbo);
   glBindFramebuffer(GL_FRAMEBUFFER, m->fbo);
   glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, m->color);
   glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                             m->ds);
   if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      printf("error: the 4-sample framebuffer is not complete\n");
      problems++;
   }
   GLint samples = 0;
   glGetIntegerv(GL_SAMPLES, &samples);
   if (samples != 4) {
      printf("error: GL_SAMPLES of the multisampled framebuffer is %d, not 4\n", samples);
      problems++;
   }
   glViewport(0, 0, size, size);
   return problems;
}

void e2e_msaa_resolve(const struct e2e_msaa *m, GLuint target)
{
   glBindFramebuffer(GL_READ_FRAMEBUFFER, m->fbo);
   glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target);
   glBlitFramebuffer(0, 0, m->size, m->size, 0, 0, m->size, m->size, GL_COLOR_BUFFER_BIT,
                     GL_NEAREST);
   glBindFramebuffer(GL_FRAMEBUFFER, target);
}

void e2e_msaa_delete(struct e2e_msaa *m)
{
   glDeleteFramebuffers(1, &m->fbo);
   glDeleteRenderbuffers(1, &m->color);
   glDeleteRenderbuffers(1, &m->ds);
}

bool e2e_has_extension(const char *name)
{
   GLint n = 0;
   glGetIntegerv(GL_NUM_EXTENSIONS, &n);
   for (GLint i = 0; i < n; i++)
      if (!strcmp((const char *)glGetStringi(GL_EXTENSIONS, (GLuint)i), name))
         return true;
   return false;
}
