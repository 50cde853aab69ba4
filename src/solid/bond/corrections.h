/* Surface correction of bond-based PD by the energy method (Madenci and
 * Oterkus 2014, Sec. 4.2; paper 000 beta_ij in Eq. 28). */
#ifndef NSPD_SOLID_BOND_CORRECTIONS_H
#define NSPD_SOLID_BOND_CORRECTIONS_H

#include "solid/pd/config.h"

#include <stdint.h>

#include <math.h>

/* What the energy method reads of a body under construction: points,
 * volumes and families, and the constants of its material. Plain arrays, so
 * the correction does not depend on the body that uses it. */
typedef struct {
    const PdConfig *cfg;
    int dim;
    int64_t n;
    const double *x[3];
    const double *volume;
    const int64_t *bond_first;
    const int32_t *bond_nbr;
    double micromodulus, horizon, spacing;
} PdFamilies;

/* Per-point surface factors g_d (d < dim), written to factor[d][i]:
 * impose u = strain * x_d e_d (strain = 1e-3) on every point, compute the PD
 * strain energy density W_i = (1/4) sum_j c nu_ij V_j s_ij^2 |xi_ij| with the
 * volume correction but no surface correction, and set g_d,i = W_classical /
 * W_i. */
int pd_surface_factors(const PdFamilies *body, double *factor[3]);

/* beta_ij from the two ends' factors, combined as an ellipse(oid) over the
 * bond direction n = xi/|xi|: beta = (sum_d n_d^2 / G_d^2)^(-1/2), with
 * G_d = (g_d,i + g_d,j) / 2. */
static inline double pd_surface_beta(int dim, const double n[3], const double gi[3],
                                     const double gj[3]) {
    double s = 0.0;
    for (int d = 0; d < dim; d++) {
        double G = 0.5 * (gi[d] + gj[d]);
        s += n[d] * n[d] / (G * G);
    }
    return 1.0 / sqrt(s);
}

#endif
