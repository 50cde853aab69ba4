/* The explicit PDDO flow step of paper 002 (Sec. 3.4, Eqs. 7, 8/35, 20-30,
 * 33; notes/pddo.md 1.1, 1.3, 1.5): from u^(n-1),
 *   7.1  the velocity conditions of Sec. 4 on the sides and fictitious nodes;
 *   7.2  grad u, lap u (Eqs. 20, 21) at every node, d = u.grad u (Eq. 23),
 *        L = lap u, then div u, div d, div L (Eqs. 22, 24, 27) and
 *        r = (rho/dt) div u - rho div d + mu div L (Eq. 33b) on the PPE rows;
 *   7.3  K_L P = R (Eq. 34) by back substitution (flow/pddo/ppe.h);
 *   7.4  u^(n) = u^(n-1) + dt (-d - grad p / rho + nu L) (Eq. 8) at the
 *        nodes that are not prescribed.
 * Forward Euler for convection and diffusion, pressure implicit: first
 * order in time, and the velocity is not discretely divergence-free (notes
 * 1.5). Stable for dt <= min(1.61 dx^2 / nu, 2 nu / |u|^2) (notes 1.5, von
 * Neumann analysis of the lattice operators); pddo_step_stable_dt gives
 * half of it.
 *
 * Velocity conditions (Sec. 4), one rule per node, by precedence where a
 * node lies on or beyond two sides (corners, which the paper leaves open):
 *   wall at rest > moving wall (lid) > inlet > periodic > outlet:
 *   wall   side nodes take the wall velocity; fictitious ones too (Eqs.
 *          36-39, 55; the paper's choice, first order at walls: it halves
 *          the wall shear, notes 1.6) or, with PDDO_WALL_ANTISYMMETRIC, its
 *          reflection 2 u_wall - u(pressure image) (second order)
 *   inlet  side and fictitious nodes take the inflow (Eqs. 57, 61), uniform
 *          or parabolic across the side (fictitious nodes take the value
 *          of their row or column)
 *   outlet the side node (exit layer) is updated by Eq. 8 like a fluid node
 *          (notes #23), fictitious nodes copy it along the normal (Eq. 52)
 *   periodic fictitious nodes copy their image, and so do d and L there
 *   body   fictitious body nodes are at rest (Eqs. 44, 47), or reflect
 *          their image with PDDO_WALL_ANTISYMMETRIC; a polar patch's wall
 *          ring is at rest (Eq. 68) and updates its pressure by the PPE
 * d and L at the other fictitious nodes come from their own truncated
 * families (notes #19). */
#ifndef NSPD_FLOW_PDDO_STEP_H
#define NSPD_FLOW_PDDO_STEP_H

#include "flow/pddo/cloud.h"
#include "flow/pddo/forces.h"
#include "flow/pddo/operators.h"
#include "flow/pddo/ppe.h"
#include "flow/pddo/share.h"

#include <stdbool.h>
#include <stdint.h>

typedef enum {
    PDDO_WALL_ZERO = 0,      /* the paper: fictitious wall nodes hold the wall velocity */
    PDDO_WALL_ANTISYMMETRIC, /* u_g = 2 u_wall - u(image): second order (notes 1.6, V6) */
} PddoWallGhosts;

/* Where the PPE's divergence term (rho/dt) div u (Eq. 33b) acts. Eq. 33b
 * comes from asking that Eq. 8's update leave div u = 0; on a node whose
 * velocity is prescribed (a wall, lid or inlet node, a body's wall ring)
 * Eq. 8 never acts, its divergence is never fed back, and the term turns
 * it into a wall pressure that grows as 1/dt (measured: the Re 100
 * cylinder's front pressure 11.7 and 13.2 kPa at dt 5e-5 and 2.5e-5 s,
 * icoFoam's 9.28 kPa; docs/VALIDATION.md). */
typedef enum {
    PDDO_DIVERGENCE_ALL_ROWS = 0, /* the paper: every PPE row */
    PDDO_DIVERGENCE_UPDATED,      /* the rows of nodes Eq. 8 updates; a prescribed node's row
                                     keeps -rho div d + mu div L, the continuous PPE's source */
} PddoDivergenceTerm;

typedef enum {
    PDDO_INLET_UNIFORM = 0, /* the paper: (inlet_u, inlet_v) on the whole side */
    PDDO_INLET_PARABOLIC,   /* 6 s (1 - s) (inlet_u, inlet_v), s in [0, 1] across the side: a
                               developed channel inflow of the same mean, 1.5 times it in the
                               middle */
} PddoInletProfile;

/* Who holds the two nodes where the inlet side meets its neighbours (the
 * problem as posed is discontinuous there: the inflow against a no-slip
 * wall). */
typedef enum {
    PDDO_INLET_CORNERS_WALL = 0, /* the wall (u = 0): the inlet's nodes carry the flow rate
                                    velocity x (length - spacing), a first-order deficit (the
                                    Re 10 cylinder's channel -0.83 % at dx 0.05 m, its drag
                                    -0.77 %) */
    PDDO_INLET_CORNERS_INLET,    /* the inflow: velocity x length, as posed (trapezoid rule);
                                    the scheme still loses some near the corners
                                    (docs/VALIDATION.md) */
} PddoInletCorners;

/* The pressure at walls and bodies. The paper's images p_g = p(image)
 * make dp/dn = 0 there, where a no-slip wall has dp/dn = mu n . lap u, and
 * its PPE source takes rho F = -rho u.grad u + mu lap u on the prescribed
 * and fictitious members of a family, where at a steady state the updated
 * nodes have G p instead. Both leave a steady flow a divergence next to the
 * wall that does not fall with the spacing at a fixed tau (docs/
 * VALIDATION.md: 5.1 to 5.6 per s at the cylinder's front, dx 0.1 to
 * 0.025 m), and with it forces that depend on tau and converge at an order
 * of 0.57. */
typedef enum {
    PDDO_WALL_PRESSURE_ZERO_GRADIENT = 0, /* the paper (Eqs. 40-43, 56, 69) */
    PDDO_WALL_PRESSURE_MOMENTUM,          /* each polar body's fictitious pressures from the
                                             momentum equation's dp/dr = -mu d(omega)/ds on its
                                             wall ring (omega from the fluid-side operators,
                                             d/ds centred along the ring), and the PPE source's
                                             prescribed and fictitious nodes taking the last
                                             step's G p in place of rho F, so that a steady
                                             state's divergence is (tau/rho) (L - D G) p alone;
                                             the rectangle's sides keep dp/dn = 0 */
} PddoWallPressure;

typedef struct {
    double rho, mu;            /* kg/m^3, Pa s */
    double dt;                 /* s */
    double wall_u[PDDO_SIDES]; /* velocity of each wall side, m/s (a lid: u of the top) */
    double wall_v[PDDO_SIDES];
    double inlet_u, inlet_v; /* inflow, m/s (the mean of a parabolic one) */
    PddoInletProfile inlet_profile;
    PddoInletCorners inlet_corners;
    PddoWallGhosts walls; /* fictitious velocities of walls, lids and bodies */
    PddoDivergenceTerm divergence;
    /* tau of the PPE's divergence term (rho/tau) div u, s; 0: dt, the
     * paper's Eq. 33b. A divergence left by a step is removed over about
     * tau / dt steps (its factor a step 1 - dt/tau), and the steady state
     * keeps div u = (tau/rho) (L - D G) p, L the PDDO Laplacian of the PPE
     * and D G the divergence of its gradient, which differ at the bodies
     * and walls: with tau = dt the steady flow and its forces depend on dt
     * (docs/VALIDATION.md), with a fixed tau they do not depend on dt at
     * all. At least dt (1 - dt/tau > -1 needs tau > dt/2). */
    double divergence_time;
    PddoWallPressure wall_pressure;
    double force_x, force_y; /* uniform body acceleration, m/s^2 (divergence-free, so
                                Eq. 33 is unchanged) */
    double spin_speed;       /* a start-up seed: every polar body's wall turns counterclockwise
                                at this speed, m/s, while time < spin_until (0: at rest) */
    double spin_until;       /* s */
} PddoStepParams;

enum { PDDO_VEL_FREE = 0, PDDO_VEL_FIXED, PDDO_VEL_COPY, PDDO_VEL_PERIODIC, PDDO_VEL_ANTI };

typedef struct {
    const PddoCloud *cloud; /* borrowed, with the operators and the PPE built on it */
    const PddoOps *ops;
    PddoPpe *ppe;
    PddoStepParams par;
    double *u, *v, *p;     /* the state, n each (p of the last step) */
    uint8_t *rule;         /* PDDO_VEL_* per node */
    int32_t *source;       /* COPY / PERIODIC / ANTI: the node read; else -1 */
    double *fix_u, *fix_v; /* FIXED: the values; ANTI: the wall velocity */
    double *scratch[9];    /* ux, uy, vx, vy, lu, lv, d1, d2, r */
    double *image_rhs;     /* NULL (the paper's zeros), or n: the right-hand side of each
                              fictitious node's pressure row p_g - s p_image
                              (PDDO_WALL_PRESSURE_MOMENTUM: the bodies' Neumann data) */
    /* PDDO_WALL_PRESSURE_MOMENTUM: each polar patch's fluid-side operators
     * and wall vorticity, and the nodes whose velocity is prescribed (not
     * periodic copies), ascending */
    PddoForces *wall;
    double *omega;
    int64_t *held;
    int64_t nheld;
    double time;
    bool spinning; /* the bodies' walls turn now (spin_speed, spin_until) */
    int64_t steps;
    double dudt_max; /* the last step's max |du/dt|, |dv/dt| over updated nodes (m/s^2): the
                        steady-state criterion */
    /* several processes (share.h): this rank's range of nodes, shared
     * after each update; NULL: one process */
    const PddoShare *share;
    double share_s; /* wall time in those shares so far */
} PddoStep;

/* Sets up the step on a cloud with its operators and PPE (borrowed: they
 * must outlive it); u = v = p = 0, then the velocity conditions. ps is
 * zeroed or freed before. NSPD_ERR_INPUT for dt, rho or mu not positive or
 * a spin without polar bodies; NSPD_ERR_NOMEM. */
int pddo_step_init(PddoStep *ps, const PddoCloud *cloud, const PddoOps *ops, PddoPpe *ppe,
                   const PddoStepParams *par);

/* Divides the step's work among share's ranks (borrowed; NULL or one
 * process: nothing): each computes its own nodes and shares them. */
void pddo_step_share(PddoStep *ps, const PddoShare *share);

/* Imposes the velocity conditions (Sec. 3.4 step 7.1) on u and v; call
 * after setting an initial field. */
void pddo_step_apply_bc(PddoStep *ps);

/* One step (7.1-7.4). NSPD_ERR_NUMERIC if the solve fails or a velocity
 * becomes non-finite (naming the node). */
int pddo_step_advance(PddoStep *ps);

/* Half the stable limit of notes 1.5 for speed umax (m/s), spacing dx. */
double pddo_step_stable_dt(double nu, double dx, double umax);

void pddo_step_free(PddoStep *ps);

#endif
