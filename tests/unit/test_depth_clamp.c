/*
 * The depth clamp (rast_raster_state.depth_clamp: GL's ARB_depth_clamp,
 * EXT_depth_clamp): each fragment's depth clamped to the depth range of its
 * primitive's viewport (rast_set_depth_ranges), held to a reference that
 * computes it from the definition in exact integers and shares no code with
 * the back end:
 *
 *  - a range's ends: glDepthRange's n and f (reversed too: n > f), in
 *    [0, 1], into the Z register: v (2^z_bits - 1) 2^frac rounded to
 *    nearest, ties away, from the float's bits;
 *  - the Z register z: clamp(z, min, max), then the buffer's rule;
 *  - a depth d the shader wrote (GL's [0, 1] first, NaN 0): d below
 *    min / FULL (exactly) stores what min does, d above max / FULL what max
 *    does, any other d its own value.
 *
 * Part 1 runs the back end on hand-made quads (every depth layout, depth
 * func and write flag, register and shader depth, random ranges, the
 * viewport switched between quads as set-up does).  Part 2 draws random
 * triangles whose depths cross both ends of their ranges, each in one of
 * four viewports by its provoking vertex's index (the last of
 * RAST_MAX_VIEWPORTS for an index beyond), through set-up and the back end:
 * the early test (register depth) and the late one (shader depth), on one
 * thread and two, the lanes and the scalar datapath, quads one by one and
 * in groups; and without the clamp, [0, 1] as before.  Each part also
 * counts the fragments the clamp moved, so that a run it never acted on
 * fails.  Part 3: a vertex depth beyond the Z register saturates at set-up,
 * counted, and its fragments still land inside the range.  Part 4: after
 * primitives with a viewport index, those of a layout without one take
 * viewport 0's scissor and range.
 *
 *   test_depth_clamp          (FIXPIPE_TEST_SEED: the random seed)
 */
#include "backend_fixture.h"

/* ------------------------------------------------------------------ */
/* The reference.                                                       */

/* A float in [0, 1] as m 2^e, m an integer below 2^24. */
static void float_parts(float v, uint64_t *m, int *e)
{
   const uint32_t b = f_bits(v);
   unsigned ex = b >> 23 & 0xff;
   *m = b & 0x7fffff;
   if (ex)
      *m |= 0x800000;
   else
      ex = 1;
   *e = (int)ex - 150;
}

static float gl_range(float v)
{
   return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;      /* NaN: 0 */
}

/* A range's end in the Z register: v (2^z_bits - 1) 2^frac, ties away. */
static uint64_t ref_bound(const struct rast_profile *p, float v)
{
   uint64_t m;
   int e;
   float_parts(gl_range(v), &m, &e);
   const u128 n = (u128)m * ((((u128)1) << p->z_bits) - 1);   /* times 2^e */
   const int s = -(e + (int)p->z.frac_bits);                   /* value = n / 2^s */
   if (s <= 0)
      return (uint64_t)(n << -s);
   if (s > 100)
      return 0;                                                 /* n < 2^53 */
   return (uint64_t)((n + ((u128)1 << (s - 1))) >> s);
}

/* The sign of d full - z, d in [0, 1], exactly. */
static int ref_cmp_depth(float d, uint64_t z, uint64_t full)
{
   uint64_t m;
   int e;
   float_parts(d, &m, &e);
   if (m == 0)
      return z ? -1 : 0;
   const int k = -e;                  /* d full = m full / 2^k, k >= 23 */
   if (k > 83)                        /* d full < 2^(24 + 44 - 84): in (0, 1) */
      return z ? -1 : 1;
   const u128 a = (u128)m * full, b = (u128)z << k;
   return a < b ? -1 : a > b;
}

struct ref_range { uint64_t lo, hi; };

static struct ref_range ref_range_of(const struct rast_profile *p, struct rast_depth_range r,
                                     bool clamp)
{
   if (!clamp)
      return (struct ref_range){ 0, ref_full(p) };
   const uint64_t a = ref_bound(p, r.n), b = ref_bound(p, r.f);
   return (struct ref_range){ a < b ? a : b, a < b ? b : a };
}

/* The stored depth of a fragment of Z register z, or of shader depth d. */
static uint32_t ref_clamped_reg(const struct rast_profile *p, enum rast_zs_layout l,
                                struct ref_range r, int64_t z)
{
   const int64_t c = z < (int64_t)r.lo ? (int64_t)r.lo : z > (int64_t)r.hi ? (int64_t)r.hi : z;
   return ref_zconv_reg(p, l, c);
}

static uint32_t ref_clamped_shader(const struct rast_profile *p, enum rast_zs_layout l,
                                   struct ref_range r, float d)
{
   d = gl_range(d);
   if (ref_cmp_depth(d, r.lo, ref_full(p)) < 0)
      return ref_zconv_reg(p, l, (int64_t)r.lo);
   if (ref_cmp_depth(d, r.hi, ref_full(p)) > 0)
      return ref_zconv_reg(p, l, (int64_t)r.hi);
   return ref_zconv_shader(l, d);
}

/* ------------------------------------------------------------------ */
/* Ranges.                                                              */

static const struct rast_depth_range range_pool[] = {
   { 0.0f, 1.0f }, { 0.2f, 0.7f }, { 0.8f, 0.3f }, { 0.5f, 0.5f }, { 0.0f, 0.25f },
   { 1.0f, 0.0f }, { 0.75f, 1.0f }, { 0.1f, 0.9f },
};
#define N_RANGE_POOL (sizeof range_pool / sizeof range_pool[0])

static struct rast_depth_range random_range(void)
{
   if (rnd(2))
      return range_pool[rnd(N_RANGE_POOL)];
   struct rast_depth_range r = { rndf(0.0f, 1.0f), rndf(0.0f, 1.0f) };
   return r;
}

static const struct rast_profile *profile_spec(const char *spec)
{
   static struct rast_profile_buf bufs[8];
   static unsigned n;
   char err[160];
   if (n == 8 || !rast_profile_parse(spec, &bufs[n], err, sizeof err)) {
      printf("profile %s: %s\n", spec, err);
      exit(2);
   }
   return &bufs[n++].p;
}

/* ------------------------------------------------------------------ */
/* Part 1: the back end on hand-made quads.                              */

static const enum rast_zs_layout z_layouts[] = {
   RAST_ZS_Z16, RAST_ZS_Z32, RAST_ZS_Z24_S8, RAST_ZS_Z24X8, RAST_ZS_S8_Z24,
   RAST_ZS_X8Z24, RAST_ZS_Z32F, RAST_ZS_Z32F_S8X24,
};
#define N_Z_LAYOUTS (sizeof z_layouts / sizeof z_layouts[0])

static uint64_t clamped_fragments;   /* whose stored depth the clamp changed */

/* A register near a range's ends, beyond [0, FULL] or anywhere. */
static int64_t pick_z(const struct rast_profile *p, struct ref_range r)
{
   const int64_t full = (int64_t)ref_full(p), lo = (int64_t)r.lo, hi = (int64_t)r.hi;
   switch (rnd(10)) {
   case 0: return lo - 1;
   case 1: return lo;
   case 2: return hi;
   case 3: return hi + 1;
   case 4: return -5000;
   case 5: return full + 77777;
   case 6: return lo - 1 - (int64_t)(rnd64() % (uint64_t)(lo + 1));
   case 7: return hi + 1 + (int64_t)(rnd64() % (uint64_t)(full - hi + 1));
   default: return (int64_t)(rnd64() % (uint64_t)(full + 1));
   }
}

/* A shader depth at a range's ends (the floats given, and their
 * neighbours), outside [0, 1], NaN, or anywhere. */
static float pick_d(struct rast_depth_range r)
{
   const float lo = fminf(r.n, r.f), hi = fmaxf(r.n, r.f);
   switch (rnd(11)) {
   case 0: return lo;
   case 1: return hi;
   case 2: return nextafterf(lo, -1.0f);
   case 3: return nextafterf(lo, 2.0f);
   case 4: return nextafterf(hi, -1.0f);
   case 5: return nextafterf(hi, 2.0f);
   case 6: return -0.25f;
   case 7: return 1.5f;
   case 8: return NAN;
   default: return rndf(0.0f, 1.0f);
   }
}

static void quads_state(const struct rast_profile *p, enum rast_zs_layout l, bool shader_depth,
                        bool clamp, bool scalar)
{
   static uint8_t zs_a[ZS_BYTES], zs_b[ZS_BYTES], c_a[CBUF_BYTES];
   struct zs_setup s;
   memset(&s, 0, sizeof s);
   s.prof = p;
   s.layout = l;
   s.dsa.depth_enabled = true;
   s.dsa.depth_func = (enum rast_func)rnd(8);
   s.dsa.depth_writemask = rnd(4) != 0;
   s.writes_depth = shader_depth;
   s.ncolor = 1;

   struct rast_depth_range ranges[RAST_MAX_VIEWPORTS];
   struct ref_range ref[RAST_MAX_VIEWPORTS];
   for (unsigned i = 0; i < RAST_MAX_VIEWPORTS; i++) {
      ranges[i] = random_range();
      ref[i] = ref_range_of(p, ranges[i], clamp);
   }
   /* the buffer's depths start anywhere in [0, 1] */
   for (unsigned i = 0; i < ZS_BYTES; i++)
      zs_a[i] = (uint8_t)rnd64();
   for (int y = 0; y < H; y++)
      for (int x = 0; x < W; x++)
         ref_zput(l, zs_a, x, y, ref_zconv_reg(p, l, (int64_t)(rnd64() % (ref_full(p) + 1))));
   memcpy(zs_b, zs_a, sizeof zs_a);

   struct rast_context *rc = rast_create(p);
   struct shader_data sd;
   memset(&sd, 0, sizeof sd);
   const struct rast_color_target t0 = make_cbuf(TF_RGBA8, c_a);
   bind_fb(rc, W, H, 1, &t0, zs_a, l);
   set_plain_blend(rc);
   rast_set_depth_stencil(rc, &s.dsa);
   struct rast_raster_state rs;
   memset(&rs, 0, sizeof rs);
   rs.half_pixel_center = true;
   rs.depth_clamp = clamp;
   rast_set_raster_state(rc, &rs);
   rast_set_depth_ranges(rc, 0, RAST_MAX_VIEWPORTS, ranges);
   rast_set_options(rc, scalar ? RAST_OPT_SCALAR : 0);
   struct rast_shader fs = make_shader(&sd, 1, shader_depth, false, false);
   rast_set_shader(rc, &fs);
   rast_validate(rc);

   for (unsigned k = 0; k < 200; k++) {
      /* set-up switches the viewport between primitives */
      const unsigned vp = rnd(RAST_MAX_VIEWPORTS);
      rast_backend_viewport(rc, vp);
      struct rast_quad q = random_quad();
      q.front_facing = true;
      for (unsigned i = 0; i < 4; i++) {
         q.z[i] = pick_z(p, ref[vp]);
         sd.depth[i] = pick_d(ranges[vp]);
      }
      sd.keep = 0xf;
      rc->quad(rc, &q);
      for (unsigned i = 0; i < 4; i++) {
         if (!(q.mask >> i & 1))
            continue;
         const uint32_t want = shader_depth ? ref_clamped_shader(p, l, ref[vp], sd.depth[i])
                                            : ref_clamped_reg(p, l, ref[vp], q.z[i]);
         const uint32_t unclamped = shader_depth ? ref_zconv_shader(l, sd.depth[i])
                                                 : ref_zconv_reg(p, l, q.z[i]);
         clamped_fragments += want != unclamped;
         ref_fragment(&s, zs_b, q.x + (int)(i & 1), q.y + (int)(i >> 1), want, true);
      }
   }
   rast_destroy(rc);

   unsigned bad = 0;
   int first = -1;
   for (int y = 0; y < H; y++)
      for (int x = 0; x < W; x++)
         if (ref_zget(l, zs_a, x, y) != ref_zget(l, zs_b, x, y) && !bad++)
            first = y * W + x;
   CHECK(bad == 0, "%s %s %s depth, func %d%s%s: %u pixels differ, first (%d, %d): %08x, want %08x",
         p->name, zs_name(l), shader_depth ? "shader" : "register", s.dsa.depth_func,
         clamp ? ", clamped" : "", scalar ? ", scalar" : "", bad, first % W, first / W,
         first < 0 ? 0 : ref_zget(l, zs_a, first % W, first / W),
         first < 0 ? 0 : ref_zget(l, zs_b, first % W, first / W));
}

static void test_quads(void)
{
   const struct rast_profile *profs[] = {
      profile_named("seed"), profile_named("wide"), profile_spec("seed:z=20.20"),
      profile_spec("seed:z=20.0"), profile_spec("wide:z=28.3"),
   };
   const unsigned before = failures;
   clamped_fragments = 0;
   for (unsigned p = 0; p < sizeof profs / sizeof profs[0]; p++)
      for (unsigned li = 0; li < N_Z_LAYOUTS; li++)
         for (unsigned sh = 0; sh < 2; sh++)
            for (unsigned it = 0; it < 12; it++)
               quads_state(profs[p], z_layouts[li], sh, it % 4 != 3, it & 1);
   CHECK(clamped_fragments > 0, "no fragment's depth was clamped: the test proves nothing");
   printf("part 1, quads through the back end: %s (%llu fragments clamped)\n",
          failures == before ? "ok" : "FAILED", (unsigned long long)clamped_fragments);
}

/* ------------------------------------------------------------------ */
/* Part 2: triangles through set-up, in four viewports.                  */

#define TW 64
#define TH 48
#define NTRI 40
#define NVP 4

/* What the shader saw last at each pixel: the Z register as walked, the
 * depth it wrote (its LINEAR input) and the triangle (a CONSTANT one). */
struct seen {
   int64_t z[TW * TH];
   float d[TW * TH];
   int32_t tri[TW * TH];
};

static void seen_quad(struct seen *s, const struct rast_quad *q, unsigned keep,
                      struct rast_shaded_quad *out)
{
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      out->depth[i] = q->in[1][0][i];
      for (unsigned c = 0; c < 4; c++)
         out->color[0][c][i] = c == 3 ? 1.0f : 0.5f;
      if (!(keep >> i & 1))
         continue;
      const int px = (q->y + (int)(i >> 1)) * TW + q->x + (int)(i & 1);
      s->z[px] = q->z[i];
      s->d[px] = q->in[1][0][i];
      s->tri[px] = (int32_t)q->in[0][0][i];
   }
}

static unsigned shade_seen(void *ctx, const struct rast_quad *q, struct rast_shaded_quad *out)
{
   seen_quad(ctx, q, q->mask, out);
   return q->mask;
}

static unsigned shade_seen_n(void *ctx, const struct rast_quad *const q[],
                             struct rast_shaded_quad *const out[], unsigned n)
{
   unsigned kept = 0;
   for (unsigned k = 0; k < n; k++) {
      seen_quad(ctx, q[k], q[k]->mask, out[k]);
      kept |= q[k]->mask << 4 * k;
   }
   return kept;
}

/* Four slots a vertex: position, the triangle's number (CONSTANT), the
 * shader's depth (LINEAR), the viewport index (an integer in x). */
struct tri { float v[3][4][4]; unsigned vp; };
static struct tri tris[NTRI];

static void make_tris(void)
{
   for (unsigned t = 0; t < NTRI; t++) {
      /* 0 to 3, and 7 and 40: the last viewport's */
      const uint32_t vp = rnd(6) == 0 ? (rnd(2) ? 7 : 40) : rnd(NVP);
      tris[t].vp = vp;
      const float cx = rndf(0, TW), cy = rndf(0, TH);
      for (unsigned k = 0; k < 3; k++) {
         float *pos = tris[t].v[k][0];
         pos[0] = cx + rndf(-30, 30);
         pos[1] = cy + rndf(-30, 30);
         pos[2] = rndf(-0.5f, 0.99f);         /* inside the seed's Z register */
         pos[3] = 1.0f;
         tris[t].v[k][1][0] = (float)t;
         tris[t].v[k][2][0] = rndf(-0.3f, 1.3f);
         memcpy(&tris[t].v[k][3][0], &vp, sizeof vp);
      }
   }
}

static uint8_t zbuf[TW * TH * 8], cbuf[TW * TH * 4];

struct exec { unsigned threads, opts, group; const char *name; };

/* Draws tris[0 .. ntri - 1]; returns the Z register's saturations. */
static uint64_t draw_scene_n(const struct rast_profile *p, enum rast_zs_layout l,
                             bool shader_depth, bool clamp, const struct rast_depth_range *ranges,
                             struct exec ex, struct seen *seen, unsigned ntri)
{
   const unsigned cpp = zs_cpp(l);
   memset(zbuf, 0, sizeof zbuf);
   memset(cbuf, 0, sizeof cbuf);
   memset(seen, 0xff, sizeof *seen);     /* tri -1: no fragment */
   struct rast_context *rc = rast_create(p);
   struct rast_framebuffer fb;
   memset(&fb, 0, sizeof fb);
   fb.width = TW;
   fb.height = TH;
   fb.nr_cbufs = 1;
   fb.cbuf[0] = (struct rast_color_target){ .base = cbuf, .stride = TW * 4, .cpp = 4,
                                            .layout = RAST_CL_RGBA8, .load = u8_load,
                                            .store = u8_store, .clamp = true };
   fb.zs = (struct rast_zs_target){ .base = zbuf, .stride = TW * (int)cpp, .layout = l };
   rast_set_framebuffer(rc, &fb);
   struct rast_raster_state rs;
   memset(&rs, 0, sizeof rs);
   rs.half_pixel_center = true;
   rs.line_width = 1.0f;
   rs.point_size = 1.0f;
   rs.depth_clamp = clamp;
   rast_set_raster_state(rc, &rs);
   set_plain_blend(rc);
   set_depth_test(rc, RAST_FUNC_ALWAYS);
   rast_set_depth_ranges(rc, 0, RAST_MAX_VIEWPORTS, ranges);
   struct rast_vertex_layout vl;
   memset(&vl, 0, sizeof vl);
   vl.vertex_size = 4;
   vl.num_varyings = 2;
   vl.varying[0] = (struct rast_varying){ .slot = 1, .interp = RAST_INTERP_CONSTANT,
                                          .usage_mask = 1 };
   vl.varying[1] = (struct rast_varying){ .slot = 2, .interp = RAST_INTERP_LINEAR,
                                          .usage_mask = 1 };
   vl.has_viewport_index = true;
   vl.viewport_slot = 3;
   rast_set_vertex_layout(rc, &vl);
   struct rast_shader fs;
   memset(&fs, 0, sizeof fs);
   fs.ctx = seen;
   fs.shade = shade_seen;
   fs.shade_n = ex.group ? shade_seen_n : NULL;
   fs.group = ex.group;
   fs.num_outputs = 1;
   fs.writes_depth = shader_depth;
   rast_set_shader(rc, &fs);
   rast_set_options(rc, ex.opts);
   if (!rast_set_threads(rc, ex.threads))
      CHECK(0, "%u threads did not start", ex.threads);
   for (unsigned t = 0; t < ntri; t++)
      rast_triangle(rc, (const float (*)[4])tris[t].v[0], (const float (*)[4])tris[t].v[1],
                    (const float (*)[4])tris[t].v[2]);
   rast_flush(rc);
   if (ex.threads > 1) {
      uint64_t serial, parallel;
      rast_get_flush_counts(rc, &serial, &parallel);
      CHECK(parallel > 0, "%s: nothing drawn on all threads", ex.name);
   }
   const struct fx_sat zsat = rast_get_stats(rc)->sat[RAST_REG_Z];
   rast_destroy(rc);
   return zsat.high + zsat.low;
}

static void draw_scene(const struct rast_profile *p, enum rast_zs_layout l, bool shader_depth,
                       bool clamp, const struct rast_depth_range *ranges, struct exec ex,
                       struct seen *seen)
{
   /* a thin triangle's slopes may saturate: the reference reads the
    * registers as walked, whatever they hold */
   (void)draw_scene_n(p, l, shader_depth, clamp, ranges, ex, seen, NTRI);
}

static uint32_t zbuf_get(enum rast_zs_layout l, int px)
{
   const uint8_t *b = zbuf + (size_t)px * zs_cpp(l);
   switch (l) {
   case RAST_ZS_Z16: return (uint32_t)b[0] | (uint32_t)b[1] << 8;
   case RAST_ZS_Z24_S8: return rd32(b) & 0xffffffu;
   default: return rd32(b);
   }
}

static void test_triangles(void)
{
   static const struct exec execs[] = {
      { 1, 0, 0, "one by one" },
      { 1, 0, 4, "groups" },
      { 2, RAST_OPT_DIVIDE, 4, "2 threads" },
      { 1, RAST_OPT_SCALAR, 0, "scalar" },
      { 2, RAST_OPT_DIVIDE | RAST_OPT_SCALAR | RAST_OPT_NOSKIP, 2, "2 threads scalar noskip" },
   };
   static const enum rast_zs_layout layouts[] = { RAST_ZS_Z24_S8, RAST_ZS_Z32F, RAST_ZS_Z16 };
   const char *profs[] = { "seed", "wide" };
   static struct seen seen;
   static uint8_t first[TW * TH * 8];
   const unsigned before = failures;
   uint64_t moved = 0, pixels = 0;

   for (unsigned scene = 0; scene < 6; scene++) {
      make_tris();
      struct rast_depth_range ranges[RAST_MAX_VIEWPORTS];
      for (unsigned i = 0; i < RAST_MAX_VIEWPORTS; i++)
         ranges[i] = random_range();
      ranges[1] = (struct rast_depth_range){ 0.8f, 0.3f };     /* reversed, always */
      for (unsigned pi = 0; pi < 2; pi++)
         for (unsigned li = 0; li < 3; li++)
            for (unsigned sh = 0; sh < 2; sh++)
               for (unsigned clamp = 0; clamp < 2; clamp++) {
                  const struct rast_profile *p = profile_named(profs[pi]);
                  const enum rast_zs_layout l = layouts[li];
                  struct ref_range ref[RAST_MAX_VIEWPORTS];
                  for (unsigned i = 0; i < RAST_MAX_VIEWPORTS; i++)
                     ref[i] = ref_range_of(p, ranges[i], clamp);
                  for (unsigned e = 0; e < sizeof execs / sizeof execs[0]; e++) {
                     draw_scene(p, l, sh, clamp, ranges, execs[e], &seen);
                     unsigned bad = 0, hit = 0;
                     for (int px = 0; px < TW * TH; px++) {
                        const uint32_t got = zbuf_get(l, px);
                        uint32_t want = 0;
                        if (seen.tri[px] >= 0) {
                           const unsigned vp = tris[seen.tri[px]].vp;
                           const struct ref_range r = ref[vp < RAST_MAX_VIEWPORTS ? vp
                                                         : RAST_MAX_VIEWPORTS - 1];
                           want = sh ? ref_clamped_shader(p, l, r, seen.d[px])
                                     : ref_clamped_reg(p, l, r, seen.z[px]);
                           const uint32_t plain = sh ? ref_zconv_shader(l, seen.d[px])
                                                     : ref_zconv_reg(p, l, seen.z[px]);
                           if (e == 0) {
                              moved += want != plain;
                              pixels++;
                           }
                           hit++;
                        }
                        if (got != want && !bad++)
                           CHECK(0, "scene %u %s %s %s depth%s, %s: pixel (%d, %d) of "
                                 "triangle %d: %08x, want %08x", scene, p->name, zs_name(l),
                                 sh ? "shader" : "register", clamp ? ", clamped" : "",
                                 execs[e].name, px % TW, px / TW, seen.tri[px], got, want);
                     }
                     CHECK(hit > TW * TH / 4, "scene %u: only %u pixels drawn", scene, hit);
                     if (e == 0)
                        memcpy(first, zbuf, sizeof first);
                     else
                        CHECK(!memcmp(first, zbuf, sizeof first), "scene %u %s %s: %s and %s "
                              "differ", scene, p->name, zs_name(l), execs[0].name,
                              execs[e].name);
                  }
               }
   }
   CHECK(moved > 0, "no pixel's depth was clamped: the test proves nothing");
   printf("part 2, triangles in viewports: %s (%llu of %llu pixels clamped)\n",
          failures == before ? "ok" : "FAILED", (unsigned long long)moved,
          (unsigned long long)pixels);
}

/* ------------------------------------------------------------------ */
/* Part 3: the Z register's reach.                                      */

/* A vertex depth beyond the Z register (seed 20.12: about [-1, 1); wide
 * 28.12: [-8, 8)) saturates at set-up and is counted in sat[RAST_REG_Z]
 * (FIXPIPE_STATS' "saturation z"); the fragments still land inside the
 * clamp's range.  One inside the register counts nothing. */
static void test_reach(void)
{
   const unsigned before = failures;
   static const struct { const char *prof; float z; bool sat; } t[] = {
      { "seed", 0.99f, false }, { "seed", 1.5f, true }, { "seed", -1.5f, true },
      { "wide", 1.5f, false }, { "wide", 7.5f, false }, { "wide", 9.0f, true },
   };
   static struct seen seen;
   for (unsigned k = 0; k < sizeof t / sizeof t[0]; k++) {
      const struct rast_profile *p = profile_named(t[k].prof);
      const enum rast_zs_layout l = RAST_ZS_Z24_S8;
      struct rast_depth_range ranges[RAST_MAX_VIEWPORTS];
      for (unsigned i = 0; i < RAST_MAX_VIEWPORTS; i++)
         ranges[i] = (struct rast_depth_range){ 0.2f, 0.6f };
      memset(&tris[0], 0, sizeof tris[0]);
      const float xy[3][2] = { { 2, 2 }, { TW - 2, 10 }, { 20, TH - 2 } };
      const float z[3] = { 0.4f, 0.45f, t[k].z };
      for (unsigned v = 0; v < 3; v++) {
         tris[0].v[v][0][0] = xy[v][0];
         tris[0].v[v][0][1] = xy[v][1];
         tris[0].v[v][0][2] = z[v];
         tris[0].v[v][0][3] = 1.0f;
      }
      const struct exec one = { 1, 0, 0, "one by one" };
      const uint64_t sat = draw_scene_n(p, l, false, true, ranges, one, &seen, 1);
      CHECK((sat > 0) == t[k].sat, "%s, a vertex at depth %g: %llu Z saturations", p->name,
            (double)t[k].z, (unsigned long long)sat);
      const struct ref_range r = ref_range_of(p, ranges[0], true);
      const uint32_t lo = ref_zconv_reg(p, l, (int64_t)r.lo), hi = ref_zconv_reg(p, l, (int64_t)r.hi);
      unsigned hit = 0, outside = 0;
      for (int px = 0; px < TW * TH; px++) {
         if (seen.tri[px] < 0)
            continue;
         hit++;
         const uint32_t got = zbuf_get(l, px);
         outside += got < lo || got > hi;
      }
      CHECK(hit > 0 && outside == 0, "%s, a vertex at depth %g: %u of %u pixels outside the "
            "range", p->name, (double)t[k].z, outside, hit);
   }
   printf("part 3, the Z register's reach: %s\n", failures == before ? "ok" : "FAILED");
}

/* ------------------------------------------------------------------ */
/* Part 4: primitives without a viewport index take viewport 0.          */

/* A triangle over the whole target at window depth z (slots as make_tris). */
static void whole_target(struct tri *t, float z, uint32_t vp)
{
   const float xy[3][2] = { { -4, -4 }, { 3 * TW, -4 }, { -4, 3 * TH } };
   memset(t, 0, sizeof *t);
   for (unsigned v = 0; v < 3; v++) {
      t->v[v][0][0] = xy[v][0];
      t->v[v][0][1] = xy[v][1];
      t->v[v][0][2] = z;
      t->v[v][0][3] = 1.0f;
      memcpy(&t->v[v][3][0], &vp, sizeof vp);
   }
}

/* A draw whose primitives take viewport 2 by their index, then one whose
 * layout has no index: GL draws the second with viewport 0, its scissor
 * and its depth range, whatever index the last primitive before it had. */
static void test_no_index(void)
{
   const unsigned before = failures;
   const struct rast_profile *p = profile_named("seed");
   const enum rast_zs_layout l = RAST_ZS_Z24_S8;
   static struct seen seen;
   memset(zbuf, 0, sizeof zbuf);
   memset(cbuf, 0, sizeof cbuf);
   memset(&seen, 0xff, sizeof seen);
   struct rast_context *rc = rast_create(p);
   struct rast_framebuffer fb;
   memset(&fb, 0, sizeof fb);
   fb.width = TW;
   fb.height = TH;
   fb.nr_cbufs = 1;
   fb.cbuf[0] = (struct rast_color_target){ .base = cbuf, .stride = TW * 4, .cpp = 4,
                                            .layout = RAST_CL_RGBA8, .load = u8_load,
                                            .store = u8_store, .clamp = true };
   fb.zs = (struct rast_zs_target){ .base = zbuf, .stride = TW * 4, .layout = l };
   rast_set_framebuffer(rc, &fb);
   struct rast_raster_state rs;
   memset(&rs, 0, sizeof rs);
   rs.half_pixel_center = true;
   rs.depth_clamp = true;
   rs.scissor = true;
   rast_set_raster_state(rc, &rs);
   set_plain_blend(rc);
   set_depth_test(rc, RAST_FUNC_ALWAYS);
   struct rast_depth_range ranges[RAST_MAX_VIEWPORTS];
   struct rast_scissor sc[RAST_MAX_VIEWPORTS];
   for (unsigned i = 0; i < RAST_MAX_VIEWPORTS; i++) {
      ranges[i] = (struct rast_depth_range){ 0.7f, 0.9f };
      sc[i] = (struct rast_scissor){ 0, 0, 8, 8 };
   }
   ranges[0] = (struct rast_depth_range){ 0.2f, 0.6f };
   sc[0] = (struct rast_scissor){ 0, 0, TW, TH };
   rast_set_depth_ranges(rc, 0, RAST_MAX_VIEWPORTS, ranges);
   rast_set_scissors(rc, 0, RAST_MAX_VIEWPORTS, sc);
   struct rast_vertex_layout vl;
   memset(&vl, 0, sizeof vl);
   vl.vertex_size = 4;
   vl.num_varyings = 2;
   vl.varying[0] = (struct rast_varying){ .slot = 1, .interp = RAST_INTERP_CONSTANT,
                                          .usage_mask = 1 };
   vl.varying[1] = (struct rast_varying){ .slot = 2, .interp = RAST_INTERP_LINEAR,
                                          .usage_mask = 1 };
   vl.has_viewport_index = true;
   vl.viewport_slot = 3;
   rast_set_vertex_layout(rc, &vl);
   struct rast_shader fs;
   memset(&fs, 0, sizeof fs);
   fs.ctx = &seen;
   fs.shade = shade_seen;
   fs.num_outputs = 1;
   rast_set_shader(rc, &fs);
   whole_target(&tris[0], 0.3f, 2);
   rast_triangle(rc, (const float (*)[4])tris[0].v[0], (const float (*)[4])tris[0].v[1],
                 (const float (*)[4])tris[0].v[2]);
   vl.has_viewport_index = false;
   rast_set_vertex_layout(rc, &vl);
   whole_target(&tris[0], 0.95f, 2);
   rast_triangle(rc, (const float (*)[4])tris[0].v[0], (const float (*)[4])tris[0].v[1],
                 (const float (*)[4])tris[0].v[2]);
   rast_flush(rc);
   rast_destroy(rc);
   const uint32_t want = ref_zconv_reg(p, l, (int64_t)ref_range_of(p, ranges[0], true).hi);
   unsigned bad = 0;
   for (int px = 0; px < TW * TH; px++)
      bad += zbuf_get(l, px) != want;
   CHECK(bad == 0, "%u of %u pixels not drawn with viewport 0's scissor and depth range "
         "(pixel (%d, %d): %08x, want %08x)", bad, TW * TH, TW - 1, TH - 1,
         zbuf_get(l, TW * TH - 1), want);
   printf("part 4, no index after an index: %s\n", failures == before ? "ok" : "FAILED");
}

int main(void)
{
   backend_seed("test_depth_clamp");
   test_quads();
   test_triangles();
   test_reach();
   test_no_index();
   return backend_summary();
}
