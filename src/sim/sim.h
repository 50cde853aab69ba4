/* The simulation: owns the state of a case and runs its time loop.
 *
 * A case has a solid, a flow (with or without fixed immersed bodies), or
 * both coupled. Per step:
 *   solid only: PD force and update (pd_step) with the fixed dt;
 *   flow only:  GKS step with the stable (CFL) dt, the last one shortened to
 *               land on the end time (immersed bodies: the ghost hook);
 *   coupled:    interface -> ghost cells -> flow step -> surface loads ->
 *               solid sub-steps (couple/fsi.h, ../shared/DESIGN.md);
 * then the outputs due. */
#ifndef NSPD_SIM_SIM_H
#define NSPD_SIM_SIM_H

#include "couple/fsi.h"
#include "couple/ibm.h"
#include "couple/ibm_surface.h"
#include "flow/flow_solver.h"
#include "io/vtk.h"
#include "sim/probes.h"
#include "sim/sim_config.h"
#include "solid/pd_body.h"

#include <stdio.h>

typedef struct {
    const char *dir; /* existing output directory; NULL writes nothing */
    bool progress;   /* progress line on stderr */
} SimRunOptions;

typedef struct {
    SimConfig cfg;
    bool has_solid, has_flow;
    PdBody solid;
    FlowSolver *flow;
    Ibm *ibm;            /* fixed immersed bodies (flow-only cases) */
    IbmPolyline *bodies; /* their polylines */
    int body_count;
    IbmSurface surface; /* their surface loads (outputs) */
    bool has_fsi;
    Fsi fsi;          /* the coupling (solid + flow) */
    double *coef_sum; /* per body: time sums of cd, cl, cd_p, cd_v, cl_p, cl_v */
    int64_t coef_samples;
    double dt;        /* solid: the fixed step; flow: the last step taken */
    double stable_dt; /* solid: the stable PD step; flow: the initial CFL step */
    double solid_substep, solid_stable_dt; /* coupled: the longest PD sub-step, the stable one */
    int64_t steps; /* planned steps (flow: estimated from the initial step) */
    int64_t step;  /* steps taken */
    double time;   /* simulated time, s */

    double *damage;      /* scratch: the damage field when an output or probe needs it */
    double *position[3]; /* scratch: current positions x + u for outputs */
    double *cells[6];    /* scratch: flow fields of the interior cells for outputs */
    ProbeState *probes;

    /* output state */
    const char *dir;
    FILE *history;
    PvdSeries pvd_solid, pvd_flow;
    int field_index;
    double next_field, next_history;
    double wall_s;
    double part_s[3]; /* wall time in the flow step, the solid steps, the coupling */
    bool interrupted;
} Sim;

enum { SIM_PART_FLOW = 0, SIM_PART_SOLID = 1, SIM_PART_COUPLING = 2 };

/* Builds everything the case describes (takes ownership of *cfg, zeroing
 * it) and fixes the time step. NSPD_ERR_INPUT for problems found while
 * building (geometry without points, inconsistent boundaries). */
int sim_create(Sim *sim, SimConfig *cfg);
void sim_destroy(Sim *sim);

/* Runs the case to its end time, writing outputs into opt->dir. Stops
 * cleanly after the current step on Ctrl-C (then NSPD_ERR_INTERRUPTED,
 * with all outputs written and summary.json marked "interrupted"). */
int sim_run(Sim *sim, const SimRunOptions *opt);

/* Advances `steps` steps (or to the end time) with no output (tests,
 * `nspd info` timing). */
int sim_advance(Sim *sim, int64_t steps);

#endif
