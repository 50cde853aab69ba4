#include "solid/pd_integrate.h"
#include "core/parallel.h"

#include "core/status.h"
#include "solid/pd_force.h"

#include <math.h>
#include <stdbool.h>

/* v += a h for every point, then the regions' prescribed velocities (from
 * the flat table body->boundary, not cfg.boundaries). */
static void kick(BondBody *body, double h) {
    const PdConfig *cfg = &body->cfg;
    const int dim = body->dim;
    const double inv_rho = 1.0 / cfg->density;
    const PdBoundaryTable *bt = &body->boundary;
#pragma omp parallel for schedule(static) if (body->n >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < body->n; i++) {
        const int r = body->region[i];
        for (int d = 0; d < dim; d++) {
            const int k = 3 * r + d; /* read only when r >= 0 */
            double b = body->external[d][i] + cfg->body_force[d];
            if (r >= 0) b += bt->force_density[k];
            body->v[d][i] += (body->force[d][i] + b) * inv_rho * h;
            if (r >= 0) {
                if (bt->velocity_given[k]) body->v[d][i] = bt->velocity[k];
                if (bt->displacement_held[k]) body->v[d][i] = 0.0;
            }
        }
    }
}

/* u += v h, then the regions' held displacements. Returns true if any
 * displacement is not finite (the NaN check rides on this pass, which reads
 * and writes u anyway: a NaN in v reaches u in the same step). */
static bool drift(BondBody *body, double h) {
    const int dim = body->dim;
    const PdBoundaryTable *bt = &body->boundary;
    bool bad = false;
#pragma omp parallel for schedule(static) reduction(|| : bad) if (body->n >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < body->n; i++) {
        const int r = body->region[i];
        for (int d = 0; d < dim; d++) {
            double u = body->u[d][i] + body->v[d][i] * h;
            if (r >= 0 && bt->displacement_held[3 * r + d]) u = bt->displacement[3 * r + d];
            body->u[d][i] = u;
            bad = bad || !isfinite(u);
        }
    }
    return bad;
}

static int report_non_finite(const BondBody *body) {
    for (int64_t i = 0; i < body->n; i++)
        for (int d = 0; d < body->dim; d++)
            if (!isfinite(body->u[d][i]) || !isfinite(body->v[d][i]))
                return NSPD_FAIL(NSPD_ERR_NUMERIC,
                                 "solid point %lld at (%g, %g, %g) m has a non-finite "
                                 "displacement or velocity at step %lld (t = %g s); the time "
                                 "step is probably above the stable limit",
                                 (long long)i, body->x[0][i], body->x[1][i], body->x[2][i],
                                 (long long)body->step + 1, body->time);
    return NSPD_FAIL(NSPD_ERR_INTERNAL, "non-finite value reported but not found");
}

int pd_step(BondBody *body, double dt) {
    bool bad;
    if (body->cfg.integrator == PD_VELOCITY_VERLET) {
        if (!body->force_valid) pd_force_compute(body);
        kick(body, 0.5 * dt);
        bad = drift(body, dt);
        pd_force_compute(body);
        kick(body, 0.5 * dt);
        body->force_valid = true;
    } else {
        pd_force_compute(body);
        kick(body, dt);
        bad = drift(body, dt);
        body->force_valid = false;
    }
    if (bad) return report_non_finite(body);
    body->step++;
    body->time += dt;
    return NSPD_OK;
}

double pd_stable_time_step(const BondBody *body) {
    double min_dt2 = INFINITY;
#pragma omp parallel for schedule(static) reduction(min                                            \
                                                    : min_dt2) if (body->n >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < body->n; i++) {
        double sum = 0.0;
        for (int64_t b = body->bond_first[i]; b < body->bond_first[i + 1]; b++)
            sum += fabs((double)body->bond_coef[b]);
        if (sum > 0.0) {
            double dt2 = 2.0 * body->cfg.density / (body->coef_scale * sum);
            if (dt2 < min_dt2) min_dt2 = dt2;
        }
    }
    return sqrt(min_dt2);
}
