/*
 * GL's depth clamp (GL_EXT_depth_clamp), GL ES 3.0, 64x64 (--case NAME):
 *
 *   clamp     glDepthRangef(0.2, 0.6), GL_DEPTH_CLAMP_EXT on
 *   reversed  glDepthRangef(0.6, 0.2), on: the range is [min(n, f), max(n, f)]
 *   off       glDepthRangef(0.2, 0.6), off: draw clips at the near and far planes
 *   halfz     as clamp, clip z in [0, w] (glClipControlEXT, GL_ZERO_TO_ONE_EXT):
 *             the range's n is then the viewport's translate, not translate - scale
 *
 * Eight bands of eight rows.  In each, a red ramp is drawn (GL_LESS,
 * depth written) whose window depth w = -0.4 + 0.025 x runs from -0.4 at
 * the left edge to 0.95 at x = 54 (bands 0-3: the vertices' depth, which
 * crosses the near plane at x = 24 and the far one at x = 40; inside the
 * seed profile's Z register, about [-1, 1)), or from -0.4 to 1.2 across
 * the whole band (bands 4-7: the geometry flat inside the range, the
 * depth gl_FragDepth's).  Then a probe quad at one window depth p, drawn
 * with glDepthRangef(0, 1), the clamp off and depth writes off, shows the
 * stored depth against p: n + 1/64 with GL_LESS (green where the stored
 * depth is larger), n - 1/64 with GL_GREATER (blue where it is smaller),
 * f - 1/64 with GL_GREATER, f + 1/64 with GL_LESS.  With the clamp the
 * stored depths are clamp(w, 0.2, 0.6): nothing below 0.2 nor above 0.6;
 * without it the ramp is cut at the planes, and a shader's depth clamped
 * to [0, 1] alone (where it reaches 1, the ramp fails GL_LESS against the
 * clear's 1 and leaves the pixel black).  Every probe's depth is at least 0.003 from the ramp's
 * at every pixel centre (the crossings lie an eighth of a pixel from one),
 * far beyond either driver's depth precision.
 *
 * Self-check (errors fail the program on any driver): the extension is
 * exposed, and every pixel has the colour the rule above gives it.
 */
#include "e2e_common.h"

#include <EGL/egl.h>
#include <GLES3/gl3.h>
#include <GLES2/gl2ext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef GL_DEPTH_CLAMP_EXT
#define GL_DEPTH_CLAMP_EXT 0x864F
#endif

#define SIZE 64
#define BAND 8
#define RAMP_END 54            /* the vertex-depth ramp's right edge, pixels */
#define DELTA (1.0f / 64.0f)

static const char fs_frag_depth[] =
   "#version 300 es\n"
   "precision highp float;\n"
   "in vec4 v_color;\n"
   "out vec4 o_color;\n"
   "void main() { o_color = vec4(1.0, 0.0, 0.0, 1.0); gl_FragDepth = v_color.x; }\n";

static float ramp_depth(float x)
{
   return -0.4f + 0.025f * x;
}

/* Pixel x (window, pixels) -> clip x, exact (a power of two). */
static float ndc_x(float x)
{
   return x / (SIZE / 2) - 1.0f;
}

struct probe { GLenum func; float depth; };

/* Band b's probe (b mod 4) for the range's ends lo < hi. */
static struct probe probe_of(unsigned b, float lo, float hi)
{
   switch (b % 4) {
   case 0: return (struct probe){ GL_LESS, lo + DELTA };
   case 1: return (struct probe){ GL_GREATER, lo - DELTA };
   case 2: return (struct probe){ GL_GREATER, hi - DELTA };
   default: return (struct probe){ GL_LESS, hi + DELTA };
   }
}

static float clampf(float v, float lo, float hi)
{
   return v < lo ? lo : v > hi ? hi : v;
}

/* The colour the rule gives pixel column i of band b: 0 black, 1 red, 2
 * green, 3 blue. */
static int expected(unsigned b, int i, bool clamp, float lo, float hi)
{
   const float x = (float)i + 0.5f, w = ramp_depth(x);
   /* the ramp's fragment: its stored depth, if it passes GL_LESS against
    * the clear's 1 (a shader depth of 1 or more does not, clamped to 1) */
   bool drawn = b >= 4 || (x < RAMP_END && (clamp || (w >= lo && w <= hi)));
   const float d = clamp ? clampf(w, lo, hi) : clampf(w, 0.0f, 1.0f);
   drawn = drawn && d < 1.0f;
   const float stored = drawn ? d : 1.0f;
   const struct probe p = probe_of(b, lo, hi);
   const bool pass = p.func == GL_LESS ? p.depth < stored : p.depth > stored;
   if (pass)
      return p.func == GL_LESS ? 2 : 3;
   return drawn ? 1 : 0;
}

static void band_quad(unsigned b, float x0, float x1, float z0, float z1, float *pos)
{
   const float y0 = -1.0f + (float)b / 4.0f, y1 = y0 + 0.25f;
   const float v[16] = { ndc_x(x0), y0, z0, 1, ndc_x(x1), y0, z1, 1,
                         ndc_x(x0), y1, z0, 1, ndc_x(x1), y1, z1, 1 };
   memcpy(pos, v, sizeof v);
}

/* The clip z (w = 1) that lands on window depth d under the range [n, f]:
 * z in [-1, 1] maps to [n, f], or z in [0, 1] with halfz. */
static float clip_z(float d, float n, float f, bool halfz)
{
   return halfz ? (d - n) / (f - n) : (2.0f * d - (n + f)) / (f - n);
}

static void scene(float n, float f, bool clamp, bool halfz)
{
   const float lo = n < f ? n : f, hi = n < f ? f : n;
   if (halfz) {
      PFNGLCLIPCONTROLEXTPROC clip =
         (PFNGLCLIPCONTROLEXTPROC)eglGetProcAddress("glClipControlEXT");
      if (!clip)
         fp_die("no glClipControlEXT");
      clip(GL_LOWER_LEFT_EXT, GL_ZERO_TO_ONE_EXT);
   }
   const GLuint color = e2e_color_program();
   const GLuint frag_depth = e2e_color_program_es3(fs_frag_depth);
   static const float red[4] = { 1, 0, 0, 1 }, green[4] = { 0, 1, 0, 1 },
                      blue[4] = { 0, 0, 1, 1 };
   glClearColor(0, 0, 0, 1);
   glClearDepthf(1.0f);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
   glEnable(GL_DEPTH_TEST);

   for (unsigned b = 0; b < 8; b++) {
      float pos[16];
      glDepthRangef(n, f);
      if (clamp)
         glEnable(GL_DEPTH_CLAMP_EXT);
      glDepthMask(GL_TRUE);
      glDepthFunc(GL_LESS);
      if (b < 4) {
         const float z0 = clip_z(ramp_depth(0), n, f, halfz);
         const float z1 = clip_z(ramp_depth(RAMP_END), n, f, halfz);
         glUseProgram(color);
         band_quad(b, 0, RAMP_END, z0, z1, pos);
         e2e_draw(GL_TRIANGLE_STRIP, 4, pos, NULL, red);
      } else {
         /* flat at window depth 0.4, inside [n, f]; the depth is the shader's */
         glUseProgram(frag_depth);
         const float z = clip_z(0.4f, n, f, halfz);
         band_quad(b, 0, SIZE, z, z, pos);
         const float d0 = ramp_depth(0), d1 = ramp_depth(SIZE);
         const float depth[16] = { d0, 0, 0, 1, d1, 0, 0, 1, d0, 0, 0, 1, d1, 0, 0, 1 };
         e2e_draw(GL_TRIANGLE_STRIP, 4, pos, depth, NULL);
      }
      glDisable(GL_DEPTH_CLAMP_EXT);
      glDepthRangef(0.0f, 1.0f);
      glDepthMask(GL_FALSE);
      const struct probe p = probe_of(b, lo, hi);
      glDepthFunc(p.func);
      glUseProgram(color);
      const float z = clip_z(p.depth, 0.0f, 1.0f, halfz);
      band_quad(b, 0, SIZE, z, z, pos);
      e2e_draw(GL_TRIANGLE_STRIP, 4, pos, NULL, p.func == GL_LESS ? green : blue);
   }
   glDepthMask(GL_TRUE);
   glDisable(GL_DEPTH_TEST);

   static unsigned char px[SIZE * SIZE * 4];
   glReadPixels(0, 0, SIZE, SIZE, GL_RGBA, GL_UNSIGNED_BYTE, px);
   static const unsigned char rgb[4][3] = { { 0, 0, 0 }, { 255, 0, 0 }, { 0, 255, 0 },
                                             { 0, 0, 255 } };
   unsigned wrong = 0, clamped_below = 0, clamped_above = 0;
   for (int y = 0; y < SIZE; y++)
      for (int i = 0; i < SIZE; i++) {
         const unsigned b = (unsigned)y / BAND;
         const int want = expected(b, i, clamp, lo, hi);
         const unsigned char *p = &px[(y * SIZE + i) * 4];
         if (memcmp(p, rgb[want], 3)) {
            if (wrong++ < 5)
               printf("error: band %u pixel (%d, %d): %u,%u,%u, want %u,%u,%u\n", b, i, y,
                      p[0], p[1], p[2], rgb[want][0], rgb[want][1], rgb[want][2]);
         }
         /* the pixels whose colour shows the clamp: red where a probe
          * beyond the range's end would have passed */
         clamped_below += b % 4 == 1 && want == 1 && ramp_depth((float)i + 0.5f) < lo - DELTA;
         clamped_above += b % 4 == 3 && want == 1 && ramp_depth((float)i + 0.5f) > hi + DELTA;
      }
   printf("stat: wrong=%u,clamped_below=%u,clamped_above=%u\n", wrong, clamped_below,
          clamped_above);
   e2e_check(wrong == 0, "pixels unlike the depth clamp's rule");
   e2e_check(!clamp || (clamped_below > 0 && clamped_above > 0),
             "no pixel shows the clamp: the check proves nothing");
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   struct fp_gl g;
   e2e_start(&g, &a, argc, argv, SIZE);
   if (a.size != SIZE)
      fp_die("the bands are laid out for --size 64");
   const char *c = e2e_opt(&a, "case", "");
   e2e_check(e2e_has_extension("GL_EXT_depth_clamp"), "GL_EXT_depth_clamp is not exposed");
   if (!strcmp(c, "clamp")) {
      if (!e2e_errors)
         scene(0.2f, 0.6f, true, false);
   } else if (!strcmp(c, "reversed")) {
      if (!e2e_errors)
         scene(0.6f, 0.2f, true, false);
   } else if (!strcmp(c, "off")) {
      if (!e2e_errors)
         scene(0.2f, 0.6f, false, false);
   } else if (!strcmp(c, "halfz")) {
      e2e_check(e2e_has_extension("GL_EXT_clip_control"), "GL_EXT_clip_control is not exposed");
      if (!e2e_errors)
         scene(0.2f, 0.6f, true, true);
   } else {
      fp_die("--case: clamp, reversed, off or halfz");
   }
   return e2e_finish(&g, &a, NULL);
}
