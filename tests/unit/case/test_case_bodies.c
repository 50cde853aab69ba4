/* io/case_bodies: the `bodies:` list of a case file, its defaults, the
 * polygon CSV files and the FILE:LINE:COL messages. */
#include "test_support.h"

#include "core/status.h"
#include "case/case_bodies.h"
#include "io/cfg_read.h"
#include "io/cfg_tree.h"

#include <stdio.h>
#include <string.h>

static void expect_message(const char *fragment) {
    if (!strstr(nspd_error_message(), fragment))
        fail_msg("message '%s' lacks '%s'", nspd_error_message(), fragment);
}

/* Reads `text` (a case file named `name`); returns the status. */
static int read_text(const char *name, const char *text, IbmBodySet *set, CfgDoc *doc) {
    assert_ok(cfg_doc_load_string(doc, name, text));
    return case_read_bodies(doc->root, "bodies", true, set);
}

static void test_all_shapes(void **state) {
    (void)state;
    const char *dir = test_scratch_dir("case_bodies");
    char csv[512], yaml[4096], name[600];
    snprintf(csv, sizeof csv, "%s/tri.csv", dir);
    FILE *f = fopen(csv, "w");
    assert_non_null(f);
    fprintf(f, "# a triangle, clockwise\nx, y\n0, 0\n0 1\n1;0  # last\n\n");
    fclose(f);
    snprintf(yaml, sizeof yaml,
             "bodies:\n"
             "  - {shape: circle, name: cyl, center: [2, 6], radius: 0.5, markers: 2048}\n"
             "  - shape: naca\n"
             "    digits: 0012\n"
             "    chord: 1.0\n"
             "    angle_deg: 2.5\n"
             "    wall: isothermal\n"
             "    wall_temperature: 300\n"
             "  - {shape: rectangle, min: [0, 0], max: [1, 2]}\n"
             "  - {shape: polygon, file: tri.csv, max_spacing: 0.25}\n");
    snprintf(name, sizeof name, "%s/case.yaml", dir);
    CfgDoc doc;
    IbmBodySet set;
    assert_ok(read_text(name, yaml, &set, &doc));
    assert_int_equal(set.count, 4);
    const IbmBodyConfig *b = set.bodies;
    assert_int_equal(b[0].kind, IBM_BODY_CIRCLE);
    assert_string_equal(b[0].name, "cyl");
    assert_true(b[0].center[0] == 2 && b[0].center[1] == 6 && b[0].radius == 0.5);
    assert_int_equal(b[0].markers, 2048);
    assert_int_equal(b[0].thermal, IBM_WALL_ADIABATIC);
    assert_int_equal(b[1].kind, IBM_BODY_NACA);
    assert_string_equal(b[1].digits, "0012");
    assert_string_equal(b[1].name, "body1");
    assert_int_equal(b[1].markers, 1024);
    assert_true(b[1].leading_edge[0] == 0 && b[1].leading_edge[1] == 0);
    assert_true(b[1].angle_deg == 2.5);
    assert_int_equal(b[1].thermal, IBM_WALL_ISOTHERMAL);
    assert_true(b[1].wall_temperature == 300);
    assert_int_equal(b[2].markers_per_side, 64);
    assert_int_equal(b[3].vertex_count, 3);
    assert_true(b[3].vertices[2] == 0 && b[3].vertices[3] == 1 && b[3].vertices[4] == 1);
    assert_true(b[3].max_spacing == 0.25);
    /* every body makes valid markers */
    for (int k = 0; k < 4; k++) {
        IbmPolyline p;
        assert_ok(ibm_body_markers(&b[k], &p));
        assert_true(ibm_polyline_area(&p) > 0.0);
        ibm_polyline_free(&p);
    }
    /* the defaults are written back into the tree (the resolved case) */
    CfgNode *item = cfg_map_find(doc.root, "bodies")->child[2];
    assert_non_null(cfg_map_find(item, "markers_per_side"));
    assert_non_null(cfg_map_find(item, "wall"));
    ibm_body_set_free(&set);
    cfg_doc_free(&doc);
}

static void expect_error(const char *text, const char *fragment) {
    CfgDoc doc;
    IbmBodySet set;
    assert_int_equal(read_text("case.yaml", text, &set, &doc), NSPD_ERR_INPUT);
    expect_message(fragment);
    ibm_body_set_free(&set);
    cfg_doc_free(&doc);
}

static void test_errors(void **state) {
    (void)state;
    expect_error("bodies:\n  - {shape: circle, center: [0, 0], radius: 1, colour: red}\n",
                 "case.yaml:2:");
    expect_error("bodies:\n  - {shape: circle, center: [0, 0], radius: 1, colour: red}\n",
                 "colour");
    expect_error("bodies:\n  - {shape: circel, center: [0, 0], radius: 1}\n", "circel");
    expect_error("bodies:\n  - {shape: circle, center: [0, 0], radius: -1}\n",
                 "case.yaml:2:37: bodies[0].radius: must be positive");
    expect_error("bodies:\n  - {shape: naca, digits: 12, chord: 1}\n", "4-digit");
    expect_error("bodies:\n  - {shape: naca, digits: 0000, chord: 1}\n", "zero thickness");
    expect_error("bodies:\n  - {shape: naca, digits: 2012, chord: 1}\n", "camber");
    expect_error("bodies:\n  - {shape: naca, digits: 0012, chord: 1, markers: 101}\n", "even");
    expect_error("bodies:\n  - {shape: rectangle, min: [0, 0], max: [1, 0]}\n", "max[1]");
    expect_error("bodies:\n  - {shape: circle, center: [0, 0], radius: 1, wall: isothermal}\n",
                 "wall_temperature");
    expect_error("bodies:\n  - {shape: circle, center: [0, 0], radius: 1, wall_temperature: 3}\n",
                 "only with wall: isothermal");
    expect_error("bodies:\n  - {shape: circle, center: [0, 0], radius: 1, markers: 4}\n",
                 "markers");
    expect_error("bodies:\n  - {shape: circle, name: a, center: [0, 0], radius: 1}\n"
                 "  - {shape: circle, name: a, center: [3, 0], radius: 1}\n",
                 "unique names");
    expect_error("bodies:\n  - {shape: circle, name: 'a b', center: [0, 0], radius: 1}\n",
                 "letters, digits");
    expect_error("bodies: []\n", "at least one body");
    expect_error("bodies:\n  - 3\n", "not a body");
    expect_error("other: 1\n", "bodies");
    /* polygons: missing, malformed, degenerate files */
    expect_error("bodies:\n  - {shape: polygon, file: /nonexistent/body.csv}\n",
                 "cannot read '/nonexistent/body.csv'");
    const char *dir = test_scratch_dir("case_bodies_bad");
    char path[512], text[1024];
    snprintf(path, sizeof path, "%s/bad.csv", dir);
    FILE *f = fopen(path, "w");
    fprintf(f, "x,y\n0,0\n1,0\n1,oops\n");
    fclose(f);
    snprintf(text, sizeof text, "bodies:\n  - {shape: polygon, file: %s}\n", path);
    expect_error(text, "bad.csv:4: '1,oops' is not a vertex");
    f = fopen(path, "w");
    fprintf(f, "0,0\n1,1\n2,2\n");
    fclose(f);
    expect_error(text, "zero area");
    f = fopen(path, "w");
    fprintf(f, "0,0\n1,0\n");
    fclose(f);
    expect_error(text, "expected at least 3");
}

static void test_optional(void **state) {
    (void)state;
    CfgDoc doc;
    IbmBodySet set;
    assert_ok(cfg_doc_load_string(&doc, "case.yaml", "flow: {}\n"));
    assert_ok(case_read_bodies(doc.root, "bodies", false, &set));
    assert_int_equal(set.count, 0);
    ibm_body_set_free(&set);
    cfg_doc_free(&doc);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_all_shapes),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_optional),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
