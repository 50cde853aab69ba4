/* ctest-labels: release
 * flow/iga/solver, ../shared/notes/iga_flow.md T4 and T5: Sod and Lax on a strip against
 * the notes' 1D prototype and the exact solution, with the closed tube's
 * mass and energy drift. Release build only: about 170 steps of 200
 * elements, a second here, half a minute under the sanitizers (the same
 * code runs there in test_solver.c). */
#include "iga_fixtures.h"
#include "test_support.h"

#include "core/status.h"
#include "flow/iga/solver.h"
#include "flow/riemann_exact.h"

#include <math.h>
#include <stdbool.h>

/* A shock tube on a strip of nx elements to t_end: L1 of the density
 * against the exact solution (20 samples an element along the middle
 * line). `fixed`: the ends' control values held (Lax's inflow), else
 * walls. */
static double tube(int nx, const IgaState *left, const IgaState *right, double t_end, bool fixed,
                   double totals0[4], double totals1[4]) {
    IgaConfig c = iga_fixture_strip(nx);
    c.initial = *right;
    if (fixed) c.side[0] = c.side[1] = IGA_SIDE_FIXED;
    Shape half = {.kind = SHAPE_RECTANGLE, .lo = {-1.0, -1.0}, .hi = {0.5, 1.0}};
    IgaRegion region = {.shapes = {.count = 1, .shapes = &half}, .state = *left};
    c.regions = &region;
    c.region_count = 1;
    IgaSolver *s;
    assert_ok(iga_solver_create(&s, &c, 0.0));
    iga_solver_totals(s, totals0);
    double t = 0.0;
    while (t < t_end - 1e-12) {
        const double dt = fmin(iga_solver_stable_dt(s), t_end - t);
        assert_ok(iga_solver_step(s, dt));
        t += dt;
    }
    iga_solver_totals(s, totals1);
    const RiemannState l = {left->p / left->T, left->u, left->p},
                       r = {right->p / right->T, right->u, right->p};
    RiemannSolution sol;
    assert_ok(riemann_exact_solve(&l, &r, 1.4, &sol));
    double l1 = 0.0;
    const int n = 20 * nx;
    for (int k = 0; k < n; k++) {
        const double x = (k + 0.5) / n;
        double Y[4];
        RiemannState e;
        iga_solver_eval(s, x, c.hi[1] / 2, Y);
        riemann_exact_sample(&sol, (x - 0.5) / t_end, &e);
        l1 += fabs(Y[0] / Y[3] - e.rho) / n;
    }
    iga_solver_destroy(&s);
    return l1;
}

/* T4: the strip is the notes' 1D discrete system (tensor product, v = 0;
 * nodal start, walls, Courant 0.3, DC 2.5 capped, 3 passes), except that
 * the cap's trace of G^-1 has two terms: the 1D prototype (iga1d.py) with
 * that cap gives L1(rho) = 1.35737e-2 at 100 elements (1.109e-2 with its
 * own), this solver 1.35742e-2. Asserted to 1e-3 (the DC makes the error
 * sensitive to round-off: 4e-5 measured). Uncapped (the code's; 3.01e-2 in
 * 1D) the strip is unstable: round-off in v grows from the diaphragm
 * (docs/VALIDATION.md). The closed tube keeps mass and energy to the
 * prototype's 1e-4 level (2e-4 asserted, notes T4). */
static void test_sod_strip(void **state) {
    (void)state;
    double t0[4], t1[4];
    const IgaState left = {1.0, 0.0, 0.0, 1.0}, right = {0.1, 0.0, 0.0, 0.8};
    const double l1 = tube(100, &left, &right, 0.2, false, t0, t1);
    print_message("iga Sod strip, 100 elements: L1(rho) %.4e, mass drift %.2e, energy drift "
                  "%.2e\n",
                  l1, (t1[0] - t0[0]) / t0[0], (t1[3] - t0[3]) / t0[3]);
    assert_close(l1, 1.35737e-2, 1e-3 * 1.35737e-2);
    assert_true(fabs(t1[0] - t0[0]) <= 2e-4 * t0[0]);
    assert_true(fabs(t1[3] - t0[3]) <= 2e-4 * t0[3]);
}

/* T5: Lax (rho, u, p = 0.445, 0.698, 3.528 | 0.5, 0, 0.571) to t = 0.14
 * with the ends' control values held, 100 elements, Courant 0.3: the 1D
 * prototype with the 2D cap gives L1(rho) = 3.84969e-2 (218 steps), this
 * strip 3.85270e-2, 7.8e-4 apart. The strip is not quite the 1D system:
 * its tau has the y metric's G_yy At_2^2 too, which the 1D one lacks (its
 * eigenvalues are +-c even where v = 0); the DC guard is not the cause
 * (the prototype with this one's relative guard gives the same 3.84969e-2).
 * Asserted to 2e-3. */
static void test_lax_strip(void **state) {
    (void)state;
    double t0[4], t1[4];
    const IgaState left = {3.528, 0.698, 0.0, 3.528 / 0.445},
                   right = {0.571, 0.0, 0.0, 0.571 / 0.5};
    const double l1 = tube(100, &left, &right, 0.14, true, t0, t1);
    print_message("iga Lax strip, 100 elements: L1(rho) %.5e\n", l1);
    assert_close(l1, 3.84969e-2, 2e-3 * 3.84969e-2);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sod_strip),
        cmocka_unit_test(test_lax_strip),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
