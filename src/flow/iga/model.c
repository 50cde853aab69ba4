/* The IGA flow behind FlowOps: the driver's cells are the elements (the
 * field at their centres), so line probes, pictures and the .vtr series
 * work as for the GKS grid; the series adds the field at the element
 * corners as point data, and point probes read it at their points.
 *
 * On several processes (decomp.h) the model shows the whole: cells are the
 * whole's elements and unknowns its control points; a state at a point is
 * read on the process that owns its element and sent to all, and the
 * output fields are each process's own elements and corners gathered on
 * rank 0 (the writer), which writes the file one process writes. */
#include "flow/iga/model.h"

#include "core/mem.h"
#include "core/status.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

enum { OUT_FIELDS = 6 }; /* density, u, v, pressure, temperature, Mach */

typedef struct {
    IgaFlowConfig cfg;
    IgaSolver *solver;
    double last_dt;
    double *face[2];            /* element faces per axis */
    double *out[OUT_FIELDS];    /* element-centre fields, the output's scratch */
    double *corner[OUT_FIELDS]; /* the same at the element corners */
    double *speed;              /* |u| at the element centres: the speed pictures */
    double *kind;               /* 0 everywhere: all fluid */
    uint8_t *blank;
    double mach_scale;  /* the Mach pictures' top (flow_mach_picture_top); 0 until fixed */
    double speed_scale; /* the speed pictures' top, m/s (flow_speed_picture_top); the same */
    int64_t probe_count;
    double *probe_xy; /* point probes: (x, y) each, the field read there */
    /* several processes: this block's element-centre and corner values
     * (OUT_FIELDS + 1 a value: the fields and the speed) before the gather */
    double *mine;
    char process_grid[32]; /* "PXxPY" for the summary (it borrows the text) */
} IgaFlow;

void iga_flow_config_free(IgaFlowConfig *c) {
    for (int r = 0; r < c->region_count; r++) shapeset_free(&c->regions[r].shapes);
    nspd_free(&c->regions);
    c->region_count = 0;
}

static void iga_config_free(void *model) {
    iga_flow_config_free(model);
}

static FlowEstimate iga_estimate(const FlowConfig *fc) {
    const IgaConfig *c = &((const IgaFlowConfig *)fc->model)->solver;
    FlowEstimate e = {0};
    if (c->elements[0] < 1 || c->elements[1] < 1 || c->degree < 1 || c->degree > 3) return e;
    const double nel = (double)c->elements[0] * c->elements[1];
    const double ncp = (c->elements[0] + (double)c->degree) * (c->elements[1] + (double)c->degree);
    e.cells = nel;
    e.items = "elements";
    e.stored_cells = ncp;
    e.bytes = iga_solver_bytes(c->degree, ncp, nel) + (OUT_FIELDS + 3.0) * 8.0 * nel;
    /* seconds of the validating build, mostly the lumped-L2 start's 64
     * sub-cells an element: 0.36 s for 150 x 150 and 1.40 s for 300 x 300
     * elements of cases/iga_cylindrical_blast.yaml (2 threads, this
     * machine), 1.6e-5 s an element */
    e.check_s = 1.6e-5 * nel;
    const IgaFlowConfig *f = fc->model;
    /* a vortex's speeds are known once it is built */
    e.stable_dt = f->has_vortex ? 0.0 : iga_config_stable_dt(c, f->regions, f->region_count);
    return e;
}

static int iga_validate(const FlowConfig *fc) {
    return iga_config_check(&((const IgaFlowConfig *)fc->model)->solver);
}

static void iga_destroy(void *impl) {
    IgaFlow *f = impl;
    iga_solver_destroy(&f->solver);
    iga_flow_config_free(&f->cfg);
    for (int a = 0; a < 2; a++) nspd_free(&f->face[a]);
    for (int k = 0; k < OUT_FIELDS; k++) nspd_free(&f->out[k]), nspd_free(&f->corner[k]);
    nspd_free(&f->speed);
    nspd_free(&f->kind);
    nspd_free(&f->blank);
    nspd_free(&f->probe_xy);
    nspd_free(&f->mine);
    nspd_free(&f);
}

/* The initial vortex as control data (p, u, v, T); ctx: the IgaFlowConfig */
static void vortex_state(void *ctx, double x, double y, double out[4]) {
    const IgaFlowConfig *fc = ctx;
    double q[4];
    flow_vortex_state(&fc->vortex, x, y, q);
    out[0] = q[3], out[1] = q[1], out[2] = q[2], out[3] = q[3] / (q[0] * fc->solver.R);
}

static int iga_create(void **impl, FlowConfig *fc) {
    IgaFlow *f;
    TRY(nspd_alloc(&f, 1, sizeof *f));
    f->cfg = *(IgaFlowConfig *)fc->model;
    nspd_free(&fc->model); /* taken */
    IgaConfig c = f->cfg.solver;
    c.regions = f->cfg.regions;
    c.region_count = f->cfg.region_count;
    c.comm = fc->comm; /* borrowed during create */
    c.processes[0] = fc->processes[0], c.processes[1] = fc->processes[1];
    if (f->cfg.has_vortex) { /* its nearest image on a periodic box */
        FlowVortex *vx = &f->cfg.vortex;
        if (c.side[0] == IGA_SIDE_PERIODIC) vx->lo_x = c.lo[0], vx->period_x = c.hi[0] - c.lo[0];
        if (c.side[2] == IGA_SIDE_PERIODIC) vx->lo_y = c.lo[1], vx->period_y = c.hi[1] - c.lo[1];
        c.init_fn = vortex_state;
        c.init_ctx = &f->cfg;
    }
    int status = iga_solver_create(&f->solver, &c, 0.0);
    const int64_t nel = (int64_t)c.elements[0] * c.elements[1];
    for (int a = 0; a < 2 && status == NSPD_OK; a++) {
        status = nspd_alloc(&f->face[a], (size_t)c.elements[a] + 1, sizeof(double));
        const IgaAxis *ax = status == NSPD_OK ? iga_solver_axis(f->solver, a) : NULL;
        for (int i = 0; ax && i <= c.elements[a]; i++)
            f->face[a][i] = i == c.elements[a] ? ax->hi : ax->lo + i * ax->h;
    }
    const size_t corners = (size_t)(c.elements[0] + 1) * (size_t)(c.elements[1] + 1);
    for (int k = 0; k < OUT_FIELDS && status == NSPD_OK; k++) {
        status = nspd_alloc(&f->out[k], (size_t)nel, sizeof(double));
        if (status == NSPD_OK) status = nspd_alloc(&f->corner[k], corners, sizeof(double));
    }
    if (status == NSPD_OK) status = nspd_alloc(&f->speed, (size_t)nel, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&f->kind, (size_t)nel, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&f->blank, (size_t)nel, 1);
    if (status == NSPD_OK) {
        const IgaDecomp *dc = iga_solver_decomp(f->solver);
        snprintf(f->process_grid, sizeof f->process_grid, "%dx%d", dc->dims[0], dc->dims[1]);
    }
    if (status == NSPD_OK && iga_decomp_divided(iga_solver_decomp(f->solver)))
        status = nspd_alloc(&f->mine, (size_t)(OUT_FIELDS + 1) * (corners + (size_t)nel),
                            sizeof(double));
    if (status != NSPD_OK) {
        iga_destroy(f);
        return status;
    }
    *impl = f;
    return NSPD_OK;
}

static double iga_stable_dt(const void *impl) {
    return iga_solver_stable_dt(((const IgaFlow *)impl)->solver);
}

static int iga_step(void *impl, double dt) {
    IgaFlow *f = impl;
    f->last_dt = dt;
    return iga_solver_step(f->solver, dt);
}

static double iga_time(const void *impl) {
    return iga_solver_time(((const IgaFlow *)impl)->solver);
}

static FlowMesh iga_mesh(const void *impl) {
    (void)impl;
    return (FlowMesh){MESH_GRID};
}

static int iga_cell_at(const void *impl, const char *name, double x, double y, int64_t *cell) {
    const IgaFlow *f = impl;
    const double at[2] = {x, y};
    for (int d = 0; d < 2; d++) {
        const IgaAxis *a = iga_solver_axis(f->solver, d);
        if (at[d] < a->lo || at[d] > a->hi)
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "probe '%s': at[%d] = %g is outside the flow's rectangle [%g, %g]; "
                             "expected a point on it",
                             name, d, at[d], a->lo, a->hi);
    }
    *cell = iga_axis_element(iga_solver_axis(f->solver, 0), x) +
            (int64_t)f->cfg.solver.elements[0] * iga_axis_element(iga_solver_axis(f->solver, 1), y);
    return NSPD_OK;
}

static int iga_grid_line(const void *impl, int64_t through, int along, int64_t **cells,
                         int64_t *count) {
    const IgaFlow *f = impl;
    const int nx = f->cfg.solver.elements[0], n = f->cfg.solver.elements[along];
    const int i = (int)(through % nx), j = (int)(through / nx);
    TRY(nspd_alloc(cells, (size_t)n, sizeof(int64_t)));
    *count = n;
    for (int k = 0; k < n; k++)
        (*cells)[k] = along == 0 ? k + (int64_t)nx * j : i + (int64_t)nx * k;
    return NSPD_OK;
}

static void iga_cell_centre(const void *impl, int64_t cell, double xy[2]) {
    const IgaFlow *f = impl;
    const int nx = f->cfg.solver.elements[0];
    const int ij[2] = {(int)(cell % nx), (int)(cell / nx)};
    for (int d = 0; d < 2; d++) {
        const IgaAxis *a = iga_solver_axis(f->solver, d);
        xy[d] = a->lo + (ij[d] + 0.5) * a->h;
    }
}

/* rho, u, v, p, T at (x, y) (NaN off this process's window) */
static void state_at(const IgaFlow *f, double x, double y, double out[5]) {
    double Y[4];
    iga_solver_eval(f->solver, x, y, Y);
    out[0] = Y[0] / (f->cfg.solver.R * Y[3]);
    out[1] = Y[1], out[2] = Y[2], out[3] = Y[0], out[4] = Y[3];
}

/* The same on every process, read where the point's element is owned
 * (collective). */
static void shared_state_at(const IgaFlow *f, double x, double y, double out[5]) {
    const IgaDecomp *dc = iga_solver_decomp(f->solver);
    const int owner = iga_solver_point_owner(f->solver, x, y);
    if (!iga_decomp_divided(dc) || dc->comm.rank == owner) state_at(f, x, y, out);
    if (iga_decomp_divided(dc)) (void)comm_bcast(&dc->comm, out, 5 * (int)sizeof(double), owner);
}

static void iga_cell_state(const void *impl, int64_t cell, double out[5]) {
    double xy[2];
    iga_cell_centre(impl, cell, xy);
    shared_state_at(impl, xy[0], xy[1], out);
}

/* A point probe reads the field at its point through the basis (exact for
 * the space), not at the centre of the element that holds it: half an
 * element is microseconds of a blast front's arrival. */
static int iga_probe_add(void *impl, const char *name, double x, double y, int64_t *id) {
    IgaFlow *f = impl;
    const IgaConfig *c = &f->cfg.solver;
    if (!(x >= c->lo[0] && x <= c->hi[0] && y >= c->lo[1] && y <= c->hi[1]))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "probe '%s' at (%g, %g) is off the flow's rectangle [%g, %g] x [%g, %g]; "
                         "expected a point inside it",
                         name, x, y, c->lo[0], c->hi[0], c->lo[1], c->hi[1]);
    TRY(nspd_realloc(&f->probe_xy, 2 * (size_t)f->probe_count, 2 * (size_t)f->probe_count + 2,
                     sizeof(double)));
    f->probe_xy[2 * f->probe_count] = x;
    f->probe_xy[2 * f->probe_count + 1] = y;
    *id = f->probe_count++;
    return NSPD_OK;
}

static void iga_probe_state(const void *impl, int64_t id, double out[5]) {
    const IgaFlow *f = impl;
    shared_state_at(f, f->probe_xy[2 * id], f->probe_xy[2 * id + 1], out);
}

static FlowReference iga_reference(const void *impl) {
    const IgaConfig *c = &((const IgaFlow *)impl)->cfg.solver;
    const IgaState *q = &c->initial;
    return (FlowReference){.rho = q->p / (c->R * q->T),
                           .u = q->u,
                           .v = q->v,
                           .p = q->p,
                           .length = 0.0,
                           .gamma = c->gamma,
                           .gas_constant = c->R};
}

static int iga_sample(void *impl, int64_t n, const double *x, const double *y, FlowSamples *out) {
    if (iga_decomp_divided(iga_solver_decomp(((IgaFlow *)impl)->solver)))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "sampling the IGA flow at points runs on one process only so far (the "
                         "penalty coupling, which moves momentum instead, runs on several)");
    for (int64_t k = 0; k < n; k++) {
        double s[5];
        state_at(impl, x[k], y[k], s);
        out->rho[k] = s[0], out->u[k] = s[1], out->v[k] = s[2], out->p[k] = s[3];
    }
    return NSPD_OK;
}

static int iga_set_sources(void *impl, FlowSources *src) {
    IgaSolver *solver = ((IgaFlow *)impl)->solver;
    int64_t outside = 0;
    if (!src) return iga_solver_set_sources(solver, 0, NULL, NULL, NULL, NULL, NULL, &outside);
    TRY(iga_solver_set_sources(solver, src->n, src->x, src->y, src->force_x, src->force_y,
                               src->power, &outside));
    src->outside = outside;
    return NSPD_OK;
}

/* The transfer weights (FlowOps.transfer): the B-spline basis itself, a
 * partition of unity, when the kind's width holds (p + 1)^2 entries
 * (quadratic for degree 2, bilinear for degree 1); otherwise the control
 * point of the largest basis value with weight 1. */
static void iga_transfer(const void *impl, FlowTransferKind kind, int64_t n, const double *x,
                         const double *y, int64_t *cell, double *w) {
    const IgaSolver *s = ((const IgaFlow *)impl)->solver;
    const int width = flow_transfer_width(kind);
    for (int64_t k = 0; k < n; k++) {
        int64_t cp[IGA_MAX_LOCAL * IGA_MAX_LOCAL];
        double b[IGA_MAX_LOCAL * IGA_MAX_LOCAL];
        const int m = iga_solver_point_basis(s, x[k], y[k], cp, b);
        int64_t *c = cell + k * width;
        double *v = w + k * width;
        for (int j = 0; j < width; j++) c[j] = -1, v[j] = 0.0;
        if (m == 0) continue;
        if (m <= width) {
            for (int j = 0; j < m; j++) c[j] = cp[j], v[j] = b[j];
        } else {
            int best = 0;
            for (int j = 1; j < m; j++)
                if (b[j] > b[best]) best = j;
            c[0] = cp[best], v[0] = 1.0;
        }
    }
}

/* The process that owns control point `cell` (FlowOps.cell_owner). */
static int iga_cell_owner(const void *impl, int64_t cell) {
    return iga_decomp_owner(iga_solver_decomp(((const IgaFlow *)impl)->solver), cell);
}

/* Whether (x, y) lies in an element within `margin` elements (around a
 * periodic axis too) of this process's own (FlowOps.point_near). */
static bool iga_point_near(const void *impl, double x, double y, int margin) {
    const IgaSolver *s = ((const IgaFlow *)impl)->solver;
    const IgaDecomp *dc = iga_solver_decomp(s);
    if (!iga_decomp_divided(dc)) return true;
    const double at[2] = {x, y};
    for (int a = 0; a < 2; a++) {
        const IgaAxis *ax = iga_solver_axis(s, a);
        const IgaWindowAxis *w = &dc->ax[a];
        const int n = ax->elements, e = iga_axis_element(ax, at[a]);
        int lo, hi;
        iga_window_own_elements(w, &lo, &hi);
        int d = e < lo ? lo - e : e >= hi ? e - hi + 1 : 0;
        if (ax->periodic && d > 0) { /* the other way round */
            const int around = e < lo ? e + n - hi + 1 : lo + n - e;
            d = around < d ? around : d;
        }
        if (d > margin) return false;
    }
    return true;
}

static void iga_lumped(const void *impl, int64_t n, const int64_t *cells, double *mass,
                       double *momentum_x, double *momentum_y) {
    iga_solver_lumped(((const IgaFlow *)impl)->solver, n, cells, mass, momentum_x, momentum_y);
}

static void iga_lumped_volume(const void *impl, int64_t n, const int64_t *cells, double *volume) {
    iga_solver_lumped_volume(((const IgaFlow *)impl)->solver, n, cells, volume);
}

static void iga_add_lumped(void *impl, int64_t n, const int64_t *cells, const double *dmx,
                           const double *dmy, const double *de) {
    iga_solver_add_lumped(((IgaFlow *)impl)->solver, n, cells, dmx, dmy, de);
}

static void iga_totals(const void *impl, double totals[4]) {
    iga_solver_totals(((const IgaFlow *)impl)->solver, totals);
}

static void iga_history(const void *impl, Report *row) {
    const IgaFlow *f = impl;
    double t[4];
    iga_solver_totals(f->solver, t);
    report_real(row, "dt_s", f->last_dt);
    report_precise(row, "mass_kg_per_m", t[0]);
    report_precise(row, "momentum_x_kg_per_s", t[1]);
    report_precise(row, "momentum_y_kg_per_s", t[2]);
    report_precise(row, "energy_J_per_m", t[3]);
    report_real(row, "dc_viscosity_max_m2_per_s", iga_solver_nu_max(f->solver));
    if (f->cfg.solver.limiter != IGA_LIMITER_NONE) {
        /* the last stage's limited control points and smallest factor,
         * and the step's substeps (docs/IGA_LIMITER.md) */
        int64_t limited;
        double alpha_min;
        int substeps;
        iga_solver_limiting(f->solver, &limited, &alpha_min, &substeps);
        report_int(row, "limited_points", limited);
        report_real(row, "limiter_alpha_min", alpha_min);
        report_int(row, "limiter_substeps", substeps);
    }
}

static void iga_summary(const void *impl, const RunStats *run, Report *out) {
    const IgaFlow *f = impl;
    const IgaConfig *c = &f->cfg.solver;
    double t[4];
    iga_solver_totals(f->solver, t);
    const int64_t nel = (int64_t)c->elements[0] * c->elements[1];
    report_int(out, "elements", nel);
    report_int(out, "control_points", iga_solver_control_count(f->solver));
    report_real(out, "element_updates_per_s",
                run->wall_s > 0 ? (double)nel * (double)run->steps / run->wall_s : 0.0);
    report_real(out, "mass_kg_per_m", t[0]);
    report_real(out, "momentum_x_kg_per_s", t[1]);
    report_real(out, "momentum_y_kg_per_s", t[2]);
    report_real(out, "energy_J_per_m", t[3]);
    /* as the GKS flow's: a closed box's late mean pressure is its energy
     * balance's */
    report_real(out, "mean_pressure_pa", iga_solver_mean_pressure(f->solver));
    /* several processes: this one's wall time in halo exchanges and
     * gathers, and the layout (PX x PY blocks) */
    const IgaDecomp *dc = iga_solver_decomp(f->solver);
    if (iga_decomp_divided(dc)) {
        report_real(out, "exchange_s", dc->seconds);
        report_text(out, "process_grid", f->process_grid);
    }
}

static void iga_info(const void *impl, size_t memory, char *buf, size_t size) {
    const IgaFlow *f = impl;
    const IgaConfig *c = &f->cfg.solver;
    int len = 0;
#define APPEND(...)                                                                                \
    len += snprintf(buf + len, size > (size_t)len ? size - (size_t)len : 0, __VA_ARGS__)
    for (int a = 0; a < 2; a++) {
        const IgaAxis *ax = iga_solver_axis(f->solver, a);
        APPEND("B-splines %c          %d elements of %.4g m on [%.6g, %.6g] m, degree %d%s\n",
               "xy"[a], ax -> elements, ax -> h, ax -> lo, ax -> hi, ax -> degree,
               ax -> periodic ? ", periodic" : "");
    }
    APPEND("control points       %lld (4 unknowns each)\n",
           (long long)iga_solver_control_count(f->solver));
    APPEND("gas                  gamma %.4g, R %.6g J/(kg K), mu %.3g Pa s, Pr %.3g\n", c->gamma,
           c->R, c->mu, c->prandtl);
    APPEND("scheme               SUPG + DC %.3g%s, %d passes, rho_inf %.3g, tau from %s\n", c->c_dc,
           c->dc_cap ? " (capped)" : "", c->passes, c->rho_inf,
           c->tau_dt > 0 ? "flow.iga.tau_dt" : "the step taken");
    APPEND("stable time step     %.6g s at the start (Courant %.3g)\n",
           iga_solver_stable_dt(f->solver), c->cfl);
    APPEND("memory               %.1f MB\n", (double)memory / 1e6);
#undef APPEND
}

static void iga_brief(const void *impl, char *buf, size_t size) {
    const IgaConfig *c = &((const IgaFlow *)impl)->cfg.solver;
    snprintf(buf, size, "%d x %d elements of degree %d, ", c->elements[0], c->elements[1],
             c->degree);
}

/* The output fields of the state s (density, u, v, p, T) into slot k of
 * `to`; returns the Mach number. */
static double output_state(const IgaConfig *c, const double s[5], double *const to[OUT_FIELDS],
                           int64_t k) {
    for (int v = 0; v < 5; v++) to[v][k] = s[v];
    to[5][k] = hypot(s[1], s[2]) / sqrt(c->gamma * s[3] / s[0]);
    return to[5][k];
}

/* iga_fields' values on several processes: each its own elements' centres
 * and its own corners (those of its elements' lower left, and the last
 * row and column at the whole's end), gathered field by field on rank 0;
 * the largest Mach number and speed of all (a max: exact). */
static void divided_fields(IgaFlow *f, double *top, double *fastest) {
    const IgaConfig *c = &f->cfg.solver;
    IgaDecomp *dc = (IgaDecomp *)iga_solver_decomp(f->solver); /* its gathers' timer */
    const int nx = c->elements[0], ny = c->elements[1];
    int ex[IGA_MAX_BLOCKS + 1], ey[IGA_MAX_BLOCKS + 1], kx[IGA_MAX_BLOCKS + 1],
        ky[IGA_MAX_BLOCKS + 1];
    iga_decomp_cuts(dc, 0, nx, ex);
    iga_decomp_cuts(dc, 1, ny, ey);
    iga_decomp_cuts(dc, 0, nx + 1, kx);
    iga_decomp_cuts(dc, 1, ny + 1, ky);
    const int bx = dc->ax[0].part, by = dc->ax[1].part;
    const int ew = ex[bx + 1] - ex[bx], eh = ey[by + 1] - ey[by];
    const int kw = kx[bx + 1] - kx[bx], kh = ky[by + 1] - ky[by];
    const int64_t ne = (int64_t)ew * eh, nk = (int64_t)kw * kh;
    double *mine = f->mine, *corner = f->mine + (OUT_FIELDS + 1) * ne;
    double *to[OUT_FIELDS], *to_corner[OUT_FIELDS];
    for (int v = 0; v < OUT_FIELDS; v++) to[v] = mine + v * ne, to_corner[v] = corner + v * nk;
    double *speed = mine + OUT_FIELDS * ne;
    for (int64_t q = 0; q < ne; q++) {
        const int64_t k = ex[bx] + q % ew + (int64_t)nx * (ey[by] + q / ew);
        double xy[2], s[5];
        iga_cell_centre(f, k, xy);
        state_at(f, xy[0], xy[1], s);
        *top = fmax(*top, output_state(c, s, to, q));
        speed[q] = hypot(s[1], s[2]);
        *fastest = fmax(*fastest, speed[q]);
    }
    for (int64_t q = 0; q < nk; q++) {
        double s[5];
        state_at(f, f->face[0][kx[bx] + q % kw], f->face[1][ky[by] + q / kw], s);
        output_state(c, s, to_corner, q);
    }
    int *const cells[2] = {ex, ey}, *const corners[2] = {kx, ky};
    const int ncell[2] = {nx, ny}, ncorner[2] = {nx + 1, ny + 1};
    /* a failed gather is MPI's (its default handler stops the job) */
    for (int v = 0; v < OUT_FIELDS; v++) {
        (void)iga_decomp_gather(dc, ncell, cells, to[v], 1, f->out[v], false);
        (void)iga_decomp_gather(dc, ncorner, corners, to_corner[v], 1, f->corner[v], false);
    }
    (void)iga_decomp_gather(dc, ncell, cells, speed, 1, f->speed, false);
    *top = comm_max(&dc->comm, *top);
    *fastest = comm_max(&dc->comm, *fastest);
}

/* The field at the element centres (cell data: pictures, and what a later
 * run starts from) and at the element corners (point data: ParaView
 * interpolates the spline's samples between them). */
static void iga_fields(void *impl, FieldSet *out) {
    IgaFlow *f = impl;
    const IgaConfig *c = &f->cfg.solver;
    const int nx = c->elements[0], ny = c->elements[1];
    double top = 0.0, fastest = 0.0;
    if (iga_decomp_divided(iga_solver_decomp(f->solver))) {
        divided_fields(f, &top, &fastest);
    } else {
        for (int64_t k = 0; k < (int64_t)nx * ny; k++) {
            double s[5];
            iga_cell_state(f, k, s);
            top = fmax(top, output_state(c, s, f->out, k));
            f->speed[k] = hypot(s[1], s[2]); /* the Mach number's numerator */
            fastest = fmax(fastest, f->speed[k]);
        }
        for (int j = 0; j <= ny; j++)
            for (int i = 0; i <= nx; i++) {
                double s[5];
                state_at(f, f->face[0][i], f->face[1][j], s);
                output_state(c, s, f->corner, i + (int64_t)(nx + 1) * j);
            }
    }
    if (f->mach_scale == 0.0) f->mach_scale = flow_mach_picture_top(top);
    if (f->speed_scale == 0.0) f->speed_scale = flow_speed_picture_top(fastest, top);
    memset(out, 0, sizeof *out);
    out->series = "flow";
    out->mesh = MESH_GRID;
    out->nx = nx, out->ny = ny;
    out->face[0] = f->face[0], out->face[1] = f->face[1];
    out->blank = f->blank;
    double *const *o = f->out;
    const FieldRef fields[] = {
        {"density", 1, {o[0], NULL, NULL}},  {"velocity", 3, {o[1], o[2], NULL}},
        {"pressure", 1, {o[3], NULL, NULL}}, {"temperature", 1, {o[4], NULL, NULL}},
        {"mach", 1, {o[5], NULL, NULL}},     {"cell_kind", 1, {f->kind, NULL, NULL}},
    };
    for (size_t k = 0; k < sizeof fields / sizeof fields[0]; k++)
        out->field[out->field_count++] = fields[k];
    double *const *q = f->corner;
    const FieldRef corner[] = {
        {"density", 1, {q[0], NULL, NULL}},  {"velocity", 3, {q[1], q[2], NULL}},
        {"pressure", 1, {q[3], NULL, NULL}}, {"temperature", 1, {q[4], NULL, NULL}},
        {"mach", 1, {q[5], NULL, NULL}},
    };
    for (size_t k = 0; k < sizeof corner / sizeof corner[0]; k++)
        out->point_field[out->point_field_count++] = corner[k];
    /* 0 to 1 while the scale is open (a gas at rest) */
    const double mach_hi = f->mach_scale > 0.0 ? f->mach_scale : 1.0;
    out->picture[out->picture_count++] = (PictureRef){.file = "mach",
                                                      .label = "Mach number",
                                                      .units = "-",
                                                      .values = o[5],
                                                      .lo = 0.0,
                                                      .hi = mach_hi,
                                                      .map = COLORMAP_VIRIDIS,
                                                      .overlay_file = "mach_damage"};
    /* |u|, paper 003's air speed (Figs. 2, 7, 11), where a solid is coupled
     * (drawn with it on top); from the velocity, no VTK array of its own */
    out->picture[out->picture_count++] =
        (PictureRef){.file = "speed",
                     .label = "speed",
                     .units = "m/s",
                     .values = f->speed,
                     .lo = 0.0,
                     .hi = f->speed_scale > 0.0 ? f->speed_scale : 1.0,
                     .map = COLORMAP_VIRIDIS,
                     .overlay_file = "speed_damage",
                     .coupled_only = true};
}

static int iga_checkpoint(void *impl, Checkpoint *ck) {
    IgaFlow *f = impl;
    TRY(iga_solver_checkpoint(f->solver, ck));
    TRY(checkpoint_io_double(ck, "iga.mach_scale", &f->mach_scale));
    TRY(checkpoint_io_double(ck, "iga.speed_scale", &f->speed_scale));
    return checkpoint_io_double(ck, "iga.last_dt", &f->last_dt);
}

const FlowOps IGA_FLOW_OPS = {
    .name = "iga",
    .distributed = true,
    .config_free = iga_config_free,
    .estimate = iga_estimate,
    .validate = iga_validate,
    .create = iga_create,
    .destroy = iga_destroy,
    .stable_dt = iga_stable_dt,
    .step = iga_step,
    .time = iga_time,
    .mesh = iga_mesh,
    .cell_state = iga_cell_state,
    .cell_at = iga_cell_at,
    .grid_line = iga_grid_line,
    .cell_centre = iga_cell_centre,
    .reference = iga_reference,
    .sample = iga_sample,
    .set_sources = iga_set_sources,
    .probe_add = iga_probe_add,
    .probe_state = iga_probe_state,
    .transfer = iga_transfer,
    .cell_owner = iga_cell_owner,
    .point_near = iga_point_near,
    .lumped = iga_lumped,
    .lumped_volume = iga_lumped_volume,
    .add_lumped = iga_add_lumped,
    .totals = iga_totals,
    .history = iga_history,
    .summary = iga_summary,
    .info = iga_info,
    .brief = iga_brief,
    .fields = iga_fields,
    .checkpoint = iga_checkpoint,
};
