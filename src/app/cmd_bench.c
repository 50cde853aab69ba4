/* nspd bench: throughput of the solvers' hot loops, one JSON object each. */
#include "app/commands.h"
#include "core/mem.h"
#include "core/status.h"
#include "core/timer.h"
#include "flow/gks_solver.h"
#include "io/json.h"
#include "solid/bond_body.h"
#include "solid/cpd_body.h"
#include "solid/pd_integrate.h"

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

/* The PD plate of paper 000 Sec. 4.2 (square lattice, delta = 3.015 dx,
 * failure test on every bond) under a small uniform strain, so that every
 * bond does the full work; N points as the nearest square. */
static int bench_pd(const BenchOptions *opt) {
    int side = (int)lround(sqrt((double)opt->points));
    if (side < 8) side = 8;
    double dx = 1e-4, length = side * dx;
    PdConfig cfg = {0};
    cfg.model = PD_PLANE_STRESS;
    cfg.dim = 2;
    cfg.spacing = dx;
    cfg.thickness = dx;
    cfg.horizon_factor = 3.015;
    cfg.density = 8000;
    cfg.youngs_modulus = 192e9;
    cfg.critical_stretch = 0.04472;
    cfg.failure = true;
    cfg.volume_correction = PD_VOLUME_LINEAR;
    cfg.surface_correction = PD_SURFACE_ENERGY;
    cfg.integrator = PD_EULER_CROMER;
    TRY(nspd_alloc(&cfg.geometry.shapes, 1, sizeof(Shape)));
    cfg.geometry.count = 1;
    cfg.geometry.shapes[0] =
        (Shape){.kind = SHAPE_RECTANGLE, .lo = {0, 0, 0}, .hi = {length, length, 0}};

    double t0 = nspd_wall_time();
    BondBody body;
    TRY(bond_body_create(&body, &cfg));
    double setup_s = nspd_wall_time() - t0;
    for (int64_t i = 0; i < body.n; i++) {
        body.u[0][i] = 1e-4 * body.x[0][i];
        body.u[1][i] = -3e-5 * body.x[1][i];
    }
    double dt = 0.8 * pd_stable_time_step(&body);
    int status = NSPD_OK;
    for (int s = 0; s < 3 && status == NSPD_OK; s++) status = pd_step(&body, dt); /* warm-up */
    t0 = nspd_wall_time();
    for (long s = 0; s < opt->steps && status == NSPD_OK; s++) status = pd_step(&body, dt);
    double seconds = nspd_wall_time() - t0;
    if (status == NSPD_OK) {
        size_t bytes = nspd_mem_live_bytes();
        double bond_bytes = (double)body.bond_count * PD_BYTES_PER_BOND;
        JsonWriter w;
        json_begin(&w, stdout);
        json_string(&w, "bench", "pd");
        json_int(&w, "points", body.n);
        json_int(&w, "bonds", body.bond_count); /* once from each end, as LAMMPS counts */
        json_int(&w, "steps", opt->steps);
        json_int(&w, "threads", omp_get_max_threads());
        json_number(&w, "seconds", seconds);
        json_number(&w, "bond_updates_per_s",
                    (double)body.bond_count * (double)opt->steps / seconds);
        json_number(&w, "bytes_per_bond", PD_BYTES_PER_BOND);
        json_number(&w, "bytes_per_point", ((double)bytes - bond_bytes) / (double)body.n);
        json_number(&w, "setup_s", setup_s);
        json_number(&w, "peak_rss_mb", nspd_peak_rss_mb());
        json_end(&w);
    }
    bond_body_destroy(&body);
    return status;
}

/* The correspondence solid (issue 14, paper 003): a square plane-strain
 * steel block (E 200 GPa, nu 0.29, rho 7870, J2 with sigma_Y 0.4 GPa and
 * H 0.1 GPa, ductile damage between eqps 0.18 and 0.2 evaluated on every
 * bond), delta = 2.5 h square families (24 neighbours inside), N points as
 * the nearest square, built through cpd_body_create. A homogeneous stretch
 * past yield (eps_xx 3e-3, eps_yy -1e-3, applied as one increment so the
 * bonds' hypoelastic stresses hold it) and random velocities up to 0.5 m/s
 * (so every step has a nonzero stress increment, loading and unloading),
 * then S velocity Verlet steps at 0.8 of the stable step. Bonds and bond
 * updates count each pair from both ends, as stored (and as bench pd and
 * LAMMPS count); bytes are nspd_mem_live_bytes before and after creation. */
static int bench_cpd(const BenchOptions *opt) {
    int side = (int)lround(sqrt((double)opt->points));
    if (side < 8) side = 8;
    double h = 1e-3, length = side * h;
    CpdConfig cfg = {0};
    cfg.pd.model = PD_PLANE_STRAIN;
    cfg.pd.dim = 2;
    cfg.pd.spacing = h;
    cfg.pd.thickness = h;
    cfg.pd.horizon_factor = 2.5;
    cfg.pd.density = 7870;
    cfg.pd.youngs_modulus = 200e9;
    cfg.pd.integrator = PD_VELOCITY_VERLET;
    cfg.poisson_ratio = 0.29;
    cfg.yield_stress = 0.4e9;
    cfg.hardening = 0.1e9;
    cfg.force = CPD_FORCE_BOND_ASSOCIATED;
    cfg.family = CPD_FAMILY_SQUARE;
    cfg.damage = CPD_DAMAGE_DUCTILE;
    cfg.plastic_strain_threshold = 0.18;
    cfg.plastic_strain_critical = 0.2;
    TRY(nspd_alloc(&cfg.pd.geometry.shapes, 1, sizeof(Shape)));
    cfg.pd.geometry.count = 1;
    cfg.pd.geometry.shapes[0] =
        (Shape){.kind = SHAPE_RECTANGLE, .lo = {0, 0, 0}, .hi = {length, length, 0}};

    const size_t before = nspd_mem_live_bytes();
    double t0 = nspd_wall_time();
    CpdBody body;
    TRY(cpd_body_create(&body, &cfg)); /* includes the power iteration for the stable step */
    double setup_s = nspd_wall_time() - t0;
    const double allocated = (double)(nspd_mem_live_bytes() - before);
    uint64_t r = 0x9E3779B97F4A7C15ull;
    for (int64_t i = 0; i < body.n; i++) {
        body.u[0][i] = 3e-3 * body.x[0][i];
        body.u[1][i] = -1e-3 * body.x[1][i];
        for (int d = 0; d < 2; d++) {
            r ^= r << 13, r ^= r >> 7, r ^= r << 17;
            body.v[d][i] = (double)(r >> 11) * 0x1.0p-53 - 0.5;
        }
    }
    cpd_force(&body, 0.0); /* u_prev = 0 to u: the stretch's stresses, past yield */
    body.force_valid = true;
    double dt = 0.8 * body.stable_dt;
    int status = NSPD_OK;
    for (int s = 0; s < 3 && status == NSPD_OK; s++) status = cpd_step(&body, dt); /* warm-up */
    t0 = nspd_wall_time();
    for (long s = 0; s < opt->steps && status == NSPD_OK; s++) status = cpd_step(&body, dt);
    double seconds = nspd_wall_time() - t0;
    if (status == NSPD_OK) {
        double eqps = 0.0;
        for (int64_t k = 0; k < body.bond_count; k++) eqps = fmax(eqps, body.eqps[k]);
        const double bond_bytes = (double)body.bond_count * CPD_BYTES_PER_BOND;
        JsonWriter w;
        json_begin(&w, stdout);
        json_string(&w, "bench", "cpd");
        json_int(&w, "points", body.n);
        json_int(&w, "bonds", body.bond_count); /* stored: each pair from both ends */
        json_int(&w, "bond_pairs", body.bond_count / 2);
        json_int(&w, "steps", opt->steps);
        json_int(&w, "threads", omp_get_max_threads());
        json_number(&w, "seconds", seconds);
        json_number(&w, "seconds_per_step", seconds / (double)opt->steps);
        json_number(&w, "bond_updates_per_s",
                    (double)body.bond_count * (double)opt->steps / seconds);
        json_number(&w, "bytes_per_bond", CPD_BYTES_PER_BOND); /* itemised in cpd_body.h */
        json_number(&w, "bytes_per_point", (allocated - bond_bytes) / (double)body.n);
        json_number(&w, "allocated_bytes", allocated);
        json_number(&w, "allocated_bytes_per_bond", allocated / (double)body.bond_count);
        json_number(&w, "setup_s", setup_s);
        json_number(&w, "dt", dt);
        json_number(&w, "max_plastic_strain", eqps);
        json_int(&w, "substeps_max", body.substeps_max);
        json_number(&w, "peak_rss_mb", nspd_peak_rss_mb());
        json_end(&w);
    }
    cpd_body_destroy(&body);
    return status;
}

/* The viscous 2D GKS step on an N x N periodic grid (flow_bench). */
static int bench_gks(const BenchOptions *opt) {
    FlowBenchResult r;
    TRY(flow_bench((int)opt->points, opt->threads > 0 ? opt->threads : omp_get_max_threads(),
                   (int)opt->steps, &r));
    JsonWriter w;
    json_begin(&w, stdout);
    json_string(&w, "bench", "gks");
    json_int(&w, "cells", r.cells);
    json_int(&w, "steps", r.steps);
    json_int(&w, "threads", r.threads);
    json_number(&w, "seconds", r.seconds);
    json_number(&w, "cell_updates_per_s", r.cell_updates_per_s);
    json_number(&w, "bytes_per_cell", r.bytes_per_cell);
    json_number(&w, "peak_rss_mb", nspd_peak_rss_mb());
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
    if (strcmp(argv[0], "pd") == 0) {
        status = bench_pd(&opt);
    } else if (strcmp(argv[0], "cpd") == 0) {
        status = bench_cpd(&opt);
    } else if (gks) {
        status = bench_gks(&opt);
    } else if (memory) {
        status = bench_memory(&opt);
    } else {
        fprintf(stderr, "nspd bench: unknown benchmark '%s' (expected pd, cpd, gks or memory)\n",
                argv[0]);
        return EXIT_BAD_INPUT;
    }
    if (status != NSPD_OK) fprintf(stderr, "nspd bench: %s\n", nspd_error_message());
    return exit_status_of(status);
}
