/* Labelled pictures: a page with a title line, the plot area (a raster of
 * the field, copied pixel for pixel, or enlarged by a whole factor without
 * smoothing when it is small), x and y axes in physical units, and one or
 * two colour bars with tick values, the field's name and its units. Drawn
 * with cairo, written as PNG through io/png.h (atomically: core/out_file.h).
 * Text uses cairo's own text API with the fontconfig font "sans-serif"
 * (DejaVu Sans on Debian, installed by scripts/deps.sh). */
#ifndef NSPD_IO_FIGURE_H
#define NSPD_IO_FIGURE_H

#include "core/fields.h" /* ColormapKind */

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

enum { FIGURE_MAX_TICKS = 8, FIGURE_MAX_BARS = 2 };

/* Font sizes, page pixels: readable on a slide with the default plot area
 * of 1000 pixels. */
#define FIGURE_TITLE_PX 22.0
#define FIGURE_LABEL_PX 18.0
#define FIGURE_TICK_PX  16.0

/* A colour scale: [lo, hi] onto `map`, labelled "label [units]". */
typedef struct {
    const char *label, *units;
    double lo, hi;
    ColormapKind map;
} FigureScale;

typedef struct {
    const char *title;
    /* The plot raster: w x h pixels 0x00RRGGBB, row 0 at the top. Pixel
     * (i, j) covers x0 + [i, i + 1] / pixels_per_m in x and
     * y_top - [j, j + 1] / pixels_per_m in y (m). */
    int w, h;
    const uint32_t *plot;
    double x0, y_top, pixels_per_m;
    int bar_count; /* 1 or 2: the field's scale, then an overlay's */
    FigureScale bar[FIGURE_MAX_BARS];
} Figure;

/* Where things are on the page (pixels, row 0 at the top). */
typedef struct {
    int width, height;
    int zoom;           /* each plot pixel is zoom x zoom page pixels */
    int plot_x, plot_y; /* the plot area's top-left corner */
    int bar_x[FIGURE_MAX_BARS], bar_y, bar_w, bar_h; /* colour bars, hi at the top */
    int title_h;                                     /* the title band: rows [0, title_h) */
} FigureLayout;

/* Tick values for [lo, hi]: multiples of the smallest step of the form
 * {1, 2, 5} x 10^k that gives at most max_ticks (2..FIGURE_MAX_TICKS) ticks
 * inside the range. Returns the count (1, the value lo, when hi <= lo or a
 * bound is not finite) and the step (0 then). */
int figure_ticks(double lo, double hi, int max_ticks, double ticks[FIGURE_MAX_TICKS], double *step);
/* A tick value as text with the decimals its step needs ("0.0", "0.2",
 * "20000", "1.5e+06"; never "-0.0"). */
void figure_format_tick(double v, double step, char *buf, size_t size);
/* The length unit that reads best for an extent (m): "m", "mm" or "µm",
 * and its number per metre. */
void figure_length_unit(double extent_m, const char **unit, double *per_m);
/* A simulated time with the unit that reads best: "0 s", "16.7 µs", "20 ms". */
void figure_format_time(double t, char *buf, size_t size);
/* An RGB colour as a raster pixel. */
uint32_t figure_pixel(const uint8_t rgb[3]);

/* The page layout of fig (measures its text). */
int figure_layout(const Figure *fig, FigureLayout *lay);
/* Draws fig and writes it as an RGB PNG. NSPD_ERR_IO, NSPD_ERR_NOMEM. */
int figure_write_png(const char *path, const Figure *fig);

/* A line plot of y against time x (s; drawn in the unit that reads best),
 * broken where a value is not finite: for history columns. */
typedef struct {
    const char *title;
    const char *x_label;           /* "time" */
    const char *y_label, *y_units; /* the column, its unit ("" for none) */
    int64_t n;
    const double *x, *y;
} FigureLine;

/* Writes the plot (1000 x 560) as PNG, or as SVG when `svg`, atomically. */
int figure_write_line_plot(const char *path, const FigureLine *p, bool svg);

#endif
