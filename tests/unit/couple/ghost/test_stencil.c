/* couple/ghost/ibm stencils: the bilinear weights of Eqs. 34-38 in every case,
 * the ghost values of Eq. 39 on a tilted wall (exact for linear fields), and
 * the degenerate cases: a wall through cell centres (d = 0), a plate thinner
 * than a cell, an airfoil's trailing edge, a concave corner, a singular
 * system. */
#include "test_support.h"

#include "core/status.h"
#include "couple/ghost/ibm.h"
#include "couple/ghost/ibm_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ---------------------------------------------------------------- kernel */

static double lcg(unsigned *s) {
    *s = *s * 1664525u + 1013904223u;
    return (*s >> 8) / 16777216.0;
}

/* phi = a + b xi + c eta + d xi eta on the scaled square; its normal
 * derivative in physical units for spacings hx, hy. */
typedef struct {
    double a, b, c, d;
} Bilinear;
static double bl(const Bilinear *f, double x, double y) {
    return f->a + f->b * x + f->c * y + f->d * x * y;
}
static double bl_dn(const Bilinear *f, double x, double y, double nx, double ny, double hx,
                    double hy) {
    return nx * (f->b + f->d * y) / hx + ny * (f->c + f->d * x) / hy;
}

static void test_weights_all_cases(void **state) {
    (void)state;
    static const double XI[4] = {0, 1, 0, 1}, ETA[4] = {0, 0, 1, 1};
    unsigned seed = 12345;
    int count[3] = {0, 0, 0};
    for (int trial = 0; trial < 3000; trial++) {
        const int nrep = trial % 3; /* the paper's cases 1, 2, 3 */
        const double hx = 0.5 + lcg(&seed), hy = 0.5 + lcg(&seed);
        int fluid[4] = {1, 1, 1, 1};
        double bx[4] = {0}, by[4] = {0}, nx[4] = {0}, ny[4] = {0};
        /* replaced nodes: node 0, or nodes 0 and 1 (a wall below) or 0 and 2 */
        const int second = lcg(&seed) < 0.5 ? 1 : 2;
        for (int r = 0; r < nrep; r++) {
            const int m = r == 0 ? 0 : second;
            fluid[m] = 0;
            /* a wall point between the node and the box centre, normal away from the node */
            const double f = 0.2 + 0.5 * lcg(&seed);
            bx[m] = XI[m] + f * (0.5 - XI[m]) + 0.1 * (lcg(&seed) - 0.5);
            by[m] = ETA[m] + f * (0.5 - ETA[m]) + 0.1 * (lcg(&seed) - 0.5);
            const double ax = (bx[m] - XI[m]) * hx, ay = (by[m] - ETA[m]) * hy;
            nx[m] = ax / hypot(ax, ay);
            ny[m] = ay / hypot(ax, ay);
        }
        const double px = 0.35 + 0.6 * lcg(&seed), py = 0.35 + 0.6 * lcg(&seed);
        double wd[4], wn[4];
        assert_int_equal(ibm_bilinear_weights(px, py, hx, hy, fluid, bx, by, nx, ny, wd, wn), 0);
        count[nrep]++;
        const Bilinear f = {lcg(&seed) - 0.5, lcg(&seed) - 0.5, lcg(&seed) - 0.5, lcg(&seed) - 0.5};
        double sd = 0.0, sn = 0.0;
        for (int m = 0; m < 4; m++) {
            /* Dirichlet: the wall value at a replaced node's wall point */
            sd += wd[m] * (fluid[m] ? bl(&f, XI[m], ETA[m]) : bl(&f, bx[m], by[m]));
            /* Neumann: the row's datum is h dphi/dn (the row is scaled by h = min(hx, hy)) */
            sn += wn[m] * (fluid[m] ? bl(&f, XI[m], ETA[m])
                                    : fmin(hx, hy) * bl_dn(&f, bx[m], by[m], nx[m], ny[m], hx, hy));
        }
        assert_close(sd, bl(&f, px, py), 1e-12);
        assert_close(sn, bl(&f, px, py), 1e-10);
    }
    /* case 1 is plain bilinear interpolation */
    int fl[4] = {1, 1, 1, 1};
    double z[4] = {0}, wd[4], wn[4];
    assert_int_equal(ibm_bilinear_weights(0.25, 0.75, 1, 2, fl, z, z, z, z, wd, wn), 0);
    assert_close(wd[0], 0.75 * 0.25, 1e-15);
    assert_close(wd[1], 0.25 * 0.25, 1e-15);
    assert_close(wd[2], 0.75 * 0.75, 1e-15);
    assert_close(wd[3], 0.25 * 0.75, 1e-15);
    for (int m = 0; m < 4; m++) assert_close(wn[m], wd[m], 1e-15);
    assert_true(count[0] > 0 && count[1] > 0 && count[2] > 0);
}

static void test_weights_singular(void **state) {
    (void)state;
    /* two replaced nodes sharing one wall point (a convex corner): equal rows */
    int fluid[4] = {0, 0, 1, 1};
    double bx[4] = {0.5, 0.5, 0, 0}, by[4] = {0.3, 0.3, 0, 0};
    double nx[4] = {0, 0, 0, 0}, ny[4] = {1, 1, 0, 0}, wd[4], wn[4];
    assert_int_equal(ibm_bilinear_weights(0.5, 0.7, 1, 1, fluid, bx, by, nx, ny, wd, wn), -1);
    /* Neumann rows with parallel normals at the same height and x: singular too */
    double bx2[4] = {0.5, 0.5, 0, 0};
    double by2[4] = {0.3, 0.6, 0, 0};
    assert_int_equal(ibm_bilinear_weights(0.5, 0.7, 1, 1, fluid, bx2, by2, nx, ny, wd, wn), -1);
}

/* ------------------------------------------------------- through the Ibm */

static GksSolver *uniform_solver(int n) {
    GksConfig c;
    gks_config_default(&c);
    c.gas_constant = 1.0;
    gks_config_uniform_grid(&c, 0.0, 1.0, n, 0.0, 1.0, n);
    GksSolver *s = NULL;
    assert_ok(gks_solver_create(&s, &c));
    return s;
}

/* A half-plane wall through (x0, y0) with unit tangent (tx, ty) (body on the
 * right of the tangent), as a big counter-clockwise quadrilateral. */
static void half_plane(double x0, double y0, double tx, double ty, int per_side, IbmPolyline *p,
                       double *buf) {
    const double L = 10.0, nx = ty, ny = -tx; /* outward normal: left of the tangent */
    /* counter-clockwise: the wall A -> B along t, then into the body (-n) */
    const double cx[4] = {x0 - L * tx, x0 + L * tx, x0 + L * tx - 2 * L * nx,
                          x0 - L * tx - 2 * L * nx};
    const double cy[4] = {y0 - L * ty, y0 + L * ty, y0 + L * ty - 2 * L * ny,
                          y0 - L * ty - 2 * L * ny};
    int k = 0;
    for (int a = 0; a < 4; a++) {
        const int b = (a + 1) % 4;
        const int parts = a == 0 ? per_side : 1; /* only the wall edge is refined */
        for (int q = 0; q < parts; q++, k++) {
            buf[k] = cx[a] + (cx[b] - cx[a]) * q / parts;
            buf[400 + k] = cy[a] + (cy[b] - cy[a]) * q / parts;
        }
    }
    memset(p, 0, sizeof *p);
    p->n = k;
    p->x = buf;
    p->y = buf + 400;
    p->vx = buf + 800;
    p->vy = buf + 1200;
    p->leading_edge = p->trailing_edge = -1;
}

static void set_state(GksSolver *s, int64_t k, double rho, double u, double v, double p) {
    GksFields f = gks_solver_fields(s);
    const double w[4] = {rho, rho * u, rho * v, p / 0.4 + 0.5 * rho * (u * u + v * v)};
    for (int q = 0; q < 4; q++) f.w[q][k] = w[q];
}

static void get_state(GksSolver *s, int64_t k, double *rho, double *u, double *v, double *p) {
    GksFields f = gks_solver_fields(s);
    *rho = f.w[0][k];
    *u = f.w[1][k] / *rho;
    *v = f.w[2][k] / *rho;
    *p = 0.4 * (f.w[3][k] - 0.5 * *rho * (*u * *u + *v * *v));
}

/* Linear fields about a straight wall (s: distance into the fluid, t: along
 * it): u, v, T linear in s with the wall's values at s = 0, p linear in t.
 * Eq. 39 and its extended form reproduce them exactly. */
static void run_tilted_wall(int thermal) {
    GksSolver *s = uniform_solver(48);
    const Grid *g = gks_solver_grid(s);
    const double ang = 0.37, tx = cos(ang), ty = sin(ang); /* 21 degrees */
    static double buf[1600];
    IbmPolyline p;
    half_plane(0.3, 0.4, tx, ty, 200, &p, buf);
    const double uw = 0.3, vw = -0.1, Tw = 1.2;
    for (int k = 0; k < p.n; k++) p.vx[k] = uw, p.vy[k] = vw;
    p.thermal = thermal;
    p.wall_temperature = Tw;
    Ibm *ibm = NULL;
    assert_ok(ibm_create(&ibm, g, &p, 1));
    IbmUpdateStats st;
    ibm_stats(ibm, &st);
    /* all three of the paper's cases occur along a tilted wall */
    assert_true(st.by_case[0] > 0 && st.by_case[1] > 0 && st.by_case[2] > 0);
    assert_true(st.max_weight_sum < 4.0);
    const double nx = ty, ny = -tx;
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) {
            const double x = g->ax[0].center[i], y = g->ax[1].center[j];
            const double sd = (x - 0.3) * nx + (y - 0.4) * ny, td = (x - 0.3) * tx + (y - 0.4) * ty;
            const double T = thermal == IBM_WALL_ISOTHERMAL ? Tw + 0.5 * sd : 1.0 + 0.2 * td;
            const double pr = 1.0 + 0.3 * td;
            set_state(s, grid_index(g, i, j), pr / T, uw + 0.7 * sd, vw - 0.4 * sd, pr);
        }
    assert_ok(ibm_attach(ibm, s));
    int checked = 0, skipped = 0;
    for (int e = 0; e < ibm_ghost_count(ibm); e++) {
        IbmGhostInfo gi;
        ibm_ghost_info(ibm, e, &gi);
        /* stencils near the box faces read its ghost layer (extrapolated, not linear) */
        if (gi.i < 3 || gi.j < 3 || gi.i >= g->nx - 3 || gi.j >= g->ny - 3) {
            skipped++;
            continue;
        }
        assert_int_not_equal(gi.level, IBM_LEVEL_NEAREST);
        const double x = g->ax[0].center[gi.i], y = g->ax[1].center[gi.j];
        const double sd = (x - 0.3) * nx + (y - 0.4) * ny, td = (x - 0.3) * tx + (y - 0.4) * ty;
        assert_close(gi.dist, -sd, 1e-12);
        assert_close(gi.normal[0], nx, 1e-12);
        assert_close(gi.normal[1], ny, 1e-12);
        double rho, u, v, pr;
        get_state(s, gi.cell, &rho, &u, &v, &pr);
        const double T = thermal == IBM_WALL_ISOTHERMAL ? Tw + 0.5 * sd : 1.0 + 0.2 * td;
        assert_close(u, uw + 0.7 * sd, 1e-12);
        assert_close(v, vw - 0.4 * sd, 1e-12);
        assert_close(pr, 1.0 + 0.3 * td, 1e-12);
        assert_close(pr / rho, T, 1e-12);
        checked++;
    }
    assert_int_equal(checked + skipped, ibm_ghost_count(ibm));
    assert_true(checked > 3 * skipped);
    ibm_destroy(&ibm);
    gks_solver_destroy(&s);
}

static void test_tilted_wall_adiabatic(void **state) {
    (void)state;
    run_tilted_wall(IBM_WALL_ADIABATIC);
}

static void test_tilted_wall_isothermal(void **state) {
    (void)state;
    run_tilted_wall(IBM_WALL_ISOTHERMAL);
}

/* A uniform state moving with the wall is a solution: every ghost, at every
 * level, must reproduce it (weights sum to one). */
static void check_uniform(Ibm *ibm, GksSolver *s, double uw, double vw) {
    const Grid *g = gks_solver_grid(s);
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) set_state(s, grid_index(g, i, j), 1.3, uw, vw, 0.9);
    assert_ok(ibm_attach(ibm, s));
    for (int e = 0; e < ibm_ghost_count(ibm); e++) {
        IbmGhostInfo gi;
        ibm_ghost_info(ibm, e, &gi);
        double rho, u, v, p;
        get_state(s, gi.cell, &rho, &u, &v, &p);
        assert_close(rho, 1.3, 1e-13);
        assert_close(u, uw, 1e-13);
        assert_close(v, vw, 1e-13);
        assert_close(p, 0.9, 1e-13);
        double sd = 0.0;
        for (int m = 0; m < 4; m++) sd += fabs(gi.wd[m]);
        assert_true(sd < 8.0 + 1e-12);
    }
}

/* Segment p-q crosses the walls (brute force, independent of couple/ghost/geometry.c). */
static int crosses(const IbmPolyline *b, double px, double py, double qx, double qy) {
    for (int k = 0; k < b->n; k++) {
        const int e = (k + 1) % b->n;
        const double ax = b->x[k], ay = b->y[k], bx = b->x[e], by = b->y[e];
        const double d1 = (bx - ax) * (py - ay) - (px - ax) * (by - ay);
        const double d2 = (bx - ax) * (qy - ay) - (qx - ax) * (by - ay);
        const double d3 = (qx - px) * (ay - py) - (ax - px) * (qy - py);
        const double d4 = (qx - px) * (by - py) - (bx - px) * (qy - py);
        if (d1 * d2 <= 0 && d3 * d4 <= 0) return 1;
    }
    return 0;
}

/* No fluid node of any stencil sits across a wall from its point. */
static void check_sight(const Ibm *ibm, const Grid *g, const IbmPolyline *b) {
    for (int e = 0; e < ibm_ghost_count(ibm); e++) {
        IbmGhostInfo gi;
        ibm_ghost_info(ibm, e, &gi);
        for (int m = 0; m < 4; m++) {
            if (gi.node[m] < 0) continue;
            const int j = (int)(gi.node[m] / g->stride) - GRID_NG,
                      i = (int)(gi.node[m] % g->stride) - GRID_NG;
            if (gi.level == IBM_LEVEL_NEAREST) continue; /* seen from the wall point */
            assert_false(
                crosses(b, gi.point[0], gi.point[1], g->ax[0].center[i], g->ax[1].center[j]));
        }
    }
}

static void test_wall_through_centres(void **state) {
    (void)state;
    GksSolver *s = uniform_solver(32);
    const Grid *g = gks_solver_grid(s);
    /* a rectangle whose bottom edge runs through a row of cell centres */
    const double yc = g->ax[1].center[20];
    IbmBodyConfig bc = {
        .kind = IBM_BODY_RECTANGLE, .min = {0.3, yc}, .max = {0.7, 0.9}, .markers_per_side = 40};
    IbmPolyline p;
    assert_ok(ibm_body_markers(&bc, &p));
    for (int k = 0; k < p.n; k++) p.vx[k] = 0.25;
    Ibm *ibm = NULL;
    assert_ok(ibm_create(&ibm, g, &p, 1));
    /* the centres on the wall are inside: tags are closed sets */
    int on_wall = 0;
    for (int i = 0; i < g->nx; i++) {
        const double x = g->ax[0].center[i];
        if (x < 0.3 || x > 0.7) continue;
        const int e = ibm_find_ghost(ibm, i, 20);
        assert_true(e >= 0);
        IbmGhostInfo gi;
        ibm_ghost_info(ibm, e, &gi);
        assert_true(gi.dist == 0.0);
        assert_int_equal(gi.level, IBM_LEVEL_EXTENDED);
        assert_true(gi.ratio == 0.0); /* phi_GC = phi_BI */
        on_wall++;
    }
    assert_true(on_wall > 5);
    check_uniform(ibm, s, 0.25, 0.0);
    /* with d = 0 the ghost carries the wall velocity whatever the flow */
    const Grid *gg = g;
    for (int j = 0; j < gg->ny; j++)
        for (int i = 0; i < gg->nx; i++) set_state(s, grid_index(gg, i, j), 1.0, 0.9, 0.3, 1.0);
    ibm_fill_ghosts(ibm, s);
    for (int i = 0; i < g->nx; i++) {
        const int e = ibm_find_ghost(ibm, i, 20);
        if (e < 0) continue;
        double rho, u, v, pr;
        get_state(s, grid_index(g, i, 20), &rho, &u, &v, &pr);
        if (g->ax[0].center[i] > 0.35 && g->ax[0].center[i] < 0.65) {
            assert_close(u, 0.25, 1e-14);
            assert_close(v, 0.0, 1e-14);
        }
    }
    ibm_destroy(&ibm);
    ibm_polyline_free(&p);
    gks_solver_destroy(&s);
}

static void test_thin_plate(void **state) {
    (void)state;
    GksSolver *s = uniform_solver(40);
    const Grid *g = gks_solver_grid(s);
    /* 0.3 cells thick, slightly tilted: ghosts with three or four non-fluid
     * nodes, fluid cells on the far side of the plate */
    double v[8] = {0.2, 0.5, 0.8, 0.52, 0.8, 0.5275, 0.2, 0.5075};
    IbmBodyConfig bc = {
        .kind = IBM_BODY_POLYGON, .vertex_count = 4, .vertices = v, .max_spacing = 0.005};
    IbmPolyline p;
    assert_ok(ibm_body_markers(&bc, &p));
    Ibm *ibm = NULL;
    assert_ok(ibm_create(&ibm, g, &p, 1));
    IbmUpdateStats st;
    ibm_stats(ibm, &st);
    assert_true(st.ghosts > 0);
    /* ghosts that serve fluid cells on both sides of the plate */
    int both = 0;
    const uint8_t *kind = ibm_kinds(ibm);
    for (int e = 0; e < ibm_ghost_count(ibm); e++) {
        IbmGhostInfo gi;
        ibm_ghost_info(ibm, e, &gi);
        both += kind[grid_index(g, gi.i, gi.j + 1)] == FLOW_CELL_FLUID &&
                kind[grid_index(g, gi.i, gi.j - 1)] == FLOW_CELL_FLUID;
    }
    assert_true(both >= 5); /* the plate holds centres over 0.35 < x < 0.575: 9 cells */
    check_sight(ibm, g, &p);
    check_uniform(ibm, s, 0.0, 0.0);
    ibm_destroy(&ibm);
    ibm_polyline_free(&p);
    gks_solver_destroy(&s);
}

static void test_trailing_edge(void **state) {
    (void)state;
    GksSolver *s = uniform_solver(64);
    const Grid *g = gks_solver_grid(s);
    IbmBodyConfig bc = {.kind = IBM_BODY_NACA,
                        .digits = "0012",
                        .chord = 0.6,
                        .leading_edge = {0.2, 0.5},
                        .angle_deg = 4.0,
                        .markers = 400};
    IbmPolyline p;
    assert_ok(ibm_body_markers(&bc, &p));
    Ibm *ibm = NULL;
    assert_ok(ibm_create(&ibm, g, &p, 1));
    check_sight(ibm, g, &p);
    check_uniform(ibm, s, 0.0, 0.0);
    /* ghosts near the trailing edge exist and are served */
    int near_te = 0;
    for (int e = 0; e < ibm_ghost_count(ibm); e++) {
        IbmGhostInfo gi;
        ibm_ghost_info(ibm, e, &gi);
        if (hypot(gi.bi[0] - p.x[0], gi.bi[1] - p.y[0]) < 2.0 / 64) near_te++;
    }
    assert_true(near_te > 0);
    ibm_destroy(&ibm);
    ibm_polyline_free(&p);
    gks_solver_destroy(&s);
}

static void test_concave_corner(void **state) {
    (void)state;
    GksSolver *s = uniform_solver(40);
    const Grid *g = gks_solver_grid(s);
    /* an L-shaped body whose reflex corner (0.495, 0.495) is 0.3 cells from the
     * centre (0.4875, 0.4875): that ghost's image point has three non-fluid
     * nodes (itself and its two neighbours in the arms) */
    double v[12] = {0.2, 0.2, 0.8, 0.2, 0.8, 0.495, 0.495, 0.495, 0.495, 0.8, 0.2, 0.8};
    IbmBodyConfig bc = {
        .kind = IBM_BODY_POLYGON, .vertex_count = 6, .vertices = v, .max_spacing = 0.01};
    IbmPolyline p;
    assert_ok(ibm_body_markers(&bc, &p));
    Ibm *ibm = NULL;
    assert_ok(ibm_create(&ibm, g, &p, 1));
    check_sight(ibm, g, &p);
    check_uniform(ibm, s, 0.0, 0.0);
    const int e = ibm_find_ghost(ibm, 19, 19);
    assert_true(e >= 0);
    IbmGhostInfo gi;
    ibm_ghost_info(ibm, e, &gi);
    assert_true(gi.bi[0] == 0.495 && gi.bi[1] == 0.495); /* the corner marker */
    assert_int_equal(gi.level, IBM_LEVEL_EXTENDED);
    assert_true(gi.ratio > 0.0 && gi.ratio < 1.0);
    IbmUpdateStats st;
    ibm_stats(ibm, &st);
    assert_true(st.by_case[1] > 0 && st.by_case[2] > 0);
    ibm_destroy(&ibm);
    ibm_polyline_free(&p);
    gks_solver_destroy(&s);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_weights_all_cases),     cmocka_unit_test(test_weights_singular),
        cmocka_unit_test(test_tilted_wall_adiabatic), cmocka_unit_test(test_tilted_wall_isothermal),
        cmocka_unit_test(test_wall_through_centres),  cmocka_unit_test(test_thin_plate),
        cmocka_unit_test(test_trailing_edge),         cmocka_unit_test(test_concave_corner),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
