/*
 * The diff heat map of fp-compare: black where the images agree, a colour
 * ramp by error magnitude elsewhere, and a legend strip under the image.
 */
#ifndef FP_HEATMAP_H
#define FP_HEATMAP_H

#include <stddef.h>

/* Height of the legend strip added below the image (0 if the image is too
 * narrow to hold one). */
int fp_heatmap_legend_height(int w);

/* Colour for a per-pixel error 1..255 (0 is black, handled by the caller). */
void fp_heatmap_ramp(int err, unsigned char rgb[3]);

/* err: w*h per-pixel errors, -1 for masked pixels.  out: w x (h + legend)
 * RGBA, allocated by the caller. */
void fp_heatmap_render(const int *err, int w, int h, unsigned char *out);

#endif
