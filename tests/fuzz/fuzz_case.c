/* fuzz_case: the case reader as `nspd check` and `nspd run` use it.
 *
 * An input is a case file, optionally followed by --set overrides: the
 * bytes up to a line "#--set" are written to SCRATCH/case.yaml, every
 * non-empty line after it is one KEY=VALUE override (at most 8). Then
 * case_read (the YAML tree, the overrides, the whole schema, files the case
 * names) and, when the case is accepted, the resolved case written as `nspd
 * run` writes case.yaml (to /dev/null). Everything is freed, so a leak is a
 * finding.
 *
 * The scratch directory also holds what a case may name, relative to the
 * case file: field.vtr (a 4 x 3 flow field, for flow.initial.from) and
 * body.csv (a triangle, for a polygon body); the seed corpus refers to
 * them.
 *
 * Built with NSPD_FUZZ_SIM (the harness fuzz_sim, from this same file), an
 * accepted case is then built as `nspd check` builds it (SimConfig.
 * check_only) with the memory estimate capped at FUZZ_SIM_MEMORY, so that
 * no input allocates more than that: the models' own refusals, found while
 * they are built, and the estimate's, are fuzzed too. Its contract adds
 * the memory refusal ("the case needs about ... GB"), which names no key.
 *
 * The contract (issue 23), asserted on every input: accepted, or refused
 * with NSPD_ERR_INPUT and a message that starts with the place (the case
 * file's FILE:LINE:COL or the --set), or NSPD_ERR_IO naming what could not
 * be read; anything else aborts, which libFuzzer reports as a finding.
 *
 * Mutations (libFuzzer builds): half libFuzzer's own (bytes, the
 * dictionary's keys), half set_mutator.h's: an override of a real key of
 * the case with an extreme value. The replay in `make test` applies the
 * latter too (replay_main --mutate). */
#include "fuzz_target.h"
#include "set_mutator.h"

#include "case/case_read.h"
#include "core/status.h"
#include "sim/sim.h"
#include "io/cfg_tree.h"
#include "io/vtk.h"

#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_OVERRIDES = 8 };

/* fuzz_sim: the most an input may make the models allocate (bytes) */
#define FUZZ_SIM_MEMORY 64e6

static char case_path[4200];
static FILE *devnull;
static int ready;   /* 0 not set up, 1 ready, -1 failed */
static int verbose; /* NSPD_FUZZ_VERBOSE set: say what became of each input (making seeds) */

static int write_field(void) {
    enum { NX = 4, NY = 3, N = NX * NY };
    const double xf[NX + 1] = {0.0, 0.25, 0.5, 0.75, 1.0}, yf[NY + 1] = {0.0, 0.5, 1.0, 1.5},
                         zf[2] = {0.0, 1.0};
    double rho[N], u[N], v[N], p[N], kind[N];
    for (int k = 0; k < N; k++) {
        rho[k] = 1.0 + 0.01 * k;
        u[k] = 0.5;
        v[k] = 0.0;
        p[k] = 0.7142857142857143;
        kind[k] = 0.0;
    }
    const VtkField fields[] = {{"density", 1, {rho, NULL, NULL}},
                               {"velocity", 3, {u, v, NULL}},
                               {"pressure", 1, {p, NULL, NULL}},
                               {"cell_kind", 1, {kind, NULL, NULL}}};
    char path[4200];
    if (!fuzz_scratch_path("field.vtr", path, sizeof path)) return -1;
    return vtk_write_rectilinear(path, NX, NY, 1, xf, yf, zf, fields, 4, NULL, 0) == NSPD_OK ? 0
                                                                                             : -1;
}

static int set_up(void) {
    static const char body[] = "x, y\n0.4, 0.4\n0.6, 0.4\n0.5, 0.6\n";
    char path[4200];
    if (!fuzz_scratch_path("case.yaml", case_path, sizeof case_path)) return -1;
    if (!fuzz_scratch_path("body.csv", path, sizeof path)) return -1;
    if (fuzz_write_file(path, body, sizeof body - 1) != 0 || write_field() != 0) return -1;
    verbose = getenv("NSPD_FUZZ_VERBOSE") != NULL;
    devnull = fopen("/dev/null", "w");
    return devnull ? 0 : -1;
}

#ifdef NSPD_FUZZ_LIBFUZZER
size_t LLVMFuzzerMutate(uint8_t *data, size_t size, size_t max_size);

size_t LLVMFuzzerCustomMutator(uint8_t *data, size_t size, size_t max_size, unsigned int seed) {
    if (seed & 1u) {
        const size_t n = fuzz_set_mutate(data, size, max_size, seed >> 1);
        if (n > 0) return n;
    }
    return LLVMFuzzerMutate(data, size, max_size);
}
#endif

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    if (ready == 0) ready = set_up() == 0 ? 1 : -1;
    if (ready < 0) abort(); /* no scratch directory: nothing can be tested */
    const size_t cut = fuzz_set_separator(data, size);
    if (fuzz_write_file(case_path, data, cut) != 0) abort();

    /* the overrides: NUL-terminated lines (an embedded NUL ends its line,
     * as it would end a command-line argument) */
    char *text = NULL, *overrides[MAX_OVERRIDES];
    int count = 0;
    if (cut < size) {
        const size_t start = cut + 6, n = size - start;
        text = malloc(n + 1);
        if (!text) abort();
        memcpy(text, data + start, n);
        text[n] = '\0';
        for (char *line = text, *next; line && count < MAX_OVERRIDES; line = next) {
            next = strchr(line, '\n');
            if (next) *next++ = '\0';
            if (line[0]) overrides[count++] = line;
        }
    }

    CfgDoc doc;
    SimConfig cfg;
    int status = case_read(case_path, overrides, count, &doc, &cfg);
    bool memory = false; /* refused by the memory estimate */
    if (status == NSPD_OK) {
        cfg_doc_write(&doc, devnull);
#ifdef NSPD_FUZZ_SIM
        cfg.max_memory_bytes = FUZZ_SIM_MEMORY;
        cfg.check_only = true;
        Sim sim;
        status = sim_create(&sim, &cfg); /* takes cfg, whatever it returns */
        if (status == NSPD_OK) sim_destroy(&sim);
        memory = status == NSPD_ERR_INPUT &&
                 strncmp(nspd_error_message(), "the case needs about ", 21) == 0;
#else
        sim_config_free(&cfg);
#endif
        cfg_doc_free(&doc);
    }
    if (verbose)
        fprintf(stderr, "fuzz_case: %s\n", status == NSPD_OK ? "accepted" : nspd_error_message());
    if (status != NSPD_OK) {
        const char *message = nspd_error_message();
        const bool placed = strncmp(message, case_path, strlen(case_path)) == 0 ||
                            strncmp(message, "--set ", 6) == 0 || memory;
        if (!message[0] || (status != NSPD_ERR_INPUT && status != NSPD_ERR_IO) ||
            (status == NSPD_ERR_INPUT && !placed)) {
            fprintf(stderr, "fuzz_case: the refusal breaks the contract: status %d, '%s'\n", status,
                    message);
            abort();
        }
    }
    nspd_error_clear();
    free(text);
    return 0;
}
