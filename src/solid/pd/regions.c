#include "solid/pd/regions.h"

#include "core/mem.h"
#include "core/parallel.h"
#include "core/status.h"

#include <math.h>

void pd_regions_assign(const PdConfig *cfg, int64_t n, const double *const x[3], int16_t *region,
                       double *const v[3]) {
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < n; i++) {
        double p[3] = {x[0][i], x[1][i], x[2][i]};
        region[i] = -1;
        for (int r = 0; r < cfg->boundary_count; r++) {
            if (shapeset_contains(&cfg->boundaries[r].region, p)) {
                region[i] = (int16_t)r;
                break;
            }
        }
        for (int k = 0; k < cfg->initial_velocity_count; k++) {
            if (shapeset_contains(&cfg->initial_velocities[k].region, p))
                for (int d = 0; d < 3; d++) v[d][i] = cfg->initial_velocities[k].velocity[d];
        }
    }
}

int pd_boundary_table_build(PdBoundaryTable *t, const PdConfig *cfg) {
    const size_t n = 3 * (size_t)cfg->boundary_count;
    TRY(nspd_alloc(&t->velocity_given, n, sizeof(uint8_t)));
    TRY(nspd_alloc(&t->displacement_held, n, sizeof(uint8_t)));
    TRY(nspd_alloc(&t->velocity, n, sizeof(double)));
    TRY(nspd_alloc(&t->displacement, n, sizeof(double)));
    TRY(nspd_alloc(&t->force_density, n, sizeof(double)));
    t->count = cfg->boundary_count;
    for (int r = 0; r < cfg->boundary_count; r++) {
        const PdBoundaryRegion *b = &cfg->boundaries[r];
        for (int d = 0; d < 3; d++) {
            const size_t k = 3 * (size_t)r + (size_t)d;
            t->velocity_given[k] = (b->velocity_mask >> d) & 1u;
            t->displacement_held[k] = (b->displacement_mask >> d) & 1u;
            t->velocity[k] = b->velocity[d];
            t->displacement[k] = b->displacement[d];
            t->force_density[k] = b->force_density[d];
        }
    }
    return NSPD_OK;
}

void pd_boundary_table_free(PdBoundaryTable *t) {
    nspd_free(&t->velocity_given);
    nspd_free(&t->displacement_held);
    nspd_free(&t->velocity);
    nspd_free(&t->displacement);
    nspd_free(&t->force_density);
    t->count = 0;
}

/* pd_kick's velocity of point i. */
static inline void kick_point(const PdMotion *m, double inv_rho, double h, int64_t i) {
    const PdBoundaryTable *bt = m->boundary;
    const int r = m->region[i];
    for (int d = 0; d < m->dim; d++) {
        const int k = 3 * r + d; /* read only when r >= 0 */
        double b = m->external[d][i] + m->body_force[d];
        if (r >= 0) b += bt->force_density[k];
        m->v[d][i] += (m->force[d][i] + b) * inv_rho * h;
        if (r >= 0) {
            if (bt->velocity_given[k]) m->v[d][i] = bt->velocity[k];
            if (bt->displacement_held[k]) m->v[d][i] = 0.0;
        }
    }
}

/* pd_drift's displacement of point i; false if it is not finite. */
static inline bool drift_point(const PdMotion *m, double h, int64_t i) {
    const PdBoundaryTable *bt = m->boundary;
    const int r = m->region[i];
    bool finite = true;
    for (int d = 0; d < m->dim; d++) {
        double u = m->u[d][i] + m->v[d][i] * h;
        if (r >= 0 && bt->displacement_held[3 * r + d]) u = bt->displacement[3 * r + d];
        m->u[d][i] = u;
        if (m->mirror_at) m->mirror[d][m->mirror_at[i]] = u;
        finite = finite && isfinite(u);
    }
    return finite;
}

/* What motion_pass does to each point. */
enum { MOTION_KICK, MOTION_DRIFT, MOTION_KICK_DRIFT };

/* One pass over the points, each thread on its share (m->balance): the
 * kick, the drift, or both point by point. Returns whether a drifted
 * displacement is not finite. */
static bool motion_pass(const PdMotion *m, double h, int what) {
    const double inv_rho = 1.0 / m->density;
    bool bad = false;
#pragma omp parallel reduction(|| : bad) if (m->n >= PARALLEL_MIN_ITEMS)
    {
        int64_t lo, hi;
        const double started = balance_begin(m->balance, m->n, &lo, &hi);
        if (what == MOTION_KICK) {
            for (int64_t i = lo; i < hi; i++) kick_point(m, inv_rho, h, i);
        } else if (what == MOTION_DRIFT) {
            for (int64_t i = lo; i < hi; i++) bad = !drift_point(m, h, i) || bad;
        } else {
            for (int64_t i = lo; i < hi; i++) {
                kick_point(m, inv_rho, h, i);
                bad = !drift_point(m, h, i) || bad;
            }
        }
        balance_end(m->balance, started);
    }
    balance_update(m->balance);
    return bad;
}

void pd_kick(const PdMotion *m, double h) {
    motion_pass(m, h, MOTION_KICK);
}

bool pd_drift(const PdMotion *m, double h) {
    return motion_pass(m, h, MOTION_DRIFT);
}

bool pd_kick_drift(const PdMotion *m, double h) {
    return motion_pass(m, h, MOTION_KICK_DRIFT);
}
