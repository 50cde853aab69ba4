/* couple/penalty with `damaged: true` (Eq. 23): a fully damaged band of a
 * wall carries no force and lets the gas through. A test-only solid - a
 * held wall of points across a channel, damage 1 in a band of rows at mid
 * height and 0 elsewhere - is registered through SolidOps (the penalty
 * coupling sees solids only through the interface), and a 2:1 pressure
 * step is released against it: the band's points never receive an
 * impulse (their velocity stays exactly 0), the gas streams through the
 * band behind the wall, and the intact rows hold it back. */
#include "test_support.h"

#include "case/case_read.h"
#include "core/mem.h"
#include "core/status.h"
#include "flow/flow.h"
#include "sim/sim.h"
#include "sim_fixtures.h"
#include "solid/solid.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

enum { NX = 30, NY = 60 }; /* points across and along the wall */
static const double X0 = 0.45, H = 0.1 / NY, GAP_LO = 0.04, GAP_HI = 0.06;

typedef struct {
    double *x[3], *u[3], *v[3], *external[3], *volume;
    double time;
} GateSolid;

static void gate_destroy(void *impl) {
    GateSolid *g = impl;
    for (int d = 0; d < 3; d++) {
        nspd_free(&g->x[d]);
        nspd_free(&g->u[d]);
        nspd_free(&g->v[d]);
        nspd_free(&g->external[d]);
    }
    nspd_free(&g->volume);
    nspd_free(&g);
}

static bool in_gap(const GateSolid *g, int64_t i) {
    return g->x[1][i] > GAP_LO && g->x[1][i] < GAP_HI;
}

static int gate_create(void **impl, PdPoints *pts, SolidConfig *cfg) {
    (void)cfg;
    GateSolid *g;
    TRY(nspd_alloc(&g, 1, sizeof *g));
    const size_t n = NX * NY;
    int status = nspd_alloc(&g->volume, n, sizeof(double));
    for (int d = 0; d < 3 && status == NSPD_OK; d++) {
        status = nspd_alloc(&g->x[d], n, sizeof(double));
        if (status == NSPD_OK) status = nspd_alloc(&g->u[d], n, sizeof(double));
        if (status == NSPD_OK) status = nspd_alloc(&g->v[d], n, sizeof(double));
        if (status == NSPD_OK) status = nspd_alloc(&g->external[d], n, sizeof(double));
    }
    if (status != NSPD_OK) {
        gate_destroy(g);
        return status;
    }
    for (int j = 0; j < NY; j++)
        for (int i = 0; i < NX; i++) {
            const int k = j * NX + i;
            g->x[0][k] = X0 + (i + 0.5) * H;
            g->x[1][k] = (j + 0.5) * H;
            g->volume[k] = H * H;
        }
    *pts =
        (PdPoints){.dim = 2, .n = (int64_t)n, .spacing = H, .thickness = 1.0, .volume = g->volume};
    for (int d = 0; d < 3; d++) {
        pts->x[d] = g->x[d];
        pts->u[d] = g->u[d];
        pts->v[d] = g->v[d];
        pts->external[d] = g->external[d];
    }
    *impl = g;
    return NSPD_OK;
}

static double gate_stable_dt(const void *impl) {
    (void)impl;
    return 1e-3;
}

/* Held: the intact points are brought back to rest (as a fixed boundary
 * region is); the band's are left as the coupling left them. */
static int gate_step(void *impl, double dt) {
    GateSolid *g = impl;
    for (int64_t i = 0; i < NX * NY; i++)
        if (!in_gap(g, i)) g->v[0][i] = g->v[1][i] = 0.0;
    g->time += dt;
    return NSPD_OK;
}

static double gate_time(const void *impl) {
    return ((const GateSolid *)impl)->time;
}

static void gate_set_time(void *impl, double t) {
    ((GateSolid *)impl)->time = t;
}

static void gate_damage(const void *impl, double *out) {
    for (int64_t i = 0; i < NX * NY; i++) out[i] = in_gap(impl, i) ? 1.0 : 0.0;
}

static double gate_modulus(const void *impl, int64_t i) {
    (void)impl;
    (void)i;
    return 200e9;
}

static double gate_density(const void *impl, int64_t i) {
    (void)impl;
    (void)i;
    return 7850.0;
}

static void gate_history(const void *impl, Report *row) {
    (void)impl;
    (void)row;
}

static void gate_summary(const void *impl, const RunStats *run, Report *out) {
    (void)impl;
    (void)run;
    (void)out;
}

static void gate_info(const void *impl, size_t memory, char *buf, size_t size) {
    (void)impl;
    snprintf(buf, size, "gate, %zu bytes\n", memory);
}

static void gate_brief(const void *impl, char *buf, size_t size) {
    (void)impl;
    snprintf(buf, size, "gate, ");
}

static const SolidOps GATE_OPS = {
    .name = "gate",
    .create = gate_create,
    .destroy = gate_destroy,
    .stable_dt = gate_stable_dt,
    .step = gate_step,
    .time = gate_time,
    .set_time = gate_set_time,
    .damage = gate_damage,
    .modulus = gate_modulus,
    .density = gate_density,
    .history = gate_history,
    .summary = gate_summary,
    .info = gate_info,
    .brief = gate_brief,
};

/* A 1 m x 0.1 m channel of 5 mm cells, 2e5 Pa left of 0.3 m, 1e5 right,
 * the penalty with damage; the bond solid of the text is replaced by the
 * gate before the build. */
static const char CASE_TEXT[] =
    "name: gap\n"
    "time: {end: 1.0}\n"
    "solid:\n"
    "  model: plane_strain\n"
    "  spacing: 0.01\n"
    "  thickness: 1.0\n"
    "  material: {density: 7850, youngs_modulus: 200.0e9}\n"
    "  geometry: [{shape: rectangle, min: [0.45, 0.0], max: [0.55, 0.1]}]\n"
    "flow:\n"
    "  gas: {gamma: 1.4, gas_constant: 287.0, prandtl: 0.72, viscosity: {law: none}}\n"
    "  grid:\n"
    "    x: {segments: [{length: 1.0, spacing: 5.0e-3}]}\n"
    "    y: {segments: [{length: 0.1, spacing: 5.0e-3}]}\n"
    "  boundaries:\n"
    "    x_min: {type: extrapolation}\n"
    "    x_max: {type: extrapolation}\n"
    "    y_min: {type: slip_wall}\n"
    "    y_max: {type: slip_wall}\n"
    "  initial:\n"
    "    state: {density: 1.2014708, velocity: [0.0, 0.0], pressure: 1.0e5}\n"
    "    regions:\n"
    "      - region: [{shape: rectangle, min: [-1.0, -1.0], max: [0.3, 1.0]}]\n"
    "        state: {density: 2.4029416, velocity: [0.0, 0.0], pressure: 2.0e5}\n"
    "coupling: {kind: penalty, damaged: true, h: 5.0e-3, dt: 1.0e-7}\n"
    "output: {field_interval: 1.0, history_interval: 1.0}\n";

/* The gas's x velocity at (x, y). */
static double gas_u(Sim *sim, double x, double y) {
    double s[5];
    fixture_flow_state_at(sim, x, y, s);
    return s[1];
}

static void test_gap(void **state) {
    (void)state;
    const SolidKind kind = solid_register(&GATE_OPS);
    assert_true(kind >= SOLID_KIND_COUNT);
    const char *path = fixture_case_file("penalty_gap", CASE_TEXT);
    CfgDoc doc;
    SimConfig cfg;
    assert_ok(case_read(path, NULL, 0, &doc, &cfg));
    solid_config_free(&cfg.solid);
    cfg.solid = (SolidConfig){.kind = kind}; /* no configuration of its own */
    Sim sim;
    assert_ok(sim_create(&sim, &cfg));
    cfg_doc_free(&doc);
    const PdPoints *p = solid_points_const(sim.solid);
    int64_t band = 0;
    while (sim.time < 1.0e-3) {
        assert_ok(sim_advance(&sim, 1));
        band = 0;
        for (int64_t i = 0; i < p->n; i++) {
            if (!(p->x[1][i] > GAP_LO && p->x[1][i] < GAP_HI)) continue;
            band++;
            /* no impulse, ever: the coupling wrote nothing to them */
            assert_true(p->v[0][i] == 0.0 && p->v[1][i] == 0.0);
        }
    }
    assert_int_equal(band, 12 * NX); /* 12 rows of 1.67 mm in the 2 cm band */
    /* behind the wall, the gas streams out of the band; the wall's intact
     * part holds it back */
    const double through = gas_u(&sim, 0.5, 0.05), blocked = gas_u(&sim, 0.5, 0.015);
    const double behind = gas_u(&sim, 0.575, 0.05);
    printf("at 1 ms: u in the band %.2f m/s, behind it %.2f m/s, in the intact wall %.3g m/s\n",
           through, behind, blocked);
    assert_true(through > 50.0 && behind > 20.0);
    assert_true(fabs(blocked) < 0.01 * through);
    sim_destroy(&sim);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_gap)};
    return cmocka_run_group_tests(tests, NULL, NULL);
}
