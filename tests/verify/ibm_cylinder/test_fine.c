/* ctest-labels: slow
 * The finest cylinder run that fits in minutes (the paper's D/512 would take
 * about 3e11 cell updates, days on two cores): D/128 near the body, started
 * from the D/32 solution at t = 12 (grid sequencing by bilinear
 * interpolation) and run 5 more D/c. Prints C_D and its parts, Cp_stag
 * against the Rayleigh pitot value, the stand-off against Billig, the
 * separation angle, Cp around the cylinder and the cost of the ghost fill. */
#include "test_support.h"

#include "../ibm_common/ibm_cases.h"

static GksSolver *solver(double h, GksSolver *from, FlowPrim *inf) {
    GksConfig c;
    ibm_cylinder_config(&c, h, IBM_CASE_SUTHERLAND_T, inf);
    GksSolver *s = ibm_case_solver(&c, from);
    assert_non_null(s);
    return s;
}

static void test_fine(void **state) {
    (void)state;
    FlowPrim inf;
    const IbmReference ref = {.rho = 1.0,
                              .u = 2.0,
                              .v = 0.0,
                              .p = 1.0 / IBM_GAMMA,
                              .length = 1.0,
                              .p_ambient = 1.0 / IBM_GAMMA};
    /* coarse start */
    GksSolver *cs = solver(1.0 / 32, NULL, &inf);
    IbmPolyline cw;
    assert_ok(ibm_cylinder_markers(1.0 / 32, &cw));
    Ibm *ci = ibm_case_body(cs, &cw, 0.5);
    assert_non_null(ci);
    IbmSurface sf;
    memset(&sf, 0, sizeof sf);
    assert_ok(ibm_surface_reserve(ci, &sf));
    assert_ok(ibm_case_advance(cs, ci, &ref, &sf, 12.0, 4.0, "D/32"));
    /* fine */
    const double h = 1.0 / 128;
    GksSolver *s = solver(h, cs, &inf);
    IbmPolyline wall;
    assert_ok(ibm_cylinder_markers(h, &wall));
    Ibm *ibm = ibm_case_body(s, &wall, 0.0);
    assert_non_null(ibm);
    assert_ok(ibm_surface_reserve(ibm, &sf));
    const Grid *g = gks_solver_grid(s);
    IbmUpdateStats st;
    ibm_stats(ibm, &st);
    printf("D/128: %d x %d cells, %d markers, %d ghosts (cases 1/2/3 %d/%d/%d, extended %d, "
           "nearest %d, max sum|w| %.3f), built in %.3f s\n",
           g->nx, g->ny, wall.n, st.ghosts, st.by_case[0], st.by_case[1], st.by_case[2],
           st.by_level[IBM_LEVEL_EXTENDED], st.by_level[IBM_LEVEL_NEAREST], st.max_weight_sum,
           st.seconds);
    const double t0 = nspd_wall_time();
    assert_ok(ibm_case_advance(s, ibm, &ref, &sf, 5.0, 0.5, "D/128"));
    const IbmBodyForces *F = &sf.forces[0];
    const double pitot = ibm_cp_stagnation_pitot(IBM_GAMMA, 2.0);
    const double standoff = 1.5 - ibm_case_shock_x(s, 6.0, 2.0);
    const double billig = 0.5 * ibm_billig_standoff_over_r(2.0);
    const double sep = atan2(F->separation[1] - 6.0, 2.0 - F->separation[0]) * 180.0 / M_PI;
    double fill = 0.0, step = 1.0;
    assert_ok(ibm_case_fill_cost(s, ibm, 10, &fill, &step));
    printf("D/128 (%.0f s): C_D %.4f (pressure %.4f, viscous %.4f), vs 1.556 %+.4f, vs 1.547 "
           "%+.4f, vs 1.525 %+.4f\n",
           nspd_wall_time() - t0, F->cd, F->cd_pressure, F->cd_viscous, F->cd / 1.556 - 1.0,
           F->cd / 1.547 - 1.0, F->cd / 1.525 - 1.0);
    printf("  Cp_stag %.4f vs pitot %.4f: %+.4f; stand-off %.4f D vs Billig %.4f D: %+.3f; "
           "separation %.1f deg from the front; C_L %.1e\n",
           F->cp_stagnation, pitot, F->cp_stagnation / pitot - 1.0, standoff, billig,
           standoff / billig - 1.0, sep, F->cl);
    printf("  ghost fill %.3g s, flow step %.3g s (%d ghosts, %ld cells): fill / step %.5f\n", fill,
           step, st.ghosts, (long)g->nx * g->ny, fill / step);
    printf("  Cp(theta), theta from the front stagnation point (upper side):\n");
    for (int deg = 0; deg <= 180; deg += 15) {
        double best = 1e9, cp = 0.0, cf = 0.0;
        for (int k = 0; k < sf.n; k++) {
            if (!sf.upper[k] && deg > 0 && deg < 180) continue;
            const double th = atan2(sf.y[k] - 6.0, 2.0 - sf.x[k]) * 180.0 / M_PI;
            if (fabs(th - deg) < best) best = fabs(th - deg), cp = sf.cp[k], cf = sf.cf[k];
        }
        printf("    %3d  Cp %+.4f  Cf %+.4f\n", deg, cp, cf);
    }
    /* Measured (500 s on 2 cores): C_D 1.5756 (pressure 1.3936, viscous
     * 0.1820), +1.3 % from the paper's 1.556; bound 1.5 % (the at
     * full resolution, which this is not). */
    assert_true(fabs(F->cd / 1.556 - 1.0) < 0.015);
    /* Measured: Cp_stag +0.26 % from the pitot value; bound 1 %. */
    assert_true(fabs(F->cp_stagnation / pitot - 1.0) < 0.01);
    /* Measured: stand-off 0.741 D, +19 % from Billig's fit (an inviscid run
     * gives the same: the fit is hypersonic, Mach 2 its edge); bound 25 %. */
    assert_true(fabs(standoff / billig - 1.0) < 0.25);
    ibm_surface_free(&sf);
    ibm_destroy(&ibm);
    ibm_destroy(&ci);
    ibm_polyline_free(&wall);
    ibm_polyline_free(&cw);
    gks_solver_destroy(&s);
    gks_solver_destroy(&cs);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_fine)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
