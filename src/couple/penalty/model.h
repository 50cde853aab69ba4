/* The volumetric penalty coupling of paper 003 (Eqs. 21-23): the gas fills
 * the whole box, and at every PD point a penalty C_P (v_gas - v_P), with
 *     C_P = beta E dt_pen / h^2                    (Eq. 22)
 *     C_P = beta (1 - d_P) E dt_pen / h^2          (Eq. 23, `damaged`)
 * pulls the two velocities together. Nothing needs a closed surface:
 * fragments fly apart and gas streams through broken material.
 *
 * Per flow step (after ../shared/notes/correspondence_and_penalty.md Sec.
 * 1a.8, with the impulse applied at once: docs/ARCHITECTURE.md says why):
 * the flow steps as if alone; the gas velocity is sampled at the points
 * with the flow's transfer weights and the penalty relaxed implicitly
 * (couple/penalty/relax.h: unconditionally stable for any beta, momentum
 * exact), or by the paper's explicit update (`integration: explicit`);
 * each point's velocity changes by its impulse J_P / m_P and the gas gets
 * minus it through the same weights, its total energy minus the impulse's
 * work on the point, J_P . (v_P + v_P') / 2, so gas total + solid
 * mechanical energy is conserved and the penalty's dissipation heats the
 * gas (`energy: momentum_only` is the paper's variant: momentum rows
 * only); then the solid takes its own sub-steps.
 * `strong` is the paper's strong coupling (Eqs. 18-20, Remark 3.1), the
 * beta -> infinity limit of the same relaxation: the points' velocities
 * are the flow's, interpolated with the transfer weights (Eq. 18), and
 * the solid's mass and internal force enter the flow's momentum rows
 * through the same weights (Eq. 19, the system W^T M_s W of relax.h). By
 * default (`strong_constraint: every_step`, the paper's) this happens at
 * every step: the flow's step is the solid's, and the solid only drifts
 * with the prescribed velocities and kicks with its force
 * (solid_advance_constrained), which the next projection hands to the
 * gas; `flow_step` is the earlier reading, the solid slaved once per flow
 * step and free over its sub-steps. `subtract_fluid` (the paper's, on by
 * default with strong) takes the fluid's forms over the solid's volume
 * out of the momentum rows (Eq. 20): in the lumped reading, unknown c's
 * gas mass and the gas's own momentum change of the step count with 1 -
 * phi_c, phi_c = sum_P W_Pc A_P / V_c the fraction of its lumped volume
 * the intact solid covers (docs/COUPLING_STRONG.md).
 *
 * Through the interfaces only: the flow's transfer, lumped and add_lumped
 * operations (flow.h), the solid's PdPoints, damage, modulus and density. */
#ifndef NSPD_COUPLE_PENALTY_MODEL_H
#define NSPD_COUPLE_PENALTY_MODEL_H

#include "flow/flow.h"

#include <stdbool.h>

/* How a 2D solid's thickness t meets the gas's unit depth: `depth_
 * consistent` (the thickness cancels: the solid is as deep as the gas, the
 * ghost-cell coupling's reading), or `plate_in_unit_depth` (a plate of
 * thickness t in one metre of gas: the solid's mass, stiffness and
 * strength per metre of depth carry t / 1 m). */
typedef enum {
    PENALTY_DEPTH_CONSISTENT = 0,
    PENALTY_PLATE_IN_UNIT_DEPTH,
} PenaltyThickness;
extern const char *const PENALTY_THICKNESS_NAMES[];

typedef enum {
    PENALTY_ENERGY_TOTAL = 0,     /* the force's work at the solid's motion enters the gas */
    PENALTY_ENERGY_MOMENTUM_ONLY, /* the paper's: the gas's total energy is left alone */
} PenaltyEnergy;
extern const char *const PENALTY_ENERGY_NAMES[];

/* When the strong coupling constrains the solid (PenaltyConfig.strong). */
typedef enum {
    PENALTY_STRONG_EVERY_STEP = 0, /* the paper's: at every (shared) step */
    PENALTY_STRONG_FLOW_STEP,      /* once per flow step, free sub-steps in between */
} PenaltyStrongConstraint;
extern const char *const PENALTY_STRONG_CONSTRAINT_NAMES[];

/* How the penalty is integrated over a step (weak coupling). */
typedef enum {
    PENALTY_IMPLICIT = 0, /* backward Euler, solved (relax.h): stable for any beta and step */
    PENALTY_EXPLICIT,     /* the paper's: the force at the step's start (penalty_explicit) */
} PenaltyIntegration;
extern const char *const PENALTY_INTEGRATION_NAMES[];

typedef struct {
    double beta; /* > 0 */
    PenaltyIntegration integration;
    bool strong; /* the beta -> infinity limit */
    PenaltyStrongConstraint strong_constraint;
    bool subtract_fluid; /* strong: Eq. 20's minus the fluid over the solid */
    bool damaged;        /* Eq. 23: C_P scaled by 1 - d_P */
    double h;            /* m, the length in C_pen; 0: the solid's lattice spacing */
    double dt;           /* s, the step in C_pen; 0: the solid's stable step */
    FlowTransferKind transfer;
    PenaltyThickness thickness;
    PenaltyEnergy energy;
    /* Sealed faces (notes Sec. 1a.7 (ii), beyond the paper): between two
     * cells the intact solid covers to at least seal_fraction of their area,
     * the gas carries only the mass the solid moves (FlowOps.seal), so no
     * pressure diffuses through the locked gas; a point covers its area
     * times 1 - d, so cracks open the faces again. */
    bool seal;
    double seal_fraction; /* in (0, 1] */
} PenaltyConfig;

struct CouplingOps;
extern const struct CouplingOps PENALTY_COUPLING_OPS;

/* The last step's relaxation, for tests (NULL when the coupling is not a
 * penalty one). */
typedef struct Coupling Coupling;
typedef struct {
    double impulse[2];    /* sum of the impulses on the points, N s per metre of depth */
    double gas[2];        /* what the gas received, the same */
    double c_pen_max;     /* kg/(m^3 s), the largest C_P of the step */
    double slip_max;      /* m/s */
    int iterations;       /* of the solve */
    int64_t outside;      /* points with no gas around them */
    double energy_to_gas; /* J per metre of depth, added so far */
    double covered_max;   /* subtract_fluid: the largest phi_c of the step */
} PenaltyStepInfo;
const PenaltyStepInfo *penalty_coupling_step(Coupling *c);

#endif
