#include "solid/bac_force.h"

#include "core/parallel.h"
#include "solid/rk_gradient.h"
#include "solid/svk.h"

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

/* The bond's deformation gradient F_b = Fm + (Y - Fm xi) (x) xi / |xi|^2. */
static void bond_gradient(int dim, const double Fi[9], const double Fj[9], const double xi[3],
                          const double Y[3], double Fb[9]) {
    double xx = 0.0;
    for (int a = 0; a < dim; a++) xx += xi[a] * xi[a];
    for (int q = 0; q < 9; q++) Fb[q] = 0.5 * (Fi[q] + Fj[q]);
    double r[3] = {0.0, 0.0, 0.0};
    for (int a = 0; a < dim; a++) {
        r[a] = Y[a];
        for (int b = 0; b < dim; b++) r[a] -= Fb[3 * a + b] * xi[b];
    }
    for (int a = 0; a < dim; a++)
        for (int b = 0; b < dim; b++) Fb[3 * a + b] += r[a] * xi[b] / xx;
}

void bac_force(const BacSystem *s, const double *const u[3], double *const force[3],
               double *work_point, double *work_bond) {
    const int dim = s->dim;
    const int64_t n = s->n;
    double *F = work_point, *w0 = work_point + 9 * n, *T = work_bond;
    rk_deformation_gradient(dim, n, u, s->volume, s->first, s->nbr, s->phi, F);
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < n; i++) {
        double w = 0.0;
        for (int64_t k = s->first[i]; k < s->first[i + 1]; k++)
            w += s->omega[k] * s->volume[s->nbr[k]];
        w0[i] = w;
    }
    /* per point: its bonds' stresses, the stress integral S_i, and T_ij */
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < n; i++) {
        double Si[9] = {0};
        for (int64_t k = s->first[i]; k < s->first[i + 1]; k++) {
            const int32_t j = s->nbr[k];
            double xi[3] = {0, 0, 0}, Y[3] = {0, 0, 0}, xx = 0.0;
            for (int a = 0; a < dim; a++) {
                xi[a] = s->x[a][j] - s->x[a][i];
                Y[a] = xi[a] + u[a][j] - u[a][i];
                xx += xi[a] * xi[a];
            }
            double Fb[9], P[9];
            bond_gradient(dim, F + 9 * i, F + 9 * (int64_t)j, xi, Y, Fb);
            svk_stress(dim, Fb, s->lambda, s->mu, P);
            const double c = s->omega[k] * (0.5 / w0[i] + 0.5 / w0[j]) * s->volume[j];
            /* S_i += c P (I - xi xi / |xi|^2) */
            for (int a = 0; a < dim; a++) {
                double Pxi = 0.0;
                for (int b = 0; b < dim; b++) Pxi += P[3 * a + b] * xi[b];
                for (int b = 0; b < dim; b++)
                    Si[3 * a + b] += c * (P[3 * a + b] - Pxi * xi[b] / xx);
                /* the direct term (omega / w0_i) P xi / |xi|^2 */
                T[(int64_t)dim * k + a] = s->omega[k] / w0[i] * Pxi / xx;
            }
        }
        for (int64_t k = s->first[i]; k < s->first[i + 1]; k++)
            for (int a = 0; a < dim; a++) {
                double v = 0.0;
                for (int b = 0; b < dim; b++) v += Si[3 * a + b] * s->phi[(int64_t)dim * k + b];
                T[(int64_t)dim * k + a] += v;
            }
    }
    /* L_i = sum_j (T_ij - T_ji) V_j, in bond order */
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < n; i++) {
        double L[3] = {0, 0, 0};
        for (int64_t k = s->first[i]; k < s->first[i + 1]; k++) {
            const double V = s->volume[s->nbr[k]];
            const int64_t r = s->reverse[k];
            for (int a = 0; a < dim; a++)
                L[a] += (T[(int64_t)dim * k + a] - T[(int64_t)dim * r + a]) * V;
        }
        for (int a = 0; a < dim; a++) force[a][i] = L[a];
    }
}
