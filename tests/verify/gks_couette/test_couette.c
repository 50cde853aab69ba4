/* Compressible Couette flow with viscous heating between isothermal walls.
 *
 * Walls at y = 0 (at rest) and y = H (moving at U), both at T_w; constant mu
 * and kappa = c_p mu / Pr; steady, uniform pressure. Exact solution:
 *     u = U y/H,   T = T_w + Pr U^2 / (2 c_p) (y/H)(1 - y/H).
 * The heating amplitude Pr U^2/(8 c_p) is set by the Prandtl number: without
 * the Prandtl fix (BGK, Pr = 1) it would be 1/0.72 = 1.39 times larger, so the
 * temperature check tests the fix. R = 1, gamma = 1.4, U = 1 (wall Mach 0.85),
 * Re = rho U H / mu = 20, 32 cells across (4 along, periodic). */
#include "test_support.h"

#include "core/timer.h"
#include "flow/gks/solver.h"

#include <math.h>
#include <stdio.h>

static void test_couette_with_heating(void **state) {
    (void)state;
    const double H = 1.0, U = 1.0, Tw = 1.0, mu = 0.05, pr = 0.72, gamma = 1.4, R = 1.0;
    const double cp = gamma * R / (gamma - 1.0), amp = pr * U * U / (8.0 * cp);
    const int ny = 32;
    GksConfig c;
    gks_config_default(&c);
    c.gamma = gamma;
    c.gas_constant = R;
    c.viscosity = VISCOSITY_CONSTANT;
    c.mu_ref = mu;
    c.prandtl = pr;
    gks_config_uniform_grid(&c, 0.0, 4.0 * H / ny, 4, 0.0, H, ny);
    const FlowBc per = {.kind = BC_PERIODIC};
    const FlowBc lo = {.kind = BC_NOSLIP_ISOTHERMAL, .wall_temperature = Tw};
    const FlowBc hi = {.kind = BC_NOSLIP_ISOTHERMAL, .wall_temperature = Tw, .wall_velocity = U};
    gks_config_set_bc(&c, FLOW_FACE_XLO, &per);
    gks_config_set_bc(&c, FLOW_FACE_XHI, &per);
    gks_config_set_bc(&c, FLOW_FACE_YLO, &lo);
    gks_config_set_bc(&c, FLOW_FACE_YHI, &hi);
    c.initial = (FlowPrim){1.0, 0.0, 0.0, 1.0}; /* at rest: the test includes the start-up */
    GksSolver *s = NULL;
    assert_ok(gks_solver_create(&s, &c));
    const double t0 = nspd_wall_time();
    /* thermal diffusivity mu/(rho Pr) = 0.069: e-folding time H^2/(pi^2 0.069) = 1.5 */
    assert_ok(gks_solver_advance(s, 30.0, 0));
    const Grid *g = gks_solver_grid(s);
    double u[4 * 32], T[4 * 32];
    gks_solver_primitive(s, FLOW_VELOCITY_X, u);
    gks_solver_primitive(s, FLOW_TEMPERATURE, T);
    double eu = 0.0, eT = 0.0, mid = 0.0;
    for (int j = 0; j < ny; j++) {
        const double y = g->ax[1].center[j] / H;
        const double ue = U * y, Te = Tw + 4.0 * amp * y * (1.0 - y);
        eu = fmax(eu, fabs(u[j * 4] - ue) / U);
        eT = fmax(eT, fabs(T[j * 4] - Te) / amp);
        if (j == ny / 2) mid = (T[j * 4] - Tw) / (Te - Tw);
    }
    printf("couette: max |u - U y/H|/U = %.3e, max |T - T_exact|/amplitude = %.3e, "
           "heating at mid-channel / exact = %.4f (%lld steps, %.2f s)\n",
           eu, eT, mid, (long long)gks_solver_step_count(s), nspd_wall_time() - t0);
    /* Measured: velocity 8.4e-5, temperature 1.00e-2 of the amplitude at 32
     * cells (2.4e-4 and 2.9e-2 at 16 cells: order ~1.3-1.4, the limiter clips
     * the temperature maximum at mid-channel). Bounds: measured + ~35 %. A
     * missing Prandtl fix would give a temperature error of 0.39. */
    assert_true(eu < 1.4e-4);
    assert_true(eT < 1.45e-2);
    gks_solver_destroy(&s);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_couette_with_heating)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
