/* couple/penalty/relax: the implicit penalty relaxation on plain arrays -
 * the closed form of nearest-cell weights, momentum exact to round-off,
 * no force between equal velocities, the kinetic energy's books with a
 * dissipation >= 0, the strong limit, and a converged solve with bilinear
 * and quadratic weights. */
#include "test_support.h"

#include "couple/penalty/relax.h"

#include <math.h>
#include <stdbool.h>
#include <string.h>

enum { MAX_POINTS = 64, MAX_CELLS = 16, MAX_WIDTH = 9 };

/* A system of `points` points with `width` entries each on `cells` cells,
 * with its cell -> entries index built as the coupling builds it. */
typedef struct {
    PenaltySystem s;
    int32_t col[MAX_POINTS * MAX_WIDTH];
    double w[MAX_POINTS * MAX_WIDTH];
    double m[MAX_POINTS], b[MAX_POINTS], v[2][MAX_POINTS];
    double mass[MAX_CELLS], u[2][MAX_CELLS];
    int64_t first[MAX_CELLS + 1];
    int32_t point[MAX_POINTS * MAX_WIDTH];
    double weight[MAX_POINTS * MAX_WIDTH];
    double sample[MAX_POINTS], x[MAX_CELLS], r[MAX_CELLS], z[MAX_CELLS], p[MAX_CELLS],
        ap[MAX_CELLS], diag[MAX_CELLS];
    PenaltyWork work;
    double J[2][MAX_POINTS];
} Fixture;

static double lcg(unsigned *state) {
    *state = *state * 1664525u + 1013904223u;
    return (double)(*state >> 8) / 16777216.0;
}

/* Random weights (a partition of unity over distinct random cells), masses
 * and velocities; b from a = a_scale * m (strong: b = m). */
static void build(Fixture *f, int points, int width, int cells, double a_scale, bool strong,
                  unsigned seed) {
    memset(f, 0, sizeof *f);
    for (int p = 0; p < points; p++) {
        double sum = 0.0;
        for (int j = 0; j < width; j++) {
            int c;
            bool fresh;
            do { /* distinct cells per point */
                c = (int)(lcg(&seed) * cells) % cells;
                fresh = true;
                for (int k = 0; k < j; k++) fresh = fresh && f->col[p * width + k] != c;
            } while (!fresh);
            f->col[p * width + j] = c;
            f->w[p * width + j] = 0.1 + lcg(&seed);
            sum += f->w[p * width + j];
        }
        for (int j = 0; j < width; j++) f->w[p * width + j] /= sum;
        f->m[p] = 50.0 * (1.0 + lcg(&seed));
        const double a = a_scale * f->m[p];
        f->b[p] = strong ? f->m[p] : a * f->m[p] / (f->m[p] + a);
        f->v[0][p] = 100.0 * (lcg(&seed) - 0.5);
        f->v[1][p] = 100.0 * (lcg(&seed) - 0.5);
    }
    for (int c = 0; c < cells; c++) {
        f->mass[c] = 0.01 * (1.0 + lcg(&seed));
        f->u[0][c] = 10.0 * (lcg(&seed) - 0.5);
        f->u[1][c] = 10.0 * (lcg(&seed) - 0.5);
    }
    for (int e = 0; e < points * width; e++) f->first[f->col[e] + 1]++;
    for (int c = 0; c < cells; c++) f->first[c + 1] += f->first[c];
    int64_t fill[MAX_CELLS];
    for (int c = 0; c < cells; c++) fill[c] = f->first[c];
    for (int e = 0; e < points * width; e++) {
        const int64_t k = fill[f->col[e]]++;
        f->point[k] = e / width;
        f->weight[k] = f->w[e];
    }
    f->work = (PenaltyWork){f->sample, f->x, f->r, f->z, f->p, f->ap, f->diag};
    f->s = (PenaltySystem){.points = points,
                           .width = width,
                           .col = f->col,
                           .w = f->w,
                           .m = f->m,
                           .b = f->b,
                           .v = {f->v[0], f->v[1]},
                           .cells = cells,
                           .mass = f->mass,
                           .u = {f->u[0], f->u[1]},
                           .first = f->first,
                           .point = f->point,
                           .weight = f->weight};
}

/* The cells' momentum change: minus each impulse through the weights. */
static void gas_change(const Fixture *f, int d, double *dm) {
    for (int c = 0; c < f->s.cells; c++) dm[c] = 0.0;
    for (int64_t e = 0; e < f->s.points * f->s.width; e++)
        dm[f->col[e]] -= f->w[e] * f->J[d][e / f->s.width];
}

static void relax(Fixture *f, PenaltyStats *st) {
    double *J[2] = {f->J[0], f->J[1]};
    penalty_relax(&f->s, &f->work, J, st);
}

/* Nearest-cell weights: the system is diagonal and its solution the
 * notes' closed form u' = (m_c u + sum b_P v_P) / (m_c + sum b_P). */
static void test_nearest_closed_form(void **state) {
    (void)state;
    static Fixture f;
    build(&f, 40, 1, 5, 30.0, false, 7u);
    PenaltyStats st;
    relax(&f, &st);
    assert_true(st.iterations <= 1);
    for (int c = 0; c < 5; c++)
        for (int d = 0; d < 2; d++) {
            double num = f.mass[c] * f.u[d][c], den = f.mass[c];
            for (int p = 0; p < 40; p++)
                if (f.col[p] == c) num += f.b[p] * f.v[d][p], den += f.b[p];
            const double u_new = num / den;
            for (int p = 0; p < 40; p++)
                if (f.col[p] == c) assert_close(f.J[d][p], f.b[p] * (u_new - f.v[d][p]), 1e-10);
        }
}

/* Whatever the weights: the gas gains exactly what the points lose, the
 * kinetic energy lost (the heat) is >= 0, and the impulses are those of
 * the backward-Euler step. */
static void check_books(int width, double a_scale, bool strong) {
    static Fixture f;
    build(&f, 48, width, 12, a_scale, strong, 11u + (unsigned)width);
    PenaltyStats st;
    relax(&f, &st);
    assert_true(st.residual <= 1e-12);
    double ke_before = 0.0, ke_after = 0.0;
    double dm[2][MAX_CELLS];
    for (int d = 0; d < 2; d++) {
        gas_change(&f, d, dm[d]);
        double points = 0.0, gas = 0.0, scale = 0.0;
        for (int p = 0; p < 48; p++) {
            points += f.J[d][p];
            scale += fabs(f.J[d][p]);
            const double v_new = f.v[d][p] + f.J[d][p] / f.m[p];
            ke_before += 0.5 * f.m[p] * f.v[d][p] * f.v[d][p];
            ke_after += 0.5 * f.m[p] * v_new * v_new;
        }
        for (int c = 0; c < 12; c++) {
            gas += dm[d][c];
            const double u_new = f.u[d][c] + dm[d][c] / f.mass[c];
            ke_before += 0.5 * f.mass[c] * f.u[d][c] * f.u[d][c];
            ke_after += 0.5 * f.mass[c] * u_new * u_new;
        }
        /* momentum: the bound of the ghost-cell exchange, 1e-12 relative */
        assert_true(fabs(points + gas) <= 1e-12 * scale);
    }
    const double heat = ke_before - ke_after;
    assert_true(heat >= 0.0);
    assert_true(heat > 1e-3 * ke_before); /* it does relax: not a vacuous bound */
    /* the backward-Euler step itself: each impulse is b_P times the slip
     * from the gas's new velocity (holds only once the solve converged) */
    for (int p = 0; p < 48; p++)
        for (int d = 0; d < 2; d++) {
            double s = 0.0;
            for (int j = 0; j < width; j++) {
                const int c = f.col[p * width + j];
                s += f.w[p * width + j] * (f.u[d][c] + dm[d][c] / f.mass[c]);
            }
            assert_close(f.J[d][p], f.b[p] * (s - f.v[d][p]), 1e-9 * f.b[p] * 100.0);
        }
}

static void test_books_nearest(void **state) {
    (void)state;
    check_books(1, 3.0, false);
}

static void test_books_bilinear(void **state) {
    (void)state;
    check_books(4, 3.0, false);
}

static void test_books_quadratic(void **state) {
    (void)state;
    check_books(9, 3.0, false);
    check_books(9, 1e8, false); /* stiff: beta far beyond any explicit bound */
    check_books(9, 0.0, true);
}

/* Points moving with the gas feel nothing: the impulse is round-off. */
static void test_no_force_at_equal_velocity(void **state) {
    (void)state;
    static Fixture f;
    build(&f, 30, 9, 10, 5.0, false, 3u);
    for (int c = 0; c < 10; c++) f.u[0][c] = 123.4, f.u[1][c] = -56.7;
    for (int p = 0; p < 30; p++) f.v[0][p] = 123.4, f.v[1][p] = -56.7;
    PenaltyStats st;
    relax(&f, &st);
    for (int p = 0; p < 30; p++) {
        assert_true(fabs(f.J[0][p]) <= 1e-12 * f.b[p] * 123.4);
        assert_true(fabs(f.J[1][p]) <= 1e-12 * f.b[p] * 56.7);
    }
}

/* The strong limit (b = m): each point leaves with its sampled velocity. */
static void test_strong_limit(void **state) {
    (void)state;
    static Fixture f;
    build(&f, 30, 4, 8, 0.0, true, 5u);
    PenaltyStats st;
    relax(&f, &st);
    assert_true(st.slip_max <= 1e-9);
    double dm[2][MAX_CELLS];
    for (int d = 0; d < 2; d++) gas_change(&f, d, dm[d]);
    for (int p = 0; p < 30; p++)
        for (int d = 0; d < 2; d++) {
            double s = 0.0;
            for (int j = 0; j < 4; j++) {
                const int c = f.col[p * 4 + j];
                s += f.w[p * 4 + j] * (f.u[d][c] + dm[d][c] / f.mass[c]);
            }
            assert_close(f.v[d][p] + f.J[d][p] / f.m[p], s, 1e-9 * 50.0);
        }
}

/* The slip a point keeps after a step falls as 1/C once the penalty is
 * stiff (backward Euler: slip' = slip (1 - b/m) ~ m / (dt k)). */
static void test_slip_falls_as_one_over_c(void **state) {
    (void)state;
    static Fixture f;
    double slip[3];
    for (int k = 0; k < 3; k++) {
        build(&f, 20, 1, 4, 1e3 * pow(10.0, k), false, 9u);
        PenaltyStats st;
        relax(&f, &st);
        slip[k] = st.slip_max;
    }
    assert_close(slip[0] / slip[1], 10.0, 0.1);
    assert_close(slip[1] / slip[2], 10.0, 0.01);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_nearest_closed_form),
        cmocka_unit_test(test_books_nearest),
        cmocka_unit_test(test_books_bilinear),
        cmocka_unit_test(test_books_quadratic),
        cmocka_unit_test(test_no_force_at_equal_velocity),
        cmocka_unit_test(test_strong_limit),
        cmocka_unit_test(test_slip_falls_as_one_over_c),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
