/* The coupling's rigid limit and its momentum exchange.
 *
 * cases/cylinder_ma2_re300.yaml at D/16 with its fixed body replaced by a PD
 * disc 10^6 times stiffer than the gas pressure and 10^4 times denser than
 * the gas (held in place by `hold: balance`): its surface loop must give the
 * rigid immersed boundary's C_D on the same grid. The PD surface is the
 * polygon through the outermost lattice points, which lie up to a spacing
 * inside the disc's edge; the disc is therefore made half a spacing larger
 * (radius 0.5 + dx/2) so that the loop's mean radius is the cylinder's.
 * Both walls have sealed ghost faces, as the case file.
 *
 * And at every coupled step the force the solid receives, sum_i V_i f_i /
 * thickness, equals the integral of the surface tractions the flow exerts,
 * to round-off (measured 1e-15 relative). */
#include "sim_fixtures.h"
#include "test_support.h"

#include <math.h>

#define GRID_D16                                                                                   \
    "flow.grid.x.segments=[{length: 0.6, spacing_start: 0.08, spacing_end: 0.0625}, {length: "     \
    "2.2, spacing: 0.0625}, {length: 7.2, spacing_start: 0.0625, spacing_end: 0.5}]",              \
        "flow.grid.y.segments=[{length: 4.6, spacing_start: 0.5, spacing_end: 0.0625}, {length: "  \
        "2.8, spacing: 0.0625}, {length: 4.6, spacing_start: 0.0625, spacing_end: 0.5}]"

static const char *const RIGID[] = {
    GRID_D16,
    "flow.bodies.0.markers=104",
    "time.end=8.0",
    "output.average_from=4.0",
};

static const char *const SOLID[] = {
    GRID_D16,
    "flow.bodies=~",
    "flow.soft_start=~",
    "flow.ghost_faces=~",
    "time.end=8.0",
    "output.average_from=4.0",
    "solid={model: plane_stress, spacing: 0.02, material: {density: 1.0e4, youngs_modulus: 1.0e6}, "
    "geometry: [{shape: disc, center: [2.0, 6.0], radius: 0.51}], integrator: velocity_verlet}",
    "coupling={hold: balance, soft_start: 0.5, ghost_faces: sealed}",
};

/* Time-averaged C_D of the run (t >= 4). */
static double average_cd(Sim *sim) {
    SimRunOptions opt = {NULL, false, NULL};
    assert_ok(sim_run(sim, &opt));
    assert_true(fixture_coupling_summary(sim, "coefficient_samples") > 10);
    return fixture_coupling_summary(sim, "cd");
}

static void test_stiff_disc_is_rigid(void **state) {
    (void)state;
    Sim rigid, soft;
    fixture_sim("cylinder_ma2_re300.yaml", RIGID, sizeof RIGID / sizeof RIGID[0], &rigid);
    double cd_rigid = average_cd(&rigid);
    sim_destroy(&rigid);
    fixture_sim("cylinder_ma2_re300.yaml", SOLID, sizeof SOLID / sizeof SOLID[0], &soft);
    double cd_pd = average_cd(&soft);
    print_message("C_D rigid immersed boundary %.4f, stiff PD disc %.4f (%+.2f %%)\n", cd_rigid,
                  cd_pd, 100 * (cd_pd / cd_rigid - 1));
    /* Measured: 1.5154 and 1.5345, +1.26 % (with reflected faces on both
     * 1.5341 and 1.5545, +1.33 %): the polygon through the lattice points is
     * not a circle at D/16; bound 2 %. */
    assert_true(fabs(cd_pd / cd_rigid - 1) < 0.02);
    sim_destroy(&soft);
}

static void test_momentum_exchange(void **state) {
    (void)state;
    const char *const balance[] = {
        GRID_D16,
        "flow.bodies=~",
        "flow.soft_start=~",
        "time.end=0.5",
        "output.average_from=0.0",
        "solid={model: plane_stress, spacing: 0.02, material: {density: 1.0e3, youngs_modulus: "
        "1.0e4}, geometry: [{shape: disc, center: [2.0, 6.0], radius: 0.51}]}",
        "coupling={soft_start: 0.5}",
    };
    Sim sim;
    fixture_sim("cylinder_ma2_re300.yaml", balance, sizeof balance / sizeof balance[0], &sim);
    double worst = 0.0;
    for (int s = 0; s < 20; s++) {
        assert_ok(sim_advance(&sim, 1));
        const BondBody *b = fixture_body(&sim);
        double received[2] = {0, 0};
        for (int64_t i = 0; i < b->n; i++)
            for (int d = 0; d < 2; d++) received[d] += b->volume[i] * b->external[d][i];
        const IbmSurface *L = ghost_coupling_surface(sim.coupling);
        CouplingLoads loads;
        coupling_loads(sim.coupling, &loads);
        double taken[2] = {0, 0}, scale = 0;
        for (int k = 0; k < L->n; k++) {
            taken[0] += L->fx[k] * L->ds[k];
            taken[1] += L->fy[k] * L->ds[k];
            scale += hypot(L->fx[k], L->fy[k]) * L->ds[k];
        }
        for (int d = 0; d < 2; d++) {
            received[d] /= b->cfg.thickness;
            worst = fmax(worst, fabs(received[d] - taken[d]) / scale);
            worst = fmax(worst, fabs(loads.force_on_solid[d] - taken[d]) / scale);
        }
    }
    print_message("force received by the solid vs taken from the flow: %.2e relative\n", worst);
    assert_true(worst < 1e-12);
    sim_destroy(&sim);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_stiff_disc_is_rigid),
                                       cmocka_unit_test(test_momentum_exchange)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
