/* fuzz_stl: the STL reader behind `shape: stl` (io/stl_read.h) and the
 * closed-surface shape it feeds (core/shape_mesh.h). The input is written
 * to SCRATCH/input.stl and read; a refusal must say where (a line for
 * ASCII, a byte offset for binary) and what; an accepted file's triangles
 * are built into a shape (or refused as not closed, with a reason) and a
 * few points are tested against it. Everything is freed, so a leak is a
 * finding; anything else aborts. */
#include "fuzz_target.h"

#include "core/mem.h"
#include "core/shape_mesh.h"
#include "core/status.h"
#include "io/stl_read.h"

#include <stdio.h>
#include <stdlib.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    char path[4200];
    if (!fuzz_scratch_path("input.stl", path, sizeof path) || fuzz_write_file(path, data, size))
        return 0;
    double *tri;
    int64_t n;
    StlReadError err;
    const int st = stl_read_file(path, &tri, &n, &err);
    if (st == NSPD_ERR_INPUT) {
        if (err.text[0] == '\0' || err.line < 0 || err.offset < 0 || err.offset > (int64_t)size) {
            fprintf(stderr, "fuzz_stl: a refusal without its place or reason\n");
            abort();
        }
        return 0;
    }
    if (st != NSPD_OK) return 0; /* out of memory: not the reader's fault */
    ShapeMesh *m;
    char why[256] = "";
    const int made = shape_mesh_create(tri, n, &m, why, sizeof why);
    nspd_free(&tri);
    if (made == NSPD_ERR_INPUT && why[0] == '\0') {
        fprintf(stderr, "fuzz_stl: a surface refused without a reason\n");
        abort();
    }
    if (made != NSPD_OK) return 0;
    double lo[3], hi[3];
    shape_mesh_bounds(m, lo, hi);
    for (int k = 0; k <= 4; k++) {
        const double p[3] = {lo[0] + 0.25 * k * (hi[0] - lo[0]), 0.5 * (lo[1] + hi[1]),
                             0.5 * (lo[2] + hi[2])};
        (void)shape_mesh_contains(m, p);
    }
    shape_mesh_free(&m);
    return 0;
}
