/* The PDDO pressure matrix solved by PETSc on the run's processes
 * (flow.pressure_solve: mumps or boomeramg; issue 58).
 *
 * Each rank hands PETSc the rows of its own node range [lo, hi) (the
 * share's ranges, flow/pddo/share.h, are PETSc's row ownership as they
 * stand: no renumbering), columns global, and PETSc holds the matrix as
 * a distributed AIJ matrix:
 *   mumps      MUMPS 5.5's distributed LU (KSP preonly, PC lu), factorised
 *              once, AMD ordering on the host (repeatable run to run:
 *              METIS's order changes between runs, docs/PERFORMANCE.md)
 *   boomeramg  BiCGStab, right-preconditioned by one V-cycle of hypre's
 *              BoomerAMG (HMIS coarsening, ext+i interpolation with at most
 *              4 weights a row, l1-Jacobi smoothing without C/F ordering:
 *              with hypre's default smoother it does not converge on this
 *              matrix, bench/ppe_solvers; ppe_petsc.c), to a relative
 *              residual ||b - K p|| / ||b|| below the tolerance, from the
 *              last step's pressure
 * PETSc's options with the prefix "pressure_" (PETSC_OPTIONS, a .petscrc)
 * override these: -pressure_ksp_monitor, -pressure_pc_hypre_boomeramg_...
 *
 * PETSc is opened on first use (dlopen, core/shared_lib.h) and started
 * over the MPI that comm_init started (or, on one process without a
 * launcher, starting it itself), without its signal handlers (nspd's
 * checkpoint on SIGTERM stays), and ended by comm_finalize. Built without
 * PETSc or MPI, ppe_petsc_create says so (NSPD_ERR_INPUT). */
#ifndef NSPD_FLOW_PDDO_PPE_PETSC_H
#define NSPD_FLOW_PDDO_PPE_PETSC_H

#include "core/comm.h"

#include <stdbool.h>
#include <stdint.h>

typedef enum {
    PPE_PETSC_MUMPS = 0,
    PPE_PETSC_BOOMERAMG,
} PpePetscMethod;

typedef struct {
    void *ksp, *mat, *b, *x; /* PETSc's KSP, Mat and two Vecs (NULL: none) */
    PpePetscMethod method;
    int64_t lo, hi;           /* this rank's rows */
    int iterations;           /* the last solve's Krylov iterations (1 for mumps) */
    int64_t iterations_total; /* over every solve */
    double residual;          /* the last solve's residual norm, as PETSc measured it */
    double factor_nnz;        /* mumps: the factors' entries over every rank (INFOG(29)) */
    double factor_mb;         /* mumps: the factorisation's memory over every rank (INFOG(22)) */
} PpePetsc;

/* Whether this nspd was built with PETSc (and MPI). */
bool ppe_petsc_built(void);

/* Makes the solver of the n x n matrix whose rows lo..hi-1 (this rank's;
 * the group's ranges in rank order cover 0..n-1) are the compressed rows
 * ap[0..hi-lo], ai, ax (row pointers from 0, global columns: the rows
 * flow/pddo/ppe.c assembles), or of its transpose; sets
 * up (factorises or builds the hierarchy). Collective over comm (NULL or
 * one process: alone). s is zeroed or freed before. NSPD_ERR_INPUT without
 * PETSc; NSPD_ERR_IO if it cannot be opened; NSPD_ERR_NUMERIC if PETSc
 * fails (its error code and where). */
int ppe_petsc_create(PpePetsc *s, const NspdComm *comm, PpePetscMethod method, double tolerance,
                     bool transpose, int64_t lo, int64_t hi, int64_t n, const int32_t *ap,
                     const int32_t *ai, const double *ax);

/* x = K^-1 b on this rank's rows: b and x hold rows lo..hi-1; x on entry
 * is the iterative method's first guess. Collective. NSPD_ERR_NUMERIC if
 * the iteration does not converge (PETSc's reason and the iterations). */
int ppe_petsc_solve(PpePetsc *s, const double *b, double *x);

void ppe_petsc_free(PpePetsc *s);

#endif
