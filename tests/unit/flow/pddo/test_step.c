/* flow/pddo/step: the explicit PDDO step of paper 002 (Eqs. 7, 8, 33, 34)
 * on the Taylor-Green vortex in a periodic box (notes/pddo.md V5):
 *     u = -cos kx sin ky e^(-2 nu k^2 t),  v = sin kx cos ky e^(-2 nu k^2 t)
 * an exact Navier-Stokes solution whose pressure balances u.grad u, so the
 * decay rate measures the PDDO Laplacian at wavenumber k and the velocity
 * error the whole scheme (convection, Eq. 33's PPE, the periodic PPE's
 * null space); the lid-driven cavity at Re 1 against the notes' prototype
 * (its dt-dependent divergence, V9); the diffusion stability limit (V4);
 * the wall shear (V7) and steady Poiseuille flow (V6) with the paper's and
 * the antisymmetric wall ghosts; the same bits on 1 and 2 threads. */
#include "test_support.h"

#include "core/timer.h"
#include "flow/pddo/cloud.h"
#include "flow/pddo/operators.h"
#include "flow/pddo/ppe.h"
#include "flow/pddo/step.h"

#include <math.h>
#include <omp.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    double rate_ratio, error, div_rms, step_s;
    int64_t nodes;
    double *state; /* u, v, p after the run, if asked for (3 n) */
} TgResult;

/* N x N periodic box of side 1, k = 2 pi, nu = 0.01, amplitude U, run to
 * t_end. */
static TgResult taylor_green(int n, double amplitude, double dt, double t_end, bool keep) {
    const double k = 2.0 * M_PI, nu = 0.01;
    PddoCloudSpec s = {
        .lo = {0.0, 0.0}, .hi = {1.0, 1.0}, .dx = 1.0 / n, .layers = 3, .horizon_factor = 3.0};
    for (int side = 0; side < PDDO_SIDES; side++) s.side[side] = PDDO_SIDE_PERIODIC;
    PddoCloud c = {0};
    PddoOps ops = {0};
    PddoPpe ppe = {0};
    PddoStep st = {0};
    assert_ok(pddo_cloud_build(&c, &s));
    assert_ok(pddo_ops_build(&ops, c.n, c.x, c.y, c.area, c.first, c.nbr, c.delta, c.node_delta,
                             &(PddoLattice){c.i, c.j, c.dx, c.patch, c.npatches}));
    assert_ok(pddo_ppe_build(&ppe, &c, &ops));
    const PddoStepParams par = {.rho = 1.0, .mu = nu, .dt = dt};
    assert_ok(pddo_step_init(&st, &c, &ops, &ppe, &par));
    for (int64_t m = 0; m < c.n; m++) {
        st.u[m] = -amplitude * cos(k * c.x[m]) * sin(k * c.y[m]);
        st.v[m] = amplitude * sin(k * c.x[m]) * cos(k * c.y[m]);
    }
    pddo_step_apply_bc(&st);
    const int steps = (int)lround(t_end / dt);
    const double t0 = nspd_wall_time();
    for (int i = 0; i < steps; i++) assert_ok(pddo_step_advance(&st));
    TgResult r = {.nodes = c.n, .step_s = (nspd_wall_time() - t0) / steps};
    /* amplitude: projection on the initial mode over the N^2 unknowns */
    const double decay = exp(-2.0 * nu * k * k * st.time);
    double num = 0.0, den = 0.0, err = 0.0, div2 = 0.0;
    int64_t count = 0;
    for (int64_t m = 0; m < c.n; m++) {
        if (st.rule[m] != PDDO_VEL_FREE) continue;
        const double su = -amplitude * cos(k * c.x[m]) * sin(k * c.y[m]);
        const double sv = amplitude * sin(k * c.x[m]) * cos(k * c.y[m]);
        num += st.u[m] * su + st.v[m] * sv;
        den += su * su + sv * sv;
        err = fmax(err, fmax(fabs(st.u[m] - su * decay), fabs(st.v[m] - sv * decay)));
        const double d =
            pddo_ops_at(&ops, PDDO_D_X, st.u, m) + pddo_ops_at(&ops, PDDO_D_Y, st.v, m);
        div2 += d * d;
        count++;
    }
    assert_int_equal(count, (int64_t)n * n);
    r.rate_ratio = -log(num / den) / st.time / (2.0 * nu * k * k);
    r.error = err / (amplitude * decay);
    r.div_rms = sqrt(div2 / (double)count) / (amplitude * k); /* in units of U k */
    if (keep) {
        r.state = malloc(3 * (size_t)c.n * sizeof(double));
        memcpy(r.state, st.u, (size_t)c.n * sizeof(double));
        memcpy(r.state + c.n, st.v, (size_t)c.n * sizeof(double));
        memcpy(r.state + 2 * c.n, st.p, (size_t)c.n * sizeof(double));
    }
    pddo_step_free(&st);
    pddo_ppe_free(&ppe);
    pddo_ops_free(&ops);
    pddo_cloud_free(&c);
    return r;
}

/* dt = 1e-3 (nu dt / dx^2 <= 0.041, U^2 dt / nu <= 0.1: far inside the
 * limits of notes 1.5; forward Euler's own rate error is sigma dt / 2 =
 * 4e-4), t = 0.1 (the amplitude falls to 0.92).
 *
 * Linear regime (U = 1e-3, convection negligible): the decay rate is the
 * PDDO Laplacian's symbol at (k, k). Measured PDDO / exact 0.90682,
 * 0.97609 for N = 16, 32: the notes' prototype values 0.9065, 0.9757 plus
 * 3.2e-4, 3.9e-4, forward Euler's sigma dt / 2; asserted to 1e-3. (N = 64
 * gives 0.99426 vs 0.9939, left out for time.)
 *
 * Nonlinear (U = 1, Re = U / (k nu) = 16): measured 0.9140, 0.9782,
 * 0.9948 for N = 16, 32, 64, slower by 7.5e-3, 2.5e-3, 9e-4 than the
 * symbol: the discrete pressure removes only the part DG/L of the gradient
 * u.grad u at 2k (about 0.7 at N = 16, notes 1.2), and the rest feeds a 2k
 * mode that returns energy to k. That excess falls at second order: the
 * rate error 1 - ratio has orders 1.98, 2.07, asserted >= 1.8, and each
 * ratio is asserted within 1e-2 of the symbol. Velocity errors (max over
 * the nodes, relative to the amplitude) 7.57e-3, 1.90e-3, 4.56e-4: orders
 * 2.00, 2.06, asserted >= 1.8 (V5). */
static void test_taylor_green(void **state) {
    (void)state;
    const int ns[3] = {16, 32, 64};
    const double notes[3] = {0.9065, 0.9757, 0.9939};
    TgResult lin[3], r[3];
    for (int i = 0; i < 3; i++) {
        lin[i] = i < 2 ? taylor_green(ns[i], 1e-3, 1e-3, 0.1, false) : (TgResult){0};
        r[i] = taylor_green(ns[i], 1.0, 1e-3, 0.1, false);
        printf("Taylor-Green N = %d: %lld nodes, %.2f ms/step; decay rate / exact: linear %.5f "
               "(notes %.4f; 0: not run), U = 1 %.5f; max velocity error %.3e, rms div u %.3e "
               "U k\n",
               ns[i], (long long)r[i].nodes, 1e3 * r[i].step_s, lin[i].rate_ratio, notes[i],
               r[i].rate_ratio, r[i].error, r[i].div_rms);
    }
    for (int i = 0; i < 3; i++) {
        if (i < 2) assert_close(lin[i].rate_ratio, notes[i], 1e-3);
        assert_close(r[i].rate_ratio, notes[i], 1e-2);
    }
    for (int i = 0; i < 2; i++) {
        const double order = log2(r[i].error / r[i + 1].error);
        const double rate = log2((1.0 - r[i].rate_ratio) / (1.0 - r[i + 1].rate_ratio));
        printf("orders %d -> %d: velocity error %.3f, decay-rate error %.3f\n", ns[i], ns[i + 1],
               order, rate);
        assert_true(order >= 1.8);
        assert_true(rate >= 1.8);
    }
}

/* The lid-driven cavity at Re 1 (paper 002 Sec. 5.1 case 1: L = 1 mm,
 * U = 1 mm/s, rho = 1000, mu = 1e-3; the paper's lid and no-slip
 * conditions with zero fictitious velocities, corners at rest), N = 50, to
 * t = 0.1 s (0.1 L / U; max du/dt has fallen to 5e-2 U^2/L, and the
 * divergence numbers below agree to 4 digits with t = 0.5 s, du/dt 7e-11
 * U^2/L: the divergence settles long before the flow). The
 * velocity is not discretely divergence-free and its steady divergence
 * depends on dt (notes 1.5, V9). Measured rms div u over the fluid nodes
 * 0.2644 (dt = 4e-4 s, nu dt / dx^2 = 1) and 0.1754 (dt = 2e-4 s) U/L, max
 * 7.06 at a lid corner: the notes' prototype gives 0.264, 0.175 and "max
 * 7"; asserted to 2e-3 (their rounding plus margin) and [6.5, 7.5]. The
 * vertical centreline's minimum u, -0.208 U at y = 0.54 L (t = 0.5 s), is printed
 * only (no independent Stokes-cavity reference is checked in). */
static double cavity_re1(double dt, double *div_max) {
    const double L = 1e-3, U = 1e-3;
    const int n = 50;
    PddoCloudSpec s = {
        .lo = {0.0, 0.0}, .hi = {L, L}, .dx = L / n, .layers = 3, .horizon_factor = 3.0};
    PddoCloud c = {0};
    PddoOps ops = {0};
    PddoPpe ppe = {0};
    PddoStep st = {0};
    assert_ok(pddo_cloud_build(&c, &s));
    assert_ok(pddo_ops_build(&ops, c.n, c.x, c.y, c.area, c.first, c.nbr, c.delta, c.node_delta,
                             &(PddoLattice){c.i, c.j, c.dx, c.patch, c.npatches}));
    assert_ok(pddo_ppe_build(&ppe, &c, &ops));
    PddoStepParams par = {.rho = 1000.0, .mu = 1e-3, .dt = dt};
    par.wall_u[PDDO_TOP] = U;
    assert_ok(pddo_step_init(&st, &c, &ops, &ppe, &par));
    /* the lid's corners are at rest, its other nodes and layers move */
    assert_close(st.u[pddo_cloud_node(&c, 0, n)], 0.0, 0.0);
    assert_close(st.u[pddo_cloud_node(&c, 1, n + 3)], U, 0.0);
    assert_close(st.u[pddo_cloud_node(&c, -1, n + 1)], 0.0, 0.0);
    const int steps = (int)lround(0.1 / dt);
    for (int i = 0; i < steps; i++) assert_ok(pddo_step_advance(&st));
    double sum = 0.0, umin = 0.0, ymin = 0.0;
    int64_t count = 0;
    *div_max = 0.0;
    for (int64_t k = 0; k < c.n; k++) {
        if (c.kind[k] != PDDO_NODE_FLUID) continue;
        const double d =
            (pddo_ops_at(&ops, PDDO_D_X, st.u, k) + pddo_ops_at(&ops, PDDO_D_Y, st.v, k)) * L / U;
        sum += d * d;
        count++;
        *div_max = fmax(*div_max, fabs(d));
    }
    for (int j = 0; j <= n; j++) {
        const int64_t k = pddo_cloud_node(&c, n / 2, j);
        if (st.u[k] < umin) umin = st.u[k], ymin = c.y[k];
    }
    printf("cavity Re 1, N = 50, dt = %g s: %lld nodes; max du/dt %.2e U^2/L; centreline min u "
           "%.4f U at y = %.3f L\n",
           dt, (long long)c.n, st.dudt_max * L / (U * U), umin / U, ymin / L);
    pddo_step_free(&st);
    pddo_ppe_free(&ppe);
    pddo_ops_free(&ops);
    pddo_cloud_free(&c);
    return sqrt(sum / (double)count);
}

static void test_cavity_re1_divergence(void **state) {
    (void)state;
    double max4, max2;
    const double rms4 = cavity_re1(4e-4, &max4), rms2 = cavity_re1(2e-4, &max2);
    printf("cavity Re 1: rms div u %.4f (dt 4e-4), %.4f (dt 2e-4) U/L; max %.3f, %.3f\n", rms4,
           rms2, max4, max2);
    assert_close(rms4, 0.264, 2e-3);
    assert_close(rms2, 0.175, 2e-3);
    assert_true(max4 > 6.5 && max4 < 7.5);
}

/* A deterministic pseudo-random number in [-1, 1]. */
static double uniform(uint64_t *s) {
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) / (double)(1ULL << 53) * 2.0 - 1.0;
}

/* max |u|, |v| after `steps` steps from a random field of amplitude 1e-6
 * (convection negligible: the linear diffusion-projection step) in a
 * 16 x 16 periodic box, nu = 1, at the given nu dt / dx^2; relative to the
 * start. Stops early once past 1e6. */
static double diffusion_growth(double number, int steps, int *taken) {
    const int n = 16;
    PddoCloudSpec s = {
        .lo = {0.0, 0.0}, .hi = {1.0, 1.0}, .dx = 1.0 / n, .layers = 3, .horizon_factor = 3.0};
    for (int side = 0; side < PDDO_SIDES; side++) s.side[side] = PDDO_SIDE_PERIODIC;
    PddoCloud c = {0};
    PddoOps ops = {0};
    PddoPpe ppe = {0};
    PddoStep st = {0};
    assert_ok(pddo_cloud_build(&c, &s));
    assert_ok(pddo_ops_build(&ops, c.n, c.x, c.y, c.area, c.first, c.nbr, c.delta, c.node_delta,
                             &(PddoLattice){c.i, c.j, c.dx, c.patch, c.npatches}));
    assert_ok(pddo_ppe_build(&ppe, &c, &ops));
    const PddoStepParams par = {.rho = 1.0, .mu = 1.0, .dt = number * s.dx * s.dx};
    assert_ok(pddo_step_init(&st, &c, &ops, &ppe, &par));
    uint64_t seed = 5;
    for (int64_t m = 0; m < c.n; m++)
        st.u[m] = 1e-6 * uniform(&seed), st.v[m] = 1e-6 * uniform(&seed);
    pddo_step_apply_bc(&st);
    double start = 0.0, now = 0.0;
    for (int64_t m = 0; m < c.n; m++) start = fmax(start, fmax(fabs(st.u[m]), fabs(st.v[m])));
    *taken = 0;
    for (int i = 0; i < steps && now <= 1e6 * start; i++, ++*taken) {
        assert_ok(pddo_step_advance(&st));
        now = 0.0;
        for (int64_t m = 0; m < c.n; m++) now = fmax(now, fmax(fabs(st.u[m]), fabs(st.v[m])));
    }
    pddo_step_free(&st);
    pddo_ppe_free(&ppe);
    pddo_ops_free(&ops);
    pddo_cloud_free(&c);
    return now / start;
}

/* V4, diffusion: the PDDO Laplacian's symbol reaches -1.2401 / dx^2 (notes
 * 1.2), so forward Euler is stable up to nu dt / dx^2 = 2 / 1.2401 = 1.613,
 * five times the 5-point limit; the pressure projection only removes
 * (never amplifies) a mode's gradient part. Measured over 300 steps: the
 * random field's maximum falls to 0.028 at 1.55 and 1.60, grows 20 times
 * at 1.63, and passes 1e6 after 159 steps at 1.70 (the worst mode's factor
 * |1 - 1.70 x 1.2401| = 1.108 per step). Asserted: < 1 at 1.55 and 1.60,
 * > 2 at 1.63, > 1e6 at 1.70: the limit is bracketed to 2 %. */
static void test_diffusion_stability_limit(void **state) {
    (void)state;
    int n_below, n_above, n1, n2;
    const double below = diffusion_growth(1.55, 300, &n_below);
    const double above = diffusion_growth(1.70, 300, &n_above);
    const double b2 = diffusion_growth(1.60, 300, &n1), a2 = diffusion_growth(1.63, 300, &n2);
    printf("diffusion limit: max |u| x %.3g after %d steps at nu dt/dx^2 = 1.55, x %.3g after %d "
           "at 1.70; %.3g (%d) at 1.60, %.3g (%d) at 1.63\n",
           below, n_below, above, n_above, b2, n1, a2, n2);
    assert_true(below < 1.0 && b2 < 1.0);
    assert_true(a2 > 2.0 && above > 1e6);
}

/* A channel of height 1 between walls at rest at y = 0 and 1 (nodes on
 * them), periodic in x over 4 spacings, N intervals across. */
static void channel(PddoCloud *c, PddoOps *ops, PddoPpe *ppe, int n) {
    PddoCloudSpec s = {
        .lo = {0.0, 0.0}, .hi = {4.0 / n, 1.0}, .dx = 1.0 / n, .layers = 3, .horizon_factor = 3.0};
    s.side[PDDO_LEFT] = s.side[PDDO_RIGHT] = PDDO_SIDE_PERIODIC;
    assert_ok(pddo_cloud_build(c, &s));
    assert_ok(pddo_ops_build(ops, c->n, c->x, c->y, c->area, c->first, c->nbr, c->delta,
                             c->node_delta,
                             &(PddoLattice){c->i, c->j, c->dx, c->patch, c->npatches}));
    assert_ok(pddo_ppe_build(ppe, c, ops));
}

/* V7: the linear shear u = y next to the wall y = 0. The PDDO du/dy at the
 * wall's nodes is exactly 0.5 with the paper's zero fictitious velocities
 * (the family sees u = 0 on one side, notes 1.6: the drag of Eqs. 74-75
 * would lose half its shear) and 1 with antisymmetric ones (the field is
 * then linear through the wall, which the operator reproduces). Measured
 * off by 2.2e-16 and 3.3e-16; asserted 1e-12. */
static void test_wall_shear(void **state) {
    (void)state;
    for (int t = 0; t < 2; t++) {
        PddoCloud c = {0};
        PddoOps ops = {0};
        PddoPpe ppe = {0};
        PddoStep st = {0};
        channel(&c, &ops, &ppe, 10);
        const PddoStepParams par = {.rho = 1.0, .mu = 1.0, .dt = 1e-3, .walls = (PddoWallGhosts)t};
        assert_ok(pddo_step_init(&st, &c, &ops, &ppe, &par));
        for (int64_t k = 0; k < c.n; k++) st.u[k] = c.y[k];
        pddo_step_apply_bc(&st);
        double worst = 0.0;
        for (int i = 0; i < 4; i++) {
            const double g = pddo_ops_at(&ops, PDDO_D_Y, st.u, pddo_cloud_node(&c, i, 0));
            worst = fmax(worst, fabs(g - (t == 0 ? 0.5 : 1.0)));
        }
        printf("wall shear of u = y, %s ghosts: off by %.1e\n", t ? "antisymmetric" : "zero",
               worst);
        assert_true(worst < 1e-12);
        pddo_step_free(&st);
        pddo_ppe_free(&ppe);
        pddo_ops_free(&ops);
        pddo_cloud_free(&c);
    }
}

/* Steady Poiseuille flow driven by a body force g = 8 (nu = 1, u_max = 1),
 * dt half the diffusion limit, run until max du/dt < 1e-9 g; the largest
 * error over the nodes relative to u_max. */
static double poiseuille(int n, PddoWallGhosts walls, int64_t *steps) {
    PddoCloud c = {0};
    PddoOps ops = {0};
    PddoPpe ppe = {0};
    PddoStep st = {0};
    channel(&c, &ops, &ppe, n);
    const double dx = 1.0 / n;
    const PddoStepParams par = {.rho = 1.0,
                                .mu = 1.0,
                                .dt = pddo_step_stable_dt(1.0, dx, 0.0),
                                .walls = walls,
                                .force_x = 8.0};
    assert_ok(pddo_step_init(&st, &c, &ops, &ppe, &par));
    do assert_ok(pddo_step_advance(&st));
    while (st.dudt_max > 8e-9 && st.steps < 100000);
    double err = 0.0;
    for (int64_t k = 0; k < c.n; k++)
        if (c.kind[k] <= PDDO_NODE_SIDE)
            err = fmax(err, fabs(st.u[k] - 4.0 * c.y[k] * (1.0 - c.y[k])));
    *steps = st.steps;
    pddo_step_free(&st);
    pddo_ppe_free(&ppe);
    pddo_ops_free(&ops);
    pddo_cloud_free(&c);
    return err;
}

/* V6: steady Poiseuille flow, walls at nodes, N = 10, 20, 40 across, run
 * to max du/dt < 1e-9 g (265 to 4,367 steps). Measured max errors / u_max:
 * the paper's zero fictitious velocities 0.1584, 0.0752, 0.0366 (orders
 * 1.08, 1.04); antisymmetric ghosts 2.412e-2, 6.029e-3, 1.507e-3 (orders
 * 2.00, 2.00). The notes' prototype: 0.158, 0.075, 0.037 and 0.024,
 * 6.0e-3, 1.5e-3. Asserted: each within 2 % of the notes' value (their
 * three printed digits: the largest gap is 1.1 %, 0.0366 vs 0.037) and
 * the orders in [0.9, 1.2] and [1.9, 2.1]. */
static void test_poiseuille_wall_orders(void **state) {
    (void)state;
    const int ns[3] = {10, 20, 40};
    double e[2][3];
    for (int t = 0; t < 2; t++)
        for (int r = 0; r < 3; r++) {
            int64_t steps;
            e[t][r] = poiseuille(ns[r], (PddoWallGhosts)t, &steps);
            printf("Poiseuille N = %d, %s ghosts: max error %.4e u_max after %lld steps\n", ns[r],
                   t ? "antisymmetric" : "zero", e[t][r], (long long)steps);
        }
    const double notes[2][3] = {{0.158, 0.075, 0.037}, {0.024, 6.0e-3, 1.5e-3}};
    for (int t = 0; t < 2; t++) {
        const double o1 = log2(e[t][0] / e[t][1]), o2 = log2(e[t][1] / e[t][2]);
        printf("orders (%s): %.3f %.3f\n", t ? "antisymmetric" : "zero", o1, o2);
        for (int r = 0; r < 3; r++) assert_close(e[t][r] / notes[t][r], 1.0, 0.02);
        const double lo = t ? 1.9 : 0.9, hi = t ? 2.1 : 1.2;
        assert_true(o1 > lo && o1 < hi && o2 > lo && o2 < hi);
    }
}

/* The open channel of paper 002 Sec. 5.2 in nondimensional form and
 * coarse: H = 1, length 5 H, uniform inflow u0 = 1 (Eqs. 57, 61, 62),
 * walls at rest, zero-pressure outlet (Eqs. 50-52), Re = 56, N = 10
 * across (969 nodes), dt = pddo_step_stable_dt, t = 15 H / u0 (1,890 steps,
 * max du/dt falls to 3e-11 u0^2 / H). Returns the exit layer's max u / u0
 * and the ratio of its trapezoidal flux to the inlet's (the inlet's corner
 * nodes belong to the walls, notes #11, so the inflow is (1 - 1/N) u0 H). */
static double channel_flow(PddoWallGhosts walls, double *flux_ratio) {
    const int n = 10;
    const double nu = 1.0 / 56.0;
    PddoCloudSpec s = {
        .lo = {0.0, 0.0}, .hi = {5.0, 1.0}, .dx = 1.0 / n, .layers = 3, .horizon_factor = 3.0};
    s.side[PDDO_LEFT] = PDDO_SIDE_INLET;
    s.side[PDDO_RIGHT] = PDDO_SIDE_OUTLET;
    PddoCloud c = {0};
    PddoOps ops = {0};
    PddoPpe ppe = {0};
    PddoStep st = {0};
    assert_ok(pddo_cloud_build(&c, &s));
    assert_ok(pddo_ops_build(&ops, c.n, c.x, c.y, c.area, c.first, c.nbr, c.delta, c.node_delta,
                             &(PddoLattice){c.i, c.j, c.dx, c.patch, c.npatches}));
    assert_ok(pddo_ppe_build(&ppe, &c, &ops));
    assert_int_equal(ppe.pinned, -1); /* the outlet fixes the level */
    const PddoStepParams par = {.rho = 1.0,
                                .mu = nu,
                                .dt = pddo_step_stable_dt(nu, s.dx, 1.5),
                                .inlet_u = 1.0,
                                .walls = walls};
    assert_ok(pddo_step_init(&st, &c, &ops, &ppe, &par));
    const int steps = (int)lround(15.0 / par.dt);
    for (int i = 0; i < steps; i++) assert_ok(pddo_step_advance(&st));
    assert_true(st.dudt_max < 1e-9);
    double umax = 0.0, in = 0.0, out = 0.0;
    for (int j = 0; j <= n; j++) {
        const double w = j == 0 || j == n ? 0.5 : 1.0;
        const int64_t e = pddo_cloud_node(&c, c.nx, j), i0 = pddo_cloud_node(&c, 0, j);
        umax = fmax(umax, st.u[e]);
        out += w * st.u[e] * s.dx, in += w * st.u[i0] * s.dx;
        assert_close(st.p[e], 0.0, 0.0); /* the exit layer's p = 0 */
    }
    *flux_ratio = out / in;
    printf("channel Re 56, N = 10, %s wall ghosts: exit max u %.4f u0, inflow %.4f u0 H, "
           "outflow / inflow %.4f, max du/dt %.1e\n",
           walls ? "antisymmetric" : "zero", umax, in, *flux_ratio, st.dudt_max);
    pddo_step_free(&st);
    pddo_ppe_free(&ppe);
    pddo_ops_free(&ops);
    pddo_cloud_free(&c);
    return umax;
}

/* Inlet, outlet and their corners in the time loop (V10, V14, coarse).
 * Zero wall ghosts: the exit layer carries the inflow to 2e-4 (measured
 * 1.0002; asserted 1e-3) and its max u is 1.302 u0 (asserted 1.30 +- 0.01);
 * finer, 1.393 (N = 20) and 1.444 (N = 40, 3.7 % below Poiseuille's 1.5:
 * the notes' prototype says 3.6 %), measured outside the suite for time.
 * Antisymmetric ghosts: the outflow is only 0.954 of the inflow (N = 10;
 * 0.965 at 20, 0.975 at 40, converging slowly): the scheme is not
 * conservative (notes V10), and with the reflected uniform inflow at the
 * inlet-wall corners it loses mass there: 0.028 of the 0.041 u0 H lost is
 * gone 0.5 H downstream, the rest along the entrance length (the flux at
 * mid-length equals the exit's to 1e-4). Recorded, asserted at
 * 0.954 +- 0.01 so that a change of the corner treatment shows here. */
static void test_channel_inlet_outlet(void **state) {
    (void)state;
    double zero_ratio, anti_ratio;
    const double zero_umax = channel_flow(PDDO_WALL_ZERO, &zero_ratio);
    channel_flow(PDDO_WALL_ANTISYMMETRIC, &anti_ratio);
    assert_close(zero_ratio, 1.0, 1e-3);
    assert_close(zero_umax, 1.30, 0.01);
    assert_close(anti_ratio, 0.954, 0.01);
}

/* V16: 5,041 nodes (above PARALLEL_MIN_ITEMS, so the loops do split),
 * 10 steps on 1 and on 2 threads: u, v and p are the same bits. */
static void test_threads_bitwise(void **state) {
    (void)state;
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    TgResult one = taylor_green(64, 1.0, 1e-3, 0.01, true);
    omp_set_num_threads(2);
    TgResult two = taylor_green(64, 1.0, 1e-3, 0.01, true);
    omp_set_num_threads(threads);
    assert_int_equal(one.nodes, two.nodes);
    assert_memory_equal(one.state, two.state, 3 * (size_t)one.nodes * sizeof(double));
    free(one.state);
    free(two.state);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_taylor_green),
        cmocka_unit_test(test_diffusion_stability_limit),
        cmocka_unit_test(test_wall_shear),
        cmocka_unit_test(test_poiseuille_wall_orders),
        cmocka_unit_test(test_channel_inlet_outlet),
        cmocka_unit_test(test_cavity_re1_divergence),
        cmocka_unit_test(test_threads_bitwise),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
