/*
 * Queries: occlusion from the model's samples_passed counter, time from
 * the OS clock, transform feedback from draw's stream output counts
 * (fp_so.c), the model's counters (fp_query_driver.c).  Rendering is
 * synchronous, so every result is ready.
 */
#include "util/u_memory.h"
#include "util/os_time.h"
#include "draw/draw_context.h"

#include "fp_context.h"

struct fp_query {
   unsigned type, index;            /* index: the vertex stream */
   uint64_t start, end;
   /* stream output: primitives written and needed, per stream (the
    * counts at begin, then what was added by the end) */
   uint64_t written[PIPE_MAX_VERTEX_STREAMS], generated[PIPE_MAX_VERTEX_STREAMS];
   bool active;
   struct fp_counter_query *counter;   /* a driver query: the model's counters */
};

static bool fp_is_occlusion(unsigned type)
{
   return type == PIPE_QUERY_OCCLUSION_COUNTER || type == PIPE_QUERY_OCCLUSION_PREDICATE ||
          type == PIPE_QUERY_OCCLUSION_PREDICATE_CONSERVATIVE;
}

static bool fp_is_so(unsigned type)
{
   return type == PIPE_QUERY_PRIMITIVES_EMITTED || type == PIPE_QUERY_PRIMITIVES_GENERATED ||
          type == PIPE_QUERY_SO_STATISTICS || type == PIPE_QUERY_SO_OVERFLOW_PREDICATE ||
          type == PIPE_QUERY_SO_OVERFLOW_ANY_PREDICATE;
}

static struct pipe_query *fp_create_query(struct pipe_context *pipe, unsigned type,
                                          unsigned index)
{
   (void)pipe;
   if (fp_is_so(type)) {
      if (index >= PIPE_MAX_VERTEX_STREAMS)
         return NULL;
   } else if (!fp_is_occlusion(type) && type != PIPE_QUERY_GPU_FINISHED &&
              type != PIPE_QUERY_TIMESTAMP && type != PIPE_QUERY_TIME_ELAPSED &&
              !fp_is_driver_query(type)) {
      return NULL;
   }
   struct fp_query *q = CALLOC_STRUCT(fp_query);
   if (!q)
      return NULL;
   q->type = type;
   q->index = index;
   if (fp_is_driver_query(type) && !(q->counter = fp_counter_query_create(type))) {
      FREE(q);
      return NULL;
   }
   return (struct pipe_query *)q;
}

static void fp_destroy_query(struct pipe_context *pipe, struct pipe_query *pq)
{
   (void)pipe;
   if (pq)
      FREE(((struct fp_query *)pq)->counter);
   FREE(pq);
}

static uint64_t fp_query_now(struct fp_context *fp, unsigned type)
{
   if (fp_is_occlusion(type))
      return rast_get_stats(fp->rast)->samples_passed;
   return os_time_get_nano();
}

/* The stream output counts since begin (`end` false: the counts now). */
static void fp_so_counts(struct fp_context *fp, struct fp_query *q, bool end)
{
   for (unsigned s = 0; s < PIPE_MAX_VERTEX_STREAMS; s++) {
      q->written[s] = fp->so_written[s] - (end ? q->written[s] : 0);
      q->generated[s] = fp->so_generated[s] - (end ? q->generated[s] : 0);
   }
}

static bool fp_begin_query(struct pipe_context *pipe, struct pipe_query *pq)
{
   struct fp_context *fp = fp_context(pipe);
   struct fp_query *q = (struct fp_query *)pq;
   q->active = true;
   if (q->counter) {
      fp_counter_query_begin(fp, q->counter);
      return true;
   }
   draw_flush(fp->draw);
   if (fp_is_so(q->type)) {
      /* draw counts generated primitives without a target only when asked */
      if (q->type == PIPE_QUERY_PRIMITIVES_GENERATED &&
          fp->active_primgen_queries++ == 0)
         draw_collect_primitives_generated(fp->draw, true);
      fp_so_counts(fp, q, false);
      return true;
   }
   q->start = fp_query_now(fp, q->type);
   q->end = q->start;
   return true;
}

static bool fp_end_query(struct pipe_context *pipe, struct pipe_query *pq)
{
   struct fp_context *fp = fp_context(pipe);
   struct fp_query *q = (struct fp_query *)pq;
   q->active = false;
   if (q->counter) {
      fp_counter_query_end(fp, q->counter);
      return true;
   }
   draw_flush(fp->draw);
   if (fp_is_so(q->type)) {
      if (q->type == PIPE_QUERY_PRIMITIVES_GENERATED && --fp->active_primgen_queries == 0)
         draw_collect_primitives_generated(fp->draw, false);
      fp_so_counts(fp, q, true);
      return true;
   }
   q->end = fp_query_now(fp, q->type);
   return true;
}

static bool fp_get_query_result(struct pipe_context *pipe, struct pipe_query *pq, bool wait,
                                union pipe_query_result *result)
{
   struct fp_query *q = (struct fp_query *)pq;
   (void)pipe; (void)wait;
   if (q->counter) {
      fp_counter_query_result(q->counter, result);
      return true;
   }
   switch (q->type) {
   case PIPE_QUERY_OCCLUSION_COUNTER:
   case PIPE_QUERY_TIME_ELAPSED:
      result->u64 = q->end - q->start;
      break;
   case PIPE_QUERY_OCCLUSION_PREDICATE:
   case PIPE_QUERY_OCCLUSION_PREDICATE_CONSERVATIVE:
      result->b = q->end != q->start;
      break;
   case PIPE_QUERY_GPU_FINISHED:
      result->b = true;
      break;
   case PIPE_QUERY_TIMESTAMP:
      result->u64 = q->end;
      break;
   case PIPE_QUERY_PRIMITIVES_EMITTED:
      result->u64 = q->written[q->index];
      break;
   case PIPE_QUERY_PRIMITIVES_GENERATED:
      result->u64 = q->generated[q->index];
      break;
   case PIPE_QUERY_SO_STATISTICS:
      result->so_statistics.num_primitives_written = q->written[q->index];
      result->so_statistics.primitives_storage_needed = q->generated[q->index];
      break;
   case PIPE_QUERY_SO_OVERFLOW_PREDICATE:
      result->b = q->generated[q->index] > q->written[q->index];
      break;
   case PIPE_QUERY_SO_OVERFLOW_ANY_PREDICATE:
      result->b = false;
      for (unsigned s = 0; s < PIPE_MAX_VERTEX_STREAMS; s++)
         result->b |= q->generated[s] > q->written[s];
      break;
   default:
      return false;
   }
   return true;
}

static void fp_set_active_query_state(struct pipe_context *pipe, bool enable)
{
   (void)pipe; (void)enable;
}

static void fp_render_condition(struct pipe_context *pipe, struct pipe_query *query,
                                bool condition, enum pipe_render_cond_flag mode)
{
   struct fp_context *fp = fp_context(pipe);
   fp->render_cond_query = query;
   fp->render_cond_cond = condition;
   fp->render_cond_mode = mode;
}

bool fp_check_render_cond(struct fp_context *fp)
{
   union pipe_query_result result;
   if (!fp->render_cond_query)
      return true;
   if (!fp_get_query_result(&fp->pipe, fp->render_cond_query, true, &result))
      return true;
   struct fp_query *q = (struct fp_query *)fp->render_cond_query;
   bool passed = (q->type == PIPE_QUERY_OCCLUSION_COUNTER || q->type == PIPE_QUERY_TIME_ELAPSED ||
                  q->type == PIPE_QUERY_TIMESTAMP) ? result.u64 != 0 : result.b;
   /* Draw when the result differs from `condition` (gallium's meaning). */
   return passed != fp->render_cond_cond;
}

void fp_init_query_functions(struct fp_context *fp)
{
   struct pipe_context *p = &fp->pipe;
   p->create_query = fp_create_query;
   p->destroy_query = fp_destroy_query;
   p->begin_query = fp_begin_query;
   p->end_query = fp_end_query;
   p->get_query_result = fp_get_query_result;
   p->set_active_query_state = fp_set_active_query_state;
   p->render_condition = fp_render_condition;
}
