/* solid/correspondence/sl_force (paper 003's ref. [10], the semi-Lagrangian
 * bond-associated force) against the Lagrangian one (bac_force), with the
 * J2 material of the paper (plane strain, yielding):
 * - along a path of homogeneous motions (stretch, shear and a 30 degree
 *   turn in eight steps) both keep the same stress in every pair, and the
 *   pairs' integrated F_b is the motion's F: the RK weights reproduce a
 *   linear field in either configuration;
 * - at the path's end no force inside the deformed body (the patch test in
 *   the current configuration);
 * - momentum to round-off for any motion of a jittered cloud;
 * - objectivity: the same stretch with a rigid turn of 40 degrees on top
 *   (in four steps, after it: a turn's increments leave the midpoint
 *   rule's unrotated strain exactly 0, while a turn during the stretch
 *   moves the stress by the rate's own discretisation error, 3e-3
 *   measured) gives the unturned forces turned, with the radial kernel (rotation
 *   invariant); the tensor kernel measured on current bonds is not, and the
 *   test prints by how much. */
#include "cloud_fixtures.h"
#include "test_support.h"

#include "core/status.h"
#include "solid/correspondence/bac_force.h"
#include "solid/correspondence/rk_gradient.h"
#include "solid/correspondence/sl_force.h"

#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

static const double E_MOD = 200e9, NU = 0.29;

/* One body with both forces' states. */
typedef struct {
    Cloud c;
    BacSystem s;
    RkKernel kernel;
    int64_t *reverse;
    BacPairs pairs;
    double *phi, *omega, *F, *work_point, *work_bond, *u[3], *u_prev[3], *f[3];
    uint8_t *ok;
    J2Material material;
    /* the Lagrangian (lag) and semi-Lagrangian (sl) states */
    BacState lag, sl;
    SlWork work;
} Body;

static double *zeros(int64_t count) {
    return calloc((size_t)(count > 0 ? count : 1), sizeof(double));
}

static void state_make(BacState *st, const Body *b, bool identity) {
    const int64_t np = b->pairs.count;
    *st = (BacState){.material = &b->material,
                     .u_prev = {b->u_prev[0], b->u_prev[1], NULL},
                     .Fb = zeros(4 * np),
                     .F_prev = zeros(9 * b->c.n),
                     .sigma = zeros(4 * np),
                     .eqps = zeros(np),
                     .principal = zeros(np),
                     .inverted = calloc((size_t)np, 1)};
    if (identity)
        for (int64_t p = 0; p < np; p++) st->Fb[p] = st->Fb[3 * np + p] = 1.0;
}

static void state_free(BacState *st) {
    free(st->Fb);
    free(st->F_prev);
    free(st->sigma);
    free(st->eqps);
    free(st->principal);
    free(st->inverted);
}

static void body_make(Body *b, int side, double jitter, RkKernel kernel) {
    memset(b, 0, sizeof *b);
    Cloud *c = &b->c;
    cloud_make(c, 2, side, 1e-3, jitter);
    const int64_t nb = c->first[c->n];
    b->kernel = kernel;
    b->phi = zeros(2 * nb);
    b->omega = zeros(nb);
    b->reverse = calloc((size_t)nb, sizeof(int64_t));
    b->ok = calloc((size_t)c->n, 1);
    b->F = zeros(9 * c->n);
    b->work_point = zeros((9 + bac_work_per_point(2)) * c->n);
    for (int a = 0; a < 2; a++) {
        b->u[a] = zeros(c->n);
        b->u_prev[a] = zeros(c->n);
        b->f[a] = zeros(c->n);
    }
    assert_int_equal(rk_gradient_weights_of(2, kernel, 2, c->n, (const double *const *)c->x,
                                            c->volume, c->first, c->nbr, c->delta, NULL, NULL,
                                            b->phi, b->ok),
                     0);
    assert_int_equal(bac_reverse_bonds(c->n, c->first, c->nbr, b->reverse), 0);
    assert_int_equal(bac_pairs_create(c->n, c->first, b->reverse, &b->pairs), NSPD_OK);
    for (int64_t i = 0; i < c->n; i++)
        for (int64_t k = c->first[i]; k < c->first[i + 1]; k++) {
            const double xi[3] = {c->x[0][c->nbr[k]] - c->x[0][i], c->x[1][c->nbr[k]] - c->x[1][i],
                                  0.0};
            b->omega[k] = rk_kernel_of(kernel, 2, xi, c->delta);
        }
    const double G = E_MOD / (2 * (1 + NU)), K = E_MOD / (3 * (1 - 2 * NU));
    b->material = (J2Material){.bulk = K, .shear = G, .yield = 0.4e9, .hardening = 0.1e9};
    b->s = (BacSystem){.dim = 2,
                       .n = c->n,
                       .x = {c->x[0], c->x[1], NULL},
                       .volume = c->volume,
                       .first = c->first,
                       .nbr = c->nbr,
                       .reverse = b->reverse,
                       .pairs = b->pairs,
                       .phi = b->phi,
                       .omega = b->omega,
                       .lambda = K - 2.0 * G / 3.0,
                       .mu = G};
    b->work_bond = zeros(bac_work_bond(&b->s, 0));
    state_make(&b->lag, b, false);
    state_make(&b->sl, b, true);
    assert_int_equal(sl_work_create(2, c->n, nb, b->pairs.count, &b->work), NSPD_OK);
}

static void body_free(Body *b) {
    state_free(&b->lag);
    state_free(&b->sl);
    sl_work_free(&b->work);
    free(b->phi);
    free(b->omega);
    free(b->reverse);
    bac_pairs_free(&b->pairs);
    free(b->ok);
    free(b->F);
    free(b->work_point);
    free(b->work_bond);
    for (int a = 0; a < 2; a++) {
        free(b->u[a]);
        free(b->u_prev[a]);
        free(b->f[a]);
    }
    cloud_free(&b->c);
}

/* u = (F - I) X, after u_prev = u */
static void move_to(Body *b, const double F[2][2]) {
    for (int64_t i = 0; i < b->c.n; i++)
        for (int a = 0; a < 2; a++) {
            b->u_prev[a][i] = b->u[a][i];
            b->u[a][i] = (F[a][0] - (a == 0)) * b->c.x[0][i] + (F[a][1] - (a == 1)) * b->c.x[1][i];
        }
}

static void force_sl(Body *b) {
    const SlWeights w = {.order = 2, .kernel = b->kernel, .delta = b->c.delta};
    double *const f[3] = {b->f[0], b->f[1], NULL};
    const double *const u[3] = {b->u[0], b->u[1], NULL};
    assert_int_equal(sl_force(&b->s, &w, &b->sl, u, f, &b->work, b->work_point), 0);
}

static void force_lagrangian(Body *b) {
    double *const f[3] = {b->f[0], b->f[1], NULL};
    const double *const u[3] = {b->u[0], b->u[1], NULL};
    bac_force(&b->s, &b->lag, u, f, b->F, b->work_point, b->work_bond);
}

/* The motion at step k of `steps`: a stretch and shear growing to
 * (1.02, 0.01; 0, 0.99) and a turn growing to `turn` radians. */
static void path_F(int k, int steps, double turn, double F[2][2]) {
    const double s = (double)k / steps, th = turn * s;
    const double U[2][2] = {{1.0 + 0.02 * s, 0.01 * s}, {0.0, 1.0 - 0.01 * s}};
    const double R[2][2] = {{cos(th), -sin(th)}, {sin(th), cos(th)}};
    for (int a = 0; a < 2; a++)
        for (int c = 0; c < 2; c++) F[a][c] = R[a][0] * U[0][c] + R[a][1] * U[1][c];
}

static bool inside(const Cloud *c, int64_t i, int side, double inset) {
    for (int a = 0; a < 2; a++)
        if (c->x[a][i] < inset || c->x[a][i] > (side - 1) * c->h - inset) return false;
    return true;
}

static void test_homogeneous_path(void **state) {
    (void)state;
    const int side = 20, steps = 8;
    Body b;
    body_make(&b, side, 0.0, RK_KERNEL_CUBIC_TENSOR);
    double F[2][2];
    for (int k = 1; k <= steps; k++) {
        path_F(k, steps, M_PI / 6, F);
        move_to(&b, F);
        force_lagrangian(&b);
        force_sl(&b);
    }
    const int64_t np = b.pairs.count;
    double dsigma = 0.0, deqps = 0.0, dF = 0.0, eqps = 0.0;
    for (int64_t p = 0; p < np; p++) {
        for (int q = 0; q < 4; q++)
            dsigma = fmax(dsigma, fabs(b.sl.sigma[q * np + p] - b.lag.sigma[q * np + p]));
        deqps = fmax(deqps, fabs(b.sl.eqps[p] - b.lag.eqps[p]));
        eqps = fmax(eqps, b.lag.eqps[p]);
        const double want[4] = {F[0][0], F[0][1], F[1][0], F[1][1]};
        for (int q = 0; q < 4; q++) dF = fmax(dF, fabs(b.sl.Fb[q * np + p] - want[q]));
    }
    print_message("homogeneous path (eight steps, plastic strain %.2e): semi-Lagrangian against "
                  "Lagrangian stress %.1e Pa (of 0.4e9), plastic strain %.1e; F_b against the "
                  "motion's F %.1e\n",
                  eqps, dsigma, deqps, dF);
    assert_true(eqps > 1e-3); /* the path yields: the state's history matters */
    /* measured 5.3e-4 Pa, 1.9e-15 and 4.1e-15: round-off (of stresses of 4e8 Pa) */
    assert_true(dsigma < 1e-2);
    assert_true(deqps < 1e-14);
    assert_true(dF < 2e-14);
    /* the patch test in the current configuration */
    force_sl(&b);
    const double scale = b.s.mu * 1e-3 / b.c.h;
    double interior = 0.0, surface = 0.0;
    for (int64_t i = 0; i < b.c.n; i++) {
        const double m = hypot(b.f[0][i], b.f[1][i]) / scale;
        if (inside(&b.c, i, side, 3 * b.c.delta))
            interior = fmax(interior, m);
        else
            surface = fmax(surface, m);
    }
    print_message("patch test on the deformed lattice: largest force density inside %.1e, near "
                  "the surface %.2f (of mu 1e-3 / h)\n",
                  interior, surface);
    assert_true(interior < 1e-10); /* measured 5.9e-12 */
    assert_true(surface > 1e-3);
    body_free(&b);
}

static void test_momentum(void **state) {
    (void)state;
    Body b;
    body_make(&b, 12, 0.2, RK_KERNEL_CUBIC_TENSOR);
    uint64_t seed = 11;
    for (int step = 0; step < 3; step++) {
        for (int64_t i = 0; i < b.c.n; i++)
            for (int a = 0; a < 2; a++) {
                seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
                b.u_prev[a][i] = b.u[a][i];
                b.u[a][i] += 1e-6 * ((double)(seed >> 11) / (double)(1ULL << 53) - 0.5);
            }
        force_sl(&b);
    }
    for (int a = 0; a < 2; a++) {
        double sum = 0.0, size = 0.0;
        for (int64_t i = 0; i < b.c.n; i++) {
            sum += b.f[a][i] * b.c.volume[i];
            size += fabs(b.f[a][i] * b.c.volume[i]);
        }
        print_message("momentum %c: |sum V L| / sum |V L| = %.1e\n", 'x' + a, fabs(sum) / size);
        assert_true(size > 0 && fabs(sum) / size < 1e-13);
    }
    body_free(&b);
}

/* The largest |f_turned - R f| over the points, relative to the largest |f|. */
static double turned_mismatch(RkKernel kernel, double turn) {
    const int side = 14, steps = 6;
    Body a, t;
    body_make(&a, side, 0.0, kernel);
    body_make(&t, side, 0.0, kernel);
    double F[2][2];
    for (int k = 1; k <= steps; k++) { /* the same stretch on both */
        path_F(k, steps, 0.0, F);
        move_to(&a, F);
        force_sl(&a);
        move_to(&t, F);
        force_sl(&t);
    }
    const double U[2][2] = {{F[0][0], F[0][1]}, {F[1][0], F[1][1]}};
    for (int k = 1; k <= 4; k++) { /* then a turn of one of them, in four steps */
        const double th = turn * k / 4.0, Rk[2][2] = {{cos(th), -sin(th)}, {sin(th), cos(th)}};
        for (int r = 0; r < 2; r++)
            for (int c = 0; c < 2; c++) F[r][c] = Rk[r][0] * U[0][c] + Rk[r][1] * U[1][c];
        move_to(&a, U);
        force_sl(&a);
        move_to(&t, F);
        force_sl(&t);
    }
    const double R[2][2] = {{cos(turn), -sin(turn)}, {sin(turn), cos(turn)}};
    double worst = 0.0, size = 0.0;
    for (int64_t i = 0; i < a.c.n; i++) {
        size = fmax(size, hypot(a.f[0][i], a.f[1][i]));
        const double r0 = R[0][0] * a.f[0][i] + R[0][1] * a.f[1][i];
        const double r1 = R[1][0] * a.f[0][i] + R[1][1] * a.f[1][i];
        worst = fmax(worst, hypot(t.f[0][i] - r0, t.f[1][i] - r1));
    }
    body_free(&a);
    body_free(&t);
    return worst / size;
}

static void test_objectivity(void **state) {
    (void)state;
    const double radial = turned_mismatch(RK_KERNEL_CUBIC_RADIAL, 40.0 * M_PI / 180.0);
    const double tensor = turned_mismatch(RK_KERNEL_CUBIC_TENSOR, 40.0 * M_PI / 180.0);
    print_message("turned 40 degrees on top of a stretch: |f - R f0| / |f0| %.1e with the radial "
                  "kernel, %.1e with the tensor kernel on current bonds\n",
                  radial, tensor);
    assert_true(radial < 1e-11);        /* measured 3.3e-13; the tensor kernel 5.3e-2 */
    assert_true(tensor > 1e3 * radial); /* the tensor kernel's known lack, seen */
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_homogeneous_path),
        cmocka_unit_test(test_momentum),
        cmocka_unit_test(test_objectivity),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
