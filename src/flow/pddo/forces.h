/* Drag and lift per unit span on a cylinder of the PDDO flow (paper 002,
 * Eqs. 72-76; notes/pddo.md 1.7), on a cloud built with a polar patch
 * (flow/pddo/polar.h).
 *
 *   F = oint_S sigma n ds,  sigma = mu (grad u + grad u^T) - p I     (Eqs. 72-73)
 *   F_D = sum_i [(2 mu u_,x - p) n_x + mu (u_,y + v_,x) n_y] ds       (Eq. 75a)
 *   F_L = sum_i [mu (u_,y + v_,x) n_x + (2 mu v_,y - p) n_y] ds       (Eq. 75b)
 * over the wall ring's ntheta nodes, ds = R dtheta (Eq. 76), n the outward
 * unit normal of the body at the node's angle (pointing into the fluid), p
 * the wall node's pressure. F is the force of the fluid on the body.
 *
 * The velocity derivatives (Eq. 75 "extracted from" Eq. 20):
 *   PDDO_TRACTION_FLUID_SIDE  (default) each wall node's own PDDO operator
 *       on its fluid-side family: the cloud family without the fictitious
 *       body rings (r >= R), built once here. Exact for quadratic velocity
 *       fields, second order otherwise, whatever the fictitious rings hold
 *       (notes 1.7, #17: with the paper's zero fictitious velocities the
 *       full family's Eq. 20 returns about half the wall shear).
 *   PDDO_TRACTION_FULL_FAMILY  the literal paper: Eq. 20 with the cloud's
 *       operators on the full family, fictitious rings included.
 * The trapezoid rule on the ring is exact for trigonometric polynomials of
 * degree < ntheta, so a field whose traction is such a polynomial on the
 * circle (every polynomial velocity of degree <= 2 and pressure of any
 * degree < ntheta - 1) integrates to round-off. One sum in ring order:
 * the same bits at any thread count. */
#ifndef NSPD_FLOW_PDDO_FORCES_H
#define NSPD_FLOW_PDDO_FORCES_H

#include "flow/pddo/cloud.h"
#include "flow/pddo/operators.h"

#include <stdint.h>

typedef enum {
    PDDO_TRACTION_FLUID_SIDE = 0,
    PDDO_TRACTION_FULL_FAMILY,
} PddoTraction;

typedef struct {
    const PddoCloud *cloud; /* borrowed */
    int patch;              /* the cloud's patch index */
    int32_t m;              /* wall nodes (ntheta) */
    int64_t wall;           /* the cloud's node of the wall ring at angle 0 */
    PddoOps side;           /* fluid-side d/dx, d/dy of the m wall nodes; neighbours offset by m */
    int64_t *first;         /* their families (m + 1; members are m + cloud node) */
    int32_t *nbr;
    double *xs, *ys, *as; /* m + n: the wall nodes, then the cloud's nodes */
} PddoForces;

typedef struct {
    double fx, fy;                   /* drag and lift per unit span, N/m (Eq. 75) */
    double fx_pressure, fy_pressure; /* the -p n part */
    double fx_viscous, fy_viscous;   /* the mu (grad u + grad u^T) n part */
} PddoForce;

/* Builds the fluid-side operators of the wall ring of the cloud's patch
 * `patch`. f is zeroed or freed before. NSPD_ERR_INPUT for a patch index
 * out of range or a wall node whose fluid-side family cannot carry a
 * quadratic fit (operators.h's rule); NSPD_ERR_NOMEM. */
int pddo_forces_build(PddoForces *f, const PddoCloud *cloud, int patch);

/* The traction sigma n on the body at wall node t (the integrand of Eq.
 * 75): n the outward unit normal, p the node's pressure, viscous the mu
 * (grad u + grad u^T) n part (N/m^2), so sigma n = -p n + viscous. At a
 * no-slip wall viscous is tangential: the wall shear stress is viscous .
 * (-ny, nx), along the counterclockwise tangent. */
typedef struct {
    double nx, ny, p, viscous_x, viscous_y;
} PddoWallTraction;

PddoWallTraction pddo_forces_traction(const PddoForces *f, PddoTraction traction,
                                      const PddoOps *ops, const double *u, const double *v,
                                      const double *p, double mu, int32_t t);

/* The force from the nodal fields u, v (m/s), p (Pa) of the cloud with
 * viscosity mu (Pa s): the traction above summed in ring order, ds = R
 * dtheta. traction picks the derivatives; ops (the cloud's operators) is
 * needed for PDDO_TRACTION_FULL_FAMILY only (else NULL). */
PddoForce pddo_forces_eval(const PddoForces *f, PddoTraction traction, const PddoOps *ops,
                           const double *u, const double *v, const double *p, double mu);

/* The vorticity dv/dx - du/dy at the m wall nodes (angle order), from
 * the fluid-side derivatives, into omega (m). */
void pddo_forces_wall_vorticity(const PddoForces *f, const double *u, const double *v,
                                double *omega);

void pddo_forces_free(PddoForces *f);

/* The period and amplitude of a lift signal (paper 002 Sec. 5.3, Re 100)
 * from samples (t, lift) in time order: upward zero crossings, each at the
 * time interpolated linearly between the sample below 0 and the next at 0
 * or above, one counting only after the lift was below -threshold since
 * the last (round-off lifts of a symmetric steady flow never count). The
 * period is the time from the first crossing to the last over their number
 * less one; the amplitude half of max - min of the samples between them.
 * Zero it and set threshold before the first sample. */
typedef struct {
    double threshold; /* N/m, > 0 */
    int64_t samples, crossings, armed;
    double prev_t, prev, first_t, last_t;
    double run_max, run_min; /* since the first crossing */
    double amp_max, amp_min; /* between the first and the last */
} PddoLiftPeriods;

void pddo_lift_periods_add(PddoLiftPeriods *lp, double t, double lift);

/* Whole periods so far (crossings less one, or 0); with at least one, the
 * period (s) and amplitude (N/m). */
int64_t pddo_lift_periods_result(const PddoLiftPeriods *lp, double *period, double *amplitude);

#endif
