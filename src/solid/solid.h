/* The solid interface: a PD solid model behind an opaque handle.
 *
 * Every PD model shares its material points (PdPoints: positions,
 * displacements, velocities, the external force density couplings write,
 * volumes, lattice indices and the family CSR); what differs between models
 * (the force, the material state, failure) sits behind the SolidOps table.
 * The driver (sim/) and the couplings call the solid_* functions, which
 * dispatch through the table once per step or output; hot loops stay inside
 * a model. A new model is a folder solid/<name>/ (its own library,
 * docs/ARCHITECTURE.md) with an ops table and its configuration struct, a
 * SolidKind and a line in the registry (solid.c); nothing in sim/, case/
 * output or the couplings changes. This header names no model's types: a
 * configuration reaches its model as an opaque pointer.
 *
 * Time: solid_advance(dt, max_substep) takes n = ceil(dt / max_substep)
 * equal sub-steps (one when the solid sets the pace); solid_set_time pins
 * the clock to the flow's when the flow sets it. */
#ifndef NSPD_SOLID_SOLID_H
#define NSPD_SOLID_SOLID_H

#include "core/checkpoint.h"
#include "core/comm.h"
#include "core/fields.h"
#include "core/report.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

typedef enum {
    SOLID_NONE = 0,       /* the case has no solid */
    SOLID_BOND,           /* bond-based PD (paper 000): solid/bond/ */
    SOLID_CORRESPONDENCE, /* correspondence PD (paper 003): solid/correspondence/ */
    SOLID_KIND_COUNT,     /* the built-in models; solid_register adds more after these */
    SOLID_KIND_MAX = SOLID_KIND_COUNT + 4
} SolidKind;

/* A solid's configuration: the kind and the model's own configuration
 * behind an opaque pointer (PdConfig of solid/pd/config.h for the bonds,
 * CpdConfig of solid/correspondence/config.h, ...), which only the case
 * reader and the model know. */
typedef struct {
    SolidKind kind;
    /* "FILE:LINE:COL: solid" (or the --set) of the section, for what the
     * model refuses when it is built (no location of its own) */
    char where[400];
    /* owned (nspd_alloc) when the kind's ops have config_free: the model's
     * create takes it (and sets this NULL), else solid_config_free frees it; otherwise
     * borrowed (a registered model's configuration, never freed) */
    void *model;
    /* the processes the solid runs on (borrowed during create): NULL or a
     * group of one, the whole body here; several (a model whose ops are
     * `distributed`), each process holds a part (below) */
    const NspdComm *comm;
} SolidConfig;

void solid_config_free(SolidConfig *cfg);
/* The body's dimension (2 or 3) of a configuration; 0 for none. */
int solid_config_dim(const SolidConfig *cfg);
/* Whether the configuration's model divides itself between processes
 * (its ops say `distributed`). */
bool solid_config_divides(const SolidConfig *cfg);

/* The points every PD model has (struct of arrays, owned by the model,
 * never reallocated after create). Couplings write `external`; everything
 * else is read-only outside the model. */
typedef struct {
    int dim;
    int64_t n;
    double spacing;   /* lattice spacing dx, m */
    double thickness; /* 2D: out-of-plane thickness, m; 3D: 1 */
    double *x[3], *u[3], *v[3];
    double *external[3]; /* force density from outside, N/m^3 (see solid/bond/body.h) */
    double *volume;
    int32_t *lattice[3];
    const int64_t *family_first; /* the family CSR: neighbours of i are */
    const int32_t *family_nbr;   /* family_nbr[family_first[i] .. family_first[i+1]) */
} PdPoints;

typedef struct Solid Solid;

/* What a solid will need, estimated from its configuration alone (nothing
 * built or allocated): checked against the machine before it is built. */
typedef struct {
    double points, bonds; /* bonds: each counted from both ends, as stored */
    double bytes;         /* peak while it is built and run */
    /* seconds `nspd check`'s validating build would take (from a rate
     * measured on this model; check skips the build above a budget) */
    double check_s;
    /* s, the stable step from the configuration alone (an interior point
     * of a full family); 0: known only once the model is built */
    double stable_dt;
} SolidEstimate;

typedef struct {
    const char *name;
    /* runs on several processes (SolidConfig.comm): create then gives
     * `pts` this process's points, a run of the whole body's order
     * (rank r's after rank r - 1's), and its ops are collective (sums and
     * counts of the whole body, in its order); the rest of its arrays (the
     * ghosts a step reads) follow the run, beyond pts.n; `attached`
     * is asked of this process's points, `modulus` and `density` with
     * whole-body indices (a model with one material ignores them) */
    bool distributed;
    /* frees what a configuration of this model owns, not the struct
     * itself (one that no create took); NULL: configurations are borrowed,
     * and create leaves them */
    void (*config_free)(void *model);
    /* the dimension (2 or 3) of the body a configuration describes */
    int (*config_dim)(const void *model);
    /* the estimate of a configuration of this model (no allocation) */
    SolidEstimate (*estimate)(const SolidConfig *cfg);
    /* optional (NULL: none beyond the reader's): the checks of a
     * configuration that need no points, which create makes too; what
     * `nspd check` runs on a case too large to build within its budget */
    int (*validate)(const SolidConfig *cfg);
    /* Builds the model from *cfg (taking its contents, zeroing them) and
     * points `pts` at its points. */
    int (*create)(void **impl, PdPoints *pts, SolidConfig *cfg);
    void (*destroy)(void *impl);
    double (*stable_dt)(const void *impl); /* without a safety factor */
    int (*step)(void *impl, double dt);    /* force + integration, one step */
    /* optional (NULL: the model cannot be constrained): one step of dt
     * whose velocities a coupling has just prescribed (the strong coupling
     * of paper 003, Eq. 18): u += dt v with the prescribed v, the force at
     * the new displacements, then v += dt f / rho (the force's impulse,
     * which the coupling hands to the flow at its next projection, Eq.
     * 19). A drift-kick: the points move only with prescribed velocities,
     * so the solid's own fast modes never enter its positions */
    int (*step_constrained)(void *impl, double dt);
    double (*time)(const void *impl);
    void (*set_time)(void *impl, double t);
    void (*damage)(const void *impl, double *out);  /* per point, 0..1 */
    double (*modulus)(const void *impl, int64_t i); /* Young's modulus at point i, Pa */
    double (*density)(const void *impl, int64_t i); /* mass density at point i, kg/m^3 */
    /* true while point i belongs to the body (bond PD: it keeps an intact
     * bond); a detached point is debris, which no wall follows. NULL: a
     * model whose points never detach */
    bool (*attached)(const void *impl, int64_t i);
    void (*history)(const void *impl, Report *row);
    void (*summary)(const void *impl, const RunStats *run, Report *out);
    void (*info)(const void *impl, size_t memory_bytes, char *buf, size_t size);
    void (*brief)(const void *impl, char *buf, size_t size); /* "N points, M bonds, " */
    /* optional (NULL: none): fields beyond the shared ones (stress, plastic
     * strain), appended to *out */
    void (*fields)(const void *impl, FieldSet *out);
    /* writes or reads (checkpoint_reading) everything a step changes, so a
     * model built from the same case continues bit for bit; NULL: the model
     * cannot be checkpointed */
    int (*checkpoint)(void *impl, Checkpoint *ck);
    /* `nspd bench <bench_name>`: the model's hot loop on its standard
     * problem of about `size` points, `steps` timed steps, the results as
     * named values in order (one JSON object); NULL: none */
    const char *bench_name;
    int (*bench)(long size, long steps, Report *out);
} SolidOps;

/* Adds a model to the registry (before any solid is created; not thread
 * safe): its kind, or SOLID_NONE when the registry is full. */
SolidKind solid_register(const SolidOps *ops);

/* The estimate of *cfg by its model (zeros for an unknown kind). */
SolidEstimate solid_estimate(const SolidConfig *cfg);

/* The model's validate op on *cfg (NSPD_OK without one). */
int solid_validate(const SolidConfig *cfg);

/* Runs the benchmark `name` of the registered model that has it into *out;
 * *found false (and NSPD_OK) when none has. */
int solid_bench(const char *name, long size, long steps, Report *out, bool *found);

/* NSPD_ERR_INPUT for an unknown kind; otherwise what the model's create
 * returns. Takes ownership of *cfg. */
int solid_create(Solid **out, SolidConfig *cfg);
void solid_destroy(Solid **s);

SolidKind solid_kind(const Solid *s);
const char *solid_name(const Solid *s);
/* The points of the whole body. On several processes the whole body's
 * view, the same on every rank: positions, volumes and lattice indices
 * from create, displacements and velocities as of the last solid_sync,
 * and the external force density a coupling writes whole (alike on every
 * rank), which solid_advance hands to each process's points; no family
 * (the bonds stay with each part). */
PdPoints *solid_points(Solid *s);
const PdPoints *solid_points_const(const Solid *s);
/* Brings the whole body's view up to date (collective; nothing on one
 * process, or when nothing advanced since the last): before anything
 * reads the points or asks solid_attached between steps. */
int solid_sync(Solid *s);
/* The same for points[0..n) of the whole body only (collective; every
 * rank passes the same list): what a coupling that reads a few points (a
 * surface) gathers instead of the whole body. */
int solid_sync_points(Solid *s, int64_t n, const int32_t *points);
/* Says that a coupling changed the whole view's velocities (alike on every
 * rank, after a solid_sync): the next solid_advance hands each process's
 * points their part first (nothing on one process, whose view is the
 * model's own). */
void solid_velocities_changed(Solid *s);
double solid_stable_dt(const Solid *s);
double solid_time(const Solid *s);
void solid_set_time(Solid *s, double t);
/* Advances by dt in n = ceil(dt / max_substep) equal sub-steps (n >= 1),
 * then checks the points: NSPD_ERR_NUMERIC naming the first point whose
 * displacement or velocity is not finite or whose speed exceeds
 * SOLID_RUNAWAY_SPEED (a blown-up integration), with its coordinates. */
int solid_advance(Solid *s, double dt, double max_substep);
/* Whether the model has SolidOps.step_constrained. */
bool solid_can_be_constrained(const Solid *s);
/* One constrained step of dt (SolidOps.step_constrained; no sub-steps),
 * then solid_advance's check of the points. */
int solid_advance_constrained(Solid *s, double dt);
/* m/s: no material point of a physical run moves this fast (meteoroid
 * impacts are below 1e5 m/s); a point that does has blown up. */
#define SOLID_RUNAWAY_SPEED 1e6
int64_t solid_last_substeps(const Solid *s);

/* The damage field (0..1 per point of the whole body), computed into the
 * handle's scratch array on each call (collective); valid until the next
 * call. */
const double *solid_damage(Solid *s);
/* Current positions x + u (for outputs and pictures), into the handle's
 * scratch; valid until the next call. */
void solid_current_positions(Solid *s, const double *out[3]);

/* Young's modulus at point i, Pa (a penalty coupling's stiffness scale). */
double solid_modulus(const Solid *s, int64_t i);
/* Mass density at point i, kg/m^3 (a penalty coupling's point masses);
 * NaN for a model that has none. */
double solid_density(const Solid *s, int64_t i);
/* True while point i belongs to the body (not debris). */
bool solid_attached(const Solid *s, int64_t i);

void solid_history(const Solid *s, Report *row);
void solid_summary(const Solid *s, const RunStats *run, Report *out);
void solid_info(const Solid *s, size_t memory_bytes, char *buf, size_t size);
void solid_brief(const Solid *s, char *buf, size_t size);
/* The fields and pictures of the current state (displacement, velocity,
 * damage, volume on the current positions); `damage` is solid_damage's
 * array of this state, computed once by the caller, who needs it too. */
void solid_fields(Solid *s, const double *damage, FieldSet *out);

/* Writes or reads the solid's state (solid.h SolidOps.checkpoint):
 * NSPD_ERR_INPUT for a model that cannot be checkpointed. */
int solid_checkpoint(Solid *s, Checkpoint *ck);

/* The concrete model if the solid is of `kind`, else NULL: for the couplings
 * tied to one representation (they refuse other kinds at create). */
void *solid_impl(Solid *s, SolidKind kind);

#endif
