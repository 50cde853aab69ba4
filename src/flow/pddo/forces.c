/* Drag and lift on a polar patch's wall ring (paper 002, Eqs. 72-76); see
 * forces.h.
 *
 * The fluid-side operators reuse pddo_ops_build on a point set of m + n
 * entries: the m wall nodes first (the only nodes whose weights are built),
 * then the whole cloud; wall node t's family is its cloud family without
 * the body rings, shifted by m. */
#include "flow/pddo/forces.h"

#include "core/mem.h"
#include "core/status.h"

#include <math.h>
#include <string.h>

int pddo_forces_build(PddoForces *f, const PddoCloud *c, int patch) {
    pddo_forces_free(f);
    if (patch < 0 || patch >= c->npatches)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "PDDO forces: patch %d of a cloud with %d polar patches; expected one "
                         "of them",
                         patch, c->npatches);
    const PddoPolarPatch *p = &c->patch[patch];
    const int32_t m = p->ntheta;
    const int64_t n = c->n, wall = p->first + (int64_t)p->rings_inside * m;
    f->cloud = c, f->patch = patch, f->m = m, f->wall = wall;
    int status = nspd_alloc(&f->first, (size_t)m + 1, sizeof(int64_t));
    if (status == NSPD_OK) status = nspd_alloc(&f->xs, (size_t)(m + n), sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&f->ys, (size_t)(m + n), sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&f->as, (size_t)(m + n), sizeof(double));
    int64_t members = 0;
    for (int32_t t = 0; t < m && status == NSPD_OK; t++) {
        const int64_t k = wall + t;
        f->first[t] = members;
        for (int64_t q = c->first[k]; q < c->first[k + 1]; q++)
            members += c->kind[c->nbr[q]] != PDDO_NODE_BODY;
    }
    if (status == NSPD_OK) f->first[m] = members;
    if (status == NSPD_OK) status = nspd_alloc(&f->nbr, (size_t)members, sizeof(int32_t));
    if (status != NSPD_OK) {
        pddo_forces_free(f);
        return status;
    }
    for (int32_t t = 0; t < m; t++) {
        const int64_t k = wall + t;
        f->xs[t] = c->x[k], f->ys[t] = c->y[k], f->as[t] = c->area[k];
        int64_t at = f->first[t];
        for (int64_t q = c->first[k]; q < c->first[k + 1]; q++)
            if (c->kind[c->nbr[q]] != PDDO_NODE_BODY) f->nbr[at++] = m + c->nbr[q];
    }
    memcpy(f->xs + m, c->x, (size_t)n * sizeof(double));
    memcpy(f->ys + m, c->y, (size_t)n * sizeof(double));
    memcpy(f->as + m, c->area, (size_t)n * sizeof(double));
    /* the wall ring's own horizon (a local one on such a patch, polar.h) */
    status = pddo_ops_build(&f->side, m, f->xs, f->ys, f->as, f->first, f->nbr, c->node_delta[wall],
                            NULL, NULL);
    if (status != NSPD_OK) pddo_forces_free(f);
    return status;
}

/* sum_j w_j (g_j - g_k) over wall node t's fluid-side family. */
static double side_derivative(const PddoForces *f, PddoOp op, const double *g, int32_t t) {
    const double gk = g[f->wall + t];
    double sum = 0.0;
    for (int64_t q = f->first[t]; q < f->first[t + 1]; q++)
        sum += pddo_ops_weight(&f->side, op, t, q) * (g[f->nbr[q] - f->m] - gk);
    return sum;
}

PddoWallTraction pddo_forces_traction(const PddoForces *f, PddoTraction traction,
                                      const PddoOps *ops, const double *u, const double *v,
                                      const double *p, double mu, int32_t t) {
    const PddoPolarPatch *pp = &f->cloud->patch[f->patch];
    const int64_t k = f->wall + t;
    double ux, uy, vx, vy;
    if (traction == PDDO_TRACTION_FULL_FAMILY) {
        ux = pddo_ops_at(ops, PDDO_D_X, u, k), uy = pddo_ops_at(ops, PDDO_D_Y, u, k);
        vx = pddo_ops_at(ops, PDDO_D_X, v, k), vy = pddo_ops_at(ops, PDDO_D_Y, v, k);
    } else {
        ux = side_derivative(f, PDDO_D_X, u, t), uy = side_derivative(f, PDDO_D_Y, u, t);
        vx = side_derivative(f, PDDO_D_X, v, t), vy = side_derivative(f, PDDO_D_Y, v, t);
    }
    /* the outward normal from the node's position (Eq. 72, the paper's n
     * per wall node) */
    const double inv_r = 1.0 / pp->radius;
    const double nx = (f->cloud->x[k] - pp->x) * inv_r, ny = (f->cloud->y[k] - pp->y) * inv_r;
    const double shear = mu * (uy + vx);
    return (PddoWallTraction){.nx = nx,
                              .ny = ny,
                              .p = p[k],
                              .viscous_x = 2.0 * mu * ux * nx + shear * ny,
                              .viscous_y = shear * nx + 2.0 * mu * vy * ny};
}

/* Eqs. 75-76. */
PddoForce pddo_forces_eval(const PddoForces *f, PddoTraction traction, const PddoOps *ops,
                           const double *u, const double *v, const double *p, double mu) {
    const PddoPolarPatch *pp = &f->cloud->patch[f->patch];
    const double ds = pp->radius * pp->dtheta;
    PddoForce out = {0};
    for (int32_t t = 0; t < f->m; t++) {
        const PddoWallTraction w = pddo_forces_traction(f, traction, ops, u, v, p, mu, t);
        out.fx_pressure -= w.p * w.nx * ds;
        out.fy_pressure -= w.p * w.ny * ds;
        out.fx_viscous += w.viscous_x * ds;
        out.fy_viscous += w.viscous_y * ds;
    }
    out.fx = out.fx_pressure + out.fx_viscous;
    out.fy = out.fy_pressure + out.fy_viscous;
    return out;
}

void pddo_forces_wall_vorticity(const PddoForces *f, const double *u, const double *v,
                                double *omega) {
    for (int32_t t = 0; t < f->m; t++)
        omega[t] = side_derivative(f, PDDO_D_X, v, t) - side_derivative(f, PDDO_D_Y, u, t);
}

void pddo_forces_free(PddoForces *f) {
    pddo_ops_free(&f->side);
    nspd_free(&f->first);
    nspd_free(&f->nbr);
    nspd_free(&f->xs);
    nspd_free(&f->ys);
    nspd_free(&f->as);
    memset(f, 0, sizeof *f);
}

void pddo_lift_periods_add(PddoLiftPeriods *lp, double t, double lift) {
    if (lp->samples > 0 && lp->armed && lp->prev < 0.0 && lift >= 0.0) {
        const double tc = lp->prev_t + (t - lp->prev_t) * (-lp->prev) / (lift - lp->prev);
        if (lp->crossings == 0)
            lp->first_t = tc, lp->run_max = lp->run_min = lift;
        else
            lp->amp_max = lp->run_max, lp->amp_min = lp->run_min;
        lp->last_t = tc;
        lp->crossings++;
        lp->armed = 0;
    }
    if (lp->crossings > 0)
        lp->run_max = fmax(lp->run_max, lift), lp->run_min = fmin(lp->run_min, lift);
    if (lift < -lp->threshold) lp->armed = 1;
    lp->prev_t = t, lp->prev = lift;
    lp->samples++;
}

int64_t pddo_lift_periods_result(const PddoLiftPeriods *lp, double *period, double *amplitude) {
    const int64_t periods = lp->crossings > 1 ? lp->crossings - 1 : 0;
    *period = periods > 0 ? (lp->last_t - lp->first_t) / (double)periods : 0.0;
    *amplitude = periods > 0 ? 0.5 * (lp->amp_max - lp->amp_min) : 0.0;
    return periods;
}
