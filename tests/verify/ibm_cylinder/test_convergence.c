/* ctest-labels: slow
 * Grid convergence of the Ma 2, Re 300 cylinder (paper 000 Sec. 4.1.2):
 * C_D, its parts, Cp_stag and the bow-shock stand-off on D/16, D/32 and
 * D/64 near the body, each run from its own soft start to t = 16 D/c (about
 * 6 minutes on one core). Prints the table and the Richardson estimate.
 *
 * "C_D box" is the drag from the fluid's momentum balance over a box around
 * the body and its bow shock (ibm_case_box_force): it does not use the wall
 * treatment, so it tells the discrete solution's drag apart from the error
 * of the surface integration. Measured (t = 16, 291 s):
 *   D/16  C_D 1.5004 (p 1.3825, v 0.1180)  box 1.5640  Cp_stag -1.26 %  stand-off 0.780 D
 *   D/32  C_D 1.5438 (p 1.3901, v 0.1537)  box 1.5606  Cp_stag +0.30 %  stand-off 0.751 D
 *   D/64  C_D 1.5717 (p 1.3914, v 0.1802)  box 1.5640  Cp_stag +0.39 %  stand-off 0.740 D
 * (test_fine.c, D/128: C_D 1.5756, p 1.3936, v 0.1820). The box drag is
 * grid-independent at 1.56 (+0.3 % from the paper's 1.556); the surface
 * pressure part converges fast, the friction part slowly (the stagnation
 * boundary layer, 2.4 sqrt(nu/a) ~ 0.07 D, is 1 to 5 cells thick on these
 * grids), so the printed three-grid Richardson estimate (order 0.64) is
 * pessimistic: D/64 -> D/128 adds only 0.004. */
#include "test_support.h"

#include "../ibm_common/ibm_cases.h"
#include "flow/gks/grid.h"

typedef struct {
    int n;
    long cells, steps;
    double cd, cdp, cdv, cps, standoff, seconds, cd_box;
} Row;

static void run(int n, double t_end, Row *r) {
    const double h = 1.0 / n;
    GksConfig c;
    FlowPrim inf;
    ibm_cylinder_config(&c, h, IBM_CASE_SUTHERLAND_T, &inf);
    GksSolver *s = ibm_case_solver(&c, NULL);
    assert_non_null(s);
    IbmPolyline wall;
    assert_ok(ibm_cylinder_markers(h, &wall));
    Ibm *ibm = ibm_case_body(s, &wall, 0.5);
    assert_non_null(ibm);
    IbmSurface sf;
    memset(&sf, 0, sizeof sf);
    assert_ok(ibm_surface_reserve(ibm, &sf));
    const IbmReference ref = {
        .rho = inf.rho, .u = inf.u, .v = inf.v, .p = inf.p, .length = 1.0, .p_ambient = inf.p};
    const double t0 = nspd_wall_time();
    char tag[16];
    snprintf(tag, sizeof tag, "D/%d", n);
    assert_ok(ibm_case_advance(s, ibm, &ref, &sf, t_end - 0.5, 4.0, tag));
    /* momentum balance over [0.4, 2.9] x [4.9, 7.1] (bow shock and near wake
     * inside), with its unsteady term over the last 0.5 */
    const Grid *g = gks_solver_grid(s);
    const int box[4] = {grid_axis_cell_of(&g->ax[0], 0.4), grid_axis_cell_of(&g->ax[0], 2.9),
                        grid_axis_cell_of(&g->ax[1], 4.9), grid_axis_cell_of(&g->ax[1], 7.1)};
    double m0, m1;
    ibm_case_box_force(s, box, inf.p, &m0);
    const double ta = gks_solver_time(s);
    assert_ok(ibm_case_advance(s, ibm, &ref, &sf, t_end, 4.0, tag));
    const double fbox = ibm_case_box_force(s, box, inf.p, &m1);
    const double dmdt = (m1 - m0) / (gks_solver_time(s) - ta);
    const IbmBodyForces *F = &sf.forces[0];
    *r = (Row){n,
               (long)g->nx * g->ny,
               (long)gks_solver_step_count(s),
               F->cd,
               F->cd_pressure,
               F->cd_viscous,
               F->cp_stagnation,
               1.5 - ibm_case_shock_x(s, 6.0, 2.0),
               nspd_wall_time() - t0,
               (fbox - dmdt) / (0.5 * inf.rho * inf.u * inf.u)};
    ibm_surface_free(&sf);
    ibm_destroy(&ibm);
    ibm_polyline_free(&wall);
    gks_solver_destroy(&s);
}

static void test_convergence(void **state) {
    (void)state;
    const double t_end = 16.0;
    Row r[3];
    const int n[3] = {16, 32, 64};
    for (int k = 0; k < 3; k++) run(n[k], t_end, &r[k]);
    const double pitot = ibm_cp_stagnation_pitot(IBM_GAMMA, 2.0);
    const double billig = 0.5 * ibm_billig_standoff_over_r(2.0);
    printf("\ncylinder Ma 2 Re 300, t = %.0f D/c (CFL 0.8, constant viscosity)\n", t_end);
    printf("| h | cells | steps | C_D | C_D,p | C_D,v | C_D box | Cp_stag / pitot - 1 | "
           "stand-off / D | s |\n|---|---|---|---|---|---|---|---|---|---|\n");
    for (int k = 0; k < 3; k++)
        printf("| D/%d | %ld | %ld | %.4f | %.4f | %.4f | %.4f | %+.4f | %.4f | %.0f |\n", r[k].n,
               r[k].cells, r[k].steps, r[k].cd, r[k].cdp, r[k].cdv, r[k].cd_box,
               r[k].cps / pitot - 1.0, r[k].standoff, r[k].seconds);
    const double d1 = r[1].cd - r[0].cd, d2 = r[2].cd - r[1].cd;
    const double order = d1 * d2 > 0.0 ? log(d1 / d2) / log(2.0) : (double)NAN;
    const double rich = isfinite(order) ? r[2].cd + d2 / (pow(2.0, order) - 1.0) : (double)NAN;
    printf("observed order %.2f, Richardson C_D %.4f; paper 1.556, references 1.547, 1.525; "
           "Billig stand-off %.4f D\n",
           order, rich, billig);
    /* D/64 surface C_D +1.0 % from the paper's 1.556; bound 2 % */
    assert_true(fabs(r[2].cd / 1.556 - 1.0) < 0.02);
    /* box drag +0.3 to +0.5 % on every grid; bound 1.5 % (the issue's) */
    for (int k = 0; k < 3; k++) assert_true(fabs(r[k].cd_box / 1.556 - 1.0) < 0.015);
    assert_true(fabs(d2) < fabs(d1)); /* converging */
    assert_true(fabs(r[2].cps / pitot - 1.0) < 0.01);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_convergence)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
