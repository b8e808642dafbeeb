/*
 * The back end's skips (backend.c, docs/datapath.md): a quad the early
 * depth/stencil test rejects whole is not shaded, a block of quads it
 * rejects whole makes no shader call, and a pass that writes no colour
 * (depth-only, stencil-only, colour mask 0) shades nothing.  Each is
 * counted (skip_early_quads, skip_shade_quads) and switched off by
 * RAST_OPT_NOSKIP, which shades every covered quad and tests after it:
 * the colour and depth/stencil buffers must be the same bytes both ways,
 * and the shader must see exactly the quads the skips do not count.  A
 * shader with side effects (rast_shader.side_effects: stores to memory)
 * must see every covered quad with the skips on, and with early_tests
 * (GL's early_fragment_tests) every quad but those the early test
 * rejects: the pixels are the same bytes all the same.
 */
#include <stdlib.h>
#include <string.h>

#include "tutil.h"

#define W 96
#define H 80

static uint64_t shaded_quads;

/* A colour from the pixel's place: any quad shaded at the wrong time
 * shows in the buffer. */
static unsigned shade_place(void *ctx, const struct rast_quad *q, struct rast_shaded_quad *out)
{
   (void)ctx;
   shaded_quads++;
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      const int x = q->x + (int)(i & 1), y = q->y + (int)(i >> 1);
      out->color[0][0][i] = (float)(x % 7) / 7.0f;
      out->color[0][1][i] = (float)(y % 5) / 5.0f;
      out->color[0][2][i] = (float)((x + y) % 3) / 3.0f;
      out->color[0][3][i] = 1.0f;
   }
   return q->mask;
}

static unsigned shade_place_n(void *ctx, const struct rast_quad *const q[],
                              struct rast_shaded_quad *const out[], unsigned n)
{
   unsigned kept = 0;
   for (unsigned i = 0; i < n; i++)
      kept |= shade_place(ctx, q[i], out[i]) << 4 * i;
   return kept;
}

struct pass {
   uint8_t color[W * H * 4];
   uint32_t zs[W * H];
   uint64_t shaded, early, unshaded, quads;
};

static void draw(struct rast_context *rc, float z, const float v[3][2])
{
   float vert[3][1][4];
   for (int i = 0; i < 3; i++) {
      vert[i][0][0] = v[i][0];
      vert[i][0][1] = v[i][1];
      vert[i][0][2] = z;
      vert[i][0][3] = 1.0f;
   }
   t_tri(rc, vert[0], vert[1], vert[2]);
}

/* The scene: a near triangle, a far one mostly behind it (early rejection
 * of whole quads and whole blocks), then a depth-only pass in front and a
 * triangle behind that (rejected where the depth-only pass wrote). */
static void scene(struct pass *p, unsigned opts, bool groups, bool side_effects, bool early_tests)
{
   struct rast_context *rc = rast_create(rast_profile_by_name("seed"));
   t_plain_state(rc);
   memset(p, 0, sizeof(*p));
   memset(p->zs, 0xff, sizeof(p->zs));
   t_bind_rgba8_z24s8(rc, p->color, p->zs, W, H);
   struct rast_shader fs;
   memset(&fs, 0, sizeof(fs));
   fs.shade = shade_place;
   if (groups) {
      fs.shade_n = shade_place_n;
      fs.group = 4;
   }
   fs.num_outputs = 1;
   fs.side_effects = side_effects;
   fs.early_tests = early_tests;
   rast_set_shader(rc, &fs);
   rast_set_options(rc, opts);
   struct rast_depth_stencil_state dsa;
   memset(&dsa, 0, sizeof(dsa));
   dsa.depth_enabled = true;
   dsa.depth_writemask = true;
   dsa.depth_func = RAST_FUNC_LESS;
   rast_set_depth_stencil(rc, &dsa);
   shaded_quads = 0;

   static const float near_tri[3][2] = { { 2.5f, 3.0f }, { 90.0f, 6.5f }, { 20.0f, 77.0f } };
   static const float far_tri[3][2] = { { 6.0f, 8.0f }, { 70.0f, 12.0f }, { 24.0f, 60.0f } };
   static const float front_tri[3][2] = { { 40.0f, 30.0f }, { 95.0f, 40.0f }, { 60.0f, 79.0f } };
   draw(rc, 0.3f, near_tri);
   draw(rc, 0.6f, far_tri);
   /* depth only: no colour channel written */
   struct rast_blend_state b;
   memset(&b, 0, sizeof b);
   b.rt[0].colormask = 0;
   rast_set_blend(rc, &b);
   draw(rc, 0.1f, front_tri);
   b.rt[0].colormask = 0xf;
   rast_set_blend(rc, &b);
   static const float back_tri[3][2] = { { 30.0f, 20.0f }, { 94.0f, 70.0f }, { 50.0f, 78.0f } };
   draw(rc, 0.2f, back_tri);
   /* no depth test and no colour: nothing but the count */
   memset(&dsa, 0, sizeof(dsa));
   rast_set_depth_stencil(rc, &dsa);
   b.rt[0].colormask = 0;
   rast_set_blend(rc, &b);
   draw(rc, 0.5f, far_tri);

   const struct rast_stats *st = rast_get_stats(rc);
   p->shaded = shaded_quads;
   p->early = st->skip_early_quads;
   p->unshaded = st->skip_shade_quads;
   p->quads = st->quads;
   rast_destroy(rc);
}

int main(void)
{
   static struct pass skip, ref, fx, fx_early;
   for (int groups = 0; groups < 2; groups++) {
      scene(&skip, 0, groups, false, false);
      scene(&ref, RAST_OPT_NOSKIP, groups, false, false);
      CHECK(!memcmp(skip.color, ref.color, sizeof(ref.color)),
            "groups %d: colour differs with the skips", groups);
      CHECK(!memcmp(skip.zs, ref.zs, sizeof(ref.zs)),
            "groups %d: depth/stencil differs with the skips", groups);
      CHECK(skip.quads == ref.quads && ref.quads > 0, "groups %d: quads %llu and %llu", groups,
            (unsigned long long)skip.quads, (unsigned long long)ref.quads);
      CHECK(ref.early == 0 && ref.unshaded == 0, "groups %d: noskip skipped %llu, %llu", groups,
            (unsigned long long)ref.early, (unsigned long long)ref.unshaded);
      CHECK(ref.shaded == ref.quads, "groups %d: noskip shaded %llu of %llu quads", groups,
            (unsigned long long)ref.shaded, (unsigned long long)ref.quads);
      CHECK(skip.early > 0 && skip.unshaded > 0, "groups %d: no skip taken (%llu, %llu)", groups,
            (unsigned long long)skip.early, (unsigned long long)skip.unshaded);
      /* every covered quad is shaded or counted as skipped, once */
      CHECK(skip.shaded + skip.early + skip.unshaded == skip.quads,
            "groups %d: %llu shaded + %llu rejected + %llu unshaded != %llu quads", groups,
            (unsigned long long)skip.shaded, (unsigned long long)skip.early,
            (unsigned long long)skip.unshaded, (unsigned long long)skip.quads);

      scene(&fx, 0, groups, true, false);
      CHECK(!memcmp(fx.color, ref.color, sizeof(ref.color)) &&
            !memcmp(fx.zs, ref.zs, sizeof(ref.zs)),
            "groups %d: side effects: the pixels differ from noskip's", groups);
      CHECK(fx.shaded == fx.quads && fx.quads == ref.quads && fx.early == 0 && fx.unshaded == 0,
            "groups %d: side effects: %llu of %llu quads shaded (%llu rejected, %llu unshaded)",
            groups, (unsigned long long)fx.shaded, (unsigned long long)fx.quads,
            (unsigned long long)fx.early, (unsigned long long)fx.unshaded);
      scene(&fx_early, 0, groups, true, true);
      CHECK(!memcmp(fx_early.color, ref.color, sizeof(ref.color)) &&
            !memcmp(fx_early.zs, ref.zs, sizeof(ref.zs)),
            "groups %d: early tests: the pixels differ from noskip's", groups);
      CHECK(fx_early.early == skip.early && fx_early.unshaded == 0 &&
            fx_early.shaded + fx_early.early == fx_early.quads,
            "groups %d: early tests: %llu shaded, %llu rejected (want %llu), %llu unshaded, "
            "%llu quads", groups, (unsigned long long)fx_early.shaded,
            (unsigned long long)fx_early.early, (unsigned long long)skip.early,
            (unsigned long long)fx_early.unshaded, (unsigned long long)fx_early.quads);
   }
   return t_summary("backend_skips");
}
