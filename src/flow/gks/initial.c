/* The initial condition of the flow operator: cell averages of the
 * configured state (uniform, regions or a function) by Gauss-Legendre
 * quadrature, and the isentropic vortex. */
#include "flow/gks/solver.h"

#include "flow/gks/solver_internal.h"

#include <math.h>

/* Gauss-Legendre points and weights on [-1/2, 1/2] for 1..4 points. */
static void gauss_rule(int n, double *x, double *w) {
    switch (n) {
    case 2: {
        const double a = 0.5 / sqrt(3.0);
        x[0] = -a, x[1] = a;
        w[0] = w[1] = 0.5;
        break;
    }
    case 3: {
        const double a = 0.5 * sqrt(0.6);
        x[0] = -a, x[1] = 0.0, x[2] = a;
        w[0] = w[2] = 5.0 / 18.0;
        w[1] = 8.0 / 18.0;
        break;
    }
    case 4: {
        const double a = 0.5 * sqrt(3.0 / 7.0 - 2.0 / 7.0 * sqrt(1.2));
        const double b = 0.5 * sqrt(3.0 / 7.0 + 2.0 / 7.0 * sqrt(1.2));
        const double wa = (18.0 + sqrt(30.0)) / 72.0, wb = (18.0 - sqrt(30.0)) / 72.0;
        x[0] = -b, x[1] = -a, x[2] = a, x[3] = b;
        w[0] = w[3] = wb;
        w[1] = w[2] = wa;
        break;
    }
    default:
        x[0] = 0.0, w[0] = 1.0;
    }
}

static void initial_prim(const GksConfig *cfg, double x, double y, FlowPrim *q) {
    if (cfg->init_fn) {
        cfg->init_fn(cfg->init_ctx, x, y, q);
        return;
    }
    *q = cfg->initial;
    const double pt[3] = {x, y, 0.0};
    for (int r = 0; r < cfg->region_count; r++)
        if (shapeset_contains(&cfg->regions[r].shapes, pt)) *q = cfg->regions[r].state;
}

/* Cell (i, j)'s average of the conserved variables by the regions' exact
 * area fractions over the background state (the regions do not overlap:
 * the case reader refuses regions whose boxes do). */
static void area_fraction_average(const GksConfig *cfg, const Grid *g, int i, int j, double gamma,
                                  double acc[4]) {
    const double x0 = g->ax[0].face[i], x1 = g->ax[0].face[i + 1];
    const double y0 = g->ax[1].face[j], y1 = g->ax[1].face[j + 1];
    const double area = (x1 - x0) * (y1 - y0);
    double c[4], rest = 1.0;
    for (int r = 0; r < cfg->region_count; r++) {
        const double f =
            shape_area_in_rect(&cfg->regions[r].shapes.shapes[0], x0, x1, y0, y1) / area;
        if (f == 0.0) continue; /* (a touching cell may give -1e-11: kept, for exact sums) */
        flow_prim_to_cons(&cfg->regions[r].state, gamma, c);
        for (int v = 0; v < 4; v++) acc[v] += f * c[v];
        rest -= f;
    }
    flow_prim_to_cons(&cfg->initial, gamma, c);
    for (int v = 0; v < 4; v++) acc[v] += fmax(rest, 0.0) * c[v];
}

void gks_solver_apply_initial(GksSolver *s, const GksConfig *cfg) {
    const Grid *g = &s->grid;
    int nq = cfg->init_quadrature;
    nq = nq < 1 ? 1 : nq > 4 ? 4 : nq;
    double gx[4], gw[4];
    gauss_rule(nq, gx, gw);
    const double gamma = s->gas.gamma;
    for (int j = 0; j < g->ny; j++) {
        for (int i = 0; i < g->nx; i++) {
            double acc[4] = {0.0, 0.0, 0.0, 0.0};
            if (cfg->init_area_fractions) {
                area_fraction_average(cfg, g, i, j, gamma, acc);
                const int64_t k = grid_index(g, i, j);
                for (int v = 0; v < 4; v++) s->w[v][k] = acc[v];
                continue;
            }
            for (int b = 0; b < nq; b++) {
                for (int a = 0; a < nq; a++) {
                    const double x = g->ax[0].center[i] + gx[a] * g->ax[0].width[i];
                    const double y = g->ax[1].center[j] + gx[b] * g->ax[1].width[j];
                    FlowPrim q;
                    double c[4];
                    initial_prim(cfg, x, y, &q);
                    flow_prim_to_cons(&q, gamma, c);
                    for (int v = 0; v < 4; v++) acc[v] += gw[a] * gw[b] * c[v];
                }
            }
            const int64_t k = grid_index(g, i, j);
            for (int v = 0; v < 4; v++) s->w[v][k] = acc[v];
        }
    }
    gks_solver_fill_boundaries(s);
}

void flow_isentropic_vortex(void *ctx, double x, double y, FlowPrim *out) {
    double q[4];
    flow_vortex_state(ctx, x, y, q);
    *out = (FlowPrim){q[0], q[1], q[2], q[3]};
}
