/* The flow benchmark (gks_bench in solver.h; `nspd bench gks`). */
#include "flow/gks/solver.h"

#include "core/mem.h"
#include "flow/gks/model.h"
#include "core/status.h"
#include "core/timer.h"
#include "flow/gks/solver_internal.h"

#include <math.h>
#include <omp.h>
#include <string.h>

int gks_bench(int cells, int threads, int steps, const NspdComm *comm, GksBenchResult *out) {
    memset(out, 0, sizeof *out);
    if (cells < 16 || threads < 1 || steps < 1)
        return NSPD_FAIL(NSPD_ERR_INPUT, "gks_bench: cells >= 16, threads >= 1, steps >= 1");
    const int n = (int)lround(sqrt((double)cells));
    const int saved = omp_get_max_threads();
    omp_set_num_threads(threads);
    GksConfig c;
    gks_config_default(&c);
    gks_config_uniform_grid(&c, 0.0, 1.0, n, 0.0, 1.0, n);
    FlowBc per = {.kind = BC_PERIODIC};
    for (int f = 0; f < 4; f++) gks_config_set_bc(&c, f, &per);
    c.viscosity = VISCOSITY_SUTHERLAND;
    c.mu_ref = 1.716e-5 * 1000.0; /* Re = rho U L / mu ~ 1e3 on the unit box */
    c.T_ref = 273.15;
    c.sutherland_S = 110.4;
    c.init_fn = NULL;
    c.initial = (FlowPrim){1.2, 0.0, 0.0, 1.0e5};
    c.comm = comm;
    /* slabs of rows, the layout docs/PERFORMANCE.md's figures measured */
    c.processes[0] = 1;
    c.processes[1] = comm ? comm->size : 1;
    GksSolver *s = NULL;
    int st = gks_solver_create(&s, &c);
    if (st < 0) {
        omp_set_num_threads(saved);
        return st;
    }
    /* Taylor-Green vortices at Mach 0.3 */
    const Grid *g = gks_solver_grid(s);
    GksFields f = gks_solver_fields(s);
    const double c0 = sqrt(1.4 * 1.0e5 / 1.2), U = 0.3 * c0;
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) {
            const double x = 2.0 * M_PI * g->ax[0].center[i], y = 2.0 * M_PI * g->ax[1].center[j];
            FlowPrim q = {1.2, U * sin(x) * cos(y), -U * cos(x) * sin(y),
                          1.0e5 + 0.25 * 1.2 * U * U * (cos(2 * x) + cos(2 * y))};
            double w[4];
            flow_prim_to_cons(&q, 1.4, w);
            const int64_t k = grid_index(g, i, j);
            for (int v = 0; v < 4; v++) f.w[v][k] = w[v];
        }
    st = gks_solver_step(s, gks_solver_stable_dt(s));
    const double comm0 = gks_solver_comm_seconds(s);
    const double t0 = nspd_wall_time();
    for (int k = 0; k < steps && st == NSPD_OK; k++)
        st = gks_solver_step(s, gks_solver_stable_dt(s));
    const double secs = comm_max(comm, nspd_wall_time() - t0);
    out->comm_seconds = comm_max(comm, gks_solver_comm_seconds(s) - comm0);
    out->cells = (int64_t)n * n;
    out->steps = steps;
    out->threads = threads;
    out->seconds = secs;
    out->cell_updates_per_s = secs > 0.0 ? (double)out->cells * steps / secs : 0.0;
    out->bytes_per_cell = (double)s->bytes / (double)out->cells;
    gks_solver_destroy(&s);
    omp_set_num_threads(saved);
    return st;
}

/* The viscous 2D GKS step on an N x N periodic grid. */
int gks_bench_report(long cells, long steps, Report *out) {
    GksBenchResult r;
    TRY(gks_bench((int)cells, omp_get_max_threads(), (int)steps, NULL, &r));
    report_text(out, "bench", "gks");
    report_int(out, "cells", r.cells);
    report_int(out, "steps", r.steps);
    report_int(out, "threads", r.threads);
    report_real(out, "seconds", r.seconds);
    report_real(out, "cell_updates_per_s", r.cell_updates_per_s);
    report_real(out, "bytes_per_cell", r.bytes_per_cell);
    report_real(out, "peak_rss_mb", nspd_peak_rss_mb());
    return NSPD_OK;
}
