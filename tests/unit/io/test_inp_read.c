/* io/inp_read: Abaqus .inp meshes. Hand-written files of two quadrilaterals
 * and a triangle (with comments, mixed case, CRLF lines, a continuation
 * line, skipped keywords, sets by list, GENERATE and earlier sets' names)
 * and of a tetrahedron and two hexahedra: centroids and areas or volumes
 * against their closed forms (exact for the rectangle and the brick, to
 * round-off for the trapezoid and the frustum); the meshed area of
 * cases/geometry/plate_hole.inp against the plate minus its polygonal
 * hole; every refusal at its line with what was expected. */
#include "test_support.h"

#include "core/mem.h"
#include "core/status.h"
#include "io/inp_read.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void read_text(const char *text, InpMesh *m) {
    InpReadError err;
    const int st = inp_read_text(text, (int64_t)strlen(text), m, &err);
    if (st != NSPD_OK) fprintf(stderr, "line %d: %s\n", err.line, err.text);
    assert_ok(st);
}

static int64_t element_of(const InpMesh *m, int64_t id) {
    for (int64_t e = 0; e < m->element_count; e++)
        if (m->element_id[e] == id) return e;
    fail_msg("no element %lld", (long long)id);
    return -1;
}

/* how many of the set's elements or nodes, and whether `id` is one */
static int64_t set_count(const InpMesh *m, const char *name, bool elements, int64_t id,
                         bool *holds) {
    const InpSet *s = inp_find_set(m, name, elements);
    assert_non_null(s);
    const int64_t n = elements ? m->element_count : m->node_count;
    uint8_t *mark = calloc((size_t)n, 1);
    const int64_t count = inp_set_mark(m, s, mark);
    *holds = false;
    for (int64_t i = 0; i < n; i++)
        if (mark[i] && (elements ? m->element_id[i] : m->node_id[i]) == id) *holds = true;
    free(mark);
    return count;
}

static const char QUADS[] = "*Heading\r\n"
                            " two quadrilaterals and a triangle\r\n"
                            "** a comment, then a part as Abaqus/CAE writes it\r\n"
                            "*Part, name=Part-1\r\n"
                            "*node, nset=ALLN\r\n"
                            "1, 0., 0.\r\n"
                            "2, 2., 0.\r\n"
                            "3, 2., 1.\r\n"
                            "4, 0., 1.\r\n"
                            "5, 3.5, 0.\r\n"
                            "6, 2.5, 1.\r\n"
                            "7, 2.5, 2.0, 0.0\r\n"
                            "*Element, TYPE=cps4r, ELSET=Rect\r\n"
                            "10, 1, 2, 3,\r\n" /* the connectivity goes on on the next line */
                            "   4\r\n"
                            "*ELEMENT, type=CPE4, elset=Trap\n"
                            "11, 2, 5, 6, 3\n"
                            "*Element, type=S3\n"
                            "12, 3, 6, 7\n"
                            "*Solid Section, elset=Rect, material=steel\n"
                            "1.,\n"
                            "*Nset, nset=Bottom\n"
                            "1, 2, 5\n"
                            "*Nset, nset=odd, generate\n"
                            "1, 7, 2\n"
                            "*Elset, elset=Both\n"
                            "rect, TRAP\n"
                            "*Elset, elset=Range, generate\n"
                            "9, 12\n"
                            "*End Part\n";

static void test_quadrilaterals(void **state) {
    (void)state;
    InpMesh m;
    read_text(QUADS, &m);
    assert_int_equal(m.dim, 2);
    assert_int_equal(m.node_count, 7);
    assert_int_equal(m.element_count, 3);
    const int64_t rect = element_of(&m, 10), trap = element_of(&m, 11), tri = element_of(&m, 12);
    assert_int_equal(m.element_shape[rect], INP_QUAD4);
    assert_int_equal(m.element_shape[tri], INP_TRI3);
    assert_int_equal(m.element_line[rect], 14); /* where it starts */
    /* the rectangle [0, 2] x [0, 1]: exact */
    assert_true(m.measure[rect] == 2.0);
    assert_true(m.centroid[3 * rect] == 1.0 && m.centroid[3 * rect + 1] == 0.5);
    /* the trapezoid (2, 0) (3.5, 0) (2.5, 1) (2, 1): area (1.5 + 0.5) / 2 =
     * 1, centroid from its two triangles' moments */
    const double cx = (2.0 + 3.5 + 2.5) / 3.0 * 0.75 + (2.0 + 2.5 + 2.0) / 3.0 * 0.25,
                 cy = (0.0 + 0.0 + 1.0) / 3.0 * 0.75 + (0.0 + 1.0 + 1.0) / 3.0 * 0.25;
    printf("trapezoid: area %.17g, centroid (%.17g, %.17g) against (%.17g, %.17g)\n",
           m.measure[trap], m.centroid[3 * trap], m.centroid[3 * trap + 1], cx, cy);
    assert_true(m.measure[trap] == 1.0);
    /* the two forms round differently: a few ulp */
    assert_true(fabs(m.centroid[3 * trap] - cx) <= 1e-15 &&
                fabs(m.centroid[3 * trap + 1] - cy) <= 1e-15);
    /* the triangle (2, 1) (2.5, 1) (2.5, 2) */
    assert_true(m.measure[tri] == 0.25);
    assert_close(m.centroid[3 * tri], 7.0 / 3.0, 4e-16);
    assert_close(m.centroid[3 * tri + 1], 4.0 / 3.0, 4e-16);
    bool holds;
    assert_int_equal(set_count(&m, "alln", false, 7, &holds), 7);
    assert_true(holds);
    assert_int_equal(set_count(&m, "BOTTOM", false, 5, &holds), 3);
    assert_true(holds);
    assert_int_equal(set_count(&m, "Odd", false, 4, &holds), 4); /* 1, 3, 5, 7 */
    assert_false(holds);
    assert_int_equal(set_count(&m, "both", true, 11, &holds), 2);
    assert_true(holds);
    assert_int_equal(set_count(&m, "range", true, 12, &holds), 3); /* 9 to 12: 10, 11, 12 */
    assert_true(holds);
    assert_null(inp_find_set(&m, "RECT", false)); /* an element set, not a node set */
    inp_mesh_free(&m);
}

static const char SOLIDS[] = "*NODE\n"
                             "1, 0, 0, 0\n"
                             "2, 1, 0, 0\n"
                             "3, 0, 1, 0\n"
                             "4, 0, 0, 1\n"
                             /* a brick [0, 2] x [0, 1] x [0, 0.5] */
                             "11, 0, 0, 0\n12, 2, 0, 0\n13, 2, 1, 0\n14, 0, 1, 0\n"
                             "15, 0, 0, 0.5\n16, 2, 0, 0.5\n17, 2, 1, 0.5\n18, 0, 1, 0.5\n"
                             /* a frustum: square 2 x 2 at z = 0, 1 x 1 at z = 1 */
                             "21, -1, -1, 0\n22, 1, -1, 0\n23, 1, 1, 0\n24, -1, 1, 0\n"
                             "25, -0.5, -0.5, 1\n26, 0.5, -0.5, 1\n27, 0.5, 0.5, 1\n"
                             "28, -0.5, 0.5, 1\n"
                             "*ELEMENT, TYPE=C3D4, ELSET=TET\n"
                             "1, 1, 2, 3, 4\n"
                             "*ELEMENT, TYPE=C3D8R, ELSET=HEX\n"
                             "2, 11, 12, 13, 14,\n"
                             "15, 16, 17, 18\n"
                             "3, 21, 22, 23, 24, 25, 26, 27, 28\n";

static void test_solids(void **state) {
    (void)state;
    InpMesh m;
    read_text(SOLIDS, &m);
    assert_int_equal(m.dim, 3);
    assert_int_equal(m.element_count, 3);
    const int64_t tet = element_of(&m, 1), brick = element_of(&m, 2), frustum = element_of(&m, 3);
    assert_close(m.measure[tet], 1.0 / 6.0, 3e-17);
    for (int d = 0; d < 3; d++) assert_true(m.centroid[3 * tet + d] == 0.25);
    printf("brick: volume %.17g, centroid (%.17g, %.17g, %.17g)\n", m.measure[brick],
           m.centroid[3 * brick], m.centroid[3 * brick + 1], m.centroid[3 * brick + 2]);
    /* the Gauss points' det J are equal for a parallelepiped and their
     * moments cancel in pairs: exact */
    assert_true(m.measure[brick] == 1.0);
    assert_true(m.centroid[3 * brick] == 1.0 && m.centroid[3 * brick + 1] == 0.5 &&
                m.centroid[3 * brick + 2] == 0.25);
    /* the frustum: V = h (a^2 + a b + b^2) / 3, z_c = h (a^2 + 2 a b + 3 b^2)
     * / (4 (a^2 + a b + b^2)) with a = 2, b = 1, h = 1 */
    const double v = 7.0 / 3.0, zc = 11.0 / 28.0;
    printf("frustum: volume %.17g (%.17g), z_c %.17g (%.17g)\n", m.measure[frustum], v,
           m.centroid[3 * frustum + 2], zc);
    /* measured 4.4e-16 and 5.6e-17: the Gauss points' irrational coordinates */
    assert_close(m.measure[frustum], v, 2e-15);
    assert_close(m.centroid[3 * frustum + 2], zc, 4e-16);
    assert_close(m.centroid[3 * frustum], 0.0, 1e-16);
    assert_close(m.centroid[3 * frustum + 1], 0.0, 1e-16);
    bool holds;
    assert_int_equal(set_count(&m, "HEX", true, 3, &holds), 2);
    assert_true(holds);
    inp_mesh_free(&m);
}

/* The plate's mesh: its elements' areas sum to the plate's W H less the
 * area of the polygon of its HOLE nodes (the mesh is conforming, its outer
 * nodes on the rectangle exactly). */
static void test_plate_area(void **state) {
    (void)state;
    InpMesh m;
    InpReadError err;
    assert_ok(
        inp_read_file(test_source_path("cases/geometry/plate_hole.inp"), INP_MAX_BYTES, &m, &err));
    const InpSet *hole = inp_find_set(&m, "HOLE", false);
    assert_non_null(hole);
    double *xy = NULL;
    int64_t n = 0;
    assert_ok(nspd_alloc(&xy, 2 * (size_t)m.node_count, sizeof(double)));
    for (int64_t q = 0; q < hole->range_count; q++) /* in the file's order */
        for (int64_t id = hole->ranges[q].first; id <= hole->ranges[q].last;
             id += hole->ranges[q].step)
            for (int64_t i = 0; i < m.node_count; i++)
                if (m.node_id[i] == id) {
                    xy[2 * n] = m.node_x[3 * i];
                    xy[2 * n + 1] = m.node_x[3 * i + 1];
                    n++;
                }
    double polygon = 0.0;
    for (int64_t i = 0, j = n - 1; i < n; j = i++)
        polygon += 0.5 * (xy[2 * j] * xy[2 * i + 1] - xy[2 * i] * xy[2 * j + 1]);
    double total = 0.0, lo = INFINITY, hi = 0.0;
    for (int64_t e = 0; e < m.element_count; e++) {
        total += m.measure[e];
        lo = fmin(lo, m.measure[e]);
        hi = fmax(hi, m.measure[e]);
    }
    const double expected = 40.0 * 80.0 - polygon;
    printf("plate_hole.inp: %lld elements (areas %.3g to %.3g mm^2), sum %.17g mm^2, plate less "
           "the %lld-gon hole %.17g mm^2: relative %.2e (the circle's pi r^2 %.6g)\n",
           (long long)m.element_count, lo, hi, total, (long long)n, expected,
           fabs(total - expected) / expected, M_PI * 36.0);
    assert_int_equal(n, 96);
    /* measured 8.8e-15 (2.7e-11 mm^2): each area's products of coordinates
     * up to 20 mm round at about 4e-14 mm^2, over 1,920 elements */
    assert_true(fabs(total - expected) <= 5e-14 * expected);
    nspd_free(&xy);
    inp_mesh_free(&m);
}

/* `text` refused at `line` with a message holding `words`. */
static void refused(const char *text, int line, const char *words) {
    InpMesh m;
    InpReadError err;
    const int st = inp_read_text(text, (int64_t)strlen(text), &m, &err);
    if (st != NSPD_ERR_INPUT || err.line != line || !strstr(err.text, words))
        fail_msg("expected a refusal at line %d with '%s'; got status %d at line %d: %s", line,
                 words, st, err.line, err.text);
    printf("  line %d: %s\n", err.line, err.text);
    assert_null(m.node_id); /* freed */
}

#define NODES4 "*NODE\n1, 0, 0\n2, 1, 0\n3, 1, 1\n4, 0, 1\n"

static void test_refusals(void **state) {
    (void)state;
    refused(NODES4 "*ELEMENT, TYPE=CPS4\n1, 1, 2, 3, 9\n", 7, "node 9, which no *NODE");
    refused(NODES4 "*ELEMENT, TYPE=CPS4\n1, 1, 2, 3\n", 7, "3 nodes; expected 4 for a CPS4");
    refused(NODES4 "*ELEMENT, TYPE=CPS3\n1, 1, 2, 3, 4\n", 7, "more than 3 nodes");
    refused(NODES4 "*ELEMENT, TYPE=CPS4\n1, 1, 4, 3, 2\n", 7, "inverted");
    refused(NODES4 "*ELEMENT, TYPE=CPS4\n1, 1, 3, 2, 4\n", 7, "area 0");
    refused(NODES4 "*NODE\n5, 0.8, 0.3\n*ELEMENT, TYPE=CPS4\n1, 1, 2, 3, 5\n", 9,
            "folded (not convex) at its node 5");
    refused(NODES4 "*ELEMENT, TYPE=CPS8\n1, 1, 2, 3, 4\n", 6, "unknown element type CPS8");
    refused("*NODE\n1, 0, 0\n2, 1.0e, 0\n", 3, "'1.0e' is not a number; expected node 2's x");
    refused("*NODE\n1, 0, 0\n2, nan, 0\n", 3, "'nan' is not a number");
    refused("*NODE\n1, 0, 0\nx2, 1, 0\n", 3, "'x2' is not a node number");
    refused(NODES4 "*ELEMENT, TYPE=CPS4\n1, 1, 2, 3, four\n", 7, "'four' is not a node number");
    refused("*NODE\n1, 0, 0\n2, 1, 0\n1, 1, 1\n", 4, "node 1 is defined again (first at line 2)");
    refused(NODES4 "*ELEMENT, TYPE=CPS4\n1, 1, 2, 3, 4\n1, 1, 2, 3, 4\n", 8,
            "element 1 is defined again");
    refused(NODES4, 5, "no element");
    refused("", 0, "no element");
    refused(NODES4 "*ELEMENT, TYPE=CPS4\n1, 1, 2, 3,\n", 7, "ends with a comma but no nodes");
    refused(NODES4 "*ELEMENT, TYPE=CPS4\n1, 1, 2, 3,\n*NSET, NSET=A\n1\n", 8,
            "a keyword where element 1's nodes go on");
    refused("*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 0\n4, 0, 0, 1\n"
            "*ELEMENT, TYPE=CPS3\n1, 1, 2, 3\n*ELEMENT, TYPE=C3D4\n2, 1, 2, 3, 4\n",
            8, "after 2D ones");
    refused("*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 0, 1, 0\n4, 0, 0, 1\n"
            "*ELEMENT, TYPE=C3D4\n1, 1, 3, 2, 4\n",
            7, "inverted");
    refused(NODES4 "*ELEMENT, TYPE=CPS4\n1, 1, 2, 3, 4\n*NSET, NSET=A\n1, 7\n", 9,
            "node set A names node 7");
    refused(NODES4 "*ELEMENT, TYPE=CPS4\n1, 1, 2, 3, 4\n*NSET, NSET=A\n1, 2\n3, 4, 5\n", 10,
            "node set A names node 5"); /* at its own line, though it follows 1 and 2 */
    refused(NODES4 "*ELEMENT, TYPE=CPS4\n1, 1, 2, 3, 4\n*ELSET, ELSET=B, GENERATE\n5, 9\n", 9,
            "holds no element");
    refused(NODES4 "*ELEMENT, TYPE=CPS4\n1, 1, 2, 3, 4\n*ELSET, ELSET=B\nNOPE\n", 9,
            "'NOPE' is not an element number or the name of an earlier element set");
    refused(NODES4 "*INCLUDE, INPUT=more.inp\n", 6, "*INCLUDE");
    refused("*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 1, 1, 1\n*ELEMENT, TYPE=CPS3\n1, 1, 2, 3\n", 6,
            "a plane z = constant");
    /* the size limit, from a file */
    char path[4200];
    snprintf(path, sizeof path, "%s/big.inp", test_scratch_dir("inp"));
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    fputs(NODES4 "*ELEMENT, TYPE=CPS4\n1, 1, 2, 3, 4\n", f);
    fclose(f);
    InpMesh m;
    InpReadError err;
    assert_ok(inp_read_file(path, 1000, &m, &err));
    inp_mesh_free(&m);
    assert_int_equal(inp_read_file(path, 40, &m, &err), NSPD_ERR_INPUT);
    assert_true(err.line == 0 && err.offset == 40 && strstr(err.text, "larger than 40 bytes"));
    printf("  byte %lld: %s\n", (long long)err.offset, err.text);
    assert_int_equal(inp_read_file("/nonexistent/x.inp", 1000, &m, &err), NSPD_ERR_IO);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_quadrilaterals),
        cmocka_unit_test(test_solids),
        cmocka_unit_test(test_plate_area),
        cmocka_unit_test(test_refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
