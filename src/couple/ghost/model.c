#include "couple/ghost/model.h"

#include "core/log.h"
#include "core/mem.h"
#include "core/status.h"
#include "couple/coupling.h"
#include "flow/gks/model.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void ghost_coupling_config_free(GhostCouplingConfig *cfg) {
    ibm_body_set_free(&cfg->bodies);
}

static const char *const COEF_NAMES[6] = {"cd",         "cl",          "cd_pressure",
                                          "cd_viscous", "cl_pressure", "cl_viscous"};

typedef struct {
    GhostCouplingConfig cfg;
    double average_from; /* s */
    bool rigid;          /* fixed bodies, no solid */
    /* the reference state has no speed: no dynamic pressure to divide by,
     * so no cd, cl, cp_stagnation columns and no cp, cf in the surface
     * tables (omitted, said once at create, instead of written as 0) */
    bool no_coefficients;
    Fsi fsi; /* two-way: the solid's surface as the walls */
    /* rigid walls */
    Ibm *ibm;
    IbmPolyline *bodies;
    IbmSurface surface;
    int body_count; /* bodies, or the solid's surface loops */
    /* time sums of cd, cl, cd_p, cd_v, cl_p, cl_v per body, from average_from on */
    double *coef_sum;
    int64_t coef_samples;
    double *table_body; /* the surface table's body column as numbers */
    int64_t table_capacity;
} GhostCoupling;

static const Ibm *ibm_of(const GhostCoupling *g) {
    return g->rigid ? g->ibm : g->fsi.ibm;
}

static IbmSurface *surface_of(GhostCoupling *g) {
    return g->rigid ? &g->surface : &g->fsi.loads;
}

static const IbmReference *reference_of(const GhostCoupling *g) {
    return g->rigid ? &g->cfg.fsi.reference : &g->fsi.cfg.reference;
}

static void ghost_destroy(void *impl) {
    GhostCoupling *g = impl;
    if (!g->rigid) fsi_destroy(&g->fsi);
    ibm_destroy(&g->ibm);
    ibm_surface_free(&g->surface);
    for (int b = 0; b < g->body_count && g->bodies; b++) ibm_polyline_free(&g->bodies[b]);
    nspd_free(&g->bodies);
    nspd_free(&g->coef_sum);
    nspd_free(&g->table_body);
    ghost_coupling_config_free(&g->cfg);
    nspd_free(&g);
}

/* Fixed bodies: markers, tags and ghost cells once, optional soft start. */
static int create_rigid(GhostCoupling *g, GksSolver *solver) {
    const IbmBodySet *set = &g->cfg.bodies;
    if (set->count == 0)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "the ghost-cell coupling has no walls: expected a solid or flow.bodies");
    TRY(nspd_alloc(&g->bodies, (size_t)set->count, sizeof(IbmPolyline)));
    g->body_count = set->count;
    for (int b = 0; b < set->count; b++) TRY(ibm_body_markers(&set->bodies[b], &g->bodies[b]));
    TRY(ibm_create(&g->ibm, gks_solver_whole_grid(solver), g->bodies, g->body_count));
    ibm_set_ghost_faces(g->ibm, (IbmGhostFaces)g->cfg.fsi.ghost_faces);
    TRY(ibm_attach(g->ibm, solver));
    if (g->cfg.fsi.soft_start > 0) ibm_soft_start(g->ibm, solver, g->cfg.fsi.soft_start);
    return ibm_surface_reserve(g->ibm, &g->surface);
}

/* The immersed boundary: its per-cell arrays over the flow's stored cells
 * (inside, kind and mark flags, a byte each, and the ghost slot, int32),
 * and per marker of a fixed body its share of the marker arrays, the
 * surface probes (two stencils per segment), the ghost stencils and their
 * spare set: about 1 kB, as measured on the NACA 0012 (6,434 markers:
 * 6.6 MB beyond the per-cell arrays). A solid's surface is not counted
 * (its markers are its surface points, known once it is built; a few
 * hundred kB for the cases). A polygon's refinement is not counted. */
static CouplingEstimate ghost_estimate(const CouplingConfig *cfg, const FlowEstimate *flow) {
    double markers = 0.0;
    const IbmBodySet *set = &((const GhostCouplingConfig *)cfg->model)->bodies;
    for (int b = 0; b < set->count; b++) {
        const IbmBodyConfig *body = &set->bodies[b];
        markers += body->kind == IBM_BODY_RECTANGLE ? 4.0 * body->markers_per_side
                   : body->kind == IBM_BODY_POLYGON ? body->vertex_count
                                                    : body->markers;
    }
    const CouplingEstimate e = {(3.0 + 4.0) * flow->stored_cells + 1024.0 * markers};
    return e;
}

static int ghost_create(void **impl, CouplingConfig *cfg, Solid *solid, Flow *flow) {
    GksSolver *solver = gks_flow_solver(flow);
    if (!solver)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "the ghost-cell coupling needs the GKS flow solver, not '%s'",
                         flow_name(flow));
    if (solid && solid_points(solid)->dim != 2)
        return NSPD_FAIL(NSPD_ERR_INPUT, "the ghost-cell coupling needs a 2D solid, not %dD",
                         solid_points(solid)->dim);
    GhostCoupling *g;
    TRY(nspd_alloc(&g, 1, sizeof *g));
    g->cfg = *(GhostCouplingConfig *)cfg->model;
    g->average_from = cfg->average_from;
    /* `nspd check`: no soft start, rigid walls' or a solid's (fsi.c) */
    if (cfg->validate_only) g->cfg.fsi.soft_start = 0.0;
    nspd_free(&cfg->model); /* taken */
    g->rigid = solid == NULL;
    int status;
    if (g->rigid) {
        status = create_rigid(g, solver);
    } else {
        status = fsi_create(&g->fsi, &g->cfg.fsi, solid, solver);
        g->body_count = g->fsi.loop_count;
    }
    if (status == NSPD_OK)
        status = nspd_alloc(&g->coef_sum, (size_t)g->body_count * 6, sizeof(double));
    const IbmReference *ref = reference_of(g);
    g->no_coefficients = !(ref->rho * (ref->u * ref->u + ref->v * ref->v) > 0.0);
    if (status == NSPD_OK && g->no_coefficients)
        nspd_log(LOG_WARN,
                 "%s: the coefficients' reference speed is 0 (the %s at rest): cd, cl and their "
                 "parts, cp_stagnation and the surface tables' cp, cf are omitted; forces are "
                 "written in N/m. For coefficients: flow.free_stream with a speed",
                 cfg->where[0] ? cfg->where : "coupling",
                 g->rigid ? "free stream, else the initial gas," : "initial gas");
    if (status != NSPD_OK) {
        ghost_destroy(g);
        return status;
    }
    *impl = g;
    return NSPD_OK;
}

static int ghost_before_flow(void *impl, Solid *solid, Flow *flow) {
    GhostCoupling *g = impl;
    if (g->rigid) return NSPD_OK;
    return fsi_move_interface(&g->fsi, solid, gks_flow_solver(flow));
}

static int ghost_after_flow(void *impl, Solid *solid, Flow *flow, double dt) {
    (void)dt;
    GhostCoupling *g = impl;
    if (g->rigid) return NSPD_OK;
    return fsi_apply_loads(&g->fsi, solid, gks_flow_solver(flow));
}

static void ghost_loads(const void *impl, CouplingLoads *out) {
    const GhostCoupling *g = impl;
    /* rigid walls pass nothing on */
    out->force_on_solid[0] = g->rigid ? 0.0 : g->fsi.force_on_solid[0];
    out->force_on_solid[1] = g->rigid ? 0.0 : g->fsi.force_on_solid[1];
}

/* The surface loads of the current state. */
static int surface_loads(GhostCoupling *g, Flow *flow, const IbmSurface **out) {
    IbmSurface *s = surface_of(g);
    TRY(ibm_surface_compute(ibm_of(g), gks_flow_solver(flow), reference_of(g), s));
    *out = s;
    return NSPD_OK;
}

/* "" for the first body, "<name>_" (rigid) or "loop<k>_" for the others. */
static void body_prefix(const GhostCoupling *g, int b, char *buf, size_t size) {
    if (b == 0)
        buf[0] = '\0';
    else if (!g->rigid)
        snprintf(buf, size, "loop%d_", b);
    else
        snprintf(buf, size, "%s_", g->cfg.bodies.bodies[b].name);
}

static void coefficients(const IbmBodyForces *f, double c[6]) {
    c[0] = f->cd;
    c[1] = f->cl;
    c[2] = f->cd_pressure;
    c[3] = f->cd_viscous;
    c[4] = f->cl_pressure;
    c[5] = f->cl_viscous;
}

static int ghost_history(void *impl, Solid *solid, Flow *flow, double time, Report *row) {
    GhostCoupling *g = impl;
    const IbmSurface *s;
    TRY(surface_loads(g, flow, &s));
    const bool averaging = time >= g->average_from;
    for (int b = 0; b < g->body_count; b++) {
        char prefix[128];
        body_prefix(g, b, prefix, sizeof prefix);
        if (g->no_coefficients) continue;
        double co[6];
        coefficients(&s->forces[b], co);
        for (int k = 0; k < 6; k++) {
            report_realf(row, co[k], "%s%s", prefix, COEF_NAMES[k]);
            if (averaging) g->coef_sum[6 * b + k] += co[k];
        }
        report_realf(row, s->forces[b].cp_stagnation, "%scp_stagnation", prefix);
    }
    if (averaging && !g->no_coefficients) g->coef_samples++;
    if (!g->rigid) {
        report_real(row, "force_x_N_per_m", g->fsi.force_on_solid[0]);
        report_real(row, "force_y_N_per_m", g->fsi.force_on_solid[1]);
        report_int(row, "substeps", solid_last_substeps(solid));
    }
    return NSPD_OK;
}

/* Time-averaged coefficients (history samples from average_from on) and the
 * last surface state's stagnation Cp and separation point. */
static int ghost_summary(void *impl, Solid *solid, Flow *flow, Report *out) {
    (void)solid;
    GhostCoupling *g = impl;
    const IbmSurface *s;
    TRY(surface_loads(g, flow, &s));
    if (g->no_coefficients) return NSPD_OK;
    report_int(out, "coefficient_samples", g->coef_samples);
    for (int b = 0; b < g->body_count; b++) {
        char prefix[128];
        body_prefix(g, b, prefix, sizeof prefix);
        for (int k = 0; k < 6; k++)
            report_realf(out,
                         g->coef_samples ? g->coef_sum[6 * b + k] / (double)g->coef_samples
                                         : (double)NAN,
                         "%s%s", prefix, COEF_NAMES[k]);
        report_realf(out, s->forces[b].cp_stagnation, "%scp_stagnation", prefix);
        if (!isnan(s->forces[b].x_separation_over_c)) /* absent while attached */
            report_realf(out, s->forces[b].x_separation_over_c, "%sx_separation_over_c", prefix);
    }
    return NSPD_OK;
}

/* surface_NNNNN.csv: per segment of every body. */
static int ghost_fields(void *impl, Solid *solid, Flow *flow, FieldSet *out) {
    (void)solid;
    GhostCoupling *g = impl;
    const IbmSurface *s;
    TRY(surface_loads(g, flow, &s));
    if (s->n > g->table_capacity) { /* grows with the marker count: amortised */
        nspd_free(&g->table_body);
        TRY(nspd_alloc(&g->table_body, (size_t)s->n, sizeof(double)));
        g->table_capacity = s->n;
    }
    for (int k = 0; k < s->n; k++) g->table_body[k] = s->body[k];
    memset(out, 0, sizeof *out);
    out->mesh = MESH_NONE;
    if (g->no_coefficients)
        out->table[out->table_count++] =
            (TableRef){.file = "surface",
                       .header = "body,arc_m,x_m,y_m,p_Pa,tau_Pa",
                       .rows = s->n,
                       .ncol = 6,
                       .col = {g->table_body, s->arc, s->x, s->y, s->p, s->tau},
                       .integer_cols = 1u};
    else
        out->table[out->table_count++] =
            (TableRef){.file = "surface",
                       .header = "body,arc_m,x_m,y_m,cp,cf,p_Pa,tau_Pa",
                       .rows = s->n,
                       .ncol = 8,
                       .col = {g->table_body, s->arc, s->x, s->y, s->cp, s->cf, s->p, s->tau},
                       .integer_cols = 1u};
    return NSPD_OK;
}

/* The time sums of the coefficients and, coupled to a solid, the
 * interface (fsi_checkpoint); fixed bodies never move. */
static int ghost_checkpoint(void *impl, Checkpoint *ck) {
    GhostCoupling *g = impl;
    TRY(checkpoint_io(ck, "ghost.coef_sum", g->coef_sum,
                      (size_t)g->body_count * 6 * sizeof(double)));
    TRY(checkpoint_io_int64(ck, "ghost.coef_samples", &g->coef_samples));
    return g->rigid ? NSPD_OK : fsi_checkpoint(&g->fsi, ck);
}

static void ghost_config_free(void *model) {
    ghost_coupling_config_free(model);
}

const CouplingOps GHOST_COUPLING_OPS = {
    .name = "ghost_cell",
    .distributed = true,
    .divided_solid = true, /* fsi.c reads the whole body's view after solid_sync */
    .config_free = ghost_config_free,
    .estimate = ghost_estimate,
    .create = ghost_create,
    .destroy = ghost_destroy,
    .before_flow = ghost_before_flow,
    .after_flow = ghost_after_flow,
    .solid_dt_limit = NULL,
    .loads = ghost_loads,
    .history = ghost_history,
    .summary = ghost_summary,
    .fields = ghost_fields,
    .checkpoint = ghost_checkpoint,
};

const Ibm *ghost_coupling_ibm(Coupling *c) {
    GhostCoupling *g = coupling_impl(c, COUPLING_GHOST_CELL);
    return g ? ibm_of(g) : NULL;
}

const IbmSurface *ghost_coupling_surface(Coupling *c) {
    GhostCoupling *g = coupling_impl(c, COUPLING_GHOST_CELL);
    return g ? surface_of(g) : NULL;
}
