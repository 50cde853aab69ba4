#include "cpd_fixtures.h"

#include "pd_fixtures.h"
#include "test_support.h"

#include "core/status.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

CpdConfig cpd_fixture_block(int nx, int ny, double h, CpdForce force) {
    CpdConfig c = {0};
    c.pd = fixture_block(2, nx, ny, 0, h);
    c.pd.model = PD_PLANE_STRAIN;
    c.pd.horizon_factor = 2.5;
    c.pd.density = CPD_STEEL_RHO;
    c.pd.youngs_modulus = CPD_STEEL_E;
    c.pd.integrator = PD_VELOCITY_VERLET;
    c.poisson_ratio = CPD_STEEL_NU;
    c.force = force;
    c.stabilisation = force == CPD_FORCE_CLASSIC ? 0.5 : 0.0;
    c.family = CPD_FAMILY_SQUARE;
    c.damage = CPD_DAMAGE_NONE;
    return c;
}

void cpd_fixture_homogeneous(const CpdBody *b, double *const u[3], const double F[4]) {
    for (int64_t i = 0; i < b->n; i++) {
        const double X = b->x[0][i], Y = b->x[1][i];
        u[0][i] = (F[0] - 1.0) * X + F[1] * Y;
        u[1][i] = F[2] * X + (F[3] - 1.0) * Y;
    }
}

double cpd_fixture_plane_wave_speed(CpdBody *b, double wavelength, const double n[2],
                                    const double e[2]) {
    const double k = 2.0 * M_PI / wavelength, A = 1e-9;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int64_t i = 0; i < b->n; i++)
        for (int a = 0; a < 2; a++) {
            lo[a] = fmin(lo[a], b->x[a][i]);
            hi[a] = fmax(hi[a], b->x[a][i]);
        }
    for (int64_t i = 0; i < b->n; i++) {
        const double s = A * sin(k * (n[0] * b->x[0][i] + n[1] * b->x[1][i]));
        for (int a = 0; a < 2; a++) {
            b->u[a][i] = s * e[a];
            b->u_prev[a][i] = 0.0;
        }
    }
    /* the material state: per point (classic) or per bond pair */
    const int64_t states = b->cfg.force == CPD_FORCE_CLASSIC ? b->n : b->pairs.count;
    memset(b->sigma, 0, (size_t)(4 * states) * sizeof(double));
    cpd_force(b, 0.0);
    const double margin = 3.5 * b->delta;
    double num = 0.0, den = 0.0;
    for (int64_t i = 0; i < b->n; i++) {
        if (b->x[0][i] < lo[0] + margin || b->x[0][i] > hi[0] - margin ||
            b->x[1][i] < lo[1] + margin || b->x[1][i] > hi[1] - margin)
            continue;
        for (int a = 0; a < 2; a++) {
            num -= b->force[a][i] * b->u[a][i];
            den += CPD_STEEL_RHO * b->u[a][i] * b->u[a][i];
        }
    }
    return sqrt(num / den) / k;
}

double cpd_fixture_kinetic(const CpdBody *b) {
    double e = 0.0;
    for (int64_t i = 0; i < b->n; i++)
        e += 0.5 * CPD_STEEL_RHO * b->volume[i] *
             (b->v[0][i] * b->v[0][i] + b->v[1][i] * b->v[1][i]);
    return e;
}

double cpd_fixture_energy_growth(CpdForce force, double factor) {
    CpdBody b;
    CpdConfig c = cpd_fixture_block(16, 16, 1e-3, force);
    assert_ok(cpd_body_create(&b, &c));
    srand(7);
    for (int64_t i = 0; i < b.n; i++)
        for (int a = 0; a < 2; a++) b.v[a][i] = 1e-3 * ((double)rand() / RAND_MAX - 0.5);
    const double e0 = cpd_fixture_kinetic(&b), dt = factor * b.stable_dt;
    double emax = e0;
    int s = 0;
    for (; s < 1000 && emax < 1e6 * e0; s++) {
        assert_ok(cpd_step(&b, dt));
        emax = fmax(emax, cpd_fixture_kinetic(&b));
    }
    print_message("%.2f dt_stable: %d steps\n", factor, s);
    cpd_body_destroy(&b);
    return emax / e0;
}
