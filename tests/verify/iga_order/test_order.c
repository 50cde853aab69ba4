/* ctest-labels: slow
 * The isogeometric flow's order of accuracy (../shared/notes/iga_flow.md
 * T8): an entropy wave rho = 1 + 0.2 sin 2 pi x, u = 1, p = 1 (R = 1,
 * gamma = 1.4) on the periodic unit square, n x 3 quadratic elements, one
 * period, DC off, the L2 projection for the start and the consistent
 * starting rate. The notes' 1D prototype gives L2(rho) = 5.88e-4,
 * 1.38e-5, 9.05e-7 at 16/32/64 elements and Courant 0.05 (order >= 3.5 in
 * space), 7.50e-4 / 7.43e-5 / 1.70e-5 at Courant 0.3 (about 2: the time
 * error). About a minute (make validate). */
#include "test_support.h"

#include "flow/iga/solver.h"
#include "flow/vortex.h"

#include <math.h>

static void wave(void *ctx, double x, double y, double out[4]) {
    (void)ctx, (void)y;
    const double rho = 1.0 + 0.2 * sin(2.0 * M_PI * x);
    out[0] = 1.0, out[1] = 1.0, out[2] = 0.0, out[3] = 1.0 / rho;
}

/* L2 of rho^h - rho over the square, 5 x 5 Gauss points an element */
static double run(int n, double cfl) {
    IgaConfig c = {
        .lo = {0.0, 0.0},
        .hi = {1.0, 3.0 / n},
        .elements = {n, 3},
        .degree = 2,
        .side = {IGA_SIDE_PERIODIC, IGA_SIDE_PERIODIC, IGA_SIDE_PERIODIC, IGA_SIDE_PERIODIC},
        .gamma = 1.4,
        .R = 1.0,
        .prandtl = 1.0,
        .init = IGA_INIT_L2,
        .init_fn = wave,
        .ydot0 = IGA_YDOT0_CONSISTENT,
        .c_dc = 0.0,
        .passes = 3,
        .rho_inf = 0.5,
        .db_iterations = 10,
        .cfl = cfl};
    IgaSolver *s;
    assert_ok(iga_solver_create(&s, &c, 0.0));
    double t = 0.0;
    while (t < 1.0 - 1e-12) {
        const double dt = fmin(iga_solver_stable_dt(s), 1.0 - t);
        assert_ok(iga_solver_step(s, dt));
        t += dt;
    }
    static const double gx[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                                 0.9061798459386640},
                        gw[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                 0.4786286704993665, 0.2369268850561891};
    double e2 = 0.0;
    const double h = 1.0 / n;
    for (int i = 0; i < n; i++)
        for (int a = 0; a < 5; a++)
            for (int j = 0; j < 3; j++)
                for (int b = 0; b < 5; b++) {
                    const double x = (i + 0.5 + 0.5 * gx[a]) * h, y = (j + 0.5 + 0.5 * gx[b]) * h;
                    double Y[4];
                    iga_solver_eval(s, x, y, Y);
                    const double d = Y[0] / Y[3] - (1.0 + 0.2 * sin(2.0 * M_PI * (x - 1.0)));
                    e2 += 0.25 * h * h * gw[a] * gw[b] * d * d;
                }
    iga_solver_destroy(&s);
    return sqrt(e2 / c.hi[1]); /* per unit height, as the 1D norm */
}

static void test_entropy_wave_order(void **state) {
    (void)state;
    for (int k = 0; k < 2; k++) {
        const double cfl = k == 0 ? 0.05 : 0.3;
        double e[3];
        for (int m = 0; m < 3; m++) e[m] = run(16 << m, cfl);
        const double o1 = log2(e[0] / e[1]), o2 = log2(e[1] / e[2]);
        print_message("iga entropy wave, Courant %.2f: L2(rho) %.3e %.3e %.3e (16/32/64), orders "
                      "%.2f %.2f\n",
                      cfl, e[0], e[1], e[2], o1, o2);
        if (k == 0)
            assert_true(o1 >= 3.5 && o2 >= 3.5);
        else
            assert_true(o2 >= 1.8);
    }
}

/* T9: the isentropic vortex of cases/vortex.yaml (strength 5, free
 * stream rho = p = 1 moving at (1, 1), R = 1, the periodic box [0, 10]^2),
 * n x n elements, to t = VORTEX_T; L2(rho) against the translated exact
 * vortex, 4 x 4 Gauss points an element, per unit area. */
enum { VORTEX_T = 1 };

static FlowVortex vortex_at(double t) {
    return (FlowVortex){.x0 = 5.0 + t,
                        .y0 = 5.0 + t,
                        .strength = 5.0,
                        .gamma = 1.4,
                        .rho_inf = 1.0,
                        .u_inf = 1.0,
                        .v_inf = 1.0,
                        .p_inf = 1.0,
                        .period_x = 10.0,
                        .period_y = 10.0};
}

static void vortex_control(void *ctx, double x, double y, double out[4]) {
    double q[4];
    flow_vortex_state(ctx, x, y, q);
    out[0] = q[3], out[1] = q[1], out[2] = q[2], out[3] = q[3] / q[0];
}

static double run_vortex(int n, double cfl, double c_dc) {
    FlowVortex v0 = vortex_at(0.0);
    IgaConfig c = {
        .lo = {0.0, 0.0},
        .hi = {10.0, 10.0},
        .elements = {n, n},
        .degree = 2,
        .side = {IGA_SIDE_PERIODIC, IGA_SIDE_PERIODIC, IGA_SIDE_PERIODIC, IGA_SIDE_PERIODIC},
        .gamma = 1.4,
        .R = 1.0,
        .prandtl = 1.0,
        .init = IGA_INIT_L2,
        .init_fn = vortex_control,
        .init_ctx = &v0,
        .ydot0 = IGA_YDOT0_CONSISTENT,
        .c_dc = c_dc,
        .dc_cap = true,
        .passes = 3,
        .rho_inf = 0.5,
        .db_iterations = 10,
        .cfl = cfl};
    IgaSolver *s;
    assert_ok(iga_solver_create(&s, &c, 0.0));
    double t = 0.0;
    while (t < VORTEX_T - 1e-12) {
        const double dt = fmin(iga_solver_stable_dt(s), VORTEX_T - t);
        assert_ok(iga_solver_step(s, dt));
        t += dt;
    }
    static const double gx[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                 0.8611363115940526},
                        gw[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                 0.3478548451374538};
    FlowVortex v1 = vortex_at(VORTEX_T);
    double e2 = 0.0;
    const double h = 10.0 / n;
    for (int j = 0; j < n; j++)
        for (int b = 0; b < 4; b++)
            for (int i = 0; i < n; i++)
                for (int a = 0; a < 4; a++) {
                    const double x = (i + 0.5 + 0.5 * gx[a]) * h, y = (j + 0.5 + 0.5 * gx[b]) * h;
                    double Y[4], q[4];
                    iga_solver_eval(s, x, y, Y);
                    flow_vortex_state(&v1, x, y, q);
                    const double d = Y[0] / Y[3] - q[0];
                    e2 += 0.25 * h * h * gw[a] * gw[b] * d * d;
                }
    iga_solver_destroy(&s);
    return sqrt(e2 / 100.0);
}

static void test_vortex_order(void **state) {
    (void)state;
    for (int k = 0; k < 2; k++) {
        const double c_dc = k == 0 ? 0.0 : 2.5;
        double e[3];
        for (int m = 0; m < 3; m++) e[m] = run_vortex(16 << m, 0.05, c_dc);
        const double o1 = log2(e[0] / e[1]), o2 = log2(e[1] / e[2]);
        print_message("iga vortex, DC %.1f, Courant 0.05, t = %d: L2(rho) %.3e %.3e %.3e "
                      "(16/32/64), orders %.2f %.2f\n",
                      c_dc, VORTEX_T, e[0], e[1], e[2], o1, o2);
        if (k == 0) assert_true(o2 >= 2.8);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_entropy_wave_order),
        cmocka_unit_test(test_vortex_order),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
