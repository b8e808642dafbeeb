/*
 * Depth test at several depth offsets: a grid of cells, one row per depth
 * function (twice: flat planes, then planes slanted in x), one column per
 * offset d in window z.  Each cell first gets a reference quad at z_ref
 * (ALWAYS, depth writes on, dark red), then a test quad at z_ref + d with
 * the row's function (depth writes off, green): green where the test passed.
 *
 * Cells with 0 < |d| < 2^-exact_bits are masked: there the result depends on
 * the driver's Z precision (the fixpipe seed profile resolves 2^-19 of full
 * scale, llvmpipe 2^-24).  --exact-bits N (default 16).  All other cells
 * also have an answer known in advance (z_test vs z_ref, exact since every
 * vertex z is a short dyadic fraction); the program checks the centre pixel
 * of each and prints self_check_errors.
 */
#include "e2e_common.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define CELL_W 15
#define CELL_H 16
#define NCOLS 17

static const GLenum funcs[8] = { GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL,
                                 GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS };
static const int exps[8] = { 4, 8, 12, 14, 16, 18, 20, 23 };

static double offset_of(int col)
{
   /* Columns: -2^-4 .. -2^-23, 0, +2^-23 .. +2^-4. */
   if (col == NCOLS / 2)
      return 0.0;
   return col < NCOLS / 2 ? -ldexp(1.0, -exps[col]) : ldexp(1.0, -exps[NCOLS - 1 - col]);
}

static int expect_pass(GLenum f, double d)
{
   switch (f) {
   case GL_NEVER: return 0;
   case GL_LESS: return d < 0;
   case GL_EQUAL: return d == 0;
   case GL_LEQUAL: return d <= 0;
   case GL_GREATER: return d > 0;
   case GL_NOTEQUAL: return d != 0;
   case GL_GEQUAL: return d >= 0;
   default: return 1;
   }
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   e2e_parse(&a, argc, argv, 256);
   int exact_bits = atoi(e2e_opt(&a, "exact-bits", "16"));
   int size = a.size;
   if (size != 256)
      fp_die("the depth test's layout is for --size 256");
   unsigned char *mask = calloc((size_t)size * size * 4, 1);
   if (!mask)
      fp_die("out of memory");

   struct fp_gl g;
   e2e_begin(&g, &a);
   glUseProgram(e2e_color_program());
   glClearColor(0, 0, 0, 1);
   glClearDepthf(1.0f);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
   glEnable(GL_DEPTH_TEST);

   static const float red[4] = { 0.4f, 0, 0, 1 }, green[4] = { 0, 1, 0, 1 };
   long ties = 0;
   int masked_cells = 0;
   for (int row = 0; row < 16; row++) {
      int slanted = row >= 8;
      GLenum f = funcs[row % 8];
      for (int col = 0; col < NCOLS; col++) {
         double d = offset_of(col);
         /* Corners 2.3 px inside the cell: no pixel centre on the sides. */
         int32_t x0 = (int32_t)lround((col * CELL_W + 2.3) * E2E_SUB);
         int32_t x1 = (int32_t)lround(((col + 1) * CELL_W - 2.3) * E2E_SUB);
         int32_t y0 = (int32_t)lround((row * CELL_H + 2.3) * E2E_SUB);
         int32_t y1 = (int32_t)lround(((row + 1) * CELL_H - 2.3) * E2E_SUB);
         int32_t gx[4] = { x0, x1, x0, x1 }, gy[4] = { y0, y0, y1, y1 };
         /* Window z: flat 0.375; slanted 5/16 on the left to 11/16 on the
          * right; short dyadic fractions, so z_ndc = 2 z - 1 and z + d stay
          * exact in float for every offset used. */
         double zl = slanted ? 0.3125 : 0.375, zr = slanted ? 0.6875 : 0.375;
         double zw[4] = { zl, zr, zl, zr };
         for (int pass = 0; pass < 2; pass++) {
            float pos[16];
            for (int k = 0; k < 4; k++) {
               pos[k * 4 + 0] = e2e_ndc(gx[k], size);
               pos[k * 4 + 1] = e2e_ndc(gy[k], size);
               pos[k * 4 + 2] = (float)(2.0 * (zw[k] + (pass ? d : 0.0)) - 1.0);
               pos[k * 4 + 3] = 1.0f;
            }
            glDepthFunc(pass ? f : GL_ALWAYS);
            glDepthMask(pass ? GL_FALSE : GL_TRUE);
            e2e_draw(GL_TRIANGLE_STRIP, 4, pos, NULL, pass ? green : red);
         }
         for (int tri = 0; tri < 2; tri++) {
            struct e2e_tri t = { { gx[tri], gx[tri + 1], gx[tri + 2] },
                                 { gy[tri], gy[tri + 1], gy[tri + 2] } };
            ties += e2e_tri_ties(&t, size, mask);
         }
         if (d != 0.0 && fabs(d) < ldexp(1.0, -exact_bits)) {
            masked_cells++;
            for (int y = row * CELL_H; y < (row + 1) * CELL_H; y++)
               for (int x = col * CELL_W; x < (col + 1) * CELL_W; x++) {
                  unsigned char *m = mask + ((size_t)(size - 1 - y) * size + x) * 4;
                  m[0] = m[1] = m[2] = m[3] = 255;
               }
         }
      }
   }

   /* The answer is known for every unmasked cell: check its centre. */
   unsigned char *px = malloc((size_t)size * size * 4);
   if (!px)
      fp_die("out of memory");
   fp_gl_read_rgba(&g, px);
   int errors = 0;
   for (int row = 0; row < 16; row++)
      for (int col = 0; col < NCOLS; col++) {
         double d = offset_of(col);
         if (d != 0.0 && fabs(d) < ldexp(1.0, -exact_bits))
            continue;
         int x = col * CELL_W + CELL_W / 2, y = row * CELL_H + CELL_H / 2;
         const unsigned char *p = px + ((size_t)(size - 1 - y) * size + x) * 4;
         int passed = p[1] > 128;
         if (passed != expect_pass(funcs[row % 8], d)) {
            if (errors < 5)
               fprintf(stderr, "depth: %s row %d offset %g: %s, expected %s\n",
                       row >= 8 ? "slanted" : "flat", row % 8, d, passed ? "passed" : "failed",
                       expect_pass(funcs[row % 8], d) ? "pass" : "fail");
            errors++;
         }
      }
   free(px);
   printf("stat: cells=%d masked_cells=%d exact_bits=%d tie_pixels=%ld self_check_errors=%d\n",
          16 * NCOLS, masked_cells, exact_bits, ties, errors);
   e2e_end(&g, &a, mask);
   free(mask);
   return 0;
}
