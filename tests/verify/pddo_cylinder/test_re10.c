/* ctest-labels: slow
 * The confined cylinder of paper 002 Sec. 5.3 at Re 10 (notes/pddo.md 2.3,
 * V15), coarse: L_x 15 m, L_y 6 m, D 1 m at (5, 3), rho 1, mu 1, uniform
 * inlet u0 = 10 m/s (Eqs. 63, 70, 71), no-slip walls (Eq. 67), outlet p = 0
 * (Eq. 66), the cylinder on a polar patch (u = 0, dp/dr = 0: Eqs. 68, 69;
 * r_patch 1.5 m, dtheta = dx / r_patch, dr = 0.69 dx, three fictitious
 * rings), run by pddo_step from rest to t = 4 s (the paper's end time) with
 * the paper's zero wall ghosts and with antisymmetric ones. Compared with
 * the paper's values (its misprints read as the notes say: probes at
 * y = 3 +- 1.2, the outlet value on the axis, Re a number): front pressure
 * 220 Pa, side pressure -37 Pa, |u| 16.9 m/s at (5, 3 +- 1.2), 13.81 m/s at
 * the outlet on the axis; drag (the paper prints none at Re 10). Pressures
 * are relative to the outlet; front = the wall node at theta = pi, side =
 * (5, 3.5), both on the wall ring; the fluid-side traction (flow/pddo/forces.h).
 *
 * Measured (one core shared with other work; dx 0.1: 11,486 nodes, K_L
 * 348,150 nonzeros, setup 0.4 s, 9 ms per step; dx 0.05: 42,220 nodes,
 * 2.6 s, 32-42 ms per step; every run steady, max |du/dt| < 1e-8 m/s^2 at
 * t = 4 s, lift < 1e-12 N/m):
 *   ghosts  dx    dt     p front  p side  |u|(5,4.2) |u|(15,3) drag (pressure + viscous) N/m
 *   zero    0.1   5e-3   186.3      4.6   15.97      13.43     379.8 (152.8 + 227.0)
 *   zero    0.1   2e-3   200.7    -14.9   16.20      13.47     365.5 (158.9 + 206.6)
 *   zero    0.1   1e-3   210.0    -25.3   16.27      13.47     360.4 (162.8 + 197.6)
 *   zero    0.1   5e-4   219.5    -33.9   16.30      13.47     359.1 (167.4 + 191.7)
 *   zero    0.05  1e-3   207.6    -22.6   16.52      13.60     387.7 (159.7 + 228.0)
 *   anti    0.1   2e-3   246.7    -50.7   16.65      13.40     307.6 (190.7 + 116.9)
 *   anti    0.1   1e-3   276.4    -71.1   16.68      13.42     321.7 (212.2 + 109.5)
 *   anti    0.1   5e-4   322.1    -98.8
 *   anti    0.05  1e-3   230.9    -40.5   16.69      13.54     299.5 (174.4 + 125.0)
 *   paper (dx 0.03, dt 1e-4)  220  -37   16.9       13.81
 * The speeds are within 1.2-3.7 % of the paper's. The wall pressures are
 * NOT converged in dt: at dx 0.1 the front pressure rises by ~9.4 Pa per
 * halving of dt with zero ghosts and by 30-46 Pa with antisymmetric ones,
 * so zero ghosts' 219.5 Pa at dt 5e-4 matching the paper is not evidence.
 * The cause is the wall ring's own PPE row: its velocity is prescribed, so
 * its discrete divergence (O(dx) for the one-sided kink of the wall) is
 * never fed back by Eq. 8, and (rho/dt) div u there drives a pressure
 * spike at the wall ring that grows as dt falls (the ray theta = pi, dt
 * 1e-3: antisymmetric 276.4 on the wall, 206.1, 187.0 on the next rings;
 * zero 210.0, 202.1, 185.7). Dropping that term on prescribed nodes (an
 * experiment, not kept) turns the spike into a dip (171 vs 201 Pa next
 * ring) at Re 10; it is now flow.divergence_term: updated
 * (test_divergence_term.c). With it, dx 0.05, antisymmetric ghosts, dt
 * 1e-3 (PCYL_DIV=1): front 208.65 Pa (rays f0 .. f2: 208.6, 219.2, 208.3),
 * drag 292.6 N/m (159.4 + 133.2) against icoFoam's 288.8 (169.8 + 119.0);
 * zero ghosts 192.9 Pa, 384.7 N/m (149.4 + 235.3). On the paper's lattice
 * (dx 0.03, `nspd run cases/cylinder_confined_re10.yaml` with antisymmetric
 * ghosts, updated, dt 1e-3): front 212.4 Pa, side -29.0 Pa, 16.57 and
 * 13.47 m/s, drag 292.2 N/m (160.7 + 131.5). The body's fictitious
 * pressures from the momentum equation's dp/dn = -mu d(omega)/ds alone
 * (an experiment of 2026-12-04) removed the dip (rays 223.6, 213.2, 190.6
 * at dx 0.1) but left the drag's dependence on tau (dx 0.05, dt 4e-4: 274.6
 * and 283.6 N/m at tau 1.6e-3 and 4e-4 s); with the PPE source's prescribed
 * nodes taking G p as well it became flow.wall_pressure: momentum
 * (PCYL_MOMENTUM=1; step.h, docs/VALIDATION.md's grid study). The
 * viscous drag differs by a factor 1.8 between the two ghost treatments
 * (zero: first order at walls, notes V6). Stability (notes 1.5 left the
 * patch unmeasured): at dx 0.1 dt 1e-2 is stable (nu dt / dx^2 = 1.0; on
 * the wall ring nu dt / (R dtheta)^2 = 9) and 1.4e-2 is not, blowing up
 * first at the inlet corner (0.1, 0.1) m, on the lattice: the patch's
 * closer nodes do not set the limit (its spectrum is set by delta). The
 * steady state at dt 1e-2 has front 169.8 Pa, drag 397.9 N/m, in line
 * with the dt trend above. The default runs both at dx 0.1,
 * dt 1e-3 (about 40 s each) as a regression; PCYL_DX, PCYL_DT, PCYL_T,
 * PCYL_RP, PCYL_ANTI (0 or 1: one treatment only), PCYL_DIV (1: the
 * divergence term on the updated rows only), PCYL_TAU (flow.divergence_time),
 * PCYL_MOMENTUM (1: flow.wall_pressure momentum) make studies. */
#include "test_support.h"

#include "core/timer.h"
#include "flow/pddo/cloud.h"
#include "flow/pddo/forces.h"
#include "flow/pddo/operators.h"
#include "flow/pddo/polar.h"
#include "flow/pddo/ppe.h"
#include "flow/pddo/step.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>

/* f at (x, y) from the nearest node k by f_k + grad f_k . (x - x_k): second
 * order, the gradient the PDDO one. */
static double probe(const PddoCloud *c, const PddoOps *ops, const double *f, double x, double y,
                    double *dist) {
    int64_t best = 0;
    double bd = INFINITY;
    for (int64_t k = 0; k < c->n; k++) {
        if (c->kind[k] == PDDO_NODE_GHOST || c->kind[k] == PDDO_NODE_BODY) continue;
        const double d = hypot(c->x[k] - x, c->y[k] - y);
        if (d < bd) bd = d, best = k;
    }
    *dist = bd;
    return f[best] + pddo_ops_at(ops, PDDO_D_X, f, best) * (x - c->x[best]) +
           pddo_ops_at(ops, PDDO_D_Y, f, best) * (y - c->y[best]);
}

static double env_or(const char *name, double fallback) {
    const char *s = getenv(name);
    return s ? atof(s) : fallback;
}

/* One run with the paper's (anti = 0) or antisymmetric wall ghosts;
 * PCYL_DX, PCYL_DT, PCYL_T, PCYL_RP override the resolution, step, end
 * time and patch radius for studies (the asserts then do not apply). */
static void run(int anti, bool study) {
    const double dx = env_or("PCYL_DX", 0.1), r_patch = env_or("PCYL_RP", 1.5);
    const double u0 = 10.0, rho = 1.0, mu = 1.0;
    const double dt = env_or("PCYL_DT", 1e-3), t_end = env_or("PCYL_T", 4.0);
    static const PddoHole hole = {.x = 5.0, .y = 3.0, .radius = 0.5};
    /* the paper's dr = 0.69 dx; dtheta such that r dtheta = dx at r_patch
     * (the paper's rule, 0.0149 rad at dx = 0.03) */
    const PddoPolarSpec polar = {.dtheta = dx / r_patch, .r_patch = r_patch};
    PddoCloudSpec s = {.lo = {0.0, 0.0},
                       .hi = {15.0, 6.0},
                       .dx = dx,
                       .layers = 3,
                       .horizon_factor = 3.0,
                       .holes = &hole,
                       .nholes = 1,
                       .polar = &polar};
    s.side[PDDO_LEFT] = PDDO_SIDE_INLET;
    s.side[PDDO_RIGHT] = PDDO_SIDE_OUTLET;
    s.side[PDDO_BOTTOM] = s.side[PDDO_TOP] = PDDO_SIDE_WALL;
    PddoCloud c = {0};
    PddoOps ops = {0};
    PddoPpe ppe = {0};
    PddoStep st = {0};
    PddoForces forces = {0};
    const double t0 = nspd_wall_time();
    assert_ok(pddo_cloud_build(&c, &s));
    assert_ok(pddo_ops_build(&ops, c.n, c.x, c.y, c.area, c.first, c.nbr, c.delta, c.node_delta,
                             &(PddoLattice){c.i, c.j, c.dx, c.patch, c.npatches}));
    assert_ok(pddo_ppe_build(&ppe, &c, &ops));
    assert_ok(pddo_forces_build(&forces, &c, 0));
    const PddoStepParams par = {
        .rho = rho,
        .mu = mu,
        .dt = dt,
        .inlet_u = u0,
        .walls = anti ? PDDO_WALL_ANTISYMMETRIC : PDDO_WALL_ZERO,
        .divergence =
            env_or("PCYL_DIV", 0.0) != 0.0 ? PDDO_DIVERGENCE_UPDATED : PDDO_DIVERGENCE_ALL_ROWS,
        .divergence_time = env_or("PCYL_TAU", 0.0),
        .wall_pressure = env_or("PCYL_MOMENTUM", 0.0) != 0.0 ? PDDO_WALL_PRESSURE_MOMENTUM
                                                             : PDDO_WALL_PRESSURE_ZERO_GRADIENT};
    assert_ok(pddo_step_init(&st, &c, &ops, &ppe, &par));
    const double setup_s = nspd_wall_time() - t0;
    const PddoPolarPatch *p = &c.patch[0];
    printf("cloud: dx %.3f m, %d x %d rings (dtheta %.4f, dr %.4f, r_out %.3f m), %lld nodes, "
           "%lld family members; K_L %lld nonzeros, L+U %.3g; setup %.2f s\n",
           dx, p->rings, p->ntheta, p->dtheta, p->dr, p->r_out, (long long)c.n,
           (long long)c.first[c.n], (long long)ppe.nnz, ppe.factor_nnz, setup_s);
    const int steps = (int)lround(t_end / dt);
    const int64_t front = p->first + (int64_t)p->rings_inside * p->ntheta + p->ntheta / 2;
    const double t1 = nspd_wall_time();
    PddoForce F = {0};
    for (int i = 1; i <= steps; i++) {
        assert_ok(pddo_step_advance(&st));
        if (i % (steps / 20) == 0 || i == steps) {
            F = pddo_forces_eval(&forces, PDDO_TRACTION_FLUID_SIDE, NULL, st.u, st.v, st.p, mu);
            printf("t %.3f s: max |du/dt| %.3e m/s^2, p front %.2f Pa, drag %.3f N/m (pressure "
                   "%.3f, viscous %.3f), lift %.2e\n",
                   st.time, st.dudt_max, st.p[front], F.fx, F.fx_pressure, F.fx_viscous, F.fy);
        }
    }
    const double run_s = nspd_wall_time() - t1;
    double d1, d2, d3, d4, d5, d6;
    const double p_front = probe(&c, &ops, st.p, 4.5, 3.0, &d1);
    const double p_side = probe(&c, &ops, st.p, 5.0, 3.5, &d2);
    double *speed = malloc((size_t)c.n * sizeof(double));
    for (int64_t k = 0; k < c.n; k++) speed[k] = hypot(st.u[k], st.v[k]);
    const double s_top = probe(&c, &ops, speed, 5.0, 4.2, &d3);
    const double s_bot = probe(&c, &ops, speed, 5.0, 1.8, &d4);
    const double s_out = probe(&c, &ops, speed, 15.0, 3.0, &d5);
    const double p_back = probe(&c, &ops, st.p, 5.5, 3.0, &d6);
    /* the lowest pressure on the line x = 5 between the cylinder and the
     * top wall (the paper's "beside the cylinder (line x = 5)") */
    double p_line = INFINITY, y_line = 0.0, dl;
    for (int i = 0; i <= 50; i++) {
        const double y = 3.5 + 0.05 * i, pl = probe(&c, &ops, st.p, 5.0, y, &dl);
        if (pl < p_line) p_line = pl, y_line = y;
    }
    const PddoForce Fp =
        pddo_forces_eval(&forces, PDDO_TRACTION_FULL_FAMILY, &ops, st.u, st.v, st.p, mu);
    printf("Re 10, dx %.3f, dt %.1e, %s wall ghosts, t %.2f s (%d steps, %.2f s, %.2f ms/step):\n"
           "  p front (4.5, 3)  %8.2f Pa  (paper 220)\n"
           "  p side  (5, 3.5)  %8.2f Pa  (paper -37)\n"
           "  p back  (5.5, 3)  %8.2f Pa  (paper ~0)\n"
           "  p lowest on x = 5 %8.2f Pa at y = %.2f m\n"
           "  |u| (5, 4.2)      %8.3f m/s (paper 16.9)\n"
           "  |u| (5, 1.8)      %8.3f m/s (paper 16.9)\n"
           "  |u| (15, 3)       %8.3f m/s (paper 13.81)\n"
           "  drag %.3f N/m (pressure %.3f, viscous %.3f), C_D %.4f; lift %.2e N/m\n"
           "  the paper's literal Eq. 20 traction: drag %.3f N/m (viscous %.3f)\n"
           "  probes' nearest nodes within %.3f m\n",
           dx, dt, anti ? "antisymmetric" : "zero", st.time, steps, run_s, 1e3 * run_s / steps,
           p_front, p_side, p_back, p_line, y_line, s_top, s_bot, s_out, F.fx, F.fx_pressure,
           F.fx_viscous, F.fx / (0.5 * rho * u0 * u0), F.fy, Fp.fx, Fp.fx_viscous,
           fmax(fmax(fmax(d1, d2), fmax(d3, d4)), fmax(d5, d6)));
    /* the measured runs of the header, dx 0.1 */
    if (!study) {
        /* the measured runs of the header (dx 0.1, dt 1e-3), as a
         * regression: the pressures to 2 %, the speeds to 0.5 %, the drag
         * to 1 % (round-off and thread count move them by far less; a
         * change of the scheme moves them by more, see the dt study) */
        static const double want[2][6] = {
            /* p front, p side, |u| (5, 4.2), |u| (15, 3), drag, pressure drag */
            {210.04, -25.25, 16.269, 13.471, 360.444, 162.801},
            {276.36, -71.07, 16.682, 13.417, 321.716, 212.201},
        };
        const double *e = want[anti];
        assert_true(st.dudt_max < 1e-6);        /* steady: 2.0e-9 and 1.6e-10 m/s^2 */
        assert_true(fabs(F.fy) < 1e-12 * F.fx); /* symmetric: lift ~1e-13 N/m */
        assert_true(fabs(p_front / e[0] - 1.0) < 0.02 && fabs(p_side / e[1] - 1.0) < 0.02);
        assert_true(fabs(s_top / e[2] - 1.0) < 5e-3 && fabs(s_out / e[3] - 1.0) < 5e-3);
        assert_true(fabs(s_bot / s_top - 1.0) < 5e-3); /* the probes' nearest nodes differ */
        assert_true(fabs(F.fx / e[4] - 1.0) < 0.01 && fabs(F.fx_pressure / e[5] - 1.0) < 0.01);
    }
    /* the pressure along the stagnation ray (theta = pi) from the wall out,
     * and around the wall ring there: a boundary layer in p shows here */
    printf("  p on the ray theta = pi, rings f0 .. f7:");
    for (int q = p->rings_inside; q < p->rings_inside + 8; q++)
        printf(" %.1f", st.p[p->first + (int64_t)q * p->ntheta + p->ntheta / 2]);
    printf(" Pa\n  div u on the ray theta = pi, rings f1 .. f4:");
    for (int q = p->rings_inside + 1; q < p->rings_inside + 5; q++) {
        const int64_t k = p->first + (int64_t)q * p->ntheta + p->ntheta / 2;
        printf(" %.3f",
               pddo_ops_at(&ops, PDDO_D_X, st.u, k) + pddo_ops_at(&ops, PDDO_D_Y, st.v, k));
    }
    printf(" 1/s\n  p on the wall ring, t = ntheta/2 - 3 .. + 3:");
    for (int t = -3; t <= 3; t++) printf(" %.1f", st.p[front + t]);
    printf(" Pa\n");
    free(speed);
    pddo_forces_free(&forces);
    pddo_step_free(&st);
    pddo_ppe_free(&ppe);
    pddo_ops_free(&ops);
    pddo_cloud_free(&c);
}

static void test_re10(void **state) {
    (void)state;
    const bool study = getenv("PCYL_DX") || getenv("PCYL_DT") || getenv("PCYL_T") ||
                       getenv("PCYL_RP") || getenv("PCYL_DIV") || getenv("PCYL_MOMENTUM") ||
                       getenv("PCYL_TAU");
    const char *only = getenv("PCYL_ANTI"); /* "0" or "1": one treatment only */
    for (int anti = 0; anti < 2; anti++)
        if (!only || atoi(only) == anti) run(anti, study);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_re10)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
