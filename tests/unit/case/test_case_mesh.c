/* case/case_mesh: a correspondence solid's points from an Abaqus mesh
 * (solid.lattice kind abaqus). A grid of 8 x 6 quadrilaterals in mm,
 * scaled and translated, its top row left out by the geometry: one point
 * per element at its centroid, the volumes the elements' areas times the
 * thickness, the spacing by default the mean element size, boundaries and
 * initial velocities from an element set (GENERATE) and a node set (the
 * elements whose nodes it holds all); and cases/plate_hole_inp.yaml: its
 * 1,920 points' volumes sum to the meshed area times the thickness, its
 * TOP and BOTTOM sets hold the outer two rows. */
#include "sim_fixtures.h"
#include "test_support.h"

#include "case/case_read.h"
#include "core/status.h"
#include "io/inp_read.h"
#include "sim/sim.h"
#include "solid/correspondence/body.h"
#include "solid/correspondence/model.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const char GRID_CASE[] =
    "name: grid_inp\n"
    "time: {end: 1.0e-7}\n"
    "solid:\n"
    "  formulation: correspondence\n"
    "  model: plane_strain\n"
    "  lattice: {kind: abaqus, file: grid.inp, scale: 1.0e-3, translate: [0.01, 0.0]}\n"
    "  material: {density: 7800, youngs_modulus: 2.0e11, poisson_ratio: 0.3}\n"
    "  geometry: [{shape: rectangle, min: [0.0, 0.0], max: [1.0, 0.005]}]\n"
    "  boundaries:\n"
    "    - {name: left, set: left, fixed: true}\n"
    "    - {name: right, set: [RIGHT], velocity: {x: 1.0}}\n"
    "  initial_velocity:\n"
    "    - {set: Right, velocity: [0.5, 0]}\n"
    "output: {vtk: false, png: false}\n";

/* 8 x 6 unit squares (mm), elements numbered row by row from 1 */
static void write_grid(const char *path) {
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs("*Heading\n a grid\n*Node\n", f);
    for (int j = 0; j <= 6; j++)
        for (int i = 0; i <= 8; i++) fprintf(f, "%d, %d., %d.\n", 1 + i + 9 * j, i, j);
    fputs("*Element, type=CPE4R\n", f);
    for (int j = 0; j < 6; j++)
        for (int i = 0; i < 8; i++) {
            const int a = 1 + i + 9 * j;
            fprintf(f, "%d, %d, %d, %d, %d\n", 1 + i + 8 * j, a, a + 1, a + 10, a + 9);
        }
    fputs("*Nset, nset=LEFT\n", f); /* the nodes at x = 0 and 1 mm */
    for (int j = 0; j <= 6; j++) fprintf(f, "%d, %d\n", 1 + 9 * j, 2 + 9 * j);
    fputs("*Elset, elset=RIGHT, generate\n8, 48, 8\n", f);
    fclose(f);
}

static void build(const char *path, Sim *sim) {
    CfgDoc doc;
    SimConfig cfg;
    assert_ok(case_read(path, NULL, 0, &doc, &cfg));
    assert_ok(sim_create(sim, &cfg));
    cfg_doc_free(&doc);
}

static void test_grid(void **state) {
    (void)state;
    char dir[1200], mesh[1300];
    snprintf(dir, sizeof dir, "%s", fixture_case_file("case_mesh", GRID_CASE));
    *strrchr(dir, '/') = '\0';
    snprintf(mesh, sizeof mesh, "%s/grid.inp", dir);
    write_grid(mesh);
    char path[1300];
    snprintf(path, sizeof path, "%s/case.yaml", dir);
    Sim sim;
    build(path, &sim);
    CpdBody *b = cpd_solid_body(sim.solid);
    assert_non_null(b);
    assert_int_equal(b->n, 40);            /* the top row's centroids (y = 5.5 mm) are outside */
    assert_close(b->spacing, 1e-3, 1e-18); /* the mean element size (1 mm^2 each) */
    double volume = 0.0;
    int left = 0, right = 0;
    for (int64_t i = 0; i < b->n; i++) {
        volume += b->volume[i];
        /* the centroids: (k + 1/2) mm, scaled and translated */
        const double k = (b->x[0][i] - 0.01) / 1e-3 - 0.5, l = b->x[1][i] / 1e-3 - 0.5;
        assert_true(fabs(k - round(k)) < 1e-9 && fabs(l - round(l)) < 1e-9 && l < 4.5);
        if (b->region[i] == 0) {
            left++;
            assert_true(round(k) == 0.0);
        } else if (b->region[i] == 1) {
            right++;
            assert_true(round(k) == 7.0);
            assert_true(b->v[0][i] == 0.5);
        } else {
            assert_int_equal(b->region[i], -1);
            assert_true(b->v[0][i] == 0.0);
        }
    }
    printf("grid: %lld points, volume %.17g m^3, %d left, %d right\n", (long long)b->n, volume,
           left, right);
    assert_int_equal(left, 5);
    assert_int_equal(right, 5);
    /* 40 elements of 1 mm^2 times the 1 mm thickness (the spacing's default) */
    assert_close(volume, 40e-9, 1e-22);
    sim_destroy(&sim);
}

static void test_plate_case(void **state) {
    (void)state;
    InpMesh m;
    InpReadError err;
    assert_ok(
        inp_read_file(test_source_path("cases/geometry/plate_hole.inp"), INP_MAX_BYTES, &m, &err));
    double area = 0.0;
    for (int64_t e = 0; e < m.element_count; e++) area += m.measure[e];
    Sim sim;
    fixture_sim("plate_hole_inp.yaml", NULL, 0, &sim);
    CpdBody *b = cpd_solid_body(sim.solid);
    assert_non_null(b);
    assert_int_equal(b->n, m.element_count);
    double volume = 0.0;
    int top = 0, bottom = 0;
    for (int64_t i = 0; i < b->n; i++) {
        volume += b->volume[i];
        if (b->region[i] == 0) top++, assert_true(b->x[1][i] > 0.0366);
        if (b->region[i] == 1) bottom++, assert_true(b->x[1][i] < -0.0366);
    }
    const double expected = area * 1e-6 * 1e-3; /* mm^2 -> m^2, times the 1 mm thickness */
    printf("plate_hole_inp: %lld points, volume %.17g m^3 against %.17g (%.1e), top %d, bottom "
           "%d\n",
           (long long)b->n, volume, expected, fabs(volume - expected) / expected, top, bottom);
    /* measured 8.4e-15: the same areas, scaled (two roundings each) and
     * summed in the points' Morton order instead of the file's */
    assert_true(fabs(volume - expected) <= 5e-14 * expected);
    assert_int_equal(top, 48); /* two rows of 24 */
    assert_int_equal(bottom, 48);
    sim_destroy(&sim);
    inp_mesh_free(&m);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_grid),
        cmocka_unit_test(test_plate_case),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
