#include "sim/sim.h"

#include "core/interrupt.h"
#include "core/log.h"
#include "core/mem.h"
#include "core/progress.h"
#include "core/status.h"
#include "core/timer.h"
#include "sim/sim_output.h"

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* The time step, fixed here once: the model that sets the pace (the flow if
 * there is one, else the solid) gives its stable step; a given time.dt
 * replaces it (with a warning when it exceeds the stable one). */
/* More steps than this are an input mistake (a time.end in the wrong unit),
 * not a run: about a year of steps at 3e4 steps/s. */
enum { SIM_MAX_STEPS = 1000000000 };

/* The steps to time.end at sim->dt, refused beyond SIM_MAX_STEPS. */
static int plan_steps(Sim *sim) {
    const SimConfig *c = &sim->cfg;
    const double steps = ceil(c->end_time / sim->dt - 1e-9);
    if (!(steps <= SIM_MAX_STEPS))
        return NSPD_FAIL(
            NSPD_ERR_INPUT,
            "%s%stime.end = %g s needs %.3g steps of %g s; expected at most %.0e steps "
            "(a shorter time.end or a coarser case)",
            c->end_time_at, c->end_time_at[0] ? ": " : "", c->end_time, steps, sim->dt,
            (double)SIM_MAX_STEPS);
    sim->steps = steps < 1 ? 1 : (int64_t)steps;
    return NSPD_OK;
}

/* A coupled step of a flow whose stable step is `stable`: the given
 * time.dt, else that step, no longer than the solid's under a coupling
 * that constrains it at every step. */
static double flow_pace(const Sim *sim, double stable) {
    if (sim->cfg.dt_given) return sim->cfg.dt;
    return sim->constrained ? fmin(stable, sim->solid_substep) : stable;
}

static int choose_pace(Sim *sim) {
    const SimConfig *c = &sim->cfg;
    sim->constrained = sim->coupling && coupling_constrains_solid(sim->coupling);
    if (sim->solid) {
        double stable = solid_stable_dt(sim->solid);
        /* a constrained solid moves with the flow's unknowns: its stable
         * step is the projected system's, at least the free solid's
         * (docs/COUPLING_STRONG.md) */
        if (c->dt_given && c->dt > stable)
            nspd_log(sim->constrained ? LOG_INFO : LOG_WARN,
                     "time.dt = %g s exceeds the stable PD time step %g s; %s", c->dt, stable,
                     sim->constrained ? "the strong coupling constrains the solid to the flow, "
                                        "whose stable step is at least that "
                                        "(docs/COUPLING_STRONG.md)"
                                      : "the run may blow up");
        /* alone, the solid steps with this; with a flow, it sub-steps with it */
        sim->solid_substep = c->dt_given ? c->dt : c->safety_factor * stable;
        if (sim->coupling)
            sim->solid_substep =
                fmin(sim->solid_substep, coupling_solid_dt_limit(sim->coupling, sim->solid));
        sim->stable_dt = stable;
        sim->dt = sim->solid_substep;
    }
    if (sim->flow) {
        sim->stable_dt = flow_stable_dt(sim->flow);
        if (c->dt_given && c->dt > sim->stable_dt)
            nspd_log(LOG_WARN, "time.dt = %g s exceeds the CFL time step %g s", c->dt,
                     sim->stable_dt);
        sim->dt = flow_pace(sim, sim->stable_dt);
    }
    return plan_steps(sim);
}

/* The memory the case will need, estimated from its configuration by each
 * model, against this machine's memory (or --max-memory): a case that
 * cannot fit is refused before anything is built. */
static int check_memory(Sim *sim) {
    const SimConfig *c = &sim->cfg;
    const SolidEstimate s = sim->solid_estimate = solid_estimate(&c->solid);
    const FlowEstimate f = sim->flow_estimate = flow_estimate(&c->flow);
    const CouplingEstimate k = coupling_estimate(&c->coupling, &f);
    sim->estimate_bytes = s.bytes + f.bytes + k.bytes;
    const bool given = c->max_memory_bytes > 0;
    const double limit = given ? c->max_memory_bytes : nspd_mem_physical_bytes();
    if (limit <= 0 || sim->estimate_bytes <= limit) return NSPD_OK;
    char sizes[160] = "";
    if (c->solid.kind != SOLID_NONE)
        snprintf(sizes, sizeof sizes, "%.3g points, %.3g bonds", s.points, s.bonds / 2);
    if (c->flow.method != FLOW_METHOD_NONE)
        snprintf(sizes + strlen(sizes), sizeof sizes - strlen(sizes), "%s%.3g %s",
                 sizes[0] ? ", " : "", f.cells, f.items ? f.items : "cells");
    return NSPD_FAIL(NSPD_ERR_INPUT,
                     "the case needs about %.3g GB (%s) and %s %.3g GB; expected a coarser case%s",
                     sim->estimate_bytes / 1e9, sizes,
                     given ? "--max-memory allows" : "this machine has", limit / 1e9,
                     given ? " or a larger --max-memory" : "");
}

/* `nspd check` builds the models only where that takes at most this long
 * (the estimates' check_s, from rates measured on each model): a larger
 * case is checked from its configuration alone (each model's validate op)
 * and described from its estimates, so that check answers within a second
 * however large the case it describes. The checks that need the points,
 * cells or nodes themselves are then the build's (nspd info, nspd run). */
#define SIM_CHECK_BUILD_S 0.5

/* check of a case too large to build within SIM_CHECK_BUILD_S: the
 * models' configurations validated, the step and the steps from the
 * estimates (unknown, 0, where a model knows its step only once built). */
static int check_unbuilt(Sim *sim) {
    SimConfig *c = &sim->cfg;
    if (c->solid.kind != SOLID_NONE) TRY(nspd_error_at(solid_validate(&c->solid), c->solid.where));
    if (c->flow.method != FLOW_METHOD_NONE)
        TRY(nspd_error_at(flow_validate(&c->flow), c->flow.where));
    const bool flow = c->flow.method != FLOW_METHOD_NONE;
    sim->stable_dt = flow ? sim->flow_estimate.stable_dt : sim->solid_estimate.stable_dt;
    sim->dt = c->dt_given ? c->dt : flow ? sim->stable_dt : c->safety_factor * sim->stable_dt;
    if (!(sim->dt > 0.0)) return NSPD_OK; /* known once built */
    return plan_steps(sim);
}

bool sim_check_builds(const Sim *sim) {
    return sim->solid_estimate.check_s + sim->flow_estimate.check_s <= SIM_CHECK_BUILD_S;
}

double sim_check_budget_s(void) {
    return SIM_CHECK_BUILD_S;
}

int sim_create(Sim *sim, SimConfig *cfg) {
    memset(sim, 0, sizeof *sim);
    sim->cfg = *cfg;
    memset(cfg, 0, sizeof *cfg);
    SimConfig *c = &sim->cfg;
    int status = check_memory(sim);
    if (status == NSPD_OK && c->check_only && !sim_check_builds(sim)) {
        status = check_unbuilt(sim);
        if (status != NSPD_OK) sim_destroy(sim);
        return status;
    }
    sim->built = true;
    /* On several processes the flow is divided (a coupling that
     * distributes takes the whole grid's cells; coupling_create checks),
     * and so is a solid alone, or a solid that divides (both PD models)
     * coupled by a coupling that takes a divided solid (the ghost-cell
     * FSI, the penalty); any other coupled solid is advanced whole by
     * every rank alike.
     * A solid alone that does not divide is refused. */
    c->flow.comm = c->coupling.comm = &c->comm;
    c->flow.processes[0] = c->processes[0];
    c->flow.processes[1] = c->processes[1];
    const bool divided =
        c->flow.method == FLOW_METHOD_NONE ||
        (coupling_divides_solid(c->coupling.kind) && solid_config_divides(&c->solid));
    c->solid.comm = divided ? &c->comm : NULL;
    if (status == NSPD_OK && c->solid.kind != SOLID_NONE)
        /* a refusal found while the model is built, said at its section */
        status = nspd_error_at(solid_create(&sim->solid, &c->solid), c->solid.where);
    /* a flow's own means (its bodies' forces), as the coupling's below */
    c->flow.average_from = c->output.average_from - 1e-12 * c->end_time;
    c->flow.validate_only = c->coupling.validate_only = c->check_only;
    if (status == NSPD_OK && c->flow.method != FLOW_METHOD_NONE)
        status = nspd_error_at(flow_create(&sim->flow, &c->flow), c->flow.where);
    if (status == NSPD_OK && c->coupling.kind != COUPLING_NONE) {
        /* averages from output.average_from, to a round-off of the end time */
        c->coupling.average_from = c->output.average_from - 1e-12 * c->end_time;
        status = nspd_error_at(coupling_create(&sim->coupling, &c->coupling, sim->solid, sim->flow),
                               c->coupling.where);
    }
    if (status == NSPD_OK) status = nspd_alloc(&sim->report, 1, sizeof *sim->report);
    if (status == NSPD_OK) status = choose_pace(sim);
    if (status == NSPD_OK) {
        int max_samples = (int)(c->end_time / c->output.history_interval) + 4;
        status = probes_create(&sim->probes, &c->output,
                               sim->solid ? solid_points_const(sim->solid) : NULL, sim->flow,
                               max_samples);
    }
    if (status != NSPD_OK) sim_destroy(sim);
    return status;
}

void sim_destroy(Sim *sim) {
    probes_destroy(&sim->probes, sim->cfg.output.probe_count);
    coupling_destroy(&sim->coupling);
    solid_destroy(&sim->solid);
    flow_destroy(&sim->flow);
    for (int k = 0; k < 2; k++) pvd_free(&sim->pvd[k]);
    history_close(&sim->history);
    nspd_free(&sim->report);
    sim_config_free(&sim->cfg);
    memset(sim, 0, sizeof *sim);
}

/* True once the run has reached its end (to a fraction of a step), or the
 * flow its own (a steady state). */
static bool finished(const Sim *sim) {
    if (!sim->flow) return sim->step >= sim->steps;
    return sim->time >= sim->cfg.end_time * (1.0 - 1e-12) || flow_finished(sim->flow);
}

/* This step's dt: the flow's stable (or the given) step, the last one
 * shortened to land on the end time; without a flow, the fixed step. */
static double step_size(const Sim *sim) {
    if (!sim->flow) return sim->dt;
    const double dt = flow_pace(sim, flow_stable_dt(sim->flow));
    const double left = sim->cfg.end_time - sim->time;
    return dt > left ? left : dt;
}

/* One step of the whole case, each part timed apart. */
static int sim_step(Sim *sim) {
    double t0 = nspd_wall_time();
    if (sim->coupling) TRY(coupling_before_flow(sim->coupling, sim->solid, sim->flow));
    double t1 = nspd_wall_time();
    const double dt = step_size(sim); /* after the walls moved: they change the stable step */
    if (sim->flow) TRY(flow_step(sim->flow, dt));
    double t2 = nspd_wall_time();
    if (sim->coupling) TRY(coupling_after_flow(sim->coupling, sim->solid, sim->flow, dt));
    double t3 = nspd_wall_time();
    if (sim->solid) {
        if (sim->constrained)
            TRY(solid_advance_constrained(sim->solid, dt));
        else
            TRY(solid_advance(sim->solid, dt, sim->flow ? sim->solid_substep : dt));
        /* with a flow, the flow's clock, not a sum of n rounded sub-steps */
        if (sim->flow) solid_set_time(sim->solid, flow_time(sim->flow));
    }
    double t4 = nspd_wall_time();
    sim->dt = dt;
    sim->time = sim->flow ? flow_time(sim->flow) : solid_time(sim->solid);
    sim->part_s[SIM_PART_COUPLING] += (t1 - t0) + (t3 - t2);
    sim->part_s[SIM_PART_FLOW] += t2 - t1;
    sim->part_s[SIM_PART_SOLID] += t4 - t3;
    sim->step++;
    return NSPD_OK;
}

int sim_advance(Sim *sim, int64_t steps) {
    for (int64_t s = 0; s < steps && !finished(sim); s++) TRY(sim_step(sim));
    return NSPD_OK;
}

/* True once `time` has reached `next` (to a fraction of a step). */
static bool due(double time, double next, double dt) {
    return time >= next - 1e-6 * dt;
}

/* Whether this process's wall clock asks for a checkpoint. */
static bool wall_checkpoint_due(const Sim *sim) {
    const double every = sim->cfg.output.checkpoint_wall_interval;
    return every > 0 && nspd_wall_time() - sim->checkpoint_wall >= every;
}

/* A checkpoint is due by the simulated-time schedule or the wall clock
 * (sim->wall_checkpoint: agreed by the processes of the run). */
static bool checkpoint_due(Sim *sim) {
    const OutputConfig *out = &sim->cfg.output;
    bool due_now = sim->wall_checkpoint;
    if (out->checkpoint_interval > 0 && due(sim->time, sim->next_checkpoint, sim->dt)) {
        due_now = true;
        while (due(sim->time, sim->next_checkpoint, sim->dt))
            sim->next_checkpoint += out->checkpoint_interval;
    }
    return due_now;
}

/* Whether `name` is a VTK file of output `from` or later of `series`:
 * <series>_NNNNN.vtr, .pvtr, _pPPPP.vtr, ... (not a picture or table). */
static bool later_vtk(const char *name, const char *series, int from) {
    const size_t len = strlen(series);
    if (strncmp(name, series, len) != 0 || name[len] != '_') return false;
    int index = 0, digits = 0;
    const char *p = name + len + 1;
    for (; *p >= '0' && *p <= '9'; p++, digits++) index = index * 10 + (*p - '0');
    const char *ext = strrchr(p, '.');
    return digits == 5 && index >= from && ext &&
           (strcmp(ext, ".vtr") == 0 || strcmp(ext, ".vtu") == 0 || strcmp(ext, ".pvtr") == 0 ||
            strcmp(ext, ".pvtu") == 0);
}

/* The VTK files of the outputs the resumed run writes again, which a run
 * stopped after its checkpoint left: gone first, so that no piece of
 * another process count is left beside the new files. */
static int remove_later_vtk(const char *dir, const char *series, int from) {
    DIR *d = opendir(dir);
    if (!d) return NSPD_FAIL(NSPD_ERR_IO, "cannot read directory '%s'", dir);
    struct dirent *e;
    char path[8192];
    while ((e = readdir(d)))
        if (later_vtk(e->d_name, series, from)) {
            snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
            remove(path);
        }
    closedir(d);
    return NSPD_OK;
}

/* A resumed run continues its files from where the checkpoint left them:
 * history.csv cut back to its length then, the .pvd series listing only
 * the files up to it, the VTK files after it removed. */
static int resume_outputs(Sim *sim) {
    if (!sim->dir) return NSPD_OK;
    TRY(history_resume(&sim->history, sim->dir, sim->history_bytes));
    static const char *const SERIES[2] = {"solid", "flow"};
    for (int k = 0; k < 2; k++) TRY(remove_later_vtk(sim->dir, SERIES[k], sim->field_index));
    for (int k = 0; k < 2; k++) {
        if (sim->pvd[k].count == 0) continue;
        char path[4200];
        snprintf(path, sizeof path, "%s/%s.pvd", sim->dir, SERIES[k]);
        TRY(pvd_write(&sim->pvd[k], path));
    }
    return NSPD_OK;
}

/* A new run writes its initial state. */
static int initial_outputs(Sim *sim) {
    const OutputConfig *out = &sim->cfg.output;
    sim->next_history = out->history_interval;
    sim->next_field = out->field_interval;
    sim->next_checkpoint = out->checkpoint_interval;
    TRY(sim_output_history(sim));
    return sim_output_fields(sim);
}

/* One step's outputs: those due, a checkpoint if due (or asked for by a
 * signal), then, when stopping on a signal, the rest of the outputs of this
 * state (after the checkpoint, which resumes as if they were never
 * written). */
static int step_outputs(Sim *sim, bool last) {
    const OutputConfig *out = &sim->cfg.output;
    const double t = sim->time;
    const bool history = due(t, sim->next_history, sim->dt) || last;
    const bool fields = due(t, sim->next_field, sim->dt) || last;
    if (history) {
        TRY(sim_output_history(sim));
        while (due(t, sim->next_history, sim->dt)) sim->next_history += out->history_interval;
    }
    if (fields) {
        TRY(sim_output_fields(sim));
        while (due(t, sim->next_field, sim->dt)) sim->next_field += out->field_interval;
    }
    if (!last && (checkpoint_due(sim) || sim->interrupted)) TRY(sim_checkpoint_write(sim));
    if (sim->interrupted && !history) TRY(sim_output_history(sim));
    if (sim->interrupted && !fields) TRY(sim_output_fields(sim));
    return NSPD_OK;
}

int sim_run(Sim *sim, const SimRunOptions *opt) {
    /* on several processes every rank runs this loop; what one decides
     * (a failure, a signal, a wall-clock checkpoint) all do, agreed once a
     * step after the step and once after its outputs (comm_agree; nothing
     * on one process), so none waits on a partner that stopped */
    const NspdComm *comm = &sim->cfg.comm;
    sim->dir = opt->dir;
    sim->piece_dir = opt->piece_dir;
    /* a resumed run's wall time continues the time already spent */
    sim->wall_start = nspd_wall_time() - sim->wall_s;
    sim->checkpoint_wall = nspd_wall_time();
    int status = NSPD_OK;
    if (sim->resumed) {
        TRY(comm_agree(comm, resume_outputs(sim), NULL, 0));
    } else {
        TRY(comm_agree(comm, sim_output_open(sim), NULL, 0));
        /* a failure from here on still ends with summary.json saying why */
        status = comm_agree(comm, initial_outputs(sim), NULL, 0);
    }

    Progress progress;
    double end = sim->flow ? sim->cfg.end_time : (double)sim->steps * sim->dt;
    double start = sim->flow ? sim->time : (double)sim->step * sim->dt;
    progress_start(&progress, stderr, start, end, opt->progress);
    while (status == NSPD_OK && !finished(sim)) {
        status = sim_step(sim);
        if (status == NSPD_ERR_NUMERIC) { /* a blow-up: say which step it was */
            char what[1024];
            snprintf(what, sizeof what, "%s", nspd_error_message());
            status =
                NSPD_FAIL(NSPD_ERR_NUMERIC,
                          "%s (in step %lld, from t = %g s; the outputs written before are kept)",
                          what, (long long)sim->step + 1, sim->time);
        }
        const bool last = status == NSPD_OK && finished(sim);
        int64_t asks[2] = {interrupt_requested() && !last, wall_checkpoint_due(sim)};
        const double t0 = nspd_wall_time();
        status = comm_agree(comm, status, asks, 2);
        sim->agree_s += nspd_wall_time() - t0;
        if (status != NSPD_OK) break;
        sim->interrupted = asks[0] != 0;
        sim->wall_checkpoint = asks[1] != 0;
        status = comm_agree(comm, step_outputs(sim, last), NULL, 0);
        if (status != NSPD_OK) break;
        progress_update(&progress, sim->step, sim->time);
        if (sim->interrupted) {
            nspd_log(LOG_WARN,
                     "stopped by %s at step %lld (t = %g s): checkpoint and outputs written; "
                     "continue with the same command and --resume",
                     interrupt_reason(), (long long)sim->step, sim->time);
            break;
        }
    }
    progress_finish(&progress, sim->step, sim->time);
    sim->wall_s = nspd_wall_time() - sim->wall_start;
    /* the failure that stopped the run, kept across the summary's writing
     * (which records it as the reason the run is incomplete) */
    char reason[1024];
    snprintf(reason, sizeof reason, "%s", status != NSPD_OK ? nspd_error_message() : "");
    int summary = sim_output_summary(sim, status, reason);
    sim_output_close(sim);
    if (summary == NSPD_OK) summary = sim_output_plots(sim);
    summary = comm_agree(comm, summary, NULL, 0);
    if (status != NSPD_OK) {
        /* writing the summary may have recorded another message: the run's is the one to show */
        if (strcmp(nspd_error_message(), reason) != 0)
            return nspd_error(status, __FILE__, __LINE__, "%s", reason);
        return status;
    }
    TRY(summary);
    return sim->interrupted ? NSPD_FAIL(NSPD_ERR_INTERRUPTED, "interrupted by the user") : NSPD_OK;
}
