#ifndef FP_FORMAT_H
#define FP_FORMAT_H

#include "pipe/p_format.h"
#include "rast/rast.h"

/* Colour target access for the model: the fast byte layouts, or load/store
 * trampolines around util_format's float unpack/pack.  False when the
 * format is not renderable. */
bool fp_format_color_target(enum pipe_format format, struct rast_color_target *ct);

enum rast_zs_layout fp_format_zs_layout(enum pipe_format format);

#endif
