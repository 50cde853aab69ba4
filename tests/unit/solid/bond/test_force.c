/* solid/bond/force, pd_integrate, pd_diagnostics: properties of the discrete
 * PD force that must hold exactly or to round-off. */
#include "pd_fixtures.h"
#include "test_support.h"

#include "solid/bond/body.h"
#include "solid/bond/diagnostics.h"
#include "solid/bond/force.h"
#include "solid/bond/integrate.h"
#include "solid/bond/stencil.h"

#include "core/mem.h"

#include <math.h>
#include <omp.h>
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

/* Two steps of force on body b through pd_force_compute (the lattice view)
 * and through the plain kernel on a copy of the bonds: the same bits,
 * forces and broken bonds, each step; then the elastic energy from the
 * view and from the rows, the same bits. Returns the bonds broken. */
static int64_t view_against_plain(BondBody *b) {
    const int64_t n = b->n, m = b->bond_count;
    float *coef = NULL;
    double *f[3];
    assert_ok(nspd_alloc(&coef, (size_t)m, sizeof *coef));
    for (int d = 0; d < 3; d++) assert_ok(nspd_alloc(&f[d], (size_t)n, 8));
    memcpy(coef, b->bond_coef, (size_t)m * sizeof *coef);
    srand(3);
    for (int step = 0; step < 2; step++) {
        for (int64_t i = 0; i < n; i++) /* stretches up to some 4 % over dx: some bonds break */
            for (int d = 0; d < b->dim; d++)
                b->u[d][i] += 0.02 * b->spacing * ((double)rand() / RAND_MAX - 0.5);
        if (b->dim == 2)
            pd_force_kernel_2d(0, n, b->x[0], b->x[1], b->u[0], b->u[1], b->bond_first, b->bond_nbr,
                               coef, b->coef_scale, b->stretch_limit2, f[0], f[1]);
        else
            pd_force_kernel_3d(0, n, b->x[0], b->x[1], b->x[2], b->u[0], b->u[1], b->u[2],
                               b->bond_first, b->bond_nbr, coef, b->coef_scale, b->stretch_limit2,
                               f[0], f[1], f[2]);
        pd_force_compute(b);
        assert_memory_equal(coef, b->bond_coef, (size_t)m * sizeof *coef);
        for (int d = 0; d < b->dim; d++)
            assert_memory_equal(f[d], b->force[d], (size_t)n * sizeof(double));
    }
    /* the elastic energy from the view and from the rows: the same bits */
    const double via_view = pd_elastic_energy(b);
    BondStencil *view = b->stencil;
    b->stencil = NULL;
    const double via_rows = pd_elastic_energy(b);
    b->stencil = view;
    assert_true(via_rows > 0.0);
    assert_memory_equal(&via_view, &via_rows, sizeof via_rows);
    int64_t broken = 0;
    for (int64_t k = 0; k < m; k++) broken += coef[k] == 0.0f;
    nspd_free(&coef);
    for (int d = 0; d < 3; d++) nspd_free(&f[d]);
    return broken;
}

/* The force through the lattice view (stencil.h) is the plain kernel, bit
 * for bit: in 2D on a block with a hole (cells with no point inside the
 * box), a failure region (breakable and unbreakable bonds) and a
 * pre-crack (bonds broken from the start); in 3D on a block with a
 * spherical hole; on blocks longest along y and z (the view's chunks then
 * lie along that axis); and a thin ring, whose box is too sparse for a
 * view, runs the plain kernel. */
static void test_lattice_view_is_the_plain_kernel(void **state) {
    (void)state;
    PdConfig cfg = fixture_block(2, 37, 21, 0, 1e-3);
    assert_ok(nspd_realloc(&cfg.geometry.shapes, 1, 2, sizeof(Shape)));
    cfg.geometry.count = 2;
    cfg.geometry.shapes[1] = (Shape){
        .kind = SHAPE_DISC, .subtract = true, .center = {20e-3, 10e-3, 0}, .radius = 4.2e-3};
    cfg.failure = true;
    cfg.critical_stretch = 0.004;
    assert_ok(nspd_alloc(&cfg.failure_region.shapes, 1, sizeof(Shape)));
    cfg.failure_region.count = 1;
    cfg.failure_region.shapes[0] =
        (Shape){.kind = SHAPE_RECTANGLE, .lo = {0, 0, 0}, .hi = {30e-3, 21e-3, 0}};
    assert_ok(nspd_alloc(&cfg.precracks, 1, sizeof(PdPrecrack)));
    cfg.precrack_count = 1;
    cfg.precracks[0] = (PdPrecrack){.a = {5e-3, 10.5e-3, 0}, .b = {12e-3, 10.5e-3, 0}};
    BondBody b;
    assert_ok(bond_body_create(&b, &cfg));
    assert_non_null(b.stencil);
    int64_t before = 0;
    for (int64_t k = 0; k < b.bond_count; k++) before += b.bond_coef[k] == 0.0f;
    assert_true(before > 20); /* the pre-crack */
    const int64_t broken = view_against_plain(&b);
    assert_true(broken > before + 100 && broken < b.bond_count / 2);
    bond_body_destroy(&b);

    PdConfig cube = fixture_block(3, 13, 11, 9, 1e-3);
    assert_ok(nspd_realloc(&cube.geometry.shapes, 1, 2, sizeof(Shape)));
    cube.geometry.count = 2;
    cube.geometry.shapes[1] = (Shape){
        .kind = SHAPE_SPHERE, .subtract = true, .center = {6e-3, 5e-3, 4e-3}, .radius = 2.6e-3};
    cube.failure = true;
    cube.critical_stretch = 0.004;
    assert_ok(bond_body_create(&b, &cube));
    assert_non_null(b.stencil);
    assert_true(view_against_plain(&b) > 100);
    bond_body_destroy(&b);

    /* bodies longest along y and along z: the chunks lie along that axis */
    for (int dim = 2; dim <= 3; dim++) {
        PdConfig tall =
            dim == 2 ? fixture_block(2, 7, 30, 0, 1e-3) : fixture_block(3, 5, 6, 14, 1e-3);
        tall.failure = true;
        tall.critical_stretch = 0.004;
        assert_ok(bond_body_create(&b, &tall));
        assert_non_null(b.stencil);
        assert_int_equal(b.stencil->major, dim - 1);
        assert_true(view_against_plain(&b) > 100);
        bond_body_destroy(&b);
    }

    PdConfig ring = fixture_block(2, 400, 400, 0, 1e-3);
    ring.geometry.shapes[0] = (Shape){.kind = SHAPE_ANNULUS,
                                      .center = {200e-3, 200e-3, 0},
                                      .inner_radius = 190e-3,
                                      .radius = 200e-3};
    assert_ok(bond_body_create(&b, &ring));
    assert_null(b.stencil);
    pd_force_compute(&b); /* the plain kernel's path runs */
    bond_body_destroy(&b);
}

/* Steps of a body through the view (the drift keeping the view's
 * displacements, stencil.h; its chunks some on the shared magnitudes,
 * some near the surface with their own) on two threads, and of the same
 * body on the plain path on one: the same bits, displacements and bonds,
 * with both integrators. */
static void test_steps_through_the_view(void **state) {
    (void)state;
    for (int integrator = 0; integrator < 2; integrator++) {
        BondBody with, without;
        for (int k = 0; k < 2; k++) {
            PdConfig cfg = fixture_block(2, 48, 17, 0, 1e-3);
            cfg.integrator = integrator ? PD_VELOCITY_VERLET : PD_EULER_CROMER;
            cfg.failure = true;
            cfg.critical_stretch = 0.002;
            BondBody *b = k ? &without : &with;
            assert_ok(bond_body_create(b, &cfg));
            assert_non_null(b->stencil);
            for (int64_t i = 0; i < b->n; i++) /* pulled apart along x: bonds break */
                b->v[0][i] = 40.0 * (b->x[0][i] - 24e-3) / 24e-3;
        }
        int64_t shared = 0; /* chunks on the shared magnitudes, and with their own */
        for (int64_t q = 0; q < with.stencil->chunks; q++) shared += with.stencil->block[q] == 0;
        assert_true(shared > 0 && shared < with.stencil->chunks);
        bond_stencil_free(&without.stencil);
        /* `with` on two threads, the cuts of its force's chunks skewed to
         * start with (then moved by the times measured, core/balance.h),
         * `without` on one: the same bits, whichever thread takes a point */
        with.force_balance = (Balance){.threads = 2, .cut = {0.0, 0.1, 1.0}};
        const int max = omp_get_max_threads();
        const double dt = 0.8 * pd_stable_time_step(&with);
        for (int s = 0; s < 60; s++) {
            omp_set_num_threads(2);
            assert_ok(pd_step(&with, dt));
            omp_set_num_threads(1);
            assert_ok(pd_step(&without, dt));
        }
        omp_set_num_threads(max);
        for (int d = 0; d < 2; d++)
            assert_memory_equal(with.u[d], without.u[d], (size_t)with.n * sizeof(double));
        assert_memory_equal(with.bond_coef, without.bond_coef,
                            (size_t)with.bond_count * sizeof(float));
        int64_t broken = 0;
        for (int64_t k = 0; k < with.bond_count; k++) broken += with.bond_coef[k] == 0.0f;
        assert_true(broken > 100);
        bond_body_destroy(&with);
        bond_body_destroy(&without);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rigid_motion_gives_no_force),
        cmocka_unit_test(test_newtons_third_law),
        cmocka_unit_test(test_force_is_energy_gradient),
        cmocka_unit_test(test_failure_is_history),
        cmocka_unit_test(test_stable_time_step),
        cmocka_unit_test(test_lattice_view_is_the_plain_kernel),
        cmocka_unit_test(test_steps_through_the_view),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
