/* Several materials in one bond-based body (solid.material as a list;
 * issue 61): each point's density and Young's modulus from the material
 * whose region holds it, no bond between two materials unless bonded (then
 * the two in series), the kick, energies and momentum by each point's
 * density, and a one-item list giving the bits of the plain map. */
#include "test_support.h"

#include "sim/sim.h"
#include "sim_fixtures.h"
#include "solid/bond/body.h"
#include "solid/bond/diagnostics.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* A 20 x 6 mm strip at 1 mm: `material` (the YAML of solid.material and
 * what follows it), 50 steps at 1e-8 s pulled at its right end */
static void strip(Sim *sim, const char *material) {
    char text[4096];
    snprintf(text, sizeof text,
             "name: materials\n"
             "time: {end: 5.0e-7, dt: 1.0e-8}\n"
             "solid:\n"
             "  model: plane_stress\n"
             "  spacing: 1.0e-3\n"
             "  thickness: 1.0e-3\n"
             "%s"
             "  geometry: [{shape: rectangle, min: [-0.01, -0.003], max: [0.01, 0.003]}]\n"
             "  boundaries:\n"
             "    - region: [{shape: rectangle, min: [0.008, -1], max: [1, 1]}]\n"
             "      velocity: {x: 5.0}\n"
             "  integrator: velocity_verlet\n"
             "output: {field_interval: 1.0, history_interval: 1.0}\n",
             material);
    fixture_sim_text(text, sim);
}

static const char TWO[] = "  material:\n"
                          "    - {name: steel, region: [{shape: rectangle, min: [-1, -1], max: "
                          "[0, 1]}], density: 7850, youngs_modulus: 200.0e9}\n"
                          "    - {name: aluminium, density: 2700, youngs_modulus: 70.0e9}\n";

/* the coefficient of point i's bond to the point at offset (dx, 0), or 0 */
static double coef_to(const BondBody *b, int64_t i, double off) {
    for (int64_t k = b->bond_first[i]; k < b->bond_first[i + 1]; k++) {
        const int32_t j = b->bond_nbr[k];
        if (fabs(b->x[0][j] - b->x[0][i] - off) < 1e-9 && fabs(b->x[1][j] - b->x[1][i]) < 1e-9)
            return fabs((double)b->bond_coef[k]);
    }
    return 0.0;
}

/* the point nearest (x, y) */
static int64_t point_at(const BondBody *b, double x, double y) {
    int64_t best = 0;
    double d = INFINITY;
    for (int64_t i = 0; i < b->n; i++) {
        const double e = hypot(b->x[0][i] - x, b->x[1][i] - y);
        if (e < d) d = e, best = i;
    }
    return best;
}

/* the largest |u_x| of material k's points */
static double moved(const BondBody *b, int k) {
    double m = 0.0;
    for (int64_t i = 0; i < b->n; i++)
        if (b->material[i] == k) m = fmax(m, fabs(b->u[0][i]));
    return m;
}

static void test_separate(void **state) {
    (void)state;
    Sim sim;
    char text[1024];
    snprintf(text, sizeof text, "%s", TWO);
    strip(&sim, text);
    BondBody *b = fixture_body(&sim);
    assert_non_null(b->material);
    int64_t steel = 0, cross = 0;
    for (int64_t i = 0; i < b->n; i++) {
        const int m = b->x[0][i] < 0.0 ? 0 : 1;
        assert_int_equal(b->material[i], m);
        assert_true(b->density[i] == (m == 0 ? 7850.0 : 2700.0));
        steel += m == 0;
        for (int64_t k = b->bond_first[i]; k < b->bond_first[i + 1]; k++)
            cross += b->material[b->bond_nbr[k]] != b->material[i];
    }
    assert_true(steel == b->n / 2 && cross == 0);
    /* the same bond in the two materials: E's ratio (coefficients are floats) */
    const double r = coef_to(b, point_at(b, 0.0055, 0.0005), 1e-3) /
                     coef_to(b, point_at(b, -0.0055, 0.0005), 1e-3);
    printf("separate: coefficient ratio aluminium / steel %.8f (E: %.8f), %lld cross bonds\n", r,
           70.0 / 200.0, (long long)cross);
    assert_true(fabs(r - 0.35) < 1e-6);
    /* kinetic energy and momentum by each point's density */
    for (int64_t i = 0; i < b->n; i++) b->v[0][i] = 3.0, b->v[1][i] = 0.0;
    double ke = 0.0, p[3];
    for (int64_t i = 0; i < b->n; i++) ke += 0.5 * b->density[i] * b->volume[i] * 9.0;
    pd_momentum(b, p);
    assert_true(fabs(pd_kinetic_energy(b) - ke) <= 1e-14 * ke);
    assert_true(fabs(p[0] - 2.0 * ke / 3.0) <= 1e-14 * ke);
    /* each material's totals (the per-material history columns) add up */
    double mass[2], kin[2], vel[2][3];
    for (int k = 0; k < 2; k++) pd_material_totals(b, k, &mass[k], &kin[k], vel[k]);
    assert_true(fabs(kin[0] + kin[1] - ke) <= 1e-14 * ke);
    assert_true(fabs(mass[0] / mass[1] - 7850.0 / 2700.0) < 1e-14); /* equal halves */
    assert_true(fabs(vel[0][0] - 3.0) < 1e-14 && fabs(vel[1][0] - 3.0) < 1e-14 && vel[0][1] == 0.0);
    /* the pulled aluminium end moves, the steel half stays at rest: no bond
     * carries the pull across */
    for (int64_t i = 0; i < b->n; i++) b->v[0][i] = 0.0;
    assert_ok(sim_advance(&sim, 50));
    assert_true(moved(b, 0) == 0.0 && moved(b, 1) > 0.0);
    sim_destroy(&sim);
}

static void test_bonded(void **state) {
    (void)state;
    Sim sim;
    char text[1024];
    snprintf(text, sizeof text, "%s  material_interface: bonded\n", TWO);
    strip(&sim, text);
    BondBody *b = fixture_body(&sim);
    /* a bond across the interface: the two in series, 2 E1 E2 / (E1 + E2) */
    const double across = coef_to(b, point_at(b, -0.0005, 0.0005), 1e-3),
                 steel = coef_to(b, point_at(b, -0.0055, 0.0005), 1e-3);
    const double want = 2.0 * 200.0 * 70.0 / 270.0 / 200.0;
    printf("bonded: across / steel %.8f (expected %.8f)\n", across / steel, want);
    assert_true(fabs(across / steel - want) < 1e-6);
    /* the pull reaches the steel through the interface */
    assert_ok(sim_advance(&sim, 50));
    assert_true(moved(b, 0) > 0.0);
    sim_destroy(&sim);
}

/* one material as a one-item list: the bits of the plain map */
static void test_list_of_one(void **state) {
    (void)state;
    Sim a, l;
    strip(&a, "  material: {density: 7850, youngs_modulus: 200.0e9}\n");
    strip(&l, "  material: [{density: 7850, youngs_modulus: 200.0e9}]\n");
    assert_ok(sim_advance(&a, 50));
    assert_ok(sim_advance(&l, 50));
    const BondBody *ba = fixture_body(&a), *bl = fixture_body(&l);
    assert_true(ba->n == bl->n);
    for (int d = 0; d < 2; d++)
        assert_memory_equal(ba->u[d], bl->u[d], (size_t)ba->n * sizeof(double));
    sim_destroy(&a);
    sim_destroy(&l);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_separate),
        cmocka_unit_test(test_bonded),
        cmocka_unit_test(test_list_of_one),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
