#include "io/figure.h"

#include "core/out_file.h"
#include "core/status.h"
#include "io/cairo_lib.h"
#include "io/colormap.h"
#include "io/png.h"

#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int figure_ticks(double lo, double hi, int max_ticks, double ticks[FIGURE_MAX_TICKS],
                 double *step) {
    ticks[0] = lo;
    *step = 0.0;
    if (!isfinite(lo) || !isfinite(hi) || !(hi > lo)) return 1;
    if (max_ticks < 2) max_ticks = 2;
    if (max_ticks > FIGURE_MAX_TICKS) max_ticks = FIGURE_MAX_TICKS;
    /* 1e-9 of a step: 1.0 / 0.2 = 5.000000000000001 still puts a tick at 1 */
    const double slack = 1e-9;
    static const double MANTISSA[3] = {1.0, 2.0, 5.0};
    double decade = pow(10.0, floor(log10((hi - lo) / max_ticks)));
    /* the first candidate gives more than max_ticks ticks; within two
     * decades one gives at most max_ticks, however the range is placed */
    for (int k = 0; k < 9; k++) {
        double s = MANTISSA[k % 3] * decade * pow(10.0, (double)(k / 3));
        double first = ceil(lo / s - slack), last = floor(hi / s + slack);
        if (last - first + 1.0 > max_ticks) continue;
        int n = (int)(last - first + 1.0);
        if (n < 1) break;
        for (int i = 0; i < n; i++) ticks[i] = (first + i) * s;
        *step = s;
        return n;
    }
    /* a range too narrow for a step between its ends: both ends */
    ticks[1] = hi;
    *step = hi - lo;
    return 2;
}

void figure_format_tick(double v, double step, char *buf, size_t size) {
    if (step > 0 && fabs(v) < 1e-6 * step) v = 0.0; /* no "-0" or "1e-17" */
    double big = fmax(fabs(v), step);
    if (step > 0 && big < 1e6 && step >= 1e-4) {
        int decimals = step >= 1.0 ? 0 : (int)ceil(-log10(step) - 1e-9);
        snprintf(buf, size, "%.*f", decimals, v);
    } else {
        snprintf(buf, size, "%.3g", v);
    }
}

void figure_length_unit(double extent_m, const char **unit, double *per_m) {
    if (extent_m < 1e-3) {
        *unit = "\xc2\xb5m"; /* µm */
        *per_m = 1e6;
    } else if (extent_m < 1.0) {
        *unit = "mm";
        *per_m = 1e3;
    } else {
        *unit = "m";
        *per_m = 1.0;
    }
}

void figure_format_time(double t, char *buf, size_t size) {
    double a = fabs(t);
    if (a == 0.0 || a >= 1.0 || !isfinite(t))
        snprintf(buf, size, "%.4g s", t);
    else if (a >= 1e-3)
        snprintf(buf, size, "%.4g ms", t * 1e3);
    else if (a >= 1e-6)
        snprintf(buf, size, "%.4g \xc2\xb5s", t * 1e6);
    else
        snprintf(buf, size, "%.4g ns", t * 1e9);
}

uint32_t figure_pixel(const uint8_t rgb[3]) {
    return (uint32_t)rgb[0] << 16 | (uint32_t)rgb[1] << 8 | (uint32_t)rgb[2];
}

/* ------------------------------------------------------------- the plan */

enum { LABEL_CHARS = 160, TICK_CHARS = 32 };

typedef struct {
    int n;
    double value[FIGURE_MAX_TICKS], step;
    char text[FIGURE_MAX_TICKS][TICK_CHARS];
} Ticks;

/* Everything drawn, placed: the layout, the ticks and the labels. */
typedef struct {
    FigureLayout lay;
    double per_m; /* axis unit per metre */
    Ticks x, y, bar[FIGURE_MAX_BARS];
    char x_label[LABEL_CHARS], y_label[LABEL_CHARS], bar_label[FIGURE_MAX_BARS][LABEL_CHARS];
    double bar_tick_w[FIGURE_MAX_BARS]; /* widest tick label of each bar */
} Plan;

/* The gaps of the page, pixels. */
enum {
    PAD = 14,        /* round the page */
    TICK_LEN = 6,    /* tick marks, outside the plot and the bars */
    TICK_GAP = 4,    /* tick mark to its label */
    LABEL_GAP = 10,  /* tick labels to the axis or bar label */
    BAR_W = 24,      /* a colour bar's width */
    BAR_GAP = 28,    /* plot to the first bar, a bar's label to the next bar */
    MIN_BAR_H = 240, /* a bar is at least this tall, so its ticks have room */
    MIN_PLOT = 480,  /* a smaller plot raster is enlarged by a whole factor */
};

static void set_font(cairo_t *cr, double px) {
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, px);
}

static double text_width(cairo_t *cr, const char *s) {
    cairo_text_extents_t e;
    cairo_text_extents(cr, s, &e);
    return e.x_advance;
}

static void make_ticks(Ticks *t, double lo, double hi, int max_ticks) {
    t->n = figure_ticks(lo, hi, max_ticks, t->value, &t->step);
    for (int k = 0; k < t->n; k++)
        figure_format_tick(t->value[k], t->step, t->text[k], sizeof t->text[k]);
}

static double widest(cairo_t *cr, const Ticks *t) {
    double w = 0.0;
    for (int k = 0; k < t->n; k++) w = fmax(w, text_width(cr, t->text[k]));
    return w;
}

/* Axis ticks: about one per 100 pixels, at most FIGURE_MAX_TICKS. */
static int ticks_for(int pixels) {
    int n = pixels / 100 + 1;
    return n < 3 ? 3 : n > FIGURE_MAX_TICKS ? FIGURE_MAX_TICKS : n;
}

static int bar_count(const Figure *fig) {
    return fig->bar_count < 1                 ? 1
           : fig->bar_count > FIGURE_MAX_BARS ? FIGURE_MAX_BARS
                                              : fig->bar_count;
}

static void plan_figure(cairo_t *cr, const Figure *fig, Plan *p) {
    memset(p, 0, sizeof *p);
    FigureLayout *lay = &p->lay;
    int longest = fig->w > fig->h ? fig->w : fig->h;
    lay->zoom = longest >= MIN_PLOT ? 1 : (MIN_PLOT + longest - 1) / longest;
    const int pw = fig->w * lay->zoom, ph = fig->h * lay->zoom;

    /* axes, in the unit that reads best for the plot's extent */
    const double lx = fig->w / fig->pixels_per_m, ly = fig->h / fig->pixels_per_m;
    const char *unit;
    figure_length_unit(fmax(lx, ly), &unit, &p->per_m);
    snprintf(p->x_label, sizeof p->x_label, "x [%s]", unit);
    snprintf(p->y_label, sizeof p->y_label, "y [%s]", unit);
    make_ticks(&p->x, fig->x0 * p->per_m, (fig->x0 + lx) * p->per_m, ticks_for(pw));
    make_ticks(&p->y, (fig->y_top - ly) * p->per_m, fig->y_top * p->per_m, ticks_for(ph));
    lay->bar_h = ph > MIN_BAR_H ? ph : MIN_BAR_H;
    lay->bar_w = BAR_W;
    const int bars = bar_count(fig);
    for (int b = 0; b < bars; b++) {
        const FigureScale *s = &fig->bar[b];
        make_ticks(&p->bar[b], s->lo, s->hi, ticks_for(lay->bar_h));
        snprintf(p->bar_label[b], sizeof p->bar_label[b], "%s [%s]", s->label ? s->label : "",
                 s->units ? s->units : "-");
    }

    set_font(cr, FIGURE_TICK_PX);
    double ytick_w = widest(cr, &p->y);
    for (int b = 0; b < bars; b++) p->bar_tick_w[b] = widest(cr, &p->bar[b]);
    set_font(cr, FIGURE_TITLE_PX);
    double title_w = text_width(cr, fig->title ? fig->title : "");

    lay->title_h = (int)(FIGURE_TITLE_PX + 2 * PAD);
    lay->plot_x = (int)ceil(PAD + FIGURE_LABEL_PX + LABEL_GAP + ytick_w + TICK_GAP + TICK_LEN);
    lay->plot_y = lay->title_h + (int)FIGURE_TICK_PX; /* room for the top tick's label */
    lay->bar_y = lay->plot_y;
    int x = lay->plot_x + pw + BAR_GAP;
    for (int b = 0; b < bars; b++) {
        lay->bar_x[b] = x;
        x += (int)ceil(BAR_W + TICK_LEN + TICK_GAP + p->bar_tick_w[b] + LABEL_GAP +
                       FIGURE_LABEL_PX) +
             BAR_GAP;
    }
    int width = x - BAR_GAP + PAD;
    if (width < (int)ceil(title_w) + 2 * PAD) width = (int)ceil(title_w) + 2 * PAD;
    lay->width = width;
    int below = ph > lay->bar_h ? ph : lay->bar_h;
    lay->height = lay->plot_y + below +
                  (int)ceil(TICK_LEN + TICK_GAP + FIGURE_TICK_PX + LABEL_GAP + FIGURE_LABEL_PX) +
                  PAD;
}

/* cairo's font cache and fontconfig's configuration live until the process
 * ends; freed at exit, so a leak checker (the ASan build of the tests) sees
 * only nspd's own blocks. Registered once, by the first picture. */
static void release_fonts(void) {
    cairo_debug_reset_static_data();
    FcFini();
}

static void register_release(void) {
    (void)atexit(release_fonts);
}

/* Called before anything is drawn: cairo opened (io/cairo_lib.h), its
 * fonts' release registered. */
static int cairo_in_use(void) {
    TRY(cairo_lib_load());
    static pthread_once_t once = PTHREAD_ONCE_INIT;
    (void)pthread_once(&once, register_release);
    return NSPD_OK;
}

/* A cairo context on a scratch surface, for measuring text. */
static int measure_context(cairo_surface_t **s, cairo_t **cr) {
    TRY(cairo_in_use());
    *s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1);
    *cr = cairo_create(*s);
    if (cairo_status(*cr) != CAIRO_STATUS_SUCCESS) {
        cairo_destroy(*cr);
        cairo_surface_destroy(*s);
        return NSPD_FAIL(NSPD_ERR_NOMEM, "cannot create a cairo context");
    }
    return NSPD_OK;
}

int figure_layout(const Figure *fig, FigureLayout *lay) {
    cairo_surface_t *s;
    cairo_t *cr;
    TRY(measure_context(&s, &cr));
    Plan p;
    plan_figure(cr, fig, &p);
    *lay = p.lay;
    cairo_destroy(cr);
    cairo_surface_destroy(s);
    return NSPD_OK;
}

/* ------------------------------------------------------------- drawing */

/* Text with its reference point at (x, y): ax = 0, 0.5, 1 puts x at the
 * text's left end, middle or right end; the text is centred on y vertically
 * (by its font's ascent) when mid_y, else y is the baseline. */
static void text_at(cairo_t *cr, const char *s, double x, double y, double ax, int mid_y) {
    cairo_font_extents_t fe;
    cairo_font_extents(cr, &fe);
    double base = mid_y ? y + 0.5 * (fe.ascent - fe.descent) : y;
    cairo_move_to(cr, x - ax * text_width(cr, s), base);
    cairo_show_text(cr, s);
}

/* Text turned a quarter counter-clockwise (reading upwards), centred on
 * (x, y). */
static void text_up(cairo_t *cr, const char *s, double x, double y) {
    cairo_save(cr);
    cairo_translate(cr, x, y);
    cairo_rotate(cr, -M_PI / 2);
    text_at(cr, s, 0.0, 0.0, 0.5, 1);
    cairo_restore(cr);
}

/* A 1-pixel line between pixel centres: crisp. */
static void hline(cairo_t *cr, double x0, double x1, double y) {
    cairo_move_to(cr, x0, floor(y) + 0.5);
    cairo_line_to(cr, x1, floor(y) + 0.5);
}

static void vline(cairo_t *cr, double x, double y0, double y1) {
    cairo_move_to(cr, floor(x) + 0.5, y0);
    cairo_line_to(cr, floor(x) + 0.5, y1);
}

/* Paints a raster of w x h pixels with its top-left corner at (x, y),
 * enlarged zx, zy times with no smoothing. */
static void paint_raster(cairo_t *cr, const uint32_t *px, int w, int h, double x, double y,
                         double zx, double zy) {
    /* cairo reads the pixels only (the surface is a paint source); its API
     * has no const */
    cairo_surface_t *src = cairo_image_surface_create_for_data((unsigned char *)(uintptr_t)px,
                                                               CAIRO_FORMAT_RGB24, w, h, 4 * w);
    cairo_save(cr);
    cairo_translate(cr, x, y);
    cairo_scale(cr, zx, zy);
    cairo_set_source_surface(cr, src, 0.0, 0.0);
    cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_NEAREST);
    cairo_rectangle(cr, 0.0, 0.0, w, h);
    cairo_fill(cr);
    cairo_restore(cr);
    cairo_surface_destroy(src);
}

static void draw_axes(cairo_t *cr, const Figure *fig, const Plan *p) {
    const FigureLayout *lay = &p->lay;
    const int pw = fig->w * lay->zoom, ph = fig->h * lay->zoom;
    const double page_per_unit = fig->pixels_per_m * lay->zoom / p->per_m;
    cairo_set_line_width(cr, 1.0);
    /* the frame, just outside the plot's pixels */
    cairo_rectangle(cr, lay->plot_x - 0.5, lay->plot_y - 0.5, pw + 1.0, ph + 1.0);
    set_font(cr, FIGURE_TICK_PX);
    const double bottom = lay->plot_y + ph;
    for (int k = 0; k < p->x.n; k++) {
        double x = lay->plot_x + (p->x.value[k] - fig->x0 * p->per_m) * page_per_unit;
        vline(cr, x, bottom + 1.0, bottom + 1.0 + TICK_LEN);
        text_at(cr, p->x.text[k], floor(x) + 0.5, bottom + TICK_LEN + TICK_GAP + FIGURE_TICK_PX,
                0.5, 0);
    }
    for (int k = 0; k < p->y.n; k++) {
        double y = lay->plot_y + (fig->y_top * p->per_m - p->y.value[k]) * page_per_unit;
        hline(cr, lay->plot_x - 1.0 - TICK_LEN, lay->plot_x - 1.0, y);
        text_at(cr, p->y.text[k], lay->plot_x - 1.0 - TICK_LEN - TICK_GAP, floor(y) + 0.5, 1.0, 1);
    }
    cairo_stroke(cr);
    set_font(cr, FIGURE_LABEL_PX);
    text_at(cr, p->x_label, lay->plot_x + 0.5 * pw,
            bottom + TICK_LEN + TICK_GAP + FIGURE_TICK_PX + LABEL_GAP + FIGURE_LABEL_PX, 0.5, 0);
    text_up(cr, p->y_label, PAD + 0.5 * FIGURE_LABEL_PX, lay->plot_y + 0.5 * ph);
}

static void draw_bar(cairo_t *cr, const Figure *fig, const Plan *p, int b) {
    const FigureLayout *lay = &p->lay;
    const FigureScale *s = &fig->bar[b];
    /* one pixel per row of the bar, stretched across it: nspd's colour map
     * exactly, top = hi */
    uint32_t column[8192];
    int n = lay->bar_h < 8192 ? lay->bar_h : 8192;
    for (int y = 0; y < n; y++) {
        uint8_t rgb[3];
        colormap_rgb(s->map, 1.0 - (double)y / (double)(n > 1 ? n - 1 : 1), rgb);
        column[y] = figure_pixel(rgb);
    }
    paint_raster(cr, column, 1, n, lay->bar_x[b], lay->bar_y, lay->bar_w, (double)lay->bar_h / n);
    const double x1 = lay->bar_x[b] + lay->bar_w, y0 = lay->bar_y, len = lay->bar_h;
    cairo_set_line_width(cr, 1.0);
    cairo_rectangle(cr, lay->bar_x[b] - 0.5, y0 - 0.5, lay->bar_w + 1.0, len + 1.0);
    set_font(cr, FIGURE_TICK_PX);
    const Ticks *t = &p->bar[b];
    const double range = s->hi > s->lo ? s->hi - s->lo : 1.0;
    for (int k = 0; k < t->n; k++) {
        /* value v sits on the row colormap_rgb gave the colour of v */
        double y = y0 + (1.0 - (t->value[k] - s->lo) / range) * (len - 1.0);
        hline(cr, x1, x1 + 1.0 + TICK_LEN, y);
        text_at(cr, t->text[k], x1 + 1.0 + TICK_LEN + TICK_GAP, floor(y) + 0.5, 0.0, 1);
    }
    cairo_stroke(cr);
    set_font(cr, FIGURE_LABEL_PX);
    text_up(cr, p->bar_label[b],
            x1 + 1.0 + TICK_LEN + TICK_GAP + p->bar_tick_w[b] + LABEL_GAP + 0.5 * FIGURE_LABEL_PX,
            y0 + 0.5 * len);
}

/* Copies an RGB24 cairo surface into an Image. */
static int surface_to_image(cairo_surface_t *page, Image *img) {
    cairo_surface_flush(page);
    const int w = cairo_image_surface_get_width(page), h = cairo_image_surface_get_height(page);
    const int stride = cairo_image_surface_get_stride(page);
    const unsigned char *data = cairo_image_surface_get_data(page);
    const uint8_t white[3] = {255, 255, 255};
    TRY(image_create(img, w, h, white));
    for (int y = 0; y < h; y++) {
        const uint32_t *row = (const uint32_t *)(const void *)(data + (size_t)y * (size_t)stride);
        uint8_t *out = img->rgb + 3 * (size_t)y * (size_t)w;
        for (int x = 0; x < w; x++) {
            out[3 * x + 0] = (uint8_t)(row[x] >> 16);
            out[3 * x + 1] = (uint8_t)(row[x] >> 8);
            out[3 * x + 2] = (uint8_t)row[x];
        }
    }
    return NSPD_OK;
}

/* An RGB page of w x h pixels and its context, with the font
 * options that give the same glyphs on every run (grey antialiasing, no
 * hinting that a desktop's settings could change). */
static cairo_t *page_open(int w, int h, cairo_surface_t **page) {
    *page = cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h);
    cairo_t *cr = cairo_create(*page);
    cairo_font_options_t *fo = cairo_font_options_create();
    cairo_font_options_set_antialias(fo, CAIRO_ANTIALIAS_GRAY);
    cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
    cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
    cairo_set_font_options(cr, fo);
    cairo_font_options_destroy(fo);
    return cr;
}

/* Ends the drawing and writes the page as a PNG (io/png.h: atomically);
 * frees the context and the page either way. */
static int page_write_png(cairo_t *cr, cairo_surface_t *page, const char *path) {
    int status = NSPD_OK;
    if (cairo_status(cr) != CAIRO_STATUS_SUCCESS)
        status = NSPD_FAIL(NSPD_ERR_NOMEM, "cannot draw '%s': %s", path,
                           cairo_status_to_string(cairo_status(cr)));
    cairo_destroy(cr);
    Image img = {0};
    if (status == NSPD_OK) status = surface_to_image(page, &img);
    cairo_surface_destroy(page);
    if (status == NSPD_OK) status = image_write_png(&img, path);
    image_destroy(&img);
    return status;
}

int figure_write_png(const char *path, const Figure *fig) {
    if (fig->w < 1 || fig->h < 1 || !(fig->pixels_per_m > 0))
        return NSPD_FAIL(NSPD_ERR_INTERNAL, "cannot draw '%s': empty plot area", path);
    cairo_surface_t *scratch;
    cairo_t *cr;
    TRY(measure_context(&scratch, &cr));
    Plan p;
    plan_figure(cr, fig, &p);
    cairo_destroy(cr);
    cairo_surface_destroy(scratch);

    cairo_surface_t *page;
    cr = page_open(p.lay.width, p.lay.height, &page);

    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_paint(cr);
    paint_raster(cr, fig->plot, fig->w, fig->h, p.lay.plot_x, p.lay.plot_y, p.lay.zoom, p.lay.zoom);
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    set_font(cr, FIGURE_TITLE_PX);
    text_at(cr, fig->title ? fig->title : "", PAD, PAD + FIGURE_TITLE_PX, 0.0, 0);
    draw_axes(cr, fig, &p);
    const int bars = bar_count(fig);
    for (int b = 0; b < bars; b++) {
        draw_bar(cr, fig, &p, b);
        cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    }
    return page_write_png(cr, page, path);
}

/* ---------------------------------------------------------- line plots */

/* The time unit that reads best for a span (s): "s", "ms", "µs" or "ns",
 * and its number per second. */
static void time_unit(double span, const char **unit, double *per_s) {
    static const char *const NAMES[] = {"s", "ms", "µs", "ns"};
    double scale = 1.0;
    int k = 0;
    while (k < 3 && span > 0.0 && span * scale < 1.0) {
        scale *= 1e3;
        k++;
    }
    *unit = NAMES[k];
    *per_s = scale;
}

/* [lo, hi] of the finite values of v (NaN, NaN when there are none). */
static void finite_range(const double *v, int64_t n, double *lo, double *hi) {
    *lo = (double)INFINITY;
    *hi = -(double)INFINITY;
    for (int64_t i = 0; i < n; i++)
        if (isfinite(v[i])) {
            *lo = fmin(*lo, v[i]);
            *hi = fmax(*hi, v[i]);
        }
    if (*lo > *hi) *lo = *hi = (double)NAN;
}

/* A constant (or empty) series still gets an axis around its value. */
static void open_range(double *lo, double *hi) {
    if (!isfinite(*lo)) {
        *lo = 0.0;
        *hi = 1.0;
    } else if (*hi <= *lo) {
        const double d = *lo != 0.0 ? 0.05 * fabs(*lo) : 1.0;
        *lo -= d;
        *hi += d;
    }
}

enum { LINE_W = 1000, LINE_H = 560 };

static cairo_status_t write_stream(void *closure, const unsigned char *data, unsigned int n) {
    return fwrite(data, 1, n, (FILE *)closure) == n ? CAIRO_STATUS_SUCCESS
                                                    : CAIRO_STATUS_WRITE_ERROR;
}

/* Draws the plot on cr (a LINE_W x LINE_H page). */
static void draw_line_plot(cairo_t *cr, const FigureLine *p) {
    const char *tu;
    double per_s;
    double x0, x1, y0, y1;
    finite_range(p->x, p->n, &x0, &x1);
    finite_range(p->y, p->n, &y0, &y1);
    open_range(&x0, &x1);
    open_range(&y0, &y1);
    time_unit(fmax(fabs(x0), fabs(x1)), &tu, &per_s);
    Ticks xt, yt;
    make_ticks(&xt, x0 * per_s, x1 * per_s, 8);
    make_ticks(&yt, y0, y1, 6);
    char x_label[LABEL_CHARS], y_label[LABEL_CHARS];
    snprintf(x_label, sizeof x_label, "%s [%s]", p->x_label, tu);
    if (p->y_units && p->y_units[0])
        snprintf(y_label, sizeof y_label, "%s [%s]", p->y_label, p->y_units);
    else
        snprintf(y_label, sizeof y_label, "%s", p->y_label);

    set_font(cr, FIGURE_TICK_PX);
    const double left = PAD + FIGURE_LABEL_PX + LABEL_GAP + widest(cr, &yt) + TICK_GAP + TICK_LEN;
    const double top = PAD + FIGURE_TITLE_PX + PAD;
    const double right = LINE_W - 2 * PAD;
    const double bottom =
        LINE_H - (PAD + FIGURE_LABEL_PX + LABEL_GAP + FIGURE_TICK_PX + TICK_GAP + TICK_LEN);
    const double sx = (right - left) / (x1 * per_s - x0 * per_s), sy = (bottom - top) / (y1 - y0);
#define PX(v) (left + ((v)*per_s - x0 * per_s) * sx)
#define PY(v) (bottom - ((v)-y0) * sy)

    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_paint(cr);
    /* grid at the ticks, then the frame and its tick marks and labels */
    cairo_set_line_width(cr, 1.0);
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    for (int k = 0; k < xt.n; k++) vline(cr, left + (xt.value[k] - x0 * per_s) * sx, top, bottom);
    for (int k = 0; k < yt.n; k++) hline(cr, left, right, PY(yt.value[k]));
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    cairo_rectangle(cr, floor(left) + 0.5, floor(top) + 0.5, floor(right - left),
                    floor(bottom - top));
    for (int k = 0; k < xt.n; k++) {
        const double x = left + (xt.value[k] - x0 * per_s) * sx;
        vline(cr, x, bottom, bottom + TICK_LEN);
        text_at(cr, xt.text[k], x, bottom + TICK_LEN + TICK_GAP + FIGURE_TICK_PX, 0.5, 0);
    }
    for (int k = 0; k < yt.n; k++) {
        const double y = PY(yt.value[k]);
        hline(cr, left - TICK_LEN, left, y);
        text_at(cr, yt.text[k], left - TICK_LEN - TICK_GAP, y, 1.0, 1);
    }
    cairo_stroke(cr);
    set_font(cr, FIGURE_LABEL_PX);
    text_at(cr, x_label, 0.5 * (left + right), LINE_H - PAD, 0.5, 0);
    text_up(cr, y_label, PAD + 0.5 * FIGURE_LABEL_PX, 0.5 * (top + bottom));
    set_font(cr, FIGURE_TITLE_PX);
    text_at(cr, p->title ? p->title : "", PAD, PAD + FIGURE_TITLE_PX, 0.0, 0);

    /* the series, broken where a value is not finite */
    cairo_save(cr);
    cairo_rectangle(cr, left, top, right - left, bottom - top);
    cairo_clip(cr);
    cairo_set_source_rgb(cr, 0.12, 0.31, 0.61);
    cairo_set_line_width(cr, 2.0);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    bool pen = false;
    for (int64_t i = 0; i < p->n; i++) {
        if (!isfinite(p->x[i]) || !isfinite(p->y[i])) {
            pen = false;
            continue;
        }
        if (pen)
            cairo_line_to(cr, PX(p->x[i]), PY(p->y[i]));
        else
            cairo_move_to(cr, PX(p->x[i]), PY(p->y[i]));
        pen = true;
    }
    if (p->n == 1 && isfinite(p->y[0])) /* a single sample: a dot */
        cairo_arc(cr, PX(p->x[0]), PY(p->y[0]), 3.0, 0.0, 2.0 * M_PI);
    cairo_stroke(cr);
    cairo_restore(cr);
    double lo, hi;
    finite_range(p->y, p->n, &lo, &hi);
    if (isnan(lo)) { /* say so rather than leave an empty frame */
        cairo_set_source_rgb(cr, 0.4, 0.4, 0.4);
        set_font(cr, FIGURE_LABEL_PX);
        text_at(cr, "no value during the run", 0.5 * (left + right), 0.5 * (top + bottom), 0.5, 1);
    }
#undef PX
#undef PY
}

int figure_write_line_plot(const char *path, const FigureLine *p, bool svg) {
    TRY(cairo_in_use());
    if (svg) {
        OutFile out;
        TRY(out_file_open(&out, path));
        cairo_surface_t *s =
            cairo_svg_surface_create_for_stream(write_stream, out.f, LINE_W, LINE_H);
        cairo_t *cr = cairo_create(s);
        draw_line_plot(cr, p);
        const bool failed = cairo_status(cr) != CAIRO_STATUS_SUCCESS;
        cairo_destroy(cr);
        cairo_surface_finish(s);
        const bool write_failed = failed || cairo_surface_status(s) != CAIRO_STATUS_SUCCESS;
        cairo_surface_destroy(s);
        return out_file_close(&out, write_failed);
    }
    cairo_surface_t *page;
    cairo_t *cr = page_open(LINE_W, LINE_H, &page);
    draw_line_plot(cr, p);
    return page_write_png(cr, page, path);
}
