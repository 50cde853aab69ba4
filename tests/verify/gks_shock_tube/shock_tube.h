/* Shared set-up of the shock-tube verification tests: a Riemann problem on
 * (0, 1) with the diaphragm at 0.5, solved along x, along y or at 45 degrees,
 * and the L1 density error against the exact solution (cell averages). */
#ifndef NSPD_TEST_SHOCK_TUBE_H
#define NSPD_TEST_SHOCK_TUBE_H

#include "core/status.h"
#include "flow/gks/solver.h"
#include "flow/riemann_exact.h"

#include <math.h>
#include <stdio.h>

typedef enum { TUBE_X, TUBE_Y, TUBE_DIAGONAL } TubeAxis;

typedef struct {
    const char *name;
    RiemannState left, right;
    double t_end;
} TubeCase;

static const TubeCase SOD = {"sod", {1.0, 0.0, 1.0}, {0.125, 0.0, 0.1}, 0.2};
static const TubeCase LAX = {"lax", {0.445, 0.698, 3.528}, {0.5, 0.0, 0.571}, 0.14};

typedef struct {
    TubeAxis axis;
    double normal[2]; /* unit normal of the diaphragm */
} TubeCtx;

/* Left state where (x, y) lies on the left of the diaphragm through (0.5, 0.5). */
typedef struct {
    const TubeCase *c;
    double nx, ny;
} TubeInit;

static void tube_init(void *ctx, double x, double y, FlowPrim *q) {
    const TubeInit *t = ctx;
    const double xi = (x - 0.5) * t->nx + (y - 0.5) * t->ny;
    const RiemannState *s = xi < 0.0 ? &t->c->left : &t->c->right;
    q->rho = s->rho;
    q->u = s->u * t->nx;
    q->v = s->u * t->ny;
    q->p = s->p;
}

/* Runs the case with n cells along the tube (n x n on the diagonal) and
 * returns the L1 density error per unit length (along the diagonal for
 * TUBE_DIAGONAL: the cells i == j against xi = (x + y - 1)/sqrt 2), or -1. */
static double tube_l1_error(const TubeCase *c, TubeAxis axis, int n, FlowLimiter limiter,
                            const GridSegment *stretched, int nseg, int64_t *fallbacks) {
    GksConfig cfg;
    gks_config_default(&cfg);
    cfg.gamma = 1.4;
    cfg.gas_constant = 1.0;
    cfg.limiter = limiter;
    cfg.cfl = 0.5;
    const FlowBc per = {.kind = BC_PERIODIC}, ext = {.kind = BC_EXTRAPOLATION};
    const GridSegment one = {.length = 1.0, .cells = 1};
    const GridSegment full = {.length = 1.0, .cells = n};
    cfg.x0 = cfg.y0 = 0.0;
    TubeInit ti = {c, 1.0, 0.0};
    for (int f = 0; f < 4; f++) gks_config_set_bc(&cfg, f, &ext);
    cfg.segment_count[0] = cfg.segment_count[1] = 1;
    if (axis == TUBE_X) {
        cfg.segments[0][0] = full;
        cfg.segments[1][0] = one;
        gks_config_set_bc(&cfg, FLOW_FACE_YLO, &per);
        gks_config_set_bc(&cfg, FLOW_FACE_YHI, &per);
    } else if (axis == TUBE_Y) {
        cfg.segments[0][0] = one;
        cfg.segments[1][0] = full;
        gks_config_set_bc(&cfg, FLOW_FACE_XLO, &per);
        gks_config_set_bc(&cfg, FLOW_FACE_XHI, &per);
        ti.nx = 0.0, ti.ny = 1.0;
    } else {
        cfg.segments[0][0] = cfg.segments[1][0] = full;
        ti.nx = ti.ny = sqrt(0.5);
    }
    if (stretched) {
        cfg.segment_count[axis == TUBE_Y ? 1 : 0] = nseg;
        for (int k = 0; k < nseg; k++) cfg.segments[axis == TUBE_Y ? 1 : 0][k] = stretched[k];
    }
    cfg.init_fn = tube_init;
    cfg.init_ctx = &ti;
    cfg.init_quadrature = axis == TUBE_DIAGONAL ? 4 : 1;
    GksSolver *s = NULL;
    if (gks_solver_create(&s, &cfg) < 0) return -1.0;
    const int st = gks_solver_advance(s, c->t_end, 0);
    RiemannSolution sol;
    riemann_exact_solve(&c->left, &c->right, 1.4, &sol);
    const Grid *g = gks_solver_grid(s);
    GksFields f = gks_solver_fields(s);
    double err = 0.0;
    if (axis == TUBE_DIAGONAL) {
        /* diagonal cells: exact average over the cell's extent in xi,
         * approximated by the average over its diagonal [-h/sqrt2, h/sqrt2] */
        for (int i = 0; i < g->nx; i++) {
            const double xc = g->ax[0].center[i], h = g->ax[0].width[i];
            const double xi = (2.0 * xc - 1.0) * sqrt(0.5);
            double ex[3];
            riemann_exact_average(&sol, 0.0, c->t_end, xi - h * sqrt(0.5), xi + h * sqrt(0.5), 64,
                                  ex);
            err += fabs(f.w[0][grid_index(g, i, i)] - ex[0]) * h;
        }
    } else {
        const GridAxis *a = &g->ax[axis == TUBE_X ? 0 : 1];
        for (int i = 0; i < a->n; i++) {
            double ex[3];
            riemann_exact_average(&sol, 0.5, c->t_end, a->face[i], a->face[i + 1], 32, ex);
            const int64_t k = axis == TUBE_X ? grid_index(g, i, 0) : grid_index(g, 0, i);
            err += fabs(f.w[0][k] - ex[0]) * a->width[i];
        }
    }
    if (fallbacks) *fallbacks = gks_solver_fallbacks_total(s);
    gks_solver_destroy(&s);
    return st < 0 ? -1.0 : err;
}

#endif
