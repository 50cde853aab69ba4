/* fuzz_inp: the Abaqus .inp reader behind solid.lattice kind abaqus
 * (io/inp_read.h) and the points it feeds (solid/pd/mesh_points.h). The
 * input is written to SCRATCH/input.inp and read; a refusal must say where
 * (a line within the file, or a byte offset within it) and what; an
 * accepted mesh must hold what the header promises (positive, finite
 * measures and centroids, node indices in range, sets that mark within
 * bounds), and a 2D one is made the solid's points (every element once,
 * its number in the third index). Everything is freed, so a leak is a
 * finding; anything else aborts. */
#include "fuzz_target.h"

#include "core/mem.h"
#include "core/status.h"
#include "io/inp_read.h"
#include "solid/pd/mesh_points.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void finding(const char *what) {
    fprintf(stderr, "fuzz_inp: %s\n", what);
    abort();
}

static void check_points(const InpMesh *m) {
    MeshPoints mp = {.n = m->element_count};
    double total = 0.0;
    for (int d = 0; d < 3; d++)
        if (nspd_alloc(&mp.x[d], (size_t)mp.n, sizeof(double)) != NSPD_OK) goto done;
    if (nspd_alloc(&mp.measure, (size_t)mp.n, sizeof(double)) != NSPD_OK) goto done;
    for (int64_t e = 0; e < mp.n; e++) {
        for (int d = 0; d < 3; d++) mp.x[d][e] = d < 2 ? m->centroid[3 * e + d] : 0.0;
        mp.measure[e] = m->measure[e];
        total += m->measure[e];
    }
    Lattice lat = {0};
    const double dx = sqrt(total / (double)mp.n);
    const int st = mesh_points_fill(&lat, &mp, 2, dx, NULL);
    if (st == NSPD_OK) {
        if (lat.n != mp.n) finding("a point per element expected");
        uint8_t *seen = calloc((size_t)mp.n, 1);
        for (int64_t p = 0; seen && p < lat.n; p++) {
            const int32_t e = lat.index[2][p];
            if (e < 0 || e >= mp.n || seen[e] || lat.x[0][p] != mp.x[0][e])
                finding("the points are not the elements, once each");
            seen[e] = 1;
            if (!(mesh_points_measure(&mp, e) > 0.0)) finding("a point without its measure");
        }
        free(seen);
    } else if (st == NSPD_ERR_INPUT && isfinite(dx) && dx > 0.0) {
        finding("the points of a read mesh refused");
    }
    lattice_free(&lat);
done:
    mesh_points_free(&mp);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    char path[4200];
    if (!fuzz_scratch_path("input.inp", path, sizeof path) || fuzz_write_file(path, data, size))
        return 0;
    int64_t lines = 1;
    for (size_t k = 0; k < size; k++) lines += data[k] == '\n';
    InpMesh m;
    InpReadError err;
    const int st = inp_read_file(path, INP_MAX_BYTES, &m, &err);
    if (st == NSPD_ERR_INPUT) {
        if (err.text[0] == '\0' || err.line < 0 || err.line > lines || err.offset < 0 ||
            err.offset > (int64_t)size)
            finding("a refusal without its place or reason");
        if (m.node_id || m.element_id || m.sets) finding("a refused mesh not freed");
        return 0;
    }
    if (st != NSPD_OK) return 0; /* out of memory: not the reader's fault */
    if ((m.dim != 2 && m.dim != 3) || m.element_count < 1) finding("a mesh without elements");
    for (int64_t e = 0; e < m.element_count; e++) {
        if (!(m.measure[e] > 0.0) || !isfinite(m.measure[e])) finding("a measure <= 0");
        for (int d = 0; d < 3; d++)
            if (!isfinite(m.centroid[3 * e + d])) finding("a centroid not finite");
        const int nodes = inp_shape_nodes((InpShape)m.element_shape[e]);
        for (int k = 0; k < nodes; k++) {
            const int64_t n = m.element_node[INP_MAX_ELEMENT_NODES * e + k];
            if (n < 0 || n >= m.node_count) finding("a node index out of range");
        }
    }
    const int64_t most = m.node_count > m.element_count ? m.node_count : m.element_count;
    uint8_t *mark = calloc((size_t)most + 1, 1);
    for (int k = 0; mark && k < m.set_count; k++) {
        const InpSet *s = &m.sets[k];
        const int64_t n = s->elements ? m.element_count : m.node_count;
        memset(mark, 0, (size_t)n);
        if (inp_set_mark(&m, s, mark) > n) finding("a set marks more than there are");
        if (inp_find_set(&m, s->name, s->elements) != s) finding("a set not found by its name");
    }
    free(mark);
    if (m.dim == 2) check_points(&m);
    inp_mesh_free(&m);
    return 0;
}
