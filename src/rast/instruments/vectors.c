/*
 * RTL test vectors of the scan-converter unit (seed 000; docs/vectors.md):
 * what enters the unit for each triangle (the Table 1 registers of its
 * three vertices, as set up) and what leaves it for each quad (coverage and
 * the per-pixel registers), as $readmemh files an RTL testbench loads, and
 * their replay through the model, every output bit compared.
 *
 * Recording sits at the unit's two boundaries: rast_triangle_pass hands the
 * input registers over (rast_vec_triangle) and the back end's quad function
 * is wrapped (rast_vec_quad) while the triangle is scanned.  The replay
 * feeds the registers to rast_vec_replay_triangle (setup.c), the same code
 * from the registers on, and compares the quads as they leave.
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

/* binding and control, 48 binary32 inputs, then s, t, r as the unit's
 * coordinate registers hold them */
#define VEC_TEX_IN_WORDS 31
#define VEC_TEX_OUT_WORDS 8     /* 16 binary32 outputs */
#define VEC_TEX_DUMPED 64       /* bindings written in the current draw */

struct rast_vectors {
   /* recording */
   char dir[512];
   FILE *in, *out;
   unsigned long first, last, frame;
   unsigned units;                 /* RAST_VEC_* */
   bool active;
   uint64_t triangles, quads, skipped;
   /* replaying: the quads the current triangle must produce */
   const struct rast_vec_quad *expect;
   uint64_t nexpect, seen, mismatches;
   FILE *log;
   uint64_t tri_index;
   /* the texture unit's: bindings written in this draw (serial -> index) */
   FILE *tbind, *tin, *tout;
   uint32_t dumped_serial[VEC_TEX_DUMPED], dumped_index[VEC_TEX_DUMPED];
   unsigned ndumped;
   uint64_t tex_binds, tex_quads, tex_skipped;
};

static uint32_t fbits(float f)
{
   uint32_t u;
   memcpy(&u, &f, sizeof(u));
   return u;
}

static float bitsf(uint32_t u)
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
   rc->vec = v;
   rc->dirty = true;           /* the back end's quad function gets wrapped */
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

static void words_to_quad(const uint64_t w[VEC_OUT_WORDS], struct rast_vec_quad *r)
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
   default: return fbits(a.f);
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

void rast_vec_triangle(struct rast_context *rc, const struct rast_front *fr, bool front)
{
   struct rast_vectors *v = rc->vec;
   uint64_t map;
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
      put(f, fbits(fr->vflt[k][0]));
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
         put(f, j < fr->npersp ? fbits(fr->vflt[k][p0 + j]) : 0);
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
   rc->vec_tri = true;
}

/* The quad's record (recording) or its check against the next expected
 * one (replaying); then the back end's own quad function. */
static void vec_quad(struct rast_context *rc, struct rast_quad *q)
{
   struct rast_vectors *v = rc->vec;
   if (rc->vec_tri) {
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
         r.w[i] = fbits(q->frag_w[i]);
      }
      for (unsigned c = 0; c < fr->ncolor && c < VEC_MAX_COLOR; c++)
         for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
            r.color[c][i] = fbits(q->in[fr->color[c].var][fr->color[c].chan][i]);
      for (unsigned j = 0; j < fr->npersp && j < VEC_MAX_PERSP; j++)
         for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
            const float d = q->in[fr->persp[j].var][fr->persp[j].chan][i];
            r.persp[j][i] = fbits(d);
            r.pword[j][i] = divided_word(fr->tex.ns, fr->tex.is_color[j], d);
         }
      if (v->in) {
         uint64_t w[VEC_OUT_WORDS];
         quad_to_words(&r, w);
         fprintf(v->out, "// quad %" PRIu64 "\n", v->quads);
         for (unsigned i = 0; i < VEC_OUT_WORDS; i++)
            put(v->out, w[i]);
         v->quads++;
      } else if (v->seen >= v->nexpect) {
         if (v->mismatches++ < 10)
            fprintf(v->log, "triangle %" PRIu64 ": a quad too many at (%d, %d)\n", v->tri_index,
                    q->x, q->y);
      } else if (memcmp(&r, &v->expect[v->seen++], sizeof(r))) {
         const struct rast_vec_quad *e = &v->expect[v->seen - 1];
         if (v->mismatches++ < 10)
            fprintf(v->log, "triangle %" PRIu64 ": quad at (%d, %d) mask %x differs from the "
                    "recorded one at (%d, %d) mask %x (z %" PRId64 " / %" PRId64 ")\n",
                    v->tri_index, r.x, r.y, r.mask, e->x, e->y, e->mask, r.z[0], e->z[0]);
      }
   }
   rc->vec_next_quad(rc, q);
}

void rast_vec_wrap_backend(struct rast_context *rc)
{
   rc->vec_next_quad = rc->quad;
   rc->quad = vec_quad;
   rc->quads = NULL;     /* one quad at a time: the order the unit emits them */
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

static uint64_t two(float a, float b)
{
   return fbits(a) | (uint64_t)fbits(b) << 32;
}

/* Pixels 0, 1 (word a) and 2, 3 (word b) of a coordinate as the unit's
 * register: binary32 rounded toward -inf into the number system (a dfx
 * word, an M.N value's low 32 bits, binary32 bits). */
static void coord_words(const struct tex_unit *u, const float c[4], uint64_t *a, uint64_t *b)
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
   put(f, two(s->lod_bias, s->min_lod));
   put(f, fbits(s->max_lod));
   put(f, two(s->border[0], s->border[1]));
   put(f, two(s->border[2], s->border[3]));
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
         put(v->tin, two(in[a][0], in[a][1]));
         put(v->tin, two(in[a][2], in[a][3]));
      }
      for (unsigned a = 0; a < 3; a++) {
         uint64_t w0, w1;
         coord_words(u, in[a], &w0, &w1);
         put(v->tin, w0);
         put(v->tin, w1);
      }
      fprintf(v->tout, "// quad %" PRIu64 "\n", v->tex_quads);
      for (unsigned c = 0; c < 4; c++) {
         put(v->tout, two(rgba[i][c][0], rgba[i][c][1]));
         put(v->tout, two(rgba[i][c][2], rgba[i][c][3]));
      }
      v->tex_quads++;
   }
}

/* ---- replaying ---- */

/* The next 64-bit word of a $readmemh file, skipping // comments. */
static bool get(FILE *f, uint64_t *w)
{
   int c;
   for (;;) {
      c = fgetc(f);
      if (c == EOF)
         return false;
      if (c == '/') {
         while (c != '\n' && c != EOF)
            c = fgetc(f);
         continue;
      }
      if (c == ' ' || c == '\n' || c == '\t' || c == '\r')
         continue;
      ungetc(c, f);
      return fscanf(f, "%" SCNx64, w) == 1;
   }
}

static bool read_words(FILE *f, uint64_t *w, unsigned n)
{
   for (unsigned i = 0; i < n; i++)
      if (!get(f, &w[i]))
         return false;
   return true;
}

static bool read_quad(FILE *f, struct rast_vec_quad *r)
{
   uint64_t w[VEC_OUT_WORDS];
   if (!read_words(f, w, VEC_OUT_WORDS))
      return false;
   words_to_quad(w, r);
   return true;
}

static bool read_triangle(FILE *f, struct rast_vec_tri *t)
{
   uint64_t w[VEC_IN_WORDS];
   if (!read_words(f, w, VEC_IN_WORDS))
      return false;
   memset(t, 0, sizeof(*t));
   t->half_pixel = w[0] & 1u;
   t->bottom_rule = (w[0] >> 1) & 1u;
   t->front_ccw = (w[0] >> 2) & 1u;
   t->ncolor = (unsigned)(w[0] >> 8) & 0xffu;
   t->npersp = (unsigned)(w[0] >> 16) & 0xffu;
   t->org_x = (int32_t)(uint32_t)w[1];
   t->org_y = (int32_t)(uint32_t)(w[1] >> 32);
   t->clip.minx = (int16_t)(uint16_t)(w[2] & 0xffffu);
   t->clip.maxx = (int16_t)(uint16_t)((w[2] >> 16) & 0xffffu);
   t->clip.miny = (int16_t)(uint16_t)((w[2] >> 32) & 0xffffu);
   t->clip.maxy = (int16_t)(uint16_t)((w[2] >> 48) & 0xffffu);
   for (unsigned k = 0; k < 3; k++) {
      t->X[k] = (int64_t)w[3 + k];
      t->Y[k] = (int64_t)w[6 + k];
      t->Z[k] = (int64_t)w[9 + k];
      t->oow[k] = bitsf((uint32_t)w[12 + k]);
   }
   for (unsigned i = 0; i < VEC_MAX_COLOR; i++) {
      t->var[i] = (uint8_t)((w[15] >> (7 * i + 2)) & 0x1fu);
      t->chan[i] = (uint8_t)((w[15] >> (7 * i)) & 3u);
      for (unsigned k = 0; k < 3; k++)
         t->color[i][k] = (int64_t)w[16 + 3 * i + k];
   }
   for (unsigned j = 0; j < VEC_MAX_PERSP; j++) {
      const unsigned m = (unsigned)(w[VEC_IN_SCAN + j / 8] >> (8 * (j % 8))) & 0xffu;
      t->pvar[j] = (uint8_t)((m >> 2) & 0x1fu);
      t->pchan[j] = (uint8_t)(m & 3u);
      t->pcolor[j] = (m >> 7) & 1u;
      for (unsigned k = 0; k < 3; k++)
         t->aw[j][k] = bitsf((uint32_t)w[VEC_IN_SCAN + 2 + 3 * j + k]);
   }
   return t->ncolor <= VEC_MAX_COLOR && t->npersp <= VEC_MAX_PERSP;
}

static unsigned shade_nothing(void *ctx, const struct rast_quad *q, struct rast_shaded_quad *out)
{
   (void)ctx;
   (void)out;
   return q->mask;
}

/* The replay context's state for a triangle: its flags and its colour
 * components as COLOR varyings (the layout decides the components' order:
 * by varying, then channel, as recorded). */
static void replay_state(struct rast_context *rc, const struct rast_vec_tri *t)
{
   struct rast_raster_state rs;
   memset(&rs, 0, sizeof(rs));
   rs.half_pixel_center = t->half_pixel;
   rs.bottom_edge_rule = t->bottom_rule;
   rs.front_ccw = t->front_ccw;
   rs.cull = RAST_CULL_NONE;
   rs.line_width = 1.0f;
   if (memcmp(&rs, &rc->rs, sizeof(rs)))
      rast_set_raster_state(rc, &rs);
   struct rast_vertex_layout vl;
   memset(&vl, 0, sizeof(vl));
   vl.pos_slot = 0;
   unsigned maxvar = 0;
   for (unsigned i = 0; i < t->ncolor; i++)
      maxvar = t->var[i] + 1u > maxvar ? t->var[i] + 1u : maxvar;
   for (unsigned j = 0; j < t->npersp; j++)
      maxvar = t->pvar[j] + 1u > maxvar ? t->pvar[j] + 1u : maxvar;
   vl.num_varyings = maxvar;
   vl.vertex_size = 1 + maxvar;
   for (unsigned j = 0; j < maxvar; j++) {
      vl.varying[j].slot = (uint8_t)(1 + j);
      vl.varying[j].interp = RAST_INTERP_CONSTANT;
   }
   for (unsigned i = 0; i < t->ncolor; i++) {
      vl.varying[t->var[i]].interp = RAST_INTERP_COLOR;
      vl.varying[t->var[i]].usage_mask |= (uint8_t)(1u << t->chan[i]);
   }
   /* components divided in binary32 (the wide profile's perspective
    * colour, array layers) replay as float_mask ones: the same division,
    * in either profile */
   for (unsigned j = 0; j < t->npersp; j++) {
      vl.varying[t->pvar[j]].interp = RAST_INTERP_PERSPECTIVE;
      vl.varying[t->pvar[j]].float_mask |= (uint8_t)(t->pcolor[j] << t->pchan[j]);
      vl.varying[t->pvar[j]].usage_mask |= (uint8_t)(1u << t->pchan[j]);
   }
   if (memcmp(&vl, &rc->vl, sizeof(vl)))
      rast_set_vertex_layout(rc, &vl);
}

/* One binding of tex.bind.hex, bound again for the replay. */
struct replay_binding {
   struct tex_unit unit;
   struct ns_stats stats;
   uint8_t *texels[TEX_MAX_LEVELS];
};

static void split(uint64_t w, float *a, float *b)
{
   *a = bitsf((uint32_t)w);
   *b = bitsf((uint32_t)(w >> 32));
}

/* Reads the next binding: false at the end (or on a malformed record, said on log). */
static bool read_binding(FILE *f, const struct numsys *ns, uint64_t index,
                         struct replay_binding *b, FILE *log)
{
   uint64_t w[8];
   if (!read_words(f, w, 8))
      return false;
   if (w[0] != index) {
      fprintf(log, "tex.bind.hex: binding %" PRIu64 " where %" PRIu64 " was due\n", w[0], index);
      return false;
   }
   struct tex_view_desc d;
   struct tex_sampler_desc s;
   memset(&d, 0, sizeof(d));
   memset(&s, 0, sizeof(s));
   memset(b, 0, sizeof(*b));
   d.target = (enum tex_target)(w[1] & 0xffu);
   d.format = (enum tex_format)((w[1] >> 8) & 0xffu);
   d.depth = (w[1] >> 16) & 1u;
   d.num_levels = (unsigned)(w[1] >> 24) & 0xffu;
   d.layers = (int32_t)(uint32_t)w[2];
   for (unsigned c = 0; c < 4; c++)
      d.swizzle[c] = (uint8_t)(w[2] >> (32 + 8 * c));
   for (unsigned a = 0; a < 3; a++)
      s.wrap[a] = (enum tex_wrap)((w[3] >> (8 * a)) & 0xffu);
   s.min_filter = (enum tex_filter)((w[3] >> 24) & 0xffu);
   s.mag_filter = (enum tex_filter)((w[3] >> 32) & 0xffu);
   s.mip = (enum tex_mip)((w[3] >> 40) & 0xffu);
   s.normalized = (w[3] >> 48) & 1u;
   s.compare = (w[3] >> 49) & 1u;
   s.func = (enum tex_func)((w[3] >> 52) & 0xfu);
   split(w[4], &s.lod_bias, &s.min_lod);
   s.max_lod = bitsf((uint32_t)w[5]);
   split(w[6], &s.border[0], &s.border[1]);
   split(w[7], &s.border[2], &s.border[3]);
   if (d.num_levels > TEX_MAX_LEVELS || d.format == TEX_FMT_CALLBACK ||
       d.format >= TEX_FMT_COUNT) {
      fprintf(log, "tex.bind.hex: binding %" PRIu64 " is malformed\n", index);
      return false;
   }
   for (unsigned l = 0; l < d.num_levels; l++) {
      uint64_t lw[3];
      if (!read_words(f, lw, 3))
         return false;
      struct tex_level *lv = &d.level[l];
      lv->w = (int32_t)(uint32_t)lw[0];
      lv->h = (int32_t)(uint32_t)(lw[0] >> 32);
      lv->d = (int32_t)(uint32_t)lw[1];
      const uint64_t bytes = lw[1] >> 32;
      lv->row_stride = (uint32_t)lw[2];
      lv->img_stride = (uint32_t)(lw[2] >> 32);
      b->texels[l] = malloc(bytes + 8);
      if (!b->texels[l])
         return false;
      for (uint64_t o = 0; o < bytes; o += 8) {
         uint64_t x;
         if (!get(f, &x))
            return false;
         memcpy(b->texels[l] + o, &x, 8);
      }
      lv->data = b->texels[l];
   }
   tex_unit_bind(&b->unit, ns, &d, &s, &b->stats);
   return true;
}

static void free_binding(struct replay_binding *b)
{
   for (unsigned l = 0; l < TEX_MAX_LEVELS; l++)
      free(b->texels[l]);
}

/* The texture unit's records: every quad sampled again with its binding,
 * its 16 outputs compared bit for bit. */
static long replay_tex(const char *dir, const struct numsys *ns, FILE *log,
                       struct rast_vectors_counts *n)
{
   char path[600];
   FILE *f[3] = { NULL, NULL, NULL };
   const char *names[3] = { "tex.bind.hex", "tex.in.hex", "tex.out.hex" };
   for (unsigned i = 0; i < 3; i++) {
      snprintf(path, sizeof(path), "%s/%s", dir, names[i]);
      f[i] = fopen(path, "r");
   }
   if (!f[0] || !f[1] || !f[2]) {
      fprintf(log, "cannot read the texture unit's vectors in %s\n", dir);
      for (unsigned i = 0; i < 3; i++)
         if (f[i])
            fclose(f[i]);
      return -1;
   }
   struct replay_binding *b = NULL;
   size_t nb = 0, cap = 0;
   long bad = 0;
   uint64_t w[VEC_TEX_IN_WORDS], o[VEC_TEX_OUT_WORDS];
   while (read_words(f[1], w, VEC_TEX_IN_WORDS)) {
      if (!read_words(f[2], o, VEC_TEX_OUT_WORDS)) {
         fprintf(log, "tex.out.hex ends before tex.in.hex\n");
         bad = -1;
         break;
      }
      const uint64_t index = (uint32_t)w[0];
      while (index >= nb) {
         if (nb == cap) {
            size_t c = cap ? 2 * cap : 8;
            struct replay_binding *nbp = realloc(b, c * sizeof(*b));
            if (!nbp) {
               bad = -1;
               break;
            }
            b = nbp;
            cap = c;
         }
         if (bad < 0 || !read_binding(f[0], ns, nb, &b[nb], log)) {
            bad = -1;
            break;
         }
         nb++;
      }
      if (bad < 0)
         break;
      struct tex_quad q;
      memset(&q, 0, sizeof(q));
      float *in[12] = { q.s, q.t, q.r, q.layer, q.ref, q.lod, q.ddx[0], q.ddx[1], q.ddx[2],
                        q.ddy[0], q.ddy[1], q.ddy[2] };
      for (unsigned a = 0; a < 12; a++) {
         split(w[1 + 2 * a], &in[a][0], &in[a][1]);
         split(w[2 + 2 * a], &in[a][2], &in[a][3]);
      }
      float rgba[4][TEX_QUAD];
      tex_unit_sample(&b[index].unit, &q, (enum tex_lod_control)(w[0] >> 32), rgba);
      /* the coordinate registers: the unit's own conversion of the inputs */
      bool same = true;
      for (unsigned a = 0; a < 3; a++) {
         uint64_t w0, w1;
         coord_words(&b[index].unit, in[a], &w0, &w1);
         same &= w0 == w[25 + 2 * a] && w1 == w[26 + 2 * a];
      }
      for (unsigned c = 0; c < 4; c++)
         same &= two(rgba[c][0], rgba[c][1]) == o[2 * c] &&
                 two(rgba[c][2], rgba[c][3]) == o[2 * c + 1];
      if (!same && bad++ < 10)
         fprintf(log, "texture quad %" PRIu64 " (binding %" PRIu64 "): red at pixel 0 %08x, "
                 "recorded %08x\n", n->tex_quads, index, fbits(rgba[0][0]), (uint32_t)o[0]);
      n->tex_quads++;
   }
   n->tex_bindings = nb;
   for (size_t i = 0; i < nb; i++)
      free_binding(&b[i]);
   free(b);
   for (unsigned i = 0; i < 3; i++)
      fclose(f[i]);
   return bad;
}

long rast_vectors_replay(const char *dir, FILE *log, struct rast_vectors_counts *counts)
{
   char path[600], line[256], profile[200] = "", interp[32] = "scanline", texfmt[32] = "";
   snprintf(path, sizeof(path), "%s/scan.txt", dir);
   FILE *h = fopen(path, "r");
   if (!h) {
      fprintf(log, "cannot read %s: %s\n", path, strerror(errno));
      return -1;
   }
   unsigned in_words = 0, out_words = 0, tex_in = 0, tex_out = 0;
   while (fgets(line, sizeof(line), h)) {
      sscanf(line, "profile %199s", profile);
      sscanf(line, "interp %31s", interp);
      sscanf(line, "texfmt %31s", texfmt);
      sscanf(line, "in_words %u", &in_words);
      sscanf(line, "out_words %u", &out_words);
      sscanf(line, "tex_in_words %u", &tex_in);
      sscanf(line, "tex_out_words %u", &tex_out);
   }
   fclose(h);
   if (in_words != VEC_IN_WORDS || out_words != VEC_OUT_WORDS ||
       tex_in != VEC_TEX_IN_WORDS || tex_out != VEC_TEX_OUT_WORDS) {
      fprintf(log, "%s: records of %u, %u, %u and %u words, this replay reads %u, %u, %u and "
              "%u\n", path, in_words, out_words, tex_in, tex_out, VEC_IN_WORDS, VEC_OUT_WORDS,
              VEC_TEX_IN_WORDS, VEC_TEX_OUT_WORDS);
      return -1;
   }
   static struct rast_profile_buf buf;
   char err[256];
   if (!rast_profile_parse(profile, &buf, err, sizeof(err))) {
      fprintf(log, "%s: profile '%s': %s\n", path, profile, err);
      return -1;
   }
   const struct numsys *ns = numsys_by_name(texfmt);
   if (!ns) {
      fprintf(log, "%s: unknown texfmt '%s'\n", path, texfmt);
      return -1;
   }
   unsigned mode = 0;
   while (rast_interp_name((enum rast_interp_mode)mode) &&
          strcmp(rast_interp_name((enum rast_interp_mode)mode), interp))
      mode++;
   if (!rast_interp_name((enum rast_interp_mode)mode)) {
      fprintf(log, "%s: unknown interpolator '%s'\n", path, interp);
      return -1;
   }

   snprintf(path, sizeof(path), "%s/scan.in.hex", dir);
   FILE *fin = fopen(path, "r");
   snprintf(path, sizeof(path), "%s/scan.out.hex", dir);
   FILE *fout = fin ? fopen(path, "r") : NULL;
   if (!fin || !fout) {
      fprintf(log, "cannot read the vectors in %s\n", dir);
      if (fin)
         fclose(fin);
      return -1;
   }
   struct rast_context *rc = rast_create(&buf.p);
   struct rast_vectors *v = calloc(1, sizeof(*v));
   size_t cap = 1024;
   struct rast_vec_quad *expect = malloc(cap * sizeof(*expect));
   if (!rc || !v || !expect) {
      fprintf(log, "out of memory\n");
      rast_destroy(rc);
      free(v);
      free(expect);
      fclose(fin);
      fclose(fout);
      return -1;
   }
   rast_set_interp(rc, mode);
   rast_set_texfmt(rc, ns);
   struct rast_framebuffer fb;
   memset(&fb, 0, sizeof(fb));
   fb.width = fb.height = buf.p.max_target;
   rast_set_framebuffer(rc, &fb);
   struct rast_shader fs;
   memset(&fs, 0, sizeof(fs));
   fs.shade = shade_nothing;
   fs.may_discard = true;       /* the back end calls the shader without a colour buffer */
   rast_set_shader(rc, &fs);
   v->log = log;
   rc->vec = v;
   rc->dirty = true;

   struct rast_vec_quad next;
   bool have_next = read_quad(fout, &next);
   long result = 0;
   uint64_t tri = 0, quads = 0;
   struct rast_vec_tri t;
   while (read_triangle(fin, &t)) {
      size_t n = 0;
      while (have_next && next.tri == tri) {
         if (n == cap) {
            struct rast_vec_quad *e = realloc(expect, 2 * cap * sizeof(*e));
            if (!e) {
               fprintf(log, "out of memory\n");
               result = -1;
               break;
            }
            expect = e;
            cap *= 2;
         }
         expect[n++] = next;
         have_next = read_quad(fout, &next);
      }
      if (result < 0)
         break;
      replay_state(rc, &t);
      v->expect = expect;
      v->nexpect = n;
      v->seen = 0;
      v->tri_index = tri;
      rast_vec_replay_triangle(rc, &t);
      if (v->seen != n && v->mismatches++ < 10)
         fprintf(log, "triangle %" PRIu64 ": %" PRIu64 " quads of the %zu recorded\n", tri,
                 v->seen, n);
      quads += n;
      tri++;
   }
   if (result == 0 && have_next && v->mismatches++ < 10)
      fprintf(log, "quads recorded for triangle %u, after the last one\n", next.tri);
   if (result == 0)
      result = (long)v->mismatches;
   memset(counts, 0, sizeof(*counts));
   counts->triangles = tri;
   counts->quads = quads;
   if (result >= 0) {
      long tb = replay_tex(dir, ns, log, counts);
      result = tb < 0 ? tb : result + tb;
   }
   rc->vec = NULL;
   rast_destroy(rc);
   free(v);
   free(expect);
   fclose(fin);
   fclose(fout);
   return result;
}
