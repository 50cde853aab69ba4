/* solid/ set-up: lattice, Morton order, neighbour search, material
 * relations, pre-cracks, surface correction. */
#include "pd_fixtures.h"
#include "test_support.h"

#include "core/mem.h"
#include "core/status.h"
#include "solid/bond/corrections.h"
#include "solid/pd/lattice.h"
#include "solid/bond/body.h"
#include "solid/pd/config.h"
#include "solid/bond/diagnostics.h"
#include "solid/pd/precrack.h"

#include <math.h>
#include <string.h>

static void test_lattice_fill_and_order(void **state) {
    (void)state;
    Shape disc = {.kind = SHAPE_DISC, .center = {0, 0, 0}, .radius = 1.0};
    ShapeSet set = {1, &disc};
    Lattice lat = {0};
    double origin[3] = {0.05, 0.05, 0};
    assert_ok(lattice_fill(&lat, &set, 2, 0.1, origin));
    /* count by brute force */
    int64_t expect = 0;
    for (int i = -20; i <= 20; i++)
        for (int j = -20; j <= 20; j++) {
            double x = 0.05 + i * 0.1, y = 0.05 + j * 0.1;
            expect += x * x + y * y <= 1.0;
        }
    assert_int_equal(lat.n, expect);
    /* Morton order: keys ascend */
    int32_t imin = INT32_MAX, jmin = INT32_MAX;
    for (int64_t p = 0; p < lat.n; p++) {
        imin = lat.index[0][p] < imin ? lat.index[0][p] : imin;
        jmin = lat.index[1][p] < jmin ? lat.index[1][p] : jmin;
    }
    uint64_t last = 0;
    for (int64_t p = 0; p < lat.n; p++) {
        uint64_t key = morton_key(2, (uint32_t)(lat.index[0][p] - imin),
                                  (uint32_t)(lat.index[1][p] - jmin), 0);
        assert_true(p == 0 || key > last);
        last = key;
        assert_close(lat.x[0][p], origin[0] + lat.index[0][p] * 0.1, 1e-15);
    }
    lattice_free(&lat);
    Shape nothing = {.kind = SHAPE_DISC, .center = {0.0, 0.0, 0}, .radius = 0.01};
    ShapeSet tiny = {1, &nothing};
    assert_int_equal(lattice_fill(&lat, &tiny, 2, 0.1, origin), NSPD_ERR_INPUT);
}

/* Brute-force neighbour count of every point against the cell list. */
static void check_neighbours(int dim, int n, int interior_expected) {
    PdConfig cfg = fixture_block(dim, n, n, n, 1e-3);
    BondBody body;
    assert_ok(bond_body_create(&body, &cfg));
    double delta = body.horizon;
    int64_t interior = -1;
    for (int64_t i = 0; i < body.n; i++) {
        int64_t count = 0;
        for (int64_t j = 0; j < body.n; j++) {
            double d2 = 0;
            for (int d = 0; d < dim; d++) d2 += pow(body.x[d][j] - body.x[d][i], 2);
            count += j != i && d2 <= delta * delta;
        }
        assert_int_equal(body.bond_first[i + 1] - body.bond_first[i], count);
        for (int64_t b = body.bond_first[i] + 1; b < body.bond_first[i + 1]; b++) {
            /* rows in offset order: dz, then dy, then dx (stencil.h) */
            int64_t key[2] = {0, 0};
            for (int e = 0; e < 2; e++)
                for (int d = dim - 1; d >= 0; d--)
                    key[e] = key[e] * 64 + body.lattice[d][body.bond_nbr[b - e]] -
                             body.lattice[d][i] + 32;
            assert_true(key[0] > key[1]);
        }
        bool inside = true;
        for (int d = 0; d < dim; d++)
            inside = inside && body.lattice[d][i] >= 3 && body.lattice[d][i] < n - 3;
        if (inside) interior = count;
    }
    assert_int_equal(interior, interior_expected);
    bond_body_destroy(&body);
}

static void test_neighbours_match_brute_force(void **state) {
    (void)state;
    check_neighbours(2, 14, 28); /* lattice points within 3.015 dx in 2D */
    check_neighbours(3, 9, 122); /* and in 3D */
}

static void test_material_relations(void **state) {
    (void)state;
    PdConfig cfg = fixture_block(2, 4, 4, 0, 1e-4);
    double delta = 3.015e-4, E = 192e9;
    assert_close(pd_micromodulus(&cfg), 9 * E / (M_PI * 1e-4 * pow(delta, 3)), 1e12);
    /* Eq. 18 with the plane-stress bulk modulus k = E / (2 (1 - nu)) equals the
     * usual sqrt(4 pi G_c / (9 E delta)) */
    double gc = 1000;
    assert_close(pd_critical_stretch_from_energy(&cfg, gc), sqrt(4 * M_PI * gc / (9 * E * delta)),
                 1e-15);
    cfg.model = PD_PLANE_STRAIN;
    assert_close(pd_critical_stretch_from_energy(&cfg, gc), sqrt(5 * M_PI * gc / (12 * E * delta)),
                 1e-15);
    assert_close(pd_micromodulus(&cfg), 48 * E / (5 * M_PI * 1e-4 * pow(delta, 3)), 1e12);
    cfg.model = PD_3D;
    cfg.dim = 3;
    assert_close(pd_micromodulus(&cfg), 12 * E / (M_PI * pow(delta, 4)), 1e17);
    double K = E / (3 * (1 - 2 * 0.25));
    assert_close(pd_critical_stretch_from_energy(&cfg, gc), sqrt(5 * gc / (9 * K * delta)), 1e-15);
    /* Rayleigh speed for nu = 1/3 (plane stress): 0.9194 of the shear speed
     * (root of the Rayleigh equation, checked independently to 4 digits) */
    cfg.model = PD_PLANE_STRESS;
    cfg.dim = 2;
    cfg.density = 8000;
    assert_close(pd_rayleigh_wave_speed(&cfg) / pd_shear_wave_speed(&cfg), 0.9194, 1e-4);
    assert_close(pd_bar_wave_speed(&cfg), sqrt(E / 8000), 1e-9);
    pd_config_free(&cfg);
}

static void test_precrack_geometry(void **state) {
    (void)state;
    PdPrecrack c = {.a = {-1, 0, 0}, .b = {1, 0, 0}};
    assert_true(precrack_cuts(&c, 2, (double[3]){0, -0.5, 0}, (double[3]){0.3, 0.5, 0}));
    assert_false(precrack_cuts(&c, 2, (double[3]){1.5, -0.5, 0}, (double[3]){1.5, 0.5, 0}));
    assert_false(precrack_cuts(&c, 2, (double[3]){0, 0.1, 0}, (double[3]){0, 0.5, 0}));
    PdPrecrack p = {.a = {0, 0, 0}, .e1 = {1, 0, 0}, .e2 = {0, 1, 0}};
    assert_true(precrack_cuts(&p, 3, (double[3]){0.5, 0.5, -1}, (double[3]){0.5, 0.5, 1}));
    assert_false(precrack_cuts(&p, 3, (double[3]){1.5, 0.5, -1}, (double[3]){1.5, 0.5, 1}));
    assert_false(precrack_cuts(&p, 3, (double[3]){0.5, 0.5, 0.1}, (double[3]){0.5, 0.5, 1}));
}

/* The crack breaks exactly the bonds that cross it; damage follows. */
static void test_precrack_breaks_crossing_bonds(void **state) {
    (void)state;
    PdConfig cfg = fixture_block(2, 20, 20, 0, 1e-3);
    assert_ok(nspd_alloc(&cfg.precracks, 1, sizeof(PdPrecrack)));
    cfg.precrack_count = 1;
    cfg.precracks[0] = (PdPrecrack){.a = {0.005, 0.010, 0}, .b = {0.015, 0.010, 0}};
    BondBody body;
    assert_ok(bond_body_create(&body, &cfg));
    int64_t broken = 0;
    for (int64_t i = 0; i < body.n; i++)
        for (int64_t b = body.bond_first[i]; b < body.bond_first[i + 1]; b++) {
            int32_t j = body.bond_nbr[b];
            bool crosses = (body.x[1][i] - 0.010) * (body.x[1][j] - 0.010) < 0;
            double t = (0.010 - body.x[1][i]) / (body.x[1][j] - body.x[1][i]);
            double xc = body.x[0][i] + t * (body.x[0][j] - body.x[0][i]);
            crosses = crosses && xc > 0.005 && xc < 0.015;
            assert_true((body.bond_coef[b] == 0.0f) == crosses);
            broken += crosses;
        }
    assert_int_equal(pd_broken_bonds(&body), broken / 2);
    double *damage;
    assert_ok(nspd_alloc(&damage, (size_t)body.n, sizeof(double)));
    pd_damage(&body, damage);
    for (int64_t i = 0; i < body.n; i++) {
        bool far = fabs(body.x[1][i] - 0.010) > body.horizon;
        if (far) assert_true(damage[i] == 0.0);
        assert_true(damage[i] >= 0.0 && damage[i] < 0.5);
    }
    nspd_free(&damage);
    bond_body_destroy(&body);
}

/* Energy errors of a 16^dim block under the calibration strain along x:
 * worst and mean |W/W_classical - 1| over all points, and the worst over
 * the deep interior (at least 2 horizons from every surface, so that every
 * neighbour shares the point's own factor). */
static void energy_errors(int dim, PdSurfaceCorrection mode, double *worst, double *mean,
                          double *deep) {
    PdConfig cfg = fixture_block(dim, 16, 16, 16, 1e-3);
    cfg.surface_correction = mode;
    BondBody body;
    assert_ok(bond_body_create(&body, &cfg));
    double w_classical = pd_classical_uniaxial_energy(&body.cfg, 1e-3);
    for (int64_t i = 0; i < body.n; i++) body.u[0][i] = 1e-3 * body.x[0][i];
    *worst = *mean = *deep = 0;
    for (int64_t i = 0; i < body.n; i++) {
        double w = 0;
        for (int64_t b = body.bond_first[i]; b < body.bond_first[i + 1]; b++) {
            int32_t j = body.bond_nbr[b];
            double e2 = 0, r2 = 0;
            for (int d = 0; d < dim; d++) {
                double e = body.x[d][j] - body.x[d][i];
                double r = e + body.u[d][j] - body.u[d][i];
                e2 += e * e;
                r2 += r * r;
            }
            double s = sqrt(r2) - sqrt(e2);
            w += 0.25 * body.coef_scale * fabs((double)body.bond_coef[b]) * s * s;
        }
        double err = fabs(w / w_classical - 1);
        int depth = 99;
        for (int d = 0; d < dim; d++) {
            int k = body.lattice[d][i], m = k < 15 - k ? k : 15 - k;
            depth = m < depth ? m : depth;
        }
        *worst = fmax(*worst, err);
        *mean += err / (double)body.n;
        if (depth >= 6) *deep = fmax(*deep, err);
    }
    bond_body_destroy(&body);
}

/* The energy method makes the deep interior exact (to the float32 storage of
 * the bond coefficients: measured 2e-8) - which also removes the 14 % error of
 * the lattice sum against the integral that calibrated c - and cuts the
 * surface errors, but cannot make them vanish: a bond's factor averages its
 * two ends. Measured on 16^dim blocks (worst, mean):
 *     2D none 0.679, 0.275   energy 0.251, 0.098   ratios 0.37, 0.36
 *     3D none 0.782, 0.311   energy 0.331, 0.115   ratios 0.42, 0.37
 * Bounds: ratios below 0.45 and 0.4, interior below 1e-6. */
static void test_surface_correction(void **state) {
    (void)state;
    for (int dim = 2; dim <= 3; dim++) {
        double worst0, mean0, deep0, worst1, mean1, deep1;
        energy_errors(dim, PD_SURFACE_NONE, &worst0, &mean0, &deep0);
        energy_errors(dim, PD_SURFACE_ENERGY, &worst1, &mean1, &deep1);
        assert_true(deep0 > 0.1); /* the uncorrected bulk is off by the lattice sum */
        assert_true(deep1 < 1e-6);
        assert_true(worst1 < 0.45 * worst0);
        assert_true(mean1 < 0.4 * mean0);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lattice_fill_and_order),
        cmocka_unit_test(test_neighbours_match_brute_force),
        cmocka_unit_test(test_material_relations),
        cmocka_unit_test(test_precrack_geometry),
        cmocka_unit_test(test_precrack_breaks_crossing_bonds),
        cmocka_unit_test(test_surface_correction),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
