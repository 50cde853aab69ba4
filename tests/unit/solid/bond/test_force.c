/* solid/bond/force, pd_integrate, pd_diagnostics: properties of the discrete
 * PD force that must hold exactly or to round-off. */
#include "pd_fixtures.h"
#include "test_support.h"

#include "solid/bond/body.h"
#include "solid/bond/diagnostics.h"
#include "solid/bond/force.h"
#include "solid/bond/integrate.h"

#include "core/mem.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Largest |force| component, the scale for round-off comparisons. */
static double force_scale(const BondBody *b) {
    double m = 0;
    for (int d = 0; d < b->dim; d++)
        for (int64_t i = 0; i < b->n; i++) m = fmax(m, fabs(b->force[d][i]));
    return m;
}

/* A smooth, non-trivial displacement field of amplitude 1e-3 dx. */
static void deform(BondBody *b) {
    for (int64_t i = 0; i < b->n; i++)
        for (int d = 0; d < b->dim; d++)
            b->u[d][i] = 1e-3 * b->spacing * sin(3.1 * b->x[0][i] / b->spacing + d) *
                         cos(1.7 * b->x[1][i] / b->spacing - d);
}

/* Bond-based PD forces depend only on bond lengths: a rigid rotation plus
 * translation gives zero force (to round-off of the large coordinates). */
static void test_rigid_motion_gives_no_force(void **state) {
    (void)state;
    for (int dim = 2; dim <= 3; dim++) {
        PdConfig cfg = fixture_block(dim, 10, 10, 10, 1e-3);
        BondBody b;
        assert_ok(bond_body_create(&b, &cfg));
        deform(&b);
        pd_force_compute(&b);
        double reference = force_scale(&b); /* what a real deformation of 1e-3 dx gives */
        double angle = 0.3, c = cos(angle), s = sin(angle);
        for (int64_t i = 0; i < b.n; i++) {
            double x = b.x[0][i], y = b.x[1][i];
            b.u[0][i] = c * x - s * y - x + 0.01;
            b.u[1][i] = s * x + c * y - y - 0.02;
            if (dim == 3) b.u[2][i] = 0.005;
        }
        pd_force_compute(&b);
        /* round-off of |y| - |xi| at |xi| ~ 3e-3 relative 1e-16, against
         * stretches of 1e-3 in the reference: ratio ~1e-12 */
        assert_true(force_scale(&b) < 1e-9 * reference);
        bond_body_destroy(&b);
    }
}

/* Pair forces are equal and opposite, so sum_i V_i f_i = 0 to round-off. */
static void test_newtons_third_law(void **state) {
    (void)state;
    for (int dim = 2; dim <= 3; dim++) {
        PdConfig cfg = fixture_block(dim, 12, 9, 7, 1e-3);
        BondBody b;
        assert_ok(bond_body_create(&b, &cfg));
        deform(&b);
        pd_force_compute(&b);
        for (int d = 0; d < dim; d++) {
            double sum = 0, mag = 0;
            for (int64_t i = 0; i < b.n; i++) {
                sum += b.volume[i] * b.force[d][i];
                mag += b.volume[i] * fabs(b.force[d][i]);
            }
            assert_true(fabs(sum) < 1e-13 * mag);
        }
        bond_body_destroy(&b);
    }
}

/* The force is minus the gradient of the elastic energy per unit volume:
 * V_i f_i = -dE/du_i, checked by central differences at a few points. The
 * energy is quadratic-plus in u, so the central difference error is
 * O(h^2) with h = 1e-7 dx: relative 1e-6 is far above it. */
static void test_force_is_energy_gradient(void **state) {
    (void)state;
    PdConfig cfg = fixture_block(2, 10, 10, 0, 1e-3);
    BondBody b;
    assert_ok(bond_body_create(&b, &cfg));
    deform(&b);
    pd_force_compute(&b);
    int64_t probes[3] = {0, b.n / 2, b.n - 7};
    for (int p = 0; p < 3; p++) {
        int64_t i = probes[p];
        for (int d = 0; d < 2; d++) {
            double h = 1e-7 * b.spacing, u0 = b.u[d][i];
            b.u[d][i] = u0 + h;
            double ep = pd_elastic_energy(&b);
            b.u[d][i] = u0 - h;
            double em = pd_elastic_energy(&b);
            b.u[d][i] = u0;
            double grad = (ep - em) / (2 * h);
            double vf = b.volume[i] * b.force[d][i];
            assert_close(vf, -grad, 1e-6 * fabs(vf) + 1e-9 * fabs(grad));
        }
    }
    bond_body_destroy(&b);
}

/* A breakable bond stretched past s_c breaks after the step that sees it
 * (Eq. 17's state is history); an unbreakable one never does. */
static void test_failure_is_history(void **state) {
    (void)state;
    PdConfig cfg = fixture_block(2, 8, 8, 0, 1e-3);
    cfg.failure = true;
    cfg.critical_stretch = 0.01;
    BondBody b;
    assert_ok(bond_body_create(&b, &cfg));
    /* 2 % uniform strain along x: every bond with a large x component breaks */
    for (int64_t i = 0; i < b.n; i++) b.u[0][i] = 0.02 * b.x[0][i];
    pd_force_compute(&b);
    double f_first = force_scale(&b);
    assert_true(f_first > 0); /* the force of that step still had the bonds */
    int64_t broken = pd_broken_bonds(&b);
    assert_true(broken > 0);
    int64_t expect = 0; /* bonds whose stretch exceeds 0.01 */
    for (int64_t i = 0; i < b.n; i++)
        for (int64_t k = b.bond_first[i]; k < b.bond_first[i + 1]; k++) {
            int32_t j = b.bond_nbr[k];
            double ex = b.x[0][j] - b.x[0][i], ey = b.x[1][j] - b.x[1][i];
            double s = sqrt(pow(1.02 * ex, 2) + ey * ey) / sqrt(ex * ex + ey * ey) - 1;
            expect += s > 0.01;
        }
    assert_int_equal(broken, expect / 2);
    bond_body_destroy(&b);

    cfg = fixture_block(2, 8, 8, 0, 1e-3);
    cfg.failure = false;
    cfg.critical_stretch = 0.01;
    assert_ok(bond_body_create(&b, &cfg));
    for (int64_t i = 0; i < b.n; i++) b.u[0][i] = 0.02 * b.x[0][i];
    pd_force_compute(&b);
    assert_int_equal(pd_broken_bonds(&b), 0);
    bond_body_destroy(&b);
}

/* dt = min_i sqrt(2 rho / sum_j k_ij) (Silling and Askari 2005), against a
 * direct evaluation at one interior point of a body without corrections,
 * where k_ij = c nu_ij V / |xi|. */
static void test_stable_time_step(void **state) {
    (void)state;
    PdConfig cfg = fixture_block(2, 12, 12, 0, 1e-3);
    cfg.surface_correction = PD_SURFACE_NONE;
    BondBody b;
    assert_ok(bond_body_create(&b, &cfg));
    double sum = 0, V = 1e-9, dx = 1e-3, delta = 3.015e-3;
    for (int i = -3; i <= 3; i++)
        for (int j = -3; j <= 3; j++) {
            double r = hypot(i, j) * dx;
            if ((i || j) && r <= delta)
                sum += b.micromodulus * pd_volume_factor(r, delta, dx, PD_VOLUME_LINEAR) * V / r;
        }
    /* interior points have the largest sum, hence the smallest step */
    assert_close(pd_stable_time_step(&b), sqrt(2 * 8000 / sum), 1e-7 * sqrt(2 * 8000 / sum));
    /* the same from the configuration alone (nspd check of a body it does
     * not build): exact in the sum, the built one's coefficients are floats */
    assert_close(pd_interior_stable_dt(&b.cfg), sqrt(2 * 8000 / sum), 1e-14 * sqrt(2 * 8000 / sum));
    bond_body_destroy(&b);
}

/* The packed kernels (force.c, what pd_force_compute runs) against the
 * plain ones on a random cloud, in 2D and 3D: rows of 0 to 40 bonds
 * (every remainder of their lanes), breakable, unbreakable and broken
 * bonds, stretches across the failure limit. Where GCC vectorises the
 * plain kernels as in the build the golden outputs come from (GCC 12,
 * -O3, AVX-512 with 256-bit vectors, as GCC tunes for Intel's cores; not the sanitised
 * build, nor GCC's tuning for AMD's Zen, which takes 512-bit vectors), the same bits, forces and
 * broken bonds; elsewhere the forces within round-off and the same bonds broken. */
static void packed_against_plain(int dim) {
    enum { N = 400, MAXROW = 40 };
    srand(7 + (unsigned)dim);
    double *x[3], *u[3], *f[3], *g[3], *p;
    int64_t *first;
    int32_t *nbr;
    float *coef, *coef2;
    for (int a = 0; a < 3; a++) {
        assert_ok(nspd_alloc(&x[a], N, 8)), assert_ok(nspd_alloc(&u[a], N, 8));
        assert_ok(nspd_alloc(&f[a], N, 8)), assert_ok(nspd_alloc(&g[a], N, 8));
    }
    const int width = dim == 2 ? 4 : 8;
    assert_ok(nspd_alloc(&p, (size_t)width * N, 8));
    assert_ok(nspd_alloc(&first, N + 1, sizeof *first));
    assert_ok(nspd_alloc(&nbr, N * MAXROW, sizeof *nbr));
    assert_ok(nspd_alloc(&coef, N * MAXROW, sizeof *coef));
    assert_ok(nspd_alloc(&coef2, N * MAXROW, sizeof *coef2));
    for (int i = 0; i < N; i++)
        for (int a = 0; a < dim; a++) {
            x[a][i] = 1e-3 * (rand() % 1000);
            u[a][i] = 1e-4 * ((double)rand() / RAND_MAX - 0.5);
            p[width * i + a] = x[a][i];
            p[width * i + (dim == 2 ? 2 : 4) + a] = u[a][i];
        }
    first[0] = 0;
    for (int i = 0; i < N; i++) {
        const int len = i % (MAXROW + 1);
        for (int m = 0; m < len; m++) {
            int j = rand() % N;
            while (j == i || (x[0][j] == x[0][i] && x[1][j] == x[1][i])) j = rand() % N;
            const int kind = rand() % 4; /* breakable, unbreakable, broken */
            nbr[first[i] + m] = j;
            coef[first[i] + m] = kind == 3 ? 0.0f : (kind == 2 ? -1.0f : 1.0f) * (float)(1 + m);
        }
        first[i + 1] = first[i] + len;
    }
    memcpy(coef2, coef, (size_t)first[N] * sizeof *coef);
    const double limit2 = 1.0 + 2e-4; /* some of the stretches above, some below */
    if (dim == 2) {
        pd_force_kernel_2d(0, N, x[0], x[1], u[0], u[1], first, nbr, coef, 3.0, limit2, f[0], f[1]);
        pd_force_kernel_2d_packed(0, N, x[0], x[1], u[0], u[1], p, first, nbr, coef2, 3.0, limit2,
                                  g[0], g[1]);
    } else {
        pd_force_kernel_3d(0, N, x[0], x[1], x[2], u[0], u[1], u[2], first, nbr, coef, 3.0, limit2,
                           f[0], f[1], f[2]);
        pd_force_kernel_3d_packed(0, N, (const double *const *)x, (const double *const *)u, p,
                                  first, nbr, coef2, 3.0, limit2, g);
    }
    int64_t broken = 0;
    for (int64_t b = 0; b < first[N]; b++) broken += coef[b] == 0.0f;
    /* a quarter broken before, and not every breakable one after */
    assert_true(broken > first[N] / 4 + 100 && broken < first[N] / 2 + first[N] / 4);
    assert_memory_equal(coef, coef2, (size_t)first[N] * sizeof *coef);
    for (int a = 0; a < dim; a++) {
#if defined(__AVX512VL__) && defined(__GNUC__) && !defined(__clang__) && __GNUC__ == 12 &&         \
    !defined(__SANITIZE_ADDRESS__) /* the sanitised build vectorises otherwise */ &&               \
    !defined(__znver3__) && !defined(__znver4__) /* tuned for AMD: 512-bit vectors */
        assert_memory_equal(f[a], g[a], N * sizeof *f[a]);
#else
        for (int i = 0; i < N; i++) assert_close(g[a][i], f[a][i], 1e-13 * (fabs(f[a][i]) + 1e-30));
#endif
    }
    for (int a = 0; a < 3; a++)
        nspd_free(&x[a]), nspd_free(&u[a]), nspd_free(&f[a]), nspd_free(&g[a]);
    nspd_free(&p), nspd_free(&first), nspd_free(&nbr), nspd_free(&coef), nspd_free(&coef2);
}

static void test_packed_kernels_are_the_plain_ones(void **state) {
    (void)state;
    packed_against_plain(2);
    packed_against_plain(3);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rigid_motion_gives_no_force),
        cmocka_unit_test(test_newtons_third_law),
        cmocka_unit_test(test_force_is_energy_gradient),
        cmocka_unit_test(test_failure_is_history),
        cmocka_unit_test(test_stable_time_step),
        cmocka_unit_test(test_packed_kernels_are_the_plain_ones),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
