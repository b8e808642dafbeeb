/* PNG I/O through libpng, with its longjmp error path kept in one place. */
#include "fp_png.h"

#include <errno.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int fp_png_write(const char *path, int w, int h, const unsigned char *rgba,
                 char *err, size_t errlen)
{
   FILE *f = fopen(path, "wb");
   if (!f) {
      snprintf(err, errlen, "%s: cannot create: %s", path, strerror(errno));
      return -1;
   }
   png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
   png_infop info = png ? png_create_info_struct(png) : NULL;
   if (!png || !info || setjmp(png_jmpbuf(png))) {
      snprintf(err, errlen, "%s: libpng write error", path);
      png_destroy_write_struct(&png, &info);
      fclose(f);
      return -1;
   }
   png_init_io(png, f);
   png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8, PNG_COLOR_TYPE_RGBA,
                PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
   png_write_info(png, info);
   for (int y = 0; y < h; y++)
      png_write_row(png, (png_const_bytep)(rgba + (size_t)y * (size_t)w * 4));
   png_write_end(png, NULL);
   png_destroy_write_struct(&png, &info);
   if (fclose(f) != 0) {
      snprintf(err, errlen, "%s: write failed: %s", path, strerror(errno));
      return -1;
   }
   return 0;
}

int fp_png_read(const char *path, int *w, int *h, unsigned char **rgba,
                char *err, size_t errlen)
{
   *rgba = NULL;
   FILE *f = fopen(path, "rb");
   if (!f) {
      snprintf(err, errlen, "%s: cannot open: %s", path, strerror(errno));
      return -1;
   }
   unsigned char sig[8];
   if (fread(sig, 1, 8, f) != 8 || png_sig_cmp(sig, 0, 8) != 0) {
      snprintf(err, errlen, "%s: not a PNG file", path);
      fclose(f);
      return -1;
   }
   png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
   png_infop info = png ? png_create_info_struct(png) : NULL;
   /* volatile: assigned between setjmp and a possible longjmp. */
   unsigned char *volatile buf = NULL;
   png_bytep *volatile rows = NULL;
   if (!png || !info || setjmp(png_jmpbuf(png))) {
      snprintf(err, errlen, "%s: corrupt or unsupported PNG", path);
      png_destroy_read_struct(&png, &info, NULL);
      free(buf);
      free(rows);
      fclose(f);
      return -1;
   }
   png_init_io(png, f);
   png_set_sig_bytes(png, 8);
   png_read_info(png, info);

   /* Normalize every PNG flavour to 8-bit RGBA. */
   png_set_expand(png);
   png_set_strip_16(png);
   png_set_gray_to_rgb(png);
   png_set_filler(png, 0xff, PNG_FILLER_AFTER);
   png_set_interlace_handling(png);
   png_read_update_info(png, info);

   png_uint_32 pw = png_get_image_width(png, info), ph = png_get_image_height(png, info);
   if (pw == 0 || ph == 0 || pw > 32768 || ph > 32768 || png_get_rowbytes(png, info) != pw * 4) {
      snprintf(err, errlen, "%s: unsupported image size or layout", path);
      png_destroy_read_struct(&png, &info, NULL);
      fclose(f);
      return -1;
   }
   buf = malloc((size_t)pw * ph * 4);
   rows = malloc(sizeof(png_bytep) * ph);
   if (!buf || !rows)
      png_error(png, "out of memory");
   for (png_uint_32 y = 0; y < ph; y++)
      rows[y] = buf + (size_t)y * pw * 4;
   png_read_image(png, rows);
   png_read_end(png, NULL);
   png_destroy_read_struct(&png, &info, NULL);
   free(rows);
   fclose(f);
   *w = (int)pw;
   *h = (int)ph;
   *rgba = buf;
   return 0;
}
