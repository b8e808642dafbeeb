/*
 * fp-persp: the seed's texture scene.  A high-contrast texture on a ground
 * plane that recedes to the horizon under strong perspective (w varies by
 * thousands across the frame, texture coordinates run into the thousands),
 * and the same texture on small planes whose coordinates carry a constant
 * offset (2^4, 2^8 .. 2^20), where a format's range or its precision near
 * that magnitude gives out.  Made to show what the texture path's
 * number format (FIXPIPE_TEXFMT) does; renders through whatever GL ES 2
 * driver EGL loads and writes a PNG.
 *
 *   fp-persp [--view ground|offset|both] [--wrap split|repeat|mirror]
 *            [--filter nearest|linear|mipmap] [--size WxH] [--frames N]
 *            [--repeat-scale K] [--no-offset] [-o out.png]
 */
#define _POSIX_C_SOURCE 200809L
#include "fp_gl.h"
#include "fp_math.h"
#include "fp_png.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define TEX_SIZE 64
#define CHECK 8              /* texels per checker square */
#define PLANE_REPEATS 4096.0f /* the ground spans +-this many texture repeats */
#define EYE_HEIGHT 0.5f      /* in texture repeats */
#define PITCH_DEG 12.0f
#define FOVY_DEG 60.0f
#define NEAR_Z 0.05f
#define FAR_Z 20000.0f
#define N_OFFSETS 5          /* 2^4, 2^8, 2^12, 2^16, 2^20 */
#define OFFSET_EXP(i) (4 + 4 * (i))

enum view { VIEW_GROUND, VIEW_OFFSET, VIEW_BOTH };
enum wrap { WRAP_SPLIT, WRAP_REPEAT, WRAP_MIRROR };
enum filter { FILTER_NEAREST, FILTER_LINEAR, FILTER_MIPMAP };
static const char *const view_names[] = { "ground", "offset", "both", NULL };
static const char *const wrap_names[] = { "split", "repeat", "mirror", NULL };
static const char *const filter_names[] = { "nearest", "linear", "mipmap", NULL };

/* The coordinates reach the rasterizer's perspective division untouched:
 * no arithmetic on them in the fragment shader, so the texture path's
 * number format, not the shader's float, decides what is sampled. */
static const char *vs_src =
   "uniform mat4 u_mvp;\n"
   "uniform vec2 u_uv_scale;\n"
   "uniform vec2 u_uv_offset;\n"
   "attribute vec3 a_pos;\n"
   "attribute vec2 a_uv;\n"
   "varying vec2 v_uv;\n"
   "void main() {\n"
   "   v_uv = a_uv * u_uv_scale + u_uv_offset;\n"
   "   gl_Position = u_mvp * vec4(a_pos, 1.0);\n"
   "}\n";
static const char *fs_src =
   "#ifdef GL_FRAGMENT_PRECISION_HIGH\n"
   "precision highp float;\n"
   "#else\n"
   "precision mediump float;\n"
   "#endif\n"
   "uniform sampler2D u_tex;\n"
   "varying vec2 v_uv;\n"
   "void main() { gl_FragColor = texture2D(u_tex, v_uv); }\n";

struct scene {
   GLuint prog, vbo, tex[2];   /* tex[0] REPEAT, tex[1] MIRRORED_REPEAT */
   GLint mvp, uv_scale, uv_offset, sampler;
};

static void usage(FILE *f)
{
   fprintf(f,
      "usage: fp-persp [--view ground|offset|both] [--wrap split|repeat|mirror]\n"
      "                [--filter nearest|linear|mipmap] [--size WxH] [--frames N]\n"
      "                [--repeat-scale K] [--no-offset] [-o out.png]\n"
      "  --view     ground: the plane receding to the horizon; offset: five small\n"
      "             planes with texture coordinates offset by 2^4, 2^8 .. 2^20;\n"
      "             both (default): ground above, offset strip below\n"
      "  --wrap     split (default): REPEAT left of the centre line, MIRRORED_REPEAT\n"
      "             right of it (the offset planes: REPEAT); or one mode everywhere\n"
      "  --filter   nearest, linear (default) or mipmap (LINEAR_MIPMAP_LINEAR)\n"
      "  --size     frame size (default 640x480)\n"
      "  --frames   render N frames and print the time per frame (default 1)\n"
      "  --repeat-scale K  the ground's texture repeats K times per world unit\n"
      "             (default 1): its coordinates, and u/w, v/w, are K times larger\n"
      "             (K = 128: |u|, |v| from about 70 at the bottom row to thousands\n"
      "             at the horizon, |u/w|, |v/w| up to about 150 everywhere); a power\n"
      "             of two keeps the vertex shader's multiply exact\n"
      "  --no-offset  draw the offset planes without their offset: what REPEAT\n"
      "             should make of them (an integer offset changes nothing)\n"
      "  -o         PNG to write (default: none)\n");
}

/* A checkerboard with one-texel grid lines and both diagonals in each
 * square: straight lines in texture space, so any bend, step or smear in
 * the picture is the addressing's doing. */
static void make_texture(unsigned char *px)
{
   for (int y = 0; y < TEX_SIZE; y++)
      for (int x = 0; x < TEX_SIZE; x++) {
         unsigned char *p = px + (y * TEX_SIZE + x) * 4;
         int cx = x % CHECK, cy = y % CHECK;
         int dark = ((x / CHECK) + (y / CHECK)) & 1;
         /* A ramp across the repeat on the light squares (red falls with
          * u, blue with v): REPEAT shows a sawtooth, MIRRORED_REPEAT a
          * triangle wave, and a wrong wrap or a lost bit shows as a jump. */
         p[0] = dark ? 24 : (unsigned char)(250 - 150 * x / (TEX_SIZE - 1));
         p[1] = dark ? 24 : 236;
         p[2] = dark ? 24 : (unsigned char)(250 - 150 * y / (TEX_SIZE - 1));
         if (cx == cy || cx == CHECK - 1 - cy) {        /* diagonals */
            p[0] = dark ? 40 : 0;
            p[1] = dark ? 200 : 110;
            p[2] = dark ? 255 : 230;
         }
         if (cx == 0 || cy == 0) {                       /* grid lines */
            p[0] = 230;
            p[1] = 30;
            p[2] = 20;
         }
         if (x == 0 && y == 0) {                         /* one mark per repeat */
            p[0] = 255;
            p[1] = 230;
            p[2] = 0;
         }
         p[3] = 255;
      }
}

static void scene_init(struct scene *s, enum filter filter)
{
   static const char *const attr[] = { "a_pos", "a_uv", NULL };
   s->prog = fp_gl_program(vs_src, fs_src, attr);
   s->mvp = glGetUniformLocation(s->prog, "u_mvp");
   s->uv_scale = glGetUniformLocation(s->prog, "u_uv_scale");
   s->uv_offset = glGetUniformLocation(s->prog, "u_uv_offset");
   s->sampler = glGetUniformLocation(s->prog, "u_tex");

   /* x, y, z, u, v.  Ground: two quads meeting at x = 0 (one per wrap
    * mode), from just behind the eye to PLANE_REPEATS ahead; one world unit
    * is one texture repeat.  Then the offset planes' one-repeat quad,
    * centred on a repeat corner. */
   const float R = PLANE_REPEATS, B = 1.0f, Q = 0.5f;
   const float v[] = {
      -R, 0, -R, -R, -R,    0, 0, -R, 0, -R,    0, 0, B, 0, B,
      -R, 0, -R, -R, -R,    0, 0, B, 0, B,     -R, 0, B, -R, B,
       0, 0, -R, 0, -R,     R, 0, -R, R, -R,    R, 0, B, R, B,
       0, 0, -R, 0, -R,     R, 0, B, R, B,      0, 0, B, 0, B,
      -Q, 0, -Q, -Q, -Q,    Q, 0, -Q, Q, -Q,    Q, 0, Q, Q, Q,
      -Q, 0, -Q, -Q, -Q,    Q, 0, Q, Q, Q,     -Q, 0, Q, -Q, Q,
   };
   glGenBuffers(1, &s->vbo);
   glBindBuffer(GL_ARRAY_BUFFER, s->vbo);
   glBufferData(GL_ARRAY_BUFFER, sizeof(v), v, GL_STATIC_DRAW);

   unsigned char *px = malloc(TEX_SIZE * TEX_SIZE * 4);
   if (!px)
      fp_die("out of memory");
   make_texture(px);
   static const GLenum modes[2] = { GL_REPEAT, GL_MIRRORED_REPEAT };
   GLenum minf = filter == FILTER_NEAREST ? GL_NEAREST
               : filter == FILTER_LINEAR ? GL_LINEAR : GL_LINEAR_MIPMAP_LINEAR;
   GLenum magf = filter == FILTER_NEAREST ? GL_NEAREST : GL_LINEAR;
   glGenTextures(2, s->tex);
   for (int i = 0; i < 2; i++) {
      glBindTexture(GL_TEXTURE_2D, s->tex[i]);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, TEX_SIZE, TEX_SIZE, 0, GL_RGBA,
                   GL_UNSIGNED_BYTE, px);
      if (filter == FILTER_MIPMAP)
         glGenerateMipmap(GL_TEXTURE_2D);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)minf);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)magf);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)modes[i]);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)modes[i]);
   }
   free(px);
   fp_gl_check("scene set-up");
}

static void scene_fini(struct scene *s)
{
   glDeleteTextures(2, s->tex);
   glDeleteBuffers(1, &s->vbo);
   glDeleteProgram(s->prog);
}

static fp_mat4 ground_mvp(float aspect)
{
   fp_mat4 p = fp_mat4_perspective(FOVY_DEG, aspect, NEAR_Z, FAR_Z);
   fp_mat4 view = fp_mat4_mul(fp_mat4_rotate(PITCH_DEG, 1, 0, 0),
                              fp_mat4_translate(0, -EYE_HEIGHT, 0));
   return fp_mat4_mul(p, view);
}

/* The w (eye-space depth) of the nearest and the farthest ground pixel:
 * the bottom row's centre and the plane's far edge. */
static void ground_w_range(double *wmin, double *wmax)
{
   double pitch = PITCH_DEG * (double)FP_PI / 180.0, half = FOVY_DEG * (double)FP_PI / 360.0;
   double d = EYE_HEIGHT / tan(pitch + half);           /* ground distance */
   *wmin = d * cos(pitch) + EYE_HEIGHT * sin(pitch);
   *wmax = PLANE_REPEATS * cos(pitch) + EYE_HEIGHT * sin(pitch);
}

static void bind_attribs(void)
{
   glEnableVertexAttribArray(0);
   glEnableVertexAttribArray(1);
   glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 5 * sizeof(float), (void *)0);
   glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 5 * sizeof(float),
                         (void *)(3 * sizeof(float)));
}

static float repeat_scale = 1.0f;   /* --repeat-scale */

static void draw_ground(const struct scene *s, enum wrap wrap, float aspect)
{
   fp_mat4 mvp = ground_mvp(aspect);
   glUniformMatrix4fv(s->mvp, 1, GL_FALSE, mvp.m);
   glUniform2f(s->uv_scale, repeat_scale, repeat_scale);
   glUniform2f(s->uv_offset, 0, 0);
   for (int half = 0; half < 2; half++) {
      int mirror = wrap == WRAP_MIRROR || (wrap == WRAP_SPLIT && half == 1);
      glBindTexture(GL_TEXTURE_2D, s->tex[mirror]);
      glDrawArrays(GL_TRIANGLES, half * 6, 6);
   }
}

/* Each panel looks down at one repeat (centred on a repeat corner, where
 * REPEAT wraps), turned so the texture's lines run diagonally; its
 * coordinates are offset by 2^(4 + 4i) in u and v. */
static int no_offset;   /* --no-offset */

static void draw_offsets(const struct scene *s, enum wrap wrap, int x0, int y0, int w, int h)
{
   glBindTexture(GL_TEXTURE_2D, s->tex[wrap == WRAP_MIRROR]);
   for (int i = 0; i < N_OFFSETS; i++) {
      int px0 = x0 + w * i / N_OFFSETS, px1 = x0 + w * (i + 1) / N_OFFSETS;
      glViewport(px0, y0, px1 - px0, h);
      float aspect = (float)(px1 - px0) / (float)h;
      fp_mat4 p = fp_mat4_perspective(50.0f, aspect, 0.5f, 50.0f);
      fp_mat4 view = fp_mat4_mul(fp_mat4_translate(0, 0, -1.7f),
                     fp_mat4_mul(fp_mat4_rotate(40.0f, 1, 0, 0),
                                 fp_mat4_rotate(20.0f, 0, 1, 0)));
      fp_mat4 mvp = fp_mat4_mul(p, view);
      float off = no_offset ? 0.0f : ldexpf(1.0f, OFFSET_EXP(i));
      glUniformMatrix4fv(s->mvp, 1, GL_FALSE, mvp.m);
      glUniform2f(s->uv_scale, 1, 1);
      glUniform2f(s->uv_offset, off, off);
      glDrawArrays(GL_TRIANGLES, 12, 6);
   }
}

static void draw_frame(const struct scene *s, enum view view, enum wrap wrap, int w, int h)
{
   glViewport(0, 0, w, h);
   glClearColor(0.30f, 0.42f, 0.62f, 1.0f);
   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
   glUseProgram(s->prog);
   glUniform1i(s->sampler, 0);
   glActiveTexture(GL_TEXTURE0);
   glBindBuffer(GL_ARRAY_BUFFER, s->vbo);
   bind_attribs();
   switch (view) {
   case VIEW_GROUND:
      draw_ground(s, wrap, (float)w / (float)h);
      break;
   case VIEW_OFFSET:
      draw_offsets(s, wrap, 0, 0, w, h);
      break;
   case VIEW_BOTH: {
      /* GL's y goes up: the ground takes the upper two thirds. */
      int hb = h / 3;
      glViewport(0, hb, w, h - hb);
      draw_ground(s, wrap, (float)w / (float)(h - hb));
      draw_offsets(s, wrap, 0, 0, w, hb);
      break;
   }
   }
}

struct persp_frame {
   const struct scene *s;
   enum view view;
   enum wrap wrap;
   int w, h;
};

static void draw_persp_frame(void *ctx)
{
   const struct persp_frame *f = ctx;
   draw_frame(f->s, f->view, f->wrap, f->w, f->h);
}

int main(int argc, char **argv)
{
   static const struct option opts[] = {
      FP_GL_OPTIONS,
      { "view", required_argument, NULL, 'v' },
      { "wrap", required_argument, NULL, 'w' },
      { "filter", required_argument, NULL, 'f' },
      { "repeat-scale", required_argument, NULL, 'r' },
      { "no-offset", no_argument, &no_offset, 1 },
      { NULL, 0, NULL, 0 },
   };
   enum view view = VIEW_BOTH;
   enum wrap wrap = WRAP_SPLIT;
   enum filter filter = FILTER_LINEAR;
   struct fp_gl_args a = { .w = 640, .h = 480, .frames = 1 };
   char *end;
   for (int c; (c = fp_gl_getopt(argc, argv, opts, "fp-persp", 48, &a, usage)) != -1;) {
      switch (c) {
      case 'v': view = (enum view)fp_arg_name("fp-persp", "--view", view_names, optarg); break;
      case 'w': wrap = (enum wrap)fp_arg_name("fp-persp", "--wrap", wrap_names, optarg); break;
      case 'f':
         filter = (enum filter)fp_arg_name("fp-persp", "--filter", filter_names, optarg);
         break;
      case 'r':
         repeat_scale = strtof(optarg, &end);
         if (*end || !(repeat_scale >= 1.0f / 1024 && repeat_scale <= 65536)) {
            fprintf(stderr, "fp-persp: bad --repeat-scale '%s' (1/1024..65536)\n", optarg);
            return 2;
         }
         break;
      }
   }
   const int w = a.w, h = a.h;

   struct fp_gl g;
   fp_gl_init(&g, w, h);
   printf("renderer: %s\n", fp_gl_renderer());
   const char *texfmt = getenv("FIXPIPE_TEXFMT");
   printf("texfmt_env: %s\n", texfmt && *texfmt ? texfmt : "(unset)");
   struct scene s;
   scene_init(&s, filter);
   glDisable(GL_DEPTH_TEST);
   glDisable(GL_CULL_FACE);

   struct persp_frame pf = { &s, view, wrap, w, h };
   struct fp_frame_times times;
   fp_gl_time_frames(a.frames, 1, draw_persp_frame, &pf, &times);
   fp_gl_check("drawing");
   double wmin, wmax;
   ground_w_range(&wmin, &wmax);
   printf("scene: view=%s wrap=%s filter=%s %dx%d repeat_scale=%g\n", view_names[view],
          wrap_names[wrap], filter_names[filter], w, h, (double)repeat_scale);
   /* The coordinates on screen: v at the bottom row's centre, and the
    * largest |u/w|, |v/w| (the frame's edges; the same on every row). */
   {
      double pitch = PITCH_DEG * (double)FP_PI / 180.0, half = FOVY_DEG * (double)FP_PI / 360.0;
      int gh = view == VIEW_BOTH ? h - h / 3 : h;
      double aspect = (double)w / (double)gh;
      double vb = repeat_scale * EYE_HEIGHT / tan(pitch + half);
      double uw = repeat_scale * tan(half) * aspect;
      printf("ground_w: %.3f..%.1f (ratio %.0f), uv up to +-%.0f repeats "
             "(repeat scale %g: |v| %.0f at the bottom row, |u/w| up to %.0f)\n",
             wmin, wmax, wmax / wmin, (double)PLANE_REPEATS * repeat_scale,
             (double)repeat_scale, vb, uw);
   }
   /* Where things are in the PNG (rows from the top), for the figure
    * scripts: the ground's rows, the horizon's, the offset strip's. */
   int ground_rows = view == VIEW_BOTH ? h - h / 3 : view == VIEW_GROUND ? h : 0;
   double yh = tan(PITCH_DEG * (double)FP_PI / 180.0) / tan(FOVY_DEG * (double)FP_PI / 360.0);
   printf("layout: ground_rows=%d horizon_row=%d offset_rows=%d offset_panels=%d "
          "offset_exps=", ground_rows, ground_rows ? (int)((1.0 - yh) / 2.0 * ground_rows) : -1,
          h - ground_rows, view == VIEW_GROUND ? 0 : N_OFFSETS);
   for (int i = 0; i < N_OFFSETS; i++)
      printf("%s%d", i ? "," : "", OFFSET_EXP(i));
   printf("%s\n", no_offset ? " (offsets removed)" : "");
   fp_print_frame_times(&times);

   if (a.out) {
      fp_gl_write_png(&g, a.out);
      printf("wrote: %s\n", a.out);
   }
   scene_fini(&s);
   fp_gl_fini(&g);
   return 0;
}
