/* The bond-based solid's benchmark (`nspd bench pd`, SolidOps.bench). */
#include "solid/bond/model.h"

#include "core/mem.h"
#include "core/status.h"
#include "core/timer.h"
#include "solid/bond/integrate.h"

#include <math.h>
#include <omp.h>

/* The PD plate of paper 000 Sec. 4.2 (square lattice, delta = 3.015 dx,
 * failure test on every bond) under a small uniform strain, so that every
 * bond does the full work; N points as the nearest square. */
int bond_bench(long points, long steps, Report *out) {
    int side = (int)lround(sqrt((double)points));
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
    for (long s = 0; s < steps && status == NSPD_OK; s++) status = pd_step(&body, dt);
    double seconds = nspd_wall_time() - t0;
    if (status == NSPD_OK) {
        size_t bytes = nspd_mem_live_bytes();
        const double per_bond = bond_bytes_per_bond(&body);
        const double bond_bytes = (double)body.bond_count * per_bond;
        report_text(out, "bench", "pd");
        report_int(out, "points", body.n);
        report_int(out, "bonds", body.bond_count); /* once from each end, as LAMMPS counts */
        report_int(out, "steps", steps);
        report_int(out, "threads", omp_get_max_threads());
        report_real(out, "seconds", seconds);
        report_real(out, "bond_updates_per_s", (double)body.bond_count * (double)steps / seconds);
        report_real(out, "bytes_per_bond", per_bond);
        report_real(out, "bytes_per_point", ((double)bytes - bond_bytes) / (double)body.n);
        report_real(out, "setup_s", setup_s);
        report_real(out, "peak_rss_mb", nspd_peak_rss_mb());
        /* each thread's share of the force's chunks at the end (core/balance.h):
         * 1/threads on alike cores, less on a slower one */
        const Balance *shares = &body.force_balance;
        for (int t = 0; t < shares->threads; t++)
            report_realf(out, shares->cut[t + 1] - shares->cut[t], "force_share_%d", t);
    }
    bond_body_destroy(&body);
    return status;
}
