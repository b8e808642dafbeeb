/*
 * Adversarial GL input (issue 11, item 5): one case per run (--case NAME),
 * each the kind of input a GL program may send and a model must survive:
 * positions, texture coordinates and point sizes that are NaN, infinite or
 * 1e30; w near 0 and negative; slivers of 1e-6 pixel; vertices on pixel
 * centres; fans and jittered meshes of 10^5 triangles at 2048 x 2048.
 *
 * Every case checks its defined result itself (docs/adversarial.md) and
 * prints one line a check:
 *   check: NAME ok|FAIL WHAT
 * and writes its picture (-o) for tests/e2e/adversarial.sh, which runs the
 * case through the sanitized driver and through llvmpipe and compares the
 * two where GL defines the picture.  Exit status: 0 when every check held,
 * 1 when one did not, 2 on a set-up error.
 *
 * The counting cases draw every triangle with ONE + ONE blending of 1/255:
 * a pixel's red byte is how many triangles covered it, so a hole is a 0 and
 * a pixel drawn twice a 2 (GL's rule for shared edges: exactly once).
 */
#include "e2e_common.h"
#include "fp_png.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static struct fp_gl *gl;
static int size;
static unsigned char *px;      /* the read-back picture, PNG row order */
static int failures;

static void check(bool ok, const char *name, const char *fmt, ...)
   __attribute__((format(printf, 3, 4)));

static void check(bool ok, const char *name, const char *fmt, ...)
{
   va_list ap;
   printf("check: %s %s ", name, ok ? "ok" : "FAIL");
   va_start(ap, fmt);
   vprintf(fmt, ap);
   va_end(ap);
   printf("\n");
   failures += !ok;
}

static void *xcalloc(size_t n, size_t s)
{
   void *p = calloc(n, s);
   if (!p)
      fp_die("out of memory");
   return p;
}

/* Window pixel coordinate (GL, y up) -> clip space at w = 1. */
static float ndc(double p)
{
   return (float)(p * 2.0 / size - 1.0);
}

static void read_back(void)
{
   glFinish();
   fp_gl_read_rgba(gl, px);
}

/* The pixel at window (x, y), GL's y up. */
static const unsigned char *at(int x, int y)
{
   return px + ((size_t)(size - 1 - y) * (size_t)size + (size_t)x) * 4;
}

/* Pixels in the window box [x0, x1) x [y0, y1) whose channel c is v (or, with
 * v < 0, not 0). */
static long count_in(int x0, int y0, int x1, int y1, int c, int v)
{
   long n = 0;
   for (int y = y0; y < y1; y++)
      for (int x = x0; x < x1; x++) {
         int b = at(x, y)[c];
         n += v < 0 ? b != 0 : b == v;
      }
   return n;
}

static void clear(void)
{
   glDisable(GL_BLEND);
   glClearColor(0, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT);
}

static const float red[4] = { 1, 0, 0, 1 }, green[4] = { 0, 1, 0, 1 };
static const float one_count[4] = { 1.0f / 255.0f, 0, 0, 1 };

/* ------------------------------------------------------------ positions */

/* A triangle in the cell (cx, cy) of side s pixels, clip space at w = 1. */
static void cell_tri(float *pos, int cx, int cy, int s)
{
   const double x = cx * s, y = cy * s;
   const double v[3][2] = { { x + 0.13 * s, y + 0.11 * s }, { x + 0.87 * s, y + 0.2 * s },
                            { x + 0.41 * s, y + 0.9 * s } };
   for (int k = 0; k < 3; k++) {
      pos[4 * k + 0] = ndc(v[k][0]);
      pos[4 * k + 1] = ndc(v[k][1]);
      pos[4 * k + 2] = 0.25f;
      pos[4 * k + 3] = 1.0f;
   }
}

/* NaN or an infinity in one coordinate of one vertex: per GL the result is
 * undefined; the model's is defined: a primitive with a position that is not
 * finite after the perspective divide is dropped before the cull stage,
 * counted (docs/adversarial.md).  Triangles, lines and points, each next to
 * a finite control of its own that must draw.  w = +inf is not among them:
 * it divides to the finite (0, 0, 0, 1/w = 0) and is drawn (case_inf_w). */
static void bad_positions(const char *name, const float *bad, int nbad)
{
   const int s = size / 16;
   clear();
   GLuint prog = e2e_color_program();
   glUseProgram(prog);
   int cell = 0;
   long control_cells = 0;
   for (int b = 0; b < nbad; b++)
      for (int k = 0; k < 3; k++)
         for (int c = 0; c < 4; c++, cell += 2) {
            if (c == 3 && bad[b] == INFINITY) {
               cell -= 2;
               continue;
            }
            float pos[12];
            /* the control, green, in the next cell */
            cell_tri(pos, (cell + 1) % 16, (cell + 1) / 16, s);
            e2e_draw(GL_TRIANGLES, 3, pos, NULL, green);
            control_cells++;
            cell_tri(pos, cell % 16, cell / 16, s);
            pos[4 * k + c] = bad[b];
            e2e_draw(GL_TRIANGLES, 3, pos, NULL, red);
            /* the same vertex as a line's end and as a point */
            e2e_draw(GL_LINES, 2, pos + (k == 2 ? 4 : 4 * k), NULL, red);
            e2e_draw(GL_POINTS, 1, pos + 4 * k, NULL, red);
         }
   read_back();
   long reds = count_in(0, 0, size, size, 0, -1);
   check(reds == 0, name, "%ld pixels drawn by primitives with a %s position (expected none)",
         reds, name);
   long empty_controls = 0;
   for (int i = 1; i < cell; i += 2) {
      int cx = i % 16, cy = i / 16;
      empty_controls += count_in(cx * s, cy * s, cx * s + s, cy * s + s, 1, 255) == 0;
   }
   check(empty_controls == 0, name, "%ld of %ld finite control triangles drew nothing",
         empty_controls, control_cells);
   glDeleteProgram(prog);
}

static void case_nan_position(void)
{
   const float bad[] = { NAN };
   bad_positions("nan-position", bad, 1);
}

static void case_inf_position(void)
{
   const float bad[] = { INFINITY, -INFINITY };
   bad_positions("inf-position", bad, 2);

   /* w = +inf at one vertex: x/w = y/w = z/w = 0, drawn as the vertex at the
    * centre of the window (flat colour: the coverage alone) */
   clear();
   GLuint prog = e2e_color_program();
   glUseProgram(prog);
   const int s = size / 8;
   glEnable(GL_BLEND);
   glBlendFunc(GL_ONE, GL_ONE);
   for (int k = 0; k < 3; k++) {
      float pos[12];
      cell_tri(pos, 2 * k + 1, 1, s);
      pos[4 * k + 3] = INFINITY;
      e2e_draw(GL_TRIANGLES, 3, pos, NULL, one_count);
      cell_tri(pos, 2 * k + 1, 6, s);
      pos[4 * k + 0] = pos[4 * k + 1] = pos[4 * k + 2] = 0.0f;
      e2e_draw(GL_TRIANGLES, 3, pos, NULL, one_count);
   }
   glDisable(GL_BLEND);
   read_back();
   unsigned char *inf_w = xcalloc((size_t)size * size, 4);
   memcpy(inf_w, px, (size_t)size * size * 4);
   clear();
   glEnable(GL_BLEND);
   glBlendFunc(GL_ONE, GL_ONE);
   for (int k = 0; k < 3; k++)
      for (int half = 0; half < 2; half++) {
         float pos[12];
         cell_tri(pos, 2 * k + 1, half ? 6 : 1, s);
         pos[4 * k + 0] = pos[4 * k + 1] = pos[4 * k + 2] = 0.0f;
         e2e_draw(GL_TRIANGLES, 3, pos, NULL, one_count);
      }
   glDisable(GL_BLEND);
   read_back();
   long differ = 0;
   for (size_t i = 0; i < (size_t)size * size * 4; i++)
      differ += inf_w[i] != px[i];
   check(differ == 0, "inf-position",
         "w = +inf drew %ld bytes unlike the same vertex at (0, 0, 0, 1)", differ);
   free(inf_w);
   glDeleteProgram(prog);
}

/* Coordinates of +-1e30 in clip space at w = 1.  GL clips them to the
 * viewport; Mesa's draw module does it in binary32 for the model as for
 * llvmpipe and softpipe (seed 004: the stages before scan conversion are
 * floating point), and adversarial.sh compares the pictures with llvmpipe's.
 *   A triangle around the window, every vertex at 1e30: binary32 cannot hold
 *     its clipped polygon (1 - 1e30 is -1e30), and every Mesa driver covers
 *     3/8 of the window (stat: around_covered, docs/adversarial.md).
 *   Wedges with one vertex at 1e30 in x, in y or in z: the clipped polygon is
 *     its limit to within 1e-30 (the edges towards the far vertex run along
 *     the axis, or the far plane cuts them at the near vertices): checked
 *     equal, byte for byte, to those limit polygons drawn as such. */
static void case_huge_position(void)
{
   clear();
   GLuint prog = e2e_color_program();
   glUseProgram(prog);
   const float H = 1e30f;
   const float around[] = { -H, -H, 0, 1, H, -H, 0, 1, 0, H, 0, 1 };
   e2e_draw(GL_TRIANGLES, 3, around, NULL, one_count);
   read_back();
   printf("stat: around_covered=%ld of %ld\n", count_in(0, 0, size, size, 0, 1),
          (long)size * size);

   /* A, B inside, C far; the limit of the clipped polygon */
   const float wedges[3][3][4] = {
      { { -0.52f, -0.47f, 0, 1 }, { 0.31f, -0.61f, 0, 1 }, { H, 0.3f, 0, 1 } },
      { { -0.93f, 0.22f, 0, 1 }, { -0.18f, 0.87f, 0, 1 }, { -0.3f, -H, 0, 1 } },
      { { 0.13f, 0.11f, 0, 1 }, { 0.81f, 0.17f, 0, 1 }, { 0.43f, 0.71f, H, 1 } },
   };
   static const float colors[3][4] = { { 1, 0, 0, 1 }, { 0, 1, 0, 1 }, { 0, 0, 1, 1 } };
   clear();
   for (int i = 0; i < 3; i++)
      e2e_draw(GL_TRIANGLES, 3, &wedges[i][0][0], NULL, colors[i]);
   read_back();
   unsigned char *far = xcalloc((size_t)size * size, 4);
   memcpy(far, px, (size_t)size * size * 4);
   clear();
   for (int i = 0; i < 2; i++) {
      const float *A = wedges[i][0], *B = wedges[i][1];
      /* x far: A, B, (1, yB), (1, yA); y far: A, B, (xB, -1), (xA, -1) */
      float a2[4] = { i ? A[0] : 1.0f, i ? -1.0f : A[1], 0, 1 };
      float b2[4] = { i ? B[0] : 1.0f, i ? -1.0f : B[1], 0, 1 };
      const float quad[] = { A[0], A[1], 0, 1, B[0], B[1], 0, 1, b2[0], b2[1], 0, 1,
                             A[0], A[1], 0, 1, b2[0], b2[1], 0, 1, a2[0], a2[1], 0, 1 };
      e2e_draw(GL_TRIANGLES, 6, quad, NULL, colors[i]);
   }
   /* z far: the far plane cuts both edges to C at A and B: nothing */
   read_back();
   long differ = 0, drawn = 0;
   for (size_t i = 0; i < (size_t)size * size * 4; i++)
      differ += far[i] != px[i];
   drawn = count_in(0, 0, size, size, 0, -1) + count_in(0, 0, size, size, 1, -1);
   check(differ == 0 && drawn > size * size / 8, "huge-position",
         "wedges to 1e30: %ld bytes unlike their limit polygons (%ld pixels drawn)", differ,
         drawn);
   /* the picture compared with llvmpipe's: the wedges */
   memcpy(px, far, (size_t)size * size * 4);
   free(far);
   glDeleteProgram(prog);
}

/* w near 0 and negative.  GL clips at -w <= x, y, z <= w:
 *   a triangle whose vertices all have w < 0 (no point passes): nothing;
 *   one vertex at (0, 0, 0, w), w = 1e-20 or 1e-37: the clip-space point is
 *     inside and divides to the window's centre: the same coverage as with
 *     w = 1 there (flat colour; checked byte for byte);
 *   w = 1e-45, +0 and -0: the model drops the triangle, its position after
 *     the divide not being finite (docs/adversarial.md): 0/0, or 1/w beyond
 *     binary32 (a denormal w, if the vertex stage has not flushed it to 0);
 *   one vertex at w = -1 beyond the window: clipped at the near and side
 *     planes (compared with llvmpipe by adversarial.sh). */
static void case_w_near_zero(void)
{
   clear();
   GLuint prog = e2e_color_program();
   glUseProgram(prog);
   const float behind[] = { 0.5f, 0.5f, 0, -1, -0.5f, 0.5f, 0, -1, 0, -0.5f, 0, -2 };
   e2e_draw(GL_TRIANGLES, 3, behind, NULL, red);
   read_back();
   long reds = count_in(0, 0, size, size, 0, -1);
   check(reds == 0, "w-near-zero", "a triangle with every w < 0 drew %ld pixels (expected none)",
         reds);

   static const float tiny_w[6] = { 1e-20f, 1e-37f, 1e-45f, 0.0f, -0.0f, -1.0f };
   static const float colors[6][4] = { { 1, 0, 0, 1 }, { 0, 1, 0, 1 }, { 0, 0, 1, 1 },
                                       { 1, 1, 0, 1 }, { 0, 1, 1, 1 }, { 1, 0, 1, 1 } };
   unsigned char *pic[2];
   for (int pass = 0; pass < 2; pass++) {
      /* pass 1: w = 1 where w is tiny, nothing where it is not finite after
       * the divide, the same at w = -1 */
      clear();
      for (int i = 0; i < 6; i++) {
         /* a column of the window each, its triangle's third vertex at the
          * centre of the window (w = -1: beyond the bottom left) */
         const float x0 = -1.0f + (float)i / 3.0f, x1 = x0 + 1.0f / 3.0f;
         float w = tiny_w[i];
         if (pass == 1 && (i == 2 || i == 3 || i == 4))
            continue;
         if (pass == 1 && i < 2)
            w = 1.0f;
         const float third[4] = { w == -1.0f ? 0.3f : 0.0f, w == -1.0f ? 0.9f : 0.0f, 0.0f, w };
         const float pos[] = { x0 + 0.02f, -0.9f, 0, 1, x1 - 0.02f, -0.7f, 0, 1,
                               third[0], third[1], third[2], third[3] };
         e2e_draw(GL_TRIANGLES, 3, pos, NULL, colors[i]);
      }
      read_back();
      pic[pass] = xcalloc((size_t)size * size, 4);
      memcpy(pic[pass], px, (size_t)size * size * 4);
   }
   long differ = 0;
   for (size_t i = 0; i < (size_t)size * size * 4; i++)
      differ += pic[0][i] != pic[1][i];
   long drawn = count_in(0, 0, size, size, 0, -1) + count_in(0, 0, size, size, 1, -1) +
                count_in(0, 0, size, size, 2, -1);
   check(differ == 0 && drawn > 1000, "w-near-zero",
         "w = 1e-20, 1e-37 drawn as w = 1, w = 1e-45, +-0 dropped: %ld bytes differ "
         "(%ld pixels drawn)", differ, drawn);
   memcpy(px, pic[0], (size_t)size * size * 4);
   free(pic[0]);
   free(pic[1]);
   glDeleteProgram(prog);
}

/* ------------------------------------------------------------ texturing */

/* 4 x 4 texels of distinct colours, NEAREST and REPEAT, and mip levels of
 * one colour each for the NEAREST_MIPMAP_NEAREST half. */
static const unsigned char level_rgb[3][3] = { { 255, 0, 0 }, { 0, 255, 0 }, { 0, 0, 255 } };

static GLuint make_texture(bool mipmapped)
{
   GLuint t;
   glGenTextures(1, &t);
   glBindTexture(GL_TEXTURE_2D, t);
   glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
   if (!mipmapped) {
      unsigned char texels[16 * 4];
      for (int i = 0; i < 16; i++) {
         texels[4 * i + 0] = (unsigned char)(32 + 64 * (i % 4));
         texels[4 * i + 1] = (unsigned char)(32 + 64 * (i / 4));
         texels[4 * i + 2] = 200;
         texels[4 * i + 3] = 255;
      }
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
   } else {
      for (int l = 0; l < 3; l++) {
         int s = 4 >> l;
         unsigned char texels[16 * 4];
         for (int i = 0; i < s * s; i++) {
            memcpy(texels + 4 * i, level_rgb[l], 3);
            texels[4 * i + 3] = 255;
         }
         glTexImage2D(GL_TEXTURE_2D, l, GL_RGBA, s, s, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
      }
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
   }
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
   glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
   return t;
}

static bool is_texel(const unsigned char *p, bool mipmapped)
{
   if (mipmapped) {
      for (int l = 0; l < 3; l++)
         if (!memcmp(p, level_rgb[l], 3))
            return true;
      return false;
   }
   return p[0] % 64 == 32 && p[1] % 64 == 32 && p[2] == 200;
}

/* Quads in bands, one vertex of each with a coordinate of bad[] in u or v:
 * NEAREST on the left half, NEAREST_MIPMAP_NEAREST on the right. */
static void texcoord_bands(const float bad[5])
{
   clear();
   for (int half = 0; half < 2; half++) {
      GLuint tex = make_texture(half == 1);
      for (int b = 0; b < 5; b++)
         for (int comp = 0; comp < 2; comp++) {
            const int row = b * 2 + comp;
            const float x0 = half ? 0.0f : -1.0f, x1 = x0 + 1.0f;
            const float y0 = -1.0f + (float)row * 0.2f, y1 = y0 + 0.2f;
            const float pos[] = { x0, y0, 0, 1, x1, y0, 0, 1, x0, y1, 0, 1,
                                  x1, y0, 0, 1, x1, y1, 0, 1, x0, y1, 0, 1 };
            float uv[] = { 0, 0, 3, 0, 0, 1, 3, 0, 3, 1, 0, 1 };
            uv[2 * 4 + comp] = bad[b];   /* the second triangle's middle vertex */
            e2e_draw_uv(GL_TRIANGLES, 6, pos, uv, 2);
         }
      glDeleteTextures(1, &tex);
   }
   read_back();
}

/* Texture coordinates NaN, +-inf and +-1e30 at one vertex of a quad, NEAREST
 * and NEAREST_MIPMAP_NEAREST (where the LOD comes from the non-finite
 * derivatives).  GL leaves the texels undefined; the model's are defined
 * (docs/adversarial.md), and checked here:
 *   every pixel is a texel of the texture, none a colour it does not have;
 *   a NaN at a vertex samples as 0 there: the same bytes as with 0.
 * (adversarial.sh checks that every datapath draws the same bytes.) */
static void case_bad_texcoord(void)
{
   GLuint prog = e2e_texture_program();
   glUseProgram(prog);
   const float zero[] = { 0.0f, INFINITY, -INFINITY, 1e30f, -1e30f };
   texcoord_bands(zero);
   unsigned char *as_zero = xcalloc((size_t)size * size, 4);
   memcpy(as_zero, px, (size_t)size * size * 4);
   const float bad[] = { NAN, INFINITY, -INFINITY, 1e30f, -1e30f };
   texcoord_bands(bad);
   long odd[2] = { 0, 0 }, differ = 0;
   for (int y = 0; y < size; y++)
      for (int x = 0; x < size; x++)
         odd[x >= size / 2] += !is_texel(at(x, y), x >= size / 2);
   for (size_t i = 0; i < (size_t)size * size * 4; i++)
      differ += as_zero[i] != px[i];
   free(as_zero);
   check(odd[0] == 0, "bad-texcoord", "NEAREST: %ld pixels not a texel of the texture", odd[0]);
   check(odd[1] == 0, "bad-texcoord",
         "NEAREST_MIPMAP_NEAREST: %ld pixels not a texel of any level", odd[1]);
   check(differ == 0, "bad-texcoord", "a NaN coordinate drew %ld bytes unlike 0 in its place",
         differ);
   glDeleteProgram(prog);
}

/* ------------------------------------------------------------ point sizes */

static GLuint point_program(void)
{
   static const char *vs =
      "attribute vec4 a_pos;\nattribute float a_size;\n"
      "void main() { gl_PointSize = a_size; gl_Position = a_pos; }\n";
   static const char *fs =
      "precision mediump float;\nuniform vec4 u_color;\n"
      "void main() { gl_FragColor = u_color; }\n";
   return e2e_program(vs, fs, "a_size");
}

/* gl_PointSize NaN, +-inf, 0, -1, 1e-30, 1e30 and finite sizes: GL clamps a
 * size to the implementation's range [1, ALIASED_POINT_SIZE_RANGE max]; the
 * model takes NaN as the smallest (docs/adversarial.md).  Each point alone
 * in the window, around a pixel centre: checked, it covers the square of its
 * clamped size, side^2 pixels for odd sides (the picture left for llvmpipe's
 * is the last: 12.5).  The window is 512: the largest square fits. */
static void case_bad_pointsize(void)
{
   GLuint prog = point_program();
   glUseProgram(prog);
   glUniform4f(glGetUniformLocation(prog, "u_color"), 0, 1, 0, 1);
   GLfloat range[2];
   glGetFloatv(GL_ALIASED_POINT_SIZE_RANGE, range);
   const float sizes[] = { NAN, INFINITY, -INFINITY, 0.0f, -1.0f, 1e-30f, 1e30f, 1.0f, 5.0f,
                           12.5f };
   const float pos[4] = { ndc(size / 2 + 0.5), ndc(size / 2 + 0.5), 0, 1 };
   for (size_t i = 0; i < sizeof(sizes) / sizeof(sizes[0]); i++) {
      clear();
      glBindBuffer(GL_ARRAY_BUFFER, 0);
      glEnableVertexAttribArray(0);
      glEnableVertexAttribArray(1);
      glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 0, pos);
      glVertexAttribPointer(1, 1, GL_FLOAT, GL_FALSE, 0, &sizes[i]);
      glDrawArrays(GL_POINTS, 0, 1);
      glDisableVertexAttribArray(0);
      glDisableVertexAttribArray(1);
      read_back();
      const float s = sizes[i];
      const float clamped = isnan(s) || s < 1.0f ? 1.0f : s > range[1] ? range[1] : s;
      const long side = lrintf(clamped), got = count_in(0, 0, size, size, 1, -1);
      const long lo = side & 1 ? side * side : (side - 1) * (side - 1);
      const long hi = side & 1 ? side * side : (side + 1) * (side + 1);
      check(got >= lo && got <= hi, "bad-pointsize",
            "size %g (clamped to %g): %ld pixels (expected %ld..%ld)", (double)s,
            (double)clamped, got, lo, hi);
   }
   glDeleteProgram(prog);
}

/* ------------------------------------------------------------ watertightness */

/* Draws triangles (window coordinates, y up) with ONE + ONE blending of 1/255
 * and checks that every pixel of the box [x0, x1) x [y0, y1) is covered once
 * and every other pixel not at all. */
static void counted(const char *name, const double (*tri)[2], long ntri, int x0, int y0, int x1,
                    int y1)
{
   clear();
   GLuint prog = e2e_color_program();
   glUseProgram(prog);
   glEnable(GL_BLEND);
   glBlendFunc(GL_ONE, GL_ONE);
   const long batch = 3 * 20000;
   float *pos = xcalloc((size_t)batch * 4, sizeof(float));
   for (long v0 = 0; v0 < 3 * ntri; v0 += batch) {
      long n = 3 * ntri - v0 < batch ? 3 * ntri - v0 : batch;
      for (long v = 0; v < n; v++) {
         pos[4 * v + 0] = ndc(tri[v0 + v][0]);
         pos[4 * v + 1] = ndc(tri[v0 + v][1]);
         pos[4 * v + 2] = 0;
         pos[4 * v + 3] = 1;
      }
      e2e_draw(GL_TRIANGLES, (int)n, pos, NULL, one_count);
   }
   free(pos);
   glDisable(GL_BLEND);
   read_back();
   long holes = 0, twice = 0, outside = 0;
   for (int y = 0; y < size; y++)
      for (int x = 0; x < size; x++) {
         int c = at(x, y)[0];
         bool in = x >= x0 && x < x1 && y >= y0 && y < y1;
         if (in)
            holes += c == 0, twice += c > 1;
         else
            outside += c != 0;
      }
   check(holes == 0 && twice == 0 && outside == 0, name,
         "%ld triangles: %ld holes, %ld pixels covered more than once, %ld outside", ntri, holes,
         twice, outside);
   glDeleteProgram(prog);
}

/* A fan around an inner point to rim points along the box's border. */
static long fan(double (*tri)[2], double cx, double cy, int x0, int y0, int x1, int y1,
                const double *t, long n)
{
   /* t[i] in [0, 1): the rim point's place along the border, anticlockwise */
   const double w = x1 - x0, h = y1 - y0, per = 2 * (w + h);
   double (*rim)[2] = xcalloc((size_t)n, sizeof(*rim));
   for (long i = 0; i < n; i++) {
      double d = t[i] * per;
      if (d < w)
         rim[i][0] = x0 + d, rim[i][1] = y0;
      else if (d < w + h)
         rim[i][0] = x1, rim[i][1] = y0 + (d - w);
      else if (d < 2 * w + h)
         rim[i][0] = x1 - (d - w - h), rim[i][1] = y1;
      else
         rim[i][0] = x0, rim[i][1] = y1 - (d - 2 * w - h);
   }
   long m = 0;
   for (long i = 0; i < n; i++) {
      const double *a = rim[i], *b = rim[(i + 1) % n];
      tri[3 * m][0] = cx, tri[3 * m][1] = cy;
      tri[3 * m + 1][0] = a[0], tri[3 * m + 1][1] = a[1];
      tri[3 * m + 2][0] = b[0], tri[3 * m + 2][1] = b[1];
      m++;
   }
   free(rim);
   return m;
}

static int cmp_double(const void *a, const void *b)
{
   double x = *(const double *)a, y = *(const double *)b;
   return x < y ? -1 : x > y;
}

/* The box's four corners must be rim points, or the fan would cut them off. */
static long with_corners(double *t, long n, int w, int h)
{
   const double per = 2.0 * (w + h);
   t[n++] = 0.0;
   t[n++] = w / per;
   t[n++] = (w + h) / per;
   t[n++] = (2.0 * w + h) / per;
   qsort(t, (size_t)n, sizeof(double), cmp_double);
   return n;
}

/* Slivers of 1e-6 pixel: a fan over a 128 x 128 box whose rim points are
 * 1e-6 pixel apart over a stretch of the border (every one of those triangles
 * is a sliver 1e-6 pixel wide at the rim), spread evenly elsewhere. */
static void case_slivers(void)
{
   const int x0 = size / 4, y0 = size / 4, x1 = x0 + size / 2, y1 = y0 + size / 2;
   const long dense = 4000, sparse = 200;
   double *t = xcalloc((size_t)(dense + sparse + 4), sizeof(double));
   const double per = 2.0 * (x1 - x0 + y1 - y0);
   long n = 0;
   for (long i = 0; i < dense; i++)   /* 1e-6 px apart from 10.3 px along the bottom */
      t[n++] = (10.3 + 1e-6 * (double)i) / per;
   for (long i = 0; i < sparse; i++)
      t[n++] = (20.0 + (per - 40.0) * (double)i / (double)sparse) / per;
   n = with_corners(t, n, x1 - x0, y1 - y0);
   double (*tri)[2] = xcalloc((size_t)n * 3, sizeof(*tri));
   long m = fan(tri, x0 + 37.3, y0 + 51.7, x0, y0, x1, y1, t, n);
   counted("slivers", (const double (*)[2])tri, m, x0, y0, x1, y1);
   free(tri);
   free(t);
}

/* A mesh whose every vertex lies on a pixel centre (i + 1/2, j + 1/2): every
 * edge runs through pixel centres, and the fill rule alone gives each of them
 * to one triangle.  The box's border is on pixel edges. */
static void case_pixel_centres(void)
{
   const int x0 = 8, y0 = 8, x1 = size - 8, y1 = size - 8;
   uint32_t rng = 0x5eed1u;
   const int n = 24;   /* interior vertices on an n x n lattice of centres */
   double (*v)[2] = xcalloc((size_t)(n + 2) * (n + 2), sizeof(*v));
   for (int j = 0; j <= n + 1; j++)
      for (int i = 0; i <= n + 1; i++) {
         double x, y;
         if (i == 0 || i == n + 1 || j == 0 || j == n + 1) {
            x = i == 0 ? x0 : i == n + 1 ? x1 : x0 + (double)(x1 - x0) * i / (n + 1);
            y = j == 0 ? y0 : j == n + 1 ? y1 : y0 + (double)(y1 - y0) * j / (n + 1);
         } else {
            x = floor(x0 + (double)(x1 - x0) * i / (n + 1)) + e2e_rand_range(&rng, -2, 2) + 0.5;
            y = floor(y0 + (double)(y1 - y0) * j / (n + 1)) + e2e_rand_range(&rng, -2, 2) + 0.5;
         }
         v[j * (n + 2) + i][0] = x;
         v[j * (n + 2) + i][1] = y;
      }
   double (*tri)[2] = xcalloc((size_t)(n + 1) * (n + 1) * 6, sizeof(*tri));
   long m = 0;
   for (int j = 0; j <= n; j++)
      for (int i = 0; i <= n; i++) {
         const double *a = v[j * (n + 2) + i], *b = v[j * (n + 2) + i + 1];
         const double *c = v[(j + 1) * (n + 2) + i], *d = v[(j + 1) * (n + 2) + i + 1];
         /* the diagonal alternates, so both its directions meet centres */
         const double *q[6][1] = { { a }, { b }, { (i + j) & 1 ? d : c },
                                   { (i + j) & 1 ? a : b }, { d }, { c } };
         for (int k = 0; k < 6; k++, m++)
            tri[m][0] = q[k][0][0], tri[m][1] = q[k][0][1];
      }
   counted("pixel-centres", (const double (*)[2])tri, m / 3, x0, y0, x1, y1);
   free(tri);
   free(v);
}

/* A fan of 10^5 triangles over the whole window, from a centre off the
 * pixel grid to rim points at random places on the border. */
static void case_fan(void)
{
   const long n = 100000;
   uint32_t rng = 0xfa2u;
   double *t = xcalloc((size_t)n + 4, sizeof(double));
   for (long i = 0; i < n; i++)
      t[i] = (double)e2e_rand(&rng) / 4294967296.0;
   long m = with_corners(t, n, size, size);
   double (*tri)[2] = xcalloc((size_t)m * 3, sizeof(*tri));
   m = fan(tri, size * 0.5 + 0.3123, size * 0.5 - 0.4567, 0, 0, size, size, t, m);
   counted("fan", (const double (*)[2])tri, m, 0, 0, size, size);
   free(tri);
   free(t);
}

/* A grid of cells over the whole window, its inner vertices moved by random
 * amounts of up to 0.2 cell in x and y (binary32 positions, nowhere near any
 * grid; below 0.25 every cell stays convex, so neither diagonal folds), two
 * triangles a cell. */
static void jitter(const char *name)
{
   const int n = 224;   /* cells a side: 100,352 triangles */
   const double cell = (double)size / n;
   uint32_t rng = 0x1177e5u;
   double (*v)[2] = xcalloc((size_t)(n + 1) * (n + 1), sizeof(*v));
   for (int j = 0; j <= n; j++)
      for (int i = 0; i <= n; i++) {
         double x = i * cell, y = j * cell;
         if (i > 0 && i < n)
            x += cell * 0.2 * ((double)e2e_rand(&rng) / 2147483648.0 - 1.0);
         if (j > 0 && j < n)
            y += cell * 0.2 * ((double)e2e_rand(&rng) / 2147483648.0 - 1.0);
         /* as the program would send it: binary32 */
         v[j * (n + 1) + i][0] = (double)ndc(x) * 0.5 * size + 0.5 * size;
         v[j * (n + 1) + i][1] = (double)ndc(y) * 0.5 * size + 0.5 * size;
      }
   double (*tri)[2] = xcalloc((size_t)n * n * 6, sizeof(*tri));
   long m = 0;
   for (int j = 0; j < n; j++)
      for (int i = 0; i < n; i++) {
         const double *a = v[j * (n + 1) + i], *b = v[j * (n + 1) + i + 1];
         const double *c = v[(j + 1) * (n + 1) + i], *d = v[(j + 1) * (n + 1) + i + 1];
         const double *q[6] = { a, b, d, a, d, c };
         if ((i ^ j) & 1)
            q[2] = c, q[3] = b, q[4] = d, q[5] = c;
         for (int k = 0; k < 6; k++, m++)
            tri[m][0] = q[k][0], tri[m][1] = q[k][1];
      }
   counted(name, (const double (*)[2])tri, m / 3, 0, 0, size, size);
   free(tri);
   free(v);
}

static void case_jitter(void)
{
   jitter("jitter");
}

/* The same at 4096 x 4096, beyond the seed profile's X/Y registers (12.12:
 * +-2048): drawn in tiles, each primitive through every tile it reaches
 * (docs/tiles.md), so a tile's border must not break a shared edge. */
static void case_jitter_tiles(void)
{
   jitter("jitter-tiles");
}

static const struct {
   const char *name;
   void (*run)(void);
   int size;
} cases[] = {
   { "nan-position", case_nan_position, 256 },
   { "inf-position", case_inf_position, 256 },
   { "huge-position", case_huge_position, 256 },
   { "w-near-zero", case_w_near_zero, 256 },
   { "bad-texcoord", case_bad_texcoord, 256 },
   { "bad-pointsize", case_bad_pointsize, 512 },
   { "slivers", case_slivers, 256 },
   { "pixel-centres", case_pixel_centres, 256 },
   { "fan", case_fan, 2048 },
   { "jitter", case_jitter, 2048 },
   { "jitter-tiles", case_jitter_tiles, 4096 },
};

int main(int argc, char **argv)
{
   struct e2e_args a;
   e2e_parse(&a, argc, argv, 256);
   const char *name = e2e_opt(&a, "case", NULL);
   int c = -1;
   for (int i = 0; name && i < (int)(sizeof(cases) / sizeof(cases[0])); i++)
      if (!strcmp(cases[i].name, name))
         c = i;
   if (c < 0) {
      fprintf(stderr, "e2e-adversarial: --case is one of:");
      for (size_t i = 0; i < sizeof(cases) / sizeof(cases[0]); i++)
         fprintf(stderr, " %s", cases[i].name);
      fprintf(stderr, "\n");
      return 2;
   }
   /* each case has its size; --size is the runner's default and not used */
   a.size = size = cases[c].size;
   px = xcalloc((size_t)size * (size_t)size, 4);
   struct fp_gl g;
   gl = &g;
   e2e_begin(&g, &a);
   cases[c].run();
   /* the picture each case leaves in px, for the comparison with llvmpipe */
   char err[512];
   fp_gl_check("the case's drawing");
   if (fp_png_write(a.out, size, size, px, err, sizeof(err)) != 0)
      fp_die("%s", err);
   fp_gl_fini(&g);
   free(px);
   printf("stat: checks_failed=%d\n", failures);
   return failures ? 1 : 0;
}
