/* Several bodies on the PDDO flow (issue 13), through the whole pipeline
 * from cases/cylinders_tandem_re10.yaml (coarse, with --set overrides):
 *  - mirror symmetry: two cylinders side by side, placed symmetrically
 *    about the channel's axis, feel mirrored forces (the same drag,
 *    opposite lifts) and two probes at mirrored points read mirrored
 *    values (the same u and p, opposite v) to round-off;
 *  - the start-up seed: a brief spin breaks the mirror symmetry, then
 *    the wall is at rest again;
 *  - the tandem case on 1 and on 2 threads: the same bits (velocity,
 *    pressure, every force column, the probes);
 *  - the case's outputs: the first body's forces under the plain names,
 *    the second's under its name (back_; body1_ by default: the GKS
 *    flow's rule), and the probes' columns in history.csv. */
#include "sim_fixtures.h"
#include "test_support.h"

#include "core/report.h"
#include "flow/flow.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const CASE = "cylinders_tandem_re10.yaml";

/* Side by side about y = 4 in a 15 m x 8 m channel (dx 0.2, patches to
 * 1 m), 50 steps of 2e-3 s from rest; probes at (6.1, 2.05) and
 * (6.1, 5.95), between nodes.
 * Measured: drags 331.354 N/m each, lifts -+4.523 N/m (the lower body
 * pulled down, the upper up); the mirror errors |L0 + L1| / |L0| 5.5e-15,
 * |D0 - D1| / D0 3.4e-16, probes (u 6.93 m/s, v 3.20 m/s, p 22.3 Pa)
 * |u_a - u_b| 1.3e-16 of |u|, |v_a + v_b| 2.1e-15 of |v|, |p_a - p_b|
 * 5.6e-15 of |p|. The cloud is mirrored only to an ulp (each patch's
 * nodes come from its own centre) and the PPE's round-off is not
 * symmetric: asserted 1e-10 relative, room for other compilers and
 * longer runs. */
static void test_mirror_symmetry(void **state) {
    (void)state;
    static const char *const sets[] = {
        "flow.domain={min: [0.0, 0.0], max: [15.0, 8.0]}",
        "flow.spacing=0.2",
        "flow.bodies=[{shape: circle, center: [5.0, 2.5], radius: 0.5, patch_radius: 1.0}, "
        "{shape: circle, center: [5.0, 5.5], radius: 0.5, patch_radius: 1.0}]",
        "output.probes=[{type: point, name: a, on: flow, at: [6.1, 2.05]}, "
        "{type: point, name: b, on: flow, at: [6.1, 5.95]}]",
        "time.dt=2e-3",
        "time.end=0.1",
        "output.average_from=0.05",
    };
    Sim sim;
    fixture_sim(CASE, sets, sizeof sets / sizeof *sets, &sim);
    assert_ok(sim_advance(&sim, 50));
    const double d0 = fixture_flow_history(&sim, "drag_n"),
                 d1 = fixture_flow_history(&sim, "body1_drag_n"),
                 l0 = fixture_flow_history(&sim, "lift_n"),
                 l1 = fixture_flow_history(&sim, "body1_lift_n");
    double a[5], b[5];
    flow_probe_state(sim.flow, sim.probes[0].point, a);
    flow_probe_state(sim.flow, sim.probes[1].point, b);
    const double el = fabs(l0 + l1) / fabs(l0), ed = fabs(d0 - d1) / d0;
    const double eu = fabs(a[1] - b[1]) / fabs(a[1]), ev = fabs(a[2] + b[2]) / fabs(a[2]),
                 ep = fabs(a[3] - b[3]) / fabs(a[3]);
    printf("side by side: drags %.6g %.6g N/m, lifts %.6g %.6g N/m; mirror errors lift %.1e drag "
           "%.1e; probes u %.6g v %.6g p %.6g: errors %.1e %.1e %.1e\n",
           d0, d1, l0, l1, el, ed, a[1], a[2], a[3], eu, ev, ep);
    assert_true(fabs(l0) > 1.0 && fabs(a[2]) > 1e-3); /* non-trivial: the check can fail */
    assert_true(el < 1e-10 && ed < 1e-10 && eu < 1e-10 && ev < 1e-10 && ep < 1e-10);
    sim_destroy(&sim);
}

/* The start-up seed (flow.seed): one cylinder on the channel's axis, dx
 * 0.2, 32 nodes a ring, so one sits on top at (5, 4.5); steps of 2e-3 s
 * from rest. Without a seed the lift stays at round-off (measured
 * 3.0e-12 N/m against a drag of 510 N/m after 5 steps); with the walls
 * turning counterclockwise at 5 m/s until 0.01 s the top node moves at
 * -5 m/s along x (exactly the prescribed value) and the lift is the
 * Magnus force's, downward (measured -16.5 N/m at 3 steps); from 0.01 s
 * the wall is at rest again (exactly 0) and the lift stays finite
 * (-23.5 N/m after 5 steps). Bounds: round-off 1e-10 of the drag
 * (as the mirror test), and a lift of at least 1 % of the drag. */
static void test_spin_seed(void **state) {
    (void)state;
    double lift[2], drag[2], top_during[5], top_after[5];
    for (int seeded = 0; seeded < 2; seeded++) {
        const char *sets[] = {
            "flow.domain={min: [0.0, 0.0], max: [15.0, 8.0]}",
            "flow.spacing=0.2",
            "flow.bodies=[{shape: circle, center: [5.0, 4.0], radius: 0.5, patch_radius: 1.0}]",
            "output.probes=[{type: point, name: top, on: flow, at: [5.0, 4.5]}]",
            "time.dt=2e-3",
            "time.end=0.1",
            "output.average_from=0.05",
            seeded ? "flow.seed={spin: 5.0, until: 0.01}" : "flow.seed=null",
        };
        Sim sim;
        fixture_sim(CASE, sets, sizeof sets / sizeof *sets, &sim);
        assert_ok(sim_advance(&sim, 3));
        if (seeded) {
            flow_probe_state(sim.flow, sim.probes[0].point, top_during);
            printf("spinning, 3 steps: top node u %.6g v %.3g m/s, lift %.6g N/m\n", top_during[1],
                   top_during[2], fixture_flow_history(&sim, "lift_n"));
            assert_true(fixture_flow_history(&sim, "lift_n") < 0.0); /* Magnus: down */
        }
        assert_ok(sim_advance(&sim, 2));
        flow_probe_state(sim.flow, sim.probes[0].point, top_after);
        lift[seeded] = fixture_flow_history(&sim, "lift_n");
        drag[seeded] = fixture_flow_history(&sim, "drag_n");
        sim_destroy(&sim);
    }
    printf("5 steps: lift %.3g N/m unseeded (drag %.6g), %.6g N/m seeded (drag %.6g); top node "
           "after the seed u %.3g v %.3g m/s\n",
           lift[0], drag[0], lift[1], drag[1], top_after[1], top_after[2]);
    assert_true(fabs(lift[0]) < 1e-10 * drag[0]);
    assert_true(top_during[1] == -5.0 && fabs(top_during[2]) < 1e-14);
    assert_true(top_after[1] == 0.0 && top_after[2] == 0.0);
    assert_true(lift[1] < -0.01 * drag[1]);
}

typedef struct {
    int64_t n;
    double *state;   /* u, v, p of the physical nodes */
    double cols[20]; /* the force and probe columns */
} Snapshot;

static const char *const COLUMNS[] = {
    "drag_n",  "lift_n",        "drag_viscous_n", "cl",       "back_drag_n", "back_lift_n",
    "back_cd", "gap_u_m_per_s", "gap_v_m_per_s",  "gap_p_Pa", "wake_p_Pa",   "outlet_u_m_per_s"};
enum { NCOL = sizeof COLUMNS / sizeof *COLUMNS };

/* The tandem case at dx 0.1 (12,453 nodes: above PARALLEL_MIN_ITEMS, so
 * the loops split), 10 steps of 1e-3 s on `threads` threads. */
static Snapshot tandem(int threads) {
    static const char *const sets[] = {"time.end=0.01", "output.average_from=0.005"};
    const int saved = omp_get_max_threads();
    omp_set_num_threads(threads);
    Sim sim;
    fixture_sim(CASE, sets, 2, &sim);
    assert_ok(sim_advance(&sim, 10));
    Snapshot s = {0};
    FieldSet fs;
    flow_fields(sim.flow, &fs);
    s.n = fs.n;
    s.state = malloc(3 * (size_t)s.n * sizeof(double));
    assert_non_null(s.state);
    memcpy(s.state, fs.field[0].data[0], (size_t)s.n * sizeof(double));
    memcpy(s.state + s.n, fs.field[0].data[1], (size_t)s.n * sizeof(double));
    memcpy(s.state + 2 * s.n, fs.field[1].data[0], (size_t)s.n * sizeof(double));
    Report *row = calloc(1, sizeof *row);
    assert_non_null(row);
    flow_history(sim.flow, row);
    probes_sample(sim.probes, sim.cfg.output.probe_count, NULL, NULL, sim.flow, sim.time, row);
    for (int k = 0; k < NCOL; k++) {
        const ReportItem *it = report_find(row, COLUMNS[k]);
        if (!it) fail_msg("no history column %s", COLUMNS[k]);
        s.cols[k] = it->real;
    }
    free(row);
    sim_destroy(&sim);
    omp_set_num_threads(saved);
    return s;
}

static void test_threads_bitwise(void **state) {
    (void)state;
    Snapshot one = tandem(1), two = tandem(2);
    printf("tandem, 10 steps: %lld physical nodes; drags %.9g %.9g N/m, gap u %.9g m/s\n",
           (long long)one.n, one.cols[0], one.cols[4], one.cols[7]);
    assert_int_equal(one.n, two.n);
    assert_memory_equal(one.state, two.state, 3 * (size_t)one.n * sizeof(double));
    assert_memory_equal(one.cols, two.cols, sizeof one.cols);
    free(one.state);
    free(two.state);
}

/* The outputs of a short run (dx 0.2): the columns and keys docs/CASES.md
 * promises, and the probes' values in history.csv as the flow reads them
 * at the end. */
static void test_case_outputs(void **state) {
    (void)state;
    static const char *const sets[] = {"flow.spacing=0.2",
                                       "time.dt=2e-3",
                                       "time.end=0.1",
                                       "output.average_from=0.05",
                                       "output.field_interval=0.1",
                                       "output.history_interval=0.05"};
    Sim sim;
    fixture_sim(CASE, sets, sizeof sets / sizeof *sets, &sim);
    const char *dir = test_scratch_dir("pddo_bodies");
    SimRunOptions opt = {dir, false, NULL};
    assert_ok(sim_run(&sim, &opt));
    double gap[5];
    flow_probe_state(sim.flow, sim.probes[0].point, gap);
    sim_destroy(&sim);
    char path[1300];
    snprintf(path, sizeof path, "%s/history.csv", dir);
    char *history = test_read_file(path);
    assert_non_null(history);
    const char *header_has[] = {",drag_n,lift_n,", ",cl,back_drag_n,", ",back_cl,",
                                ",gap_u_m_per_s,gap_v_m_per_s,gap_p_Pa,", ",outlet_p_Pa"};
    for (size_t k = 0; k < sizeof header_has / sizeof *header_has; k++)
        if (!strstr(history, header_has[k])) fail_msg("history.csv lacks %s", header_has[k]);
    assert_null(strstr(history, "gap_T_K"));
    assert_null(strstr(history, "body0_"));
    /* the last row's gap_p_Pa (its column found in the header), as the
     * flow reads it now */
    int column = 0;
    for (const char *h = history; h < strstr(history, ",gap_p_Pa,"); h++) column += *h == ',';
    const char *last = history + strlen(history) - 2;
    while (last > history && *last != '\n') last--;
    const char *field = last + 1;
    for (int c = 0; c <= column; c++) field = strchr(field, ',') + 1;
    const double p = strtod(field, NULL);
    printf("history.csv: gap p %.9g Pa at the end (the flow: %.9g Pa)\n", p, gap[3]);
    assert_true(fabs(p - gap[3]) <= 1e-8 * fabs(gap[3]));
    free(history);
    snprintf(path, sizeof path, "%s/summary.json", dir);
    char *summary = test_read_file(path);
    assert_non_null(summary);
    const char *keys[] = {
        "\"cd\": ", "\"lift_periods\": ", "\"back_cd\": ", "\"back_lift_periods\": "};
    for (size_t k = 0; k < sizeof keys / sizeof *keys; k++)
        if (!strstr(summary, keys[k])) fail_msg("summary.json lacks %s", keys[k]);
    free(summary);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_mirror_symmetry),
        cmocka_unit_test(test_spin_seed),
        cmocka_unit_test(test_threads_bitwise),
        cmocka_unit_test(test_case_outputs),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
