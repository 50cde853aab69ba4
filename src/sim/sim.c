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

static int create_solid(Sim *sim) {
    /* the body takes its own copy of the solid configuration */
    PdConfig solid_cfg = sim->cfg.solid;
    memset(&sim->cfg.solid, 0, sizeof sim->cfg.solid);
    sim->cfg.has_solid = false;
    int status = pd_body_create(&sim->solid, &solid_cfg);
    if (status != NSPD_OK) {
        pd_config_free(&solid_cfg);
        return status;
    }
    sim->has_solid = true;
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
    TRY(nspd_alloc(&sim->damage, (size_t)sim->solid.n, sizeof(double)));
    for (int d = 0; d < sim->solid.dim; d++)
        TRY(nspd_alloc(&sim->position[d], (size_t)sim->solid.n, sizeof(double)));
    return NSPD_OK;
}

static int create_flow(Sim *sim) {
    FlowCaseConfig *fc = &sim->cfg.flow;
    FlowConfig *c = &fc->solver;
    if (fc->has_vortex) { /* the hook needs the vortex at its final address */
        FlowVortex *vx = &fc->vortex;
        if (c->bc[FLOW_FACE_XLO].seg[0].kind == BC_PERIODIC) {
            GridSegment *s = c->segments[0];
            vx->lo_x = c->x0;
            vx->period_x = 0;
            for (int k = 0; k < c->segment_count[0]; k++) vx->period_x += s[k].length;
        }
        if (c->bc[FLOW_FACE_YLO].seg[0].kind == BC_PERIODIC) {
            GridSegment *s = c->segments[1];
            vx->lo_y = c->y0;
            vx->period_y = 0;
            for (int k = 0; k < c->segment_count[1]; k++) vx->period_y += s[k].length;
        }
        c->init_fn = flow_isentropic_vortex;
        c->init_ctx = vx;
    }
    if (fc->has_field) {
        c->init_fn = flow_field_sample;
        c->init_ctx = &fc->field;
    }
    TRY(flow_solver_create(&sim->flow, c));
    sim->has_flow = true;
    const Grid *g = flow_solver_grid(sim->flow);
    for (int k = 0; k < 6; k++)
        TRY(nspd_alloc(&sim->cells[k], (size_t)g->nx * (size_t)g->ny, sizeof(double)));
    sim->stable_dt = flow_solver_stable_dt(sim->flow);
    if (sim->cfg.dt_given) {
        sim->dt = sim->cfg.dt;
        if (sim->dt > sim->stable_dt)
            nspd_log(LOG_WARN, "time.dt = %g s exceeds the CFL time step %g s", sim->dt,
                     sim->stable_dt);
    } else {
        sim->dt = sim->stable_dt;
    }
    sim->steps = (int64_t)ceil(sim->cfg.end_time / sim->dt - 1e-9);
    return NSPD_OK;
}

/* Fixed immersed bodies of a flow case. */
static int create_bodies(Sim *sim) {
    const IbmBodySet *set = &sim->cfg.flow.bodies;
    if (set->count == 0) return NSPD_OK;
    TRY(nspd_alloc(&sim->bodies, (size_t)set->count, sizeof(IbmPolyline)));
    sim->body_count = set->count;
    for (int b = 0; b < set->count; b++) TRY(ibm_body_markers(&set->bodies[b], &sim->bodies[b]));
    TRY(ibm_create(&sim->ibm, flow_solver_grid(sim->flow), sim->bodies, sim->body_count));
    ibm_set_ghost_faces(sim->ibm, (IbmGhostFaces)sim->cfg.flow.ghost_faces);
    TRY(ibm_attach(sim->ibm, sim->flow));
    if (sim->cfg.flow.soft_start > 0) ibm_soft_start(sim->ibm, sim->flow, sim->cfg.flow.soft_start);
    TRY(ibm_surface_reserve(sim->ibm, &sim->surface));
    TRY(nspd_alloc(&sim->coef_sum, (size_t)sim->body_count * 6, sizeof(double)));
    sim->stable_dt = flow_solver_stable_dt(sim->flow);
    return NSPD_OK;
}

/* The coupling: the solid's surface becomes the flow's immersed boundary.
 * The solid sub-steps; its stable step was computed by create_solid. */
static int create_coupling(Sim *sim) {
    TRY(fsi_create(&sim->fsi, &sim->cfg.coupling, &sim->solid, sim->flow));
    sim->has_fsi = true;
    sim->body_count = sim->fsi.loop_count;
    TRY(nspd_alloc(&sim->coef_sum, (size_t)sim->body_count * 6, sizeof(double)));
    return NSPD_OK;
}

int sim_create(Sim *sim, SimConfig *cfg) {
    memset(sim, 0, sizeof *sim);
    sim->cfg = *cfg;
    memset(cfg, 0, sizeof *cfg);
    int status = NSPD_OK;
    if (sim->cfg.has_solid) status = create_solid(sim);
    double pd_dt = sim->dt, pd_stable = sim->stable_dt;
    if (status == NSPD_OK && sim->cfg.has_flow) status = create_flow(sim);
    if (status == NSPD_OK && sim->has_flow) status = create_bodies(sim);
    if (status == NSPD_OK && sim->cfg.has_coupling) {
        status = create_coupling(sim);
        /* the flow sets the pace; the solid sub-steps within each flow step */
        sim->solid_substep = sim->cfg.dt_given ? pd_dt : sim->cfg.safety_factor * pd_stable;
        sim->solid_stable_dt = pd_stable;
        sim->steps = (int64_t)ceil(sim->cfg.end_time / flow_solver_stable_dt(sim->flow) - 1e-9);
    }
    if (status == NSPD_OK) {
        int max_samples = (int)(sim->cfg.end_time / sim->cfg.output.history_interval) + 4;
        status = probes_create(&sim->probes, &sim->cfg.output, sim->has_solid ? &sim->solid : NULL,
                               sim->flow, max_samples);
    }
    if (status != NSPD_OK) sim_destroy(sim);
    return status;
}

void sim_destroy(Sim *sim) {
    probes_destroy(&sim->probes, sim->cfg.output.probe_count);
    if (sim->has_fsi) fsi_destroy(&sim->fsi);
    ibm_destroy(&sim->ibm);
    ibm_surface_free(&sim->surface);
    for (int b = 0; b < sim->body_count && sim->bodies; b++) ibm_polyline_free(&sim->bodies[b]);
    nspd_free(&sim->bodies);
    nspd_free(&sim->coef_sum);
    if (sim->has_solid) pd_body_destroy(&sim->solid);
    flow_solver_destroy(&sim->flow);
    nspd_free(&sim->damage);
    for (int d = 0; d < 3; d++) nspd_free(&sim->position[d]);
    for (int k = 0; k < 6; k++) nspd_free(&sim->cells[k]);
    pvd_free(&sim->pvd_solid);
    pvd_free(&sim->pvd_flow);
    if (sim->history) fclose(sim->history);
    sim_config_free(&sim->cfg);
    memset(sim, 0, sizeof *sim);
}

/* True once the run has reached its end (to a fraction of a step). */
static bool finished(const Sim *sim) {
    if (sim->has_solid && !sim->has_flow) return sim->step >= sim->steps;
    return sim->time >= sim->cfg.end_time * (1.0 - 1e-12);
}

/* One coupled step: interface, flow, loads, solid sub-steps (timed apart). */
static int coupled_step(Sim *sim) {
    double t0 = nspd_wall_time();
    TRY(fsi_move_interface(&sim->fsi, &sim->solid, sim->flow));
    double dt = sim->cfg.dt_given ? sim->cfg.dt : flow_solver_stable_dt(sim->flow);
    double left = sim->cfg.end_time - sim->time;
    if (dt > left) dt = left;
    double t1 = nspd_wall_time();
    TRY(flow_solver_step(sim->flow, dt));
    sim->dt = dt;
    sim->time = flow_solver_time(sim->flow);
    double t2 = nspd_wall_time();
    TRY(fsi_apply_loads(&sim->fsi, &sim->solid, sim->flow));
    double t3 = nspd_wall_time();
    TRY(fsi_advance_solid(&sim->fsi, &sim->solid, dt, sim->solid_substep, sim->time));
    double t4 = nspd_wall_time();
    sim->part_s[SIM_PART_COUPLING] += (t1 - t0) + (t3 - t2);
    sim->part_s[SIM_PART_FLOW] += t2 - t1;
    sim->part_s[SIM_PART_SOLID] += t4 - t3;
    return NSPD_OK;
}

/* One step of the whole case. */
static int sim_step(Sim *sim) {
    if (sim->has_fsi) {
        TRY(coupled_step(sim));
    } else if (sim->has_solid) {
        double t0 = nspd_wall_time();
        TRY(pd_step(&sim->solid, sim->dt));
        sim->part_s[SIM_PART_SOLID] += nspd_wall_time() - t0;
        sim->time = sim->solid.time;
    } else {
        double t0 = nspd_wall_time();
        double dt = sim->cfg.dt_given ? sim->cfg.dt : flow_solver_stable_dt(sim->flow);
        double left = sim->cfg.end_time - sim->time;
        if (dt > left) dt = left; /* land on the end time */
        TRY(flow_solver_step(sim->flow, dt));
        sim->part_s[SIM_PART_FLOW] += nspd_wall_time() - t0;
        sim->dt = dt;
        sim->time = flow_solver_time(sim->flow);
    }
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
    double end = sim->has_solid ? (double)sim->steps * sim->dt : sim->cfg.end_time;
    progress_start(&progress, stderr, end, opt->progress);
    int status = NSPD_OK;
    while (!finished(sim)) {
        status = sim_step(sim);
        if (status != NSPD_OK) break;
        const double t = sim->time;
        const bool last = finished(sim);
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
        progress_update(&progress, sim->step, t);
        if (sim->interrupted) {
            nspd_log(LOG_WARN, "interrupted at step %lld (t = %g s): outputs written",
                     (long long)sim->step, t);
            break;
        }
    }
    progress_finish(&progress, sim->step, sim->time);
    sim->wall_s = nspd_wall_time() - t0;
    int summary = sim_output_summary(sim, status);
    sim_output_close(sim);
    if (status != NSPD_OK) return status;
    TRY(summary);
    return sim->interrupted ? NSPD_FAIL(NSPD_ERR_INTERRUPTED, "interrupted by the user") : NSPD_OK;
}
