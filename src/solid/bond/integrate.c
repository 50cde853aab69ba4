#include "solid/bond/integrate.h"
#include "core/parallel.h"

#include "core/status.h"
#include "core/timer.h"
#include "solid/bond/force.h"
#include "solid/bond/halo.h"
#include "solid/bond/stencil.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>

/* The body's arrays as the shared kick and drift read them; the drift
 * writes the lattice view's displacements too (stencil.h). */
static PdMotion motion_of(BondBody *body) {
    PdMotion m = {.dim = body->dim,
                  .n = body->n,
                  .density = body->cfg.density,
                  .point_density = body->density,
                  .body_force = body->cfg.body_force,
                  .x = {body->x[0], body->x[1], body->x[2]},
                  .region = body->region,
                  .boundary = &body->boundary};
    for (int d = 0; d < 3; d++) {
        m.u[d] = body->u[d];
        m.v[d] = body->v[d];
        m.force[d] = body->force[d];
        m.external[d] = body->external[d];
        if (body->stencil) m.mirror[d] = body->stencil->u[d];
    }
    if (body->stencil) m.mirror_at = body->stencil->point_cell;
    m.balance = &body->motion_balance;
    return m;
}

/* The first point (the whole body's lowest index, on any number of
 * processes) whose displacement or velocity is not finite. */
static int report_non_finite(const BondBody *body) {
    char text[400] = "";
    int64_t first = INT64_MAX;
    for (int64_t i = 0; i < body->n && first == INT64_MAX; i++)
        for (int d = 0; d < body->dim; d++)
            if (!isfinite(body->u[d][i]) || !isfinite(body->v[d][i])) {
                first = bond_halo_global(body, i);
                snprintf(text, sizeof text,
                         "solid point %lld at (%g, %g, %g) m has a non-finite displacement or "
                         "velocity at step %lld (t = %g s); the time step is probably above the "
                         "stable limit",
                         (long long)first, body->x[0][i], body->x[1][i], body->x[2][i],
                         (long long)body->step + 1, body->time);
                break;
            }
    if (body->halo)
        first = comm_first_failure(&body->halo->points.comm, first, text, (int)sizeof text);
    if (first == INT64_MAX)
        return NSPD_FAIL(NSPD_ERR_INTERNAL, "non-finite value reported but not found");
    return NSPD_FAIL(NSPD_ERR_NUMERIC, "%s", text);
}

/* After the drift: the ghosts' displacements from their owners, into the
 * view too, whose cells the drift brought up to date (stencil.h). */
static void exchange_and_mark(BondBody *body) {
    bond_halo_exchange(body);
    if (!body->stencil) return;
    bond_stencil_refresh_ghosts(body->stencil, body);
    body->stencil->u_current = true;
}

int pd_step(BondBody *body, double dt) {
    bool bad;
    const PdMotion m = motion_of(body);
    if (body->cfg.integrator == PD_VELOCITY_VERLET) {
        if (!body->force_valid) TRY(pd_force_compute(body));
        const double t = body->time;
        pd_kick(&m, 0.5 * dt, t, t + 0.5 * dt);
        bad = pd_drift(&m, dt, t + dt);
        exchange_and_mark(body);
        TRY(pd_force_compute(body));
        pd_kick(&m, 0.5 * dt, t + dt, t + dt);
        body->force_valid = true;
    } else {
        TRY(pd_force_compute(body));
        bad = pd_kick_drift(&m, dt, body->time, body->time + dt);
        exchange_and_mark(body);
        body->force_valid = false;
    }
    /* on several processes all fail together (integers: exact) */
    if (body->halo) {
        const double t0 = nspd_wall_time();
        bad = comm_max_i64(&body->halo->points.comm, bad) != 0;
        body->halo->points.seconds += nspd_wall_time() - t0;
    }
    if (bad) return report_non_finite(body);
    body->step++;
    body->time += dt;
    return NSPD_OK;
}

int pd_step_constrained(BondBody *body, double dt) {
    const PdMotion m = motion_of(body);
    const double t = body->time;
    bool bad = pd_drift(&m, dt, t + dt);
    exchange_and_mark(body);
    TRY(pd_force_compute(body));
    pd_kick(&m, dt, t + dt, t + dt);
    /* velocity Verlet's next step kicks with this force */
    body->force_valid = body->cfg.integrator == PD_VELOCITY_VERLET;
    if (body->halo) bad = comm_max_i64(&body->halo->points.comm, bad) != 0;
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
            const double rho = body->density ? body->density[i] : body->cfg.density;
            double dt2 = 2.0 * rho / (body->coef_scale * sum);
            if (dt2 < min_dt2) min_dt2 = dt2;
        }
    }
    /* on several processes the least over all (-max(-x): exact) */
    if (body->halo) min_dt2 = -comm_max(&body->halo->points.comm, -min_dt2);
    return sqrt(min_dt2);
}

double pd_interior_stable_dt(const PdConfig *cfg) {
    const double m = cfg->horizon_factor, dx = cfg->spacing;
    if (!(m > 0.0 && dx > 0.0 && cfg->density > 0.0) || m > 64.0) return 0.0;
    const int reach = (int)floor(m), dim = cfg->dim;
    const double volume = pow(dx, dim) * (dim == 2 ? cfg->thickness : 1.0);
    const double c = pd_micromodulus(cfg);
    double sum = 0.0;
    for (int k = dim == 3 ? -reach : 0; k <= (dim == 3 ? reach : 0); k++)
        for (int j = -reach; j <= reach; j++)
            for (int i = -reach; i <= reach; i++) {
                const double r2 = (double)(i * i + j * j + k * k);
                if (r2 == 0.0 || r2 > m * m) continue;
                const double len = sqrt(r2) * dx;
                sum += c * pd_volume_factor(len, m * dx, dx, cfg->volume_correction) * volume / len;
            }
    if (!(sum > 0.0)) return 0.0;
    double dt = sqrt(2.0 * cfg->density / sum);
    /* several materials: the least of theirs (sum scales with E) */
    for (int k = 1; k < cfg->material_count; k++) {
        const PdMaterial *mk = &cfg->materials[k];
        dt = fmin(dt, sqrt(2.0 * mk->density / (sum * mk->youngs_modulus / cfg->youngs_modulus)));
    }
    return dt;
}
