/* PNG images: an RGB canvas, simple drawing, and writing with libpng. */
#ifndef NSPD_IO_PNG_H
#define NSPD_IO_PNG_H

#include "io/colormap.h"

#include <stdint.h>

typedef struct {
    int width, height;
    uint8_t *rgb; /* width * height * 3, row 0 at the top */
} Image;

int image_create(Image *img, int width, int height, const uint8_t background[3]);
void image_destroy(Image *img);
void image_fill_rect(Image *img, int x0, int y0, int x1, int y1, const uint8_t rgb[3]);
/* A vertical colour bar at [x0, x1) x [y0, y1): top = 1, bottom = 0. */
void image_colorbar(Image *img, ColormapKind kind, int x0, int y0, int x1, int y1);
/* Writes img as an 8-bit RGB PNG. NSPD_ERR_IO on failure. */
int image_write_png(const Image *img, const char *path);

#endif
