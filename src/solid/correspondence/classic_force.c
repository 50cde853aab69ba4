#include "solid/correspondence/classic_force.h"

#include "solid/correspondence/bac_force.h"

#include "core/parallel.h"
#include "solid/correspondence/svk_kernel.h"

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

static double scale_of(const ClassicSystem *s, int64_t k) {
    return s->bond_scale ? s->bond_scale[k] : 1.0;
}

/* K_i and, for each displacement field given (u, and u_prev or NULL),
 * N = sum_j omega (u_j - u_i) (x) xi V_j. */
static void shape_sums(const ClassicSystem *s, int64_t i, const double *const u[3],
                       const double *const up[3], double K[9], double N[9], double Np[9]) {
    const int dim = s->dim;
    for (int64_t k = s->first[i]; k < s->first[i + 1]; k++) {
        const int32_t j = s->nbr[k];
        const double w = s->omega[k] * scale_of(s, k) * s->volume[j];
        double xi[3] = {0, 0, 0}, du[3] = {0, 0, 0}, dp[3] = {0, 0, 0};
        for (int a = 0; a < dim; a++) {
            xi[a] = s->x[a][j] - s->x[a][i];
            if (u) du[a] = u[a][j] - u[a][i];
            if (up) dp[a] = up[a][j] - up[a][i];
        }
        for (int a = 0; a < dim; a++)
            for (int b = 0; b < dim; b++) {
                K[3 * a + b] += w * xi[a] * xi[b];
                if (u) N[3 * a + b] += w * du[a] * xi[b];
                if (up) Np[3 * a + b] += w * dp[a] * xi[b];
            }
    }
    if (dim == 2) K[8] = 1.0;
}

/* H = N K^-1 (dim x dim of row-major 3 x 3) */
static void times_inverse(int dim, const double N[9], const double Kinv[9], double H[9]) {
    for (int a = 0; a < dim; a++)
        for (int b = 0; b < dim; b++) {
            double v = 0.0;
            for (int c = 0; c < dim; c++) v += N[3 * a + c] * Kinv[3 * c + b];
            H[3 * a + b] = v;
        }
}

/* P_i of the J2 point i from F^{n+1} = I + H and F^n = I + Hp (2D): the
 * material step bac_force takes per bond pair (j2_step_2d). */
static void point_stress(ClassicState *st, int64_t i, const double H[9], const double Hp[9],
                         double P[9]) {
    const double F[4] = {1.0 + H[0], H[1], H[3], 1.0 + H[4]};
    const double Fp[4] = {1.0 + Hp[0], Hp[1], Hp[3], 1.0 + Hp[4]};
    double P2[4], zz = 0.0;
    double *strain_zz = st->strain_zz ? &st->strain_zz[i] : &zz;
    st->inverted[i] =
        (uint8_t)j2_step_2d(st->material, st->material->plane_stress, F, Fp, st->sigma + 4 * i,
                            &st->eqps[i], strain_zz, P2, &st->principal[i]);
    P[0] = P2[0], P[1] = P2[1], P[3] = P2[2], P[4] = P2[3];
}

/* Point i's F_i and P_i, and T_ij of its bonds; false when K_i is singular
 * (then F_i = I, P_i = 0 and T_ij = 0). */
static bool point_state(const ClassicSystem *s, ClassicState *st, int64_t i,
                        const double *const u[3], double g, double F[9], double P[9], double *T) {
    const int dim = s->dim;
    double K[9] = {0}, N[9] = {0}, Np[9] = {0};
    shape_sums(s, i, u, st ? st->u_prev : NULL, K, N, Np);
    double Kinv[9], H[9] = {0}, A[9] = {0};
    memset(F, 0, 9 * sizeof(double));
    memset(P, 0, 9 * sizeof(double));
    for (int a = 0; a < 3; a++) F[4 * a] = 1.0;
    const bool ok = shape_inverse(K, Kinv);
    if (st && !ok) {
        st->inverted[i] = 0; /* no F_i: the stress stays as it was (the point is debris) */
        st->principal[i] = 0.0;
    }
    if (ok) {
        /* H = F - I = N K^-1, then P = F S(E) (or the J2 update) and A = P K^-1 */
        times_inverse(dim, N, Kinv, H);
        for (int a = 0; a < dim; a++)
            for (int b = 0; b < dim; b++) F[3 * a + b] += H[3 * a + b];
        if (st) {
            double Hp[9] = {0};
            times_inverse(dim, Np, Kinv, Hp);
            point_stress(st, i, H, Hp, P);
        } else {
            svk_stress(dim, F, s->lambda, s->mu, P);
        }
        times_inverse(dim, P, Kinv, A);
    }
    for (int64_t k = s->first[i]; k < s->first[i + 1]; k++) {
        double *t = T + (int64_t)dim * k;
        if (!ok) {
            for (int a = 0; a < dim; a++) t[a] = 0.0;
            continue;
        }
        const int32_t j = s->nbr[k];
        const double omega = s->omega[k] * scale_of(s, k);
        double xi[3] = {0, 0, 0};
        for (int a = 0; a < dim; a++) xi[a] = s->x[a][j] - s->x[a][i];
        for (int a = 0; a < dim; a++) {
            double Axi = 0.0, Hxi = 0.0;
            for (int b = 0; b < dim; b++) {
                Axi += A[3 * a + b] * xi[b];
                Hxi += H[3 * a + b] * xi[b];
            }
            const double z = (u[a][j] - u[a][i]) - Hxi;
            t[a] = omega * (Axi + g * z);
        }
    }
    return ok;
}

int64_t classic_shape_check(const ClassicSystem *s, const uint8_t *redo, uint8_t *ok) {
    int64_t missing = 0;
#pragma omp parallel for schedule(static) reduction(+ : missing) if (s->first[s->n] >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < s->n; i++) {
        if (redo && !redo[i]) continue;
        double K[9] = {0}, Kinv[9];
        shape_sums(s, i, NULL, NULL, K, NULL, NULL);
        ok[i] = shape_inverse(K, Kinv) ? 1 : 0;
        missing += ok[i] ? 0 : 1;
    }
    return missing;
}

int64_t classic_force(const ClassicSystem *s, ClassicState *st, const double *const u[3],
                      double *const force[3], double *work_point, double *work_bond) {
    const int dim = s->dim;
    const int64_t n = s->n;
    double *F = work_point, *P = work_point + 9 * n, *T = work_bond;
    /* the penalty's coefficient C_s c / delta (c: the header's micromodulus) */
    const double c = dim == 3
                         ? 18.0 * (s->lambda + 2.0 * s->mu / 3.0) / (M_PI * pow(s->delta, 4))
                         : 12.0 * (s->lambda + s->mu) / (M_PI * s->delta * s->delta * s->delta) /
                               (s->thickness > 0.0 ? s->thickness : 1.0);
    const double g = s->stabilisation * c / s->delta;
    int64_t singular = 0;
#pragma omp parallel for schedule(static) reduction(+ : singular) if (s->first[n] >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < n; i++)
        singular += point_state(s, st, i, u, g, F + 9 * i, P + 9 * i, T) ? 0 : 1;
    if (s->exchange_bonds) s->exchange_bonds(s->exchange_context, T);
    bac_gather(dim, n, s->first, s->nbr, s->reverse, s->volume, T, force);
    return singular;
}
