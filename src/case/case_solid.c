#include "case/case_solid.h"

#include "core/mem.h"
#include "core/status.h"
#include "case/case_shapes.h"
#include "io/cfg_read.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const char *const AXES[] = {"x", "y", "z"};

/* {x: 1, y: 2} -> values and a mask of the components given. */
static int read_components(CfgNode *map, const char *key, int dim, unsigned *mask,
                           double value[3]) {
    CfgNode *node;
    TRY(cfg_opt_map(map, key, &node));
    *mask = 0;
    if (!node) return NSPD_OK;
    for (int d = 0; d < dim && d < 3; d++) { /* dim <= 3: AXES has 3 */
        bool given;
        TRY(cfg_maybe_double(node, AXES[d], &value[d], &given));
        if (given) *mask |= 1u << d;
    }
    TRY(cfg_end_map(node));
    if (!*mask)
        return cfg_fail(node, "no component given; expected some of %s",
                        dim == 2 ? "x, y" : "x, y, z");
    return NSPD_OK;
}

static int read_material(CfgNode *solid, PdConfig *cfg) {
    CfgNode *m;
    TRY(cfg_req_map(solid, "material", &m));
    TRY(cfg_req_double(m, "density", &cfg->density));
    TRY(cfg_check_positive(m, "density", cfg->density, "a density in kg/m^3"));
    TRY(cfg_req_double(m, "youngs_modulus", &cfg->youngs_modulus));
    TRY(cfg_check_positive(m, "youngs_modulus", cfg->youngs_modulus, "Young's modulus in Pa"));
    double nu_model = pd_model_poisson_ratio(cfg->model), nu;
    TRY(cfg_opt_double(m, "poisson_ratio", nu_model, &nu));
    if (fabs(nu - nu_model) > 1e-3)
        return cfg_fail_at(m, "poisson_ratio",
                           "%g is not possible: bond-based peridynamics fixes Poisson's ratio at "
                           "%.4g for %s; expected %.4g or no key",
                           nu, nu_model, PD_MODEL_NAMES[cfg->model], nu_model);
    bool has_sc, has_gc;
    TRY(cfg_maybe_double(m, "critical_stretch", &cfg->critical_stretch, &has_sc));
    TRY(cfg_maybe_double(m, "fracture_energy", &cfg->fracture_energy, &has_gc));
    if (has_sc && has_gc)
        return cfg_fail_at(m, "fracture_energy",
                           "both critical_stretch and fracture_energy given; expected one of them");
    if (has_sc)
        TRY(cfg_check_positive(m, "critical_stretch", cfg->critical_stretch,
                               "a critical bond stretch s_c > 0"));
    if (has_gc) {
        TRY(cfg_check_positive(m, "fracture_energy", cfg->fracture_energy,
                               "a critical energy release rate G_c in J/m^2"));
        cfg->critical_stretch = pd_critical_stretch_from_energy(cfg, cfg->fracture_energy);
    }
    TRY(cfg_end_map(m));
    return NSPD_OK;
}

static int read_failure(CfgNode *solid, PdConfig *cfg) {
    CfgNode *f;
    TRY(cfg_opt_map(solid, "failure", &f));
    if (!f) {
        cfg->failure = false;
        return NSPD_OK;
    }
    TRY(cfg_opt_bool(f, "enabled", true, &cfg->failure));
    TRY(case_read_shapes(f, "region", cfg->dim, false, &cfg->failure_region));
    TRY(cfg_end_map(f));
    if (cfg->failure && !(cfg->critical_stretch > 0))
        return cfg_fail_at(f, "enabled",
                           "failure is on but the material has no critical_stretch or "
                           "fracture_energy; expected one of them in solid.material");
    return NSPD_OK;
}

static int read_precracks(CfgNode *solid, PdConfig *cfg) {
    CfgNode *seq;
    TRY(cfg_opt_seq(solid, "precracks", &seq));
    if (!seq) return NSPD_OK;
    TRY(nspd_alloc(&cfg->precracks, (size_t)seq->count, sizeof(PdPrecrack)));
    cfg->precrack_count = seq->count;
    for (int i = 0; i < seq->count; i++) {
        CfgNode *item = seq->child[i];
        PdPrecrack *c = &cfg->precracks[i];
        if (item->kind != CFG_MAP)
            return cfg_fail(item, "not a crack; expected {from: [x, y], to: [x, y]}%s",
                            cfg->dim == 3 ? " or in 3D {corner: [..], edge1: [..], edge2: [..]}"
                                          : "");
        if (cfg->dim == 2) {
            TRY(cfg_req_vec(item, "from", 2, c->a));
            TRY(cfg_req_vec(item, "to", 2, c->b));
            if (c->a[0] == c->b[0] && c->a[1] == c->b[1])
                return cfg_fail_at(item, "to", "the crack has zero length; expected to != from");
        } else {
            TRY(cfg_req_vec(item, "corner", 3, c->a));
            TRY(cfg_req_vec(item, "edge1", 3, c->e1));
            TRY(cfg_req_vec(item, "edge2", 3, c->e2));
        }
        TRY(cfg_end_map(item));
    }
    return NSPD_OK;
}

static int read_boundaries(CfgNode *solid, PdConfig *cfg) {
    CfgNode *seq;
    TRY(cfg_opt_seq(solid, "boundaries", &seq));
    if (!seq) return NSPD_OK;
    if (seq->count > 30000) return cfg_fail(seq, "too many regions; expected at most 30000");
    TRY(nspd_alloc(&cfg->boundaries, (size_t)seq->count, sizeof(PdBoundaryRegion)));
    cfg->boundary_count = seq->count;
    for (int i = 0; i < seq->count; i++) {
        CfgNode *item = seq->child[i];
        PdBoundaryRegion *r = &cfg->boundaries[i];
        if (item->kind != CFG_MAP)
            return cfg_fail(item, "not a boundary region; expected a map with name and region");
        const char *name;
        char fallback[32];
        snprintf(fallback, sizeof fallback, "region%d", i);
        TRY(cfg_opt_string(item, "name", fallback, &name));
        snprintf(r->name, sizeof r->name, "%s", name);
        TRY(case_read_shapes(item, "region", cfg->dim, true, &r->region));
        TRY(read_components(item, "velocity", cfg->dim, &r->velocity_mask, r->velocity));
        TRY(read_components(item, "displacement", cfg->dim, &r->displacement_mask,
                            r->displacement));
        bool fixed;
        TRY(cfg_opt_bool(item, "fixed", false, &fixed));
        if (fixed) {
            if (r->velocity_mask || r->displacement_mask)
                return cfg_fail_at(item, "fixed",
                                   "fixed with velocity or displacement; expected one of them");
            r->displacement_mask = (1u << cfg->dim) - 1;
        }
        if (r->velocity_mask & r->displacement_mask)
            return cfg_fail_at(item, "displacement",
                               "a component has both a velocity and a displacement; expected one");
        double zero[3] = {0, 0, 0};
        TRY(cfg_opt_vec(item, "force_density", cfg->dim, zero, r->force_density));
        TRY(cfg_end_map(item));
    }
    return NSPD_OK;
}

static int read_initial_velocities(CfgNode *solid, PdConfig *cfg) {
    CfgNode *seq;
    TRY(cfg_opt_seq(solid, "initial_velocity", &seq));
    if (!seq) return NSPD_OK;
    TRY(nspd_alloc(&cfg->initial_velocities, (size_t)seq->count, sizeof(PdInitialVelocity)));
    cfg->initial_velocity_count = seq->count;
    for (int i = 0; i < seq->count; i++) {
        CfgNode *item = seq->child[i];
        if (item->kind != CFG_MAP) return cfg_fail(item, "expected a map with region and velocity");
        TRY(case_read_shapes(item, "region", cfg->dim, true, &cfg->initial_velocities[i].region));
        TRY(cfg_req_vec(item, "velocity", cfg->dim, cfg->initial_velocities[i].velocity));
        TRY(cfg_end_map(item));
    }
    return NSPD_OK;
}

/* The lattice sites in the geometry's box bound the points the body can
 * have, and the builder scans them all (a byte each): a spacing far too
 * small for the geometry (a unit slip, 1e-8 m for 1e-4) is refused here,
 * saying how many there would be, before anything is allocated. */
enum { CASE_MAX_LATTICE_SITES = 1 << 30 }; /* 1.07e9: 8.6 GB of point positions in 3D alone */

static int check_lattice_size(CfgNode *s, const PdConfig *cfg) {
    double lo[3], hi[3];
    if (!shapeset_bounds(&cfg->geometry, cfg->dim, lo, hi)) return NSPD_OK; /* said later */
    double sites = 1.0;
    for (int d = 0; d < cfg->dim && d < 3; d++)
        sites *= floor((hi[d] - lo[d]) / cfg->spacing) + 1.0;
    if (!(sites <= CASE_MAX_LATTICE_SITES))
        return cfg_fail_at(s, "spacing",
                           "%g m puts %.3g lattice sites in the geometry's bounding box; "
                           "expected at most %.3g (a larger spacing)",
                           cfg->spacing, sites, (double)CASE_MAX_LATTICE_SITES);
    return NSPD_OK;
}

int case_read_solid(CfgNode *s, PdConfig *cfg) {
    memset(cfg, 0, sizeof *cfg);
    int model;
    TRY(cfg_req_enum(s, "model", PD_MODEL_NAMES, &model));
    cfg->model = (PdModel)model;
    cfg->dim = cfg->model == PD_3D ? 3 : 2;
    TRY(cfg_req_double(s, "spacing", &cfg->spacing));
    TRY(cfg_check_positive(s, "spacing", cfg->spacing, "the lattice spacing dx in m"));
    if (cfg->dim == 2) {
        TRY(cfg_opt_double(s, "thickness", cfg->spacing, &cfg->thickness));
        TRY(cfg_check_positive(s, "thickness", cfg->thickness, "the plate thickness in m"));
    }
    TRY(cfg_opt_double(s, "horizon_factor", 3.015, &cfg->horizon_factor));
    if (!(cfg->horizon_factor >= 1.0))
        return cfg_fail_at(s, "horizon_factor",
                           "%g makes the horizon smaller than the spacing; expected m >= 1 "
                           "(3.015 is usual)",
                           cfg->horizon_factor);
    /* m = 50 is already 7,850 bonds per point in 2D and 520,000 in 3D; 10^6
     * spacings once kept the family count busy for hours */
    if (!(cfg->horizon_factor <= 50.0))
        return cfg_fail_at(s, "horizon_factor",
                           "%g spacings; expected m <= 50 (3.015 is usual; convergence studies "
                           "go to about 10)",
                           cfg->horizon_factor);
    /* absent: the lattice starts half a spacing inside the geometry's bounding box */
    CfgNode *origin = cfg_map_find(s, "lattice_origin");
    if (origin) origin->used = true;
    if (origin && !origin->is_null) {
        TRY(cfg_req_vec(s, "lattice_origin", cfg->dim, cfg->lattice_origin));
        cfg->has_lattice_origin = true;
    }
    TRY(read_material(s, cfg));
    TRY(case_read_shapes(s, "geometry", cfg->dim, true, &cfg->geometry));
    TRY(check_lattice_size(s, cfg));
    TRY(read_failure(s, cfg));
    TRY(read_precracks(s, cfg));
    TRY(read_boundaries(s, cfg));
    TRY(read_initial_velocities(s, cfg));
    double zero[3] = {0, 0, 0};
    TRY(cfg_opt_vec(s, "body_force", cfg->dim, zero, cfg->body_force));
    int v, srf, integ;
    TRY(cfg_opt_enum(s, "volume_correction", PD_VOLUME_NAMES, PD_VOLUME_LINEAR, &v));
    TRY(cfg_opt_enum(s, "surface_correction", PD_SURFACE_NAMES, PD_SURFACE_ENERGY, &srf));
    TRY(cfg_opt_enum(s, "integrator", PD_INTEGRATOR_NAMES, PD_EULER_CROMER, &integ));
    cfg->volume_correction = (PdVolumeCorrection)v;
    cfg->surface_correction = (PdSurfaceCorrection)srf;
    cfg->integrator = (PdIntegrator)integ;
    return cfg_end_map(s);
}
