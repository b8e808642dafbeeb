#ifndef FP_RESOURCE_H
#define FP_RESOURCE_H

#include "pipe/p_state.h"

struct sw_displaytarget;

/* Linear storage: level L, layer/face/slice Z starts at
 * data + level_offset[L] + Z * img_stride[L]. */
struct fp_resource {
   struct pipe_resource base;
   struct sw_displaytarget *dt;    /* winsys surfaces; kept mapped */
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
