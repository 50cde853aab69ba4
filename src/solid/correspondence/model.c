#include "solid/correspondence/model.h"

#include "core/mem.h"
#include "core/status.h"
#include "solid/correspondence/halo.h"
#include "solid/pd/lattice.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The model: the body, and the per-point fields it reports (scratch; on
 * several processes the whole body's, gathered). */
typedef struct {
    CpdBody body;
    double *stress[3]; /* xx, yy, xy of the point's Cauchy stress, Pa */
    double *stress_zz; /* Pa */
    double *mises;     /* von Mises stress, Pa */
    double *plastic;   /* mean equivalent plastic strain of its intact bonds (classic: its own) */
    double *jacobian;  /* det F_i */
    double *broken;    /* volume-weighted fraction of the point's bonds broken */
} CpdSolid;

static int cpd_create(void **impl, PdPoints *pts, SolidConfig *cfg) {
    CpdSolid *cs;
    TRY(nspd_alloc(&cs, 1, sizeof *cs));
    CpdBody *b = &cs->body;
    CpdConfig cc = *(CpdConfig *)cfg->model;
    nspd_free(&cfg->model); /* taken */
    /* on several processes each builds and keeps its part (halo.h) */
    const NspdComm self = comm_self();
    int status = cpd_body_create_divided(b, &cc, cfg->comm ? cfg->comm : &self);
    const size_t n = status == NSPD_OK ? (size_t)cpd_whole_points(b) : 1;
    for (int d = 0; d < 3 && status == NSPD_OK; d++) status = nspd_alloc(&cs->stress[d], n, 8);
    if (status == NSPD_OK) status = nspd_alloc(&cs->stress_zz, n, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&cs->mises, n, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&cs->plastic, n, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&cs->jacobian, n, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&cs->broken, n, sizeof(double));
    if (status != NSPD_OK) {
        cpd_config_free(&cc);
        CpdSolid *p = cs;
        cpd_body_destroy(&p->body);
        for (int d = 0; d < 3; d++) nspd_free(&p->stress[d]);
        nspd_free(&p->stress_zz);
        nspd_free(&p->mises);
        nspd_free(&p->plastic);
        nspd_free(&p->jacobian);
        nspd_free(&p->broken);
        nspd_free(&cs);
        return status;
    }
    *pts = (PdPoints){.dim = b->dim,
                      .n = b->n,
                      .spacing = b->spacing,
                      .thickness = b->dim == 2 ? b->cfg.pd.thickness : 1.0,
                      .volume = b->volume,
                      .family_first = b->first,
                      .family_nbr = b->nbr};
    for (int d = 0; d < 3; d++) {
        pts->x[d] = b->x[d];
        pts->u[d] = b->u[d];
        pts->v[d] = b->v[d];
        pts->external[d] = b->external[d];
        pts->lattice[d] = b->lattice[d];
    }
    *impl = cs;
    return NSPD_OK;
}

static void cpd_destroy(void *impl) {
    CpdSolid *cs = impl;
    cpd_body_destroy(&cs->body);
    for (int d = 0; d < 3; d++) nspd_free(&cs->stress[d]);
    nspd_free(&cs->stress_zz);
    nspd_free(&cs->mises);
    nspd_free(&cs->plastic);
    nspd_free(&cs->jacobian);
    nspd_free(&cs->broken);
    nspd_free(&cs);
}

/* Seconds per stored bond of the validating build (`nspd check`), the
 * stable step's 30 power iterations most of it: 0.42 s for the 85,872 of
 * cases/hollow_square_pressure.yaml (2 threads, this machine; median of 3). */
#define CPD_CHECK_S_PER_BOND 5.0e-6

/* Points as the bond-based model counts them; bonds: the square (or disc)
 * family of an interior point; bytes: per point 27 work doubles (2D: F, F
 * at u_prev, 1 / w0, S and the direct force), phi_sum, 6 motion arrays,
 * volume, region, load, flags, lattice and 8 field arrays (about 530 B),
 * per bond CPD_BYTES_PER_BOND (classic: CPD_CLASSIC_BYTES_PER_BOND,
 * and CPD_CLASSIC_BYTES_PER_POINT more per point for the point state); the
 * search's disc of sqrt(2) delta before the square filter. */
static SolidEstimate cpd_estimate(const SolidConfig *sc) {
    const CpdConfig *cfg = sc->model;
    const PdConfig *pd = &cfg->pd;
    SolidEstimate e = {0};
    double sites, fraction;
    if (pd->lattice_kind == PD_LATTICE_POLAR) /* all its elements: the geometry only filters */
        e.points = (double)pd->polar.rings * (double)pd->polar.sectors;
    else if (pd->lattice_kind == PD_LATTICE_ABAQUS) /* the same: all the mesh's elements */
        e.points = (double)pd->mesh.n;
    else if (!lattice_estimate(&pd->geometry, pd->dim, pd->spacing, &sites, &fraction))
        return e;
    else
        e.points = ceil(sites * fraction);
    const double m = pd->horizon_factor;
    const int reach = (int)floor(m * sqrt((double)pd->dim));
    double family = 0, searched = 0;
    for (int k = pd->dim == 3 ? -reach : 0; k <= (pd->dim == 3 ? reach : 0); k++)
        for (int j = -reach; j <= reach; j++)
            for (int i = -reach; i <= reach; i++) {
                if (!(i || j || k)) continue;
                const double r2 = (double)(i * i + j * j + k * k);
                if (r2 <= m * m * (double)pd->dim) searched += 1;
                const bool in = cfg->family == CPD_FAMILY_SQUARE
                                    ? (abs(i) <= m && abs(j) <= m && abs(k) <= m)
                                    : r2 <= m * m;
                if (in) family += 1;
            }
    e.bonds = e.points * family;
    const bool classic = cfg->force == CPD_FORCE_CLASSIC;
    /* plane stress adds the thickness strain, 8 B per state (pair or
     * point), and the bond-associated force's flag, 8 B per pair */
    const bool plane_stress = pd->model == PD_PLANE_STRESS;
    const double zz = plane_stress ? 8.0 : 0.0, pair_zz = plane_stress ? 16.0 : 0.0;
    const double per_point = 530.0 + (classic ? CPD_CLASSIC_BYTES_PER_POINT + zz : 0);
    const double per_bond = classic ? CPD_CLASSIC_BYTES_PER_BOND : CPD_BYTES_PER_BOND + pair_zz / 2;
    e.bytes = per_point * e.points + per_bond * e.bonds + 4.0 * searched * e.points;
    /* the step comes from a power iteration on the built body: not known */
    e.check_s = CPD_CHECK_S_PER_BOND * e.bonds;
    return e;
}

static double cpd_stable(const void *impl) {
    return ((const CpdSolid *)impl)->body.stable_dt;
}

static int cpd_step_op(void *impl, double dt) {
    return cpd_step(&((CpdSolid *)impl)->body, dt);
}

static int cpd_step_constrained_op(void *impl, double dt) {
    return cpd_step_constrained(&((CpdSolid *)impl)->body, dt);
}

static double cpd_time(const void *impl) {
    return ((const CpdSolid *)impl)->body.time;
}

static void cpd_set_time(void *impl, double t) {
    ((CpdSolid *)impl)->body.time = t;
}

static void cpd_damage(const void *impl, double *out) {
    cpd_point_damage(&((const CpdSolid *)impl)->body, out, NULL);
}

static double cpd_modulus(const void *impl, int64_t i) {
    (void)i; /* one material per body */
    return ((const CpdSolid *)impl)->body.cfg.pd.youngs_modulus;
}

static double cpd_density(const void *impl, int64_t i) {
    (void)i;
    return ((const CpdSolid *)impl)->body.cfg.pd.density;
}

static bool cpd_attached(const void *impl, int64_t i) {
    const CpdBody *b = &((const CpdSolid *)impl)->body;
    for (int64_t k = b->first[i]; k < b->first[i + 1]; k++)
        if (b->damage[k] < 1.0) return true;
    return false;
}

/* output only: summed in sequence over the whole body's points, so the
 * same at any thread or process count (the run's terms gathered) */
static double kinetic_energy(const CpdBody *b) {
    double *term = NULL, *all = NULL, e = 0.0;
    if (nspd_alloc(&term, (size_t)b->n + 1, sizeof *term) != NSPD_OK) return (double)NAN;
    for (int64_t i = 0; i < b->n; i++) {
        double v2 = 0.0;
        for (int d = 0; d < b->dim; d++) v2 += b->v[d][i] * b->v[d][i];
        term[i] = 0.5 * b->cfg.pd.density * b->volume[i] * v2;
    }
    all = cpd_halo_whole(b, term, 1);
    const int64_t n = cpd_whole_points(b);
    for (int64_t i = 0; all && i < n; i++) e += all[i];
    if (!all) e = (double)NAN;
    nspd_free(&term);
    nspd_free(&all);
    return e;
}

/* each pair broken counts from both its ends, wherever they are */
static int64_t broken_pairs(const CpdBody *b) {
    int64_t k = 0;
    for (int64_t q = 0; q < b->bond_count; q++) k += b->damage[q] >= 1.0 ? 1 : 0;
    return cpd_halo_sum(b, k) / 2;
}

static double max_of(const double *a, int64_t n) {
    double m = 0.0;
    for (int64_t i = 0; i < n; i++) m = fmax(m, a[i]);
    return m;
}

/* The volume fraction of the points whose damage (of the run's points)
 * lies in [lo, hi), summed in the whole body's order. */
static double damaged_fraction(const CpdBody *b, const double *damage, double lo, double hi) {
    double *d = cpd_halo_whole(b, damage, 1), *volume = cpd_halo_whole(b, b->volume, 1);
    double in = 0.0, all = 0.0;
    const int64_t n = d && volume ? cpd_whole_points(b) : 0;
    for (int64_t i = 0; i < n; i++) {
        all += volume[i];
        in += d[i] >= lo && d[i] < hi ? volume[i] : 0.0;
    }
    nspd_free(&d);
    nspd_free(&volume);
    return all > 0.0 ? in / all : 0.0;
}

double cpd_mass_loss(const CpdBody *b, const double *damage) {
    return damaged_fraction(b, damage, 0.99, (double)INFINITY);
}

double cpd_partly_damaged(const CpdBody *b, const double *damage) {
    return damaged_fraction(b, damage, nextafter(0.0, 1.0), 0.99);
}

/* The points whose damage is at least Eq. 24's 0.99 (what the mass loss
 * weighs): paper 003 Fig. 8's count of fully damaged nodes. Each rank
 * counts its own points; an integer sum over the ranks is exact. */
int64_t cpd_fully_damaged(const CpdBody *b, const double *damage) {
    int64_t k = 0;
    for (int64_t i = 0; i < b->n; i++) k += damage[i] >= 0.99 ? 1 : 0;
    return cpd_halo_sum(b, k);
}

static int64_t root_of(int64_t *parent, int64_t i) {
    while (parent[i] != i) {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

/* Over the whole body's rows of intact bonds (cpd_halo_intact_rows: the
 * ranks' rows gathered, neighbours by whole index). */
int64_t cpd_fragment_count(const CpdBody *b, int64_t *debris) {
    int64_t *parent = NULL, *first = NULL, *nbr = NULL;
    const int64_t n = cpd_whole_points(b);
    if (cpd_halo_intact_rows(b, &first, &nbr) != NSPD_OK ||
        nspd_alloc(&parent, (size_t)n + 1, sizeof(int64_t)) != NSPD_OK) {
        nspd_free(&first);
        nspd_free(&nbr);
        return -1;
    }
    for (int64_t i = 0; i < n; i++) parent[i] = i;
    int64_t loose = 0;
    for (int64_t i = 0; i < n; i++) {
        for (int64_t k = first[i]; k < first[i + 1]; k++) {
            const int64_t ri = root_of(parent, i), rj = root_of(parent, nbr[k]);
            if (ri != rj) parent[ri < rj ? rj : ri] = ri < rj ? ri : rj;
        }
        loose += first[i + 1] > first[i] ? 0 : 1;
    }
    int64_t roots = 0;
    for (int64_t i = 0; i < n; i++) roots += root_of(parent, i) == i ? 1 : 0;
    nspd_free(&parent);
    nspd_free(&first);
    nspd_free(&nbr);
    if (debris) *debris = loose;
    return roots - loose; /* a loose point is its own root */
}

/* max plastic strain over bonds, and mass loss from the mean damage */
static void state_numbers(const CpdSolid *cs, double *max_eqps, double *mass_loss,
                          double *max_damage, double *partly, int64_t *fully) {
    const CpdBody *b = &cs->body;
    double m = 0.0; /* over intact bonds: a broken bond's state stops at its break */
    if (b->cfg.force == CPD_FORCE_CLASSIC) /* per point: over the points not debris */
        for (int64_t i = 0; i < b->n; i++) m = b->ok[i] ? fmax(m, b->eqps[i]) : m;
    else
        for (int64_t k = 0; k < b->bond_count; k++)
            if (b->damage[k] < 1.0) m = fmax(m, b->eqps[b->pairs.of[k]]);
    *max_eqps = cpd_halo_max(b, m);        /* exact */
    cpd_point_damage(b, cs->broken, NULL); /* the scratch holds the mean damage here */
    *mass_loss = cpd_mass_loss(b, cs->broken);
    *partly = cpd_partly_damaged(b, cs->broken);
    *fully = cpd_fully_damaged(b, cs->broken);
    *max_damage = cpd_halo_max(b, max_of(cs->broken, b->n));
}

static void cpd_history(const void *impl, Report *row) {
    const CpdSolid *cs = impl;
    const CpdBody *b = &cs->body;
    double eqps, loss, dmax, partly;
    int64_t fully;
    state_numbers(cs, &eqps, &loss, &dmax, &partly, &fully);
    report_real(row, "kinetic_energy_J", kinetic_energy(b));
    if (b->has_contact) { /* the columns only where there is contact: other cases' unchanged */
        report_real(row, "contact_energy_J",
                    pd_contact_energy(&b->contact, (const double *const *)b->x,
                                      (const double *const *)b->u, b->volume));
        report_real(row, "contact_min_distance_m",
                    pd_contact_min_distance(&b->contact, (const double *const *)b->x,
                                            (const double *const *)b->u, b->delta));
    }
    report_int(row, "broken_bonds", broken_pairs(b));
    report_real(row, "max_plastic_strain", eqps);
    report_real(row, "max_damage", dmax);
    report_real(row, "mass_loss", loss);
    report_int(row, "fully_damaged_points", fully);
}

static void cpd_summary(const void *impl, const RunStats *run, Report *out) {
    const CpdSolid *cs = impl;
    const CpdBody *b = &cs->body;
    double eqps, loss, dmax, partly;
    int64_t fully;
    state_numbers(cs, &eqps, &loss, &dmax, &partly, &fully);
    const int64_t bonds = cpd_whole_bonds(b);
    report_int(out, "points", cpd_whole_points(b));
    report_int(out, "bonds", bonds / 2);
    const int64_t broken = broken_pairs(b);
    report_int(out, "broken_bonds", broken);
    report_real(out, "broken_bond_fraction", bonds ? 2.0 * (double)broken / (double)bonds : 0.0);
    report_real(out, "max_damage", dmax);
    report_real(out, "max_plastic_strain", eqps);
    report_real(out, "mass_loss", loss);
    report_int(out, "fully_damaged_points", fully);
    report_real(out, "partly_damaged_fraction", partly);
    int64_t debris = 0;
    report_int(out, "fragment_count", cpd_fragment_count(b, &debris));
    report_int(out, "debris_points", debris);
    report_real(out, "kinetic_energy_J", kinetic_energy(b));
    report_real(out, "stable_dt_damaged_s", b->stable_now);
    report_int(out, "substeps_max", b->substeps_max);
    report_real(out, "bond_updates_per_s",
                run->wall_s > 0 ? (double)bonds * (double)run->steps / run->wall_s : 0.0);
    /* several processes: this one's wall time in the ghosts' exchanges */
    if (b->halo)
        report_real(out, "solid_exchange_s", b->halo->points.seconds + b->halo->bonds.seconds);
}

static void cpd_info(const void *impl, size_t memory, char *buf, size_t size) {
    const CpdBody *b = &((const CpdSolid *)impl)->body;
    const CpdConfig *c = &b->cfg;
    int len = 0;
#define APPEND(...)                                                                                \
    len += snprintf(buf + len, size > (size_t)len ? size - (size_t)len : 0, __VA_ARGS__)
    APPEND("model                correspondence (%s), %s\n", CPD_FORCE_NAMES[c->force],
           PD_MODEL_NAMES[c->pd.model]);
    if (c->force == CPD_FORCE_CLASSIC)
        APPEND("stabilisation        C_s %.4g (Silling 2017 zero-energy penalty)\n",
               c->stabilisation);
    const int64_t points = cpd_whole_points(b), bonds = cpd_whole_bonds(b);
    APPEND("points               %lld\n", (long long)points);
    APPEND("bonds                %lld (%.1f per point, %s family)\n", (long long)bonds / 2,
           (double)bonds / (double)points, CPD_FAMILY_NAMES[c->family]);
    if (c->pd.lattice_kind == PD_LATTICE_POLAR)
        APPEND("lattice              polar: %d rings x %d sectors about (%.6g, %.6g) m, r %.6g "
               "to %.6g m\n",
               (int)c->pd.polar.rings, (int)c->pd.polar.sectors, c->pd.polar.center[0],
               c->pd.polar.center[1], c->pd.polar.inner_radius, c->pd.polar.outer_radius);
    APPEND("spacing              %.6g m%s\n", b->spacing,
           c->pd.lattice_kind == PD_LATTICE_POLAR ? " (radial)" : "");
    APPEND("horizon              %.6g m (%.4g x spacing)\n", b->delta, c->pd.horizon_factor);
    APPEND("material             E %.6g Pa, nu %.4g, yield %.6g Pa, hardening %.6g Pa\n",
           c->pd.youngs_modulus, c->poisson_ratio, c->yield_stress, c->hardening);
    APPEND("damage               %s\n", CPD_DAMAGE_NAMES[c->damage]);
    APPEND("P-wave speed         %.6g m/s\n", sqrt((b->lambda + 2.0 * b->mu) / c->pd.density));
    APPEND("stable time step     %.6g s (power iteration; re-estimated as damage grows, "
           "with sub-steps)\n",
           b->stable_dt);
    APPEND("memory               %.1f MB in solver arrays (%d bytes per bond)\n",
           (double)memory / 1e6,
           c->force == CPD_FORCE_CLASSIC ? CPD_CLASSIC_BYTES_PER_BOND : CPD_BYTES_PER_BOND);
#undef APPEND
}

static void cpd_brief(const void *impl, char *buf, size_t size) {
    const CpdBody *b = &((const CpdSolid *)impl)->body;
    snprintf(buf, size, "%lld points, %lld bonds, ", (long long)cpd_whole_points(b),
             (long long)cpd_whole_bonds(b) / 2);
}

/* Per point: the omega-weighted mean of its intact bonds' unrotated stress
 * and plastic strain (classic: the point's own), the stress rotated by the
 * point's own F_i (closed form), its von Mises value and J = det F_i (from
 * the last force pass). */
static void cpd_fields(const void *impl, FieldSet *out) {
    const CpdSolid *cs = impl;
    const CpdBody *b = &cs->body;
    const double *F = b->work_point;
#pragma omp parallel for schedule(static) if (b->n >= 4096)
    for (int64_t i = 0; i < b->n; i++) {
        double w = 0.0, s[4] = {0, 0, 0, 0}, ep = 0.0;
        if (b->cfg.force == CPD_FORCE_CLASSIC) {
            w = 1.0, ep = b->eqps[i];
            memcpy(s, b->sigma + 4 * i, sizeof s);
        }
        for (int64_t k = b->first[i]; k < b->first[i + 1] && b->cfg.force != CPD_FORCE_CLASSIC;
             k++) {
            const double wk = b->omega[k] * b->scale[k];
            w += wk;
            const int64_t p = b->pairs.of[k]; /* the state is per pair, by component */
            for (int q = 0; q < 4; q++) s[q] += wk * b->sigma[q * b->pairs.count + p];
            ep += wk * b->eqps[p];
        }
        const double inv = w > 0.0 ? 1.0 / w : 0.0;
        for (int q = 0; q < 4; q++) s[q] *= inv;
        const double *Fi = F + 9 * i;
        double R[4] = {1, 0, 0, 1};
        const double Fi2[4] = {Fi[0], Fi[1], Fi[3], Fi[4]};
        if (b->force_valid) j2_polar_rotation_2d(Fi2, R);
        /* sigma = R s R^T for the in-plane part [xx xy; xy yy] */
        const double a = s[0], d = s[1], c = s[3];
        const double r00 = R[0], r01 = R[1], r10 = R[2], r11 = R[3];
        const double t00 = r00 * a + r01 * c, t01 = r00 * c + r01 * d;
        const double t10 = r10 * a + r11 * c, t11 = r10 * c + r11 * d;
        const double sxx = t00 * r00 + t01 * r01, sxy = t00 * r10 + t01 * r11;
        const double syy = t10 * r10 + t11 * r11;
        cs->stress[0][i] = sxx;
        cs->stress[1][i] = syy;
        cs->stress[2][i] = sxy;
        cs->stress_zz[i] = s[2];
        const double p = (sxx + syy + s[2]) / 3.0;
        const double dx = sxx - p, dy = syy - p, dz = s[2] - p;
        cs->mises[i] = sqrt(1.5 * (dx * dx + dy * dy + dz * dz + 2.0 * sxy * sxy));
        cs->plastic[i] = ep * inv;
        cs->jacobian[i] = b->force_valid ? Fi[0] * Fi[4] - Fi[1] * Fi[3] : 1.0;
    }
    cpd_point_damage(b, NULL, cs->broken);
    if (b->halo) { /* the whole body's (solid.c writes each rank's piece of them) */
        double *const field[8] = {cs->stress[0], cs->stress[1], cs->stress[2], cs->stress_zz,
                                  cs->mises,     cs->plastic,   cs->jacobian,  cs->broken};
        for (int f = 0; f < 8; f++) {
            double *all = cpd_halo_whole(b, field[f], 1);
            if (all) memcpy(field[f], all, (size_t)cpd_whole_points(b) * sizeof(double));
            nspd_free(&all);
        }
    }
    out->field[out->field_count++] =
        (FieldRef){"stress", 3, {cs->stress[0], cs->stress[1], cs->stress[2]}};
    out->field[out->field_count++] = (FieldRef){"stress_zz", 1, {cs->stress_zz, NULL, NULL}};
    out->field[out->field_count++] = (FieldRef){"mises_stress", 1, {cs->mises, NULL, NULL}};
    out->field[out->field_count++] = (FieldRef){"plastic_strain", 1, {cs->plastic, NULL, NULL}};
    out->field[out->field_count++] = (FieldRef){"J", 1, {cs->jacobian, NULL, NULL}};
    out->field[out->field_count++] = (FieldRef){"broken_fraction", 1, {cs->broken, NULL, NULL}};
    /* fixed scales per series: the plastic strain to the ductile law's
     * critical value (0.2 if none), von Mises to twice the yield stress (a
     * brittle body: its critical stress; else 1e-3 E) */
    const CpdConfig *c = &b->cfg;
    const double ep_hi = c->damage == CPD_DAMAGE_DUCTILE ? c->plastic_strain_critical : 0.2;
    const double s_hi = c->yield_stress > 0.0             ? 2.0 * c->yield_stress
                        : c->damage == CPD_DAMAGE_BRITTLE ? c->critical_stress
                                                          : 1e-3 * c->pd.youngs_modulus;
    out->picture[out->picture_count++] = (PictureRef){.file = "plastic_strain",
                                                      .label = "equivalent plastic strain",
                                                      .units = "-",
                                                      .values = cs->plastic,
                                                      .lo = 0.0,
                                                      .hi = ep_hi,
                                                      .map = COLORMAP_INFERNO,
                                                      .overlay_map = COLORMAP_INFERNO};
    /* drawn over the flow (mach_damage, speed_damage): a body that can
     * break its damage (solid.c's picture; paper 003 Figs. 7 and 11), one
     * that cannot its plastic strain (the chamber's Fig. 2) */
    out->overlay_picture = c->damage != CPD_DAMAGE_NONE ? "damage" : NULL;
    out->picture[out->picture_count++] = (PictureRef){.file = "mises_stress",
                                                      .label = "von Mises stress",
                                                      .units = "Pa",
                                                      .values = cs->mises,
                                                      .lo = 0.0,
                                                      .hi = s_hi,
                                                      .map = COLORMAP_VIRIDIS,
                                                      .overlay_map = COLORMAP_INFERNO};
}

/* Everything a step changes: motion, forces (velocity Verlet reuses the
 * last), the held external loads, the material state (per bond, or per
 * point for the classic force), the RK weights (damage rescales them; the
 * classic force has none) and the F_i of the last force pass (fields read it). */
static int cpd_checkpoint(void *impl, Checkpoint *ck) {
    CpdBody *b = &((CpdSolid *)impl)->body;
    const size_t d8 = sizeof(double);
    static const char *const NAMES[4][3] = {{"cpd.u0", "cpd.u1", "cpd.u2"},
                                            {"cpd.v0", "cpd.v1", "cpd.v2"},
                                            {"cpd.force0", "cpd.force1", "cpd.force2"},
                                            {"cpd.external0", "cpd.external1", "cpd.external2"}};
    /* records in the one process's layout on any number (halo.h) */
    for (int d = 0; d < b->dim && d < 3; d++) {
        TRY(cpd_halo_io_points(b, ck, NAMES[0][d], b->u[d], d8));
        TRY(cpd_halo_io_points(b, ck, NAMES[1][d], b->v[d], d8));
        TRY(cpd_halo_io_points(b, ck, NAMES[2][d], b->force[d], d8));
        TRY(cpd_halo_io_points(b, ck, NAMES[3][d], b->external[d], d8));
    }
    /* the material state: per point (classic) or per pair */
    if (b->cfg.force == CPD_FORCE_CLASSIC) {
        TRY(cpd_halo_io_points(b, ck, "cpd.sigma", b->sigma, 4 * d8));
        TRY(cpd_halo_io_points(b, ck, "cpd.eqps", b->eqps, d8));
    } else {
        TRY(cpd_halo_io_pairs(b, ck, "cpd.sigma", b->sigma, d8, 4));
        TRY(cpd_halo_io_pairs(b, ck, "cpd.eqps", b->eqps, d8, 1));
    }
    TRY(cpd_halo_io_bonds(b, ck, "cpd.damage", b->damage, d8));
    TRY(cpd_halo_io_bonds(b, ck, "cpd.scale", b->scale, d8));
    if (b->cfg.force == CPD_FORCE_CLASSIC) {
        TRY(cpd_halo_io_points(b, ck, "cpd.principal", b->principal, d8));
        TRY(cpd_halo_io_points(b, ck, "cpd.inverted", b->inverted, 1));
        if (b->strain_zz) TRY(cpd_halo_io_points(b, ck, "cpd.strain_zz", b->strain_zz, d8));
    } else {
        TRY(cpd_halo_io_pairs(b, ck, "cpd.principal", b->principal, d8, 1));
        TRY(cpd_halo_io_pairs(b, ck, "cpd.inverted", b->inverted, 1, 1));
        if (b->strain_zz) TRY(cpd_halo_io_pairs(b, ck, "cpd.strain_zz", b->strain_zz, d8, 1));
    }
    if (b->phi) TRY(cpd_halo_io_bonds(b, ck, "cpd.phi", b->phi, (size_t)b->dim * d8));
    /* the semi-Lagrangian frame's F_b is the pairs' state (sl_force.h) */
    if (b->cfg.frame == CPD_FRAME_SEMI_LAGRANGIAN)
        TRY(cpd_halo_io_pairs(b, ck, "cpd.Fb", b->Fb, d8, 4));
    TRY(cpd_halo_io_points(b, ck, "cpd.ok", b->ok, 1));
    TRY(cpd_halo_io_points(b, ck, "cpd.F", b->work_point, 9 * d8));
    for (int d = 0; d < b->dim && d < 3; d++) {
        static const char *const MODE[3] = {"cpd.mode0", "cpd.mode1", "cpd.mode2"};
        TRY(cpd_halo_io_points(b, ck, MODE[d], b->mode[d], d8));
    }
    TRY(checkpoint_io_double(ck, "cpd.stable_now", &b->stable_now));
    TRY(checkpoint_io_int64(ck, "cpd.estimated_at", &b->estimated_at));
    TRY(checkpoint_io_int64(ck, "cpd.substeps_max", &b->substeps_max));
    int grew = b->damage_grew;
    TRY(checkpoint_io_int(ck, "cpd.damage_grew", &grew));
    b->damage_grew = grew != 0;
    TRY(checkpoint_io_int64(ck, "cpd.step", &b->step));
    TRY(checkpoint_io_double(ck, "cpd.time", &b->time));
    int valid = b->force_valid;
    TRY(checkpoint_io_int(ck, "cpd.force_valid", &valid));
    b->force_valid = valid != 0;
    cpd_inverse_weights(b);          /* the damage may have been read */
    b->Fb_now = b->Fb_given = false; /* formed again at the next force */
    return NSPD_OK;
}

static void cpd_config_free_model(void *model) {
    cpd_config_free(model);
}

static int cpd_config_dim(const void *model) {
    return ((const CpdConfig *)model)->pd.dim;
}

const SolidOps CPD_SOLID_OPS = {
    .name = "correspondence",
    .distributed = true,
    .config_free = cpd_config_free_model,
    .config_dim = cpd_config_dim,
    .estimate = cpd_estimate,
    .create = cpd_create,
    .destroy = cpd_destroy,
    .stable_dt = cpd_stable,
    .step = cpd_step_op,
    .step_constrained = cpd_step_constrained_op,
    .time = cpd_time,
    .set_time = cpd_set_time,
    .damage = cpd_damage,
    .modulus = cpd_modulus,
    .density = cpd_density,
    .attached = cpd_attached,
    .history = cpd_history,
    .summary = cpd_summary,
    .info = cpd_info,
    .brief = cpd_brief,
    .fields = cpd_fields,
    .checkpoint = cpd_checkpoint,
    .bench_name = "cpd",
    .bench = cpd_bench,
};

CpdBody *cpd_solid_body(Solid *s) {
    CpdSolid *cs = solid_impl(s, SOLID_CORRESPONDENCE);
    return cs ? &cs->body : NULL;
}
