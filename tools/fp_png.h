/*
 * PNG in and out for the demo, the comparator and the e2e tests.
 * Images in memory are always 8-bit RGBA, rows top to bottom, so every
 * caller can compare buffers byte for byte whatever the file held.
 */
#ifndef FP_PNG_H
#define FP_PNG_H

#include <stddef.h>

/* 0 on success; on failure a message in err. */
int fp_png_write(const char *path, int w, int h, const unsigned char *rgba,
                 char *err, size_t errlen);

/* 0 on success (*rgba is malloc'ed, caller frees); on failure a message
 * in err that says why: missing file, not a PNG, or a libpng error. */
int fp_png_read(const char *path, int *w, int *h, unsigned char **rgba,
                char *err, size_t errlen);

#endif
