#include <getopt.h>
#include <math.h>
#include <string.h>
#include "tutil.h"

unsigned t_failures;

static uint64_t rng_state = 0x9E3779B97F4A7C15ull;

void t_seed(uint64_t s) { rng_state = s ? s : 1; }

static uint64_t rng(void)
{
   /* xorshift64*: reproducible across hosts */
   rng_state ^= rng_state >> 12;
   rng_state ^= rng_state << 25;
   rng_state ^= rng_state >> 27;
   return rng_state * 0x2545F4914F6CDD1Dull;
}

double t_rand(void)
{
   return (double)(rng() >> 11) * (1.0 / 9007199254740992.0);
}

unsigned t_shade_record(void *ctx, const struct rast_quad *q, struct rast_shaded_quad *out)
{
   struct tctx *t = ctx;
   (void)out;
   if ((q->x & 1) || (q->y & 1) || q->mask == 0 || q->mask > 15)
      t->badquad++;
   for (unsigned i = 0; i < 4; i++) {
      if (!(q->mask & (1u << i)))
         continue;
      int x = q->x + (int)(i & 1), y = q->y + (int)(i >> 1);
      if (x < t->minx) t->minx = x;
      if (x > t->maxx) t->maxx = x;
      if (y < t->miny) t->miny = y;
      if (y > t->maxy) t->maxy = y;
      if (x < 0 || y < 0 || x >= t->w || y >= t->h) {
         t->outside++;
         continue;
      }
      size_t idx = (size_t)y * (size_t)t->w + (size_t)x;
      if (t->stamp[idx] == t->id)
         t->dups++;
      t->stamp[idx] = t->id;
      if (t->counting && t->hits[idx] < 255)
         t->hits[idx]++;
      t->count++;
   }
   if (t->hook)
      t->hook(t, q);
   return 0;   /* discard everything: no framebuffer is touched */
}

void t_init(struct tctx *t, const char *profile, int w, int h)
{
   memset(t, 0, sizeof(*t));
   char err[256];
   t->profile_buf = malloc(sizeof(*t->profile_buf));
   if (!t->profile_buf || !rast_profile_parse(profile, t->profile_buf, err, sizeof(err))) {
      fprintf(stderr, "profile %s: %s\n", profile, err);
      exit(1);
   }
   t->prof = &t->profile_buf->p;
   t->rc = rast_create(t->prof);
   t->w = w;
   t->h = h;
   t->stamp = calloc((size_t)w * (size_t)h, sizeof(uint32_t));
   t->hits = calloc((size_t)w * (size_t)h, 1);
   if (!t->rc || !t->stamp || !t->hits)
      exit(1);

   struct rast_framebuffer fb;
   memset(&fb, 0, sizeof(fb));
   fb.width = (unsigned)w;
   fb.height = (unsigned)h;
   rast_set_framebuffer(t->rc, &fb);

   struct rast_vertex_layout vl = t_layout_pos();
   rast_set_vertex_layout(t->rc, &vl);

   struct rast_shader fs;
   memset(&fs, 0, sizeof(fs));
   fs.ctx = t;
   fs.shade = t_shade_record;
   fs.may_discard = true;
   fs.reads_fragcoord = true;       /* the hooks read every input */
   rast_set_shader(t->rc, &fs);
   t_raster(t, true, false);
}

void t_raster(struct tctx *t, bool half_pixel, bool bottom_rule)
{
   t_raster_scissor(t, half_pixel, bottom_rule, false);
}

void t_raster_scissor(struct tctx *t, bool half_pixel, bool bottom_rule, bool scissor)
{
   struct rast_raster_state rs;
   memset(&rs, 0, sizeof(rs));
   rs.half_pixel_center = half_pixel;
   rs.bottom_edge_rule = bottom_rule;
   rs.scissor = scissor;
   rs.cull = RAST_CULL_NONE;
   rs.line_width = 1.0f;
   rast_set_raster_state(t->rc, &rs);
}

void t_fini(struct tctx *t)
{
   rast_destroy(t->rc);
   free(t->stamp);
   free(t->hits);
   free(t->profile_buf);
}

void t_begin(struct tctx *t)
{
   t->id++;
   t->count = t->dups = t->outside = t->badquad = 0;
   t->minx = t->miny = 1 << 30;
   t->maxx = t->maxy = -(1 << 30);
}

uint64_t t_sat_class(const struct rast_stats *s, enum rast_reg_class c)
{
   return s->sat[c].high + s->sat[c].low;
}

uint64_t t_sat_total(const struct rast_stats *s)
{
   uint64_t n = 0;
   for (unsigned c = 0; c < RAST_REG_COUNT; c++)
      n += t_sat_class(s, (enum rast_reg_class)c);
   return n;
}

int t_summary(const char *name)
{
   if (t_failures) {
      printf("%s: %u failure(s)\n", name, t_failures);
      return 1;
   }
   printf("%s: all checks passed\n", name);
   return 0;
}

static inline bool edge_in(int64_t e, int64_t dcdx, int64_t dcdy, bool bottom_rule)
{
   if (e > 0)
      return true;
   if (e < 0)
      return false;
   if (dcdx < 0)
      return true;
   if (dcdx == 0)
      return bottom_rule ? dcdy < 0 : dcdy > 0;
   return false;
}

uint64_t t_ref_triangle(const int64_t Xin[3], const int64_t Yin[3], int64_t S, int64_t H,
                        bool bottom_rule, struct rast_scissor clip, t_visit visit, void *ctx)
{
   int64_t X[3] = { Xin[0], Xin[1], Xin[2] }, Y[3] = { Yin[0], Yin[1], Yin[2] };
   int64_t det = (X[0] - X[2]) * (Y[1] - Y[2]) - (Y[0] - Y[2]) * (X[1] - X[2]);
   if (det == 0)
      return 0;
   if (det > 0) {   /* llvmpipe's orientation: inside has all E > 0 */
      int64_t t;
      t = X[1]; X[1] = X[2]; X[2] = t;
      t = Y[1]; Y[1] = Y[2]; Y[2] = t;
   }
   int64_t dcdx[3], dcdy[3];
   for (int i = 0; i < 3; i++) {
      int k = (i + 1) % 3;
      dcdx[i] = Y[i] - Y[k];
      dcdy[i] = X[i] - X[k];
   }
   int64_t minx = X[0], maxx = X[0], miny = Y[0], maxy = Y[0];
   for (int i = 1; i < 3; i++) {
      if (X[i] < minx) minx = X[i];
      if (X[i] > maxx) maxx = X[i];
      if (Y[i] < miny) miny = Y[i];
      if (Y[i] > maxy) maxy = Y[i];
   }
   int64_t x0 = (minx - H) / S - 1, x1 = (maxx - H) / S + 1;
   int64_t y0 = (miny - H) / S - 1, y1 = (maxy - H) / S + 1;
   if (x0 < clip.minx) x0 = clip.minx;
   if (y0 < clip.miny) y0 = clip.miny;
   if (x1 > clip.maxx - 1) x1 = clip.maxx - 1;
   if (y1 > clip.maxy - 1) y1 = clip.maxy - 1;
   uint64_t n = 0;
   for (int64_t j = y0; j <= y1; j++) {
      int64_t py = j * S + H;
      for (int64_t i = x0; i <= x1; i++) {
         int64_t px = i * S + H;
         bool in = true;
         for (int e = 0; e < 3 && in; e++) {
            int64_t ev = dcdx[e] * (X[e] - px) - dcdy[e] * (Y[e] - py);
            in = edge_in(ev, dcdx[e], dcdy[e], bottom_rule);
         }
         if (in) {
            n++;
            if (visit)
               visit(ctx, (int)i, (int)j);
         }
      }
   }
   return n;
}

void t_load_rgba8(const uint8_t *src, unsigned n, float (*rgba)[4])
{
   for (unsigned i = 0; i < n; i++)
      for (unsigned c = 0; c < 4; c++)
         rgba[i][c] = src[4 * i + c] / 255.0f;
}

void t_store_rgba8(uint8_t *dst, unsigned n, const float (*rgba)[4])
{
   for (unsigned i = 0; i < n; i++)
      for (unsigned c = 0; c < 4; c++) {
         float v = rgba[i][c] < 0 ? 0 : rgba[i][c] > 1 ? 1 : rgba[i][c];
         dst[4 * i + c] = (uint8_t)(v * 255.0f + 0.5f);
      }
}

void t_plain_state(struct rast_context *rc)
{
   struct rast_vertex_layout vl = t_layout_pos();
   rast_set_vertex_layout(rc, &vl);
   struct rast_raster_state rs;
   memset(&rs, 0, sizeof rs);
   rs.half_pixel_center = true;
   rs.line_width = 1.0f;
   rs.point_size = 1.0f;
   rast_set_raster_state(rc, &rs);
   struct rast_blend_state b;
   memset(&b, 0, sizeof b);
   b.rt[0].colormask = 0xf;
   rast_set_blend(rc, &b);
}

void t_depth_count_hits(struct rast_context *rc, enum rast_func func)
{
   struct rast_depth_stencil_state dsa;
   memset(&dsa, 0, sizeof(dsa));
   dsa.depth_enabled = true;
   dsa.depth_writemask = true;
   dsa.depth_func = func;
   for (unsigned f = 0; f < 2; f++)
      dsa.stencil[f] = (struct rast_stencil_face){ true, RAST_FUNC_ALWAYS, RAST_STENCIL_KEEP,
                                                   RAST_STENCIL_INCR_WRAP,
                                                   RAST_STENCIL_INCR_WRAP, 0xff, 0xff };
   rast_set_depth_stencil(rc, &dsa);
}

void t_bind_rgba8_z24s8(struct rast_context *rc, uint8_t *color, uint32_t *zs, int w, int h)
{
   t_bind_rgba8_z24s8_samples(rc, color, zs, w, h, 1);
}

void t_bind_rgba8_z24s8_samples(struct rast_context *rc, uint8_t *color, uint32_t *zs, int w,
                                int h, unsigned samples)
{
   struct rast_framebuffer fb;
   memset(&fb, 0, sizeof(fb));
   fb.width = (unsigned)w;
   fb.height = (unsigned)h;
   fb.samples = samples;
   fb.nr_cbufs = 1;
   fb.cbuf[0] = (struct rast_color_target){ .base = color, .stride = w * 4, .cpp = 4,
                                            .layout = RAST_CL_RGBA8, .load = t_load_rgba8,
                                            .store = t_store_rgba8, .clamp = true,
                                            .sample_stride = (size_t)w * (size_t)h * 4 };
   fb.zs = (struct rast_zs_target){ .base = (uint8_t *)zs, .stride = w * 4,
                                    .layout = zs ? RAST_ZS_Z24_S8 : RAST_ZS_NONE,
                                    .sample_stride = (size_t)w * (size_t)h * 4 };
   rast_set_framebuffer(rc, &fb);
}

struct rast_vertex_layout t_layout_pos(void)
{
   struct rast_vertex_layout vl;
   memset(&vl, 0, sizeof(vl));
   vl.vertex_size = 1;
   vl.pos_slot = 0;
   return vl;
}

struct rast_varying *t_layout_add(struct rast_vertex_layout *vl, enum rast_interp interp,
                                  unsigned usage_mask)
{
   struct rast_varying *v = &vl->varying[vl->num_varyings++];
   *v = (struct rast_varying){ .slot = (uint8_t)vl->vertex_size++, .interp = (uint8_t)interp,
                               .usage_mask = (uint8_t)usage_mask };
   return v;
}

void t_layout_persp_color(struct rast_context *rc)
{
   struct rast_vertex_layout vl = t_layout_pos();
   t_layout_add(&vl, RAST_INTERP_PERSPECTIVE, 0x3);
   t_layout_add(&vl, RAST_INTERP_COLOR, 0xf);
   rast_set_vertex_layout(rc, &vl);
}

void t_count_seed_args(int argc, char **argv, const char *name, const char *count_name,
                       uint64_t max_count, uint64_t *count, uint64_t *seed)
{
   const struct option opts[] = {
      { count_name, required_argument, NULL, 'n' },
      { "seed", required_argument, NULL, 's' },
      { NULL, 0, NULL, 0 },
   };
   int c;
   while ((c = getopt_long(argc, argv, "", opts, NULL)) != -1) {
      if (c == '?')
         break;
      char *end = NULL;
      const unsigned long long v = strtoull(optarg, &end, 0);
      if (end == optarg || *end || (c == 'n' && v > max_count))
         break;
      if (c == 'n')
         *count = (uint64_t)v;
      else
         *seed = (uint64_t)v;
   }
   if (c != -1 || optind < argc) {
      fprintf(stderr, "usage: %s [--%s N] [--seed S]\n", name, count_name);
      exit(2);
   }
}

void t_scene_args(int argc, char **argv, const char *name, unsigned *scenes, uint64_t *seed)
{
   uint64_t n = *scenes;
   t_count_seed_args(argc, argv, name, "scenes", 0xffffffffu, &n, seed);
   *scenes = (unsigned)n;
}

unsigned t_shade_fetch_count(void *ctx, const struct rast_quad *q, struct rast_shaded_quad *out)
{
   (void)ctx;
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      out->color[0][0][i] = q->last[0][0][i] + 1.0f / 255.0f;
      out->color[0][1][i] = q->last[0][1][i];
      out->color[0][2][i] = 0.5f;
      out->color[0][3][i] = 1.0f;
   }
   return q->mask;
}

unsigned t_shade_fetch_count_n(void *ctx, const struct rast_quad *const q[],
                               struct rast_shaded_quad *const out[], unsigned n)
{
   unsigned kept = 0;
   for (unsigned i = 0; i < n; i++)
      kept |= t_shade_fetch_count(ctx, q[i], out[i]) << 4 * i;
   return kept;
}

static float t_snap4096(float v) { return roundf(v * 4096.0f) / 4096.0f; }

void t_random_slot_tri(struct t_slot_tri *tr, int w, int h)
{
   const double pick = t_rand();
   const float cx = (float)(w * t_rand()), cy = (float)(h * t_rand());
   const float r = pick < 0.3 ? 4.0f : pick < 0.8 ? 20.0f : 60.0f;
   for (int i = 0; i < 3; i++) {
      float *pos = tr->v[i][0];
      pos[0] = t_snap4096(cx + (float)(r * (2 * t_rand() - 1)));
      pos[1] = t_snap4096(cy + (float)(r * (2 * t_rand() - 1)));
      pos[2] = (float)t_rand();
      pos[3] = 1.0f / (float)(0.5 + 3.5 * t_rand());      /* 1/w */
      for (int s = 1; s < 4; s++)
         for (int c = 0; c < 4; c++)
            tr->v[i][s][c] = (float)(s == 2 ? t_rand() : 8 * t_rand() - 4);
   }
}

long double t_exact_plane(const int64_t X[3], const int64_t Y[3], const int64_t ra[3],
                          int64_t px, int64_t py)
{
   __extension__ typedef __int128 i128;
   const int64_t e1x = X[1] - X[0], e1y = Y[1] - Y[0], e2x = X[2] - X[0], e2y = Y[2] - Y[0];
   const int64_t qx = px - X[0], qy = py - Y[0];
   const i128 det = (i128)e1x * e2y - (i128)e1y * e2x;
   const i128 na = (i128)qx * e2y - (i128)qy * e2x, nb = (i128)e1x * qy - (i128)e1y * qx;
   const i128 num = na * (ra[1] - ra[0]) + nb * (ra[2] - ra[0]);
   return (long double)ra[0] + (long double)num / (long double)det;
}
