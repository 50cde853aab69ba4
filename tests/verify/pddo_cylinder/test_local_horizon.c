/* A polar patch's local horizon (`bodies[].horizon: local`, flow/pddo/
 * polar.h) through the whole pipeline from cases/cylinder_confined_re10.yaml,
 * coarse (dx 0.2 m, patch to 1 m, antisymmetric ghosts, divergence_term
 * updated, wall_pressure momentum, tau = dt = 2e-3 s), each run to its
 * steady state (max |du/dt| below 1e-4 m/s^2).
 *
 * With the cloud's one horizon delta = 3 dx the rings' spacing does not
 * set the wall operators' error, delta does: the patch refined (dr and
 * dtheta halved) moves the drag from 248.00 to 236.11 N/m (-4.8 %, away
 * from icoFoam's converged 288.8 N/m, docs/VALIDATION.md; the viscous part
 * 74.22 -> 67.82). With the local horizon the same two patches give 268.22
 * and 275.78 N/m (viscous 91.76 -> 110.98). Asserted: on the same nodes
 * the local horizon is nearer icoFoam's drag by more than 1 % of it, and
 * its finer patch nearer again by more than 1 % (measured 7.0 % and
 * 2.6 %); either fails if the local horizon stops acting. About 3 s. */
#include "sim_fixtures.h"
#include "test_support.h"

#include <math.h>
#include <stdio.h>

/* The steady drag (N/m) of the coarse cylinder with the patch `body`. */
static double steady_drag(const char *body) {
    char body_set[256], label[160];
    snprintf(body_set, sizeof body_set,
             "flow.bodies=[{shape: circle, center: [5.0, 3.0], radius: 0.5, patch_radius: 1.0%s}]",
             body);
    snprintf(label, sizeof label, "patch {%s}", body);
    const char *sets[] = {
        body_set,
        "flow.wall_pressure=momentum",
        "flow.divergence_time=2e-3",
        "time.dt=2e-3",
    };
    return fixture_coarse_cylinder_drag(sets, (int)(sizeof sets / sizeof *sets), label);
}

static void test_refined_patch(void **state) {
    (void)state;
    const char *fine = ", dr_over_spacing: 0.345, dtheta: 0.1";
    const double lattice[2] = {steady_drag(""), steady_drag(fine)};
    char local_fine[128];
    snprintf(local_fine, sizeof local_fine, "%s, horizon: local", fine);
    const double local[2] = {steady_drag(", horizon: local"), steady_drag(local_fine)};
    printf("patch refined: drag %+.3f %% (lattice horizon), %+.3f %% (local)\n",
           100 * (lattice[1] / lattice[0] - 1.0), 100 * (local[1] / local[0] - 1.0));
    const double icofoam = 288.8; /* N/m, converged (docs/VALIDATION.md) */
    /* the local horizon nearer icoFoam on the same nodes, and nearer
     * again on the finer patch, by at least 1 % of the drag each */
    assert_true(fabs(local[0] - icofoam) < fabs(lattice[0] - icofoam) - 0.01 * icofoam);
    assert_true(fabs(local[1] - icofoam) < fabs(local[0] - icofoam) - 0.01 * icofoam);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_refined_patch)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
