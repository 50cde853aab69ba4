/* The PDDO flow behind the flow interface (model.h). */
#include "flow/pddo/model.h"

#include "core/comm.h"
#include "core/mem.h"
#include "core/parallel.h"
#include "core/reduce.h"
#include "core/status.h"
#include "core/timer.h"
#include "flow/flow.h"
#include "flow/pddo/forces.h"
#include "flow/pddo/operators.h"
#include "flow/pddo/ppe.h"
#include "flow/pddo/sample.h"
#include "flow/pddo/share.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Output scratch over the physical nodes: x, y, u, v, p, vorticity,
 * divergence, speed, node kind. */
enum { OX, OY, OU, OV, OP, OW, OD, OS, OK_KIND, OUT_ARRAYS };
/* Per-node scratch over the whole cloud: du/dx, du/dy, dv/dx, dv/dy, a
 * sum's terms. */
enum { GUX, GUY, GVX, GVY, TERM, NODE_ARRAYS };
enum { LINE_COLS = 5 };
/* a body's wall table: theta (deg), x, y, p, wall shear, traction x, y */
enum { WALL_COLS = 7 };

/* A force's record: the last step's force, the dt-weighted sums from
 * average_from on (fx, fy, fx_p, fx_v, fy_p, fy_v) and the lift's upward
 * zero crossings there. */
typedef struct {
    PddoForce force;
    double sum[6];
    PddoLiftPeriods lift;
} BodyRecord;

typedef struct {
    PddoFlowConfig cfg;
    PddoCloud cloud;
    PddoOps ops;
    PddoPpe ppe;
    PddoStep step;
    NspdComm comm;      /* the processes that share the flow (one: comm_self) */
    PddoShare share;    /* several processes: each one's range of nodes (share.h) */
    bool validate_only; /* `nspd check`: conditioning only, no weights or pressure matrix */
    double setup_s;     /* wall time of the cloud, operators and factorisation (log and info) */
    int64_t physical;   /* fluid and side nodes */
    int64_t *phys;      /* their node numbers */
    double *weight;     /* their areas in the trapezoidal rule: halved on each side a node is on */
    double *out[OUT_ARRAYS];
    double *node[NODE_ARRAYS];
    double *sorted;      /* picture ranges */
    int64_t steady_step; /* the step at which max |du/dt| first fell below the tolerance, or -1 */
    /* line tables: the nodes on both sides of each station and the weight of the second */
    int64_t line_rows[PDDO_MAX_LINES];
    int32_t *line_a[PDDO_MAX_LINES], *line_b[PDDO_MAX_LINES];
    double *line_w[PDDO_MAX_LINES];
    double *line_col[PDDO_MAX_LINES][LINE_COLS];
    char line_file[PDDO_MAX_LINES][PDDO_LINE_NAME + 8];
    /* the bodies' forces: each body's operators and record */
    PddoForces forces[PDDO_MAX_BODIES];
    BodyRecord body[PDDO_MAX_BODIES];
    double *wall_col[PDDO_MAX_BODIES][WALL_COLS]; /* each body's wall table (pddo_fields) */
    char wall_file[PDDO_MAX_BODIES][PDDO_LINE_NAME + 8];
    double averaged_s; /* the time summed in the records */
    PddoSample probes; /* the driver's point probes (flow/pddo/sample.h) */
} PddoFlow;

double pddo_flow_smallest_spacing(const PddoFlowConfig *c) {
    const PddoCloudSpec *s = &c->cloud;
    /* the limit is the Laplacian's, whose weights scale with the horizon:
     * notes 1.5's 1.61 dx^2 is for delta = 3 dx (dx (h / 3) is dx itself
     * there, the same bits) */
    double h = s->dx * (s->horizon_factor / 3.0);
    for (int b = 0; b < c->body_count; b++) {
        PddoPolarPatch p;
        if (pddo_polar_layout(&p, c->bodies[b].x, c->bodies[b].y, c->bodies[b].radius, &c->polar[b],
                              s->dx) != NSPD_OK)
            continue;
        const double delta = s->horizon_factor * s->dx;
        h = fmin(h, pddo_polar_horizon(&p, p.rings_inside, delta) / 3.0);
    }
    return h;
}

double pddo_flow_dt_limit(const PddoFlowConfig *c) {
    return 2.0 * pddo_step_stable_dt(c->step.mu / c->step.rho, pddo_flow_smallest_spacing(c),
                                     c->velocity_scale);
}

/* Nodes and family members of a configuration, counted as the cloud
 * builder would (families: 28 in the bulk, fewer on the outer layers). */
static void count_nodes(const PddoFlowConfig *c, double *nodes, double *members) {
    const PddoCloudSpec *s = &c->cloud;
    double n[2];
    for (int a = 0; a < 2; a++) {
        const double q = round((s->hi[a] - s->lo[a]) / s->dx);
        n[a] =
            s->side[2 * a] == PDDO_SIDE_PERIODIC ? q + 2.0 * s->layers : q + 1.0 + 2.0 * s->layers;
    }
    *nodes = n[0] * n[1];
    const double h = s->horizon_factor;
    *members = *nodes * fmax(4.0, M_PI * h * h - 1.0);
    for (int b = 0; b < c->body_count; b++) { /* the patch's rings for the lattice it removes */
        PddoPolarPatch p;
        if (pddo_polar_layout(&p, c->bodies[b].x, c->bodies[b].y, c->bodies[b].radius, &c->polar[b],
                              s->dx) != NSPD_OK)
            continue;
        const double ring_nodes = (double)pddo_polar_count(&p);
        const double removed = M_PI * p.r_cut * p.r_cut / (s->dx * s->dx);
        *nodes += ring_nodes - removed;
        /* ring families: about pi delta^2 / (dr r dtheta) at r = 2 R on average */
        const double delta = h * s->dx;
        *members += ring_nodes * M_PI * delta * delta / (p.dr * 2.0 * p.radius * p.dtheta) -
                    removed * (M_PI * h * h - 1.0);
    }
}

/* Seconds per node of the validating build (`nspd check`: the cloud and
 * the operators' conditioning): 0.26 s for the 122,833 nodes of
 * cases/cylinder_confined_re100.yaml (2 threads, this machine; median of
 * 3), rounded up. */
#define PDDO_CHECK_S_PER_NODE 2.2e-6

/* Bytes: the cloud (coordinates, area, indices, kinds: 52 per node, and
 * the family's int32 per member), the four operators' float64 weights per
 * member and the slices' int32 neighbour (operators.h; the slices'
 * padding measured under 1 % on the paper's cylinder; templates keep
 * about half of them on a lattice, not counted: the estimate bounds), K_L (int32 + float64 per
 * member and node), its LU factors (UMFPACK, about 12 bytes per nonzero; nonzeros of L + U with the
 * AMD/METIS ordering measured on the confined cylinder, dx 0.1 to 0.03 m: 3.9e6 at 12,424
 * nodes, 8.2e6 at 21,233, 2.0e7 at 45,768, 3.4e7 at 70,345, 6.7e7 at 122,833, that is 29 to 32
 * n^1.25 (21 n log2 n, fitted on small cavities, fell 35 % short at 122,833); 32 n^1.25 bounds them
 * and the cavity's 3.0e6 at 11,449 nodes), the step's 14 arrays per node and the output scratch. */
static FlowEstimate pddo_estimate(const FlowConfig *fc) {
    const PddoFlowConfig *c = fc->model;
    FlowEstimate e = {0};
    if (!(c->cloud.dx > 0.0)) return e;
    double n, m;
    count_nodes(c, &n, &m);
    e.cells = n;
    e.items = "nodes";
    e.stored_cells = n;
    const double factor = 32.0 * pow(n, 1.25);
    /* flow.pressure_solve: runs holds about 8 bytes a factor nonzero more
     * while U is regrouped beside UMFPACK's factor (measured: peak resident
     * set 1,623 MB against 1,105 MB at the paper's cylinder, 6.67e7
     * nonzeros: 7.8 bytes each) */
    const double runs = c->pressure_runs ? 8.0 * factor : 0.0;
    /* boomeramg: no factor, PETSc's copy of the matrix and a hierarchy
     * about as large (operator complexity 1.14, bench/ppe_solvers) */
    const double lu = c->pressure.petsc && c->pressure.method == PPE_PETSC_BOOMERAMG
                          ? 2.0 * 12.0 * (m + n)
                          : 12.0 * factor;
    e.bytes = 52.0 * n + 4.0 * m + (4.0 * 8.0 + 4.0) * m + 12.0 * (m + n) + lu + runs +
              14.0 * 8.0 * n + (OUT_ARRAYS + NODE_ARRAYS + 1) * 8.0 * n;
    e.check_s = PDDO_CHECK_S_PER_NODE * n;
    e.stable_dt = c->step.dt; /* fixed by the reader */
    return e;
}

/* The cloud's layout checked without its nodes (pddo_cloud_check). */
static int pddo_validate(const FlowConfig *fc) {
    const PddoFlowConfig *c = fc->model;
    PddoCloudSpec spec = c->cloud;
    if (c->body_count > 0) {
        spec.holes = c->bodies;
        spec.nholes = c->body_count;
        spec.polar = c->polar;
    }
    return pddo_cloud_check(&spec);
}

static void pddo_destroy(void *impl) {
    PddoFlow *f = impl;
    for (int b = 0; b < PDDO_MAX_BODIES; b++) {
        pddo_forces_free(&f->forces[b]);
        for (int k = 0; k < WALL_COLS; k++) nspd_free(&f->wall_col[b][k]);
    }
    pddo_sample_free(&f->probes);
    pddo_step_free(&f->step);
    pddo_ppe_free(&f->ppe);
    pddo_share_free(&f->share);
    pddo_ops_free(&f->ops);
    pddo_cloud_free(&f->cloud);
    nspd_free(&f->phys);
    nspd_free(&f->weight);
    for (int k = 0; k < OUT_ARRAYS; k++) nspd_free(&f->out[k]);
    for (int k = 0; k < NODE_ARRAYS; k++) nspd_free(&f->node[k]);
    nspd_free(&f->sorted);
    for (int l = 0; l < PDDO_MAX_LINES; l++) {
        nspd_free(&f->line_a[l]);
        nspd_free(&f->line_b[l]);
        nspd_free(&f->line_w[l]);
        for (int k = 0; k < LINE_COLS; k++) nspd_free(&f->line_col[l][k]);
    }
    nspd_free(&f);
}

/* The stations of line l: along its axis every lattice index of the
 * physical nodes, across it the two indices around `at`. */
static int build_line(PddoFlow *f, int l) {
    const PddoCloud *c = &f->cloud;
    const PddoLine *line = &f->cfg.lines[l];
    const int along = line->along, across = 1 - along;
    const int n_across = across == 0 ? c->nx : c->ny, n_along = along == 0 ? c->nx : c->ny;
    const bool periodic_along = c->side[2 * along] == PDDO_SIDE_PERIODIC;
    const bool periodic_across = c->side[2 * across] == PDDO_SIDE_PERIODIC;
    const double lo = f->cfg.cloud.lo[across];
    double q = (line->at[across] - lo) / c->dx;
    const int top = periodic_across ? n_across - 1 : n_across;
    if (!(q >= -1e-9 && q <= top + 1e-9))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "line '%s': at %g m is outside the nodes' [%g, %g] m across it",
                         line->name, line->at[across], lo, lo + top * c->dx);
    q = fmin(fmax(q, 0.0), (double)top);
    int i0 = (int)floor(q);
    double w = q - i0;
    if (w < 1e-9) w = 0.0;
    if (w > 1.0 - 1e-9) i0++, w = 0.0;
    const int i1 = w > 0.0 ? i0 + 1 : i0;
    const int64_t stations = periodic_along ? n_along : n_along + 1;
    int64_t rows = 0; /* stations whose nodes exist (a polar patch removes some) */
    for (int64_t r = 0; r < stations; r++) {
        const int s = (int)r;
        const int64_t a = along == 0 ? pddo_cloud_node(c, s, i0) : pddo_cloud_node(c, i0, s);
        const int64_t b = along == 0 ? pddo_cloud_node(c, s, i1) : pddo_cloud_node(c, i1, s);
        rows += a >= 0 && b >= 0;
    }
    if (rows == 0) return NSPD_FAIL(NSPD_ERR_INPUT, "line '%s': no lattice node on it", line->name);
    f->line_rows[l] = rows;
    TRY(nspd_alloc(&f->line_a[l], (size_t)rows, sizeof(int32_t)));
    TRY(nspd_alloc(&f->line_b[l], (size_t)rows, sizeof(int32_t)));
    TRY(nspd_alloc(&f->line_w[l], (size_t)rows, sizeof(double)));
    for (int k = 0; k < LINE_COLS; k++)
        TRY(nspd_alloc(&f->line_col[l][k], (size_t)rows, sizeof(double)));
    for (int64_t r = 0, st = 0; r < stations; r++) {
        const int s = (int)r;
        const int64_t a = along == 0 ? pddo_cloud_node(c, s, i0) : pddo_cloud_node(c, i0, s);
        const int64_t b = along == 0 ? pddo_cloud_node(c, s, i1) : pddo_cloud_node(c, i1, s);
        if (a < 0 || b < 0) continue;
        f->line_a[l][st] = (int32_t)a, f->line_b[l][st] = (int32_t)b, f->line_w[l][st] = w;
        st++;
    }
    /* through a local: the name lives in *f too, which -Wrestrict flags */
    char file[sizeof f->line_file[l]];
    snprintf(file, sizeof file, "line_%s", line->name);
    memcpy(f->line_file[l], file, sizeof file);
    return NSPD_OK;
}

static int build(PddoFlow *f) {
    const double t0 = nspd_wall_time();
    if (f->cfg.body_count > 0) {
        f->cfg.cloud.holes = f->cfg.bodies;
        f->cfg.cloud.nholes = f->cfg.body_count;
        f->cfg.cloud.polar = f->cfg.polar;
    }
    TRY(pddo_cloud_build(&f->cloud, &f->cfg.cloud));
    const PddoCloud *c = &f->cloud;
    if (f->validate_only) {
        /* `nspd check`: the operators' conditioning without their weights,
         * no pressure matrix (its assembly and factors cannot fail on a
         * cloud that passes; the run checks them) */
        TRY(pddo_ops_check(&f->ops, c->n, c->x, c->y, c->area, c->first, c->nbr, c->delta,
                           c->node_delta));
    } else {
        TRY(pddo_ops_build(&f->ops, c->n, c->x, c->y, c->area, c->first, c->nbr, c->delta,
                           c->node_delta,
                           &(PddoLattice){c->i, c->j, c->dx, c->patch, c->npatches}));
        if (comm_distributed(&f->comm)) TRY(pddo_share_init(&f->share, &f->ops, &f->comm));
        TRY(pddo_ppe_build_shared(&f->ppe, c, &f->ops, &f->share, &f->cfg.pressure));
        if (f->cfg.pressure_runs) TRY(pddo_ppe_use_runs(&f->ppe));
    }
    TRY(pddo_step_init(&f->step, c, &f->ops, &f->ppe, &f->cfg.step));
    pddo_step_share(&f->step, &f->share);
    for (int b = 0; b < c->npatches; b++) {
        TRY(pddo_forces_build(&f->forces[b], c, b));
        for (int k = 0; k < WALL_COLS; k++)
            TRY(nspd_alloc(&f->wall_col[b][k], (size_t)f->forces[b].m, sizeof(double)));
        char file[sizeof f->wall_file[b]]; /* through a local, as build_line's */
        if (b == 0)
            snprintf(file, sizeof file, "wall");
        else
            snprintf(file, sizeof file, "wall_%s", f->cfg.body_name[b]);
        memcpy(f->wall_file[b], file, sizeof file);
    }
    f->setup_s = nspd_wall_time() - t0;
    for (int64_t k = 0; k < c->n; k++)
        if (pddo_node_physical(c->kind[k])) f->physical++;
    TRY(nspd_alloc(&f->phys, (size_t)f->physical, sizeof(int64_t)));
    int64_t m = 0;
    for (int64_t k = 0; k < c->n; k++)
        if (pddo_node_physical(c->kind[k])) f->phys[m++] = k;
    for (int k = 0; k < OUT_ARRAYS; k++)
        TRY(nspd_alloc(&f->out[k], (size_t)f->physical, sizeof(double)));
    for (int k = 0; k < NODE_ARRAYS; k++)
        TRY(nspd_alloc(&f->node[k], (size_t)c->n, sizeof(double)));
    TRY(nspd_alloc(&f->sorted, (size_t)f->physical, sizeof(double)));
    TRY(nspd_alloc(&f->weight, (size_t)f->physical, sizeof(double)));
    for (int64_t q = 0; q < f->physical; q++) {
        const int64_t k = f->phys[q];
        f->weight[q] = c->area[k];
        for (int s = 0; s < PDDO_SIDES; s++)
            if ((unsigned)c->sides[k] >> s & 1u) f->weight[q] *= 0.5;
        if (c->kind[k] == PDDO_NODE_WALL) f->weight[q] *= 0.5; /* half in the body */
        f->out[OX][q] = c->x[k], f->out[OY][q] = c->y[k];
        f->out[OK_KIND][q] = c->kind[k];
    }
    for (int l = 0; l < f->cfg.line_count; l++) TRY(build_line(f, l));
    return NSPD_OK;
}

static int pddo_create(void **impl, FlowConfig *fc) {
    PddoFlow *f;
    TRY(nspd_alloc(&f, 1, sizeof *f));
    f->cfg = *(PddoFlowConfig *)fc->model;
    nspd_free(&fc->model);                  /* taken */
    f->cfg.average_from = fc->average_from; /* the driver's, as a coupling's */
    f->validate_only = fc->validate_only;
    f->steady_step = -1;
    f->comm = fc->comm && fc->comm->size > 0 ? *fc->comm : comm_self(); /* borrowed during create */
    int status = NSPD_OK;
    if (comm_distributed(&f->comm) && fc->processes[0] > 0 && fc->processes[1] != 1)
        status = NSPD_FAIL(NSPD_ERR_INPUT,
                           "--processes %dx%d: the PDDO flow divides its node list into ranges "
                           "of equal work, not a grid; expected --processes %d (or %dx1)",
                           fc->processes[0], fc->processes[1], f->comm.size, f->comm.size);
    if (status == NSPD_OK) status = build(f);
    if (status != NSPD_OK) {
        pddo_destroy(f);
        return status;
    }
    *impl = f;
    return NSPD_OK;
}

/* The case's step: given (checked against the limit when the case was
 * read) or half the limit; constant, so the driver never warns. */
static double pddo_stable_dt(const void *impl) {
    return ((const PddoFlow *)impl)->cfg.step.dt;
}

/* The lift below which a crossing does not arm: |cl| = 1e-3 (round-off
 * lifts of a symmetric steady flow, ~1e-13 N/m, never count). */
static double lift_threshold(const PddoFlow *f) {
    const PddoFlowConfig *c = &f->cfg;
    return 1e-3 * 0.5 * c->step.rho * c->reference_velocity * c->reference_velocity *
           c->reference_length;
}

/* The six parts of a force in the order of BodyRecord.sum. */
static void force_parts(const PddoForce *F, double part[6]) {
    part[0] = F->fx, part[1] = F->fy, part[2] = F->fx_pressure;
    part[3] = F->fx_viscous, part[4] = F->fy_pressure, part[5] = F->fy_viscous;
}

/* From average_from on: the record's dt-weighted sums and the lift's
 * periods (pddo_lift_periods_add). */
static void record_add(BodyRecord *r, double t, double dt, double threshold) {
    double part[6];
    force_parts(&r->force, part);
    for (int k = 0; k < 6; k++) r->sum[k] += part[k] * dt;
    r->lift.threshold = threshold;
    pddo_lift_periods_add(&r->lift, t, r->force.fy);
}

/* Each body's force after a step of dt; from average_from on the records. */
static void record_force(PddoFlow *f, double dt) {
    const int nb = f->cloud.npatches;
    for (int b = 0; b < nb; b++)
        f->body[b].force = pddo_forces_eval(&f->forces[b], PDDO_TRACTION_FLUID_SIDE, NULL,
                                            f->step.u, f->step.v, f->step.p, f->cfg.step.mu);
    const double t = f->step.time;
    if (t < f->cfg.average_from) return;
    f->averaged_s += dt;
    const double threshold = lift_threshold(f);
    for (int b = 0; b < nb; b++) record_add(&f->body[b], t, dt, threshold);
}

/* The prefix of body b's history columns and summary keys: none for the
 * first, "<name>_" for the others (the GKS flow's rule, couple/
 * couple/ghost/model.c). */
static void body_prefix(const PddoFlow *f, int b, char *buf, size_t size) {
    if (b == 0)
        buf[0] = '\0';
    else
        snprintf(buf, size, "%s_", f->cfg.body_name[b]);
}

static int pddo_step(void *impl, double dt) {
    PddoFlow *f = impl;
    f->step.par.dt = dt; /* the driver shortens the last step to land on the end time */
    TRY(pddo_step_advance(&f->step));
    if (f->cloud.npatches > 0) record_force(f, dt);
    if (f->steady_step < 0 && f->cfg.steady_tolerance > 0.0 &&
        f->step.dudt_max < f->cfg.steady_tolerance)
        f->steady_step = f->step.steps;
    return NSPD_OK;
}

static double pddo_time(const void *impl) {
    return ((const PddoFlow *)impl)->step.time;
}

static bool pddo_finished(const void *impl) {
    return ((const PddoFlow *)impl)->steady_step >= 0;
}

static FlowMesh pddo_mesh(const void *impl) {
    (void)impl;
    return (FlowMesh){MESH_POINTS};
}

/* Nothing the configuration points to is owned (fixed-size members). */
static void pddo_config_free(void *model) {
    (void)model;
}

static void pddo_cell_state(const void *impl, int64_t node, double out[5]) {
    const PddoFlow *f = impl;
    out[0] = f->cfg.step.rho;
    out[1] = f->step.u[node];
    out[2] = f->step.v[node];
    out[3] = f->step.p[node];
    out[4] = 0.0; /* incompressible: no temperature */
}

/* A point probe: its interpolation stencil (flow/pddo/sample.h). */
static int pddo_probe_add(void *impl, const char *name, double x, double y, int64_t *id) {
    PddoFlow *f = impl;
    TRY(pddo_sample_add(&f->probes, &f->cloud, x, y, name));
    *id = f->probes.n - 1;
    return NSPD_OK;
}

static void pddo_probe_state(const void *impl, int64_t id, double out[5]) {
    const PddoFlow *f = impl;
    out[0] = f->cfg.step.rho;
    out[1] = pddo_sample_at(&f->probes, f->step.u, id);
    out[2] = pddo_sample_at(&f->probes, f->step.v, id);
    out[3] = pddo_sample_at(&f->probes, f->step.p, id);
    out[4] = (double)NAN; /* incompressible: no temperature */
}

static FlowReference pddo_reference(const void *impl) {
    const PddoFlow *f = impl;
    return (FlowReference){
        .rho = f->cfg.step.rho, .u = f->cfg.reference_velocity, .length = f->cfg.reference_length};
}

static void pddo_totals(const void *impl, double totals[4]) {
    const PddoFlow *f = impl;
    const double rho = f->cfg.step.rho;
    double *t = f->node[TERM];
    double sum[4] = {0, 0, 0, 0};
    for (int what = 0; what < 4; what++) {
        for (int64_t q = 0; q < f->physical; q++) {
            const int64_t k = f->phys[q];
            const double u = f->step.u[k], v = f->step.v[k];
            const double term = what == 0   ? 1.0
                                : what == 1 ? u
                                : what == 2 ? v
                                            : 0.5 * (u * u + v * v);
            t[q] = rho * term * f->weight[q];
        }
        sum[what] = reduce_sum(t, f->physical);
    }
    memcpy(totals, sum, sizeof sum);
}

/* max |div u| over the fluid nodes (the sides' nodes hold prescribed
 * velocities) of the current state; the velocity gradients into node[]
 * (on several processes each rank's own nodes', and to every rank with
 * `whole`). Collective there. */
static double max_divergence(const PddoFlow *f, bool whole) {
    const PddoCloud *c = &f->cloud;
    double *const *g = f->node;
    pddo_ops_apply(&f->ops, PDDO_D_X, f->step.u, g[GUX]);
    pddo_ops_apply(&f->ops, PDDO_D_Y, f->step.u, g[GUY]);
    pddo_ops_apply(&f->ops, PDDO_D_X, f->step.v, g[GVX]);
    pddo_ops_apply(&f->ops, PDDO_D_Y, f->step.v, g[GVY]);
    int64_t lo, hi;
    pddo_share_nodes(&f->share, c->n, &lo, &hi);
    double m = 0.0;
    for (int64_t k = lo; k < hi; k++)
        if (c->kind[k] == PDDO_NODE_FLUID) m = fmax(m, fabs(g[GUX][k] + g[GVY][k]));
    if (!pddo_share_divided(&f->share)) return m;
    for (int a = GUX; whole && a <= GVY; a++) (void)pddo_share(&f->share, g[a], false);
    return comm_max(&f->comm, m); /* a max is exact */
}

static double dynamic_pressure(const PddoFlow *f) {
    return 0.5 * f->cfg.step.rho * f->cfg.reference_velocity * f->cfg.reference_velocity;
}

/* A body's history columns, their names prefixed (body_prefix). */
static void history_force(Report *row, const char *prefix, const PddoForce *F, const PddoFlow *f) {
    const double qL = dynamic_pressure(f) * f->cfg.reference_length;
    char name[REPORT_MAX_NAME];
#define COLUMN(report, key, value)                                                                 \
    (snprintf(name, sizeof name, "%s%s", prefix, key), report(row, name, value))
    COLUMN(report_precise, "drag_n", F->fx);
    COLUMN(report_precise, "lift_n", F->fy);
    COLUMN(report_real, "drag_pressure_n", F->fx_pressure);
    COLUMN(report_real, "drag_viscous_n", F->fx_viscous);
    COLUMN(report_real, "lift_pressure_n", F->fy_pressure);
    COLUMN(report_real, "lift_viscous_n", F->fy_viscous);
    COLUMN(report_precise, "cd", F->fx / qL);
    COLUMN(report_precise, "cl", F->fy / qL);
#undef COLUMN
}

/* The flow rate per metre of depth (m^2/s) through side s into the
 * rectangle: the normal velocity over the side's nodes by the trapezoid
 * rule (the side's end nodes half weight), the same rule the line tables'
 * users apply. */
static double side_flow_rate(const PddoFlow *f, int s) {
    const PddoCloud *c = &f->cloud;
    const int across = s < PDDO_BOTTOM ? c->ny : c->nx; /* intervals along the side */
    const int at = s == PDDO_LEFT || s == PDDO_BOTTOM ? 0 : (s == PDDO_RIGHT ? c->nx : c->ny);
    const double into = s % 2 == 0 ? 1.0 : -1.0;
    const double *vel = s < PDDO_BOTTOM ? f->step.u : f->step.v;
    double q = 0.0;
    for (int t = 0; t <= across; t++) {
        const int64_t k = s < PDDO_BOTTOM ? pddo_cloud_node(c, at, t) : pddo_cloud_node(c, t, at);
        if (k < 0) continue;
        q += (t == 0 || t == across ? 0.5 : 1.0) * vel[k];
    }
    return into * q * c->dx;
}

static void pddo_history(const void *impl, Report *row) {
    const PddoFlow *f = impl;
    double totals[4];
    pddo_totals(f, totals);
    report_real(row, "dt_s", f->step.steps > 0 ? f->step.par.dt : 0.0);
    report_precise(row, "dudt_max_m_per_s2", f->step.dudt_max);
    report_precise(row, "kinetic_energy_J_per_m", totals[3]);
    report_precise(row, "momentum_x_kg_per_s", totals[1]);
    report_precise(row, "momentum_y_kg_per_s", totals[2]);
    report_real(row, "div_max_per_s", max_divergence(f, false));
    report_real(row, "ppe_shift", f->ppe.shift);
    /* the inlet's and the outlets' flow rates: the scheme's mass balance */
    double in = 0.0, out = 0.0;
    bool has_in = false, has_out = false;
    for (int s = 0; s < PDDO_SIDES; s++) {
        if (f->cloud.side[s] == PDDO_SIDE_INLET) in += side_flow_rate(f, s), has_in = true;
        if (f->cloud.side[s] == PDDO_SIDE_OUTLET) out -= side_flow_rate(f, s), has_out = true;
    }
    if (has_in) report_precise(row, "inflow_m2_per_s", in);
    if (has_out) report_precise(row, "outflow_m2_per_s", out);
    for (int b = 0; b < f->cloud.npatches; b++) {
        char prefix[PDDO_LINE_NAME + 1];
        body_prefix(f, b, prefix, sizeof prefix);
        history_force(row, prefix, &f->body[b].force, f);
    }
}

/* A body's summary keys, their names prefixed (body_prefix): the
 * means over the window (the last step's force when the run ended, steady,
 * before it began) and the lift's periods. */
static void summary_force(Report *out, const char *prefix, const BodyRecord *r, const PddoFlow *f) {
    const double qL = dynamic_pressure(f) * f->cfg.reference_length;
    const double T = f->averaged_s > 0.0 ? f->averaged_s : 1.0;
    double last[6];
    force_parts(&r->force, last);
    const double *m = f->averaged_s > 0.0 ? r->sum : last;
    char name[REPORT_MAX_NAME];
#define KEY(report, key, value)                                                                    \
    (snprintf(name, sizeof name, "%s%s", prefix, key), report(out, name, value))
    KEY(report_real, "drag_n", m[0] / T);
    KEY(report_real, "lift_n", m[1] / T);
    KEY(report_real, "drag_pressure_n", m[2] / T);
    KEY(report_real, "drag_viscous_n", m[3] / T);
    KEY(report_real, "lift_pressure_n", m[4] / T);
    KEY(report_real, "lift_viscous_n", m[5] / T);
    KEY(report_real, "cd", m[0] / T / qL);
    KEY(report_real, "cl", m[1] / T / qL);
    double period, amp;
    const int64_t periods = pddo_lift_periods_result(&r->lift, &period, &amp);
    KEY(report_int, "lift_periods", periods);
    if (periods > 0) {
        KEY(report_real, "lift_amplitude_n", amp);
        KEY(report_real, "cl_amplitude", amp / qL);
        KEY(report_real, "period_s", period);
        KEY(report_real, "strouhal",
            f->cfg.reference_length / (period * f->cfg.reference_velocity));
    }
#undef KEY
}

static void pddo_summary(const void *impl, const RunStats *run, Report *out) {
    const PddoFlow *f = impl;
    const PddoCloud *c = &f->cloud;
    double totals[4];
    pddo_totals(f, totals);
    report_int(out, "nodes", c->n);
    report_int(out, "physical_nodes", f->physical);
    report_int(out, "intervals_x", c->nx);
    report_int(out, "intervals_y", c->ny);
    report_int(out, "family_members", c->first[c->n]);
    report_int(out, "ppe_nonzeros", f->ppe.nnz);
    report_real(out, "factor_nonzeros", f->ppe.factor_nnz);
    report_real(out, "factor_mb", f->ppe.factor_bytes / 1e6);
    report_real(out, "setup_s", f->setup_s); /* the cloud, operators and the solver's setup */
    report_real(out, "pressure_solve_s", f->ppe.solve_s);
    if (f->cfg.pressure.petsc) /* Krylov iterations over the run's solves (1 each: mumps) */
        report_int(out, "pressure_iterations", f->ppe.petsc.iterations_total);
    if (pddo_share_divided(&f->share)) /* the shares of each step and of the solve */
        report_real(out, "exchange_s", f->step.share_s + f->ppe.share_s);
    report_real(out, "dt_s", f->step.par.dt);
    report_real(out, "dt_limit_s", pddo_flow_dt_limit(&f->cfg));
    report_real(out, "reynolds",
                f->cfg.step.rho * f->cfg.reference_velocity * f->cfg.reference_length /
                    f->cfg.step.mu);
    report_bool(out, "steady", f->steady_step >= 0);
    report_int(out, "steady_step", f->steady_step);
    report_real(out, "dudt_max_m_per_s2", f->step.dudt_max);
    report_real(out, "kinetic_energy_J_per_m", totals[3]);
    report_real(out, "div_max_per_s", max_divergence(f, false));
    const int nb = f->cloud.npatches;
    if (nb > 0) {
        report_real(out, "average_from_s", f->cfg.average_from);
        report_real(out, "averaged_s", f->averaged_s);
    }
    for (int b = 0; b < nb; b++) {
        char prefix[PDDO_LINE_NAME + 1];
        body_prefix(f, b, prefix, sizeof prefix);
        summary_force(out, prefix, &f->body[b], f);
    }
    report_real(out, "node_updates_per_s",
                run->wall_s > 0 ? (double)c->n * (double)run->steps / run->wall_s : 0.0);
}

static void pddo_info(const void *impl, size_t memory, char *buf, size_t size) {
    const PddoFlow *f = impl;
    const PddoCloud *c = &f->cloud;
    const PddoFlowConfig *cfg = &f->cfg;
    static const char *const KIND[] = {"wall", "inlet", "outlet", "periodic"};
    int len = 0;
#define APPEND(...)                                                                                \
    len += snprintf(buf + len, size > (size_t)len ? size - (size_t)len : 0, __VA_ARGS__)
    APPEND(
        "PDDO rectangle       [%.6g, %.6g] x [%.6g, %.6g] m, spacing %.4g m, %d x %d intervals\n",
        cfg->cloud.lo[0], cfg->cloud.hi[0], cfg->cloud.lo[1], cfg->cloud.hi[1], c->dx, c->nx,
        c->ny);
    APPEND("nodes                %lld (%lld physical, %d fictitious layers), horizon %.3g dx, "
           "%.1f neighbours per node\n",
           (long long)c->n, (long long)f->physical, c->layers, cfg->cloud.horizon_factor,
           (double)c->first[c->n] / (double)c->n);
    for (int b = 0; b < c->npatches; b++) {
        const PddoPolarPatch *p = &c->patch[b];
        const double wall = c->node_delta[p->first + (int64_t)p->rings_inside * p->ntheta];
        APPEND("polar patch %-8d %d rings of %d (%d fictitious), dr %.4g m, dtheta %.4g rad, to "
               "%.4g m; horizon %s, %.4g m on the wall ring\n",
               b, p->rings, p->ntheta, p->rings_inside, p->dr, p->dtheta, p->r_out,
               p->local_horizon > 0.0 ? "local" : "the lattice's", wall);
    }
    {
        const PddoOps *ops = &f->ops;
        const int64_t slices = pddo_ops_slices(ops);
        int64_t turned = 0;
        for (int64_t s = 0; s < slices; s++)
            turned += ops->slice_tpl[s] >= 0 && ops->tpl_turned[ops->slice_tpl[s]];
        APPEND("operators            %lld of %lld slices of %d nodes on %d templates (%lld of "
               "them turned on polar rings), %.1f MB of weights in the rest\n",
               (long long)ops->templated, (long long)slices, PDDO_LANES, ops->templates,
               (long long)turned, 36e-6 * (double)ops->slice_first[slices]);
    }
    APPEND("sides                left %s, right %s, bottom %s, top %s; wall ghosts %s; "
           "(rho/dt) div u on %s\n",
           KIND[c->side[0]], KIND[c->side[1]], KIND[c->side[2]], KIND[c->side[3]],
           cfg->step.walls == PDDO_WALL_ANTISYMMETRIC ? "antisymmetric" : "paper (zero)",
           cfg->step.divergence == PDDO_DIVERGENCE_UPDATED ? "the updated nodes' rows"
                                                           : "every PPE row (paper)");
    APPEND("fluid                rho %.6g kg/m^3, mu %.6g Pa s, Re %.6g (U %.4g m/s, L %.4g m)\n",
           cfg->step.rho, cfg->step.mu,
           cfg->step.rho * cfg->reference_velocity * cfg->reference_length / cfg->step.mu,
           cfg->reference_velocity, cfg->reference_length);
    APPEND("time step            %.6g s (stable limit %.6g s)\n", cfg->step.dt,
           pddo_flow_dt_limit(cfg));
    if (cfg->step.spin_speed != 0.0)
        APPEND("seed                 the bodies' walls turn at %.4g m/s (counterclockwise "
               "positive) until t = %.4g s\n",
               cfg->step.spin_speed, cfg->step.spin_until);
    const char *level = f->ppe.pinned >= 0 ? "level pinned" : "level fixed by the outlet";
    const PddoPpeSolver *solver = &f->ppe.solver;
    if (solver->petsc && solver->method == PPE_PETSC_MUMPS)
        APPEND("pressure equation    %lld nonzeros, MUMPS on PETSc: L+U %.4g nonzeros, %.1f MB "
               "over every process, %s, set up in %.2f s\n",
               (long long)f->ppe.nnz, f->ppe.factor_nnz, f->ppe.factor_bytes / 1e6, level,
               f->setup_s);
    else if (solver->petsc)
        APPEND("pressure equation    %lld nonzeros, BiCGStab with BoomerAMG on PETSc to a "
               "relative residual of %.3g, %s, set up in %.2f s\n",
               (long long)f->ppe.nnz, solver->tolerance, level, f->setup_s);
    else
        APPEND("pressure equation    %lld nonzeros, L+U %.4g nonzeros (%.1f MB), rcond %.2g, %s, "
               "set up in %.2f s\n",
               (long long)f->ppe.nnz, f->ppe.factor_nnz, f->ppe.factor_bytes / 1e6, f->ppe.rcond,
               level, f->setup_s);
    if (solver->petsc) {
        APPEND("memory               %.1f MB in arrays (%.0f bytes per node); PETSc's matrix "
               "and solver beside them\n",
               (double)memory / 1e6, (double)memory / (double)c->n);
    } else if (f->ppe.runs) {
        APPEND("memory               %.1f MB in arrays (%.0f bytes per node), the LU factors by "
               "runs (%.1f MB) among them\n",
               (double)memory / 1e6, (double)memory / (double)c->n,
               8e-6 * (double)(lu_runs_entries(&f->ppe.runs_u) + lu_runs_entries(&f->ppe.runs_l)));
        APPEND("two-thread solve     %lld stages of independent parts: %.2f of one thread's "
               "entries on the longer path\n",
               (long long)f->ppe.runs_u.stages - 1, f->ppe.two_thread_share);
    } else {
        APPEND("memory               %.1f MB in arrays (%.0f bytes per node) and %.1f MB of LU "
               "factors\n",
               (double)memory / 1e6, (double)memory / (double)c->n, f->ppe.factor_bytes / 1e6);
    }
#undef APPEND
}

static void pddo_brief(const void *impl, char *buf, size_t size) {
    const PddoFlow *f = impl;
    snprintf(buf, size, "%lld PDDO nodes, ", (long long)f->cloud.n);
}

static int64_t pddo_fallbacks_total(const void *impl) {
    (void)impl;
    return 0;
}

static int compare_double(const void *a, const void *b) {
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The 1st and 99th percentiles of v (n values): a picture's range that
 * the singular corners of a cavity or an inlet do not swamp. */
static void range(PddoFlow *f, const double *v, int64_t n, double *lo, double *hi) {
    memcpy(f->sorted, v, (size_t)n * sizeof *v);
    qsort(f->sorted, (size_t)n, sizeof *f->sorted, compare_double);
    *lo = f->sorted[n / 100];
    *hi = f->sorted[n - 1 - n / 100];
    if (!(*hi > *lo)) *hi = *lo + 1.0;
}

/* Body b's wall table: per wall node, counterclockwise from theta = 0
 * (the +x side), its angle, position, pressure, wall shear stress and
 * traction sigma n on the body (forces.h; the forces' fluid-side
 * derivatives). */
static void wall_table(PddoFlow *f, int b, TableRef *t) {
    const PddoForces *F = &f->forces[b];
    const PddoPolarPatch *pp = &f->cloud.patch[b];
    double *const *col = f->wall_col[b];
    for (int32_t r = 0; r < F->m; r++) {
        const PddoWallTraction w = pddo_forces_traction(
            F, PDDO_TRACTION_FLUID_SIDE, NULL, f->step.u, f->step.v, f->step.p, f->cfg.step.mu, r);
        const int64_t k = F->wall + r;
        col[0][r] = (double)r * pp->dtheta * (180.0 / M_PI);
        col[1][r] = f->cloud.x[k], col[2][r] = f->cloud.y[k];
        col[3][r] = w.p;
        col[4][r] = w.viscous_y * w.nx - w.viscous_x * w.ny;
        col[5][r] = w.viscous_x - w.p * w.nx, col[6][r] = w.viscous_y - w.p * w.ny;
    }
    *t = (TableRef){.file = f->wall_file[b],
                    .header = "theta_deg,x,y,p,wall_shear,traction_x,traction_y",
                    .rows = F->m,
                    .ncol = WALL_COLS};
    for (int k = 0; k < WALL_COLS; k++) t->col[k] = col[k];
}

static void pddo_fields(void *impl, FieldSet *out) {
    PddoFlow *f = impl;
    const PddoCloud *c = &f->cloud;
    double *const *o = f->out;
    double *const *g = f->node;
    max_divergence(f, true); /* the velocity gradients into node[] */
    for (int64_t q = 0; q < f->physical; q++) {
        const int64_t k = f->phys[q];
        const double u = f->step.u[k], v = f->step.v[k];
        o[OU][q] = u, o[OV][q] = v, o[OP][q] = f->step.p[k];
        o[OW][q] = g[GVX][k] - g[GUY][k];
        o[OD][q] = g[GUX][k] + g[GVY][k];
        o[OS][q] = hypot(u, v);
    }
    memset(out, 0, sizeof *out);
    out->series = "flow";
    out->mesh = MESH_POINTS;
    out->n = f->physical;
    out->dim = 2;
    out->position[0] = o[OX];
    out->position[1] = o[OY];
    out->spacing = c->dx;
    const FieldRef fields[] = {
        {"velocity", 3, {o[OU], o[OV], NULL}}, {"pressure", 1, {o[OP], NULL, NULL}},
        {"vorticity", 1, {o[OW], NULL, NULL}}, {"divergence", 1, {o[OD], NULL, NULL}},
        {"speed", 1, {o[OS], NULL, NULL}},     {"node_kind", 1, {o[OK_KIND], NULL, NULL}},
    };
    for (size_t k = 0; k < sizeof fields / sizeof fields[0]; k++)
        out->field[out->field_count++] = fields[k];
    double plo, phi, wlo, whi;
    range(f, o[OP], f->physical, &plo, &phi);
    range(f, o[OW], f->physical, &wlo, &whi);
    const double wmax = fmax(fabs(wlo), fabs(whi));
    out->picture[out->picture_count++] = (PictureRef){.file = "speed",
                                                      .label = "speed",
                                                      .units = "m/s",
                                                      .values = o[OS],
                                                      .lo = 0.0,
                                                      .hi = 1.1 * f->cfg.velocity_scale,
                                                      .map = COLORMAP_VIRIDIS};
    out->picture[out->picture_count++] = (PictureRef){.file = "pressure",
                                                      .label = "pressure (1st-99th percentile)",
                                                      .units = "Pa",
                                                      .values = o[OP],
                                                      .lo = plo,
                                                      .hi = phi,
                                                      .map = COLORMAP_VIRIDIS};
    out->picture[out->picture_count++] = (PictureRef){.file = "vorticity",
                                                      .label = "vorticity (to the 99th percentile)",
                                                      .units = "1/s",
                                                      .values = o[OW],
                                                      .lo = -wmax,
                                                      .hi = wmax,
                                                      .map = COLORMAP_INFERNO};
    for (int l = 0; l < f->cfg.line_count; l++) {
        double *const *col = f->line_col[l];
        for (int64_t r = 0; r < f->line_rows[l]; r++) {
            const int32_t a = f->line_a[l][r], b = f->line_b[l][r];
            const double w = f->line_w[l][r], w0 = 1.0 - w;
            col[0][r] = w0 * c->x[a] + w * c->x[b];
            col[1][r] = w0 * c->y[a] + w * c->y[b];
            col[2][r] = w0 * f->step.u[a] + w * f->step.u[b];
            col[3][r] = w0 * f->step.v[a] + w * f->step.v[b];
            col[4][r] = w0 * f->step.p[a] + w * f->step.p[b];
        }
        TableRef *t = &out->table[out->table_count++];
        *t = (TableRef){.file = f->line_file[l],
                        .header = "x,y,u,v,p",
                        .rows = f->line_rows[l],
                        .ncol = LINE_COLS};
        for (int k = 0; k < LINE_COLS; k++) t->col[k] = col[k];
    }
    for (int b = 0; b < c->npatches; b++) wall_table(f, b, &out->table[out->table_count++]);
}

/* A body's force record. */
static int checkpoint_record(Checkpoint *ck, BodyRecord *r) {
    int64_t six = 6;
    TRY(checkpoint_io_array(ck, "pddo.force_sum", r->sum, sizeof(double), &six, 6));
    PddoLiftPeriods *lp = &r->lift;
    PddoForce *F = &r->force;
    double *const d[] = {&F->fx,          &F->fy,         &F->fx_pressure, &F->fx_viscous,
                         &F->fy_pressure, &F->fy_viscous, &lp->prev_t,     &lp->prev,
                         &lp->first_t,    &lp->last_t,    &lp->run_max,    &lp->run_min,
                         &lp->amp_max,    &lp->amp_min};
    static const char *const name[] = {
        "pddo.fx",      "pddo.fy",          "pddo.fx_p",      "pddo.fx_v",    "pddo.fy_p",
        "pddo.fy_v",    "pddo.lift_prev_t", "pddo.lift_prev", "pddo.cross_0", "pddo.cross_last",
        "pddo.run_max", "pddo.run_min",     "pddo.amp_max",   "pddo.amp_min"};
    for (size_t k = 0; k < sizeof d / sizeof d[0]; k++)
        TRY(checkpoint_io_double(ck, name[k], d[k]));
    TRY(checkpoint_io_int64(ck, "pddo.lift_samples", &lp->samples));
    TRY(checkpoint_io_int64(ck, "pddo.crossings", &lp->crossings));
    return checkpoint_io_int64(ck, "pddo.armed", &lp->armed);
}

/* Everything a step changes: the velocity and pressure of every node, the
 * clock, the last step's rate and the steady-state mark. */
static int pddo_checkpoint(void *impl, Checkpoint *ck) {
    PddoFlow *f = impl;
    const int64_t n = f->cloud.n;
    int64_t count = n;
    TRY(checkpoint_io_array(ck, "pddo.u", f->step.u, sizeof(double), &count, n));
    TRY(checkpoint_io_array(ck, "pddo.v", f->step.v, sizeof(double), &count, n));
    TRY(checkpoint_io_array(ck, "pddo.p", f->step.p, sizeof(double), &count, n));
    if (count != n)
        return NSPD_FAIL(NSPD_ERR_INPUT, "checkpoint: %lld PDDO nodes; the case has %lld",
                         (long long)count, (long long)n);
    TRY(checkpoint_io_double(ck, "pddo.time", &f->step.time));
    TRY(checkpoint_io_int64(ck, "pddo.steps", &f->step.steps));
    TRY(checkpoint_io_double(ck, "pddo.dt", &f->step.par.dt));
    TRY(checkpoint_io_double(ck, "pddo.dudt_max", &f->step.dudt_max));
    TRY(checkpoint_io_double(ck, "pddo.shift", &f->ppe.shift));
    const int nb = f->cloud.npatches;
    if (nb > 0) TRY(checkpoint_io_double(ck, "pddo.averaged_s", &f->averaged_s));
    for (int b = 0; b < nb; b++) TRY(checkpoint_record(ck, &f->body[b]));
    return checkpoint_io_int64(ck, "pddo.steady_step", &f->steady_step);
}

const FlowOps PDDO_FLOW_OPS = {
    .name = "pddo",
    .distributed = true,
    .config_free = pddo_config_free,
    .estimate = pddo_estimate,
    .validate = pddo_validate,
    .create = pddo_create,
    .destroy = pddo_destroy,
    .stable_dt = pddo_stable_dt,
    .step = pddo_step,
    .time = pddo_time,
    .finished = pddo_finished,
    .mesh = pddo_mesh,
    .cell_state = pddo_cell_state,
    .reference = pddo_reference,
    .sample = NULL,
    .set_sources = NULL,
    .probe_add = pddo_probe_add,
    .probe_state = pddo_probe_state,
    .totals = pddo_totals,
    .history = pddo_history,
    .summary = pddo_summary,
    .info = pddo_info,
    .brief = pddo_brief,
    .fallbacks_total = pddo_fallbacks_total,
    .fields = pddo_fields,
    .checkpoint = pddo_checkpoint,
};
