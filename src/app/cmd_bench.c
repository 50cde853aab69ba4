/* nspd bench: throughput of the solvers' hot loops, one JSON object each.
 * A model's benchmark is its own (SolidOps.bench, FlowOps.bench: pd, cpd,
 * gks); the machine's memory bandwidth is measured here. */
#include "app/commands.h"
#include "core/mem.h"
#include "core/report.h"
#include "core/status.h"
#include "core/timer.h"
#include "flow/flow.h"
#include "io/json.h"
#include "solid/solid.h"

#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    long points, steps;
    int threads;
} BenchOptions;

static bool parse(int argc, char **argv, BenchOptions *opt) {
    for (int i = 0; i < argc; i += 2) { /* an option and its value */
        const char *a = argv[i];
        long value = i + 1 < argc ? strtol(argv[i + 1], NULL, 10) : 0;
        if ((strcmp(a, "--points") == 0 || strcmp(a, "--cells") == 0) && value > 0) {
            opt->points = value;
        } else if (strcmp(a, "--steps") == 0 && value > 0) {
            opt->steps = value;
        } else if (strcmp(a, "--threads") == 0 && value > 0) {
            opt->threads = (int)value;
        } else {
            fprintf(stderr,
                    "nspd bench: bad option '%s' (expected --points/--cells N, --steps S, "
                    "--threads T with positive values)\n",
                    a);
            return false;
        }
    }
    return true;
}

/* A model's benchmark `name` (*found false when no model has one). The
 * report lives on this stack frame (131 kB): allocated before the run, or
 * static, it moved the addresses the solver's arrays get (the static one
 * shifted the heap by its size) and with them the GKS step by 4-6 %
 * (measured, pairs of runs against the previous binary; 1.01 on the
 * stack), which is not what a benchmark should measure. */
static int bench_model(const char *name, const BenchOptions *opt, bool *found) {
    Report r;
    report_clear(&r);
    TRY(solid_bench(name, opt->points, opt->steps, &r, found));
    if (!*found) TRY(flow_bench(name, opt->points, opt->steps, &r, found));
    if (!*found) return NSPD_OK;
    JsonWriter w;
    json_begin(&w, stdout);
    for (int k = 0; k < r.n; k++) {
        const ReportItem *it = &r.item[k];
        if (it->kind == REPORT_TEXT)
            json_string(&w, it->name, it->text);
        else if (it->kind == REPORT_INT)
            json_int(&w, it->name, it->count);
        else
            json_number(&w, it->name, it->real);
    }
    json_end(&w);
    return NSPD_OK;
}

/* STREAM-style triad a = b + s c over three arrays of `points` doubles
 * (default 2^25 each, 768 MB in all: far beyond the caches): the machine's
 * sustainable memory bandwidth, the ceiling of a memory-bound kernel.
 * Counts 24 bytes per element (two reads, one write; the write-allocate read
 * is not counted, as in STREAM). */
static int bench_memory(const BenchOptions *opt) {
    int64_t n = opt->points;
    double *a, *b, *c;
    TRY(nspd_alloc(&a, (size_t)n, sizeof(double)));
    int status = nspd_alloc(&b, (size_t)n, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&c, (size_t)n, sizeof(double));
    if (status != NSPD_OK) {
        nspd_free(&a);
        nspd_free(&b);
        return status;
    }
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < n; i++) {
        a[i] = 0.0;
        b[i] = 1.0;
        c[i] = 2.0;
    }
    double best = 0.0;
    for (long rep = 0; rep < opt->steps; rep++) {
        double t0 = nspd_wall_time();
#pragma omp parallel for schedule(static)
        for (int64_t i = 0; i < n; i++) a[i] = b[i] + 3.0 * c[i];
        double rate = 24.0 * (double)n / (nspd_wall_time() - t0);
        if (rate > best) best = rate;
    }
    JsonWriter w;
    json_begin(&w, stdout);
    json_string(&w, "bench", "memory");
    json_int(&w, "doubles_per_array", n);
    json_int(&w, "repeats", opt->steps);
    json_int(&w, "threads", omp_get_max_threads());
    json_number(&w, "triad_bytes_per_s", best);
    json_number(&w, "check", a[n / 2]); /* 7: keeps the loop from being optimised away */
    json_end(&w);
    nspd_free(&a);
    nspd_free(&b);
    nspd_free(&c);
    return NSPD_OK;
}

int cmd_bench(int argc, char **argv) {
    if (argc < 1) {
        fprintf(stderr, "usage: nspd bench pd [--points N] [--threads T] [--steps S]\n"
                        "       nspd bench cpd [--points N] [--threads T] [--steps S]\n"
                        "       nspd bench gks [--cells N] [--threads T] [--steps S]\n"
                        "       nspd bench memory [--points N] [--threads T] [--steps REPEATS]\n");
        return EXIT_BAD_INPUT;
    }
    bool gks = strcmp(argv[0], "gks") == 0, memory = strcmp(argv[0], "memory") == 0;
    BenchOptions opt = {memory ? (1L << 25)
                        : gks  ? 1000000
                               : 250000,
                        memory ? 10
                        : gks  ? 20
                               : 50,
                        0};
    if (!parse(argc - 1, argv + 1, &opt)) return EXIT_BAD_INPUT;
    if (opt.threads > 0) omp_set_num_threads(opt.threads);
    int status;
    bool found = true;
    if (memory) {
        status = bench_memory(&opt);
    } else {
        status = bench_model(argv[0], &opt, &found);
    }
    if (!found) {
        fprintf(stderr, "nspd bench: unknown benchmark '%s' (expected pd, cpd, gks or memory)\n",
                argv[0]);
        return EXIT_BAD_INPUT;
    }
    if (status != NSPD_OK) fprintf(stderr, "nspd bench: %s\n", nspd_error_message());
    return exit_status_of(status);
}
