/*
 * Unit tests of the fragment back end (src/rast/backend/): colour (8-bit and float targets, blending, the affine lanes against the
 * scalar path, groups of quads and the depth test on them, colour masks and
 * routing, no shader), through the
 * public API (rast_create, rast_set_*, rast_validate, then rc->quad on
 * hand-made quads) against backend_fixture.h's per-pixel reference.
 * Seed of the random quads: FIXPIPE_TEST_SEED (default fixed), printed.
 */
#include "backend_fixture.h"

static void test_blend(void)
{
   static struct color_ctx cc;
   unsigned before = failures, combos = 0;

   for (unsigned fi = 0; fi < TF_COUNT; fi++) {
      const enum tfmt f = (enum tfmt)fi;
      for (unsigned eq = 0; eq < 5; eq++)
         for (unsigned sfac = 0; sfac <= RAST_BF_INV_SRC1_ALPHA; sfac++)
            for (unsigned dfac = 0; dfac <= RAST_BF_INV_SRC1_ALPHA; dfac++) {
               struct rast_context *rc = color_context(&cc, "seed", make_cbuf(f, cc.mem[0]));
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
               use_test_shader(rc, &cc.sd, 2, false);

               for (unsigned rep = 0; rep < 4; rep++) {
               static uint8_t old[CBUF_BYTES];
               color_fill_keep(&cc, 0, f, old);
               struct rast_quad q = random_quad();
               /* A quarter of the values outside [0, 1] (of a signed
                * target's, [-1, 1]): the clamps matter. */
               const float lo = f == TF_F32_SNORM ? -1.5f : -0.25f;
               for (unsigned o = 0; o < 2; o++)
                  for (unsigned c = 0; c < 4; c++)
                     for (unsigned i = 0; i < 4; i++)
                        cc.sd.color[o][c][i] = rndf(lo, 1.25f);
               rc->quad(rc, &q);

               const bool clampin = f != TF_F32;
               for (unsigned i = 0; i < 4; i++) {
                  const struct quad_px p = quad_pixel(&q, i, &cc.t[0], cc.mem[0], old);
                  if (!quad_covers(&q, i, p, cc.t[0].cpp, "blend"))
                     continue;
                  double s[4], s1[4], d[4], kk[4];
                  for (unsigned c = 0; c < 4; c++) {
                     s[c] = cc.sd.color[0][c][i];
                     s1[c] = cc.sd.color[1][c][i];
                     d[c] = dst_value(f, cb_get(f, &cc.t[0], old, p.x, p.y, c), c);
                     kk[c] = k[c];
                     if (clampin) {
                        s[c] = clamp_fmt(f, s[c]); s1[c] = clamp_fmt(f, s1[c]);
                        d[c] = clamp_fmt(f, d[c]); kk[c] = clamp_fmt(f, kk[c]);
                     }
                  }
                  for (unsigned c = 0; c < 4; c++) {
                     const double want = ref_blend(bt, c, s, s1, d, kk);
                     const float got = cb_get(f, &cc.t[0], cc.mem[0], p.x, p.y, c);
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
      cc[m].t[0] = make_cbuf(f, cc[m].mem[0]);
      bind_fb(rc[m], w, h, 1, cc[m].t, NULL, RAST_ZS_NONE);
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
            struct rast_context *rc = color_context(&cc, "wide", make_cbuf(f, cc.mem[0]));
            const struct rast_blend_state bs = over_blend(cm, blend);
            rast_set_blend(rc, &bs);
            use_test_shader(rc, &cc.sd, 1, false);
            static uint8_t old[CBUF_BYTES];
            color_fill_keep(&cc, 0, f, old);
            struct rast_quad q;
            memset(&q, 0, sizeof q);
            q.x = 4; q.y = 2; q.mask = 0xf;
            random_unorm8(cc.sd.color[0]);
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
                  d = clamp_fmt(f, d);
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
      struct rast_color_target cbufs[4];
      for (unsigned i = 0; i < 4; i++) {
         cbufs[i] = cc.t[i] = make_cbuf(fmts[i], cc.mem[i]);
         color_fill_random(&cc, i, fmts[i]);
      }
      cbufs[1].base = NULL;
      bind_fb(rc, W, H, 4, cbufs, NULL, RAST_ZS_NONE);
      set_plain_blend(rc);
      use_test_shader(rc, &cc.sd, mode == 2 ? 3 : 4, mode == 0);
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
   struct rast_context *rc = color_context(&cc, "seed", make_cbuf(TF_RGBA8, cc.mem[0]));
   set_plain_blend(rc);
   use_test_shader(rc, &cc.sd, 1, false);
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
   const struct rast_color_target t0 = make_cbuf(TF_RGBA8, cb);
   bind_fb(rc, W, H, 1, &t0, zs, RAST_ZS_Z24_S8);
   set_depth_test(rc, RAST_FUNC_ALWAYS);
   set_plain_blend(rc);
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
               const struct rast_color_target t0 = make_cbuf(TF_RGBA8, cb[m]);
               bind_fb(rc[m], fw, fh, 1, &t0, zs[m], s.layout);
               set_plain_blend(rc[m]);
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
   backend_seed("test_backend_color");
   test_ubyte();
   test_blend();
   test_affine_lanes();
   test_affine_groups();
   test_depth_groups();
   test_colormask();
   test_color_routing();
   test_no_shader();
   return backend_summary();
}
