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
#include "vortex_fixtures.h"

#include <math.h>

/* A periodic box [0, w] x [0, h] of nx x ny quadratic elements started from
 * init_fn (p, u, v, T; R = 1, gamma = 1.4) by the L2 projection with the
 * consistent starting rate, the capped DC at c_dc (0: off), 3 passes. */
static IgaConfig periodic_box(double w, double h, int nx, int ny,
                              void (*init_fn)(void *, double, double, double[4]), void *ctx,
                              double c_dc, double cfl) {
    return (IgaConfig){
        .lo = {0.0, 0.0},
        .hi = {w, h},
        .elements = {nx, ny},
        .degree = 2,
        .side = {IGA_SIDE_PERIODIC, IGA_SIDE_PERIODIC, IGA_SIDE_PERIODIC, IGA_SIDE_PERIODIC},
        .gamma = 1.4,
        .R = 1.0,
        .prandtl = 1.0,
        .init = IGA_INIT_L2,
        .init_fn = init_fn,
        .init_ctx = ctx,
        .ydot0 = IGA_YDOT0_CONSISTENT,
        .c_dc = c_dc,
        .dc_cap = true,
        .passes = 3,
        .rho_inf = 0.5,
        .db_iterations = 10,
        .cfl = cfl};
}

/* Builds the solver of c and steps it to t_end at its stable step. */
static IgaSolver *run_to(const IgaConfig *c, double t_end) {
    IgaSolver *s;
    assert_ok(iga_solver_create(&s, c, 0.0));
    double t = 0.0;
    while (t < t_end - 1e-12) {
        const double dt = fmin(iga_solver_stable_dt(s), t_end - t);
        assert_ok(iga_solver_step(s, dt));
        t += dt;
    }
    return s;
}

/* A Gauss rule on [-1, 1]. */
typedef struct {
    int n;
    double x[5], w[5];
} Gauss;

static const Gauss GAUSS4 = {
    4,
    {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526},
    {0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538}};
static const Gauss GAUSS5 = {
    5,
    {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831, 0.9061798459386640},
    {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
     0.2369268850561891}};

/* L2 of rho^h - rho(x, y) over the solver's rectangle per unit area, the
 * rule's points in each element; frees the solver. */
static double l2_rho_error(IgaSolver *s, const Gauss *g, double (*rho)(void *, double, double),
                           void *ctx) {
    const IgaConfig *c = iga_solver_config(s);
    const int nx = c->elements[0], ny = c->elements[1];
    const double hx = (c->hi[0] - c->lo[0]) / nx, hy = (c->hi[1] - c->lo[1]) / ny;
    double e2 = 0.0;
    for (int j = 0; j < ny; j++)
        for (int b = 0; b < g->n; b++)
            for (int i = 0; i < nx; i++)
                for (int a = 0; a < g->n; a++) {
                    const double x = c->lo[0] + (i + 0.5 + 0.5 * g->x[a]) * hx,
                                 y = c->lo[1] + (j + 0.5 + 0.5 * g->x[b]) * hy;
                    double Y[4];
                    iga_solver_eval(s, x, y, Y);
                    const double d = Y[0] / Y[3] - rho(ctx, x, y);
                    e2 += 0.25 * hx * hy * g->w[a] * g->w[b] * d * d;
                }
    const double area = (c->hi[0] - c->lo[0]) * (c->hi[1] - c->lo[1]);
    iga_solver_destroy(&s);
    return sqrt(e2 / area);
}

static void wave(void *ctx, double x, double y, double out[4]) {
    (void)ctx, (void)y;
    const double rho = 1.0 + 0.2 * sin(2.0 * M_PI * x);
    out[0] = 1.0, out[1] = 1.0, out[2] = 0.0, out[3] = 1.0 / rho;
}

/* the wave after one period: where it started */
static double wave_rho(void *ctx, double x, double y) {
    (void)ctx, (void)y;
    return 1.0 + 0.2 * sin(2.0 * M_PI * (x - 1.0));
}

/* L2 of rho^h - rho over the n x 3 strip per unit height, 5 x 5 Gauss
 * points an element */
static double run(int n, double cfl) {
    const IgaConfig c = periodic_box(1.0, 3.0 / n, n, 3, wave, NULL, 0.0, cfl);
    return l2_rho_error(run_to(&c, 1.0), &GAUSS5, wave_rho, NULL);
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
 * stream rho = p = 1 moving at (1, 1), R = 1, the periodic box [0, 10]^2,
 * started at (5, 5)), n x n elements, to t = VORTEX_T; L2(rho) against the
 * translated exact vortex, 4 x 4 Gauss points an element, per unit area. */
enum { VORTEX_T = 1 };

static void vortex_control(void *ctx, double x, double y, double out[4]) {
    double q[4];
    flow_vortex_state(ctx, x, y, q);
    out[0] = q[3], out[1] = q[1], out[2] = q[2], out[3] = q[3] / q[0];
}

static double vortex_rho(void *ctx, double x, double y) {
    double q[4];
    flow_vortex_state(ctx, x, y, q);
    return q[0];
}

static double run_vortex(int n, double cfl, double c_dc) {
    FlowVortex v0 = vortex_fixture_at(5.0, 0.0), v1 = vortex_fixture_at(5.0, VORTEX_T);
    const IgaConfig c = periodic_box(10.0, 10.0, n, n, vortex_control, &v0, c_dc, cfl);
    return l2_rho_error(run_to(&c, VORTEX_T), &GAUSS4, vortex_rho, &v1);
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

/* The limited step (flow.iga.limiter: convex, docs/IGA_LIMITER.md) on the
 * same smooth flows at Courant 0.3: how much of the Galerkin step's order
 * the relaxed bounds keep (issue 57: "it must keep the scheme's order on
 * smooth flow"). */
static void test_limited_order(void **state) {
    (void)state;
    double e[2][4];
    for (int m = 0; m < 4; m++) {
        /* 5 elements across: the limiter's periodic stencil needs 2 p + 1 */
        IgaConfig c = periodic_box(1.0, 5.0 / (16 << m), 16 << m, 5, wave, NULL, 0.0, 0.3);
        c.limiter = IGA_LIMITER_CONVEX;
        e[0][m] = l2_rho_error(run_to(&c, 1.0), &GAUSS5, wave_rho, NULL);
        FlowVortex v0 = vortex_fixture_at(5.0, 0.0), v1 = vortex_fixture_at(5.0, VORTEX_T);
        IgaConfig cv = periodic_box(10.0, 10.0, 16 << m, 16 << m, vortex_control, &v0, 0.0, 0.3);
        cv.limiter = IGA_LIMITER_CONVEX;
        e[1][m] = l2_rho_error(run_to(&cv, VORTEX_T), &GAUSS4, vortex_rho, &v1);
    }
    double o[2][3];
    for (int k = 0; k < 2; k++) {
        for (int m = 0; m < 3; m++) o[k][m] = log2(e[k][m] / e[k][m + 1]);
        print_message("iga limited %s, Courant 0.3: L2(rho) %.3e %.3e %.3e %.3e (16..128), orders "
                      "%.2f %.2f %.2f\n",
                      k == 0 ? "entropy wave" : "vortex", e[k][0], e[k][1], e[k][2], e[k][3],
                      o[k][0], o[k][1], o[k][2]);
    }
    /* Measured (2026-12-07): the wave 1.25e-2, 2.53e-4, 5.99e-5, 1.49e-5,
     * orders 5.63 2.08 2.01 - the Galerkin step's own 2 at Courant 0.3 (its
     * time error, T8 above: 7.43e-5 / 1.70e-5 at 32 / 64), 3.5 times its
     * error: on 16 elements the bounds clip the wave's extrema, from 32 on
     * they relax. The vortex 1.89e-2, 7.93e-3, 2.88e-3, 9.89e-4, orders
     * 1.26 1.46 1.54: the bounds still clip the vortex's smooth density
     * minimum on 128 x 128 (the known price of local bounds at a smooth
     * extremum, docs/IGA_LIMITER.md), the order rising with the mesh. The
     * bounds: the wave's last two orders >= 1.9, the vortex's last >= 1.4
     * and rising (0.1 below each measured value). */
    assert_true(o[0][1] >= 1.9 && o[0][2] >= 1.9);
    assert_true(o[1][2] >= 1.4 && o[1][2] > o[1][0]);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_entropy_wave_order),
        cmocka_unit_test(test_vortex_order),
        cmocka_unit_test(test_limited_order),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
