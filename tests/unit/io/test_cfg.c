/* io/cfg_*: YAML tree with positions, typed getters, unknown keys,
 * overrides, and the resolved-case round trip. */
#include "test_support.h"

#include "core/status.h"
#include "io/cfg_read.h"
#include "io/cfg_tree.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Loads text; asserts success. */
static void load(CfgDoc *doc, const char *text) {
    assert_ok(cfg_doc_load_string(doc, "case.yaml", text));
}

/* Asserts that the last error message contains `fragment`. */
static void expect_message(const char *fragment) {
    if (!strstr(nspd_error_message(), fragment))
        fail_msg("message '%s' lacks '%s'", nspd_error_message(), fragment);
}

static void test_positions_and_paths(void **state) {
    (void)state;
    CfgDoc doc;
    load(&doc, "name: a\nsolid:\n  material:\n    density: 8000\n  list:\n    - {x: 1}\n");
    CfgNode *solid = cfg_map_find(doc.root, "solid");
    CfgNode *density = cfg_map_find(cfg_map_find(solid, "material"), "density");
    assert_int_equal(density->line, 4);
    assert_int_equal(density->col, 5);
    char path[128], where[128];
    cfg_node_path(density, path, sizeof path);
    assert_string_equal(path, "solid.material.density");
    cfg_node_where(density, where, sizeof where);
    assert_string_equal(where, "case.yaml:4:5");
    CfgNode *x = cfg_map_find(cfg_map_find(solid, "list")->child[0], "x");
    cfg_node_path(x, path, sizeof path);
    assert_string_equal(path, "solid.list[0].x");
    cfg_doc_free(&doc);
}

static void test_syntax_and_structure_errors(void **state) {
    (void)state;
    CfgDoc doc;
    assert_int_equal(cfg_doc_load_string(&doc, "case.yaml", "a: 1\nb: [1, 2\n"), NSPD_ERR_INPUT);
    expect_message("case.yaml:3:1: YAML syntax error");
    assert_int_equal(cfg_doc_load_string(&doc, "case.yaml", "a: 1\nb: 2\na: 3\n"), NSPD_ERR_INPUT);
    expect_message("case.yaml:3:1: duplicate key 'a' (first given at line 1)");
    assert_int_equal(cfg_doc_load_string(&doc, "case.yaml", "a: &x 1\nb: *x\n"), NSPD_ERR_INPUT);
    expect_message("case.yaml:2:4: YAML aliases");
    assert_int_equal(cfg_doc_load_string(&doc, "case.yaml", "- 1\n- 2\n"), NSPD_ERR_INPUT);
    expect_message("expected a map");
    assert_int_equal(cfg_doc_load_string(&doc, "case.yaml", "a: 1\n---\nb: 2\n"), NSPD_ERR_INPUT);
    expect_message("a second YAML document");
    load(&doc, "# only a comment\n");
    assert_int_equal(doc.root->kind, CFG_MAP);
    assert_int_equal(doc.root->count, 0);
    cfg_doc_free(&doc);
    assert_int_equal(cfg_doc_load_file(&doc, "/nonexistent/case.yaml"), NSPD_ERR_IO);
}

static void test_typed_getters(void **state) {
    (void)state;
    CfgDoc doc;
    load(&doc, "d: 2.5e3\ni: 12\nb: true\ns: plane_stress\nv: [1, 2]\nq: \"7\"\nn: ~\n");
    CfgNode *r = doc.root;
    double d, v[2];
    int64_t i;
    bool b;
    int e;
    static const char *const names[] = {"plane_stress", "plane_strain", NULL};
    assert_ok(cfg_req_double(r, "d", &d));
    assert_true(d == 2500.0);
    assert_ok(cfg_req_int(r, "i", &i));
    assert_int_equal(i, 12);
    assert_ok(cfg_opt_bool(r, "b", false, &b));
    assert_true(b);
    assert_ok(cfg_req_enum(r, "s", names, &e));
    assert_int_equal(e, 0);
    assert_ok(cfg_req_vec(r, "v", 2, v));
    assert_true(v[0] == 1 && v[1] == 2);
    /* a quoted number is text */
    assert_int_equal(cfg_req_double(r, "q", &d), NSPD_ERR_INPUT);
    expect_message("case.yaml:6:1: q: got text in quotes; expected a number");
    /* null means "use the default", and the default is written back */
    assert_ok(cfg_opt_double(r, "n", 4.0, &d));
    assert_true(d == 4.0);
    assert_string_equal(cfg_map_find(r, "n")->text, "4");
    assert_ok(cfg_end_map(r));
    cfg_doc_free(&doc);
}

static void test_type_errors_point_at_the_value(void **state) {
    (void)state;
    CfgDoc doc;
    load(&doc,
         "solid:\n  spacing: fast\n  n: 1.5\n  flag: maybe\n  model: planar\n  v: [1]\n  m: 3\n");
    CfgNode *s = cfg_map_find(doc.root, "solid");
    double d, v[2];
    int64_t i;
    bool b;
    int e;
    CfgNode *m;
    static const char *const names[] = {"plane_stress", "3d", NULL};
    assert_int_equal(cfg_req_double(s, "spacing", &d), NSPD_ERR_INPUT);
    expect_message("case.yaml:2:3: solid.spacing: 'fast' is not a number; expected a number");
    assert_int_equal(cfg_req_int(s, "n", &i), NSPD_ERR_INPUT);
    expect_message("solid.n: '1.5' is not a whole number; expected an integer");
    assert_int_equal(cfg_opt_bool(s, "flag", false, &b), NSPD_ERR_INPUT);
    expect_message(
        "case.yaml:4:3: solid.flag: 'maybe' is not a yes/no value; expected true or false");
    assert_int_equal(cfg_req_enum(s, "model", names, &e), NSPD_ERR_INPUT);
    expect_message(
        "solid.model: 'planar' is not a known choice; expected one of: plane_stress, 3d");
    assert_int_equal(cfg_req_vec(s, "v", 2, v), NSPD_ERR_INPUT);
    expect_message("solid.v: a list of 1 numbers; expected exactly 2");
    assert_int_equal(cfg_req_map(s, "m", &m), NSPD_ERR_INPUT);
    expect_message("case.yaml:7:3: solid.m: got a single value; expected a map");
    cfg_doc_free(&doc);
}

static void test_missing_and_unknown_keys(void **state) {
    (void)state;
    CfgDoc doc;
    load(&doc, "solid:\n  densty: 8000\n  spacing: 1\n");
    CfgNode *s = cfg_map_find(doc.root, "solid");
    double d;
    assert_int_equal(cfg_req_double(s, "density", &d), NSPD_ERR_INPUT);
    expect_message("case.yaml:1:1: solid.density: missing required key; expected a number");
    assert_ok(cfg_req_double(s, "spacing", &d));
    assert_ok(cfg_opt_double(s, "density", 1.0, &d));
    assert_int_equal(cfg_end_map(s), NSPD_ERR_INPUT);
    expect_message("case.yaml:2:3: solid.densty: unknown key (did you mean 'density'?)");
    cfg_doc_free(&doc);
}

static void test_range_checks(void **state) {
    (void)state;
    CfgDoc doc;
    load(&doc, "m:\n  density: -8000\n  f: 2\n");
    CfgNode *m = cfg_map_find(doc.root, "m");
    double d;
    assert_ok(cfg_req_double(m, "density", &d));
    assert_int_equal(cfg_check_positive(m, "density", d, "a density in kg/m^3"), NSPD_ERR_INPUT);
    expect_message("case.yaml:2:3: m.density: must be positive, got -8000; expected a density");
    assert_int_equal(cfg_check_range(m, "f", 2.0, 0.0, 1.0, "a fraction"), NSPD_ERR_INPUT);
    expect_message("m.f: 2 is out of range; expected a fraction");
    cfg_doc_free(&doc);
}

static void test_overrides(void **state) {
    (void)state;
    CfgDoc doc;
    load(&doc, "time:\n  end: 1\nlist:\n  - {a: 1}\n");
    assert_ok(cfg_doc_override(&doc, "time.end=2.5"));
    assert_ok(cfg_doc_override(&doc, "time.dt=1e-3"));
    assert_ok(cfg_doc_override(&doc, "new.deep.key=[1, 2]"));
    assert_ok(cfg_doc_override(&doc, "list.0.a=7"));
    double d;
    CfgNode *t = cfg_map_find(doc.root, "time");
    assert_ok(cfg_req_double(t, "end", &d));
    assert_true(d == 2.5);
    assert_ok(cfg_req_double(t, "dt", &d));
    assert_true(d == 1e-3);
    double v[2];
    assert_ok(cfg_req_vec(cfg_map_find(cfg_map_find(doc.root, "new"), "deep"), "key", 2, v));
    assert_true(v[1] == 2);
    assert_int_equal(cfg_doc_override(&doc, "list.5.a=1"), NSPD_ERR_INPUT);
    expect_message("--set list.5.a=1: '5' is not an item of a 1-item list");
    assert_int_equal(cfg_doc_override(&doc, "noequals"), NSPD_ERR_INPUT);
    /* a wrong value reports the --set that gave it */
    assert_ok(cfg_doc_override(&doc, "time.end=soon"));
    t = cfg_map_find(doc.root, "time");
    assert_int_equal(cfg_req_double(t, "end", &d), NSPD_ERR_INPUT);
    expect_message("--set time.end=soon: time.end: 'soon' is not a number");
    cfg_doc_free(&doc);
}

static void test_resolved_round_trip(void **state) {
    (void)state;
    CfgDoc doc;
    load(&doc, "name: \"x\"\nsolid: {spacing: 1.0e-4, v: [1, 2]}\n");
    double d;
    assert_ok(cfg_opt_double(cfg_map_find(doc.root, "solid"), "horizon_factor", 3.015, &d));
    const char *dir = test_scratch_dir("cfg_round_trip");
    char path[1200];
    snprintf(path, sizeof path, "%s/case.yaml", dir);
    FILE *f = fopen(path, "w");
    assert_ok(cfg_doc_write(&doc, f));
    fclose(f);
    cfg_doc_free(&doc);
    assert_ok(cfg_doc_load_file(&doc, path));
    CfgNode *s = cfg_map_find(doc.root, "solid");
    assert_ok(cfg_req_double(s, "horizon_factor", &d));
    assert_true(d == 3.015);
    assert_ok(cfg_req_double(s, "spacing", &d));
    assert_true(d == 1.0e-4);
    assert_true(cfg_map_find(doc.root, "name")->quoted);
    cfg_doc_free(&doc);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_positions_and_paths),
        cmocka_unit_test(test_syntax_and_structure_errors),
        cmocka_unit_test(test_typed_getters),
        cmocka_unit_test(test_type_errors_point_at_the_value),
        cmocka_unit_test(test_missing_and_unknown_keys),
        cmocka_unit_test(test_range_checks),
        cmocka_unit_test(test_overrides),
        cmocka_unit_test(test_resolved_round_trip),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
