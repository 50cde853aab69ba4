/* Energy-method surface correction.
 *
 * Near a free surface a point's horizon is truncated, so it is softer than
 * the bulk. Under a homogeneous strain the classical strain energy density
 * is known exactly; the ratio of it to the PD energy density at each point
 * is that point's correction factor along the strained axis. Interior
 * points get a factor close to 1 (not exactly 1: the lattice sum differs
 * from the integral that calibrated c), which also removes the discretisation
 * error of the bulk stiffness. The stretch used is the exact (nonlinear) one
 * of the imposed displacement, as in Madenci and Oterkus' code; at 1e-3 the
 * difference from the linearised stretch is 1e-3 relative. */
#include "solid/bond/corrections.h"
#include "core/parallel.h"

#include "core/status.h"

#include <math.h>

int pd_surface_factors(const PdFamilies *body, double *factor[3]) {
    const double strain = 1e-3; /* small enough to be linear, large against round-off */
    const PdConfig *cfg = body->cfg;
    const int dim = body->dim;
    const double c = body->micromodulus, horizon = body->horizon, dx = body->spacing;
    const double w_classical = pd_classical_uniaxial_energy(cfg, strain);
    for (int axis = 0; axis < dim; axis++) {
        double *g = factor[axis];
#pragma omp parallel for schedule(static) if (body->n >= PARALLEL_MIN_ITEMS)
        for (int64_t i = 0; i < body->n; i++) {
            double w = 0.0;
            for (int64_t b = body->bond_first[i]; b < body->bond_first[i + 1]; b++) {
                int32_t j = body->bond_nbr[b];
                double xi2 = 0.0, y2 = 0.0;
                for (int d = 0; d < dim; d++) {
                    double e = body->x[d][j] - body->x[d][i];
                    double y = d == axis ? (1.0 + strain) * e : e;
                    xi2 += e * e;
                    y2 += y * y;
                }
                double xi = sqrt(xi2), s = (sqrt(y2) - xi) / xi;
                double nu = pd_volume_factor(xi, horizon, dx, cfg->volume_correction);
                w += 0.25 * c * nu * body->volume[j] * s * s * xi;
            }
            g[i] = w > 0.0 ? w_classical / w : 1.0; /* an isolated point has no energy to fix */
        }
    }
    return NSPD_OK;
}
