/* The correspondence solid with the classic force (correspondence.force:
 * classic; solid/correspondence/classic_force.h with a J2 state per point): the material
 * integrated at every point on a homogeneous path (F_i = N_i K_i^-1 is
 * exact for a linear displacement at any point with an invertible K_i,
 * boundary points included: C7), wave speeds with the zero-energy penalty
 * (C4), the stable step with the penalty in the operator (C6), momentum
 * with damage and thread independence (C9). Fixtures as in
 * test_solid.c. */
#include "cpd_fixtures.h"
#include "test_support.h"

#include "core/mem.h"
#include "core/status.h"
#include "solid/correspondence/body.h"

#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

/* paper 003's steel */
static const double RHO = CPD_STEEL_RHO, YIELD = CPD_STEEL_YIELD, HARD = CPD_STEEL_HARDENING;

static CpdConfig block(int nx, int ny, double h) {
    return cpd_fixture_block(nx, ny, h, CPD_FORCE_CLASSIC);
}

static void make(CpdBody *b, CpdConfig c) {
    assert_ok(cpd_body_create(b, &c));
}

/* Drives the body through homogeneous F(t) and checks after each
 * increment that every point's F_i is F and its stress and plastic strain
 * are the material point's, integrated alone with the same midpoint
 * increments. Returns the worst stress/strain deviation; *worst_F the
 * worst |F_i - F|. Interior and boundary points are reported apart. */
static double follow_path(CpdBody *b, const double (*path)[4], int steps, double *worst_F,
                          double *worst_boundary) {
    double sig[4] = {0, 0, 0, 0}, eqps = 0.0, worst = 0.0;
    *worst_F = 0.0, *worst_boundary = 0.0;
    for (int s = 1; s <= steps; s++) {
        cpd_fixture_homogeneous(b, b->u_prev, path[s - 1]);
        cpd_fixture_homogeneous(b, b->u, path[s]);
        cpd_force(b, 0.0);
        double Fm[4], dF[4], de[3];
        for (int q = 0; q < 4; q++) {
            Fm[q] = 0.5 * (path[s - 1][q] + path[s][q]);
            dF[q] = path[s][q] - path[s - 1][q];
        }
        assert_int_equal(j2_unrotated_increment_2d(Fm, dF, 1.0, de), 1);
        j2_update(&b->material, de, sig, &eqps);
        const double scale = fabs(sig[0]) + fabs(sig[1]) + fabs(sig[2]) + fabs(sig[3]) + YIELD;
        for (int64_t i = 0; i < b->n; i++) {
            double d = 0.0;
            for (int q = 0; q < 4; q++) d = fmax(d, fabs(b->sigma[4 * i + q] - sig[q]) / scale);
            d = fmax(d, fabs(b->eqps[i] - eqps) / fmax(eqps, 1e-3));
            worst = fmax(worst, d);
            /* a full square family of 2.5 h has 24 bonds; fewer: near the boundary */
            if (b->first[i + 1] - b->first[i] < 24) *worst_boundary = fmax(*worst_boundary, d);
            const double *Fi = b->work_point + 9 * i;
            const double Fi2[4] = {Fi[0], Fi[1], Fi[3], Fi[4]};
            for (int q = 0; q < 4; q++) *worst_F = fmax(*worst_F, fabs(Fi2[q] - path[s][q]));
        }
    }
    return worst;
}

/* C7 in the classic body: uniaxial strain to 5 % and back, then simple
 * shear to 0.3, on a 12 x 12 block with J2 (every point; 80 of its 144
 * points have truncated families). Measured, worst over all points and
 * steps (boundary points alike): uniaxial 1.1e-16 of the stress, |F_i - F|
 * 3.0e-17; shear 7.2e-14, |F_i - F| 3.9e-16 (round-off of N_i K_i^-1).
 * Tolerances 1e-10 (the issue's) and 1e-12 for F_i. */
static void test_homogeneous_paths_follow_the_material(void **state) {
    (void)state;
    CpdConfig c = block(12, 12, 1e-3);
    c.yield_stress = YIELD;
    c.hardening = HARD;
    CpdBody b;
    make(&b, c);
    enum { N = 200 };
    static double path[2 * N + 1][4];
    for (int s = 0; s <= 2 * N; s++) {
        const double e = 0.05 * (s <= N ? s : 2 * N - s) / N;
        path[s][0] = 1.0 + e, path[s][1] = 0.0, path[s][2] = 0.0, path[s][3] = 1.0;
    }
    double wF, wb;
    const double uniaxial = follow_path(&b, (const double(*)[4])path, 2 * N, &wF, &wb);
    print_message("uniaxial strain 5 %% and back: worst point deviation %.3g (boundary %.3g), "
                  "|F_i - F| %.3g\n",
                  uniaxial, wb, wF);
    assert_true(uniaxial < 1e-10 && wb < 1e-10);
    assert_true(wF < 1e-12);
    assert_true(b.eqps[0] > 0.03); /* it did yield: eps_p(0.05) = 0.0316 loading alone */
    cpd_body_destroy(&b);

    c = block(12, 12, 1e-3);
    c.yield_stress = YIELD;
    c.hardening = HARD;
    make(&b, c);
    for (int s = 0; s <= N; s++)
        path[s][0] = 1.0, path[s][1] = 0.3 * s / N, path[s][2] = 0.0, path[s][3] = 1.0;
    const double shear = follow_path(&b, (const double(*)[4])path, N, &wF, &wb);
    print_message("simple shear to 0.3: worst point deviation %.3g (boundary %.3g), |F_i - F| "
                  "%.3g\n",
                  shear, wb, wF);
    assert_true(shear < 1e-10 && wb < 1e-10);
    assert_true(wF < 1e-12);
    cpd_body_destroy(&b);
}

/* C4: the P and shear wave speeds of plane strain steel from the interior
 * operator, along x and along the diagonal, bare (C_s = 0) and with the
 * default penalty C_s = 0.5. Measured (P, S; along x, diagonal):
 *     C_s = 0:    10 h -8.79/-9.27 % both;  20 h -2.27/-2.40 %;  40 h -0.57/-0.61 %
 *     C_s = 0.5:  10 h P -8.37/-8.82, S -7.36/-7.76 %;  20 h P -2.16/-2.28,
 *                 S -1.90/-2.00 %;  40 h P -0.54/-0.57, S -0.48/-0.50 %
 * Bare, P and S are slowed by the same factor (to 1e-5, asserted): F_i is
 * the family average of the gradient and L_i the family average of the
 * divergence, so the operator is the continuum one times a smoothing
 * factor of k delta alone, whatever the polarisation: this is the classic
 * model's own dispersion, about 1.5 times the bond-associated model's
 * (-1.55 % at 20 h). The penalty stiffens only the non-affine part, S
 * more than P. So the 2 % holds from 40 h on (asserted), and at
 * 20 h the bound is 2.5 % (asserted; the worst is P diagonal, -2.28 %). */
static void test_wave_speeds(void **state) {
    (void)state;
    const double h = 1e-3;
    const double r2 = sqrt(0.5);
    const double dirs[2][2] = {{1.0, 0.0}, {r2, r2}}, perp[2][2] = {{0.0, 1.0}, {-r2, r2}};
    const double lengths[3] = {10.0, 20.0, 40.0};
    for (int pass = 0; pass < 2; pass++) {
        CpdConfig c = block(36, 36, h);
        c.stabilisation = pass ? 0.5 : 0.0;
        CpdBody b;
        make(&b, c);
        const double cp = sqrt((b.lambda + 2.0 * b.mu) / RHO), cs = sqrt(b.mu / RHO);
        for (int l = 0; l < 3; l++)
            for (int d = 0; d < 2; d++) {
                const double p =
                    cpd_fixture_plane_wave_speed(&b, lengths[l] * h, dirs[d], dirs[d]) / cp - 1.0;
                const double s =
                    cpd_fixture_plane_wave_speed(&b, lengths[l] * h, dirs[d], perp[d]) / cs - 1.0;
                print_message("C_s %.1f, wavelength %2.0f h, %s: P %+.3f %%, S %+.3f %%\n",
                              c.stabilisation, lengths[l], d ? "diagonal" : "along x", 100 * p,
                              100 * s);
                if (!pass) assert_true(fabs(p - s) < 1e-5);
                if (pass && lengths[l] >= 20.0) {
                    const double bound = lengths[l] >= 40.0 ? 0.02 : 0.025;
                    assert_true(fabs(p) < bound);
                    assert_true(fabs(s) < bound);
                }
            }
        cpd_body_destroy(&b);
    }
}

/* C6: the power-iteration step of the classic operator (the penalty
 * included) is the stability limit. Measured: the kinetic energy never
 * exceeds its start at 0.98, and grows 2.9e6-fold (where the run stops)
 * at 1.05; bounds 10 and 1e3 as in test_solid.c. */
static void test_stable_step(void **state) {
    (void)state;
    const double under = cpd_fixture_energy_growth(CPD_FORCE_CLASSIC, 0.98),
                 over = cpd_fixture_energy_growth(CPD_FORCE_CLASSIC, 1.05);
    print_message("kinetic energy growth: %.3g at 0.98 dt_stable, %.3g at 1.05\n", under, over);
    assert_true(under < 10.0);
    assert_true(over > 1e3);
}

typedef struct {
    double momentum;
    int64_t broken, bonds, n;
    double *damage, *u;
} Shaken;

/* A brittle block pulled apart: momentum, damage and displacement at a
 * given thread count. */
static void run_shaken(int threads, Shaken *out) {
    omp_set_num_threads(threads);
    CpdConfig c = block(16, 16, 1e-3);
    c.damage = CPD_DAMAGE_BRITTLE;
    c.critical_stress = 1.0e9;
    c.damage_ramp = 0.01;
    CpdBody b;
    make(&b, c);
    srand(11);
    for (int64_t i = 0; i < b.n; i++)
        for (int a = 0; a < 2; a++)
            b.v[a][i] = (a == 0 ? (b.x[0][i] > 0.008 ? 20.0 : -20.0) : 0.0) +
                        4.0 * ((double)rand() / RAND_MAX - 0.5);
    double p0[2] = {0, 0}, scale = 0.0;
    for (int64_t i = 0; i < b.n; i++)
        for (int a = 0; a < 2; a++) {
            p0[a] += RHO * b.volume[i] * b.v[a][i];
            scale += RHO * b.volume[i] * fabs(b.v[a][i]);
        }
    for (int s = 0; s < 200; s++) assert_ok(cpd_step(&b, 0.8 * b.stable_dt));
    double p1[2] = {0, 0};
    for (int64_t i = 0; i < b.n; i++)
        for (int a = 0; a < 2; a++) {
            p1[a] += RHO * b.volume[i] * b.v[a][i];
            assert_true(isfinite(b.u[a][i]) && isfinite(b.force[a][i]));
        }
    out->momentum = hypot(p1[0] - p0[0], p1[1] - p0[1]) / scale;
    out->broken = 0;
    for (int64_t k = 0; k < b.bond_count; k++) {
        out->broken += b.damage[k] >= 1.0;
        /* symmetric damage: both ends of a pair hold the same bits */
        assert_memory_equal(&b.damage[k], &b.damage[b.reverse[k]], sizeof(double));
    }
    out->bonds = b.bond_count;
    out->n = b.n;
    out->damage = malloc((size_t)b.bond_count * sizeof(double));
    memcpy(out->damage, b.damage, (size_t)b.bond_count * sizeof(double));
    out->u = malloc((size_t)b.n * sizeof(double));
    memcpy(out->u, b.u[0], (size_t)b.n * sizeof(double));
    cpd_body_destroy(&b);
}

/* C9 for the classic force: momentum to round-off while bonds break
 * (measured 1.1e-16 of the sum of |momenta| after 200 steps with 1862 of
 * 5220 bonds broken; tolerance 1e-13, as for the bond-associated model),
 * both ends of every pair hold the same damage bits, no value is
 * non-finite, and 1 and 2 threads give the same bits. */
static void test_momentum_and_threads_with_damage(void **state) {
    (void)state;
    Shaken one, two;
    run_shaken(1, &one);
    run_shaken(2, &two);
    omp_set_num_threads(2);
    print_message("momentum drift %.3g (1 thread), %.3g (2); %lld of %lld bonds broken\n",
                  one.momentum, two.momentum, (long long)one.broken, (long long)one.bonds);
    assert_true(one.broken > 100);
    assert_true(one.momentum < 1e-13 && two.momentum < 1e-13);
    assert_int_equal(one.broken, two.broken);
    assert_memory_equal(one.damage, two.damage, (size_t)one.bonds * sizeof(double));
    assert_memory_equal(one.u, two.u, (size_t)one.n * sizeof(double));
    free(one.damage);
    free(two.damage);
    free(one.u);
    free(two.u);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_homogeneous_paths_follow_the_material),
        cmocka_unit_test(test_wave_speeds),
        cmocka_unit_test(test_stable_step),
        cmocka_unit_test(test_momentum_and_threads_with_damage),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
