/*
 * The replay of RTL test vectors (docs/vectors.md): DIR's records through a
 * new context and texture units, every output bit compared with the
 * recorded one.  Verification, not the model: tools (fp-vectors) and tests
 * link it, the driver does not.  The triangles enter set-up from their
 * registers (rast_setup_from_registers); each quad leaving the scan converter
 * reaches check_quad through the recorder's observer in check mode.
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
#include "verify/vectors_replay.h"

/* The quads the current triangle must produce, and what was seen. */
struct replay_check {
   const struct rast_vec_quad *expect;
   uint64_t nexpect, seen, mismatches, tri_index;
   FILE *log;
};

static void check_quad(void *ctx, const struct rast_vec_quad *r)
{
   struct replay_check *c = ctx;
   if (c->seen >= c->nexpect) {
      if (c->mismatches++ < 10)
         fprintf(c->log, "triangle %" PRIu64 ": a quad too many at (%d, %d)\n", c->tri_index,
                 r->x, r->y);
   } else if (memcmp(r, &c->expect[c->seen++], sizeof(*r))) {
      const struct rast_vec_quad *e = &c->expect[c->seen - 1];
      if (c->mismatches++ < 10)
         fprintf(c->log, "triangle %" PRIu64 ": quad at (%d, %d) mask %x differs from the "
                 "recorded one at (%d, %d) mask %x (z %" PRId64 " / %" PRId64 ")\n",
                 c->tri_index, r->x, r->y, r->mask, e->x, e->y, e->mask, r->z[0], e->z[0]);
   }
}

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

bool rast_vectors_read_quad(FILE *f, struct rast_vec_quad *r)
{
   uint64_t w[VEC_OUT_WORDS];
   if (!read_words(f, w, VEC_OUT_WORDS))
      return false;
   rast_vec_words_to_quad(w, r);
   return true;
}

bool rast_vectors_read_triangle(FILE *f, struct rast_tri_regs *t)
{
   uint64_t w[VEC_IN_WORDS];
   if (!read_words(f, w, VEC_IN_WORDS))
      return false;
   memset(t, 0, sizeof(*t));
   t->half_pixel = w[0] & 1u;
   t->bottom_rule = (w[0] >> 1) & 1u;
   t->front_ccw = (w[0] >> 2) & 1u;
   t->front = (w[0] >> 3) & 1u;
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
      t->oow[k] = rast_vec_bitsf((uint32_t)w[12 + k]);
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
         t->aw[j][k] = rast_vec_bitsf((uint32_t)w[VEC_IN_SCAN + 2 + 3 * j + k]);
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
static void replay_state(struct rast_context *rc, const struct rast_tri_regs *t)
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
   *a = rast_vec_bitsf((uint32_t)w);
   *b = rast_vec_bitsf((uint32_t)(w >> 32));
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
   s.max_lod = rast_vec_bitsf((uint32_t)w[5]);
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
         rast_vec_coord_words(&b[index].unit, in[a], &w0, &w1);
         same &= w0 == w[25 + 2 * a] && w1 == w[26 + 2 * a];
      }
      for (unsigned c = 0; c < 4; c++)
         same &= rast_vec_two(rgba[c][0], rgba[c][1]) == o[2 * c] &&
                 rast_vec_two(rgba[c][2], rgba[c][3]) == o[2 * c + 1];
      if (!same && bad++ < 10)
         fprintf(log, "texture quad %" PRIu64 " (binding %" PRIu64 "): red at pixel 0 %08x, "
                 "recorded %08x\n", n->tex_quads, index, rast_vec_fbits(rgba[0][0]), (uint32_t)o[0]);
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

bool rast_vectors_read_header(const char *dir, struct rast_vectors_header *hd, FILE *log)
{
   char path[600], line[256];
   snprintf(path, sizeof(path), "%s/scan.txt", dir);
   FILE *h = fopen(path, "r");
   if (!h) {
      fprintf(log, "cannot read %s: %s\n", path, strerror(errno));
      return false;
   }
   memset(hd, 0, sizeof(*hd));
   strcpy(hd->interp, "scanline");
   unsigned in_words = 0, out_words = 0, tex_in = 0, tex_out = 0;
   while (fgets(line, sizeof(line), h)) {
      sscanf(line, "profile %199s", hd->profile);
      sscanf(line, "interp %31s", hd->interp);
      sscanf(line, "texfmt %31s", hd->texfmt);
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
      return false;
   }
   char err[256];
   if (!rast_profile_parse(hd->profile, &hd->profile_buf, err, sizeof(err))) {
      fprintf(log, "%s: profile '%s': %s\n", path, hd->profile, err);
      return false;
   }
   return true;
}

long rast_vectors_replay(const char *dir, FILE *log, struct rast_vectors_counts *counts)
{
   char path[600];
   static struct rast_vectors_header hd;
   if (!rast_vectors_read_header(dir, &hd, log))
      return -1;
   struct rast_profile_buf *const bp = &hd.profile_buf;
   const char *const interp = hd.interp, *const texfmt = hd.texfmt;
   snprintf(path, sizeof(path), "%s/scan.txt", dir);
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
   struct rast_context *rc = rast_create(&bp->p);
   struct replay_check chk = { .log = log };
   struct replay_check *v = &chk;
   size_t cap = 1024;
   struct rast_vec_quad *expect = malloc(cap * sizeof(*expect));
   if (!rc || !expect || !rast_vectors_check_open(rc, check_quad, &chk)) {
      fprintf(log, "out of memory\n");
      rast_destroy(rc);
      free(expect);
      fclose(fin);
      fclose(fout);
      return -1;
   }
   rast_set_interp(rc, mode);
   rast_set_texfmt(rc, ns);
   struct rast_framebuffer fb;
   memset(&fb, 0, sizeof(fb));
   fb.width = fb.height = bp->p.max_target;
   rast_set_framebuffer(rc, &fb);
   struct rast_shader fs;
   memset(&fs, 0, sizeof(fs));
   fs.shade = shade_nothing;
   fs.may_discard = true;       /* the back end calls the shader without a colour buffer */
   rast_set_shader(rc, &fs);

   struct rast_vec_quad next;
   bool have_next = rast_vectors_read_quad(fout, &next);
   long result = 0;
   uint64_t tri = 0, quads = 0;
   struct rast_tri_regs t;
   while (rast_vectors_read_triangle(fin, &t)) {
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
         have_next = rast_vectors_read_quad(fout, &next);
      }
      if (result < 0)
         break;
      replay_state(rc, &t);
      v->expect = expect;
      v->nexpect = n;
      v->seen = 0;
      v->tri_index = tri;
      rast_vectors_check_triangle(rc, tri);
      rast_setup_from_registers(rc, &t);
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
   rast_vectors_close(rc);
   rast_destroy(rc);
   free(expect);
   fclose(fin);
   fclose(fout);
   return result;
}
