/* Maxwellian moments, micro slopes and the vectorisable math of the GKS
 * kernel, each against numerical quadrature or libm. */
#include "test_support.h"

#include "flow/gks/flux_kernel.h"

#include <math.h>

static const double K = 3.0; /* gamma = 1.4 */

/* (lambda/pi)^(1/2) \int_lo^hi u^n exp(-lambda (u - U)^2) du, composite Simpson. */
static double quad_u(int n, double U, double lam, double lo, double hi) {
    const int N = 40000;
    const double h = (hi - lo) / N;
    double s = 0.0;
    for (int k = 0; k <= N; k++) {
        const double u = lo + k * h, w = (k == 0 || k == N) ? 1.0 : (k % 2 ? 4.0 : 2.0);
        s += w * pow(u, n) * exp(-lam * (u - U) * (u - U));
    }
    return s * h / 3.0 * sqrt(lam / M_PI);
}

static void test_exp_log_erfc(void **state) {
    (void)state;
    double worst = 0.0;
    for (double x = -700.0; x <= 700.0; x += 0.0137) {
        const double e = fabs(gks_exp(x) / exp(x) - 1.0);
        worst = e > worst ? e : worst;
    }
    assert_true(worst < 1e-15); /* measured 4.4e-16 */
    assert_true(gks_exp(-(double)INFINITY) < 1e-300);
    worst = 0.0;
    for (double x = 1e-300; x < 1e300; x *= 1.37) {
        const double e = fabs(gks_log(x) - log(x)) / fmax(1.0, fabs(log(x)));
        worst = e > worst ? e : worst;
    }
    for (double x = 0.5; x < 2.0; x += 0.001) {
        const double e = fabs(gks_log(x) - log(x));
        worst = e > worst ? e : worst;
    }
    assert_true(worst < 1e-15);
    worst = 0.0;
    for (double z = 0.0; z < 6.0; z += 0.001) {
        const double e = fabs(gks_erfcx(z) * gks_exp(-z * z) / erfc(z) - 1.0);
        worst = e > worst ? e : worst;
    }
    assert_true(worst < 1e-14); /* measured 4e-15: the rounding of z^2 inside exp */
    for (double z = 6.0; z < 26.0; z += 0.01) {
        const double e = fabs(gks_erfcx(z) * exp(-z * z) / erfc(z) - 1.0);
        worst = e > worst ? e : worst;
    }
    assert_true(worst < 1e-13);
}

static void test_half_moments_vs_quadrature(void **state) {
    (void)state;
    const double Us[] = {-2.3, -0.4, 0.0, 0.7, 3.1};
    const double lams[] = {0.3, 1.0, 4.0};
    for (int a = 0; a < 5; a++)
        for (int b = 0; b < 3; b++) {
            const double U = Us[a], lam = lams[b];
            const GksPrim q = gks_prim(1.3, U, 0.2, lam);
            const double x = sqrt(lam) * U;
            GksMoments mp, mm, mf;
            gks_moments_half(&mp, &q, K, 1.0, gks_exp(-x * x), gks_erfcx(fabs(x)));
            gks_moments_half(&mm, &q, K, -1.0, gks_exp(-x * x), gks_erfcx(fabs(x)));
            gks_moments_full(&mf, &q, K);
            const double wide = 14.0 / sqrt(lam);
            for (int n = 0; n <= 6; n++) {
                const double qp = quad_u(n, U, lam, 0.0, fabs(U) + wide);
                const double qm = quad_u(n, U, lam, -fabs(U) - wide, 0.0);
                const double scale = 1.0 + fabs(qp) + fabs(qm);
                assert_close(mp.u[n], qp, 1e-11 * scale);
                assert_close(mm.u[n], qm, 1e-11 * scale);
                assert_close(mf.u[n], qp + qm, 1e-11 * scale);
            }
            for (int n = 0; n <= 5; n++) {
                const double qv = quad_u(n, 0.2, lam, 0.2 - wide, 0.2 + wide);
                assert_close(mf.v[n], qv, 1e-11 * (1.0 + fabs(qv)));
            }
            /* xi: K independent components, each a 1D Maxwellian at rest */
            const double x2 = quad_u(2, 0.0, lam, -wide, wide),
                         x4 = quad_u(4, 0.0, lam, -wide, wide);
            assert_close(mf.xi2, K * x2, 1e-11 * mf.xi2);
            assert_close(mf.xi4, K * x4 + K * (K - 1.0) * x2 * x2, 1e-11 * mf.xi4);
        }
}

/* <u^a v^b c psi>: 2D quadrature in (u, v) on the u > 0 half, xi analytic. */
static void quad_moment(const GksPrim *q, int a, int b, const double c[4], double out[4]) {
    const int N = 1600;
    const double wide = 12.0 / sqrt(q->lam);
    const double ulo = 0.0, uhi = fabs(q->U) + wide, vlo = q->V - wide, vhi = q->V + wide;
    const double hu = (uhi - ulo) / N, hv = (vhi - vlo) / N;
    const double xi2 = K / (2.0 * q->lam), xi4 = K * (K + 2.0) / (4.0 * q->lam * q->lam);
    for (int n = 0; n < 4; n++) out[n] = 0.0;
    for (int i = 0; i <= N; i++) {
        const double u = ulo + i * hu, wu = (i == 0 || i == N) ? 1.0 : (i % 2 ? 4.0 : 2.0);
        for (int j = 0; j <= N; j++) {
            const double v = vlo + j * hv, wv = (j == 0 || j == N) ? 1.0 : (j % 2 ? 4.0 : 2.0);
            const double g =
                wu * wv * exp(-q->lam * ((u - q->U) * (u - q->U) + (v - q->V) * (v - q->V)));
            const double base = pow(u, a) * pow(v, b) * g;
            const double s = u * u + v * v; /* psi4 = (s + xi^2)/2 */
            /* c psi with xi averaged: <(s + xi2)/2>, <((s + xi2)/2)^2> */
            const double p1 = 0.5 * (s + xi2), p2 = 0.25 * (s * s + 2.0 * s * xi2 + xi4);
            const double cp = c[0] + c[1] * u + c[2] * v; /* the psi4-free part of c */
            out[0] += base * (cp + c[3] * p1);
            out[1] += base * u * (cp + c[3] * p1);
            out[2] += base * v * (cp + c[3] * p1);
            out[3] += base * (cp * p1 + c[3] * p2);
        }
    }
    for (int n = 0; n < 4; n++) out[n] *= hu * hv / 9.0 * q->lam / M_PI;
}

static void test_polynomial_moments(void **state) {
    (void)state;
    const GksPrim q = gks_prim(1.0, 0.3, -0.4, 1.7);
    const double x = sqrt(q.lam) * q.U;
    GksMoments m;
    gks_moments_half(&m, &q, K, 1.0, gks_exp(-x * x), gks_erfcx(fabs(x)));
    const double c[4] = {0.3, -1.2, 0.7, 0.9};
    const int ab[][2] = {{0, 0}, {1, 0}, {2, 0}, {1, 1}};
    for (int t = 0; t < 4; t++) {
        double got[4] = {0, 0, 0, 0}, ref[4];
        gks_moment_add(&m, ab[t][0], ab[t][1], c, 1.0, got);
        quad_moment(&q, ab[t][0], ab[t][1], c, ref);
        for (int n = 0; n < 4; n++) assert_close(got[n], ref[n], 1e-9 * (1.0 + fabs(ref[n])));
    }
}

/* The notes' slope solve (R2, R3, R4 form) for comparison. */
static void notes_slope(const GksPrim *q, const double dw[4], double a[4]) {
    const double r = q->rho, U = q->U, V = q->V, l = q->lam;
    const double R2 = (dw[1] - U * dw[0]) / r, R3 = (dw[2] - V * dw[0]) / r;
    const double R4 = dw[3] / r - (U * U + V * V + (K + 2.0) / (2.0 * l)) * dw[0] / (2.0 * r);
    a[3] = 4.0 * l * l / (K + 2.0) * (2.0 * R4 - 2.0 * U * R2 - 2.0 * V * R3);
    a[2] = 2.0 * l * R3 - V * a[3];
    a[1] = 2.0 * l * R2 - U * a[3];
    a[0] = dw[0] / r - U * a[1] - V * a[2] - 0.5 * a[3] * (U * U + V * V + (K + 2.0) / (2.0 * l));
}

static void test_micro_slopes_and_compatibility(void **state) {
    (void)state;
    const double w[4] = {1.2, 0.5, -0.3, 3.1};
    const double dx[4] = {0.4, -0.2, 0.1, 0.9}, dy[4] = {-0.1, 0.3, 0.25, -0.4};
    const GksPrim q = gks_prim_from_w(w, K);
    const GksDPrim px = gks_dprim(&q, dx, K), py = gks_dprim(&q, dy, K);
    double a[4], b[4], A[4], an[4];
    gks_micro(&q, &px, K, a);
    gks_micro(&q, &py, K, b);
    notes_slope(&q, dx, an);
    for (int n = 0; n < 4; n++) assert_close(a[n], an[n], 1e-13 * (1.0 + fabs(an[n])));
    GksMoments m;
    gks_moments_full(&m, &q, K);
    double back[4] = {0, 0, 0, 0};
    gks_moment_add(&m, 0, 0, a, q.rho, back);
    for (int n = 0; n < 4; n++) assert_close(back[n], dx[n], 1e-13);
    /* compatibility: rho <(a u + b v + A) psi> = 0 with A from the Euler equations */
    const GksDPrim pt = gks_dprim_dt(&q, &px, &py, 1.4);
    gks_micro(&q, &pt, K, A);
    double c[4] = {0, 0, 0, 0};
    gks_moment_add(&m, 1, 0, a, q.rho, c);
    gks_moment_add(&m, 0, 1, b, q.rho, c);
    gks_moment_add(&m, 0, 0, A, q.rho, c);
    for (int n = 0; n < 4; n++) assert_close(c[n], 0.0, 1e-13);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_exp_log_erfc),
        cmocka_unit_test(test_half_moments_vs_quadrature),
        cmocka_unit_test(test_polynomial_moments),
        cmocka_unit_test(test_micro_slopes_and_compatibility),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
