#include "solid/correspondence/sl_force.h"

#include "core/mem.h"
#include "core/parallel.h"
#include "core/status.h"
#include "solid/correspondence/j2_kernel.h"

#include <string.h>

int sl_work_create(int dim, int64_t n, int64_t nb, int64_t np, SlWork *w) {
    memset(w, 0, sizeof *w);
    const size_t pn = (size_t)(n > 0 ? n : 1), bn = (size_t)(nb > 0 ? nb : 1),
                 pp = (size_t)(np > 0 ? np : 1), d = (size_t)dim;
    for (int a = 0; a < 3; a++) {
        TRY(nspd_alloc(&w->y[a], pn, sizeof(double)));
        TRY(nspd_alloc(&w->y_prev[a], pn, sizeof(double)));
        TRY(nspd_alloc(&w->du[a], pn, sizeof(double)));
    }
    TRY(nspd_alloc(&w->phi, d * bn, sizeof(double)));
    TRY(nspd_alloc(&w->omega, bn, sizeof(double)));
    TRY(nspd_alloc(&w->c, bn, sizeof(double)));
    TRY(nspd_alloc(&w->phi_rev, d * bn, sizeof(double)));
    TRY(nspd_alloc(&w->phi_sum, d * pn, sizeof(double)));
    TRY(nspd_alloc(&w->inv_w0, pn, sizeof(double)));
    TRY(nspd_alloc(&w->G, 9 * pn, sizeof(double)));
    TRY(nspd_alloc(&w->tau, 4 * pp, sizeof(double)));
    TRY(nspd_alloc(&w->ok, pn, 1));
    TRY(nspd_alloc(&w->scale_fit, bn, sizeof(double)));
    return NSPD_OK;
}

void sl_work_free(SlWork *w) {
    for (int a = 0; a < 3; a++) {
        nspd_free(&w->y[a]);
        nspd_free(&w->y_prev[a]);
        nspd_free(&w->du[a]);
    }
    nspd_free(&w->phi);
    nspd_free(&w->omega);
    nspd_free(&w->c);
    nspd_free(&w->phi_rev);
    nspd_free(&w->phi_sum);
    nspd_free(&w->inv_w0);
    nspd_free(&w->G);
    nspd_free(&w->tau);
    nspd_free(&w->ok);
    nspd_free(&w->scale_fit);
    w->fitted = false;
}

/* Pair p's step: G_b from the points' G on the bond's vectors at the step's
 * start (yp) and end (y), F_b^{n+1} = G_b F_b^n, the J2 update from F_b^n
 * to F_b^{n+1}, and tau_b = P_b F_b^T (0 for a broken pair, whose state
 * stays as bac_force keeps it). */
static void pair_step(const BacSystem *s, const BacState *st, const SlWork *w, int64_t p) {
    const int64_t np = s->pairs.count, k = s->pairs.bond[p], i = s->pairs.point[p];
    const int32_t j = s->nbr[k];
    const double yp[2] = {w->y_prev[0][j] - w->y_prev[0][i], w->y_prev[1][j] - w->y_prev[1][i]};
    const double Y[2] = {w->y[0][j] - w->y[0][i], w->y[1][j] - w->y[1][i]};
    const double inv = 1.0 / (yp[0] * yp[0] + yp[1] * yp[1]);
    const double g[2] = {yp[0] * inv, yp[1] * inv};
    const double *Gi = w->G + 9 * i, *Gj = w->G + 9 * (int64_t)j;
    const double m00 = 0.5 * (Gi[0] + Gj[0]), m01 = 0.5 * (Gi[1] + Gj[1]);
    const double m10 = 0.5 * (Gi[3] + Gj[3]), m11 = 0.5 * (Gi[4] + Gj[4]);
    const double r0 = Y[0] - (m00 * yp[0] + m01 * yp[1]);
    const double r1 = Y[1] - (m10 * yp[0] + m11 * yp[1]);
    const double Gb[4] = {m00 + r0 * g[0], m01 + r0 * g[1], m10 + r1 * g[0], m11 + r1 * g[1]};
    double Fp[4], F[4];
    for (int q = 0; q < 4; q++) Fp[q] = st->Fb[q * np + p];
    F[0] = Gb[0] * Fp[0] + Gb[1] * Fp[2], F[1] = Gb[0] * Fp[1] + Gb[1] * Fp[3];
    F[2] = Gb[2] * Fp[0] + Gb[3] * Fp[2], F[3] = Gb[2] * Fp[1] + Gb[3] * Fp[3];
    for (int q = 0; q < 4; q++) st->Fb[q * np + p] = F[q];
    double *tau = w->tau;
    if (s->bond_scale && s->bond_scale[k] == 0.0) {
        for (int q = 0; q < 4; q++) tau[q * np + p] = 0.0;
        return;
    }
    const int plane_stress = st->material->plane_stress;
    double sigma[4], eqps = st->eqps[p], zz = plane_stress ? st->strain_zz[p] : 0.0, P[4],
                     principal;
    for (int q = 0; q < 4; q++) sigma[q] = st->sigma[q * np + p];
    const int inverted =
        j2_step_2d(st->material, plane_stress, F, Fp, sigma, &eqps, &zz, P, &principal);
    /* tau = P F^T (= J sigma: P = sigma cof F, times the thickness stretch) */
    tau[0 * np + p] = P[0] * F[0] + P[1] * F[1];
    tau[1 * np + p] = P[0] * F[2] + P[1] * F[3];
    tau[2 * np + p] = P[2] * F[0] + P[3] * F[1];
    tau[3 * np + p] = P[2] * F[2] + P[3] * F[3];
    for (int q = 0; q < 4; q++) st->sigma[q * np + p] = sigma[q];
    st->eqps[p] = eqps, st->principal[p] = principal, st->inverted[p] = (uint8_t)inverted;
    if (plane_stress) st->strain_zz[p] = zz;
}

/* The kernel of every bond on the positions y (its damage scale is applied
 * where the weights and sums read it). */
static void bond_kernels(const BacSystem *s, const SlWeights *wt, double *const y[3],
                         double *omega) {
#pragma omp parallel for schedule(static) if (s->first[s->n] >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < s->n; i++)
        for (int64_t k = s->first[i]; k < s->first[i + 1]; k++) {
            const int32_t j = s->nbr[k];
            double b[3] = {0.0, 0.0, 0.0};
            for (int a = 0; a < s->dim; a++) b[a] = y[a][j] - y[a][i];
            omega[k] = rk_kernel_of(wt->kernel, s->dim, b, wt->delta);
        }
}

int64_t sl_force(const BacSystem *s, const SlWeights *wt, BacState *st, const double *const u[3],
                 double *const force[3], SlWork *w, double *work_point) {
    const int dim = s->dim;
    const int64_t n = s->n, np = s->pairs.count;
    const int64_t nb = s->first[n];
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < n; i++)
        for (int a = 0; a < dim; a++) w->y_prev[a][i] = s->x[a][i] + st->u_prev[a][i];
    /* the step's relative deformation gradient, on the weights at its start
     * (the last fit's, where it was made at these positions and damage) */
    bool kept = w->fitted;
    for (int a = 0; a < dim && kept; a++)
        kept = memcmp(w->y_prev[a], w->y[a], (size_t)n * sizeof(double)) == 0;
    if (kept && s->bond_scale)
        kept = memcmp(w->scale_fit, s->bond_scale, (size_t)nb * sizeof(double)) == 0;
    if (!kept)
        rk_gradient_weights_of(wt->order, wt->kernel, dim, n, (const double *const *)w->y_prev,
                               s->volume, s->first, s->nbr, wt->delta, s->bond_scale, NULL, w->phi,
                               w->ok);
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < n; i++)
        for (int a = 0; a < dim; a++) {
            w->y[a][i] = s->x[a][i] + u[a][i];
            w->du[a][i] = u[a][i] - st->u_prev[a][i];
        }
    rk_deformation_gradient(dim, n, (const double *const *)w->du, NULL, s->volume, s->first, s->nbr,
                            w->phi, w->G, NULL);
#pragma omp parallel for schedule(static) if (np >= PARALLEL_MIN_ITEMS)
    for (int64_t p = 0; p < np; p++) pair_step(s, st, w, p);
    /* the force on the configuration at the step's end */
    const int64_t missing = rk_gradient_weights_of(
        wt->order, wt->kernel, dim, n, (const double *const *)w->y, s->volume, s->first, s->nbr,
        wt->delta, s->bond_scale, NULL, w->phi, w->ok);
    for (int64_t k = 0; k < nb; k++) w->scale_fit[k] = s->bond_scale ? s->bond_scale[k] : 1.0;
    w->fitted = s->bond_scale != NULL;
    bond_kernels(s, wt, w->y, w->omega);
    BacSystem now = *s;
    for (int a = 0; a < 3; a++) now.x[a] = w->y[a];
    now.phi = w->phi, now.omega = w->omega;
    now.inv_w0 = w->inv_w0, now.c = w->c, now.phi_rev = w->phi_rev, now.phi_sum = w->phi_sum;
    bac_inverse_weights(&now, NULL, w->inv_w0);
    bac_coefficients(&now, w->inv_w0, NULL, w->c, w->phi_rev, w->phi_sum);
    bac_stress_force(&now, w->c, w->phi_rev, w->phi_sum, w->tau, force, work_point);
    return missing;
}
