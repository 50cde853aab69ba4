/* Laminar flat-plate boundary layer against Blasius (shared set-up).
 *
 * Free stream Mach 0.3 (R = 1, gamma = 1.4, rho = 1, p = 1/gamma so c = 1,
 * U = 0.3), plate from x = 0 to x = 1 on the bottom face (adiabatic no-slip),
 * symmetry ahead of it from x = -upstream, characteristic far field on the
 * inflow and top faces, back pressure at the outflow (x = 1.2). The domain
 * must be large: with the top at 0.25 and the inflow at -0.2 the
 * displacement of the layer sets up a favourable pressure gradient (1.3 % of
 * the dynamic pressure over the plate) and Cf rises to +5 % of Blasius by
 * x = 0.8; with the top at 1.2 and the inflow at -1 the deviation is ~1 %. mu constant with
 * Re_L = rho U L / mu = 1e5. Skin friction from the two wall cells by a
 * one-sided quadratic through u(0) = 0, compared with Cf = 0.664/sqrt(Re_x). */
#ifndef NSPD_TEST_BLASIUS_H
#define NSPD_TEST_BLASIUS_H

#include "core/status.h"
#include "core/timer.h"
#include "flow/gks/solver.h"

#include <math.h>
#include <stdio.h>

typedef struct {
    double dy_wall; /* first cell height */
    double dx_le;   /* spacing at the leading edge */
    double t_end;
    double height;   /* domain height */
    double upstream; /* length of the symmetry plane ahead of the plate */
} BlasiusSetup;

/* Runs the case; writes the worst relative Cf error over x in [x_lo, x_hi]
 * and the mean one; returns the status. */
static int blasius_run(const BlasiusSetup *b, double x_lo, double x_hi, double *worst, double *mean,
                       double *seconds_steps, int verbose) {
    const double U = 0.3, L = 1.0, Re = 1e5, mu = U * L / Re;
    GksConfig c;
    gks_config_default(&c);
    c.gamma = 1.4;
    c.gas_constant = 1.0;
    c.viscosity = VISCOSITY_CONSTANT;
    c.mu_ref = mu;
    c.prandtl = 0.72;
    c.cfl = 0.6;
    c.x0 = -b->upstream;
    c.y0 = 0.0;
    c.segment_count[0] = 2;
    c.segments[0][0] =
        (GridSegment){.length = b->upstream, .h_start = 0.2 * b->upstream, .h_end = b->dx_le};
    c.segments[0][1] = (GridSegment){.length = 1.0, .h_start = b->dx_le, .h_end = 0.03};
    c.segment_count[1] = 1;
    c.segments[1][0] =
        (GridSegment){.length = b->height, .h_start = b->dy_wall, .h_end = 0.08 * b->height};
    const FlowPrim inf = {1.0, U, 0.0, 1.0 / 1.4};
    const FlowBc far = {.kind = BC_SUBSONIC_INFLOW, .state = inf};
    const FlowBc out = {.kind = BC_SUBSONIC_OUTFLOW, .pressure = inf.p};
    gks_config_set_bc(&c, FLOW_FACE_XLO, &far);
    gks_config_set_bc(&c, FLOW_FACE_YHI, &far);
    gks_config_set_bc(&c, FLOW_FACE_XHI, &out);
    c.bc[FLOW_FACE_YLO].count = 2;
    c.bc[FLOW_FACE_YLO].seg[0] = (FlowBc){.kind = BC_SYMMETRY};
    c.bc[FLOW_FACE_YLO].seg[1] = (FlowBc){.kind = BC_NOSLIP_ADIABATIC, .start = 0.0};
    c.initial = inf;
    GksSolver *s = NULL;
    int st = gks_solver_create(&s, &c);
    if (st < 0) return st;
    const double t0 = nspd_wall_time();
    st = gks_solver_advance(s, b->t_end, 0);
    if (st < 0) {
        gks_solver_destroy(&s);
        return st;
    }
    const Grid *g = gks_solver_grid(s);
    GksFields f = gks_solver_fields(s);
    const double y1 = g->ax[1].center[0], y2 = g->ax[1].center[1];
    double w = 0.0, sum = 0.0;
    int n = 0;
    for (int i = 0; i < g->nx; i++) {
        const double x = g->ax[0].center[i];
        if (x < (verbose ? 0.0 : x_lo) || x > (verbose ? 1.0 : x_hi)) continue;
        const int64_t k1 = grid_index(g, i, 0), k2 = grid_index(g, i, 1);
        const double u1 = f.w[1][k1] / f.w[0][k1], u2 = f.w[1][k2] / f.w[0][k2];
        const double dudy = (u1 * y2 * y2 - u2 * y1 * y1) / (y1 * y2 * (y2 - y1));
        const double cf = mu * dudy / (0.5 * inf.rho * U * U);
        const double ref = 0.664 / sqrt(inf.rho * U * x / mu);
        const double e = cf / ref - 1.0;
        if (verbose) {
            const int jt = g->ny - 1;
            const int64_t kt = grid_index(g, i, jt);
            const double pw =
                0.4 * (f.w[3][k1] - 0.5 * (f.w[1][k1] * u1 + f.w[2][k1] * f.w[2][k1] / f.w[0][k1]));
            printf("  x %.4f Re_x %.0f Cf/Cf_Blasius - 1 = %+.4f  p_wall/p_inf - 1 = %+.2e  "
                   "u_top/U - 1 = %+.2e v_top/U %+.2e\n",
                   x, inf.rho * U * x / mu, e, pw / inf.p - 1.0, f.w[1][kt] / f.w[0][kt] / U - 1.0,
                   f.w[2][kt] / f.w[0][kt] / U);
        }
        if (fabs(e) > fabs(w)) w = e;
        sum += e;
        n++;
    }
    *worst = w;
    *mean = n ? sum / n : 0.0;
    seconds_steps[0] = nspd_wall_time() - t0;
    seconds_steps[1] = (double)gks_solver_step_count(s);
    seconds_steps[2] = (double)g->nx * g->ny;
    gks_solver_destroy(&s);
    return NSPD_OK;
}

#endif
