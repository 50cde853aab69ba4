#include "solid/bond/diagnostics.h"
#include "core/parallel.h"

#include "core/mem.h"
#include "core/reduce.h"
#include "core/status.h"
#include "solid/bond/halo.h"

#include <math.h>

/* A point with every bond intact has damage 0 exactly: its intact sum
 * would repeat the initial one term by term (the same bonds, lengths,
 * factors and order as the build's), so only points with a broken bond
 * take the sum. */
static bool all_intact(const BondBody *body, int64_t i) {
    bool intact = true;
    for (int64_t b = body->bond_first[i]; b < body->bond_first[i + 1]; b++)
        intact &= body->bond_coef[b] != 0.0f;
    return intact;
}

void pd_damage(const BondBody *body, double *damage) {
    const int dim = body->dim;
#pragma omp parallel for schedule(static) if (body->n >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < body->n; i++) {
        if (all_intact(body, i)) {
            damage[i] = 0.0;
            continue;
        }
        double intact = 0.0;
        for (int64_t b = body->bond_first[i]; b < body->bond_first[i + 1]; b++) {
            if (body->bond_coef[b] == 0.0f) continue;
            int32_t j = body->bond_nbr[b];
            double len2 = 0.0;
            for (int d = 0; d < dim; d++) {
                double e = body->x[d][j] - body->x[d][i];
                len2 += e * e;
            }
            intact += pd_volume_factor(sqrt(len2), body->horizon, body->spacing,
                                       body->cfg.volume_correction) *
                      body->volume[j];
        }
        double total = body->initial_bond_volume[i];
        damage[i] = total > 0.0 ? 1.0 - intact / total : 0.0;
    }
}

int64_t pd_broken_bonds(const BondBody *body) {
    int64_t broken = 0;
#pragma omp parallel for schedule(static) reduction(+ : broken) if (body->n >= PARALLEL_MIN_ITEMS)
    for (int64_t b = 0; b < body->bond_count; b++) broken += body->bond_coef[b] == 0.0f;
    /* on several processes each end of a crossing bond is on its own
     * rank, and the sum of integers is exact */
    if (body->halo) broken = comm_sum_i64(&body->halo->points.comm, broken);
    return broken / 2;
}

/* The energies' terms of point i. */
static double kinetic_term(const BondBody *body, int64_t i) {
    double v2 = 0.0;
    for (int d = 0; d < body->dim; d++) v2 += body->v[d][i] * body->v[d][i];
    return 0.5 * body->cfg.density * body->volume[i] * v2;
}

static double elastic_term(const BondBody *body, int64_t i) {
    double w = 0.0;
    for (int64_t b = body->bond_first[i]; b < body->bond_first[i + 1]; b++) {
        double k = fabs((double)body->bond_coef[b]);
        if (k == 0.0) continue;
        int32_t j = body->bond_nbr[b];
        double e2 = 0.0, r2 = 0.0;
        for (int d = 0; d < body->dim; d++) {
            double e = body->x[d][j] - body->x[d][i];
            double r = e + body->u[d][j] - body->u[d][i];
            e2 += e * e;
            r2 += r * r;
        }
        double stretch = sqrt(r2) - sqrt(e2);
        w += k * stretch * stretch;
    }
    return 0.25 * body->coef_scale * w * body->volume[i];
}

/* The sum of a per-point term over the whole body in reduce.h's order.
 * On several processes each rank's terms are gathered in the whole
 * body's order and summed alike on every rank: the additions of one
 * process, whatever the number (a failed gather is MPI's abort). */
static double body_sum(const BondBody *body, double (*term)(const BondBody *, int64_t)) {
    if (!body->halo) {
        double partial[REDUCE_CHUNKS];
#pragma omp parallel for schedule(static) if (body->n >= PARALLEL_MIN_ITEMS)
        for (int c = 0; c < REDUCE_CHUNKS; c++) {
            int64_t lo, hi;
            reduce_chunk(body->n, c, &lo, &hi);
            double s = 0.0;
            for (int64_t i = lo; i < hi; i++) s += term(body, i);
            partial[c] = s;
        }
        return reduce_combine(partial);
    }
    const int64_t total = body->halo->points.total;
    double *mine = NULL, *all = NULL, sum = (double)NAN;
    if (nspd_alloc(&mine, (size_t)body->n + 1, sizeof *mine) == NSPD_OK &&
        nspd_alloc(&all, (size_t)total, sizeof *all) == NSPD_OK) {
        for (int64_t i = 0; i < body->n; i++) mine[i] = term(body, i);
        (void)comm_allgatherv(&body->halo->points.comm, mine, (int)body->n, all);
        sum = reduce_sum(all, total);
    }
    nspd_free(&mine);
    nspd_free(&all);
    return sum;
}

double pd_kinetic_energy(const BondBody *body) {
    return body_sum(body, kinetic_term);
}

double pd_elastic_energy(const BondBody *body) {
    return body_sum(body, elastic_term);
}

void pd_momentum(const BondBody *body, double p[3]) {
    for (int d = 0; d < 3; d++) {
        double partial[REDUCE_CHUNKS];
#pragma omp parallel for schedule(static) if (body->n >= PARALLEL_MIN_ITEMS)
        for (int c = 0; c < REDUCE_CHUNKS; c++) {
            int64_t lo, hi;
            reduce_chunk(body->n, c, &lo, &hi);
            double s = 0.0;
            if (d < body->dim)
                for (int64_t i = lo; i < hi; i++) s += body->volume[i] * body->v[d][i];
            partial[c] = s;
        }
        p[d] = body->cfg.density * reduce_combine(partial);
    }
}
