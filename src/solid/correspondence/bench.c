/* The correspondence solid's benchmark (`nspd bench cpd`, SolidOps.bench). */
#include "solid/correspondence/model.h"

#include "core/mem.h"
#include "core/status.h"
#include "core/timer.h"

#include <math.h>
#include <omp.h>
#include <stdint.h>

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
int cpd_bench(long points, long steps, Report *out) {
    int side = (int)lround(sqrt((double)points));
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
    for (long s = 0; s < steps && status == NSPD_OK; s++) status = cpd_step(&body, dt);
    double seconds = nspd_wall_time() - t0;
    if (status == NSPD_OK) {
        double eqps = 0.0;
        for (int64_t p = 0; p < body.pairs.count; p++) eqps = fmax(eqps, body.eqps[p]);
        const double bond_bytes = (double)body.bond_count * CPD_BYTES_PER_BOND;
        report_text(out, "bench", "cpd");
        report_int(out, "points", body.n);
        report_int(out, "bonds", body.bond_count); /* stored: each pair from both ends */
        report_int(out, "bond_pairs", body.bond_count / 2);
        report_int(out, "steps", steps);
        report_int(out, "threads", omp_get_max_threads());
        report_real(out, "seconds", seconds);
        report_real(out, "seconds_per_step", seconds / (double)steps);
        report_real(out, "bond_updates_per_s", (double)body.bond_count * (double)steps / seconds);
        report_real(out, "bytes_per_bond", CPD_BYTES_PER_BOND); /* itemised in body.h */
        report_real(out, "bytes_per_point", (allocated - bond_bytes) / (double)body.n);
        report_real(out, "allocated_bytes", allocated);
        report_real(out, "allocated_bytes_per_bond", allocated / (double)body.bond_count);
        report_real(out, "setup_s", setup_s);
        report_real(out, "dt", dt);
        report_real(out, "max_plastic_strain", eqps);
        report_int(out, "substeps_max", body.substeps_max);
        report_real(out, "peak_rss_mb", nspd_peak_rss_mb());
    }
    cpd_body_destroy(&body);
    return status;
}
