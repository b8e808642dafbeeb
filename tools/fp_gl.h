/*
 * A GL ES 2 context on EGL surfaceless with an offscreen FBO (RGBA8 colour,
 * depth24/stencil8), shared by fp-demo and the e2e tests.  Surfaceless has no
 * window surface, so every program draws into the FBO and reads it back.
 * Errors are fatal: these are test programs, a message and exit(2) is the
 * most useful thing they can do.
 */
#ifndef FP_GL_H
#define FP_GL_H

#include <GLES2/gl2.h>
#include <getopt.h>
#include <stdbool.h>
#include <stdio.h>

struct fp_gl {
   void *dpy, *ctx;            /* EGLDisplay, EGLContext */
   GLuint fbo, color_rb, ds_rb;
   int w, h;
};

/* Creates the context and the FBO, bound and with the viewport set. */
void fp_gl_init(struct fp_gl *g, int w, int h);
void fp_gl_fini(struct fp_gl *g);

/* GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)". */
const char *fp_gl_renderer(void);

/* Compiles and links; attribs[i] is bound to location i (NULL-terminated). */
GLuint fp_gl_program(const char *vs, const char *fs, const char *const *attribs);
/* The same with a geometry shader between them (gs NULL: none). */
GLuint fp_gl_program_gs(const char *vs, const char *gs, const char *fs,
                        const char *const *attribs);
/* The same with any of the stages between them (NULL: none): tessellation
 * control and evaluation, geometry. */
GLuint fp_gl_program_stages(const char *vs, const char *tcs, const char *tes, const char *gs,
                            const char *fs, const char *const *attribs);
/* A compute program (GL ES 3.1); errors are fatal as above. */
GLuint fp_gl_compute_program(const char *cs);

/* The whole FBO as RGBA8 rows top to bottom (PNG order; GL's are bottom up). */
void fp_gl_read_rgba(const struct fp_gl *g, unsigned char *out);

/* Frame times of fp_gl_time_frames: the first frame pays for shader
 * compilation (llvmpipe JITs), so it is kept apart from the rest; the median
 * of the rest too, since on a shared machine other processes' load skews the
 * mean in both directions and the median much less. */
struct fp_frame_times {
   int frames, warmup;
   double first_ms, warmup_ms;            /* frame 1; frames 1..warmup */
   double mean_ms, median_ms;             /* frames warmup+1..N: the steady state */
};

/* Draws `frames` frames with draw(ctx), each finished with glFinish; the
 * first `warmup` (1 or more, fewer than frames) are timed apart: start-up,
 * and a tiered driver's frames before its shaders are compiled. */
void fp_gl_time_frames(int frames, int warmup, void (*draw)(void *ctx), void *ctx,
                       struct fp_frame_times *t);
/* first_frame_ms, warmup_frames: W ms: X, and with frames past the warm-up
 * `frames: N ms_per_frame: X (frames W+1..N)` and ms_per_frame_median: the
 * lines the scripts read. */
void fp_print_frame_times(const struct fp_frame_times *t);

/* The command line of the GL programs, through getopt_long: -o PNG,
 * --size WxH (each in [min_size, 8192]), --frames N and -h/--help are
 * shared; FP_GL_OPTIONS heads each program's table of long options.
 * fp_gl_getopt returns the next of the program's own options (optarg
 * holds its value) or -1 at the end, and sets the shared ones in a (which
 * holds their defaults).
 * It ends the program after --help (usage on stdout, status 0), and after
 * an option getopt_long refuses, a bad value or an operand (status 2). */
struct fp_gl_args {
   int w, h, frames;
   const char *out;
};
enum { FP_OPT_SIZE = 0x100, FP_OPT_FRAMES };
#define FP_GL_OPTIONS                                       \
   { "size", required_argument, NULL, FP_OPT_SIZE },        \
   { "frames", required_argument, NULL, FP_OPT_FRAMES },    \
   { "help", no_argument, NULL, 'h' }
int fp_gl_getopt(int argc, char **argv, const struct option *opts, const char *prog,
                 int min_size, struct fp_gl_args *a, void (*usage)(FILE *));

/* Values of the programs' own options; on a bad one they print a message
 * naming prog, option and the accepted values, and exit(2).  A count is
 * in [1, 1000000]; a name one of names (NULL-terminated), its index. */
int fp_arg_count(const char *prog, const char *option, const char *v);
int fp_arg_name(const char *prog, const char *option, const char *const *names, const char *v);

/* Reads the FBO and writes it to a PNG file; exits with a message on failure. */
void fp_gl_write_png(const struct fp_gl *g, const char *path);

/* Exits with the GL error if there is one; where says what was going on. */
void fp_gl_check(const char *where);

_Noreturn void fp_die(const char *fmt, ...);

#endif
