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
    fprintf(sim->history, "step,time_s");
    if (sim->has_solid)
        fprintf(sim->history, ",kinetic_energy_J,elastic_energy_J,total_energy_J,broken_bonds");
    if (sim->has_flow)
        fprintf(sim->history, ",dt_s,mass_kg_per_m,momentum_x_kg_per_s,momentum_y_kg_per_s,"
                              "energy_J_per_m,fallbacks");
    probes_write_header(sim->probes, sim->cfg.output.probe_count,
                        sim->has_solid ? sim->solid.dim : 2, sim->history);
    fputc('\n', sim->history);
    return NSPD_OK;
}

int sim_output_history(Sim *sim) {
    const PdBody *b = sim->has_solid ? &sim->solid : NULL;
    const bool need_damage = b && probes_need_damage(&sim->cfg.output);
    if (need_damage) pd_damage(b, sim->damage);
    FILE *csv = sim->history;
    if (csv) {
        fprintf(csv, "%lld,%.9g", (long long)sim->step, sim->time);
        if (b) {
            double ke = pd_kinetic_energy(b), we = pd_elastic_energy(b);
            fprintf(csv, ",%.9g,%.9g,%.9g,%lld", ke, we, ke + we, (long long)pd_broken_bonds(b));
        }
        if (sim->has_flow) {
            double totals[4];
            flow_solver_totals(sim->flow, totals);
            fprintf(csv, ",%.9g,%.12g,%.12g,%.12g,%.12g,%lld", sim->step ? sim->dt : 0.0, totals[0],
                    totals[1], totals[2], totals[3],
                    (long long)flow_solver_fallbacks_last(sim->flow));
        }
    }
    /* without a directory the probes still keep their own records */
    probes_sample(sim->probes, sim->cfg.output.probe_count, b, need_damage ? sim->damage : NULL,
                  sim->flow, sim->time, csv);
    if (!csv) return NSPD_OK;
    fputc('\n', csv);
    if (fflush(csv) != 0) return NSPD_FAIL(NSPD_ERR_IO, "cannot write history.csv");
    return NSPD_OK;
}

static int solid_fields(Sim *sim) {
    const PdBody *b = &sim->solid;
    const OutputConfig *out = &sim->cfg.output;
    char name[256], path[4096];
    /* current positions x + u, so cracks show as openings */
    double *const *pos = sim->position;
    for (int d = 0; d < b->dim; d++)
        for (int64_t i = 0; i < b->n; i++) pos[d][i] = b->x[d][i] + b->u[d][i];
    if (out->vtk) {
        snprintf(name, sizeof name, "solid_%05d.vtu", sim->field_index);
        path_in(sim, path, sizeof path, name);
        VtkField fields[] = {
            {"displacement", 3, {b->u[0], b->u[1], b->dim == 3 ? b->u[2] : NULL}},
            {"velocity", 3, {b->v[0], b->v[1], b->dim == 3 ? b->v[2] : NULL}},
            {"damage", 1, {sim->damage, NULL, NULL}},
            {"volume", 1, {b->volume, NULL, NULL}},
        };
        TRY(vtk_write_points(path, b->n, (const double *const *)pos, fields, 4));
        char pvd[4096];
        path_in(sim, pvd, sizeof pvd, "solid.pvd");
        TRY(pvd_add(&sim->pvd_solid, pvd, sim->time, name));
    }
    if (out->png) {
        snprintf(name, sizeof name, "damage_%05d.png", sim->field_index);
        path_in(sim, path, sizeof path, name);
        RenderOptions ro = {0.0, 1.0, COLORMAP_VIRIDIS, out->png_max_pixels};
        TRY(render_points_png(path, b->n, (const double *const *)pos, sim->damage, b->spacing,
                              &ro));
    }
    return NSPD_OK;
}

/* Numerical schlieren (Quirk 1994): S = exp(-k |grad rho| / max |grad rho|),
 * k = 15, from central differences of the density on the stretched grid. */
static void schlieren(const Grid *g, const double *rho, const uint8_t *solid, double *out) {
    int nx = g->nx, ny = g->ny;
    double gmax = 0.0;
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            int il = i > 0 ? i - 1 : i, ir = i < nx - 1 ? i + 1 : i;
            int jl = j > 0 ? j - 1 : j, jr = j < ny - 1 ? j + 1 : j;
            double gx = ir > il ? (rho[(int64_t)j * nx + ir] - rho[(int64_t)j * nx + il]) /
                                      (g->ax[0].center[ir] - g->ax[0].center[il])
                                : 0.0;
            double gy = jr > jl ? (rho[(int64_t)jr * nx + i] - rho[(int64_t)jl * nx + i]) /
                                      (g->ax[1].center[jr] - g->ax[1].center[jl])
                                : 0.0;
            double m = solid[(int64_t)j * nx + i] ? 0.0 : sqrt(gx * gx + gy * gy);
            out[(int64_t)j * nx + i] = m;
            if (m > gmax) gmax = m;
        }
    for (int64_t c = 0; c < (int64_t)nx * ny; c++)
        out[c] = gmax > 0.0 ? exp(-15.0 * out[c] / gmax) : 1.0;
}

static int flow_fields(Sim *sim) {
    const OutputConfig *out = &sim->cfg.output;
    const Grid *g = flow_solver_grid(sim->flow);
    const int64_t ncell = (int64_t)g->nx * g->ny;
    static const FlowField order[6] = {FLOW_DENSITY,  FLOW_VELOCITY_X,  FLOW_VELOCITY_Y,
                                       FLOW_PRESSURE, FLOW_TEMPERATURE, FLOW_MACH};
    for (int k = 0; k < 6; k++) flow_solver_primitive(sim->flow, order[k], sim->cells[k]);
    /* cell kinds of the interior cells, as 0/1 "solid" and as a field */
    FlowFields f = flow_solver_fields(sim->flow);
    uint8_t *solid;
    double *kind;
    TRY(nspd_alloc(&solid, (size_t)ncell, 1));
    int status = nspd_alloc(&kind, (size_t)ncell, sizeof(double));
    for (int j = 0; j < g->ny && status == NSPD_OK; j++)
        for (int i = 0; i < g->nx; i++) {
            uint8_t k = f.kind[grid_index(g, i, j)];
            solid[(int64_t)j * g->nx + i] = k != FLOW_CELL_FLUID;
            kind[(int64_t)j * g->nx + i] = k;
        }
    char name[256], path[4096];
    if (status == NSPD_OK && out->vtk) {
        snprintf(name, sizeof name, "flow_%05d.vtr", sim->field_index);
        path_in(sim, path, sizeof path, name);
        double zf[2] = {0.0, 0.0};
        VtkField fields[] = {
            {"density", 1, {sim->cells[0], NULL, NULL}},
            {"velocity", 3, {sim->cells[1], sim->cells[2], NULL}},
            {"pressure", 1, {sim->cells[3], NULL, NULL}},
            {"temperature", 1, {sim->cells[4], NULL, NULL}},
            {"mach", 1, {sim->cells[5], NULL, NULL}},
            {"cell_kind", 1, {kind, NULL, NULL}},
        };
        status = vtk_write_rectilinear(path, g->nx, g->ny, 1, g->ax[0].face, g->ax[1].face, zf,
                                       fields, 6);
        if (status == NSPD_OK) {
            char pvd[4096];
            path_in(sim, pvd, sizeof pvd, "flow.pvd");
            status = pvd_add(&sim->pvd_flow, pvd, sim->time, name);
        }
    }
    if (status == NSPD_OK && out->png) {
        double mach_max = 0.0;
        for (int64_t c = 0; c < ncell; c++)
            if (!solid[c] && sim->cells[5][c] > mach_max) mach_max = sim->cells[5][c];
        snprintf(name, sizeof name, "mach_%05d.png", sim->field_index);
        path_in(sim, path, sizeof path, name);
        RenderOptions ro = {0.0, mach_max > 0 ? mach_max : 1.0, COLORMAP_VIRIDIS,
                            out->png_max_pixels};
        status = render_grid_png(path, g->nx, g->ny, g->ax[0].face, g->ax[1].face, sim->cells[5],
                                 solid, &ro);
    }
    if (status == NSPD_OK && out->png) {
        /* the temperature scratch is free again: reuse it for the schlieren */
        schlieren(g, sim->cells[0], solid, sim->cells[4]);
        snprintf(name, sizeof name, "schlieren_%05d.png", sim->field_index);
        path_in(sim, path, sizeof path, name);
        RenderOptions ro = {0.0, 1.0, COLORMAP_GRAY, out->png_max_pixels};
        status = render_grid_png(path, g->nx, g->ny, g->ax[0].face, g->ax[1].face, sim->cells[4],
                                 solid, &ro);
    }
    nspd_free(&solid);
    nspd_free(&kind);
    return status;
}

int sim_output_fields(Sim *sim) {
    if (!sim->dir) return NSPD_OK;
    if (sim->has_solid) pd_damage(&sim->solid, sim->damage);
    if (sim->has_solid) TRY(solid_fields(sim));
    if (sim->has_flow) TRY(flow_fields(sim));
    TRY(probes_write_lines(sim->probes, sim->cfg.output.probe_count,
                           sim->has_solid ? &sim->solid : NULL, sim->damage, sim->flow, sim->time,
                           sim->dir, sim->field_index));
    sim->field_index++;
    return NSPD_OK;
}

static void solid_summary(Sim *sim, JsonWriter *w) {
    const PdBody *b = &sim->solid;
    pd_damage(b, sim->damage);
    double max_damage = 0;
    for (int64_t i = 0; i < b->n; i++) max_damage = fmax(max_damage, sim->damage[i]);
    json_number(w, "dt_s", sim->dt);
    json_number(w, "stable_dt_s", sim->stable_dt);
    json_int(w, "points", b->n);
    json_int(w, "bonds", b->bond_count / 2);
    json_int(w, "broken_bonds", pd_broken_bonds(b));
    json_number(w, "max_damage", max_damage);
    json_number(w, "kinetic_energy_J", pd_kinetic_energy(b));
    json_number(w, "elastic_energy_J", pd_elastic_energy(b));
    json_number(w, "bond_updates_per_s",
                sim->wall_s > 0 ? (double)b->bond_count * (double)sim->step / sim->wall_s : 0.0);
}

static void flow_summary(Sim *sim, JsonWriter *w) {
    const Grid *g = flow_solver_grid(sim->flow);
    double totals[4];
    flow_solver_totals(sim->flow, totals);
    int64_t cells = (int64_t)g->nx * g->ny;
    json_int(w, "cells", cells);
    json_int(w, "cells_x", g->nx);
    json_int(w, "cells_y", g->ny);
    json_number(w, "cell_updates_per_s",
                sim->wall_s > 0 ? (double)cells * (double)sim->step / sim->wall_s : 0.0);
    json_int(w, "fallbacks", flow_solver_fallbacks_total(sim->flow));
    json_number(w, "mass_kg_per_m", totals[0]);
    json_number(w, "momentum_x_kg_per_s", totals[1]);
    json_number(w, "momentum_y_kg_per_s", totals[2]);
    json_number(w, "energy_J_per_m", totals[3]);
}

int sim_output_summary(Sim *sim, int run_status) {
    if (!sim->dir) return NSPD_OK;
    char path[4096];
    path_in(sim, path, sizeof path, "summary.json");
    FILE *f = fopen(path, "w");
    if (!f) return NSPD_FAIL(NSPD_ERR_IO, "cannot create '%s'", path);
    JsonWriter w;
    json_begin(&w, f);
    json_string(&w, "case", sim->cfg.name);
    json_number(&w, "time_s", sim->time);
    json_int(&w, "steps", sim->step);
    json_number(&w, "wall_s", sim->wall_s);
    json_int(&w, "threads", omp_get_max_threads());
    json_bool(&w, "completed", run_status == NSPD_OK && !sim->interrupted);
    json_bool(&w, "interrupted", sim->interrupted);
    if (sim->has_solid) solid_summary(sim, &w);
    if (sim->has_flow) flow_summary(sim, &w);
    json_number(&w, "peak_rss_mb", nspd_peak_rss_mb());
    for (int k = 0; k < sim->cfg.output.probe_count; k++) {
        const ProbeState *p = &sim->probes[k];
        if (p->cfg->kind != PROBE_CRACK_TIP) continue;
        char key[128];
        static const char *const axis[] = {"x", "y", "z"};
        for (int d = 0; d < sim->solid.dim; d++) {
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
