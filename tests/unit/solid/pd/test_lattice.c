/* solid/pd/lattice: the polar lattice of a ring (paper 003 Sec. 4.3):
 * one point per annular-sector element at its centroid, the elements'
 * areas summing to the ring's, exact mirror symmetry, the (sector, ring)
 * indices and their parity, the geometry as a filter, refusals. */
#include "test_support.h"

#include "core/mem.h"
#include "core/status.h"
#include "solid/pd/lattice.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* the paper's coarse ring: r_i = 7 cm, r_o = 10 cm, dr = 2 mm; 268
 * sectors is the default (2 pi 0.085 / 0.002 = 267.0 rounded to a
 * multiple of 4) */
static const PolarLattice RING = {
    .center = {0.0, 0.0}, .inner_radius = 0.07, .outer_radius = 0.1, .rings = 15, .sectors = 268};

/* point of lattice index (k, q): slot[q * sectors + k], -1 if absent */
static int64_t *slots_of(const Lattice *lat, const PolarLattice *spec) {
    const int64_t cells = (int64_t)spec->rings * spec->sectors;
    int64_t *slot = malloc((size_t)cells * sizeof *slot);
    assert_non_null(slot);
    for (int64_t c = 0; c < cells; c++) slot[c] = -1;
    for (int64_t p = 0; p < lat->n; p++) {
        const int32_t k = lat->index[0][p], q = lat->index[1][p];
        assert_true(k >= 0 && k < spec->sectors && q >= 0 && q < spec->rings);
        assert_int_equal(lat->index[2][p], 0);
        const int64_t c = (int64_t)q * spec->sectors + k;
        assert_int_equal(slot[c], -1); /* each index once */
        slot[c] = p;
    }
    return slot;
}

static void test_count_volumes_radii(void **state) {
    (void)state;
    Lattice lat = {0};
    assert_ok(lattice_fill_polar(&lat, &RING, NULL));
    assert_int_equal(lat.n, 15 * 268);
    int64_t *slot = slots_of(&lat, &RING);
    free(slot);
    assert_close(lattice_polar_spacing(&RING), 0.002, 1e-17);
    assert_int_equal(lattice_polar_sectors(0.07, 0.1, 0.002), 268);
    /* the areas: pi (r_o^2 - r_i^2) = 0.0160221 m^2, to round-off (the
     * areas telescope; measured 6.7e-15 relative, the 4020 terms summed
     * in order; their bound n eps / 2 is 4.5e-13) */
    const double thickness = 5e-3, ring = M_PI * (0.1 * 0.1 - 0.07 * 0.07);
    double total = 0.0;
    for (int64_t p = 0; p < lat.n; p++) total += lattice_polar_area(&RING, lat.index[1][p]);
    printf("polar ring: %lld points, areas' sum off pi (r_o^2 - r_i^2) by %.2g relative\n",
           (long long)lat.n, fabs(total - ring) / ring);
    assert_close(total * thickness, ring * thickness, 1e-13 * ring * thickness);
    /* each point inside its own ring, the rings inside (r_i, r_o) */
    const double dr = 0.002;
    for (int64_t p = 0; p < lat.n; p++) {
        const double r = hypot(lat.x[0][p], lat.x[1][p]);
        const int32_t q = lat.index[1][p];
        assert_true(r > 0.07 + q * dr && r < 0.07 + (q + 1) * dr);
        assert_true(lat.x[2][p] == 0.0);
    }
    /* Morton order of (sector, ring) */
    for (int64_t p = 1; p < lat.n; p++)
        assert_true(morton_key(2, (uint32_t)lat.index[0][p - 1], (uint32_t)lat.index[1][p - 1], 0) <
                    morton_key(2, (uint32_t)lat.index[0][p], (uint32_t)lat.index[1][p], 0));
    lattice_free(&lat);
}

/* The centroid of one coarse element against a midpoint quadrature of
 * its area: r_i = 1, r_o = 2, 4 sectors (quarter annuli). */
static void test_centroid(void **state) {
    (void)state;
    const PolarLattice quarter = {
        .center = {0, 0}, .inner_radius = 1.0, .outer_radius = 2.0, .rings = 1, .sectors = 4};
    Lattice lat = {0};
    assert_ok(lattice_fill_polar(&lat, &quarter, NULL));
    assert_int_equal(lat.n, 4);
    int64_t *slot = slots_of(&lat, &quarter);
    const int64_t p = slot[0]; /* sector 0: angles 0 to pi/2 */
    free(slot);
    double mx = 0, my = 0, area = 0;
    const int m = 400;
    for (int i = 0; i < m; i++)
        for (int j = 0; j < m; j++) {
            const double r = 1.0 + (i + 0.5) / m, t = (j + 0.5) / m * M_PI / 2;
            const double da = r * (1.0 / m) * (M_PI / 2 / m);
            mx += r * cos(t) * da;
            my += r * sin(t) * da;
            area += da;
        }
    /* exact: 28 / (9 pi) = 0.990 for both; the quadrature's error ~1e-6 */
    assert_close(lat.x[0][p], 28.0 / (9.0 * M_PI), 1e-12);
    assert_close(lat.x[0][p], mx / area, 1e-5);
    assert_close(lat.x[1][p], my / area, 1e-5);
    assert_true(lat.x[0][p] == lat.x[1][p]); /* on the diagonal: one value */
    assert_close(lattice_polar_area(&quarter, 0), 3.0 * M_PI / 4.0, 1e-15);
    lattice_free(&lat);
}

/* Mirrored about both axes bit for bit, and about the diagonal when 4
 * divides the sector count (centre 0: the products round alike). */
static void check_symmetry(int32_t sectors) {
    PolarLattice spec = RING;
    spec.sectors = sectors;
    Lattice lat = {0};
    assert_ok(lattice_fill_polar(&lat, &spec, NULL));
    int64_t *slot = slots_of(&lat, &spec);
    const int32_t n = sectors;
    for (int32_t q = 0; q < spec.rings; q++)
        for (int32_t k = 0; k < n; k++) {
            const int64_t p = slot[(int64_t)q * n + k];
            const int64_t h = slot[(int64_t)q * n + (n - 1 - k)]; /* horizontal line */
            const int64_t v = slot[(int64_t)q * n + ((n / 2 - 1 - k + n) % n)]; /* vertical */
            assert_true(lat.x[0][h] == lat.x[0][p] && lat.x[1][h] == -lat.x[1][p]);
            assert_true(lat.x[0][v] == -lat.x[0][p] && lat.x[1][v] == lat.x[1][p]);
            if (n % 4 == 0) {
                const int64_t d = slot[(int64_t)q * n + ((n / 4 - 1 - k + n) % n)];
                assert_true(lat.x[0][d] == lat.x[1][p] && lat.x[1][d] == lat.x[0][p]);
            }
            /* the angle is (k + 1/2) 2 pi / n to round-off */
            const double angle = atan2(lat.x[1][p], lat.x[0][p]);
            const double want = remainder((k + 0.5) * 2.0 * M_PI / n, 2.0 * M_PI);
            assert_close(angle, want, 1e-13);
        }
    free(slot);
    lattice_free(&lat);
}

static void test_symmetry(void **state) {
    (void)state;
    check_symmetry(268); /* the default: a multiple of 4 */
    check_symmetry(30);  /* 2 mod 4: a sector on the vertical line */
}

/* The index parity (sector + ring) alternates between neighbours along
 * both directions, across the seam k = n - 1 -> 0 too (n even): the
 * stable step's checkerboard start. */
static void test_parity(void **state) {
    (void)state;
    Lattice lat = {0};
    assert_ok(lattice_fill_polar(&lat, &RING, NULL));
    int64_t *slot = slots_of(&lat, &RING);
    const int32_t n = RING.sectors;
    for (int32_t q = 0; q < RING.rings; q++)
        for (int32_t k = 0; k < n; k++) {
            const int64_t p = slot[(int64_t)q * n + k], a = slot[(int64_t)q * n + (k + 1) % n];
            const int parity_p = (lat.index[0][p] + lat.index[1][p]) & 1;
            assert_int_not_equal(parity_p, (lat.index[0][a] + lat.index[1][a]) & 1);
            if (q + 1 < RING.rings) {
                const int64_t o = slot[(int64_t)(q + 1) * n + k];
                assert_int_not_equal(parity_p, (lat.index[0][o] + lat.index[1][o]) & 1);
            }
        }
    free(slot);
    lattice_free(&lat);
}

/* The geometry filters by centroid: the half plane x > 0 keeps half the
 * elements; a disc off the ring keeps none (refused). */
static void test_filter_and_refusals(void **state) {
    (void)state;
    ShapeSet half = {0};
    assert_ok(nspd_alloc(&half.shapes, 1, sizeof(Shape)));
    half.count = 1;
    half.shapes[0] =
        (Shape){.kind = SHAPE_RECTANGLE, .lo = {0.0, -1.0, 0.0}, .hi = {1.0, 1.0, 0.0}};
    Lattice lat = {0};
    assert_ok(lattice_fill_polar(&lat, &RING, &half));
    assert_int_equal(lat.n, 15 * 268 / 2);
    for (int64_t p = 0; p < lat.n; p++) assert_true(lat.x[0][p] > 0.0);
    half.shapes[0] = (Shape){.kind = SHAPE_DISC, .center = {0.5, 0.5, 0.0}, .radius = 0.01};
    assert_int_equal(lattice_fill_polar(&lat, &RING, &half), NSPD_ERR_INPUT);
    shapeset_free(&half);

    PolarLattice bad = RING;
    bad.sectors = 267; /* odd: the parity would break at the seam */
    assert_int_equal(lattice_fill_polar(&lat, &bad, NULL), NSPD_ERR_INPUT);
    bad = RING;
    bad.rings = 0;
    assert_int_equal(lattice_fill_polar(&lat, &bad, NULL), NSPD_ERR_INPUT);
    bad = RING;
    bad.inner_radius = 0.1;
    assert_int_equal(lattice_fill_polar(&lat, &bad, NULL), NSPD_ERR_INPUT);
    bad = RING;
    bad.inner_radius = 0.0;
    assert_int_equal(lattice_fill_polar(&lat, &bad, NULL), NSPD_ERR_INPUT);
    assert_int_equal(lat.n, 0);
    lattice_free(&lat);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_count_volumes_radii),
        cmocka_unit_test(test_centroid),
        cmocka_unit_test(test_symmetry),
        cmocka_unit_test(test_parity),
        cmocka_unit_test(test_filter_and_refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
