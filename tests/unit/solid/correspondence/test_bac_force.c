/* solid/correspondence/bac_force (notes 1c.10): on a randomly perturbed lattice, momentum
 * is conserved to round-off for any displacement (C9) and a rigid rotation
 * of 30 degrees gives no force anywhere (objectivity). On nspd's regular
 * lattice, a homogeneous deformation gives no force at points 3 delta
 * inside the body (the patch test C2; nearer the surface the PD surface
 * effect, and at 2 delta the kernel sums of truncated families, give
 * forces), and a quadratic displacement gives div(sigma) inside, exactly
 * but for the geometric nonlinearity (C3's consistency).
 * On perturbed clouds the patch test does not hold (measured: 0.14, 0.71,
 * 2.8 of mu 1e-3 / h inside at 1, 5, 20 % jitter), like every scheme of
 * nodal integration without a consistency correction; nspd's solids sit
 * on a lattice. */
#include "cloud_fixtures.h"
#include "test_support.h"

#include "core/mem.h"
#include "core/status.h"
#include "solid/correspondence/bac_force.h"
#include "solid/correspondence/rk_gradient.h"

#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

/* steel of paper 003: E = 200 GPa, nu = 0.29 */
static const double E_MOD = 200e9, NU = 0.29;

typedef struct {
    Cloud c;
    BacSystem s;
    double *phi, *omega, *work_point, *work_bond, *u[3], *f[3];
    int64_t *reverse;
    BacPairs pairs;
    uint8_t *ok;
} Setup;

static void setup_make(Setup *t, int side, double jitter) {
    memset(t, 0, sizeof *t);
    Cloud *c = &t->c;
    cloud_make(c, 2, side, 1e-3, jitter);
    const int64_t bonds = c->first[c->n];
    t->phi = calloc((size_t)(2 * bonds), sizeof(double));
    t->omega = calloc((size_t)bonds, sizeof(double));
    t->reverse = calloc((size_t)bonds, sizeof(int64_t));
    t->ok = calloc((size_t)c->n, 1);
    t->work_point = calloc((size_t)((9 + bac_work_per_point(2)) * c->n), sizeof(double));
    t->work_bond = calloc((size_t)(bac_work_per_bond(2) * bonds), sizeof(double));
    for (int a = 0; a < 2; a++) {
        t->u[a] = calloc((size_t)c->n, sizeof(double));
        t->f[a] = calloc((size_t)c->n, sizeof(double));
    }
    assert_int_equal(rk_gradient_weights(2, c->n, (const double *const *)c->x, c->volume, c->first,
                                         c->nbr, c->delta, NULL, t->phi, t->ok),
                     0);
    assert_int_equal(bac_reverse_bonds(c->n, c->first, c->nbr, t->reverse), 0);
    assert_int_equal(bac_pairs_create(c->n, c->first, t->reverse, &t->pairs), NSPD_OK);
    cloud_omega(c, t->omega);
    t->s = (BacSystem){.dim = 2,
                       .n = c->n,
                       .x = {c->x[0], c->x[1], NULL},
                       .volume = c->volume,
                       .first = c->first,
                       .nbr = c->nbr,
                       .reverse = t->reverse,
                       .pairs = t->pairs,
                       .phi = t->phi,
                       .omega = t->omega,
                       .lambda = E_MOD * NU / ((1 + NU) * (1 - 2 * NU)),
                       .mu = E_MOD / (2 * (1 + NU))};
}

static void setup_free(Setup *t) {
    free(t->phi);
    free(t->omega);
    free(t->reverse);
    bac_pairs_free(&t->pairs);
    free(t->ok);
    free(t->work_point);
    free(t->work_bond);
    for (int a = 0; a < 2; a++) {
        free(t->u[a]);
        free(t->f[a]);
    }
    cloud_free(&t->c);
}

static void force(Setup *t) {
    double *const f[3] = {t->f[0], t->f[1], NULL};
    const double *const u[3] = {t->u[0], t->u[1], NULL};
    bac_force(&t->s, NULL, u, f, t->work_point, t->work_point + 9 * t->c.n, t->work_bond);
}

/* Points at least `inset` inside the cloud's lattice box. */
static bool inside(const Cloud *c, int64_t i, int side, double inset) {
    for (int a = 0; a < 2; a++)
        if (c->x[a][i] < inset || c->x[a][i] > (side - 1) * c->h - inset) return false;
    return true;
}

static void test_momentum(void **state) {
    (void)state;
    Setup t;
    setup_make(&t, 12, 0.2);
    uint64_t seed = 7;
    for (int64_t i = 0; i < t.c.n; i++)
        for (int a = 0; a < 2; a++) {
            seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
            t.u[a][i] = 1e-6 * ((double)(seed >> 11) / (double)(1ULL << 53) - 0.5);
        }
    force(&t);
    for (int a = 0; a < 2; a++) {
        double sum = 0.0, size = 0.0;
        for (int64_t i = 0; i < t.c.n; i++) {
            sum += t.f[a][i] * t.c.volume[i];
            size += fabs(t.f[a][i] * t.c.volume[i]);
        }
        print_message("momentum %c: |sum V L| / sum |V L| = %.1e\n", 'x' + a, fabs(sum) / size);
        assert_true(size > 0 && fabs(sum) / size < 1e-13);
    }
    setup_free(&t);
}

static void test_rigid_rotation(void **state) {
    (void)state;
    Setup t;
    setup_make(&t, 12, 0.2);
    const double th = M_PI / 6, R[2][2] = {{cos(th), -sin(th)}, {sin(th), cos(th)}};
    for (int64_t i = 0; i < t.c.n; i++)
        for (int a = 0; a < 2; a++)
            t.u[a][i] = R[a][0] * t.c.x[0][i] + R[a][1] * t.c.x[1][i] - t.c.x[a][i];
    force(&t);
    /* scale: the force density of a strain of 1e-3, mu 1e-3 / h */
    const double scale = t.s.mu * 1e-3 / t.c.h;
    double worst = 0.0;
    for (int64_t i = 0; i < t.c.n; i++)
        for (int a = 0; a < 2; a++) worst = fmax(worst, fabs(t.f[a][i]));
    print_message("rigid rotation: largest force density %.1e of mu 1e-3 / h\n", worst / scale);
    assert_true(worst / scale < 1e-9);
    setup_free(&t);
}

static void test_patch(void **state) {
    (void)state;
    const int side = 20;
    Setup t;
    setup_make(&t, side, 0.0);
    const double F[2][2] = {{1.001, 0.0005}, {-0.0003, 0.9995}};
    for (int64_t i = 0; i < t.c.n; i++)
        for (int a = 0; a < 2; a++)
            t.u[a][i] = (F[a][0] - (a == 0)) * t.c.x[0][i] + (F[a][1] - (a == 1)) * t.c.x[1][i];
    force(&t);
    const double scale = t.s.mu * 1e-3 / t.c.h;
    double interior = 0.0, surface = 0.0;
    for (int64_t i = 0; i < t.c.n; i++) {
        const double m = hypot(t.f[0][i], t.f[1][i]) / scale;
        if (inside(&t.c, i, side, 3 * t.c.delta))
            interior = fmax(interior, m);
        else
            surface = fmax(surface, m);
    }
    print_message("patch test: largest force density inside %.1e, near the surface %.2f "
                  "(of mu 1e-3 / h)\n",
                  interior, surface);
    /* measured 4.2e-13: round-off */
    assert_true(interior < 1e-11);
    assert_true(surface > 1e-3); /* the surface effect exists: the test sees forces */
    setup_free(&t);
}

/* u_x = a x^2 with a x <= 1e-6 over the block: inside, L_x = 2 a (lambda +
 * 2 mu) and L_y = 0 to first order; Saint Venant-Kirchhoff's geometric
 * nonlinearity is of the order of a x (measured: the error is 3.75e-6 at
 * a x = 1e-6 and 3.75e-4 at 1e-4, so it is all nonlinearity). */
static void test_quadratic_divergence(void **state) {
    (void)state;
    const int side = 24;
    Setup t;
    setup_make(&t, side, 0.0);
    const double a = 1e-6 / (side * t.c.h); /* a x <= 1e-6 */
    for (int64_t i = 0; i < t.c.n; i++) t.u[0][i] = a * t.c.x[0][i] * t.c.x[0][i];
    force(&t);
    const double want = 2 * a * (t.s.lambda + 2 * t.s.mu);
    double worst = 0.0;
    for (int64_t i = 0; i < t.c.n; i++)
        if (inside(&t.c, i, side, 3 * t.c.delta))
            worst = fmax(worst, fmax(fabs(t.f[0][i] - want), fabs(t.f[1][i])) / want);
    print_message("quadratic field: largest interior error of div sigma %.2e\n", worst);
    assert_true(worst < 1e-5);
    setup_free(&t);
}

/* The convergence check (C3): a smooth field, u = A (sin(k x),
 * sin(k y) / 2) with k = 2 pi / wavelength, the wavelength 16, 32 and 64
 * h (the same body refined at fixed delta / h = 2.5), A so small that the
 * force is linear (k A = 1e-9). Inside (3 delta from the surface) the force
 * density against the continuum's div sigma = -(lambda + 2 mu) k^2 u,
 * relative to its largest value: second order (measured 4.8e-2, 1.2e-2,
 * 3.1e-3: orders 1.96, 1.99; the square of the plane-wave speed error of
 * test_solid.c, 3.1 % at 20 h); required within [1.8, 2.2] for the
 * finer pair. */
static void test_force_convergence(void **state) {
    (void)state;
    double e[3];
    for (int r = 0; r < 3; r++) {
        const int per_wave = 16 << r, side = 3 * per_wave / 2;
        Setup t;
        setup_make(&t, side, 0.0);
        const double k = 2.0 * M_PI / (per_wave * t.c.h), A = 1e-9 / k;
        for (int64_t i = 0; i < t.c.n; i++) {
            t.u[0][i] = A * sin(k * t.c.x[0][i]);
            t.u[1][i] = 0.5 * A * sin(k * t.c.x[1][i]);
        }
        force(&t);
        const double scale = (t.s.lambda + 2 * t.s.mu) * k * k * A;
        double worst = 0.0;
        for (int64_t i = 0; i < t.c.n; i++)
            if (inside(&t.c, i, side, 3 * t.c.delta))
                for (int a = 0; a < 2; a++)
                    worst = fmax(worst, fabs(t.f[a][i] + scale * t.u[a][i] / A) / scale);
        e[r] = worst;
        setup_free(&t);
    }
    const double p01 = log2(e[0] / e[1]), p12 = log2(e[1] / e[2]);
    print_message("sine field, interior force error: %.2e %.2e %.2e at 16, 32, 64 h per "
                  "wavelength; orders %.2f, %.2f\n",
                  e[0], e[1], e[2], p01, p12);
    assert_true(p12 > 1.8 && p12 < 2.2);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_momentum),
        cmocka_unit_test(test_rigid_rotation),
        cmocka_unit_test(test_patch),
        cmocka_unit_test(test_quadratic_divergence),
        cmocka_unit_test(test_force_convergence),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
