#include "couple/coupling.h"

#include "core/mem.h"
#include "core/status.h"

#include <math.h>
#include <string.h>

/* The built-in couplings' ops tables, each defined in its own folder
 * (couple/ghost/model.c): the one place the interface names a coupling,
 * by declaration only, so no coupling header is in its include tree. */
extern const CouplingOps GHOST_COUPLING_OPS;
extern const CouplingOps PENALTY_COUPLING_OPS;

/* The registry: one ops table per CouplingKind; coupling_register fills
 * the slots after the built-in ones. */
static const CouplingOps *COUPLING_MODELS[COUPLING_KIND_MAX] = {
    [COUPLING_GHOST_CELL] = &GHOST_COUPLING_OPS,
    [COUPLING_PENALTY] = &PENALTY_COUPLING_OPS,
};

CouplingKind coupling_register(const CouplingOps *ops) {
    for (int k = COUPLING_KIND_COUNT; k < COUPLING_KIND_MAX; k++)
        if (!COUPLING_MODELS[k] || COUPLING_MODELS[k] == ops) {
            COUPLING_MODELS[k] = ops;
            return (CouplingKind)k;
        }
    return COUPLING_NONE;
}

struct Coupling {
    const CouplingOps *ops;
    CouplingKind kind;
    void *impl;
};

/* The ops table of a kind, or NULL for none or an unknown one. */
static const CouplingOps *kind_ops(CouplingKind kind) {
    return kind > COUPLING_NONE && kind < COUPLING_KIND_MAX ? COUPLING_MODELS[kind] : NULL;
}

bool coupling_divides_solid(CouplingKind kind) {
    const CouplingOps *ops = kind_ops(kind);
    return ops && ops->divided_solid;
}

void coupling_config_free(CouplingConfig *cfg) {
    const CouplingOps *ops = kind_ops(cfg->kind);
    if (cfg->model && ops && ops->config_free) {
        ops->config_free(cfg->model);
        nspd_free(&cfg->model);
    }
    memset(cfg, 0, sizeof *cfg);
}

CouplingEstimate coupling_estimate(const CouplingConfig *cfg, const FlowEstimate *flow) {
    const CouplingEstimate none = {0};
    const CouplingOps *ops = kind_ops(cfg->kind);
    if (!ops || !ops->estimate) return none;
    return ops->estimate(cfg, flow);
}

int coupling_create(Coupling **out, CouplingConfig *cfg, Solid *solid, Flow *flow) {
    *out = NULL;
    const CouplingOps *ops = kind_ops(cfg->kind);
    if (!ops) return NSPD_FAIL(NSPD_ERR_INPUT, "unknown coupling %d", (int)cfg->kind);
    if (!flow) return NSPD_FAIL(NSPD_ERR_INPUT, "the %s coupling needs a flow", ops->name);
    if (comm_distributed(cfg->comm) && !ops->distributed)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "the %s coupling runs on one process, not on %d; expected a run without "
                         "mpirun (or mpirun -n 1)",
                         ops->name, cfg->comm->size);
    Coupling *c;
    TRY(nspd_alloc(&c, 1, sizeof *c));
    c->kind = cfg->kind;
    c->ops = ops;
    int status = c->ops->create(&c->impl, cfg, solid, flow);
    if (status != NSPD_OK) {
        nspd_free(&c);
        return status;
    }
    *out = c;
    return NSPD_OK;
}

void coupling_destroy(Coupling **cp) {
    Coupling *c = *cp;
    if (!c) return;
    if (c->impl) c->ops->destroy(c->impl);
    nspd_free(cp);
}

CouplingKind coupling_kind(const Coupling *c) {
    return c->kind;
}

const char *coupling_name(const Coupling *c) {
    return c->ops->name;
}

int coupling_before_flow(Coupling *c, Solid *solid, Flow *flow) {
    return c->ops->before_flow ? c->ops->before_flow(c->impl, solid, flow) : NSPD_OK;
}

/* A load that is not finite would wreck the solid silently: whatever the
 * coupling, the run stops there and says so (a coupling may say more
 * first: the ghost-cell one names the surface point). */
int coupling_after_flow(Coupling *c, Solid *solid, Flow *flow, double dt) {
    TRY(c->ops->after_flow(c->impl, solid, flow, dt));
    CouplingLoads loads;
    coupling_loads(c, &loads);
    if (isfinite(loads.force_on_solid[0]) && isfinite(loads.force_on_solid[1])) return NSPD_OK;
    return NSPD_FAIL(NSPD_ERR_NUMERIC,
                     "the %s coupling's load on the solid is not finite (%g, %g) N/m at "
                     "t = %g s: the flow next to the solid has broken down",
                     c->ops->name, loads.force_on_solid[0], loads.force_on_solid[1],
                     flow_time(flow));
}

double coupling_solid_dt_limit(const Coupling *c, const Solid *solid) {
    return c->ops->solid_dt_limit ? c->ops->solid_dt_limit(c->impl, solid) : (double)INFINITY;
}

bool coupling_constrains_solid(const Coupling *c) {
    return c->ops->constrains_solid && c->ops->constrains_solid(c->impl);
}

void coupling_loads(const Coupling *c, CouplingLoads *out) {
    c->ops->loads(c->impl, out);
}

int coupling_history(Coupling *c, Solid *solid, Flow *flow, double time, Report *row) {
    return c->ops->history(c->impl, solid, flow, time, row);
}

int coupling_summary(Coupling *c, Solid *solid, Flow *flow, Report *out) {
    return c->ops->summary(c->impl, solid, flow, out);
}

int coupling_fields(Coupling *c, Solid *solid, Flow *flow, FieldSet *out) {
    if (!c->ops->fields) { /* a coupling with no fields of its own */
        memset(out, 0, sizeof *out);
        out->mesh = MESH_NONE;
        return NSPD_OK;
    }
    return c->ops->fields(c->impl, solid, flow, out);
}

int coupling_checkpoint(Coupling *c, Checkpoint *ck) {
    if (!c->ops->checkpoint)
        return NSPD_FAIL(NSPD_ERR_INPUT, "the coupling '%s' cannot be checkpointed", c->ops->name);
    return c->ops->checkpoint(c->impl, ck);
}

void *coupling_impl(Coupling *c, CouplingKind kind) {
    return c && c->kind == kind ? c->impl : NULL;
}
