/* Colour maps built in Oklab (Ottosson 2020), a space where straight lines
 * are close to perceptually uniform: the ramp passes through anchor colours
 * (those of matplotlib's viridis and inferno at t = 0, 1/4, ..., 1) and is
 * interpolated linearly in Oklab between them, so lightness rises
 * monotonically and equal steps in t read as equal steps in colour. The
 * 256-entry tables are built once, at the first call, under pthread_once:
 * renderers may then run on several threads at a time. */
#include "io/colormap.h"

#include <math.h>
#include <pthread.h>

enum { TABLE = 256, ANCHORS = 5 };

static const uint8_t VIRIDIS_ANCHORS[ANCHORS][3] = {{0x44, 0x01, 0x54},
                                                    {0x3b, 0x52, 0x8b},
                                                    {0x21, 0x91, 0x8c},
                                                    {0x5e, 0xc9, 0x62},
                                                    {0xfd, 0xe7, 0x25}};
static const uint8_t INFERNO_ANCHORS[ANCHORS][3] = {{0x00, 0x00, 0x04},
                                                    {0x57, 0x10, 0x6e},
                                                    {0xbc, 0x37, 0x54},
                                                    {0xf9, 0x8e, 0x09},
                                                    {0xfc, 0xff, 0xa4}};

static double srgb_to_linear(double c) {
    return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

static double linear_to_srgb(double c) {
    c = c < 0 ? 0 : c > 1 ? 1 : c;
    return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}

static void rgb_to_oklab(const uint8_t rgb[3], double lab[3]) {
    double r = srgb_to_linear(rgb[0] / 255.0), g = srgb_to_linear(rgb[1] / 255.0),
           b = srgb_to_linear(rgb[2] / 255.0);
    double l = cbrt(0.4122214708 * r + 0.5363325363 * g + 0.0514459929 * b);
    double m = cbrt(0.2119034982 * r + 0.6806995451 * g + 0.1073969566 * b);
    double s = cbrt(0.0883024619 * r + 0.2817188376 * g + 0.6299787005 * b);
    lab[0] = 0.2104542553 * l + 0.7936177850 * m - 0.0040720468 * s;
    lab[1] = 1.9779984951 * l - 2.4285922050 * m + 0.4505937099 * s;
    lab[2] = 0.0259040371 * l + 0.7827717662 * m - 0.8086757660 * s;
}

static void oklab_to_rgb(const double lab[3], uint8_t rgb[3]) {
    double l = lab[0] + 0.3963377774 * lab[1] + 0.2158037573 * lab[2];
    double m = lab[0] - 0.1055613458 * lab[1] - 0.0638541728 * lab[2];
    double s = lab[0] - 0.0894841775 * lab[1] - 1.2914855480 * lab[2];
    l = l * l * l;
    m = m * m * m;
    s = s * s * s;
    double lin[3] = {4.0767416621 * l - 3.3077115913 * m + 0.2309699292 * s,
                     -1.2684380046 * l + 2.6097574011 * m - 0.3413193965 * s,
                     -0.0041960863 * l - 0.7034186147 * m + 1.7076147010 * s};
    for (int c = 0; c < 3; c++) rgb[c] = (uint8_t)lround(255.0 * linear_to_srgb(lin[c]));
}

static void build(const uint8_t anchors[ANCHORS][3], uint8_t table[TABLE][3]) {
    double lab[ANCHORS][3];
    for (int a = 0; a < ANCHORS; a++) rgb_to_oklab(anchors[a], lab[a]);
    for (int i = 0; i < TABLE; i++) {
        double t = (double)i / (TABLE - 1) * (ANCHORS - 1);
        int a = (int)t < ANCHORS - 1 ? (int)t : ANCHORS - 2;
        double f = t - a, mix[3];
        for (int c = 0; c < 3; c++) mix[c] = (1 - f) * lab[a][c] + f * lab[a + 1][c];
        oklab_to_rgb(mix, table[i]);
    }
}

/* Written once, by build_tables under tables_once; read-only afterwards. */
static uint8_t viridis[TABLE][3], inferno[TABLE][3];
static pthread_once_t tables_once = PTHREAD_ONCE_INIT;

static void build_tables(void) {
    build(VIRIDIS_ANCHORS, viridis);
    build(INFERNO_ANCHORS, inferno);
}

void colormap_rgb(ColormapKind kind, double t, uint8_t rgb[3]) {
    pthread_once(&tables_once, build_tables);
    if (t != t) {
        rgb[0] = rgb[1] = rgb[2] = 128;
        return;
    }
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    int i = (int)lround(t * (TABLE - 1));
    if (kind == COLORMAP_GRAY) {
        rgb[0] = rgb[1] = rgb[2] = (uint8_t)i;
        return;
    }
    const uint8_t *c = kind == COLORMAP_INFERNO ? inferno[i] : viridis[i];
    rgb[0] = c[0];
    rgb[1] = c[1];
    rgb[2] = c[2];
}
