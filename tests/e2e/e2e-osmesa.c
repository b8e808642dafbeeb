/*
 * An OSMesa program: desktop GL 1.x immediate mode into a client buffer, no
 * EGL and no X.  Shows that OSMesa programs run through every driver of
 * `./fixpipe run`, llvmpipe included (Debian installs no libOSMesa: the
 * launcher gives llvmpipe runs our build's libOSMesa and nothing else of it).
 * libOSMesa.so.8 is opened at run time, so this builds without its -dev
 * package.  Gouraud triangles over a cleared background, a scissored clear.
 *
 *   e2e-osmesa -o out.png [--mask mask.png] [--size N]
 */
#include <dlfcn.h>
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fp_png.h"

typedef unsigned int GLenum;
typedef int GLint;
typedef int GLsizei;
typedef float GLfloat;
typedef unsigned char GLboolean;
typedef unsigned int GLbitfield;
typedef struct osmesa_context *OSMesaContext;

#define GL_RGBA 0x1908
#define GL_UNSIGNED_BYTE 0x1401
#define GL_TRIANGLES 0x0004
#define GL_COLOR_BUFFER_BIT 0x4000
#define GL_SCISSOR_TEST 0x0C11
#define GL_RENDERER 0x1F01

struct osmesa {
   OSMesaContext (*CreateContextExt)(GLenum, GLint, GLint, GLint, OSMesaContext);
   GLboolean (*MakeCurrent)(OSMesaContext, void *, GLenum, GLsizei, GLsizei);
   void (*DestroyContext)(OSMesaContext);
   void *(*GetProcAddress)(const char *);
};

struct gl {
   void (*ClearColor)(GLfloat, GLfloat, GLfloat, GLfloat);
   void (*Clear)(GLbitfield);
   void (*Enable)(GLenum);
   void (*Disable)(GLenum);
   void (*Scissor)(GLint, GLint, GLsizei, GLsizei);
   void (*Begin)(GLenum);
   void (*End)(void);
   void (*Color3f)(GLfloat, GLfloat, GLfloat);
   void (*Vertex2f)(GLfloat, GLfloat);
   void (*Finish)(void);
   const unsigned char *(*GetString)(GLenum);
};

static void *sym(void *lib, const char *name)
{
   void *p = dlsym(lib, name);
   if (!p) {
      fprintf(stderr, "error: %s not found in libOSMesa.so.8\n", name);
      exit(1);
   }
   return p;
}

static void *proc(const struct osmesa *os, const char *name)
{
   void *p = os->GetProcAddress(name);
   if (!p) {
      fprintf(stderr, "error: OSMesaGetProcAddress(%s) failed\n", name);
      exit(1);
   }
   return p;
}

static int usage(const char *prog)
{
   fprintf(stderr, "usage: %s -o out.png [--mask mask.png] [--size N (16..4096)]\n", prog);
   return 2;
}

int main(int argc, char **argv)
{
   static const struct option longopts[] = {
      { "mask", required_argument, NULL, 'm' },
      { "size", required_argument, NULL, 's' },
      { NULL, 0, NULL, 0 },
   };
   const char *out = NULL, *mask = NULL;
   int size = 256;
   for (int c; (c = getopt_long(argc, argv, "o:", longopts, NULL)) != -1;) {
      switch (c) {
      case 'o': out = optarg; break;
      case 'm': mask = optarg; break;
      case 's': size = atoi(optarg); break;
      default: return usage(argv[0]);
      }
   }
   if (optind < argc || !out || size < 16 || size > 4096)
      return usage(argv[0]);

   void *lib = dlopen("libOSMesa.so.8", RTLD_NOW | RTLD_LOCAL);
   if (!lib) {
      fprintf(stderr, "error: cannot open libOSMesa.so.8: %s\n", dlerror());
      return 1;
   }
   struct osmesa os;
   *(void **)&os.CreateContextExt = sym(lib, "OSMesaCreateContextExt");
   *(void **)&os.MakeCurrent = sym(lib, "OSMesaMakeCurrent");
   *(void **)&os.DestroyContext = sym(lib, "OSMesaDestroyContext");
   *(void **)&os.GetProcAddress = sym(lib, "OSMesaGetProcAddress");

   OSMesaContext ctx = os.CreateContextExt(GL_RGBA, 16, 0, 0, NULL);
   unsigned char *buf = calloc((size_t)size * size, 4);
   if (!ctx || !buf || !os.MakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, size, size)) {
      fprintf(stderr, "error: no OSMesa context\n");
      return 1;
   }
   struct gl gl;
   *(void **)&gl.ClearColor = proc(&os, "glClearColor");
   *(void **)&gl.Clear = proc(&os, "glClear");
   *(void **)&gl.Enable = proc(&os, "glEnable");
   *(void **)&gl.Disable = proc(&os, "glDisable");
   *(void **)&gl.Scissor = proc(&os, "glScissor");
   *(void **)&gl.Begin = proc(&os, "glBegin");
   *(void **)&gl.End = proc(&os, "glEnd");
   *(void **)&gl.Color3f = proc(&os, "glColor3f");
   *(void **)&gl.Vertex2f = proc(&os, "glVertex2f");
   *(void **)&gl.Finish = proc(&os, "glFinish");
   *(void **)&gl.GetString = proc(&os, "glGetString");
   printf("renderer: %s\n", (const char *)gl.GetString(GL_RENDERER));

   gl.ClearColor(0.1f, 0.2f, 0.3f, 1.0f);
   gl.Clear(GL_COLOR_BUFFER_BIT);
   gl.Enable(GL_SCISSOR_TEST);
   gl.Scissor(size / 8, size / 8, size / 4, size / 4);
   gl.ClearColor(0.9f, 0.9f, 0.2f, 1.0f);
   gl.Clear(GL_COLOR_BUFFER_BIT);
   gl.Disable(GL_SCISSOR_TEST);
   /* vertices off the pixel centres and their ties: coverage, not ties */
   gl.Begin(GL_TRIANGLES);
   for (int i = 0; i < 6; i++) {
      const float a = -0.9f + 0.3f * (float)i;
      gl.Color3f(1, 0, 0);
      gl.Vertex2f(a, -0.83f);
      gl.Color3f(0, 1, 0);
      gl.Vertex2f(a + 0.27f, -0.71f + 0.11f * (float)i);
      gl.Color3f(0, 0, 1);
      gl.Vertex2f(a + 0.05f, 0.87f - 0.07f * (float)i);
   }
   gl.End();
   gl.Finish();

   /* OSMesa's row 0 is the bottom row */
   unsigned char *img = malloc((size_t)size * size * 4);
   if (!img)
      return 1;
   for (int y = 0; y < size; y++)
      memcpy(img + (size_t)y * size * 4, buf + (size_t)(size - 1 - y) * size * 4,
             (size_t)size * 4);
   char err[256];
   if (fp_png_write(out, size, size, img, err, sizeof(err))) {
      fprintf(stderr, "error: %s\n", err);
      return 1;
   }
   if (mask) {
      memset(img, 0, (size_t)size * size * 4);   /* nothing left out */
      if (fp_png_write(mask, size, size, img, err, sizeof(err))) {
         fprintf(stderr, "error: %s\n", err);
         return 1;
      }
   }
   os.DestroyContext(ctx);
   free(img);
   free(buf);
   return 0;
}
