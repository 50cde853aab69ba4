/* The parts of a PD body's set-up and motion that do not depend on the
 * force model: which boundary region holds each point, the initial
 * velocities, the flat table of prescribed motions the integrator reads,
 * and the kick and drift of an explicit step (paper 000 Eq. 30, velocity
 * Verlet). The bond-based body (solid/bond/body.c) and the correspondence body
 * (solid/correspondence/body.c) both build and move their points with these. */
#ifndef NSPD_SOLID_PD_REGIONS_H
#define NSPD_SOLID_PD_REGIONS_H

#include "core/balance.h"
#include "solid/pd/config.h"

#include <stdbool.h>
#include <stdint.h>

/* The boundary regions of cfg.boundaries as the integrator reads them: plain
 * arrays built at creation (no shapes, names or pointers to follow, so a
 * device copy is a copy of five arrays). Entry 3 r + d is component d of
 * region r; point i belongs to region region[i] (or none if -1). Changing
 * cfg.boundaries after creation does not reach the integrator: change the
 * table. */
typedef struct {
    int count;                  /* regions */
    uint8_t *velocity_given;    /* 1: velocity component prescribed */
    uint8_t *displacement_held; /* 1: displacement component held (velocity 0) */
    double *velocity;           /* m/s, where given */
    double *displacement;       /* m, where held */
    double *force_density;      /* N/m^3 added on the region's points */
    /* Loads that vary (PdBoundaryRegion): entry k > 0 of these replaces the
     * constant by expressions[k - 1] at (t, the point's reference x, y, z);
     * all 0 when the case has no expression (varies false). */
    uint16_t *velocity_expr, *displacement_expr, *force_expr;
    uint16_t body_force_expr[3];
    int expression_count;
    Expr *expressions;
    bool varies;
} PdBoundaryTable;

/* region[i]: the first of cfg.boundaries whose shapes hold point i, or -1;
 * v: the initial velocities of cfg.initial_velocities (the last that holds
 * the point wins; an expression at t = 0 and the point's x), left as they
 * are elsewhere. */
void pd_regions_assign(const PdConfig *cfg, int64_t n, const double *const x[3], int16_t *region,
                       double *const v[3]);

/* Flattens cfg.boundaries into *t (NSPD_ERR_NOMEM); free with
 * pd_boundary_table_free. */
int pd_boundary_table_build(PdBoundaryTable *t, const PdConfig *cfg);
void pd_boundary_table_free(PdBoundaryTable *t);

/* What an explicit step moves: the points' motion arrays and what drives
 * them (borrowed pointers; force and external are force densities, N/m^3). */
typedef struct {
    int dim;
    int64_t n;
    double density;              /* kg/m^3 */
    const double *point_density; /* optional (NULL: density everywhere): per point, kg/m^3 */
    const double *body_force;    /* 3 components, N/m^3 on every point */
    const double *x[3];          /* reference positions: where load expressions are evaluated */
    double *u[3], *v[3];
    const double *force[3], *external[3];
    const int16_t *region;
    const PdBoundaryTable *boundary;
    /* Optional (NULL: none): a second copy of u the drift keeps up too,
     * point i's at mirror[d][mirror_at[i]] (the bond-based body's lattice
     * view, which the force would otherwise copy from u every step). */
    double *mirror[3];
    const int32_t *mirror_at;
    /* Optional (NULL: equal shares): the threads' shares of the points,
     * moved toward equal times after each pass (core/balance.h). */
    Balance *balance;
} PdMotion;

/* v += (force + external + body force + region force density) / rho * h,
 * the loads at time t_load (that of `force`), then the regions' prescribed
 * velocities at t_end, the time the kick brings v to (a held displacement:
 * v = 0, or for one that varies its rate (g(t_end + h) - g(t_end - h)) /
 * 2 h). */
void pd_kick(const PdMotion *m, double h, double t_load, double t_end);
/* u += v h, then the regions' held displacements at t_end (into the mirror
 * too, if any). Returns true if any
 * displacement is not finite (the NaN check rides on this pass, which reads
 * and writes u anyway: a NaN in v reaches u in the same step). */
bool pd_drift(const PdMotion *m, double h, double t_end);
/* pd_kick then pd_drift, by h both, in one pass over the points (the
 * Euler-Cromer step: the same bits, half the reads). */
bool pd_kick_drift(const PdMotion *m, double h, double t_load, double t_end);

#endif
