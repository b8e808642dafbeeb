/*
 * draw's back end: post-transform vertices (window x, y, z, 1/w in slot 0,
 * then one float[4] slot per fragment-shader input, then the point size if
 * the vertex shader writes one) go to the model primitive by primitive.
 */
#include <string.h>

#include "util/u_memory.h"
#include "util/u_prim.h"
#include "draw/draw_context.h"
#include "draw/draw_vbuf.h"
#include "draw/draw_vertex.h"

#include "fp_context.h"
#include "fp_screen.h"

/* draw passes vertex counts as ushort: a batch must stay far below 65536
 * vertices (the smallest vertex is 16 bytes), or counts wrap and draw
 * writes past the buffer. */
#define FP_MAX_VBUF_INDICES 1024
#define FP_MAX_VBUF_BYTES   (64 * 1024)

struct fp_vbuf_render {
   struct vbuf_render base;
   struct fp_context *fp;
   enum pipe_prim_type prim;
   unsigned vertex_size;          /* bytes */
   void *vertices;
   size_t vertices_size;
};

static struct fp_vbuf_render *fp_vbuf(struct vbuf_render *r)
{
   return (struct fp_vbuf_render *)r;
}

static enum rast_interp fp_interp(unsigned tgsi_interp)
{
   switch (tgsi_interp) {
   case TGSI_INTERPOLATE_CONSTANT: return RAST_INTERP_CONSTANT;
   case TGSI_INTERPOLATE_LINEAR: return RAST_INTERP_LINEAR;
   case TGSI_INTERPOLATE_COLOR: return RAST_INTERP_COLOR;
   default: return RAST_INTERP_PERSPECTIVE;
   }
}

/* On points, the inputs GL_COORD_REPLACE turns into sprite coordinates:
 * gallium's sprite_coord_enable bits name GENERIC (or TEXCOORD) indices;
 * PCOORD always is one (llvmpipe's setup_point_coefficients). */
static bool fp_is_sprite_coord(const struct fp_context *fp, unsigned name, unsigned index)
{
   if (name == TGSI_SEMANTIC_PCOORD)
      return true;
   if (name != TGSI_SEMANTIC_GENERIC && name != TGSI_SEMANTIC_TEXCOORD)
      return false;
   return fp->rasterizer && index < 32 &&
          (fp->rasterizer->base.sprite_coord_enable >> index & 1u);
}

/* The vertex shader's output feeding fragment input (name, index), or -1.
 * Generic varyings reach TGSI shifted by 9 (st), and nir_to_tgsi spells a
 * shifted location of 32 or more as PATCH[location - 32] in one stage and
 * as GENERIC[location] in another (the vertex shader of a program with
 * transform feedback varyings, and its fragment shader: piglit
 * ext_transform_feedback-max-varyings): the two name the same slot. */
static int fp_vs_output(struct draw_context *draw, unsigned name, unsigned index)
{
   int src = draw_find_shader_output(draw, name, index);
   if (src >= 0)
      return src;
   if (name == TGSI_SEMANTIC_COLOR)
      return draw_find_shader_output(draw, TGSI_SEMANTIC_BCOLOR, index);
   if (name == TGSI_SEMANTIC_GENERIC && index >= 32)
      return draw_find_shader_output(draw, TGSI_SEMANTIC_PATCH, index - 32);
   if (name == TGSI_SEMANTIC_PATCH)
      return draw_find_shader_output(draw, TGSI_SEMANTIC_GENERIC, index + 32);
   return -1;
}

/* The rebase of a PERSPECTIVE input (fp_rebase.c) with the samplers bound. */
static void rebase_of(const struct fp_context *fp, unsigned i, struct rast_varying *vr)
{
   vr->rebase_mask = vr->rebase_even = 0;
   if (vr->interp == RAST_INTERP_PERSPECTIVE && !(fp->opts->debug & FP_DEBUG_NOREBASE))
      fp_rebase_modes(fp, i, &vr->rebase_mask, &vr->rebase_even);
}

/* Samplers bound since the layout was built (draw asks for the layout again
 * only when its own state changes, which a sampler is not): the rebase
 * masks brought up to date, the rest of the layout as it is. */
void fp_vbuf_update_rebase(struct fp_context *fp)
{
   if (!fp->vl_valid || fp->vl_fs != fp->fs)
      return;
   struct rast_vertex_layout vl = fp->vl;
   for (unsigned i = 0; i < vl.num_varyings; i++)
      rebase_of(fp, i, &vl.varying[i]);
   if (memcmp(&vl, &fp->vl, sizeof(vl)) != 0) {
      fp->vl = vl;
      rast_set_vertex_layout(fp->rast, &fp->vl);
   }
}

/* The last stage's output `semantic`, if it has one, as the next slot. */
static void emit_slot(struct draw_context *draw, struct vertex_info *vinfo, unsigned semantic,
                      bool *has, unsigned *slot)
{
   const int src = draw_find_shader_output(draw, semantic, 0);
   if (src >= 0) {
      *has = true;
      *slot = vinfo->num_attribs;
      draw_emit_vertex_attr(vinfo, EMIT_4F, src);
   }
}

/* The layout depends on the FS inputs, the VS outputs, the rasterizer's
 * sprite coordinates and on the extra attributes draw's stages (smooth
 * points and lines) allocate while a draw is running, so it is rebuilt
 * whenever draw asks. */
static const struct vertex_info *fp_vbuf_get_vertex_info(struct vbuf_render *r)
{
   struct fp_context *fp = fp_vbuf(r)->fp;
   struct draw_context *draw = fp->draw;
   struct vertex_info *vinfo = &fp->vinfo;
   struct rast_vertex_layout vl;

   memset(vinfo, 0, sizeof(*vinfo));
   memset(&vl, 0, sizeof(vl));
   draw_emit_vertex_attr(vinfo, EMIT_4F,
                         draw_find_shader_output(draw, TGSI_SEMANTIC_POSITION, 0));
   vl.pos_slot = 0;

   if (fp->fs) {
      const struct tgsi_shader_info *info = &fp->fs->info;
      unsigned n = MIN2(info->num_inputs, RAST_MAX_VARYINGS);
      for (unsigned i = 0; i < n; i++) {
         unsigned name = info->input_semantic_name[i];
         unsigned index = info->input_semantic_index[i];
         const int src = fp_vs_output(draw, name, index);
         vl.varying[i].slot = (uint8_t)vinfo->num_attribs;
         vl.varying[i].interp = fp_interp(info->input_interpolate[i]);
         /* fp_fs.c computes these itself: nothing to interpolate. */
         vl.varying[i].usage_mask = (name == TGSI_SEMANTIC_POSITION ||
                                     name == TGSI_SEMANTIC_FACE) ? 0
                                    : info->input_usage_mask[i];
         if (fp_is_sprite_coord(fp, name, index))
            vl.point_coord_mask |= 1u << i;
         rebase_of(fp, i, &vl.varying[i]);
         /* an array layer: divided in binary32 (rast_varying.float_mask) */
         if (vl.varying[i].interp == RAST_INTERP_PERSPECTIVE)
            vl.varying[i].float_mask = fp->fs->layer_read[i] & vl.varying[i].usage_mask;
         draw_emit_vertex_attr(vinfo, EMIT_4F, src);
      }
      vl.num_varyings = n;
   }
   /* Per-primitive registers the model reads from a vertex slot of their
    * own: gl_PointSize, for rast_point when point_size_per_vertex is set;
    * the face of unfilled polygons' lines and points (draw's unfilled
    * stage adds it as an extra output while such a draw runs); a geometry
    * shader's gl_Layer and gl_ViewportIndex, read as integers (draw has
    * applied the viewport's transform itself). */
   emit_slot(draw, vinfo, TGSI_SEMANTIC_PSIZE, &vl.has_psize, &vl.psize_slot);
   emit_slot(draw, vinfo, TGSI_SEMANTIC_FACE, &vl.has_face, &vl.face_slot);
   emit_slot(draw, vinfo, TGSI_SEMANTIC_LAYER, &vl.has_layer, &vl.layer_slot);
   emit_slot(draw, vinfo, TGSI_SEMANTIC_VIEWPORT_INDEX, &vl.has_viewport_index,
             &vl.viewport_slot);
   draw_compute_vertex_size(vinfo);
   vl.vertex_size = vinfo->num_attribs;

   if (!fp->vl_valid || memcmp(&vl, &fp->vl, sizeof(vl)) != 0) {
      fp->vl = vl;
      fp->vl_valid = true;
      rast_set_vertex_layout(fp->rast, &fp->vl);
   }
   fp->vl_fs = fp->fs;
   return vinfo;
}

static boolean fp_vbuf_allocate_vertices(struct vbuf_render *r, ushort vertex_size,
                                         ushort nr_vertices)
{
   struct fp_vbuf_render *v = fp_vbuf(r);
   size_t size = (size_t)vertex_size * nr_vertices;
   if (v->vertices_size < size) {
      align_free(v->vertices);
      v->vertices = align_malloc(size, 16);
      v->vertices_size = v->vertices ? size : 0;
   }
   v->vertex_size = vertex_size;
   return v->vertices != NULL;
}

static void *fp_vbuf_map_vertices(struct vbuf_render *r)
{
   return fp_vbuf(r)->vertices;
}

static void fp_vbuf_unmap_vertices(struct vbuf_render *r, ushort min_index, ushort max_index)
{
   (void)r; (void)min_index; (void)max_index;
}

static void fp_vbuf_release_vertices(struct vbuf_render *r)
{
   (void)r;   /* keep the allocation for the next batch */
}

static void fp_vbuf_set_primitive(struct vbuf_render *r, enum pipe_prim_type prim)
{
   fp_vbuf(r)->prim = prim;
}

typedef const float (*fp_vert)[4];

#define V(i) ((fp_vert)((const uint8_t *)v->vertices + (size_t)(IDX(i)) * stride))

/* One body for draw_elements and draw_arrays; IDX maps a position in the
 * primitive stream to a vertex number, TRI, LINE and POINT take each
 * primitive's vertices. */
#define FP_EMIT_PRIMS(TRI, LINE, POINT)                                        \
   do {                                                                        \
      const bool first = v->fp->rasterizer && v->fp->rasterizer->base.flatshade_first; \
      unsigned i;                                                              \
      switch (v->prim) {                                                       \
      case PIPE_PRIM_POINTS:                                                   \
         for (i = 0; i < nr; i++) POINT(V(i));                                 \
         break;                                                                \
      case PIPE_PRIM_LINES:                                                    \
         for (i = 1; i < nr; i += 2) LINE(V(i - 1), V(i));                     \
         break;                                                                \
      case PIPE_PRIM_LINE_STRIP:                                               \
         for (i = 1; i < nr; i++) LINE(V(i - 1), V(i));                        \
         break;                                                                \
      case PIPE_PRIM_LINE_LOOP:                                                \
         for (i = 1; i < nr; i++) LINE(V(i - 1), V(i));                        \
         if (nr > 1) LINE(V(nr - 1), V(0));                                    \
         break;                                                                \
      case PIPE_PRIM_TRIANGLES:                                                \
         for (i = 2; i < nr; i += 3) TRI(V(i - 2), V(i - 1), V(i));            \
         break;                                                                \
      case PIPE_PRIM_TRIANGLE_STRIP:                                           \
         for (i = 2; i < nr; i++) {                                            \
            if (first)                                                         \
               TRI(V(i - 2), V(i + (i & 1) - 1), V(i - (i & 1)));              \
            else                                                               \
               TRI(V(i + (i & 1) - 2), V(i - (i & 1) - 1), V(i));              \
         }                                                                     \
         break;                                                                \
      case PIPE_PRIM_TRIANGLE_FAN:                                             \
         for (i = 2; i < nr; i++) {                                            \
            if (first)                                                         \
               TRI(V(i - 1), V(i), V(0));                                      \
            else                                                               \
               TRI(V(0), V(i - 1), V(i));                                      \
         }                                                                     \
         break;                                                                \
      case PIPE_PRIM_POLYGON:   /* GL: vertex 0 provokes, whatever the mode */ \
         for (i = 2; i < nr; i++) {                                            \
            if (first)                                                         \
               TRI(V(0), V(i - 1), V(i));                                      \
            else                                                               \
               TRI(V(i - 1), V(i), V(0));                                      \
         }                                                                     \
         break;                                                                \
      case PIPE_PRIM_QUADS:                                                    \
         for (i = 3; i < nr; i += 4) {                                         \
            if (first) {                                                       \
               TRI(V(i), V(i - 3), V(i - 2));                                  \
               TRI(V(i), V(i - 2), V(i - 1));                                  \
            } else {                                                           \
               TRI(V(i - 3), V(i - 2), V(i));                                  \
               TRI(V(i - 2), V(i - 1), V(i));                                  \
            }                                                                  \
         }                                                                     \
         break;                                                                \
      case PIPE_PRIM_QUAD_STRIP:                                               \
         for (i = 3; i < nr; i += 2) {                                         \
            if (first) {                                                       \
               TRI(V(i), V(i - 3), V(i - 2));                                  \
               TRI(V(i), V(i - 1), V(i - 3));                                  \
            } else {                                                           \
               TRI(V(i - 3), V(i - 2), V(i));                                  \
               TRI(V(i - 1), V(i - 3), V(i));                                  \
            }                                                                  \
         }                                                                     \
         break;                                                                \
      default:                                                                 \
         break;                                                                \
      }                                                                        \
   } while (0)

#define FP_DRAW_TRI(a, b, c) rast_triangle(v->fp->rast, a, b, c)
#define FP_DRAW_LINE(a, b) rast_line(v->fp->rast, a, b)
#define FP_DRAW_POINT(a) rast_point(v->fp->rast, a)

/* Twice a triangle's area in pixels, from its window position (slot 0). */
static inline double fp_tri_area2(fp_vert a, fp_vert b, fp_vert c)
{
   const double d = ((double)b[0][0] - a[0][0]) * ((double)c[0][1] - a[0][1]) -
                    ((double)c[0][0] - a[0][0]) * ((double)b[0][1] - a[0][1]);
   return d < 0 ? -d : d;
}

/* The quads a batch's triangles cover, about (lines and points count
 * nothing): where an interpreted shader is bound, before it is drawn. */
#define FP_AREA_TRI(a, b, c) (area2 += fp_tri_area2(a, b, c))
#define FP_AREA_NONE(...) ((void)0)

/* Also brings the fragment shader up to date: draw's stages (polygon
 * stipple, smooth lines and points) bind their own variants mid-draw. */
static bool fp_vbuf_discard(struct fp_vbuf_render *v)
{
   if (v->fp->fs_dirty)
      fp_fs_validate(v->fp);
   /* a sample mask without the target's samples draws nothing, but the
    * vertex stage, transform feedback included, still ran */
   return (v->fp->rasterizer && v->fp->rasterizer->base.rasterizer_discard) ||
          !(v->fp->sample_mask & ((1u << v->fp->fb_samples) - 1));
}

/* The batch's vertices are reused by the next one: the model draws what it
 * queued (on every thread) before draw moves on. */
static void fp_vbuf_drawn(struct fp_vbuf_render *v)
{
   rast_flush(v->fp->rast);
   fp_fs_batch_done(v->fp);
}

static void fp_vbuf_draw_elements(struct vbuf_render *r, const ushort *indices, uint nr)
{
   struct fp_vbuf_render *v = fp_vbuf(r);
   const size_t stride = v->vertex_size;
#define IDX(i) indices[i]
   if (fp_fs_batch_may_compile(v->fp)) {
      double area2 = 0;
      FP_EMIT_PRIMS(FP_AREA_TRI, FP_AREA_NONE, FP_AREA_NONE);
      fp_fs_batch_ahead(v->fp, area2 / 8);
   }
   if (fp_vbuf_discard(v))
      return;
   FP_EMIT_PRIMS(FP_DRAW_TRI, FP_DRAW_LINE, FP_DRAW_POINT);
#undef IDX
   fp_vbuf_drawn(v);
}

static void fp_vbuf_draw_arrays(struct vbuf_render *r, unsigned start, uint nr)
{
   struct fp_vbuf_render *v = fp_vbuf(r);
   const size_t stride = v->vertex_size;
#define IDX(i) (start + (i))
   if (fp_fs_batch_may_compile(v->fp)) {
      double area2 = 0;
      FP_EMIT_PRIMS(FP_AREA_TRI, FP_AREA_NONE, FP_AREA_NONE);
      fp_fs_batch_ahead(v->fp, area2 / 8);
   }
   if (fp_vbuf_discard(v))
      return;
   FP_EMIT_PRIMS(FP_DRAW_TRI, FP_DRAW_LINE, FP_DRAW_POINT);
#undef IDX
   fp_vbuf_drawn(v);
}

/* draw's stream output counts of a draw, for the queries (fp_query.c). */
static void fp_vbuf_set_so_info(struct vbuf_render *r, unsigned stream, unsigned primitives,
                                unsigned generated)
{
   struct fp_context *fp = fp_vbuf(r)->fp;
   if (stream >= PIPE_MAX_VERTEX_STREAMS)
      return;
   fp->so_written[stream] += primitives;
   fp->so_generated[stream] += generated;
}

static void fp_vbuf_pipeline_statistics(struct vbuf_render *r,
                                        const struct pipe_query_data_pipeline_statistics *s)
{
   (void)r; (void)s;
}

static void fp_vbuf_destroy(struct vbuf_render *r)
{
   struct fp_vbuf_render *v = fp_vbuf(r);
   align_free(v->vertices);
   FREE(v);
}

struct vbuf_render *fp_create_vbuf_render(struct fp_context *fp)
{
   struct fp_vbuf_render *v = CALLOC_STRUCT(fp_vbuf_render);
   if (!v)
      return NULL;
   v->fp = fp;
   v->base.max_indices = FP_MAX_VBUF_INDICES;
   v->base.max_vertex_buffer_bytes = FP_MAX_VBUF_BYTES;
   v->base.get_vertex_info = fp_vbuf_get_vertex_info;
   v->base.allocate_vertices = fp_vbuf_allocate_vertices;
   v->base.map_vertices = fp_vbuf_map_vertices;
   v->base.unmap_vertices = fp_vbuf_unmap_vertices;
   v->base.set_primitive = fp_vbuf_set_primitive;
   v->base.draw_elements = fp_vbuf_draw_elements;
   v->base.draw_arrays = fp_vbuf_draw_arrays;
   v->base.release_vertices = fp_vbuf_release_vertices;
   v->base.set_stream_output_info = fp_vbuf_set_so_info;
   v->base.pipeline_statistics = fp_vbuf_pipeline_statistics;
   v->base.destroy = fp_vbuf_destroy;
   return &v->base;
}
