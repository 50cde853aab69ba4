/* Mesh points: the elements' centroids as a lattice (mesh_points.h). */
#include "solid/pd/mesh_points.h"

#include "core/mem.h"
#include "core/status.h"

#include <math.h>
#include <stdlib.h>

typedef struct {
    uint64_t key;
    int64_t element;
} Keyed;

static int compare_keyed(const void *a, const void *b) {
    const Keyed *x = a, *y = b;
    if (x->key != y->key) return (x->key > y->key) - (x->key < y->key);
    return (x->element > y->element) - (x->element < y->element);
}

/* The cell of dx from the lower corner along one axis; a mesh far wider
 * than 2^31 spacings shares cells at its edge (the order only). */
static int32_t cell_of(double x, double lo, double dx) {
    const double c = floor((x - lo) / dx);
    return c < (double)INT32_MAX ? (int32_t)c : INT32_MAX;
}

int mesh_points_fill(Lattice *lat, const MeshPoints *mesh, int dim, double dx,
                     const ShapeSet *filter) {
    lattice_free(lat);
    if (dim != 2)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "points from a mesh in %dD; expected a 2D solid (no 3D solid runs on "
                         "points off a lattice)",
                         dim);
    if (mesh->n < 1 || mesh->n > INT32_MAX || !(dx > 0.0))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "a mesh of %lld elements with spacing %g m; expected 1 to 2^31 - 1 "
                         "elements and a spacing > 0",
                         (long long)mesh->n, dx);
    double lo[2] = {INFINITY, INFINITY};
    for (int64_t e = 0; e < mesh->n; e++)
        for (int d = 0; d < 2; d++) lo[d] = fmin(lo[d], mesh->x[d][e]);
    const bool filtered = filter && filter->count > 0;
    Keyed *keyed;
    TRY(nspd_alloc(&keyed, (size_t)mesh->n, sizeof *keyed));
    int64_t n = 0;
    for (int64_t e = 0; e < mesh->n; e++) {
        const double p[3] = {mesh->x[0][e], mesh->x[1][e], 0.0};
        if (filtered && !shapeset_contains(filter, p)) continue;
        const uint32_t i = (uint32_t)cell_of(p[0], lo[0], dx),
                       j = (uint32_t)cell_of(p[1], lo[1], dx);
        keyed[n++] = (Keyed){morton_key(2, i, j, 0), e};
    }
    if (n == 0) {
        nspd_free(&keyed);
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "no element centroid of the mesh falls inside the solid geometry; "
                         "expected the geometry to cover the mesh, or no geometry");
    }
    qsort(keyed, (size_t)n, sizeof *keyed, compare_keyed);
    int status = NSPD_OK;
    lat->n = n;
    for (int d = 0; d < 3 && status == NSPD_OK; d++) {
        status = nspd_alloc(&lat->x[d], (size_t)n, sizeof(double));
        if (status == NSPD_OK) status = nspd_alloc(&lat->index[d], (size_t)n, sizeof(int32_t));
    }
    if (status == NSPD_OK)
        for (int64_t p = 0; p < n; p++) {
            const int64_t e = keyed[p].element;
            for (int d = 0; d < 2; d++) {
                lat->x[d][p] = mesh->x[d][e];
                lat->index[d][p] = cell_of(mesh->x[d][e], lo[d], dx);
            }
            lat->x[2][p] = 0.0;
            lat->index[2][p] = (int32_t)e;
        }
    nspd_free(&keyed);
    if (status != NSPD_OK) lattice_free(lat);
    return status;
}

double mesh_points_measure(const MeshPoints *mesh, int32_t index2) {
    return index2 >= 0 && index2 < mesh->n ? mesh->measure[index2] : 0.0;
}

void mesh_points_free(MeshPoints *mesh) {
    for (int d = 0; d < 3; d++) nspd_free(&mesh->x[d]);
    nspd_free(&mesh->measure);
    mesh->n = 0;
}
