/* Quick-look pictures of point clouds: each material point is a square of
 * its lattice spacing, coloured by a scalar; the view is x to the right, y
 * up, fitted to the deformed body. In 3D the picture looks down z and shows,
 * per pixel, the largest value along the line of sight. */
#ifndef NSPD_IO_RENDER_H
#define NSPD_IO_RENDER_H

#include "io/colormap.h"

#include <stdint.h>

typedef struct {
    double vmin, vmax; /* colour scale: vmin -> 0, vmax -> 1 */
    ColormapKind colormap;
    int max_pixels; /* longest side of the plot area */
} RenderOptions;

/* Writes a PNG of n points at positions pos[0], pos[1] (current, m), each
 * `spacing` wide, coloured by values[i], with a colour bar on the right. */
int render_points_png(const char *path, int64_t n, const double *const pos[2], const double *values,
                      double spacing, const RenderOptions *opt);

/* Writes a PNG of a cell field on a tensor-product grid: cell (i, j) spans
 * [xf[i], xf[i+1]] x [yf[j], yf[j+1]]; values[j * nx + i]. Pixels are square
 * in physical space, so stretched cells keep their true size. Cells whose
 * `mask` entry is non-zero (mask may be NULL) are drawn grey. */
int render_grid_png(const char *path, int nx, int ny, const double *xf, const double *yf,
                    const double *values, const uint8_t *mask, const RenderOptions *opt);

#endif
