/* The explicit PDDO flow step (paper 002 Sec. 3.4); see step.h.
 *
 * Invariant between steps: u and v satisfy the velocity conditions (every
 * FIXED node holds its value, every COPY / PERIODIC node its source's), so
 * outputs and probes may read them directly. Every loop is per node with a
 * fixed order of its family sums: the same bits at any thread count. */
#include "flow/pddo/step.h"

#include "core/mem.h"
#include "core/parallel.h"
#include "core/status.h"
#include "core/timer.h"

#include <math.h>
#include <omp.h>
#include <stdbool.h>
#include <string.h>

enum { UX, UY, VX, VY, LU, LV, D1, D2, R };

/* Precedence of the sides' velocity rules (step.h), smaller first. */
static int rank(const PddoStepParams *par, PddoSideKind kind, int side) {
    if (kind == PDDO_SIDE_WALL) return par->wall_u[side] == 0.0 && par->wall_v[side] == 0.0 ? 0 : 1;
    if (kind == PDDO_SIDE_INLET) return 2;
    if (kind == PDDO_SIDE_PERIODIC) return 3;
    return 4;
}

/* The rule of node k. */
static void node_rule(PddoStep *ps, int64_t k) {
    const PddoCloud *c = ps->cloud;
    ps->rule[k] = PDDO_VEL_FREE, ps->source[k] = -1;
    if (c->kind[k] == PDDO_NODE_FLUID) return;
    const bool anti = ps->par.walls == PDDO_WALL_ANTISYMMETRIC;
    if (c->kind[k] == PDDO_NODE_WALL) { /* a polar wall ring: at rest (Eq. 68) */
        ps->rule[k] = PDDO_VEL_FIXED;
        ps->fix_u[k] = ps->fix_v[k] = 0.0;
        return;
    }
    if (c->kind[k] == PDDO_NODE_BODY) {
        ps->rule[k] = anti ? PDDO_VEL_ANTI : PDDO_VEL_FIXED;
        ps->fix_u[k] = ps->fix_v[k] = 0.0;
        ps->source[k] = anti ? c->image[k] : -1;
        return;
    }
    int best = -1, best_rank = 99;
    for (int s = 0; s < PDDO_SIDES; s++) {
        if (!((unsigned)c->sides[k] >> s & 1u)) continue;
        const int r = rank(&ps->par, c->side[s], s);
        if (r < best_rank) best_rank = r, best = s;
    }
    if (best < 0) return; /* a periodic axis' node 0: not on any side */
    if (ps->par.inlet_corners == PDDO_INLET_CORNERS_INLET && c->kind[k] == PDDO_NODE_SIDE)
        for (int s = 0; s < PDDO_SIDES; s++) /* the inlet's own corner nodes, not its ghosts */
            if (((unsigned)c->sides[k] >> s & 1u) && c->side[s] == PDDO_SIDE_INLET) best = s;
    switch (c->side[best]) {
    case PDDO_SIDE_WALL:
        /* the wall's own nodes hold its velocity; its fictitious ones too
         * (the paper) or its reflection about it through the pressure image
         * (u_g = 2 u_w - u_image: linear across the wall, second order) */
        ps->rule[k] = anti && c->kind[k] == PDDO_NODE_GHOST ? PDDO_VEL_ANTI : PDDO_VEL_FIXED;
        ps->fix_u[k] = ps->par.wall_u[best], ps->fix_v[k] = ps->par.wall_v[best];
        if (ps->rule[k] == PDDO_VEL_ANTI) ps->source[k] = c->image[k];
        return;
    case PDDO_SIDE_INLET: {
        ps->rule[k] = PDDO_VEL_FIXED;
        double shape = 1.0;
        if (ps->par.inlet_profile == PDDO_INLET_PARABOLIC) {
            /* s across the side, from the lattice indices (exact at the
             * sides' nodes); 0 beyond the sides */
            const double s = best == PDDO_LEFT || best == PDDO_RIGHT
                                 ? (double)c->j[k] / (double)c->ny
                                 : (double)c->i[k] / (double)c->nx;
            shape = s > 0.0 && s < 1.0 ? 6.0 * s * (1.0 - s) : 0.0;
        }
        ps->fix_u[k] = shape * ps->par.inlet_u, ps->fix_v[k] = shape * ps->par.inlet_v;
        return;
    }
    case PDDO_SIDE_PERIODIC:
        ps->rule[k] = PDDO_VEL_PERIODIC, ps->source[k] = c->image[k];
        return;
    case PDDO_SIDE_OUTLET: {
        if (c->kind[k] == PDDO_NODE_SIDE) return; /* the exit layer is updated */
        /* Eq. 52: the exit-layer node along the outlet's normal; a corner
         * beyond a periodic axis too takes that axis' image */
        int i = c->i[k], j = c->j[k];
        if (best == PDDO_LEFT || best == PDDO_RIGHT)
            i = best == PDDO_LEFT ? 0 : c->nx;
        else
            j = best == PDDO_BOTTOM ? 0 : c->ny;
        if (c->side[PDDO_LEFT] == PDDO_SIDE_PERIODIC) i = (i % c->nx + c->nx) % c->nx;
        if (c->side[PDDO_BOTTOM] == PDDO_SIDE_PERIODIC) j = (j % c->ny + c->ny) % c->ny;
        ps->rule[k] = PDDO_VEL_COPY, ps->source[k] = (int32_t)pddo_cloud_node(c, i, j);
        return;
    }
    }
}

/* The bodies' wall velocity: spin_speed counterclockwise about each polar
 * patch's centre while time < spin_until, else rest. A wall ring node or
 * fictitious body node takes the wall's velocity at its own angle (the
 * reflection of PDDO_VEL_ANTI needs the wall's, not a rigid rotation's).
 * Loops only when the state changes: twice a run. */
static void update_spin(PddoStep *ps) {
    const bool spin = ps->par.spin_speed != 0.0 && ps->time < ps->par.spin_until;
    if (spin == ps->spinning) return;
    ps->spinning = spin;
    const PddoCloud *c = ps->cloud;
    const double speed = spin ? ps->par.spin_speed : 0.0;
    for (int64_t k = 0; k < c->n; k++) {
        if (c->kind[k] != PDDO_NODE_WALL && c->kind[k] != PDDO_NODE_BODY) continue;
        int best = 0; /* the patch whose wall is nearest */
        double gap = INFINITY;
        for (int b = 0; b < c->npatches; b++) {
            const PddoPolarPatch *pt = &c->patch[b];
            const double d = fabs(hypot(c->x[k] - pt->x, c->y[k] - pt->y) - pt->radius);
            if (d < gap) gap = d, best = b;
        }
        const PddoPolarPatch *pt = &c->patch[best];
        const double dx = c->x[k] - pt->x, dy = c->y[k] - pt->y, r = hypot(dx, dy);
        ps->fix_u[k] = -speed * dy / r, ps->fix_v[k] = speed * dx / r;
    }
}

/* A node whose velocity is prescribed (not a periodic copy of a free one).
 * Measured on the Re 10 cylinder (dx 0.1 m): with the rectangle's sides
 * held as well as the body's nodes, the drag moves 0.05 % between tau
 * 1.6e-3 and 4e-4 s, with the body's nodes alone 0.48 %. */
static bool is_held(const PddoStep *ps, int64_t k) {
    return ps->rule[k] != PDDO_VEL_FREE && ps->rule[k] != PDDO_VEL_PERIODIC;
}

/* PDDO_WALL_PRESSURE_MOMENTUM's arrays: the fictitious rows' data, each
 * polar patch's fluid-side operators, and the prescribed nodes' list. */
static int momentum_init(PddoStep *ps) {
    const PddoCloud *c = ps->cloud;
    int status = nspd_alloc(&ps->image_rhs, (size_t)c->n, sizeof(double));
    int32_t widest = 1;
    for (int b = 0; b < c->npatches; b++)
        widest = c->patch[b].ntheta > widest ? c->patch[b].ntheta : widest;
    if (status == NSPD_OK) status = nspd_alloc(&ps->omega, (size_t)widest, sizeof(double));
    if (status == NSPD_OK && c->npatches > 0)
        status = nspd_alloc(&ps->wall, (size_t)c->npatches, sizeof(PddoForces));
    for (int b = 0; b < c->npatches && status == NSPD_OK; b++)
        status = pddo_forces_build(&ps->wall[b], c, b);
    int64_t held = 0;
    for (int64_t k = 0; k < c->n; k++) held += is_held(ps, k);
    if (status == NSPD_OK) status = nspd_alloc(&ps->held, (size_t)held, sizeof(int64_t));
    if (status != NSPD_OK) return status;
    for (int64_t k = 0; k < c->n; k++)
        if (is_held(ps, k)) ps->held[ps->nheld++] = k;
    return NSPD_OK;
}

/* The polar bodies' fictitious pressure rows p_g - p_image = -(r_image -
 * r_g) dp/dr, with the momentum equation's dp/dr = mu e_r . lap u =
 * -mu d(omega)/ds on a no-slip wall (lap u = -curl omega where div u = 0;
 * s counterclockwise), omega from the fluid-side operators on the wall ring
 * and d/ds centred along it: the pressure extended smoothly across the
 * wall instead of evenly (which puts a kink in it wherever dp/dr != 0). */
static void body_pressure_rows(PddoStep *ps) {
    const PddoCloud *c = ps->cloud;
    for (int b = 0; b < c->npatches; b++) {
        const PddoPolarPatch *pt = &c->patch[b];
        const int32_t m = pt->ntheta;
        const double ds2 = 2.0 * pt->radius * pt->dtheta;
        pddo_forces_wall_vorticity(&ps->wall[b], ps->u, ps->v, ps->omega);
        for (int q = 0; q < pt->rings_inside; q++)
            for (int32_t t = 0; t < m; t++) {
                const int64_t g = pt->first + (int64_t)q * m + t, im = c->image[g];
                const double dist = hypot(c->x[im] - pt->x, c->y[im] - pt->y) -
                                    hypot(c->x[g] - pt->x, c->y[g] - pt->y);
                const double dw_ds = (ps->omega[(t + 1) % m] - ps->omega[(t + m - 1) % m]) / ds2;
                ps->image_rhs[g] = dist * ps->par.mu * dw_ds;
            }
    }
}

/* On the prescribed nodes the PPE source's rho F (d1, d2 and the
 * Laplacians lu, lv) becomes the last step's G p: at a steady state the
 * updated nodes have G p = rho F (Eq. 8), so the source is then D G p on
 * every row and the steady divergence (tau/rho) (L - D G) p, which smooth
 * data make small, instead of carrying the mismatch of rho F and G p at the
 * walls. The prescribed nodes are not updated, so nothing else reads these
 * values. */
static void held_source(const PddoStep *ps, double *const *w, int64_t lo, int64_t hi) {
    const int64_t n = ps->nheld;
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t h = 0; h < n; h++) {
        const int64_t k = ps->held[h];
        if (k < lo || k >= hi) continue; /* another process's */
        const PddoOp op[] = {PDDO_D_X, PDDO_D_Y};
        const double *const f[] = {ps->p, ps->p};
        double grad_p[2];
        pddo_ops_at_many(ps->ops, 2, op, f, k, grad_p);
        w[D1][k] = -grad_p[0] / ps->par.rho;
        w[D2][k] = -grad_p[1] / ps->par.rho;
        w[LU][k] = w[LV][k] = 0.0;
    }
}

int pddo_step_init(PddoStep *ps, const PddoCloud *cloud, const PddoOps *ops, PddoPpe *ppe,
                   const PddoStepParams *par) {
    pddo_step_free(ps);
    if (!(par->dt > 0.0) || !(par->rho > 0.0) || !(par->mu > 0.0))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "PDDO step: dt %g s, rho %g kg/m^3, mu %g Pa s; expected all > 0", par->dt,
                         par->rho, par->mu);
    if (par->divergence_time != 0.0 && !(par->divergence_time >= par->dt))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "PDDO step: divergence_time %g s with dt %g s; expected at least dt (a "
                         "shorter one over-corrects the divergence, and under dt/2 it grows)",
                         par->divergence_time, par->dt);
    if (par->spin_speed != 0.0 && cloud->npatches == 0)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "PDDO step: a spin of %g m/s; expected polar bodies to turn",
                         par->spin_speed);
    ps->cloud = cloud, ps->ops = ops, ps->ppe = ppe, ps->par = *par;
    const size_t n = (size_t)cloud->n;
    int status = NSPD_OK;
    double **arrays[] = {&ps->u, &ps->v, &ps->p, &ps->fix_u, &ps->fix_v};
    for (size_t a = 0; a < sizeof arrays / sizeof *arrays && status == NSPD_OK; a++)
        status = nspd_alloc(arrays[a], n, sizeof(double));
    for (int a = 0; a < 9 && status == NSPD_OK; a++)
        status = nspd_alloc(&ps->scratch[a], n, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&ps->rule, n, 1);
    if (status == NSPD_OK) status = nspd_alloc(&ps->source, n, sizeof(int32_t));
    if (status != NSPD_OK) {
        pddo_step_free(ps);
        return status;
    }
    for (int64_t k = 0; k < cloud->n; k++) {
        node_rule(ps, k);
        const int32_t s = ps->source[k];
        /* copies read nodes that are not copies themselves (pass 2 of apply_bc) */
        if (ps->rule[k] >= PDDO_VEL_COPY && (s < 0 || ps->rule[s] >= PDDO_VEL_COPY)) {
            pddo_step_free(ps);
            return NSPD_FAIL(NSPD_ERR_INTERNAL, "PDDO step: node %lld copies a prescribed node",
                             (long long)k);
        }
    }
    if (par->wall_pressure == PDDO_WALL_PRESSURE_MOMENTUM) {
        status = momentum_init(ps);
        if (status != NSPD_OK) {
            pddo_step_free(ps);
            return status;
        }
    }
    update_spin(ps);
    pddo_step_apply_bc(ps);
    return NSPD_OK;
}

void pddo_step_share(PddoStep *ps, const PddoShare *share) {
    ps->share = pddo_share_divided(share) ? share : NULL;
}

/* The arrays' own ranges to every rank (several processes). */
static int share_arrays(PddoStep *ps, int count, double *const *arrays) {
    if (!ps->share) return NSPD_OK;
    const double t0 = nspd_wall_time();
    for (int a = 0; a < count; a++) TRY(pddo_share(ps->share, arrays[a], false));
    ps->share_s += nspd_wall_time() - t0;
    return NSPD_OK;
}

void pddo_step_apply_bc(PddoStep *ps) {
    const int64_t n = ps->cloud->n;
    double *u = ps->u, *v = ps->v;
    const uint8_t *rule = ps->rule;
    const int32_t *src = ps->source;
    /* prescribed values first, then the copies and reflections, whose
     * sources are free or prescribed nodes (checked at init) */
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t k = 0; k < n; k++)
        if (rule[k] == PDDO_VEL_FIXED) u[k] = ps->fix_u[k], v[k] = ps->fix_v[k];
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t k = 0; k < n; k++) {
        if (rule[k] == PDDO_VEL_COPY || rule[k] == PDDO_VEL_PERIODIC)
            u[k] = u[src[k]], v[k] = v[src[k]];
        else if (rule[k] == PDDO_VEL_ANTI)
            u[k] = 2.0 * ps->fix_u[k] - u[src[k]], v[k] = 2.0 * ps->fix_v[k] - v[src[k]];
    }
}

/* Periodic fictitious nodes take their image's value of f (after f was
 * computed at every node): d and L are then exactly periodic. */
static void copy_periodic(const PddoStep *ps, double *f) {
    const int64_t n = ps->cloud->n;
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t k = 0; k < n; k++)
        if (ps->rule[k] == PDDO_VEL_PERIODIC) f[k] = f[ps->source[k]];
}

/* The failure of a step whose velocity became non-finite at node `bad`:
 * against the linear stability limit with the fastest prescribed velocity
 * (notes/pddo.md 1.5), or, within it, a high cell Peclet number (measured:
 * the cavity at Re 1000 on 100 x 100 intervals, Pe 10, blows up from a lid
 * corner at half the limit, 1e-6 s, and decays smoothly at a quarter). */
static int blow_up(const PddoStep *ps, int64_t bad) {
    const PddoCloud *c = ps->cloud;
    const double nu = ps->par.mu / ps->par.rho, dt = ps->par.dt;
    double umax = 0.0;
    for (int64_t k = 0; k < c->n; k++)
        if (ps->rule[k] == PDDO_VEL_FIXED) umax = fmax(umax, hypot(ps->fix_u[k], ps->fix_v[k]));
    double h = c->dx; /* the smallest horizon over 3 (pddo_flow_smallest_spacing) */
    for (int64_t k = 0; k < c->n; k++) h = fmin(h, c->node_delta[k] / 3.0);
    const double limit = 2.0 * pddo_step_stable_dt(nu, h, umax);
    if (dt > limit)
        return NSPD_FAIL(NSPD_ERR_NUMERIC,
                         "PDDO step %lld: velocity not finite at node %lld (%g, %g) m; expected "
                         "a stable step, dt <= %g s here (dt %g s)",
                         (long long)ps->steps, (long long)bad, c->x[bad], c->y[bad], limit, dt);
    return NSPD_FAIL(NSPD_ERR_NUMERIC,
                     "PDDO step %lld: velocity not finite at node %lld (%g, %g) m with dt %g s "
                     "within the linear stability limit %g s; expected a smaller step or a finer "
                     "lattice (cell Peclet number U dx/nu = %.3g with U = %g m/s, the fastest "
                     "prescribed velocity)",
                     (long long)ps->steps, (long long)bad, c->x[bad], c->y[bad], dt, limit,
                     umax * c->dx / nu, umax);
}

int pddo_step_advance(PddoStep *ps) {
    const PddoOps *ops = ps->ops;
    const int64_t n = ps->cloud->n;
    double *const *w = ps->scratch;
    double *u = ps->u, *v = ps->v, *p = ps->p;
    const double rho = ps->par.rho, mu = ps->par.mu, dt = ps->par.dt, nu = mu / rho;
    const double tau = ps->par.divergence_time > 0.0 ? ps->par.divergence_time : dt;
    update_spin(ps);        /* a no-op unless the caller set the time (a restart) */
    pddo_step_apply_bc(ps); /* 7.1 (a no-op between steps; the caller may have set u) */

    /* 7.2: first and second derivatives of the velocity (Eqs. 20, 21) */
    {
        const PddoOp op[] = {PDDO_D_X, PDDO_D_Y, PDDO_D_X, PDDO_D_Y, PDDO_LAP, PDDO_LAP};
        const double *const f[] = {u, u, v, v, u, v};
        double *const out[] = {w[UX], w[UY], w[VX], w[VY], w[LU], w[LV]};
        pddo_ops_apply_many(ops, 6, op, f, out);
    }
    /* d = u.grad u (Eq. 23) pointwise at every node (this process's) */
    int64_t own_lo, own_hi;
    pddo_share_nodes(ps->share, n, &own_lo, &own_hi);
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t k = own_lo; k < own_hi; k++) {
        w[D1][k] = u[k] * w[UX][k] + v[k] * w[UY][k];
        w[D2][k] = u[k] * w[VX][k] + v[k] * w[VY][k];
    }
    if (ps->par.wall_pressure == PDDO_WALL_PRESSURE_MOMENTUM) {
        body_pressure_rows(ps); /* from the whole u, v: every process alike */
        held_source(ps, w, own_lo, own_hi);
    }
    /* the divergences below read d and L at the families' members */
    TRY(share_arrays(ps, 4, (double *const[]){w[D1], w[D2], w[LU], w[LV]}));
    copy_periodic(ps, w[D1]);
    copy_periodic(ps, w[D2]);
    copy_periodic(ps, w[LU]);
    copy_periodic(ps, w[LV]);
    /* r (Eq. 33b) on the PPE rows; the boundary rows' right-hand sides are
     * the paper's zeros (ppe.h) */
    const uint8_t *row = ps->ppe->row;
    enum { L = PDDO_LANES };
    /* a slice of nodes at a time, the divergences in SIMD lanes; the
     * threads' slices of equal cost (pddo_ops_share) */
#pragma omp parallel if (n >= PARALLEL_MIN_ITEMS)
    {
        int64_t lo, hi;
        pddo_ops_share(ops, omp_get_thread_num(), omp_get_num_threads(), &lo, &hi);
        for (int64_t s = lo; s < hi; s++) {
            const PddoOp op[] = {PDDO_D_X, PDDO_D_Y, PDDO_D_X, PDDO_D_Y};
            const double *const f[] = {w[D1], w[D2], w[LU], w[LV]};
            double d[4 * L];
            pddo_ops_slice_many(ops, 4, op, f, s, d);
            for (int l = 0; l < L && s * L + l < n; l++) {
                const int64_t k = s * L + l;
                if (row[k] != PDDO_ROW_PPE) {
                    w[R][k] = row[k] == PDDO_ROW_IMAGE && ps->image_rhs ? ps->image_rhs[k] : 0.0;
                    continue;
                }
                const double div_u = w[UX][k] + w[VY][k];
                const double div_d = d[l] + d[L + l], div_l = d[2 * L + l] + d[3 * L + l];
                const bool feeds_back =
                    ps->par.divergence == PDDO_DIVERGENCE_ALL_ROWS || ps->rule[k] == PDDO_VEL_FREE;
                w[R][k] = (feeds_back ? rho / tau * div_u : 0.0) - rho * div_d + mu * div_l;
            }
        }
    }
    /* 7.3 */
    TRY(pddo_ppe_solve(ps->ppe, w[R], p));
    /* 7.4 (Eq. 8); grad p only where the velocity is updated */
    int64_t bad = n;
    double rate = 0.0; /* max |du/dt|: a max is exact, so any thread count gives these bits */
#pragma omp parallel reduction(min : bad) reduction(max : rate) if (n >= PARALLEL_MIN_ITEMS)
    {
        int64_t lo, hi;
        pddo_ops_share(ops, omp_get_thread_num(), omp_get_num_threads(), &lo, &hi);
        for (int64_t s = lo; s < hi; s++) {
            const PddoOp op[] = {PDDO_D_X, PDDO_D_Y};
            const double *const f[] = {p, p};
            double grad_p[2 * L];
            pddo_ops_slice_many(ops, 2, op, f, s, grad_p);
            for (int l = 0; l < L && s * L + l < n; l++) {
                const int64_t k = s * L + l;
                if (ps->rule[k] != PDDO_VEL_FREE) continue;
                const double du = -w[D1][k] - grad_p[l] / rho + nu * w[LU][k] + ps->par.force_x;
                const double dv = -w[D2][k] - grad_p[L + l] / rho + nu * w[LV][k] + ps->par.force_y;
                u[k] += dt * du;
                v[k] += dt * dv;
                rate = fmax(rate, fmax(fabs(du), fabs(dv)));
                if (!isfinite(u[k]) || !isfinite(v[k])) bad = k < bad ? k : bad;
            }
        }
    }
    if (ps->share) { /* a min and a max are exact: the same on every process */
        bad = comm_min_i64(&ps->share->comm, bad);
        rate = comm_max(&ps->share->comm, rate);
    }
    TRY(share_arrays(ps, 2, (double *const[]){u, v}));
    ps->dudt_max = rate;
    ps->time += dt;
    ps->steps++;
    update_spin(ps); /* the walls' velocity at the new time */
    pddo_step_apply_bc(ps);
    if (bad < n) return blow_up(ps, bad);
    return NSPD_OK;
}

double pddo_step_stable_dt(double nu, double dx, double umax) {
    const double diffusion = 1.6 * dx * dx / nu;
    const double convection = umax > 0.0 ? 2.0 * nu / (umax * umax) : (double)INFINITY;
    return 0.5 * fmin(diffusion, convection);
}

void pddo_step_free(PddoStep *ps) {
    nspd_free(&ps->u);
    nspd_free(&ps->v);
    nspd_free(&ps->p);
    nspd_free(&ps->fix_u);
    nspd_free(&ps->fix_v);
    for (int a = 0; a < 9; a++) nspd_free(&ps->scratch[a]);
    nspd_free(&ps->rule);
    nspd_free(&ps->source);
    nspd_free(&ps->image_rhs);
    nspd_free(&ps->omega);
    nspd_free(&ps->held);
    for (int b = 0; ps->wall && b < ps->cloud->npatches; b++) pddo_forces_free(&ps->wall[b]);
    nspd_free(&ps->wall);
    memset(ps, 0, sizeof *ps);
}
