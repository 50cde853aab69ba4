/* Shared set-ups of the immersed-boundary verification cases (header only).
 *
 * Non-dimensionalisation (all cases): R = 1, gamma = 1.4, rho_inf = 1,
 * p_inf = 1/gamma (so c_inf = 1 and T_inf = 1/gamma), U_inf = Ma, reference
 * length L = 1 (cylinder diameter, airfoil chord), mu_inf = rho U L / Re.
 * Viscosity: constant, mu = mu_inf (IBM_CASE_SUTHERLAND_T = 0). The paper
 * gives Ma and Re only. Measured on the cylinder: with constant mu the
 * drag from the fluid's momentum balance is 1.561 at D/32 (0.3 % from the
 * paper's 1.556) and the surface integral 1.572 at D/64, 1.576 at D/128;
 * Sutherland's law with the free stream at 300 K (S = 0.368 T_inf) adds
 * 2.8 % (D/32, t = 30: 1.5675 against 1.5243): at Mach 2 the stagnation
 * region is 1.8 T_inf hot, where that law's mu is 1.52 mu_inf, and the
 * friction drag grows about as sqrt(mu). So the paper's numbers match a
 * constant viscosity (the plain GKS collision time tau = mu / p);
 * Sutherland stays one argument away.
 * Prandtl 0.72.
 *
 * Cylinder (paper 000 Sec. 4.1.2): domain (0, 10) x (0, 12), centre (2, 6),
 * D = 1. Grid (x): [0, 0.6] stretched 0.08 -> h, [0.6, 2.8] uniform h (bow
 * shock at x ~ 0.85, body 1.5 .. 2.5, base region), [2.8, 10] stretched h ->
 * 0.5; (y): [0, 4.6] stretched 0.5 -> h, [4.6, 7.4] uniform h, [7.4, 12]
 * stretched h -> 0.5. The paper's "D/512 near the cylinder, D/2 far" is
 * this layout with h = D/512. Free stream: supersonic inflow at x_min (the
 * state is imposed: all characteristics enter), zeroth-order extrapolation
 * at x_max and on both y faces (the bow shock leaves through x_max; the y
 * faces see the free stream or outgoing waves).
 *
 * Airfoil (paper 000 Sec. 4.1.1): NACA 0012 at zero incidence, leading edge
 * at the origin, chord 1, domain (-10, 20) x (-10, 10). x: [-10, -0.1]
 * stretched 0.5 -> h, [-0.1, 1.3] uniform h, [1.3, 20] stretched h -> 0.5.
 * y: a ladder of uniform segments mirrored about the chord line: [-0.2, 0.2]
 * at h, then 6 segments per side whose spacing grows by (0.5/h)^(1/6) and a
 * last one at ~0.5. Uniform segments have widths L/n, so mirrored cells get
 * bitwise equal widths (a stretched segment's ratio is solved from its
 * first spacing, so a coarse-to-fine segment is not the mirror of a
 * fine-to-coarse one: that made the grid 10 % asymmetric). Boundaries: the
 * characteristic far field (subsonic inflow condition) on all four faces. */
#ifndef NSPD_TEST_IBM_CASES_H
#define NSPD_TEST_IBM_CASES_H

#include "core/status.h"
#include "core/timer.h"
#include "couple/ghost/ibm.h"
#include "couple/ghost/wall_loads.h"
#include "flow/gks/solver.h"
#include "flow/gks/flux_kernel.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define IBM_GAMMA             1.4
#define IBM_CASE_SUTHERLAND_T 0.0 /* <= 0: constant viscosity (see above) */

/* Free stream and gas of a case at Mach `ma`, Reynolds `re` (reference
 * length 1); sutherland_T <= 0 gives a constant viscosity. */
static inline void ibm_case_gas(GksConfig *c, double ma, double re, double sutherland_T,
                                FlowPrim *inf) {
    gks_config_default(c);
    c->gamma = IBM_GAMMA;
    c->gas_constant = 1.0;
    c->prandtl = 0.72;
    const double T_inf = 1.0 / IBM_GAMMA, mu = ma / re;
    c->mu_ref = mu;
    if (sutherland_T > 0.0) {
        c->viscosity = VISCOSITY_SUTHERLAND;
        c->T_ref = T_inf;
        c->sutherland_S = T_inf * 110.4 / sutherland_T;
    } else {
        c->viscosity = VISCOSITY_CONSTANT;
    }
    *inf = (FlowPrim){1.0, ma, 0.0, 1.0 / IBM_GAMMA};
    c->initial = *inf;
}

/* Uniform segments mirrored about the middle of [lo, hi]: a fine core of
 * spacing h and half-width a, then `steps` segments of `cells` cells each
 * whose spacing grows geometrically towards H, then the rest at ~H. */
static inline int ibm_case_ladder(GridSegment *seg, double lo, double hi, double a, double h,
                                  double H, int steps, int cells) {
    const double half = 0.5 * (hi - lo);
    const double r = pow(H / h, 1.0 / (steps + 1));
    GridSegment side[FLOW_MAX_SEGMENTS];
    int ns = 0;
    double used = a, hk = h;
    for (int k = 0; k < steps; k++) {
        hk *= r;
        side[ns++] = (GridSegment){.length = cells * hk, .cells = cells};
        used += cells * hk;
    }
    const double rest = half - used;
    int n = (int)lround(rest / H);
    side[ns++] = (GridSegment){.length = rest, .cells = n < 1 ? 1 : n};
    int q = 0;
    for (int k = ns - 1; k >= 0; k--) seg[q++] = side[k];
    /* an even count: a face, not a centre, on the symmetry line (a centre on it
     * is equidistant from both surfaces, and its tie-break is one-sided) */
    seg[q++] = (GridSegment){.length = 2.0 * a, .cells = 2 * (int)lround(a / h)};
    for (int k = 0; k < ns; k++) seg[q++] = side[k];
    return q;
}

static inline void ibm_cylinder_config(GksConfig *c, double h, double sutherland_T, FlowPrim *inf) {
    ibm_case_gas(c, 2.0, 300.0, sutherland_T, inf);
    c->x0 = 0.0;
    c->y0 = 0.0;
    c->segment_count[0] = 3;
    c->segments[0][0] = (GridSegment){.length = 0.6, .h_start = 0.08, .h_end = h};
    c->segments[0][1] = (GridSegment){.length = 2.2, .h_start = h};
    c->segments[0][2] = (GridSegment){.length = 7.2, .h_start = h, .h_end = 0.5};
    c->segment_count[1] = 3;
    c->segments[1][0] = (GridSegment){.length = 4.6, .h_start = 0.5, .h_end = h};
    c->segments[1][1] = (GridSegment){.length = 2.8, .h_start = h};
    c->segments[1][2] = (GridSegment){.length = 4.6, .h_start = h, .h_end = 0.5};
    const FlowBc in = {.kind = BC_SUPERSONIC_INFLOW, .state = *inf};
    const FlowBc ex = {.kind = BC_EXTRAPOLATION};
    gks_config_set_bc(c, FLOW_FACE_XLO, &in);
    gks_config_set_bc(c, FLOW_FACE_XHI, &ex);
    gks_config_set_bc(c, FLOW_FACE_YLO, &ex);
    gks_config_set_bc(c, FLOW_FACE_YHI, &ex);
}

/* h_le: spacing of the leading-edge box [-0.03, 0.05] x [-a, a] (the nose
 * radius is 0.0158 c: 4 cells at c/256); h_body: spacing along the chord
 * from x = 0.3 to 1.3; the domain is (-up, down) x (-half, half). The
 * paper's layout is h_le = h_body = c/512, a covering the airfoil, domain
 * (-10, 20) x (-10, 10). */
typedef struct {
    double h_le, h_body, a;
    double up, down, half; /* domain extents, chords */
} NacaGrid;

static inline void ibm_naca_config(GksConfig *c, const NacaGrid *n, double sutherland_T,
                                   FlowPrim *inf) {
    ibm_case_gas(c, 0.5, 5000.0, sutherland_T, inf);
    const double H = fmin(0.5, 0.05 * n->half);
    c->x0 = -n->up;
    c->segment_count[0] = 5;
    c->segments[0][0] = (GridSegment){.length = n->up - 0.03, .h_start = H, .h_end = n->h_le};
    c->segments[0][1] = (GridSegment){.length = 0.08, .h_start = n->h_le};
    c->segments[0][2] = (GridSegment){.length = 0.25, .h_start = n->h_le, .h_end = n->h_body};
    c->segments[0][3] = (GridSegment){.length = 1.0, .h_start = n->h_body};
    c->segments[0][4] = (GridSegment){.length = n->down - 1.3, .h_start = n->h_body, .h_end = H};
    c->y0 = -n->half;
    c->segment_count[1] =
        ibm_case_ladder(c->segments[1], -n->half, n->half, n->a, n->h_le, H, 6, 6);
    const FlowBc far = {.kind = BC_SUBSONIC_INFLOW, .state = *inf};
    for (int f = 0; f < 4; f++) gks_config_set_bc(c, f, &far);
}

/* The markers of a body with spacing about h/2 around it. */
static inline int ibm_cylinder_markers(double h, IbmPolyline *p) {
    const int n = 8 * (int)ceil(M_PI / h / 4.0); /* ~2 per cell, multiple of 8 */
    const IbmBodyConfig b = {
        .kind = IBM_BODY_CIRCLE, .center = {2.0, 6.0}, .radius = 0.5, .markers = n < 64 ? 64 : n};
    return ibm_body_markers(&b, p);
}

/* Cosine spacing: pi / markers at mid-chord, ~h_le^2 at the nose. */
static inline int ibm_naca_markers(double h, IbmPolyline *p) {
    int n = 2 * (int)ceil(M_PI / h); /* cosine spacing: h/2 at mid-chord, finer at the ends */
    const IbmBodyConfig b = {
        .kind = IBM_BODY_NACA, .digits = "0012", .chord = 1.0, .markers = n < 128 ? 128 : n};
    return ibm_body_markers(&b, p);
}

/* Grid sequencing: the initial state of a finer solver by bilinear
 * interpolation of a coarser solver's conserved variables (cell centres,
 * ghost values included: near a wall they are the immersed boundary's
 * extrapolations). */
static inline void ibm_case_interp(void *ctx, double x, double y, FlowPrim *out) {
    GksSolver *c = ctx;
    const Grid *g = gks_solver_grid(c);
    const GksFields f = gks_solver_fields(c);
    int ij[2];
    double w[2];
    const double p[2] = {x, y};
    for (int a = 0; a < 2; a++) {
        const GridAxis *ax = &g->ax[a];
        int lo = -1, hi = ax->n;
        if (p[a] <= ax->center[-1])
            hi = 0;
        else if (p[a] >= ax->center[ax->n])
            lo = ax->n - 1;
        while (hi - lo > 1) {
            const int mid = (lo + hi) / 2;
            if (ax->center[mid] <= p[a])
                lo = mid;
            else
                hi = mid;
        }
        lo = lo < -1 ? -1 : lo > ax->n - 1 ? ax->n - 1 : lo;
        ij[a] = lo;
        w[a] = (p[a] - ax->center[lo]) / (ax->center[lo + 1] - ax->center[lo]);
        w[a] = w[a] < 0.0 ? 0.0 : w[a] > 1.0 ? 1.0 : w[a];
    }
    double q[4] = {0, 0, 0, 0};
    for (int m = 0; m < 4; m++) {
        const int i = ij[0] + (m & 1), j = ij[1] + (m >> 1);
        const double wm = ((m & 1) ? w[0] : 1.0 - w[0]) * ((m >> 1) ? w[1] : 1.0 - w[1]);
        for (int v = 0; v < 4; v++) q[v] += wm * f.w[v][grid_index(g, i, j)];
    }
    flow_cons_to_prim(q, gks_solver_gas(c)->gamma, out);
}

/* The cases' flow solver: c at CFL 0.8, started by interpolation of `from`
 * (grid sequencing) when given. NULL on failure. */
static inline GksSolver *ibm_case_solver(GksConfig *c, GksSolver *from) {
    c->cfl = 0.8;
    if (from) {
        c->init_fn = ibm_case_interp;
        c->init_ctx = from;
    }
    GksSolver *s = NULL;
    return gks_solver_create(&s, c) == NSPD_OK ? s : NULL;
}

/* One wall as the attached immersed boundary of s; the flow within
 * soft_start of it starts at rest (0: none, for a flow started from a
 * developed one). NULL on failure. */
static inline Ibm *ibm_case_body(GksSolver *s, const IbmPolyline *wall, double soft_start) {
    Ibm *ibm = NULL;
    if (ibm_create(&ibm, gks_solver_grid(s), wall, 1) != NSPD_OK) return NULL;
    if (ibm_attach(ibm, s) != NSPD_OK) {
        ibm_destroy(&ibm);
        return NULL;
    }
    if (soft_start > 0.0) ibm_soft_start(ibm, s, soft_start);
    return ibm;
}

/* Advances to t_end, printing the coefficients of body 0 every `every`
 * (<= 0: never); leaves the surface of the last state in *sf. */
static inline int ibm_case_advance(GksSolver *s, Ibm *ibm, const IbmReference *ref, IbmSurface *sf,
                                   double t_end, double every, const char *tag) {
    double next = every > 0.0 ? gks_solver_time(s) + every : HUGE_VAL;
    const double t0 = nspd_wall_time();
    while (gks_solver_time(s) < t_end) {
        double dt = gks_solver_stable_dt(s);
        if (gks_solver_time(s) + dt > t_end) dt = t_end - gks_solver_time(s);
        TRY(gks_solver_step(s, dt));
        if (gks_solver_time(s) >= next - 1e-12 || gks_solver_time(s) >= t_end) {
            TRY(ibm_surface_compute(ibm, s, ref, sf));
            const IbmBodyForces *F = &sf->forces[0];
            if (every > 0.0)
                printf("  %s t %6.2f  CD %.4f (p %.4f, v %.4f)  CL %+.2e  Cp_stag %.4f  "
                       "(%lld steps, %.0f s)\n",
                       tag, gks_solver_time(s), F->cd, F->cd_pressure, F->cd_viscous, F->cl,
                       F->cp_stagnation, (long long)gks_solver_step_count(s),
                       nspd_wall_time() - t0);
            next += every;
        }
    }
    return ibm_surface_compute(ibm, s, ref, sf);
}

/* Bow-shock position on the stagnation line y = yc: the first crossing of
 * the mean of the free-stream and normal-shock densities, scanning from x_min
 * (linear between cell centres, average of the two rows next to yc). */
static inline double ibm_case_shock_x(GksSolver *s, double yc, double mach) {
    const Grid *g = gks_solver_grid(s);
    const GksFields f = gks_solver_fields(s);
    const double gm = IBM_GAMMA, m2 = mach * mach;
    const double ratio = (gm + 1.0) * m2 / ((gm - 1.0) * m2 + 2.0);
    const double mid = 0.5 * (1.0 + ratio);
    int j = 0;
    while (j + 1 < g->ny && g->ax[1].center[j + 1] <= yc) j++;
    double prev = 0.0, xp = 0.0;
    for (int i = 0; i < g->nx; i++) {
        const double r = 0.5 * (f.w[0][grid_index(g, i, j)] + f.w[0][grid_index(g, i, j + 1)]);
        const double x = g->ax[0].center[i];
        if (i > 0 && r >= mid && prev < mid) return xp + (x - xp) * (mid - prev) / (r - prev);
        prev = r;
        xp = x;
    }
    return (double)NAN;
}

/* Billig's correlation for the bow-shock stand-off of a cylinder:
 * Delta / R = 0.386 exp(4.67 / M^2) (Billig 1967, J. Spacecraft Rockets 4). */
static inline double ibm_billig_standoff_over_r(double mach) {
    return 0.386 * exp(4.67 / (mach * mach));
}

/* The x-force on whatever is inside the box of cells [i0, i1) x [j0, j1)
 * from the momentum balance of the fluid: minus the flux of x-momentum
 * (rho u u_n + (p - p_ref) n_x - tau_xn) out of the box faces (face values
 * by averaging the two cells, stresses by central differences, mu(T) at the
 * face); the caller subtracts d/dt of *momentum (fluid cells' rho u). An
 * estimate of the drag that does not use the wall treatment at all. */
static inline double ibm_case_box_force(GksSolver *s, const int box[4], double p_ref,
                                        double *momentum) {
    const Grid *g = gks_solver_grid(s);
    const GksFields f = gks_solver_fields(s);
    const GksParams *gas = gks_solver_gas(s);
    const double gm1 = gas->gamma - 1.0, *xc = g->ax[0].center, *yc = g->ax[1].center;
#define IBM_Q(i, j, q)                                                                             \
    (q == 0 ? f.w[0][grid_index(g, i, j)]                                                          \
            : f.w[q][grid_index(g, i, j)] / f.w[0][grid_index(g, i, j)])
    double F = 0.0;
    for (int side = 0; side < 2; side++) { /* faces normal to x */
        const int i = side ? box[1] : box[0];
        const double nx = side ? 1.0 : -1.0;
        for (int j = box[2]; j < box[3]; j++) {
            double m[2][4];
            for (int c = 0; c < 2; c++) {
                const int ii = i - 1 + c;
                const double r = IBM_Q(ii, j, 0), u = IBM_Q(ii, j, 1), v = IBM_Q(ii, j, 2);
                m[c][0] = r, m[c][1] = u, m[c][2] = v;
                m[c][3] = gm1 * (f.w[3][grid_index(g, ii, j)] - 0.5 * r * (u * u + v * v));
            }
            const double r = 0.5 * (m[0][0] + m[1][0]), u = 0.5 * (m[0][1] + m[1][1]);
            const double p = 0.5 * (m[0][3] + m[1][3]);
            const double mu = gks_viscosity(gas, p / (r * gas->R), gas->law);
            const double dudx = (m[1][1] - m[0][1]) / (xc[i] - xc[i - 1]);
            const double dvdy = 0.5 *
                                (IBM_Q(i, j + 1, 2) - IBM_Q(i, j - 1, 2) + IBM_Q(i - 1, j + 1, 2) -
                                 IBM_Q(i - 1, j - 1, 2)) /
                                (yc[j + 1] - yc[j - 1]);
            const double txx = mu * (4.0 / 3.0 * dudx - 2.0 / 3.0 * dvdy);
            F -= (r * u * u + (p - p_ref) - txx) * nx * g->ax[1].width[j];
        }
    }
    for (int side = 0; side < 2; side++) { /* faces normal to y */
        const int j = side ? box[3] : box[2];
        const double ny = side ? 1.0 : -1.0;
        for (int i = box[0]; i < box[1]; i++) {
            const double r0 = IBM_Q(i, j - 1, 0), r1 = IBM_Q(i, j, 0);
            const double u0 = IBM_Q(i, j - 1, 1), u1 = IBM_Q(i, j, 1);
            const double v0 = IBM_Q(i, j - 1, 2), v1 = IBM_Q(i, j, 2);
            const double r = 0.5 * (r0 + r1), u = 0.5 * (u0 + u1), v = 0.5 * (v0 + v1);
            const double p =
                0.5 * gm1 * (f.w[3][grid_index(g, i, j - 1)] + f.w[3][grid_index(g, i, j)]) -
                0.25 * gm1 * (r0 * (u0 * u0 + v0 * v0) + r1 * (u1 * u1 + v1 * v1));
            const double mu = gks_viscosity(gas, p / (r * gas->R), gas->law);
            const double dudy = (u1 - u0) / (yc[j] - yc[j - 1]);
            const double dvdx = 0.5 *
                                (IBM_Q(i + 1, j, 2) - IBM_Q(i - 1, j, 2) + IBM_Q(i + 1, j - 1, 2) -
                                 IBM_Q(i - 1, j - 1, 2)) /
                                (xc[i + 1] - xc[i - 1]);
            F -= (r * u * v - mu * (dudy + dvdx)) * ny * g->ax[0].width[i];
        }
    }
#undef IBM_Q
    double mom = 0.0;
    for (int j = box[2]; j < box[3]; j++)
        for (int i = box[0]; i < box[1]; i++) {
            const int64_t k = grid_index(g, i, j);
            if (f.kind[k] == FLOW_CELL_FLUID)
                mom += f.w[1][k] * g->ax[0].width[i] * g->ax[1].width[j];
        }
    *momentum = mom;
    return F;
}

/* Seconds per ghost fill and per flow step (including its fill), over n of
 * each on the current state (the steps advance it). */
static inline int ibm_case_fill_cost(GksSolver *s, Ibm *ibm, int n, double *fill, double *step) {
    const double dt = gks_solver_stable_dt(s);
    double t0 = nspd_wall_time();
    for (int k = 0; k < n; k++) TRY(gks_solver_step(s, dt));
    *step = (nspd_wall_time() - t0) / n;
    t0 = nspd_wall_time();
    for (int k = 0; k < 10 * n; k++) ibm_fill_ghosts(ibm, s);
    *fill = (nspd_wall_time() - t0) / (10 * n);
    return NSPD_OK;
}

#endif
