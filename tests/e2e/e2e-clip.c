/*
 * What draw does before the model: clip and cull distances
 * (GL_EXT_clip_cull_distance) and the polygon offset clamp
 * (GL_EXT_polygon_offset_clamp), GL ES 3.0 (--case NAME, 64x64 unless
 * --size says):
 *
 *   distances     random triangles, each vertex with a clip distance (a
 *                 slanted plane cuts them) and a cull distance (a triangle
 *                 whose three vertices are all beyond a second plane goes)
 *   offset-clamp  a sloped plane drawn over a flat one that it crosses,
 *                 with a polygon offset that the slope makes larger than
 *                 their distance anywhere, and a clamp that leaves it in
 *                 front where it is more than the clamp nearer
 *
 * Self-checks (errors fail the program on any driver): the extension is
 * exposed; in distances, a triangle wholly beyond the cull plane draws
 * nothing and one half beyond the clip plane draws its near half only; in
 * offset-clamp, the plane shows where it is more than the clamp nearer and
 * not where it is less.
 */
#include "e2e_common.h"

#include <EGL/egl.h>
#include <GLES3/gl3.h>
#include <GLES2/gl2ext.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef GL_CLIP_DISTANCE0_EXT
#define GL_CLIP_DISTANCE0_EXT 0x3000
#endif

static unsigned char *ties;

static const char vs_distances[] =
   "#version 300 es\n"
   "#extension GL_EXT_clip_cull_distance : require\n"
   "in vec4 a_pos;\n"
   "in vec4 a_color;\n"
   "out vec4 v_color;\n"
   "void main() {\n"
   "   gl_Position = a_pos;\n"
   "   gl_ClipDistance[0] = 0.6 - a_pos.x - 0.5 * a_pos.y;\n"
   "   gl_CullDistance[0] = a_pos.y + 0.5;\n"
   "   v_color = a_color;\n"
   "}\n";

static const char fs_color[] =
   "#version 300 es\n"
   "precision highp float;\n"
   "in vec4 v_color;\n"
   "out vec4 o_color;\n"
   "void main() { o_color = v_color; }\n";

static const char *const attribs[] = { "a_pos", "a_color", NULL };

static void pixel(int x, int y, unsigned char px[4])
{
   glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
}

static void scene_distances(int size)
{
   glUseProgram(fp_gl_program(vs_distances, fs_color, attribs));
   glEnable(GL_CLIP_DISTANCE0_EXT);
   glClearColor(0, 0, 0, 1);
   glClear(GL_COLOR_BUFFER_BIT);
   const float white[4] = { 1, 1, 1, 1 };
   unsigned char px[4];

   /* below y = -0.5 at every vertex: culled whole */
   const float culled[] = { -0.9f, -0.9f, 0, 1, 0.0f, -0.9f, 0, 1, -0.5f, -0.6f, 0, 1 };
   e2e_draw(GL_TRIANGLES, 3, culled, NULL, white);
   pixel(size * 3 / 10, size / 8, px);
   e2e_check(px[0] == 0, "a triangle beyond the cull plane at every vertex was drawn");
   /* across the clip plane x + y/2 = 0.6: the near side drawn, the far not */
   const float cut[] = { -0.2f, -0.2f, 0, 1, 0.9f, -0.2f, 0, 1, 0.3f, 0.4f, 0, 1 };
   e2e_draw(GL_TRIANGLES, 3, cut, NULL, white);
   unsigned char near[4], far[4];
   pixel((int)((0.2f + 1) * 0.5f * size), (int)((-0.1f + 1) * 0.5f * size), near);
   pixel((int)((0.8f + 1) * 0.5f * size), (int)((-0.15f + 1) * 0.5f * size), far);
   printf("stat: clip=%u,%u\n", near[0], far[0]);
   e2e_check(near[0] == 255 && far[0] == 0, "the clip distance did not cut the triangle");

   glClear(GL_COLOR_BUFFER_BIT);
   uint32_t seed = 0x636c6970u;
   for (int t = 0; t < 40; t++) {
      float pos[12], col[12];
      struct e2e_tri tri;
      for (int i = 0; i < 3; i++) {
         tri.x[i] = e2e_rand_range(&seed, -size / 4, size + size / 4) * E2E_SUB;
         tri.y[i] = e2e_rand_range(&seed, -size / 4, size + size / 4) * E2E_SUB;
         pos[4 * i + 0] = e2e_ndc(tri.x[i], size);
         pos[4 * i + 1] = e2e_ndc(tri.y[i], size);
         pos[4 * i + 2] = 0.0f;
         pos[4 * i + 3] = 1.0f;
         col[4 * i + 0] = (float)e2e_rand_range(&seed, 0, 255) / 255.0f;
         col[4 * i + 1] = (float)e2e_rand_range(&seed, 0, 255) / 255.0f;
         col[4 * i + 2] = (float)e2e_rand_range(&seed, 0, 255) / 255.0f;
         col[4 * i + 3] = 1.0f;
      }
      e2e_draw(GL_TRIANGLES, 3, pos, col, NULL);
      e2e_tri_ties(&tri, size, ties);
   }
   glDisable(GL_CLIP_DISTANCE0_EXT);
}

static const char vs_plain[] =
   "#version 300 es\n"
   "in vec4 a_pos;\n"
   "in vec4 a_color;\n"
   "out vec4 v_color;\n"
   "void main() { gl_Position = a_pos; v_color = a_color; }\n";

static void scene_offset_clamp(int size)
{
   void (*offset_clamp)(GLfloat, GLfloat, GLfloat) =
      (void (*)(GLfloat, GLfloat, GLfloat))eglGetProcAddress("glPolygonOffsetClampEXT");
   if (!offset_clamp)
      fp_die("no glPolygonOffsetClampEXT");
   glUseProgram(fp_gl_program(vs_plain, fs_color, attribs));
   glEnable(GL_DEPTH_TEST);
   glDepthFunc(GL_LESS);
   glClearColor(0, 0, 0, 1);
   glClearDepthf(1.0f);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

   /* the flat plane at z = 0 (depth 0.5), blue */
   const float flat[] = { -1, -1, 0, 1, 1, -1, 0, 1, -1, 1, 0, 1, 1, 1, 0, 1 };
   const float blue[4] = { 0, 0, 1, 1 };
   e2e_draw(GL_TRIANGLE_STRIP, 4, flat, NULL, blue);

   /* the sloped plane crosses it at x = 0, nearer on the left: its window
    * depth runs from 0.45 to 0.55 over the target, a slope of 0.1 / size a
    * pixel.  A factor of 40 makes the offset 4 / size (0.0625 at 64), more
    * than it is ever nearer; the clamp of 0.02 leaves it in front where it
    * is more than 0.02 nearer: the left fifth of the target. */
   offset_clamp(40.0f, 0.0f, 0.02f);
   glEnable(GL_POLYGON_OFFSET_FILL);
   const float slope[] = { -1, -1, -0.1f, 1, 1, -1, 0.1f, 1, -1, 1, -0.1f, 1, 1, 1, 0.1f, 1 };
   const float yellow[4] = { 1, 1, 0, 1 };
   e2e_draw(GL_TRIANGLE_STRIP, 4, slope, NULL, yellow);
   glDisable(GL_POLYGON_OFFSET_FILL);

   unsigned char left[4], mid[4];
   pixel(size / 16, size / 2, left);          /* 0.044 nearer: in front */
   pixel(size * 3 / 8, size / 2, mid);        /* 0.0125 nearer: behind */
   printf("stat: offset=%u,%u\n", left[0], mid[0]);
   e2e_check(left[0] == 255 && left[2] == 0, "the clamped offset hides the plane where it is "
             "more than the clamp nearer");
   e2e_check(mid[0] == 0 && mid[2] == 255, "the offset leaves the plane in front where it is "
             "less than the clamp nearer");
   glDisable(GL_DEPTH_TEST);
}

int main(int argc, char **argv)
{
   struct e2e_args a;
   struct fp_gl g;
   e2e_start(&g, &a, argc, argv, 64);
   const char *c = e2e_opt(&a, "case", "");
   ties = calloc((size_t)a.size * (size_t)a.size, 4);
   if (!ties)
      fp_die("out of memory");
   if (!strcmp(c, "distances")) {
      e2e_check(e2e_has_extension("GL_EXT_clip_cull_distance"),
                "GL_EXT_clip_cull_distance is not exposed");
      if (!e2e_errors)
         scene_distances(a.size);
   } else if (!strcmp(c, "offset-clamp")) {
      e2e_check(e2e_has_extension("GL_EXT_polygon_offset_clamp"),
                "GL_EXT_polygon_offset_clamp is not exposed");
      if (!e2e_errors)
         scene_offset_clamp(a.size);
   } else {
      fp_die("--case: distances or offset-clamp");
   }
   const int status = e2e_finish(&g, &a, ties);
   free(ties);
   return status;
}
