/* vtk_same A B: whether two rectilinear grids that nspd wrote hold the
 * same bits: the cells per axis, every face coordinate and every cell
 * array (names, components, values). Either file may be a .vtr or the
 * .pvtr of the pieces that several processes wrote (read back whole by
 * io/vtk_read.h), so a run of several processes is held against the run
 * of one array by array (tests/mpi/run.sh).
 *   exit status: 0 the same, 1 different (the first difference printed),
 *   2 a file could not be read */
#include "core/status.h"
#include "io/vtk_read.h"

#include <stdio.h>
#include <string.h>

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
    for (int k = 0; k < a->array_count; k++) {
        const VtkCellArray *x = &a->arrays[k], *y = &b->arrays[k];
        if (strcmp(x->name, y->name) != 0 || x->components != y->components) {
            snprintf(buf, size, "array %d: '%s' (%d) and '%s' (%d)", k, x->name, x->components,
                     y->name, y->components);
            return buf;
        }
        for (size_t i = 0; i < cells * (size_t)x->components; i++)
            if (memcmp(&x->data[i], &y->data[i], sizeof(double)) != 0) {
                snprintf(buf, size, "'%s' at value %zu: %.17g and %.17g", x->name, i, x->data[i],
                         y->data[i]);
                return buf;
            }
    }
    return NULL;
}

int main(int argc, char **argv) {
    if (argc != 3) {
        fprintf(stderr, "usage: vtk_same A.vtr|A.pvtr B.vtr|B.pvtr\n");
        return 2;
    }
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
