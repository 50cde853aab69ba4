/* The pre-cracked plate of paper 000 Sec. 4.2 at one fifth of the paper's
 * resolution (100 x 100 points, dx = 0.5 mm, 250 steps): the crack grows
 * straight, symmetrically, below the Rayleigh speed, and the result does not
 * depend on the thread count.
 *
 * Scaling: dt scales with dx (6.6835e-8 s = 5 x the paper's, the same
 * fraction of the stable step), and s_c with 1/sqrt(delta) so that the
 * fracture energy G_c = 9 E delta s_c^2 / (4 pi) stays the paper's 83 kJ/m^2
 * (0.04472 / sqrt(5) = 0.02); at s_c = 0.04472 the coarse plate would be five
 * times tougher and the crack would not move. */
#include "sim_fixtures.h"
#include "test_support.h"

#include "core/mem.h"
#include "solid/bond/diagnostics.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const COARSE[] = {
    "solid.spacing=5e-4",
    "solid.thickness=5e-4",
    "time.dt=6.6835e-8",
    "solid.material.critical_stretch=0.02",
    "solid.geometry=[{shape: rectangle, min: [-0.025, -0.0265], max: [0.025, 0.0265]}]",
    "output.history_interval=6.6835e-8",
    "output.probes.1.region=[{shape: rectangle, min: [-0.025, 0.0], max: [0.025, 5.0e-4]}]",
};
enum { NCOARSE = sizeof COARSE / sizeof COARSE[0] };

static void run_coarse(Sim *sim, int threads, const char *dir) {
    omp_set_num_threads(threads);
    fixture_sim("plate_crack.yaml", COARSE, NCOARSE, sim);
    SimRunOptions opt = {dir, false, NULL};
    assert_ok(sim_run(sim, &opt));
}

/* Largest |crack_tip_y_m| over the rows of history.csv in `dir`. */
static double max_tip_offset(const char *dir) {
    char path[1200];
    snprintf(path, sizeof path, "%s/history.csv", dir);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    char line[4096];
    assert_non_null(fgets(line, sizeof line, f));
    int column = 0;
    for (char *tok = strtok(line, ",\n"); tok && strcmp(tok, "crack_tip_y_m");
         tok = strtok(NULL, ",\n"))
        column++;
    double worst = 0;
    int rows = 0;
    while (fgets(line, sizeof line, f)) {
        char *tok = strtok(line, ",\n");
        for (int k = 0; k < column && tok; k++) tok = strtok(NULL, ",\n");
        assert_non_null(tok);
        double y = strtod(tok, NULL);
        if (y == y) worst = fmax(worst, fabs(y));
        rows++;
    }
    fclose(f);
    assert_true(rows > 200); /* every step of 250 */
    return worst;
}

/* Index of the lattice point mirrored in x and/or y (-1 if absent). */
static int64_t mirror(const BondBody *b, const int64_t *grid, int32_t lo[2], int32_t n[2],
                      int64_t i, bool mx, bool my) {
    int32_t ix = b->lattice[0][i] - lo[0], iy = b->lattice[1][i] - lo[1];
    if (mx) ix = n[0] - 1 - ix;
    if (my) iy = n[1] - 1 - iy;
    return grid[(int64_t)iy * n[0] + ix];
}

static void test_straight_symmetric_crack(void **state) {
    (void)state;
    Sim sim;
    const char *dir = test_scratch_dir("pd_plate");
    run_coarse(&sim, 2, dir);
    const BondBody *b = fixture_body(&sim);
    double *damage;
    assert_ok(nspd_alloc(&damage, (size_t)b->n, sizeof(double)));
    pd_damage(b, damage);

    /* lattice -> point map for the mirror images */
    int32_t lo[2] = {INT32_MAX, INT32_MAX}, hi[2] = {INT32_MIN, INT32_MIN}, n[2];
    for (int64_t i = 0; i < b->n; i++)
        for (int d = 0; d < 2; d++) {
            lo[d] = b->lattice[d][i] < lo[d] ? b->lattice[d][i] : lo[d];
            hi[d] = b->lattice[d][i] > hi[d] ? b->lattice[d][i] : hi[d];
        }
    n[0] = hi[0] - lo[0] + 1;
    n[1] = hi[1] - lo[1] + 1;
    int64_t *grid;
    assert_ok(nspd_alloc(&grid, (size_t)n[0] * (size_t)n[1], sizeof(int64_t)));
    for (int64_t i = 0; i < b->n; i++)
        grid[(int64_t)(b->lattice[1][i] - lo[1]) * n[0] + (b->lattice[0][i] - lo[0])] = i;

    /* Symmetry about both axes. The lattice coordinates are rounded
     * symmetrically about the plate's centre, so mirrored bonds have bitwise
     * equal coefficients; what is left is the different order in which
     * mirrored points sum their bonds (round-off 1e-16), which on this plate
     * changes no bond's fate: measured difference 0 for both mirrors. The
     * bound allows the crack faces' round-off to flip a few bonds (a point
     * loses 1/25 of its bond volume per bond). */
    for (int axis = 0; axis < 2; axis++) {
        double worst = 0;
        for (int64_t i = 0; i < b->n; i++)
            worst = fmax(worst,
                         fabs(damage[i] - damage[mirror(b, grid, lo, n, i, axis == 0, axis == 1)]));
        print_message("mirror %c: largest damage difference %.3g\n", axis ? 'y' : 'x', worst);
        assert_true(worst < 0.1);
    }

    /* The crack stays on the centre line: the tracked tip at every step, and
     * every point that has lost at least half its bonds (separated material;
     * measured |y| <= 1.5 dx), within two spacings. Broken bonds themselves
     * form a process zone up to 3 dx wide (bonds from the third row). */
    double dx = b->spacing, max_y = 0;
    for (int64_t i = 0; i < b->n; i++)
        if (damage[i] >= 0.5) max_y = fmax(max_y, fabs(b->x[1][i]));
    double tip_y = max_tip_offset(dir);
    print_message("separated points within |y| <= %.2f dx, tip within %.2f dx\n", max_y / dx,
                  tip_y / dx);
    assert_true(max_y <= 2 * dx);
    assert_true(tip_y <= 2 * dx);

    /* It grew well beyond the pre-crack (tip at 5 mm) at a speed below the
     * Rayleigh speed. */
    const ProbeState *tip = &sim.probes[0];
    double speed = probe_crack_speed(tip), c_r = pd_rayleigh_wave_speed(&b->cfg);
    print_message("tip x %.2f mm, speed %.0f m/s = %.2f c_R\n", 1e3 * tip->last_tip[0], speed,
                  speed / c_r);
    assert_true(tip->last_tip[0] > 0.015);
    assert_true(speed > 0 && speed < c_r);
    nspd_free(&grid);
    nspd_free(&damage);
    sim_destroy(&sim);
}

/* Each point's force is summed in a fixed order whatever thread computes it,
 * and every reduction uses fixed chunks: 1 and 2 threads agree bit for bit. */
static void test_threads_bitwise(void **state) {
    (void)state;
    Sim one, two;
    run_coarse(&one, 1, NULL);
    run_coarse(&two, 2, NULL);
    const BondBody *a = fixture_body(&one), *b = fixture_body(&two);
    assert_int_equal(a->n, b->n);
    for (int d = 0; d < 2; d++) {
        assert_memory_equal(a->u[d], b->u[d], (size_t)a->n * sizeof(double));
        assert_memory_equal(a->v[d], b->v[d], (size_t)a->n * sizeof(double));
    }
    assert_memory_equal(a->bond_coef, b->bond_coef, (size_t)a->bond_count * sizeof(float));
    double e1 = pd_elastic_energy(a), e2 = pd_elastic_energy(b);
    assert_memory_equal(&e1, &e2, sizeof e1);
    sim_destroy(&one);
    sim_destroy(&two);
    omp_set_num_threads(2);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_straight_symmetric_crack),
        cmocka_unit_test(test_threads_bitwise),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
