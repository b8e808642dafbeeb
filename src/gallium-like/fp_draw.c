/*
 * draw_vbo: map vertex and index buffers for draw (everything is CPU
 * memory), bring the fragment shader up to date, and let draw run.
 */
#include "util/u_draw.h"
#include "util/u_inlines.h"
#include "util/u_prim.h"
#include "draw/draw_context.h"

#include "fp_context.h"
#include "fp_resource.h"

static void fp_draw_vbo_model(struct pipe_context *pipe, const struct pipe_draw_info *info,
                              unsigned drawid_offset,
                              const struct pipe_draw_indirect_info *indirect,
                              const struct pipe_draw_start_count_bias *draws,
                              unsigned num_draws)
{
   struct fp_context *fp = fp_context(pipe);
   struct draw_context *draw = fp->draw;

   if (num_draws > 1) {
      util_draw_multi(pipe, info, drawid_offset, indirect, draws, num_draws);
      return;
   }
   if (indirect && indirect->buffer) {
      util_draw_indirect(pipe, info, indirect);
      return;
   }
   /* glDrawTransformFeedback: draw takes the count from the target */
   const bool count_from_so = indirect && indirect->count_from_stream_output;
   if ((!draws[0].count && !count_from_so) || !info->instance_count)
      return;
   if (!fp->vs || !fp->velems)
      return;
   if (!fp_check_render_cond(fp))
      return;

   if (unlikely(fp->vectors_pending))
      fp_vectors_start(fp);
   if (unlikely(fp->vectors_on))
      rast_vectors_draw(fp->rast);
   fp_vs_count(fp, (uint64_t)draws[0].count * info->instance_count);
   if (!fp_tess_validate(fp))
      return;
   if (fp->fs_dirty) {
      fp_fs_validate(fp);
      fp_vbuf_update_rebase(fp);
   }

   /* The sizes bound draw's vertex fetch (robust buffer access): a client
    * array's is unknown, so unbounded; a missing array has none, and
    * draw reads zeros for it, as llvmpipe. */
   for (unsigned i = 0; i < fp->num_vertex_buffers; i++) {
      const struct pipe_vertex_buffer *vb = &fp->vertex_buffer[i];
      const void *buf = NULL;
      size_t size = 0;
      if (vb->is_user_buffer) {
         buf = vb->buffer.user;
         size = buf ? ~(size_t)0 : 0;
      } else if (vb->buffer.resource) {
         buf = fp_resource(vb->buffer.resource)->data;
         size = vb->buffer.resource->width0;
      }
      draw_set_mapped_vertex_buffer(draw, i, buf, size);
   }

   const void *indices = NULL;
   if (info->index_size) {
      unsigned available = ~0u;
      if (info->has_user_indices) {
         indices = info->index.user;
      } else if (info->index.resource) {
         indices = fp_resource(info->index.resource)->data;
         available = info->index.resource->width0;
      }
      if (!indices)
         return;
      draw_set_indexes(draw, (const ubyte *)indices, info->index_size, available);
   }

   /* The extra outputs draw's stages add to each vertex (the unfilled
    * stage's face for lines and points of polygons, the primitive id the
    * assembler injects, the smooth lines' and points' coordinates), as
    * llvmpipe asks for them: the driver must, and a smooth line stage's
    * flush removes them all.  Cheap, and the same slots for the same
    * state, so every draw. */
   draw_prepare_shader_outputs(draw);
   draw_vbo(draw, info, drawid_offset, indirect, draws, num_draws, fp->patch_vertices);

   for (unsigned i = 0; i < fp->num_vertex_buffers; i++)
      draw_set_mapped_vertex_buffer(draw, i, NULL, 0);
   if (indices)
      draw_set_indexes(draw, NULL, 0, 0);
   /* Nothing may stay queued: user buffers are only valid during the call. */
   draw_flush(draw);
}

/* FIXPIPE_EVENTS takes each call's row around it (fp_events.c). */
static void fp_draw_vbo(struct pipe_context *pipe, const struct pipe_draw_info *info,
                        unsigned drawid_offset, const struct pipe_draw_indirect_info *indirect,
                        const struct pipe_draw_start_count_bias *draws, unsigned num_draws)
{
   struct fp_context *fp = fp_context(pipe);
   if (unlikely(fp->events_pending))
      fp_events_start(fp);
   if (likely(!fp->events)) {
      fp_draw_vbo_model(pipe, info, drawid_offset, indirect, draws, num_draws);
      return;
   }
   fp_events_draw_begin(fp);
   fp_draw_vbo_model(pipe, info, drawid_offset, indirect, draws, num_draws);
   fp_events_draw_end(fp);
}

void fp_init_draw_functions(struct fp_context *fp)
{
   fp->pipe.draw_vbo = fp_draw_vbo;
}
