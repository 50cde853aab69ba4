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
 * Two threads: the solve runs in stages (lu_runs_cut), each either one
 * range of runs on one thread or two ranges side by side that do not read
 * each other (in an elimination tree, two sets of subtrees below a node):
 *   SCATTER  the first range's columns have no row in the second; the
 *            second's scatters past the stage are logged and applied
 *            after the join, in run order, so every unknown receives its
 *            updates in the serial order;
 *   GATHER   the second range's rows have no column in the first.
 * Cuts lie at run starts, so the bits are those of the serial solve, on
 * one thread and on two.
 * Kernels: plain arrays, no allocation in the solve. */
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
    /* the stages (lu_runs_cut; see above), in solve order: runs
     * [stage[3i], stage[3i+1]) beside [stage[3i+1], stage[3i+2]) (equal:
     * one thread) */
    int64_t stages, *stage;
    int64_t *tail;  /* SCATTER: per run of a stage's second part, where its updates past the
                       stage start in its outside list */
    int64_t logged; /* SCATTER: the most updates one stage logs */
} LuRuns;

/* The lower triangle of n pivots whose off-diagonal entries are, for
 * pivot k, idx[ptr[k] .. ptr[k+1]) (ascending) with values val[...]: its
 * row (GATHER: all columns < k) or its column (SCATTER: all rows > k).
 * Runs hold at most max_run pivots. diag (n, kept by the caller) or NULL
 * for a unit diagonal. No cut (lu_runs_cut sets one). NSPD_ERR_NOMEM; *r
 * zeroed on entry. */
int lu_runs_build(LuRuns *r, LuRunsForm form, int64_t n, const int64_t *ptr, const int32_t *idx,
                  const double *val, const double *diag, int64_t max_run);

/* The stages that shorten the two-thread solves of one factor most:
 * first (SCATTER) solved over pivots 0 .. n-1, then second (GATHER) over
 * the same pivots in reversed order, as P^T A Q = L U is solved through
 * U^T and L^T. A stage runs pivots [x, a) beside [a, b), which must not
 * reach each other in either triangle; cuts lie at run starts of both (no
 * run is broken, so the bits are those of the serial solve). Greedily, at
 * most LU_RUNS_MAX_STAGES: the stage of what is left that minimises
 * max(first part, second part) + the rest (in entries), while one
 * shortens it; each found by one sweep over the pivots with a heap of each
 * run's next reach. Set on both; *share: the two-thread time over the
 * one-thread time, in entries (1: nothing splits). NSPD_ERR_NOMEM. */
enum { LU_RUNS_MAX_STAGES = 16 };
int lu_runs_cut(LuRuns *first, LuRuns *second, double *share);

/* The scratch lu_runs_solve takes, in doubles. */
int64_t lu_runs_scratch(const LuRuns *r);

/* y <- T^-1 y for the triangle T of r, each stage with two parts on two
 * threads where the team allows (the same bits on one); scratch:
 * lu_runs_scratch(r) doubles. */
void lu_runs_solve(const LuRuns *r, double *y, double *scratch);

/* Stored doubles (blocks and triangles) and indices, for memory reports. */
int64_t lu_runs_entries(const LuRuns *r);

void lu_runs_free(LuRuns *r);

#endif
