/*
 * Transform feedback: draw's stream output writes the vertex stage's outputs
 * into buffer resources, as on softpipe (everything is CPU memory, so a
 * target's mapping is its resource's storage).  The primitives written and
 * needed per stream come back through the vbuf stage (fp_vbuf.c) for the
 * queries (fp_query.c).  Nothing of this reaches the model: stream output
 * lies before clipping, in the vertex stage draw runs.
 */
#include "util/u_inlines.h"
#include "util/u_memory.h"
#include "draw/draw_context.h"

#include "fp_context.h"
#include "fp_resource.h"

static struct pipe_stream_output_target *
fp_create_so_target(struct pipe_context *pipe, struct pipe_resource *buffer,
                    unsigned buffer_offset, unsigned buffer_size)
{
   struct draw_so_target *t = CALLOC_STRUCT(draw_so_target);
   if (!t)
      return NULL;
   t->target.context = pipe;
   t->target.reference.count = 1;
   pipe_resource_reference(&t->target.buffer, buffer);
   t->target.buffer_offset = buffer_offset;
   t->target.buffer_size = buffer_size;
   return &t->target;
}

static void fp_so_target_destroy(struct pipe_context *pipe,
                                 struct pipe_stream_output_target *target)
{
   (void)pipe;
   pipe_resource_reference(&target->buffer, NULL);
   FREE(target);
}

/* offsets[i] (unsigned)-1: append where the target left off (its
 * internal_offset, which draw keeps); anything else starts there. */
static void fp_set_so_targets(struct pipe_context *pipe, unsigned num_targets,
                              struct pipe_stream_output_target **targets,
                              const unsigned *offsets)
{
   struct fp_context *fp = fp_context(pipe);
   unsigned i;
   draw_flush(fp->draw);
   for (i = 0; i < num_targets; i++) {
      pipe_so_target_reference((struct pipe_stream_output_target **)&fp->so_targets[i],
                               targets[i]);
      if (targets[i]) {
         fp->so_targets[i]->mapping = fp_resource(targets[i]->buffer)->data;
         if (offsets[i] != (unsigned)-1)
            fp->so_targets[i]->internal_offset = offsets[i];
      }
   }
   for (; i < fp->num_so_targets; i++)
      pipe_so_target_reference((struct pipe_stream_output_target **)&fp->so_targets[i], NULL);
   fp->num_so_targets = num_targets;
   draw_set_mapped_so_targets(fp->draw, fp->num_so_targets, fp->so_targets);
}

/* Where an appending target goes on (glDrawTransformFeedback's count). */
static unsigned fp_so_offset(struct pipe_stream_output_target *target)
{
   return ((struct draw_so_target *)target)->internal_offset;
}

void fp_so_release(struct fp_context *fp)
{
   for (unsigned i = 0; i < fp->num_so_targets; i++)
      pipe_so_target_reference((struct pipe_stream_output_target **)&fp->so_targets[i], NULL);
   fp->num_so_targets = 0;
}

void fp_init_so_functions(struct fp_context *fp)
{
   struct pipe_context *p = &fp->pipe;
   p->create_stream_output_target = fp_create_so_target;
   p->stream_output_target_destroy = fp_so_target_destroy;
   p->set_stream_output_targets = fp_set_so_targets;
   p->stream_output_target_offset = fp_so_offset;
}
