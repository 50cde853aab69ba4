/* The implicit penalty relaxation of one flow step (relax.h). */
#include "couple/penalty/relax.h"

#include <math.h>

/* out_P = sum_j W_Pj x[col]: each point's sample of the cell field x. */
static void sample(const PenaltySystem *s, const double *x, double *out) {
    const int width = s->width;
    for (int64_t p = 0; p < s->points; p++) {
        double sum = 0.0;
        for (int j = 0; j < width; j++) {
            const int32_t c = s->col[p * width + j];
            if (c >= 0) sum += s->w[p * width + j] * x[c];
        }
        out[p] = sum;
    }
}

/* y = A x = m x + sum_P b_P W_P (W_P . x), gathered per cell (no scatter). */
static void apply(const PenaltySystem *s, PenaltyWork *wk, const double *x, double *y) {
    sample(s, x, wk->sample);
    for (int64_t c = 0; c < s->cells; c++) {
        double sum = s->mass[c] * x[c];
        for (int64_t k = s->first[c]; k < s->first[c + 1]; k++) {
            const int32_t p = s->point[k];
            sum += s->b[p] * s->weight[k] * wk->sample[p];
        }
        y[c] = sum;
    }
}

static double dot(const double *a, const double *b, int64_t n) {
    double sum = 0.0;
    for (int64_t k = 0; k < n; k++) sum += a[k] * b[k];
    return sum;
}

/* One component d: preconditioned CG on A u' = m u + sum_P b_P W_P v_P
 * from u' = u; the solution in wk->x. */
static void solve(const PenaltySystem *s, PenaltyWork *wk, int d, int *iterations,
                  double *residual) {
    const int64_t nc = s->cells;
    double *x = wk->x, *r = wk->r, *z = wk->z, *p = wk->p, *ap = wk->ap;
    for (int64_t c = 0; c < nc; c++) x[c] = s->u[d][c];
    apply(s, wk, x, ap);
    double rhs_norm2 = 0.0;
    for (int64_t c = 0; c < nc; c++) {
        double rhs = s->mass[c] * s->u[d][c];
        for (int64_t k = s->first[c]; k < s->first[c + 1]; k++) {
            const int32_t pt = s->point[k];
            rhs += s->b[pt] * s->weight[k] * s->v[d][pt];
        }
        rhs_norm2 += rhs * rhs;
        r[c] = rhs - ap[c];
        z[c] = r[c] / wk->diag[c];
        p[c] = z[c];
    }
    const double scale2 = rhs_norm2 > 0.0 ? rhs_norm2 : 1.0;
    double rz = dot(r, z, nc), rr = dot(r, r, nc);
    int it = 0;
    while (rr > PENALTY_CG_TOL * PENALTY_CG_TOL * scale2 && it < PENALTY_CG_MAX) {
        apply(s, wk, p, ap);
        const double pap = dot(p, ap, nc);
        if (!(pap > 0.0)) break;
        const double alpha = rz / pap;
        for (int64_t c = 0; c < nc; c++) {
            x[c] += alpha * p[c];
            r[c] -= alpha * ap[c];
            z[c] = r[c] / wk->diag[c];
        }
        const double rz_new = dot(r, z, nc);
        const double beta = rz_new / rz;
        rz = rz_new;
        for (int64_t c = 0; c < nc; c++) p[c] = z[c] + beta * p[c];
        rr = dot(r, r, nc);
        it++;
    }
    *iterations = it;
    *residual = sqrt(rr / scale2);
}

void penalty_relax(const PenaltySystem *s, PenaltyWork *wk, double *J[2], PenaltyStats *stats) {
    *stats = (PenaltyStats){0};
    /* the preconditioner: A's diagonal, m_c + sum_P b_P W_Pc^2 */
    for (int64_t c = 0; c < s->cells; c++) {
        double diag = s->mass[c];
        for (int64_t k = s->first[c]; k < s->first[c + 1]; k++)
            diag += s->b[s->point[k]] * s->weight[k] * s->weight[k];
        wk->diag[c] = diag;
    }
    for (int d = 0; d < 2; d++) {
        int it = 0;
        double res = 0.0;
        solve(s, wk, d, &it, &res);
        if (it > stats->iterations) stats->iterations = it;
        if (res > stats->residual) stats->residual = res;
        sample(s, wk->x, wk->sample);
        for (int64_t p = 0; p < s->points; p++) {
            const double rel = wk->sample[p] - s->v[d][p];
            J[d][p] = s->b[p] * rel;
            stats->slip_work += s->b[p] * rel * rel;
        }
    }
    /* the slip left after the step: v' - s' = (v - s') (1 - b/m) */
    for (int64_t p = 0; p < s->points; p++) {
        if (!(s->b[p] > 0.0)) continue;
        const double keep = (1.0 - s->b[p] / s->m[p]) / s->b[p];
        const double slip = hypot(J[0][p] * keep, J[1][p] * keep);
        if (slip > stats->slip_max) stats->slip_max = slip;
    }
}
