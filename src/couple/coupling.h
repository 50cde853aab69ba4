/* The coupling interface: how a solid and a flow exchange walls and loads,
 * behind an opaque handle. One coupled step of the driver (sim/sim.c):
 *     coupling_before_flow   the solid's state becomes the flow's boundary
 *     flow step
 *     coupling_after_flow    the flow's state becomes the solid's load
 *     solid sub-steps        no longer than coupling_solid_dt_limit
 * A coupling may have no solid (rigid walls) but always has a flow. A new
 * coupling is a folder couple/<name>/ (its own library,
 * docs/ARCHITECTURE.md) with an ops table and its configuration struct, a
 * CouplingKind and a line in the registry (coupling.c); create refuses
 * the solid/flow pairs it does not support with NSPD_ERR_INPUT. This
 * header names no coupling's types: a configuration reaches its coupling
 * as an opaque pointer. */
#ifndef NSPD_COUPLE_COUPLING_H
#define NSPD_COUPLE_COUPLING_H

#include "core/fields.h"
#include "core/report.h"
#include "flow/flow.h"
#include "solid/solid.h"

#include <stdbool.h>

typedef enum {
    COUPLING_NONE = 0,
    COUPLING_GHOST_CELL, /* sharp ghost-cell immersed boundary: couple/ghost/ */
    COUPLING_PENALTY,    /* volumetric penalty (paper 003): couple/penalty/ */
    COUPLING_KIND_COUNT, /* the built-in couplings; coupling_register adds more after these */
    COUPLING_KIND_MAX = COUPLING_KIND_COUNT + 4
} CouplingKind;

/* A coupling's configuration: the kind, what every coupling shares, and
 * the coupling's own configuration behind an opaque pointer
 * (GhostCouplingConfig of couple/ghost/model.h, ...), which only the case
 * reader and the coupling know. */
typedef struct {
    CouplingKind kind;
    /* "FILE:LINE:COL: coupling" (or the --set) of the section, for what the
     * coupling refuses when it is built */
    char where[400];
    /* s: the loads are time-averaged from this time on (the driver sets it
     * from output.average_from, less a round-off margin of the end time) */
    double average_from;
    /* `nspd check`: as FlowConfig.validate_only (no soft start of the gas
     * around fixed bodies: it changes the initial field, never refuses) */
    bool validate_only;
    /* the processes that share the run (as FlowConfig.comm): only a
     * coupling whose ops say `distributed` takes a group of several */
    const NspdComm *comm;
    /* owned (nspd_alloc) when the kind's ops have config_free: the coupling's
     * create takes it (and sets this NULL), else coupling_config_free frees it; otherwise
     * borrowed (a registered coupling's configuration, never freed) */
    void *model;
} CouplingConfig;

void coupling_config_free(CouplingConfig *cfg);

/* What the flow did to the solid in the last step. */
typedef struct {
    double force_on_solid[2]; /* N per m of depth */
} CouplingLoads;

typedef struct Coupling Coupling;

/* What a coupling will need beside its models, estimated from the
 * configurations alone (nothing built). */
typedef struct {
    double bytes;
} CouplingEstimate;

typedef struct CouplingOps {
    const char *name;
    /* runs on several processes (CouplingConfig.comm); its ops are then
     * collective, as the flow's */
    bool distributed;
    /* on several processes it takes a solid divided between them (the
     * whole body's view of solid.h: it writes the loads whole and reads
     * points after solid_sync); otherwise every rank advances the whole
     * solid */
    bool divided_solid;
    /* frees what a configuration of this coupling owns, not the struct
     * itself (one that no create took); NULL: configurations are borrowed,
     * and create leaves them */
    void (*config_free)(void *model);
    /* the estimate for a flow of estimate *flow (NULL op: nothing beyond
     * the models) */
    CouplingEstimate (*estimate)(const CouplingConfig *cfg, const FlowEstimate *flow);
    /* solid may be NULL (rigid walls); takes ownership of *cfg's contents */
    int (*create)(void **impl, CouplingConfig *cfg, Solid *solid, Flow *flow);
    void (*destroy)(void *impl);
    int (*before_flow)(void *impl, Solid *solid, Flow *flow); /* NULL: nothing to do */
    int (*after_flow)(void *impl, Solid *solid, Flow *flow, double dt);
    /* the longest solid sub-step the coupling allows (INFINITY: no limit) */
    double (*solid_dt_limit)(const void *impl, const Solid *solid);
    /* optional (NULL: false): the coupling prescribes the solid's
     * velocities at every step, so the driver advances the solid by one
     * solid_advance_constrained per flow step, no longer than its
     * sub-step (sim.h Sim.constrained) */
    bool (*constrains_solid)(const void *impl);
    void (*loads)(const void *impl, CouplingLoads *out);
    /* the loads of the current state as history columns (and the running
     * time averages, from average_from on) */
    int (*history)(void *impl, Solid *solid, Flow *flow, double time, Report *row);
    int (*summary)(void *impl, Solid *solid, Flow *flow, Report *out);
    /* tables of the current state (surface pressure and friction); NULL:
     * none */
    int (*fields)(void *impl, Solid *solid, Flow *flow, FieldSet *out);
    /* writes or reads (checkpoint_reading) what the coupling carries from
     * step to step (called after the solid's and the flow's, which it may
     * read); NULL: it cannot be checkpointed */
    int (*checkpoint)(void *impl, Checkpoint *ck);
} CouplingOps;

/* Adds a coupling to the registry (before any is created; not thread safe):
 * its kind, or COUPLING_NONE when the registry is full. */
CouplingKind coupling_register(const CouplingOps *ops);

/* Whether a coupling of `kind` takes a divided solid (CouplingOps). */
bool coupling_divides_solid(CouplingKind kind);

/* The estimate of *cfg by its coupling (zero for an unknown kind). */
CouplingEstimate coupling_estimate(const CouplingConfig *cfg, const FlowEstimate *flow);
int coupling_create(Coupling **out, CouplingConfig *cfg, Solid *solid, Flow *flow);
void coupling_destroy(Coupling **c);
CouplingKind coupling_kind(const Coupling *c);
const char *coupling_name(const Coupling *c);
int coupling_before_flow(Coupling *c, Solid *solid, Flow *flow);
int coupling_after_flow(Coupling *c, Solid *solid, Flow *flow, double dt);
double coupling_solid_dt_limit(const Coupling *c, const Solid *solid);
bool coupling_constrains_solid(const Coupling *c);
void coupling_loads(const Coupling *c, CouplingLoads *out);
int coupling_history(Coupling *c, Solid *solid, Flow *flow, double time, Report *row);
int coupling_summary(Coupling *c, Solid *solid, Flow *flow, Report *out);
int coupling_fields(Coupling *c, Solid *solid, Flow *flow, FieldSet *out);
/* Writes or reads the coupling's state (CouplingOps.checkpoint):
 * NSPD_ERR_INPUT for a coupling that cannot be checkpointed. */
int coupling_checkpoint(Coupling *c, Checkpoint *ck);

/* The concrete coupling if it is of `kind`, else NULL. */
void *coupling_impl(Coupling *c, CouplingKind kind);

#endif
