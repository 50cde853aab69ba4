/* The correspondence solid as a whole (solid/correspondence/body.h; notes 1c.10):
 * the material integrated in the body on homogeneous paths (every bond,
 * surface ones included, must follow the material point: C7 through the
 * RK consistency), objectivity of the body under a large rigid rotation
 * (C8), wave speeds from the dispersion of the interior operator (C4), the
 * stable step (C6), momentum with damage and thread independence (C9),
 * the damage ramp and Eq. 24 (C11), fragments, and the pressure load's
 * resultant. */
#include "cpd_fixtures.h"
#include "test_support.h"

#include "core/mem.h"
#include "core/status.h"
#include "solid/correspondence/body.h"
#include "solid/correspondence/model.h"
#include "solid/correspondence/rk_gradient.h"

#include <math.h>
#include <omp.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

/* paper 003's steel */
static const double RHO = CPD_STEEL_RHO, YIELD = CPD_STEEL_YIELD, HARD = CPD_STEEL_HARDENING;

static CpdConfig block(int nx, int ny, double h) {
    return cpd_fixture_block(nx, ny, h, CPD_FORCE_BOND_ASSOCIATED);
}

static void make(CpdBody *b, CpdConfig c) {
    assert_ok(cpd_body_create(b, &c));
}

/* Drives the body through homogeneous F(t) (the caller's path) and checks
 * after each increment that every bond's stress and plastic strain equal
 * the material point's, integrated alone with the same midpoint increments. */
static double follow_path(CpdBody *b, const double (*path)[4], int steps) {
    double sig[4] = {0, 0, 0, 0}, eqps = 0.0, worst = 0.0, zz = 0.0;
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
        double dzz;
        j2_update_zz(&b->material, de, sig, &eqps, &dzz);
        zz += dzz;
        const double scale = fabs(sig[0]) + fabs(sig[1]) + fabs(sig[2]) + fabs(sig[3]) + YIELD;
        const int64_t np = b->pairs.count; /* the state is per pair, by component */
        for (int64_t p = 0; p < np; p++) {
            for (int q = 0; q < 4; q++)
                worst = fmax(worst, fabs(b->sigma[q * np + p] - sig[q]) / scale);
            worst = fmax(worst, fabs(b->eqps[p] - eqps) / fmax(eqps, 1e-3));
            if (b->strain_zz)
                worst = fmax(worst, fabs(b->strain_zz[p] - zz) / fmax(fabs(zz), 1e-3));
        }
    }
    return worst;
}

/* C7 in the body: uniaxial strain to 5 % and back, then simple shear to
 * 0.3, on a 12 x 12 block with J2. Every bond, those of surface points
 * too, sees F_b = F (RK consistency) and so the material point's history.
 * Measured: 3.7e-14 (uniaxial, 400 increments) and 1.4e-13 (shear) of
 * the stress over all bonds and steps (round-off of F_b accumulated);
 * tolerance 1e-10, as the issue asks. */
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
    const double uniaxial = follow_path(&b, (const double(*)[4])path, 2 * N);
    print_message("uniaxial strain 5 %% and back: worst bond deviation %.3g\n", uniaxial);
    assert_true(uniaxial < 1e-10);
    assert_true(b.eqps[0] > 0.03); /* it did yield: eps_p(0.05) = 0.0316 loading alone */
    cpd_body_destroy(&b);

    c = block(12, 12, 1e-3);
    c.yield_stress = YIELD;
    c.hardening = HARD;
    make(&b, c);
    for (int s = 0; s <= N; s++)
        path[s][0] = 1.0, path[s][1] = 0.3 * s / N, path[s][2] = 0.0, path[s][3] = 1.0;
    const double shear = follow_path(&b, (const double(*)[4])path, N);
    print_message("simple shear to 0.3: worst bond deviation %.3g\n", shear);
    assert_true(shear < 1e-10);
    cpd_body_destroy(&b);

    /* plane stress: the thickness strain of every bond follows the point's
     * (sum of de_zz; it scales the forces) along a biaxial stretch to 10 % */
    c = block(12, 12, 1e-3);
    c.pd.model = PD_PLANE_STRESS;
    c.yield_stress = YIELD;
    c.hardening = HARD;
    make(&b, c);
    for (int s = 0; s <= N; s++)
        path[s][0] = 1.0 + 0.1 * s / N, path[s][1] = 0.0, path[s][2] = 0.0,
        path[s][3] = 1.0 + 0.03 * s / N;
    const double stress = follow_path(&b, (const double(*)[4])path, N);
    print_message("plane stress biaxial 10 %%: worst bond deviation %.3g, thickness strain %.5f\n",
                  stress, b.strain_zz[0]);
    assert_true(stress < 1e-10);
    assert_true(b.strain_zz[0] < -0.05); /* plastic flow thins the plate */
    cpd_body_destroy(&b);
}

/* C8 in the body: a block stretched 0.1 % (elastic), then turned rigidly
 * by 90 degrees in 100 steps: the unrotated stresses must not move and the
 * forces must turn with the body. Measured: stress change 5.9e-12 of the
 * stress, force 3.2e-12 of the largest force; tolerances 1e-10 and 1e-9. */
static void test_rigid_rotation_keeps_the_stress(void **state) {
    (void)state;
    CpdBody b;
    make(&b, block(10, 10, 1e-3));
    enum { N = 100 };
    const double stretch[4] = {1.001, 0.0, 0.0, 1.0};
    static double path[2][4];
    memcpy(path[0], (double[4]){1, 0, 0, 1}, sizeof path[0]);
    memcpy(path[1], stretch, sizeof path[1]);
    follow_path(&b, (const double(*)[4])path, 1);
    const int64_t nb = b.pairs.count; /* the state is per pair */
    double *sigma0 = malloc((size_t)(4 * nb) * sizeof(double));
    double *f0[2] = {malloc((size_t)b.n * sizeof(double)), malloc((size_t)b.n * sizeof(double))};
    memcpy(sigma0, b.sigma, (size_t)(4 * nb) * sizeof(double));
    memcpy(f0[0], b.force[0], (size_t)b.n * sizeof(double));
    memcpy(f0[1], b.force[1], (size_t)b.n * sizeof(double));
    double fmax_ = 0.0;
    for (int64_t i = 0; i < b.n; i++) fmax_ = fmax(fmax_, hypot(f0[0][i], f0[1][i]));
    for (int s = 1; s <= N; s++) {
        const double t0 = 0.5 * M_PI * (s - 1) / N, t1 = 0.5 * M_PI * s / N;
        const double R0[4] = {cos(t0), -sin(t0), sin(t0), cos(t0)};
        const double R1[4] = {cos(t1), -sin(t1), sin(t1), cos(t1)};
        double F0[4], F1[4];
        for (int r = 0; r < 2; r++)
            for (int q = 0; q < 2; q++) {
                F0[2 * r + q] = R0[2 * r] * stretch[q] + R0[2 * r + 1] * stretch[2 + q];
                F1[2 * r + q] = R1[2 * r] * stretch[q] + R1[2 * r + 1] * stretch[2 + q];
            }
        cpd_fixture_homogeneous(&b, b.u_prev, F0);
        cpd_fixture_homogeneous(&b, b.u, F1);
        cpd_force(&b, 0.0);
    }
    double ds = 0.0, df = 0.0;
    for (int64_t k = 0; k < 4 * nb; k++)
        ds = fmax(ds, fabs(b.sigma[k] - sigma0[k]) / (fabs(sigma0[0]) + 1.0));
    /* at 90 degrees the force (fx, fy) has become (-fy, fx) */
    for (int64_t i = 0; i < b.n; i++)
        df = fmax(df, hypot(b.force[0][i] + f0[1][i], b.force[1][i] - f0[0][i]) / fmax_);
    print_message("90 degree rotation: stress change %.3g, force change %.3g\n", ds, df);
    assert_true(ds < 1e-10);
    assert_true(df < 1e-9);
    free(sigma0);
    free(f0[0]);
    free(f0[1]);
    cpd_body_destroy(&b);
}

/* C4: the P and shear wave speeds of plane strain steel (5770.8 and
 * 3138.5 m/s) from the interior operator, along x and along the diagonal.
 * The paper's RK order 2, measured at 20 h: P -1.55 % (along x) and
 * -1.65 % (diagonal), S -1.54 % and -1.63 %; at 40 h -0.39 to -0.42 %; at
 * 10 h -5.8 to -6.3 %: second order in h / wavelength, nearly isotropic.
 * Tolerance: the 2 % from 20 h on (the margin at 20 h is 0.35 %:
 * this is the real bound). RK order 3: -0.44 to -0.48 % at 20 h, -0.11 to
 * -0.12 % at 40 h, -1.9 to -2.0 % at 10 h (still second order: the bond's
 * F_b averages F_i and F_j); bound 0.6 % from 20 h, so the gain is held. */
static void wave_speeds(int order, double bound) {
    const double h = 1e-3;
    CpdBody b;
    CpdConfig c = block(36, 36, h);
    c.rk_order = order;
    make(&b, c);
    const double cp = sqrt((b.lambda + 2.0 * b.mu) / RHO), cs = sqrt(b.mu / RHO);
    assert_true(fabs(cp - 5770.8) < 0.5 && fabs(cs - 3138.5) < 0.5);
    const double r2 = sqrt(0.5);
    const double dirs[2][2] = {{1.0, 0.0}, {r2, r2}}, perp[2][2] = {{0.0, 1.0}, {-r2, r2}};
    const double lengths[3] = {10.0, 20.0, 40.0};
    for (int l = 0; l < 3; l++)
        for (int d = 0; d < 2; d++) {
            const double p =
                cpd_fixture_plane_wave_speed(&b, lengths[l] * h, dirs[d], dirs[d]) / cp - 1.0;
            const double s =
                cpd_fixture_plane_wave_speed(&b, lengths[l] * h, dirs[d], perp[d]) / cs - 1.0;
            print_message("order %d, wavelength %2.0f h, %s: P %+.3f %%, S %+.3f %%\n", order,
                          lengths[l], d ? "diagonal" : "along x", 100 * p, 100 * s);
            if (lengths[l] >= 20.0) {
                assert_true(fabs(p) < bound);
                assert_true(fabs(s) < bound);
            }
        }
    cpd_body_destroy(&b);
}

static void test_wave_speeds(void **state) {
    (void)state;
    wave_speeds(2, 0.02);
    wave_speeds(3, 0.006);
}

/* C6: the power-iteration step is the stability limit: 2 % under it the
 * energy stays bounded for 1000 steps, 5 % over it the highest mode grows.
 * Measured: the kinetic energy never exceeds its start at 0.98; at 1.05 it
 * has grown 1.1e6-fold after 18 steps. */
static void test_stable_step(void **state) {
    (void)state;
    const double under = cpd_fixture_energy_growth(CPD_FORCE_BOND_ASSOCIATED, 0.98),
                 over = cpd_fixture_energy_growth(CPD_FORCE_BOND_ASSOCIATED, 1.05);
    print_message("kinetic energy growth: %.3g at 0.98 dt_stable, %.3g at 1.05\n", under, over);
    assert_true(under < 10.0);
    assert_true(over > 1e3);
}

/* A brittle block shaken hard enough to break bonds: momentum and the
 * damage field at 1 and 2 threads. */
typedef struct {
    double momentum;
    int64_t broken, bonds, n;
    double *damage, *u;
    bool refresh_whole; /* the kept 1 / w0 and coefficients equal a full refresh's */
} Shaken;

/* form_fb: F_b at each step's start formed again from F at u_prev instead
 * of taken from the last step (the body's Fb_now cleared after each step) */
static void run_shaken(int threads, bool form_fb, Shaken *out) {
    omp_set_num_threads(threads);
    CpdConfig c = block(16, 16, 1e-3);
    c.damage = CPD_DAMAGE_BRITTLE;
    c.critical_stress = 1.0e9;
    c.damage_ramp = 0.01;
    CpdBody b;
    make(&b, c);
    /* the halves pulled apart at +-20 m/s, with a random part of +-2 m/s */
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
    for (int s = 0; s < 200; s++) {
        assert_ok(cpd_step(&b, 0.8 * b.stable_dt));
        if (form_fb) b.Fb_now = false;
    }
    double p1[2] = {0, 0};
    for (int64_t i = 0; i < b.n; i++)
        for (int a = 0; a < 2; a++) p1[a] += RHO * b.volume[i] * b.v[a][i];
    out->momentum = hypot(p1[0] - p0[0], p1[1] - p0[1]) / scale;
    out->broken = 0;
    for (int64_t k = 0; k < b.bond_count; k++) out->broken += b.damage[k] >= 1.0;
    out->bonds = b.bond_count;
    out->n = b.n;
    out->damage = malloc((size_t)b.bond_count * sizeof(double));
    memcpy(out->damage, b.damage, (size_t)b.bond_count * sizeof(double));
    out->u = malloc((size_t)b.n * sizeof(double));
    memcpy(out->u, b.u[0], (size_t)b.n * sizeof(double));
    /* the weights were refreshed only where damage changed, step by step:
     * the same bits as refreshing all of them now */
    const size_t nb = (size_t)b.bond_count, n = (size_t)b.n;
    double *kept = malloc((4 * nb + 3 * n) * sizeof(double));
    memcpy(kept, b.coef_c, nb * sizeof(double));
    memcpy(kept + nb, b.phi_rev, 2 * nb * sizeof(double));
    memcpy(kept + 3 * nb, b.phi_sum, 2 * n * sizeof(double));
    memcpy(kept + 3 * nb + 2 * n, b.inv_w0, n * sizeof(double));
    cpd_inverse_weights(&b);
    out->refresh_whole = memcmp(kept, b.coef_c, nb * sizeof(double)) == 0 &&
                         memcmp(kept + nb, b.phi_rev, 2 * nb * sizeof(double)) == 0 &&
                         memcmp(kept + 3 * nb, b.phi_sum, 2 * n * sizeof(double)) == 0 &&
                         memcmp(kept + 3 * nb + 2 * n, b.inv_w0, n * sizeof(double)) == 0;
    free(kept);
    cpd_body_destroy(&b);
}

/* C9: momentum to round-off while bonds break (measured 1.0e-16 of the sum
 * of |momenta| after 200 steps with 590 of 5220 bonds broken, sub-steps
 * included; tolerance 1e-13), and 1 and 2 threads give the same damage and
 * displacement bits; so does forming F_b at every step's start instead of
 * keeping the last step's, and the weights refreshed only where damage
 * changed equal a whole refresh. */
static void test_momentum_and_threads_with_damage(void **state) {
    (void)state;
    Shaken one, two, formed;
    run_shaken(1, false, &one);
    run_shaken(2, false, &two);
    run_shaken(2, true, &formed);
    assert_true(one.refresh_whole && two.refresh_whole && formed.refresh_whole);
    assert_memory_equal(formed.u, two.u, (size_t)two.n * sizeof(double));
    assert_memory_equal(formed.damage, two.damage, (size_t)two.bonds * sizeof(double));
    free(formed.damage);
    free(formed.u);
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

/* C11: a homogeneous plastic stretch past eps_th: every bond's damage is
 * the ramp of its plastic strain (all bonds alike), the weights are
 * recomputed with the damaged kernel (a uniform scale leaves them equal),
 * and once every bond is broken every point is debris and Eq. 24 counts
 * the whole mass. */
static void test_ductile_damage_ramp(void **state) {
    (void)state;
    CpdConfig c = block(10, 10, 1e-3);
    c.yield_stress = YIELD;
    c.hardening = HARD;
    c.damage = CPD_DAMAGE_DUCTILE;
    c.plastic_strain_threshold = 0.18;
    c.plastic_strain_critical = 0.2;
    CpdBody b;
    make(&b, c);
    double *phi0 = malloc((size_t)(2 * b.bond_count) * sizeof(double));
    memcpy(phi0, b.phi, (size_t)(2 * b.bond_count) * sizeof(double));
    double *fresh = malloc((size_t)(2 * b.bond_count) * sizeof(double));
    uint8_t *ok = malloc((size_t)b.n);
    double prev[4] = {1, 0, 0, 1}, F[4] = {1, 0, 0, 1};
    int checked = 0;
    double worst = 0.0;
    for (int s = 1; s <= 400 && b.damage[0] < 1.0; s++) {
        memcpy(prev, F, sizeof F);
        F[0] = 1.0 + 0.5 * s / 400.0;
        cpd_fixture_homogeneous(&b, b.u_prev, prev);
        cpd_fixture_homogeneous(&b, b.u, F);
        cpd_force(&b, 0.0);
        const double expect = j2_damage_ductile(b.eqps[0], 0.18, 0.2);
        for (int64_t k = 0; k < b.bond_count; k++) /* eqps alike to 1e-13 (above) */
            assert_close(b.damage[k], b.damage[0], 1e-9);
        if (b.damage[0] < 1.0) assert_close(b.damage[0], expect, 1e-15);
        if (b.damage[0] > 0.0 && b.damage[0] < 1.0) {
            checked++;
            /* recomputed: the same bits as weights computed afresh with the
             * damaged kernel; and at points with whole families (24 bonds)
             * equal to the undamaged ones, relative to the point's largest
             * weight, as a uniform scale must leave them (near corners the
             * moment matrix is too ill-conditioned for that comparison:
             * the scale varies in its last bits from bond to bond). The
             * bound: measured up to 1.22e-12 of the largest weight on an
             * AMD EPYC (GCC tuned for znver3, 512-bit lanes), below 1e-12
             * on the Xeon the golden files came from; the moment matrix's
             * inverse loses about cond ~ 1e4 times eps */
            const double *const *x = (const double *const *)b.x;
            assert_int_equal(rk_gradient_weights(2, b.n, x, b.volume, b.first, b.nbr, b.delta,
                                                 b.scale, fresh, ok),
                             0);
            assert_memory_equal(fresh, b.phi, (size_t)(2 * b.bond_count) * sizeof(double));
            for (int64_t i = 0; i < b.n; i++) {
                if (b.first[i + 1] - b.first[i] != 24) continue;
                double big = 0.0;
                for (int64_t q = 2 * b.first[i]; q < 2 * b.first[i + 1]; q++)
                    big = fmax(big, fabs(phi0[q]));
                for (int64_t q = 2 * b.first[i]; q < 2 * b.first[i + 1]; q++) {
                    worst = fmax(worst, fabs(b.phi[q] - phi0[q]) / big);
                    assert_close(b.phi[q], phi0[q], 3e-12 * big);
                }
            }
        }
    }
    print_message("ramp checked at %d intermediate damage levels; weights within %.2e of the "
                  "undamaged\n",
                  checked, worst);
    assert_true(checked >= 3);
    assert_true(b.damage[0] == 1.0);
    double *dmean = malloc((size_t)b.n * sizeof(double));
    cpd_point_damage(&b, dmean, NULL);
    assert_close(cpd_mass_loss(&b, dmean), 1.0, 0.0);
    assert_int_equal(cpd_fully_damaged(&b, dmean), b.n);
    for (int64_t i = 0; i < b.n; i++) dmean[i] = i % 4 == 0 ? 0.99 : 0.989;
    int64_t count = 0;
    for (int64_t i = 0; i < b.n; i++) count += i % 4 == 0;
    assert_close(cpd_mass_loss(&b, dmean), (double)count / (double)b.n, 1e-15);
    assert_int_equal(cpd_fully_damaged(&b, dmean), count); /* 0.99 counts, 0.989 does not */
    assert_close(cpd_partly_damaged(&b, dmean), 1.0 - (double)count / (double)b.n, 1e-15);
    for (int64_t i = 0; i < b.n; i += 2) dmean[i] = 0.0; /* undamaged: neither */
    int64_t partly = 0;
    for (int64_t i = 0; i < b.n; i++) partly += i % 2 == 1;
    assert_close(cpd_partly_damaged(&b, dmean), (double)partly / (double)b.n, 1e-15);
    int64_t debris;
    assert_int_equal(cpd_fragment_count(&b, &debris), 0);
    assert_int_equal(debris, b.n);
    free(dmean);
    free(phi0);
    free(fresh);
    free(ok);
    cpd_body_destroy(&b);
}

/* A pre-crack across the whole block leaves two fragments; a closed
 * pressurised cavity pushes with zero resultant, and one face with p
 * times its length times the thickness. */
static void test_fragments_and_pressure(void **state) {
    (void)state;
    CpdConfig c = block(20, 20, 1e-3);
    c.pd.precrack_count = 1;
    assert_ok(nspd_alloc(&c.pd.precracks, 1, sizeof(PdPrecrack)));
    c.pd.precracks[0].a[0] = -1.0, c.pd.precracks[0].a[1] = 0.0101;
    c.pd.precracks[0].b[0] = 1.0, c.pd.precracks[0].b[1] = 0.0101;
    CpdBody b;
    make(&b, c);
    int64_t debris;
    assert_int_equal(cpd_fragment_count(&b, &debris), 2);
    assert_int_equal(debris, 0);
    cpd_body_destroy(&b);

    /* a 20 x 20 mm block with a 10 x 10 mm cavity; the cavity at 1 MPa */
    c = block(20, 20, 1e-3);
    Shape *shapes;
    assert_ok(nspd_alloc(&shapes, 2, sizeof(Shape)));
    shapes[0] = c.pd.geometry.shapes[0];
    shapes[1] = (Shape){.kind = SHAPE_RECTANGLE, .lo = {0.005, 0.005, 0}, .hi = {0.015, 0.015, 0}};
    shapes[1].subtract = true;
    nspd_free(&c.pd.geometry.shapes);
    c.pd.geometry.shapes = shapes;
    c.pd.geometry.count = 2;
    c.pressure_count = 1;
    assert_ok(nspd_alloc(&c.pressures, 1, sizeof(CpdPressure)));
    c.pressures[0].region.count = 1;
    assert_ok(nspd_alloc(&c.pressures[0].region.shapes, 1, sizeof(Shape)));
    c.pressures[0].region.shapes[0] = shapes[1];
    c.pressures[0].region.shapes[0].subtract = false;
    c.pressures[0].peak = 1e6;
    make(&b, c);
    cpd_force(&b, 1.0); /* u = 0: only the pressure */
    double total[2] = {0, 0}, left = 0.0;
    for (int64_t i = 0; i < b.n; i++) {
        total[0] += b.force[0][i] * b.volume[i];
        total[1] += b.force[1][i] * b.volume[i];
        if (b.x[0][i] < 0.005 && b.x[0][i] > 0.004) left += b.force[0][i] * b.volume[i];
    }
    print_message("cavity resultant (%.3g, %.3g) N; left face %.6g N\n", total[0], total[1], left);
    assert_true(fabs(total[0]) < 1e-9 && fabs(total[1]) < 1e-9);
    /* the left face: 10 mm long, thickness 1 mm (fixture), pushed to -x */
    assert_close(left, -1e6 * 0.01 * 1e-3, 1e-9);
    cpd_body_destroy(&b);
}

/* The debris rule: two pre-cracks across a 12 x 12 block, one spacing
 * apart, leave the row between them with collinear families (no quadratic
 * fit in y): all 12 points become debris, their bonds break from both
 * ends, the block is two fragments, and a stretched step gives finite
 * forces everywhere. */
static void test_debris_rule(void **state) {
    (void)state;
    const double h = 1e-3;
    CpdConfig c = block(12, 12, h);
    assert_ok(nspd_alloc(&c.pd.precracks, 2, sizeof(PdPrecrack)));
    c.pd.precrack_count = 2;
    for (int k = 0; k < 2; k++) {
        c.pd.precracks[k].a[0] = -1.0, c.pd.precracks[k].b[0] = 1.0;
        c.pd.precracks[k].a[1] = c.pd.precracks[k].b[1] = (6.0 + k) * h;
    }
    CpdBody b;
    make(&b, c);
    int64_t debris, lost = 0;
    assert_int_equal(cpd_fragment_count(&b, &debris), 2);
    assert_int_equal(debris, 12);
    for (int64_t i = 0; i < b.n; i++) {
        const bool middle = fabs(b.x[1][i] - 6.5 * h) < 0.1 * h;
        assert_int_equal(b.ok[i], middle ? 0 : 1);
        lost += middle;
    }
    assert_int_equal(lost, 12);
    const double F[4] = {1.001, 0.0, 0.0, 1.002};
    cpd_fixture_homogeneous(&b, b.u, F);
    assert_ok(cpd_step(&b, 0.5 * b.stable_dt));
    for (int64_t i = 0; i < b.n; i++)
        assert_true(isfinite(b.force[0][i]) && isfinite(b.force[1][i]));
    cpd_body_destroy(&b);
}

/* The critical-stretch law kept for comparison with bond-based PD: under
 * F = diag(1.011, 1) and s_c = 0.01 exactly the bonds along x (stretch
 * 0.011) break; the diagonal ones (at most 0.0088) and those along y stay. */
static void test_stretch_law(void **state) {
    (void)state;
    CpdConfig c = block(10, 10, 1e-3);
    c.damage = CPD_DAMAGE_STRETCH;
    c.critical_stretch = 0.01;
    CpdBody b;
    make(&b, c);
    const double F[4] = {1.011, 0.0, 0.0, 1.0};
    cpd_fixture_homogeneous(&b, b.u_prev, (const double[4]){1, 0, 0, 1});
    cpd_fixture_homogeneous(&b, b.u, F);
    cpd_force(&b, 0.0);
    int64_t broken = 0;
    for (int64_t i = 0; i < b.n; i++)
        for (int64_t k = b.first[i]; k < b.first[i + 1]; k++) {
            const bool along_x = b.x[1][b.nbr[k]] == b.x[1][i];
            assert_true(b.damage[k] == (along_x ? 1.0 : 0.0));
            broken += along_x;
        }
    assert_true(broken > 0);
    cpd_body_destroy(&b);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_homogeneous_paths_follow_the_material),
        cmocka_unit_test(test_rigid_rotation_keeps_the_stress),
        cmocka_unit_test(test_wave_speeds),
        cmocka_unit_test(test_stable_step),
        cmocka_unit_test(test_momentum_and_threads_with_damage),
        cmocka_unit_test(test_ductile_damage_ramp),
        cmocka_unit_test(test_fragments_and_pressure),
        cmocka_unit_test(test_debris_rule),
        cmocka_unit_test(test_stretch_law),
    };
    if (getenv("TEST_FILTER")) cmocka_set_test_filter(getenv("TEST_FILTER"));
    return cmocka_run_group_tests(tests, NULL, NULL);
}
