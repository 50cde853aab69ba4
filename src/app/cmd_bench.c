/* nspd bench: throughput of the solvers' hot loops, one JSON object each.
 * A model's benchmark is its own (SolidOps.bench, FlowOps.bench: pd, cpd,
 * gks); the machine's memory bandwidth and FP64 peak (the roofline's two
 * ceilings) are measured here. */
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
            command_usage(stderr, command_help("bench"), false);
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

/* FP64 peak: independent fused multiply-adds a = fma(a, x, y) (two flops
 * each), enough chains to keep every FMA pipe busy through its latency;
 * once in SIMD lanes (FLOPS_CHAINS chains: the vector peak at the
 * compiler's vector width, the ceiling of a vectorised kernel) and once
 * one at a time (8 chains, each held in its own register: the scalar peak,
 * the ceiling of a kernel the compiler leaves scalar, such as the IGA
 * flow's 4 x 4 algebra). nspd's kernels are ISO C without contraction
 * (CMakeLists.txt), so their multiplies and adds are separate
 * instructions: half these rates is their ceiling. Each thread runs its
 * own chains. */
enum { FLOPS_CHAINS = 64 };

static double fma_vector(long iterations) {
    double a[FLOPS_CHAINS];
    const double x = 0.999999, y = 1e-6;
    for (int k = 0; k < FLOPS_CHAINS; k++) a[k] = 1.0 + k * 1e-3;
    for (long it = 0; it < iterations; it++) {
#pragma omp simd
        for (int k = 0; k < FLOPS_CHAINS; k++) a[k] = fma(a[k], x, y);
    }
    double sum = 0.0;
    for (int k = 0; k < FLOPS_CHAINS; k++) sum += a[k];
    return sum;
}

/* a = fma(a, x, y) with `a` kept alone in a register (no lanes) */
#define SCALAR_FMA(a)                                                                              \
    do {                                                                                           \
        (a) = fma((a), x, y);                                                                      \
        __asm__("" : "+x"(a));                                                                     \
    } while (0)

static double fma_scalar(long iterations) {
    const double x = 0.999999, y = 1e-6;
    double a0 = 1.0, a1 = 1.001, a2 = 1.002, a3 = 1.003, a4 = 1.004, a5 = 1.005, a6 = 1.006,
           a7 = 1.007;
    for (long it = 0; it < 8L * iterations; it++) { /* 8 x 8 = FLOPS_CHAINS an iteration */
        SCALAR_FMA(a0);
        SCALAR_FMA(a1);
        SCALAR_FMA(a2);
        SCALAR_FMA(a3);
        SCALAR_FMA(a4);
        SCALAR_FMA(a5);
        SCALAR_FMA(a6);
        SCALAR_FMA(a7);
    }
    return a0 + a1 + a2 + a3 + a4 + a5 + a6 + a7;
}

static int bench_flops(const BenchOptions *opt) {
    const long iterations = opt->points;
    double best[2] = {0.0, 0.0}, check = 0.0;
    for (int simd = 0; simd < 2; simd++)
        for (long rep = 0; rep < opt->steps; rep++) {
            double t0 = nspd_wall_time(), sum = 0.0;
#pragma omp parallel reduction(+ : sum)
            sum += simd ? fma_vector(iterations) : fma_scalar(iterations);
            const double t = nspd_wall_time() - t0;
            const double rate =
                2.0 * FLOPS_CHAINS * (double)iterations * (double)omp_get_max_threads() / t;
            if (rate > best[simd]) best[simd] = rate;
            check += sum;
        }
    JsonWriter w;
    json_begin(&w, stdout);
    json_string(&w, "bench", "flops");
    json_int(&w, "iterations", iterations);
    json_int(&w, "repeats", opt->steps);
    json_int(&w, "threads", omp_get_max_threads());
    json_number(&w, "fp64_simd_flops_per_s", best[1]);
    json_number(&w, "fp64_scalar_flops_per_s", best[0]);
    json_number(&w, "check", check); /* keeps the chains from being optimised away */
    json_end(&w);
    return NSPD_OK;
}

int cmd_bench(int argc, char **argv) {
    if (argc < 1) {
        fprintf(stderr, "nspd bench: which benchmark?\n");
        command_usage(stderr, command_help("bench"), false);
        return EXIT_BAD_INPUT;
    }
    bool gks = strcmp(argv[0], "gks") == 0, memory = strcmp(argv[0], "memory") == 0;
    bool flops = strcmp(argv[0], "flops") == 0;
    BenchOptions opt = {memory  ? (1L << 25)
                        : flops ? 20000000
                        : gks   ? 1000000
                                : 250000,
                        memory || flops ? 10
                        : gks           ? 20
                                        : 50,
                        0};
    if (!parse(argc - 1, argv + 1, &opt)) return EXIT_BAD_INPUT;
    if (opt.threads > 0) omp_set_num_threads(opt.threads);
    int status;
    bool found = true;
    if (memory) {
        status = bench_memory(&opt);
    } else if (flops) {
        status = bench_flops(&opt);
    } else {
        status = bench_model(argv[0], &opt, &found);
    }
    if (!found) {
        fprintf(stderr,
                "nspd bench: unknown benchmark '%s' (expected pd, cpd, gks, memory or flops)\n",
                argv[0]);
        return EXIT_BAD_INPUT;
    }
    if (status != NSPD_OK) fprintf(stderr, "nspd bench: %s\n", nspd_error_message());
    return exit_status_of(status);
}
