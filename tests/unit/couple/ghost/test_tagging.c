/* couple/ghost/ibm tagging and geometry: inside/outside with points on edges and
 * vertices and rays through vertices, several bodies, nearest wall points
 * against brute force, and the ghost-layer invariants. */
#include "test_support.h"

#include "core/status.h"
#include "couple/ghost/ibm.h"
#include "couple/ghost/ibm_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const Grid *test_grid(GksSolver **s, int n, double lo, double hi) {
    GksConfig c;
    gks_config_default(&c);
    gks_config_uniform_grid(&c, lo, hi, n, lo, hi, n);
    assert_ok(gks_solver_create(s, &c));
    return gks_solver_grid(*s);
}

static IbmPolyline poly(int n, double *x, double *y) {
    IbmPolyline p;
    memset(&p, 0, sizeof p);
    p.n = n;
    p.x = x;
    p.y = y;
    p.leading_edge = p.trailing_edge = -1;
    return p;
}

static void test_inside_edges_vertices(void **state) {
    (void)state;
    GksSolver *s = NULL;
    const Grid *g = test_grid(&s, 16, -1.0, 3.0);
    /* a unit square and a diamond (edges at 45 degrees) */
    double sx[4] = {0, 1, 1, 0}, sy[4] = {0, 0, 1, 1};
    double dx[4] = {2, 2.5, 2, 1.5}, dy[4] = {0, 0.5, 1, 0.5};
    IbmPolyline b[2] = {poly(4, sx, sy), poly(4, dx, dy)};
    Ibm *ibm = NULL;
    assert_ok(ibm_create(&ibm, g, b, 2));
    /* on edges and vertices: inside (tags are closed sets) */
    const double on[][2] = {{0, 0},       {1, 1},       {0.5, 0},     {1, 0.5},    {0, 0.3},
                            {0.25, 1},    {2, 0},       {2.5, 0.5},   {2, 1},      {1.5, 0.5},
                            {2.25, 0.25}, {1.75, 0.75}, {2.25, 0.75}, {1.75, 0.25}};
    for (size_t k = 0; k < sizeof on / sizeof on[0]; k++)
        assert_int_equal(ibm_point_inside(ibm, on[k][0], on[k][1]), 1);
    /* inside and outside, including points whose horizontal ray passes
     * through a vertex (y = 0.5 through the diamond's side vertices, y = 0
     * and 1 along the square's edges) */
    const double in[][2] = {{0.5, 0.5}, {2, 0.5}, {1e-12, 1e-12}, {0.999, 0.5}, {2.0, 0.999}};
    for (size_t k = 0; k < sizeof in / sizeof in[0]; k++)
        assert_int_equal(ibm_point_inside(ibm, in[k][0], in[k][1]), 1);
    const double out[][2] = {{-0.5, 0.5},        {1.25, 0.5},        {2.75, 0.5},
                             {-0.5, 0},          {1.25, 0},          {-0.5, 1},
                             {1.25, 1},          {0.5, -1e-12},      {0.5, 1 + 1e-12},
                             {1.5 - 1e-12, 0.5}, {2.5 + 1e-12, 0.5}, {2, 1 + 1e-12}};
    for (size_t k = 0; k < sizeof out / sizeof out[0]; k++)
        assert_int_equal(ibm_point_inside(ibm, out[k][0], out[k][1]), 0);
    ibm_destroy(&ibm);
    gks_solver_destroy(&s);
}

/* Winding number by brute force (a different formulation: signed angles). */
static int brute_inside(const IbmPolyline *b, int nb, double x, double y) {
    for (int q = 0; q < nb; q++) {
        double ang = 0.0;
        for (int k = 0; k < b[q].n; k++) {
            const int e = (k + 1) % b[q].n;
            const double ax = b[q].x[k] - x, ay = b[q].y[k] - y;
            const double bx = b[q].x[e] - x, by = b[q].y[e] - y;
            ang += atan2(ax * by - ay * bx, ax * bx + ay * by);
        }
        if (fabs(ang) > M_PI) return 1;
    }
    return 0;
}

static void brute_nearest(const IbmPolyline *b, int nb, double x, double y, double *d) {
    *d = (double)INFINITY;
    for (int q = 0; q < nb; q++)
        for (int k = 0; k < b[q].n; k++) {
            const int e = (k + 1) % b[q].n;
            const double ax = b[q].x[k], ay = b[q].y[k], ex = b[q].x[e] - ax, ey = b[q].y[e] - ay;
            double t = ((x - ax) * ex + (y - ay) * ey) / (ex * ex + ey * ey);
            t = t < 0 ? 0 : t > 1 ? 1 : t;
            *d = fmin(*d, hypot(x - ax - t * ex, y - ay - t * ey));
        }
}

static void test_tags_and_nearest(void **state) {
    (void)state;
    GksSolver *s = NULL;
    const Grid *g = test_grid(&s, 96, 0.0, 1.0);
    IbmBodyConfig c1 = {
        .kind = IBM_BODY_CIRCLE, .center = {0.3, 0.35}, .radius = 0.17, .markers = 300};
    IbmBodyConfig c2 = {.kind = IBM_BODY_NACA,
                        .digits = "2412",
                        .chord = 0.5,
                        .leading_edge = {0.4, 0.7},
                        .angle_deg = 8,
                        .markers = 400};
    /* overlapping the circle: inside the union */
    IbmBodyConfig c3 = {
        .kind = IBM_BODY_RECTANGLE, .min = {0.42, 0.2}, .max = {0.8, 0.3}, .markers_per_side = 60};
    IbmPolyline b[3];
    assert_ok(ibm_body_markers(&c1, &b[0]));
    assert_ok(ibm_body_markers(&c2, &b[1]));
    assert_ok(ibm_body_markers(&c3, &b[2]));
    Ibm *ibm = NULL;
    assert_ok(ibm_create(&ibm, g, b, 3));
    const uint8_t *kind = ibm_kinds(ibm);
    int64_t fluid = 0, ghost = 0, solid = 0;
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) {
            const int64_t k = grid_index(g, i, j);
            const int in = brute_inside(b, 3, g->ax[0].center[i], g->ax[1].center[j]);
            assert_int_equal(kind[k] != FLOW_CELL_FLUID, in);
            /* ghost layers: a fluid cell never has a SOLID cell within Manhattan
             * distance 2; a ghost always has a fluid one */
            int near_fluid = 0, near_solid = 0;
            for (int bj = -2; bj <= 2; bj++)
                for (int ai = -(2 - abs(bj)); ai <= 2 - abs(bj); ai++) {
                    const int q = i + ai, p = j + bj;
                    if (q < 0 || p < 0 || q >= g->nx || p >= g->ny || (ai == 0 && bj == 0))
                        continue;
                    const uint8_t kk = kind[grid_index(g, q, p)];
                    near_fluid |= kk == FLOW_CELL_FLUID;
                    near_solid |= kk == FLOW_CELL_SOLID;
                }
            if (kind[k] == FLOW_CELL_FLUID) assert_false(near_solid), fluid++;
            if (kind[k] == FLOW_CELL_GHOST) assert_true(near_fluid), ghost++;
            if (kind[k] == FLOW_CELL_SOLID) assert_false(near_fluid), solid++;
        }
    assert_true(ghost > 0 && solid > 0 && fluid > 0);
    IbmUpdateStats st;
    ibm_stats(ibm, &st);
    assert_int_equal(st.ghosts, (int)ghost);
    assert_int_equal(st.solid_cells, solid);
    /* nearest wall points against brute force, at random points */
    unsigned seed = 7;
    for (int q = 0; q < 2000; q++) {
        seed = seed * 1664525u + 1013904223u;
        const double x = (seed >> 8) / 16777216.0 * 1.4 - 0.2;
        seed = seed * 1664525u + 1013904223u;
        const double y = (seed >> 8) / 16777216.0 * 1.4 - 0.2;
        double ref;
        const IbmWallPoint w = ibm_nearest(ibm, x, y);
        brute_nearest(b, 3, x, y, &ref);
        assert_close(w.d, ref, 1e-14);
        assert_close(hypot(x - w.bx, y - w.by), w.d, 1e-14);
    }
    ibm_destroy(&ibm);
    for (int q = 0; q < 3; q++) ibm_polyline_free(&b[q]);
    gks_solver_destroy(&s);
}

static void test_refused(void **state) {
    (void)state;
    GksSolver *s = NULL;
    const Grid *g = test_grid(&s, 8, 0.0, 1.0);
    double x[3] = {0.2, 0.2, 0.6}, y[3] = {0.2, 0.6, 0.2}; /* clockwise */
    IbmPolyline p = poly(3, x, y);
    Ibm *ibm = NULL;
    assert_int_equal(ibm_create(&ibm, g, &p, 1), NSPD_ERR_INPUT);
    assert_null(ibm);
    assert_int_equal(ibm_create(&ibm, g, &p, 0), NSPD_ERR_INPUT);
    gks_solver_destroy(&s);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_inside_edges_vertices),
        cmocka_unit_test(test_tags_and_nearest),
        cmocka_unit_test(test_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
