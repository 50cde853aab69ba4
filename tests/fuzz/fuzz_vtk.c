/* fuzz_vtk: the readers of nspd's VTK files: the .vtr (or the .pvtr of
 * its pieces) as flow.initial.from uses it, and the .vtu point sets (or
 * their .pvtu).
 *
 * The input is written to SCRATCH/input.vtr and read with
 * vtk_read_rectilinear; when it is accepted, the arrays a flow starts from
 * are looked up (vtk_find_cell_array) and every value of them and of the
 * face coordinates is read, so an array shorter than its grid is an
 * AddressSanitizer report. The same bytes are read as a point set
 * (vtk_read_points), every point and value of it touched. Then the same
 * file goes through the case
 * reader's path (a small flow case with `initial: {from: input.vtr}`),
 * which checks the arrays and builds the flow's field source from them.
 * Everything is freed, so a leak is a finding.
 *
 * The refusal contract (issue 23), asserted on every input: the reader
 * refuses with NSPD_ERR_INPUT or NSPD_ERR_IO and a message that names the
 * file; the case reader refuses at the case's FILE:LINE:COL (the `from`
 * key). Anything else aborts: a finding. */
#include "fuzz_target.h"

#include "case/case_read.h"
#include "core/status.h"
#include "io/vtk_read.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char CASE[] =
    "name: fuzz_vtk\n"
    "time: {end: 1.0}\n"
    "flow:\n"
    "  gas: {gamma: 1.4, gas_constant: 1.0, viscosity: {law: none}}\n"
    "  free_stream: {mach: 0.5, density: 1.0, pressure: 0.7142857142857143}\n"
    "  grid:\n"
    "    x: {start: 0.0, segments: [{length: 1.0, cells: 8}]}\n"
    "    y: {start: 0.0, segments: [{length: 1.0, cells: 8}]}\n"
    "  boundaries:\n"
    "    x_min: {type: extrapolation}\n"
    "    x_max: {type: extrapolation}\n"
    "    y_min: {type: periodic}\n"
    "    y_max: {type: periodic}\n"
    "  initial: {from: input.vtr}\n";

static char vtr_path[4200], case_path[4200];
static int ready;   /* 0 not set up, 1 ready, -1 failed */
static int verbose; /* NSPD_FUZZ_VERBOSE set: say what became of each input (making seeds) */

static int set_up(void) {
    if (!fuzz_scratch_path("input.vtr", vtr_path, sizeof vtr_path) ||
        !fuzz_scratch_path("case.yaml", case_path, sizeof case_path))
        return -1;
    verbose = getenv("NSPD_FUZZ_VERBOSE") != NULL;
    return fuzz_write_file(case_path, CASE, sizeof CASE - 1);
}

/* Reads every value, so that ASan sees an array shorter than declared. */
static double touch(const double *data, size_t count) {
    double sum = 0.0;
    for (size_t i = 0; i < count; i++) sum += data[i];
    return sum;
}

static void read_arrays(const VtkRectilinear *g) {
    static const struct {
        const char *name;
        int components;
    } wanted[] = {{"density", 1}, {"velocity", 3}, {"pressure", 1}, {"cell_kind", 1}};
    const size_t cells = (size_t)g->n[0] * (size_t)g->n[1] * (size_t)g->n[2];
    volatile double sink = 0.0; /* keeps the reads */
    for (size_t k = 0; k < sizeof wanted / sizeof wanted[0]; k++) {
        const VtkCellArray *a = vtk_find_cell_array(g, wanted[k].name, wanted[k].components);
        if (a) sink += touch(a->data, cells * (size_t)a->components);
    }
    for (int a = 0; a < 3; a++) sink += touch(g->face[a], (size_t)g->n[a] + 1);
    (void)sink;
}

/* A refusal that breaks the contract: said, then abort (libFuzzer saves
 * the input). */
static void broken(const char *who, int status) {
    fprintf(stderr, "fuzz_vtk: %s's refusal breaks the contract: status %d, '%s'\n", who, status,
            nspd_error_message());
    abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    if (ready == 0) ready = set_up() == 0 ? 1 : -1;
    if (ready < 0 || fuzz_write_file(vtr_path, data, size) != 0) abort();

    VtkRectilinear grid;
    int status = vtk_read_rectilinear(vtr_path, &grid);
    if (status == NSPD_OK) read_arrays(&grid);
    if (status != NSPD_OK && ((status != NSPD_ERR_INPUT && status != NSPD_ERR_IO) ||
                              !strstr(nspd_error_message(), vtr_path)))
        broken("the .vtr reader", status);
    if (verbose)
        fprintf(stderr, "fuzz_vtk: %s\n", status == NSPD_OK ? "read" : nspd_error_message());
    vtk_rectilinear_free(&grid);

    VtkPointSet set;
    status = vtk_read_points(vtr_path, &set);
    if (status == NSPD_OK) {
        volatile double sink = touch(set.points, 3 * (size_t)set.n); /* keeps the reads */
        for (int k = 0; k < set.array_count; k++)
            sink += touch(set.arrays[k].data, (size_t)set.n * (size_t)set.arrays[k].components);
        (void)sink;
    }
    if (status != NSPD_OK && ((status != NSPD_ERR_INPUT && status != NSPD_ERR_IO) ||
                              !strstr(nspd_error_message(), vtr_path)))
        broken("the .vtu reader", status);
    vtk_point_set_free(&set);

    CfgDoc doc;
    SimConfig cfg;
    status = case_read(case_path, NULL, 0, &doc, &cfg);
    if (status == NSPD_OK) {
        sim_config_free(&cfg);
        cfg_doc_free(&doc);
    } else if ((status != NSPD_ERR_INPUT && status != NSPD_ERR_IO) ||
               strncmp(nspd_error_message(), case_path, strlen(case_path)) != 0) {
        broken("the case reader", status);
    }
    if (verbose)
        fprintf(stderr, "fuzz_vtk: case %s\n",
                status == NSPD_OK ? "accepted" : nspd_error_message());
    nspd_error_clear();
    return 0;
}
