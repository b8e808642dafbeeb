/*
 * Unit tests of the fragment back end (src/rast/backend*.c), through the
 * public API: rast_create + rast_set_* + rast_validate, then rc->quad on
 * hand-made quads.  Results are checked against a straightforward per-pixel
 * reference written here (GL ES semantics, switch per pixel, exact
 * arithmetic), which shares no code with the back end.
 *
 * Seed of the random quads: FIXPIPE_TEST_SEED (default fixed), printed.
 */
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

static uint64_t rnd64(void)
{
   uint64_t x = rng_state;
   x ^= x << 13; x ^= x >> 7; x ^= x << 17;
   return rng_state = x;
}

static unsigned rnd(unsigned n) { return (unsigned)(rnd64() % n); }
static float rndf(float lo, float hi) { return lo + (hi - lo) * (float)(rnd64() >> 40) / (float)(1 << 24); }

static unsigned popc(unsigned m) { return (unsigned)__builtin_popcount(m); }

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

static unsigned test_shade(void *ctx, const struct rast_quad *q, struct rast_shaded_quad *out)
{
   struct shader_data *sd = ctx;
   sd->calls++;
   sd->pixels += popc(q->mask);
   sd->empty_calls += q->mask == 0;
   memcpy(out->color, sd->color, sizeof sd->color);
   memcpy(out->depth, sd->depth, sizeof sd->depth);
   return q->mask & sd->keep;
}

static struct rast_shader make_shader(struct shader_data *sd, unsigned outputs, bool writes_depth,
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

static void f32_load(const uint8_t *src, unsigned n, float (*rgba)[4])
{
   memcpy(rgba, src, n * 16);
}

static void f32_store(uint8_t *dst, unsigned n, const float (*rgba)[4])
{
   memcpy(dst, rgba, n * 16);
}

static uint8_t ref_ubyte(double v)
{
   if (!(v > 0.0))
      return 0;
   if (v >= 1.0)
      return 255;
   return (uint8_t)lrint(v * 255.0);
}

/* RGBA8 again, through the generic path. */
static void u8_load(const uint8_t *src, unsigned n, float (*rgba)[4])
{
   for (unsigned i = 0; i < n; i++)
      for (unsigned c = 0; c < 4; c++)
         rgba[i][c] = src[4 * i + c] / 255.0f;
}

static void u8_store(uint8_t *dst, unsigned n, const float (*rgba)[4])
{
   for (unsigned i = 0; i < n; i++)
      for (unsigned c = 0; c < 4; c++)
         dst[4 * i + c] = ref_ubyte(rgba[i][c]);
}

enum tfmt { TF_RGBA8, TF_BGRA8, TF_BGRX8, TF_F32, TF_F32_CLAMP, TF_GEN8, TF_COUNT };
static const char *const tfmt_name[TF_COUNT] = {
   "RGBA8", "BGRA8", "BGRX8", "F32(generic)", "F32-clamp(generic)", "RGBA8(generic)"
};

static unsigned tfmt_cpp(enum tfmt f) { return f == TF_F32 || f == TF_F32_CLAMP ? 16 : 4; }

static struct rast_color_target make_cbuf(enum tfmt f, uint8_t *mem)
{
   struct rast_color_target t;
   memset(&t, 0, sizeof t);
   t.base = mem;
   t.cpp = tfmt_cpp(f);
   t.stride = (int)(W * t.cpp + 12);     /* padding catches stride mistakes */
   t.load = f == TF_F32 || f == TF_F32_CLAMP ? f32_load : u8_load;
   t.store = f == TF_F32 || f == TF_F32_CLAMP ? f32_store : u8_store;
   t.clamp = f != TF_F32;
   t.layout = f == TF_RGBA8 ? RAST_CL_RGBA8 : f == TF_BGRA8 ? RAST_CL_BGRA8 :
              f == TF_BGRX8 ? RAST_CL_BGRX8 : RAST_CL_GENERIC;
   return t;
}

#define CBUF_BYTES ((W * 16 + 12) * H)

/* Channel c of pixel (x, y) as the format stores it. */
static float cb_get(enum tfmt f, const struct rast_color_target *t, const uint8_t *mem,
                    int x, int y, unsigned c)
{
   const uint8_t *p = mem + y * t->stride + x * (int)t->cpp;
   float v;
   switch (f) {
   case TF_F32: case TF_F32_CLAMP: memcpy(&v, p + 4 * c, 4); return v;
   case TF_BGRA8: case TF_BGRX8: return p[c == 3 ? 3 : 2 - c];
   default: return p[c];
   }
}

static bool is8(enum tfmt f) { return f != TF_F32 && f != TF_F32_CLAMP; }

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

static unsigned zs_cpp(enum rast_zs_layout l)
{
   switch (l) {
   case RAST_ZS_Z16: return 2;
   case RAST_ZS_Z32F_S8X24: return 8;
   case RAST_ZS_S8: return 1;
   default: return 4;
   }
}

static unsigned zs_bits(enum rast_zs_layout l)    /* unorm bits, 0: float or none */
{
   switch (l) {
   case RAST_ZS_Z16: return 16;
   case RAST_ZS_Z32: return 32;
   case RAST_ZS_Z24_S8: case RAST_ZS_Z24X8: case RAST_ZS_S8_Z24: case RAST_ZS_X8Z24: return 24;
   default: return 0;
   }
}

static bool zs_has_z(enum rast_zs_layout l) { return l != RAST_ZS_S8 && l != RAST_ZS_NONE; }
static bool zs_is_float(enum rast_zs_layout l) { return l == RAST_ZS_Z32F || l == RAST_ZS_Z32F_S8X24; }
static bool zs_has_s(enum rast_zs_layout l)
{
   return l == RAST_ZS_Z24_S8 || l == RAST_ZS_S8_Z24 || l == RAST_ZS_Z32F_S8X24 || l == RAST_ZS_S8;
}

static int zs_stride(enum rast_zs_layout l) { return (int)(W * zs_cpp(l) + 8); }
#define ZS_BYTES ((W * 8 + 8) * H)

static uint32_t rd32(const uint8_t *p)
{
   return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static void wr32(uint8_t *p, uint32_t v)
{
   p[0] = (uint8_t)v; p[1] = (uint8_t)(v >> 8); p[2] = (uint8_t)(v >> 16); p[3] = (uint8_t)(v >> 24);
}

/* Depth as stored: unorm code, or the float's bits. */
static uint32_t ref_zget(enum rast_zs_layout l, const uint8_t *buf, int x, int y)
{
   const uint8_t *p = buf + y * zs_stride(l) + x * (int)zs_cpp(l);
   switch (l) {
   case RAST_ZS_Z16: return (uint32_t)p[0] | (uint32_t)p[1] << 8;
   case RAST_ZS_Z24_S8: case RAST_ZS_Z24X8: return rd32(p) % (1u << 24);
   case RAST_ZS_S8_Z24: case RAST_ZS_X8Z24: return rd32(p) / 256u;
   default: return rd32(p);
   }
}

static void ref_zput(enum rast_zs_layout l, uint8_t *buf, int x, int y, uint32_t z)
{
   uint8_t *p = buf + y * zs_stride(l) + x * (int)zs_cpp(l);
   switch (l) {
   case RAST_ZS_Z16: p[0] = (uint8_t)z; p[1] = (uint8_t)(z >> 8); break;
   case RAST_ZS_Z24_S8: case RAST_ZS_Z24X8: p[0] = (uint8_t)z; p[1] = (uint8_t)(z >> 8); p[2] = (uint8_t)(z >> 16); break;
   case RAST_ZS_S8_Z24: case RAST_ZS_X8Z24: p[1] = (uint8_t)z; p[2] = (uint8_t)(z >> 8); p[3] = (uint8_t)(z >> 16); break;
   default: wr32(p, z); break;
   }
}

static uint8_t *ref_sptr(enum rast_zs_layout l, uint8_t *buf, int x, int y)
{
   uint8_t *p = buf + y * zs_stride(l) + x * (int)zs_cpp(l);
   switch (l) {
   case RAST_ZS_Z24_S8: return p + 3;
   case RAST_ZS_Z32F_S8X24: return p + 4;
   default: return p;
   }
}

static float bits_f(uint32_t b) { float f; memcpy(&f, &b, 4); return f; }
static uint32_t f_bits(float f) { uint32_t b; memcpy(&b, &f, 4); return b; }

static uint64_t ref_full(const struct rast_profile *p)
{
   return (((uint64_t)1 << p->z_bits) - 1) << p->z.frac_bits;
}

/* The rule of backend_zs.c, from its definition: Zc / FULL * (2^N - 1)
 * rounded to nearest (halves up), exactly; float: the quotient rounded once. */
static uint32_t ref_zconv_reg(const struct rast_profile *prof, enum rast_zs_layout l, int64_t z)
{
   const uint64_t full = ref_full(prof);
   const uint64_t zc = z < 0 ? 0 : (uint64_t)z > full ? full : (uint64_t)z;
   if (zs_is_float(l))
      return f_bits((float)((long double)zc / (long double)full));
   const u128 m = ((u128)1 << zs_bits(l)) - 1;
   return (uint32_t)((2 * (u128)zc * m + full) / (2 * (u128)full));
}

static uint32_t ref_zconv_shader(enum rast_zs_layout l, float d)
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

static bool ref_cmp(enum rast_func f, double a, double b)
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

static unsigned ref_sop(enum rast_stencil_op op, unsigned s, unsigned ref)
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
static bool ref_fragment(const struct zs_setup *s, uint8_t *zsbuf, int x, int y,
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

static void fill_zs(const struct zs_setup *s, uint8_t *buf, const int64_t *zpool,
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

static void make_script(struct quad_script *qs, unsigned n, const int64_t *zpool,
                        const float *dpool, bool discard)
{
   for (unsigned k = 0; k < n; k++) {
      struct quad_script *s = &qs[k];
      memset(s, 0, sizeof *s);
      s->q.x = 2 * (int)rnd(W / 2);
      s->q.y = 2 * (int)rnd(H / 2);
      s->q.mask = 1 + rnd(15);
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
static struct zs_run_result run_backend(const struct zs_setup *s, uint8_t *zsbuf, uint8_t *cbuf,
                                        const struct quad_script *qs, unsigned n)
{
   struct rast_context *rc = rast_create(s->prof);
   struct shader_data sd;
   memset(&sd, 0, sizeof sd);

   struct rast_framebuffer fb;
   memset(&fb, 0, sizeof fb);
   fb.width = W;
   fb.height = H;
   fb.nr_cbufs = 1;
   fb.cbuf[0] = make_cbuf(TF_RGBA8, s->ncolor ? cbuf : NULL);
   fb.zs.base = zsbuf;
   fb.zs.layout = s->layout;
   fb.zs.stride = zs_stride(s->layout);
   rast_set_framebuffer(rc, &fb);

   struct rast_blend_state bs;
   memset(&bs, 0, sizeof bs);
   bs.rt[0].colormask = 0xf;
   rast_set_blend(rc, &bs);
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

static uint64_t run_reference(const struct zs_setup *s, uint8_t *zsbuf, uint8_t *cbuf,
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

static void make_pools(const struct rast_profile *prof, int64_t *zpool, float *dpool)
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
static void zs_compare(struct zs_setup *s, unsigned nquads, const char *what)
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

static void random_face(struct rast_stencil_face *f)
{
   f->enabled = true;
   f->func = (enum rast_func)rnd(8);
   f->fail_op = (enum rast_stencil_op)rnd(8);
   f->zfail_op = (enum rast_stencil_op)rnd(8);
   f->zpass_op = (enum rast_stencil_op)rnd(8);
   f->valuemask = rnd(3) ? (uint8_t)rnd64() : 0xff;
   f->writemask = rnd(3) ? (uint8_t)rnd64() : 0xff;
}

/* Every depth func on every Z layout, with and without writes, from the
 * rasterizer's Z and from the shader's. */
static void test_depth_funcs(void)
{
   const char *profs[] = { "seed", "wide" };
   unsigned before = failures;
   for (unsigned p = 0; p < 2; p++)
      for (unsigned li = 0; li < N_ZS_LAYOUTS; li++)
         for (unsigned f = 0; f < 8; f++)
            for (unsigned wr = 0; wr < 2; wr++)
               for (unsigned sh = 0; sh < 2; sh++) {
                  struct zs_setup s;
                  memset(&s, 0, sizeof s);
                  s.prof = profile_named(profs[p]);
                  s.layout = zs_layouts[li];
                  s.dsa.depth_enabled = true;
                  s.dsa.depth_func = (enum rast_func)f;
                  s.dsa.depth_writemask = wr;
                  s.writes_depth = sh;
                  s.ncolor = 1;
                  zs_compare(&s, 200, sh ? "depth func, shader depth" : "depth func");
               }
   printf("depth funcs x layouts x profiles: %s\n", failures == before ? "ok" : "FAILED");
}

/* Stencil: random faces, two-sided or not, with and without depth. */
static void test_stencil(void)
{
   const char *profs[] = { "seed", "wide" };
   unsigned before = failures;
   for (unsigned it = 0; it < 400; it++) {
      struct zs_setup s;
      memset(&s, 0, sizeof s);
      s.prof = profile_named(profs[it & 1]);
      static const enum rast_zs_layout sl[] = { RAST_ZS_Z24_S8, RAST_ZS_S8_Z24,
                                                RAST_ZS_Z32F_S8X24, RAST_ZS_S8, RAST_ZS_Z16 };
      s.layout = sl[rnd(5)];
      random_face(&s.dsa.stencil[0]);
      random_face(&s.dsa.stencil[1]);
      s.dsa.stencil[1].enabled = rnd(2);
      s.dsa.depth_enabled = rnd(2);
      s.dsa.depth_func = (enum rast_func)rnd(8);
      s.dsa.depth_writemask = rnd(2);
      s.ref[0] = (uint8_t)rnd64();
      s.ref[1] = (uint8_t)rnd64();
      s.ref[0] = rnd(4) ? s.ref[0] : 0;
      s.writes_depth = rnd(4) == 0;
      s.may_discard = rnd(4) == 0;
      s.ncolor = rnd(4) ? 1 : 0;
      zs_compare(&s, 256, "stencil random");
   }
   printf("stencil random states: %s\n", failures == before ? "ok" : "FAILED");
}

/* Hand-computed stencil cases, independent of ref_sop. */
static void test_stencil_ops_fixed(void)
{
   struct { enum rast_stencil_op op; uint8_t before, ref, wmask, after; } t[] = {
      { RAST_STENCIL_INCR_WRAP, 255, 0, 0xff, 0 },
      { RAST_STENCIL_DECR_WRAP, 0, 0, 0xff, 255 },
      { RAST_STENCIL_INCR, 255, 0, 0xff, 255 },
      { RAST_STENCIL_DECR, 0, 0, 0xff, 0 },
      { RAST_STENCIL_INCR, 7, 0, 0xff, 8 },
      { RAST_STENCIL_INVERT, 0x5a, 0, 0x0f, 0x55 },
      { RAST_STENCIL_REPLACE, 0x12, 0xab, 0xf0, 0xa2 },
      { RAST_STENCIL_ZERO, 0xff, 0, 0x3c, 0xc3 },
      { RAST_STENCIL_KEEP, 0x42, 0x99, 0xff, 0x42 },
      { RAST_STENCIL_INCR_WRAP, 0x0f, 0, 0x0f, 0x00 },   /* 0x10 masked to the low nibble */
   };
   const struct rast_profile *prof = profile_named("seed");
   unsigned before = failures;

   for (unsigned k = 0; k < sizeof t / sizeof t[0]; k++)
      for (unsigned back = 0; back < 2; back++) {
         static uint8_t zs[ZS_BYTES], cb[CBUF_BYTES];
         memset(zs, 0, sizeof zs);
         struct rast_context *rc = rast_create(prof);
         struct shader_data sd;
         memset(&sd, 0, sizeof sd);
         sd.keep = 0xf;
         struct rast_framebuffer fb;
         memset(&fb, 0, sizeof fb);
         fb.width = W; fb.height = H; fb.nr_cbufs = 1;
         fb.cbuf[0] = make_cbuf(TF_RGBA8, cb);
         fb.zs.base = zs; fb.zs.layout = RAST_ZS_Z24_S8; fb.zs.stride = zs_stride(RAST_ZS_Z24_S8);
         rast_set_framebuffer(rc, &fb);
         struct rast_blend_state bs;
         memset(&bs, 0, sizeof bs);
         bs.rt[0].colormask = 0xf;
         rast_set_blend(rc, &bs);
         struct rast_depth_stencil_state dsa;
         memset(&dsa, 0, sizeof dsa);
         /* The face under test passes (ALWAYS) and runs the op; the other
          * face would fail and zero the value. */
         struct rast_stencil_face live = { true, RAST_FUNC_ALWAYS, RAST_STENCIL_ZERO,
                                           RAST_STENCIL_ZERO, t[k].op, 0xff, t[k].wmask };
         struct rast_stencil_face other = { true, RAST_FUNC_NEVER, RAST_STENCIL_ZERO,
                                            RAST_STENCIL_ZERO, RAST_STENCIL_ZERO, 0xff, 0xff };
         dsa.stencil[0] = back ? other : live;
         dsa.stencil[1] = back ? live : other;
         rast_set_depth_stencil(rc, &dsa);
         rast_set_stencil_ref(rc, back ? 0 : t[k].ref, back ? t[k].ref : 0);
         struct rast_shader fs = make_shader(&sd, 1, false, false, false);
         rast_set_shader(rc, &fs);
         rast_validate(rc);

         zs[3] = t[k].before;                       /* pixel (0,0), bits 24..31 */
         zs[0] = 0x11; zs[1] = 0x22; zs[2] = 0x33;  /* depth bits must survive */
         struct rast_quad q;
         memset(&q, 0, sizeof q);
         q.mask = 1;
         q.front_facing = !back;
         rc->quad(rc, &q);
         CHECK(zs[3] == t[k].after, "op %d on %s face: %u -> %u, want %u", t[k].op,
               back ? "back" : "front", t[k].before, zs[3], t[k].after);
         CHECK(zs[0] == 0x11 && zs[1] == 0x22 && zs[2] == 0x33, "stencil write touched depth");
         CHECK(rast_get_stats(rc)->samples_passed == 1, "ALWAYS stencil passes");
         rast_destroy(rc);
      }
   printf("stencil ops (fixed cases, both faces): %s\n", failures == before ? "ok" : "FAILED");
}

/* The rule's division as a multiply (rast_zdiv, the default path) against
 * the division, on every Z register width and fraction the profiles can
 * have and every unorm depth: the ends, and random registers. */
static void test_depth_conversion_mul(void)
{
   unsigned before = failures, exact = 0;
   for (unsigned zb = 8; zb <= 32; zb++)
      for (unsigned f = 0; f <= 16; f += 4)
         for (unsigned nb = 16; nb <= 32; nb += 8) {
            const uint64_t full = ((UINT64_C(1) << zb) - 1) << f;
            const uint64_t max = (UINT64_C(1) << nb) - 1;
            struct rast_zdiv d;
            if (!rast_zdiv_init(&d, full, max)) {
               if (full <= UINT64_MAX / (2 * max + 1))   /* the numerator fits 64 bits */
                  CHECK(0, "zdiv: no multiply for z_bits %u, frac %u, unorm%u", zb, f, nb);
               continue;
            }
            exact++;
            for (unsigned i = 0; i < 20000; i++) {
               const uint64_t z = i == 0 ? 0 : i == 1 ? full : i == 2 ? full - 1 : i == 3 ? 1
                                : i == 4 ? full / 2 : rnd64() % (full + 1);
               const uint32_t want = rast_z_to_unorm(z, full, max);
               const uint32_t got = rast_zdiv_to_unorm(&d, z, full, max);
               if (got != want) {
                  CHECK(0, "zdiv: z_bits %u frac %u unorm%u, z %llu: %u, want %u", zb, f, nb,
                       (unsigned long long)z, got, want);
                  break;
               }
            }
         }
   printf("depth conversion by multiply: %u formats, %s\n", exact,
          failures == before ? "same as the division" : "FAILED");
}

/* A group's kept pixels counted for the occlusion queries: every mask. */
static void test_popcount16(void)
{
   unsigned bad = 0;
   for (unsigned m = 0; m < 65536; m++)
      bad += rast_popcount16(m) != (unsigned)__builtin_popcount(m);
   CHECK(bad == 0, "rast_popcount16: %u masks miscounted", bad);
}

/* Values worked out by hand from the conversion rule (backend_zs.c). */
static void test_depth_conversion_fixed(void)
{
   const struct rast_profile *seed = profile_named("seed"), *wide = profile_named("wide");
   struct { const struct rast_profile *p; enum rast_zs_layout l; int64_t z; uint32_t want; } t[] = {
      { NULL, RAST_ZS_Z24X8, 1 << 12, 32 },                 /* seed: 1 * (2^24-1)/(2^19-1) */
      { NULL, RAST_ZS_Z24X8, (int64_t)1 << 30, 8388624 },   /* seed: 2^18 of 2^19-1 */
      { NULL, RAST_ZS_Z24X8, ((int64_t)1 << 31) - 4096, 0xffffff },
      { NULL, RAST_ZS_Z24X8, ((int64_t)1 << 31) + 4096, 0xffffff },
      { NULL, RAST_ZS_Z24X8, -1, 0 },
      { NULL, RAST_ZS_Z16, 1 << 12, 0 },
      { NULL, RAST_ZS_Z16, ((int64_t)1 << 30) + 5, 32768 },
      { NULL, RAST_ZS_Z32, ((int64_t)1 << 31) - 4096, 0xffffffffu },
      { NULL, RAST_ZS_Z32, (int64_t)1 << 30, 2147487744u },
      { NULL, RAST_ZS_Z32F, ((int64_t)1 << 31) - 4096, 0x3f800000u },
      { wide, RAST_ZS_Z24X8, (1000 << 12) + 2048, 1001 },   /* wide: round the register */
      { wide, RAST_ZS_Z24X8, (1000 << 12) + 2047, 1000 },
      { wide, RAST_ZS_Z24X8, (int64_t)0xffffff << 12, 0xffffff },
      { wide, RAST_ZS_Z32, (int64_t)0xffffff << 12, 0xffffffffu },
      { wide, RAST_ZS_Z32F, 0, 0 },
   };
   unsigned before = failures;
   for (unsigned k = 0; k < sizeof t / sizeof t[0]; k++) {
      const struct rast_profile *p = t[k].p ? t[k].p : seed;
      static uint8_t zs[ZS_BYTES];
      memset(zs, 0xee, sizeof zs);
      struct rast_context *rc = rast_create(p);
      struct shader_data sd;
      memset(&sd, 0, sizeof sd);
      sd.keep = 0xf;
      struct rast_framebuffer fb;
      memset(&fb, 0, sizeof fb);
      fb.width = W; fb.height = H;
      fb.zs.base = zs; fb.zs.layout = t[k].l; fb.zs.stride = zs_stride(t[k].l);
      rast_set_framebuffer(rc, &fb);
      struct rast_depth_stencil_state dsa;
      memset(&dsa, 0, sizeof dsa);
      dsa.depth_enabled = true;
      dsa.depth_writemask = true;
      dsa.depth_func = RAST_FUNC_ALWAYS;
      rast_set_depth_stencil(rc, &dsa);
      struct rast_shader fs = make_shader(&sd, 0, false, false, false);
      rast_set_shader(rc, &fs);
      rast_validate(rc);
      struct rast_quad q;
      memset(&q, 0, sizeof q);
      q.x = 2; q.y = 4; q.mask = 8;
      q.z[3] = t[k].z;
      rc->quad(rc, &q);
      uint32_t got = ref_zget(t[k].l, zs, 3, 5);
      CHECK(got == t[k].want, "%s %s Z %lld -> %u, want %u", p->name, zs_name(t[k].l),
            (long long)t[k].z, got, t[k].want);
      CHECK(ref_zget(t[k].l, zs, 2, 4) == ref_zget(t[k].l, zs, 0, 0), "masked pixel written");
      CHECK(sd.calls == 0, "depth-only pass without colour must not shade (%u calls)", sd.calls);
      rast_destroy(rc);
   }
   printf("depth conversion (hand-computed values): %s\n", failures == before ? "ok" : "FAILED");
}

/* The compare is in buffer units: two register values one code apart in
 * the register but on the same Z16 code are EQUAL. */
static void test_depth_buffer_units(void)
{
   unsigned before = failures;
   const struct rast_profile *p = profile_named("seed");
   static uint8_t zs[ZS_BYTES];
   memset(zs, 0, sizeof zs);
   struct rast_context *rc = rast_create(p);
   struct shader_data sd;
   memset(&sd, 0, sizeof sd);
   sd.keep = 0xf;
   struct rast_framebuffer fb;
   memset(&fb, 0, sizeof fb);
   fb.width = W; fb.height = H;
   fb.zs.base = zs; fb.zs.layout = RAST_ZS_Z16; fb.zs.stride = zs_stride(RAST_ZS_Z16);
   rast_set_framebuffer(rc, &fb);
   struct rast_depth_stencil_state dsa;
   memset(&dsa, 0, sizeof dsa);
   dsa.depth_enabled = true;
   dsa.depth_writemask = true;
   dsa.depth_func = RAST_FUNC_ALWAYS;
   rast_set_depth_stencil(rc, &dsa);
   struct rast_shader fs = make_shader(&sd, 0, false, false, false);
   rast_set_shader(rc, &fs);
   rast_validate(rc);
   struct rast_quad q;
   memset(&q, 0, sizeof q);
   q.mask = 1;
   q.z[0] = (int64_t)300000 << 12;
   rc->quad(rc, &q);
   dsa.depth_func = RAST_FUNC_EQUAL;
   rast_set_depth_stencil(rc, &dsa);
   rast_validate(rc);
   q.z[0] += 1;     /* 1/4096 of a register unit: far below one Z16 code */
   rast_reset_stats(rc);
   rc->quad(rc, &q);
   CHECK(rast_get_stats(rc)->samples_passed == 1, "EQUAL in buffer units must pass");
   dsa.depth_func = RAST_FUNC_LESS;
   rast_set_depth_stencil(rc, &dsa);
   rast_validate(rc);
   q.z[0] -= 2;
   rast_reset_stats(rc);
   rc->quad(rc, &q);
   CHECK(rast_get_stats(rc)->samples_passed == 0, "LESS in buffer units must fail on the same code");
   rast_destroy(rc);
   printf("depth compare in buffer units: %s\n", failures == before ? "ok" : "FAILED");
}

/* Early (shader can't discard or write depth) and late paths on the same
 * input must write the same bytes; the early path shades fewer pixels. */
static void test_early_late(void)
{
   unsigned before = failures;
   uint64_t early_shaded = 0, late_shaded = 0, passed = 0, early_calls = 0, late_calls = 0;
   for (unsigned it = 0; it < 200; it++) {
      static uint8_t zs0[ZS_BYTES], zs1[ZS_BYTES], c0[CBUF_BYTES], c1[CBUF_BYTES];
      static struct quad_script qs[256];
      struct zs_setup s;
      memset(&s, 0, sizeof s);
      s.prof = profile_named(it & 1 ? "wide" : "seed");
      s.layout = zs_layouts[rnd(N_ZS_LAYOUTS)];
      s.dsa.depth_enabled = true;
      s.dsa.depth_func = (enum rast_func)(rnd(4) ? RAST_FUNC_LESS : rnd(8));
      s.dsa.depth_writemask = rnd(4) != 0;
      if (rnd(2)) {
         random_face(&s.dsa.stencil[0]);
         random_face(&s.dsa.stencil[1]);
         s.dsa.stencil[1].enabled = rnd(2);
         s.ref[0] = (uint8_t)rnd64();
         s.ref[1] = (uint8_t)rnd64();
      }
      s.ncolor = 1;
      int64_t zpool[8];
      float dpool[8];
      make_pools(s.prof, zpool, dpool);
      fill_zs(&s, zs0, zpool, dpool);
      memcpy(zs1, zs0, sizeof zs0);
      for (unsigned i = 0; i < CBUF_BYTES; i++)
         c0[i] = c1[i] = (uint8_t)rnd64();
      make_script(qs, 256, zpool, dpool, false);

      s.may_discard = false;
      struct zs_run_result e = run_backend(&s, zs0, c0, qs, 256);
      s.may_discard = true;     /* the same shader, keeping every pixel */
      struct zs_run_result l = run_backend(&s, zs1, c1, qs, 256);

      const bool zs_work =
         (zs_has_z(s.layout) && !(s.dsa.depth_func == RAST_FUNC_ALWAYS && !s.dsa.depth_writemask)) ||
         (s.dsa.stencil[0].enabled && zs_has_s(s.layout));
      CHECK(!zs_work || e.quad != l.quad, "early and late must be different paths (%s)",
            zs_name(s.layout));
      CHECK(zs_work || e.shaded == l.shaded, "no depth/stencil work, yet the paths shade differently");
      CHECK(memcmp(zs0, zs1, sizeof zs0) == 0, "early/late zs differ (%s)", zs_name(s.layout));
      CHECK(memcmp(c0, c1, sizeof c0) == 0, "early/late colour differ (%s)", zs_name(s.layout));
      CHECK(e.samples == l.samples, "early/late occlusion counts differ");
      CHECK(e.shaded == e.samples, "early path shaded %llu pixels, %llu passed",
            (unsigned long long)e.shaded, (unsigned long long)e.samples);
      CHECK(e.calls <= l.calls, "early path made more shader calls than the late one");
      early_calls += e.calls;
      late_calls += l.calls;
      early_shaded += e.shaded;
      late_shaded += l.shaded;
      passed += e.samples;
   }
   CHECK(early_shaded < late_shaded, "early depth saved no shading");
   CHECK(early_calls < late_calls, "early depth skipped no rejected quad");
   printf("early vs late depth: %s (shaded %llu early vs %llu late, %llu passed)\n",
          failures == before ? "ok" : "FAILED", (unsigned long long)early_shaded,
          (unsigned long long)late_shaded, (unsigned long long)passed);
}

/* ------------------------------------------------------------------ */
/* Blend.                                                               */

static double clampd(double v) { return v < 0 ? 0 : v > 1 ? 1 : v; }

static double ref_factor(enum rast_blend_factor f, unsigned c, const double s[4],
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

static double ref_blend(const struct rast_blend_target *bt, unsigned c, const double s[4],
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

static void color_fill_random(struct color_ctx *cc, unsigned i, enum tfmt f)
{
   if (is8(f)) {
      for (unsigned b = 0; b < CBUF_BYTES; b++)
         cc->mem[i][b] = (uint8_t)rnd64();
   } else {
      for (unsigned b = 0; b + 4 <= CBUF_BYTES; b += 4) {
         float v = rndf(-0.5f, 1.5f);
         memcpy(&cc->mem[i][b], &v, 4);
      }
   }
}

/* Expected channel c after writing `res` (float) into format f. */
static bool chan_ok(enum tfmt f, unsigned c, float got, double want)
{
   if (f == TF_BGRX8 && c == 3)
      return got == 255;
   if (is8(f)) {
      const double w = clampd(want) * 255.0;
      return fabs(got - w) <= 1.0;    /* 1/255 after rounding */
   }
   if (f == TF_F32_CLAMP)
      want = clampd(want);
   return fabs(got - want) <= 1e-5 + 1e-5 * fabs(want);
}

static double dst_value(enum tfmt f, float raw, unsigned c)
{
   if (f == TF_BGRX8 && c == 3)
      return 1.0;
   if (is8(f))
      return raw / 255.0;
   return f == TF_F32_CLAMP ? clampd(raw) : raw;
}

static void test_blend(void)
{
   static struct color_ctx cc;
   unsigned before = failures, combos = 0;

   for (unsigned fi = 0; fi < TF_COUNT; fi++) {
      const enum tfmt f = (enum tfmt)fi;
      const struct rast_profile *p = profile_named("seed");
      for (unsigned eq = 0; eq < 5; eq++)
         for (unsigned sfac = 0; sfac <= RAST_BF_INV_SRC1_ALPHA; sfac++)
            for (unsigned dfac = 0; dfac <= RAST_BF_INV_SRC1_ALPHA; dfac++) {
               struct rast_context *rc = rast_create(p);
               memset(&cc.sd, 0, sizeof cc.sd);
               cc.sd.keep = 0xf;
               struct rast_framebuffer fb;
               memset(&fb, 0, sizeof fb);
               fb.width = W; fb.height = H; fb.nr_cbufs = 1;
               fb.cbuf[0] = cc.t[0] = make_cbuf(f, cc.mem[0]);
               rast_set_framebuffer(rc, &fb);
               struct rast_blend_state bs;
               memset(&bs, 0, sizeof bs);
               struct rast_blend_target *bt = &bs.rt[0];
               bt->blend_enable = true;
               bt->colormask = 0xf;
               bt->rgb_eq = (enum rast_blend_eq)eq;
               bt->alpha_eq = (enum rast_blend_eq)(rnd(3) ? eq : rnd(5));
               bt->rgb_src = (enum rast_blend_factor)sfac;
               bt->rgb_dst = (enum rast_blend_factor)dfac;
               bt->alpha_src = (enum rast_blend_factor)(rnd(2) ? sfac : rnd(19));
               bt->alpha_dst = (enum rast_blend_factor)(rnd(2) ? dfac : rnd(19));
               rast_set_blend(rc, &bs);
               float k[4];
               for (unsigned c = 0; c < 4; c++)
                  k[c] = rndf(-0.5f, 1.5f);
               rast_set_blend_color(rc, k);
               struct rast_shader fs = make_shader(&cc.sd, 2, false, false, false);
               rast_set_shader(rc, &fs);
               rast_validate(rc);

               for (unsigned rep = 0; rep < 4; rep++) {
               color_fill_random(&cc, 0, f);
               static uint8_t old[CBUF_BYTES];
               memcpy(old, cc.mem[0], CBUF_BYTES);
               struct rast_quad q;
               memset(&q, 0, sizeof q);
               q.x = 2 * (int)rnd(W / 2);
               q.y = 2 * (int)rnd(H / 2);
               q.mask = 1 + rnd(15);
               /* A quarter of the values outside [0, 1]: the clamps matter. */
               for (unsigned o = 0; o < 2; o++)
                  for (unsigned c = 0; c < 4; c++)
                     for (unsigned i = 0; i < 4; i++)
                        cc.sd.color[o][c][i] = rndf(-0.25f, 1.25f);
               rc->quad(rc, &q);

               const bool clampin = f != TF_F32;
               for (unsigned i = 0; i < 4; i++) {
                  const int x = q.x + (int)(i & 1), y = q.y + (int)(i >> 1);
                  const uint8_t *px = cc.mem[0] + y * cc.t[0].stride + x * (int)cc.t[0].cpp;
                  const uint8_t *po = old + y * cc.t[0].stride + x * (int)cc.t[0].cpp;
                  if (!(q.mask & (1u << i))) {
                     CHECK(memcmp(px, po, cc.t[0].cpp) == 0, "masked-off pixel written");
                     continue;
                  }
                  double s[4], s1[4], d[4], kk[4];
                  for (unsigned c = 0; c < 4; c++) {
                     s[c] = cc.sd.color[0][c][i];
                     s1[c] = cc.sd.color[1][c][i];
                     d[c] = dst_value(f, cb_get(f, &cc.t[0], old, x, y, c), c);
                     kk[c] = k[c];
                     if (clampin) {
                        s[c] = clampd(s[c]); s1[c] = clampd(s1[c]);
                        d[c] = clampd(d[c]); kk[c] = clampd(kk[c]);
                     }
                  }
                  for (unsigned c = 0; c < 4; c++) {
                     const double want = ref_blend(bt, c, s, s1, d, kk);
                     const float got = cb_get(f, &cc.t[0], cc.mem[0], x, y, c);
                     CHECK(chan_ok(f, c, got, want),
                           "%s eq %u/%u src %u/%u dst %u/%u chan %u: got %g want %g",
                           tfmt_name[f], bt->rgb_eq, bt->alpha_eq, bt->rgb_src, bt->alpha_src,
                           bt->rgb_dst, bt->alpha_dst, c, is8(f) ? got / 255.0 : got, want);
                  }
               }
               }
               combos++;
               rast_destroy(rc);
            }
   }
   printf("blend: %u equation x factor combinations on %d formats: %s\n", combos, TF_COUNT,
          failures == before ? "ok" : "FAILED");
}

/* The usual alpha blends on 8-bit targets, full quads on four lanes
 * (backend_color.c's c8_blend_affine4) against the per-pixel loop
 * (RAST_OPT_SCALAR): the same bytes, for every factor of the affine set
 * on each of rgb/alpha src/dst, sources with NaN, -0, infinities and
 * values outside [0, 1], every destination byte; and the unblended store
 * (c8_lanes.h's c8_store_quad4 against rast_store8_quad) the same way. */
static float rnd_special(void)
{
   static const float special[] = { 0.0f, -0.0f, 1.0f, 0.5f, NAN, INFINITY, -INFINITY,
                                    1.0f / 510.0f, 0.99999994f, 1.00000012f, -1e-30f };
   return rnd(4) ? rndf(-0.25f, 1.25f) : special[rnd(sizeof(special) / sizeof(special[0]))];
}

/* Blend combination `combo` of the affine set: factors ZERO, ONE,
 * SRC_ALPHA, INV_SRC_ALPHA for rgb src, rgb dst, alpha src, alpha dst, two
 * bits each; 256: no blending. */
static const struct rast_blend_target *affine_state(unsigned combo, struct rast_blend_state *bs)
{
   static const enum rast_blend_factor fac[] = { RAST_BF_ZERO, RAST_BF_ONE, RAST_BF_SRC_ALPHA,
                                                 RAST_BF_INV_SRC_ALPHA };
   memset(bs, 0, sizeof *bs);
   struct rast_blend_target *bt = &bs->rt[0];
   bt->blend_enable = combo < 256;
   bt->colormask = 0xf;
   bt->rgb_eq = bt->alpha_eq = RAST_BLEND_ADD;
   bt->rgb_src = fac[combo & 3];
   bt->rgb_dst = fac[(combo >> 2) & 3];
   bt->alpha_src = fac[(combo >> 4) & 3];
   bt->alpha_dst = fac[(combo >> 6) & 3];
   return bt;
}

static unsigned shade_group_src(void *ctx, const struct rast_quad *const q[],
                                struct rast_shaded_quad *const out[], unsigned n);

/* Two contexts on one target of format f, w x h, with blend state bs: the
 * lanes (rc[0]) and the per-pixel loop (rc[1], RAST_OPT_SCALAR), their
 * targets the same random bytes; `groups`: the shader has its wide form
 * (shade_group_src), so the back end takes groups of quads. */
static void lanes_and_scalar(struct rast_context *rc[2], struct color_ctx cc[2], enum tfmt f,
                             const struct rast_blend_state *bs, unsigned w, unsigned h,
                             bool groups)
{
   for (unsigned m = 0; m < 2; m++) {
      rc[m] = rast_create(profile_named("seed"));
      rast_set_options(rc[m], m ? RAST_OPT_SCALAR : 0);
      memset(&cc[m].sd, 0, sizeof cc[m].sd);
      cc[m].sd.keep = 0xf;
      struct rast_framebuffer fb;
      memset(&fb, 0, sizeof fb);
      fb.width = w; fb.height = h; fb.nr_cbufs = 1;
      fb.cbuf[0] = cc[m].t[0] = make_cbuf(f, cc[m].mem[0]);
      rast_set_framebuffer(rc[m], &fb);
      rast_set_blend(rc[m], bs);
      struct rast_shader fs = make_shader(&cc[m].sd, 1, false, false, false);
      if (groups) {
         fs.shade_n = shade_group_src;
         fs.group = RAST_GROUP_MAX;
      }
      rast_set_shader(rc[m], &fs);
      rast_validate(rc[m]);
      CHECK(!groups || rc[m]->quads != NULL, "a shader with a wide form takes groups");
   }
   color_fill_random(&cc[0], 0, f);
   memcpy(cc[1].mem[0], cc[0].mem[0], CBUF_BYTES);
}

/* Every 8-bit format and combination of the affine set (and the unblended
 * store), the lanes (rc[0]) against the per-pixel loop (rc[1]): `reps`
 * draws of `draw` into both on a w x h target, then the buffers compared.
 * `groups`: the shader has its wide form.  Returns the draws. */
typedef void (*affine_draw_fn)(struct rast_context *rc[2], struct color_ctx cc[2]);

static unsigned affine_lanes_vs_scalar(affine_draw_fn draw, unsigned reps, unsigned w,
                                       unsigned h, bool groups)
{
   static struct color_ctx cc[2];
   unsigned draws = 0;
   for (unsigned fi = 0; fi < 3; fi++) {
      const enum tfmt f = (enum tfmt)fi;         /* RGBA8, BGRA8, BGRX8 */
      for (unsigned combo = 0; combo <= 256; combo++) {   /* 256: no blending */
         struct rast_context *rc[2];
         struct rast_blend_state bs;
         const struct rast_blend_target *bt = affine_state(combo, &bs);
         lanes_and_scalar(rc, cc, f, &bs, w, h, groups);
         for (unsigned rep = 0; rep < reps; rep++, draws++)
            draw(rc, cc);
         CHECK(memcmp(cc[0].mem[0], cc[1].mem[0], CBUF_BYTES) == 0,
               "%s %s src %u/%u dst %u/%u: %s on lanes and scalar differ", tfmt_name[f],
               combo < 256 ? "affine blend" : "store", bt->rgb_src, bt->alpha_src, bt->rgb_dst,
               bt->alpha_dst, groups ? "groups" : "quads");
         rast_destroy(rc[0]);
         rast_destroy(rc[1]);
      }
   }
   return draws;
}

/* One quad at a random place of the W x H target, full or partial. */
static void draw_quad(struct rast_context *rc[2], struct color_ctx cc[2])
{
   struct rast_quad q;
   memset(&q, 0, sizeof q);
   q.x = 2 * (int)rnd(W / 2);
   q.y = 2 * (int)rnd(H / 2);
   q.mask = rnd(4) ? 0xf : 1 + rnd(15);
   for (unsigned c = 0; c < 4; c++)
      for (unsigned i = 0; i < 4; i++)
         cc[0].sd.color[0][c][i] = rnd_special();
   cc[1].sd = cc[0].sd;
   rc[0]->quad(rc[0], &q);
   rc[1]->quad(rc[1], &q);
}

static void test_affine_lanes(void)
{
   const unsigned before = failures;
   const unsigned quads = affine_lanes_vs_scalar(draw_quad, 64, W, H, false);
   printf("affine blend and store on lanes: %u quads against the scalar loop: %s\n", quads,
          failures == before ? "ok" : "FAILED");
}

/* The same blends and the store on a group's quads in one call
 * (rast_context.quads, the shader's wide form): on the 512-bit set the
 * group's quads go through one vector of sixteen lanes (backend_lanes.c),
 * against the per-pixel loop (RAST_OPT_SCALAR) given the same groups.  A
 * group holds 1 to 4 quads at different places with their own colours,
 * full and partial masks; the framebuffer is 15 x 11, so that quads on its
 * right and bottom edges have pixels outside and take the per-quad way
 * beside the others of their group. */
static float group_src[W / 2][H / 2][4][RAST_QUAD_SIZE];
static unsigned group_calls, group_multi;   /* multi: groups of two quads or more */

static unsigned shade_group_src(void *ctx, const struct rast_quad *const q[],
                                struct rast_shaded_quad *const out[], unsigned n)
{
   (void)ctx;
   unsigned kept = 0;
   group_calls++;
   for (unsigned i = 0; i < n; i++) {
      memcpy(out[i]->color[0], group_src[q[i]->x / 2][q[i]->y / 2], sizeof(out[i]->color[0]));
      kept |= q[i]->mask << 4 * i;
   }
   return kept;
}

/* A group of 1 to 4 quads at different places of the 15 x 11 target. */
static void draw_group(struct rast_context *rc[2], struct color_ctx cc[2])
{
   const int fw = W - 1, fh = H - 1;
   (void)cc;
   struct rast_quad q[RAST_GROUP_MAX];
   bool used[W / 2][H / 2];
   memset(used, 0, sizeof used);
   memset(q, 0, sizeof q);
   const unsigned want = 1 + rnd(RAST_GROUP_MAX);
   unsigned n = 0;
   while (n < want) {
      const unsigned qx = rnd(W / 2), qy = rnd(H / 2);
      if (used[qx][qy])
         continue;
      used[qx][qy] = true;
      unsigned mask = rnd(3) ? 0xf : 1 + rnd(15);
      if (2 * (int)qx + 1 >= fw)
         mask &= 0x5;                   /* the right column is outside */
      if (2 * (int)qy + 1 >= fh)
         mask &= 0x3;                   /* the bottom row is outside */
      if (!mask)
         continue;
      q[n].x = 2 * (int)qx;
      q[n].y = 2 * (int)qy;
      q[n].mask = mask;
      for (unsigned c = 0; c < 4; c++)
         for (unsigned i = 0; i < 4; i++)
            group_src[qx][qy][c][i] = rnd_special();
      n++;
   }
   for (unsigned m = 0; m < 2; m++) {
      struct rast_quad qm[RAST_GROUP_MAX];
      memcpy(qm, q, sizeof q);
      rc[m]->quads(rc[m], qm, n);
   }
   group_multi += n > 1;
}

static void test_affine_groups(void)
{
   const unsigned before = failures;
   group_calls = group_multi = 0;
   const unsigned groups = affine_lanes_vs_scalar(draw_group, 48, W - 1, H - 1, true);
   CHECK(group_calls == 2 * group_multi && group_multi > groups / 2,
         "every group of two quads or more was shaded in one call (%u of %u)", group_calls,
         2 * group_multi);
   printf("affine blend and store on groups (%s set%s): %u groups against the scalar loop: %s\n",
          rast_lanes()->isa, rast_lanes()->c8_group(RAST_CL_RGBA8, true) ? ", sixteen lanes" : "",
          groups, failures == before ? "ok" : "FAILED");
}

/* Colour mask, with and without blending, on every format. */
static void test_colormask(void)
{
   static struct color_ctx cc;
   unsigned before = failures;
   for (unsigned fi = 0; fi < TF_COUNT; fi++)
      for (unsigned cm = 0; cm < 16; cm++)
         for (unsigned blend = 0; blend < 2; blend++) {
            const enum tfmt f = (enum tfmt)fi;
            struct rast_context *rc = rast_create(profile_named("wide"));
            memset(&cc.sd, 0, sizeof cc.sd);
            cc.sd.keep = 0xf;
            struct rast_framebuffer fb;
            memset(&fb, 0, sizeof fb);
            fb.width = W; fb.height = H; fb.nr_cbufs = 1;
            fb.cbuf[0] = cc.t[0] = make_cbuf(f, cc.mem[0]);
            rast_set_framebuffer(rc, &fb);
            struct rast_blend_state bs;
            memset(&bs, 0, sizeof bs);
            bs.rt[0].colormask = (uint8_t)cm;
            bs.rt[0].blend_enable = blend;
            bs.rt[0].rgb_src = bs.rt[0].alpha_src = RAST_BF_SRC_ALPHA;
            bs.rt[0].rgb_dst = bs.rt[0].alpha_dst = RAST_BF_INV_SRC_ALPHA;
            rast_set_blend(rc, &bs);
            struct rast_shader fs = make_shader(&cc.sd, 1, false, false, false);
            rast_set_shader(rc, &fs);
            rast_validate(rc);
            color_fill_random(&cc, 0, f);
            static uint8_t old[CBUF_BYTES];
            memcpy(old, cc.mem[0], CBUF_BYTES);
            struct rast_quad q;
            memset(&q, 0, sizeof q);
            q.x = 4; q.y = 2; q.mask = 0xf;
            for (unsigned c = 0; c < 4; c++)
               for (unsigned i = 0; i < 4; i++)
                  cc.sd.color[0][c][i] = (float)rnd(256) / 255.0f;
            rc->quad(rc, &q);
            for (unsigned i = 0; i < 4; i++) {
               const int x = q.x + (int)(i & 1), y = q.y + (int)(i >> 1);
               const float sa = cc.sd.color[0][3][i];
               for (unsigned c = 0; c < 4; c++) {
                  const float got = cb_get(f, &cc.t[0], cc.mem[0], x, y, c);
                  const float was = cb_get(f, &cc.t[0], old, x, y, c);
                  if (!(cm & (1u << c))) {
                     CHECK(got == was, "%s mask %x: channel %u changed", tfmt_name[f], cm, c);
                     continue;
                  }
                  double d = dst_value(f, was, c);
                  if (f != TF_F32)
                     d = clampd(d);
                  const double s = cc.sd.color[0][c][i];
                  const double want = blend ? s * sa + d * (1 - sa) : s;
                  CHECK(chan_ok(f, c, got, want), "%s mask %x blend %u: chan %u", tfmt_name[f],
                        cm, blend, c);
               }
            }
            rast_destroy(rc);
         }
   printf("colour mask: %s\n", failures == before ? "ok" : "FAILED");
}

/* color0_to_all and per-output targets, with an unbound cbuf in between. */
static void test_color_routing(void)
{
   static struct color_ctx cc;
   static const enum tfmt fmts[4] = { TF_RGBA8, TF_RGBA8 /* unbound */, TF_BGRA8, TF_F32 };
   unsigned before = failures;
   for (unsigned mode = 0; mode < 3; mode++) {
      /* 0: color0_to_all; 1: one output per cbuf; 2: fewer outputs than cbufs */
      struct rast_context *rc = rast_create(profile_named("seed"));
      memset(&cc.sd, 0, sizeof cc.sd);
      cc.sd.keep = 0xf;
      struct rast_framebuffer fb;
      memset(&fb, 0, sizeof fb);
      fb.width = W; fb.height = H; fb.nr_cbufs = 4;
      for (unsigned i = 0; i < 4; i++) {
         cc.t[i] = make_cbuf(fmts[i], cc.mem[i]);
         fb.cbuf[i] = cc.t[i];
         color_fill_random(&cc, i, fmts[i]);
      }
      fb.cbuf[1].base = NULL;
      rast_set_framebuffer(rc, &fb);
      struct rast_blend_state bs;
      memset(&bs, 0, sizeof bs);
      bs.rt[0].colormask = 0xf;
      rast_set_blend(rc, &bs);
      struct rast_shader fs = make_shader(&cc.sd, mode == 2 ? 3 : 4, false, false, mode == 0);
      rast_set_shader(rc, &fs);
      rast_validate(rc);
      static uint8_t old[4][CBUF_BYTES];
      for (unsigned i = 0; i < 4; i++)
         memcpy(old[i], cc.mem[i], CBUF_BYTES);
      for (unsigned o = 0; o < 4; o++)
         for (unsigned c = 0; c < 4; c++)
            for (unsigned i = 0; i < 4; i++)
               cc.sd.color[o][c][i] = (float)(o * 50 + c * 10 + i) / 255.0f;
      struct rast_quad q;
      memset(&q, 0, sizeof q);
      q.x = 6; q.y = 8; q.mask = 0xf;
      rc->quad(rc, &q);
      CHECK(memcmp(old[1], cc.mem[1], CBUF_BYTES) == 0, "unbound cbuf touched");
      for (unsigned b = 0; b < 4; b++) {
         if (b == 1)
            continue;
         const bool untouched = mode == 2 && b == 3;
         const unsigned o = mode == 0 ? 0 : b;
         for (unsigned i = 0; i < 4; i++) {
            const int x = q.x + (int)(i & 1), y = q.y + (int)(i >> 1);
            for (unsigned c = 0; c < 4; c++) {
               const float got = cb_get(fmts[b], &cc.t[b], cc.mem[b], x, y, c);
               const float was = cb_get(fmts[b], &cc.t[b], old[b], x, y, c);
               if (untouched)
                  CHECK(got == was, "cbuf %u has no output but was written", b);
               else
                  CHECK(chan_ok(fmts[b], c, got, cc.sd.color[o][c][i]),
                        "mode %u cbuf %u chan %u: got %g want output %u", mode, b, c, got, o);
            }
         }
      }
      rast_destroy(rc);
   }
   printf("color0_to_all / per-output routing: %s\n", failures == before ? "ok" : "FAILED");
}

/* Mesa's float_to_ubyte: exact on k/255, round to nearest elsewhere. */
static void test_ubyte(void)
{
   static struct color_ctx cc;
   unsigned before = failures;
   struct rast_context *rc = rast_create(profile_named("seed"));
   memset(&cc.sd, 0, sizeof cc.sd);
   cc.sd.keep = 0xf;
   struct rast_framebuffer fb;
   memset(&fb, 0, sizeof fb);
   fb.width = W; fb.height = H; fb.nr_cbufs = 1;
   fb.cbuf[0] = cc.t[0] = make_cbuf(TF_RGBA8, cc.mem[0]);
   rast_set_framebuffer(rc, &fb);
   struct rast_blend_state bs;
   memset(&bs, 0, sizeof bs);
   bs.rt[0].colormask = 0xf;
   rast_set_blend(rc, &bs);
   struct rast_shader fs = make_shader(&cc.sd, 1, false, false, false);
   rast_set_shader(rc, &fs);
   rast_validate(rc);
   for (unsigned it = 0; it < 4096; it++) {
      float v[4];
      for (unsigned i = 0; i < 4; i++) {
         v[i] = it < 64 ? (float)(it * 4 + i) / 255.0f : rndf(-0.1f, 1.1f);
         for (unsigned c = 0; c < 4; c++)
            cc.sd.color[0][c][i] = v[i];
      }
      if (it == 100) { v[0] = NAN; cc.sd.color[0][0][0] = NAN; }
      struct rast_quad q;
      memset(&q, 0, sizeof q);
      q.mask = 0xf;
      rc->quad(rc, &q);
      for (unsigned i = 0; i < 4; i++) {
         const uint8_t got = cc.mem[0][(int)(i >> 1) * cc.t[0].stride + (int)(i & 1) * 4];
         if (it < 64)
            CHECK(got == it * 4 + i, "k/255 for k=%u stored as %u", it * 4 + i, got);
         else if (v[i] != v[i])
            CHECK(got == 0, "NaN must store 0");
         else
            CHECK(fabs(got - clampd(v[i]) * 255.0) <= 0.5 + 1e-3, "%g stored as %u", v[i], got);
      }
   }
   rast_destroy(rc);
   printf("float -> unorm8 store: %s\n", failures == before ? "ok" : "FAILED");
}

/* No shader: nothing is drawn, nothing counted. */
static void test_no_shader(void)
{
   unsigned before = failures;
   static uint8_t cb[CBUF_BYTES], zs[ZS_BYTES], old_c[CBUF_BYTES], old_z[ZS_BYTES];
   for (unsigned i = 0; i < CBUF_BYTES; i++) old_c[i] = cb[i] = (uint8_t)rnd64();
   for (unsigned i = 0; i < ZS_BYTES; i++) old_z[i] = zs[i] = (uint8_t)rnd64();
   struct rast_context *rc = rast_create(profile_named("seed"));
   struct rast_framebuffer fb;
   memset(&fb, 0, sizeof fb);
   fb.width = W; fb.height = H; fb.nr_cbufs = 1;
   fb.cbuf[0] = make_cbuf(TF_RGBA8, cb);
   fb.zs.base = zs; fb.zs.layout = RAST_ZS_Z24_S8; fb.zs.stride = zs_stride(RAST_ZS_Z24_S8);
   rast_set_framebuffer(rc, &fb);
   struct rast_depth_stencil_state dsa;
   memset(&dsa, 0, sizeof dsa);
   dsa.depth_enabled = dsa.depth_writemask = true;
   dsa.depth_func = RAST_FUNC_ALWAYS;
   rast_set_depth_stencil(rc, &dsa);
   struct rast_blend_state bs;
   memset(&bs, 0, sizeof bs);
   bs.rt[0].colormask = 0xf;
   rast_set_blend(rc, &bs);
   struct rast_shader fs;
   memset(&fs, 0, sizeof fs);
   fs.num_outputs = 1;
   rast_set_shader(rc, &fs);
   rast_validate(rc);
   struct rast_quad q;
   memset(&q, 0, sizeof q);
   q.mask = 0xf;
   rc->quad(rc, &q);
   CHECK(memcmp(cb, old_c, sizeof cb) == 0 && memcmp(zs, old_z, sizeof zs) == 0,
         "a NULL shader drew something");
   CHECK(rast_get_stats(rc)->samples_passed == 0, "a NULL shader counted samples");
   rast_destroy(rc);
   printf("no shader, nothing drawn: %s\n", failures == before ? "ok" : "FAILED");
}

/* ------------------------------------------------------------------ */
/* Logic op.                                                            */

/* RGB565 as a driver format (generic path, 2 bytes, no alpha bits): red in
 * bits 11..15, green 5..10, blue 0..4, little-endian. */
static unsigned u565_chan(float v, unsigned max)
{
   return (unsigned)lrint(clampd(v) * max);   /* NaN: clampd gives NaN, never stored here */
}

static void u565_load(const uint8_t *src, unsigned n, float (*rgba)[4])
{
   for (unsigned i = 0; i < n; i++) {
      const unsigned v = src[2 * i] | (unsigned)src[2 * i + 1] << 8;
      rgba[i][0] = (float)(v >> 11) / 31.0f;
      rgba[i][1] = (float)((v >> 5) & 63) / 63.0f;
      rgba[i][2] = (float)(v & 31) / 31.0f;
      rgba[i][3] = 1.0f;
   }
}

static void u565_store(uint8_t *dst, unsigned n, const float (*rgba)[4])
{
   for (unsigned i = 0; i < n; i++) {
      const unsigned v = u565_chan(rgba[i][0], 31) << 11 | u565_chan(rgba[i][1], 63) << 5 |
                         u565_chan(rgba[i][2], 31);
      dst[2 * i] = (uint8_t)v;
      dst[2 * i + 1] = (uint8_t)(v >> 8);
   }
}

/* GL's definition: the op's value is its truth table, bit (2s + d). */
static uint8_t ref_lop_byte(unsigned op, uint8_t s, uint8_t d)
{
   uint8_t r = 0;
   for (unsigned b = 0; b < 8; b++) {
      const unsigned sb = (s >> b) & 1, db = (d >> b) & 1;
      r |= (uint8_t)(((op >> (2 * sb + db)) & 1) << b);
   }
   return r;
}

enum lfmt { LF_RGBA8, LF_BGRA8, LF_BGRX8, LF_GEN8, LF_565, LF_F32, LF_COUNT };
static const char *const lfmt_name[LF_COUNT] = {
   "RGBA8", "BGRA8", "BGRX8", "RGBA8(generic)", "RGB565(generic)", "F32(generic)"
};

static struct rast_color_target lop_cbuf(enum lfmt f, uint8_t *mem)
{
   static const enum tfmt as_t[LF_COUNT] = { TF_RGBA8, TF_BGRA8, TF_BGRX8, TF_GEN8, TF_GEN8,
                                             TF_F32 };
   struct rast_color_target t = make_cbuf(as_t[f], mem);
   if (f == LF_565) {
      t.cpp = 2;
      t.stride = W * 2 + 6;
      t.load = u565_load;
      t.store = u565_store;
   }
   return t;
}

/* The stored bytes of the source, and which bits of the pixel each channel
 * owns, for format f: what a GL implementation stores, written out. */
static void lop_ref_pixel(enum lfmt f, const double s[4], uint8_t *bytes, uint8_t chan[4][4])
{
   memset(chan, 0, 16);
   switch (f) {
   case LF_565: {
      const unsigned v = (unsigned)lrint(clampd(s[0]) * 31) << 11 |
                         (unsigned)lrint(clampd(s[1]) * 63) << 5 |
                         (unsigned)lrint(clampd(s[2]) * 31);
      bytes[0] = (uint8_t)v;
      bytes[1] = (uint8_t)(v >> 8);
      chan[0][1] = 0xf8;                       /* red: bits 11..15 */
      chan[1][0] = 0xe0; chan[1][1] = 0x07;    /* green: bits 5..10 */
      chan[2][0] = 0x1f;                       /* blue: bits 0..4 */
      break;
   }
   case LF_BGRA8: case LF_BGRX8:
      for (unsigned c = 0; c < 4; c++) {
         const unsigned k = c == 3 ? 3 : 2 - c;
         bytes[k] = f == LF_BGRX8 && c == 3 ? 255 : ref_ubyte(s[c]);
         chan[c][k] = 0xff;
      }
      break;
   default:
      for (unsigned c = 0; c < 4; c++) {
         bytes[c] = ref_ubyte(s[c]);
         chan[c][c] = 0xff;
      }
      break;
   }
}

/* All 16 ops x 16 colour masks on the 8-bit layouts and two driver formats,
 * blend state left enabled (the op replaces it); a float target stores the
 * source unchanged. */
static void test_logicop(void)
{
   static struct color_ctx cc;
   static uint8_t old[CBUF_BYTES];
   unsigned before = failures, combos = 0;

   for (unsigned fi = 0; fi < LF_COUNT; fi++)
      for (unsigned op = 0; op < 16; op++)
         for (unsigned cm = 1; cm < 16; cm++) {
            const enum lfmt f = (enum lfmt)fi;
            struct rast_context *rc = rast_create(profile_named(rnd(2) ? "seed" : "wide"));
            memset(&cc.sd, 0, sizeof cc.sd);
            cc.sd.keep = 0xf;
            struct rast_framebuffer fb;
            memset(&fb, 0, sizeof fb);
            fb.width = W; fb.height = H; fb.nr_cbufs = 1;
            fb.cbuf[0] = cc.t[0] = lop_cbuf(f, cc.mem[0]);
            rast_set_framebuffer(rc, &fb);
            struct rast_blend_state bs;
            memset(&bs, 0, sizeof bs);
            bs.logicop_enable = true;
            bs.logicop_func = (enum rast_logicop)op;
            bs.rt[0].colormask = (uint8_t)cm;
            bs.rt[0].blend_enable = true;
            bs.rt[0].rgb_src = bs.rt[0].alpha_src = RAST_BF_SRC_ALPHA;
            bs.rt[0].rgb_dst = bs.rt[0].alpha_dst = RAST_BF_INV_SRC_ALPHA;
            rast_set_blend(rc, &bs);
            struct rast_shader fs = make_shader(&cc.sd, 1, false, false, false);
            rast_set_shader(rc, &fs);
            rast_validate(rc);

            for (unsigned rep = 0; rep < 3; rep++) {
               color_fill_random(&cc, 0, f == LF_F32 ? TF_F32 : TF_RGBA8);
               memcpy(old, cc.mem[0], CBUF_BYTES);
               struct rast_quad q;
               memset(&q, 0, sizeof q);
               q.x = 2 * (int)rnd(W / 2);
               q.y = 2 * (int)rnd(H / 2);
               q.mask = 1 + rnd(15);
               for (unsigned c = 0; c < 4; c++)
                  for (unsigned i = 0; i < 4; i++)
                     cc.sd.color[0][c][i] = rnd(4) ? (float)rnd(256) / 255.0f
                                                   : rndf(-0.25f, 1.25f);
               rc->quad(rc, &q);

               const unsigned cpp = cc.t[0].cpp;
               for (unsigned i = 0; i < 4; i++) {
                  const int x = q.x + (int)(i & 1), y = q.y + (int)(i >> 1);
                  const uint8_t *px = cc.mem[0] + y * cc.t[0].stride + x * (int)cpp;
                  const uint8_t *po = old + y * cc.t[0].stride + x * (int)cpp;
                  if (!(q.mask & (1u << i))) {
                     CHECK(memcmp(px, po, cpp) == 0, "logic op wrote a masked-off pixel");
                     continue;
                  }
                  double s[4];
                  for (unsigned c = 0; c < 4; c++)
                     s[c] = cc.sd.color[0][c][i];
                  if (f == LF_F32) {
                     for (unsigned c = 0; c < 4; c++) {
                        float got;
                        memcpy(&got, px + 4 * c, 4);
                        const float want = cm & (1u << c) ? (float)s[c] : bits_f(0);
                        float was;
                        memcpy(&was, po + 4 * c, 4);
                        CHECK(got == (cm & (1u << c) ? want : was),
                              "F32 op %u mask %x chan %u: got %g (float targets take the "
                              "source)", op, cm, c, got);
                     }
                     continue;
                  }
                  uint8_t sb[4], chan[4][4], wm[4] = { 0, 0, 0, 0 };
                  lop_ref_pixel(f, s, sb, chan);
                  for (unsigned c = 0; c < 4; c++)
                     if (cm & (1u << c))
                        for (unsigned k = 0; k < cpp; k++)
                           wm[k] |= chan[c][k];
                  for (unsigned k = 0; k < cpp; k++) {
                     uint8_t want = (uint8_t)((ref_lop_byte(op, sb[k], po[k]) & wm[k]) |
                                              (po[k] & ~wm[k]));
                     if (f == LF_BGRX8 && k == 3 && (cm & 8) && op != RAST_LOGICOP_NOOP)
                        want = 255;              /* X: every store writes 255 */
                     CHECK(px[k] == want, "%s op %u mask %x pixel %u byte %u: got %02x want %02x"
                           " (src %02x dst %02x)", lfmt_name[f], op, cm, i, k, px[k], want,
                           sb[k], po[k]);
                  }
               }
            }
            combos++;
            rast_destroy(rc);
         }
   printf("logic op: %u op x colour mask x format combinations: %s\n", combos,
          failures == before ? "ok" : "FAILED");
}

/* Logic op behind the depth test (the early path) and with two targets of
 * different layouts, one float: the op reaches every normalized target. */
static void test_logicop_paths(void)
{
   static struct color_ctx cc;
   static uint8_t old[2][CBUF_BYTES], zs[ZS_BYTES];
   unsigned before = failures;
   struct rast_context *rc = rast_create(profile_named("seed"));
   memset(&cc.sd, 0, sizeof cc.sd);
   cc.sd.keep = 0xf;
   struct rast_framebuffer fb;
   memset(&fb, 0, sizeof fb);
   fb.width = W; fb.height = H; fb.nr_cbufs = 2;
   fb.cbuf[0] = cc.t[0] = lop_cbuf(LF_BGRA8, cc.mem[0]);
   fb.cbuf[1] = cc.t[1] = lop_cbuf(LF_565, cc.mem[1]);
   memset(zs, 0, sizeof zs);          /* depth 0: GEQUAL passes, twice */
   fb.zs.base = zs; fb.zs.layout = RAST_ZS_Z24_S8; fb.zs.stride = zs_stride(RAST_ZS_Z24_S8);
   rast_set_framebuffer(rc, &fb);
   struct rast_depth_stencil_state dsa;
   memset(&dsa, 0, sizeof dsa);
   dsa.depth_enabled = dsa.depth_writemask = true;
   dsa.depth_func = RAST_FUNC_GEQUAL;
   rast_set_depth_stencil(rc, &dsa);
   struct rast_blend_state bs;
   memset(&bs, 0, sizeof bs);
   bs.logicop_enable = true;
   bs.logicop_func = RAST_LOGICOP_XOR;
   bs.rt[0].colormask = 0xf;
   rast_set_blend(rc, &bs);
   struct rast_shader fs = make_shader(&cc.sd, 1, false, false, true);
   rast_set_shader(rc, &fs);
   rast_validate(rc);
   for (unsigned b = 0; b < 2; b++) {
      color_fill_random(&cc, b, TF_RGBA8);
      memcpy(old[b], cc.mem[b], CBUF_BYTES);
   }
   for (unsigned c = 0; c < 4; c++)
      for (unsigned i = 0; i < 4; i++)
         cc.sd.color[0][c][i] = (float)rnd(256) / 255.0f;
   struct rast_quad q;
   memset(&q, 0, sizeof q);
   q.x = 2; q.y = 4; q.mask = 0xf;
   for (unsigned i = 0; i < 4; i++)
      q.z[i] = (int64_t)1 << 20;
   rc->quad(rc, &q);
   for (unsigned b = 0; b < 2; b++) {
      const enum lfmt f = b ? LF_565 : LF_BGRA8;
      const unsigned cpp = cc.t[b].cpp;
      for (unsigned i = 0; i < 4; i++) {
         const int x = q.x + (int)(i & 1), y = q.y + (int)(i >> 1);
         const uint8_t *px = cc.mem[b] + y * cc.t[b].stride + x * (int)cpp;
         const uint8_t *po = old[b] + y * cc.t[b].stride + x * (int)cpp;
         double s[4];
         uint8_t sb[4], chan[4][4];
         for (unsigned c = 0; c < 4; c++)
            s[c] = cc.sd.color[0][c][i];
         lop_ref_pixel(f, s, sb, chan);
         for (unsigned k = 0; k < cpp; k++)
            CHECK(px[k] == (sb[k] ^ po[k]), "%s behind depth: byte %u got %02x want %02x",
                  lfmt_name[f], k, px[k], sb[k] ^ po[k]);
      }
   }
   CHECK(rast_get_stats(rc)->samples_passed == 4, "the depth test did not run");
   /* Again: XOR twice restores the buffers. */
   rc->quad(rc, &q);
   CHECK(memcmp(cc.mem[0], old[0], CBUF_BYTES) == 0 && memcmp(cc.mem[1], old[1], CBUF_BYTES) == 0,
         "XOR applied twice did not restore the buffers");
   rast_destroy(rc);
   printf("logic op behind depth, two targets: %s\n", failures == before ? "ok" : "FAILED");
}

/* The early depth test of a group on lanes (backend_lanes.c) against the
 * per-quad functions (RAST_OPT_SCALAR): every func, with and without
 * writes, on both layouts with 24 bits in the low bits of a word (the
 * stencil or padding byte beside them random and kept), groups of one to
 * four quads at distinct places, some partly covered at the target's last
 * column and row (those groups take the per-quad path), registers below 0
 * and above full scale.  The same depth and colour bytes, the same counts. */
static void test_depth_groups(void)
{
   static uint8_t zs[2][ZS_BYTES], cb[2][CBUF_BYTES];
   if (!rast_lanes()->zgroup(RAST_FUNC_LESS, true)) {
      printf("depth groups on lanes: not in this instruction set (%s)\n", rast_lanes()->isa);
      return;
   }
   static const enum rast_zs_layout layouts[] = { RAST_ZS_Z24_S8, RAST_ZS_Z24X8 };
   const unsigned fw = W - 1, fh = H - 1;        /* a last column and row of half quads */
   unsigned before = failures, lanes_groups = 0, groups = 0;
   for (unsigned li = 0; li < 2; li++)
      for (unsigned f = 0; f < 8; f++)
         for (unsigned wr = 0; wr < 2; wr++) {
            struct zs_setup s;
            memset(&s, 0, sizeof s);
            s.prof = profile_named("seed");
            s.layout = layouts[li];
            s.dsa.depth_enabled = true;
            s.dsa.depth_func = (enum rast_func)f;
            s.dsa.depth_writemask = wr;
            int64_t zpool[8];
            float dpool[8];
            make_pools(s.prof, zpool, dpool);
            fill_zs(&s, zs[0], zpool, dpool);
            memcpy(zs[1], zs[0], ZS_BYTES);
            for (unsigned i = 0; i < CBUF_BYTES; i++)
               cb[0][i] = cb[1][i] = (uint8_t)rnd64();
            struct rast_context *rc[2];
            struct shader_data sd[2];
            for (unsigned m = 0; m < 2; m++) {
               rc[m] = rast_create(s.prof);
               rast_set_options(rc[m], m ? RAST_OPT_SCALAR : 0);
               memset(&sd[m], 0, sizeof sd[m]);
               struct rast_framebuffer fb;
               memset(&fb, 0, sizeof fb);
               fb.width = fw;
               fb.height = fh;
               fb.nr_cbufs = 1;
               fb.cbuf[0] = make_cbuf(TF_RGBA8, cb[m]);
               fb.zs.base = zs[m];
               fb.zs.layout = s.layout;
               fb.zs.stride = zs_stride(s.layout);
               rast_set_framebuffer(rc[m], &fb);
               struct rast_blend_state bs;
               memset(&bs, 0, sizeof bs);
               bs.rt[0].colormask = 0xf;
               rast_set_blend(rc[m], &bs);
               rast_set_depth_stencil(rc[m], &s.dsa);
               struct rast_shader fs = make_shader(&sd[m], 1, false, false, false);
               fs.shade_n = shade_group_src;
               fs.group = RAST_GROUP_MAX;
               rast_set_shader(rc[m], &fs);
               rast_validate(rc[m]);
            }
            const struct rast_backend *be0 = rc[0]->back_priv, *be1 = rc[1]->back_priv;
            /* ALWAYS without a write has no depth work at all */
            const bool work = f != RAST_FUNC_ALWAYS || wr;
            CHECK(rc[0]->quads && be0 && !be0->zgroup == !work,
                  "%s func %u write %u: %s group on lanes", zs_name(s.layout), f, wr,
                  work ? "no" : "a");
            CHECK(be1 && !be1->zgroup, "RAST_OPT_SCALAR keeps the per-quad depth test");
            for (unsigned g = 0; g < 300; g++) {
               struct rast_quad q[RAST_GROUP_MAX];
               memset(q, 0, sizeof q);
               const unsigned n = 1 + rnd(RAST_GROUP_MAX);
               bool lanes = true;
               for (unsigned i = 0; i < n; i++) {
                  bool apart;
                  do {
                     q[i].x = 2 * (int)rnd(W / 2);
                     q[i].y = 2 * (int)rnd(H / 2);
                     apart = true;
                     for (unsigned j = 0; j < i; j++)
                        apart &= q[j].x != q[i].x || q[j].y != q[i].y;
                  } while (!apart);
                  unsigned mask = rnd(3) ? 0xf : 1 + rnd(15);
                  if ((unsigned)q[i].x + 1 >= fw)
                     mask &= 0x5;               /* the right column is outside */
                  if ((unsigned)q[i].y + 1 >= fh)
                     mask &= 0x3;               /* the bottom row is outside */
                  q[i].mask = mask ? mask : 1;
                  for (unsigned k = 0; k < 4; k++)
                     q[i].z[k] = rnd(8) ? zpool[rnd(8)] : (int64_t)(rnd64() % (1u << 31));
                  for (unsigned c = 0; c < 4; c++)
                     for (unsigned k = 0; k < 4; k++)
                        group_src[q[i].x / 2][q[i].y / 2][c][k] = (float)rnd(256) / 255.0f;
                  lanes &= q[i].mask == 0xf ||
                           ((unsigned)q[i].x + 1 < fw && (unsigned)q[i].y + 1 < fh);
               }
               groups++;
               lanes_groups += lanes;
               for (unsigned m = 0; m < 2; m++) {
                  struct rast_quad qm[RAST_GROUP_MAX];
                  memcpy(qm, q, sizeof qm);
                  rc[m]->quads(rc[m], qm, n);
               }
            }
            CHECK(memcmp(zs[0], zs[1], ZS_BYTES) == 0, "%s func %u write %u: depth groups on "
                  "lanes and per quad leave different depth bytes", zs_name(s.layout), f, wr);
            CHECK(memcmp(cb[0], cb[1], CBUF_BYTES) == 0, "%s func %u write %u: different "
                  "colour bytes", zs_name(s.layout), f, wr);
            const struct rast_stats *a = rast_get_stats(rc[0]), *b = rast_get_stats(rc[1]);
            CHECK(a->samples_passed == b->samples_passed && a->pixels_shaded == b->pixels_shaded &&
                     a->skip_early_quads == b->skip_early_quads,
                  "%s func %u write %u: samples passed %llu vs %llu, shaded %llu vs %llu, "
                  "rejected quads %llu vs %llu", zs_name(s.layout), f, wr,
                  (unsigned long long)a->samples_passed, (unsigned long long)b->samples_passed,
                  (unsigned long long)a->pixels_shaded, (unsigned long long)b->pixels_shaded,
                  (unsigned long long)a->skip_early_quads, (unsigned long long)b->skip_early_quads);
            rast_destroy(rc[0]);
            rast_destroy(rc[1]);
         }
   CHECK(lanes_groups > groups / 4, "only %u of %u groups could take the lanes", lanes_groups,
         groups);
   printf("depth groups on lanes against per quad: %u groups, %u of them on lanes: %s\n",
          groups, lanes_groups, failures == before ? "ok" : "FAILED");
}

int main(void)
{
   const char *seed = getenv("FIXPIPE_TEST_SEED");
   if (seed)
      rng_state = strtoull(seed, NULL, 0) | 1;
   printf("test_backend: seed 0x%llx\n", (unsigned long long)rng_state);

   test_depth_conversion_fixed();
   test_depth_conversion_mul();
   test_popcount16();
   test_depth_buffer_units();
   test_depth_funcs();
   test_stencil_ops_fixed();
   test_stencil();
   test_early_late();
   test_ubyte();
   test_blend();
   test_affine_lanes();
   test_affine_groups();
   test_depth_groups();
   test_colormask();
   test_color_routing();
   test_no_shader();
   test_logicop();
   test_logicop_paths();

   printf("%u checks, %u failures\n", checks, failures);
   return failures ? 1 : 0;
}
