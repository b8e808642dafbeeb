/*
 * Unit tests of the fragment back end (src/rast/backend/): the depth and stencil stage (depth conversions, functions, buffer units,
 * stencil operations, early and late tests), through the
 * public API (rast_create, rast_set_*, rast_validate, then rc->quad on
 * hand-made quads) against backend_fixture.h's per-pixel reference.
 * Seed of the random quads: FIXPIPE_TEST_SEED (default fixed), printed.
 */
#include "backend_fixture.h"

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
         const struct rast_color_target t0 = make_cbuf(TF_RGBA8, cb);
         bind_fb(rc, W, H, 1, &t0, zs, RAST_ZS_Z24_S8);
         set_plain_blend(rc);
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
         use_test_shader(rc, &sd, 1, false);

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

/* A depth-only pass on zs in layout l (no colour buffer, the shader sd
 * has no output): depth ALWAYS, written. */
static struct rast_context *depth_only(const struct rast_profile *p, struct shader_data *sd,
                                       uint8_t *zs, enum rast_zs_layout l)
{
   struct rast_context *rc = rast_create(p);
   bind_fb(rc, W, H, 0, NULL, zs, l);
   set_depth_test(rc, RAST_FUNC_ALWAYS);
   use_test_shader(rc, sd, 0, false);
   return rc;
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
      struct shader_data sd;
      struct rast_context *rc = depth_only(p, &sd, zs, t[k].l);
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
   struct shader_data sd;
   struct rast_context *rc = depth_only(p, &sd, zs, RAST_ZS_Z16);
   struct rast_quad q;
   memset(&q, 0, sizeof q);
   q.mask = 1;
   q.z[0] = (int64_t)300000 << 12;
   rc->quad(rc, &q);
   set_depth_test(rc, RAST_FUNC_EQUAL);
   rast_validate(rc);
   q.z[0] += 1;     /* 1/4096 of a register unit: far below one Z16 code */
   rast_reset_stats(rc);
   rc->quad(rc, &q);
   CHECK(rast_get_stats(rc)->samples_passed == 1, "EQUAL in buffer units must pass");
   set_depth_test(rc, RAST_FUNC_LESS);
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

int main(void)
{
   backend_seed("test_backend_zs");
   test_depth_conversion_fixed();
   test_depth_conversion_mul();
   test_popcount16();
   test_depth_buffer_units();
   test_depth_funcs();
   test_stencil_ops_fixed();
   test_stencil();
   test_early_late();
   return backend_summary();
}
