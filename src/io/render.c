#include "io/render.h"

#include "core/mem.h"
#include "core/status.h"
#include "core/search.h" /* the cell of a pixel */
#include "io/figure.h"

#include <math.h>

enum { WHITE = 0xffffff, GREY = 0x808080 }; /* no data; a body's cells */

/* The figure of a plot raster and its colour scale(s). */
static Figure figure_of(const RenderOptions *opt, const uint32_t *plot, int w, int h, double x0,
                        double y_top, double scale) {
    Figure fig = {.title = opt->title,
                  .w = w,
                  .h = h,
                  .plot = plot,
                  .x0 = x0,
                  .y_top = y_top,
                  .pixels_per_m = scale,
                  .bar_count = 1};
    fig.bar[0] = (FigureScale){opt->label, opt->units, opt->vmin, opt->vmax, opt->colormap};
    return fig;
}

int render_points_png(const char *path, int64_t n, const double *const pos[2], const double *values,
                      double spacing, const RenderOptions *opt) {
    double lo[2] = {(double)INFINITY, (double)INFINITY},
           hi[2] = {-(double)INFINITY, -(double)INFINITY};
    for (int64_t i = 0; i < n; i++)
        for (int d = 0; d < 2; d++) {
            lo[d] = fmin(lo[d], pos[d][i]);
            hi[d] = fmax(hi[d], pos[d][i]);
        }
    if (!(hi[0] >= lo[0]) || !(hi[1] >= lo[1]))
        return NSPD_FAIL(NSPD_ERR_NUMERIC, "cannot draw '%s': positions are not finite", path);
    for (int d = 0; d < 2; d++) {
        lo[d] -= 0.5 * spacing;
        hi[d] += 0.5 * spacing;
    }
    double extent = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    double scale = opt->max_pixels / extent; /* pixels per metre */
    int w = (int)ceil((hi[0] - lo[0]) * scale), h = (int)ceil((hi[1] - lo[1]) * scale);

    /* per-pixel maximum of the normalised value; -1 = no point */
    float *best;
    TRY(nspd_alloc(&best, (size_t)w * (size_t)h, sizeof(float)));
    for (int64_t p = 0; p < (int64_t)w * h; p++) best[p] = -1.0f;
    double range = opt->vmax > opt->vmin ? opt->vmax - opt->vmin : 1.0;
    for (int64_t i = 0; i < n; i++) {
        /* the point's cell [x - dx/2, x + dx/2]^2, at least one pixel */
        int x0 = (int)floor((pos[0][i] - 0.5 * spacing - lo[0]) * scale);
        int x1 = (int)ceil((pos[0][i] + 0.5 * spacing - lo[0]) * scale);
        int y0 = (int)floor((hi[1] - pos[1][i] - 0.5 * spacing) * scale);
        int y1 = (int)ceil((hi[1] - pos[1][i] + 0.5 * spacing) * scale);
        if (x1 <= x0) x1 = x0 + 1;
        if (y1 <= y0) y1 = y0 + 1;
        float t = (float)fmin(1.0, fmax(0.0, (values[i] - opt->vmin) / range));
        for (int y = y0 < 0 ? 0 : y0; y < y1 && y < h; y++)
            for (int x = x0 < 0 ? 0 : x0; x < x1 && x < w; x++)
                if (t > best[(int64_t)y * w + x]) best[(int64_t)y * w + x] = t;
    }
    uint32_t *plot;
    int status = nspd_alloc(&plot, (size_t)w * (size_t)h, sizeof(uint32_t));
    if (status != NSPD_OK) {
        nspd_free(&best);
        return status;
    }
    for (int64_t p = 0; p < (int64_t)w * h; p++) {
        uint8_t rgb[3];
        if (best[p] < 0) {
            plot[p] = WHITE;
            continue;
        }
        colormap_rgb(opt->colormap, (double)best[p], rgb);
        plot[p] = figure_pixel(rgb);
    }
    nspd_free(&best);
    Figure fig = figure_of(opt, plot, w, h, lo[0], hi[1], scale);
    status = figure_write_png(path, &fig);
    nspd_free(&plot);
    return status;
}

/* Draws overlay points into the plot raster. */
static void draw_points(uint32_t *plot, int w, int h, double x0, double ytop, double scale,
                        const RenderPoints *pts) {
    double range = pts->vmax > pts->vmin ? pts->vmax - pts->vmin : 1.0;
    for (int64_t i = 0; i < pts->n; i++) {
        int xa = (int)floor((pts->pos[0][i] - 0.5 * pts->spacing - x0) * scale);
        int xb = (int)ceil((pts->pos[0][i] + 0.5 * pts->spacing - x0) * scale);
        int ya = (int)floor((ytop - pts->pos[1][i] - 0.5 * pts->spacing) * scale);
        int yb = (int)ceil((ytop - pts->pos[1][i] + 0.5 * pts->spacing) * scale);
        if (xb <= xa) xb = xa + 1;
        if (yb <= ya) yb = ya + 1;
        xa = xa < 0 ? 0 : xa;
        ya = ya < 0 ? 0 : ya;
        xb = xb > w ? w : xb;
        yb = yb > h ? h : yb;
        uint8_t rgb[3];
        colormap_rgb(pts->colormap, (pts->values[i] - pts->vmin) / range, rgb);
        const uint32_t px = figure_pixel(rgb);
        for (int y = ya; y < yb; y++)
            for (int x = xa; x < xb; x++) plot[(int64_t)y * w + x] = px;
    }
}

int render_grid_png(const char *path, int nx, int ny, const double *xf, const double *yf,
                    const double *values, const uint8_t *mask, const RenderOptions *opt,
                    const RenderPoints *overlay) {
    double x0 = xf[0], y0 = yf[0], x1 = xf[nx], y1 = yf[ny];
    if (opt->window[2] > opt->window[0] && opt->window[3] > opt->window[1]) {
        x0 = fmax(x0, opt->window[0]);
        y0 = fmax(y0, opt->window[1]);
        x1 = fmin(x1, opt->window[2]);
        y1 = fmin(y1, opt->window[3]);
    }
    double lx = x1 - x0, ly = y1 - y0;
    double scale = opt->max_pixels / fmax(lx, ly);
    int w = (int)ceil(lx * scale), h = (int)ceil(ly * scale);
    if (w < 1) w = 1;
    if (h < 1) h = 1;
    uint32_t *plot;
    TRY(nspd_alloc(&plot, (size_t)w * (size_t)h, sizeof(uint32_t)));
    int *column;
    int status = nspd_alloc(&column, (size_t)w, sizeof(int));
    if (status != NSPD_OK) {
        nspd_free(&plot);
        return status;
    }
    for (int x = 0; x < w; x++) column[x] = search_bracket(xf, 0, nx, x0 + (x + 0.5) / scale);
    double range = opt->vmax > opt->vmin ? opt->vmax - opt->vmin : 1.0;
    for (int y = 0; y < h; y++) {
        int j = search_bracket(yf, 0, ny, y1 - (y + 0.5) / scale);
        for (int x = 0; x < w; x++) {
            int64_t cell = (int64_t)j * nx + column[x];
            uint32_t px = GREY;
            if (!mask || !mask[cell]) {
                uint8_t rgb[3];
                colormap_rgb(opt->colormap, (values[cell] - opt->vmin) / range, rgb);
                px = figure_pixel(rgb);
            }
            plot[(int64_t)y * w + x] = px;
        }
    }
    if (overlay) draw_points(plot, w, h, x0, y1, scale, overlay);
    Figure fig = figure_of(opt, plot, w, h, x0, y1, scale);
    if (overlay) {
        fig.bar_count = 2;
        fig.bar[1] = (FigureScale){overlay->label, overlay->units, overlay->vmin, overlay->vmax,
                                   overlay->colormap};
    }
    status = figure_write_png(path, &fig);
    nspd_free(&column);
    nspd_free(&plot);
    return status;
}
