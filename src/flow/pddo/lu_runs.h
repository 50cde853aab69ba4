/* Triangular factors stored by runs of pivots, for the PDDO pressure
 * solve (ppe.c, flow.pressure_solve: runs; issue 26).
 *
 * A sparse LU factor from a frontal method (UMFPACK) is made of runs:
 * consecutive pivots of one frontal matrix share their pattern. A run is
 * kept as its small triangle and one dense block over the unknowns outside
 * it, so the triangular solve gathers or scatters those unknowns once per
 * run and streams the block in SIMD lanes, instead of reading an index and
 * a value per entry. On the paper's Re 100 cylinder (122,833 pivots, 6.67e7
 * entries) 91 % of the entries lie in runs of 8 pivots or more, and the
 * solve takes 50 ms against UMFPACK's own 111 ms
 * (docs/PERFORMANCE.md; measured by a prototype since folded in here,
 * git show daed58e:bench/ppe_solvers/supernodal.c).
 *
 * Two forms, for the two ways a factor groups:
 *   LU_RUNS_GATHER   a lower triangle given by rows: a run of rows whose
 *                    columns left of the run are the same; the block's
 *                    products are summed over its columns into one sum per
 *                    row (lanes over the rows, no reduction chain), then
 *                    the run's triangle column by column;
 *   LU_RUNS_SCATTER  a lower triangle given by columns: a run of columns
 *                    whose rows below the run are the same; the run's
 *                    unknowns come from its triangle, then the block's
 *                    products are scattered once.
 * Kernels: plain arrays, no allocation in the solve, one thread (the same
 * bits at any thread count). */
#ifndef NSPD_FLOW_PDDO_LU_RUNS_H
#define NSPD_FLOW_PDDO_LU_RUNS_H

#include <stdint.h>

typedef enum { LU_RUNS_GATHER, LU_RUNS_SCATTER } LuRunsForm;

typedef struct {
    LuRunsForm form;
    int64_t n, count;
    int64_t widest, longest; /* the most unknowns outside a run; the most pivots in one */
    int64_t *start;          /* run s: pivots start[s] .. start[s+1]-1 */
    int64_t *cp;             /* its outside unknowns idx[cp[s] .. cp[s+1]) */
    int32_t *idx;
    int64_t *bp; /* its block, then its triangle (packed by columns), at bx + bp[s] */
    double *bx;
    const double *diag; /* the diagonal (not owned), NULL: a unit diagonal */
} LuRuns;

/* The lower triangle of n pivots whose off-diagonal entries are, for
 * pivot k, idx[ptr[k] .. ptr[k+1]) (ascending) with values val[...]: its
 * row (GATHER: all columns < k) or its column (SCATTER: all rows > k).
 * Runs hold at most max_run pivots. diag (n, kept by the caller) or NULL
 * for a unit diagonal. NSPD_ERR_NOMEM; *r zeroed on entry. */
int lu_runs_build(LuRuns *r, LuRunsForm form, int64_t n, const int64_t *ptr, const int32_t *idx,
                  const double *val, const double *diag, int64_t max_run);

/* y <- T^-1 y for the triangle T of r; scratch: r->widest + r->longest
 * doubles. */
void lu_runs_solve(const LuRuns *r, double *y, double *scratch);

/* Stored doubles (blocks and triangles) and indices, for memory reports. */
int64_t lu_runs_entries(const LuRuns *r);

void lu_runs_free(LuRuns *r);

#endif
