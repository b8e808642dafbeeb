/*
 * Stencil: a fixed opening sequence (REPLACE 255, INCR_WRAP over it, then
 * DECR_WRAP, INVERT, INCR, DECR) and then random passes with random
 * functions, references, value and write masks, sfail/zfail/zpass ops and
 * two-sided state (CW and CCW triangles), against a depth buffer that makes
 * half the triangles fail the depth test.  Triangles are tie-free, so every
 * difference is in the stencil logic.  The buffer is then made visible:
 * one full-screen pass per value v = 0..255 with EQUAL v writes a colour
 * whose red is v.  --passes N (default 64 random passes), --size (128).
 */
#include "e2e_common.h"

#include <stdio.h>
#include <stdlib.h>

static const GLenum funcs[8] = { GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL,
                                 GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS };
static const GLenum ops[8] = { GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR,
                               GL_DECR, GL_INCR_WRAP, GL_DECR_WRAP, GL_INVERT };

static void random_tri(uint32_t *rng, int size, int big, struct e2e_tri *t)
{
   int lim = size * E2E_SUB, r = (big ? size : size / 3) * E2E_SUB;
   do {
      int cx = e2e_rand_range(rng, 0, lim), cy = e2e_rand_range(rng, 0, lim);
      for (int k = 0; k < 3; k++) {
         int x = cx + e2e_rand_range(rng, -r, r), y = cy + e2e_rand_range(rng, -r, r);
         t->x[k] = x < 0 ? 0 : x > lim ? lim : x;
         t->y[k] = y < 0 ? 0 : y > lim ? lim : y;
      }
   } while (e2e_tri_area2(t) == 0 || e2e_tri_ties(t, size, NULL) != 0);
}

static void draw_tri(const struct e2e_tri *t, int size, float z_ndc)
{
   static const float white[4] = { 1, 1, 1, 1 };
   float pos[12];
   for (int k = 0; k < 3; k++) {
      pos[k * 4 + 0] = e2e_ndc(t->x[k], size);
      pos[k * 4 + 1] = e2e_ndc(t->y[k], size);
      pos[k * 4 + 2] = z_ndc;
      pos[k * 4 + 3] = 1.0f;
   }
   e2e_draw(GL_TRIANGLES, 3, pos, NULL, white);
}

static GLuint pick_mask(uint32_t *rng)
{
   static const GLuint common[4] = { 0xff, 0xff, 0x0f, 0xf0 };
   int k = e2e_rand_range(rng, 0, 4);
   return k < 4 ? common[k] : e2e_rand(rng) & 0xff;
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   e2e_parse(&a, argc, argv, 128);
   int passes = atoi(e2e_opt(&a, "passes", "64"));
   int size = a.size;

   struct fp_gl g;
   e2e_begin(&g, &a);
   glUseProgram(e2e_color_program());
   glClearColor(0, 0, 0, 1);
   glClearStencil(0);
   glClearDepthf(0.5f);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

   glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
   glEnable(GL_STENCIL_TEST);
   glEnable(GL_DEPTH_TEST);
   glDepthFunc(GL_LESS);
   glDepthMask(GL_FALSE);

   uint32_t rng = 0x5eed5eedu;
   struct e2e_tri t;
   /* The opening: wrap-around in both directions on purpose. */
   static const struct { GLenum op; GLint ref; } opening[6] = {
      { GL_REPLACE, 255 }, { GL_INCR_WRAP, 0 }, { GL_DECR_WRAP, 0 },
      { GL_INVERT, 0 }, { GL_INCR, 0 }, { GL_DECR, 0 },
   };
   for (int i = 0; i < 6; i++) {
      glStencilFunc(GL_ALWAYS, opening[i].ref, 0xff);
      glStencilOp(GL_KEEP, GL_KEEP, opening[i].op);
      glStencilMask(0xff);
      random_tri(&rng, size, 1, &t);
      draw_tri(&t, size, -0.5f);   /* window z 0.25 < 0.5: depth passes */
   }

   int two_sided = 0, depth_fails = 0, cw = 0;
   for (int i = 0; i < passes; i++) {
      int sep = e2e_rand_range(&rng, 0, 1);
      for (int face = 0; face < (sep ? 2 : 1); face++) {
         GLenum which = sep ? (face ? GL_BACK : GL_FRONT) : GL_FRONT_AND_BACK;
         glStencilFuncSeparate(which, funcs[e2e_rand_range(&rng, 0, 7)],
                               e2e_rand_range(&rng, 0, 255), pick_mask(&rng));
         glStencilOpSeparate(which, ops[e2e_rand_range(&rng, 0, 7)],
                             ops[e2e_rand_range(&rng, 0, 7)], ops[e2e_rand_range(&rng, 0, 7)]);
         glStencilMaskSeparate(which, pick_mask(&rng));
      }
      two_sided += sep;
      random_tri(&rng, size, e2e_rand_range(&rng, 0, 3) == 0, &t);
      cw += e2e_tri_area2(&t) < 0;
      int fail = e2e_rand_range(&rng, 0, 1);
      depth_fails += fail;
      draw_tri(&t, size, fail ? 0.5f : -0.5f);
   }

   /* Make the stencil values visible, one value per pass. */
   glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
   glDisable(GL_DEPTH_TEST);
   glStencilMask(0);
   glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
   static const float quad[16] = { -1, -1, 0, 1, 1, -1, 0, 1, -1, 1, 0, 1, 1, 1, 0, 1 };
   for (int v = 0; v < 256; v++) {
      float rgba[4] = { (float)v / 255.0f, (float)(255 - v) / 255.0f,
                        (float)((v * 53) & 255) / 255.0f, 1.0f };
      glStencilFunc(GL_EQUAL, v, 0xff);
      e2e_draw(GL_TRIANGLE_STRIP, 4, quad, NULL, rgba);
   }
   glDisable(GL_STENCIL_TEST);

   unsigned char *px = malloc((size_t)size * size * 4);
   int seen[256] = { 0 }, distinct = 0;
   if (!px)
      fp_die("out of memory");
   fp_gl_read_rgba(&g, px);
   for (size_t i = 0; i < (size_t)size * size; i++)
      if (!seen[px[i * 4]]++)
         distinct++;
   free(px);
   printf("stat: passes=%d two_sided=%d cw=%d depth_fail=%d distinct_values=%d\n", passes + 6,
          two_sided, cw, depth_fails, distinct);
   e2e_end(&g, &a, NULL);
   return 0;
}
