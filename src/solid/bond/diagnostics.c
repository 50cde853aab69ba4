#include "solid/bond/diagnostics.h"
#include "core/parallel.h"

#include "core/mem.h"
#include "core/reduce.h"
#include "core/status.h"
#include "solid/bond/halo.h"
#include "solid/bond/stencil.h"

#include <math.h>
#if defined(__AVX512F__)
#include <immintrin.h>
#endif

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

/* The energies' terms of point i (`terms`: the elastic ones, from the
 * lattice view, or NULL). */
static double kinetic_term(const BondBody *body, const double *terms, int64_t i) {
    (void)terms;
    double v2 = 0.0;
    for (int d = 0; d < body->dim; d++) v2 += body->v[d][i] * body->v[d][i];
    return 0.5 * (body->density ? body->density[i] : body->cfg.density) * body->volume[i] * v2;
}

static double elastic_term(const BondBody *body, const double *terms, int64_t i) {
    if (terms) return terms[i];
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

/* elastic_term of the held points of chunk q of the lattice view into
 * terms[]: a lane a point, its bonds in offset order (the rows' order),
 * the same operations, so the same bits (a missing or broken bond adds
 * 0). DIM is a constant in each instance. */
static inline __attribute__((always_inline)) void
elastic_chunk(const int DIM, const BondBody *body, const BondStencil *s, int64_t q, double *terms) {
    const int64_t c = s->chunk_cell[q];
    const uint16_t *sq = s->state + q * s->offsets;
    const float *kq = s->magnitude + (int64_t)s->block[q] * s->offsets * 8;
    const double *x0 = s->x[0], *x1 = s->x[1], *x2 = s->x[DIM - 1];
    const double *u0 = s->u[0], *u1 = s->u[1], *u2 = s->u[DIM - 1];
    double w[8] = {0};
#if defined(__AVX512F__) && defined(__AVX512VL__)
    /* the loop below in 512-bit lanes (GCC leaves it scalar) */
    __m512d acc = _mm512_setzero_pd();
    for (int o = 0; o < s->offsets; o++) {
        const int64_t j = c + s->shift[o];
        const __m512d k = _mm512_cvtps_pd(_mm256_load_ps(kq + 8 * o));
        const __m512d ex = _mm512_sub_pd(_mm512_loadu_pd(x0 + j), _mm512_load_pd(x0 + c));
        const __m512d ey = _mm512_sub_pd(_mm512_loadu_pd(x1 + j), _mm512_load_pd(x1 + c));
        const __m512d rx =
            _mm512_sub_pd(_mm512_add_pd(ex, _mm512_loadu_pd(u0 + j)), _mm512_load_pd(u0 + c));
        const __m512d ry =
            _mm512_sub_pd(_mm512_add_pd(ey, _mm512_loadu_pd(u1 + j)), _mm512_load_pd(u1 + c));
        __m512d e2 = _mm512_add_pd(_mm512_mul_pd(ex, ex), _mm512_mul_pd(ey, ey));
        __m512d r2 = _mm512_add_pd(_mm512_mul_pd(rx, rx), _mm512_mul_pd(ry, ry));
        if (DIM == 3) {
            const __m512d ez = _mm512_sub_pd(_mm512_loadu_pd(x2 + j), _mm512_load_pd(x2 + c));
            const __m512d rz =
                _mm512_sub_pd(_mm512_add_pd(ez, _mm512_loadu_pd(u2 + j)), _mm512_load_pd(u2 + c));
            e2 = _mm512_add_pd(e2, _mm512_mul_pd(ez, ez));
            r2 = _mm512_add_pd(r2, _mm512_mul_pd(rz, rz));
        }
        const __m512d stretch = _mm512_sub_pd(_mm512_sqrt_pd(r2), _mm512_sqrt_pd(e2));
        const __m512d term =
            _mm512_maskz_mul_pd((__mmask8)sq[o], _mm512_mul_pd(k, stretch), stretch);
        acc = _mm512_add_pd(acc, term);
    }
    _mm512_storeu_pd(w, acc);
#else
    for (int o = 0; o < s->offsets; o++) {
        const int64_t sh = s->shift[o];
        const float *k8 = kq + 8 * o;
        const unsigned bonded = sq[o];
#pragma omp simd
        for (int l = 0; l < 8; l++) {
            const int64_t i = c + l, j = i + sh;
            const double k = (double)k8[l];
            const double ex = x0[j] - x0[i], rx = ex + u0[j] - u0[i];
            const double ey = x1[j] - x1[i], ry = ey + u1[j] - u1[i];
            double e2 = ex * ex + ey * ey, r2 = rx * rx + ry * ry;
            if (DIM == 3) {
                const double ez = x2[j] - x2[i], rz = ez + u2[j] - u2[i];
                e2 += ez * ez, r2 += rz * rz;
            }
            const double stretch = sqrt(r2) - sqrt(e2), term = k * stretch * stretch;
            w[l] += bonded >> l & 1 ? term : 0.0; /* a select: term is formed either way */
        }
    }
#endif
    for (int l = 0; l < 8; l++) {
        const int32_t i = s->cell_point[c + l];
        if (i >= 0 && i < body->n) terms[i] = 0.25 * body->coef_scale * w[l] * body->volume[i];
    }
}

/* The sum of a per-point term over the whole body in reduce.h's order.
 * On several processes each rank's terms are gathered in the whole
 * body's order and summed alike on every rank: the additions of one
 * process, whatever the number (a failed gather is MPI's abort). */
static double body_sum(const BondBody *body, const double *terms,
                       double (*term)(const BondBody *, const double *, int64_t)) {
    if (!body->halo) {
        double partial[REDUCE_CHUNKS];
#pragma omp parallel for schedule(static) if (body->n >= PARALLEL_MIN_ITEMS)
        for (int c = 0; c < REDUCE_CHUNKS; c++) {
            int64_t lo, hi;
            reduce_chunk(body->n, c, &lo, &hi);
            double s = 0.0;
            for (int64_t i = lo; i < hi; i++) s += term(body, terms, i);
            partial[c] = s;
        }
        return reduce_combine(partial);
    }
    const int64_t total = body->halo->points.total;
    double *mine = NULL, *all = NULL, sum = (double)NAN;
    if (nspd_alloc(&mine, (size_t)body->n + 1, sizeof *mine) == NSPD_OK &&
        nspd_alloc(&all, (size_t)total, sizeof *all) == NSPD_OK) {
        for (int64_t i = 0; i < body->n; i++) mine[i] = term(body, terms, i);
        (void)comm_allgatherv(&body->halo->points.comm, mine, (int)body->n, all);
        sum = reduce_sum(all, total);
    }
    nspd_free(&mine);
    nspd_free(&all);
    return sum;
}

double pd_kinetic_energy(const BondBody *body) {
    return body_sum(body, NULL, kinetic_term);
}

double pd_elastic_energy(const BondBody *body) {
    double *terms = NULL; /* from the view when there is one (and memory) */
    if (body->stencil && nspd_alloc(&terms, (size_t)body->n + 1, sizeof *terms) == NSPD_OK) {
        const BondStencil *s = body->stencil;
        bond_stencil_refresh(body->stencil, body);
#pragma omp parallel for schedule(static) if (body->bond_count >= PARALLEL_MIN_ITEMS)
        for (int64_t q = 0; q < s->chunks; q++) {
            if (body->dim == 2)
                elastic_chunk(2, body, s, q, terms);
            else
                elastic_chunk(3, body, s, q, terms);
        }
    }
    const double sum = body_sum(body, terms, elastic_term);
    nspd_free(&terms);
    return sum;
}

void pd_momentum(const BondBody *body, double p[3]) {
    /* one density: it multiplies the sum; several: each point's its own */
    const double *rho = body->density;
    for (int d = 0; d < 3; d++) {
        double partial[REDUCE_CHUNKS];
#pragma omp parallel for schedule(static) if (body->n >= PARALLEL_MIN_ITEMS)
        for (int c = 0; c < REDUCE_CHUNKS; c++) {
            int64_t lo, hi;
            reduce_chunk(body->n, c, &lo, &hi);
            double s = 0.0;
            if (d < body->dim)
                for (int64_t i = lo; i < hi; i++)
                    s += (rho ? rho[i] : 1.0) * body->volume[i] * body->v[d][i];
            partial[c] = s;
        }
        p[d] = (rho ? 1.0 : body->cfg.density) * reduce_combine(partial);
    }
}

void pd_material_totals(const BondBody *body, int k, double *mass, double *kinetic,
                        double velocity[3]) {
    double m = 0.0, e = 0.0, p[3] = {0.0, 0.0, 0.0};
    for (int64_t i = 0; i < body->n; i++) {
        if (body->material[i] != k) continue;
        const double mi = body->density[i] * body->volume[i];
        double v2 = 0.0;
        for (int d = 0; d < body->dim; d++) {
            p[d] += mi * body->v[d][i];
            v2 += body->v[d][i] * body->v[d][i];
        }
        m += mi;
        e += 0.5 * mi * v2;
    }
    *mass = m;
    *kinetic = e;
    for (int d = 0; d < 3; d++) velocity[d] = m > 0.0 ? p[d] / m : 0.0;
}
