/*
 * Coverage of non-antialiased triangles: random flat triangles, each in its
 * own colour, no blending, no depth.  The final colour of a pixel names the
 * last triangle that covered it, so equal images mean equal coverage.
 *
 *   --ties avoid  (default) vertices anywhere on the 1/256 grid, triangles
 *                 with a pixel centre exactly on an edge are re-drawn: the
 *                 fill rule never decides, every difference is a real one.
 *   --ties allow  vertices on the half-pixel grid, so many centres lie on
 *                 edges; those pixels are the mask, and differences there are
 *                 the two drivers' fill-rule conventions, counted apart.
 *   --count N     number of triangles (default 300)
 */
#include "e2e_common.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void random_tri(uint32_t *rng, int size, int snap, struct e2e_tri *t)
{
   /* A mix of small, medium and large triangles around a random centre;
    * every vertex stays inside the target, so no clipping adds vertices off
    * the grid. */
   static const int radius_px[] = { 3, 12, 40, 120 };
   int r = radius_px[e2e_rand_range(rng, 0, 3)] * E2E_SUB;
   int lim = size * E2E_SUB;
   int cx = e2e_rand_range(rng, 0, lim), cy = e2e_rand_range(rng, 0, lim);
   for (int k = 0; k < 3; k++) {
      int x = cx + e2e_rand_range(rng, -r, r), y = cy + e2e_rand_range(rng, -r, r);
      x = x < 0 ? 0 : x > lim ? lim : x;
      y = y < 0 ? 0 : y > lim ? lim : y;
      t->x[k] = x / snap * snap;
      t->y[k] = y / snap * snap;
   }
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   e2e_parse(&a, argc, argv, 256);
   const char *ties_mode = e2e_opt(&a, "ties", "avoid");
   int allow = !strcmp(ties_mode, "allow");
   if (!allow && strcmp(ties_mode, "avoid"))
      fp_die("--ties must be avoid or allow");
   int count = atoi(e2e_opt(&a, "count", "300"));
   int size = a.size;

   unsigned char *mask = calloc((size_t)size * (size_t)size * 4, 1);
   if (!mask)
      fp_die("out of memory");

   struct fp_gl g;
   e2e_begin(&g, &a);
   GLuint prog = e2e_color_program();
   glUseProgram(prog);
   glClearColor(0, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT);

   uint32_t rng = allow ? 0x1234567u : 0x89abcdefu;
   long rejected = 0, tie_sum = 0, ccw = 0;
   for (int n = 0; n < count; n++) {
      struct e2e_tri t;
      for (;;) {
         random_tri(&rng, size, allow ? E2E_SUB / 2 : 1, &t);
         if (e2e_tri_area2(&t) == 0) {
            rejected++;
            continue;
         }
         long ties = e2e_tri_ties(&t, size, NULL);
         if (!allow && ties) {
            rejected++;
            continue;
         }
         tie_sum += e2e_tri_ties(&t, size, mask);
         break;
      }
      ccw += e2e_tri_area2(&t) > 0;
      /* A distinct colour per triangle, never the black background. */
      uint32_t c = ((uint32_t)(n + 1) * 2654435761u) >> 8;
      float rgba[4] = { (float)(c & 255) / 255.0f, (float)((c >> 8) & 255) / 255.0f,
                        (float)((c >> 16) | 1) / 255.0f, 1.0f };
      float pos[12];
      for (int k = 0; k < 3; k++) {
         pos[k * 4 + 0] = e2e_ndc(t.x[k], size);
         pos[k * 4 + 1] = e2e_ndc(t.y[k], size);
         pos[k * 4 + 2] = 0.0f;
         pos[k * 4 + 3] = 1.0f;
      }
      e2e_draw(GL_TRIANGLES, 3, pos, NULL, rgba);
   }

   long masked = 0;
   for (size_t i = 0; i < (size_t)size * (size_t)size; i++)
      masked += mask[i * 4] != 0;
   printf("stat: triangles=%d ccw=%ld rejected=%ld tie_pixels=%ld tie_hits=%ld\n", count, ccw,
          rejected, masked, tie_sum);
   e2e_end(&g, &a, mask);
   free(mask);
   return 0;
}
