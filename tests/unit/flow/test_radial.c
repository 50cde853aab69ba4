/* ctest-labels: release
 * The 1D radial reference solver (flow/radial.h): Sod's tube against the
 * exact solution with its L1 order; a gas at rest kept at rest and mass and
 * energy conserved to round-off in the cylinder and the sphere; the
 * Sedov-Taylor fronts of a line and a point blast against the exact radius
 * (flow/sedov.h: an independent check of the geometric terms); and the
 * strong shocks of pressure ratio 1e4 (cases/strong_shock_*.yaml) converging
 * to a fine solution of their own at the order measured below. */
#include "test_support.h"

#include "core/status.h"
#include "flow/radial.h"
#include "flow/riemann_exact.h"
#include "flow/sedov.h"

#include <math.h>
#include <stdio.h>

static const RadialState STRONG_CHARGE = {1, 0, 1}, STRONG_AMBIENT = {1, 0, 1e-4};

static void solve(int nu, long cells, double length, double r0, const RadialState *charge,
                  const RadialState *ambient, double t, RadialSolver *s) {
    const RadialConfig cfg = {
        .nu = nu, .gamma = 1.4, .length = length, .cells = cells, .outer_wall = true, .cfl = 0.4};
    assert_ok(radial_create(&cfg, ambient, s));
    radial_set_charge(s, r0, charge, ambient);
    assert_ok(radial_advance(s, t));
}

/* sum V |rho_c - <rho_f>| / sum V, the fine solution averaged over each
 * coarse cell (the fine grid refines the coarse one by an integer ratio) */
static double l1_density(const RadialSolver *c, const RadialSolver *f) {
    const long ratio = f->cfg.cells / c->cfg.cells;
    double err = 0, vol = 0;
    for (long i = 0; i < c->cfg.cells; i++) {
        double m = 0, v = 0;
        for (long k = i * ratio; k < (i + 1) * ratio; k++)
            m += f->volume[k] * f->rho[k], v += f->volume[k];
        err += c->volume[i] * fabs(c->rho[i] - m / v);
        vol += c->volume[i];
    }
    return err / vol;
}

static void test_sod_order(void **state) {
    (void)state;
    const RadialState left = {1, 0, 1}, right = {0.125, 0, 0.1};
    const RiemannState l = {1, 0, 1}, r = {0.125, 0, 0.1};
    RiemannSolution exact;
    assert_ok(riemann_exact_solve(&l, &r, 1.4, &exact));
    double e[4];
    for (int k = 0; k < 4; k++) {
        RadialSolver s;
        solve(1, 100L << k, 1.0, 0.5, &left, &right, 0.2, &s);
        double err = 0;
        const double h = 1.0 / (double)s.cfg.cells;
        for (long i = 0; i < s.cfg.cells; i++) {
            double q[3];
            riemann_exact_average(&exact, 0.5, 0.2, (double)i * h, (double)(i + 1) * h, 64, q);
            err += h * fabs(s.rho[i] - q[0]);
        }
        e[k] = err;
        radial_free(&s);
    }
    printf("Sod L1(rho) on 100..800 cells: %.3e %.3e %.3e %.3e, orders %.2f %.2f %.2f\n", e[0],
           e[1], e[2], e[3], log2(e[0] / e[1]), log2(e[1] / e[2]), log2(e[2] / e[3]));
    /* measured 1.225e-3 at 800 cells, orders 0.77 0.86 0.87 (a first-order
     * shock and contact in a second-order scheme); 10 % above them */
    assert_true(e[3] < 1.35e-3);
    for (int k = 0; k < 3; k++) assert_true(log2(e[k] / e[k + 1]) > 0.7);
}

static void test_rest_and_conservation(void **state) {
    (void)state;
    for (int nu = 2; nu <= 3; nu++) {
        RadialSolver s;
        const RadialState rest = {1.3, 0, 2.5};
        solve(nu, 200, 1.0, 0.0, &rest, &rest, 1.0, &s);
        double umax = 0, dp = 0;
        for (long i = 0; i < s.cfg.cells; i++) {
            const RadialState w = radial_state(&s, i);
            umax = fmax(umax, fabs(w.u)), dp = fmax(dp, fabs(w.p / 2.5 - 1));
        }
        printf("nu %d at rest after %ld steps: |u| %.2e, |dp|/p %.2e\n", nu, s.steps, umax, dp);
        /* measured 7e-16: the source p (A+ - A-) cancels the flux difference
         * to round-off (a source at the cell centre instead leaves O(h)) */
        assert_true(umax < 1e-14 && dp < 1e-14);
        radial_free(&s);

        const RadialConfig cfg = {
            .nu = nu, .gamma = 1.4, .length = 1.0, .cells = 400, .outer_wall = true, .cfl = 0.4};
        assert_ok(radial_create(&cfg, &STRONG_AMBIENT, &s));
        radial_set_charge(&s, 0.25, &STRONG_CHARGE, &STRONG_AMBIENT);
        double m0, e0, m1, e1;
        radial_totals(&s, &m0, &e0);
        assert_ok(radial_advance(&s, 3.0)); /* the shock reflected from the outer wall */
        radial_totals(&s, &m1, &e1);
        printf("nu %d strong shock to t = 3 (%ld steps): mass %.2e, energy %.2e relative\n", nu,
               s.steps, fabs(m1 / m0 - 1), fabs(e1 / e0 - 1));
        /* measured 1e-15: sums of 400 terms over a few thousand steps */
        assert_true(fabs(m1 / m0 - 1) < 1e-13 && fabs(e1 / e0 - 1) < 1e-13);
        radial_free(&s);
    }
}

/* the outer half-rise of the density between the ambient 1 and the peak */
static double front(const RadialSolver *s) {
    double peak = 0;
    for (long i = 0; i < s->cfg.cells; i++) peak = fmax(peak, s->rho[i]);
    const double half = 0.5 * (1 + peak), h = s->cfg.length / (double)s->cfg.cells;
    for (long i = s->cfg.cells - 1; i > 0; i--)
        if (s->rho[i - 1] >= half && s->rho[i] < half)
            return h * ((double)i - 0.5 + (s->rho[i - 1] - half) / (s->rho[i - 1] - s->rho[i]));
    return NAN;
}

static void test_sedov_fronts(void **state) {
    (void)state;
    for (int nu = 2; nu <= 3; nu++) {
        /* the energy that puts the exact front at r_s(1) = 1 (rho0 = 1), in a
         * charge of 10 cells: E per radian^(nu-1) = p / (gamma - 1) V(r0) */
        const double whole = pow(sedov_front_constant(nu, 1.4), -(nu + 2.0));
        const double per_radian = whole / (nu == 2 ? 2 * M_PI : 4 * M_PI);
        const double r0 = 0.024, p = per_radian * 0.4 * nu / pow(r0, nu);
        const RadialState charge = {1, 0, p}, ambient = {1, 0, 1e-6 * p};
        RadialSolver s;
        solve(nu, 500, 1.2, r0, &charge, &ambient, 1.0, &s);
        printf("Sedov nu %d, pressure ratio 1e6: front %.5f against 1 (%+.3f %%), %ld steps\n", nu,
               front(&s), 100 * (front(&s) - 1), s.steps);
        /* measured +0.30 % (line) and +1.20 % (point, whose shell is
         * thinner: +0.11 % on 2000 cells) */
        assert_true(fabs(front(&s) - 1) < (nu == 2 ? 0.004 : 0.015));
        radial_free(&s);
    }
}

static void test_strong_shock_orders(void **state) {
    (void)state;
    for (int nu = 2; nu <= 3; nu++) {
        RadialSolver fine;
        solve(nu, 1600, 1.5, 0.25, &STRONG_CHARGE, &STRONG_AMBIENT, 0.5, &fine);
        double e[4];
        for (int k = 0; k < 4; k++) {
            RadialSolver s;
            solve(nu, 50L << k, 1.5, 0.25, &STRONG_CHARGE, &STRONG_AMBIENT, 0.5, &s);
            e[k] = l1_density(&s, &fine);
            radial_free(&s);
        }
        printf("nu %d strong 1e4 L1(rho) on 50..400 vs 1600: %.3e %.3e %.3e %.3e, orders %.2f %.2f "
               "%.2f\n",
               nu, e[0], e[1], e[2], e[3], log2(e[0] / e[1]), log2(e[1] / e[2]), log2(e[2] / e[3]));
        /* measured: cylinder 2.07e-2 at 400, orders 0.36 0.46 1.01; sphere
         * 8.00e-3, 0.48 0.67 0.88 (the inward shock and the contact
         * resolved only from 200 cells on); 10 % above them */
        assert_true(e[3] < (nu == 2 ? 2.3e-2 : 8.8e-3));
        assert_true(log2(e[2] / e[3]) > (nu == 2 ? 0.9 : 0.8));
        for (int k = 0; k < 3; k++) assert_true(e[k + 1] < e[k]);
        radial_free(&fine);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sod_order),
        cmocka_unit_test(test_rest_and_conservation),
        cmocka_unit_test(test_sedov_fronts),
        cmocka_unit_test(test_strong_shock_orders),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
