#include "solid/solid.h"

#include "core/mem.h"
#include "core/status.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* The built-in models' ops tables, each defined in its own folder
 * (solid/bond/model.c, solid/correspondence/model.c): the one place the
 * interface names a model, by declaration only, so no model header is in
 * its include tree. */
extern const SolidOps BOND_SOLID_OPS, CPD_SOLID_OPS;

/* The registry: one ops table per SolidKind; solid_register fills the
 * slots after the built-in ones. */
static const SolidOps *SOLID_MODELS[SOLID_KIND_MAX] = {
    [SOLID_BOND] = &BOND_SOLID_OPS,
    [SOLID_CORRESPONDENCE] = &CPD_SOLID_OPS,
};

SolidKind solid_register(const SolidOps *ops) {
    for (int k = SOLID_KIND_COUNT; k < SOLID_KIND_MAX; k++)
        if (!SOLID_MODELS[k] || SOLID_MODELS[k] == ops) {
            SOLID_MODELS[k] = ops;
            return (SolidKind)k;
        }
    return SOLID_NONE;
}

struct Solid {
    const SolidOps *ops;
    SolidKind kind;
    void *impl;
    PdPoints points; /* the model's: on several processes this one's part */
    /* several processes: the group, the whole body's view (solid_sync)
     * and the whole body's index of points' point 0 */
    NspdComm comm;
    PdPoints whole;
    int64_t first;
    int64_t *run_first;     /* per rank, its run's first point; the whole count last */
    uint8_t *attached;      /* the whole body's solid_attached, as of the last sync */
    uint8_t *attached_mine; /* this process's points' (scratch) */
    int64_t advances;       /* solid_advance calls so far */
    int64_t synced_at;      /* `advances` at the last solid_sync (-1: never) */
    int64_t last_substeps;
    bool velocities_changed; /* by a coupling, in the whole view (solid_velocities_changed) */
    double *damage;          /* scratch for solid_damage (the model's points) */
    double *damage_whole;    /* several processes: the whole body's damage */
    double *position[3];     /* scratch for solid_current_positions */
};

/* What the driver, the outputs and the probes see: the whole body. */
static const PdPoints *view(const Solid *s) {
    return comm_distributed(&s->comm) ? &s->whole : &s->points;
}

/* The whole body's view on every rank (solid.h): the ranks' runs
 * gathered in rank order, which is the whole body's order. */
static int build_whole(Solid *s) {
    const PdPoints *p = &s->points;
    PdPoints *w = &s->whole;
    const int ranks = s->comm.size;
    int64_t *runs = NULL;
    TRY(nspd_alloc(&s->run_first, (size_t)ranks + 1, sizeof *s->run_first));
    TRY(nspd_alloc(&runs, (size_t)ranks, sizeof *runs));
    int status = comm_allgatherv_bytes(&s->comm, &p->n, (int)sizeof p->n, runs);
    int64_t total = 0;
    for (int q = 0; q < ranks; q++) {
        s->run_first[q] = total;
        total += runs[q];
    }
    s->run_first[ranks] = total;
    s->first = s->run_first[s->comm.rank];
    nspd_free(&runs);
    TRY(status);
    *w = (PdPoints){.dim = p->dim, .n = total, .spacing = p->spacing, .thickness = p->thickness};
    const size_t n = (size_t)total;
    const int count = (int)p->n;
    /* all three components where the model has them (a 2D body's third
     * is zero, and the probes read it); the motion's beyond dim never
     * change */
    for (int d = 0; d < 3; d++) {
        if (p->x[d]) {
            TRY(nspd_alloc(&w->x[d], n, sizeof(double)));
            TRY(comm_allgatherv(&s->comm, p->x[d], count, w->x[d]));
        }
        if (p->u[d]) TRY(nspd_alloc(&w->u[d], n, sizeof(double)));
        if (p->v[d]) TRY(nspd_alloc(&w->v[d], n, sizeof(double)));
        if (p->lattice[d]) {
            TRY(nspd_alloc(&w->lattice[d], n, sizeof(int32_t)));
            TRY(comm_allgatherv_bytes(&s->comm, p->lattice[d], count * (int)sizeof(int32_t),
                                      w->lattice[d]));
        }
    }
    /* the couplings' loads, written whole (the same bits on every rank),
     * each rank's run handed to its model before each advance */
    for (int d = 0; d < p->dim; d++) TRY(nspd_alloc(&w->external[d], n, sizeof(double)));
    TRY(nspd_alloc(&w->volume, n, sizeof(double)));
    TRY(comm_allgatherv(&s->comm, p->volume, count, w->volume));
    TRY(nspd_alloc(&s->damage_whole, n, sizeof(double)));
    TRY(nspd_alloc(&s->attached, n, 1));
    TRY(nspd_alloc(&s->attached_mine, (size_t)p->n + 1, 1));
    s->synced_at = -1;
    return solid_sync(s);
}

static void free_whole(Solid *s) {
    PdPoints *w = &s->whole;
    for (int d = 0; d < 3; d++) {
        nspd_free(&w->x[d]);
        nspd_free(&w->u[d]);
        nspd_free(&w->v[d]);
        nspd_free(&w->lattice[d]);
        nspd_free(&w->external[d]);
    }
    nspd_free(&w->volume);
    nspd_free(&s->damage_whole);
    nspd_free(&s->attached);
    nspd_free(&s->attached_mine);
    nspd_free(&s->run_first);
}

int solid_sync(Solid *s) {
    if (!comm_distributed(&s->comm) || s->synced_at == s->advances) return NSPD_OK;
    const PdPoints *p = &s->points;
    for (int d = 0; d < p->dim; d++) {
        TRY(comm_allgatherv(&s->comm, p->u[d], (int)p->n, s->whole.u[d]));
        TRY(comm_allgatherv(&s->comm, p->v[d], (int)p->n, s->whole.v[d]));
    }
    /* this rank's points' attachment, then every rank's run in rank order */
    for (int64_t i = 0; i < p->n; i++)
        s->attached_mine[i] = s->ops->attached ? s->ops->attached(s->impl, i) : 1;
    const int status = comm_allgatherv_bytes(&s->comm, s->attached_mine, (int)p->n, s->attached);
    if (status == NSPD_OK) s->synced_at = s->advances;
    return status;
}

void solid_velocities_changed(Solid *s) {
    s->velocities_changed = comm_distributed(&s->comm);
}

/* The ops table of a kind, or NULL for none or an unknown one. */
static const SolidOps *kind_ops(SolidKind kind) {
    return kind > SOLID_NONE && kind < SOLID_KIND_MAX ? SOLID_MODELS[kind] : NULL;
}

void solid_config_free(SolidConfig *cfg) {
    const SolidOps *ops = kind_ops(cfg->kind);
    if (cfg->model && ops && ops->config_free) {
        ops->config_free(cfg->model);
        nspd_free(&cfg->model);
    }
    memset(cfg, 0, sizeof *cfg);
}

bool solid_config_divides(const SolidConfig *cfg) {
    const SolidOps *ops = kind_ops(cfg->kind);
    return ops && ops->distributed;
}

int solid_config_dim(const SolidConfig *cfg) {
    const SolidOps *ops = kind_ops(cfg->kind);
    return ops && ops->config_dim && cfg->model ? ops->config_dim(cfg->model) : 0;
}

SolidEstimate solid_estimate(const SolidConfig *cfg) {
    const SolidEstimate none = {0};
    const SolidOps *ops = kind_ops(cfg->kind);
    if (!ops || !ops->estimate) return none;
    SolidEstimate e = ops->estimate(cfg);
    e.bytes +=
        e.points * (double)(sizeof(double) * 4); /* the handle's damage and position scratch */
    return e;
}

int solid_validate(const SolidConfig *cfg) {
    const SolidOps *ops = kind_ops(cfg->kind);
    return ops && ops->validate ? ops->validate(cfg) : NSPD_OK;
}

int solid_bench(const char *name, long size, long steps, Report *out, bool *found) {
    *found = false;
    for (int k = SOLID_NONE + 1; k < SOLID_KIND_MAX; k++) {
        const SolidOps *ops = SOLID_MODELS[k];
        if (ops && ops->bench && ops->bench_name && strcmp(ops->bench_name, name) == 0) {
            *found = true;
            return ops->bench(size, steps, out);
        }
    }
    return NSPD_OK;
}

/* The rank whose run holds whole-body point g. */
static int run_owner(const Solid *s, int64_t g) {
    int lo = 0, hi = s->comm.size - 1;
    while (lo < hi) {
        const int mid = (lo + hi + 1) / 2;
        if (s->run_first[mid] <= g)
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

int solid_sync_points(Solid *s, int64_t n, const int32_t *points) {
    if (!comm_distributed(&s->comm) || s->synced_at == s->advances) return NSPD_OK;
    const PdPoints *p = &s->points;
    const int width = 2 * p->dim + 1; /* u, v, attached */
    int *owner = NULL;
    double *mine = NULL, *all = NULL;
    int status = nspd_alloc(&owner, (size_t)n + 1, sizeof *owner);
    if (status == NSPD_OK) status = nspd_alloc(&mine, (size_t)(n * width) + 1, sizeof *mine);
    if (status == NSPD_OK) status = nspd_alloc(&all, (size_t)(n * width) + 1, sizeof *all);
    if (status == NSPD_OK) {
        double *m = mine;
        for (int64_t k = 0; k < n; k++) {
            owner[k] = run_owner(s, points[k]);
            if (owner[k] != s->comm.rank) continue;
            const int64_t i = points[k] - s->first;
            for (int d = 0; d < p->dim; d++) *m++ = p->u[d][i], *m++ = p->v[d][i];
            *m++ = s->ops->attached ? (double)s->ops->attached(s->impl, i) : 1.0;
        }
        status = comm_share_items(&s->comm, n, owner, width, mine, all);
    }
    for (int64_t k = 0; k < n && status == NSPD_OK; k++) {
        const double *a = all + k * width;
        for (int d = 0; d < p->dim; d++)
            s->whole.u[d][points[k]] = a[2 * d], s->whole.v[d][points[k]] = a[2 * d + 1];
        s->attached[points[k]] = a[2 * p->dim] != 0.0;
    }
    nspd_free(&owner);
    nspd_free(&mine);
    nspd_free(&all);
    return status;
}

int solid_create(Solid **out, SolidConfig *cfg) {
    *out = NULL;
    if (!kind_ops(cfg->kind))
        return NSPD_FAIL(NSPD_ERR_INPUT, "unknown solid model %d", (int)cfg->kind);
    const SolidOps *ops = kind_ops(cfg->kind);
    const NspdComm comm = cfg->comm ? *cfg->comm : comm_self();
    if (comm_distributed(&comm) && !ops->distributed)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "solid: the %s model runs on one process only, not on %d; expected a run "
                         "without mpirun (or mpirun -n 1)",
                         ops->name, comm.size);
    Solid *s;
    TRY(nspd_alloc(&s, 1, sizeof *s));
    s->kind = cfg->kind;
    s->ops = ops;
    s->comm = comm;
    int status = s->ops->create(&s->impl, &s->points, cfg);
    if (status == NSPD_OK && comm_distributed(&comm)) status = build_whole(s);
    if (status == NSPD_OK) status = nspd_alloc(&s->damage, (size_t)s->points.n + 1, sizeof(double));
    for (int d = 0; d < s->points.dim && status == NSPD_OK; d++)
        status = nspd_alloc(&s->position[d], (size_t)view(s)->n, sizeof(double));
    if (status != NSPD_OK) {
        solid_destroy(&s);
        return status;
    }
    *out = s;
    return NSPD_OK;
}

void solid_destroy(Solid **sp) {
    Solid *s = *sp;
    if (!s) return;
    if (s->impl) s->ops->destroy(s->impl);
    free_whole(s);
    nspd_free(&s->damage);
    for (int d = 0; d < 3; d++) nspd_free(&s->position[d]);
    nspd_free(sp);
}

SolidKind solid_kind(const Solid *s) {
    return s->kind;
}

const char *solid_name(const Solid *s) {
    return s->ops->name;
}

PdPoints *solid_points(Solid *s) {
    return comm_distributed(&s->comm) ? &s->whole : &s->points;
}

const PdPoints *solid_points_const(const Solid *s) {
    return view(s);
}

double solid_stable_dt(const Solid *s) {
    return s->ops->stable_dt(s->impl);
}

double solid_time(const Solid *s) {
    return s->ops->time(s->impl);
}

void solid_set_time(Solid *s, double t) {
    s->ops->set_time(s->impl, t);
}

/* The first point (the whole body's lowest index: the same on any thread
 * or process count) whose displacement or velocity is not finite or whose
 * speed is a runaway's. */
static int check_points(const Solid *s) {
    const PdPoints *p = &s->points;
    const double limit2 = SOLID_RUNAWAY_SPEED * SOLID_RUNAWAY_SPEED;
    int64_t first = p->n;
#pragma omp parallel for schedule(static) reduction(min : first) if (p->n >= 65536)
    for (int64_t i = 0; i < p->n; i++) {
        double u2 = 0.0, v2 = 0.0;
        for (int d = 0; d < p->dim; d++) {
            u2 += p->u[d][i] * p->u[d][i];
            v2 += p->v[d][i] * p->v[d][i];
        }
        /* NaN fails every comparison: !(x <= limit) catches it */
        if (!(u2 <= DBL_MAX) || !(v2 <= limit2)) first = i < first ? i : first;
    }
    char text[512] = "";
    int64_t bad = first < p->n ? s->first + first : INT64_MAX;
    if (bad != INT64_MAX) {
        const int64_t i = first;
        double speed = 0.0, disp = 0.0;
        for (int d = 0; d < p->dim; d++) {
            speed += p->v[d][i] * p->v[d][i];
            disp += p->u[d][i] * p->u[d][i];
        }
        char where[128];
        if (p->dim == 3)
            snprintf(where, sizeof where, "(%g, %g, %g)", p->x[0][i], p->x[1][i], p->x[2][i]);
        else
            snprintf(where, sizeof where, "(%g, %g)", p->x[0][i], p->x[1][i]);
        snprintf(text, sizeof text,
                 "the solid blew up by t = %g s: point %lld at %s m has displacement %g m and "
                 "speed %g m/s (limit %g m/s); expected a smaller time step (time.dt, "
                 "time.safety_factor)",
                 solid_time(s), (long long)bad, where, sqrt(disp), sqrt(speed),
                 SOLID_RUNAWAY_SPEED);
    }
    bad = comm_first_failure(&s->comm, bad, text, (int)sizeof text);
    return bad == INT64_MAX ? NSPD_OK : NSPD_FAIL(NSPD_ERR_NUMERIC, "%s", text);
}

/* Before an advance: on several processes the couplings' loads and
 * velocities handed to this process's points. */
static void take_whole_view(Solid *s) {
    if (comm_distributed(&s->comm)) { /* the couplings' loads on this process's points */
        const PdPoints *p = &s->points;
        for (int d = 0; d < p->dim; d++)
            memcpy(p->external[d], s->whole.external[d] + s->first, (size_t)p->n * sizeof(double));
        for (int d = 0; d < p->dim && s->velocities_changed; d++) /* and their velocities */
            memcpy(p->v[d], s->whole.v[d] + s->first, (size_t)p->n * sizeof(double));
    }
    s->velocities_changed = false;
    s->advances++;
}

bool solid_can_be_constrained(const Solid *s) {
    return s->ops->step_constrained != NULL;
}

int solid_advance_constrained(Solid *s, double dt) {
    take_whole_view(s);
    TRY(s->ops->step_constrained(s->impl, dt));
    s->last_substeps = 1;
    return check_points(s);
}

int solid_advance(Solid *s, double dt, double max_substep) {
    take_whole_view(s);
    int64_t n = (int64_t)ceil(dt / max_substep * (1.0 - 1e-12));
    if (n < 1) n = 1;
    double h = dt / (double)n;
    for (int64_t k = 0; k < n; k++) TRY(s->ops->step(s->impl, h));
    s->last_substeps = n;
    return check_points(s);
}

int64_t solid_last_substeps(const Solid *s) {
    return s->last_substeps;
}

const double *solid_damage(Solid *s) {
    s->ops->damage(s->impl, s->damage);
    if (!comm_distributed(&s->comm)) return s->damage;
    /* a failed gather is MPI's abort */
    (void)comm_allgatherv(&s->comm, s->damage, (int)s->points.n, s->damage_whole);
    return s->damage_whole;
}

void solid_current_positions(Solid *s, const double *out[3]) {
    const PdPoints *p = view(s);
    for (int d = 0; d < 3; d++) out[d] = NULL;
    for (int d = 0; d < p->dim; d++) {
        for (int64_t i = 0; i < p->n; i++) s->position[d][i] = p->x[d][i] + p->u[d][i];
        out[d] = s->position[d];
    }
}

double solid_modulus(const Solid *s, int64_t i) {
    return s->ops->modulus(s->impl, i);
}

double solid_density(const Solid *s, int64_t i) {
    return s->ops->density ? s->ops->density(s->impl, i) : (double)NAN;
}

bool solid_attached(const Solid *s, int64_t i) {
    if (comm_distributed(&s->comm)) return s->attached[i] != 0;
    return s->ops->attached ? s->ops->attached(s->impl, i) : true;
}

void solid_history(const Solid *s, Report *row) {
    s->ops->history(s->impl, row);
}

void solid_summary(const Solid *s, const RunStats *run, Report *out) {
    s->ops->summary(s->impl, run, out);
}

void solid_info(const Solid *s, size_t memory_bytes, char *buf, size_t size) {
    s->ops->info(s->impl, memory_bytes, buf, size);
}

void solid_brief(const Solid *s, char *buf, size_t size) {
    s->ops->brief(s->impl, buf, size);
}

/* A divided solid's piece of the .pvtu: this rank's run of the whole
 * view's fields, which every rank holds (a distributed model's own fields
 * are whole views too), so each writes its own points, in the whole
 * body's order. */
static void piece_of(const Solid *s, FieldSet *out) {
    FieldPiece *pc = &out->piece;
    const int64_t lo = s->run_first[s->comm.rank];
    pc->index = s->comm.rank;
    pc->count = s->comm.size;
    pc->n = s->run_first[s->comm.rank + 1] - lo;
    for (int d = 0; d < 3; d++) pc->position[d] = out->position[d] ? out->position[d] + lo : NULL;
    for (int k = 0; k < out->field_count; k++) {
        FieldRef f = out->field[k];
        for (int c = 0; c < 3; c++) f.data[c] = f.data[c] ? f.data[c] + lo : NULL;
        pc->field[pc->field_count++] = f;
    }
}

void solid_fields(Solid *s, const double *damage, FieldSet *out) {
    const PdPoints *p = view(s);
    memset(out, 0, sizeof *out);
    out->series = "solid";
    out->mesh = MESH_POINTS;
    out->n = p->n;
    out->dim = p->dim;
    out->spacing = p->spacing;
    /* current positions x + u, so cracks show as openings */
    solid_current_positions(s, out->position);
    const bool d3 = p->dim == 3;
    out->field[out->field_count++] =
        (FieldRef){"displacement", 3, {p->u[0], p->u[1], d3 ? p->u[2] : NULL}};
    out->field[out->field_count++] =
        (FieldRef){"velocity", 3, {p->v[0], p->v[1], d3 ? p->v[2] : NULL}};
    out->field[out->field_count++] = (FieldRef){"damage", 1, {damage, NULL, NULL}};
    out->field[out->field_count++] = (FieldRef){"volume", 1, {p->volume, NULL, NULL}};
    if (s->ops->fields) s->ops->fields(s->impl, out);
    if (comm_distributed(&s->comm)) piece_of(s, out);
    out->picture[out->picture_count++] = (PictureRef){.file = "damage",
                                                      .label = "damage",
                                                      .units = "-",
                                                      .values = damage,
                                                      .lo = 0.0,
                                                      .hi = 1.0,
                                                      .map = COLORMAP_VIRIDIS,
                                                      .overlay_map = COLORMAP_INFERNO};
}

int solid_checkpoint(Solid *s, Checkpoint *ck) {
    if (!s->ops->checkpoint)
        return NSPD_FAIL(NSPD_ERR_INPUT, "the solid model '%s' cannot be checkpointed",
                         s->ops->name);
    TRY(checkpoint_io_int64(ck, "solid.last_substeps", &s->last_substeps));
    TRY(s->ops->checkpoint(s->impl, ck));
    if (!checkpoint_reading(ck) || !comm_distributed(&s->comm)) return NSPD_OK;
    /* read back: the whole body's view, and the loads the model holds
     * (a coupling may advance on them before it writes new ones) */
    s->synced_at = -1;
    const PdPoints *p = &s->points;
    for (int d = 0; d < p->dim; d++)
        TRY(comm_allgatherv(&s->comm, p->external[d], (int)p->n, s->whole.external[d]));
    return solid_sync(s);
}

void *solid_impl(Solid *s, SolidKind kind) {
    return s && s->kind == kind ? s->impl : NULL;
}
