/* core/shape_mesh and io/stl_read: a closed triangulated surface as a
 * shape. The containment test against an independent one (the winding
 * number, the solid angles' sum) at every point of a lattice whose rows
 * pass exactly through the mesh's vertices and edges (the ray's
 * degenerate cases); the enclosed volume against the polyhedron's exact
 * one; open and flat surfaces refused; binary and ASCII STL files of the
 * same mesh read to the same triangles; bad files refused at their line or
 * byte. */
#include "test_support.h"

#include "core/mem.h"
#include "core/shape.h"
#include "core/shape_mesh.h"
#include "core/status.h"
#include "io/stl_read.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* An octahedron subdivided `level` times and pushed onto the unit sphere,
 * scaled by (a, b, c) (the vertices at exact dyadic or simple coordinates
 * at level 0); 8 4^level triangles into tri (9 doubles each). */
static int64_t ellipsoid(int level, const double abc[3], double **tri) {
    int64_t n = 8;
    double *t;
    assert_ok(nspd_alloc(&t, 9 * 8, sizeof(double)));
    for (int k = 0; k < 8; k++) {
        const double sx = k & 1 ? -1 : 1, sy = k & 2 ? -1 : 1, sz = k & 4 ? -1 : 1;
        const double v[9] = {sx, 0, 0, 0, sy, 0, 0, 0, sz};
        memcpy(t + 9 * k, v, sizeof v);
        if (sx * sy * sz < 0) /* all outward: the winding number and the volume need it */
            for (int d = 0; d < 3; d++) {
                const double w = t[9 * k + 3 + d];
                t[9 * k + 3 + d] = t[9 * k + 6 + d], t[9 * k + 6 + d] = w;
            }
    }
    for (int l = 0; l < level; l++) {
        double *u;
        assert_ok(nspd_alloc(&u, (size_t)(9 * 4 * n), sizeof(double)));
        for (int64_t k = 0; k < n; k++) {
            const double *a = t + 9 * k, *b = a + 3, *c = a + 6;
            double m[3][3];
            for (int d = 0; d < 3; d++) {
                m[0][d] = 0.5 * (a[d] + b[d]);
                m[1][d] = 0.5 * (b[d] + c[d]);
                m[2][d] = 0.5 * (c[d] + a[d]);
            }
            for (int e = 0; e < 3; e++) { /* onto the sphere */
                const double r = sqrt(m[e][0] * m[e][0] + m[e][1] * m[e][1] + m[e][2] * m[e][2]);
                for (int d = 0; d < 3; d++) m[e][d] /= r;
            }
            const double *quad[4][3] = {
                {a, m[0], m[2]}, {m[0], b, m[1]}, {m[2], m[1], c}, {m[0], m[1], m[2]}};
            for (int q = 0; q < 4; q++)
                for (int v = 0; v < 3; v++) memcpy(u + 9 * (4 * k + q) + 3 * v, quad[q][v], 24);
        }
        nspd_free(&t);
        t = u;
        n *= 4;
    }
    for (int64_t k = 0; k < 3 * n; k++)
        for (int d = 0; d < 3; d++) t[3 * k + d] *= abc[d];
    *tri = t;
    return n;
}

/* The winding number at p (Van Oosterom-Strackee solid angles / 4 pi). */
static double winding(const double *tri, int64_t n, const double p[3]) {
    double w = 0.0;
    for (int64_t k = 0; k < n; k++) {
        double a[3], b[3], c[3];
        for (int d = 0; d < 3; d++) {
            a[d] = tri[9 * k + d] - p[d];
            b[d] = tri[9 * k + 3 + d] - p[d];
            c[d] = tri[9 * k + 6 + d] - p[d];
        }
        const double la = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]),
                     lb = sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]),
                     lc = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        const double det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                           a[2] * (b[0] * c[1] - b[1] * c[0]);
        const double dot = la * lb * lc + (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) * lc +
                           (b[0] * c[0] + b[1] * c[1] + b[2] * c[2]) * la +
                           (c[0] * a[0] + c[1] * a[1] + c[2] * a[2]) * lb;
        w += 2.0 * atan2(det, dot);
    }
    return fabs(w) / (4.0 * M_PI);
}

/* the enclosed volume, by the divergence theorem */
static double volume(const double *tri, int64_t n) {
    double v = 0.0;
    for (int64_t k = 0; k < n; k++) {
        const double *a = tri + 9 * k, *b = a + 3, *c = a + 6;
        v += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
             a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
    return fabs(v) / 6.0;
}

static void test_against_winding_number(void **state) {
    (void)state;
    double *tri;
    const double abc[3] = {1.0, 0.75, 0.5};
    const int64_t n = ellipsoid(3, abc, &tri); /* 512 triangles */
    ShapeMesh *m;
    char why[256];
    assert_ok(shape_mesh_create(tri, n, &m, why, sizeof why));
    /* a lattice of spacing 1/8 (0.75 / 6, 0.5 / 4): its rows meet the
     * vertices of level 0 and run along edges of the subdivision */
    int64_t points = 0, inside = 0, wrong = 0;
    const double h = 0.125;
    for (int i = -9; i <= 9; i++)
        for (int j = -7; j <= 7; j++)
            for (int k = -5; k <= 5; k++) {
                const double p[3] = {i * h, j * h, k * h};
                const double w = winding(tri, n, p);
                /* on the surface (a face 1/2, an edge or a vertex some other
                 * fraction): either answer is right; off it w is 0 or 1 */
                if (w > 1e-6 && w < 1.0 - 1e-6) continue;
                const bool in = shape_mesh_contains(m, p);
                wrong += in != (w > 0.5);
                inside += in;
                points++;
            }
    /* the ray's worst cases: through the vertices of level 0 and on the axes */
    const double hard[][3] = {{-2, 0, 0},   {0, 0, 0},      {0.5, 0, 0},  {0, 0.7, 0},
                              {0, 0, 0.49}, {-0.3, 0, 0.1}, {0.2, 0.1, 0}};
    for (size_t q = 0; q < sizeof hard / sizeof hard[0]; q++)
        wrong += shape_mesh_contains(m, hard[q]) != (winding(tri, n, hard[q]) > 0.5);
    /* the volume by counting lattice points against the exact one */
    double count = 0.0;
    const double g = 0.02;
    for (double x = -1 + 0.5 * g; x < 1; x += g)
        for (double y = -0.75 + 0.5 * g; y < 0.75; y += g)
            for (double z = -0.5 + 0.5 * g; z < 0.5; z += g)
                count += shape_mesh_contains(m, (const double[3]){x, y, z});
    const double exact = volume(tri, n), counted = count * g * g * g;
    printf("stl ellipsoid of %lld triangles: %lld of %lld lattice points inside, %lld differ "
           "from the winding number; volume %.5f counted, %.5f exact (%.2e)\n",
           (long long)n, (long long)inside, (long long)points, (long long)wrong, counted, exact,
           fabs(counted - exact) / exact);
    assert_true(wrong == 0);
    assert_true(inside > 100);
    /* measured 3.3e-4: the lattice's own error at g = 0.02 (about the
     * surface's area g / 2 / volume / sqrt of the points), bound 2e-3 */
    assert_true(fabs(counted - exact) / exact < 2e-3);
    /* the shape kind around it, in 2D: the section z = 0.25 */
    Shape s = {.kind = SHAPE_STL, .mesh = m, .section = true, .section_z = 0.25};
    assert_true(shape_contains(&s, (const double[3]){0.0, 0.0, 0.0}));
    assert_true(!shape_contains(&s, (const double[3]){0.95, 0.0, 0.0})); /* outside at z 0.25 */
    ShapeSet set = {1, NULL};
    assert_ok(nspd_alloc(&set.shapes, 1, sizeof(Shape)));
    set.shapes[0] = s;
    shapeset_free(&set); /* frees the mesh */
    nspd_free(&tri);
}

/* A box of 12 triangles, each face cut by its diagonal, queried where the
 * rays run exactly through the diagonals of the end faces (points on a
 * shared edge: counted once, whatever the rounding of the two triangles'
 * edge functions) - the case that once put a sliver of points outside a
 * specimen. */
static void test_rays_through_diagonals(void **state) {
    (void)state;
    const double lo[3] = {0.0, -10.0, -2.0}, hi[3] = {1.0, 10.0, 2.0};
    double tri[12 * 9];
    int t = 0;
    for (int axis = 0; axis < 3; axis++)
        for (int side = 0; side < 2; side++) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            double c[4][3];
            for (int k = 0; k < 4; k++) {
                c[k][axis] = side ? hi[axis] : lo[axis];
                c[k][u] = (k == 1 || k == 2) ? hi[u] : lo[u];
                c[k][v] = k >= 2 ? hi[v] : lo[v];
            }
            const int order[2][3] = {{0, 1, 2}, {0, 2, 3}};
            for (int h = 0; h < 2; h++, t++)
                for (int k = 0; k < 3; k++) memcpy(tri + 9 * t + 3 * k, c[order[h][k]], 24);
        }
    ShapeMesh *m;
    char why[256];
    assert_ok(shape_mesh_create(tri, 12, &m, why, sizeof why));
    int64_t wrong = 0, on_diagonal = 0;
    for (int j = -39; j <= 39; j++)
        for (int k = -39; k <= 39; k++) {
            const double y = 0.25 * j, z = 0.05 * k; /* (y, z) on the diagonal z = y / 5 */
            on_diagonal += 5.0 * z == y;
            wrong += !shape_mesh_contains(m, (const double[3]){0.5, y, z});
            wrong += shape_mesh_contains(m, (const double[3]){-0.5, y, z});
            wrong += shape_mesh_contains(m, (const double[3]){1.5, y, z});
        }
    printf("box: %lld of 3 x 6241 queries wrong, %lld rays through the diagonals\n",
           (long long)wrong, (long long)on_diagonal);
    assert_true(on_diagonal > 10 && wrong == 0);
    shape_mesh_free(&m);
}

/* A prism of a regular n-gon (radius r, centre cx, z in [-1, 1]), its
 * faces fanned from the centre and its sides cut by diagonals, outward;
 * 4 n triangles appended at tri + 9 * at. */
static int prism(double *tri, int at, int n, double r, double cx) {
    for (int k = 0; k < n; k++) {
        const double a0 = 2 * M_PI * k / n, a1 = 2 * M_PI * ((k + 1) % n) / n;
        const double p[2] = {cx + r * cos(a0), r * sin(a0)}, q[2] = {cx + r * cos(a1), r * sin(a1)};
        const double t[4][9] = {{cx, 0, 1, p[0], p[1], 1, q[0], q[1], 1},
                                {cx, 0, -1, q[0], q[1], -1, p[0], p[1], -1},
                                {p[0], p[1], -1, q[0], q[1], -1, q[0], q[1], 1},
                                {p[0], p[1], -1, q[0], q[1], 1, p[0], p[1], 1}};
        memcpy(tri + 9 * (at + 4 * k), t, sizeof t);
    }
    return at + 4 * n;
}

static void test_section(void **state) {
    (void)state;
    double tri[2 * 4 * 32 * 9];
    const int n = prism(tri, 0, 32, 1.0, 0.0);
    ShapeMesh *m;
    char why[256];
    assert_ok(shape_mesh_create(tri, n, &m, why, sizeof why));
    double *xy;
    int count;
    assert_ok(shape_mesh_section(m, 0.3, &xy, &count, why, sizeof why));
    const double area = polygon_signed_area(xy, count), exact = 16.0 * sin(2 * M_PI / 32);
    printf("section of a 32-gon prism: %d vertices, area %.15f (exact %.15f)\n", count, area,
           exact);
    /* counter-clockwise, the 32 corners and a point on each side's diagonal */
    assert_true(count == 64 && fabs(area - exact) < 1e-14 * exact);
    nspd_free(&xy);
    assert_int_equal(shape_mesh_section(m, 1.5, &xy, &count, why, sizeof why), NSPD_ERR_INPUT);
    assert_non_null(strstr(why, "segments"));
    shape_mesh_free(&m);
    /* two prisms: two loops, refused (one body each) */
    const int n2 = prism(tri, n, 32, 1.0, 3.0);
    assert_ok(shape_mesh_create(tri, n2, &m, why, sizeof why));
    assert_int_equal(shape_mesh_section(m, 0.0, &xy, &count, why, sizeof why), NSPD_ERR_INPUT);
    assert_non_null(strstr(why, "more than one loop"));
    shape_mesh_free(&m);
}

static void test_refusals(void **state) {
    (void)state;
    double *tri;
    const double one[3] = {1, 1, 1};
    const int64_t n = ellipsoid(1, one, &tri);
    ShapeMesh *m;
    char why[256];
    assert_int_equal(shape_mesh_create(tri, n - 1, &m, why, sizeof why), NSPD_ERR_INPUT);
    assert_non_null(strstr(why, "not closed"));
    assert_null(m);
    for (int64_t k = 0; k < 3 * n; k++) tri[3 * k + 2] = 0.0; /* flattened */
    assert_int_equal(shape_mesh_create(tri, n, &m, why, sizeof why), NSPD_ERR_INPUT);
    assert_non_null(strstr(why, "flat"));
    nspd_free(&tri);
}

static void write_file(const char *path, const void *data, size_t size) {
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_true(fwrite(data, 1, size, f) == size);
    fclose(f);
}

static void test_stl_files(void **state) {
    (void)state;
    double *tri;
    const double abc[3] = {0.5, 0.25, 0.125};
    const int64_t n = ellipsoid(2, abc, &tri);
    /* binary: the coordinates as floats */
    const size_t size = 84 + 50 * (size_t)n;
    unsigned char *bin = calloc(size, 1);
    memcpy(bin, "solid but binary: a header may start so", 39);
    bin[80] = (unsigned char)n;
    bin[81] = (unsigned char)(n >> 8);
    char *ascii = malloc(200 * (size_t)n + 100);
    int len = sprintf(ascii, "solid test\n");
    for (int64_t k = 0; k < n; k++) {
        len += sprintf(ascii + len, "  facet normal 0 0 1\n    outer loop\n");
        for (int v = 0; v < 3; v++) {
            float f[3];
            for (int d = 0; d < 3; d++) {
                f[d] = (float)tri[9 * k + 3 * v + d];
                tri[9 * k + 3 * v + d] = (double)f[d]; /* what both files hold */
            }
            memcpy(bin + 84 + 50 * k + 12 + 12 * v, f, 12);
            len += sprintf(ascii + len, "      vertex %.9g %.9g %.9g\n", (double)f[0], (double)f[1],
                           (double)f[2]);
        }
        len += sprintf(ascii + len, "    endloop\n  endfacet\n");
    }
    len += sprintf(ascii + len, "endsolid test\n");
    char pb[1200], pa[1200];
    snprintf(pb, sizeof pb, "%s/b.stl", test_scratch_dir("stl"));
    snprintf(pa, sizeof pa, "%s/a.stl", test_scratch_dir("stl"));
    write_file(pb, bin, size);
    write_file(pa, ascii, (size_t)len);
    double *tb, *ta;
    int64_t nb, na;
    StlReadError err;
    assert_ok(stl_read_file(pb, &tb, &nb, &err));
    assert_ok(stl_read_file(pa, &ta, &na, &err));
    assert_true(nb == n && na == n);
    assert_memory_equal(tb, tri, (size_t)(9 * n) * sizeof(double));
    /* the ASCII file's decimals (9 digits) read back to the same floats */
    for (int64_t k = 0; k < 9 * n; k++) assert_true((float)ta[k] == (float)tri[k]);
    nspd_free(&tb);
    nspd_free(&ta);
    /* refusals: a truncated binary (by its size), a bad ASCII word */
    write_file(pb, bin, size - 7);
    assert_int_equal(stl_read_file(pb, &tb, &nb, &err), NSPD_ERR_INPUT);
    assert_true(err.offset == 80 && strstr(err.text, "states 128 triangles")); /* not text */
    char *bad = strstr(ascii, "vertex") + 7; /* the first vertex's x, line 4 */
    bad[0] = 'q';
    write_file(pa, ascii, (size_t)len);
    assert_int_equal(stl_read_file(pa, &ta, &na, &err), NSPD_ERR_INPUT);
    assert_true(err.line == 4 && strstr(err.text, "is not a number"));
    const char *cut = "solid x\n facet normal 0 0 1\n";
    write_file(pa, cut, strlen(cut));
    assert_int_equal(stl_read_file(pa, &ta, &na, &err), NSPD_ERR_INPUT);
    assert_true(err.line == 2 && strstr(err.text, "expected 'outer'"));
    write_file(pa, "hello", 5);
    assert_int_equal(stl_read_file(pa, &ta, &na, &err), NSPD_ERR_INPUT);
    free(bin);
    free(ascii);
    nspd_free(&tri);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_against_winding_number),
        cmocka_unit_test(test_rays_through_diagonals),
        cmocka_unit_test(test_section),
        cmocka_unit_test(test_refusals),
        cmocka_unit_test(test_stl_files),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
