/* sim/probes: the branch angle measured on synthetic damage fields: a
 * straight crack that splits into two straight branches at known angles. */
#include "pd_fixtures.h"
#include "test_support.h"

#include "core/mem.h"
#include "sim/probes.h"
#include "solid/bond/model.h"

#include <math.h>

/* Damage 0.5 within one spacing of the crack: the stem along +x from x = 5 mm
 * to the branch point (30 mm, 20 mm), then two branches at +up and -down
 * degrees; 0 elsewhere. */
static void y_shaped(const BondBody *b, double up, double down, double *damage) {
    const double bx = 0.030, by = 0.020, dx = b->spacing;
    for (int64_t i = 0; i < b->n; i++) {
        double x = b->x[0][i], y = b->x[1][i], d = (double)INFINITY;
        if (x >= 0.005 && x <= bx) d = fabs(y - by);
        for (int k = 0; k < 2; k++) {
            double a = (k ? -down : up) * M_PI / 180.0, ux = cos(a), uy = sin(a);
            double s = (x - bx) * ux + (y - by) * uy;
            if (s >= 0) d = fmin(d, fabs(-(x - bx) * uy + (y - by) * ux));
        }
        damage[i] = d <= dx ? 0.5 : 0.0;
    }
}

static void check(double up, double down) {
    PdConfig cfg = fixture_block(2, 160, 80, 0, 5e-4); /* 80 mm x 40 mm */
    BondBody b;
    assert_ok(bond_body_create(&b, &cfg));
    PdPoints pts;
    bond_solid_points_of(&b, &pts);
    double *damage;
    assert_ok(nspd_alloc(&damage, (size_t)b.n, sizeof(double)));
    y_shaped(&b, up, down, damage);
    ProbeConfig c = {.kind = PROBE_BRANCHES,
                     .at = {0.010, 0.020, 0},
                     .direction = {1, 0, 0},
                     .damage_threshold = 0.35};
    BranchResult r;
    assert_ok(probe_branches(&c, &pts, damage, &r));
    print_message("branches +%.0f / -%.0f deg: measured %.1f (%.1f, %.1f) at (%.1f, %.1f) mm\n", up,
                  down, r.angle_deg, r.upper_deg, r.lower_deg, 1e3 * r.point[0], 1e3 * r.point[1]);
    assert_true(r.branched);
    /* the lattice turns each branch into a staircase of spacing 0.5 mm over
     * 20-40 mm: the fitted angles are within a degree (measured within 0.6) */
    assert_close(r.upper_deg, up, 1.0);
    assert_close(r.lower_deg, -down, 1.0);
    assert_close(r.point[0], 0.030, 2e-3);
    assert_close(r.point[1], 0.020, 1e-3);
    nspd_free(&damage);
    bond_body_destroy(&b);
}

static void test_symmetric_and_skewed_branches(void **state) {
    (void)state;
    check(65, 65); /* 130 deg, the paper's 30-50 MPa cylinders */
    check(35, 35); /* 70 deg, the 60 MPa one */
    check(50, 20);
}

/* A 160 x 80 block (spacing 0.5 mm) and its damage field (allocated here):
 * a straight crack, damage 0.5 within 0.5 mm of y = 20 mm. */
static double *straight_crack_block(BondBody *b) {
    PdConfig cfg = fixture_block(2, 160, 80, 0, 5e-4);
    assert_ok(bond_body_create(b, &cfg));
    double *damage;
    assert_ok(nspd_alloc(&damage, (size_t)b->n, sizeof(double)));
    for (int64_t i = 0; i < b->n; i++) damage[i] = fabs(b->x[1][i] - 0.020) <= 5e-4 ? 0.5 : 0.0;
    return damage;
}

static void test_straight_crack_does_not_branch(void **state) {
    (void)state;
    BondBody b;
    double *damage = straight_crack_block(&b);
    PdPoints pts;
    bond_solid_points_of(&b, &pts);
    ProbeConfig c = {.kind = PROBE_BRANCHES,
                     .at = {0.010, 0.020, 0},
                     .direction = {1, 0, 0},
                     .damage_threshold = 0.35};
    BranchResult r;
    assert_ok(probe_branches(&c, &pts, damage, &r));
    assert_false(r.branched);
    assert_true(isnan(r.angle_deg));
    nspd_free(&damage);
    bond_body_destroy(&b);
}

/* With `extent` set, the run reports the first measurement whose branches
 * span it, not what the damage field looks like at the end (after the
 * body has broken up and damage is everywhere). */
static void test_first_branching_is_kept(void **state) {
    (void)state;
    BondBody b;
    double *damage = straight_crack_block(&b);
    PdPoints pts;
    bond_solid_points_of(&b, &pts);
    static Report row; /* the history row the probes append to (not checked here) */
    ProbeConfig c = {.kind = PROBE_BRANCHES,
                     .at = {0.010, 0.020, 0},
                     .direction = {1, 0, 0},
                     .damage_threshold = 0.35,
                     .extent = 0.005};
    ProbeState p = {.cfg = &c, .t_first_branch = (double)NAN};
    /* t = 1: a straight crack, no branch yet */
    probes_sample(&p, 1, &pts, damage, NULL, 1.0, &row);
    report_clear(&row);
    assert_true(isnan(p.t_first_branch));
    /* t = 2: the Y of 130 degrees */
    y_shaped(&b, 65, 65, damage);
    probes_sample(&p, 1, &pts, damage, NULL, 2.0, &row);
    report_clear(&row);
    /* t = 3: damage in horizontal stripes every 2 mm (a shattered body) */
    for (int64_t i = 0; i < b.n; i++) damage[i] = fmod(b.x[1][i] + 1e-4, 0.002) < 6e-4 ? 0.5 : 0.0;
    probes_sample(&p, 1, &pts, damage, NULL, 3.0, &row);
    report_clear(&row);
    BranchResult r;
    double t;
    assert_ok(probe_branch_report(&p, &pts, damage, &r, &t));
    assert_true(t == 2.0);
    assert_close(r.angle_deg, 130.0, 2.0);
    /* branches that never span `extent` are not reported */
    c.extent = 1.0;
    ProbeState s = {.cfg = &c, .t_first_branch = (double)NAN};
    probes_sample(&s, 1, &pts, damage, NULL, 3.0, &row);
    report_clear(&row);
    assert_ok(probe_branch_report(&s, &pts, damage, &r, &t));
    assert_false(r.branched);
    assert_true(isnan(r.angle_deg) && isnan(t));
    /* without `extent`, the end state is measured */
    c.extent = 0;
    ProbeState q = {.cfg = &c, .t_first_branch = (double)NAN};
    probes_sample(&q, 1, &pts, damage, NULL, 3.0, &row);
    report_clear(&row);
    assert_ok(probe_branch_report(&q, &pts, damage, &r, &t));
    assert_true(isnan(t));
    assert_true(fabs(r.angle_deg - 130.0) > 10.0);
    nspd_free(&damage);
    bond_body_destroy(&b);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_first_branching_is_kept),
        cmocka_unit_test(test_symmetric_and_skewed_branches),
        cmocka_unit_test(test_straight_crack_does_not_branch),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
