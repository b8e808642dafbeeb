/*
 * What every e2e test program shares: its command line, a flat/Gouraud
 * colour program, drawing from client arrays, the exact sub-pixel grid and
 * its tie test, and writing the result and the mask.
 *
 * Every program is run once per driver and prints
 *   renderer: <GL_RENDERER>       (the runner checks it names the driver)
 *   stat: key=value               (figures the runner repeats on its line)
 * and writes -o OUT.png (what was rendered) and --mask MASK.png (pixels the
 * comparison leaves out, non-zero = excluded; computed on the CPU, so both
 * drivers' masks must be identical).
 */
#ifndef E2E_COMMON_H
#define E2E_COMMON_H

#include "fp_gl.h"

#include <stdint.h>

/* Vertices live on a 1/256 pixel grid: positions are integers in these
 * units, exactly representable for every driver under test. */
#define E2E_SUB 256

struct e2e_args {
   const char *out, *mask;
   int size;                 /* square target side in pixels */
   const char *opt[8][2];    /* test-specific "--name value" pairs */
   int nopt;
};

/* Parses -o, --mask, --size and keeps any other "--name value" pair;
 * exits with usage on error.  default_size when --size is absent. */
void e2e_parse(struct e2e_args *a, int argc, char **argv, int default_size);
/* The value of a test-specific option, or def. */
const char *e2e_opt(const struct e2e_args *a, const char *name, const char *def);

/* Creates the context, prints the renderer. */
void e2e_begin(struct fp_gl *g, const struct e2e_args *a);
/* e2e_parse, then e2e_begin. */
void e2e_start(struct fp_gl *g, struct e2e_args *a, int argc, char **argv, int default_size);
/* Reads back, writes -o and --mask (mask may be NULL: nothing excluded),
 * tears down. */
void e2e_end(struct fp_gl *g, const struct e2e_args *a, const unsigned char *mask);

/* Self-checks, which fail the program on any driver: a check that does
 * not hold prints "error: WHAT" and counts in e2e_errors. */
extern int e2e_errors;
void e2e_check(bool ok, const char *what);
/* Whether the context is GL ES 3.1 or later (a self-check). */
bool e2e_check_es31(void);
/* The end of a self-checking program: a GL error is a failed check, then
 * e2e_end; returns the exit status, 1 after a failed check. */
int e2e_finish(struct fp_gl *g, const struct e2e_args *a, const unsigned char *mask);

/* Whether the context (GL ES 3.0 or later) exposes the extension `name`. */
bool e2e_has_extension(const char *name);

/* Compiles and links vs and fs with a_pos bound to location 0 and attr1 (if
 * not NULL) to 1, the locations e2e_draw and e2e_draw_uv feed. */
GLuint e2e_program(const char *vs, const char *fs, const char *attr1);

/* Program with a_pos (vec4, clip space) and a_color (vec4) varying. */
GLuint e2e_color_program(void);
/* Draws n vertices of mode from client arrays: pos 4 floats, color 4 floats
 * (color NULL: attribute 1 constant at rgba). */
void e2e_draw(GLenum mode, int n, const float *pos, const float *color, const float rgba[4]);

/* Program with a_pos (vec4, clip space) and a_uv (vec2) varying into
 * texture2D(u_tex, v_uv) and nothing else (u_tex left at unit 0). */
GLuint e2e_texture_program(void);
/* Draws n vertices of mode from client arrays: pos 4 floats, attribute 1
 * (a texture coordinate) ncomp floats. */
void e2e_draw_uv(GLenum mode, int n, const float *pos, const float *uv, int ncomp);
/* A rectangle of clip space, (x0, y0) to (x1, y1), its texture coordinates
 * (attribute 1) (u0, v0) to (u1, v1) over it. */
void e2e_draw_rect(float x0, float y0, float x1, float y1, float u0, float v0, float u1,
                   float v1);

/* GLSL ES 3.00: a_pos (vec4, clip space) and a_color (vec4) varying as
 * v_color into the fragment shader fs. */
GLuint e2e_color_program_es3(const char *fs);
/* GLSL ES 3.10: a_pos (vec4, clip space) and a_uv (vec2) varying as v_uv
 * into the fragment shader fs. */
GLuint e2e_uv_program_es31(const char *fs);

/* Each sample of a 4-sample 2-D texture of side size/2 into a quarter of
 * the side-`size` framebuffer `target` (sample k in column k & 1, row
 * k >> 1) by texelFetch, so that each sample's own value is compared, not
 * the resolve's mean (GL ES 3.1). */
void e2e_show_samples(GLuint tex, GLuint target, int size);

/* The filters and wrap modes of the texture bound to target. */
void e2e_tex_params(GLenum target, GLenum min, GLenum mag, GLenum wrap_s, GLenum wrap_t);
/* A size x size RGBA 2D texture with every level down to 1x1, bound: level
 * l's texels (l * step, 255 - l * step, a checker of hi and lo, 255);
 * filters min and mag, REPEAT. */
GLuint e2e_mip_texture(int size, int step, int hi, int lo, GLenum min, GLenum mag);

/* A 4-sample FBO of size x size (RGBA8 colour, depth24/stencil8), GL ES
 * 3.0: create binds it and sets the viewport, and returns the number of
 * problems it printed as "error:" lines (not complete, GL_SAMPLES not 4);
 * resolve blits it into `target` (glBlitFramebuffer) and binds that. */
struct e2e_msaa { GLuint fbo, color, ds; int size; };
int e2e_msaa_create(struct e2e_msaa *m, int size);
void e2e_msaa_resolve(const struct e2e_msaa *m, GLuint target);
void e2e_msaa_delete(struct e2e_msaa *m);

/* Sub-pixel grid unit -> clip-space x or y for a target of `size` pixels;
 * exact for power-of-two sizes. */
float e2e_ndc(int32_t sub, int size);

/* Deterministic PRNG (xorshift32): the same triangles on every machine. */
uint32_t e2e_rand(uint32_t *state);
int e2e_rand_range(uint32_t *state, int lo, int hi);   /* inclusive */

/* A triangle in grid units, window coordinates (y up, as GL). */
struct e2e_tri { int32_t x[3], y[3]; };

/* Number of pixel centres (i+0.5, j+0.5) inside the target that lie exactly
 * on an edge of the triangle, inside its closed span: the pixels where the
 * fill rule alone decides.  If mask != NULL, marks them (PNG row order,
 * RGBA, value 255). */
long e2e_tri_ties(const struct e2e_tri *t, int size, unsigned char *mask);
/* Twice the signed area in grid units squared (0: degenerate). */
int64_t e2e_tri_area2(const struct e2e_tri *t);

#endif
