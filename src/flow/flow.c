#include "flow/flow.h"

#include "core/mem.h"
#include "core/status.h"

#include <math.h>
#include <string.h>

/* The built-in solvers' ops tables, each defined in its own folder
 * (flow/gks/model.c, flow/pddo/model.c): the one place the interface names
 * a model, by declaration only, so no model header is in its include tree. */
extern const FlowOps GKS_FLOW_OPS, PDDO_FLOW_OPS, IGA_FLOW_OPS;

/* The registry: one ops table per FlowMethod; flow_register fills the
 * slots after the built-in ones. */
static const FlowOps *FLOW_METHODS[FLOW_METHOD_MAX] = {
    [FLOW_METHOD_GKS] = &GKS_FLOW_OPS,
    [FLOW_METHOD_PDDO] = &PDDO_FLOW_OPS,
    [FLOW_METHOD_IGA] = &IGA_FLOW_OPS,
};

FlowMethod flow_register(const FlowOps *ops) {
    for (int m = FLOW_METHOD_COUNT; m < FLOW_METHOD_MAX; m++)
        if (!FLOW_METHODS[m] || FLOW_METHODS[m] == ops) {
            FLOW_METHODS[m] = ops;
            return (FlowMethod)m;
        }
    return FLOW_METHOD_NONE;
}

struct Flow {
    const FlowOps *ops;
    FlowMethod method;
    void *impl;
};

/* The ops table of a method, or NULL for none or an unknown one. */
static const FlowOps *method_ops(FlowMethod method) {
    return method > FLOW_METHOD_NONE && method < FLOW_METHOD_MAX ? FLOW_METHODS[method] : NULL;
}

void flow_config_free(FlowConfig *cfg) {
    const FlowOps *ops = method_ops(cfg->method);
    if (cfg->model && ops && ops->config_free) {
        ops->config_free(cfg->model);
        nspd_free(&cfg->model);
    }
    memset(cfg, 0, sizeof *cfg);
}

FlowEstimate flow_estimate(const FlowConfig *cfg) {
    const FlowEstimate none = {0};
    const FlowOps *ops = method_ops(cfg->method);
    if (!ops || !ops->estimate) return none;
    return ops->estimate(cfg);
}

int flow_validate(const FlowConfig *cfg) {
    const FlowOps *ops = method_ops(cfg->method);
    return ops && ops->validate ? ops->validate(cfg) : NSPD_OK;
}

int flow_bench(const char *name, long size, long steps, Report *out, bool *found) {
    *found = false;
    for (int m = FLOW_METHOD_NONE + 1; m < FLOW_METHOD_MAX; m++) {
        const FlowOps *ops = FLOW_METHODS[m];
        if (ops && ops->bench && ops->bench_name && strcmp(ops->bench_name, name) == 0) {
            *found = true;
            return ops->bench(size, steps, out);
        }
    }
    return NSPD_OK;
}

int flow_create(Flow **out, FlowConfig *cfg) {
    *out = NULL;
    if (!method_ops(cfg->method))
        return NSPD_FAIL(NSPD_ERR_INPUT, "unknown flow solver %d", (int)cfg->method);
    const FlowOps *ops = method_ops(cfg->method);
    if (comm_distributed(cfg->comm) && !ops->distributed)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "the '%s' flow runs on one process, not on %d; expected a run without "
                         "mpirun (or mpirun -n 1)",
                         ops->name, cfg->comm->size);
    Flow *f;
    TRY(nspd_alloc(&f, 1, sizeof *f));
    f->method = cfg->method;
    f->ops = method_ops(cfg->method);
    int status = f->ops->create(&f->impl, cfg);
    if (status != NSPD_OK) {
        nspd_free(&f);
        return status;
    }
    *out = f;
    return NSPD_OK;
}

void flow_destroy(Flow **fp) {
    Flow *f = *fp;
    if (!f) return;
    if (f->impl) f->ops->destroy(f->impl);
    nspd_free(fp);
}

FlowMethod flow_method(const Flow *f) {
    return f->method;
}

const char *flow_name(const Flow *f) {
    return f->ops->name;
}

double flow_stable_dt(const Flow *f) {
    return f->ops->stable_dt(f->impl);
}

int flow_step(Flow *f, double dt) {
    return f->ops->step(f->impl, dt);
}

double flow_time(const Flow *f) {
    return f->ops->time(f->impl);
}

bool flow_finished(const Flow *f) {
    return f->ops->finished && f->ops->finished(f->impl);
}

FlowMesh flow_mesh(const Flow *f) {
    return f->ops->mesh(f->impl);
}

void flow_cell_state(const Flow *f, int64_t cell, double out[5]) {
    f->ops->cell_state(f->impl, cell, out);
}

int flow_cell_at(const Flow *f, const char *name, double x, double y, int64_t *cell) {
    if (!f->ops->cell_at)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "probe '%s': probes on the flow need a grid; the '%s' solver has none "
                         "(expected a point probe)",
                         name, f->ops->name);
    return f->ops->cell_at(f->impl, name, x, y, cell);
}

int flow_grid_line(const Flow *f, const char *name, int64_t through, int along, int64_t **cells,
                   int64_t *count) {
    if (!f->ops->grid_line)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "probe '%s': probes on the flow need a grid; the '%s' solver has none "
                         "(expected a point probe)",
                         name, f->ops->name);
    return f->ops->grid_line(f->impl, through, along, cells, count);
}

void flow_cell_centre(const Flow *f, int64_t cell, double xy[2]) {
    f->ops->cell_centre(f->impl, cell, xy);
}

FlowReference flow_reference(const Flow *f) {
    return f->ops->reference(f->impl);
}

int flow_sample(Flow *f, int64_t n, const double *x, const double *y, FlowSamples *out) {
    if (!f->ops->sample)
        return NSPD_FAIL(NSPD_ERR_INPUT, "the '%s' flow solver cannot be sampled at points",
                         f->ops->name);
    return f->ops->sample(f->impl, n, x, y, out);
}

int flow_set_sources(Flow *f, FlowSources *src) {
    if (!f->ops->set_sources)
        return NSPD_FAIL(NSPD_ERR_INPUT, "the '%s' flow solver takes no sources", f->ops->name);
    return f->ops->set_sources(f->impl, src);
}

const char *const FLOW_TRANSFER_NAMES[] = {"nearest", "bilinear", "quadratic", NULL};

int flow_transfer_width(FlowTransferKind kind) {
    static const int WIDTH[FLOW_TRANSFER_KINDS] = {1, 4, 9};
    return kind >= 0 && kind < FLOW_TRANSFER_KINDS ? WIDTH[kind] : 0;
}

bool flow_has_transfer(const Flow *f) {
    return f->ops->transfer && f->ops->lumped && f->ops->lumped_volume && f->ops->add_lumped;
}

int flow_cell_owner(const Flow *f, int64_t cell) {
    return f->ops->cell_owner ? f->ops->cell_owner(f->impl, cell) : 0;
}

bool flow_point_near(const Flow *f, double x, double y, int margin) {
    return f->ops->point_near ? f->ops->point_near(f->impl, x, y, margin) : true;
}

void flow_transfer(const Flow *f, FlowTransferKind kind, int64_t n, const double *x,
                   const double *y, int64_t *cell, double *w) {
    f->ops->transfer(f->impl, kind, n, x, y, cell, w);
}

void flow_lumped(const Flow *f, int64_t n, const int64_t *cells, double *mass, double *momentum_x,
                 double *momentum_y) {
    f->ops->lumped(f->impl, n, cells, mass, momentum_x, momentum_y);
}

void flow_add_lumped(Flow *f, int64_t n, const int64_t *cells, const double *dmx, const double *dmy,
                     const double *de) {
    f->ops->add_lumped(f->impl, n, cells, dmx, dmy, de);
}

void flow_lumped_volume(const Flow *f, int64_t n, const int64_t *cells, double *volume) {
    f->ops->lumped_volume(f->impl, n, cells, volume);
}

bool flow_can_seal(const Flow *f) {
    return f->ops->seal != NULL;
}

int flow_seal(Flow *f, int64_t n, const int64_t *cells, const double *area, const double *u,
              const double *v, double fraction) {
    return f->ops->seal(f->impl, n, cells, area, u, v, fraction);
}

bool flow_has_point_probes(const Flow *f) {
    return f->ops->probe_add != NULL;
}

int flow_probe_add(Flow *f, const char *name, double x, double y, int64_t *id) {
    if (!f->ops->probe_add)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "probe '%s': point probes on the flow need a grid or a solver that "
                         "samples its nodes; the '%s' solver has neither",
                         name, f->ops->name);
    return f->ops->probe_add(f->impl, name, x, y, id);
}

void flow_probe_state(const Flow *f, int64_t id, double out[5]) {
    f->ops->probe_state(f->impl, id, out);
}

void flow_totals(const Flow *f, double totals[4]) {
    f->ops->totals(f->impl, totals);
}

void flow_history(const Flow *f, Report *row) {
    f->ops->history(f->impl, row);
}

void flow_summary(const Flow *f, const RunStats *run, Report *out) {
    f->ops->summary(f->impl, run, out);
}

void flow_info(const Flow *f, size_t memory_bytes, char *buf, size_t size) {
    f->ops->info(f->impl, memory_bytes, buf, size);
}

void flow_brief(const Flow *f, char *buf, size_t size) {
    f->ops->brief(f->impl, buf, size);
}

int64_t flow_fallbacks_total(const Flow *f) {
    return f->ops->fallbacks_total ? f->ops->fallbacks_total(f->impl) : 0;
}

void flow_fields(Flow *f, FieldSet *out) {
    f->ops->fields(f->impl, out);
}

int flow_checkpoint(Flow *f, Checkpoint *ck) {
    if (!f->ops->checkpoint)
        return NSPD_FAIL(NSPD_ERR_INPUT, "the flow solver '%s' cannot be checkpointed",
                         f->ops->name);
    return f->ops->checkpoint(f->impl, ck);
}

void *flow_impl(Flow *f, FlowMethod method) {
    return f && f->method == method ? f->impl : NULL;
}

/* 1.25 times a positive finite `largest`, rounded up to two significant
 * digits */
static double picture_top(double largest) {
    const double v = 1.25 * largest, unit = pow(10.0, floor(log10(v)) - 1.0);
    /* the 1e-12 keeps 1.25 * 2 = 2.5 at 2.5, not one unit above */
    return ceil(v / unit * (1.0 - 1e-12)) * unit;
}

double flow_mach_picture_top(double largest) {
    if (!(largest >= FLOW_MACH_AT_REST) || !isfinite(largest)) return 0.0;
    return picture_top(largest);
}

double flow_speed_picture_top(double largest_speed, double largest_mach) {
    if (flow_mach_picture_top(largest_mach) == 0.0) return 0.0;
    if (!(largest_speed > 0.0) || !isfinite(largest_speed)) return 0.0;
    return picture_top(largest_speed);
}
