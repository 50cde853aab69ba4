#include "io/png.h"

#include "core/mem.h"
#include "core/status.h"
#include "core/out_file.h"

#include <png.h>
#include <stdio.h>

int image_create(Image *img, int width, int height, const uint8_t background[3]) {
    img->width = width;
    img->height = height;
    TRY(nspd_alloc(&img->rgb, (size_t)width * (size_t)height * 3, 1));
    image_fill_rect(img, 0, 0, width, height, background);
    return NSPD_OK;
}

void image_destroy(Image *img) {
    nspd_free(&img->rgb);
    img->width = img->height = 0;
}

void image_fill_rect(Image *img, int x0, int y0, int x1, int y1, const uint8_t rgb[3]) {
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 > img->width) x1 = img->width;
    if (y1 > img->height) y1 = img->height;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            uint8_t *p = img->rgb + 3 * ((size_t)y * (size_t)img->width + (size_t)x);
            p[0] = rgb[0];
            p[1] = rgb[1];
            p[2] = rgb[2];
        }
}

int image_write_png(const Image *img, const char *path) {
    OutFile out;
    TRY(out_file_open(&out, path));
    FILE *f = out.f;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!png || !info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        /* libpng's write error (a full disk): the close names the OS's reason */
        return out_file_close(&out, 1);
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)img->width, (png_uint_32)img->height, 8,
                 PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    /* one filter (each row less the one above) and zlib level 3: libpng's
     * adaptive choice among all five filters at level 6 took half of a
     * small run's time (the Sod tube with its pictures 0.45 s, 0.21 s
     * so) for files a quarter smaller than these (docs/PERFORMANCE.md,
     * "Pictures") */
    png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
    png_set_compression_level(png, 3);
    png_write_info(png, info);
    for (int y = 0; y < img->height; y++)
        png_write_row(png, img->rgb + 3 * (size_t)y * (size_t)img->width);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return out_file_close(&out, 0);
}
