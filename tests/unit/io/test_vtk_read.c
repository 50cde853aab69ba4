/* Starting a flow from a stored field: io/vtk_read.c reads back what
 * io/vtk.c writes, and flow/gks/field_sample.c interpolates it.
 *  - round trip: every value and face coordinate comes back bit for bit;
 *  - bad files (missing, empty, truncated, foreign) fail with NSPD_ERR_IO /
 *    NSPD_ERR_INPUT and a message naming the file;
 *  - pieces: the grid written by several processes (a .pvtr naming one
 *    .vtr a block, io/vtk.h) reads back as the whole one, bit for bit; a
 *    cell held twice, a cell held by none, a missing piece and pieces that
 *    disagree on a face are refused;
 *  - point sets: a .vtu and the .pvtu of its pieces read back as the
 *    points written, in piece order, bit for bit;
 *  - sampling: exact at the stored centres, exact for a field linear in x
 *    and y between them on a stretched grid (bilinear interpolation), the
 *    nearest centre outside them, and cells inside a body left out. */
#include "test_support.h"

#include "core/status.h"
#include "flow/gks/field_sample.h"
#include "io/vtk.h"
#include "io/vtk_read.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

enum { NX = 7, NY = 5 };

/* A stretched grid: faces x_i = i + 0.1 i^2, y_j = 2 j + 0.05 j^2. */
static void faces(double *xf, double *yf) {
    for (int i = 0; i <= NX; i++) xf[i] = i + 0.1 * i * i;
    for (int j = 0; j <= NY; j++) yf[j] = 2.0 * j + 0.05 * j * j;
}

static double linear(double x, double y, double a) {
    return a + 0.25 * x - 0.125 * y;
}

/* Writes a field linear in x and y at the cell centres; cell (1, 1) is a
 * body cell (kind 1) holding nonsense that sampling must not see. With
 * points, a node density of -7 and a node velocity too (point data, as the
 * IGA flow writes), which the reader must skip. */
static void write_field_with(const char *path, bool points) {
    double xf[NX + 1], yf[NY + 1], zf[2] = {0.0, 0.0};
    faces(xf, yf);
    static double rho[NX * NY], u[NX * NY], v[NX * NY], p[NX * NY], kind[NX * NY];
    for (int j = 0; j < NY; j++)
        for (int i = 0; i < NX; i++) {
            const int k = j * NX + i;
            const double x = 0.5 * (xf[i] + xf[i + 1]), y = 0.5 * (yf[j] + yf[j + 1]);
            rho[k] = linear(x, y, 3.0);
            u[k] = linear(x, y, -1.0);
            v[k] = linear(x, y, 0.5);
            p[k] = linear(x, y, 5.0);
            kind[k] = 0.0;
        }
    kind[1 * NX + 1] = 1.0;
    rho[1 * NX + 1] = 1e6;
    VtkField fields[] = {
        {"density", 1, {rho, NULL, NULL}},
        {"velocity", 3, {u, v, NULL}},
        {"pressure", 1, {p, NULL, NULL}},
        {"cell_kind", 1, {kind, NULL, NULL}},
    };
    static double node_rho[(NX + 1) * (NY + 1)], node_u[(NX + 1) * (NY + 1)];
    for (int k = 0; k < (NX + 1) * (NY + 1); k++) node_rho[k] = -7.0, node_u[k] = 1e9;
    VtkField nodes[] = {{"density", 1, {node_rho, NULL, NULL}},
                        {"velocity", 3, {node_u, NULL, NULL}}};
    assert_ok(vtk_write_rectilinear(path, NX, NY, 1, xf, yf, zf, fields, 4, points ? nodes : NULL,
                                    points ? 2 : 0));
}

static void write_field(const char *path) {
    write_field_with(path, false);
}

/* Reads the NX x NY grid of faces() at `path` (a .vtr or a .pvtr),
 * checking its size and every face bit for bit. */
static void read_stretched(const char *path, VtkRectilinear *g) {
    assert_ok(vtk_read_rectilinear(path, g));
    assert_int_equal(g->n[0], NX);
    assert_int_equal(g->n[1], NY);
    assert_int_equal(g->n[2], 1);
    double xf[NX + 1], yf[NY + 1];
    faces(xf, yf);
    assert_memory_equal(g->face[0], xf, sizeof xf);
    assert_memory_equal(g->face[1], yf, sizeof yf);
}

static void test_round_trip(void **state) {
    (void)state;
    char path[1200];
    snprintf(path, sizeof path, "%s/field.vtr", test_scratch_dir("vtk_read"));
    write_field(path);
    VtkRectilinear g;
    read_stretched(path, &g);
    double xf[NX + 1], yf[NY + 1];
    faces(xf, yf);
    const VtkCellArray *vel = vtk_find_cell_array(&g, "velocity", 3);
    assert_non_null(vel);
    assert_null(vtk_find_cell_array(&g, "velocity", 1));
    const double x = 0.5 * (xf[2] + xf[3]), y = 0.5 * (yf[3] + yf[4]);
    const int k = 3 * NX + 2;
    assert_true(vel->data[3 * k] == linear(x, y, -1.0)); /* bit for bit */
    assert_true(vel->data[3 * k + 1] == linear(x, y, 0.5));
    assert_true(vel->data[3 * k + 2] == 0.0);
    vtk_rectilinear_free(&g);
}

/* The same file with point data: the cells' arrays come back, the nodes'
 * are skipped. */
static void test_point_data_skipped(void **state) {
    (void)state;
    char path[1200];
    snprintf(path, sizeof path, "%s/points.vtr", test_scratch_dir("vtk_read_points"));
    write_field_with(path, true);
    VtkRectilinear g;
    assert_ok(vtk_read_rectilinear(path, &g));
    assert_int_equal(g.array_count, 4);
    double xf[NX + 1], yf[NY + 1];
    faces(xf, yf);
    const VtkCellArray *rho = vtk_find_cell_array(&g, "density", 1);
    assert_non_null(rho);
    const int k = 3 * NX + 2;
    assert_true(rho->data[k] == linear(0.5 * (xf[2] + xf[3]), 0.5 * (yf[3] + yf[4]), 3.0));
    vtk_rectilinear_free(&g);
}

static void expect_failure(const char *path, int status, const char *words) {
    VtkRectilinear g;
    assert_int_equal(vtk_read_rectilinear(path, &g), status);
    assert_non_null(strstr(nspd_error_message(), path));
    assert_non_null(strstr(nspd_error_message(), words));
    vtk_rectilinear_free(&g);
}

static void test_bad_files(void **state) {
    (void)state;
    const char *dir = test_scratch_dir("vtk_read_bad");
    char good[1200], path[1200];
    snprintf(good, sizeof good, "%s/good.vtr", dir);
    write_field(good);

    snprintf(path, sizeof path, "%s/missing.vtr", dir);
    expect_failure(path, NSPD_ERR_IO, "cannot open");

    snprintf(path, sizeof path, "%s/empty.vtr", dir);
    fclose(fopen(path, "wb"));
    expect_failure(path, NSPD_ERR_INPUT, "empty");

    snprintf(path, sizeof path, "%s/points.vtu", dir);
    const double *pos[3] = {NULL, NULL, NULL};
    assert_ok(vtk_write_points(path, 0, pos, NULL, 0));
    expect_failure(path, NSPD_ERR_INPUT, "not a VTK rectilinear grid");

    /* the good file cut short inside its data */
    FILE *in = fopen(good, "rb");
    static char buf[1 << 16];
    size_t n = fread(buf, 1, sizeof buf, in);
    fclose(in);
    snprintf(path, sizeof path, "%s/truncated.vtr", dir);
    FILE *out = fopen(path, "wb");
    fwrite(buf, 1, n - 200, out);
    fclose(out);
    expect_failure(path, NSPD_ERR_INPUT, "truncated");
}

/* The field of write_field cut into three pieces, {i0, i1, j0, j1}: two
 * blocks side by side below, one across the top; their .pvtr at `pvtr`
 * naming `sources` (NULL: the pieces' own names). */
static const int PIECES[3][4] = {{0, 3, 0, 2}, {3, NX, 0, 2}, {0, NX, 2, NY}};

static void write_pieces(const char *dir, const char *pvtr, const int (*cells)[4], int count,
                         const char *const *sources) {
    double xf[NX + 1], yf[NY + 1];
    faces(xf, yf);
    static double rho[NX * NY], vel[NX * NY];
    for (int p = 0; p < 3; p++) {
        const int *c = PIECES[p];
        int k = 0;
        for (int j = c[2]; j < c[3]; j++)
            for (int i = c[0]; i < c[1]; i++, k++) {
                rho[k] = linear(i, j, 3.0);
                vel[k] = linear(i, j, -1.0);
            }
        VtkField fields[] = {{"density", 1, {rho, NULL, NULL}}, {"velocity", 3, {NULL, vel, NULL}}};
        char path[1300];
        snprintf(path, sizeof path, "%s/piece_%d.vtr", dir, p);
        assert_ok(vtk_write_rectilinear_piece(path, c, xf + c[0], yf + c[2], fields, 2));
    }
    static const char *const own[3] = {"piece_0.vtr", "piece_1.vtr", "piece_2.vtr"};
    VtkField declared[] = {{"density", 1, {NULL}}, {"velocity", 3, {NULL}}};
    char path[1300];
    snprintf(path, sizeof path, "%s/%s", dir, pvtr);
    assert_ok(vtk_write_pvtr(path, NX, NY, count, cells, sources ? sources : own, declared, 2));
}

static void test_pieces(void **state) {
    (void)state;
    const char *dir = test_scratch_dir("vtk_read_pieces");
    write_pieces(dir, "whole.pvtr", PIECES, 3, NULL);
    char path[1300];
    snprintf(path, sizeof path, "%s/whole.pvtr", dir);
    VtkRectilinear g;
    read_stretched(path, &g);
    double xf[NX + 1], yf[NY + 1];
    faces(xf, yf);
    const VtkCellArray *rho = vtk_find_cell_array(&g, "density", 1),
                       *vel = vtk_find_cell_array(&g, "velocity", 3);
    assert_non_null(rho);
    assert_non_null(vel);
    for (int j = 0; j < NY; j++)
        for (int i = 0; i < NX; i++) {
            const int k = j * NX + i;
            assert_true(rho->data[k] == linear(i, j, 3.0));
            assert_true(vel->data[3 * k] == 0.0 && vel->data[3 * k + 1] == linear(i, j, -1.0));
        }
    vtk_rectilinear_free(&g);

    /* the first piece named twice, the second not at all */
    static const int twice[3][4] = {{0, 3, 0, 2}, {0, 3, 0, 2}, {0, NX, 2, NY}};
    static const char *const twice_src[3] = {"piece_0.vtr", "piece_0.vtr", "piece_2.vtr"};
    write_pieces(dir, "twice.pvtr", twice, 3, twice_src);
    snprintf(path, sizeof path, "%s/twice.pvtr", dir);
    expect_failure(path, NSPD_ERR_INPUT, "two pieces hold cell (0, 0, 0)");
    /* the top piece left out */
    write_pieces(dir, "gap.pvtr", PIECES, 2, NULL);
    snprintf(path, sizeof path, "%s/gap.pvtr", dir);
    expect_failure(path, NSPD_ERR_INPUT, "its 2 pieces hold 14 cells; the whole grid has 35");
    /* a piece's file missing */
    static const char *const missing[3] = {"piece_0.vtr", "nowhere.vtr", "piece_2.vtr"};
    write_pieces(dir, "missing.pvtr", PIECES, 3, missing);
    snprintf(path, sizeof path, "%s/missing.pvtr", dir);
    expect_failure(path, NSPD_ERR_IO, "nowhere.vtr");
    /* the second piece's file placed where its faces are not */
    static const int shifted[3][4] = {{0, 3, 0, 2}, {0, 4, 2, 4}, {0, NX, 2, NY}};
    write_pieces(dir, "shifted.pvtr", shifted, 3, NULL);
    snprintf(path, sizeof path, "%s/shifted.pvtr", dir);
    expect_failure(path, NSPD_ERR_INPUT, "two pieces disagree on the x face");
}

/* Five points with a scalar and a 2D vector, whole and in two pieces
 * (the first two points, the last three). */
static void test_point_sets(void **state) {
    (void)state;
    const char *dir = test_scratch_dir("vtk_read_points_sets");
    enum { N = 5 };
    double x[N], y[N], damage[N], u[N], v[N];
    for (int i = 0; i < N; i++) {
        x[i] = 0.1 * i + 1.0 / 3.0;
        y[i] = -0.7 * i;
        damage[i] = i / 7.0;
        u[i] = 1e-3 * i * i;
        v[i] = -u[i] / 3.0;
    }
    char whole[1300], pvtu[1300], path[1300];
    snprintf(whole, sizeof whole, "%s/whole.vtu", dir);
    const double *pos[3] = {x, y, NULL};
    VtkField fields[] = {{"displacement", 3, {u, v, NULL}}, {"damage", 1, {damage, NULL, NULL}}};
    assert_ok(vtk_write_points(whole, N, pos, fields, 2));
    static const int lo[3] = {0, 2, N};
    static const char *const sources[2] = {"part_0.vtu", "part_1.vtu"};
    for (int p = 0; p < 2; p++) {
        const int a = lo[p];
        const double *ppos[3] = {x + a, y + a, NULL};
        VtkField pf[] = {{"displacement", 3, {u + a, v + a, NULL}},
                         {"damage", 1, {damage + a, NULL, NULL}}};
        snprintf(path, sizeof path, "%s/%s", dir, sources[p]);
        assert_ok(vtk_write_points(path, lo[p + 1] - a, ppos, pf, 2));
    }
    snprintf(pvtu, sizeof pvtu, "%s/whole.pvtu", dir);
    assert_ok(vtk_write_pvtu(pvtu, 2, sources, fields, 2));
    for (int k = 0; k < 2; k++) {
        VtkPointSet set;
        assert_ok(vtk_read_points(k ? pvtu : whole, &set));
        assert_int_equal(set.n, N);
        assert_int_equal(set.array_count, 2);
        assert_string_equal(set.arrays[0].name, "displacement");
        assert_int_equal(set.arrays[0].components, 3);
        for (int i = 0; i < N; i++) {
            assert_true(set.points[3 * i] == x[i] && set.points[3 * i + 1] == y[i] &&
                        set.points[3 * i + 2] == 0.0);
            assert_true(set.arrays[0].data[3 * i] == u[i] && set.arrays[0].data[3 * i + 1] == v[i]);
            assert_true(set.arrays[1].data[i] == damage[i]);
        }
        vtk_point_set_free(&set);
    }
    /* a grid is not a point set, nor a point set a grid */
    snprintf(path, sizeof path, "%s/grid.vtr", dir);
    write_field(path);
    VtkPointSet set;
    assert_int_equal(vtk_read_points(path, &set), NSPD_ERR_INPUT);
    assert_non_null(strstr(nspd_error_message(), "not a VTK point set"));
    vtk_point_set_free(&set);
    expect_failure(pvtu, NSPD_ERR_INPUT, "expected a .vtr");
}

static void load(FlowFieldSource *s) {
    char path[1200];
    snprintf(path, sizeof path, "%s/field.vtr", test_scratch_dir("vtk_read_sample"));
    write_field(path);
    VtkRectilinear g;
    assert_ok(vtk_read_rectilinear(path, &g));
    assert_ok(flow_field_source_create(s, g.n[0], g.n[1], g.face[0], g.face[1]));
    const VtkCellArray *rho = vtk_find_cell_array(&g, "density", 1),
                       *vel = vtk_find_cell_array(&g, "velocity", 3),
                       *p = vtk_find_cell_array(&g, "pressure", 1),
                       *kind = vtk_find_cell_array(&g, "cell_kind", 1);
    for (int k = 0; k < NX * NY; k++) {
        s->rho[k] = rho->data[k];
        s->u[k] = vel->data[3 * k];
        s->v[k] = vel->data[3 * k + 1];
        s->p[k] = p->data[k];
        s->valid[k] = kind->data[k] != 1.0;
    }
    vtk_rectilinear_free(&g);
}

static void test_sampling(void **state) {
    (void)state;
    FlowFieldSource s;
    load(&s);
    FlowPrim q;
    /* at a stored centre: that cell's state exactly */
    flow_field_sample(&s, s.xc[4], s.yc[2], &q);
    assert_true(q.rho == s.rho[2 * NX + 4] && q.p == s.p[2 * NX + 4]);
    /* between centres away from the body cell: the linear field, to
     * round-off (bilinear interpolation is exact for it) */
    double worst = 0.0;
    for (int a = 0; a < 40; a++) {
        const double x = s.xc[2] + (s.xc[NX - 1] - s.xc[2]) * a / 39.0;
        const double y = s.yc[2] + (s.yc[NY - 1] - s.yc[2]) * ((a * 7) % 40) / 39.0;
        flow_field_sample(&s, x, y, &q);
        worst = fmax(worst, fabs(q.rho - linear(x, y, 3.0)));
        worst = fmax(worst, fabs(q.u - linear(x, y, -1.0)));
        worst = fmax(worst, fabs(q.v - linear(x, y, 0.5)));
        worst = fmax(worst, fabs(q.p - linear(x, y, 5.0)));
    }
    assert_true(worst < 1e-13);
    /* beyond the last centre: the nearest centre's value */
    flow_field_sample(&s, 1e3, -1e3, &q);
    assert_true(q.u == s.u[NX - 1]);
    /* next to the body cell (1, 1): its value (1e6) is left out, the other
     * three weighted and renormalised */
    const double x = 0.5 * (s.xc[1] + s.xc[2]), y = 0.5 * (s.yc[1] + s.yc[2]);
    flow_field_sample(&s, x, y, &q);
    const double others = (s.rho[1 * NX + 2] + s.rho[2 * NX + 1] + s.rho[2 * NX + 2]) / 3.0;
    assert_true(fabs(q.rho - others) < 1e-14);
    /* at the body cell's own centre the gas cells carry no weight: the
     * nearest of them, (2, 1) (centres 1.4 apart in x, 2.2 in y) */
    flow_field_sample(&s, s.xc[1], s.yc[1], &q);
    assert_true(q.rho == s.rho[1 * NX + 2]);
    flow_field_source_free(&s);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_round_trip), cmocka_unit_test(test_point_data_skipped),
        cmocka_unit_test(test_bad_files),  cmocka_unit_test(test_pieces),
        cmocka_unit_test(test_point_sets), cmocka_unit_test(test_sampling),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
