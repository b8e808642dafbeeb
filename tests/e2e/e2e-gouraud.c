/*
 * Gouraud colour interpolation: random triangles with a random colour at
 * each vertex, plus a fan whose triangles share edges, all with w = 1 (so
 * screen-linear and perspective-correct interpolation agree) and no tie
 * pixels (coverage is the coverage test's business; here only colour may
 * differ).  --count N (default 120).
 */
#include "e2e_common.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static int tri_ok(const struct e2e_tri *t, int size)
{
   return e2e_tri_area2(t) != 0 && e2e_tri_ties(t, size, NULL) == 0;
}

static void emit(const struct e2e_tri *t, int size, uint32_t *rng)
{
   float pos[12], col[12];
   for (int k = 0; k < 3; k++) {
      pos[k * 4 + 0] = e2e_ndc(t->x[k], size);
      pos[k * 4 + 1] = e2e_ndc(t->y[k], size);
      pos[k * 4 + 2] = 0.0f;
      pos[k * 4 + 3] = 1.0f;
      for (int c = 0; c < 3; c++)
         col[k * 4 + c] = (float)e2e_rand_range(rng, 0, 255) / 255.0f;
      col[k * 4 + 3] = 1.0f;
   }
   e2e_draw(GL_TRIANGLES, 3, pos, col, NULL);
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   e2e_parse(&a, argc, argv, 256);
   int count = atoi(e2e_opt(&a, "count", "120"));
   int size = a.size, lim = size * E2E_SUB;

   struct fp_gl g;
   e2e_begin(&g, &a);
   glUseProgram(e2e_color_program());
   glClearColor(0, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT);

   uint32_t rng = 0x2468aceu;
   long rejected = 0;
   for (int n = 0; n < count; n++) {
      struct e2e_tri t;
      do {
         int r = (e2e_rand_range(&rng, 0, 1) ? 30 : 110) * E2E_SUB;
         int cx = e2e_rand_range(&rng, 0, lim), cy = e2e_rand_range(&rng, 0, lim);
         for (int k = 0; k < 3; k++) {
            int x = cx + e2e_rand_range(&rng, -r, r), y = cy + e2e_rand_range(&rng, -r, r);
            t.x[k] = x < 0 ? 0 : x > lim ? lim : x;
            t.y[k] = y < 0 ? 0 : y > lim ? lim : y;
         }
      } while (!tri_ok(&t, size) && ++rejected);
      emit(&t, size, &rng);
   }

   /* A fan of 24 triangles around a centre that is not on a pixel centre;
    * shared edges must not double-draw or leave gaps (no tie by choice of
    * the rim points, nudged until none lies on a pixel centre line). */
   int cx = lim / 2 + 37, cy = lim / 2 + 91, fan_r = lim * 3 / 8, fan_rejected = 0;
   int32_t rim[25][2];
   for (int i = 0; i <= 24; i++) {
      double ang = 2.0 * 3.14159265358979 * (i % 24) / 24.0;
      rim[i][0] = cx + (int32_t)lround(fan_r * cos(ang));
      rim[i][1] = cy + (int32_t)lround(fan_r * sin(ang));
   }
   for (int i = 0; i < 24; i++) {
      struct e2e_tri t = { { cx, rim[i][0], rim[i + 1][0] }, { cy, rim[i][1], rim[i + 1][1] } };
      while (!tri_ok(&t, size)) {
         /* Move the far vertex by one grid unit; the next triangle uses it.
          * The closing vertex is the first one's, already fixed. */
         if (i == 23)
            fp_die("the fan's closing triangle has tie pixels: change its centre");
         t.x[2] += 1;
         rim[i + 1][0] = t.x[2];
         fan_rejected++;
      }
      emit(&t, size, &rng);
   }
   printf("stat: triangles=%d rejected=%ld fan_nudges=%d\n", count + 24, rejected, fan_rejected);
   e2e_end(&g, &a, NULL);
   return 0;
}
