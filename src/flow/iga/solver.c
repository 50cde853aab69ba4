#include "flow/iga/solver.h"

#include "core/exact_sum.h"
#include "core/mem.h"
#include "core/parallel.h"
#include "core/status.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

struct IgaSolver {
    IgaConfig cfg;
    IgaAxis ax[2];
    /* this process's window of the control points (decomp.h): every
     * per-point array is the window's, every per-element one its local
     * elements'; on one process the whole */
    IgaDecomp dc;
    int ncx, ncy;   /* control points per axis in the window */
    int64_t ncp;    /* ncx ncy */
    int nex;        /* local elements along x */
    int64_t nel;    /* local elements */
    int gncx, gncy; /* control points per axis of the whole */
    int width;      /* p + 1 */
    int local;      /* (p + 1)^2 functions per element */
    IgaQpParams qp;
    double am, af, gam; /* generalised-alpha: alpha_m, alpha_f, gamma */
    /* control arrays, 4 (or 16) doubles per control point */
    double *Y, *Yd, *Yn, *Ydn, *Ya, *Yda, *R, *M;
    /* element-owned slots: local x 4 residual, local x 16 mass, nu max */
    double *eR, *eM, *eNu;
    double *mass; /* per control point: add_lumped's masses */
    /* point sources (iga_solver_set_sources): src_n points, each with the
     * local control points and basis values of its element and its force
     * and power */
    int64_t src_n;
    int64_t *src_cp;
    double *src_w, *src_f;
    /* per axis and control index: the elements that touch it (ascending)
     * and the local index there, width entries each, sup_n used */
    int *sup_n[2], *sup_e[2], *sup_a[2];
    double time;
    int64_t steps;
    double nu_max;
    /* convex limiting (limiter.h): its state, the invariant step at the
     * last start, the sources per control point (3 a point) and the last
     * step's substeps */
    IgaLimiter lim;
    double lim_bound;
    bool lim_ready; /* lim holds U0's preparation (limited_stage) */
    double *node_src;
    double *U0, *U1, *U2; /* conservative: the step's start, a stage, the next */
    int substeps;
};

int iga_config_check(const IgaConfig *c) {
    if (c->degree < 1 || c->degree > IGA_MAX_DEGREE)
        return NSPD_FAIL(NSPD_ERR_INPUT, "iga: degree %d; expected 1, 2 or 3", c->degree);
    for (int a = 0; a < 2; a++) {
        const bool per = c->side[2 * a] == IGA_SIDE_PERIODIC;
        if (per != (c->side[2 * a + 1] == IGA_SIDE_PERIODIC))
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "iga: periodic on one %c side only; expected both or neither",
                             a == 0 ? 'x' : 'y');
        if (c->elements[a] < (per ? c->degree + 1 : 1))
            return NSPD_FAIL(NSPD_ERR_INPUT, "iga: %d elements along %c; expected at least %d",
                             c->elements[a], a == 0 ? 'x' : 'y', per ? c->degree + 1 : 1);
    }
    if (!(c->gamma > 1.0 && c->gamma < 3.0) || !(c->R > 0.0) || !(c->mu >= 0.0) ||
        !(c->prandtl > 0.0))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "iga: gas gamma %g, R %g, mu %g, Pr %g; expected 1 < gamma < 3, R > 0, "
                         "mu >= 0, Pr > 0",
                         c->gamma, c->R, c->mu, c->prandtl);
    if (!(c->cfl > 0.0 && c->cfl <= 0.5))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "iga: Courant number %g; expected (0, 0.5] (the explicit passes blow up "
                         "above about 0.6, iga_flow.md 3.6)",
                         c->cfl);
    if ((int)c->limiter < IGA_LIMITER_NONE || (int)c->limiter > IGA_LIMITER_CONVEX)
        return NSPD_FAIL(NSPD_ERR_INPUT, "iga: limiter %d; expected none, positivity or convex",
                         (int)c->limiter);
    /* the limited update is the Euler equations' (docs/IGA_LIMITER.md), and
     * its wave-speed bound holds for gamma <= 5/3 (idp_lambda_waves) */
    if (c->limiter != IGA_LIMITER_NONE && (c->mu > 0.0 || c->gamma > 5.0 / 3.0))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "iga: limiter with viscosity mu %g and gamma %g; expected an inviscid "
                         "gas (flow.gas.viscosity.law: none) with gamma <= 5/3: the limited "
                         "scheme is the Euler equations'",
                         c->mu, c->gamma);
    if (c->passes < 1 || c->passes > 100 || !(c->rho_inf >= 0.0 && c->rho_inf <= 1.0) ||
        !(c->c_dc >= 0.0) || c->db_iterations < 1 || c->db_iterations > 50 || !(c->tau_dt >= 0.0))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "iga: passes %d, rho_inf %g, dc %g, tau iterations %d, tau_dt %g; "
                         "expected 1..100, [0, 1], >= 0, 1..50, >= 0",
                         c->passes, c->rho_inf, c->c_dc, c->db_iterations, c->tau_dt);
    return NSPD_OK;
}

/* The elements touching each control point of an axis, ascending. */
static int build_support(IgaSolver *s, int axis) {
    const IgaAxis *a = &s->ax[axis];
    const int w = s->width, n = a->count;
    TRY(nspd_alloc(&s->sup_n[axis], (size_t)n, sizeof(int)));
    TRY(nspd_alloc(&s->sup_e[axis], (size_t)n * (size_t)w, sizeof(int)));
    TRY(nspd_alloc(&s->sup_a[axis], (size_t)n * (size_t)w, sizeof(int)));
    for (int e = 0; e < a->elements; e++) /* ascending e: each list ends up sorted */
        for (int l = 0; l < w; l++) {
            const int k = iga_axis_index(a, e, l);
            const int m = s->sup_n[axis][k]++;
            s->sup_e[axis][k * w + m] = e;
            s->sup_a[axis][k * w + m] = l;
        }
    return NSPD_OK;
}

/* The local control point of function (a, b) of local element (ex, ey). */
static int64_t control_index(const IgaSolver *s, int ex, int ey, int a, int b) {
    return iga_window_function(&s->dc.ax[0], ex, a) +
           (int64_t)s->ncx * iga_window_function(&s->dc.ax[1], ey, b);
}

/* The global control point of function (a, b) of global element (ex, ey). */
static int64_t global_index(const IgaSolver *s, int ex, int ey, int a, int b) {
    return iga_axis_index(&s->ax[0], ex, a) + (int64_t)s->gncx * iga_axis_index(&s->ax[1], ey, b);
}

/* The global element of local element (ex, ey) along axis a. */
static int global_element(const IgaSolver *s, int axis, int le) {
    return s->dc.ax[axis].element[le];
}

/* The t-th control point along side f (x_min, x_max, y_min, y_max) and
 * the side's number of them. */
static int side_count(const IgaSolver *s, int f) {
    return f / 2 == 0 ? s->gncy : s->gncx;
}

/* its local index, -1 off this process's window */
static int64_t side_point(const IgaSolver *s, int f, int t) {
    const int axis = f / 2, across = f % 2 == 0 ? 0 : (axis == 0 ? s->gncx : s->gncy) - 1;
    return iga_decomp_local(&s->dc, axis == 0 ? across + (int64_t)s->gncx * t
                                              : t + (int64_t)s->gncx * across);
}

/* The tabulated values (or slopes) of element e at its Gauss point q. */
static const double *at_point(const IgaAxis *a, const double *table, int e, int q) {
    return table + ((size_t)e * (size_t)a->gauss + (size_t)q) * (size_t)(a->degree + 1);
}

/* |u| + c of a state */
static double signal_speed(const IgaConfig *c, double u, double v, double T) {
    return sqrt(u * u + v * v) + sqrt(c->gamma * c->R * T);
}

/* cfl min(hx, hy) / the largest signal speed */
static double step_of(const IgaConfig *c, double rate) {
    const double h =
        fmin((c->hi[0] - c->lo[0]) / c->elements[0], (c->hi[1] - c->lo[1]) / c->elements[1]);
    return rate > 0.0 ? c->cfl * h / rate : (double)INFINITY;
}

double iga_solver_stable_dt(const IgaSolver *s) {
    double rate = 0.0;
    for (int64_t q = 0; q < iga_decomp_owned_count(&s->dc); q++) {
        const double *y = s->Y + 4 * iga_decomp_owned(&s->dc, q);
        rate = fmax(rate, signal_speed(&s->cfg, y[1], y[2], y[3]));
    }
    const double dt = step_of(&s->cfg, comm_max(&s->dc.comm, rate)); /* a max: exact */
    return s->cfg.limiter == IGA_LIMITER_NONE ? dt : fmin(dt, s->lim_bound);
}

double iga_config_stable_dt(const IgaConfig *c, const IgaRegion *regions, int count) {
    if (c->init_fn || iga_config_check(c) != NSPD_OK) return 0.0;
    double rate = signal_speed(c, c->initial.u, c->initial.v, c->initial.T);
    for (int r = 0; r < count; r++) {
        const IgaState *q = &regions[r].state;
        rate = fmax(rate, signal_speed(c, q->u, q->v, q->T));
    }
    return rate > 0.0 ? step_of(c, rate) : 0.0;
}

/* Element e's residual and lumped-mass slots from the alpha-level values
 * Ya, Yda (notes 1.3): Gauss points of the tensor rule, kernel.h's body. */
static void element_residual(IgaSolver *s, int64_t e) {
    const int w = s->width, L = s->local, lx = (int)(e % s->nex), ly = (int)(e / s->nex);
    const int ex = global_element(s, 0, lx), ey = global_element(s, 1, ly);
    const IgaAxis *ax = &s->ax[0], *ay = &s->ax[1];
    double y[IGA_MAX_LOCAL * IGA_MAX_LOCAL][4], yd[IGA_MAX_LOCAL * IGA_MAX_LOCAL][4];
    for (int b = 0; b < w; b++)
        for (int a = 0; a < w; a++) {
            const int64_t k = control_index(s, lx, ly, a, b);
            for (int v = 0; v < 4; v++)
                y[b * w + a][v] = s->Ya[4 * k + v], yd[b * w + a][v] = s->Yda[4 * k + v];
        }
    double *er = s->eR + e * L * 4, *em = s->eM + e * L * 16;
    memset(er, 0, sizeof(double) * (size_t)L * 4);
    memset(em, 0, sizeof(double) * (size_t)L * 16);
    double nu_e = 0.0;
    for (int qy = 0; qy < ay->gauss; qy++)
        for (int qx = 0; qx < ax->gauss; qx++) {
            const double *nx = at_point(ax, ax->value, ex, qx),
                         *dx = at_point(ax, ax->slope, ex, qx),
                         *ny = at_point(ay, ay->value, ey, qy),
                         *dy = at_point(ay, ay->slope, ey, qy);
            const double wq = ax->weight[qx] * ay->weight[qy];
            double Y[4] = {0}, Yd[4] = {0}, Yx[4] = {0}, Yy[4] = {0};
            for (int b = 0; b < w; b++)
                for (int a = 0; a < w; a++) {
                    const double n = nx[a] * ny[b], nxd = dx[a] * ny[b], nyd = nx[a] * dy[b];
                    for (int v = 0; v < 4; v++) {
                        Y[v] += n * y[b * w + a][v];
                        Yd[v] += n * yd[b * w + a][v];
                        Yx[v] += nxd * y[b * w + a][v];
                        Yy[v] += nyd * y[b * w + a][v];
                    }
                }
            double gal[4], fx[4], fy[4], A0[16], nu;
            iga_point_residual(&s->qp, Y, Yd, Yx, Yy, gal, fx, fy, A0, &nu);
            nu_e = fmax(nu_e, nu);
            for (int b = 0; b < w; b++)
                for (int a = 0; a < w; a++) {
                    const double n = wq * nx[a] * ny[b], nxd = wq * dx[a] * ny[b],
                                 nyd = wq * nx[a] * dy[b];
                    double *r = er + (b * w + a) * 4, *m = em + (b * w + a) * 16;
                    for (int v = 0; v < 4; v++) r[v] += n * gal[v] + nxd * fx[v] + nyd * fy[v];
                    for (int k = 0; k < 16; k++) m[k] += n * A0[k];
                }
        }
    s->eNu[e] = nu_e;
}

/* R and the lumped blocks M of every control point: the element slots of
 * its support summed in ascending element order. */
static void gather(IgaSolver *s) {
    const int w = s->width, L = s->local;
    const int64_t own = iga_decomp_owned_count(&s->dc);
    const int *lex = s->dc.ax[0].local_element, *ley = s->dc.ax[1].local_element;
#pragma omp parallel for schedule(static) if (own >= PARALLEL_MIN_ITEMS)
    for (int64_t q = 0; q < own; q++) {
        const int64_t k = iga_decomp_owned(&s->dc, q);
        /* the support's lists are the whole axis's, by global index */
        const int i = s->dc.ax[0].global[k % s->ncx], j = s->dc.ax[1].global[k / s->ncx];
        double r[4] = {0}, m[16] = {0};
        for (int bj = 0; bj < s->sup_n[1][j]; bj++)
            for (int bi = 0; bi < s->sup_n[0][i]; bi++) {
                const int64_t e =
                    lex[s->sup_e[0][i * w + bi]] + (int64_t)s->nex * ley[s->sup_e[1][j * w + bj]];
                const int l = s->sup_a[1][j * w + bj] * w + s->sup_a[0][i * w + bi];
                const double *er = s->eR + (e * L + l) * 4, *em = s->eM + (e * L + l) * 16;
                for (int v = 0; v < 4; v++) r[v] += er[v];
                for (int c = 0; c < 16; c++) m[c] += em[c];
            }
        memcpy(s->R + 4 * k, r, sizeof r);
        memcpy(s->M + 16 * k, m, sizeof m);
    }
}

/* The point sources' Galerkin term, -N_A(x_q) f_q in R_A, in point order
 * (serial: the same bits on any thread count; sources are few). */
static void add_sources(IgaSolver *s) {
    const int L = s->local;
    for (int64_t q = 0; q < s->src_n; q++) {
        const double *f = s->src_f + 3 * q;
        for (int l = 0; l < L; l++) {
            const int64_t k = s->src_cp[q * L + l];
            if (k < 0 || !iga_decomp_owns(&s->dc, (int)(k % s->ncx), (int)(k / s->ncx))) continue;
            double *r = s->R + 4 * k;
            const double w = s->src_w[q * L + l];
            for (int v = 0; v < 3; v++) r[1 + v] -= w * f[v];
        }
    }
}

static void residual(IgaSolver *s, double dt) {
    const double tdt = s->cfg.tau_dt > 0.0 ? s->cfg.tau_dt : dt;
    s->qp.tau_s = 4.0 / (tdt * tdt);
    /* the local elements that touch an own point */
    const IgaWindowAxis *wx = &s->dc.ax[0], *wy = &s->dc.ax[1];
    const int64_t nel = (int64_t)wx->en * wy->en;
#pragma omp parallel for schedule(static) if (nel >= PARALLEL_MIN_ITEMS / 16)
    for (int64_t q = 0; q < nel; q++)
        element_residual(s, wx->e0 + q % wx->en + (int64_t)s->nex * (wy->e0 + q / wx->en));
    gather(s);
    add_sources(s);
    double nu = 0.0;
    for (int64_t q = 0; q < nel; q++)
        nu = fmax(nu, s->eNu[wx->e0 + q % wx->en + (int64_t)s->nex * (wy->e0 + q / wx->en)]);
    s->nu_max = comm_max(&s->dc.comm, nu);
}

/* Walls and fixed sides (notes 2.4): at their control points the rows of
 * what is held get R = 0 and an identity row and column in M. */
static void hold(double *r, double *m, int v) {
    r[v] = 0.0;
    for (int c = 0; c < 4; c++) m[4 * v + c] = m[4 * c + v] = 0.0;
    m[5 * v] = 1.0;
}

static void apply_sides(IgaSolver *s) {
    for (int f = 0; f < 4; f++) {
        const IgaSideKind kind = s->cfg.side[f];
        if (kind == IGA_SIDE_PERIODIC) continue;
        for (int t = 0; t < side_count(s, f); t++) {
            const int64_t k = side_point(s, f, t);
            if (k < 0) continue;
            double *r = s->R + 4 * k, *m = s->M + 16 * k;
            if (kind == IGA_SIDE_SLIP)
                hold(r, m, 1 + f / 2);
            else
                for (int v = 0; v < 4; v++) hold(r, m, v);
        }
    }
}

/* Yd -= M^-1 R and, with step (gamma dt), Y -= step M^-1 R. */
static void block_update(IgaSolver *s, double step) {
    const int64_t own = iga_decomp_owned_count(&s->dc);
#pragma omp parallel for schedule(static) if (own >= PARALLEL_MIN_ITEMS)
    for (int64_t q = 0; q < own; q++) {
        const int64_t k = iga_decomp_owned(&s->dc, q);
        double inv[16], d[4];
        if (!iga_mat4_inverse(s->M + 16 * k, inv)) {
            for (int v = 0; v < 4; v++) s->Yd[4 * k + v] = NAN; /* caught by the range check */
            continue;
        }
        iga_mat4_vec(inv, s->R + 4 * k, d);
        for (int v = 0; v < 4; v++) {
            s->Yd[4 * k + v] -= d[v];
            if (step != 0.0) s->Y[4 * k + v] -= step * d[v];
        }
    }
}

/* The first own control point (the lowest global index, on any number of
 * processes) where p or T left the physical range; collective. */
static int check_range(const IgaSolver *s) {
    char text[600] = "";
    int64_t first = INT64_MAX;
    for (int64_t q = 0; q < iga_decomp_owned_count(&s->dc) && first == INT64_MAX; q++) {
        const int64_t k = iga_decomp_owned(&s->dc, q);
        const double *y = s->Y + 4 * k, *yd = s->Yd + 4 * k;
        bool ok = y[0] > 0.0 && y[3] > 0.0 && isfinite(y[0] + y[1] + y[2] + y[3]) &&
                  isfinite(yd[0] + yd[1] + yd[2] + yd[3]);
        if (ok) continue;
        first = iga_decomp_global(&s->dc, k);
        const int i = (int)(first % s->gncx), j = (int)(first / s->gncx);
        snprintf(text, sizeof text,
                 "iga flow: p = %g Pa, T = %g K, u = (%g, %g) m/s at control point (%d, %d) near "
                 "(%g, %g) m at t = %g s; expected p, T > 0 (%s)",
                 y[0], y[3], y[1], y[2], i, j, iga_axis_greville(&s->ax[0], i),
                 iga_axis_greville(&s->ax[1], j), s->time,
                 s->cfg.limiter == IGA_LIMITER_NONE
                     ? "flow.iga.limiter: convex keeps them positive at any charge"
                     : "the limited step keeps them positive: please report the case");
    }
    if (iga_decomp_divided(&s->dc))
        first = comm_first_failure(&s->dc.comm, first, text, (int)sizeof text);
    return first == INT64_MAX ? NSPD_OK : NSPD_FAIL(NSPD_ERR_NUMERIC, "%s", text);
}

/* The halo's values and rates from their owners (after the owned points'
 * update). A failed exchange is MPI's (its default handler stops the
 * job). */
static void exchange_values(IgaSolver *s, bool values, bool rates) {
    double *both[2] = {s->Y, s->Yd};
    if (values && rates)
        (void)iga_decomp_exchange(&s->dc, both, 2, 4);
    else if (values || rates)
        (void)iga_decomp_exchange(&s->dc, values ? both : both + 1, 1, 4);
}

/* The high-order step (notes 3.2): the predictor and the corrector
 * passes. */
static void high_order_step(IgaSolver *s, double dt) {
    const size_t bytes = sizeof(double) * 4 * (size_t)s->ncp;
    memcpy(s->Yn, s->Y, bytes);
    memcpy(s->Ydn, s->Yd, bytes);
    /* predictor: Y unchanged, Yd scaled (notes 3.2) */
    for (int64_t k = 0; k < 4 * s->ncp; k++) s->Yd[k] = (s->gam - 1.0) / s->gam * s->Ydn[k];
    for (int pass = 0; pass < s->cfg.passes; pass++) {
        for (int64_t k = 0; k < 4 * s->ncp; k++) {
            s->Ya[k] = s->Yn[k] + s->af * (s->Y[k] - s->Yn[k]);
            s->Yda[k] = s->Ydn[k] + s->am * (s->Yd[k] - s->Ydn[k]);
        }
        residual(s, dt);
        for (int64_t k = 0; k < 16 * s->ncp; k++) s->M[k] *= s->am;
        apply_sides(s);
        block_update(s, s->gam * dt);
        exchange_values(s, true, true);
    }
}

/* The point sources per control point (fx, fy, power), in point order:
 * the low-order update's share of what add_sources gives the residual. */
static const double *node_sources(IgaSolver *s) {
    if (s->src_n == 0) return NULL;
    memset(s->node_src, 0, sizeof(double) * 3 * (size_t)s->ncp);
    for (int64_t q = 0; q < s->src_n; q++)
        for (int l = 0; l < s->local; l++) {
            const int64_t k = s->src_cp[q * s->local + l];
            if (k < 0) continue; /* off the window */
            double *n = s->node_src + 3 * k;
            for (int v = 0; v < 3; v++) n[v] += s->src_w[q * s->local + l] * s->src_f[3 * q + v];
        }
    return s->node_src;
}

/* The limiter's preparation of U and the invariant step of the whole
 * (the smallest of every process's own points: exact). */
static double prepare_limiter(IgaSolver *s, const double *U) {
    return -comm_max(&s->dc.comm, -iga_limiter_prepare(&s->lim, U));
}

/* The limited step's start: U0 = U(Y), and its preparation, whose bound
 * caps the next time step (iga_solver_stable_dt) and which the next
 * step's first stage reuses (limited_stage). */
static void prepare_start(IgaSolver *s) {
    for (int64_t k = 0; k < s->ncp; k++)
        idp_from_primitive(s->cfg.R, s->qp.cv, s->Y + 4 * k, s->U0 + 4 * k);
    s->lim_bound = prepare_limiter(s, s->U0);
    s->lim_ready = true;
}

/* One limited stage of h from `from` into `to` = a from0 + (1 - a) (the
 * stage's result); false when h exceeds the stage state's invariant
 * step (*bound: that step). */
static bool limited_stage(IgaSolver *s, double h, const double *src, const double *from, double a,
                          double *to, double *bound) {
    /* the step's first stage starts where the last step's end was
     * prepared for the next time step (limited_step): not again */
    int64_t again = !(s->lim_ready && from == s->U0 &&
                      memcmp(from, s->lim.U, sizeof(double) * 4 * (size_t)s->ncp) == 0);
    /* every process prepares if one must (the bound is a reduction) */
    if (iga_decomp_divided(&s->dc)) again = comm_max_i64(&s->dc.comm, again);
    if (again) s->lim_bound = prepare_limiter(s, from);
    s->lim_ready = false;
    *bound = s->lim_bound;
    if (h > *bound) return false;
    iga_limiter_stage(&s->lim, h, src, to);
    if (a > 0.0)
        for (int64_t k = 0; k < 4 * s->ncp; k++) to[k] = a * s->U0[k] + (1.0 - a) * to[k];
    (void)iga_decomp_exchange(&s->dc, &to, 1, 4); /* a failure is MPI's abort */
    return true;
}

/* The limited step (docs/IGA_LIMITER.md): the strong-stability-preserving
 * Runge-Kutta scheme of order 3 (Shu & Osher 1988), each stage a limited
 * forward-Euler update, so a convex combination of invariant states. A
 * stage whose state allows less than the step restarts the step with 0.9
 * of what it allows: the step of dt is taken in substeps, all of the same
 * length, that each keep every stage invariant. */
static void limited_step(IgaSolver *s, double dt) {
    for (int64_t k = 0; k < s->ncp; k++)
        idp_from_primitive(s->cfg.R, s->qp.cv, s->Y + 4 * k, s->U0 + 4 * k);
    const double *src = node_sources(s);
    double left = dt, h = dt;
    s->substeps = 0;
    while (left > 0.0) {
        h = fmin(h, left);
        double bound;
        if (!limited_stage(s, h, src, s->U0, 0.0, s->U1, &bound) ||
            !limited_stage(s, h, src, s->U1, 0.75, s->U2, &bound) ||
            !limited_stage(s, h, src, s->U2, 1.0 / 3.0, s->U1, &bound)) {
            h = 0.9 * bound;
            continue;
        }
        memcpy(s->U0, s->U1, sizeof(double) * 4 * (size_t)s->ncp);
        left = h >= left ? 0.0 : left - h;
        s->substeps++;
    }
    for (int64_t k = 0; k < s->ncp; k++)
        idp_to_primitive(s->cfg.R, s->qp.cv, s->U0 + 4 * k, s->Y + 4 * k);
    /* from Y's conservative values, the round trip's last bits included:
     * the state the next step starts from */
    prepare_start(s);
}

int iga_solver_step(IgaSolver *s, double dt) {
    s->substeps = 1;
    if (s->cfg.limiter == IGA_LIMITER_NONE)
        high_order_step(s, dt);
    else
        limited_step(s, dt);
    s->time += dt;
    s->steps++;
    return check_range(s);
}

/* ------------------------------------------------------------ initial data */

static void state_at(const IgaConfig *c, double x, double y, double out[4]) {
    if (c->init_fn) {
        c->init_fn(c->init_ctx, x, y, out);
        return;
    }
    IgaState st = c->initial;
    const double pt[3] = {x, y, 0.0};
    for (int r = 0; r < c->region_count; r++)
        if (shapeset_contains(&c->regions[r].shapes, pt)) st = c->regions[r].state;
    out[0] = st.p, out[1] = st.u, out[2] = st.v, out[3] = st.T;
}

static void init_nodal(IgaSolver *s) {
    for (int j = 0; j < s->ncy; j++)
        for (int i = 0; i < s->ncx; i++)
            state_at(&s->cfg, iga_axis_greville(&s->ax[0], s->dc.ax[0].global[i]),
                     iga_axis_greville(&s->ax[1], s->dc.ax[1].global[j]),
                     s->Y + 4 * (i + (int64_t)s->ncx * j));
}

/* Y_A = int N_A Y0 / int N_A (notes 2.5). Each element is sampled on
 * SUB x SUB sub-cells with the element's Gauss rule on each; with
 * exact_areas, a region's share of the element is then scaled to its
 * exact area there (a disc's or a rectangle's), so that int p^h = int p0
 * on any mesh. */
enum { SUB = 8 };

/* y = M x for the consistent mass matrix M_AB = int N_A N_B (Gauss;
 * serial, in element order). */
static void mass_apply(const IgaSolver *s, const double *x, double *y) {
    const IgaAxis *ax = &s->ax[0], *ay = &s->ax[1];
    const int w = s->width;
    memset(y, 0, sizeof(double) * (size_t)s->ncp);
    for (int64_t e = 0; e < s->nel; e++) {
        const int ex = (int)(e % ax->elements), ey = (int)(e / ax->elements);
        for (int qy = 0; qy < ay->gauss; qy++)
            for (int qx = 0; qx < ax->gauss; qx++) {
                const double *nx = at_point(ax, ax->value, ex, qx),
                             *ny = at_point(ay, ay->value, ey, qy);
                double v = 0.0;
                for (int b = 0; b < w; b++)
                    for (int a = 0; a < w; a++)
                        v += nx[a] * ny[b] * x[control_index(s, ex, ey, a, b)];
                v *= ax->weight[qx] * ay->weight[qy];
                for (int b = 0; b < w; b++)
                    for (int a = 0; a < w; a++)
                        y[control_index(s, ex, ey, a, b)] += v * nx[a] * ny[b];
            }
    }
}

/* The L2 projection: M Y_v = num_v for each variable, by conjugate
 * gradients preconditioned with the lumped mass (den), from the lumped
 * solution, to 1e-14 of the right side (the mass matrix's condition number
 * does not grow with the mesh: tens of iterations). R and M are scratch
 * here (nothing has stepped yet). */
static void project_l2(IgaSolver *s, const double *num, const double *den) {
    const int64_t n = s->ncp;
    double *x = s->R, *r = s->M, *z = s->M + n, *p = s->M + 2 * n, *q = s->M + 3 * n,
           *b = s->M + 4 * n;
    for (int v = 0; v < 4; v++) {
        double bb = 0.0;
        for (int64_t k = 0; k < n; k++)
            b[k] = num[4 * k + v], x[k] = b[k] / den[k], bb += b[k] * b[k];
        mass_apply(s, x, q);
        double rz = 0.0;
        for (int64_t k = 0; k < n; k++)
            r[k] = b[k] - q[k], z[k] = r[k] / den[k], p[k] = z[k], rz += r[k] * z[k];
        for (int it = 0; it < 500; it++) {
            double rr = 0.0;
            for (int64_t k = 0; k < n; k++) rr += r[k] * r[k];
            if (rr <= 1e-28 * bb) break;
            mass_apply(s, p, q);
            double pq = 0.0;
            for (int64_t k = 0; k < n; k++) pq += p[k] * q[k];
            const double alpha = rz / pq;
            double rz_new = 0.0;
            for (int64_t k = 0; k < n; k++) {
                x[k] += alpha * p[k];
                r[k] -= alpha * q[k];
                z[k] = r[k] / den[k];
                rz_new += r[k] * z[k];
            }
            for (int64_t k = 0; k < n; k++) p[k] = z[k] + rz_new / rz * p[k];
            rz = rz_new;
        }
        for (int64_t k = 0; k < n; k++) s->Y[4 * k + v] = x[k];
    }
}

static int init_lumped(IgaSolver *s, bool exact_areas) {
    const IgaConfig *c = &s->cfg;
    const int w = s->width, L = s->local, nr = c->region_count;
    double *num = NULL, *den = NULL, *phi = NULL; /* phi: (nr + 1) x L per element */
    TRY(nspd_alloc(&num, (size_t)s->ncp * 4, sizeof(double)));
    int status = nspd_alloc(&den, (size_t)s->ncp, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&phi, (size_t)(nr + 1) * (size_t)L, sizeof(double));
    const IgaAxis *ax = &s->ax[0], *ay = &s->ax[1];
    /* the reference rule back from the table (both axes have the degree,
     * hence the rule) */
    double gx[IGA_MAX_LOCAL] = {0}, gw[IGA_MAX_LOCAL] = {0};
    for (int q = 0; q < ax->gauss; q++) {
        gx[q] = (ax->point[q] - ax->lo) / ax->h;
        gw[q] = ax->weight[q] / ax->h;
    }
    /* the local elements in ascending global order: each point's sums
     * then take its elements in the order one process does */
    const IgaWindowAxis *wx = &s->dc.ax[0], *wy = &s->dc.ax[1];
    for (int64_t e = 0; status == NSPD_OK && e < s->nel; e++) {
        const int lx = wx->sorted[e % s->nex], ly = wy->sorted[e / s->nex];
        const int ex = wx->element[lx], ey = wy->element[ly];
        const double x0 = ax->knots[ex + ax->degree], y0 = ay->knots[ey + ay->degree];
        memset(phi, 0, sizeof(double) * (size_t)(nr + 1) * (size_t)L);
        for (int sj = 0; sj < SUB; sj++)
            for (int si = 0; si < SUB; si++)
                for (int qy = 0; qy < ay->gauss; qy++)
                    for (int qx = 0; qx < ax->gauss; qx++) {
                        const double x = x0 + (si + gx[qx]) * ax->h / SUB,
                                     y = y0 + (sj + gx[qy]) * ay->h / SUB;
                        const double wq = gw[qx] * gw[qy] * ax->h * ay->h / (SUB * SUB);
                        const double pt[3] = {x, y, 0.0};
                        int owner = 0; /* 0: background, r + 1: region r */
                        for (int r = 0; r < nr; r++)
                            if (shapeset_contains(&c->regions[r].shapes, pt)) owner = r + 1;
                        double bx[IGA_MAX_LOCAL], by[IGA_MAX_LOCAL];
                        iga_axis_eval(ax, ex, x, bx, NULL);
                        iga_axis_eval(ay, ey, y, by, NULL);
                        if (c->init_fn) { /* a function: straight into the sums */
                            double f[4];
                            c->init_fn(c->init_ctx, x, y, f);
                            for (int b = 0; b < w; b++)
                                for (int a = 0; a < w; a++) {
                                    const int64_t k = control_index(s, lx, ly, a, b);
                                    const double n = wq * bx[a] * by[b];
                                    for (int v = 0; v < 4; v++) num[4 * k + v] += n * f[v];
                                    den[k] += n;
                                }
                            continue;
                        }
                        for (int b = 0; b < w; b++)
                            for (int a = 0; a < w; a++)
                                phi[owner * L + b * w + a] += wq * bx[a] * by[b];
                    }
        if (exact_areas)
            for (int r = 0; r < nr; r++) {
                const ShapeSet *set = &c->regions[r].shapes;
                if (set->count != 1) continue;
                const double area =
                    shape_area_in_rect(&set->shapes[0], x0, x0 + ax->h, y0, y0 + ay->h);
                if (area < 0.0) continue;
                double sampled = 0.0, total = 0.0;
                for (int l = 0; l < L; l++) sampled += phi[(r + 1) * L + l];
                for (int o = 0; o <= nr; o++)
                    for (int l = 0; l < L; l++) total += phi[o * L + l];
                /* the region's share scaled to its exact area, taken from
                 * (or given to) the background's */
                for (int l = 0; l < L; l++) {
                    double want;
                    if (sampled > 0.0)
                        want = phi[(r + 1) * L + l] * area / sampled;
                    else { /* too small to be sampled: spread like the element's mean */
                        double col = 0.0;
                        for (int o = 0; o <= nr; o++) col += phi[o * L + l];
                        want = area * col / total;
                    }
                    phi[l] -= want - phi[(r + 1) * L + l];
                    phi[(r + 1) * L + l] = want;
                }
            }
        /* accumulate: serial in element order, so the sums do not depend
         * on threads */
        for (int b = 0; b < w && !c->init_fn; b++)
            for (int a = 0; a < w; a++) {
                const int64_t k = control_index(s, lx, ly, a, b);
                for (int o = 0; o <= nr; o++) {
                    const double f = phi[o * L + b * w + a];
                    const IgaState st = o == 0 ? c->initial : c->regions[o - 1].state;
                    num[4 * k] += f * st.p, num[4 * k + 1] += f * st.u;
                    num[4 * k + 2] += f * st.v, num[4 * k + 3] += f * st.T;
                    den[k] += f;
                }
            }
    }
    /* a rim point of the window lacks some of its elements: its value
     * comes from its owner (create's exchange) */
    if (status == NSPD_OK)
        for (int64_t k = 0; k < s->ncp; k++)
            for (int v = 0; v < 4 && den[k] > 0.0; v++) s->Y[4 * k + v] = num[4 * k + v] / den[k];
    if (status == NSPD_OK && c->init == IGA_INIT_L2) project_l2(s, num, den);
    nspd_free(&num);
    nspd_free(&den);
    nspd_free(&phi);
    return status;
}

/* The starting rate that makes the residual vanish (notes 2.5: lumped
 * fixed-point passes of R(Y0, Yd) = 0). */
static void consistent_rate(IgaSolver *s, double dt0) {
    memcpy(s->Ya, s->Y, sizeof(double) * 4 * (size_t)s->ncp);
    for (int it = 0; it < 30; it++) {
        memcpy(s->Yda, s->Yd, sizeof(double) * 4 * (size_t)s->ncp);
        residual(s, dt0);
        apply_sides(s);
        block_update(s, 0.0);
        exchange_values(s, false, true);
    }
}

void iga_solver_destroy(IgaSolver **sp) {
    IgaSolver *s = *sp;
    if (!s) return;
    for (int a = 0; a < 2; a++) {
        iga_axis_destroy(&s->ax[a]);
        nspd_free(&s->sup_n[a]);
        nspd_free(&s->sup_e[a]);
        nspd_free(&s->sup_a[a]);
    }
    double **arrays[] = {&s->Y,     &s->Yd,    &s->Yn,       &s->Ydn, &s->Ya,  &s->Yda,
                         &s->R,     &s->M,     &s->eR,       &s->eM,  &s->eNu, &s->mass,
                         &s->src_w, &s->src_f, &s->node_src, &s->U0,  &s->U1,  &s->U2};
    iga_limiter_destroy(&s->lim);
    iga_decomp_destroy(&s->dc);
    nspd_free(&s->src_cp);
    for (size_t k = 0; k < sizeof arrays / sizeof arrays[0]; k++) nspd_free(arrays[k]);
    nspd_free(sp);
}

double iga_solver_bytes(int degree, double control_points, double elements) {
    const double local = (degree + 1.0) * (degree + 1.0);
    return control_points * (7 * 4 + 16) * 8.0 + elements * (local * 20.0 + 1.0) * 8.0;
}

int iga_solver_create(IgaSolver **out, const IgaConfig *cfg, double dt0) {
    *out = NULL;
    TRY(iga_config_check(cfg));
    IgaSolver *s;
    TRY(nspd_alloc(&s, 1, sizeof *s));
    s->cfg = *cfg;
    s->cfg.regions = NULL; /* borrowed only here */
    s->cfg.region_count = 0;
    int status = NSPD_OK;
    for (int a = 0; a < 2 && status == NSPD_OK; a++)
        status = iga_axis_create(&s->ax[a], cfg->degree, cfg->elements[a], cfg->lo[a], cfg->hi[a],
                                 cfg->side[2 * a] == IGA_SIDE_PERIODIC);
    if (status != NSPD_OK) {
        iga_solver_destroy(&s);
        return status;
    }
    s->width = cfg->degree + 1;
    s->local = s->width * s->width;
    s->gncx = s->ax[0].count, s->gncy = s->ax[1].count;
    /* the halo: the points of the elements touching own points, or those
     * the limiter's pair fluxes reach (decomp.h); 8 doubles a point (Y
     * and Yd) at most an exchange */
    const int halo = cfg->limiter == IGA_LIMITER_NONE ? cfg->degree : 3 * cfg->degree;
    s->cfg.comm = NULL; /* borrowed only here */
    status = iga_decomp_create(&s->dc, cfg->comm, cfg->processes, s->ax, halo, 8);
    if (status == NSPD_OK && iga_decomp_divided(&s->dc) && cfg->init == IGA_INIT_L2)
        status = NSPD_FAIL(NSPD_ERR_INPUT,
                           "iga: the L2 projection start (flow.iga.init: l2, for order studies) "
                           "runs on one process only; expected lumped_l2 or nodal on several");
    if (status != NSPD_OK) {
        iga_solver_destroy(&s);
        return status;
    }
    s->ncx = s->dc.ax[0].n, s->ncy = s->dc.ax[1].n;
    s->ncp = (int64_t)s->ncx * s->ncy;
    s->nex = s->dc.ax[0].ne;
    s->nel = (int64_t)s->nex * s->dc.ax[1].ne;
    const double ri = cfg->rho_inf;
    s->am = 0.5 * (3.0 - ri) / (1.0 + ri);
    s->af = 1.0 / (1.0 + ri);
    s->gam = 0.5 + s->am - s->af;
    const double cv = cfg->R / (cfg->gamma - 1.0);
    s->qp = (IgaQpParams){.R = cfg->R,
                          .cv = cv,
                          .mu = cfg->mu,
                          .lambda = -2.0 * cfg->mu / 3.0,
                          .kappa = cfg->mu * cfg->gamma * cv / cfg->prandtl,
                          .c_dc = cfg->c_dc,
                          .dc_cap = cfg->dc_cap,
                          .db_iterations = cfg->db_iterations,
                          .tau_s = 1.0,
                          .G = {4.0 / (s->ax[0].h * s->ax[0].h), 4.0 / (s->ax[1].h * s->ax[1].h)}};
    double **four[] = {&s->Y, &s->Yd, &s->Yn, &s->Ydn, &s->Ya, &s->Yda, &s->R};
    for (size_t k = 0; k < sizeof four / sizeof four[0] && status == NSPD_OK; k++)
        status = nspd_alloc(four[k], (size_t)s->ncp * 4, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&s->M, (size_t)s->ncp * 16, sizeof(double));
    if (status == NSPD_OK)
        status = nspd_alloc(&s->eR, (size_t)s->nel * (size_t)s->local * 4, sizeof(double));
    if (status == NSPD_OK)
        status = nspd_alloc(&s->eM, (size_t)s->nel * (size_t)s->local * 16, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&s->eNu, (size_t)s->nel, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&s->mass, (size_t)s->ncp, sizeof(double));
    for (int a = 0; a < 2 && status == NSPD_OK; a++) status = build_support(s, a);
    if (status == NSPD_OK) {
        IgaConfig with_regions = s->cfg;
        with_regions.regions = cfg->regions;
        with_regions.region_count = cfg->region_count;
        const IgaConfig keep = s->cfg;
        s->cfg = with_regions;
        if (cfg->init == IGA_INIT_NODAL)
            init_nodal(s);
        else
            status = init_lumped(s, cfg->exact_areas);
        s->cfg = keep;
    }
    if (status == NSPD_OK) {
        /* walls: no normal velocity at their control points */
        for (int f = 0; f < 4; f++)
            if (cfg->side[f] == IGA_SIDE_SLIP)
                for (int t = 0; t < side_count(s, f); t++) {
                    const int64_t k = side_point(s, f, t);
                    if (k >= 0) s->Y[4 * k + 1 + f / 2] = 0.0;
                }
        exchange_values(s, true, false); /* the window's rim from its owners */
        status = check_range(s);
    }
    if (status == NSPD_OK && cfg->limiter != IGA_LIMITER_NONE) {
        bool wall[4], fixed[4];
        for (int f = 0; f < 4; f++)
            wall[f] = cfg->side[f] == IGA_SIDE_SLIP, fixed[f] = cfg->side[f] == IGA_SIDE_FIXED;
        status = iga_limiter_create(&s->lim, cfg->limiter, s->ax, &s->dc, wall, fixed, cfg->gamma,
                                    cfg->R);
        if (status == NSPD_OK)
            status = nspd_alloc(&s->node_src, (size_t)s->ncp * 3, sizeof(double));
        double **cons[] = {&s->U0, &s->U1, &s->U2};
        for (int k = 0; k < 3 && status == NSPD_OK; k++)
            status = nspd_alloc(cons[k], (size_t)s->ncp * 4, sizeof(double));
        if (status == NSPD_OK) prepare_start(s);
    }
    if (status == NSPD_OK && cfg->ydot0 == IGA_YDOT0_CONSISTENT) {
        consistent_rate(s, dt0 > 0.0 ? dt0 : iga_solver_stable_dt(s));
        status = check_range(s);
    }
    if (status != NSPD_OK) {
        iga_solver_destroy(&s);
        return status;
    }
    *out = s;
    return NSPD_OK;
}

/* -------------------------------------------------------------- accessors */

double iga_solver_time(const IgaSolver *s) {
    return s->time;
}

int64_t iga_solver_steps(const IgaSolver *s) {
    return s->steps;
}

const IgaAxis *iga_solver_axis(const IgaSolver *s, int axis) {
    return &s->ax[axis];
}

const IgaConfig *iga_solver_config(const IgaSolver *s) {
    return &s->cfg;
}

double *iga_solver_values(IgaSolver *s) {
    return s->Y;
}

double *iga_solver_rates(IgaSolver *s) {
    return s->Yd;
}

int64_t iga_solver_control_count(const IgaSolver *s) {
    return (int64_t)s->gncx * s->gncy;
}

const IgaDecomp *iga_solver_decomp(const IgaSolver *s) {
    return &s->dc;
}

double iga_solver_nu_max(const IgaSolver *s) {
    return s->nu_max;
}

void iga_solver_limiting(const IgaSolver *s, int64_t *limited, double *alpha_min, int *substeps) {
    /* each process's own points' (limiter.c): a sum of integers, a min */
    *limited = comm_sum_i64(&s->dc.comm, s->lim.limited);
    *alpha_min = -comm_max(&s->dc.comm, -s->lim.alpha_min);
    *substeps = s->substeps;
}

/* The field of local element (ex, ey) with basis values bx, by: Y^h = sum N_k
 * Y_k for the high-order scheme; U^h = sum N_k U(Y_k), the limited
 * scheme's field (a convex combination of admissible states), into U
 * when U is not NULL. */
static void field_in(const IgaSolver *s, int ex, int ey, const double *bx, const double *by,
                     double Y[4], double *U) {
    const int w = s->width;
    const bool cons = s->cfg.limiter != IGA_LIMITER_NONE;
    double sum[4] = {0};
    for (int b = 0; b < w; b++)
        for (int a = 0; a < w; a++) {
            const int64_t k = control_index(s, ex, ey, a, b);
            double q[4];
            if (cons)
                idp_from_primitive(s->cfg.R, s->qp.cv, s->Y + 4 * k, q);
            else
                for (int v = 0; v < 4; v++) q[v] = s->Y[4 * k + v];
            for (int v = 0; v < 4; v++) sum[v] += bx[a] * by[b] * q[v];
        }
    if (cons) {
        idp_to_primitive(s->cfg.R, s->qp.cv, sum, Y);
        if (U)
            for (int v = 0; v < 4; v++) U[v] = sum[v];
    } else {
        for (int v = 0; v < 4; v++) Y[v] = sum[v];
        if (U) idp_from_primitive(s->cfg.R, s->qp.cv, Y, U);
    }
}

bool iga_solver_eval(const IgaSolver *s, double x, double y, double out[4]) {
    const IgaAxis *ax = &s->ax[0], *ay = &s->ax[1];
    const int ex = iga_axis_element(ax, x), ey = iga_axis_element(ay, y);
    const int lx = s->dc.ax[0].local_element[ex], ly = s->dc.ax[1].local_element[ey];
    if (lx < 0 || ly < 0) {
        for (int v = 0; v < 4; v++) out[v] = (double)NAN;
        return false;
    }
    double bx[IGA_MAX_LOCAL], by[IGA_MAX_LOCAL];
    iga_axis_eval(ax, ex, x, bx, NULL);
    iga_axis_eval(ay, ey, y, by, NULL);
    field_in(s, lx, ly, bx, by, out, NULL);
    return true;
}

int iga_solver_point_owner(const IgaSolver *s, double x, double y) {
    return iga_decomp_element_owner(&s->dc, iga_axis_element(&s->ax[0], x),
                                    iga_axis_element(&s->ax[1], y));
}

/* Gauss sums over the rectangle: rho, rho u, rho v, rho E and p; each
 * process its own elements', every term added exactly (exact_sum.h), so
 * the sums are the same bits on any number of processes (collective). */
static void quadrature_sums(const IgaSolver *s, double sums[5]) {
    const IgaAxis *ax = &s->ax[0], *ay = &s->ax[1];
    const IgaWindowAxis *wx = &s->dc.ax[0], *wy = &s->dc.ax[1];
    ExactSum sum[5];
    for (int v = 0; v < 5; v++) exact_sum_clear(&sum[v]);
    int ex0, ex1, ey0, ey1;
    iga_window_own_elements(wx, &ex0, &ex1);
    iga_window_own_elements(wy, &ey0, &ey1);
    for (int ey = ey0; ey < ey1; ey++)
        for (int ex = ex0; ex < ex1; ex++) {
            const int lx = wx->local_element[ex], ly = wy->local_element[ey];
            for (int qy = 0; qy < ay->gauss; qy++)
                for (int qx = 0; qx < ax->gauss; qx++) {
                    const double *nx = at_point(ax, ax->value, ex, qx),
                                 *ny = at_point(ay, ay->value, ey, qy);
                    double Y[4], U[4];
                    field_in(s, lx, ly, nx, ny, Y, U);
                    const double wq = ax->weight[qx] * ay->weight[qy];
                    if (s->cfg.limiter != IGA_LIMITER_NONE)
                        for (int v = 0; v < 4; v++) exact_sum_add(&sum[v], wq * U[v]);
                    else {
                        const double rho = Y[0] / (s->cfg.R * Y[3]);
                        exact_sum_add(&sum[0], wq * rho);
                        exact_sum_add(&sum[1], wq * rho * Y[1]);
                        exact_sum_add(&sum[2], wq * rho * Y[2]);
                        exact_sum_add(&sum[3],
                                      wq * rho *
                                          (s->qp.cv * Y[3] + 0.5 * (Y[1] * Y[1] + Y[2] * Y[2])));
                    }
                    exact_sum_add(&sum[4], wq * Y[0]);
                }
        }
    (void)exact_sum_reduce(&s->dc.comm, sum, 5); /* a failure is MPI's abort */
    for (int v = 0; v < 5; v++) sums[v] = exact_sum_value(&sum[v]);
}

void iga_solver_totals(const IgaSolver *s, double totals[4]) {
    double sums[5];
    quadrature_sums(s, sums);
    memcpy(totals, sums, 4 * sizeof(double));
}

double iga_solver_mean_pressure(const IgaSolver *s) {
    double sums[5];
    quadrature_sums(s, sums);
    return sums[4] / ((s->cfg.hi[0] - s->cfg.lo[0]) * (s->cfg.hi[1] - s->cfg.lo[1]));
}

/* One per-point array (4 doubles a point) as the whole's, so that a
 * checkpoint is the same on any number of processes and any other reads
 * it: the own blocks gathered on writing, the window cut out on reading. */
static int io_points(IgaSolver *s, Checkpoint *ck, const char *name, double *values) {
    const int64_t whole = 4 * iga_solver_control_count(s);
    if (!iga_decomp_divided(&s->dc)) {
        int64_t count = whole;
        TRY(checkpoint_io_array(ck, name, values, sizeof(double), &count, whole));
        if (count != whole)
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "checkpoint: %lld IGA control values; the case has %lld",
                             (long long)count, (long long)whole);
        return NSPD_OK;
    }
    double *all = NULL, *mine = NULL;
    const int64_t own = iga_decomp_owned_count(&s->dc);
    TRY(nspd_alloc(&all, (size_t)whole, sizeof(double)));
    int status = nspd_alloc(&mine, 4 * (size_t)own + 1, sizeof(double));
    int cx[IGA_MAX_BLOCKS + 1], cy[IGA_MAX_BLOCKS + 1];
    int *const cut[2] = {cx, cy};
    const int n[2] = {s->gncx, s->gncy};
    if (status == NSPD_OK && (s->dc.dims[0] > IGA_MAX_BLOCKS || s->dc.dims[1] > IGA_MAX_BLOCKS))
        status = NSPD_FAIL(NSPD_ERR_INPUT, "iga flow: more than %d blocks along an axis",
                           IGA_MAX_BLOCKS);
    if (status == NSPD_OK) {
        iga_decomp_cuts(&s->dc, 0, s->gncx, cx);
        iga_decomp_cuts(&s->dc, 1, s->gncy, cy);
    }
    if (status == NSPD_OK && !checkpoint_reading(ck)) {
        for (int64_t q = 0; q < own; q++)
            memcpy(mine + 4 * q, values + 4 * iga_decomp_owned(&s->dc, q), 4 * sizeof(double));
        status = iga_decomp_gather(&s->dc, n, cut, mine, 4, all, true);
    }
    int64_t count = whole;
    if (status == NSPD_OK)
        status = checkpoint_io_array(ck, name, all, sizeof(double), &count, whole);
    if (status == NSPD_OK && count != whole)
        status = NSPD_FAIL(NSPD_ERR_INPUT, "checkpoint: %lld IGA control values; the case has %lld",
                           (long long)count, (long long)whole);
    if (status == NSPD_OK && checkpoint_reading(ck))
        for (int64_t k = 0; k < s->ncp; k++)
            memcpy(values + 4 * k, all + 4 * iga_decomp_global(&s->dc, k), 4 * sizeof(double));
    nspd_free(&all);
    nspd_free(&mine);
    return status;
}

int iga_solver_checkpoint(IgaSolver *s, Checkpoint *ck) {
    TRY(io_points(s, ck, "iga.values", s->Y));
    TRY(io_points(s, ck, "iga.rates", s->Yd));
    TRY(checkpoint_io_double(ck, "iga.time", &s->time));
    TRY(checkpoint_io_int64(ck, "iga.steps", &s->steps));
    /* the limited step's time-step bound is of the state read, as it was
     * of the state written when the run went on */
    if (checkpoint_reading(ck) && s->cfg.limiter != IGA_LIMITER_NONE) prepare_start(s);
    return NSPD_OK;
}

/* ------------------------------------------------ what a coupling exchanges */

int iga_solver_point_basis(const IgaSolver *s, double x, double y, int64_t *cp, double *w) {
    const IgaAxis *ax = &s->ax[0], *ay = &s->ax[1];
    if (!(x >= ax->lo && x <= ax->hi && y >= ay->lo && y <= ay->hi)) return 0;
    const int ex = iga_axis_element(ax, x), ey = iga_axis_element(ay, y), n = s->width;
    double bx[IGA_MAX_LOCAL], by[IGA_MAX_LOCAL];
    iga_axis_eval(ax, ex, x, bx, NULL);
    iga_axis_eval(ay, ey, y, by, NULL);
    for (int b = 0; b < n; b++)
        for (int a = 0; a < n; a++) {
            cp[b * n + a] = global_index(s, ex, ey, a, b);
            w[b * n + a] = bx[a] * by[b];
        }
    return s->local;
}

int iga_solver_set_sources(IgaSolver *s, int64_t n, const double *x, const double *y,
                           const double *fx, const double *fy, const double *power,
                           int64_t *outside) {
    const int L = s->local;
    int64_t *cp = NULL;
    double *w = NULL, *f = NULL;
    int64_t kept = 0;
    *outside = 0;
    if (n > 0) {
        TRY(nspd_alloc(&cp, (size_t)n * (size_t)L, sizeof *cp));
        int status = nspd_alloc(&w, (size_t)n * (size_t)L, sizeof *w);
        if (status == NSPD_OK) status = nspd_alloc(&f, (size_t)n * 3, sizeof *f);
        if (status != NSPD_OK) {
            nspd_free(&cp);
            nspd_free(&w);
            return status;
        }
        for (int64_t q = 0; q < n; q++) {
            if (iga_solver_point_basis(s, x[q], y[q], cp + kept * L, w + kept * L) == 0) {
                (*outside)++;
                continue;
            }
            /* every process is given every point: it keeps those that
             * reach its window, their points by local index (-1 off it) */
            bool near = false;
            for (int l = 0; l < L; l++) {
                int64_t *c = cp + kept * L + l;
                *c = iga_decomp_local(&s->dc, *c);
                near |= *c >= 0;
            }
            if (!near) continue;
            f[3 * kept] = fx[q];
            f[3 * kept + 1] = fy[q];
            f[3 * kept + 2] = power ? power[q] : 0.0;
            kept++;
        }
    }
    nspd_free(&s->src_cp);
    nspd_free(&s->src_w);
    nspd_free(&s->src_f);
    s->src_cp = cp, s->src_w = w, s->src_f = f, s->src_n = kept;
    return NSPD_OK;
}

/* int N_A rho^h over the support of own control point k (local; Gauss,
 * the support's elements in ascending order); with `unit`, int N_A. */
static double lumped_integral(const IgaSolver *s, int64_t k, bool unit) {
    const IgaAxis *ax = &s->ax[0], *ay = &s->ax[1];
    const int w = s->width, i = s->dc.ax[0].global[k % s->ncx], j = s->dc.ax[1].global[k / s->ncx];
    const int *lex = s->dc.ax[0].local_element, *ley = s->dc.ax[1].local_element;
    double m = 0.0;
    for (int bj = 0; bj < s->sup_n[1][j]; bj++)
        for (int bi = 0; bi < s->sup_n[0][i]; bi++) {
            const int ex = s->sup_e[0][i * w + bi], ey = s->sup_e[1][j * w + bj];
            const int lx = lex[ex], ly = ley[ey];
            const int la = s->sup_a[0][i * w + bi], lb = s->sup_a[1][j * w + bj];
            for (int qy = 0; qy < ay->gauss; qy++)
                for (int qx = 0; qx < ax->gauss; qx++) {
                    const double *nx = at_point(ax, ax->value, ex, qx),
                                 *ny = at_point(ay, ay->value, ey, qy);
                    const double wq = ax->weight[qx] * ay->weight[qy] * nx[la] * ny[lb];
                    if (unit) {
                        m += wq;
                        continue;
                    }
                    double p = 0.0, T = 0.0;
                    for (int b = 0; b < w; b++)
                        for (int a = 0; a < w; a++) {
                            const int64_t c = control_index(s, lx, ly, a, b);
                            p += nx[a] * ny[b] * s->Y[4 * c];
                            T += nx[a] * ny[b] * s->Y[4 * c + 3];
                        }
                    m += wq * p / (s->cfg.R * T);
                }
        }
    return m;
}

/* The local index of global point g where this process owns it, else -1. */
static int64_t own_local(const IgaSolver *s, int64_t g) {
    const int64_t k = iga_decomp_local(&s->dc, g);
    return k >= 0 && iga_decomp_owns(&s->dc, (int)(k % s->ncx), (int)(k / s->ncx)) ? k : -1;
}

void iga_solver_lumped_volume(const IgaSolver *s, int64_t n, const int64_t *cps, double *volume) {
    for (int64_t q = 0; q < n; q++) {
        const int64_t k = own_local(s, cps[q]);
        volume[q] = k < 0 ? (double)NAN : lumped_integral(s, k, true);
    }
}

void iga_solver_lumped(const IgaSolver *s, int64_t n, const int64_t *cps, double *mass, double *mx,
                       double *my) {
    for (int64_t q = 0; q < n; q++) {
        const int64_t k = own_local(s, cps[q]);
        if (k < 0) {
            mass[q] = mx[q] = my[q] = (double)NAN;
            continue;
        }
        const double m = lumped_integral(s, k, false);
        mass[q] = m;
        mx[q] = m * s->Y[4 * k + 1];
        my[q] = m * s->Y[4 * k + 2];
    }
}

void iga_solver_add_lumped(IgaSolver *s, int64_t n, const int64_t *cps, const double *dmx,
                           const double *dmy, const double *de) {
    const double cv = s->qp.cv;
    /* every mass before any change (a change at one control point moves
     * its neighbours' masses), by local index (the points are distinct) */
    double *mass = s->mass;
    for (int64_t q = 0; q < n; q++) {
        const int64_t k = own_local(s, cps[q]);
        if (k >= 0) mass[k] = lumped_integral(s, k, false);
    }
    for (int64_t q = 0; q < n; q++) {
        const int64_t k = own_local(s, cps[q]);
        if (k < 0) continue; /* another process's */
        double *y = s->Y + 4 * k;
        const double m = mass[k], rho = y[0] / (s->cfg.R * y[3]);
        const double e_old = m * (cv * y[3] + 0.5 * (y[1] * y[1] + y[2] * y[2]));
        if (dmx) y[1] += dmx[q] / m;
        if (dmy) y[2] += dmy[q] / m;
        /* the total energy: the new kinetic part and what was handed over;
         * the density at the control point kept, so p follows T */
        const double e_new = e_old + (de ? de[q] : 0.0);
        y[3] = (e_new / m - 0.5 * (y[1] * y[1] + y[2] * y[2])) / cv;
        y[0] = rho * s->cfg.R * y[3];
    }
    /* the halo from the owners: every process calls (FlowOps) */
    exchange_values(s, true, false);
}
