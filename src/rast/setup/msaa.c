/*
 * Four samples a pixel: GL ES 3.0's multisampling in the model.
 *
 * A sample is a point of the pixel, and the scan converter already decides
 * coverage for a point: the pixel centre, by the ceil circuit on exact
 * registers.  So sample k is the same circuit at the sample's position
 * (fr->Hx, fr->Hy instead of the centre's H): every register of the walk —
 * X_left, X_right, Z, colour, 1/w — is the one the hardware would walk for
 * that point, exactly, with the top-left rule applied per sample.
 *
 * The shader runs once a pixel, not once a sample.  A primitive is drawn
 * strip by strip of scan lines, each strip in five walks:
 *
 *   the centre:  the walk at the pixel centres shades the pixels whose
 *                centre is covered and keeps their outputs in the strip's
 *                cache; nothing is written;
 *   sample k:    the walk at sample k (0..3, those in the sample mask) runs
 *                the back end on sample k's planes — depth, stencil, blend,
 *                occlusion count — with the cached outputs.  A pixel covered
 *                at sample k but not at its centre, and not shaded yet, is
 *                shaded here with the registers at sample k (the first
 *                covered sample: the centroid rule of hardware) and cached
 *                for the samples after it.
 *
 * A shader that reads the target (framebuffer fetch) reads one sample's
 * colour, and one shaded per sample (sample shading, gl_SampleID) must see
 * each sample's own inputs, so such shaders run once a sample instead: no
 * centre walk and no cache, the back end of sample k's walk shades each
 * pixel covered at sample k with the registers at sample k (after fetching
 * sample k's colour), the quads telling the shader k.  A shader writing
 * gl_SampleMask runs so too, its invocation for sample k keeping k where
 * the output has bit k.  With GL_MULTISAMPLE disabled (rs.single_sample)
 * every walk samples the centre, and the shader runs once a pixel.
 *
 * docs/msaa.md has the argument, the costs and what stays single-sampled.
 */
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rast/backend/backend_priv.h"
#include "rast/setup/front.h"

const float rast_sample_pos_4x[RAST_MSAA_SAMPLES][2] = {
   { 0.375f, 0.125f }, { 0.875f, 0.375f }, { 0.125f, 0.625f }, { 0.625f, 0.875f }
};

/* Scan lines a strip: the cache holds one strip of the target.  Each walk
 * of a strip runs from the primitive's top and draws the strip's quad
 * rows only (rc->rows_lo, rows_hi), as a thread draws its bands: a walk
 * started lower would round its registers' steps otherwise. */
#define MSAA_STRIP_ROWS 64

typedef unsigned (*msaa_shade_func)(void *ctx, const struct rast_quad *quad,
                                    struct rast_shaded_quad *out);
typedef unsigned (*msaa_shade_n_func)(void *ctx, const struct rast_quad *const q[],
                                      struct rast_shaded_quad *const out[], unsigned n);

struct rast_msaa {
   /* The strip's cache of shaded pixels: [row - y0][x]. */
   unsigned width, ncol;          /* pixels a row; colour outputs kept a pixel */
   uint32_t *stamp;               /* the strip's serial where the entry is its own */
   uint8_t *kept;                 /* the shader kept the pixel (no discard) */
   float *depth;                  /* the shader's depth output */
   float *color;                  /* [pixel][ncol][4] */
   uint32_t serial;
   int64_t y0;                    /* the strip's first scan line, in the target */
   /* While the walks run: the real shader and the sample being drawn. */
   msaa_shade_func shade;
   msaa_shade_n_func shade_n;     /* its wide form, or NULL */
   void *ctx;
   unsigned sample;
   bool centre;
   bool a2c;
   struct rast_quad scratch;      /* a quad narrowed to its unshaded pixels */
   struct rast_shaded_quad out;
};

static bool msaa_reserve(struct rast_context *rc)
{
   struct rast_msaa *m = rc->msaa;
   unsigned ncol = rc->fs.num_outputs ? rc->fs.num_outputs : 1;
   if (ncol > RAST_MAX_CBUFS)
      ncol = RAST_MAX_CBUFS;
   if (m && m->width >= rc->fb.width && m->ncol >= ncol)
      return true;
   rast_msaa_destroy(rc);
   m = calloc(1, sizeof *m);
   if (!m)
      return false;
   const size_t n = (size_t)rc->fb.width * MSAA_STRIP_ROWS;
   m->width = rc->fb.width;
   m->ncol = ncol;
   m->stamp = calloc(n, sizeof *m->stamp);
   m->kept = malloc(n);
   m->depth = malloc(n * sizeof *m->depth);
   m->color = malloc(n * ncol * 4 * sizeof *m->color);
   rc->msaa = m;
   if (!m->stamp || !m->kept || !m->depth || !m->color) {
      rast_msaa_destroy(rc);
      return false;
   }
   return true;
}

/* A primitive the model cannot draw for want of its cache: said once, not
 * drawn in silence. */
static void msaa_out_of_memory(const struct rast_context *rc)
{
   static atomic_bool said;
   if (!atomic_exchange(&said, true))
      fprintf(stderr, "fixpipe: out of memory for the multisample cache of a %u-pixel-wide "
              "target: its primitives are not drawn\n", rc->fb.width);
}

void rast_msaa_destroy(struct rast_context *rc)
{
   struct rast_msaa *m = rc->msaa;
   if (!m)
      return;
   free(m->stamp);
   free(m->kept);
   free(m->depth);
   free(m->color);
   free(m);
   rc->msaa = NULL;
}

static inline size_t entry(const struct rast_msaa *m, const struct rast_quad *q, unsigned i)
{
   return (size_t)(q->y + (int)(i >> 1) - m->y0) * m->width + (size_t)(q->x + (int)(i & 1));
}

/* The real shader on the pixels `mask` of q; their outputs into the cache. */
static void shade_into_cache(struct rast_msaa *m, const struct rast_quad *q, unsigned mask)
{
   const struct rast_quad *in = q;
   if (mask != q->mask) {
      m->scratch = *q;
      m->scratch.mask = mask;
      in = &m->scratch;
   }
   const unsigned kept = m->shade(m->ctx, in, &m->out) & mask;
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      if (!(mask >> i & 1u))
         continue;
      const size_t e = entry(m, q, i);
      m->stamp[e] = m->serial;
      m->kept[e] = (uint8_t)(kept >> i & 1u);
      m->depth[e] = m->out.depth[i];
      float *c = &m->color[e * m->ncol * 4];
      for (unsigned o = 0; o < m->ncol; o++)
         for (unsigned ch = 0; ch < 4; ch++)
            c[o * 4 + ch] = m->out.color[o][ch][i];
   }
}

/* The centre walk's back end: shade, keep, write nothing. */
static void centre_quad(struct rast_context *rc, struct rast_quad *q)
{
   rc->stats.pixels_shaded += rast_popcount4(q->mask);
   shade_into_cache(rc->msaa, q, q->mask);
}

/* Alpha to coverage keeps, of the pixels `kept`, those whose first output's
 * alpha is above k/4 for the sample k drawn (llvmpipe's rule). */
static inline unsigned a2c(const struct rast_msaa *m, const struct rast_shaded_quad *out,
                           unsigned kept)
{
   if (m->a2c)
      for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
         if (!(out->color[0][3][i] > (float)m->sample * (1.0f / RAST_MSAA_SAMPLES)))
            kept &= ~(1u << i);
   return kept;
}

/* The shader the back end calls in a sample's walk: the cached outputs,
 * the pixels not shaded yet shaded now; alpha to coverage for this sample. */
static unsigned cached_shade(void *ctx, const struct rast_quad *q, struct rast_shaded_quad *out)
{
   struct rast_context *rc = ctx;
   struct rast_msaa *m = rc->msaa;
   unsigned miss = 0;
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
      if ((q->mask >> i & 1u) && m->stamp[entry(m, q, i)] != m->serial)
         miss |= 1u << i;
   /* the back end counted the quad's pixels as shaded: only these are */
   rc->stats.pixels_shaded += rast_popcount4(miss);
   rc->stats.pixels_shaded -= rast_popcount4(q->mask);
   if (miss)
      shade_into_cache(m, q, miss);

   unsigned kept = 0;
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++) {
      if (!(q->mask >> i & 1u))
         continue;
      const size_t e = entry(m, q, i);
      const float *c = &m->color[e * m->ncol * 4];
      for (unsigned o = 0; o < m->ncol; o++)
         for (unsigned ch = 0; ch < 4; ch++)
            out->color[o][ch][i] = c[o * 4 + ch];
      out->depth[i] = m->depth[e];
      kept |= (unsigned)m->kept[e] << i;
   }
   return a2c(m, out, kept);
}

/* Once a sample (framebuffer fetch): the shader itself, on one quad or,
 * in its wide form, on several; alpha to coverage as above. */
static unsigned sample_shade(void *ctx, const struct rast_quad *q, struct rast_shaded_quad *out)
{
   const struct rast_msaa *m = ((struct rast_context *)ctx)->msaa;
   return a2c(m, out, m->shade(m->ctx, q, out) & q->mask);
}

static unsigned sample_shade_n(void *ctx, const struct rast_quad *const q[],
                               struct rast_shaded_quad *const out[], unsigned n)
{
   const struct rast_msaa *m = ((struct rast_context *)ctx)->msaa;
   const unsigned got = m->shade_n(m->ctx, q, out, n);
   unsigned kept = 0;
   for (unsigned i = 0; i < n; i++)
      kept |= a2c(m, out[i], got >> 4 * i & q[i]->mask) << 4 * i;
   return kept;
}

/* gl_SampleMask: of the pixels `kept`, those whose output has the bit of
 * the sample drawn. */
static inline unsigned out_mask(const struct rast_msaa *m, const struct rast_shaded_quad *out,
                                unsigned kept)
{
   for (unsigned i = 0; i < RAST_QUAD_SIZE; i++)
      if (!(out->sample_mask[i] >> m->sample & 1u))
         kept &= ~(1u << i);
   return kept;
}

static unsigned sample_shade_mask(void *ctx, const struct rast_quad *q,
                                  struct rast_shaded_quad *out)
{
   return out_mask(((struct rast_context *)ctx)->msaa, out, sample_shade(ctx, q, out));
}

static unsigned sample_shade_mask_n(void *ctx, const struct rast_quad *const q[],
                                    struct rast_shaded_quad *const out[], unsigned n)
{
   const struct rast_msaa *m = ((struct rast_context *)ctx)->msaa;
   const unsigned got = sample_shade_n(ctx, q, out, n);
   unsigned kept = 0;
   for (unsigned i = 0; i < n; i++)
      kept |= out_mask(m, out[i], got >> 4 * i & 15u) << 4 * i;
   return kept;
}

static unsigned cached_shade_n(void *ctx, const struct rast_quad *const q[],
                               struct rast_shaded_quad *const out[], unsigned n)
{
   unsigned kept = 0;
   for (unsigned i = 0; i < n; i++)
      kept |= cached_shade(ctx, q[i], out[i]) << 4 * i;
   return kept;
}

/* One walk.  The set-up's counters (the primitive, its vertices) count
 * once, in the primitive's first walk; the walks' own count every time. */
static void one_pass(struct rast_context *rc, enum rast_prim_kind kind, const float (*v0)[4],
                     const float (*v1)[4], const float (*v2)[4], bool *first)
{
   if (!*first)
      rast_count_stretch(rc, false);
   *first = false;
   switch (kind) {
   case RAST_PRIM_TRIANGLE: rast_triangle_pass(rc, v0, v1, v2); break;
   case RAST_PRIM_LINE:     rast_line_pass(rc, v0, v1); break;
   case RAST_PRIM_POINT:    rast_point_pass(rc, v0); break;
   }
}

void rast_msaa_pass(struct rast_context *rc, enum rast_prim_kind kind, const float (*v0)[4],
                    const float (*v1)[4], const float (*v2)[4])
{
   struct rast_front *fr = rast_front_begin(rc, kind == RAST_PRIM_POINT);
   const unsigned samples = rc->sample_mask & ((1u << RAST_MSAA_SAMPLES) - 1);
   float box[4];
   if (!rc->fs.shade || !samples || !rast_prim_extent(rc, kind, v0, v1, v2, box))
      return;
   if (!msaa_reserve(rc)) {
      msaa_out_of_memory(rc);
      return;
   }
   struct rast_msaa *m = rc->msaa;

   /* The strips: the primitive's scan lines inside the pass's clip. */
   const struct rast_scissor clip = rc->clip;
   int64_t top = (int64_t)floorf(box[1]) - rc->org_y, bot = (int64_t)ceilf(box[3]) - rc->org_y;
   if (top < clip.miny) top = clip.miny;
   if (bot > clip.maxy) bot = clip.maxy;
   top &= ~(int64_t)1;

   const rast_quad_func quad = rc->quad;
   const rast_quads_func quads = rc->quads;
   const struct rast_shader fs = rc->fs;
   const bool counting = rc->counting;
   const bool shades = rast_backend_shades(rc);
   /* GL_MULTISAMPLE disabled: every walk at the centre, sample 0 */
   const bool at_centre = rc->rs.single_sample;
   const bool masks = fs.writes_sample_mask && !at_centre;
   const bool per_sample = fs.fetch_mask != 0 || masks || (fs.per_sample && !at_centre);
   bool first = true;
   m->shade = fs.shade;
   m->shade_n = fs.shade_n;
   m->ctx = fs.ctx;
   m->a2c = rc->blend.alpha_to_coverage;
   rc->msaa_busy = true;
   /* the samples' back end shades through the cache; the centre's calls
    * the shader itself (centre_quad) */
   rc->fs.shade = masks        ? sample_shade_mask
                  : per_sample ? sample_shade
                               : cached_shade;
   rc->fs.shade_n = !fs.shade_n   ? NULL
                    : masks      ? sample_shade_mask_n
                    : per_sample ? sample_shade_n
                                 : cached_shade_n;
   rc->fs.ctx = rc;

   for (int64_t y = top; y < bot; y += MSAA_STRIP_ROWS) {
      rc->rows_lo = y;
      rc->rows_hi = y + MSAA_STRIP_ROWS;
      m->y0 = y + rc->org_y;
      if (++m->serial == 0) {           /* the stamps wrapped: none is current */
         memset(m->stamp, 0, (size_t)m->width * MSAA_STRIP_ROWS * sizeof *m->stamp);
         m->serial = 1;
      }

      if (shades && !per_sample) {
         fr->Hx = fr->Hy = fr->H;
         rc->quad = centre_quad;
         rc->quads = NULL;
         one_pass(rc, kind, v0, v1, v2, &first);
      }

      rc->quad = quad;
      rc->quads = quads;
      for (unsigned k = 0; k < RAST_MSAA_SAMPLES; k++) {
         if (!(samples >> k & 1u))
            continue;
         m->sample = k;
         fr->Hx = at_centre ? fr->H
                            : fr->H - fr->S / 2 + (int64_t)(rast_sample_pos_4x[k][0] * (float)fr->S);
         fr->Hy = at_centre ? fr->H
                            : fr->H - fr->S / 2 + (int64_t)(rast_sample_pos_4x[k][1] * (float)fr->S);
         rast_backend_sample(rc, k);
         fr_set_sample(fr, at_centre ? 0 : k);
         one_pass(rc, kind, v0, v1, v2, &first);
      }
   }
   rast_backend_sample(rc, 0);
   fr_set_sample(fr, 0);
   rc->fs = fs;
   fr->Hx = fr->Hy = fr->H;
   rc->msaa_busy = false;
   rc->rows_lo = INT64_MIN;
   rc->rows_hi = INT64_MAX;
   rast_count_stretch(rc, counting);
}
