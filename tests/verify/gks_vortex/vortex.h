/* Isentropic vortex in a periodic box [0,10]^2 (Yee et al.; eps = 5,
 * free stream rho = p = 1, R = 1, velocity (1, 1)): set-up and L1 error of
 * the density against the exact (translated) solution, cell averages by 4x4
 * Gauss points. Shared by the order test and the stretched-grid test. */
#ifndef NSPD_TEST_VORTEX_H
#define NSPD_TEST_VORTEX_H

#include "flow/gks/solver.h"
#include "vortex_fixtures.h"

#include <math.h>

/* started at (8, 8) */
static FlowVortex vortex_at(double t) {
    return vortex_fixture_at(8.0, t);
}

/* nseg/segments: NULL for a uniform n x n grid, else the same segment list on both axes.
 * Returns the L1 density error (integral over the box / box area), or -1. */
static double vortex_l1_error(int n, double t_end, FlowLimiter limiter, int nseg,
                              const GridSegment *segments) {
    GksConfig c;
    gks_config_default(&c);
    c.gas_constant = 1.0;
    c.limiter = limiter;
    c.cfl = 0.5;
    gks_config_uniform_grid(&c, 0.0, 10.0, n, 0.0, 10.0, n);
    if (segments) {
        c.segment_count[0] = c.segment_count[1] = nseg;
        for (int k = 0; k < nseg; k++) c.segments[0][k] = c.segments[1][k] = segments[k];
    }
    const FlowBc per = {.kind = BC_PERIODIC};
    for (int f = 0; f < 4; f++) gks_config_set_bc(&c, f, &per);
    FlowVortex v0 = vortex_at(0.0);
    c.init_fn = flow_isentropic_vortex;
    c.init_ctx = &v0;
    c.init_quadrature = 4;
    GksSolver *s = NULL;
    if (gks_solver_create(&s, &c) < 0) return -1.0;
    if (gks_solver_advance(s, t_end, 0) < 0) {
        gks_solver_destroy(&s);
        return -1.0;
    }
    /* exact cell averages: the same quadrature on the translated vortex */
    FlowVortex v1 = vortex_at(t_end);
    const double gx[4] = {-0.5 * sqrt(3.0 / 7.0 + 2.0 / 7.0 * sqrt(1.2)),
                          -0.5 * sqrt(3.0 / 7.0 - 2.0 / 7.0 * sqrt(1.2)),
                          0.5 * sqrt(3.0 / 7.0 - 2.0 / 7.0 * sqrt(1.2)),
                          0.5 * sqrt(3.0 / 7.0 + 2.0 / 7.0 * sqrt(1.2))};
    const double gw[4] = {(18.0 - sqrt(30.0)) / 72.0, (18.0 + sqrt(30.0)) / 72.0,
                          (18.0 + sqrt(30.0)) / 72.0, (18.0 - sqrt(30.0)) / 72.0};
    const Grid *g = gks_solver_grid(s);
    GksFields f = gks_solver_fields(s);
    double err = 0.0;
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) {
            double ex = 0.0;
            for (int b = 0; b < 4; b++)
                for (int a = 0; a < 4; a++) {
                    FlowPrim q;
                    flow_isentropic_vortex(&v1, g->ax[0].center[i] + gx[a] * g->ax[0].width[i],
                                           g->ax[1].center[j] + gx[b] * g->ax[1].width[j], &q);
                    ex += gw[a] * gw[b] * q.rho;
                }
            err += fabs(f.w[0][grid_index(g, i, j)] - ex) * g->ax[0].width[i] * g->ax[1].width[j];
        }
    gks_solver_destroy(&s);
    return err / 100.0;
}

#endif
