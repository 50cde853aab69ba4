#include "solid/correspondence/bac_force.h"

#include "core/parallel.h"
#include "solid/correspondence/rk_gradient.h"
#include "solid/correspondence/svk.h"

#include <math.h>
#include <stdbool.h>
#include <string.h>

void bac_gather(int dim, int64_t n, const int64_t *first, const int32_t *nbr,
                const int64_t *reverse, const double *volume, const double *T,
                double *const force[3]) {
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < n; i++) {
        double L[3] = {0, 0, 0};
        for (int64_t k = first[i]; k < first[i + 1]; k++) {
            const double V = volume[nbr[k]];
            const int64_t r = reverse[k];
            for (int a = 0; a < dim; a++)
                L[a] += (T[(int64_t)dim * k + a] - T[(int64_t)dim * r + a]) * V;
        }
        for (int a = 0; a < dim; a++) force[a][i] = L[a];
    }
}

int64_t bac_reverse_bonds(int64_t n, const int64_t *first, const int32_t *nbr, int64_t *reverse) {
    int64_t missing = 0;
#pragma omp parallel for schedule(static) reduction(+ : missing) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < n; i++)
        for (int64_t k = first[i]; k < first[i + 1]; k++) {
            const int32_t j = nbr[k];
            reverse[k] = -1;
            for (int64_t m = first[j]; m < first[j + 1]; m++)
                if (nbr[m] == (int32_t)i) {
                    reverse[k] = m;
                    break;
                }
            missing += reverse[k] < 0 ? 1 : 0;
        }
    return missing;
}

/* The bond's deformation gradient F_b = Fm + (Y - Fm xi) (x) xi / |xi|^2,
 * with g = xi / |xi|^2 (one division a bond, formed by the caller). 2D in
 * closed form on the four in-plane entries (the rest of F is 0 in 2D, as
 * rk_deformation_gradient leaves it): the generic loops over 9 entries
 * through memory cost more than the arithmetic. */
static inline void bond_gradient(int dim, const double Fi[9], const double Fj[9],
                                 const double xi[3], const double g[3], const double Y[3],
                                 double Fb[9]) {
    if (dim == 2) {
        const double m00 = 0.5 * (Fi[0] + Fj[0]), m01 = 0.5 * (Fi[1] + Fj[1]);
        const double m10 = 0.5 * (Fi[3] + Fj[3]), m11 = 0.5 * (Fi[4] + Fj[4]);
        const double r0 = Y[0] - m00 * xi[0] - m01 * xi[1];
        const double r1 = Y[1] - m10 * xi[0] - m11 * xi[1];
        for (int q = 0; q < 9; q++) Fb[q] = 0.0;
        Fb[0] = m00 + r0 * g[0], Fb[1] = m01 + r0 * g[1];
        Fb[3] = m10 + r1 * g[0], Fb[4] = m11 + r1 * g[1];
        return;
    }
    for (int q = 0; q < 9; q++) Fb[q] = 0.5 * (Fi[q] + Fj[q]);
    double r[3] = {0.0, 0.0, 0.0};
    for (int a = 0; a < dim; a++) {
        r[a] = Y[a];
        for (int b = 0; b < dim; b++) r[a] -= Fb[3 * a + b] * xi[b];
    }
    for (int a = 0; a < dim; a++)
        for (int b = 0; b < dim; b++) Fb[3 * a + b] += r[a] * g[b];
}

/* P_b of bond k from its F_b (and, with a J2 state, F_b at the start of
 * the step): SVK, or the Green-Naghdi hypoelastic update in the unrotated
 * frame with the midpoint increment (the rotation of F_mid carries the
 * rate; a rigid rotation gives de = 0 exactly, notes 1c.6) and J2 radial
 * return (1c.7), P = J sigma F^-T. */
static void bond_stress(const BacSystem *s, BacState *st, int64_t k, const double Fb[9],
                        const double Fb_prev[9], double P[9]) {
    if (!st) {
        svk_stress(s->dim, Fb, s->lambda, s->mu, P);
        return;
    }
    const double F[4] = {Fb[0], Fb[1], Fb[3], Fb[4]};
    const double Fm[4] = {0.5 * (Fb_prev[0] + Fb[0]), 0.5 * (Fb_prev[1] + Fb[1]),
                          0.5 * (Fb_prev[3] + Fb[3]), 0.5 * (Fb_prev[4] + Fb[4])};
    const double dF[4] = {Fb[0] - Fb_prev[0], Fb[1] - Fb_prev[1], Fb[3] - Fb_prev[3],
                          Fb[4] - Fb_prev[4]};
    double de[3], *sigma = st->sigma + 4 * k, P2[4];
    for (int q = 0; q < 9; q++) P[q] = 0.0;
    const bool upright = F[0] * F[3] - F[1] * F[2] > 0.0;
    st->inverted[k] = upright ? 0 : 1;
    if (!upright || !j2_unrotated_increment_2d(Fm, dF, 1.0, de)) {
        st->inverted[k] = 1;
        st->principal[k] = 0.0;
        return;
    }
    double dzz;
    j2_update_zz(st->material, de, sigma, &st->eqps[k], &dzz);
    st->principal[k] = j2_max_principal(sigma); /* invariant under the in-plane rotation */
    j2_piola_2d(F, sigma, P2);
    const double thick = st->strain_zz ? exp(st->strain_zz[k] += dzz) : 1.0;
    P[0] = thick * P2[0], P[1] = thick * P2[1], P[3] = thick * P2[2], P[4] = thick * P2[3];
}

/* Copies bond k's material state (and its outputs) to its reverse r. */
static void copy_state(BacState *st, int64_t k, int64_t r) {
    for (int q = 0; q < 4; q++) st->sigma[4 * r + q] = st->sigma[4 * k + q];
    st->eqps[r] = st->eqps[k];
    st->principal[r] = st->principal[k];
    st->inverted[r] = st->inverted[k];
    if (st->strain_zz) st->strain_zz[r] = st->strain_zz[k];
}

void bac_force(const BacSystem *s, BacState *st, const double *const u[3], double *const force[3],
               double *work_point, double *work_bond) {
    const int dim = s->dim, dd = dim * dim;
    const int64_t n = s->n, nb = s->first[n];
    double *F = work_point, *Fp = work_point + 9 * n, *inv_w0 = work_point + 18 * n, *T = work_bond,
           *Pb = work_bond + (int64_t)dim * nb;
    rk_deformation_gradient(dim, n, u, s->volume, s->first, s->nbr, s->phi, F);
    if (st) rk_deformation_gradient(dim, n, st->u_prev, s->volume, s->first, s->nbr, s->phi, Fp);
        /* 1 / w0 per point (0 where w0 = 0), read by every bond of the point's
         * neighbours: the same quotient as each bond would form */
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < n; i++) {
        double w = 0.0;
        for (int64_t k = s->first[i]; k < s->first[i + 1]; k++)
            w += s->omega[k] * (s->bond_scale ? s->bond_scale[k] : 1.0) * s->volume[s->nbr[k]];
        inv_w0[i] = w > 0.0 ? 1.0 / w : 0.0;
    }
    /* per pair, from its lower-numbered bond: F_b(ij) = F_b(ji) bit for bit,
     * so the pair's stress (and its state update) is computed once and
     * copied to the reverse bond - the bits each end would compute. Each
     * reverse bond is written by its pair's one canonical bond only. */
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < n; i++) {
        for (int64_t k = s->first[i]; k < s->first[i + 1]; k++) {
            const int64_t r = s->reverse[k];
            if (r >= 0 && r < k) continue; /* the pair's other bond computes it */
            if (s->bond_scale && s->bond_scale[k] == 0.0) continue; /* broken: no stress */
            const int32_t j = s->nbr[k];
            double xi[3] = {0, 0, 0}, Y[3] = {0, 0, 0}, Yp[3] = {0, 0, 0}, xx = 0.0;
            for (int a = 0; a < dim; a++) {
                xi[a] = s->x[a][j] - s->x[a][i];
                Y[a] = xi[a] + (u[a][j] - u[a][i]);
                if (st) Yp[a] = xi[a] + (st->u_prev[a][j] - st->u_prev[a][i]);
                xx += xi[a] * xi[a];
            }
            const double inv_xx = 1.0 / xx;
            const double g[3] = {xi[0] * inv_xx, xi[1] * inv_xx, xi[2] * inv_xx};
            double Fb[9], Fbp[9] = {0}, P[9];
            bond_gradient(dim, F + 9 * i, F + 9 * (int64_t)j, xi, g, Y, Fb);
            if (st) bond_gradient(dim, Fp + 9 * i, Fp + 9 * (int64_t)j, xi, g, Yp, Fbp);
            bond_stress(s, st, k, Fb, Fbp, P);
            for (int a = 0; a < dim; a++)
                for (int b = 0; b < dim; b++) Pb[dd * k + dim * a + b] = P[3 * a + b];
            if (r < 0) continue;
            for (int q = 0; q < dd; q++) Pb[dd * r + q] = Pb[dd * k + q];
            if (st) copy_state(st, k, r);
        }
    }
    /* per point: the stress integral S_i, and T_ij */
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < n; i++) {
        double Si[9] = {0};
        const double inv_wi = inv_w0[i];
        for (int64_t k = s->first[i]; k < s->first[i + 1]; k++) {
            const int32_t j = s->nbr[k];
            if (s->bond_scale && s->bond_scale[k] == 0.0) {
                /* broken: no force, and its stress (no longer defined) is left as it was */
                for (int a = 0; a < dim; a++) T[(int64_t)dim * k + a] = 0.0;
                continue;
            }
            double xi[3] = {0, 0, 0}, xx = 0.0, g[3] = {0, 0, 0};
            for (int a = 0; a < dim; a++) {
                xi[a] = s->x[a][j] - s->x[a][i];
                xx += xi[a] * xi[a];
            }
            const double inv_xx = 1.0 / xx; /* one division a bond: g = xi / |xi|^2 */
            for (int a = 0; a < dim; a++) g[a] = xi[a] * inv_xx;
            const double *P = Pb + dd * k;
            const double omega = s->omega[k] * (s->bond_scale ? s->bond_scale[k] : 1.0);
            const double inv_wj = inv_w0[j];
            const double c = omega * (0.5 * inv_wi + 0.5 * inv_wj) * s->volume[j];
            /* S_i += c P (I - xi xi / |xi|^2) */
            for (int a = 0; a < dim; a++) {
                double Pxi = 0.0;
                for (int b = 0; b < dim; b++) Pxi += P[dim * a + b] * xi[b];
                for (int b = 0; b < dim; b++) Si[3 * a + b] += c * (P[dim * a + b] - Pxi * g[b]);
                /* the direct term (omega / w0_i) P xi / |xi|^2 */
                T[(int64_t)dim * k + a] = omega * inv_wi * Pxi * inv_xx;
            }
        }
        for (int64_t k = s->first[i]; k < s->first[i + 1]; k++)
            for (int a = 0; a < dim; a++) {
                double v = 0.0;
                for (int b = 0; b < dim; b++) v += Si[3 * a + b] * s->phi[(int64_t)dim * k + b];
                T[(int64_t)dim * k + a] += v;
            }
    }
    bac_gather(dim, n, s->first, s->nbr, s->reverse, s->volume, T, force);
}
