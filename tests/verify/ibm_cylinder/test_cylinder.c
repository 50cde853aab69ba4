/* Supersonic cylinder, Ma 2, Re 300 (paper 000 Sec. 4.1.2), at D/32 near
 * the body, to t = 10 D/c (about 40 s on one core; CFL 0.8, which changed
 * C_D by 0.03 % against 0.5): drag against the paper and its references,
 * stagnation pressure against the Rayleigh pitot formula, bow-shock
 * stand-off against Billig's correlation, and the cost of the ghost fill
 * against the flow step. Set-up: tests/verify/ibm_common/ibm_cases.h. */
#include "test_support.h"

#include "../ibm_common/ibm_cases.h"

static void test_cylinder(void **state) {
    (void)state;
    const double h = 1.0 / 32, mach = 2.0;
    GksConfig c;
    FlowPrim inf;
    ibm_cylinder_config(&c, h, IBM_CASE_SUTHERLAND_T, &inf);
    GksSolver *s = ibm_case_solver(&c, NULL);
    assert_non_null(s);
    IbmPolyline wall;
    assert_ok(ibm_cylinder_markers(h, &wall));
    Ibm *ibm = ibm_case_body(s, &wall, 0.5);
    assert_non_null(ibm);
    IbmUpdateStats st;
    ibm_stats(ibm, &st);
    const Grid *g = gks_solver_grid(s);
    printf("cylinder D/32: %d x %d cells, %d markers, %d ghosts (cases 1/2/3: %d/%d/%d, "
           "extended %d, nearest %d), build %.4f s\n",
           g->nx, g->ny, wall.n, st.ghosts, st.by_case[0], st.by_case[1], st.by_case[2],
           st.by_level[IBM_LEVEL_EXTENDED], st.by_level[IBM_LEVEL_NEAREST], st.seconds);
    IbmSurface sf;
    memset(&sf, 0, sizeof sf);
    assert_ok(ibm_surface_reserve(ibm, &sf));
    const IbmReference ref = {
        .rho = inf.rho, .u = inf.u, .v = inf.v, .p = inf.p, .length = 1.0, .p_ambient = inf.p};
    const double t0 = nspd_wall_time();
    assert_ok(ibm_case_advance(s, ibm, &ref, &sf, 10.0, 2.0, "D/32"));
    const double wall_s = nspd_wall_time() - t0;
    const IbmBodyForces *F = &sf.forces[0];
    const double pitot = ibm_cp_stagnation_pitot(IBM_GAMMA, mach);
    const double xs = ibm_case_shock_x(s, 6.0, mach), standoff = 1.5 - xs;
    const double billig = 0.5 * ibm_billig_standoff_over_r(mach);
    double fill = 0.0, step = 1.0;
    assert_ok(ibm_case_fill_cost(s, ibm, 20, &fill, &step));
    printf("cylinder D/32, t = 10 (%.0f s): C_D = %.4f (pressure %.4f, viscous %.4f), "
           "C_D/1.556 - 1 = %+.4f, C_D/1.55 - 1 = %+.4f\n",
           wall_s, F->cd, F->cd_pressure, F->cd_viscous, F->cd / 1.556 - 1.0, F->cd / 1.55 - 1.0);
    printf("  Cp_stag = %.4f, Rayleigh pitot %.4f: %+.4f; stand-off %.4f D, Billig %.4f D: %+.3f\n",
           F->cp_stagnation, pitot, F->cp_stagnation / pitot - 1.0, standoff, billig,
           standoff / billig - 1.0);
    printf("  ghost fill %.3g s per call, flow step %.3g s: fill / step = %.4f\n", fill, step,
           fill / step);
    /* Measured: C_D 1.5573 at t = 10 (1.5438 at t = 16; D/64 and the
     * convergence table in test_convergence.c), +0.5 % from 1.55;
     * requirement 5 % (the bound at this resolution). */
    assert_true(fabs(F->cd / 1.55 - 1.0) < 0.05);
    /* Measured: Cp_stag 1.6671 vs 1.6573 (+0.6 %; +0.3 % at t = 16);
     * requirement 2 %. */
    assert_true(fabs(F->cp_stagnation / pitot - 1.0) < 0.02);
    /* Measured: stand-off 0.734 D vs Billig's 0.620 D (+18 %), still growing
     * slowly (0.751 D at t = 16). An inviscid run on the same grid gives
     * 0.73 D, so the gap is not the viscous layer: Billig's "cylinder-wedge"
     * fit comes from hypersonic data and Mach 2 is at its edge. Bound 25 %. */
    assert_true(fabs(standoff / billig - 1.0) < 0.25);
    /* Measured: 1.0e-3 of a step (174 ghosts, 17712 cells). */
    assert_true(fill / step < 0.05);
    assert_close(F->cl, 0.0, 1e-3); /* symmetric to round-off plus a weak wake mode */
    ibm_surface_free(&sf);
    ibm_destroy(&ibm);
    ibm_polyline_free(&wall);
    gks_solver_destroy(&s);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_cylinder)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
