/* Triangular factors stored by runs of pivots (lu_runs.h). */
#include "flow/pddo/lu_runs.h"

#include "core/mem.h"
#include "core/search.h"
#include "core/status.h"

#include <omp.h>
#include <string.h>

/* Whether pivot k joins the run that pivot k - 1 is in: GATHER, row k is
 * row k-1 and then k-1; SCATTER, column k-1 is k and then column k. */
static int joins(LuRunsForm form, const int64_t *ptr, const int32_t *idx, int64_t k) {
    const int64_t a = ptr[k - 1], la = ptr[k] - a, b = ptr[k], lb = ptr[k + 1] - b;
    if (form == LU_RUNS_GATHER)
        return lb == la + 1 && idx[b + la] == k - 1 &&
               memcmp(idx + a, idx + b, (size_t)la * sizeof *idx) == 0;
    return la == lb + 1 && idx[a] == k &&
           memcmp(idx + a + 1, idx + b, (size_t)lb * sizeof *idx) == 0;
}

/* The unknowns outside run [k0, k1): GATHER, row k0's columns; SCATTER,
 * column k1-1's rows. */
static void outside(LuRunsForm form, const int64_t *ptr, int64_t k0, int64_t k1, int64_t *at,
                    int64_t *count) {
    const int64_t k = form == LU_RUNS_GATHER ? k0 : k1 - 1;
    *at = ptr[k];
    *count = ptr[k + 1] - ptr[k];
}

/* The packed position of entry (row q, column t), q > t, of an ns x ns
 * strictly lower triangle stored column by column. */
static inline int64_t tri_at(int64_t ns, int64_t q, int64_t t) {
    return t * (2 * ns - t - 1) / 2 + (q - t - 1);
}

int lu_runs_build(LuRuns *r, LuRunsForm form, int64_t n, const int64_t *ptr, const int32_t *idx,
                  const double *val, const double *diag, int64_t max_run) {
    memset(r, 0, sizeof *r);
    r->form = form, r->n = n, r->diag = diag;
    TRY(nspd_alloc(&r->start, (size_t)n + 1, sizeof *r->start));
    int64_t outside_total = 0, entries = 0;
    for (int64_t k = 0; k < n;) {
        int64_t k1 = k + 1;
        while (k1 < n && k1 - k < max_run && joins(form, ptr, idx, k1)) k1++;
        int64_t at, c;
        outside(form, ptr, k, k1, &at, &c);
        const int64_t ns = k1 - k;
        r->start[r->count++] = k;
        outside_total += c;
        entries += ns * c + ns * (ns - 1) / 2;
        if (c > r->widest) r->widest = c;
        if (ns > r->longest) r->longest = ns;
        k = k1;
    }
    r->start[r->count] = n;
    /* one serial stage (lu_runs_cut divides it) */
    TRY(nspd_alloc(&r->stage, 3, sizeof *r->stage));
    r->stages = 1, r->stage[1] = r->stage[2] = r->count;
    TRY(nspd_alloc(&r->cp, (size_t)r->count + 1, sizeof *r->cp));
    TRY(nspd_alloc(&r->bp, (size_t)r->count + 1, sizeof *r->bp));
    r->cp[0] = r->bp[0] = 0;
    TRY(nspd_alloc(&r->idx, (size_t)(outside_total > 0 ? outside_total : 1), sizeof *r->idx));
    TRY(nspd_alloc(&r->bx, (size_t)(entries > 0 ? entries : 1), sizeof *r->bx));
    for (int64_t s = 0; s < r->count; s++) {
        const int64_t k0 = r->start[s], k1 = r->start[s + 1], ns = k1 - k0;
        int64_t at, c;
        outside(form, ptr, k0, k1, &at, &c);
        r->cp[s + 1] = r->cp[s] + c;
        r->bp[s + 1] = r->bp[s] + ns * c + ns * (ns - 1) / 2;
        memcpy(r->idx + r->cp[s], idx + at, (size_t)c * sizeof *idx);
        double *B = r->bx + r->bp[s], *T = B + ns * c;
        for (int64_t q = 0; q < ns; q++) {
            const int64_t a = ptr[k0 + q];
            if (form == LU_RUNS_GATHER) {
                /* row q: the outside columns, then the run's columns 0 .. q-1;
                 * the block column by column (lanes over the run's rows) */
                for (int64_t m = 0; m < c; m++) B[m * ns + q] = val[a + m];
                for (int64_t t = 0; t < q; t++) T[tri_at(ns, q, t)] = val[a + c + t];
            } else {
                /* column q: the run's rows q+1 .. ns-1, then the outside rows;
                 * the block row by row of the run (lanes over the outside) */
                const int64_t inside = ns - 1 - q;
                for (int64_t t = 0; t < inside; t++) T[tri_at(ns, q + 1 + t, q)] = val[a + t];
                for (int64_t m = 0; m < c; m++) B[q * c + m] = val[a + inside + m];
            }
        }
    }
    return NSPD_OK;
}

/* Runs of fewer pivots than this take the short paths below: on the
 * paper's cylinder 93 % of the runs, 9 % of the entries. */
enum { SHORT_RUN = 16 };

/* A GATHER run of NS < SHORT_RUN pivots (a constant where it is inlined):
 * its sums in registers, read straight from y. Each sum runs over the
 * block's columns in order from 0.0 and then over the triangle's pivots in
 * order, as in solve_range's lanes: the same bits, without the sums' round
 * trips through memory (a dependent load a column). */
static inline __attribute__((always_inline)) void gather_short(const int NS, int64_t c,
                                                               const int32_t *out, const double *B,
                                                               const double *T, const double *diag,
                                                               double *y, double *yk) {
    double acc[SHORT_RUN] = {0.0};
    for (int64_t m = 0; m < c; m++) {
        const double gm = y[out[m]];
        for (int q = 0; q < NS; q++) acc[q] += B[m * NS + q] * gm;
    }
    for (int q = 0; q < NS; q++) {
        const double a = yk[q] - acc[q];
        const double z = diag ? a / diag[q] : a;
        yk[q] = z;
        const double *col = T + tri_at(NS, q + 1, q);
        for (int t = q + 1; t < NS; t++) acc[t] += col[t - q - 1] * z;
    }
}

/* A SCATTER run of NS < SHORT_RUN pivots: its triangle, then each outside
 * unknown's update summed over the pivots in order from 0.0 in a register
 * (solve_range sums them in g, pivot by pivot: the same order, the same
 * bits) and subtracted at once, the ones at or past `direct` logged. */
static inline __attribute__((always_inline)) void
scatter_short(const int NS, int64_t c, const int32_t *out, const double *B, const double *T,
              const double *diag, double *y, double *yk, int64_t direct, double **log) {
    double z[SHORT_RUN];
    for (int q = 0; q < NS; q++) {
        z[q] = diag ? yk[q] / diag[q] : yk[q];
        yk[q] = z[q];
        const double *col = T + tri_at(NS, q + 1, q);
        for (int t = q + 1; t < NS; t++) yk[t] -= col[t - q - 1] * z[q];
    }
    for (int64_t m = 0; m < c; m++) {
        double g = 0.0;
        for (int q = 0; q < NS; q++) g += B[q * c + m] * z[q];
        if (m < direct)
            y[out[m]] -= g;
        else
            *(*log)++ = g;
    }
}

/* The short paths with the run's length a constant, so that the sums stay
 * in registers; 0 for a run they do not take. */
static int run_short(const LuRuns *r, int64_t ns, int64_t c, const int32_t *out, const double *B,
                     const double *T, const double *diag, double *y, double *yk, int64_t direct,
                     double **log) {
#define SHORT_CASE(N)                                                                              \
    case N:                                                                                        \
        if (r->form == LU_RUNS_GATHER)                                                             \
            gather_short(N, c, out, B, T, diag, y, yk);                                            \
        else                                                                                       \
            scatter_short(N, c, out, B, T, diag, y, yk, direct, log);                              \
        return 1;
    switch (ns) {
        SHORT_CASE(1)
        SHORT_CASE(2)
        SHORT_CASE(3)
        SHORT_CASE(4)
        SHORT_CASE(5)
        SHORT_CASE(6)
        SHORT_CASE(7)
        SHORT_CASE(8)
        SHORT_CASE(9)
        SHORT_CASE(10)
        SHORT_CASE(11)
        SHORT_CASE(12)
        SHORT_CASE(13)
        SHORT_CASE(14)
        SHORT_CASE(15)
    default:
        return 0;
    }
#undef SHORT_CASE
}

/* The blocks' stream is asked for this many doubles (16 KB) past each
 * run's start (solve_range): the cylinder's two-triangle solve 7 % faster
 * on 1 thread and 6 % on 2 than without (4 KB: 5 %; 64 KB: 3-4 %;
 * docs/PERFORMANCE.md). */
enum { PREFETCH_AHEAD = 2048 };

/* Runs [s0, s1) of the solve; SCATTER with a log: the updates of unknowns
 * at or past the run's tail go to *log in order instead of into y. */
static void solve_range(const LuRuns *r, int64_t s0, int64_t s1, double *y, double *scratch,
                        double *log) {
    double *g = scratch, *acc = scratch + r->widest;
    /* The blocks are one stream through memory, but the hardware prefetcher
     * follows demand loads only, and a run's gathers and triangle leave the
     * stream idle: each run asks for the stream ahead of its start, so the
     * next runs' blocks are on their way meanwhile. Offsets in bx, a cache
     * line (8 doubles) at a time. */
    int64_t fetched = r->bp[s0];
    for (int64_t s = s0; s < s1; s++) {
        const int64_t k0 = r->start[s], ns = r->start[s + 1] - k0, c = r->cp[s + 1] - r->cp[s];
        const int32_t *out = r->idx + r->cp[s];
        const double *B = r->bx + r->bp[s], *T = B + ns * c;
        const int64_t ahead =
            r->bp[s] + PREFETCH_AHEAD < r->bp[s1] ? r->bp[s] + PREFETCH_AHEAD : r->bp[s1];
        if (fetched < r->bp[s]) fetched = r->bp[s]; /* past a long run's block */
        for (; fetched < ahead; fetched += 8) __builtin_prefetch(r->bx + fetched);
        /* SCATTER with a log: the updates from `direct` on are logged */
        const int64_t direct = log ? r->tail[s] : c;
        if (ns < SHORT_RUN) {
            if (run_short(r, ns, c, out, B, T, r->diag ? r->diag + k0 : NULL, y, y + k0, direct,
                          &log))
                continue;
        }
        if (r->form == LU_RUNS_GATHER) {
            for (int64_t m = 0; m < c; m++) g[m] = y[out[m]];
            for (int64_t q = 0; q < ns; q++) acc[q] = 0.0;
            for (int64_t m = 0; m < c; m++) {
                const double gm = g[m], *bm = B + m * ns;
#pragma omp simd
                for (int64_t q = 0; q < ns; q++) acc[q] += bm[q] * gm;
            }
            for (int64_t q = 0; q < ns; q++) {
                const double a = y[k0 + q] - acc[q];
                const double z = r->diag ? a / r->diag[k0 + q] : a;
                y[k0 + q] = z;
                const double *col = T + tri_at(ns, q + 1, q);
                for (int64_t t = q + 1; t < ns; t++) acc[t] += col[t - q - 1] * z;
            }
        } else {
            for (int64_t q = 0; q < ns; q++) {
                const double z = r->diag ? y[k0 + q] / r->diag[k0 + q] : y[k0 + q];
                y[k0 + q] = z;
                const double *col = T + tri_at(ns, q + 1, q);
                for (int64_t t = q + 1; t < ns; t++) y[k0 + t] -= col[t - q - 1] * z;
            }
            for (int64_t m = 0; m < c; m++) g[m] = 0.0;
            for (int64_t q = 0; q < ns; q++) {
                const double z = y[k0 + q], *row = B + q * c;
#pragma omp simd
                for (int64_t m = 0; m < c; m++) g[m] += row[m] * z;
            }
            for (int64_t m = 0; m < direct; m++) y[out[m]] -= g[m];
            for (int64_t m = direct; m < c; m++) *log++ = g[m];
        }
    }
}

int64_t lu_runs_scratch(const LuRuns *r) {
    return 2 * (r->widest + r->longest) + r->logged + 1;
}

void lu_runs_solve(const LuRuns *r, double *y, double *scratch) {
    const int64_t w = r->widest + r->longest;
    double *log = scratch + 2 * w;
    const int two = omp_get_max_threads() > 1;
    const int scatter = r->form == LU_RUNS_SCATTER;
    for (int64_t i = 0; i < r->stages; i++) {
        const int64_t lo = r->stage[3 * i], mid = r->stage[3 * i + 1], hi = r->stage[3 * i + 2];
        if (mid == hi) {
            solve_range(r, lo, mid, y, scratch, NULL);
            continue;
        }
#pragma omp parallel num_threads(2) if (two)
        {
            const int t = omp_get_thread_num(), nt = omp_get_num_threads();
            for (int part = t; part < 2; part += nt) {
                if (part == 0)
                    solve_range(r, lo, mid, y, scratch, NULL);
                else
                    solve_range(r, mid, hi, y, scratch + w, scatter ? log : NULL);
            }
        }
        if (scatter) {
            /* the second part's updates past the stage, in run order: each
             * unknown gets them after the first part's, as on one thread */
            const double *at = log;
            for (int64_t s = mid; s < hi; s++) {
                const int32_t *out = r->idx + r->cp[s];
                for (int64_t m = r->tail[s]; m < r->cp[s + 1] - r->cp[s]; m++) y[out[m]] -= *at++;
            }
        }
    }
}

/* The runs of r as groups of pivots in the factor's order (a GATHER
 * triangle in reversed order read backwards): group s holds pivots
 * [lo[s], hi[s]) and reaches the pivots of its outside list, all at or past
 * hi[s]; reach(s, m) is the m-th of them, ascending. */
static int64_t group_lo(const LuRuns *r, int64_t s) {
    return r->form == LU_RUNS_SCATTER ? r->start[s] : r->n - r->start[r->count - s];
}
static int64_t group_hi(const LuRuns *r, int64_t s) {
    return r->form == LU_RUNS_SCATTER ? r->start[s + 1] : r->n - r->start[r->count - 1 - s];
}
static int64_t group_len(const LuRuns *r, int64_t s) {
    const int64_t t = r->form == LU_RUNS_SCATTER ? s : r->count - 1 - s;
    return r->cp[t + 1] - r->cp[t];
}
static int64_t group_reach(const LuRuns *r, int64_t s, int64_t m) {
    if (r->form == LU_RUNS_SCATTER) return r->idx[r->cp[s] + m];
    const int64_t t = r->count - 1 - s;
    return r->n - 1 - r->idx[r->cp[t + 1] - 1 - m];
}

/* The first reach of group s at or past v: its position (len if none). */
static int64_t reach_from(const LuRuns *r, int64_t s, int64_t v) {
    int64_t lo = 0, hi = group_len(r, s);
    while (lo < hi) {
        const int64_t mid = lo + (hi - lo) / 2;
        if (group_reach(r, s, mid) < v)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

/* A binary min-heap of (pivot, group, triangle) entries: each group's
 * current reach. */
typedef struct {
    int64_t key, group;
    int tri;
} Reach;

static void heap_push(Reach *h, int64_t *n, Reach e) {
    int64_t i = (*n)++;
    while (i > 0 && h[(i - 1) / 2].key > e.key) h[i] = h[(i - 1) / 2], i = (i - 1) / 2;
    h[i] = e;
}

static Reach heap_pop(Reach *h, int64_t *n) {
    const Reach top = h[0], last = h[--*n];
    int64_t i = 0;
    for (;;) {
        int64_t c = 2 * i + 1;
        if (c >= *n) break;
        if (c + 1 < *n && h[c + 1].key < h[c].key) c++;
        if (h[c].key >= last.key) break;
        h[i] = h[c], i = c;
    }
    if (*n > 0) h[i] = last;
    return top;
}

/* The run that starts at pivot k of r's own order (-1: none). */
static int64_t run_at(const LuRuns *r, int64_t k) {
    const int64_t lo = search_first_at_least(r->start, r->count, k);
    return lo < r->count && r->start[lo] == k ? lo : k == r->n ? r->count : -1;
}

/* Whether the runs [s0, s1) of r reach none of the pivots [a, b). */
static int apart(const LuRuns *r, int64_t s0, int64_t s1, int64_t a, int64_t b) {
    for (int64_t s = s0; s < s1; s++) {
        const int64_t c = r->cp[s + 1] - r->cp[s];
        const int64_t m = search_first_at_least_i32(r->idx + r->cp[s], c, a);
        if (m < c && r->idx[r->cp[s] + m] < b) return 0;
    }
    return 1;
}

/* r's stages from the cuts (x_i, a_i, b_i) of the factor's order (pivots
 * [x_i, a_i) beside [a_i, b_i), x_(i+1) = b_i, at run starts), in r's own
 * order: SCATTER runs them first to last and then [b_last, n); GATHER
 * (reversed) [0, n - b_last) first, then the stages last to first. Each is
 * checked: the part that runs first on one thread must not reach the
 * other part. */
static int set_stages(LuRuns *r, const int64_t *cuts, int64_t m) {
    const int64_t n = r->n, scatter = r->form == LU_RUNS_SCATTER;
    nspd_free(&r->stage);
    TRY(nspd_alloc(&r->stage, 3 * (size_t)(m + 1), sizeof *r->stage));
    r->stages = m + 1;
    for (int64_t i = 0; i <= m; i++) {
        int64_t k[3];
        if (i == (scatter ? m : 0)) { /* the serial rest */
            const int64_t b = m > 0 ? cuts[3 * (m - 1) + 2] : 0;
            k[0] = scatter ? b : 0, k[1] = k[2] = scatter ? n : n - b;
        } else {
            const int64_t *c = cuts + 3 * (scatter ? i : m - i);
            k[0] = scatter ? c[0] : n - c[2], k[1] = scatter ? c[1] : n - c[1];
            k[2] = scatter ? c[2] : n - c[0];
        }
        for (int q = 0; q < 3; q++) {
            r->stage[3 * i + q] = run_at(r, k[q]);
            if (r->stage[3 * i + q] < 0)
                return NSPD_FAIL(NSPD_ERR_INTERNAL, "a cut inside a run of the factor");
        }
        const int64_t *t = r->stage + 3 * i;
        const int ok =
            scatter ? apart(r, t[0], t[1], k[1], k[2]) : apart(r, t[1], t[2], k[0], k[1]);
        if (!ok) return NSPD_FAIL(NSPD_ERR_INTERNAL, "a cut whose parts reach each other");
    }
    if (scatter) {
        TRY(nspd_alloc(&r->tail, (size_t)r->count + 1, sizeof *r->tail));
        for (int64_t i = 0; i < m; i++) {
            const int64_t *t = r->stage + 3 * i, b = cuts[3 * i + 2];
            int64_t logged = 0;
            for (int64_t s = t[1]; s < t[2]; s++) {
                const int64_t c = r->cp[s + 1] - r->cp[s];
                r->tail[s] = search_first_at_least_i32(r->idx + r->cp[s], c, b);
                logged += c - r->tail[s];
            }
            if (logged > r->logged) r->logged = logged;
        }
    }
    return NSPD_OK;
}

/* What lu_runs_cut sweeps with: per pivot the work before it and whether
 * both triangles' runs start there; the groups by the pivot they end at;
 * the heap. */
typedef struct {
    const LuRuns *t[2];
    int64_t n;
    double *before;
    uint8_t *common;
    int64_t *ends, *end_at;
    Reach *heap;
} Sweep;

/* The best stage of pivots [x, n): [x, a) beside [a, b), then [b, n) on
 * one thread, minimising max(W[x, a), W[a, b)) + W[b, n); its time (W[x,
 * n): none better), *a and *b (0: none). The groups that start at or past
 * x and end at or before a are in the first part; the second may reach up
 * to the lowest pivot at or past a that one of them reaches. */
static double best_stage(Sweep *w, int64_t x, int64_t *a_out, int64_t *b_out) {
    const int64_t n = w->n;
    const double *before = w->before;
    double best = before[n] - before[x];
    int64_t heap_n = 0;
    *a_out = *b_out = 0;
    for (int64_t a = x + 1, e = w->end_at[x]; a < n; a++) {
        for (; e < w->end_at[a]; e++) {
            const int f = (int)(w->ends[e] % 2);
            const int64_t s = w->ends[e] / 2;
            if (group_lo(w->t[f], s) < x) continue;
            const int64_t m = reach_from(w->t[f], s, a);
            if (m < group_len(w->t[f], s))
                heap_push(w->heap, &heap_n, (Reach){group_reach(w->t[f], s, m), s, f});
        }
        while (heap_n > 0 && w->heap[0].key < a) {
            Reach r = heap_pop(w->heap, &heap_n);
            const int64_t m = reach_from(w->t[r.tri], r.group, a);
            if (m < group_len(w->t[r.tri], r.group)) {
                r.key = group_reach(w->t[r.tri], r.group, m);
                heap_push(w->heap, &heap_n, r);
            }
        }
        if (w->common[a] != 2) continue;
        int64_t b = heap_n > 0 ? w->heap[0].key : n;
        while (b > a && b < n && w->common[b] != 2) b--;
        if (b <= a) continue;
        const double one = before[a] - before[x], two = before[b] - before[a];
        const double time = (one > two ? one : two) + before[n] - before[b];
        if (time < best) best = time, *a_out = a, *b_out = b;
    }
    return best;
}

int lu_runs_cut(LuRuns *first, LuRuns *second, double *share) {
    *share = 1.0;
    const int64_t n = first->n;
    if (first->form != LU_RUNS_SCATTER || second->form != LU_RUNS_GATHER || second->n != n)
        return NSPD_OK;
    Sweep w = {.t = {first, second}, .n = n};
    int64_t *cuts = NULL, m = 0;
    const int64_t groups = first->count + second->count;
    int status = nspd_alloc(&w.before, (size_t)n + 1, sizeof *w.before);
    if (status == NSPD_OK) status = nspd_alloc(&w.common, (size_t)n + 1, 1);
    if (status == NSPD_OK) status = nspd_alloc(&w.end_at, (size_t)n + 2, sizeof *w.end_at);
    if (status == NSPD_OK) status = nspd_alloc(&w.ends, (size_t)groups, sizeof *w.ends);
    if (status == NSPD_OK) status = nspd_alloc(&w.heap, (size_t)groups, sizeof *w.heap);
    if (status == NSPD_OK) status = nspd_alloc(&cuts, 3 * LU_RUNS_MAX_STAGES, sizeof *cuts);
    if (status != NSPD_OK) goto done;
    double *work = w.before + 1; /* work[k], summed in place below */
    for (int f = 0; f < 2; f++)
        for (int64_t s = 0; s < w.t[f]->count; s++) {
            const int64_t lo = group_lo(w.t[f], s), hi = group_hi(w.t[f], s);
            const int64_t ns = hi - lo, c = group_len(w.t[f], s);
            w.common[lo]++;
            for (int64_t q = 0; q < ns; q++) work[lo + q] += (double)(c + ns - 1 - q);
            w.end_at[hi + 1]++; /* counted, then grouped by the pivot they end at */
        }
    for (int64_t k = 0; k < n; k++) w.before[k + 1] += w.before[k];
    for (int64_t k = 0; k <= n; k++) w.end_at[k + 1] += w.end_at[k];
    for (int f = 0; f < 2; f++)
        for (int64_t s = 0; s < w.t[f]->count; s++)
            w.ends[w.end_at[group_hi(w.t[f], s)]++] = 2 * s + f; /* end_at[k]: end of k's */
    /* greedily: the best stage of what is left, while one shortens it */
    double time = 0.0;
    int64_t x = 0;
    while (m < LU_RUNS_MAX_STAGES) {
        int64_t a, b;
        const double t = best_stage(&w, x, &a, &b);
        if (b == 0) break;
        cuts[3 * m] = x, cuts[3 * m + 1] = a, cuts[3 * m + 2] = b;
        time += t - (w.before[n] - w.before[b]);
        m++, x = b;
    }
    time += w.before[n] - w.before[x];
    *share = w.before[n] > 0.0 ? time / w.before[n] : 1.0;
    if (m > 0) {
        status = set_stages(first, cuts, m);
        if (status == NSPD_OK) status = set_stages(second, cuts, m);
    }
done:
    nspd_free(&w.before), nspd_free(&w.common), nspd_free(&w.ends), nspd_free(&w.end_at);
    nspd_free(&w.heap), nspd_free(&cuts);
    return status;
}

int64_t lu_runs_entries(const LuRuns *r) {
    return r->count > 0 ? r->bp[r->count] : 0;
}

void lu_runs_free(LuRuns *r) {
    nspd_free(&r->start);
    nspd_free(&r->cp);
    nspd_free(&r->idx);
    nspd_free(&r->bp);
    nspd_free(&r->bx);
    nspd_free(&r->tail);
    nspd_free(&r->stage);
    memset(r, 0, sizeof *r);
}
