/* io/ writers: PNG (read back with libpng), VTK XML (block sizes and
 * values read back independently of VTK), JSON, colour maps. */
#include "test_support.h"

#include "core/status.h"
#include "io/colormap.h"
#include "io/json.h"
#include "io/png.h"
#include "io/vtk.h"

#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void test_png_round_trip(void **state) {
    (void)state;
    const char *dir = test_scratch_dir("writers_png");
    char path[1200];
    snprintf(path, sizeof path, "%s/a.png", dir);
    Image img;
    const uint8_t white[3] = {255, 255, 255}, red[3] = {200, 10, 20};
    assert_ok(image_create(&img, 40, 30, white));
    image_fill_rect(&img, 5, 6, 10, 12, red);
    assert_ok(image_write_png(&img, path));
    image_destroy(&img);

    png_image read;
    memset(&read, 0, sizeof read);
    read.version = PNG_IMAGE_VERSION;
    assert_true(png_image_begin_read_from_file(&read, path));
    read.format = PNG_FORMAT_RGB;
    assert_int_equal(read.width, 40);
    assert_int_equal(read.height, 30);
    uint8_t *px = malloc(PNG_IMAGE_SIZE(read));
    assert_true(png_image_finish_read(&read, NULL, px, 0, NULL));
    assert_memory_equal(px + 3 * (7 * 40 + 6), red, 3);
    assert_memory_equal(px, white, 3);
    free(px);
}

static void test_colormap_is_monotone_in_lightness(void **state) {
    (void)state;
    double last = -1;
    for (int i = 0; i <= 20; i++) {
        uint8_t c[3];
        colormap_rgb(COLORMAP_VIRIDIS, i / 20.0, c);
        double luma = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
        assert_true(luma > last); /* a perceptual map gets lighter all the way */
        last = luma;
    }
    uint8_t lo[3], hi[3];
    colormap_rgb(COLORMAP_VIRIDIS, -5, lo);
    colormap_rgb(COLORMAP_VIRIDIS, 0, hi);
    assert_memory_equal(lo, hi, 3); /* clamped */
}

/* Reads the appended block that starts at `offset` (after the '_'). */
static const uint8_t *block(const char *file, long appended, unsigned long long offset,
                            uint64_t *bytes) {
    const uint8_t *p = (const uint8_t *)file + appended + offset;
    memcpy(bytes, p, 8);
    return p + 8;
}

static void test_vtu_layout(void **state) {
    (void)state;
    const char *dir = test_scratch_dir("writers_vtk");
    char path[1200];
    snprintf(path, sizeof path, "%s/p.vtu", dir);
    double x[3] = {0, 1, 2}, y[3] = {5, 6, 7}, s[3] = {0.5, 0.25, 0.125};
    const double *pos[3] = {x, y, NULL};
    VtkField f[] = {{"s", 1, {s, NULL, NULL}}, {"v", 3, {x, y, NULL}}};
    assert_ok(vtk_write_points(path, 3, pos, f, 2));
    char *text = test_read_file(path);
    assert_non_null(text);
    char *appended = strstr(text, "encoding=\"raw\">\n_");
    assert_non_null(appended);
    long start = (long)(appended - text) + (long)strlen("encoding=\"raw\">\n_");
    /* the field "v" is the second array: after s (8 + 24 bytes) */
    unsigned long long off;
    char *decl = strstr(text, "Name=\"v\"");
    assert_non_null(decl);
    assert_int_equal(sscanf(strstr(decl, "offset=\"") + 8, "%llu", &off), 1);
    assert_int_equal(off, 32);
    uint64_t bytes;
    const uint8_t *data = block(text, start, off, &bytes);
    assert_int_equal(bytes, 3 * 3 * 8);
    double v[9];
    memcpy(v, data, sizeof v);
    assert_true(v[3] == 1 && v[4] == 6 && v[5] == 0); /* interleaved, z = 0 */
    free(text);

    PvdSeries series = {0};
    char pvd[1200];
    snprintf(pvd, sizeof pvd, "%s/p.pvd", dir);
    assert_ok(pvd_add(&series, pvd, 0.0, "p.vtu"));
    assert_ok(pvd_add(&series, pvd, 1.5e-6, "q.vtu"));
    text = test_read_file(pvd);
    assert_non_null(strstr(text, "timestep=\"1.5e-06\" part=\"0\" file=\"q.vtu\""));
    free(text);
    pvd_free(&series);
}

static void test_json(void **state) {
    (void)state;
    const char *dir = test_scratch_dir("writers_json");
    char path[1200];
    snprintf(path, sizeof path, "%s/s.json", dir);
    FILE *f = fopen(path, "w");
    JsonWriter w;
    json_begin(&w, f);
    json_number(&w, "a", 1.5);
    json_int(&w, "b", 7);
    json_bool(&w, "c", true);
    json_string(&w, "d", "say \"hi\"");
    json_number(&w, "e", 0.0 / 0.0);
    json_end(&w);
    fclose(f);
    char *text = test_read_file(path);
    assert_string_equal(
        text, "{\n  \"a\": 1.5,\n  \"b\": 7,\n  \"c\": true,\n  \"d\": \"say \\\"hi\\\"\",\n"
              "  \"e\": null\n}\n");
    free(text);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_png_round_trip),
        cmocka_unit_test(test_colormap_is_monotone_in_lightness),
        cmocka_unit_test(test_vtu_layout),
        cmocka_unit_test(test_json),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
