#include "solid/pd/regions.h"

#include "core/mem.h"
#include "core/parallel.h"
#include "core/status.h"

#include <math.h>
#include <string.h>

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
        const double X[EXPR_VARIABLES] = {0.0, p[0], p[1], p[2]};
        for (int k = 0; k < cfg->initial_velocity_count; k++) {
            const PdInitialVelocity *iv = &cfg->initial_velocities[k];
            if (shapeset_contains(&iv->region, p))
                for (int d = 0; d < 3; d++)
                    v[d][i] = iv->velocity_expr[d]
                                  ? expr_eval(&cfg->expressions[iv->velocity_expr[d] - 1], X)
                                  : iv->velocity[d];
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
    TRY(nspd_alloc(&t->velocity_expr, n, sizeof(uint16_t)));
    TRY(nspd_alloc(&t->displacement_expr, n, sizeof(uint16_t)));
    TRY(nspd_alloc(&t->force_expr, n, sizeof(uint16_t)));
    if (cfg->expression_count > 0) {
        TRY(nspd_alloc(&t->expressions, (size_t)cfg->expression_count, sizeof(Expr)));
        memcpy(t->expressions, cfg->expressions, (size_t)cfg->expression_count * sizeof(Expr));
    }
    t->expression_count = cfg->expression_count;
    t->varies = cfg->expression_count > 0;
    for (int d = 0; d < 3; d++) t->body_force_expr[d] = cfg->body_force_expr[d];
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
            t->velocity_expr[k] = b->velocity_expr[d];
            t->displacement_expr[k] = b->displacement_expr[d];
            t->force_expr[k] = b->force_expr[d];
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
    nspd_free(&t->velocity_expr);
    nspd_free(&t->displacement_expr);
    nspd_free(&t->force_expr);
    nspd_free(&t->expressions);
    t->expression_count = 0;
    t->varies = false;
    t->count = 0;
}

/* The times a pass evaluates load expressions at. */
typedef struct {
    double load, end;
} PassTimes;

/* A load component: the constant, or expression e - 1 at (t, point i). */
static inline double load_at(const PdMotion *m, uint16_t e, double constant, double t, int64_t i) {
    if (!e) return constant;
    const double X[EXPR_VARIABLES] = {t, m->x[0][i], m->x[1][i], m->x[2][i]};
    return expr_eval(&m->boundary->expressions[e - 1], X);
}

/* pd_kick's velocity of point i. */
static inline void kick_point(const PdMotion *m, double inv_rho, double h, PassTimes t, int64_t i) {
    const PdBoundaryTable *bt = m->boundary;
    const int r = m->region[i];
    if (m->point_density) inv_rho = 1.0 / m->point_density[i]; /* several materials */
    for (int d = 0; d < m->dim; d++) {
        const int k = 3 * r + d; /* read only when r >= 0 */
        double b =
            m->external[d][i] + load_at(m, bt->body_force_expr[d], m->body_force[d], t.load, i);
        if (r >= 0) b += load_at(m, bt->force_expr[k], bt->force_density[k], t.load, i);
        m->v[d][i] += (m->force[d][i] + b) * inv_rho * h;
        if (r >= 0) {
            if (bt->velocity_given[k])
                m->v[d][i] = load_at(m, bt->velocity_expr[k], bt->velocity[k], t.end, i);
            if (bt->displacement_held[k]) {
                const uint16_t e = bt->displacement_expr[k];
                m->v[d][i] =
                    e ? (load_at(m, e, 0.0, t.end + h, i) - load_at(m, e, 0.0, t.end - h, i)) /
                            (2.0 * h)
                      : 0.0;
            }
        }
    }
}

/* pd_drift's displacement of point i; false if it is not finite. */
static inline bool drift_point(const PdMotion *m, double h, double t_end, int64_t i) {
    const PdBoundaryTable *bt = m->boundary;
    const int r = m->region[i];
    bool finite = true;
    for (int d = 0; d < m->dim; d++) {
        double u = m->u[d][i] + m->v[d][i] * h;
        if (r >= 0 && bt->displacement_held[3 * r + d])
            u = load_at(m, bt->displacement_expr[3 * r + d], bt->displacement[3 * r + d], t_end, i);
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
static bool motion_pass(const PdMotion *m, double h, PassTimes t, int what) {
    const double inv_rho = 1.0 / m->density;
    bool bad = false;
#pragma omp parallel reduction(|| : bad) if (m->n >= PARALLEL_MIN_ITEMS)
    {
        int64_t lo, hi;
        const double started = balance_begin(m->balance, m->n, &lo, &hi);
        if (what == MOTION_KICK) {
            for (int64_t i = lo; i < hi; i++) kick_point(m, inv_rho, h, t, i);
        } else if (what == MOTION_DRIFT) {
            for (int64_t i = lo; i < hi; i++) bad = !drift_point(m, h, t.end, i) || bad;
        } else {
            for (int64_t i = lo; i < hi; i++) {
                kick_point(m, inv_rho, h, t, i);
                bad = !drift_point(m, h, t.end, i) || bad;
            }
        }
        balance_end(m->balance, started);
    }
    balance_update(m->balance);
    return bad;
}

void pd_kick(const PdMotion *m, double h, double t_load, double t_end) {
    motion_pass(m, h, (PassTimes){t_load, t_end}, MOTION_KICK);
}

bool pd_drift(const PdMotion *m, double h, double t_end) {
    return motion_pass(m, h, (PassTimes){t_end, t_end}, MOTION_DRIFT);
}

bool pd_kick_drift(const PdMotion *m, double h, double t_load, double t_end) {
    return motion_pass(m, h, (PassTimes){t_load, t_end}, MOTION_KICK_DRIFT);
}
