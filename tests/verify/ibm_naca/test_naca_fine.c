/* ctest-labels: slow
 * NACA 0012, Ma 0.5, Re 5000, zero incidence at the paper's resolution:
 * c/512 over the whole airfoil and its near wake band, domain (-10, 20) x
 * (-10, 10) (paper 000 Sec. 4.1.1). Started from a c/64 solution at t = 12
 * (grid sequencing), then 6 more c/c_inf (3 chord passages).
 * Prints Cp(x/c) on both sides, C_D (pressure, friction), the upper
 * separation point, Cp_stag against the isentropic value and C_L. */
#include "test_support.h"

#include "../ibm_common/ibm_cases.h"

static GksSolver *solver(const NacaGrid *ng, GksSolver *from) {
    GksConfig c;
    FlowPrim inf;
    ibm_naca_config(&c, ng, IBM_CASE_SUTHERLAND_T, &inf);
    GksSolver *s = ibm_case_solver(&c, from);
    assert_non_null(s);
    return s;
}

static void test_naca_fine(void **state) {
    (void)state;
    const IbmReference ref = {.rho = 1.0,
                              .u = 0.5,
                              .v = 0.0,
                              .p = 1.0 / IBM_GAMMA,
                              .length = 1.0,
                              .p_ambient = 1.0 / IBM_GAMMA};
    const NacaGrid coarse = {1.0 / 128, 1.0 / 64, 0.1, 10.0, 20.0, 10.0};
    const NacaGrid fine = {1.0 / 512, 1.0 / 512, 0.1, 10.0, 20.0, 10.0};
    GksSolver *cs = solver(&coarse, NULL);
    IbmPolyline cw;
    assert_ok(ibm_naca_markers(1.0 / 128, &cw));
    Ibm *ci = ibm_case_body(cs, &cw, 0.1);
    assert_non_null(ci);
    IbmSurface sf;
    memset(&sf, 0, sizeof sf);
    assert_ok(ibm_surface_reserve(ci, &sf));
    assert_ok(ibm_case_advance(cs, ci, &ref, &sf, 12.0, 4.0, "c/64"));

    GksSolver *s = solver(&fine, cs);
    IbmPolyline wall;
    assert_ok(ibm_naca_markers(1.0 / 1024, &wall));
    Ibm *ibm = ibm_case_body(s, &wall, 0.0);
    assert_non_null(ibm);
    assert_ok(ibm_surface_reserve(ibm, &sf));
    const Grid *g = gks_solver_grid(s);
    IbmUpdateStats st;
    ibm_stats(ibm, &st);
    printf("c/512: %d x %d cells, %d markers, %d ghosts (cases 1/2/3 %d/%d/%d, extended %d, "
           "nearest %d)\n",
           g->nx, g->ny, wall.n, st.ghosts, st.by_case[0], st.by_case[1], st.by_case[2],
           st.by_level[IBM_LEVEL_EXTENDED], st.by_level[IBM_LEVEL_NEAREST]);
    const double t0 = nspd_wall_time();
    assert_ok(ibm_case_advance(s, ibm, &ref, &sf, 6.0, 0.5, "c/512"));
    const IbmBodyForces *F = &sf.forces[0];
    const double cp0 = ibm_cp_stagnation_isentropic(IBM_GAMMA, 0.5);
    printf("c/512 (%.0f s): C_D %.5f (pressure %.5f, friction %.5f); upper separation x/c %.4f; "
           "Cp_stag %.4f vs isentropic %.4f (%+.4f); C_L %.2e\n",
           nspd_wall_time() - t0, F->cd, F->cd_pressure, F->cd_viscous, F->x_separation_over_c,
           F->cp_stagnation, cp0, F->cp_stagnation / cp0 - 1.0, F->cl);
    printf("  x/c    Cp upper  Cp lower  Cf upper\n");
    for (int q = 0; q <= 20; q++) {
        const double xc = q / 20.0;
        double bu = 1e9, bl = 1e9, cu = 0, cl = 0, fu = 0;
        for (int k = 0; k < sf.n; k++) {
            const double d = fabs(sf.x[k] - xc);
            if (sf.upper[k] && d < bu) bu = d, cu = sf.cp[k], fu = sf.cf[k];
            if (!sf.upper[k] && d < bl) bl = d, cl = sf.cp[k];
        }
        printf("  %.2f  %+.4f  %+.4f  %+.5f\n", xc, cu, cl, fu);
    }
    /* Measured (231 s on 2 cores, 996 x 204 cells): C_D 0.0527 (pressure
     * 0.0224, friction 0.0303), upper separation x/c 0.784, Cp_stag 1.0552
     * (-0.8 % from isentropic: the far field's start-up transient has not
     * left the (-10, 20) x (-10, 10) box; -0.3 % in a smaller one), |C_L|
     * 2.8e-7 and growing about 4x per 2 time units (round-off amplified by
     * a weak wake mode; the flow solver is mirror symmetric to round-off
     * only). */
    assert_true(fabs(F->cp_stagnation / cp0 - 1.0) < 0.02);
    assert_true(fabs(F->cl) < 1e-6);
    assert_true(F->x_separation_over_c > 0.7 && F->x_separation_over_c < 0.9);
    ibm_surface_free(&sf);
    ibm_destroy(&ibm);
    ibm_destroy(&ci);
    ibm_polyline_free(&wall);
    ibm_polyline_free(&cw);
    gks_solver_destroy(&s);
    gks_solver_destroy(&cs);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_naca_fine)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
