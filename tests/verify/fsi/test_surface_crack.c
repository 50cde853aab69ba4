/* A crack that reaches the surface stays closed to the flow (the chosen
 * behaviour, couple/ghost/fsi.h): the interface is the surface loop traced on the
 * intact lattice, so it bridges the crack's mouth however far it opens, and
 * the grid stays consistent.
 *
 * A block 1 x 1 with a pre-crack from its left face to its middle, in gas
 * at rest, is pulled apart: its upper and lower halves start at +-0.05
 * (the speed of sound is 1), failure off. By t = 1 the mouth has opened by
 * 0.105 (measured), 6.7 cells of 1/64: every one of the 150 cells between
 * the crack faces is still solid or ghost, never fluid, and the run stays
 * finite. The segment across the mouth (5 spacings long) carries no load. */
#include "sim_fixtures.h"
#include "test_support.h"

#include <math.h>

static const char CASE[] = "name: surface_crack\n"
                           "time: {end: 1.0}\n"
                           "solid:\n"
                           "  model: plane_stress\n"
                           "  spacing: 0.02\n"
                           "  material: {density: 100.0, youngs_modulus: 100.0}\n"
                           "  geometry: [{shape: rectangle, min: [1.0, 1.0], max: [2.0, 2.0]}]\n"
                           "  precracks: [{from: [0.9, 1.5], to: [1.5, 1.5]}]\n"
                           "  initial_velocity:\n"
                           "    - {region: [{shape: rectangle, min: [0, 1.5], max: [3, 3]}], "
                           "velocity: [0.0, 0.05]}\n"
                           "    - {region: [{shape: rectangle, min: [0, 0], max: [3, 1.5]}], "
                           "velocity: [0.0, -0.05]}\n"
                           "  integrator: velocity_verlet\n"
                           "flow:\n"
                           "  gas: {gamma: 1.4, gas_constant: 1.0}\n"
                           "  grid:\n"
                           "    x: {segments: [{length: 3.0, cells: 192}]}\n"
                           "    y: {segments: [{length: 3.0, cells: 192}]}\n"
                           "  boundaries:\n"
                           "    x_min: {type: slip_wall}\n"
                           "    x_max: {type: slip_wall}\n"
                           "    y_min: {type: slip_wall}\n"
                           "    y_max: {type: slip_wall}\n"
                           "  initial: {state: {density: 1.0, pressure: 0.7142857142857143}}\n"
                           "coupling: {wall: adiabatic}\n";

static void test_crack_stays_closed(void **state) {
    (void)state;
    Sim sim;
    fixture_sim_text(CASE, &sim);
    SimRunOptions opt = {NULL, false, NULL};
    assert_ok(sim_run(&sim, &opt));
    const BondBody *b = fixture_body(&sim);
    /* the mouth's opening: the gap between the two points nearest to the
     * left face just above and below the crack */
    double upper = (double)INFINITY, lower = -(double)INFINITY;
    for (int64_t i = 0; i < b->n; i++) {
        if (b->x[0][i] > 1.02) continue;
        double y = b->x[1][i] + b->u[1][i];
        if (b->x[1][i] > 1.5)
            upper = fmin(upper, y);
        else
            lower = fmax(lower, y);
    }
    const Grid *g = gks_solver_grid(fixture_flow(&sim));
    const uint8_t *kind = ibm_kinds(ghost_coupling_ibm(sim.coupling));
    int inside = 0, fluid = 0;
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) {
            double x = g->ax[0].center[i], y = g->ax[1].center[j];
            if (x < 1.02 || x > 1.4 || y < lower + 0.01 || y > upper - 0.01) continue;
            inside++;
            fluid += kind[grid_index(g, i, j)] == FLOW_CELL_FLUID;
        }
    print_message("mouth opening %.4f (%.1f cells); %d cells between the faces, %d of them fluid\n",
                  upper - lower - 0.02, (upper - lower - 0.02) * 64, inside, fluid);
    assert_true(upper - lower - 0.02 > 3.0 / 64); /* it did open by several cells */
    assert_true(inside > 20);
    assert_int_equal(fluid, 0);
    /* the segment across the opened mouth is a bridge: longer than 2.5
     * spacings, not wetted, no load (IbmReference.bridge_length) */
    const IbmSurface *loads = ghost_coupling_surface(sim.coupling);
    int bridges = 0;
    for (int s = 0; s < loads->n; s++) {
        if (loads->ds[s] <= 2.5 * b->spacing) continue;
        bridges++;
        assert_true(isnan(loads->cp[s]));
        assert_true(loads->fx[s] == 0.0 && loads->fy[s] == 0.0);
    }
    print_message("%d bridge segment(s)\n", bridges);
    assert_true(bridges >= 1);
    sim_destroy(&sim);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_crack_stays_closed)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
