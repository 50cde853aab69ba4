#include "solid/bond/diagnostics.h"
#include "core/parallel.h"

#include "core/reduce.h"

#include <math.h>

void pd_damage(const BondBody *body, double *damage) {
    const int dim = body->dim;
#pragma omp parallel for schedule(static) if (body->n >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < body->n; i++) {
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
    return broken / 2;
}

double pd_kinetic_energy(const BondBody *body) {
    double partial[REDUCE_CHUNKS];
#pragma omp parallel for schedule(static) if (body->n >= PARALLEL_MIN_ITEMS)
    for (int c = 0; c < REDUCE_CHUNKS; c++) {
        int64_t lo, hi;
        reduce_chunk(body->n, c, &lo, &hi);
        double s = 0.0;
        for (int64_t i = lo; i < hi; i++) {
            double v2 = 0.0;
            for (int d = 0; d < body->dim; d++) v2 += body->v[d][i] * body->v[d][i];
            s += 0.5 * body->cfg.density * body->volume[i] * v2;
        }
        partial[c] = s;
    }
    return reduce_combine(partial);
}

double pd_elastic_energy(const BondBody *body) {
    const int dim = body->dim;
    double partial[REDUCE_CHUNKS];
#pragma omp parallel for schedule(static) if (body->n >= PARALLEL_MIN_ITEMS)
    for (int c = 0; c < REDUCE_CHUNKS; c++) {
        int64_t lo, hi;
        reduce_chunk(body->n, c, &lo, &hi);
        double s = 0.0;
        for (int64_t i = lo; i < hi; i++) {
            double w = 0.0;
            for (int64_t b = body->bond_first[i]; b < body->bond_first[i + 1]; b++) {
                double k = fabs((double)body->bond_coef[b]);
                if (k == 0.0) continue;
                int32_t j = body->bond_nbr[b];
                double e2 = 0.0, r2 = 0.0;
                for (int d = 0; d < dim; d++) {
                    double e = body->x[d][j] - body->x[d][i];
                    double r = e + body->u[d][j] - body->u[d][i];
                    e2 += e * e;
                    r2 += r * r;
                }
                double stretch = sqrt(r2) - sqrt(e2);
                w += k * stretch * stretch;
            }
            s += 0.25 * body->coef_scale * w * body->volume[i];
        }
        partial[c] = s;
    }
    return reduce_combine(partial);
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
