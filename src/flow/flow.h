/* The flow interface: a flow solver behind an opaque handle.
 *
 * The driver (sim/), the couplings and the probes call the flow_* functions,
 * which dispatch through the FlowOps table once per step, sample or output;
 * hot loops stay inside a solver. A new solver is a folder flow/<name>/
 * (its own library, docs/ARCHITECTURE.md) with an ops table and its
 * configuration struct, a FlowMethod and a line in the registry (flow.c);
 * nothing in sim/, case/ output or the probes changes. This header names
 * no solver's types: a configuration reaches its solver as an opaque
 * pointer. A coupling tied to one representation (the ghost-cell immersed
 * boundary needs the GKS grid) reaches the concrete solver through the
 * checked accessor of that solver (gks_flow_solver) and refuses the others
 * when it is created. */
#ifndef NSPD_FLOW_FLOW_H
#define NSPD_FLOW_FLOW_H

#include "core/checkpoint.h"
#include "core/comm.h"
#include "core/fields.h"
#include "core/report.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

typedef enum {
    FLOW_METHOD_NONE = 0, /* the case has no flow */
    FLOW_METHOD_GKS,      /* gas-kinetic BGK-NS finite volumes (paper 000): flow/gks/ */
    FLOW_METHOD_PDDO,     /* incompressible PDDO on node clouds (paper 002): flow/pddo/ */
    FLOW_METHOD_IGA,      /* isogeometric SUPG compressible flow (paper 003): flow/iga/ */
    FLOW_METHOD_COUNT,    /* the built-in solvers; flow_register adds more after these */
    FLOW_METHOD_MAX = FLOW_METHOD_COUNT + 4
} FlowMethod;

/* A flow's configuration: the method, what every flow shares, and the
 * method's own configuration behind an opaque pointer (GksCaseConfig of
 * flow/gks/model.h, PddoFlowConfig of flow/pddo/model.h, ...), which only
 * the case reader and the solver know. */
typedef struct {
    FlowMethod method;
    /* "FILE:LINE:COL: flow" (or the --set) of the section, for what the
     * solver refuses when it is built (no location of its own) */
    char where[400];
    /* s: time averages (a body's forces) are taken from this time on; the
     * driver sets it from output.average_from, less a round-off margin of
     * the end time */
    double average_from;
    /* `nspd check`: build what validates the case and skip what cannot fail
     * on a valid one and costs time (a factorisation); the flow is then
     * described, never stepped */
    bool validate_only;
    /* the processes that share the flow (NULL or a group of one: this
     * process alone); borrowed during create. Only a solver whose ops say
     * `distributed` takes a group of several (flow_create refuses it for
     * the others). Every rank then calls every flow_* function in the same
     * order: the solver's ops may communicate (they are collective), and
     * the grid, cells and fields they show are the whole flow's. */
    const NspdComm *comm;
    /* the process grid asked for on several processes (`nspd run
     * --processes PXxPY`): PX blocks along x times PY along y, their
     * product the group's size; {0, 0}: the solver's own choice (the GKS
     * flow: the grid of the fewest halo cells). A layout, not the case:
     * results are the same bits on any. */
    int processes[2];
    /* owned (nspd_alloc) when the method's ops have config_free: the solver's
     * create takes it (and sets this NULL), else flow_config_free frees it; otherwise
     * borrowed (a registered solver's configuration, never freed) */
    void *model;
} FlowConfig;

void flow_config_free(FlowConfig *cfg);

/* Where the solver's unknowns live, for probes and output. */
typedef struct {
    MeshKind kind;
} FlowMesh;

/* The reference state of force and pressure coefficients: the free stream
 * if the case defines one, else the initial state; the reference length
 * (0 if none was given). */
typedef struct {
    double rho, u, v, p;
    double length;
    double gamma, gas_constant;
} FlowReference;

/* Samples of the flow at points, struct of arrays (n values each). */
typedef struct {
    double *rho, *u, *v, *p;
} FlowSamples;

/* Forces and power a coupling puts into the gas at points, for the next
 * steps: point k at (x[k], y[k]) gives the gas the force (force_x[k],
 * force_y[k]) and the power power[k], per metre of depth (N/m, W/m; power
 * NULL: none). The power is all the energy the gas receives: the work of
 * the force on the moving gas is the caller's to include. The solver
 * spreads each onto the cell or node that holds the point, in point order
 * (the same bits on any thread count). */
typedef struct {
    int64_t n;
    const double *x, *y;
    const double *force_x, *force_y, *power;
    int64_t outside; /* out: points with no gas there (off the mesh, in a body): dropped */
} FlowSources;

/* How a volumetric coupling moves velocity and momentum between points
 * and the flow's unknowns (cells, or control points): the unknown that
 * holds the point; bilinear between the four nearest; quadratic B-spline
 * weights on the 3 x 3 nearest. The weights are >= 0 and sum to 1 (a
 * partition of unity), so what is spread with them is conserved. */
typedef enum {
    FLOW_TRANSFER_NEAREST = 0,
    FLOW_TRANSFER_BILINEAR,
    FLOW_TRANSFER_QUADRATIC,
    FLOW_TRANSFER_KINDS
} FlowTransferKind;

extern const char *const FLOW_TRANSFER_NAMES[]; /* "nearest", "bilinear", "quadratic" */

/* Entries per point of a transfer of `kind`: 1, 4 or 9. */
int flow_transfer_width(FlowTransferKind kind);

typedef struct Flow Flow;

/* What a flow will need, estimated from its configuration alone. */
typedef struct {
    double cells;      /* or nodes */
    const char *items; /* what `cells` counts: "cells" or "nodes" */
    /* cells with the layers of ghosts and padding that per-cell arrays
     * hold (what a coupling sizes its own per-cell arrays by) */
    double stored_cells;
    double bytes;
    /* seconds `nspd check`'s validating build would take (from a rate
     * measured on this solver; check skips the build above a budget) */
    double check_s;
    /* s, the stable step of the initial state from the configuration
     * alone; 0: known only once the solver is built */
    double stable_dt;
} FlowEstimate;

typedef struct FlowOps {
    const char *name;
    /* the solver runs on several processes (FlowConfig.comm) */
    bool distributed;
    /* frees what a configuration of this solver owns, not the struct
     * itself (one that no create took); NULL: configurations are borrowed,
     * and create leaves them */
    void (*config_free)(void *model);
    /* the estimate of a configuration of this solver (no allocation) */
    FlowEstimate (*estimate)(const FlowConfig *cfg);
    /* optional (NULL: none beyond the reader's): the checks of a
     * configuration that need no cells or nodes, which create makes too;
     * what `nspd check` runs on a case too large to build within its
     * budget */
    int (*validate)(const FlowConfig *cfg);
    /* Builds the solver from *cfg, taking ownership of its contents. */
    int (*create)(void **impl, FlowConfig *cfg);
    void (*destroy)(void *impl);
    double (*stable_dt)(const void *impl);
    int (*step)(void *impl, double dt);
    double (*time)(const void *impl);
    /* true once the flow has reached its own end (a steady state): the
     * driver stops the run there, before time.end; NULL: never */
    bool (*finished)(const void *impl);
    FlowMesh (*mesh)(const void *impl);
    /* density, u, v, pressure, temperature at node/cell `cell` of the mesh */
    void (*cell_state)(const void *impl, int64_t cell, double out[5]);
    /* a grid (MESH_GRID): the cell that holds (x, y) into *cell, or
     * NSPD_ERR_INPUT naming the probe `name` for a point off the grid */
    int (*cell_at)(const void *impl, const char *name, double x, double y, int64_t *cell);
    /* a grid: the cells of the row (along 0) or column (along 1) through
     * cell `through`, in order along the axis, into *cells (allocated by
     * nspd_alloc, the caller's to free) and their number into *count */
    int (*grid_line)(const void *impl, int64_t through, int along, int64_t **cells, int64_t *count);
    /* a grid: the centre of cell `cell` */
    void (*cell_centre)(const void *impl, int64_t cell, double xy[2]);
    FlowReference (*reference)(const void *impl);
    /* the state at n points (x[k], y[k]), interpolated (for couplings that
     * read the flow where a solid's points are); NULL: not supported (an
     * input error when asked) */
    int (*sample)(void *impl, int64_t n, const double *x, const double *y, FlowSamples *out);
    /* replaces the sources of the next steps (NULL src: none); NULL op:
     * the solver takes none (an input error when asked) */
    int (*set_sources)(void *impl, FlowSources *src);
    /* The transfer weights of n points (x[k], y[k]): point k's entries are
     * cell[k * width + j], w[k * width + j] for j < flow_transfer_width
     * (cell -1 and w 0 where a point has fewer; every cell -1 for a point
     * off the mesh). Allocation free. NULL: no volumetric coupling. */
    void (*transfer)(const void *impl, FlowTransferKind kind, int64_t n, const double *x,
                     const double *y, int64_t *cell, double *w);
    /* The process that holds unknown `cell` (its rank in the flow's
     * group). NULL: one process holds them all. */
    int (*cell_owner)(const void *impl, int64_t cell);
    /* Whether the point (x, y) lies in a cell within `margin` cells (along
     * each axis, around a periodic one) of those this process holds: the
     * points whose stencils can reach them. NULL, or one process: true. */
    bool (*point_near)(const void *impl, double x, double y, int margin);
    /* The lumped mass (kg per metre of depth) and momentum (kg m/s per
     * metre) of the n unknowns cells[k]; on several processes only
     * unknowns this process holds (cell_owner; NaN for others), no
     * message sent. */
    void (*lumped)(const void *impl, int64_t n, const int64_t *cells, double *mass,
                   double *momentum_x, double *momentum_y);
    /* The lumped volume int N_A (m^2 per metre of depth: a cell's area,
     * a control point's basis integral) of the n unknowns cells[k], as
     * `lumped` (NaN for another process's): the volume a coupling's
     * covered fraction is measured against (paper 003 Eq. 20). */
    void (*lumped_volume)(const void *impl, int64_t n, const int64_t *cells, double *volume);
    /* Adds momentum and total energy (per metre of depth; a NULL array:
     * none of that) to the n unknowns cells[k] (distinct), between steps;
     * on several processes, what is added to unknowns another process
     * holds is dropped (each process passes its own). */
    void (*add_lumped)(void *impl, int64_t n, const int64_t *cells, const double *dmx,
                       const double *dmy, const double *de);
    /* Sealed faces inside a solid, for the next steps: a solid moving at
     * (u[k], v[k]) covers area[k] m^2 (per metre of depth) of the n
     * unknowns cells[k] (distinct); between two cells it covers to at least
     * `fraction` of their area, the gas carries only the mass the solid's
     * motion moves (no numerical pressure diffusion through locked gas).
     * Replaces the last call's. NULL: the solver cannot (a coupling that
     * asks refuses the flow when it is built). */
    int (*seal)(void *impl, int64_t n, const int64_t *cells, const double *area, const double *u,
                const double *v, double fraction);
    /* point probes on a mesh without cells (MESH_POINTS), or on a grid
     * whose field is defined between the cells (B-splines): prepares the
     * state at (x, y) once, before the run (it may allocate), and returns
     * its handle for probe_state in *id; NSPD_ERR_INPUT naming the probe
     * `name` for a point outside the fluid. NULL: none (a grid's probes
     * read cell_state of the cell that holds the point) */
    int (*probe_add)(void *impl, const char *name, double x, double y, int64_t *id);
    /* density, u, v, pressure, temperature at probe `id` (NaN for what the
     * solver does not have); allocation free */
    void (*probe_state)(const void *impl, int64_t id, double out[5]);
    /* integrals of mass, x and y momentum, energy over the fluid */
    void (*totals)(const void *impl, double totals[4]);
    void (*history)(const void *impl, Report *row);
    void (*summary)(const void *impl, const RunStats *run, Report *out);
    void (*info)(const void *impl, size_t memory_bytes, char *buf, size_t size);
    void (*brief)(const void *impl, char *buf, size_t size); /* "nx x ny cells, " */
    /* reduced-order events, for the log (NULL: a solver without them) */
    int64_t (*fallbacks_total)(const void *impl);
    /* the fields and pictures of the current state, into the solver's own
     * scratch (no allocation) */
    void (*fields)(void *impl, FieldSet *out);
    /* writes or reads (checkpoint_reading) everything a step changes, so a
     * solver built from the same case continues bit for bit; NULL: the
     * solver cannot be checkpointed */
    int (*checkpoint)(void *impl, Checkpoint *ck);
    /* `nspd bench <bench_name>`: the solver's hot loop on its standard
     * problem of about `size` cells or nodes, `steps` timed steps, the
     * results as named values in order (one JSON object); NULL: none */
    const char *bench_name;
    int (*bench)(long size, long steps, Report *out);
} FlowOps;

/* Adds a solver to the registry (before any flow is created; not thread
 * safe): its method number, or FLOW_METHOD_NONE when the registry is full.
 * How a model outside the tree - or a test - plugs in. */
FlowMethod flow_register(const FlowOps *ops);

/* The estimate of *cfg by its solver (zeros for an unknown method). */
FlowEstimate flow_estimate(const FlowConfig *cfg);

/* The solver's validate op on *cfg (NSPD_OK without one). */
int flow_validate(const FlowConfig *cfg);

/* Runs the benchmark `name` of the registered solver that has it into
 * *out; *found false (and NSPD_OK) when none has. */
int flow_bench(const char *name, long size, long steps, Report *out, bool *found);

/* NSPD_ERR_INPUT for an unknown method; otherwise what the solver's create
 * returns. Takes ownership of *cfg. */
int flow_create(Flow **out, FlowConfig *cfg);
void flow_destroy(Flow **f);

FlowMethod flow_method(const Flow *f);
const char *flow_name(const Flow *f);
double flow_stable_dt(const Flow *f);
int flow_step(Flow *f, double dt);
double flow_time(const Flow *f);
bool flow_finished(const Flow *f);
FlowMesh flow_mesh(const Flow *f);
void flow_cell_state(const Flow *f, int64_t cell, double out[5]);
/* FlowOps.cell_at, grid_line, cell_centre: NSPD_ERR_INPUT naming the probe
 * for a solver without a grid. */
int flow_cell_at(const Flow *f, const char *name, double x, double y, int64_t *cell);
int flow_grid_line(const Flow *f, const char *name, int64_t through, int along, int64_t **cells,
                   int64_t *count);
void flow_cell_centre(const Flow *f, int64_t cell, double xy[2]);
FlowReference flow_reference(const Flow *f);
int flow_sample(Flow *f, int64_t n, const double *x, const double *y, FlowSamples *out);
int flow_set_sources(Flow *f, FlowSources *src);
/* FlowOps.transfer, lumped, lumped_volume, add_lumped: only where flow_has_transfer (a
 * coupling that needs them refuses other flows when it is built). */
bool flow_has_transfer(const Flow *f);
int flow_cell_owner(const Flow *f, int64_t cell);
bool flow_point_near(const Flow *f, double x, double y, int margin);
void flow_transfer(const Flow *f, FlowTransferKind kind, int64_t n, const double *x,
                   const double *y, int64_t *cell, double *w);
void flow_lumped(const Flow *f, int64_t n, const int64_t *cells, double *mass, double *momentum_x,
                 double *momentum_y);
void flow_lumped_volume(const Flow *f, int64_t n, const int64_t *cells, double *volume);
void flow_add_lumped(Flow *f, int64_t n, const int64_t *cells, const double *dmx, const double *dmy,
                     const double *de);
/* FlowOps.seal: only where flow_can_seal. */
bool flow_can_seal(const Flow *f);
int flow_seal(Flow *f, int64_t n, const int64_t *cells, const double *area, const double *u,
              const double *v, double fraction);
/* Whether the solver reads point probes at their points (probe_add). */
bool flow_has_point_probes(const Flow *f);
/* FlowOps.probe_add; NSPD_ERR_INPUT for a solver without point probes. */
int flow_probe_add(Flow *f, const char *name, double x, double y, int64_t *id);
void flow_probe_state(const Flow *f, int64_t id, double out[5]);
void flow_totals(const Flow *f, double totals[4]);
void flow_history(const Flow *f, Report *row);
void flow_summary(const Flow *f, const RunStats *run, Report *out);
void flow_info(const Flow *f, size_t memory_bytes, char *buf, size_t size);
void flow_brief(const Flow *f, char *buf, size_t size);
int64_t flow_fallbacks_total(const Flow *f);
void flow_fields(Flow *f, FieldSet *out);

/* The top of a compressible flow's Mach pictures (`mach`, and the
 * `mach_damage` drawn from it), fixed for the series so the frames of a
 * movie compare, from the largest Mach number of an output (`largest`:
 * over the fluid cells, with the free stream's where the flow has one):
 * 1.25 times it, rounded up to two significant digits (1.7 -> 2.2,
 * 2 -> 2.5). 0 while the gas is at rest (largest below
 * FLOW_MACH_AT_REST, or not finite): that frame is drawn 0 to 1 and the
 * next output's data fixes the scale, so a blast that starts at rest is
 * not drawn on 0 to 1 throughout. `output.mach_range` replaces it
 * (sim/sim_output.c). */
#define FLOW_MACH_AT_REST 1e-2
double flow_mach_picture_top(double largest);
/* The top of the speed pictures (`speed`, |u| in m/s, and the
 * `speed_damage` drawn from it: paper 003's Figs. 2 and 7), fixed for the
 * series as the Mach pictures' is and at the same output: 1.25 times the
 * largest speed of the output (`largest_speed`, m/s, over the fluid cells
 * and the free stream), rounded up to two significant digits; 0 while
 * the gas is at rest by the Mach pictures' test (`largest_mach`, as
 * flow_mach_picture_top takes it, below FLOW_MACH_AT_REST) or the speed
 * is not a positive finite number: that frame is drawn 0 to 1 m/s. */
double flow_speed_picture_top(double largest_speed, double largest_mach);

/* Writes or reads the flow's state (FlowOps.checkpoint): NSPD_ERR_INPUT
 * for a solver that cannot be checkpointed. */
int flow_checkpoint(Flow *f, Checkpoint *ck);

/* The concrete solver if the flow is of `method`, else NULL. */
void *flow_impl(Flow *f, FlowMethod method);

#endif
