#include "sim/sim_output.h"

#include "core/mem.h"
#include "core/status.h"
#include "io/json.h"
#include "io/render.h"
#include "io/vtk.h"
#include "solid/pd_diagnostics.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>

static void path_in(const Sim *sim, char *buf, size_t size, const char *name) {
    snprintf(buf, size, "%s/%s", sim->dir, name);
}

int sim_output_open(Sim *sim) {
    if (!sim->dir) return NSPD_OK;
    char path[4096];
    path_in(sim, path, sizeof path, "history.csv");
    sim->history = fopen(path, "w");
    if (!sim->history) return NSPD_FAIL(NSPD_ERR_IO, "cannot create '%s'", path);
    fprintf(sim->history,
            "step,time_s,kinetic_energy_J,elastic_energy_J,total_energy_J,broken_bonds");
    probes_write_header(sim->probes, sim->cfg.output.probe_count, sim->solid.dim, sim->history);
    fputc('\n', sim->history);
    return NSPD_OK;
}

int sim_output_history(Sim *sim) {
    const PdBody *b = &sim->solid;
    const bool need_damage = probes_need_damage(&sim->cfg.output);
    if (need_damage) pd_damage(b, sim->damage);
    if (!sim->history) { /* no directory: keep the probes' own records going */
        probes_sample(sim->probes, sim->cfg.output.probe_count, b, sim->damage, NULL);
        return NSPD_OK;
    }
    double ke = pd_kinetic_energy(b), we = pd_elastic_energy(b);
    fprintf(sim->history, "%lld,%.9g,%.9g,%.9g,%.9g,%lld", (long long)b->step, b->time, ke, we,
            ke + we, (long long)pd_broken_bonds(b));
    probes_sample(sim->probes, sim->cfg.output.probe_count, b, need_damage ? sim->damage : NULL,
                  sim->history);
    fputc('\n', sim->history);
    if (fflush(sim->history) != 0) return NSPD_FAIL(NSPD_ERR_IO, "cannot write history.csv");
    return NSPD_OK;
}

int sim_output_fields(Sim *sim) {
    if (!sim->dir) return NSPD_OK;
    const PdBody *b = &sim->solid;
    const OutputConfig *out = &sim->cfg.output;
    pd_damage(b, sim->damage);
    char name[256], path[4096];
    /* current positions x + u, so cracks show as openings */
    double *const *pos = sim->position;
    for (int d = 0; d < b->dim; d++)
        for (int64_t i = 0; i < b->n; i++) pos[d][i] = b->x[d][i] + b->u[d][i];
    int status = NSPD_OK;
    if (out->vtk) {
        snprintf(name, sizeof name, "solid_%05d.vtu", sim->field_index);
        path_in(sim, path, sizeof path, name);
        VtkField fields[] = {
            {"displacement", 3, {b->u[0], b->u[1], b->dim == 3 ? b->u[2] : NULL}},
            {"velocity", 3, {b->v[0], b->v[1], b->dim == 3 ? b->v[2] : NULL}},
            {"damage", 1, {sim->damage, NULL, NULL}},
            {"volume", 1, {b->volume, NULL, NULL}},
        };
        status = vtk_write_points(path, b->n, (const double *const *)pos, fields, 4);
        if (status == NSPD_OK) {
            char pvd[4096];
            path_in(sim, pvd, sizeof pvd, "solid.pvd");
            status = pvd_add(&sim->pvd, pvd, b->time, name);
        }
    }
    if (status == NSPD_OK && out->png) {
        snprintf(name, sizeof name, "damage_%05d.png", sim->field_index);
        path_in(sim, path, sizeof path, name);
        RenderOptions ro = {0.0, 1.0, COLORMAP_VIRIDIS, out->png_max_pixels};
        status =
            render_points_png(path, b->n, (const double *const *)pos, sim->damage, b->spacing, &ro);
    }
    if (status == NSPD_OK)
        status = probes_write_lines(sim->probes, out->probe_count, b, sim->damage, sim->dir,
                                    sim->field_index);
    sim->field_index++;
    return status;
}

int sim_output_summary(Sim *sim, int run_status) {
    if (!sim->dir) return NSPD_OK;
    const PdBody *b = &sim->solid;
    char path[4096];
    path_in(sim, path, sizeof path, "summary.json");
    FILE *f = fopen(path, "w");
    if (!f) return NSPD_FAIL(NSPD_ERR_IO, "cannot create '%s'", path);
    pd_damage(b, sim->damage);
    double max_damage = 0;
    for (int64_t i = 0; i < b->n; i++) max_damage = fmax(max_damage, sim->damage[i]);
    JsonWriter w;
    json_begin(&w, f);
    json_string(&w, "case", sim->cfg.name);
    json_number(&w, "time_s", b->time);
    json_int(&w, "steps", b->step);
    json_number(&w, "wall_s", sim->wall_s);
    json_int(&w, "threads", omp_get_max_threads());
    json_bool(&w, "completed", run_status == NSPD_OK && !sim->interrupted);
    json_bool(&w, "interrupted", sim->interrupted);
    json_number(&w, "dt_s", sim->dt);
    json_number(&w, "stable_dt_s", sim->stable_dt);
    json_int(&w, "points", b->n);
    json_int(&w, "bonds", b->bond_count / 2);
    json_int(&w, "broken_bonds", pd_broken_bonds(b));
    json_number(&w, "max_damage", max_damage);
    json_number(&w, "kinetic_energy_J", pd_kinetic_energy(b));
    json_number(&w, "elastic_energy_J", pd_elastic_energy(b));
    json_number(&w, "bond_updates_per_s",
                sim->wall_s > 0 ? (double)b->bond_count * (double)b->step / sim->wall_s : 0.0);
    json_number(&w, "peak_rss_mb", nspd_peak_rss_mb());
    for (int k = 0; k < sim->cfg.output.probe_count; k++) {
        const ProbeState *p = &sim->probes[k];
        if (p->cfg->kind != PROBE_CRACK_TIP) continue;
        char key[128];
        static const char *const axis[] = {"x", "y", "z"};
        for (int d = 0; d < b->dim; d++) {
            snprintf(key, sizeof key, "%s_tip_%s_m", p->cfg->name, axis[d]);
            json_number(&w, key, p->last_tip[d]);
        }
        snprintf(key, sizeof key, "%s_speed_m_per_s", p->cfg->name);
        json_number(&w, key, probe_crack_speed(p));
    }
    json_end(&w);
    if (fclose(f) != 0) return NSPD_FAIL(NSPD_ERR_IO, "cannot write '%s'", path);
    return NSPD_OK;
}

void sim_output_close(Sim *sim) {
    if (sim->history) fclose(sim->history);
    sim->history = NULL;
}
