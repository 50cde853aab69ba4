/* The volumetric penalty between PD points and the flow's unknowns,
 * integrated implicitly over one flow step (paper 003, Eqs. 21-23;
 * ../shared/notes/correspondence_and_penalty.md Sec. 1a.6).
 *
 * Over a step of dt the penalty alone is, per metre of depth,
 *     m_P dv_P/dt = -k_P (v_P - sum_c W_Pc u_c)
 *     m_c du_c/dt = sum_P W_Pc k_P (v_P - sum_c' W_Pc' u_c')
 * Backward Euler, with the points' velocities eliminated
 * (v_P' = (m_P v_P + a_P s_P') / (m_P + a_P), a_P = dt k_P, s_P' the
 * sampled velocity), leaves the cells' system
 *     (diag(m_c) + sum_P b_P W_P W_P^T) u' = m_c u + sum_P b_P W_P v_P,
 *     b_P = a_P m_P / (m_P + a_P)            (b_P = m_P: the strong limit)
 * symmetric positive definite; solved by conjugate gradients with the
 * diagonal as preconditioner (nearest-cell weights: diagonal, one
 * iteration). The impulse on point P is J_P = b_P (s_P' - v_P) and the
 * caller hands each cell -sum_P W_Pc J_P: the exchange is pairwise, so
 * momentum is exact to round-off whatever the solver's tolerance, and the
 * relative velocity decays for any dt and any stiffness.
 *
 * Plain arrays, no allocation. The rows' sums run over their entries in
 * point order and the dot products are exact sums (core/exact_sum.h), so
 * the answer is the same bits on any number of threads and processes.
 *
 * Divided between processes (issue 28), each process forms the rows of the
 * cells it holds and the impulses of the points it owns (those whose own
 * cell, the one holding them, it holds); a row reads the samples of the
 * points that touch its cell, which read the cells of their stencils:
 * those that other processes hold arrive through `exchange` before each
 * product, and the dot products' sums are added across processes by
 * `reduce`. */
#ifndef NSPD_COUPLE_PENALTY_RELAX_H
#define NSPD_COUPLE_PENALTY_RELAX_H

#include "core/exact_sum.h"

#include <stdint.h>

/* What one process of several forms (PenaltySystem.div; NULL: all). */
typedef struct {
    int64_t own_cells;
    const int64_t *own_cell; /* the cells whose rows it forms */
    int64_t near_points;
    const int64_t *near_point; /* the points that touch them */
    int64_t own_points;
    const int64_t *own_point; /* the points whose impulses it forms (J's other entries: 0) */
    /* x at the cells the near points read and other processes hold, from
     * them (collective) */
    void (*exchange)(void *ctx, double *x);
    /* s[0..count) added over the processes (collective) */
    void (*reduce)(void *ctx, ExactSum *s, int count);
    void *ctx;
} PenaltyDivision;

typedef struct {
    int64_t points;
    int width;          /* entries per point */
    const int32_t *col; /* points * width: the entry's cell (0 .. cells-1), -1: none */
    const double *w;    /* points * width: its weight */
    const double *m;    /* points: m_P (kg per metre of depth) */
    const double *b;    /* points: b_P (kg per metre of depth); 0 decouples */
    const double *v[2]; /* points: velocity at the start of the relaxation */
    int64_t cells;
    const double *mass; /* cells: kg per metre of depth, > 0 */
    const double *u[2]; /* cells: velocity at the start */
    double *u_out[2];   /* cells: the velocity after, this process's cells (NULL: not wanted) */
    /* the same entries by cell, in point order within a cell: cell c's are
     * k = first[c] .. first[c+1]-1, of point point[k] with weight weight[k] */
    const int64_t *first; /* cells + 1 */
    const int32_t *point;
    const double *weight;
    const PenaltyDivision *div; /* NULL: one process */
} PenaltySystem;

/* Scratch of the solve: one array per point, six per cell. */
typedef struct {
    double *sample;                    /* points */
    double *x, *r, *z, *p, *ap, *diag; /* cells */
} PenaltyWork;

typedef struct {
    int iterations;   /* the most of the two components' */
    double residual;  /* the largest relative residual reached */
    double slip_max;  /* max over points of |s_P' - v_P'| after the step, m/s (the
                         process's own points: a max over processes is the whole's) */
    double slip_work; /* sum_P J_P . (s_P' - v_P) = sum_P b_P |s_P' - v_P|^2,
                         J per metre, >= 0 (a scale of the step's dissipation) */
} PenaltyStats;

/* Relative residual at which the solve stops, and its most iterations. */
#define PENALTY_CG_TOL 1e-13
enum { PENALTY_CG_MAX = 500 };

/* Solves the step's system and writes each point's impulse (N s per metre
 * of depth) into J[0][P], J[1][P]. */
void penalty_relax(const PenaltySystem *s, PenaltyWork *work, double *J[2], PenaltyStats *stats);

/* The paper's explicit update instead (its predictor-multicorrector holds
 * the penalty force at the step's start): J_P = b_P (s_P - v_P), b_P =
 * a_P = dt k_P, s_P sampled from the cells' velocities at the start; no
 * solve. Momentum is as exact (the cells get -sum_P W_Pc J_P), but the
 * relative velocity decays only while a_P (1/m_P + sum_c W_Pc^2 / m_c) < 2:
 * beyond, the exchange overshoots and grows (stats->slip_max says so). */
void penalty_explicit(const PenaltySystem *s, PenaltyWork *work, double *J[2], PenaltyStats *stats);

#endif
