/* PNG images: an RGB canvas, and writing it with libpng (atomically,
 * through core/out_file.h). io/figure.h draws the pictures. */
#ifndef NSPD_IO_PNG_H
#define NSPD_IO_PNG_H

#include <stdint.h>

typedef struct {
    int width, height;
    uint8_t *rgb; /* width * height * 3, row 0 at the top */
} Image;

int image_create(Image *img, int width, int height, const uint8_t background[3]);
void image_destroy(Image *img);
void image_fill_rect(Image *img, int x0, int y0, int x1, int y1, const uint8_t rgb[3]);
/* Writes img as an 8-bit RGB PNG. NSPD_ERR_IO on failure. */
int image_write_png(const Image *img, const char *path);

#endif
