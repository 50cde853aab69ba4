/* Ghost-layer filling of the box boundary conditions. */
#include "test_support.h"

#include "core/status.h"
#include "flow/gks/bc.h"
#include "flow/gks/flux.h"

#include <math.h>
#include <stdlib.h>

typedef struct {
    Grid g;
    double *w[4];
    GksParams gas;
} Box;

static void box_make(Box *b, bool periodic_x) {
    assert_ok(grid_create_uniform(&b->g, 0.0, 1.0, 6, 0.0, 1.0, 5, periodic_x, false));
    for (int v = 0; v < 4; v++) b->w[v] = calloc((size_t)b->g.size, sizeof(double));
    gks_params_default(&b->gas, 1.4, 1.0);
    for (int j = 0; j < b->g.ny; j++)
        for (int i = 0; i < b->g.nx; i++) {
            const FlowPrim q = {1.0 + 0.1 * i, 0.3 + 0.05 * j, -0.2 + 0.01 * i, 1.0 + 0.02 * j};
            double c[4];
            flow_prim_to_cons(&q, 1.4, c);
            for (int v = 0; v < 4; v++) b->w[v][grid_index(&b->g, i, j)] = c[v];
        }
}

static void box_free(Box *b) {
    for (int v = 0; v < 4; v++) free(b->w[v]);
    grid_destroy(&b->g);
}

static FlowPrim at(const Box *b, int i, int j) {
    const int64_t k = grid_index(&b->g, i, j);
    const double c[4] = {b->w[0][k], b->w[1][k], b->w[2][k], b->w[3][k]};
    FlowPrim q;
    flow_cons_to_prim(c, 1.4, &q);
    return q;
}

static void set_all(FlowFaceBc bc[4], const FlowBc *x, const FlowBc *y) {
    for (int f = 0; f < 4; f++) {
        bc[f].count = 1;
        bc[f].seg[0] = f < 2 ? *x : *y;
    }
}

static void test_walls_and_periodic(void **state) {
    (void)state;
    Box b;
    box_make(&b, true);
    FlowFaceBc bc[4];
    const FlowBc per = {.kind = BC_PERIODIC};
    const FlowBc wall = {
        .kind = BC_NOSLIP_ISOTHERMAL, .wall_temperature = 1.5, .wall_velocity = 0.7};
    set_all(bc, &per, &wall);
    bc[FLOW_FACE_YHI].seg[0] = (FlowBc){.kind = BC_SLIP_WALL};
    assert_ok(bc_validate(&b.g, bc));
    bc_fill(&b.g, bc, &b.gas, b.w, NULL);
    for (int j = 0; j < b.g.ny; j++) {
        const FlowPrim g = at(&b, -1, j), s = at(&b, b.g.nx - 1, j);
        assert_close(g.rho, s.rho, 1e-15);
        const FlowPrim g2 = at(&b, b.g.nx + 1, j), s2 = at(&b, 1, j);
        assert_close(g2.u, s2.u, 1e-15);
    }
    for (int i = 0; i < b.g.nx; i++) {
        /* isothermal moving wall at y = 0: mean of ghost and image is the wall value */
        for (int k = 0; k < 2; k++) {
            const FlowPrim g = at(&b, i, -1 - k), m = at(&b, i, k);
            assert_close(0.5 * (g.u + m.u), 0.7, 1e-14);
            assert_close(0.5 * (g.v + m.v), 0.0, 1e-14);
            assert_close(0.5 * (g.p / g.rho + m.p / m.rho), 1.5, 1e-14);
            assert_close(g.p, m.p, 1e-14);
        }
        /* slip wall at the top: u_n flips, the rest mirrors */
        const FlowPrim g = at(&b, i, b.g.ny), m = at(&b, i, b.g.ny - 1);
        assert_close(g.v, -m.v, 1e-15);
        assert_close(g.u, m.u, 1e-15);
        assert_close(g.rho, m.rho, 1e-15);
    }
    box_free(&b);
}

static void test_characteristic_conditions(void **state) {
    (void)state;
    Box b;
    box_make(&b, false);
    FlowFaceBc bc[4];
    const FlowPrim inf = {1.0, 0.3, -0.2, 1.0};
    const FlowBc far = {.kind = BC_SUBSONIC_INFLOW, .state = inf};
    const FlowBc out = {.kind = BC_SUBSONIC_OUTFLOW, .pressure = 0.9};
    set_all(bc, &far, &far);
    bc[FLOW_FACE_XHI].seg[0] = out;
    assert_ok(bc_validate(&b.g, bc));
    /* interior = free stream: the far field must return the free stream */
    for (int j = 0; j < b.g.ny; j++)
        for (int i = 0; i < b.g.nx; i++) {
            double c[4];
            flow_prim_to_cons(&inf, 1.4, c);
            for (int v = 0; v < 4; v++) b.w[v][grid_index(&b.g, i, j)] = c[v];
        }
    bc_fill(&b.g, bc, &b.gas, b.w, NULL);
    const FlowPrim g = at(&b, -1, 2);
    assert_close(g.rho, inf.rho, 1e-14);
    assert_close(g.u, inf.u, 1e-14);
    assert_close(g.v, inf.v, 1e-14);
    assert_close(g.p, inf.p, 1e-14);
    /* back pressure: imposed, with the interior entropy */
    const FlowPrim o = at(&b, b.g.nx, 2);
    assert_close(o.p, 0.9, 1e-14);
    assert_close(o.p / pow(o.rho, 1.4), inf.p / pow(inf.rho, 1.4), 1e-13);
    /* a periodic face needs its partner and a periodic axis */
    bc[FLOW_FACE_XLO].seg[0] = (FlowBc){.kind = BC_PERIODIC};
    assert_int_equal(bc_validate(&b.g, bc), NSPD_ERR_INPUT);
    box_free(&b);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_walls_and_periodic),
        cmocka_unit_test(test_characteristic_conditions),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
