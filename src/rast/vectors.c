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

#include "rast/front.h"
#include "rast/vectors.h"

struct rast_vectors {
   /* recording */
   char dir[512];
   FILE *in, *out;
   unsigned long first, last, frame;
   bool active;
   uint64_t triangles, quads, skipped;
   /* replaying: the quads the current triangle must produce */
   const struct rast_vec_quad *expect;
   uint64_t nexpect, seen, mismatches;
   FILE *log;
   uint64_t tri_index;
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
   fprintf(f, "unit scan\nprofile %s\ninterp %s\nin_words %u\nout_words %u\n"
           "color_components_max %u\ntriangles %" PRIu64 "\nquads %" PRIu64 "\n"
           "triangles_not_recorded %" PRIu64 "\n", rc->profile->name,
           rast_interp_name((enum rast_interp_mode)(rc->interp & 3u)), VEC_IN_WORDS,
           VEC_OUT_WORDS, VEC_MAX_COLOR, v->triangles, v->quads, v->skipped);
   if (v->last == ~0ul)
      fprintf(f, "frames %lu-\n", v->first);
   else
      fprintf(f, "frames %lu-%lu\n", v->first, v->last);
   fclose(f);
}

bool rast_vectors_open(struct rast_context *rc, const char *dir, unsigned long first,
                       unsigned long last, char *err, size_t errlen)
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
   if (!v->in || !v->out) {
      snprintf(err, errlen, "cannot write %s: %s", path, strerror(errno));
      if (v->in)
         fclose(v->in);
      free(v);
      return false;
   }
   v->first = first;
   v->last = last;
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
   }
   free(v);
   rc->vec = NULL;
}

static void put(FILE *f, uint64_t w)
{
   fprintf(f, "%016" PRIx64 "\n", w);
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
   if (!v->in || !v->active)
      return;
   if (!color_map(fr, &map) || rc->vl.num_varyings > 32) {
      v->skipped++;
      return;
   }
   FILE *f = v->in;
   fprintf(f, "// triangle %" PRIu64 "\n", v->triangles);
   put(f, (uint64_t)rc->rs.half_pixel_center | (uint64_t)rc->rs.bottom_edge_rule << 1 |
          (uint64_t)rc->rs.front_ccw << 2 | (uint64_t)front << 3 | (uint64_t)fr->ncolor << 8);
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
      if (v->in) {
         FILE *f = v->out;
         fprintf(f, "// quad %" PRIu64 "\n", v->quads);
         put(f, r.tri | (uint64_t)r.mask << 32 | (uint64_t)r.front << 36);
         put(f, (uint32_t)r.x | (uint64_t)(uint32_t)r.y << 32);
         for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
            put(f, (uint64_t)r.z[i]);
         put(f, r.w[0] | (uint64_t)r.w[1] << 32);
         put(f, r.w[2] | (uint64_t)r.w[3] << 32);
         for (unsigned c = 0; c < VEC_MAX_COLOR; c++) {
            put(f, r.color[c][0] | (uint64_t)r.color[c][1] << 32);
            put(f, r.color[c][2] | (uint64_t)r.color[c][3] << 32);
         }
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
   rc->quad2 = NULL;     /* one quad at a time: the order the unit emits them */
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

static bool read_quad(FILE *f, struct rast_vec_quad *r)
{
   uint64_t w[VEC_OUT_WORDS];
   for (unsigned i = 0; i < VEC_OUT_WORDS; i++)
      if (!get(f, &w[i]))
         return false;
   memset(r, 0, sizeof(*r));
   r->tri = (uint32_t)w[0];
   r->mask = (unsigned)(w[0] >> 32) & 0xfu;
   r->front = (w[0] >> 36) & 1u;
   r->x = (int32_t)(uint32_t)w[1];
   r->y = (int32_t)(uint32_t)(w[1] >> 32);
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
      r->z[i] = (int64_t)w[2 + i];
   r->w[0] = (uint32_t)w[6];
   r->w[1] = (uint32_t)(w[6] >> 32);
   r->w[2] = (uint32_t)w[7];
   r->w[3] = (uint32_t)(w[7] >> 32);
   for (unsigned c = 0; c < VEC_MAX_COLOR; c++) {
      r->color[c][0] = (uint32_t)w[8 + 2 * c];
      r->color[c][1] = (uint32_t)(w[8 + 2 * c] >> 32);
      r->color[c][2] = (uint32_t)w[9 + 2 * c];
      r->color[c][3] = (uint32_t)(w[9 + 2 * c] >> 32);
   }
   return true;
}

static bool read_triangle(FILE *f, struct rast_vec_tri *t)
{
   uint64_t w[VEC_IN_WORDS];
   for (unsigned i = 0; i < VEC_IN_WORDS; i++)
      if (!get(f, &w[i]))
         return false;
   memset(t, 0, sizeof(*t));
   t->half_pixel = w[0] & 1u;
   t->bottom_rule = (w[0] >> 1) & 1u;
   t->front_ccw = (w[0] >> 2) & 1u;
   t->ncolor = (unsigned)(w[0] >> 8) & 0xffu;
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
   return t->ncolor <= VEC_MAX_COLOR;
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
   if (memcmp(&vl, &rc->vl, sizeof(vl)))
      rast_set_vertex_layout(rc, &vl);
}

long rast_vectors_replay(const char *dir, FILE *log, uint64_t *ntri, uint64_t *nquads)
{
   char path[600], line[256], profile[200] = "", interp[32] = "scanline";
   snprintf(path, sizeof(path), "%s/scan.txt", dir);
   FILE *h = fopen(path, "r");
   if (!h) {
      fprintf(log, "cannot read %s: %s\n", path, strerror(errno));
      return -1;
   }
   unsigned in_words = 0, out_words = 0;
   while (fgets(line, sizeof(line), h)) {
      sscanf(line, "profile %199s", profile);
      sscanf(line, "interp %31s", interp);
      sscanf(line, "in_words %u", &in_words);
      sscanf(line, "out_words %u", &out_words);
   }
   fclose(h);
   if (in_words != VEC_IN_WORDS || out_words != VEC_OUT_WORDS) {
      fprintf(log, "%s: records of %u and %u words, this replay reads %u and %u\n", path,
              in_words, out_words, VEC_IN_WORDS, VEC_OUT_WORDS);
      return -1;
   }
   static struct rast_profile_buf buf;
   char err[256];
   if (!rast_profile_parse(profile, &buf, err, sizeof(err))) {
      fprintf(log, "%s: profile '%s': %s\n", path, profile, err);
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
   *ntri = tri;
   *nquads = quads;
   rc->vec = NULL;
   rast_destroy(rc);
   free(v);
   free(expect);
   fclose(fin);
   fclose(fout);
   return result;
}
