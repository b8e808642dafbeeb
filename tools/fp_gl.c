/* EGL surfaceless + FBO set-up for the offscreen GL ES 2 programs. */
/* clock_gettime */
#define _POSIX_C_SOURCE 200809L
#include "fp_gl.h"
#include "fp_png.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES2/gl2ext.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

void fp_die(const char *fmt, ...)
{
   va_list ap;
   va_start(ap, fmt);
   fputs("error: ", stderr);
   vfprintf(stderr, fmt, ap);
   fputc('\n', stderr);
   va_end(ap);
   exit(2);
}

static int has_ext(const char *list, const char *name)
{
   size_t n = strlen(name);
   for (const char *p = list; p && (p = strstr(p, name)); p += n)
      if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
         return 1;
   return 0;
}

static EGLDisplay open_display(void)
{
   const char *cext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
   if (has_ext(cext, "EGL_MESA_platform_surfaceless")) {
      PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display =
         (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
      if (get_platform_display)
         return get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
   }
   /* Older loaders: EGL_PLATFORM=surfaceless in the environment does it. */
   return eglGetDisplay(EGL_DEFAULT_DISPLAY);
}

void fp_gl_init(struct fp_gl *g, int w, int h)
{
   memset(g, 0, sizeof(*g));
   g->w = w;
   g->h = h;

   EGLDisplay dpy = open_display();
   EGLint major, minor;
   if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, &major, &minor))
      fp_die("EGL surfaceless display failed to initialize (0x%x); "
             "is GALLIUM_DRIVER a driver this Mesa knows?", eglGetError());
   if (!eglBindAPI(EGL_OPENGL_ES_API))
      fp_die("eglBindAPI(GLES) failed");

   const char *dext = eglQueryString(dpy, EGL_EXTENSIONS);
   if (!has_ext(dext, "EGL_KHR_surfaceless_context"))
      fp_die("EGL_KHR_surfaceless_context is missing");

   EGLConfig cfg = (EGLConfig)0;   /* EGL_NO_CONFIG_KHR */
   if (!has_ext(dext, "EGL_KHR_no_config_context")) {
      const EGLint attr[] = { EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT,
                              EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE };
      EGLint n = 0;
      if (!eglChooseConfig(dpy, attr, &cfg, 1, &n) || n < 1)
         fp_die("no EGL config for GL ES 2");
   }
   const EGLint ctx_attr[] = { EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE };
   EGLContext ctx = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, ctx_attr);
   if (ctx == EGL_NO_CONTEXT)
      fp_die("eglCreateContext(ES 2) failed (0x%x)", eglGetError());
   if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx))
      fp_die("eglMakeCurrent(surfaceless) failed (0x%x)", eglGetError());
   g->dpy = dpy;
   g->ctx = ctx;

   const char *gext = (const char *)glGetString(GL_EXTENSIONS);
   if (!has_ext(gext, "GL_OES_packed_depth_stencil"))
      fp_die("GL_OES_packed_depth_stencil is missing");
   GLenum color_fmt = has_ext(gext, "GL_OES_rgb8_rgba8") ? GL_RGBA8_OES : GL_RGBA4;
   if (color_fmt != GL_RGBA8_OES)
      fp_die("GL_OES_rgb8_rgba8 is missing: no RGBA8 renderbuffer");

   glGenFramebuffers(1, &g->fbo);
   glBindFramebuffer(GL_FRAMEBUFFER, g->fbo);
   glGenRenderbuffers(1, &g->color_rb);
   glBindRenderbuffer(GL_RENDERBUFFER, g->color_rb);
   glRenderbufferStorage(GL_RENDERBUFFER, color_fmt, w, h);
   glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, g->color_rb);
   glGenRenderbuffers(1, &g->ds_rb);
   glBindRenderbuffer(GL_RENDERBUFFER, g->ds_rb);
   glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8_OES, w, h);
   glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, g->ds_rb);
   glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, g->ds_rb);
   GLenum st = glCheckFramebufferStatus(GL_FRAMEBUFFER);
   if (st != GL_FRAMEBUFFER_COMPLETE)
      fp_die("FBO %dx%d incomplete (0x%x)", w, h, st);
   fp_gl_check("FBO set-up");
   glViewport(0, 0, w, h);
}

void fp_gl_fini(struct fp_gl *g)
{
   glDeleteRenderbuffers(1, &g->ds_rb);
   glDeleteRenderbuffers(1, &g->color_rb);
   glDeleteFramebuffers(1, &g->fbo);
   eglMakeCurrent(g->dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
   eglDestroyContext(g->dpy, g->ctx);
   eglTerminate(g->dpy);
}

const char *fp_gl_renderer(void)
{
   const char *r = (const char *)glGetString(GL_RENDERER);
   return r ? r : "(unknown)";
}

static GLuint compile(GLenum type, const char *src)
{
   GLuint s = glCreateShader(type);
   glShaderSource(s, 1, &src, NULL);
   glCompileShader(s);
   GLint ok = 0;
   glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
   if (!ok) {
      char log[2048] = "";
      glGetShaderInfoLog(s, sizeof(log), NULL, log);
      fp_die("%s shader: %s", type == GL_VERTEX_SHADER     ? "vertex"
                              : type == GL_FRAGMENT_SHADER ? "fragment"
                              : type == 0x8DD9             ? "geometry"
                              : type == 0x8E88             ? "tessellation control"
                              : type == 0x8E87             ? "tessellation evaluation"
                                                           : "compute", log);
   }
   return s;
}

static void link(GLuint p)
{
   glLinkProgram(p);
   GLint ok = 0;
   glGetProgramiv(p, GL_LINK_STATUS, &ok);
   if (!ok) {
      char log[2048] = "";
      glGetProgramInfoLog(p, sizeof(log), NULL, log);
      fp_die("link: %s", log);
   }
}

GLuint fp_gl_program_stages(const char *vs, const char *tcs, const char *tes, const char *gs,
                            const char *fs, const char *const *attribs)
{
   /* the stages' GL ES 3.2 enums: vertex, tessellation control and
    * evaluation, geometry, fragment */
   const char *const src[5] = { vs, tcs, tes, gs, fs };
   const GLenum type[5] = { GL_VERTEX_SHADER, 0x8E88, 0x8E87, 0x8DD9, GL_FRAGMENT_SHADER };
   GLuint sh[5] = { 0 };
   GLuint p = glCreateProgram();
   for (int i = 0; i < 5; i++) {
      if (!src[i])
         continue;
      sh[i] = compile(type[i], src[i]);
      glAttachShader(p, sh[i]);
   }
   for (GLuint i = 0; attribs && attribs[i]; i++)
      glBindAttribLocation(p, i, attribs[i]);
   link(p);
   for (int i = 0; i < 5; i++)
      if (sh[i])
         glDeleteShader(sh[i]);
   return p;
}

GLuint fp_gl_program_gs(const char *vs, const char *gs, const char *fs,
                        const char *const *attribs)
{
   return fp_gl_program_stages(vs, NULL, NULL, gs, fs, attribs);
}

GLuint fp_gl_program(const char *vs, const char *fs, const char *const *attribs)
{
   return fp_gl_program_gs(vs, NULL, fs, attribs);
}

GLuint fp_gl_compute_program(const char *cs)
{
   GLuint p = glCreateProgram();
   GLuint c = compile(0x91B9 /* GL_COMPUTE_SHADER, GL ES 3.1 */, cs);
   glAttachShader(p, c);
   link(p);
   glDeleteShader(c);
   return p;
}

void fp_gl_read_rgba(const struct fp_gl *g, unsigned char *out)
{
   size_t row = (size_t)g->w * 4;
   unsigned char *tmp = malloc(row * (size_t)g->h);
   if (!tmp)
      fp_die("out of memory");
   glPixelStorei(GL_PACK_ALIGNMENT, 1);
   glReadPixels(0, 0, g->w, g->h, GL_RGBA, GL_UNSIGNED_BYTE, tmp);
   fp_gl_check("glReadPixels");
   for (int y = 0; y < g->h; y++)
      memcpy(out + (size_t)y * row, tmp + (size_t)(g->h - 1 - y) * row, row);
   free(tmp);
}

void fp_gl_check(const char *where)
{
   GLenum e = glGetError();
   if (e != GL_NO_ERROR)
      fp_die("GL error 0x%x during %s", e, where);
}

void fp_gl_write_png(const struct fp_gl *g, const char *path)
{
   unsigned char *px = malloc((size_t)g->w * (size_t)g->h * 4);
   char err[512];
   if (!px)
      fp_die("out of memory");
   fp_gl_read_rgba(g, px);
   if (fp_png_write(path, g->w, g->h, px, err, sizeof(err)) != 0)
      fp_die("%s", err);
   free(px);
}

static double now_ms(void)
{
   struct timespec t;
   clock_gettime(CLOCK_MONOTONIC, &t);
   return (double)t.tv_sec * 1e3 + (double)t.tv_nsec / 1e6;
}

static int cmp_double(const void *a, const void *b)
{
   double x = *(const double *)a, y = *(const double *)b;
   return (x > y) - (x < y);
}

void fp_gl_time_frames(int frames, int warmup, void (*draw)(void *ctx), void *ctx,
                       struct fp_frame_times *t)
{
   if (frames < 1)
      frames = 1;
   if (warmup < 1 || warmup >= frames)
      warmup = frames > 1 ? (warmup < 1 ? 1 : frames - 1) : 1;
   double *dts = calloc((size_t)frames, sizeof(double));
   if (!dts)
      fp_die("out of memory");
   double warm = 0, rest = 0;
   for (int f = 0; f < frames; f++) {
      double t0 = now_ms();
      draw(ctx);
      glFinish();
      dts[f] = now_ms() - t0;
      if (f < warmup)
         warm += dts[f];
      else
         rest += dts[f];
   }
   t->frames = frames;
   t->warmup = warmup;
   t->first_ms = dts[0];
   t->warmup_ms = warm;
   t->mean_ms = t->median_ms = 0;
   if (frames > warmup) {
      int n = frames - warmup;
      double *d = dts + warmup;
      qsort(d, (size_t)n, sizeof(double), cmp_double);
      t->mean_ms = rest / n;
      t->median_ms = n % 2 ? d[n / 2] : (d[n / 2 - 1] + d[n / 2]) / 2;
   }
   free(dts);
}

void fp_print_frame_times(const struct fp_frame_times *t)
{
   printf("first_frame_ms: %.2f\n", t->first_ms);
   printf("warmup_frames: %d ms: %.2f\n", t->warmup, t->warmup_ms);
   if (t->frames > t->warmup) {
      printf("frames: %d ms_per_frame: %.2f (frames %d..%d)\n", t->frames, t->mean_ms,
             t->warmup + 1, t->frames);
      printf("ms_per_frame_median: %.2f\n", t->median_ms);
   }
}

_Noreturn static void bad_value(const char *prog, const char *option, const char *v,
                                const char *accepted)
{
   fprintf(stderr, "%s: bad %s '%s' (%s)\n", prog, option, v, accepted);
   exit(2);
}

int fp_arg_count(const char *prog, const char *option, const char *v)
{
   char *end;
   long n = strtol(v, &end, 10);
   if (*end || n < 1 || n > 1000000)
      bad_value(prog, option, v, "1..1000000");
   return (int)n;
}

int fp_arg_name(const char *prog, const char *option, const char *const *names, const char *v)
{
   char accepted[256] = "";
   for (int k = 0; names[k]; k++) {
      if (!strcmp(v, names[k]))
         return k;
      snprintf(accepted + strlen(accepted), sizeof(accepted) - strlen(accepted), "%s%s",
               k ? ", " : "", names[k]);
   }
   bad_value(prog, option, v, accepted);
}

int fp_gl_getopt(int argc, char **argv, const struct option *opts, const char *prog,
                 int min_size, struct fp_gl_args *a, void (*usage)(FILE *))
{
   int c;
   char junk;
   while ((c = getopt_long(argc, argv, "ho:", opts, NULL)) != -1) {
      switch (c) {
      case 'o': a->out = optarg; break;
      case FP_OPT_FRAMES: a->frames = fp_arg_count(prog, "--frames", optarg); break;
      case FP_OPT_SIZE:
         if (sscanf(optarg, "%dx%d%c", &a->w, &a->h, &junk) != 2 || a->w < min_size ||
             a->h < min_size || a->w > 8192 || a->h > 8192) {
            char accepted[32];
            snprintf(accepted, sizeof(accepted), "WxH, %d..8192", min_size);
            bad_value(prog, "--size", optarg, accepted);
         }
         break;
      case 'h': usage(stdout); exit(0);
      case '?': usage(stderr); exit(2);
      default: return c;
      }
   }
   if (optind < argc) {
      fprintf(stderr, "%s: unexpected argument '%s'\n", prog, argv[optind]);
      usage(stderr);
      exit(2);
   }
   return -1;
}
