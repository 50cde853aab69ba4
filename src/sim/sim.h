/* The simulation: the driver over a solid, a flow and a coupling (each
 * optional, each behind its interface: solid/solid.h, flow/flow.h,
 * couple/coupling.h). One step, whatever the case holds:
 *     dt = the flow's stable (CFL) step, or the given one, shortened to land
 *          on the end time; without a flow, the solid's fixed step
 *     coupling: before the flow   (the solid's state becomes the flow's walls)
 *     flow step
 *     coupling: after the flow    (the flow's state becomes the solid's load)
 *     solid: dt in sub-steps no longer than its own stable step and the
 *            coupling's limit, its clock then pinned to the flow's
 * then the outputs due. Nothing here knows a concrete model. */
#ifndef NSPD_SIM_SIM_H
#define NSPD_SIM_SIM_H

#include "couple/coupling.h"
#include "flow/flow.h"
#include "io/run_files.h"
#include "io/vtk.h"
#include "sim/probes.h"
#include "sim/sim_config.h"
#include "solid/solid.h"

typedef struct {
    /* existing output directory; NULL writes nothing (on several
     * processes: the ranks other than the writer, rank 0) */
    const char *dir;
    bool progress; /* progress line on stderr */
    /* on several processes, every rank: the output directory (made by the
     * writer), where each writes its piece of the fields that models hand
     * out in pieces (FieldPiece); NULL otherwise */
    const char *piece_dir;
} SimRunOptions;

enum { SIM_CHECKPOINTS_KEPT = 2 };

enum { SIM_PART_FLOW = 0, SIM_PART_SOLID = 1, SIM_PART_COUPLING = 2, SIM_PART_COUNT = 3 };

typedef struct {
    SimConfig cfg;
    Solid *solid;         /* NULL: no solid */
    Flow *flow;           /* NULL: no flow */
    Coupling *coupling;   /* NULL: nothing coupled */
    double dt;            /* the last step taken (without a flow: the fixed step) */
    double stable_dt;     /* the pacing model's stable step at the start (flow: CFL) */
    double solid_substep; /* with a flow: the longest solid sub-step */
    /* the coupling prescribes the solid's velocities at every step (the
     * strong coupling of paper 003): one constrained solid step per flow
     * step, the flow's step no longer than solid_substep unless time.dt
     * is given */
    bool constrained;
    double estimate_bytes; /* the memory the case was estimated to need before it was built */
    SolidEstimate solid_estimate; /* the models' estimates, before anything was built */
    FlowEstimate flow_estimate;
    /* the models were built (false only for a check of a case too large
     * to build within the check's budget: sim_check_builds) */
    bool built;
    int64_t steps; /* planned steps (with a flow: estimated from the first step) */
    int64_t step;  /* steps taken */
    double time;   /* simulated time, s */
    ProbeState *probes;

    /* output state */
    Report *report; /* the history row and the summary being assembled */
    const char *dir;
    const char *piece_dir; /* SimRunOptions.piece_dir */
    HistoryFile history;
    PvdSeries pvd[2]; /* solid, flow */
    int field_index;
    double next_field, next_history;
    double wall_s;                 /* wall time of the run, resumed parts included */
    double wall_start;             /* when the run would have started, had it never stopped */
    double part_s[SIM_PART_COUNT]; /* wall time in the flow, the solid, the coupling */
    double agree_s; /* several processes: wall time agreeing on each step's outcome */
    bool interrupted;

    /* checkpoints (sim_checkpoint.c) */
    uint64_t case_hash;     /* of the resolved case, recorded in each checkpoint */
    bool resumed;           /* the state was read from a checkpoint: continue its files */
    double next_checkpoint; /* simulated time of the next scheduled one */
    bool wall_checkpoint;   /* this step: the wall clock asks for one (sim_run) */
    double checkpoint_wall; /* wall time of the last one (or of the start) */
    int64_t history_bytes;  /* history.csv's length at the checkpoint read */
    int checkpoints_written;
} Sim;

/* Builds everything the case describes (takes ownership of *cfg, zeroing
 * it) and fixes the time step. NSPD_ERR_INPUT for problems found while
 * building (geometry without points, inconsistent boundaries, a coupling
 * that does not support the models). */
int sim_create(Sim *sim, SimConfig *cfg);

/* Whether `nspd check` builds the models of a case of these estimates
 * (sim->solid_estimate, flow_estimate): when building takes at most
 * sim_check_budget_s() seconds. */
bool sim_check_builds(const Sim *sim);
double sim_check_budget_s(void);
void sim_destroy(Sim *sim);

/* Runs the case to its end time, writing outputs into opt->dir. Stops
 * cleanly after the current step on Ctrl-C (then NSPD_ERR_INTERRUPTED,
 * with all outputs written and summary.json marked "interrupted"). */
int sim_run(Sim *sim, const SimRunOptions *opt);

/* Writes DIR/checkpoint_<step>.nspd of the current state (after the
 * step's outputs), keeping the newest SIM_CHECKPOINTS_KEPT. */
int sim_checkpoint_write(Sim *sim);

/* Reads the newest whole checkpoint in `dir` into a simulation just built
 * from the same case (sim->case_hash set), so that sim_run continues the
 * run and its files there. NSPD_ERR_INPUT when there is none, or it was
 * written for another case, binary or layout (a damaged newest one is
 * passed over for the one before, with a warning). */
int sim_resume(Sim *sim, const char *dir);

/* Advances `steps` steps (or to the end time) with no output (tests,
 * `nspd info` timing). */
int sim_advance(Sim *sim, int64_t steps);

#endif
