/* A new model needs no edit in sim/, case/ or the output code: three
 * test-only models - a flow that holds a uniform state, a rigid row of
 * points moving at a constant velocity, and a coupling that only counts
 * its calls - are registered through the same ops tables the built-in
 * models use, run by the unchanged driver, and appear in history.csv,
 * summary.json and the VTK series. The ghost-cell coupling refuses the
 * uniform flow with an input error. */
#include "test_support.h"

#include "core/mem.h"
#include "core/status.h"
#include "couple/coupling.h"
#include "couple/ghost/model.h"
#include "flow/flow.h"
#include "sim/sim.h"
#include "solid/solid.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------ a uniform flow */

typedef struct {
    int n; /* n x n cells on the unit square */
    double rho, u, p;
} UniformConfig;

typedef struct {
    UniformConfig cfg;
    double *face; /* n + 1 face coordinates, both axes (its own grid: no other model's) */
    double time;
    double *density; /* n * n, for output */
} UniformFlow;

static int uniform_create(void **impl, FlowConfig *cfg) {
    UniformFlow *f;
    TRY(nspd_alloc(&f, 1, sizeof *f));
    f->cfg = *(const UniformConfig *)cfg->model;
    int n = f->cfg.n;
    int status = nspd_alloc(&f->face, (size_t)n + 1, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&f->density, (size_t)(n * n), sizeof(double));
    if (status != NSPD_OK) {
        nspd_free(&f->face);
        nspd_free(&f);
        return status;
    }
    for (int k = 0; k <= n; k++) f->face[k] = (double)k / n;
    for (int c = 0; c < n * n; c++) f->density[c] = f->cfg.rho;
    *impl = f;
    return NSPD_OK;
}

static void uniform_destroy(void *impl) {
    UniformFlow *f = impl;
    nspd_free(&f->face);
    nspd_free(&f->density);
    nspd_free(&f);
}

static double uniform_stable_dt(const void *impl) {
    (void)impl;
    return 0.1;
}

static int uniform_step(void *impl, double dt) {
    ((UniformFlow *)impl)->time += dt;
    return NSPD_OK;
}

static double uniform_time(const void *impl) {
    return ((const UniformFlow *)impl)->time;
}

static FlowMesh uniform_mesh(const void *impl) {
    (void)impl;
    return (FlowMesh){MESH_GRID};
}

static void uniform_cell_state(const void *impl, int64_t cell, double out[5]) {
    (void)cell;
    const UniformConfig *c = &((const UniformFlow *)impl)->cfg;
    double q[5] = {c->rho, c->u, 0.0, c->p, c->p / c->rho};
    memcpy(out, q, sizeof q);
}

static FlowReference uniform_reference(const void *impl) {
    const UniformConfig *c = &((const UniformFlow *)impl)->cfg;
    return (FlowReference){c->rho, c->u, 0.0, c->p, 1.0, 1.4, 1.0};
}

static void uniform_history(const void *impl, Report *row) {
    report_precise(row, "uniform_mass_kg_per_m", ((const UniformFlow *)impl)->cfg.rho);
}

static void uniform_summary(const void *impl, const RunStats *run, Report *out) {
    (void)run;
    int n = ((const UniformFlow *)impl)->cfg.n;
    report_int(out, "uniform_cells", n * n);
}

static void uniform_info(const void *impl, size_t memory, char *buf, size_t size) {
    (void)impl;
    snprintf(buf, size, "uniform flow, %zu bytes\n", memory);
}

static void uniform_brief(const void *impl, char *buf, size_t size) {
    snprintf(buf, size, "%d uniform cells, ", ((const UniformFlow *)impl)->cfg.n);
}

static int64_t uniform_fallbacks(const void *impl) {
    (void)impl;
    return 0;
}

static void uniform_fields(void *impl, FieldSet *out) {
    UniformFlow *f = impl;
    memset(out, 0, sizeof *out);
    out->series = "flow";
    out->mesh = MESH_GRID;
    out->nx = out->ny = f->cfg.n;
    out->face[0] = f->face;
    out->face[1] = f->face;
    out->field[out->field_count++] = (FieldRef){"density", 1, {f->density, NULL, NULL}};
}

static const FlowOps UNIFORM_FLOW_OPS = {
    .name = "uniform",
    .create = uniform_create,
    .destroy = uniform_destroy,
    .stable_dt = uniform_stable_dt,
    .step = uniform_step,
    .time = uniform_time,
    .mesh = uniform_mesh,
    .cell_state = uniform_cell_state,
    .reference = uniform_reference,
    .history = uniform_history,
    .summary = uniform_summary,
    .info = uniform_info,
    .brief = uniform_brief,
    .fallbacks_total = uniform_fallbacks,
    .fields = uniform_fields,
};

/* ------------------------------------------------ a rigid row of points */

typedef struct {
    int n;
    double velocity; /* m/s along x */
} RigidConfig;

typedef struct {
    RigidConfig cfg;
    double time;
    double *x[3], *u[3], *v[3], *external[3], *volume;
} RigidSolid;

static void rigid_destroy(void *impl) {
    RigidSolid *r = impl;
    for (int d = 0; d < 3; d++) {
        nspd_free(&r->x[d]);
        nspd_free(&r->u[d]);
        nspd_free(&r->v[d]);
        nspd_free(&r->external[d]);
    }
    nspd_free(&r->volume);
    nspd_free(&r);
}

static int rigid_create(void **impl, PdPoints *pts, SolidConfig *cfg) {
    RigidSolid *r;
    TRY(nspd_alloc(&r, 1, sizeof *r));
    r->cfg = *(const RigidConfig *)cfg->model;
    const size_t n = (size_t)r->cfg.n;
    int status = nspd_alloc(&r->volume, n, sizeof(double));
    for (int d = 0; d < 3 && status == NSPD_OK; d++) {
        status = nspd_alloc(&r->x[d], n, sizeof(double));
        if (status == NSPD_OK) status = nspd_alloc(&r->u[d], n, sizeof(double));
        if (status == NSPD_OK) status = nspd_alloc(&r->v[d], n, sizeof(double));
        if (status == NSPD_OK) status = nspd_alloc(&r->external[d], n, sizeof(double));
    }
    if (status != NSPD_OK) {
        rigid_destroy(r);
        return status;
    }
    for (int i = 0; i < r->cfg.n; i++) {
        r->x[0][i] = 0.1 * i;
        r->v[0][i] = r->cfg.velocity;
        r->volume[i] = 1e-2;
    }
    *pts =
        (PdPoints){.dim = 2, .n = r->cfg.n, .spacing = 0.1, .thickness = 1.0, .volume = r->volume};
    for (int d = 0; d < 3; d++) {
        pts->x[d] = r->x[d];
        pts->u[d] = r->u[d];
        pts->v[d] = r->v[d];
        pts->external[d] = r->external[d];
    }
    *impl = r;
    return NSPD_OK;
}

static double rigid_stable_dt(const void *impl) {
    (void)impl;
    return 0.05;
}

static int rigid_step(void *impl, double dt) {
    RigidSolid *r = impl;
    for (int i = 0; i < r->cfg.n; i++) r->u[0][i] += r->v[0][i] * dt;
    r->time += dt;
    return NSPD_OK;
}

static double rigid_time(const void *impl) {
    return ((const RigidSolid *)impl)->time;
}

static void rigid_set_time(void *impl, double t) {
    ((RigidSolid *)impl)->time = t;
}

static void rigid_damage(const void *impl, double *out) {
    for (int i = 0; i < ((const RigidSolid *)impl)->cfg.n; i++) out[i] = 0.0;
}

static double rigid_modulus(const void *impl, int64_t i) {
    (void)impl;
    (void)i;
    return INFINITY;
}

static void rigid_history(const void *impl, Report *row) {
    report_real(row, "rigid_displacement_m", ((const RigidSolid *)impl)->u[0][0]);
}

static void rigid_summary(const void *impl, const RunStats *run, Report *out) {
    (void)run;
    report_int(out, "rigid_points", ((const RigidSolid *)impl)->cfg.n);
}

static void rigid_info(const void *impl, size_t memory, char *buf, size_t size) {
    (void)impl;
    snprintf(buf, size, "rigid row, %zu bytes\n", memory);
}

static void rigid_brief(const void *impl, char *buf, size_t size) {
    snprintf(buf, size, "%d rigid points, ", ((const RigidSolid *)impl)->cfg.n);
}

static const SolidOps RIGID_SOLID_OPS = {
    .name = "rigid",
    .create = rigid_create,
    .destroy = rigid_destroy,
    .stable_dt = rigid_stable_dt,
    .step = rigid_step,
    .time = rigid_time,
    .set_time = rigid_set_time,
    .damage = rigid_damage,
    .modulus = rigid_modulus,
    .history = rigid_history,
    .summary = rigid_summary,
    .info = rigid_info,
    .brief = rigid_brief,
};

/* ------------------------------------------------ a coupling that counts */

typedef struct {
    int64_t before, after;
} Counter;

static int counter_create(void **impl, CouplingConfig *cfg, Solid *solid, Flow *flow) {
    (void)cfg;
    if (!solid || !flow) return NSPD_FAIL(NSPD_ERR_INPUT, "the counter needs both sides");
    Counter *c;
    TRY(nspd_alloc(&c, 1, sizeof *c));
    *impl = c;
    return NSPD_OK;
}

static void counter_destroy(void *impl) {
    Counter *c = impl;
    nspd_free(&c);
}

static int counter_before(void *impl, Solid *solid, Flow *flow) {
    (void)solid;
    (void)flow;
    ((Counter *)impl)->before++;
    return NSPD_OK;
}

static int counter_after(void *impl, Solid *solid, Flow *flow, double dt) {
    (void)solid;
    (void)flow;
    (void)dt;
    ((Counter *)impl)->after++;
    return NSPD_OK;
}

static double counter_limit(const void *impl, const Solid *solid) {
    (void)impl;
    (void)solid;
    return 0.02; /* tighter than the solid's own 0.8 x 0.05 s */
}

static void counter_loads(const void *impl, CouplingLoads *out) {
    (void)impl;
    out->force_on_solid[0] = out->force_on_solid[1] = 0.0;
}

static int counter_history(void *impl, Solid *solid, Flow *flow, double time, Report *row) {
    (void)solid;
    (void)flow;
    (void)time;
    report_int(row, "coupling_calls", ((Counter *)impl)->before + ((Counter *)impl)->after);
    return NSPD_OK;
}

static int counter_summary(void *impl, Solid *solid, Flow *flow, Report *out) {
    (void)solid;
    (void)flow;
    report_int(out, "coupling_before_calls", ((Counter *)impl)->before);
    return NSPD_OK;
}

static int counter_fields(void *impl, Solid *solid, Flow *flow, FieldSet *out) {
    (void)impl;
    (void)solid;
    (void)flow;
    memset(out, 0, sizeof *out);
    return NSPD_OK;
}

static const CouplingOps COUNTER_OPS = {
    .name = "counter",
    .create = counter_create,
    .destroy = counter_destroy,
    .before_flow = counter_before,
    .after_flow = counter_after,
    .solid_dt_limit = counter_limit,
    .loads = counter_loads,
    .history = counter_history,
    .summary = counter_summary,
    .fields = counter_fields,
};

/* The same coupling, whose load on the solid stops being finite after its
 * third step (a broken-down flow next to the solid). */
static void nan_loads(const void *impl, CouplingLoads *out) {
    const bool broken = ((const Counter *)impl)->after >= 3;
    out->force_on_solid[0] = broken ? (double)NAN : 0.0;
    out->force_on_solid[1] = 0.0;
}

static const CouplingOps NAN_LOADS_OPS = {
    .name = "nan_loads",
    .create = counter_create,
    .destroy = counter_destroy,
    .before_flow = counter_before,
    .after_flow = counter_after,
    .solid_dt_limit = counter_limit,
    .loads = nan_loads,
    .history = counter_history,
    .summary = counter_summary,
    .fields = counter_fields,
};

/* ------------------------------------------------ the tests */

static UniformConfig UNIFORM = {4, 1.2, 3.0, 1e5};
static RigidConfig RIGID = {5, 2.0};

static void config(SimConfig *c, FlowMethod flow, SolidKind solid, CouplingKind coupling) {
    memset(c, 0, sizeof *c);
    snprintf(c->name, sizeof c->name, "extension");
    c->end_time = 1.0;
    c->safety_factor = 0.8;
    c->flow.method = flow;
    c->flow.model = &UNIFORM; /* borrowed: the ops have no config_free */
    c->solid.kind = solid;
    c->solid.model = &RIGID;
    c->coupling.kind = coupling;
    if (coupling == COUPLING_GHOST_CELL) /* a built-in coupling owns its (empty) configuration */
        assert_ok(nspd_alloc(&c->coupling.model, 1, sizeof(GhostCouplingConfig)));
    c->output = (OutputConfig){.field_interval = 0.5, .history_interval = 0.1, .vtk = true};
}

static void test_registered_models_run_unchanged(void **state) {
    (void)state;
    FlowMethod flow = flow_register(&UNIFORM_FLOW_OPS);
    SolidKind solid = solid_register(&RIGID_SOLID_OPS);
    CouplingKind coupling = coupling_register(&COUNTER_OPS);
    assert_true(flow >= FLOW_METHOD_COUNT && solid >= SOLID_KIND_COUNT &&
                coupling >= COUPLING_KIND_COUNT);
    SimConfig c;
    config(&c, flow, solid, coupling);
    Sim sim;
    assert_ok(sim_create(&sim, &c));
    assert_close(sim.solid_substep, 0.02, 0.0); /* the coupling's limit */
    const char *dir = test_scratch_dir("extension");
    SimRunOptions opt = {dir, false, NULL};
    assert_ok(sim_run(&sim, &opt));
    assert_int_equal(sim.step, 10);
    assert_int_equal(solid_last_substeps(sim.solid), 5); /* 0.1 s in steps of 0.02 s */
    /* the rigid row moved 2 m/s x 1 s, and its clock is the flow's */
    assert_close(solid_points(sim.solid)->u[0][3], 2.0, 1e-12);
    assert_close(solid_time(sim.solid), 1.0, 1e-15);
    sim_destroy(&sim);

    char path[4200];
    snprintf(path, sizeof path, "%s/history.csv", dir);
    char *history = test_read_file(path);
    assert_non_null(history);
    assert_true(strncmp(history,
                        "step,time_s,rigid_displacement_m,uniform_mass_kg_per_m,coupling_calls\n",
                        70) == 0);
    assert_non_null(strstr(history, "\n10,1,2,1.2,20\n"));
    free(history);
    snprintf(path, sizeof path, "%s/summary.json", dir);
    char *summary = test_read_file(path);
    assert_non_null(summary);
    assert_non_null(strstr(summary, "\"rigid_points\": 5"));
    assert_non_null(strstr(summary, "\"uniform_cells\": 16"));
    assert_non_null(strstr(summary, "\"coupling_before_calls\": 10"));
    free(summary);
    static const char *const files[] = {"flow_00002.vtr", "solid_00002.vtu", "flow.pvd",
                                        "solid.pvd"};
    for (int k = 0; k < 4; k++) {
        snprintf(path, sizeof path, "%s/%s", dir, files[k]);
        char *text = test_read_file(path);
        if (!text) fail_msg("no %s", files[k]);
        free(text);
    }
}

static void test_ghost_cells_refuse_another_flow(void **state) {
    (void)state;
    SimConfig c;
    config(&c, flow_register(&UNIFORM_FLOW_OPS), SOLID_NONE, COUPLING_GHOST_CELL);
    Sim sim;
    assert_int_equal(sim_create(&sim, &c), NSPD_ERR_INPUT);
    assert_non_null(strstr(nspd_error_message(), "GKS"));
}

/* A load that is not finite stops the run in the step it appears, whatever
 * the coupling, and summary.json says why. */
static void test_non_finite_load_stops_the_run(void **state) {
    (void)state;
    SimConfig c;
    config(&c, flow_register(&UNIFORM_FLOW_OPS), solid_register(&RIGID_SOLID_OPS),
           coupling_register(&NAN_LOADS_OPS));
    Sim sim;
    assert_ok(sim_create(&sim, &c));
    const char *dir = test_scratch_dir("extension_nan");
    SimRunOptions opt = {dir, false, NULL};
    assert_int_equal(sim_run(&sim, &opt), NSPD_ERR_NUMERIC);
    assert_int_equal(sim.step, 2); /* the third step failed */
    assert_non_null(strstr(nspd_error_message(),
                           "the nan_loads coupling's load on the solid is not finite (nan, 0)"));
    assert_non_null(strstr(nspd_error_message(), "in step 3, from t = 0.2 s"));
    sim_destroy(&sim);
    char path[4200];
    snprintf(path, sizeof path, "%s/summary.json", dir);
    char *summary = test_read_file(path);
    assert_non_null(summary);
    assert_non_null(strstr(summary, "\"completed\": false"));
    assert_non_null(strstr(summary, "\"stopped_by\": \"the nan_loads coupling"));
    free(summary);
}

/* A model without a checkpoint operation: asking for a checkpoint is an
 * input error that names it, and nothing is left behind. */
static void test_checkpoint_of_a_model_without_one(void **state) {
    (void)state;
    SimConfig c;
    config(&c, flow_register(&UNIFORM_FLOW_OPS), SOLID_NONE, COUPLING_NONE);
    Sim sim;
    assert_ok(sim_create(&sim, &c));
    const char *dir = test_scratch_dir("extension_checkpoint");
    sim.dir = dir;
    assert_int_equal(sim_checkpoint_write(&sim), NSPD_ERR_INPUT);
    assert_non_null(
        strstr(nspd_error_message(), "the flow solver 'uniform' cannot be checkpointed"));
    char path[4200];
    snprintf(path, sizeof path, "%s/checkpoint_000000000000.nspd.part", dir);
    assert_null(test_read_file(path));
    snprintf(path, sizeof path, "%s/checkpoint_000000000000.nspd", dir);
    assert_null(test_read_file(path));
    sim_destroy(&sim);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_registered_models_run_unchanged),
        cmocka_unit_test(test_ghost_cells_refuse_another_flow),
        cmocka_unit_test(test_non_finite_load_stops_the_run),
        cmocka_unit_test(test_checkpoint_of_a_model_without_one),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
