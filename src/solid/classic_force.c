#include "solid/classic_force.h"

#include "core/parallel.h"
#include "solid/svk.h"

#include <math.h>
#include <stdbool.h>
#include <string.h>

/* K^-1 of a shape tensor (row-major 3 x 3; 2D embedded with K_33 = 1, so
 * that one formula serves both); false when K is singular by the rule of
 * CLASSIC_MIN_SHAPE. The determinant is scaled by the diagonal so that the
 * test does not depend on the units or on delta. */
static bool shape_inverse(const double K[9], double Kinv[9]) {
    for (int a = 0; a < 3; a++)
        if (!(K[4 * a] > 0.0)) return false;
    double cof[9];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            const int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
            cof[3 * r + c] = K[3 * r1 + c1] * K[3 * r2 + c2] - K[3 * r1 + c2] * K[3 * r2 + c1];
        }
    const double det = K[0] * cof[0] + K[1] * cof[1] + K[2] * cof[2];
    if (!(det / (K[0] * K[4] * K[8]) >= CLASSIC_MIN_SHAPE)) return false;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) Kinv[3 * r + c] = cof[3 * c + r] / det;
    return true;
}

/* Point i's F_i and P_i, and T_ij of its bonds; false when K_i is singular
 * (then F_i = I, P_i = 0 and T_ij = 0). */
static bool point_state(const ClassicSystem *s, int64_t i, const double *const u[3], double g,
                        double F[9], double P[9], double *T) {
    const int dim = s->dim;
    double K[9] = {0}, N[9] = {0};
    for (int64_t k = s->first[i]; k < s->first[i + 1]; k++) {
        const int32_t j = s->nbr[k];
        const double w = s->omega[k] * s->volume[j];
        double xi[3] = {0, 0, 0}, du[3] = {0, 0, 0};
        for (int a = 0; a < dim; a++) {
            xi[a] = s->x[a][j] - s->x[a][i];
            du[a] = u[a][j] - u[a][i];
        }
        for (int a = 0; a < dim; a++)
            for (int b = 0; b < dim; b++) {
                K[3 * a + b] += w * xi[a] * xi[b];
                N[3 * a + b] += w * du[a] * xi[b];
            }
    }
    if (dim == 2) K[8] = 1.0;
    double Kinv[9], H[9] = {0}, A[9] = {0};
    memset(F, 0, 9 * sizeof(double));
    memset(P, 0, 9 * sizeof(double));
    for (int a = 0; a < 3; a++) F[4 * a] = 1.0;
    const bool ok = shape_inverse(K, Kinv);
    if (ok) {
        /* H = F - I = N K^-1, then P = F S(E) and A = P K^-1 */
        for (int a = 0; a < dim; a++)
            for (int b = 0; b < dim; b++) {
                double v = 0.0;
                for (int c = 0; c < dim; c++) v += N[3 * a + c] * Kinv[3 * c + b];
                H[3 * a + b] = v;
                F[3 * a + b] += v;
            }
        svk_stress(dim, F, s->lambda, s->mu, P);
        for (int a = 0; a < dim; a++)
            for (int b = 0; b < dim; b++) {
                double v = 0.0;
                for (int c = 0; c < dim; c++) v += P[3 * a + c] * Kinv[3 * c + b];
                A[3 * a + b] = v;
            }
    }
    for (int64_t k = s->first[i]; k < s->first[i + 1]; k++) {
        double *t = T + (int64_t)dim * k;
        if (!ok) {
            for (int a = 0; a < dim; a++) t[a] = 0.0;
            continue;
        }
        const int32_t j = s->nbr[k];
        double xi[3] = {0, 0, 0};
        for (int a = 0; a < dim; a++) xi[a] = s->x[a][j] - s->x[a][i];
        for (int a = 0; a < dim; a++) {
            double Axi = 0.0, Hxi = 0.0;
            for (int b = 0; b < dim; b++) {
                Axi += A[3 * a + b] * xi[b];
                Hxi += H[3 * a + b] * xi[b];
            }
            const double z = (u[a][j] - u[a][i]) - Hxi;
            t[a] = s->omega[k] * (Axi + g * z);
        }
    }
    return ok;
}

int64_t classic_force(const ClassicSystem *s, const double *const u[3], double *const force[3],
                      double *work_point, double *work_bond) {
    const int dim = s->dim;
    const int64_t n = s->n;
    double *F = work_point, *P = work_point + 9 * n, *T = work_bond;
    /* the penalty's coefficient C_s c / delta (c: the header's micromodulus) */
    const double c = dim == 3
                         ? 18.0 * (s->lambda + 2.0 * s->mu / 3.0) / (M_PI * pow(s->delta, 4))
                         : 12.0 * (s->lambda + s->mu) / (M_PI * s->delta * s->delta * s->delta);
    const double g = s->stabilisation * c / s->delta;
    int64_t singular = 0;
#pragma omp parallel for schedule(static) reduction(+ : singular) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < n; i++)
        singular += point_state(s, i, u, g, F + 9 * i, P + 9 * i, T) ? 0 : 1;
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
    return singular;
}
