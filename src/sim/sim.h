/* The simulation: owns the state of a case and runs its time loop.
 *
 * Per step (solid-only cases): PD force and update (pd_step), then the
 * outputs due. The flow and the coupling join this loop in later stages:
 * interface -> ghost cells -> flow step -> surface loads -> solid sub-steps
 * -> outputs (../shared/DESIGN.md). */
#ifndef NSPD_SIM_SIM_H
#define NSPD_SIM_SIM_H

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
    PdBody solid;
    double dt, stable_dt;
    int64_t steps;
    double *damage;      /* scratch: the damage field when an output or probe needs it */
    double *position[3]; /* scratch: current positions x + u for outputs */
    ProbeState *probes;

    /* output state */
    const char *dir;
    FILE *history;
    PvdSeries pvd;
    int field_index;
    double next_field, next_history;
    double wall_s;
    bool interrupted;
} Sim;

/* Builds everything the case describes (takes ownership of *cfg, zeroing
 * it) and fixes the time step: the case's dt, or safety_factor x the stable
 * step. NSPD_ERR_INPUT for geometry problems found while building. */
int sim_create(Sim *sim, SimConfig *cfg);
void sim_destroy(Sim *sim);

/* Runs the case to its end time, writing outputs into opt->dir. Stops
 * cleanly after the current step on Ctrl-C (then NSPD_ERR_INTERRUPTED,
 * with all outputs written and summary.json marked "interrupted"). */
int sim_run(Sim *sim, const SimRunOptions *opt);

/* Advances `steps` steps with no output (tests, `nspd info` timing). */
int sim_advance(Sim *sim, int64_t steps);

#endif
