/*
 * RTL test vectors of the scan-converter unit (seed 000; docs/vectors.md):
 * what enters the unit for each triangle (the Table 1 registers of its
 * three vertices, as set up) and what leaves it for each quad (coverage and
 * the per-pixel registers), as $readmemh files an RTL testbench loads.
 *
 * Recording sits at the unit's two boundaries, as observers the units call
 * when installed: rast_triangle_pass hands the input registers over
 * (vec_triangle) and the back end's quad function is wrapped (vec_quad)
 * while the triangle is scanned.  The replay (src/verify/vectors_replay.c)
 * feeds the registers to rast_setup_from_registers (setup.c), the same code
 * from the registers on, and checks the quads' records as they leave.
 *
 * Files in DIR: scan.in.hex (VEC_IN_WORDS words a triangle), scan.out.hex
 * (VEC_OUT_WORDS a quad), 64-bit words in hexadecimal, one a line, each
 * record opened by a // comment; scan.txt: the profile, the interpolator
 * and the counts.
 */
#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fixed/numsys.h"
#include "rast/setup/front.h"
#include "rast/tex/tex.h"
#include "rast/tex/tex_ns.h"
#include "rast/instruments/vectors.h"

#define VEC_TEX_DUMPED 64       /* bindings written in the current draw */

struct rast_vectors {
   /* recording */
   char dir[512];
   FILE *in, *out;
   unsigned long first, last, frame;
   unsigned units;                 /* RAST_VEC_* */
   bool active;
   uint64_t triangles, quads, skipped;
   /* checking (the replay, src/verify): each quad's record handed over */
   rast_vec_check_fn check;
   void *check_ctx;
   uint64_t tri_index;
   /* the triangle being scanned has a record: its quads get theirs */
   bool tri_recorded;
   /* the texture unit's: bindings written in this draw (serial -> index) */
   FILE *tbind, *tin, *tout;
   uint32_t dumped_serial[VEC_TEX_DUMPED], dumped_index[VEC_TEX_DUMPED];
   unsigned ndumped;
   uint64_t tex_binds, tex_quads, tex_skipped;
};

static void vec_install(struct rast_context *rc, struct rast_vectors *v);

uint32_t rast_vec_fbits(float f)
{
   uint32_t u;
   memcpy(&u, &f, sizeof(u));
   return u;
}

float rast_vec_bitsf(uint32_t u)
{
   float f;
   memcpy(&f, &u, sizeof(f));
   return f;
}

/* ---- recording ---- */

static void write_header(const struct rast_context *rc, const struct rast_vectors *v)
{
   char path[600];
   snprintf(path, sizeof(path), "%s/scan.txt", v->dir);
   FILE *f = fopen(path, "w");
   if (!f)
      return;
   fprintf(f, "units scan persp\nprofile %s\ninterp %s\ntexfmt %s\nin_words %u\n"
           "out_words %u\ncolor_components_max %u\nperspective_components_max %u\ntriangles %" PRIu64 "\nquads %" PRIu64 "\n"
           "triangles_not_recorded %" PRIu64 "\ntex_in_words %u\ntex_out_words %u\n"
           "tex_bindings %" PRIu64 "\ntex_quads %" PRIu64 "\ntex_quads_not_recorded %" PRIu64
           "\n", rc->profile->name,
           rast_interp_name((enum rast_interp_mode)(rc->interp & 3u)), rc->texfmt->name,
           VEC_IN_WORDS, VEC_OUT_WORDS, VEC_MAX_COLOR, VEC_MAX_PERSP, v->triangles, v->quads,
           v->skipped, VEC_TEX_IN_WORDS, VEC_TEX_OUT_WORDS, v->tex_binds, v->tex_quads,
           v->tex_skipped);
   if (v->last == ~0ul)
      fprintf(f, "frames %lu-\n", v->first);
   else
      fprintf(f, "frames %lu-%lu\n", v->first, v->last);
   fclose(f);
}

bool rast_vectors_open(struct rast_context *rc, const char *dir, unsigned long first,
                       unsigned long last, unsigned units, char *err, size_t errlen)
{
   struct rast_vectors *v = calloc(1, sizeof(*v));
   if (!v || strlen(dir) >= sizeof(v->dir)) {
      snprintf(err, errlen, "%s", v ? "directory name too long" : "out of memory");
      free(v);
      return false;
   }
   strcpy(v->dir, dir);
   char path[600];
   snprintf(path, sizeof(path), "%s/scan.in.hex", dir);
   v->in = fopen(path, "w");
   snprintf(path, sizeof(path), "%s/scan.out.hex", dir);
   v->out = v->in ? fopen(path, "w") : NULL;
   snprintf(path, sizeof(path), "%s/tex.bind.hex", dir);
   v->tbind = v->out ? fopen(path, "w") : NULL;
   snprintf(path, sizeof(path), "%s/tex.in.hex", dir);
   v->tin = v->tbind ? fopen(path, "w") : NULL;
   snprintf(path, sizeof(path), "%s/tex.out.hex", dir);
   v->tout = v->tin ? fopen(path, "w") : NULL;
   if (!v->tout) {
      snprintf(err, errlen, "cannot write %s: %s", path, strerror(errno));
      FILE *fs[] = { v->in, v->out, v->tbind, v->tin };
      for (unsigned i = 0; i < 4; i++)
         if (fs[i])
            fclose(fs[i]);
      free(v);
      return false;
   }
   fprintf(v->tbind, "// fixpipe texture-unit bindings: 8 words, then each level's 3 words "
           "and texels (docs/vectors.md)\n");
   fprintf(v->tin, "// fixpipe texture-unit inputs, %u words a quad (docs/vectors.md)\n",
           VEC_TEX_IN_WORDS);
   fprintf(v->tout, "// fixpipe texture-unit outputs, %u words a quad (docs/vectors.md)\n",
           VEC_TEX_OUT_WORDS);
   v->first = first;
   v->last = last;
   v->units = units;
   v->active = first == 0;
   fprintf(v->in, "// fixpipe scan-unit inputs, %u words a triangle (docs/vectors.md)\n",
           VEC_IN_WORDS);
   fprintf(v->out, "// fixpipe scan-unit outputs, %u words a quad (docs/vectors.md)\n",
           VEC_OUT_WORDS);
   vec_install(rc, v);
   write_header(rc, v);
   return true;
}

void rast_vectors_frame(struct rast_context *rc, unsigned long frames)
{
   struct rast_vectors *v = rc->vec;
   if (!v || !v->in)
      return;
   v->frame = frames;
   v->active = frames >= v->first && frames <= v->last;
   fflush(v->in);
   fflush(v->out);
   fflush(v->tbind);
   fflush(v->tin);
   fflush(v->tout);
   write_header(rc, v);
}

void rast_vectors_close(struct rast_context *rc)
{
   struct rast_vectors *v = rc->vec;
   if (!v)
      return;
   if (v->in) {
      write_header(rc, v);
      fclose(v->in);
      fclose(v->out);
      fclose(v->tbind);
      fclose(v->tin);
      fclose(v->tout);
   }
   free(v);
   rc->vec = NULL;
   rc->observe_triangle = NULL;
   rc->observe_backend = NULL;
   rc->dirty = true;
}

static void put(FILE *f, uint64_t w)
{
   fprintf(f, "%016" PRIx64 "\n", w);
}

/* Four 32-bit values of a quad's pixels in two words: pixels 0, 1 in the
 * first (low half first), 2, 3 in the second. */
static void pair4(const uint32_t v[4], uint64_t *w)
{
   w[0] = v[0] | (uint64_t)v[1] << 32;
   w[1] = v[2] | (uint64_t)v[3] << 32;
}

static void unpair4(const uint64_t *w, uint32_t v[4])
{
   v[0] = (uint32_t)w[0];
   v[1] = (uint32_t)(w[0] >> 32);
   v[2] = (uint32_t)w[1];
   v[3] = (uint32_t)(w[1] >> 32);
}

/* A quad's record and its words in scan.out.hex (docs/vectors.md), both ways. */
static void quad_to_words(const struct rast_vec_quad *r, uint64_t w[VEC_OUT_WORDS])
{
   w[0] = r->tri | (uint64_t)r->mask << 32 | (uint64_t)r->front << 36;
   w[1] = (uint32_t)r->x | (uint64_t)(uint32_t)r->y << 32;
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
      w[2 + i] = (uint64_t)r->z[i];
   pair4(r->w, &w[6]);
   for (unsigned c = 0; c < VEC_MAX_COLOR; c++)
      pair4(r->color[c], &w[8 + 2 * c]);
   for (unsigned j = 0; j < VEC_MAX_PERSP; j++) {
      pair4(r->persp[j], &w[VEC_OUT_SCAN + 2 * j]);
      pair4(r->pword[j], &w[VEC_OUT_SCAN + 2 * VEC_MAX_PERSP + 2 * j]);
   }
}

void rast_vec_words_to_quad(const uint64_t w[VEC_OUT_WORDS], struct rast_vec_quad *r)
{
   memset(r, 0, sizeof(*r));
   r->tri = (uint32_t)w[0];
   r->mask = (unsigned)(w[0] >> 32) & 0xfu;
   r->front = (w[0] >> 36) & 1u;
   r->x = (int32_t)(uint32_t)w[1];
   r->y = (int32_t)(uint32_t)(w[1] >> 32);
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
      r->z[i] = (int64_t)w[2 + i];
   unpair4(&w[6], r->w);
   for (unsigned c = 0; c < VEC_MAX_COLOR; c++)
      unpair4(&w[8 + 2 * c], r->color[c]);
   for (unsigned j = 0; j < VEC_MAX_PERSP; j++) {
      unpair4(&w[VEC_OUT_SCAN + 2 * j], r->persp[j]);
      unpair4(&w[VEC_OUT_SCAN + 2 * VEC_MAX_PERSP + 2 * j], r->pword[j]);
   }
}

/* A value of the number system as its register holds it: a dfx word
 * ([23] sign, [22:19] L, [18:0] M for dfx24), an M.N value in two's
 * complement, binary32 bits. */
static uint64_t ns_word(const struct numsys *ns, ns_val a)
{
   switch (ns->family) {
   case NUMSYS_DFX: return dfx_pack(ns->dfx, a.d);
   case NUMSYS_FIXED: return (uint64_t)a.x;
   default: return rast_vec_fbits(a.f);
   }
}

/* A divided value as the division's register held it: the shader's float
 * converted back, exact in a dfx system (a mantissa of at most 24 bits);
 * 0 in the others, whose results binary32 cannot always hold. */
static uint32_t divided_word(const struct numsys *ns, bool color, float f)
{
   struct ns_stats st = { 0, 0 };
   if (color || ns->family != NUMSYS_DFX)
      return 0;
   return (uint32_t)ns_word(ns, ns->from_float(ns, f, &st));
}

/* The triangle's colour components, at most VEC_MAX_COLOR; false if more. */
static bool color_map(const struct rast_front *fr, uint64_t *map)
{
   if (fr->ncolor > VEC_MAX_COLOR)
      return false;
   *map = 0;
   for (unsigned i = 0; i < fr->ncolor; i++)
      *map |= (uint64_t)((fr->color[i].var & 0x1fu) << 2 | (fr->color[i].chan & 3u)) << (7 * i);
   return true;
}

static void vec_triangle(struct rast_context *rc, const struct rast_front *fr, bool front)
{
   struct rast_vectors *v = rc->vec;
   uint64_t map;
   v->tri_recorded = false;
   if (!v->in || !v->active || !(v->units & RAST_VEC_SCAN))
      return;
   if (!color_map(fr, &map) || fr->npersp > VEC_MAX_PERSP || rc->vl.num_varyings > 32) {
      v->skipped++;
      return;
   }
   FILE *f = v->in;
   fprintf(f, "// triangle %" PRIu64 "\n", v->triangles);
   put(f, (uint64_t)rc->rs.half_pixel_center | (uint64_t)rc->rs.bottom_edge_rule << 1 |
          (uint64_t)rc->rs.front_ccw << 2 | (uint64_t)front << 3 | (uint64_t)fr->ncolor << 8 |
          (uint64_t)fr->npersp << 16);
   put(f, (uint32_t)rc->org_x | (uint64_t)(uint32_t)rc->org_y << 32);
   put(f, (uint64_t)(uint16_t)rc->clip.minx | (uint64_t)(uint16_t)rc->clip.maxx << 16 |
          (uint64_t)(uint16_t)rc->clip.miny << 32 | (uint64_t)(uint16_t)rc->clip.maxy << 48);
   for (unsigned k = 0; k < 3; k++)
      put(f, (uint64_t)fr->X[k]);
   for (unsigned k = 0; k < 3; k++)
      put(f, (uint64_t)fr->Y[k]);
   for (unsigned k = 0; k < 3; k++)
      put(f, (uint64_t)fr->vfix[k][0]);
   for (unsigned k = 0; k < 3; k++)
      put(f, rast_vec_fbits(fr->vflt[k][0]));
   put(f, map);
   for (unsigned i = 0; i < VEC_MAX_COLOR; i++)
      for (unsigned k = 0; k < 3; k++)
         put(f, i < fr->ncolor ? (uint64_t)fr->vfix[k][1 + i] : 0);
   /* the perspective division's: its components, then A/w at each vertex */
   uint64_t pmap[2] = { 0, 0 };
   for (unsigned j = 0; j < fr->npersp; j++)
      pmap[j / 8] |= (uint64_t)((fr->persp[j].var & 0x1fu) << 2 | (fr->persp[j].chan & 3u) |
                                (unsigned)fr->tex.is_color[j] << 7) << (8 * (j % 8));
   put(f, pmap[0]);
   put(f, pmap[1]);
   const unsigned p0 = 1 + fr->nlin;          /* vflt[]: 1/w, LINEAR, PERSPECTIVE */
   for (unsigned j = 0; j < VEC_MAX_PERSP; j++)
      for (unsigned k = 0; k < 3; k++)
         put(f, j < fr->npersp ? rast_vec_fbits(fr->vflt[k][p0 + j]) : 0);
   /* the division's set-up: 1/det and k (det·2^-k in [1/2, 1)), the planes */
   const struct fr_tex *t = &fr->tex;
   const bool div = fr->npersp > 0;
   put(f, div ? (ns_word(t->ns, t->rdet) & ((UINT64_C(1) << 56) - 1)) | (uint64_t)t->k << 56
              : 0);
   for (unsigned p = 0; p < 1 + VEC_MAX_PERSP; p++) {
      const bool on = div && p <= fr->npersp;
      const struct numsys *ns = p && on && t->is_color[p - 1] ? t->fns : t->ns;
      put(f, on ? ns_word(ns, t->pl[p].v0) : 0);
      put(f, on ? ns_word(ns, t->pl[p].d1) : 0);
      put(f, on ? ns_word(ns, t->pl[p].d2) : 0);
   }
   v->tri_index = v->triangles++;
   v->tri_recorded = true;
}

/* The quad's record, written (recording) or handed to the replay's check;
 * then the back end's own quad function. */
static void vec_quad(struct rast_context *rc, struct rast_quad *q)
{
   struct rast_vectors *v = rc->vec;
   if (rc->scanning_triangle && v->tri_recorded) {
      const struct rast_front *fr = rast_front(rc);
      struct rast_vec_quad r;
      memset(&r, 0, sizeof(r));
      r.tri = v->tri_index;
      r.mask = q->mask;
      r.front = q->front_facing;
      r.x = q->x;
      r.y = q->y;
      for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
         r.z[i] = q->z[i];
         r.w[i] = rast_vec_fbits(q->frag_w[i]);
      }
      for (unsigned c = 0; c < fr->ncolor && c < VEC_MAX_COLOR; c++)
         for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
            r.color[c][i] = rast_vec_fbits(q->in[fr->color[c].var][fr->color[c].chan][i]);
      for (unsigned j = 0; j < fr->npersp && j < VEC_MAX_PERSP; j++)
         for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
            const float d = q->in[fr->persp[j].var][fr->persp[j].chan][i];
            r.persp[j][i] = rast_vec_fbits(d);
            r.pword[j][i] = divided_word(fr->tex.ns, fr->tex.is_color[j], d);
         }
      if (v->in) {
         uint64_t w[VEC_OUT_WORDS];
         quad_to_words(&r, w);
         fprintf(v->out, "// quad %" PRIu64 "\n", v->quads);
         for (unsigned i = 0; i < VEC_OUT_WORDS; i++)
            put(v->out, w[i]);
         v->quads++;
      } else if (v->check) {
         v->check(v->check_ctx, &r);
      }
   }
   rc->vec_next_quad(rc, q);
}

static void vec_wrap_backend(struct rast_context *rc)
{
   rc->vec_next_quad = rc->quad;
   rc->quad = vec_quad;
   rc->quads = NULL;     /* one quad at a time: the order the unit emits them */
}

/* The recorder observes set-up and the back end from outside: the units
 * call whatever observer is installed (rast_context.observe_*). */
static void vec_install(struct rast_context *rc, struct rast_vectors *v)
{
   rc->vec = v;
   rc->observe_triangle = vec_triangle;
   rc->observe_backend = vec_wrap_backend;
   rc->dirty = true;           /* the back end's quad function gets wrapped */
}

bool rast_vectors_check_open(struct rast_context *rc, rast_vec_check_fn check, void *ctx)
{
   struct rast_vectors *v = calloc(1, sizeof(*v));
   if (!v)
      return false;
   v->check = check;
   v->check_ctx = ctx;
   v->active = true;
   vec_install(rc, v);
   rc->observe_triangle = NULL;   /* the replay enters set-up from the registers */
   return true;
}

void rast_vectors_check_triangle(struct rast_context *rc, uint64_t index)
{
   rc->vec->tri_index = index;
   rc->vec->tri_recorded = true;
}

/* ---- the texture unit ---- */

bool rast_vectors_on(const struct rast_context *rc)
{
   return rc->vec && rc->vec->in && rc->vec->active;
}

void rast_vectors_draw(struct rast_context *rc)
{
   if (rc->vec)
      rc->vec->ndumped = 0;
}

uint64_t rast_vec_two(float a, float b)
{
   return rast_vec_fbits(a) | (uint64_t)rast_vec_fbits(b) << 32;
}

/* Pixels 0, 1 (word a) and 2, 3 (word b) of a coordinate as the unit's
 * register: binary32 rounded toward -inf into the number system (a dfx
 * word, an M.N value's low 32 bits, binary32 bits). */
void rast_vec_coord_words(const struct tex_unit *u, const float c[4], uint64_t *a, uint64_t *b)
{
   struct ns_stats st = { 0, 0 };
   uint32_t w[4];
   for (unsigned i = 0; i < 4; i++)
      w[i] = (uint32_t)ns_word(u->ns, tex_ns_coord(u->ns, tex_ns_kind(u->ns), c[i], &st));
   *a = w[0] | (uint64_t)w[1] << 32;
   *b = w[2] | (uint64_t)w[3] << 32;
}

/* The bytes of a level the unit can read. */
static uint64_t level_bytes(const struct tex_view_desc *d, const struct tex_level *lv)
{
   const int64_t images = d->target == TEX_TARGET_3D ? lv->d : d->layers > 1 ? d->layers : 1;
   return images > 1 ? (uint64_t)lv->img_stride * (uint64_t)images
                     : (uint64_t)lv->row_stride * (uint64_t)lv->h;
}

/* The binding's record: its descriptors, then every level's texels. */
static void write_binding(struct rast_vectors *v, const struct tex_unit *u, uint32_t index)
{
   FILE *f = v->tbind;
   const struct tex_view_desc *d = &u->view;
   const struct tex_sampler_desc *s = &u->samp;
   fprintf(f, "// binding %u\n", index);
   put(f, index);
   put(f, (uint64_t)d->target | (uint64_t)d->format << 8 | (uint64_t)d->depth << 16 |
          (uint64_t)d->num_levels << 24);
   put(f, (uint32_t)d->layers | (uint64_t)d->swizzle[0] << 32 | (uint64_t)d->swizzle[1] << 40 |
          (uint64_t)d->swizzle[2] << 48 | (uint64_t)d->swizzle[3] << 56);
   put(f, (uint64_t)s->wrap[0] | (uint64_t)s->wrap[1] << 8 | (uint64_t)s->wrap[2] << 16 |
          (uint64_t)s->min_filter << 24 | (uint64_t)s->mag_filter << 32 |
          (uint64_t)s->mip << 40 | (uint64_t)s->normalized << 48 |
          (uint64_t)s->compare << 49 | (uint64_t)s->func << 52);
   put(f, rast_vec_two(s->lod_bias, s->min_lod));
   put(f, rast_vec_fbits(s->max_lod));
   put(f, rast_vec_two(s->border[0], s->border[1]));
   put(f, rast_vec_two(s->border[2], s->border[3]));
   for (unsigned l = 0; l < d->num_levels; l++) {
      const struct tex_level *lv = &d->level[l];
      const uint64_t bytes = level_bytes(d, lv);
      put(f, (uint32_t)lv->w | (uint64_t)(uint32_t)lv->h << 32);
      put(f, (uint32_t)lv->d | bytes << 32);
      put(f, lv->row_stride | (uint64_t)lv->img_stride << 32);
      for (uint64_t b = 0; b < bytes; b += 8) {
         uint64_t w = 0;
         const uint64_t n = bytes - b < 8 ? bytes - b : 8;
         memcpy(&w, lv->data + b, n);          /* little-endian: byte 0 in bits 7:0 */
         put(f, w);
      }
   }
}

void rast_vectors_tex(struct rast_context *rc, const struct tex_unit *u,
                      const struct tex_quad *q, unsigned n, unsigned ctl,
                      const float (*rgba)[4][4])
{
   struct rast_vectors *v = rc->vec;
   if (!rast_vectors_on(rc) || !(v->units & RAST_VEC_TEX))
      return;
   /* formats the driver decodes (callbacks: depth, compressed) are not the unit's */
   if (u->view.format == TEX_FMT_CALLBACK) {
      v->tex_skipped += n;
      return;
   }
   unsigned k = 0;
   while (k < v->ndumped && v->dumped_serial[k] != u->bind_serial)
      k++;
   if (k == v->ndumped) {
      if (k == VEC_TEX_DUMPED) {
         v->tex_skipped += n;
         return;
      }
      v->dumped_serial[k] = u->bind_serial;
      v->dumped_index[k] = (uint32_t)v->tex_binds++;
      v->ndumped++;
      write_binding(v, u, v->dumped_index[k]);
   }
   for (unsigned i = 0; i < n; i++) {
      const struct tex_quad *t = &q[i];
      fprintf(v->tin, "// quad %" PRIu64 "\n", v->tex_quads);
      put(v->tin, v->dumped_index[k] | (uint64_t)ctl << 32);
      const float *in[12] = { t->s, t->t, t->r, t->layer, t->ref, t->lod, t->ddx[0], t->ddx[1],
                              t->ddx[2], t->ddy[0], t->ddy[1], t->ddy[2] };
      for (unsigned a = 0; a < 12; a++) {
         put(v->tin, rast_vec_two(in[a][0], in[a][1]));
         put(v->tin, rast_vec_two(in[a][2], in[a][3]));
      }
      for (unsigned a = 0; a < 3; a++) {
         uint64_t w0, w1;
         rast_vec_coord_words(u, in[a], &w0, &w1);
         put(v->tin, w0);
         put(v->tin, w1);
      }
      fprintf(v->tout, "// quad %" PRIu64 "\n", v->tex_quads);
      for (unsigned c = 0; c < 4; c++) {
         put(v->tout, rast_vec_two(rgba[i][c][0], rgba[i][c][1]));
         put(v->tout, rast_vec_two(rgba[i][c][2], rgba[i][c][3]));
      }
      v->tex_quads++;
   }
}

