/*
 * fp-demo: renders the demo scenes offscreen through whatever GL ES 2 driver
 * EGL loads (GALLIUM_DRIVER picks it) and writes the frame as a PNG.
 *
 *   fp-demo [--scene gouraud|mesh|textured|all] [--size WxH] [-o out.png]
 *           [--frames N [--warmup W]]
 */
#define _POSIX_C_SOURCE 200809L
#include "fp_gl.h"
#include "fp_perfmon.h"
#include "fp_png.h"
#include "fp_scenes.h"

#include <stdio.h>

enum scene { SCENE_GOURAUD, SCENE_MESH, SCENE_TEXTURED, SCENE_ALL };
static const char *const scene_names[] = { "gouraud", "mesh", "textured", "all", NULL };

static void usage(FILE *f)
{
   fprintf(f,
      "usage: fp-demo [--scene gouraud|mesh|textured|all] [--size WxH] [-o out.png]\n"
      "               [--frames N [--warmup W]]\n"
      "  --scene    what to draw (default all: the three scenes in one frame)\n"
      "  --size     frame size (default 512x512)\n"
      "  -o         PNG to write (default: none)\n"
      "  --frames   render N frames and print the time per frame (default 1)\n"
      "  --warmup   the first W of them timed apart (default 1): start-up, and the\n"
      "             frames before a tiered driver has compiled its shaders\n");
}

static void viewport(int x, int y, int w, int h)
{
   glViewport(x, y, w, h);
   glScissor(x, y, w, h);
}

static void draw_frame(const struct fp_scenes *s, enum scene which, int w, int h)
{
   glDisable(GL_SCISSOR_TEST);
   glClearColor(0.08f, 0.09f, 0.12f, 1.0f);
   glClearDepthf(1.0f);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
   float aspect = (float)w / (float)h;
   switch (which) {
   case SCENE_GOURAUD: viewport(0, 0, w, h); fp_scene_gouraud(s, aspect); break;
   case SCENE_MESH: viewport(0, 0, w, h); fp_scene_mesh(s, aspect); break;
   case SCENE_TEXTURED: viewport(0, 0, w, h); fp_scene_textured(s, aspect); break;
   case SCENE_ALL: {
      /* Top left gouraud, top right mesh, bottom half the textured floor
       * (GL's y goes up, so "top" is the upper y range). */
      int hw = w / 2, hh = h / 2;
      glEnable(GL_SCISSOR_TEST);
      viewport(0, hh, hw, h - hh);
      fp_scene_gouraud(s, (float)hw / (float)(h - hh));
      viewport(hw, hh, w - hw, h - hh);
      fp_scene_mesh(s, (float)(w - hw) / (float)(h - hh));
      viewport(0, 0, w, hh);
      fp_scene_textured(s, (float)w / (float)hh);
      glDisable(GL_SCISSOR_TEST);
      viewport(0, 0, w, h);
      break;
   }
   }
}

struct demo_frame {
   const struct fp_scenes *s;
   enum scene which;
   int w, h;
};

static void draw_demo_frame(void *ctx)
{
   const struct demo_frame *f = ctx;
   draw_frame(f->s, f->which, f->w, f->h);
}

/* One more frame, measured by the modeled chip's cycle model through
 * GL_AMD_performance_monitor (fixpipe's driver queries, docs/cycles.md):
 * the time the chip would take at its clock, beside the host's. */
static void modeled_frame(struct demo_frame *df)
{
   static const char *const names[] = { "fp-cycles", "fp-modeled-us" };
   const char *why = "";
   struct fp_perfmon *m = fp_perfmon_open(names, 2, &why);
   if (!m) {
      printf("modeled: none (%s)\n", why);
      return;
   }
   double v[2];
   fp_perfmon_begin(m);
   draw_demo_frame(df);
   if (fp_perfmon_end(m, v) && v[1] > 0)
      printf("modeled_cycles_per_frame: %.0f modeled_ms_per_frame: %.3f clock_mhz: %.0f\n",
             v[0], v[1] / 1000.0, v[0] / v[1]);
   else
      printf("modeled: no result\n");
   fp_perfmon_close(m);
}

int main(int argc, char **argv)
{
   static const struct option opts[] = {
      FP_GL_OPTIONS,
      { "scene", required_argument, NULL, 's' },
      { "warmup", required_argument, NULL, 'w' },
      { NULL, 0, NULL, 0 },
   };
   enum scene which = SCENE_ALL;
   struct fp_gl_args a = { .w = 512, .h = 512, .frames = 1 };
   int warmup = 1;
   for (int c; (c = fp_gl_getopt(argc, argv, opts, "fp-demo", 16, &a, usage)) != -1;) {
      if (c == 's')
         which = (enum scene)fp_arg_name("fp-demo", "--scene", scene_names, optarg);
      else
         warmup = fp_arg_count("fp-demo", "--warmup", optarg);
   }

   if (a.frames > 1 && warmup >= a.frames) {
      fprintf(stderr, "fp-demo: --warmup %d leaves no frame of --frames %d to time\n", warmup,
              a.frames);
      return 2;
   }

   struct fp_gl g;
   fp_gl_init(&g, a.w, a.h);
   printf("renderer: %s\n", fp_gl_renderer());
   struct fp_scenes s;
   fp_scenes_init(&s);

   struct demo_frame df = { &s, which, a.w, a.h };
   struct fp_frame_times times;
   fp_gl_time_frames(a.frames, warmup, draw_demo_frame, &df, &times);
   fp_gl_check("drawing");
   printf("scene: %s %dx%d\n", scene_names[which], a.w, a.h);
   fp_print_frame_times(&times);
   modeled_frame(&df);

   if (a.out) {
      fp_gl_write_png(&g, a.out);
      printf("wrote: %s\n", a.out);
   }
   fp_scenes_fini(&s);
   fp_gl_fini(&g);
   return 0;
}
