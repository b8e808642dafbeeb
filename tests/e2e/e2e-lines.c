/*
 * Coverage of lines and points: random primitives, each in its own colour,
 * no blending, no depth.  The final colour of a pixel names the last
 * primitive that covered it, so equal images mean equal coverage.
 *
 *   --kind lines    (default) GL_LINES, GL_LINE_STRIP and GL_LINE_LOOP,
 *                   segments x-major, y-major, exactly diagonal, axis-aligned,
 *                   short (< 3 px) and long (up to the target's side)
 *   --kind points   gl_PointSize from --sizes (default "1,4"), flat colour
 *   --kind sprites  as points, coloured by gl_PointCoord: sprite coordinates
 *   --width W       line width (default 1)
 *   --snap grid     end points anywhere on the 1/256 sub-pixel grid
 *   --snap centre   end points on pixel centres (i + 1/2, j + 1/2)
 *   --snap mixed    (default) each primitive picks one of the two
 *   --count N       number of primitives (default 400)
 *
 * Every vertex stays inside the target, so clipping adds no vertex off the
 * grid.  No mask: one-pixel lines have no fill-rule convention to leave
 * out (the diamond-exit rule decides every end pixel).
 */
#include "e2e_common.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum kind { K_LINES, K_POINTS, K_SPRITES };
enum snap { S_GRID, S_CENTRE, S_MIXED };

/* Segment classes, picked at random for every segment. */
enum seg { SEG_XMAJOR, SEG_YMAJOR, SEG_DIAGONAL, SEG_AXIS, SEG_SHORT, SEG_LONG, SEG_COUNT };

static int32_t snap_to(int32_t v, int centre)
{
   if (!centre)
      return v;
   return (v >> 8) * E2E_SUB + E2E_SUB / 2;
}

/* A vertex inside the target, away from the border by `margin` grid units. */
static void random_point(uint32_t *rng, int size, int margin, int centre, int32_t *x, int32_t *y)
{
   int lim = size * E2E_SUB;
   *x = snap_to(e2e_rand_range(rng, margin, lim - margin), centre);
   *y = snap_to(e2e_rand_range(rng, margin, lim - margin), centre);
}

/* The other end of a segment of class cls from (x0, y0); 0 when it would
 * leave the target or have no length. */
static int random_end(uint32_t *rng, int size, int centre, enum seg cls, int32_t x0, int32_t y0,
                      int32_t *x1, int32_t *y1)
{
   const int lim = size * E2E_SUB, margin = E2E_SUB;
   const int maxlen = size * E2E_SUB * 9 / 10;
   int dx = 0, dy = 0;
   const int sx = e2e_rand(rng) & 1 ? 1 : -1, sy = e2e_rand(rng) & 1 ? 1 : -1;
   switch (cls) {
   case SEG_XMAJOR:
      dx = e2e_rand_range(rng, E2E_SUB, maxlen / 3);
      dy = e2e_rand_range(rng, 0, dx - 1);
      break;
   case SEG_YMAJOR:
      dy = e2e_rand_range(rng, E2E_SUB, maxlen / 3);
      dx = e2e_rand_range(rng, 0, dy - 1);
      break;
   case SEG_DIAGONAL:
      dx = dy = e2e_rand_range(rng, 1, maxlen / 3);
      break;
   case SEG_AXIS:
      if (e2e_rand(rng) & 1)
         dx = e2e_rand_range(rng, 1, maxlen / 2);
      else
         dy = e2e_rand_range(rng, 1, maxlen / 2);
      break;
   case SEG_SHORT:
      dx = e2e_rand_range(rng, 0, 3 * E2E_SUB);
      dy = e2e_rand_range(rng, 0, 3 * E2E_SUB);
      break;
   default:
      dx = e2e_rand_range(rng, maxlen / 2, maxlen);
      dy = e2e_rand_range(rng, 0, maxlen);
      if (e2e_rand(rng) & 1) {
         int t = dx;
         dx = dy;
         dy = t;
      }
      break;
   }
   if (centre) {
      /* Whole pixels keep the end on a centre; the diagonal stays one. */
      dx = (dx + E2E_SUB / 2) / E2E_SUB * E2E_SUB;
      dy = cls == SEG_DIAGONAL ? dx : (dy + E2E_SUB / 2) / E2E_SUB * E2E_SUB;
   }
   *x1 = x0 + sx * dx;
   *y1 = y0 + sy * dy;
   if (*x1 < margin || *y1 < margin || *x1 > lim - margin || *y1 > lim - margin)
      return 0;
   return *x1 != x0 || *y1 != y0;
}

static const char *const vs_lines =
   "attribute vec4 a_pos;\n"
   "attribute vec4 a_color;\n"
   "attribute float a_size;\n"
   "varying vec4 v_color;\n"
   "void main() { v_color = a_color; gl_Position = a_pos; gl_PointSize = a_size; }\n";
static const char *const fs_flat =
   "precision mediump float;\n"
   "varying vec4 v_color;\n"
   "void main() { gl_FragColor = v_color; }\n";
static const char *const fs_sprite =
   "precision highp float;\n"
   "varying vec4 v_color;\n"
   "void main() { gl_FragColor = vec4(gl_PointCoord, v_color.b, 1.0); }\n";

static void draw(GLenum mode, int n, const float *pos, float size, const float rgba[4])
{
   glBindBuffer(GL_ARRAY_BUFFER, 0);
   glEnableVertexAttribArray(0);
   glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 0, pos);
   glDisableVertexAttribArray(1);
   glVertexAttrib4fv(1, rgba);
   glDisableVertexAttribArray(2);
   glVertexAttrib1f(2, size);
   glDrawArrays(mode, 0, n);
   glDisableVertexAttribArray(0);
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   e2e_parse(&a, argc, argv, 256);
   const char *ks = e2e_opt(&a, "kind", "lines"), *ss = e2e_opt(&a, "snap", "mixed");
   enum kind kind = !strcmp(ks, "lines") ? K_LINES : !strcmp(ks, "points") ? K_POINTS :
                    !strcmp(ks, "sprites") ? K_SPRITES : (enum kind)-1;
   enum snap snap = !strcmp(ss, "grid") ? S_GRID : !strcmp(ss, "centre") ? S_CENTRE :
                    !strcmp(ss, "mixed") ? S_MIXED : (enum snap)-1;
   if ((int)kind < 0)
      fp_die("--kind must be lines, points or sprites");
   if ((int)snap < 0)
      fp_die("--snap must be grid, centre or mixed");
   const float width = (float)atof(e2e_opt(&a, "width", "1"));
   const int count = atoi(e2e_opt(&a, "count", "400"));
   float sizes[8];
   int nsizes = 0;
   for (const char *p = e2e_opt(&a, "sizes", "1,4"); *p && nsizes < 8;) {
      sizes[nsizes++] = (float)strtod(p, (char **)&p);
      if (*p == ',')
         p++;
      else if (*p)
         fp_die("--sizes is a comma-separated list of point sizes");
   }
   if (width < 1 || count < 1 || nsizes < 1)
      fp_die("bad --width, --count or --sizes");
   const int size = a.size;

   struct fp_gl g;
   e2e_begin(&g, &a);
   static const char *const attr[] = { "a_pos", "a_color", "a_size", NULL };
   GLuint prog = fp_gl_program(vs_lines, kind == K_SPRITES ? fs_sprite : fs_flat, attr);
   glUseProgram(prog);
   glClearColor(0, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   GLfloat range[2];
   glGetFloatv(kind == K_LINES ? GL_ALIASED_LINE_WIDTH_RANGE : GL_ALIASED_POINT_SIZE_RANGE,
               range);
   if (kind == K_LINES) {
      if (width > range[1])
         fp_die("line width %g above the driver's %g", width, range[1]);
      glLineWidth(width);
   }

   uint32_t rng = 0x5eed1u ^ (uint32_t)kind * 0x9e3779b9u ^ (uint32_t)snap * 0x85ebca6bu;
   long segs[SEG_COUNT] = { 0 }, prims[3] = { 0 }, verts = 0, centred = 0;
   for (int n = 0; n < count; n++) {
      const int centre = snap == S_CENTRE || (snap == S_MIXED && (e2e_rand(&rng) & 1));
      centred += centre;
      /* A distinct colour per primitive, never the black background. */
      uint32_t c = ((uint32_t)(n + 1) * 2654435761u) >> 8;
      float rgba[4] = { (float)(c & 255) / 255.0f, (float)((c >> 8) & 255) / 255.0f,
                        (float)((c >> 16) | 1) / 255.0f, 1.0f };
      int32_t x[8], y[8];
      int nv = 0;
      GLenum mode;
      float psize = 1;

      if (kind != K_LINES) {
         mode = GL_POINTS;
         psize = sizes[e2e_rand_range(&rng, 0, nsizes - 1)];
         nv = e2e_rand_range(&rng, 1, 8);
         for (int k = 0; k < nv; k++)
            random_point(&rng, size, E2E_SUB * 4, centre, &x[k], &y[k]);
      } else {
         static const GLenum modes[3] = { GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP };
         const int m = e2e_rand_range(&rng, 0, 2);
         mode = modes[m];
         prims[m]++;
         const int want = m == 0 ? 2 * e2e_rand_range(&rng, 1, 4) : e2e_rand_range(&rng, 2, 6);
         while (nv < want) {
            enum seg cls = (enum seg)e2e_rand_range(&rng, 0, SEG_COUNT - 1);
            /* LINES: every pair is its own segment. */
            if (nv == 0 || (m == 0 && nv % 2 == 0)) {
               random_point(&rng, size, E2E_SUB, centre, &x[nv], &y[nv]);
               nv++;
               continue;
            }
            int32_t x1, y1;
            int tries = 0;
            while (!random_end(&rng, size, centre, cls, x[nv - 1], y[nv - 1], &x1, &y1)) {
               /* Near a corner a long segment may not fit: a short one does. */
               if (++tries == 50)
                  cls = SEG_SHORT;
               if (tries > 1000)
                  fp_die("no segment end inside the target");
            }
            x[nv] = x1;
            y[nv] = y1;
            nv++;
            segs[cls]++;
         }
      }
      verts += nv;
      float pos[8 * 4];
      for (int k = 0; k < nv; k++) {
         pos[k * 4 + 0] = e2e_ndc(x[k], size);
         pos[k * 4 + 1] = e2e_ndc(y[k], size);
         pos[k * 4 + 2] = 0.0f;
         pos[k * 4 + 3] = 1.0f;
      }
      draw(mode, nv, pos, psize, rgba);
   }

   if (kind == K_LINES) {
      printf("stat: lines=%ld strips=%ld loops=%ld vertices=%ld centred=%ld width=%g"
             " xmajor=%ld ymajor=%ld diagonal=%ld axis=%ld short=%ld long=%ld\n",
             prims[0], prims[1], prims[2], verts, centred, width, segs[SEG_XMAJOR],
             segs[SEG_YMAJOR], segs[SEG_DIAGONAL], segs[SEG_AXIS], segs[SEG_SHORT],
             segs[SEG_LONG]);
   } else {
      printf("stat: draws=%d points=%ld centred=%ld sizes=%s range=%g..%g\n", count, verts,
             centred, e2e_opt(&a, "sizes", "1,4"), range[0], range[1]);
   }
   e2e_end(&g, &a, NULL);
   return 0;
}
