/* The implicit penalty relaxation of one flow step (relax.h). */
#include "couple/penalty/relax.h"

#include <math.h>
#include <string.h>

/* The items one process works on: a list, or all n (list NULL). */
typedef struct {
    int64_t n;
    const int64_t *list;
} Items;

static inline int64_t item(Items it, int64_t k) {
    return it.list ? it.list[k] : k;
}

static Items own_cells(const PenaltySystem *s) {
    return s->div ? (Items){s->div->own_cells, s->div->own_cell} : (Items){s->cells, NULL};
}
static Items near_points(const PenaltySystem *s) {
    return s->div ? (Items){s->div->near_points, s->div->near_point} : (Items){s->points, NULL};
}
static Items own_points(const PenaltySystem *s) {
    return s->div ? (Items){s->div->own_points, s->div->own_point} : (Items){s->points, NULL};
}

/* x at the cells other processes hold, from them. */
static void exchange(const PenaltySystem *s, double *x) {
    if (s->div && s->div->exchange) s->div->exchange(s->div->ctx, x);
}

/* The sums of every process added. */
static void reduce(const PenaltySystem *s, ExactSum *sums, int count) {
    if (s->div && s->div->reduce) s->div->reduce(s->div->ctx, sums, count);
}

/* out_P = sum_j W_Pj x[col] for the points `pts`: each point's sample of
 * the cell field x (x current at every cell they read). */
static void sample(const PenaltySystem *s, Items pts, const double *x, double *out) {
    const int width = s->width;
    for (int64_t q = 0; q < pts.n; q++) {
        const int64_t p = item(pts, q);
        double sum = 0.0;
        for (int j = 0; j < width; j++) {
            const int32_t c = s->col[p * width + j];
            if (c >= 0) sum += s->w[p * width + j] * x[c];
        }
        out[p] = sum;
    }
}

/* y = A x = m x + sum_P b_P W_P (W_P . x) at this process's cells,
 * gathered per cell (no scatter); x's other cells arrive first. */
static void apply(const PenaltySystem *s, PenaltyWork *wk, double *x, double *y) {
    exchange(s, x);
    sample(s, near_points(s), x, wk->sample);
    const Items cells = own_cells(s);
    for (int64_t q = 0; q < cells.n; q++) {
        const int64_t c = item(cells, q);
        double sum = s->mass[c] * x[c];
        for (int64_t k = s->first[c]; k < s->first[c + 1]; k++) {
            const int32_t p = s->point[k];
            sum += s->b[p] * s->weight[k] * wk->sample[p];
        }
        y[c] = sum;
    }
}

/* The whole's sum of a[c] b[c] over the cells, exact. */
static void dot_add(ExactSum *sum, Items cells, const double *a, const double *b) {
    for (int64_t q = 0; q < cells.n; q++) {
        const int64_t c = item(cells, q);
        exact_sum_add(sum, a[c] * b[c]);
    }
}

/* One component d: preconditioned CG on A u' = m u + sum_P b_P W_P v_P
 * from u' = u; the solution in wk->x (this process's cells). */
static void solve(const PenaltySystem *s, PenaltyWork *wk, int d, int *iterations,
                  double *residual) {
    const Items cells = own_cells(s);
    double *x = wk->x, *r = wk->r, *z = wk->z, *p = wk->p, *ap = wk->ap;
    for (int64_t q = 0; q < cells.n; q++) x[item(cells, q)] = s->u[d][item(cells, q)];
    apply(s, wk, x, ap);
    ExactSum sums[3]; /* |rhs|^2, r . z, r . r */
    for (int k = 0; k < 3; k++) exact_sum_clear(&sums[k]);
    for (int64_t q = 0; q < cells.n; q++) {
        const int64_t c = item(cells, q);
        double rhs = s->mass[c] * s->u[d][c];
        for (int64_t k = s->first[c]; k < s->first[c + 1]; k++) {
            const int32_t pt = s->point[k];
            rhs += s->b[pt] * s->weight[k] * s->v[d][pt];
        }
        exact_sum_add(&sums[0], rhs * rhs);
        r[c] = rhs - ap[c];
        z[c] = r[c] / wk->diag[c];
        p[c] = z[c];
    }
    dot_add(&sums[1], cells, r, z);
    dot_add(&sums[2], cells, r, r);
    reduce(s, sums, 3);
    const double rhs_norm2 = exact_sum_value(&sums[0]);
    const double scale2 = rhs_norm2 > 0.0 ? rhs_norm2 : 1.0;
    double rz = exact_sum_value(&sums[1]), rr = exact_sum_value(&sums[2]);
    int it = 0;
    while (rr > PENALTY_CG_TOL * PENALTY_CG_TOL * scale2 && it < PENALTY_CG_MAX) {
        apply(s, wk, p, ap);
        exact_sum_clear(&sums[0]);
        dot_add(&sums[0], cells, p, ap);
        reduce(s, sums, 1);
        const double pap = exact_sum_value(&sums[0]);
        if (!(pap > 0.0)) break;
        const double alpha = rz / pap;
        for (int64_t q = 0; q < cells.n; q++) {
            const int64_t c = item(cells, q);
            x[c] += alpha * p[c];
            r[c] -= alpha * ap[c];
            z[c] = r[c] / wk->diag[c];
        }
        exact_sum_clear(&sums[0]);
        exact_sum_clear(&sums[1]);
        dot_add(&sums[0], cells, r, z);
        dot_add(&sums[1], cells, r, r);
        reduce(s, sums, 2);
        const double rz_new = exact_sum_value(&sums[0]);
        const double beta = rz_new / rz;
        rz = rz_new;
        rr = exact_sum_value(&sums[1]);
        for (int64_t q = 0; q < cells.n; q++) {
            const int64_t c = item(cells, q);
            p[c] = z[c] + beta * p[c];
        }
        it++;
    }
    *iterations = it;
    *residual = sqrt(rr / scale2);
}

/* Component d of the impulses of this process's points from the cells'
 * velocities in wk->x (those of other processes' cells arrive first):
 * J_P = b_P (s_P - v_P), s_P sampled; sum_P b_P |s_P - v_P|^2 added to
 * *slip_work. */
static void impulses(const PenaltySystem *s, PenaltyWork *wk, double *J, int d,
                     ExactSum *slip_work) {
    const Items pts = own_points(s);
    exchange(s, wk->x);
    sample(s, pts, wk->x, wk->sample);
    if (s->div) memset(J, 0, (size_t)s->points * sizeof(double));
    for (int64_t q = 0; q < pts.n; q++) {
        const int64_t p = item(pts, q);
        const double rel = wk->sample[p] - s->v[d][p];
        J[p] = s->b[p] * rel;
        exact_sum_add(slip_work, s->b[p] * rel * rel);
    }
}

/* The largest slip of this process's points after their velocity change
 * J / m: v' - s = (v - s) (1 - b/m), |J| (1 - b/m) / b. */
static double slip_max(const PenaltySystem *s, double *const J[2]) {
    const Items pts = own_points(s);
    double most = 0.0;
    for (int64_t q = 0; q < pts.n; q++) {
        const int64_t p = item(pts, q);
        if (!(s->b[p] > 0.0)) continue;
        const double keep = (1.0 - s->b[p] / s->m[p]) / s->b[p];
        const double slip = hypot(J[0][p] * keep, J[1][p] * keep);
        if (slip > most) most = slip;
    }
    return most;
}

void penalty_explicit(const PenaltySystem *s, PenaltyWork *wk, double *J[2], PenaltyStats *stats) {
    *stats = (PenaltyStats){0};
    const Items cells = own_cells(s);
    ExactSum slip_work;
    exact_sum_clear(&slip_work);
    for (int d = 0; d < 2; d++) {
        for (int64_t q = 0; q < cells.n; q++) wk->x[item(cells, q)] = s->u[d][item(cells, q)];
        impulses(s, wk, J[d], d, &slip_work);
    }
    reduce(s, &slip_work, 1);
    stats->slip_work = exact_sum_value(&slip_work);
    /* the points' slip after their velocity change alone (the cells'
     * change, after, is the caller's) */
    stats->slip_max = slip_max(s, J);
}

void penalty_relax(const PenaltySystem *s, PenaltyWork *wk, double *J[2], PenaltyStats *stats) {
    *stats = (PenaltyStats){0};
    const Items cells = own_cells(s);
    /* the preconditioner: A's diagonal, m_c + sum_P b_P W_Pc^2 */
    for (int64_t q = 0; q < cells.n; q++) {
        const int64_t c = item(cells, q);
        double diag = s->mass[c];
        for (int64_t k = s->first[c]; k < s->first[c + 1]; k++)
            diag += s->b[s->point[k]] * s->weight[k] * s->weight[k];
        wk->diag[c] = diag;
    }
    ExactSum slip_work;
    exact_sum_clear(&slip_work);
    for (int d = 0; d < 2; d++) {
        int it = 0;
        double res = 0.0;
        solve(s, wk, d, &it, &res);
        if (it > stats->iterations) stats->iterations = it;
        if (res > stats->residual) stats->residual = res;
        if (s->u_out[d])
            for (int64_t q = 0; q < cells.n; q++)
                s->u_out[d][item(cells, q)] = wk->x[item(cells, q)];
        impulses(s, wk, J[d], d, &slip_work);
    }
    reduce(s, &slip_work, 1);
    stats->slip_work = exact_sum_value(&slip_work);
    stats->slip_max = slip_max(s, J);
}
