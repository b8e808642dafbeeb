/* Shared helpers of the model's unit tests: a context whose fragment
 * shader records coverage, and the exact reference rasterizer. */
#ifndef FIXPIPE_TUTIL_H
#define FIXPIPE_TUTIL_H

#include <stdio.h>
#include <stdlib.h>
#include <stdint.h>
#include <stdbool.h>
#include "rast/rast.h"

extern unsigned t_failures;

/* xorshift64 (Marsaglia): one step of a test's reproducible random
 * numbers; each test keeps and seeds its own state. */
static inline uint64_t t_xorshift(uint64_t *state)
{
   *state ^= *state << 13;
   *state ^= *state >> 7;
   *state ^= *state << 17;
   return *state;
}

#define CHECK(cond, ...) do { \
      if (!(cond)) { \
         if (t_failures++ < 20) { \
            fprintf(stderr, "%s:%d: FAIL %s: ", __FILE__, __LINE__, #cond); \
            fprintf(stderr, __VA_ARGS__); \
            fputc('\n', stderr); \
         } \
      } \
   } while (0)

struct tctx;
typedef void (*t_quad_hook)(struct tctx *t, const struct rast_quad *q);

/* t_init's shader: it records the quad's pixels (stamp, hits, counts),
 * calls the hook, and discards the quad. */
unsigned t_shade_record(void *ctx, const struct rast_quad *q, struct rast_shaded_quad *out);
/* A framebuffer-fetch shader that counts in red: 1/255 added to the red
 * it fetches from colour buffer 0, green kept, blue 0.5, alpha 1 (fetch
 * mask 1); _n the same on n quads (rast_shader.shade_n). */
unsigned t_shade_fetch_count(void *ctx, const struct rast_quad *q, struct rast_shaded_quad *out);
unsigned t_shade_fetch_count_n(void *ctx, const struct rast_quad *const q[],
                               struct rast_shaded_quad *const out[], unsigned n);

struct tctx {
   struct rast_context *rc;
   const struct rast_profile *prof;
   struct rast_profile_buf *profile_buf;   /* prof's storage (t_init's spec) */
   int w, h;
   uint32_t *stamp;          /* last primitive id that covered each pixel */
   uint8_t *hits;            /* per-pixel count, when counting is on */
   bool counting;
   uint32_t id;
   uint64_t count, dups, outside, badquad;
   int minx, maxx, miny, maxy;   /* the box of the covered pixels, inside or not */
   t_quad_hook hook;
   void *user;
};

/* A bytes-RGBA8 target's generic load and store (the driver's role). */
void t_load_rgba8(const uint8_t *src, unsigned n, float (*rgba)[4]);
void t_store_rgba8(uint8_t *dst, unsigned n, const float (*rgba)[4]);

/* A w x h RGBA8 colour buffer and a Z24S8 buffer as the framebuffer. */
void t_bind_rgba8_z24s8(struct rast_context *rc, uint8_t *color, uint32_t *zs, int w, int h);
/* The same on a target of `samples` samples a pixel (1, or RAST_MSAA_SAMPLES planes
 * of w x h pixels each, one after the other, in both buffers). */
void t_bind_rgba8_z24s8_samples(struct rast_context *rc, uint8_t *color, uint32_t *zs, int w,
                                int h, unsigned samples);
/* A vertex layout built a varying at a time: t_layout_pos, the position
 * alone in slot 0; t_layout_add, a varying in the next slot, interpolated
 * as interp, the components in usage_mask read (returned, for the fields
 * of the rarer cases). */
struct rast_vertex_layout t_layout_pos(void);
struct rast_varying *t_layout_add(struct rast_vertex_layout *vl, enum rast_interp interp,
                                  unsigned usage_mask);
/* Vertices of three slots: position, a PERSPECTIVE varying (x, y read) and
 * a COLOR varying (all four read). */
#define T_PERSP_COLOR_SLOTS 3
void t_layout_persp_color(struct rast_context *rc);

/* The plainest state around a shader: position-only vertices, GL's pixel
 * centres, 1-pixel lines and points, colour 0 written unblended. */
void t_plain_state(struct rast_context *rc);

/* Depth tested by `func` and written; the stencil (both faces) counts
 * every hit of a pixel, passed or not (INCR_WRAP). */
void t_depth_count_hits(struct rast_context *rc, enum rast_func func);

void t_init(struct tctx *t, const char *profile, int w, int h);
void t_fini(struct tctx *t);
/* The raster state: GL's pixel centres or not, the bottom edge rule or the
 * top one, no culling, 1-pixel lines; t_raster_scissor: the scissor test
 * on or off. */
void t_raster(struct tctx *t, bool half_pixel, bool bottom_rule);
void t_raster_scissor(struct tctx *t, bool half_pixel, bool bottom_rule, bool scissor);
void t_begin(struct tctx *t);      /* a new primitive id, counters zeroed */
uint64_t t_sat_total(const struct rast_stats *s);
uint64_t t_sat_class(const struct rast_stats *s, enum rast_reg_class c);
double t_rand(void);               /* [0, 1) */
void t_seed(uint64_t s);
int t_summary(const char *name);
/* "[--COUNT N] [--seed S]" of a test's command line (COUNT: count_name,
 * e.g. "triangles"), numbers as strtoull reads them (0x: hex), N at most
 * max_count, into *count and *seed (left as they are when absent);
 * anything else: the test's usage on stderr and exit(2). */
void t_count_seed_args(int argc, char **argv, const char *name, const char *count_name,
                       uint64_t max_count, uint64_t *count, uint64_t *seed);
/* The same for a scene test: "[--scenes N] [--seed S]". */
void t_scene_args(int argc, char **argv, const char *name, unsigned *scenes, uint64_t *seed);

/* The reference: exact 64-bit edge functions on the fixed-point vertices
 * (units of 2^-N), pixel centres (i*S + H, j*S + H), llvmpipe's tie rule.
 * Calls visit for every covered pixel inside clip; returns the count. */
typedef void (*t_visit)(void *ctx, int x, int y);
uint64_t t_ref_triangle(const int64_t X[3], const int64_t Y[3], int64_t S, int64_t H,
                        bool bottom_rule, struct rast_scissor clip, t_visit visit, void *ctx);

/* A random triangle of the multisample tests on a w x h target: vertices on
 * the 1/4096 grid (some beyond the target), 1/w in [1/4, 2], and four
 * slots after the position, slot 2 in [0, 1) (a colour), the others in
 * [-4, 4). */
struct t_slot_tri { float v[3][4][4]; };
void t_random_slot_tri(struct t_slot_tri *tr, int w, int h);
/* The exact plane of the registers ra[3] of vertices (X, Y) (1/4096 pixel)
 * at the point (px, py), in the registers' units (rational arithmetic). */
long double t_exact_plane(const int64_t X[3], const int64_t Y[3], const int64_t ra[3],
                          int64_t px, int64_t py);

/* ISO C before C2x does not convert float (*)[4] to const float (*)[4]. */
#define T_V(p) ((const float (*)[4])(p))
static inline void t_tri(struct rast_context *rc, float (*a)[4], float (*b)[4], float (*c)[4])
{
   rast_triangle(rc, T_V(a), T_V(b), T_V(c));
}
/* A triangle of one-slot vertices (position only) at z = 0.5, w = 1. */
static inline void t_tri_xy(struct rast_context *rc, const float v[3][2])
{
   float vert[3][1][4];
   for (int i = 0; i < 3; i++) {
      vert[i][0][0] = v[i][0];
      vert[i][0][1] = v[i][1];
      vert[i][0][2] = 0.5f;
      vert[i][0][3] = 1.0f;
   }
   t_tri(rc, vert[0], vert[1], vert[2]);
}
static inline void t_line(struct rast_context *rc, float (*a)[4], float (*b)[4])
{
   rast_line(rc, T_V(a), T_V(b));
}

#endif
