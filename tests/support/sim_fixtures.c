#include "sim_fixtures.h"

#include "test_support.h"

#include "case/case_read.h"
#include "flow/flow.h"

#include <stdio.h>

void fixture_sim(const char *case_file, const char *const *overrides, int count, Sim *sim) {
    char rel[512];
    snprintf(rel, sizeof rel, "cases/%s", case_file);
    CfgDoc doc;
    SimConfig cfg;
    assert_ok(case_read(test_source_path(rel), (char *const *)overrides, count, &doc, &cfg));
    assert_ok(sim_create(sim, &cfg));
    cfg_doc_free(&doc);
}

const char *fixture_case_file(const char *tag, const char *yaml) {
    static char path[1200];
    snprintf(path, sizeof path, "%s/case.yaml", test_scratch_dir(tag));
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(yaml, f);
    fclose(f);
    return path;
}

void fixture_sim_text(const char *yaml, Sim *sim) {
    const char *path = fixture_case_file("fixture_case", yaml);
    CfgDoc doc;
    SimConfig cfg;
    assert_ok(case_read(path, NULL, 0, &doc, &cfg));
    assert_ok(sim_create(sim, &cfg));
    cfg_doc_free(&doc);
}

BondBody *fixture_body(Sim *sim) {
    BondBody *b = bond_solid_body(sim->solid);
    assert_non_null(b);
    return b;
}

GksSolver *fixture_flow(Sim *sim) {
    GksSolver *f = gks_flow_solver(sim->flow);
    assert_non_null(f);
    return f;
}

void fixture_flow_state_at(Sim *sim, double x, double y, double out[5]) {
    int64_t cell;
    assert_ok(flow_cell_at(sim->flow, "fixture", x, y, &cell));
    flow_cell_state(sim->flow, cell, out);
}

double fixture_coupling_summary(Sim *sim, const char *name) {
    static Report r; /* large for the stack of a test; tests are single-threaded */
    report_clear(&r);
    assert_non_null(sim->coupling);
    assert_ok(coupling_summary(sim->coupling, sim->solid, sim->flow, &r));
    const ReportItem *it = report_find(&r, name);
    if (!it) fail_msg("the coupling reports no '%s'", name);
    return it->kind == REPORT_INT ? (double)it->count : it->real;
}

double fixture_flow_history(const Sim *sim, const char *name) {
    static Report row; /* large for the stack of a test; tests are single-threaded */
    report_clear(&row);
    flow_history(sim->flow, &row);
    const ReportItem *it = report_find(&row, name);
    if (!it) fail_msg("the flow has no history column '%s'", name);
    return it->real;
}

double fixture_coarse_cylinder_drag(const char *const *sets, int count, const char *label) {
    enum { BASE = 6, MAX_SETS = 16 };
    const char *all[BASE + MAX_SETS] = {
        "flow.spacing=0.2", "flow.walls=antisymmetric",   "flow.divergence_term=updated",
        "time.end=4.0",     "flow.steady_tolerance=1e-4", "output.average_from=0",
    };
    assert_true(count <= MAX_SETS);
    for (int i = 0; i < count; i++) all[BASE + i] = sets[i];
    Sim sim;
    fixture_sim("cylinder_confined_re10.yaml", all, BASE + count, &sim);
    SimRunOptions opt = {NULL, false, NULL};
    assert_ok(sim_run(&sim, &opt));
    assert_true(flow_finished(sim.flow)); /* steady before time.end */
    const double drag = fixture_flow_history(&sim, "drag_n");
    printf("%s: steady after %lld steps, drag %.6f N/m (pressure %.6f, viscous %.6f)\n", label,
           (long long)sim.step, drag, fixture_flow_history(&sim, "drag_pressure_n"),
           fixture_flow_history(&sim, "drag_viscous_n"));
    sim_destroy(&sim);
    return drag;
}
