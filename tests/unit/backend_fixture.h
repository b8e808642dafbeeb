/*
 * The back end's unit tests' fixture (test_backend_zs.c, test_backend_color.c,
 * test_backend_logicop.c): the harness (CHECK, the seeded random numbers),
 * the targets' formats and their reference reads and writes, and the
 * per-pixel reference of the depth and stencil stage and of blending (GL ES
 * semantics, exact arithmetic), which shares no code with the back end.
 * Each test program includes it once.
 */
#ifndef TEST_BACKEND_FIXTURE_H
#define TEST_BACKEND_FIXTURE_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rast/rast.h"
#include "rast/rast_priv.h"
#include "rast/backend/backend_priv.h"
#include "rast/host/lanes.h"

#if !defined(__SIZEOF_INT128__)
#error "the reference depth conversion uses unsigned __int128"
#endif
__extension__ typedef unsigned __int128 u128;

/* ------------------------------------------------------------------ */
/* Harness.                                                             */

static unsigned checks, failures;

#define CHECK(cond, ...) do { \
   checks++; \
   if (!(cond)) { \
      if (failures++ < 30) { \
         printf("FAIL %s:%d: %s: ", __FILE__, __LINE__, #cond); \
         printf(__VA_ARGS__); \
         printf("\n"); \
      } \
   } \
} while (0)

static uint64_t rng_state = 0x9e3779b97f4a7c15u;

static inline uint64_t rnd64(void)
{
   uint64_t x = rng_state;
   x ^= x << 13; x ^= x >> 7; x ^= x << 17;
   return rng_state = x;
}

static inline unsigned rnd(unsigned n) { return (unsigned)(rnd64() % n); }
static inline float rndf(float lo, float hi) { return lo + (hi - lo) * (float)(rnd64() >> 40) / (float)(1 << 24); }

static inline unsigned popc(unsigned m) { return (unsigned)__builtin_popcount(m); }

#define W 16
#define H 12

static const struct rast_profile *profile_named(const char *n)
{
   const struct rast_profile *p = rast_profile_by_name(n);
   if (!p) {
      printf("no profile %s\n", n);
      exit(2);
   }
   return p;
}

/* ------------------------------------------------------------------ */
/* The test shader: outputs what the test put in `sd`.                   */

struct shader_data {
   float color[RAST_MAX_CBUFS][4][RAST_QUAD_SIZE];
   float depth[RAST_QUAD_SIZE];
   unsigned keep;                 /* bits cleared: discarded */
   unsigned calls, pixels;
   unsigned empty_calls;          /* shaded with no live pixel: wasted work */
};

static inline unsigned test_shade(void *ctx, const struct rast_quad *q, struct rast_shaded_quad *out)
{
   struct shader_data *sd = ctx;
   sd->calls++;
   sd->pixels += popc(q->mask);
   sd->empty_calls += q->mask == 0;
   memcpy(out->color, sd->color, sizeof sd->color);
   memcpy(out->depth, sd->depth, sizeof sd->depth);
   return q->mask & sd->keep;
}

static inline struct rast_shader make_shader(struct shader_data *sd, unsigned outputs, bool writes_depth,
                                      bool may_discard, bool to_all)
{
   struct rast_shader fs;
   memset(&fs, 0, sizeof fs);
   fs.ctx = sd;
   fs.shade = test_shade;
   fs.num_outputs = outputs;
   fs.writes_depth = writes_depth;
   fs.may_discard = may_discard;
   fs.color0_to_all = to_all;
   return fs;
}

/* ------------------------------------------------------------------ */
/* Driver-supplied formats for RAST_CL_GENERIC.                         */

static inline void f32_load(const uint8_t *src, unsigned n, float (*rgba)[4])
{
   memcpy(rgba, src, n * 16);
}

static inline void f32_store(uint8_t *dst, unsigned n, const float (*rgba)[4])
{
   memcpy(dst, rgba, n * 16);
}

static inline uint8_t ref_ubyte(double v)
{
   if (!(v > 0.0))
      return 0;
   if (v >= 1.0)
      return 255;
   return (uint8_t)lrint(v * 255.0);
}

/* RGBA8 again, through the generic path. */
static inline void u8_load(const uint8_t *src, unsigned n, float (*rgba)[4])
{
   for (unsigned i = 0; i < n; i++)
      for (unsigned c = 0; c < 4; c++)
         rgba[i][c] = src[4 * i + c] / 255.0f;
}

static inline void u8_store(uint8_t *dst, unsigned n, const float (*rgba)[4])
{
   for (unsigned i = 0; i < n; i++)
      for (unsigned c = 0; c < 4; c++)
         dst[4 * i + c] = ref_ubyte(rgba[i][c]);
}

/* TF_F32_SNORM: float storage of a signed normalized target, clamped to
 * [-1, 1]. */
enum tfmt { TF_RGBA8, TF_BGRA8, TF_BGRX8, TF_F32, TF_F32_CLAMP, TF_GEN8, TF_F32_SNORM, TF_COUNT };
static const char *const tfmt_name[TF_COUNT] = {
   "RGBA8", "BGRA8", "BGRX8", "F32(generic)", "F32-clamp(generic)", "RGBA8(generic)",
   "F32-snorm(generic)"
};

static inline bool is_f32(enum tfmt f)
{
   return f == TF_F32 || f == TF_F32_CLAMP || f == TF_F32_SNORM;
}

static inline unsigned tfmt_cpp(enum tfmt f) { return is_f32(f) ? 16 : 4; }

static inline struct rast_color_target make_cbuf(enum tfmt f, uint8_t *mem)
{
   struct rast_color_target t;
   memset(&t, 0, sizeof t);
   t.base = mem;
   t.cpp = tfmt_cpp(f);
   t.stride = (int)(W * t.cpp + 12);     /* padding catches stride mistakes */
   t.load = is_f32(f) ? f32_load : u8_load;
   t.store = is_f32(f) ? f32_store : u8_store;
   t.clamp = f != TF_F32;
   t.snorm = f == TF_F32_SNORM;
   t.layout = f == TF_RGBA8 ? RAST_CL_RGBA8 : f == TF_BGRA8 ? RAST_CL_BGRA8 :
              f == TF_BGRX8 ? RAST_CL_BGRX8 : RAST_CL_GENERIC;
   return t;
}

#define CBUF_BYTES ((W * 16 + 12) * H)

/* Pixel (x, y)'s bytes in mem, a target laid out as t. */
static inline const uint8_t *cb_pixel(const struct rast_color_target *t, const uint8_t *mem,
                                      int x, int y)
{
   return mem + y * t->stride + x * (int)t->cpp;
}

/* Channel c of pixel (x, y) as the format stores it. */
static inline float cb_get(enum tfmt f, const struct rast_color_target *t, const uint8_t *mem,
                    int x, int y, unsigned c)
{
   const uint8_t *p = cb_pixel(t, mem, x, y);
   float v;
   switch (f) {
   case TF_F32: case TF_F32_CLAMP: case TF_F32_SNORM: memcpy(&v, p + 4 * c, 4); return v;
   case TF_BGRA8: case TF_BGRX8: return p[c == 3 ? 3 : 2 - c];
   default: return p[c];
   }
}

static inline bool is8(enum tfmt f) { return !is_f32(f); }

/* ------------------------------------------------------------------ */
/* Reference depth/stencil.                                             */

static const enum rast_zs_layout zs_layouts[] = {
   RAST_ZS_Z16, RAST_ZS_Z32, RAST_ZS_Z24_S8, RAST_ZS_Z24X8, RAST_ZS_S8_Z24,
   RAST_ZS_X8Z24, RAST_ZS_Z32F, RAST_ZS_Z32F_S8X24, RAST_ZS_S8
};
#define N_ZS_LAYOUTS (sizeof zs_layouts / sizeof zs_layouts[0])

static const char *zs_name(enum rast_zs_layout l)
{
   static const char *const n[] = { "NONE", "Z16", "Z32", "Z24_S8", "Z24X8", "S8_Z24",
                                    "X8Z24", "Z32F", "Z32F_S8X24", "S8" };
   return n[l];
}

static inline unsigned zs_cpp(enum rast_zs_layout l)
{
   switch (l) {
   case RAST_ZS_Z16: return 2;
   case RAST_ZS_Z32F_S8X24: return 8;
   case RAST_ZS_S8: return 1;
   default: return 4;
   }
}

static inline unsigned zs_bits(enum rast_zs_layout l)    /* unorm bits, 0: float or none */
{
   switch (l) {
   case RAST_ZS_Z16: return 16;
   case RAST_ZS_Z32: return 32;
   case RAST_ZS_Z24_S8: case RAST_ZS_Z24X8: case RAST_ZS_S8_Z24: case RAST_ZS_X8Z24: return 24;
   default: return 0;
   }
}

static inline bool zs_has_z(enum rast_zs_layout l) { return l != RAST_ZS_S8 && l != RAST_ZS_NONE; }
static inline bool zs_is_float(enum rast_zs_layout l) { return l == RAST_ZS_Z32F || l == RAST_ZS_Z32F_S8X24; }
static inline bool zs_has_s(enum rast_zs_layout l)
{
   return l == RAST_ZS_Z24_S8 || l == RAST_ZS_S8_Z24 || l == RAST_ZS_Z32F_S8X24 || l == RAST_ZS_S8;
}

static inline int zs_stride(enum rast_zs_layout l) { return (int)(W * zs_cpp(l) + 8); }
#define ZS_BYTES ((W * 8 + 8) * H)

/* The tests' framebuffer: w x h, colour targets cbufs[0..n), and the
 * depth/stencil buffer zs in `layout` (RAST_ZS_NONE: none). */
static inline void bind_fb(struct rast_context *rc, unsigned w, unsigned h, unsigned n,
                           const struct rast_color_target *cbufs, uint8_t *zs,
                           enum rast_zs_layout layout)
{
   struct rast_framebuffer fb;
   memset(&fb, 0, sizeof fb);
   fb.width = w;
   fb.height = h;
   fb.nr_cbufs = n;
   for (unsigned i = 0; i < n; i++)
      fb.cbuf[i] = cbufs[i];
   fb.zs.base = zs;
   fb.zs.layout = layout;
   fb.zs.stride = layout != RAST_ZS_NONE ? zs_stride(layout) : 0;
   rast_set_framebuffer(rc, &fb);
}

/* Colour 0 written whole, unblended. */
static inline void set_plain_blend(struct rast_context *rc)
{
   struct rast_blend_state bs;
   memset(&bs, 0, sizeof bs);
   bs.rt[0].colormask = 0xf;
   rast_set_blend(rc, &bs);
}

/* Colour 0 under colour mask cm, blended "over" (SRC_ALPHA,
 * INV_SRC_ALPHA) when `blend`. */
static inline struct rast_blend_state over_blend(unsigned cm, bool blend)
{
   struct rast_blend_state bs;
   memset(&bs, 0, sizeof bs);
   bs.rt[0].colormask = (uint8_t)cm;
   bs.rt[0].blend_enable = blend;
   bs.rt[0].rgb_src = bs.rt[0].alpha_src = RAST_BF_SRC_ALPHA;
   bs.rt[0].rgb_dst = bs.rt[0].alpha_dst = RAST_BF_INV_SRC_ALPHA;
   return bs;
}

/* The depth test by func, with depth writes; no stencil. */
static inline void set_depth_test(struct rast_context *rc, enum rast_func func)
{
   struct rast_depth_stencil_state dsa;
   memset(&dsa, 0, sizeof dsa);
   dsa.depth_enabled = dsa.depth_writemask = true;
   dsa.depth_func = func;
   rast_set_depth_stencil(rc, &dsa);
}

/* The test shader on sd (cleared, every pixel kept) with `outputs`
 * outputs, colour 0 to every target with to_all, bound; then the state
 * validated. */
static inline void use_test_shader(struct rast_context *rc, struct shader_data *sd,
                                   unsigned outputs, bool to_all)
{
   memset(sd, 0, sizeof *sd);
   sd->keep = 0xf;
   struct rast_shader fs = make_shader(sd, outputs, false, false, to_all);
   rast_set_shader(rc, &fs);
   rast_validate(rc);
}

/* A quad at a random place of the W x H target, 1 to 4 of its pixels covered. */
static inline struct rast_quad random_quad(void)
{
   struct rast_quad q;
   memset(&q, 0, sizeof q);
   q.x = 2 * (int)rnd(W / 2);
   q.y = 2 * (int)rnd(H / 2);
   q.mask = 1 + rnd(15);
   return q;
}

/* A quad's colours, each channel k/255 for a random k. */
static inline void random_unorm8(float color[4][RAST_QUAD_SIZE])
{
   for (unsigned c = 0; c < 4; c++)
      for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
         color[c][i] = (float)rnd(256) / 255.0f;
}

static inline uint32_t rd32(const uint8_t *p)
{
   return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static inline void wr32(uint8_t *p, uint32_t v)
{
   p[0] = (uint8_t)v; p[1] = (uint8_t)(v >> 8); p[2] = (uint8_t)(v >> 16); p[3] = (uint8_t)(v >> 24);
}

/* Depth as stored: unorm code, or the float's bits. */
static inline uint32_t ref_zget(enum rast_zs_layout l, const uint8_t *buf, int x, int y)
{
   const uint8_t *p = buf + y * zs_stride(l) + x * (int)zs_cpp(l);
   switch (l) {
   case RAST_ZS_Z16: return (uint32_t)p[0] | (uint32_t)p[1] << 8;
   case RAST_ZS_Z24_S8: case RAST_ZS_Z24X8: return rd32(p) % (1u << 24);
   case RAST_ZS_S8_Z24: case RAST_ZS_X8Z24: return rd32(p) / 256u;
   default: return rd32(p);
   }
}

static inline void ref_zput(enum rast_zs_layout l, uint8_t *buf, int x, int y, uint32_t z)
{
   uint8_t *p = buf + y * zs_stride(l) + x * (int)zs_cpp(l);
   switch (l) {
   case RAST_ZS_Z16: p[0] = (uint8_t)z; p[1] = (uint8_t)(z >> 8); break;
   case RAST_ZS_Z24_S8: case RAST_ZS_Z24X8: p[0] = (uint8_t)z; p[1] = (uint8_t)(z >> 8); p[2] = (uint8_t)(z >> 16); break;
   case RAST_ZS_S8_Z24: case RAST_ZS_X8Z24: p[1] = (uint8_t)z; p[2] = (uint8_t)(z >> 8); p[3] = (uint8_t)(z >> 16); break;
   default: wr32(p, z); break;
   }
}

static inline uint8_t *ref_sptr(enum rast_zs_layout l, uint8_t *buf, int x, int y)
{
   uint8_t *p = buf + y * zs_stride(l) + x * (int)zs_cpp(l);
   switch (l) {
   case RAST_ZS_Z24_S8: return p + 3;
   case RAST_ZS_Z32F_S8X24: return p + 4;
   default: return p;
   }
}

static inline float bits_f(uint32_t b) { float f; memcpy(&f, &b, 4); return f; }
static inline uint32_t f_bits(float f) { uint32_t b; memcpy(&b, &f, 4); return b; }

static inline uint64_t ref_full(const struct rast_profile *p)
{
   return (((uint64_t)1 << p->z_bits) - 1) << p->z.frac_bits;
}

/* The rule of backend_zs.c, from its definition: Zc / FULL * (2^N - 1)
 * rounded to nearest (halves up), exactly; float: the quotient rounded once. */
static inline uint32_t ref_zconv_reg(const struct rast_profile *prof, enum rast_zs_layout l, int64_t z)
{
   const uint64_t full = ref_full(prof);
   const uint64_t zc = z < 0 ? 0 : (uint64_t)z > full ? full : (uint64_t)z;
   if (zs_is_float(l))
      return f_bits((float)((long double)zc / (long double)full));
   const u128 m = ((u128)1 << zs_bits(l)) - 1;
   return (uint32_t)((2 * (u128)zc * m + full) / (2 * (u128)full));
}

static inline uint32_t ref_zconv_shader(enum rast_zs_layout l, float d)
{
   if (!(d > 0.0f))
      d = 0.0f;
   if (d > 1.0f)
      d = 1.0f;
   if (zs_is_float(l))
      return f_bits(d);
   const long double m = (long double)((((uint64_t)1) << zs_bits(l)) - 1);
   return (uint32_t)floorl((long double)d * m + 0.5L);
}

static inline bool ref_cmp(enum rast_func f, double a, double b)
{
   switch (f) {
   case RAST_FUNC_NEVER: return false;
   case RAST_FUNC_LESS: return a < b;
   case RAST_FUNC_EQUAL: return a == b;
   case RAST_FUNC_LEQUAL: return a <= b;
   case RAST_FUNC_GREATER: return a > b;
   case RAST_FUNC_NOTEQUAL: return a != b;
   case RAST_FUNC_GEQUAL: return a >= b;
   case RAST_FUNC_ALWAYS: return true;
   }
   return false;
}

static inline unsigned ref_sop(enum rast_stencil_op op, unsigned s, unsigned ref)
{
   switch (op) {
   case RAST_STENCIL_KEEP: return s;
   case RAST_STENCIL_ZERO: return 0;
   case RAST_STENCIL_REPLACE: return ref;
   case RAST_STENCIL_INCR: return s < 255 ? s + 1 : 255;
   case RAST_STENCIL_DECR: return s > 0 ? s - 1 : 0;
   case RAST_STENCIL_INCR_WRAP: return (s + 1) % 256;
   case RAST_STENCIL_DECR_WRAP: return (s + 255) % 256;
   case RAST_STENCIL_INVERT: return 255 - s;
   }
   return s;
}

struct zs_setup {
   const struct rast_profile *prof;
   enum rast_zs_layout layout;
   struct rast_depth_stencil_state dsa;
   uint8_t ref[2];
   bool writes_depth, may_discard;
   unsigned ncolor;          /* 0: no colour buffer (depth-only pass) */
};

/* GL ES for one fragment; returns whether it reaches the colour buffer. */
static inline bool ref_fragment(const struct zs_setup *s, uint8_t *zsbuf, int x, int y,
                         uint32_t zfrag, bool front)
{
   const enum rast_zs_layout l = s->layout;
   const bool stest = s->dsa.stencil[0].enabled && zs_has_s(l);
   const bool ztest = s->dsa.depth_enabled && zs_has_z(l);
   const unsigned face = (!front && s->dsa.stencil[1].enabled) ? 1 : 0;
   const struct rast_stencil_face *sf = &s->dsa.stencil[face];
   bool spass = true, zpass = true;
   unsigned sv = 0;

   if (stest) {
      sv = *ref_sptr(l, zsbuf, x, y);
      spass = ref_cmp(sf->func, s->ref[face] & sf->valuemask, sv & sf->valuemask);
   }
   if (spass && ztest) {
      uint32_t zb = ref_zget(l, zsbuf, x, y);
      zpass = zs_is_float(l) ? ref_cmp(s->dsa.depth_func, bits_f(zfrag), bits_f(zb))
                             : ref_cmp(s->dsa.depth_func, zfrag, zb);
   }
   if (stest) {
      unsigned n = ref_sop(!spass ? sf->fail_op : !zpass ? sf->zfail_op : sf->zpass_op,
                           sv, s->ref[face]);
      n = (sv & ~(unsigned)sf->writemask) | (n & sf->writemask);
      *ref_sptr(l, zsbuf, x, y) = (uint8_t)n;
   }
   if (spass && zpass && ztest && s->dsa.depth_writemask)
      ref_zput(l, zsbuf, x, y, zfrag);
   return spass && zpass;
}

/* ------------------------------------------------------------------ */
/* Random depth/stencil runs: the back end against ref_fragment.        */

struct zs_run_result {
   uint64_t samples, shaded;
   unsigned calls;
   rast_quad_func quad;
};

static inline void fill_zs(const struct zs_setup *s, uint8_t *buf, const int64_t *zpool,
                    const float *dpool)
{
   for (unsigned i = 0; i < ZS_BYTES; i++)
      buf[i] = (uint8_t)rnd64();
   if (!zs_has_z(s->layout))
      return;
   for (int y = 0; y < H; y++)
      for (int x = 0; x < W; x++) {
         uint32_t z = s->writes_depth ? ref_zconv_shader(s->layout, dpool[rnd(8)])
                                      : ref_zconv_reg(s->prof, s->layout, zpool[rnd(8)]);
         ref_zput(s->layout, buf, x, y, z);
      }
}

struct quad_script {
   struct rast_quad q;
   float depth[4];
   float color[4][4];
   unsigned keep;
};

static inline void make_script(struct quad_script *qs, unsigned n, const int64_t *zpool,
                        const float *dpool, bool discard)
{
   for (unsigned k = 0; k < n; k++) {
      struct quad_script *s = &qs[k];
      memset(s, 0, sizeof *s);
      s->q = random_quad();
      s->q.front_facing = rnd(2);
      for (unsigned i = 0; i < 4; i++) {
         s->q.z[i] = rnd(8) ? zpool[rnd(8)] : (int64_t)(rnd64() % (1u << 31));
         s->depth[i] = dpool[rnd(8)];
         for (unsigned c = 0; c < 4; c++)
            s->color[c][i] = (float)rnd(256) / 255.0f;
      }
      s->keep = discard ? rnd(16) : 0xf;
   }
}

/* Runs the script through the back end; buffers are updated in place. */
static inline struct zs_run_result run_backend(const struct zs_setup *s, uint8_t *zsbuf, uint8_t *cbuf,
                                        const struct quad_script *qs, unsigned n)
{
   struct rast_context *rc = rast_create(s->prof);
   struct shader_data sd;
   memset(&sd, 0, sizeof sd);

   const struct rast_color_target t0 = make_cbuf(TF_RGBA8, s->ncolor ? cbuf : NULL);
   bind_fb(rc, W, H, 1, &t0, zsbuf, s->layout);
   set_plain_blend(rc);
   rast_set_depth_stencil(rc, &s->dsa);
   rast_set_stencil_ref(rc, s->ref[0], s->ref[1]);
   struct rast_shader fs = make_shader(&sd, 1, s->writes_depth, s->may_discard, false);
   rast_set_shader(rc, &fs);
   rast_validate(rc);

   for (unsigned k = 0; k < n; k++) {
      struct rast_quad q = qs[k].q;
      memcpy(sd.depth, qs[k].depth, sizeof sd.depth);
      memcpy(sd.color[0], qs[k].color, sizeof qs[k].color);
      sd.keep = qs[k].keep;
      rc->quad(rc, &q);
      CHECK(q.mask == qs[k].q.mask && q.x == qs[k].q.x, "quad %u modified by the back end", k);
   }
   struct zs_run_result r;
   r.samples = rast_get_stats(rc)->samples_passed;
   r.shaded = rast_get_stats(rc)->pixels_shaded;
   r.calls = sd.calls;
   r.quad = rc->quad;
   CHECK(r.shaded == sd.pixels, "pixels_shaded %llu, shader saw %u",
         (unsigned long long)r.shaded, sd.pixels);
   CHECK(sd.empty_calls == 0, "%u shader calls on quads with no live pixel", sd.empty_calls);
   rast_destroy(rc);
   return r;
}

static inline uint64_t run_reference(const struct zs_setup *s, uint8_t *zsbuf, uint8_t *cbuf,
                              const struct quad_script *qs, unsigned n)
{
   const int stride = (int)(W * 4 + 12);
   uint64_t samples = 0;
   for (unsigned k = 0; k < n; k++) {
      const struct quad_script *sc = &qs[k];
      for (unsigned i = 0; i < 4; i++) {
         if (!(sc->q.mask & (1u << i)) || !(sc->keep & (1u << i)))
            continue;
         const int x = sc->q.x + (int)(i & 1), y = sc->q.y + (int)(i >> 1);
         uint32_t zf = s->writes_depth ? ref_zconv_shader(s->layout, sc->depth[i])
                                       : ref_zconv_reg(s->prof, s->layout, sc->q.z[i]);
         if (!ref_fragment(s, zsbuf, x, y, zf, sc->q.front_facing))
            continue;
         samples++;
         if (s->ncolor)
            for (unsigned c = 0; c < 4; c++)
               cbuf[y * stride + x * 4 + (int)c] = ref_ubyte(sc->color[c][i]);
      }
   }
   return samples;
}

static inline void make_pools(const struct rast_profile *prof, int64_t *zpool, float *dpool)
{
   const int64_t full = (int64_t)ref_full(prof);
   zpool[0] = 0;
   zpool[1] = full;
   zpool[2] = -5000;                 /* below 0: clamps */
   zpool[3] = full + 77777;          /* beyond full scale: clamps */
   for (unsigned i = 4; i < 8; i++)
      zpool[i] = (int64_t)(rnd64() % (uint64_t)(full + 1));
   dpool[0] = 0.0f;
   dpool[1] = 1.0f;
   dpool[2] = -0.25f;
   dpool[3] = 1.5f;
   dpool[4] = NAN;
   for (unsigned i = 5; i < 8; i++)
      dpool[i] = rndf(0.0f, 1.0f);
}

/* One random state on one layout: back end and reference from the same
 * buffers and script must leave the same bytes and counts. */
static inline void zs_compare(struct zs_setup *s, unsigned nquads, const char *what)
{
   static uint8_t zs_a[ZS_BYTES], zs_b[ZS_BYTES], c_a[CBUF_BYTES], c_b[CBUF_BYTES];
   static struct quad_script qs[256];
   int64_t zpool[8];
   float dpool[8];

   if (nquads > 256)
      nquads = 256;
   make_pools(s->prof, zpool, dpool);
   fill_zs(s, zs_a, zpool, dpool);
   memcpy(zs_b, zs_a, sizeof zs_a);
   for (unsigned i = 0; i < CBUF_BYTES; i++)
      c_a[i] = c_b[i] = (uint8_t)rnd64();
   make_script(qs, nquads, zpool, dpool, s->may_discard);

   struct zs_run_result r = run_backend(s, zs_a, c_a, qs, nquads);
   uint64_t samples = run_reference(s, zs_b, c_b, qs, nquads);

   unsigned bad = 0, first = 0;
   for (unsigned i = 0; i < ZS_BYTES; i++)
      if (zs_a[i] != zs_b[i] && !bad++)
         first = i;
   CHECK(bad == 0, "%s: %s %s func %d: %u zs bytes differ, first at %u (got %02x want %02x)",
         what, s->prof->name, zs_name(s->layout), s->dsa.depth_func, bad, first,
         zs_a[first], zs_b[first]);
   bad = 0;
   for (unsigned i = 0; i < CBUF_BYTES; i++)
      if (c_a[i] != c_b[i] && !bad++)
         first = i;
   CHECK(bad == 0, "%s: %s %s: %u colour bytes differ, first at %u", what, s->prof->name,
         zs_name(s->layout), bad, first);
   CHECK(r.samples == samples, "%s: %s %s: samples_passed %llu want %llu", what,
         s->prof->name, zs_name(s->layout), (unsigned long long)r.samples,
         (unsigned long long)samples);
}

static inline void random_face(struct rast_stencil_face *f)
{
   f->enabled = true;
   f->func = (enum rast_func)rnd(8);
   f->fail_op = (enum rast_stencil_op)rnd(8);
   f->zfail_op = (enum rast_stencil_op)rnd(8);
   f->zpass_op = (enum rast_stencil_op)rnd(8);
   f->valuemask = rnd(3) ? (uint8_t)rnd64() : 0xff;
   f->writemask = rnd(3) ? (uint8_t)rnd64() : 0xff;
}

/* ------------------------------------------------------------------ */
/* Blend.                                                               */

static inline double clampd(double v) { return v < 0 ? 0 : v > 1 ? 1 : v; }
static inline double clamp_snorm(double v) { return v < -1 ? -1 : v > 1 ? 1 : v; }
/* What a target of format f clamps blend inputs and results to. */
static inline double clamp_fmt(enum tfmt f, double v)
{
   return f == TF_F32 ? v : f == TF_F32_SNORM ? clamp_snorm(v) : clampd(v);
}

static inline double ref_factor(enum rast_blend_factor f, unsigned c, const double s[4],
                         const double s1[4], const double d[4], const double k[4])
{
   switch (f) {
   case RAST_BF_ZERO: return 0;
   case RAST_BF_ONE: return 1;
   case RAST_BF_SRC_COLOR: return s[c];
   case RAST_BF_INV_SRC_COLOR: return 1 - s[c];
   case RAST_BF_SRC_ALPHA: return s[3];
   case RAST_BF_INV_SRC_ALPHA: return 1 - s[3];
   case RAST_BF_DST_COLOR: return d[c];
   case RAST_BF_INV_DST_COLOR: return 1 - d[c];
   case RAST_BF_DST_ALPHA: return d[3];
   case RAST_BF_INV_DST_ALPHA: return 1 - d[3];
   case RAST_BF_CONST_COLOR: return k[c];
   case RAST_BF_INV_CONST_COLOR: return 1 - k[c];
   case RAST_BF_CONST_ALPHA: return k[3];
   case RAST_BF_INV_CONST_ALPHA: return 1 - k[3];
   case RAST_BF_SRC_ALPHA_SATURATE: return c == 3 ? 1 : fmin(s[3], 1 - d[3]);
   case RAST_BF_SRC1_COLOR: return s1[c];
   case RAST_BF_INV_SRC1_COLOR: return 1 - s1[c];
   case RAST_BF_SRC1_ALPHA: return s1[3];
   case RAST_BF_INV_SRC1_ALPHA: return 1 - s1[3];
   }
   return NAN;
}

static inline double ref_blend(const struct rast_blend_target *bt, unsigned c, const double s[4],
                        const double s1[4], const double d[4], const double k[4])
{
   const bool a = c == 3;
   const enum rast_blend_eq eq = a ? bt->alpha_eq : bt->rgb_eq;
   const double sf = ref_factor(a ? bt->alpha_src : bt->rgb_src, c, s, s1, d, k);
   const double df = ref_factor(a ? bt->alpha_dst : bt->rgb_dst, c, s, s1, d, k);
   switch (eq) {
   case RAST_BLEND_ADD: return s[c] * sf + d[c] * df;
   case RAST_BLEND_SUBTRACT: return s[c] * sf - d[c] * df;
   case RAST_BLEND_REVERSE_SUBTRACT: return d[c] * df - s[c] * sf;
   case RAST_BLEND_MIN: return fmin(s[c], d[c]);
   case RAST_BLEND_MAX: return fmax(s[c], d[c]);
   }
   return NAN;
}

struct color_ctx {
   struct rast_context *rc;
   struct shader_data sd;
   uint8_t mem[RAST_MAX_CBUFS][CBUF_BYTES];
   struct rast_color_target t[RAST_MAX_CBUFS];
};

/* A context of the profile named `prof` drawing into cc's target 0, t0
 * (W x H, no depth/stencil buffer). */
static inline struct rast_context *color_context(struct color_ctx *cc, const char *prof,
                                                 struct rast_color_target t0)
{
   struct rast_context *rc = rast_create(profile_named(prof));
   cc->t[0] = t0;
   bind_fb(rc, W, H, 1, cc->t, NULL, RAST_ZS_NONE);
   return rc;
}

/* Pixel i of quad q on target t: where it is, its bytes now (in mem) and
 * before the draw (in old). */
struct quad_px {
   int x, y;
   const uint8_t *now, *was;
};

static inline struct quad_px quad_pixel(const struct rast_quad *q, unsigned i,
                                        const struct rast_color_target *t, const uint8_t *mem,
                                        const uint8_t *old)
{
   struct quad_px p;
   p.x = q->x + (int)(i & 1);
   p.y = q->y + (int)(i >> 1);
   p.now = cb_pixel(t, mem, p.x, p.y);
   p.was = cb_pixel(t, old, p.x, p.y);
   return p;
}

/* Whether q covers its pixel i, p; one it does not cover must have kept
 * its bytes. */
static inline bool quad_covers(const struct rast_quad *q, unsigned i, struct quad_px p,
                               unsigned cpp, const char *what)
{
   if (q->mask & (1u << i))
      return true;
   CHECK(memcmp(p.now, p.was, cpp) == 0, "%s: pixel (%d, %d) not covered, yet written", what,
         p.x, p.y);
   return false;
}

static inline void color_fill_random(struct color_ctx *cc, unsigned i, enum tfmt f)
{
   if (is8(f)) {
      for (unsigned b = 0; b < CBUF_BYTES; b++)
         cc->mem[i][b] = (uint8_t)rnd64();
   } else {
      for (unsigned b = 0; b + 4 <= CBUF_BYTES; b += 4) {
         float v = rndf(f == TF_F32_SNORM ? -1.5f : -0.5f, 1.5f);
         memcpy(&cc->mem[i][b], &v, 4);
      }
   }
}

/* Target i of cc filled as color_fill_random does, and copied into old. */
static inline void color_fill_keep(struct color_ctx *cc, unsigned i, enum tfmt f, uint8_t *old)
{
   color_fill_random(cc, i, f);
   memcpy(old, cc->mem[i], CBUF_BYTES);
}

/* Expected channel c after writing `res` (float) into format f. */
static inline bool chan_ok(enum tfmt f, unsigned c, float got, double want)
{
   if (f == TF_BGRX8 && c == 3)
      return got == 255;
   if (is8(f)) {
      const double w = clampd(want) * 255.0;
      return fabs(got - w) <= 1.0;    /* 1/255 after rounding */
   }
   want = clamp_fmt(f, want);
   return fabs(got - want) <= 1e-5 + 1e-5 * fabs(want);
}

static inline double dst_value(enum tfmt f, float raw, unsigned c)
{
   if (f == TF_BGRX8 && c == 3)
      return 1.0;
   if (is8(f))
      return raw / 255.0;
   return clamp_fmt(f, raw);
}

/* The seed (FIXPIPE_TEST_SEED, default fixed), printed by each program. */
static inline void backend_seed(const char *name)
{
   const char *seed = getenv("FIXPIPE_TEST_SEED");
   if (seed)
      rng_state = strtoull(seed, NULL, 0) | 1;
   printf("%s: seed 0x%llx\n", name, (unsigned long long)rng_state);
}

static inline int backend_summary(void)
{
   printf("%u checks, %u failures\n", checks, failures);
   return failures ? 1 : 0;
}

#endif
