/* The pressure Poisson equation of the PDDO flow solver (paper 002, Eqs. 7,
 * 31-34; notes/pddo.md 1.4): K_L P = R, one row per node, assembled once,
 * factorised once by sparse LU (SuiteSparse UMFPACK: K_L is not symmetric),
 * solved every step by back substitution.
 *
 * Rows (Eq. 31c read row by row, with the boundary rows of Sec. 4):
 *   PDDO_ROW_PPE        fluid nodes and the sides' nodes of walls, lids and
 *                       inlets: the PDDO Laplacian, (K_L)_kj = c_kj (j in
 *                       H_k), (K_L)_kk = -sum_j c_kj; right-hand side r_k
 *                       (Eq. 33b)
 *   PDDO_ROW_IMAGE      fictitious nodes: p_g - s p_image (s = +1 walls,
 *                       lids, inlets, bodies; -1 outlets; cloud.h);
 *                       right-hand side 0 in the paper
 *   PDDO_ROW_DIRICHLET  the nodes of an outlet side: p_k (Eqs. 50, 51a);
 *                       right-hand side the pressure there, 0 in the paper
 *
 * Without an outlet every pressure condition is a Neumann one (the cavity)
 * and K_L 1 = 0: K_L is singular with the constant as its null space, and
 * the discrete compatibility condition y . R = 0 (y the left null vector)
 * does not hold for Eq. 33b's R to round-off. The paper is silent; as the
 * notes recommend, the right-hand side is made consistent and the level
 * pinned: R <- R - (y . R / y . m) m with m the indicator of the PPE rows
 * (a uniform shift of the source), and the PPE row of the fluid node
 * nearest the rectangle's centre is replaced by p = 0 (harmless once R is
 * consistent: that row is then implied by the others). y is computed once,
 * exactly, by one transposed solve with the pinned factor (ppe.c); on
 * the rectangle it is the trapezoidal rule's weights on the PPE rows
 * (tests/unit/flow/pddo/test_ppe.c).
 *
 * UMFPACK works with 32-bit indices here (umfpack_di_*): at most 2^31 - 1
 * nonzeros, about 70 million nodes. Its BLAS on Debian is the reference one
 * (single-threaded), so the solve is the same bits at any thread count. */
#ifndef NSPD_FLOW_PDDO_PPE_H
#define NSPD_FLOW_PDDO_PPE_H

#include "flow/pddo/cloud.h"
#include "flow/pddo/lu_runs.h"
#include "flow/pddo/operators.h"
#include "flow/pddo/ppe_petsc.h"
#include "flow/pddo/share.h"

#include <stdbool.h>
#include <stdint.h>

typedef enum {
    PDDO_ROW_PPE = 0,
    PDDO_ROW_IMAGE,
    PDDO_ROW_DIRICHLET,
} PddoRow;

/* How K_L is solved: UMFPACK's LU on rank 0 (the default), or PETSc on
 * every rank (flow.pressure_solve: mumps or boomeramg; ppe_petsc.h). */
typedef struct {
    bool petsc;
    PpePetscMethod method;
    double tolerance; /* boomeramg: the relative residual to reach */
} PddoPpeSolver;

typedef struct {
    int64_t n;
    uint8_t *row; /* PddoRow of each node */
    /* the matrix's rows row_lo..row_hi-1 in compressed rows (ap from 0,
     * global columns): all n with UMFPACK (the factorised matrix), this
     * rank's own range with PETSc */
    int64_t row_lo, row_hi;
    int32_t *ap, *ai;
    double *ax;
    int64_t pinned;  /* the node whose row is p = 0, or -1 (an outlet fixes the level) */
    int32_t pin_len; /* the pinned node's own PPE row (for pddo_ppe_apply) */
    int32_t *pin_col;
    double *pin_val;
    double *null_left; /* singular case: y with K_L^T y = 0, y[pinned] = 1; else NULL */
    double null_ppe;   /* y . m */
    double *work;      /* n: the right-hand side as solved */
    void *numeric;     /* UMFPACK's factor (NULL once pddo_ppe_use_runs took it) */
    /* pddo_ppe_use_runs: UMFPACK's factor by runs of pivots (lu_runs.h),
     * with its permutations, U's diagonal and the row scaling */
    bool runs;
    LuRuns runs_u, runs_l;
    int32_t *perm_row, *perm_col;
    double *diag_u, *row_scale, *runs_y, *runs_scratch;
    int scale_recip;
    /* the runs' two-thread solve over the one-thread one, in entries
     * (lu_runs_cut; 1: nothing splits) */
    double two_thread_share;
    double shift; /* the last solve's consistency shift (y . R / y . m); 0 if regular */
    /* measured at build */
    int64_t nnz;       /* nonzeros of K_L */
    double factor_nnz; /* nonzeros of L + U */
    double factor_bytes;
    double rcond;   /* UMFPACK's reciprocal condition estimate */
    double solve_s; /* wall time in the triangular solves so far */
    /* several processes (share.h; NULL: one): rank 0 alone factorises and
     * solves, the right-hand side's rows gathered to it and the pressure
     * sent back to every rank */
    const PddoShare *share;
    double share_s; /* wall time in that gather and broadcast */
    /* PETSc (solver.petsc): each rank's rows of K_L in PETSc, solved by
     * all; the right-hand side shared before the singular case's shift
     * and the pressure after */
    PddoPpeSolver solver;
    PpePetsc petsc;
} PddoPpe;

/* Assembles K_L for the cloud with the operators built on its families,
 * factorises it (and in the singular case finds y). ppe is zeroed or freed
 * before. NSPD_ERR_NUMERIC if the factorisation finds K_L singular where an
 * outlet should fix the level; NSPD_ERR_NOMEM; NSPD_ERR_INPUT for more than
 * 2^31 - 1 nonzeros. */
int pddo_ppe_build(PddoPpe *ppe, const PddoCloud *cloud, const PddoOps *ops);

/* The same on share's processes (borrowed; NULL or one process: as
 * pddo_ppe_build) with solver (NULL: UMFPACK). UMFPACK: rank 0
 * factorises, the others keep the rows' kinds only; PETSc: each rank
 * hands its own range's rows to PETSc, which factorises (mumps) or builds
 * its hierarchy (boomeramg) on all ranks, and the singular case's y comes
 * from a solve with the transpose. pddo_ppe_solve is then collective:
 * each rank passes the rows of its own range (the others are not read)
 * and every rank gets the whole pressure: with UMFPACK the same bits as
 * one process; with PETSc the solver's own rounding, which depends on
 * the rank count (mumps: the factor's distribution; boomeramg: its
 * tolerance and the hierarchy's partition). */
int pddo_ppe_build_shared(PddoPpe *ppe, const PddoCloud *cloud, const PddoOps *ops,
                          const PddoShare *share, const PddoPpeSolver *solver);

/* Solves with UMFPACK's factor stored by runs of pivots from now on
 * (flow.pressure_solve: runs; lu_runs.h): U by rows and then L by columns
 * are taken from UMFPACK, its factor freed as soon as L is copied, and the
 * runs cut into two-thread stages (lu_runs_cut). The answers differ from
 * UMFPACK's solve in the last bits (4e-15 of max |p| on the paper's
 * cylinder) and are the same on one thread and two; the solve takes half
 * the time there on one thread, a third on two. While U is regrouped,
 * UMFPACK's factor and two copies of U are held: the peak resident set
 * there was 1,623 MB against 1,105 MB. NSPD_ERR_NOMEM. */
int pddo_ppe_use_runs(PddoPpe *ppe);

/* p = K_L^-1 rhs, rhs with the meaning per row given above (n values; not
 * modified). In the singular case the consistent part of rhs is solved and
 * the pinned node gets p = 0; ppe->shift says how inconsistent rhs was.
 * NSPD_ERR_NUMERIC if UMFPACK fails. */
int pddo_ppe_solve(PddoPpe *ppe, const double *rhs, double *p);

/* out = K_L p with the unpinned matrix (every PPE row as assembled);
 * with the whole matrix held only (not on PETSc's divided rows). */
void pddo_ppe_apply(const PddoPpe *ppe, const double *p, double *out);

void pddo_ppe_free(PddoPpe *ppe);

#endif
