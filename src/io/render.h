/* Pictures of fields: the plot area's raster is drawn here pixel by pixel,
 * then labelled by io/figure.h (title, axes in physical units, colour bars
 * with tick values, the field's name and units). Point clouds: each
 * material point is a square of its lattice spacing, coloured by a scalar;
 * the view is x to the right, y up, fitted to the deformed body. In 3D the
 * picture looks down z and shows, per pixel, the largest value along the
 * line of sight. */
#ifndef NSPD_IO_RENDER_H
#define NSPD_IO_RENDER_H

#include "io/colormap.h"

#include <stdint.h>

typedef struct {
    double vmin, vmax; /* colour scale: vmin -> 0, vmax -> 1 */
    ColormapKind colormap;
    int max_pixels;    /* longest side of the plot area */
    double window[4];  /* grid pictures: x0, y0, x1, y1 shown (m); x1 <= x0: the whole grid */
    const char *title; /* the title line */
    const char *label, *units; /* the colour bar's: "Mach number", "-" */
} RenderOptions;

/* Points drawn over a grid picture (the solid over the flow). */
typedef struct {
    int64_t n;
    const double *pos[2]; /* current positions, m */
    const double *values; /* coloured with `colormap` over [vmin, vmax] */
    double spacing;       /* each point a square of this side, m */
    double vmin, vmax;
    ColormapKind colormap;
    const char *label, *units; /* the second colour bar's */
} RenderPoints;

/* Writes a PNG of n points at positions pos[0], pos[1] (current, m), each
 * `spacing` wide, coloured by values[i], with a colour bar on the right. */
int render_points_png(const char *path, int64_t n, const double *const pos[2], const double *values,
                      double spacing, const RenderOptions *opt);

/* Writes a PNG of a cell field on a tensor-product grid: cell (i, j) spans
 * [xf[i], xf[i+1]] x [yf[j], yf[j+1]]; values[j * nx + i]. Pixels are square
 * in physical space, so stretched cells keep their true size. Cells whose
 * `mask` entry is non-zero (mask may be NULL) are drawn grey; `overlay`
 * points (may be NULL) are drawn on top with their own colour map, with a
 * second colour bar. */
int render_grid_png(const char *path, int nx, int ny, const double *xf, const double *yf,
                    const double *values, const uint8_t *mask, const RenderOptions *opt,
                    const RenderPoints *overlay);

#endif
