#include "solid/bond/model.h"

#include "core/mem.h"
#include "core/status.h"
#include "solid/bond/body.h"
#include "solid/bond/halo.h"
#include "solid/bond/stencil.h"
#include "solid/pd/lattice.h"
#include "solid/bond/diagnostics.h"
#include "solid/bond/integrate.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The model: the body and what `nspd info` reports of its start. */
typedef struct {
    BondBody body;
    double initial_stable_dt; /* s, at creation */
} BondSolid;

static int bond_create(void **impl, PdPoints *pts, SolidConfig *cfg) {
    BondSolid *bs;
    TRY(nspd_alloc(&bs, 1, sizeof *bs));
    BondBody *b = &bs->body;
    /* the body takes its own copy of the configuration */
    PdConfig pd = *(PdConfig *)cfg->model;
    nspd_free(&cfg->model); /* taken */
    /* on several processes each builds and keeps its part (halo.h) */
    int status = bond_body_create_divided(b, &pd, cfg->comm);
    if (status != NSPD_OK) {
        pd_config_free(&pd);
        nspd_free(&bs);
        return status;
    }
    bs->initial_stable_dt = pd_stable_time_step(b);
    bond_solid_points_of(b, pts);
    *impl = bs;
    return NSPD_OK;
}

void bond_solid_points_of(BondBody *b, PdPoints *pts) {
    *pts = (PdPoints){.dim = b->dim,
                      .n = b->n,
                      .spacing = b->spacing,
                      .thickness = b->dim == 2 ? b->cfg.thickness : 1.0,
                      .volume = b->volume,
                      .family_first = b->bond_first,
                      .family_nbr = b->bond_nbr};
    for (int d = 0; d < 3; d++) {
        pts->x[d] = b->x[d];
        pts->u[d] = b->u[d];
        pts->v[d] = b->v[d];
        pts->external[d] = b->external[d];
        pts->lattice[d] = b->lattice[d];
    }
}

/* Seconds per stored bond of the validating build (`nspd check`): 0.50 s
 * for the 7.0e6 of cases/plate_crack.yaml, 0.17 s for the 1.7e6 of
 * block_3d.yaml (2 threads, this machine; medians of 3), the larger rate. */
#define BOND_CHECK_S_PER_BOND 1.0e-7

/* Points: the lattice sites inside the geometry (sampled); bonds: the
 * family of an interior point, |xi| <= delta on the lattice, for every
 * point (an upper bound: surface points have fewer). Bytes: what
 * body.c allocates per point (158: positions, displacements,
 * velocities, forces, external forces, lattice indices, volume, region,
 * damage denominator, row offsets; and the lattice view's cell of x and
 * u with its maps, taking a cell a point: 41 more in 2D, 57 in 3D) and
 * per bond (9: the rows' 8 and the view's state bits and magnitude
 * blocks, 0.56 on the paper's plate, up to 4.25 on a body all surface),
 * plus the building's peak (a byte per lattice site and 16 per point
 * while ordering them, or
 * 24 per point of surface factors). */
static SolidEstimate bond_estimate(const SolidConfig *sc) {
    const PdConfig *cfg = sc->model;
    SolidEstimate e = {0};
    double sites, fraction;
    if (!lattice_estimate(&cfg->geometry, cfg->dim, cfg->spacing, &sites, &fraction)) return e;
    e.points = ceil(sites * fraction);
    const double m = cfg->horizon_factor;
    const int reach = (int)floor(m);
    double family = 0;
    for (int k = cfg->dim == 3 ? -reach : 0; k <= (cfg->dim == 3 ? reach : 0); k++)
        for (int j = -reach; j <= reach; j++)
            for (int i = -reach; i <= reach; i++)
                if ((i || j || k) && (double)(i * i + j * j + k * k) <= m * m) family += 1;
    e.bonds = e.points * family;
    const double per_point = cfg->dim == 2 ? 199.0 : 215.0, per_bond = PD_BYTES_PER_BOND + 1.0,
                 build = fmax(sites + 16.0 * e.points, 24.0 * e.points);
    e.bytes = per_point * e.points + per_bond * e.bonds + build;
    e.check_s = BOND_CHECK_S_PER_BOND * e.bonds;
    e.stable_dt = pd_interior_stable_dt(cfg);
    return e;
}

static void bond_destroy(void *impl) {
    BondSolid *bs = impl;
    bond_body_destroy(&bs->body);
    nspd_free(&bs);
}

static double bond_stable_dt(const void *impl) {
    return pd_stable_time_step(&((const BondSolid *)impl)->body);
}

static int bond_step(void *impl, double dt) {
    return pd_step(&((BondSolid *)impl)->body, dt);
}

static int bond_step_constrained(void *impl, double dt) {
    return pd_step_constrained(&((BondSolid *)impl)->body, dt);
}

static double bond_time(const void *impl) {
    return ((const BondSolid *)impl)->body.time;
}

static void bond_set_time(void *impl, double t) {
    ((BondSolid *)impl)->body.time = t;
}

static void bond_damage(const void *impl, double *out) {
    pd_damage(&((const BondSolid *)impl)->body, out);
}

static double bond_modulus(const void *impl, int64_t i) {
    (void)i; /* one material per body */
    return ((const BondSolid *)impl)->body.cfg.youngs_modulus;
}

static double bond_density(const void *impl, int64_t i) {
    const BondBody *b = &((const BondSolid *)impl)->body;
    return b->density ? b->density[i] : b->cfg.density;
}

static bool bond_attached(const void *impl, int64_t i) {
    const BondBody *b = &((const BondSolid *)impl)->body;
    for (int64_t k = b->bond_first[i]; k < b->bond_first[i + 1]; k++)
        if (b->bond_coef[k] != 0.0f) return true; /* 0: broken (body.h) */
    return false;
}

/* One per-point array (`size`-byte elements) or the bonds' coefficients
 * as the whole body's: on several processes the runs of the ranks are
 * gathered in rank order (the whole body's order: halo.h), and on
 * reading each rank cuts out its run, and its ghosts' values. So a
 * checkpoint is the same on any number of processes and any other reads
 * it. */
static int io_whole(BondBody *b, Checkpoint *ck, const char *name, void *mine, size_t size,
                    bool bonds) {
    const BondHalo *h = b->halo;
    if (!h) return checkpoint_io(ck, name, mine, (size_t)(bonds ? b->bond_count : b->n) * size);
    const PointHalo *p = &h->points;
    if (bonds)
        return halo_checkpoint_io(&p->comm, h->bond_first, b->bond_count, h->bonds, NULL, 0, ck,
                                  name, mine, size);
    return halo_checkpoint_io(&p->comm, p->first, b->n, p->total, p->ghost, b->ghosts, ck, name,
                              mine, size);
}

/* The state a step changes: displacements, velocities, forces (velocity
 * Verlet reuses the last one), the external loads a coupling holds over
 * the sub-steps, the bonds (0: broken), the clock and step count. */
static int bond_checkpoint(void *impl, Checkpoint *ck) {
    BondBody *b = &((BondSolid *)impl)->body;
    static const char *const NAMES[4][3] = {{"bond.u0", "bond.u1", "bond.u2"},
                                            {"bond.v0", "bond.v1", "bond.v2"},
                                            {"bond.force0", "bond.force1", "bond.force2"},
                                            {"bond.external0", "bond.external1", "bond.external2"}};
    for (int d = 0; d < b->dim && d < 3; d++) { /* dim is 2 or 3 */
        TRY(io_whole(b, ck, NAMES[0][d], b->u[d], sizeof(double), false));
        TRY(io_whole(b, ck, NAMES[1][d], b->v[d], sizeof(double), false));
        TRY(io_whole(b, ck, NAMES[2][d], b->force[d], sizeof(double), false));
        TRY(io_whole(b, ck, NAMES[3][d], b->external[d], sizeof(double), false));
    }
    TRY(io_whole(b, ck, "bond.coef", b->bond_coef, sizeof(float), true));
    if (b->stencil && checkpoint_reading(ck)) TRY(bond_stencil_take(b->stencil, b));
    TRY(checkpoint_io_int64(ck, "bond.step", &b->step));
    TRY(checkpoint_io_double(ck, "bond.time", &b->time));
    int valid = b->force_valid;
    TRY(checkpoint_io_int(ck, "bond.force_valid", &valid));
    b->force_valid = valid != 0;
    return NSPD_OK;
}

/* The whole body's points and stored bonds (this process's on one). */
static int64_t whole_points(const BondBody *b) {
    return b->halo ? b->halo->points.total : b->n;
}

static int64_t whole_bonds(const BondBody *b) {
    return b->halo ? b->halo->bonds : b->bond_count;
}

/* Several materials: each one's kinetic energy and mean velocity, named
 * after it (history columns and summary keys). */
static void report_materials(const BondBody *b, Report *r) {
    if (!b->material) return;
    for (int k = 0; k < b->cfg.material_count; k++) {
        const char *name = b->cfg.materials[k].name;
        double mass, ke, v[3];
        pd_material_totals(b, k, &mass, &ke, v);
        report_realf(r, ke, "%s_kinetic_energy_J", name);
        for (int d = 0; d < b->dim; d++)
            report_realf(r, v[d], "%s_velocity_%c_m_per_s", name, "xyz"[d]);
    }
}

static void bond_history(const void *impl, Report *row) {
    const BondBody *b = &((const BondSolid *)impl)->body;
    double ke = pd_kinetic_energy(b), we = pd_elastic_energy(b);
    report_real(row, "kinetic_energy_J", ke);
    report_real(row, "elastic_energy_J", we);
    if (b->has_contact) { /* the columns only where there is contact: other cases' unchanged */
        const double wc = pd_contact_energy(&b->contact, (const double *const *)b->x,
                                            (const double *const *)b->u, b->volume);
        report_real(row, "contact_energy_J", wc);
        report_real(row, "total_energy_J", ke + we + wc);
        report_real(row, "contact_min_distance_m",
                    pd_contact_min_distance(&b->contact, (const double *const *)b->x,
                                            (const double *const *)b->u, b->horizon));
    } else {
        report_real(row, "total_energy_J", ke + we);
    }
    report_int(row, "broken_bonds", pd_broken_bonds(b));
    report_materials(b, row);
}

static void bond_summary(const void *impl, const RunStats *run, Report *out) {
    const BondBody *b = &((const BondSolid *)impl)->body;
    const int64_t points = whole_points(b), bonds = whole_bonds(b);
    report_int(out, "points", points);
    report_int(out, "bonds", bonds / 2);
    const int64_t broken = pd_broken_bonds(b);
    report_int(out, "broken_bonds", broken);
    report_real(out, "broken_bond_fraction", bonds ? 2.0 * (double)broken / (double)bonds : 0.0);
    double max_damage = 0.0, *damage;
    if (nspd_alloc(&damage, (size_t)b->n, sizeof(double)) == NSPD_OK) { /* once, at the end */
        pd_damage(b, damage);
        for (int64_t i = 0; i < b->n; i++) max_damage = fmax(max_damage, damage[i]);
        nspd_free(&damage);
        if (b->halo) max_damage = comm_max(&b->halo->points.comm, max_damage); /* exact */
    } else {
        max_damage = (double)NAN;
    }
    report_real(out, "max_damage", max_damage);
    report_real(out, "kinetic_energy_J", pd_kinetic_energy(b));
    report_real(out, "elastic_energy_J", pd_elastic_energy(b));
    report_materials(b, out);
    if (b->has_contact) report_int(out, "contact_list_builds", b->contact.builds);
    report_real(out, "bond_updates_per_s",
                run->wall_s > 0 ? (double)bonds * (double)run->steps / run->wall_s : 0.0);
    /* several processes: this one's wall time in the ghosts' exchanges
     * and the step's reductions */
    if (b->halo) report_real(out, "solid_exchange_s", b->halo->points.seconds);
}

static void bond_info(const void *impl, size_t memory, char *buf, size_t size) {
    const BondBody *b = &((const BondSolid *)impl)->body;
    int len = 0;
#define APPEND(...)                                                                                \
    len += snprintf(buf + len, size > (size_t)len ? size - (size_t)len : 0, __VA_ARGS__)
    APPEND("model                %s, %dD\n", PD_MODEL_NAMES[b->cfg.model], b->dim);
    APPEND("points               %lld\n", (long long)whole_points(b));
    APPEND("bonds                %lld (%.1f per point; %lld broken at start)\n",
           (long long)whole_bonds(b) / 2, (double)whole_bonds(b) / (double)whole_points(b),
           (long long)pd_broken_bonds(b));
    APPEND("spacing              %.6g m\n", b->spacing);
    APPEND("horizon              %.6g m (%.4g x spacing)\n", b->horizon, b->cfg.horizon_factor);
    APPEND("micromodulus         %.6g\n", b->micromodulus);
    if (b->cfg.failure)
        APPEND("critical stretch     %.6g\n", b->cfg.critical_stretch);
    else
        APPEND("critical stretch     (failure off)\n");
    APPEND("bar wave speed       %.6g m/s (Rayleigh %.6g m/s)\n", pd_bar_wave_speed(&b->cfg),
           pd_rayleigh_wave_speed(&b->cfg));
    APPEND("stable time step     %.6g s\n", ((const BondSolid *)impl)->initial_stable_dt);
    const double per_bond = bond_bytes_per_bond(b);
    APPEND("memory               %.1f MB in solver arrays (%.1f bytes per bond + %.0f per point)\n",
           (double)memory / 1e6, per_bond,
           ((double)memory - (double)b->bond_count * per_bond) / (double)b->n);
#undef APPEND
}

static void bond_brief(const void *impl, char *buf, size_t size) {
    const BondBody *b = &((const BondSolid *)impl)->body;
    snprintf(buf, size, "%lld points, %lld bonds, ", (long long)whole_points(b),
             (long long)whole_bonds(b) / 2);
}

static void bond_config_free(void *model) {
    pd_config_free(model);
}

static int bond_config_dim(const void *model) {
    return ((const PdConfig *)model)->dim;
}

const SolidOps BOND_SOLID_OPS = {
    .name = "bond",
    .distributed = true,
    .config_free = bond_config_free,
    .config_dim = bond_config_dim,
    .estimate = bond_estimate,
    .create = bond_create,
    .destroy = bond_destroy,
    .stable_dt = bond_stable_dt,
    .step = bond_step,
    .step_constrained = bond_step_constrained,
    .time = bond_time,
    .set_time = bond_set_time,
    .damage = bond_damage,
    .modulus = bond_modulus,
    .density = bond_density,
    .attached = bond_attached,
    .history = bond_history,
    .summary = bond_summary,
    .info = bond_info,
    .brief = bond_brief,
    .fields = NULL,
    .checkpoint = bond_checkpoint,
    .bench_name = "pd",
    .bench = bond_bench,
};

BondBody *bond_solid_body(Solid *s) {
    BondSolid *bs = solid_impl(s, SOLID_BOND);
    return bs ? &bs->body : NULL;
}
