/* The one symbol Mesa's sw_helper.h needs to create the fixpipe screen. */
#ifndef FP_PUBLIC_H
#define FP_PUBLIC_H

#ifdef __cplusplus
extern "C" {
#endif

struct pipe_screen;
struct sw_winsys;

struct pipe_screen *fixpipe_create_screen(struct sw_winsys *winsys);

#ifdef __cplusplus
}
#endif

#endif
