/* NACA 0012, Ma 0.5, Re 5000, zero incidence (paper 000 Sec. 4.1.1), coarse
 * version for `make test` (about 45 s on one core): stagnation pressure
 * against the isentropic value and zero lift by symmetry.
 *
 * Grid: c/384 in the leading-edge box (the nose radius 0.0158 c is 6 cells:
 * the stagnation pressure needs it; at c/256 it came out 1.3 % low and the
 * run developed an asymmetric mode that amplified round-off by 10 per 0.8
 * time units), c/32 along the chord, a smaller domain than the paper's,
 * (-4, 8) x (-4, 4): the stagnation pressure does not depend on it, and the
 * acoustic start-up transient leaves it sooner (with (-10, 20) x (-10, 10) the
 * total pressure one chord upstream was still 6 % of q low at t = 5). CFL
 * 0.8 (stable; halves the cost). Soft start over 0.1 c. The grid is mirror
 * symmetric to the last bit in its widths, the markers exactly. */
#include "test_support.h"

#include "../ibm_common/ibm_cases.h"

static void test_naca_coarse(void **state) {
    (void)state;
    const NacaGrid ng = {
        .h_le = 1.0 / 384, .h_body = 1.0 / 32, .a = 0.02, .up = 4.0, .down = 8.0, .half = 4.0};
    GksConfig c;
    FlowPrim inf;
    ibm_naca_config(&c, &ng, IBM_CASE_SUTHERLAND_T, &inf);
    GksSolver *s = ibm_case_solver(&c, NULL);
    assert_non_null(s);
    IbmPolyline wall;
    assert_ok(ibm_naca_markers(ng.h_body / 2, &wall));
    Ibm *ibm = ibm_case_body(s, &wall, 0.1);
    assert_non_null(ibm);
    const Grid *g = gks_solver_grid(s);
    IbmUpdateStats st;
    ibm_stats(ibm, &st);
    printf("naca coarse: %d x %d cells, %d markers, %d ghosts (cases 1/2/3: %d/%d/%d, "
           "extended %d, nearest %d)\n",
           g->nx, g->ny, wall.n, st.ghosts, st.by_case[0], st.by_case[1], st.by_case[2],
           st.by_level[IBM_LEVEL_EXTENDED], st.by_level[IBM_LEVEL_NEAREST]);
    IbmSurface sf;
    memset(&sf, 0, sizeof sf);
    assert_ok(ibm_surface_reserve(ibm, &sf));
    const IbmReference ref = {
        .rho = inf.rho, .u = inf.u, .v = inf.v, .p = inf.p, .length = 1.0, .p_ambient = inf.p};
    const double t0 = nspd_wall_time();
    assert_ok(ibm_case_advance(s, ibm, &ref, &sf, 4.5, 0.9, "naca"));
    const IbmBodyForces *F = &sf.forces[0];
    const double cp0 = ibm_cp_stagnation_isentropic(IBM_GAMMA, 0.5);
    printf("naca coarse, t = 4.5 (%.0f s): Cp_stag %.4f vs isentropic %.4f: %+.4f; C_L %.2e; "
           "C_D %.5f (pressure %.5f, friction %.5f); upper separation x/c = %.3f\n",
           nspd_wall_time() - t0, F->cp_stagnation, cp0, F->cp_stagnation / cp0 - 1.0, F->cl, F->cd,
           F->cd_pressure, F->cd_viscous, F->x_separation_over_c);
    /* Measured: Cp_stag 1.0554 vs 1.0641 (-0.81 %; -0.5 % at t = 6, -0.3 % with
     * c/512 at the nose); requirement 2 %. */
    assert_true(fabs(F->cp_stagnation / cp0 - 1.0) < 0.02);
    /* Measured: |C_L| 1.8e-13 (round-off: the flow solver's y-flux is mirror
     * symmetric to round-off, not bitwise); requirement 1e-6. */
    assert_true(fabs(F->cl) < 1e-6);
    /* the stagnation point is the leading edge */
    assert_close(F->stagnation[0], 0.0, 0.01);
    assert_close(F->stagnation[1], 0.0, 0.01);
    ibm_surface_free(&sf);
    ibm_destroy(&ibm);
    ibm_polyline_free(&wall);
    gks_solver_destroy(&s);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_naca_coarse)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
