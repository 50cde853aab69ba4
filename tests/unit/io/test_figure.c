/* io/figure: tick values, labels' units, and a labelled picture of a known
 * field (a linear ramp on a grid) read back with libpng: the plot area's
 * pixels are the colour map's colours of the field, the colour bars run from
 * the map's colour of lo to that of hi, and the title, axis and bar labels
 * put ink on the page (their glyphs are not compared). */
#include "test_support.h"

#include "io/colormap.h"
#include "io/figure.h"
#include "io/render.h"

#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static void expect_ticks(double lo, double hi, int max_ticks, int n, double first, double step) {
    double t[FIGURE_MAX_TICKS], s;
    assert_int_equal(figure_ticks(lo, hi, max_ticks, t, &s), n);
    assert_true(fabs(s - step) <= 1e-12 * step);
    for (int k = 0; k < n; k++) assert_true(fabs(t[k] - (first + k * step)) <= 1e-9 * step);
}

static void test_ticks(void **state) {
    (void)state;
    expect_ticks(0.0, 1.0, 8, 6, 0.0, 0.2);                  /* 0, 0.2, ..., 1: 0.1 gives 11 */
    expect_ticks(0.0, 1.37e5, 8, 7, 0.0, 2e4);               /* 0, 2e4, ..., 1.2e5: 1e4 gives 14 */
    expect_ticks(-1.0, 1.0, 8, 5, -1.0, 0.5);                /* 0.2 gives 11 */
    expect_ticks(0.0, 2.57, 8, 6, 0.0, 0.5);                 /* a Mach scale: 2.5 is the last */
    expect_ticks(-25.3, 25.3, 8, 5, -20.0, 10.0);            /* the plate in mm */
    expect_ticks(0.0, 1.0, 3, 3, 0.0, 0.5);                  /* fewer ticks asked: larger steps */
    expect_ticks(1.0e-3, 1.0e-3 + 6e-9, 8, 7, 1.0e-3, 1e-9); /* a narrow range off zero */
    double t[FIGURE_MAX_TICKS], s;
    assert_int_equal(figure_ticks(2.0, 2.0, 8, t, &s), 1); /* no range: the value alone */
    assert_true(t[0] == 2.0 && s == 0.0);
    assert_int_equal(figure_ticks(0.0, NAN, 8, t, &s), 1);
}

static void test_labels(void **state) {
    (void)state;
    char b[64];
    figure_format_tick(3 * 0.2, 0.2, b, sizeof b); /* 0.6000000000000001 */
    assert_string_equal(b, "0.6");
    figure_format_tick(-1e-17, 0.2, b, sizeof b); /* round-off of 0: not "-0.0" */
    assert_string_equal(b, "0.0");
    figure_format_tick(1.2e5, 2e4, b, sizeof b);
    assert_string_equal(b, "120000");
    figure_format_tick(0.05, 0.05, b, sizeof b);
    assert_string_equal(b, "0.05");
    figure_format_tick(1.5e6, 5e5, b, sizeof b);
    assert_string_equal(b, "1.5e+06");
    figure_format_time(16.7e-6, b, sizeof b);
    assert_string_equal(b, "16.7 \xc2\xb5s");
    figure_format_time(0.0, b, sizeof b);
    assert_string_equal(b, "0 s");
    figure_format_time(0.02, b, sizeof b);
    assert_string_equal(b, "20 ms");
    const char *unit;
    double per_m;
    figure_length_unit(0.0506, &unit, &per_m); /* the plate: 50.6 mm */
    assert_string_equal(unit, "mm");
    assert_true(per_m == 1e3);
    figure_length_unit(12.0, &unit, &per_m); /* the cylinder's flow domain */
    assert_string_equal(unit, "m");
}

/* Reads an RGB PNG; *w, *h its size. */
static uint8_t *read_png(const char *path, int *w, int *h) {
    png_image im;
    memset(&im, 0, sizeof im);
    im.version = PNG_IMAGE_VERSION;
    assert_true(png_image_begin_read_from_file(&im, path));
    im.format = PNG_FORMAT_RGB;
    uint8_t *px = malloc(PNG_IMAGE_SIZE(im));
    assert_non_null(px);
    assert_true(png_image_finish_read(&im, NULL, px, 0, NULL));
    *w = (int)im.width;
    *h = (int)im.height;
    return px;
}

static const uint8_t *pixel(const uint8_t *px, int w, int x, int y) {
    return px + 3 * ((size_t)y * (size_t)w + (size_t)x);
}

/* Dark pixels (text, lines) in [x0, x1) x [y0, y1). */
static int ink(const uint8_t *px, int w, int x0, int y0, int x1, int y1) {
    int n = 0;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) {
            const uint8_t *p = pixel(px, w, x, y);
            n += p[0] + p[1] + p[2] < 3 * 128;
        }
    return n;
}

static void expect_map(const uint8_t *got, ColormapKind map, double t) {
    uint8_t want[3];
    colormap_rgb(map, t, want);
    assert_memory_equal(got, want, 3);
}

/* A ramp v = x on 50 x 20 cells of 10 mm, x in [0, 0.5] m, y in [0, 0.2] m,
 * with cell (0, 0) masked and (optionally) one overlay point. */
enum { NX = 50, NY = 20 };

static void ramp_picture(const char *path, const RenderPoints *overlay, int max_pixels,
                         Figure *fig) {
    static double xf[NX + 1], yf[NY + 1], v[NX * NY];
    static uint8_t mask[NX * NY];
    for (int i = 0; i <= NX; i++) xf[i] = 0.01 * i;
    for (int j = 0; j <= NY; j++) yf[j] = 0.01 * j;
    for (int j = 0; j < NY; j++)
        for (int i = 0; i < NX; i++) v[j * NX + i] = 0.01 * (i + 0.5);
    mask[0] = 1;
    const RenderOptions ro = {0.0,          0.5,    COLORMAP_VIRIDIS, max_pixels,
                              {0, 0, 0, 0}, "ramp", "ramp",           "m"};
    assert_ok(render_grid_png(path, NX, NY, xf, yf, v, mask, &ro, overlay));
    /* the figure render_grid_png drew: its layout depends on these only */
    const double scale = max_pixels / 0.5;
    *fig = (Figure){.title = "ramp",
                    .w = (int)ceil(0.5 * scale),
                    .h = (int)ceil(0.2 * scale),
                    .x0 = 0.0,
                    .y_top = 0.2,
                    .pixels_per_m = scale,
                    .bar_count = overlay ? 2 : 1};
    fig->bar[0] = (FigureScale){"ramp", "m", 0.0, 0.5, COLORMAP_VIRIDIS};
    if (overlay)
        fig->bar[1] = (FigureScale){overlay->label, overlay->units, overlay->vmin, overlay->vmax,
                                    overlay->colormap};
}

static void test_ramp_picture(void **state) {
    (void)state;
    const char *dir = test_scratch_dir("figure_ramp");
    char path[1200], part[1300];
    snprintf(path, sizeof path, "%s/ramp.png", dir);
    Figure fig;
    ramp_picture(path, NULL, 500, &fig); /* 1000 pixels per metre: a cell is 10 pixels */
    snprintf(part, sizeof part, "%s.part", path);
    assert_int_equal(access(part, F_OK), -1); /* written whole, then renamed */
    FigureLayout lay;
    assert_ok(figure_layout(&fig, &lay));
    int w, h;
    uint8_t *px = read_png(path, &w, &h);
    assert_int_equal(w, lay.width);
    assert_int_equal(h, lay.height);
    assert_int_equal(lay.zoom, 1);

    /* the plot area: pixel (x, y) shows the cell under its centre */
    for (int y = 5; y < 200; y += 10)
        for (int x = 15; x < 500; x += 10) {
            int i = x / 10;
            expect_map(pixel(px, w, lay.plot_x + x, lay.plot_y + y), COLORMAP_VIRIDIS,
                       0.01 * (i + 0.5) / 0.5);
        }
    const uint8_t grey[3] = {128, 128, 128}; /* the masked cell, bottom left */
    assert_memory_equal(pixel(px, w, lay.plot_x + 5, lay.plot_y + 195), grey, 3);
    /* the frame is outside the plot's pixels */
    assert_true(ink(px, w, lay.plot_x - 1, lay.plot_y + 50, lay.plot_x, lay.plot_y + 51) == 1);

    /* the colour bar: hi at the top, lo at the bottom */
    const int bx = lay.bar_x[0] + lay.bar_w / 2;
    expect_map(pixel(px, w, bx, lay.bar_y), COLORMAP_VIRIDIS, 1.0);
    expect_map(pixel(px, w, bx, lay.bar_y + lay.bar_h - 1), COLORMAP_VIRIDIS, 0.0);
    expect_map(pixel(px, w, bx, lay.bar_y + (lay.bar_h - 1) / 2), COLORMAP_VIRIDIS,
               1.0 - (double)((lay.bar_h - 1) / 2) / (lay.bar_h - 1));

    /* text: the title band, the x tick labels and axis label below the plot,
     * the y ones left of it, the bar's tick labels and name right of it */
    assert_true(ink(px, w, 0, 0, w, lay.title_h) > 100);
    assert_true(ink(px, w, lay.plot_x, lay.plot_y + 208, lay.plot_x + 500, h) > 200);
    assert_true(ink(px, w, 0, lay.plot_y, lay.plot_x - 8, lay.plot_y + 200) > 100);
    assert_true(ink(px, w, lay.bar_x[0] + lay.bar_w + 1, lay.bar_y, w, lay.bar_y + lay.bar_h) >
                200);
    /* and nothing outside where it belongs: the page's right margin is blank */
    assert_int_equal(ink(px, w, w - 8, 0, w, h), 0);
    free(px);
}

static void test_overlay_has_second_bar(void **state) {
    (void)state;
    const char *dir = test_scratch_dir("figure_overlay");
    char path[1200];
    snprintf(path, sizeof path, "%s/overlay.png", dir);
    const double px0[1] = {0.255}, py0[1] = {0.105}, val[1] = {1.0};
    const RenderPoints pts = {1, {px0, py0}, val, 0.01, 0.0, 1.0, COLORMAP_INFERNO, "damage", "-"};
    Figure fig;
    ramp_picture(path, &pts, 100, &fig); /* 200 pixels per metre: a 100-pixel plot */
    FigureLayout lay;
    assert_ok(figure_layout(&fig, &lay));
    const int z = lay.zoom;
    assert_int_equal(z, 5); /* enlarged to the 480 pixels text needs round it */
    int w, h;
    uint8_t *px = read_png(path, &w, &h);
    assert_int_equal(w, lay.width);
    /* the point covers plot pixels 50-51 x 18-19 round (0.255, 0.105) m, each
     * z x z page pixels: its far corners */
    expect_map(pixel(px, w, lay.plot_x + z * 51 + z - 1, lay.plot_y + z * 19 + z - 1),
               COLORMAP_INFERNO, 1.0);
    /* a ramp pixel, enlarged without smoothing: its first and last page pixels */
    for (int d = 0; d < z; d += z - 1)
        expect_map(pixel(px, w, lay.plot_x + z * 10 + d, lay.plot_y + z * 18 + d), COLORMAP_VIRIDIS,
                   0.01 * 5.5 / 0.5);
    const int bx = lay.bar_x[1] + lay.bar_w / 2;
    assert_true(lay.bar_x[1] > lay.bar_x[0] + lay.bar_w);
    expect_map(pixel(px, w, bx, lay.bar_y), COLORMAP_INFERNO, 1.0);
    expect_map(pixel(px, w, bx, lay.bar_y + lay.bar_h - 1), COLORMAP_INFERNO, 0.0);
    /* the second bar has its own tick labels and name */
    assert_true(ink(px, w, lay.bar_x[1] + lay.bar_w + 1, lay.bar_y, w, lay.bar_y + lay.bar_h) >
                200);
    free(px);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ticks),
        cmocka_unit_test(test_labels),
        cmocka_unit_test(test_ramp_picture),
        cmocka_unit_test(test_overlay_has_second_bar),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
