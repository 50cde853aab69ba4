/* The Sedov-Taylor blast of cases/sedov_quadrant.yaml (pressure ratio
 * 1.39e7) on both backgrounds at a coarse size: the quadrant 0.72 wide in
 * 30 x 30 cells or elements of 0.024, to t = 0.3, where the exact front is
 * at r_s = 0.5477 (src/flow/sedov.h; 23 cells out). Asserted: density and
 * pressure positive in every cell at every step (the isogeometric flow's
 * control points too: its step fails otherwise), the front (the outer
 * half-rise of the density between the ambient 1 and the ray's peak)
 * along the x axis and along the diagonal within the bounds below of the
 * exact radius and of each other, and, on the isogeometric flow, mass
 * and energy conserved to round-off (the limited scheme's totals are
 * sums of control values). The 200 x 200 numbers are in
 * docs/VALIDATION.md ("Sedov-Taylor blast"). */
#include "sim_fixtures.h"
#include "test_support.h"

#include "flow/sedov.h"

#include <math.h>
#include <stdio.h>

enum { N = 30 };
static const double H = 0.024, T_END = 0.3;

/* The outer half-rise of the density along cells (i0 + s di, j0 + s dj). */
static double front_along(Sim *sim, int di, int dj) {
    double rho[N], r[N], peak = 0.0;
    for (int s = 0; s < N; s++) {
        const double x = (s * di + 0.5) * H, y = (s * dj + 0.5) * H;
        double q[5];
        fixture_flow_state_at(sim, x, y, q);
        rho[s] = q[0], r[s] = hypot(x, y);
        peak = fmax(peak, rho[s]);
    }
    const double half = 0.5 * (1.0 + peak);
    for (int s = N - 1; s > 0; s--)
        if (rho[s - 1] >= half && rho[s] < half)
            return r[s - 1] + (r[s] - r[s - 1]) * (rho[s - 1] - half) / (rho[s - 1] - rho[s]);
    return NAN;
}

static void run_blast(const char *method, double tol_exact, double tol_rays) {
    char m[64];
    snprintf(m, sizeof m, "flow.method=%s", method);
    const char *sets[] = {m, "flow.grid.x.segments=[{length: 0.72, spacing: 0.024}]",
                          "flow.grid.y.segments=[{length: 0.72, spacing: 0.024}]", "time.end=0.3",
                          "output.probes=[]"};
    Sim sim;
    fixture_sim("sedov_quadrant.yaml", sets, 5, &sim);
    double t0[4];
    flow_totals(sim.flow, t0);
    double rho_min = INFINITY, p_min = INFINITY;
    int steps = 0;
    while (flow_time(sim.flow) < T_END - 1e-12) {
        assert_ok(sim_advance(&sim, 1));
        steps++;
        for (int j = 0; j < N; j++)
            for (int i = 0; i < N; i++) {
                double q[5];
                fixture_flow_state_at(&sim, (i + 0.5) * H, (j + 0.5) * H, q);
                rho_min = fmin(rho_min, q[0]), p_min = fmin(p_min, q[3]);
            }
        assert_true(rho_min > 0.0 && p_min > 0.0);
    }
    const double exact = sedov_front_radius(2, 1.4, 4.0 * (t0[3] - 1e-5 * 0.72 * 0.72 / 0.4), 1.0,
                                            flow_time(sim.flow));
    const double axis = front_along(&sim, 1, 0), diag = front_along(&sim, 1, 1);
    double t1[4];
    flow_totals(sim.flow, t1);
    print_message("%s: %d steps to t = %.4g; front %.4f (axis) %.4f (diagonal), exact %.4f: "
                  "%+.2f %%, %+.2f %%, rays %.2f %% apart; min rho %.3g, p %.3g; mass %+.1e, "
                  "energy %+.1e\n",
                  method, steps, flow_time(sim.flow), axis, diag, exact, 100 * (axis / exact - 1),
                  100 * (diag / exact - 1), 100 * fabs(axis - diag) / exact, rho_min, p_min,
                  t1[0] / t0[0] - 1, t1[3] / t0[3] - 1);
    assert_true(fabs(axis / exact - 1) <= tol_exact && fabs(diag / exact - 1) <= tol_exact);
    assert_true(fabs(axis - diag) / exact <= tol_rays);
    if (method[0] == 'i') {
        assert_true(fabs(t1[0] / t0[0] - 1) <= 1e-12);
        assert_true(fabs(t1[3] / t0[3] - 1) <= 1e-12);
    }
    sim_destroy(&sim);
}

static void test_iga(void **state) {
    (void)state;
    run_blast("iga", 0.05, 0.05);
}

static void test_gks(void **state) {
    (void)state;
    run_blast("gks", 0.05, 0.05);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_iga),
        cmocka_unit_test(test_gks),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
