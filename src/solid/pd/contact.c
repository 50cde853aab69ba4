#include "solid/pd/contact.h"

#include "core/mem.h"
#include "core/neighbours.h"
#include "core/parallel.h"
#include "core/reduce.h"
#include "core/status.h"

#include <math.h>

int pd_contact_create(PdContact *c, const PdContactConfig *cfg, int dim, int64_t n, double dx,
                      double horizon, double micromodulus) {
    *c = (PdContact){.dim = dim,
                     .n = n,
                     .spacing = dx,
                     .cutoff = cfg->distance * dx,
                     .skin = cfg->skin * dx,
                     .compression = cfg->compression,
                     .coef = cfg->stiffness * micromodulus / horizon};
    for (int d = 0; d < dim; d++) {
        TRY(nspd_alloc(&c->y[d], (size_t)n, sizeof(double)));
        TRY(nspd_alloc(&c->u_built[d], (size_t)n, sizeof(double)));
    }
    return NSPD_OK;
}

void pd_contact_free(PdContact *c) {
    for (int d = 0; d < 3; d++) {
        nspd_free(&c->y[d]);
        nspd_free(&c->u_built[d]);
    }
    nspd_free(&c->first);
    nspd_free(&c->nbr);
}

/* Whether a point has moved by more than skin / 2 since the last build (or
 * there is none). The max reduction is exact. */
static bool lists_stale(const PdContact *c, const double *const u[3]) {
    if (!c->first) return true;
    const double limit2 = 0.25 * c->skin * c->skin;
    bool stale = false;
#pragma omp parallel for schedule(static) reduction(|| : stale) if (c->n >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < c->n; i++) {
        double m2 = 0.0;
        for (int d = 0; d < c->dim; d++) {
            const double s = u[d][i] - c->u_built[d][i];
            m2 += s * s;
        }
        stale = stale || m2 > limit2;
    }
    return stale;
}

static int rebuild(PdContact *c, const double *const x[3], const double *const u[3]) {
    for (int d = 0; d < c->dim; d++)
        for (int64_t i = 0; i < c->n; i++) {
            c->y[d][i] = x[d][i] + u[d][i];
            c->u_built[d][i] = u[d][i];
        }
    nspd_free(&c->first);
    nspd_free(&c->nbr);
    c->builds++;
    return neighbours_find(c->n, c->dim, (const double *const *)c->y, c->cutoff + c->skin,
                           &c->first, &c->nbr);
}

/* The pair i, j: the offset y_j - y_i into dy and d_s - d (> 0 in
 * contact, with the distance d into *dist). Most candidates are beyond the
 * cutoff, where d_s <= cutoff says no contact before any root. */
static inline double overlap(const PdContact *c, const double *const x[3], const double *const u[3],
                             int64_t i, int64_t j, double dy[3], double *dist) {
    double d2 = 0.0, xi2 = 0.0;
    for (int d = 0; d < c->dim; d++) {
        const double xi = x[d][j] - x[d][i];
        dy[d] = xi + (u[d][j] - u[d][i]);
        d2 += dy[d] * dy[d];
        xi2 += xi * xi;
    }
    if (d2 >= c->cutoff * c->cutoff) return 0.0;
    const double ds = fmin(c->compression * sqrt(xi2), c->cutoff);
    if (!(d2 < ds * ds)) return 0.0;
    *dist = sqrt(d2);
    return ds - *dist;
}

int pd_contact_add(PdContact *c, const double *const x[3], const double *const u[3],
                   const double *volume, double *const force[3]) {
    if (lists_stale(c, u)) TRY(rebuild(c, x, u));
#pragma omp parallel for schedule(static) if (c->n >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < c->n; i++) {
        double f[3] = {0.0, 0.0, 0.0};
        for (int64_t k = c->first[i]; k < c->first[i + 1]; k++) {
            const int64_t j = c->nbr[k];
            double dy[3], d;
            const double s = overlap(c, x, u, i, j, dy, &d);
            if (s > 0.0) {
                const double m = c->coef * s / d * volume[j];
                for (int a = 0; a < c->dim; a++) f[a] -= m * dy[a];
            }
        }
        for (int a = 0; a < c->dim; a++) force[a][i] += f[a];
    }
    return NSPD_OK;
}

/* point i's share of W: 1/2 sum_j c_s / (2 delta) (d_s - d)^2 V_i V_j */
static double point_energy(const PdContact *c, const double *const x[3], const double *const u[3],
                           const double *volume, int64_t i) {
    double w = 0.0;
    for (int64_t k = c->first[i]; k < c->first[i + 1]; k++) {
        double dy[3], d;
        const double s = overlap(c, x, u, i, c->nbr[k], dy, &d);
        w += s * s * volume[c->nbr[k]];
    }
    return 0.25 * c->coef * w * volume[i];
}

double pd_contact_energy(const PdContact *c, const double *const x[3], const double *const u[3],
                         const double *volume) {
    if (!c->first) return 0.0;
    double partial[REDUCE_CHUNKS];
#pragma omp parallel for schedule(static) if (c->n >= PARALLEL_MIN_ITEMS)
    for (int k = 0; k < REDUCE_CHUNKS; k++) {
        int64_t lo, hi;
        reduce_chunk(c->n, k, &lo, &hi);
        double w = 0.0;
        for (int64_t i = lo; i < hi; i++) w += point_energy(c, x, u, volume, i);
        partial[k] = w;
    }
    return reduce_combine(partial);
}

double pd_contact_min_distance(const PdContact *c, const double *const x[3],
                               const double *const u[3], double reference) {
    double best = INFINITY;
    if (!c->first) return best;
#pragma omp parallel for schedule(static) reduction(min : best) if (c->n >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < c->n; i++)
        for (int64_t k = c->first[i]; k < c->first[i + 1]; k++) {
            const int64_t j = c->nbr[k];
            double d2 = 0.0, xi2 = 0.0;
            for (int d = 0; d < c->dim; d++) {
                const double xi = x[d][j] - x[d][i], dy = xi + (u[d][j] - u[d][i]);
                d2 += dy * dy;
                xi2 += xi * xi;
            }
            if (xi2 > reference * reference) best = fmin(best, sqrt(d2));
        }
    return best;
}
