/* vtk_same A B: whether two rectilinear grids or two point sets that nspd
 * wrote hold the same bits: the cells per axis, every face coordinate and
 * every cell array (names, components, values); or the points, their
 * positions and every point array. Either file may be whole (.vtr, .vtu)
 * or the parallel file of the pieces that several processes wrote (.pvtr,
 * .pvtu; read back whole by io/vtk_read.h), so a run of several processes
 * is held against the run of one array by array (tests/mpi/run.sh). The
 * vertex cells of a point set number its own file's points and are not
 * compared.
 *   exit status: 0 the same, 1 different (the first difference printed),
 *   2 a file could not be read */
#include "core/status.h"
#include "io/vtk_read.h"

#include <stdbool.h>
#include <stdio.h>
#include <string.h>

static const char *array_difference(const VtkCellArray *x, const VtkCellArray *y, size_t n,
                                    char *buf, size_t size);

/* The first difference between a and b, or NULL. */
static const char *difference(const VtkRectilinear *a, const VtkRectilinear *b, char *buf,
                              size_t size) {
    for (int d = 0; d < 3; d++)
        if (a->n[d] != b->n[d]) {
            snprintf(buf, size, "%d and %d cells along %c", a->n[d], b->n[d], 'x' + d);
            return buf;
        }
    for (int d = 0; d < 3; d++)
        if (memcmp(a->face[d], b->face[d], ((size_t)a->n[d] + 1) * sizeof(double)) != 0) {
            snprintf(buf, size, "the %c faces", 'x' + d);
            return buf;
        }
    if (a->array_count != b->array_count) {
        snprintf(buf, size, "%d and %d cell arrays", a->array_count, b->array_count);
        return buf;
    }
    const size_t cells = (size_t)a->n[0] * (size_t)a->n[1] * (size_t)a->n[2];
    const char *why = NULL;
    for (int k = 0; k < a->array_count && !why; k++)
        why = array_difference(&a->arrays[k], &b->arrays[k], cells, buf, size);
    return why;
}

/* The first difference between two arrays of n tuples, or NULL. */
static const char *array_difference(const VtkCellArray *x, const VtkCellArray *y, size_t n,
                                    char *buf, size_t size) {
    if (strcmp(x->name, y->name) != 0 || x->components != y->components) {
        snprintf(buf, size, "'%s' (%d) and '%s' (%d)", x->name, x->components, y->name,
                 y->components);
        return buf;
    }
    for (size_t i = 0; i < n * (size_t)x->components; i++)
        if (memcmp(&x->data[i], &y->data[i], sizeof(double)) != 0) {
            snprintf(buf, size, "'%s' at value %zu: %.17g and %.17g", x->name, i, x->data[i],
                     y->data[i]);
            return buf;
        }
    return NULL;
}

static const char *points_difference(const VtkPointSet *a, const VtkPointSet *b, char *buf,
                                     size_t size) {
    if (a->n != b->n) {
        snprintf(buf, size, "%lld and %lld points", (long long)a->n, (long long)b->n);
        return buf;
    }
    const VtkCellArray pa = {"Points", 3, a->points}, pb = {"Points", 3, b->points};
    const char *why = array_difference(&pa, &pb, (size_t)a->n, buf, size);
    if (why) return why;
    if (a->array_count != b->array_count) {
        snprintf(buf, size, "%d and %d point arrays", a->array_count, b->array_count);
        return buf;
    }
    for (int k = 0; k < a->array_count && !why; k++)
        why = array_difference(&a->arrays[k], &b->arrays[k], (size_t)a->n, buf, size);
    return why;
}

static bool ends_with(const char *s, const char *tail) {
    const size_t n = strlen(s), m = strlen(tail);
    return n >= m && strcmp(s + n - m, tail) == 0;
}

static int same_points(const char *path_a, const char *path_b) {
    VtkPointSet a, b;
    int status = vtk_read_points(path_a, &a);
    if (status == NSPD_OK)
        status = vtk_read_points(path_b, &b);
    else
        memset(&b, 0, sizeof b);
    const char *why = NULL;
    char buf[512];
    if (status == NSPD_OK)
        why = points_difference(&a, &b, buf, sizeof buf);
    else
        fprintf(stderr, "vtk_same: %s\n", nspd_error_message());
    if (why) printf("%s and %s differ: %s\n", path_a, path_b, why);
    vtk_point_set_free(&a);
    vtk_point_set_free(&b);
    return status != NSPD_OK ? 2 : why ? 1 : 0;
}

int main(int argc, char **argv) {
    if (argc != 3) {
        fprintf(stderr, "usage: vtk_same A.vtr|A.pvtr|A.vtu|A.pvtu B.vtr|B.pvtr|B.vtu|B.pvtu\n");
        return 2;
    }
    if (ends_with(argv[1], "vtu")) return same_points(argv[1], argv[2]);
    VtkRectilinear a, b;
    int status = vtk_read_rectilinear(argv[1], &a);
    if (status == NSPD_OK)
        status = vtk_read_rectilinear(argv[2], &b);
    else
        memset(&b, 0, sizeof b);
    if (status != NSPD_OK) {
        fprintf(stderr, "vtk_same: %s\n", nspd_error_message());
        vtk_rectilinear_free(&a);
        vtk_rectilinear_free(&b);
        return 2;
    }
    char buf[512];
    const char *why = difference(&a, &b, buf, sizeof buf);
    if (why) printf("%s and %s differ: %s\n", argv[1], argv[2], why);
    vtk_rectilinear_free(&a);
    vtk_rectilinear_free(&b);
    return why ? 1 : 0;
}
