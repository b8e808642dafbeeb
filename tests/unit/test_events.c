/*
 * The event maps (rast/instruments/events.c, docs/events.md): which quads
 * an event is charged to, by the rule of events.h, on triangles whose
 * events are known in advance:
 *  - a triangle whose vertex colour is beyond the COLOR register (2.0 is
 *    510/255, above 9.12's 256/255): set-up events, on every quad it draws;
 *  - a triangle whose lower half has a left edge flatter than the dx/dy
 *    register holds (4080 pixels over about one scan line; 12.12 holds
 *    2048): the slope saturates when the edge is loaded, at scan line 39,
 *    inside the walk of quad row 38, so on that row's first quad alone;
 *  - an in-range triangle: on no quad.
 * Then: the same maps, byte for byte, on two threads with every batch
 * divided between them; the draws' counter differences add up to
 * rast_get_stats; and the counters are those of a run without the maps.
 */
#include <string.h>
#include "tutil.h"
#include "rast/instruments/events.h"

#define W 64
#define H 64
#define MAXQ 4096

struct rec_quad { int x, y; unsigned mask, tri; };
static struct rec_quad quads[MAXQ];
static unsigned nquads, cur_tri;

/* The shader: records the quads it is given when ctx is set (one thread
 * only: it writes shared memory), keeps no pixel.  tutil's recorder would
 * count into one tctx from every thread. */
static unsigned shade(void *ctx, const struct rast_quad *q, struct rast_shaded_quad *out)
{
   (void)out;
   if (ctx && nquads < MAXQ)
      quads[nquads++] = (struct rec_quad){ q->x, q->y, q->mask, cur_tri };
   return 0;
}

static void tri(struct rast_context *rc, const float p[3][2], float c)
{
   float v[3][2][4];
   for (unsigned k = 0; k < 3; k++) {
      v[k][0][0] = p[k][0];
      v[k][0][1] = p[k][1];
      v[k][0][2] = 0.5f;
      v[k][0][3] = 1.0f;
      for (unsigned i = 0; i < 4; i++)
         v[k][1][i] = c;
   }
   t_tri(rc, v[0], v[1], v[2]);
   rast_flush(rc);          /* queued on threads: the vertices must outlive the draw */
}

static const float tri_color[3][2] = { { 2, 2 }, { 40, 3 }, { 5, 30 } };
static const float tri_flat[3][2] = { { 10, 10 }, { -2040, 39.5f }, { 2040, 40.51f } };
static const float tri_plain[3][2] = { { 30, 44 }, { 62, 46 }, { 40, 62 } };

struct result {
   uint16_t map[RAST_EV_COUNT][W * H];
   uint64_t total[RAST_EV_COUNT], sum[RAST_EV_COUNT];
   struct rast_stats stats;
};

/* The three triangles, each a draw (flushed), with the maps attached or not. */
static void run(struct result *r, unsigned threads, bool attach, bool record)
{
   struct tctx t;
   t_init(&t, "seed", W, H);
   struct rast_vertex_layout vl = t_layout_pos();
   t_layout_add(&vl, RAST_INTERP_COLOR, 0xf);
   rast_set_vertex_layout(t.rc, &vl);
   struct rast_shader fs;
   memset(&fs, 0, sizeof(fs));
   fs.ctx = record ? &t : NULL;
   fs.shade = shade;
   fs.may_discard = true;
   fs.reads_fragcoord = true;
   rast_set_shader(t.rc, &fs);
   CHECK(rast_set_threads(t.rc, threads), "%u threads", threads);
   if (threads > 1)
      rast_set_options(t.rc, RAST_OPT_DIVIDE);
   struct rast_events *ev = attach ? rast_events_attach(t.rc) : NULL;
   CHECK(!attach || ev, "attach");
   if (ev)
      CHECK(rast_events_target(ev, true, W, H), "target");

   const float (*const scene[3])[2] = { tri_color, tri_flat, tri_plain };
   const float colors[3] = { 2.0f, 0.5f, 0.25f };
   memset(r->sum, 0, sizeof(r->sum));
   uint64_t before[RAST_EV_COUNT];
   for (unsigned c = 0; c < RAST_EV_COUNT; c++)
      before[c] = rast_ev_count(rast_get_stats(t.rc), (enum rast_ev_class)c);
   for (unsigned k = 0; k < 3; k++) {
      cur_tri = k;
      tri(t.rc, scene[k], colors[k]);
      for (unsigned c = 0; c < RAST_EV_COUNT; c++) {
         const uint64_t now = rast_ev_count(rast_get_stats(t.rc), (enum rast_ev_class)c);
         r->sum[c] += now - before[c];
         before[c] = now;
      }
   }
   r->stats = *rast_get_stats(t.rc);
   for (unsigned c = 0; c < RAST_EV_COUNT; c++)
      r->total[c] = rast_ev_count(&r->stats, (enum rast_ev_class)c);
   memset(r->map, 0, sizeof(r->map));
   if (ev) {
      for (unsigned c = 0; c < RAST_EV_COUNT; c++) {
         unsigned w, h;
         const uint16_t *m = rast_events_map(ev, (enum rast_ev_class)c, &w, &h);
         CHECK(m && w == W && h == H, "map %u", c);
         if (m && w == W && h == H)
            memcpy(r->map[c], m, sizeof(r->map[c]));
      }
      rast_events_detach(t.rc, ev);
   }
   t_fini(&t);
}

static void expect_quad(uint16_t *m, const struct rec_quad *q)
{
   for (unsigned i = 0; i < 4; i++) {
      const int x = q->x + (int)(i & 1), y = q->y + (int)(i >> 1);
      if (q->mask >> i & 1 && x >= 0 && y >= 0 && x < W && y < H)
         m[y * W + x]++;
   }
}

static unsigned marked(const uint16_t *m)
{
   unsigned n = 0;
   for (unsigned i = 0; i < W * H; i++)
      n += m[i] != 0;
   return n;
}

int main(void)
{
   static struct result one, two, off;
   static uint16_t want[RAST_EV_COUNT][W * H];
   nquads = 0;
   run(&one, 1, true, true);

   /* the expected maps from the quads the back end was given */
   const struct rec_quad *first38 = NULL;
   for (unsigned i = 0; i < nquads; i++) {
      if (quads[i].tri == 0)
         expect_quad(want[RAST_EV_COLOR], &quads[i]);
      if (quads[i].tri == 1 && quads[i].y == 38 && !first38)
         first38 = &quads[i];
   }
   CHECK(first38 != NULL, "the flat triangle drew nothing on row 38");
   if (first38)
      expect_quad(want[RAST_EV_DXDY], first38);
   CHECK(one.total[RAST_EV_COLOR] > 0 && one.total[RAST_EV_DXDY] == 1,
         "the scene's events: colour %llu, dx/dy %llu",
         (unsigned long long)one.total[RAST_EV_COLOR],
         (unsigned long long)one.total[RAST_EV_DXDY]);
   CHECK(marked(want[RAST_EV_COLOR]) > 100, "colour triangle covers %u pixels",
         marked(want[RAST_EV_COLOR]));
   for (unsigned c = 0; c < RAST_EV_COUNT; c++)
      CHECK(!memcmp(one.map[c], want[c], sizeof(want[c])),
            "map %s: %u pixels marked, %u expected", rast_ev_class_name((enum rast_ev_class)c),
            marked(one.map[c]), marked(want[c]));

   /* the counters: the draws add up, and the maps change none */
   run(&off, 1, false, false);
   for (unsigned c = 0; c < RAST_EV_COUNT; c++) {
      CHECK(one.sum[c] == one.total[c], "class %u: draws %llu, total %llu", c,
            (unsigned long long)one.sum[c], (unsigned long long)one.total[c]);
      CHECK(one.total[c] == off.total[c], "class %u: %llu with the maps, %llu without", c,
            (unsigned long long)one.total[c], (unsigned long long)off.total[c]);
   }
   CHECK(one.stats.quads == off.stats.quads && one.stats.triangles == off.stats.triangles &&
         one.stats.pixels_shaded == off.stats.pixels_shaded, "work counters differ");

   /* two threads, each batch divided: the same maps and counters */
   run(&two, 2, true, false);
   for (unsigned c = 0; c < RAST_EV_COUNT; c++) {
      CHECK(!memcmp(one.map[c], two.map[c], sizeof(one.map[c])),
            "map %s differs on two threads", rast_ev_class_name((enum rast_ev_class)c));
      CHECK(two.total[c] == one.total[c] && two.sum[c] == two.total[c],
            "class %u on two threads", c);
   }
   return t_summary("events");
}
