/* The generic writer: it asks each part of the case (solid, flow, coupling,
 * probes) for its history columns, summary keys and fields, and hands them
 * to io/run_files.h. It knows no model.
 *
 * On several processes every rank asks (a model's answers are collective:
 * it gathers its fields and reduces its sums), and the rank that has the
 * directory (rank 0) writes. */
#include "sim/sim_output.h"

#include "core/mem.h"
#include "core/status.h"
#include "io/history_plot.h"

#include <math.h>
#include <omp.h>
#include <string.h>

int sim_output_open(Sim *sim) {
    if (!sim->dir) return NSPD_OK;
    return history_open(&sim->history, sim->dir);
}

/* The damage field when a probe or output needs it (NULL without a solid). */
static const double *damage_if(Sim *sim, bool needed) {
    return sim->solid && needed ? solid_damage(sim->solid) : NULL;
}

int sim_output_history(Sim *sim) {
    if (sim->solid) TRY(solid_sync(sim->solid));
    const bool need_damage = probes_need_damage(&sim->cfg.output);
    const double *damage = damage_if(sim, need_damage);
    Report *row = sim->report;
    report_clear(row);
    report_int(row, "step", sim->step);
    report_real(row, "time_s", sim->time);
    if (sim->solid) solid_history(sim->solid, row);
    if (sim->flow) flow_history(sim->flow, row);
    if (sim->coupling) TRY(coupling_history(sim->coupling, sim->solid, sim->flow, sim->time, row));
    /* without a directory the probes still keep their own records */
    probes_sample(sim->probes, sim->cfg.output.probe_count,
                  sim->solid ? solid_points_const(sim->solid) : NULL, damage, sim->flow, sim->time,
                  row);
    if (!sim->dir) return NSPD_OK;
    return history_write(&sim->history, row);
}

/* Whether this process takes part in the outputs: it writes them, or the
 * run is shared and the writer needs its part. */
static bool takes_part(const Sim *sim) {
    return sim->dir || comm_distributed(&sim->cfg.comm);
}

/* One field set's files: this process's piece (every process of a set in
 * pieces) and, on the writer, the rest. */
static int write_set(Sim *sim, const FieldSet *set, const FieldSet *overlay,
                     const FieldOutputOptions *opt, PvdSeries *pvd) {
    if (sim->piece_dir) TRY(field_set_write_piece(sim->piece_dir, sim->field_index, set, opt));
    if (!sim->dir) return NSPD_OK;
    return field_set_write(sim->dir, sim->field_index, sim->time, set, overlay, opt, pvd);
}

/* Every rank makes every call, a failed write or not: the models' fields
 * are collective (gathers), so a rank that stopped at its failure would
 * leave the others waiting. The first failure is returned (and agreed by
 * the caller). */
int sim_output_fields(Sim *sim) {
    if (!takes_part(sim)) return NSPD_OK;
    if (sim->solid) TRY(solid_sync(sim->solid));
    const OutputConfig *out = &sim->cfg.output;
    const FieldOutputOptions opt = {out->vtk, out->png, out->png_max_pixels, sim->cfg.name};
    FieldSet solid_set, flow_set, coupling_set;
    const FieldSet *overlay = NULL;
    /* one damage field for the solid's files and the line probes */
    const double *damage = damage_if(sim, true);
    int status = NSPD_OK;
    if (sim->solid) {
        solid_fields(sim->solid, damage, &solid_set);
        status = write_set(sim, &solid_set, NULL, &opt, &sim->pvd[0]);
        overlay = &solid_set;
    }
    if (sim->flow) {
        flow_fields(sim->flow, &flow_set);
        if (out->mach_range_given) /* output.mach_range: the flow's own scale replaced */
            for (int k = 0; k < flow_set.picture_count; k++)
                if (strcmp(flow_set.picture[k].file, "mach") == 0) {
                    flow_set.picture[k].lo = out->mach_range[0];
                    flow_set.picture[k].hi = out->mach_range[1];
                }
        /* the solid drawn over the flow where the two are coupled */
        if (status == NSPD_OK)
            status = write_set(sim, &flow_set, sim->coupling ? overlay : NULL, &opt, &sim->pvd[1]);
    }
    if (sim->coupling) {
        const int got = coupling_fields(sim->coupling, sim->solid, sim->flow, &coupling_set);
        if (status == NSPD_OK) status = got;
        if (status == NSPD_OK) status = write_set(sim, &coupling_set, NULL, &opt, NULL);
    }
    for (int k = 0; k < sim->cfg.output.probe_count; k++) {
        const TableRef *t = probe_line_table(
            &sim->probes[k], sim->solid ? solid_points_const(sim->solid) : NULL, damage, sim->flow);
        if (t && sim->dir && status == NSPD_OK)
            status = table_write(sim->dir, sim->field_index, sim->time, t);
    }
    sim->field_index++;
    return status;
}

int sim_output_summary(Sim *sim, int run_status, const char *reason) {
    if (!takes_part(sim)) return NSPD_OK;
    static const char *const PART_KEYS[SIM_PART_COUNT] = {"flow_s", "solid_s", "coupling_s"};
    const bool part_present[SIM_PART_COUNT] = {sim->flow != NULL, sim->solid != NULL,
                                               sim->coupling != NULL};
    const RunStats run = {sim->step, sim->wall_s};
    if (sim->solid) TRY(solid_sync(sim->solid));
    Report *r = sim->report;
    report_clear(r);
    report_text(r, "case", sim->cfg.name);
    report_real(r, "time_s", sim->time);
    report_int(r, "steps", sim->step);
    report_real(r, "wall_s", sim->wall_s);
    for (int k = 0; k < SIM_PART_COUNT; k++)
        if (part_present[k]) report_real(r, PART_KEYS[k], sim->part_s[k]);
    report_int(r, "threads", omp_get_max_threads());
    if (comm_distributed(&sim->cfg.comm)) {
        report_int(r, "processes", sim->cfg.comm.size);
        report_real(r, "agree_s", sim->agree_s);
    }
    report_bool(r, "completed", run_status == NSPD_OK && !sim->interrupted);
    report_bool(r, "interrupted", sim->interrupted);
    if (run_status != NSPD_OK && run_status != NSPD_ERR_INTERRUPTED)
        report_text(r, "stopped_by", reason);
    if (sim->solid) {
        report_real(r, "dt_s", sim->dt);
        report_real(r, "stable_dt_s", sim->stable_dt);
        solid_summary(sim->solid, &run, r);
    }
    if (sim->flow) flow_summary(sim->flow, &run, r);
    int status = NSPD_OK;
    if (sim->coupling) status = coupling_summary(sim->coupling, sim->solid, sim->flow, r);
    report_real(r, "peak_rss_mb", nspd_peak_rss_mb());
    if (status == NSPD_OK)
        status = probes_summary(sim->probes, sim->cfg.output.probe_count,
                                sim->solid ? solid_points_const(sim->solid) : NULL,
                                damage_if(sim, true), r);
    if (status == NSPD_OK && sim->dir) status = summary_write(sim->dir, r);
    return status;
}

void sim_output_close(Sim *sim) {
    history_close(&sim->history);
}

int sim_output_plots(Sim *sim) {
    if (!sim->dir || !sim->cfg.output.plots) return NSPD_OK;
    int written;
    return history_plots(sim->dir, sim->cfg.name, NULL, 0, false, &written);
}
