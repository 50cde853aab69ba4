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

/* ------------------------------------------------------------ immersed bodies */

static const Ibm *sim_ibm(const Sim *sim) {
    return sim->has_fsi ? sim->fsi.ibm : sim->ibm;
}

/* The reference of the force coefficients: the free stream, else the
 * initial state; the reference length, else 1 m. */
static IbmReference reference(const Sim *sim) {
    if (sim->has_fsi) return sim->fsi.cfg.reference;
    const FlowCaseConfig *f = &sim->cfg.flow;
    const FlowPrim *q = f->has_free_stream ? &f->free_stream : &f->solver.initial;
    return (IbmReference){.rho = q->rho,
                          .u = q->u,
                          .v = q->v,
                          .p = q->p,
                          .length = f->reference_length > 0 ? f->reference_length : 1.0,
                          .p_ambient = q->p};
}

/* Surface loads of the current state (computed here). */
static int surface_loads(Sim *sim, const IbmSurface **out) {
    IbmSurface *s = sim->has_fsi ? &sim->fsi.loads : &sim->surface;
    IbmReference ref = reference(sim);
    TRY(ibm_surface_compute(sim_ibm(sim), sim->flow, &ref, s));
    *out = s;
    return NSPD_OK;
}

/* "" for the first body, "<name>_" for the others. */
static void body_prefix(const Sim *sim, int b, char *buf, size_t size) {
    if (b == 0)
        buf[0] = '\0';
    else if (sim->has_fsi)
        snprintf(buf, size, "loop%d_", b);
    else
        snprintf(buf, size, "%s_", sim->cfg.flow.bodies.bodies[b].name);
}

static const char *const COEF_NAMES[6] = {"cd",         "cl",          "cd_pressure",
                                          "cd_viscous", "cl_pressure", "cl_viscous"};

static void coefficients(const IbmBodyForces *f, double c[6]) {
    c[0] = f->cd;
    c[1] = f->cl;
    c[2] = f->cd_pressure;
    c[3] = f->cd_viscous;
    c[4] = f->cl_pressure;
    c[5] = f->cl_viscous;
}

/* surface_NNNNN.csv: per segment of every body. */
static int write_surface(Sim *sim, const IbmSurface *s) {
    char name[64], path[4096];
    snprintf(name, sizeof name, "surface_%05d.csv", sim->field_index);
    path_in(sim, path, sizeof path, name);
    FILE *f = fopen(path, "w");
    if (!f) return NSPD_FAIL(NSPD_ERR_IO, "cannot create '%s'", path);
    fprintf(f, "# t = %.9g s\nbody,arc_m,x_m,y_m,cp,cf,p_Pa,tau_Pa\n", sim->time);
    for (int k = 0; k < s->n; k++)
        fprintf(f, "%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", s->body[k], s->arc[k], s->x[k],
                s->y[k], s->cp[k], s->cf[k], s->p[k], s->tau[k]);
    if (fclose(f) != 0) return NSPD_FAIL(NSPD_ERR_IO, "cannot write '%s'", path);
    return NSPD_OK;
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
    for (int b = 0; b < (sim_ibm(sim) ? sim->body_count : 0); b++) {
        char prefix[128];
        body_prefix(sim, b, prefix, sizeof prefix);
        for (int k = 0; k < 6; k++) fprintf(sim->history, ",%s%s", prefix, COEF_NAMES[k]);
        fprintf(sim->history, ",%scp_stagnation", prefix);
    }
    if (sim->has_fsi) fprintf(sim->history, ",force_x_N_per_m,force_y_N_per_m,substeps");
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
    if (sim_ibm(sim)) {
        const IbmSurface *s;
        TRY(surface_loads(sim, &s));
        bool averaging = sim->time >= sim->cfg.output.average_from - 1e-12 * sim->cfg.end_time;
        for (int k_body = 0; k_body < sim->body_count; k_body++) {
            double co[6];
            coefficients(&s->forces[k_body], co);
            for (int k = 0; k < 6; k++) {
                if (csv) fprintf(csv, ",%.9g", co[k]);
                if (averaging) sim->coef_sum[6 * k_body + k] += co[k];
            }
            if (csv) fprintf(csv, ",%.9g", s->forces[k_body].cp_stagnation);
        }
        if (averaging) sim->coef_samples++;
        if (csv && sim->has_fsi)
            fprintf(csv, ",%.9g,%.9g,%lld", sim->fsi.force_on_solid[0], sim->fsi.force_on_solid[1],
                    (long long)sim->fsi.substeps);
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
        RenderOptions ro = {0.0, 1.0, COLORMAP_VIRIDIS, out->png_max_pixels, {0, 0, 0, 0}};
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
        RenderOptions ro = {0.0,
                            mach_max > 0 ? mach_max : 1.0,
                            COLORMAP_VIRIDIS,
                            out->png_max_pixels,
                            {0, 0, 0, 0}};
        status = render_grid_png(path, g->nx, g->ny, g->ax[0].face, g->ax[1].face, sim->cells[5],
                                 solid, &ro, NULL);
    }
    if (status == NSPD_OK && out->png && sim->has_fsi) {
        /* the coupled picture: Mach number with the solid's damage on top */
        RenderPoints pts = {sim->solid.n,
                            {sim->position[0], sim->position[1]},
                            sim->damage,
                            sim->solid.spacing,
                            0.0,
                            1.0,
                            COLORMAP_INFERNO};
        snprintf(name, sizeof name, "mach_damage_%05d.png", sim->field_index);
        path_in(sim, path, sizeof path, name);
        double mach_max = 0.0;
        for (int64_t c2 = 0; c2 < ncell; c2++)
            if (!solid[c2] && sim->cells[5][c2] > mach_max) mach_max = sim->cells[5][c2];
        RenderOptions ro = {0.0,
                            mach_max > 0 ? mach_max : 1.0,
                            COLORMAP_VIRIDIS,
                            out->png_max_pixels,
                            {0, 0, 0, 0}};
        /* the window: the solid's box, enlarged by its own size on each side */
        double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
        for (int64_t i = 0; i < sim->solid.n; i++)
            for (int d = 0; d < 2; d++) {
                lo[d] = fmin(lo[d], sim->position[d][i]);
                hi[d] = fmax(hi[d], sim->position[d][i]);
            }
        double size = fmax(hi[0] - lo[0], hi[1] - lo[1]);
        ro.window[0] = lo[0] - size;
        ro.window[1] = lo[1] - size;
        ro.window[2] = hi[0] + size;
        ro.window[3] = hi[1] + size;
        status = render_grid_png(path, g->nx, g->ny, g->ax[0].face, g->ax[1].face, sim->cells[5],
                                 solid, &ro, &pts);
    }
    if (status == NSPD_OK && out->png) {
        /* the temperature scratch is free again: reuse it for the schlieren */
        schlieren(g, sim->cells[0], solid, sim->cells[4]);
        snprintf(name, sizeof name, "schlieren_%05d.png", sim->field_index);
        path_in(sim, path, sizeof path, name);
        RenderOptions ro = {0.0, 1.0, COLORMAP_GRAY, out->png_max_pixels, {0, 0, 0, 0}};
        status = render_grid_png(path, g->nx, g->ny, g->ax[0].face, g->ax[1].face, sim->cells[4],
                                 solid, &ro, NULL);
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
    if (sim_ibm(sim)) {
        const IbmSurface *s;
        TRY(surface_loads(sim, &s));
        TRY(write_surface(sim, s));
    }
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
    json_number(w, "broken_bond_fraction",
                b->bond_count ? 2.0 * (double)pd_broken_bonds(b) / (double)b->bond_count : 0.0);
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

/* Time-averaged coefficients (history samples from output.average_from on)
 * and the last surface state's stagnation Cp and separation point. */
static void bodies_summary(Sim *sim, JsonWriter *w) {
    const IbmSurface *s;
    if (surface_loads(sim, &s) != NSPD_OK) return;
    json_int(w, "coefficient_samples", sim->coef_samples);
    for (int b = 0; b < sim->body_count; b++) {
        char prefix[128], key[256];
        body_prefix(sim, b, prefix, sizeof prefix);
        for (int k = 0; k < 6; k++) {
            snprintf(key, sizeof key, "%s%s", prefix, COEF_NAMES[k]);
            json_number(w, key,
                        sim->coef_samples ? sim->coef_sum[6 * b + k] / (double)sim->coef_samples
                                          : (double)NAN);
        }
        snprintf(key, sizeof key, "%scp_stagnation", prefix);
        json_number(w, key, s->forces[b].cp_stagnation);
        if (!isnan(s->forces[b].x_separation_over_c)) { /* absent while attached */
            snprintf(key, sizeof key, "%sx_separation_over_c", prefix);
            json_number(w, key, s->forces[b].x_separation_over_c);
        }
    }
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
    if (sim->has_flow) json_number(&w, "flow_s", sim->part_s[SIM_PART_FLOW]);
    if (sim->has_solid) json_number(&w, "solid_s", sim->part_s[SIM_PART_SOLID]);
    if (sim->has_fsi) json_number(&w, "coupling_s", sim->part_s[SIM_PART_COUPLING]);
    json_int(&w, "threads", omp_get_max_threads());
    json_bool(&w, "completed", run_status == NSPD_OK && !sim->interrupted);
    json_bool(&w, "interrupted", sim->interrupted);
    if (sim->has_solid) solid_summary(sim, &w);
    if (sim->has_flow) flow_summary(sim, &w);
    if (sim_ibm(sim)) bodies_summary(sim, &w);
    json_number(&w, "peak_rss_mb", nspd_peak_rss_mb());
    for (int k = 0; k < sim->cfg.output.probe_count && sim->has_solid; k++) {
        const ProbeState *p = &sim->probes[k];
        if (p->cfg->kind != PROBE_POINT || p->cfg->target != PROBE_ON_SOLID) continue;
        char key[128];
        snprintf(key, sizeof key, "%s_dx_max_m", p->cfg->name);
        json_number(&w, key, p->dx_max);
        snprintf(key, sizeof key, "t_%s_dx_max_s", p->cfg->name);
        json_number(&w, key, p->t_dx_max);
    }
    /* branches: per probe, then the overall answer - the side that branched
     * (the first listed if both did) */
    BranchResult best = {0};
    const char *best_side = NULL;
    for (int k = 0; k < sim->cfg.output.probe_count && sim->has_solid; k++) {
        const ProbeState *p = &sim->probes[k];
        if (p->cfg->kind != PROBE_BRANCHES) continue;
        BranchResult br;
        double t_branch;
        if (probe_branch_report(p, &sim->solid, sim->damage, &br, &t_branch) != NSPD_OK) continue;
        char key[128];
        const char *name = p->cfg->name;
        snprintf(key, sizeof key, "%s_branch_time_s", name);
        json_number(&w, key, t_branch);
        snprintf(key, sizeof key, "%s_branched", name);
        json_bool(&w, key, br.branched);
        snprintf(key, sizeof key, "%s_branch_angle_deg", name);
        json_number(&w, key, br.angle_deg);
        snprintf(key, sizeof key, "%s_branch_upper_deg", name);
        json_number(&w, key, br.upper_deg);
        snprintf(key, sizeof key, "%s_branch_lower_deg", name);
        json_number(&w, key, br.lower_deg);
        snprintf(key, sizeof key, "%s_branch_point_x_m", name);
        json_number(&w, key, br.point[0]);
        snprintf(key, sizeof key, "%s_branch_point_y_m", name);
        json_number(&w, key, br.point[1]);
        if (br.branched && !best_side) {
            best = br;
            best_side = name;
        }
    }
    if (best_side) {
        json_number(&w, "branch_angle_deg", best.angle_deg);
        json_string(&w, "branch_side", best_side);
    } else {
        for (int k = 0; k < sim->cfg.output.probe_count; k++)
            if (sim->probes[k].cfg->kind == PROBE_BRANCHES) {
                json_number(&w, "branch_angle_deg", (double)NAN);
                break;
            }
    }
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
