#include "sim/sim.h"

#include "core/interrupt.h"
#include "core/log.h"
#include "core/mem.h"
#include "core/progress.h"
#include "core/status.h"
#include "core/timer.h"
#include "sim/sim_output.h"
#include "solid/pd_integrate.h"

#include <math.h>
#include <string.h>

int sim_create(Sim *sim, SimConfig *cfg) {
    memset(sim, 0, sizeof *sim);
    sim->cfg = *cfg;
    memset(cfg, 0, sizeof *cfg);
    /* the body takes its own copy of the solid configuration */
    PdConfig solid_cfg = sim->cfg.solid;
    memset(&sim->cfg.solid, 0, sizeof sim->cfg.solid);
    sim->cfg.has_solid = false;
    int status = pd_body_create(&sim->solid, &solid_cfg);
    if (status != NSPD_OK) {
        pd_config_free(&solid_cfg);
        sim_destroy(sim);
        return status;
    }
    sim->stable_dt = pd_stable_time_step(&sim->solid);
    if (sim->cfg.dt_given) {
        sim->dt = sim->cfg.dt;
        if (sim->dt > sim->stable_dt)
            nspd_log(LOG_WARN,
                     "time.dt = %g s exceeds the stable PD time step %g s; the run may blow up",
                     sim->dt, sim->stable_dt);
    } else {
        sim->dt = sim->cfg.safety_factor * sim->stable_dt;
    }
    sim->steps = (int64_t)ceil(sim->cfg.end_time / sim->dt - 1e-9);
    if (sim->steps < 1) sim->steps = 1;
    status = nspd_alloc(&sim->damage, (size_t)sim->solid.n, sizeof(double));
    for (int d = 0; d < sim->solid.dim && status == NSPD_OK; d++)
        status = nspd_alloc(&sim->position[d], (size_t)sim->solid.n, sizeof(double));
    if (status == NSPD_OK) {
        int max_samples = (int)(sim->cfg.end_time / sim->cfg.output.history_interval) + 4;
        status = probes_create(&sim->probes, &sim->cfg.output, &sim->solid, max_samples);
    }
    if (status != NSPD_OK) sim_destroy(sim);
    return status;
}

void sim_destroy(Sim *sim) {
    probes_destroy(&sim->probes, sim->cfg.output.probe_count);
    pd_body_destroy(&sim->solid);
    nspd_free(&sim->damage);
    for (int d = 0; d < 3; d++) nspd_free(&sim->position[d]);
    pvd_free(&sim->pvd);
    if (sim->history) fclose(sim->history);
    sim_config_free(&sim->cfg);
    memset(sim, 0, sizeof *sim);
}

int sim_advance(Sim *sim, int64_t steps) {
    for (int64_t s = 0; s < steps; s++) TRY(pd_step(&sim->solid, sim->dt));
    return NSPD_OK;
}

/* True once `time` has reached `next` (to a fraction of a step). */
static bool due(double time, double next, double dt) {
    return time >= next - 1e-6 * dt;
}

int sim_run(Sim *sim, const SimRunOptions *opt) {
    sim->dir = opt->dir;
    const OutputConfig *out = &sim->cfg.output;
    double t0 = nspd_wall_time();
    TRY(sim_output_open(sim));
    TRY(sim_output_history(sim));
    TRY(sim_output_fields(sim));
    sim->next_history = out->history_interval;
    sim->next_field = out->field_interval;

    Progress progress;
    progress_start(&progress, stderr, sim->steps * sim->dt, opt->progress);
    int status = NSPD_OK;
    for (int64_t s = 0; s < sim->steps; s++) {
        status = pd_step(&sim->solid, sim->dt);
        if (status != NSPD_OK) break;
        const double t = sim->solid.time;
        const bool last = s + 1 == sim->steps;
        sim->interrupted = interrupt_requested() && !last;
        if (due(t, sim->next_history, sim->dt) || last || sim->interrupted) {
            status = sim_output_history(sim);
            while (due(t, sim->next_history, sim->dt)) sim->next_history += out->history_interval;
        }
        if (status == NSPD_OK && (due(t, sim->next_field, sim->dt) || last || sim->interrupted)) {
            status = sim_output_fields(sim);
            while (due(t, sim->next_field, sim->dt)) sim->next_field += out->field_interval;
        }
        if (status != NSPD_OK) break;
        progress_update(&progress, sim->solid.step, t);
        if (sim->interrupted) {
            nspd_log(LOG_WARN, "interrupted at step %lld (t = %g s): outputs written",
                     (long long)sim->solid.step, t);
            break;
        }
    }
    progress_finish(&progress, sim->solid.step, sim->solid.time);
    sim->wall_s = nspd_wall_time() - t0;
    int summary = sim_output_summary(sim, status);
    sim_output_close(sim);
    if (status != NSPD_OK) return status;
    TRY(summary);
    return sim->interrupted ? NSPD_FAIL(NSPD_ERR_INTERRUPTED, "interrupted by the user") : NSPD_OK;
}
