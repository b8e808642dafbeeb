/*
 * Robust vertex fetch (GL_KHR_robust_buffer_access_behavior, 64x64):
 * points, one a pixel, whose colour attribute comes from a buffer of 16
 * colours too short for the draw: vertices past its end (non-indexed from
 * a first inside it and from far beyond), out-of-range indices (32-bit,
 * far beyond; 16-bit), instances past its end, and an attribute offset
 * that leaves no room for one vertex.  Every point's position comes from
 * gl_VertexID or gl_InstanceID, never from a buffer; its alpha from a
 * second attribute in a buffer long enough for the draw (or constant).
 *
 * Self-checks (errors fail the program on any driver): the extension is
 * exposed; every point is drawn; a vertex inside the short buffer reads
 * its own colour; one outside reads zero or a colour of the buffer, never
 * memory outside it (buffers of another colour lie around it), and the
 * draw does not crash; the long buffer's attribute reads its own value
 * however far the short one's runs out.  What an out-of-range vertex
 * reads is the driver's choice (llvmpipe zero, fixpipe the last vertex),
 * so the mask leaves those pixels out of the comparison.
 */
#include "e2e_common.h"

#include <GLES3/gl3.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define ENTRIES 16   /* colours in the short buffer */
#define LONG 128     /* entries of the long buffer */
#define POINTS 64    /* points a draw, one a column */

static const char vs[] =
   "#version 300 es\n"
   "in vec4 a_color;\n"
   "in float a_check;\n"
   "uniform int u_first;\n"
   "uniform int u_instanced;\n"
   "uniform int u_row;\n"
   "flat out vec4 v_color;\n"
   "void main() {\n"
   "   int x = u_instanced != 0 ? gl_InstanceID : (gl_VertexID - u_first) & 63;\n"
   "   gl_Position = vec4((float(x) + 0.5) / 32.0 - 1.0,\n"
   "                      (float(u_row) + 0.5) / 32.0 - 1.0, 0.0, 1.0);\n"
   "   gl_PointSize = 1.0;\n"
   "   v_color = vec4(a_color.rgb, a_check);\n"
   "}\n";

static const char fs[] =
   "#version 300 es\n"
   "precision highp float;\n"
   "flat in vec4 v_color;\n"
   "out vec4 o_color;\n"
   "void main() { o_color = v_color; }\n";

enum kind { LINEAR, INDEXED32, INDEXED16, INSTANCED };

/* One row of points: how it draws, and which of its points read inside
 * the short buffer (column x reads entry x - inside_from when inside). */
struct row_case {
   const char *name;
   enum kind kind;
   int first;          /* LINEAR: first vertex */
   unsigned index_add; /* INDEXED: index of column x is x + index_add */
   int offset;         /* the colour attribute's offset into its buffer */
   bool check_attr;    /* a_check from the long buffer (else constant 1) */
   int inside_from;    /* entry of column 0, or -1: no column reads inside */
};

static const struct row_case cases[] = {
   { "linear-past-end", LINEAR, 8, 0, 0, true, 8 },
   { "linear-far", LINEAR, 1 << 20, 0, 0, false, -1 },
   { "indexed-past-end", INDEXED32, 0, 0, 0, true, 0 },
   { "indexed-far", INDEXED32, 0, 64u << 16, 0, false, -1 },
   { "indexed16-past-end", INDEXED16, 0, 64 * 1000, 0, false, -1 },
   { "instanced-past-end", INSTANCED, 0, 0, 0, false, 0 },
   { "no-room-for-a-vertex", LINEAR, 0, 0, ENTRIES * 4 - 2, false, -1 },
};
#define NCASES (int)(sizeof(cases) / sizeof(cases[0]))

static int row_of(int c) { return 4 * c + 2; }

static void entry_color(int i, unsigned char rgb[3])
{
   rgb[0] = (unsigned char)(20 + 14 * i);
   rgb[1] = (unsigned char)(240 - 13 * i);
   rgb[2] = (unsigned char)(60 + 11 * i);
}

static GLuint buffer_of(const void *data, GLsizeiptr size, GLenum target)
{
   GLuint b;
   glGenBuffers(1, &b);
   glBindBuffer(target, b);
   glBufferData(target, size, data, GL_STATIC_DRAW);
   return b;
}

/* Buffers of the short one's size in a colour it does not hold, made
 * around it so that memory past its end likely holds that colour. */
static void poison_buffers(GLuint *b, int n)
{
   unsigned char poison[ENTRIES * 4];
   for (int i = 0; i < ENTRIES; i++)
      memcpy(poison + 4 * i, (const unsigned char[]){ 255, 0, 255, 255 }, 4);
   for (int i = 0; i < n; i++)
      b[i] = buffer_of(poison, sizeof(poison), GL_ARRAY_BUFFER);
}

static void draw_case(const struct row_case *rc, GLuint prog, GLuint colors, GLuint checks)
{
   glUniform1i(glGetUniformLocation(prog, "u_row"), row_of((int)(rc - cases)));
   glUniform1i(glGetUniformLocation(prog, "u_instanced"), rc->kind == INSTANCED);
   glUniform1i(glGetUniformLocation(prog, "u_first"), rc->kind == LINEAR ? rc->first : 0);

   glBindBuffer(GL_ARRAY_BUFFER, colors);
   glVertexAttribPointer(0, 4, GL_UNSIGNED_BYTE, GL_TRUE, 4, (const void *)(intptr_t)rc->offset);
   glVertexAttribDivisor(0, rc->kind == INSTANCED);
   glEnableVertexAttribArray(0);
   if (rc->check_attr) {
      glBindBuffer(GL_ARRAY_BUFFER, checks);
      glVertexAttribPointer(1, 1, GL_UNSIGNED_BYTE, GL_TRUE, 1, NULL);
      glEnableVertexAttribArray(1);
   } else {
      glDisableVertexAttribArray(1);
      glVertexAttrib1f(1, 1.0f);
   }

   switch (rc->kind) {
   case LINEAR:
      glDrawArrays(GL_POINTS, rc->first, POINTS);
      break;
   case INSTANCED:
      glDrawArraysInstanced(GL_POINTS, 0, 1, POINTS);
      break;
   case INDEXED32:
   case INDEXED16: {
      GLuint idx32[POINTS];
      GLushort idx16[POINTS];
      for (unsigned x = 0; x < POINTS; x++) {
         idx32[x] = x + rc->index_add;
         idx16[x] = (GLushort)(x + rc->index_add);
      }
      const bool wide = rc->kind == INDEXED32;
      GLuint ib = buffer_of(wide ? (const void *)idx32 : (const void *)idx16,
                            wide ? (GLsizeiptr)sizeof(idx32) : (GLsizeiptr)sizeof(idx16),
                            GL_ELEMENT_ARRAY_BUFFER);
      glDrawElements(GL_POINTS, POINTS, wide ? GL_UNSIGNED_INT : GL_UNSIGNED_SHORT, NULL);
      glDeleteBuffers(1, &ib);
      break;
   }
   }
}

static bool is_entry(const unsigned char *px)
{
   for (int i = 0; i < ENTRIES; i++) {
      unsigned char rgb[3];
      entry_color(i, rgb);
      if (!memcmp(px, rgb, 3))
         return true;
   }
   return false;
}

/* Checks one row; marks its out-of-range points in the mask. */
static void check_case(const struct row_case *rc, const unsigned char *img,
                       unsigned char *mask, int size, int *outside_buffer, int *wrong)
{
   const int y = size - 1 - row_of((int)(rc - cases));   /* PNG rows run top down */
   for (int x = 0; x < POINTS; x++) {
      const size_t k = 4 * ((size_t)y * (size_t)size + (size_t)x);
      const unsigned char *px = img + k;
      const int entry = rc->inside_from < 0 ? -1 : rc->inside_from + x;
      const unsigned vertex = (unsigned)(rc->kind == LINEAR ? rc->first + x : x);
      const unsigned char alpha = rc->check_attr ? (unsigned char)(vertex + 1) : (unsigned char)255;
      if (px[3] != alpha)
         ++*wrong;   /* not drawn, or the long buffer's attribute misread */
      if (entry >= 0 && entry < ENTRIES) {
         unsigned char rgb[3];
         entry_color(entry, rgb);
         *wrong += memcmp(px, rgb, 3) != 0;
      } else {
         const bool zero = !px[0] && !px[1] && !px[2];
         *outside_buffer += !zero && !is_entry(px);
         memset(mask + k, 255, 4);
      }
   }
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   struct fp_gl g;
   e2e_start(&g, &a, argc, argv, 64);
   if (a.size != 64)
      fp_die("--size: 64");
   e2e_check(e2e_has_extension("GL_KHR_robust_buffer_access_behavior"),
             "GL_KHR_robust_buffer_access_behavior is not exposed");

   static const char *const attribs[] = { "a_color", "a_check", NULL };
   const GLuint prog = fp_gl_program(vs, fs, attribs);
   glUseProgram(prog);

   GLuint before[4], after[4];
   poison_buffers(before, 4);
   unsigned char colors[ENTRIES * 4];
   for (int i = 0; i < ENTRIES; i++) {
      entry_color(i, colors + 4 * i);
      colors[4 * i + 3] = 255;
   }
   const GLuint short_buf = buffer_of(colors, sizeof(colors), GL_ARRAY_BUFFER);
   poison_buffers(after, 4);
   unsigned char checks[LONG];
   for (int i = 0; i < LONG; i++)
      checks[i] = (unsigned char)(i + 1);
   const GLuint long_buf = buffer_of(checks, sizeof(checks), GL_ARRAY_BUFFER);

   glClearColor(0, 0, 0, 0);
   glClear(GL_COLOR_BUFFER_BIT);
   for (int c = 0; c < NCASES; c++)
      draw_case(&cases[c], prog, short_buf, long_buf);

   const size_t n = (size_t)a.size * (size_t)a.size * 4;
   unsigned char *img = malloc(n), *mask = calloc(n, 1);
   if (!img || !mask)
      fp_die("out of memory");
   fp_gl_read_rgba(&g, img);
   int total_outside = 0, total_wrong = 0;
   for (int c = 0; c < NCASES; c++) {
      int outside = 0, wrong = 0;
      check_case(&cases[c], img, mask, a.size, &outside, &wrong);
      printf("stat: %s_outside_buffer=%d,%s_wrong=%d\n", cases[c].name, outside,
             cases[c].name, wrong);
      total_outside += outside;
      total_wrong += wrong;
   }
   e2e_check(total_outside == 0, "a vertex fetch read outside its buffer");
   e2e_check(total_wrong == 0,
             "a point not drawn, or an in-range fetch that did not read its own value");

   glDeleteBuffers(4, before);
   glDeleteBuffers(4, after);
   glDeleteBuffers(1, &short_buf);
   glDeleteBuffers(1, &long_buf);
   free(img);
   const int status = e2e_finish(&g, &a, mask);
   free(mask);
   return status;
}
