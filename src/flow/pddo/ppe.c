/* K_L of paper 002 (Eqs. 31-34): assembly, UMFPACK factorisation, solve.
 *
 * The matrix is assembled in compressed rows, each row's columns ascending
 * (the families are sorted; the diagonal is slotted in). Compressed rows of
 * K_L are compressed columns of K_L^T, so UMFPACK factorises K_L^T and the
 * solve asks for the transposed system (UMFPACK_At), which is K_L p = R;
 * the singular case's left null vector is the plain system with the same
 * factor (UMFPACK_A). No copy, no transposition.
 *
 * Left null vector. With K' = K_L with the pinned row k0 replaced by
 * e_k0^T, and y the left null vector scaled to y_k0 = 1,
 *     K'^T y = sum_(i != k0) y_i K_i^T + e_k0 = -K_k0^T + e_k0,
 * since sum_i y_i K_i = 0. K' is regular, so one solve with that
 * right-hand side gives y exactly (to the factor's round-off). */
#include "flow/pddo/ppe.h"

#include "core/mem.h"
#include "core/parallel.h"
#include "core/status.h"
#include "core/timer.h"
#include "flow/pddo/umfpack_lib.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

static int row_kind(const PddoCloud *c, int64_t k) {
    if (c->kind[k] == PDDO_NODE_GHOST || c->kind[k] == PDDO_NODE_BODY) return PDDO_ROW_IMAGE;
    if (c->kind[k] == PDDO_NODE_SIDE) {
        for (int s = 0; s < PDDO_SIDES; s++)
            if (((unsigned)c->sides[k] >> s & 1u) && c->side[s] == PDDO_SIDE_OUTLET)
                return PDDO_ROW_DIRICHLET;
    }
    return PDDO_ROW_PPE;
}

/* The fluid node nearest the middle of the rectangle: the pinned level of
 * the singular case (any PPE row would do once R is consistent; the middle
 * keeps it away from the corners' singular pressures). */
static int64_t middle_node(const PddoCloud *c) {
    const int64_t o = pddo_cloud_node(c, 0, 0), t = pddo_cloud_node(c, c->nx, c->ny);
    const double mx = 0.5 * (c->x[o] + c->x[t]), my = 0.5 * (c->y[o] + c->y[t]);
    int64_t best = -1;
    double best_d = INFINITY;
    for (int64_t k = 0; k < c->n; k++) {
        if (c->kind[k] != PDDO_NODE_FLUID) continue;
        const double d = hypot(c->x[k] - mx, c->y[k] - my);
        if (d < best_d) best_d = d, best = k;
    }
    return best;
}

/* Row k of K_L into (col, val), columns ascending; returns its length. */
static int32_t assemble_row(const PddoCloud *c, const PddoOps *ops, int row, int64_t k,
                            int32_t *col, double *val) {
    int32_t len = 0;
    if (row == PDDO_ROW_DIRICHLET) {
        col[0] = (int32_t)k, val[0] = 1.0;
        return 1;
    }
    if (row == PDDO_ROW_IMAGE) {
        const int32_t g = (int32_t)k, im = c->image[k];
        const double s = -(double)c->image_sign[k];
        if (g < im)
            col[0] = g, val[0] = 1.0, col[1] = im, val[1] = s;
        else
            col[0] = im, val[0] = s, col[1] = g, val[1] = 1.0;
        return 2;
    }
    double diag = 0.0;
    for (int64_t m = ops->first[k]; m < ops->first[k + 1]; m++)
        diag -= pddo_ops_weight(ops, PDDO_LAP, k, m);
    bool placed = false;
    for (int64_t m = ops->first[k]; m < ops->first[k + 1]; m++) {
        if (!placed && ops->nbr[m] > k) col[len] = (int32_t)k, val[len++] = diag, placed = true;
        col[len] = ops->nbr[m], val[len++] = pddo_ops_weight(ops, PDDO_LAP, k, m);
    }
    if (!placed) col[len] = (int32_t)k, val[len++] = diag;
    return len;
}

/* UMFPACK's failure `status` in `what`; estimate_gb > 0: the symbolic
 * analysis's estimate of the factorisation's peak, said with running out
 * of memory. */
static int umf_fail_sized(int status, const char *what, double estimate_gb) {
    if (status == UMFPACK_ERROR_out_of_memory) {
        char estimate[64] = "";
        if (estimate_gb > 0.0)
            snprintf(estimate, sizeof estimate, " (its estimate %.3g GB)", estimate_gb);
        return NSPD_FAIL(NSPD_ERR_NOMEM,
                         "PDDO pressure matrix: UMFPACK's %s ran out of memory%s; expected fewer "
                         "nodes, or flow.pressure_solve: mumps or boomeramg (PETSc, on every "
                         "process)",
                         what, estimate);
    }
    return NSPD_FAIL(NSPD_ERR_NUMERIC, "PDDO pressure matrix: UMFPACK %s returned %d", what,
                     status);
}

static int umf_fail(int status, const char *what) {
    return umf_fail_sized(status, what, 0.0);
}

static int factorise(PddoPpe *p) {
    TRY(umfpack_lib_load());
    double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
    umfpack_di_defaults(control);
    /* AMD on K_L + K_L^T, then METIS, the sparser kept: at the paper's
     * cylinder (122,833 nodes) the factors hold 66.7e6 entries (541 MB)
     * against AMD's 82.8e6 (671 MB), and each back-substitution reads
     * them all (docs/PERFORMANCE.md) */
    control[UMFPACK_ORDERING] = UMFPACK_ORDERING_CHOLMOD;
    void *symbolic = NULL;
    const int n = (int)p->n;
    int s = umfpack_di_symbolic(n, n, p->ap, p->ai, p->ax, &symbolic, control, info);
    if (s != UMFPACK_OK) return umf_fail(s, "symbolic analysis");
    /* what the symbolic analysis expects the factorisation to need: on
     * the Re 100 cylinder at 4x the paper's nodes (478,999) 32.2 GB, past
     * this machine's 24 GB and the 16 GB (2^31 units) that UMFPACK's
     * 32-bit version addresses, and the factorisation stops there
     * (docs/PERFORMANCE.md) */
    const double estimate_gb =
        1e-9 * info[UMFPACK_PEAK_MEMORY_ESTIMATE] * info[UMFPACK_SIZE_OF_UNIT];
    s = umfpack_di_numeric(p->ap, p->ai, p->ax, symbolic, &p->numeric, control, info);
    umfpack_di_free_symbolic(&symbolic);
    if (s == UMFPACK_WARNING_singular_matrix)
        return NSPD_FAIL(NSPD_ERR_NUMERIC,
                         "PDDO pressure matrix: singular (%s); expected a regular matrix with "
                         "the level %s",
                         "a zero pivot", p->pinned >= 0 ? "pinned" : "fixed by an outlet");
    if (s != UMFPACK_OK) return umf_fail_sized(s, "numeric factorisation", estimate_gb);
    p->factor_nnz = info[UMFPACK_LNZ] + info[UMFPACK_UNZ];
    p->factor_bytes = info[UMFPACK_NUMERIC_SIZE] * info[UMFPACK_SIZE_OF_UNIT];
    p->rcond = info[UMFPACK_RCOND];
    return NSPD_OK;
}

/* x = M^-1 b (sys UMFPACK_At: K_L, as assembled by rows) or M^-T b. */
static int umf_solve(const PddoPpe *p, int sys, double *x, const double *b) {
    double control[UMFPACK_CONTROL], info[UMFPACK_INFO];
    umfpack_di_defaults(control);
    /* no iterative refinement: it costs a solve each, and the direct
     * solution's residual is 9e-15 to 5e-13 of max |R| for 529 to 5,041
     * nodes already (tests/unit/flow/pddo/test_ppe.c); it grows with the condition number,
     * so the largest clouds should measure it again */
    control[UMFPACK_IRSTEP] = 0;
    const int s = umfpack_di_solve(sys, p->ap, p->ai, p->ax, x, b, p->numeric, control, info);
    return s == UMFPACK_OK ? NSPD_OK : umf_fail(s, "solve");
}

/* The group the matrix is shared by (one process: the self group). */
static NspdComm ppe_comm(const PddoPpe *p) {
    return p->share ? p->share->comm : comm_self();
}

/* The singular case's y: the right-hand side -K_k0^T + e_k0 of
 * K'^T y (the header's derivation) into p->work, y allocated. */
static int null_rhs(PddoPpe *p) {
    double *b = p->work;
    memset(b, 0, (size_t)p->n * sizeof(double));
    for (int32_t m = 0; m < p->pin_len; m++) b[p->pin_col[m]] = -p->pin_val[m];
    b[p->pinned] += 1.0;
    return nspd_alloc(&p->null_left, (size_t)p->n, sizeof(double));
}

/* y . m, m the indicator of the PPE rows (serial: the same bits anywhere) */
static void null_ppe_sum(PddoPpe *p) {
    p->null_ppe = 0.0;
    for (int64_t k = 0; k < p->n; k++)
        if (p->row[k] == PDDO_ROW_PPE) p->null_ppe += p->null_left[k];
}

/* PETSc's solver of K_L on this rank's rows and, in the singular case, y
 * by one solve with K'^T (a solver of the transpose, freed after). */
static int build_petsc(PddoPpe *p) {
    const int64_t n = p->n;
    const int64_t lo = p->row_lo, hi = p->row_hi; /* this rank's range (build) */
    const NspdComm comm = ppe_comm(p);
    const PddoPpeSolver *s = &p->solver;
    TRY(ppe_petsc_create(&p->petsc, &comm, s->method, s->tolerance, false, lo, hi, n, p->ap, p->ai,
                         p->ax));
    p->factor_nnz = p->petsc.factor_nnz;
    p->factor_bytes = 1e6 * p->petsc.factor_mb;
    if (p->pinned < 0) return NSPD_OK;
    TRY(null_rhs(p));
    const double *b = p->work;
    PpePetsc t = {0};
    /* by MUMPS, whichever solves the steps: BoomerAMG does not converge on
     * the transpose (500 BiCGStab iterations on the 729-node cavity: AMG
     * reads strength from rows, and K'^T's rows are K's columns); one
     * distributed factorisation, freed at once */
    int status = ppe_petsc_create(&t, &comm, PPE_PETSC_MUMPS, s->tolerance, true, lo, hi, n, p->ap,
                                  p->ai, p->ax);
    if (status == NSPD_OK) status = ppe_petsc_solve(&t, b + lo, p->null_left + lo);
    ppe_petsc_free(&t);
    TRY(status);
    TRY(pddo_share(p->share, p->null_left, false));
    null_ppe_sum(p);
    return NSPD_OK;
}

static int build(PddoPpe *p, const PddoCloud *c, const PddoOps *ops) {
    const int64_t n = c->n;
    p->n = n;
    p->pinned = -1;
    /* the rows held: all (UMFPACK factorises the whole matrix), or this
     * rank's own for PETSc, which needs no other */
    int64_t lo = 0, hi = n;
    if (p->solver.petsc) pddo_share_nodes(p->share, n, &lo, &hi);
    p->row_lo = lo, p->row_hi = hi;
    TRY(nspd_alloc(&p->row, (size_t)n, 1));
    TRY(nspd_alloc(&p->work, (size_t)n, sizeof(double)));
    TRY(nspd_alloc(&p->ap, (size_t)(hi - lo) + 1, sizeof(int32_t)));
    bool outlet = false;
    int64_t nnz = 0, held = 0;
    for (int64_t k = 0; k < n; k++) {
        p->row[k] = (uint8_t)row_kind(c, k);
        outlet = outlet || p->row[k] == PDDO_ROW_DIRICHLET;
        const int64_t len = p->row[k] == PDDO_ROW_PPE ? ops->first[k + 1] - ops->first[k] + 1
                                                      : (p->row[k] == PDDO_ROW_IMAGE ? 2 : 1);
        nnz += len;
        if (k >= lo && k < hi) held += len;
    }
    if (nnz > INT32_MAX || n > INT32_MAX)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "PDDO pressure matrix: %lld nonzeros exceed 32-bit indices; expected "
                         "fewer nodes",
                         (long long)nnz);
    p->nnz = nnz;
    TRY(nspd_alloc(&p->ai, (size_t)held, sizeof(int32_t)));
    TRY(nspd_alloc(&p->ax, (size_t)held, sizeof(double)));
    for (int64_t k = lo; k < hi; k++) {
        const int32_t at = p->ap[k - lo];
        p->ap[k - lo + 1] = at + assemble_row(c, ops, p->row[k], k, p->ai + at, p->ax + at);
    }
    if (!outlet) {
        p->pinned = middle_node(c);
        if (p->pinned < 0)
            return NSPD_FAIL(NSPD_ERR_INPUT, "PDDO pressure matrix: no fluid node to pin");
        /* its PPE row as assembled, on every rank (y's right-hand side),
         * and p = 0 in its place where the row is held */
        const int64_t k0 = p->pinned;
        const int32_t len = (int32_t)(ops->first[k0 + 1] - ops->first[k0] + 1);
        TRY(nspd_alloc(&p->pin_col, (size_t)len, sizeof(int32_t)));
        TRY(nspd_alloc(&p->pin_val, (size_t)len, sizeof(double)));
        p->pin_len = assemble_row(c, ops, p->row[k0], k0, p->pin_col, p->pin_val);
        if (k0 >= lo && k0 < hi)
            for (int32_t m = p->ap[k0 - lo]; m < p->ap[k0 - lo + 1]; m++)
                p->ax[m] = p->ai[m] == k0 ? 1.0 : 0.0;
    }
    if (p->solver.petsc) return build_petsc(p);
    if (pddo_share_divided(p->share) && p->share->comm.rank != 0) return NSPD_OK; /* rank 0's */
    TRY(factorise(p));
    if (p->pinned >= 0) {
        TRY(null_rhs(p));
        TRY(umf_solve(p, UMFPACK_A, p->null_left, p->work));
        null_ppe_sum(p);
    }
    return NSPD_OK;
}

int pddo_ppe_build_shared(PddoPpe *ppe, const PddoCloud *cloud, const PddoOps *ops,
                          const PddoShare *share, const PddoPpeSolver *solver) {
    pddo_ppe_free(ppe);
    ppe->share = pddo_share_divided(share) ? share : NULL;
    if (solver) ppe->solver = *solver;
    int status = build(ppe, cloud, ops);
    if (ppe->share) status = comm_agree(&ppe->share->comm, status, NULL, 0);
    if (status != NSPD_OK) pddo_ppe_free(ppe);
    return status;
}

int pddo_ppe_build(PddoPpe *ppe, const PddoCloud *cloud, const PddoOps *ops) {
    return pddo_ppe_build_shared(ppe, cloud, ops, NULL, NULL);
}

/* The most pivots a run holds: measured on the paper's cylinder (solve
 * 50.2 ms at 1,024, 51.0 at 64, 56.2 at 16; bench/ppe_solvers) */
enum { PPE_RUN_MAX = 1024 };

/* U's rows (the columns of U^T: entries right of the diagonal, ascending)
 * as LU_RUNS_SCATTER runs, with the permutations, U's diagonal and the row
 * scaling. */
static int runs_of_u(PddoPpe *p, int unz) {
    const int n = (int)p->n;
    int *Up = NULL, *Ui = NULL;
    int32_t *rows = NULL;
    int64_t *ptr = NULL, *at = NULL;
    double *Ux = NULL, *vals = NULL;
    int status = nspd_alloc(&Up, (size_t)n + 1, sizeof *Up);
    if (status == NSPD_OK) status = nspd_alloc(&Ui, (size_t)unz, sizeof *Ui);
    if (status == NSPD_OK) status = nspd_alloc(&Ux, (size_t)unz, sizeof *Ux);
    if (status == NSPD_OK) status = nspd_alloc(&ptr, (size_t)n + 1, sizeof *ptr);
    if (status == NSPD_OK) status = nspd_alloc(&at, (size_t)n + 1, sizeof *at);
    if (status == NSPD_OK) status = nspd_alloc(&p->perm_row, (size_t)n, sizeof *p->perm_row);
    if (status == NSPD_OK) status = nspd_alloc(&p->perm_col, (size_t)n, sizeof *p->perm_col);
    if (status == NSPD_OK) status = nspd_alloc(&p->diag_u, (size_t)n, sizeof *p->diag_u);
    if (status == NSPD_OK) status = nspd_alloc(&p->row_scale, (size_t)n, sizeof *p->row_scale);
    if (status == NSPD_OK) {
        const int s = umfpack_di_get_numeric(NULL, NULL, NULL, Up, Ui, Ux, p->perm_row, p->perm_col,
                                             p->diag_u, &p->scale_recip, p->row_scale, p->numeric);
        if (s != UMFPACK_OK) status = umf_fail(s, "get_numeric (U)");
    }
    if (status == NSPD_OK) {
        for (int k = 0; k < n; k++)
            for (int m = Up[k]; m < Up[k + 1]; m++)
                if (Ui[m] != k) ptr[Ui[m] + 1]++;
        for (int k = 0; k < n; k++) ptr[k + 1] += ptr[k];
        memcpy(at, ptr, (size_t)n * sizeof *at);
        status = nspd_alloc(&rows, (size_t)ptr[n], sizeof *rows);
        if (status == NSPD_OK) status = nspd_alloc(&vals, (size_t)ptr[n], sizeof *vals);
    }
    if (status == NSPD_OK) {
        /* columns of U in order: each row's entries come ascending */
        for (int k = 0; k < n; k++)
            for (int m = Up[k]; m < Up[k + 1]; m++)
                if (Ui[m] != k) rows[at[Ui[m]]] = k, vals[at[Ui[m]]++] = Ux[m];
        nspd_free(&Ux); /* the largest temporary, before the runs are made */
        nspd_free(&Ui);
        status =
            lu_runs_build(&p->runs_u, LU_RUNS_SCATTER, n, ptr, rows, vals, p->diag_u, PPE_RUN_MAX);
    }
    nspd_free(&Up), nspd_free(&Ui), nspd_free(&Ux), nspd_free(&ptr), nspd_free(&at);
    nspd_free(&rows), nspd_free(&vals);
    return status;
}

/* L's columns (the rows of L^T: entries below the diagonal), in reversed
 * numbering k' = n - 1 - k so that L^T's backward solve runs forward, as
 * LU_RUNS_GATHER runs with a unit diagonal; UMFPACK's factor is freed once
 * L is copied out (U's runs must be made first). */
static int runs_of_l(PddoPpe *p, int lnz) {
    const int n = (int)p->n;
    int *Lp = NULL, *Lj = NULL;
    int32_t *cols = NULL;
    int64_t *ptr = NULL, *at = NULL;
    double *Lx = NULL, *vals = NULL;
    int status = nspd_alloc(&Lp, (size_t)n + 1, sizeof *Lp);
    if (status == NSPD_OK) status = nspd_alloc(&Lj, (size_t)lnz, sizeof *Lj);
    if (status == NSPD_OK) status = nspd_alloc(&Lx, (size_t)lnz, sizeof *Lx);
    if (status == NSPD_OK) status = nspd_alloc(&ptr, (size_t)n + 1, sizeof *ptr);
    if (status == NSPD_OK) status = nspd_alloc(&at, (size_t)n + 1, sizeof *at);
    if (status == NSPD_OK) {
        const int s = umfpack_di_get_numeric(Lp, Lj, Lx, NULL, NULL, NULL, NULL, NULL, NULL, NULL,
                                             NULL, p->numeric);
        if (s != UMFPACK_OK) status = umf_fail(s, "get_numeric (L)");
        /* U's runs are made and this is the last read of UMFPACK's factor:
         * freed before L is regrouped, which lowers the peak memory */
        if (status == NSPD_OK) umfpack_di_free_numeric(&p->numeric);
    }
    if (status == NSPD_OK) {
        for (int i = 0; i < n; i++)
            for (int m = Lp[i]; m < Lp[i + 1]; m++)
                if (Lj[m] != i) ptr[n - 1 - Lj[m] + 1]++;
        for (int k = 0; k < n; k++) ptr[k + 1] += ptr[k];
        memcpy(at, ptr, (size_t)n * sizeof *at);
        status = nspd_alloc(&cols, (size_t)ptr[n], sizeof *cols);
        if (status == NSPD_OK) status = nspd_alloc(&vals, (size_t)ptr[n], sizeof *vals);
    }
    if (status == NSPD_OK) {
        /* rows of L from the last: each reversed row's columns come ascending */
        for (int i = n - 1; i >= 0; i--)
            for (int m = Lp[i]; m < Lp[i + 1]; m++)
                if (Lj[m] != i) {
                    const int k = n - 1 - Lj[m];
                    cols[at[k]] = n - 1 - i, vals[at[k]++] = Lx[m];
                }
        nspd_free(&Lx);
        nspd_free(&Lj);
        status = lu_runs_build(&p->runs_l, LU_RUNS_GATHER, n, ptr, cols, vals, NULL, PPE_RUN_MAX);
    }
    nspd_free(&Lp), nspd_free(&Lj), nspd_free(&Lx), nspd_free(&ptr), nspd_free(&at);
    nspd_free(&cols), nspd_free(&vals);
    return status;
}

int pddo_ppe_use_runs(PddoPpe *ppe) {
    if (ppe->runs || !ppe->numeric) return NSPD_OK; /* done, or another rank's factor */
    int lnz, unz, rows, cols, udiag;
    const int s = umfpack_di_get_lunz(&lnz, &unz, &rows, &cols, &udiag, ppe->numeric);
    if (s != UMFPACK_OK) return umf_fail(s, "get_lunz");
    TRY(runs_of_u(ppe, unz));
    TRY(runs_of_l(ppe, lnz)); /* frees UMFPACK's factor */
    TRY(lu_runs_cut(&ppe->runs_u, &ppe->runs_l, &ppe->two_thread_share));
    const int64_t u = lu_runs_scratch(&ppe->runs_u), l = lu_runs_scratch(&ppe->runs_l);
    TRY(nspd_alloc(&ppe->runs_scratch, (size_t)(u > l ? u : l), sizeof(double)));
    TRY(nspd_alloc(&ppe->runs_y, (size_t)ppe->n, sizeof(double)));
    ppe->runs = true;
    return NSPD_OK;
}

/* p = K_L^-1 b by the runs: K_L is the transpose of the matrix UMFPACK
 * factorised (its compressed rows read as columns), P R^-1 K_L^T Q = L U,
 * so K_L = Q U^T L^T P R^-1 and p = R P^T L^-T U^-T Q^T b. */
static void runs_solve(const PddoPpe *ppe, const double *b, double *x) {
    const int64_t n = ppe->n;
    double *y = ppe->runs_y;
    /* the permutations and the scaling move or scale each value alone:
     * the same bits on any number of threads */
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t k = 0; k < n; k++) y[k] = b[ppe->perm_col[k]];
    lu_runs_solve(&ppe->runs_u, y, ppe->runs_scratch);
    /* L^T's backward solve as a forward one in reversed numbering */
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t k = 0; k < n / 2; k++) {
        const double t = y[k];
        y[k] = y[n - 1 - k], y[n - 1 - k] = t;
    }
    lu_runs_solve(&ppe->runs_l, y, ppe->runs_scratch);
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t k = 0; k < n; k++) {
        const int32_t r = ppe->perm_row[k];
        const double w = y[n - 1 - k];
        x[r] = ppe->scale_recip ? w * ppe->row_scale[r] : w / ppe->row_scale[r];
    }
}

/* The singular case's consistency shift and pinned row (the header's
 * R <- R - (y . R / y . m) m), from the whole b: on every rank alike. */
static void make_consistent(PddoPpe *ppe, double *b) {
    const int64_t n = ppe->n;
    ppe->shift = 0.0;
    if (ppe->pinned < 0) return;
    /* serial sums: the same order, hence bits, at any thread count */
    double yr = 0.0;
    for (int64_t k = 0; k < n; k++) yr += ppe->null_left[k] * b[k];
    ppe->shift = yr / ppe->null_ppe;
    for (int64_t k = 0; k < n; k++)
        if (ppe->row[k] == PDDO_ROW_PPE) b[k] -= ppe->shift;
    b[ppe->pinned] = 0.0;
}

/* The solve of the whole right-hand side b (modified) on this process. */
static int solve_whole(PddoPpe *ppe, double *b, double *p) {
    make_consistent(ppe, b);
    const double t0 = nspd_wall_time();
    int status = NSPD_OK;
    if (ppe->runs)
        runs_solve(ppe, b, p);
    else
        status = umf_solve(ppe, UMFPACK_At, p, b);
    ppe->solve_s += nspd_wall_time() - t0;
    return status;
}

/* PETSc's solve: p's own rows are the first guess and the answer, then
 * shared with every rank. */
static int solve_petsc(PddoPpe *ppe, double *b, double *p) {
    int64_t lo, hi;
    pddo_share_nodes(ppe->share, ppe->n, &lo, &hi);
    double t0 = nspd_wall_time();
    if (ppe->pinned >= 0) TRY(pddo_share(ppe->share, b, false)); /* y . b reads every row */
    ppe->share_s += nspd_wall_time() - t0;
    make_consistent(ppe, b);
    t0 = nspd_wall_time();
    int status = ppe_petsc_solve(&ppe->petsc, b + lo, p + lo);
    ppe->solve_s += nspd_wall_time() - t0;
    if (ppe->share) TRY(comm_agree(&ppe->share->comm, status, NULL, 0));
    TRY(status);
    t0 = nspd_wall_time();
    status = pddo_share(ppe->share, p, false);
    ppe->share_s += nspd_wall_time() - t0;
    return status;
}

int pddo_ppe_solve(PddoPpe *ppe, const double *rhs, double *p) {
    const int64_t n = ppe->n;
    double *b = ppe->work;
    memcpy(b, rhs, (size_t)n * sizeof(double));
    if (ppe->solver.petsc) return solve_petsc(ppe, b, p);
    if (!ppe->share) return solve_whole(ppe, b, p);
    const NspdComm *comm = &ppe->share->comm;
    double t0 = nspd_wall_time();
    TRY(pddo_share(ppe->share, b, true)); /* the rows to rank 0 */
    ppe->share_s += nspd_wall_time() - t0;
    int status = comm->rank == 0 ? solve_whole(ppe, b, p) : NSPD_OK;
    TRY(comm_agree(comm, status, NULL, 0));
    t0 = nspd_wall_time();
    status = comm_bcast(comm, p, (int)(n * (int64_t)sizeof(double)), 0);
    if (status == NSPD_OK) status = comm_bcast(comm, &ppe->shift, (int)sizeof ppe->shift, 0);
    ppe->share_s += nspd_wall_time() - t0;
    return status;
}

void pddo_ppe_apply(const PddoPpe *ppe, const double *p, double *out) {
    const int64_t n = ppe->n;
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t k = 0; k < n; k++) {
        const bool pin = k == ppe->pinned;
        const int32_t *col = pin ? ppe->pin_col : ppe->ai + ppe->ap[k];
        const double *val = pin ? ppe->pin_val : ppe->ax + ppe->ap[k];
        const int32_t len = pin ? ppe->pin_len : ppe->ap[k + 1] - ppe->ap[k];
        double sum = 0.0;
        for (int32_t m = 0; m < len; m++) sum += val[m] * p[col[m]];
        out[k] = sum;
    }
}

void pddo_ppe_free(PddoPpe *ppe) {
    ppe_petsc_free(&ppe->petsc);
    if (ppe->numeric) umfpack_di_free_numeric(&ppe->numeric);
    lu_runs_free(&ppe->runs_u);
    lu_runs_free(&ppe->runs_l);
    nspd_free(&ppe->perm_row);
    nspd_free(&ppe->perm_col);
    nspd_free(&ppe->diag_u);
    nspd_free(&ppe->row_scale);
    nspd_free(&ppe->runs_y);
    nspd_free(&ppe->runs_scratch);
    nspd_free(&ppe->row);
    nspd_free(&ppe->ap);
    nspd_free(&ppe->ai);
    nspd_free(&ppe->ax);
    nspd_free(&ppe->pin_col);
    nspd_free(&ppe->pin_val);
    nspd_free(&ppe->null_left);
    nspd_free(&ppe->work);
    memset(ppe, 0, sizeof *ppe);
}
