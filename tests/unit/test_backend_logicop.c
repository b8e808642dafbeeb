/*
 * Unit tests of the fragment back end (src/rast/backend/): logic operations (every op, colour mask and format; behind the depth test
 * on two targets), through the
 * public API (rast_create, rast_set_*, rast_validate, then rc->quad on
 * hand-made quads) against backend_fixture.h's per-pixel reference.
 * Seed of the random quads: FIXPIPE_TEST_SEED (default fixed), printed.
 */
#include "backend_fixture.h"

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
            struct rast_context *rc = color_context(&cc, rnd(2) ? "seed" : "wide",
                                                    lop_cbuf(f, cc.mem[0]));
            struct rast_blend_state bs = over_blend(cm, true);   /* the op replaces it */
            bs.logicop_enable = true;
            bs.logicop_func = (enum rast_logicop)op;
            rast_set_blend(rc, &bs);
            use_test_shader(rc, &cc.sd, 1, false);

            for (unsigned rep = 0; rep < 3; rep++) {
               color_fill_keep(&cc, 0, f == LF_F32 ? TF_F32 : TF_RGBA8, old);
               struct rast_quad q = random_quad();
               for (unsigned c = 0; c < 4; c++)
                  for (unsigned i = 0; i < 4; i++)
                     cc.sd.color[0][c][i] = rnd(4) ? (float)rnd(256) / 255.0f
                                                   : rndf(-0.25f, 1.25f);
               rc->quad(rc, &q);

               const unsigned cpp = cc.t[0].cpp;
               for (unsigned i = 0; i < 4; i++) {
                  const struct quad_px p = quad_pixel(&q, i, &cc.t[0], cc.mem[0], old);
                  const uint8_t *px = p.now, *po = p.was;
                  if (!quad_covers(&q, i, p, cpp, "logic op"))
                     continue;
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
   cc.t[0] = lop_cbuf(LF_BGRA8, cc.mem[0]);
   cc.t[1] = lop_cbuf(LF_565, cc.mem[1]);
   memset(zs, 0, sizeof zs);          /* depth 0: GEQUAL passes, twice */
   bind_fb(rc, W, H, 2, cc.t, zs, RAST_ZS_Z24_S8);
   set_depth_test(rc, RAST_FUNC_GEQUAL);
   struct rast_blend_state bs;
   memset(&bs, 0, sizeof bs);
   bs.logicop_enable = true;
   bs.logicop_func = RAST_LOGICOP_XOR;
   bs.rt[0].colormask = 0xf;
   rast_set_blend(rc, &bs);
   use_test_shader(rc, &cc.sd, 1, true);
   for (unsigned b = 0; b < 2; b++)
      color_fill_keep(&cc, b, TF_RGBA8, old[b]);
   random_unorm8(cc.sd.color[0]);
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
         const struct quad_px p = quad_pixel(&q, i, &cc.t[b], cc.mem[b], old[b]);
         const uint8_t *px = p.now, *po = p.was;
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

int main(void)
{
   backend_seed("test_backend_logicop");
   test_logicop();
   test_logicop_paths();
   return backend_summary();
}
