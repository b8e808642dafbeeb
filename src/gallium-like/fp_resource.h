#ifndef FP_RESOURCE_H
#define FP_RESOURCE_H

#include "pipe/p_state.h"

struct sw_displaytarget;

/* Linear storage: level L, layer/face/slice Z starts at
 * data + level_offset[L] + Z * img_stride[L]. */
struct fp_resource {
   struct pipe_resource base;
   struct sw_displaytarget *dt;    /* winsys surfaces; kept mapped */
   /* A window's front buffer (resource_create_front): its drawable, and
    * whether the window shows pixels the buffer does not have (another
    * buffer was presented to it since: a swap), which the next use of the
    * buffer first reads back (fp_resource_sync_front). */
   const void *front_private;
   bool front_stale;
   uint8_t *data;
   bool user_memory;
   unsigned stride[PIPE_MAX_TEXTURE_LEVELS];
   size_t img_stride[PIPE_MAX_TEXTURE_LEVELS];
   size_t level_offset[PIPE_MAX_TEXTURE_LEVELS];
};

static inline struct fp_resource *fp_resource(struct pipe_resource *r)
{
   return (struct fp_resource *)r;
}

/* A window's front buffer gets the window's pixels where another buffer
 * was presented to the window since it was last used (front_stale): what
 * reading or drawing into the front after a swap must see.  Every use of
 * a resource's memory by the driver calls it first; a no-op for any other
 * resource. */
void fp_resource_sync_front(struct pipe_resource *pt);
/* A buffer was presented to the window of `front_private`: its front
 * buffer, if it is another resource, is now stale. */
struct fp_screen;
void fp_resource_presented(struct fp_screen *s, struct pipe_resource *shown,
                           const void *front_private);

/* A multisampled resource keeps its samples as planes of the
 * single-sampled layout, one after the other, like layers: sample s of
 * layer l is image l * samples + s (rast.h, RAST_MSAA_SAMPLES). */
static inline unsigned fp_resource_samples(const struct pipe_resource *r)
{
   return r->nr_samples > 1 ? r->nr_samples : 1;
}

static inline uint8_t *fp_resource_image(struct pipe_resource *r, unsigned level,
                                         unsigned layer)
{
   struct fp_resource *fr = fp_resource(r);
   return fr->data + fr->level_offset[level] +
          (size_t)layer * fp_resource_samples(r) * fr->img_stride[level];
}

void fp_init_screen_resource_funcs(struct pipe_screen *screen);
void fp_init_context_resource_funcs(struct pipe_context *pipe);

#endif
