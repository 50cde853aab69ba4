#include "case/case_solid.h"

#include "core/mem.h"
#include "core/status.h"
#include "case/case_loads.h"
#include "case/case_mesh.h"
#include "case/case_shapes.h"
#include "io/cfg_read.h"
#include "solid/correspondence/config.h"
#include "solid/pd/config.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const char *const AXES[] = {"x", "y", "z"};

/* item's `name` into out (size PD_MAX_NAME), default "<prefix><index>" */
static int read_item_name(CfgNode *item, const char *prefix, int index, char *out) {
    char fallback[32];
    snprintf(fallback, sizeof fallback, "%s%d", prefix, index);
    const char *name;
    TRY(cfg_opt_string(item, "name", fallback, &name));
    snprintf(out, PD_MAX_NAME, "%s", name);
    return NSPD_OK;
}

/* The first of `keys` present in map, or NULL (keys another key excludes). */
static const char *first_present(const CfgNode *map, const char *const *keys, int count) {
    for (int k = 0; k < count; k++)
        if (cfg_map_find(map, keys[k])) return keys[k];
    return NULL;
}

/* {x: 1, y: "20*t"} -> values (numbers or load expressions, case_loads.h)
 * and a mask of the components given. */
static int read_components(CfgNode *map, const char *key, PdConfig *cfg, unsigned *mask,
                           double value[3], uint16_t expr[3]) {
    const int dim = cfg->dim;
    CfgNode *node;
    TRY(cfg_opt_map(map, key, &node));
    *mask = 0;
    if (!node) return NSPD_OK;
    for (int d = 0; d < dim && d < 3; d++) { /* dim <= 3: AXES has 3 */
        bool given;
        TRY(case_maybe_load(node, AXES[d], cfg, &value[d], &expr[d], &given));
        if (given) *mask |= 1u << d;
    }
    TRY(cfg_end_map(node));
    if (!*mask)
        return cfg_fail(node, "no component given; expected some of %s",
                        dim == 2 ? "x, y" : "x, y, z");
    return NSPD_OK;
}

/* density and Young's modulus, the keys every PD material has */
static int read_elastic(CfgNode *m, PdConfig *cfg) {
    TRY(cfg_req_double(m, "density", &cfg->density));
    TRY(cfg_check_positive(m, "density", cfg->density, "a density in kg/m^3"));
    TRY(cfg_req_double(m, "youngs_modulus", &cfg->youngs_modulus));
    TRY(cfg_check_positive(m, "youngs_modulus", cfg->youngs_modulus, "Young's modulus in Pa"));
    return NSPD_OK;
}

/* One material's map: density, E, the model's Poisson's ratio and (the
 * first only: one per body) the critical stretch or fracture energy. */
static int read_material_map(CfgNode *m, PdConfig *cfg, bool first) {
    TRY(read_elastic(m, cfg));
    double nu_model = pd_model_poisson_ratio(cfg->model), nu;
    TRY(cfg_opt_double(m, "poisson_ratio", nu_model, &nu));
    if (fabs(nu - nu_model) > 1e-3)
        return cfg_fail_at(m, "poisson_ratio",
                           "%g is not possible: bond-based peridynamics fixes Poisson's ratio at "
                           "%.4g for %s; expected %.4g or no key",
                           nu, nu_model, PD_MODEL_NAMES[cfg->model], nu_model);
    if (!first) {
        static const char *const BODY_WIDE[] = {"critical_stretch", "fracture_energy"};
        const char *key = first_present(m, BODY_WIDE, 2);
        if (key)
            return cfg_fail_at(m, key,
                               "one critical stretch for the body; expected %s in the first "
                               "material only (bonds break only in failure.region)",
                               key);
        return NSPD_OK;
    }
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
    return NSPD_OK;
}

/* solid.material: a map, or a list of them with regions (several
 * materials, PdMaterial; the first's density and E are the body's). */
static int read_material(CfgNode *solid, PdConfig *cfg) {
    const CfgNode *node = cfg_map_find(solid, "material");
    if (!node || node->kind != CFG_SEQ) {
        CfgNode *m;
        TRY(cfg_req_map(solid, "material", &m));
        TRY(read_material_map(m, cfg, true));
        return cfg_end_map(m);
    }
    CfgNode *seq;
    TRY(cfg_req_seq(solid, "material", &seq));
    if (seq->count < 1 || seq->count > 255)
        return cfg_fail(seq, "%d materials; expected 1 to 255", seq->count);
    TRY(nspd_alloc(&cfg->materials, (size_t)seq->count, sizeof(PdMaterial)));
    cfg->material_count = seq->count;
    double first_density = 0.0, first_e = 0.0;
    for (int i = 0; i < seq->count; i++) {
        CfgNode *m = seq->child[i];
        if (m->kind != CFG_MAP)
            return cfg_fail(m, "not a material; expected a map with region, density and "
                               "youngs_modulus");
        PdMaterial *pm = &cfg->materials[i];
        TRY(read_item_name(m, "material", i, pm->name));
        const bool last = i == seq->count - 1;
        TRY(case_read_shapes(m, "region", cfg->dim, !last, &pm->region));
        TRY(read_material_map(m, cfg, i == 0));
        pm->density = cfg->density;
        pm->youngs_modulus = cfg->youngs_modulus;
        if (i == 0) first_density = cfg->density, first_e = cfg->youngs_modulus;
        TRY(cfg_end_map(m));
    }
    cfg->density = first_density; /* the body's: the first material's */
    cfg->youngs_modulus = first_e;
    int bonded;
    static const char *const INTERFACES[] = {"separate", "bonded", NULL};
    TRY(cfg_opt_enum(solid, "material_interface", INTERFACES, 0, &bonded));
    cfg->materials_bonded = bonded == 1;
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

/* item's region: `region` (shapes), or `set` (the mesh's sets), one of them */
static int read_region_or_set(CfgNode *item, PdConfig *cfg, const CaseMesh *mesh,
                              ShapeSet *region) {
    bool from_set;
    TRY(case_read_set_region(item, "set", mesh, region, &from_set));
    if (!from_set) return case_read_shapes(item, "region", cfg->dim, true, region);
    if (cfg_map_find(item, "region"))
        return cfg_fail_at(item, "region", "both region and set given; expected one of them");
    return NSPD_OK;
}

static int read_boundaries(CfgNode *solid, PdConfig *cfg, const CaseMesh *mesh) {
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
        TRY(read_item_name(item, "region", i, r->name));
        TRY(read_region_or_set(item, cfg, mesh, &r->region));
        TRY(read_components(item, "velocity", cfg, &r->velocity_mask, r->velocity,
                            r->velocity_expr));
        TRY(read_components(item, "displacement", cfg, &r->displacement_mask, r->displacement,
                            r->displacement_expr));
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
        TRY(case_opt_load_vec(item, "force_density", cfg->dim, zero, cfg, r->force_density,
                              r->force_expr));
        TRY(cfg_end_map(item));
    }
    return NSPD_OK;
}

static int read_initial_velocities(CfgNode *solid, PdConfig *cfg, const CaseMesh *mesh) {
    CfgNode *seq;
    TRY(cfg_opt_seq(solid, "initial_velocity", &seq));
    if (!seq) return NSPD_OK;
    TRY(nspd_alloc(&cfg->initial_velocities, (size_t)seq->count, sizeof(PdInitialVelocity)));
    cfg->initial_velocity_count = seq->count;
    for (int i = 0; i < seq->count; i++) {
        CfgNode *item = seq->child[i];
        if (item->kind != CFG_MAP) return cfg_fail(item, "expected a map with region and velocity");
        TRY(read_region_or_set(item, cfg, mesh, &cfg->initial_velocities[i].region));
        PdInitialVelocity *iv = &cfg->initial_velocities[i];
        TRY(case_req_load_vec(item, "velocity", cfg->dim, cfg, iv->velocity, iv->velocity_expr));
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
    if (cfg->lattice_kind != PD_LATTICE_SQUARE) return NSPD_OK; /* counted where they are read */
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

/* solid.lattice: absent or kind square, the square lattice of `spacing`
 * (nothing written into the resolved case when absent); kind polar, the
 * ring's polar lattice (solid/pd/lattice.h), whose radial spacing becomes
 * the solid's spacing. The polar keys are looked up under square too, so
 * that the map's key list names them and a stray one is refused by name. */
static const char *const POLAR_KEYS[] = {"center", "inner_radius", "outer_radius", "rings",
                                         "sectors"};

static int read_polar(CfgNode *s, PdConfig *cfg) {
    CfgNode *m;
    cfg->lattice_kind = PD_LATTICE_SQUARE;
    TRY(cfg_opt_map(s, "lattice", &m));
    if (!m) return NSPD_OK;
    int kind;
    TRY(cfg_opt_enum(m, "kind", PD_LATTICE_NAMES, PD_LATTICE_SQUARE, &kind));
    if (kind == PD_LATTICE_SQUARE) {
        for (size_t k = 0; k < sizeof POLAR_KEYS / sizeof *POLAR_KEYS; k++)
            if (cfg_map_find(m, POLAR_KEYS[k]))
                return cfg_fail_at(m, POLAR_KEYS[k],
                                   "a key of the polar lattice; expected kind: polar, or no %s",
                                   POLAR_KEYS[k]);
        return cfg_end_map(m);
    }
    cfg->lattice_kind = PD_LATTICE_POLAR;
    if (cfg->dim != 2) return cfg_fail_at(m, "kind", "polar with a 3D model; expected a 2D model");
    if (cfg->has_lattice_origin)
        return cfg_fail_at(s, "lattice_origin",
                           "the square lattice's origin with a polar lattice; expected no "
                           "lattice_origin");
    PolarLattice *p = &cfg->polar;
    TRY(cfg_req_vec(m, "center", 2, p->center));
    TRY(cfg_req_double(m, "inner_radius", &p->inner_radius));
    /* a full disc (r_i = 0) would crowd its inner ring's sectors, each a
     * sliver, into the centre */
    TRY(cfg_check_positive(m, "inner_radius", p->inner_radius,
                           "the ring's inner radius r_i > 0 in m (the polar lattice is a ring)"));
    TRY(cfg_req_double(m, "outer_radius", &p->outer_radius));
    if (!(p->outer_radius > p->inner_radius))
        return cfg_fail_at(m, "outer_radius", "%g m with inner_radius %g m; expected r_o > r_i",
                           p->outer_radius, p->inner_radius);
    const double width = p->outer_radius - p->inner_radius;
    const double fit = floor(width / cfg->spacing + 0.5);
    if (!(fit <= (double)(1 << 24)))
        return cfg_fail_at(s, "spacing",
                           "%g m puts %.3g rings in the polar lattice's %g m; expected at most "
                           "%d (a larger spacing)",
                           cfg->spacing, fit, width, 1 << 24);
    const int64_t fitted = fit < 1.0 ? 1 : (int64_t)fit;
    int64_t rings;
    TRY(cfg_opt_int(m, "rings", fitted, &rings));
    if (rings < 1)
        return cfg_fail_at(m, "rings",
                           "%lld; expected at least 1 ring (no key: %lld, from the "
                           "spacing)",
                           (long long)rings, (long long)fitted);
    if (rings != fitted)
        return cfg_fail_at(m, "rings",
                           "%lld, but the spacing %g m fits %lld in the ring's %g m; expected "
                           "%lld, or solid.spacing %g m for %lld rings (the radial spacing is "
                           "the solid's spacing)",
                           (long long)rings, cfg->spacing, (long long)fitted, width,
                           (long long)fitted, width / (double)rings, (long long)rings);
    const double dr = width / (double)rings;
    int64_t sectors;
    TRY(cfg_opt_int(m, "sectors", lattice_polar_sectors(p->inner_radius, p->outer_radius, dr),
                    &sectors));
    /* an odd count would break the index parity (sector + ring) at the
     * seam, where the stable step's power iteration starts from a
     * checkerboard */
    if (sectors < 4 || sectors > (1 << 24) || sectors % 2 != 0)
        return cfg_fail_at(m, "sectors",
                           "%lld; expected an even number of sectors around, 4 to %d (no key: "
                           "%lld, near-square elements at the mid radius)",
                           (long long)sectors, 1 << 24,
                           (long long)lattice_polar_sectors(p->inner_radius, p->outer_radius, dr));
    if (!((double)rings * (double)sectors <= CASE_MAX_LATTICE_SITES))
        return cfg_fail_at(m, "sectors",
                           "%lld rings x %lld sectors; expected at most %.3g points (a larger "
                           "spacing or fewer sectors)",
                           (long long)rings, (long long)sectors, (double)CASE_MAX_LATTICE_SITES);
    p->rings = (int32_t)rings;
    p->sectors = (int32_t)sectors;
    cfg->spacing = dr;
    return cfg_end_map(m);
}

/* solid.lattice.kind as written, or NULL (before the lattice is read) */
static const char *lattice_kind_text(const CfgNode *s) {
    const CfgNode *lattice = cfg_map_find(s, "lattice");
    const CfgNode *kind =
        lattice && lattice->kind == CFG_MAP ? cfg_map_find(lattice, "kind") : NULL;
    return kind && kind->kind == CFG_SCALAR ? kind->text : NULL;
}

/* solid.lattice {kind: abaqus, file, scale, translate}: the mesh's
 * elements as the points (case_mesh.h); *mean_size the default spacing */
static int read_abaqus(CfgNode *s, PdConfig *cfg, CaseMesh *mesh, double *mean_size) {
    CfgNode *m;
    TRY(cfg_req_map(s, "lattice", &m));
    int kind;
    TRY(cfg_req_enum(m, "kind", PD_LATTICE_NAMES, &kind));
    cfg->lattice_kind = PD_LATTICE_ABAQUS;
    if (cfg_map_find(s, "lattice_origin"))
        return cfg_fail_at(s, "lattice_origin",
                           "the square lattice's origin with a mesh's points; expected no "
                           "lattice_origin");
    TRY(case_read_abaqus(m, cfg->dim, mesh, &cfg->mesh, mean_size));
    return cfg_end_map(m);
}

/* The keys both formulations read the same way, up to the material
 * (mesh: where a kind: abaqus lattice's mesh is kept, NULL when the
 * formulation takes none). */
static int read_lattice(CfgNode *s, PdConfig *cfg, double default_horizon, CaseMesh *mesh) {
    int model;
    TRY(cfg_req_enum(s, "model", PD_MODEL_NAMES, &model));
    cfg->model = (PdModel)model;
    cfg->dim = cfg->model == PD_3D ? 3 : 2;
    const char *kind = lattice_kind_text(s);
    const bool from_mesh = mesh && kind && strcmp(kind, "abaqus") == 0;
    double mean_size = 0.0;
    if (from_mesh) TRY(read_abaqus(s, cfg, mesh, &mean_size));
    /* a mesh's points: the spacing is nominal (the horizon m dx, contact),
     * by default the mean element size */
    if (from_mesh)
        TRY(cfg_opt_double(s, "spacing", mean_size, &cfg->spacing));
    else
        TRY(cfg_req_double(s, "spacing", &cfg->spacing));
    TRY(cfg_check_positive(s, "spacing", cfg->spacing, "the lattice spacing dx in m"));
    if (cfg->dim == 2) {
        TRY(cfg_opt_double(s, "thickness", cfg->spacing, &cfg->thickness));
        TRY(cfg_check_positive(s, "thickness", cfg->thickness, "the plate thickness in m"));
    }
    TRY(cfg_opt_double(s, "horizon_factor", default_horizon, &cfg->horizon_factor));
    if (!(cfg->horizon_factor >= 1.0))
        return cfg_fail_at(s, "horizon_factor",
                           "%g makes the horizon smaller than the spacing; expected m >= 1 "
                           "(%g is usual)",
                           cfg->horizon_factor, default_horizon);
    /* m = 50 is already 7,850 bonds per point in 2D and 520,000 in 3D; 10^6
     * spacings once kept the family count busy for hours */
    if (!(cfg->horizon_factor <= 50.0))
        return cfg_fail_at(s, "horizon_factor",
                           "%g spacings; expected m <= 50 (%g is usual; convergence studies "
                           "go to about 10)",
                           cfg->horizon_factor, default_horizon);
    /* absent: the lattice starts half a spacing inside the geometry's bounding box */
    CfgNode *origin = cfg_map_find(s, "lattice_origin");
    if (origin) origin->used = true;
    if (origin && !origin->is_null) {
        TRY(cfg_req_vec(s, "lattice_origin", cfg->dim, cfg->lattice_origin));
        cfg->has_lattice_origin = true;
    }
    return from_mesh ? NSPD_OK : read_polar(s, cfg);
}

/* The keys after the material that both formulations share. */
static int read_body(CfgNode *s, PdConfig *cfg, const CaseMesh *mesh) {
    /* with a polar lattice or a mesh's points the geometry is optional: it
     * filters the elements by their centroids */
    TRY(case_read_shapes(s, "geometry", cfg->dim, cfg->lattice_kind == PD_LATTICE_SQUARE,
                         &cfg->geometry));
    TRY(check_lattice_size(s, cfg));
    TRY(read_precracks(s, cfg));
    TRY(read_boundaries(s, cfg, mesh));
    TRY(read_initial_velocities(s, cfg, mesh));
    double zero[3] = {0, 0, 0};
    TRY(case_opt_load_vec(s, "body_force", cfg->dim, zero, cfg, cfg->body_force,
                          cfg->body_force_expr));
    return NSPD_OK;
}

/* solid.contact (solid/pd/contact.h); absent: off, and nothing written
 * into the resolved case */
static int read_contact(CfgNode *s, PdConfig *cfg) {
    CfgNode *c;
    TRY(cfg_opt_map(s, "contact", &c));
    PdContactConfig *k = &cfg->contact;
    *k = (PdContactConfig){0};
    if (!c) return NSPD_OK;
    TRY(cfg_opt_bool(c, "enabled", true, &k->enabled));
    TRY(cfg_opt_double(c, "distance", 1.35, &k->distance));
    TRY(cfg_check_range(c, "distance", k->distance, 0.1, 3.0,
                        "the contact distance in lattice spacings, in [0.1, 3]"));
    TRY(cfg_opt_double(c, "compression", 0.9, &k->compression));
    TRY(cfg_check_range(c, "compression", k->compression, 0.0, 1.0,
                        "the fraction of a near pair's reference distance where contact starts, "
                        "in [0, 1]"));
    TRY(cfg_opt_double(c, "stiffness", 15.0, &k->stiffness));
    TRY(cfg_check_positive(c, "stiffness", k->stiffness,
                           "the contact stiffness as a multiple of the micromodulus c"));
    TRY(cfg_opt_double(c, "skin", 0.5, &k->skin));
    TRY(cfg_check_range(c, "skin", k->skin, 0.05, 5.0,
                        "the candidate lists' margin in lattice spacings, in [0.05, 5]"));
    return cfg_end_map(c);
}

static int read_bond(CfgNode *s, PdConfig *cfg) {
    /* refused before the polar keys are read (the force runs on the
     * square lattice's view: solid/bond/stencil.h) */
    const char *kind = lattice_kind_text(s);
    if (kind && (strcmp(kind, "polar") == 0 || strcmp(kind, "abaqus") == 0))
        return cfg_fail(cfg_map_find(cfg_map_find(s, "lattice"), "kind"),
                        "%s with the bond-based solid, whose force runs on the square "
                        "lattice's fixed offsets; expected kind: square, or solid.formulation: "
                        "correspondence",
                        kind);
    TRY(read_lattice(s, cfg, 3.015, NULL));
    TRY(read_material(s, cfg));
    TRY(read_body(s, cfg, NULL));
    TRY(read_failure(s, cfg));
    TRY(read_contact(s, cfg));
    int v, srf, integ;
    TRY(cfg_opt_enum(s, "volume_correction", PD_VOLUME_NAMES, PD_VOLUME_LINEAR, &v));
    TRY(cfg_opt_enum(s, "surface_correction", PD_SURFACE_NAMES, PD_SURFACE_ENERGY, &srf));
    TRY(cfg_opt_enum(s, "integrator", PD_INTEGRATOR_NAMES, PD_EULER_CROMER, &integ));
    cfg->volume_correction = (PdVolumeCorrection)v;
    cfg->surface_correction = (PdSurfaceCorrection)srf;
    cfg->integrator = (PdIntegrator)integ;
    return NSPD_OK;
}

static int read_cpd_material(CfgNode *s, CpdConfig *cfg) {
    CfgNode *m;
    TRY(cfg_req_map(s, "material", &m));
    TRY(read_elastic(m, &cfg->pd));
    TRY(cfg_req_double(m, "poisson_ratio", &cfg->poisson_ratio));
    if (!(cfg->poisson_ratio > -1.0 && cfg->poisson_ratio < 0.5))
        return cfg_fail_at(m, "poisson_ratio", "%g; expected a Poisson's ratio in (-1, 0.5)",
                           cfg->poisson_ratio);
    TRY(cfg_opt_double(m, "yield_stress", 0.0, &cfg->yield_stress));
    if (!(cfg->yield_stress >= 0.0))
        return cfg_fail_at(m, "yield_stress",
                           "%g; expected the initial yield stress sigma_Y in Pa (0 or no key: "
                           "elastic)",
                           cfg->yield_stress);
    TRY(cfg_opt_double(m, "hardening_modulus", 0.0, &cfg->hardening));
    if (!(cfg->hardening >= 0.0))
        return cfg_fail_at(m, "hardening_modulus",
                           "%g; expected the linear hardening modulus H = d sigma_y / d eqps "
                           ">= 0 in Pa",
                           cfg->hardening);
    return cfg_end_map(m);
}

static int read_cpd_failure(CfgNode *s, CpdConfig *cfg) {
    CfgNode *f;
    cfg->damage = CPD_DAMAGE_NONE;
    cfg->plastic_strain_threshold = 0.18;
    cfg->plastic_strain_critical = 0.2;
    cfg->damage_ramp = 0.01;
    TRY(cfg_opt_map(s, "failure", &f));
    if (!f) return NSPD_OK;
    int law;
    TRY(cfg_req_enum(f, "law", CPD_DAMAGE_NAMES, &law));
    cfg->damage = (CpdDamageLaw)law;
    if (cfg->damage == CPD_DAMAGE_DUCTILE) {
        TRY(cfg_opt_double(f, "plastic_strain_threshold", 0.18, &cfg->plastic_strain_threshold));
        TRY(cfg_opt_double(f, "plastic_strain_critical", 0.2, &cfg->plastic_strain_critical));
        if (!(cfg->plastic_strain_threshold >= 0.0 &&
              cfg->plastic_strain_critical > cfg->plastic_strain_threshold))
            return cfg_fail_at(f, "plastic_strain_critical",
                               "%g with threshold %g; expected 0 <= threshold < critical",
                               cfg->plastic_strain_critical, cfg->plastic_strain_threshold);
        if (!(cfg->yield_stress > 0.0))
            return cfg_fail_at(f, "law",
                               "ductile failure needs plasticity; expected "
                               "solid.material.yield_stress > 0");
    } else if (cfg->damage == CPD_DAMAGE_STRETCH) {
        TRY(cfg_req_double(f, "critical_stretch", &cfg->critical_stretch));
        TRY(cfg_check_positive(f, "critical_stretch", cfg->critical_stretch,
                               "the bond stretch s_c at which a bond breaks"));
    } else if (cfg->damage == CPD_DAMAGE_BRITTLE) {
        TRY(cfg_req_double(f, "critical_stress", &cfg->critical_stress));
        TRY(cfg_check_positive(f, "critical_stress", cfg->critical_stress,
                               "the maximum principal stress sigma_cr at which a bond breaks, Pa"));
        TRY(cfg_opt_double(f, "ramp", 0.01, &cfg->damage_ramp));
        TRY(cfg_check_range(f, "ramp", cfg->damage_ramp, 0.0, 0.5,
                            "the relative width of the damage ramp below sigma_cr (0: a step)"));
    }
    return cfg_end_map(f);
}

static int read_cpd_pressures(CfgNode *s, CpdConfig *cfg) {
    CfgNode *seq;
    TRY(cfg_opt_seq(s, "pressure_loads", &seq));
    if (!seq) return NSPD_OK;
    if (seq->count > 64) return cfg_fail(seq, "too many pressure loads; expected at most 64");
    TRY(nspd_alloc(&cfg->pressures, (size_t)seq->count, sizeof(CpdPressure)));
    cfg->pressure_count = seq->count;
    for (int i = 0; i < seq->count; i++) {
        CfgNode *item = seq->child[i];
        CpdPressure *p = &cfg->pressures[i];
        if (item->kind != CFG_MAP)
            return cfg_fail(item, "not a pressure load; expected a map with region and peak");
        TRY(read_item_name(item, "pressure", i, p->name));
        TRY(case_read_shapes(item, "region", cfg->pd.dim, true, &p->region));
        /* a pressure history: the expression `pressure`, or the trapezoid */
        double constant;
        bool has_expr;
        TRY(case_maybe_load(item, "pressure", &cfg->pd, &constant, &p->expr, &has_expr));
        if (has_expr) {
            if (!p->expr) p->peak = constant; /* a number: held from t = 0 */
            static const char *const TRAPEZOID[] = {"peak", "rise_time", "hold_time", "fall_time"};
            const char *key = first_present(item, TRAPEZOID, 4);
            if (key)
                return cfg_fail_at(item, key,
                                   "both pressure and %s given; expected the expression "
                                   "pressure or the trapezoid's keys",
                                   key);
        } else {
            TRY(cfg_req_double(item, "peak", &p->peak));
            TRY(cfg_opt_double(item, "rise_time", 0.0, &p->rise));
            TRY(cfg_opt_double(item, "hold_time", 0.0, &p->hold));
            TRY(cfg_opt_double(item, "fall_time", 0.0, &p->fall));
            if (!(p->rise >= 0.0 && p->hold >= 0.0 && p->fall >= 0.0))
                return cfg_fail(item,
                                "a negative time; expected rise_time, hold_time, fall_time >= 0");
        }
        TRY(cfg_end_map(item));
    }
    return NSPD_OK;
}

static int read_correspondence(CfgNode *s, CpdConfig *cfg, CaseMesh *mesh) {
    PdConfig *pd = &cfg->pd;
    TRY(read_lattice(s, pd, 2.5, mesh));
    if (pd->dim != 2)
        return cfg_fail_at(s, "model",
                           "%s: the correspondence solid is 2D; expected plane_strain or "
                           "plane_stress",
                           PD_MODEL_NAMES[pd->model]);
    TRY(read_cpd_material(s, cfg));
    TRY(read_body(s, pd, mesh));
    TRY(read_cpd_failure(s, cfg));
    TRY(read_cpd_pressures(s, cfg));
    if (pd->lattice_kind != PD_LATTICE_SQUARE && cfg->pressure_count > 0)
        return cfg_fail_at(s, "pressure_loads",
                           "with %s: a pressure acts on the square lattice's cell faces; "
                           "expected no pressure_loads, or solid.lattice.kind: square",
                           pd->lattice_kind == PD_LATTICE_POLAR ? "a polar lattice"
                                                                : "a mesh's points (kind: abaqus)");
    TRY(read_contact(s, pd));
    CfgNode *c;
    TRY(cfg_opt_map(s, "correspondence", &c));
    int force = CPD_FORCE_BOND_ASSOCIATED, family = CPD_FAMILY_SQUARE;
    cfg->rk_order = 2;
    /* C_s = 0.5: Peridynamics.jl's default for this penalty (ZEMSilling,
     * notes 1c.3), so the control model is the one most users run; on a
     * periodic patch it lifts every spurious zero-energy mode of the bare
     * model (tests/unit/solid/correspondence/test_zero_energy.c: the smallest nonzero
     * eigenvalue from 1.1e-3 to 0.17 of the largest) while it moves the
     * speeds of a 20 h wave by +0.1 % (P) and +0.4 % (S) only
     * (tests/unit/solid/correspondence/test_classic.c) */
    double stabilisation = 0.5;
    if (c) {
        TRY(cfg_opt_enum(c, "force", CPD_FORCE_NAMES, CPD_FORCE_BOND_ASSOCIATED, &force));
        bool given = true;
        if (force == CPD_FORCE_CLASSIC)
            TRY(cfg_opt_double(c, "stabilisation", stabilisation, &stabilisation));
        else
            TRY(cfg_maybe_double(c, "stabilisation", &stabilisation, &given));
        if (given && force != CPD_FORCE_CLASSIC)
            return cfg_fail_at(c, "stabilisation",
                               "the zero-energy stabilisation belongs to the classic "
                               "correspondence force (the %s force has no zero-energy modes); "
                               "expected force: classic, or no stabilisation",
                               CPD_FORCE_NAMES[force]);
        if (!(stabilisation >= 0.0))
            return cfg_fail_at(c, "stabilisation", "must be >= 0, got %g", stabilisation);
        TRY(cfg_opt_enum(c, "family", CPD_FAMILY_NAMES, CPD_FAMILY_SQUARE, &family));
        int kernel;
        TRY(cfg_opt_enum(c, "kernel", RK_KERNEL_NAMES, RK_KERNEL_CUBIC_TENSOR, &kernel));
        cfg->kernel = (RkKernel)kernel;
        int64_t order;
        TRY(cfg_opt_int(c, "rk_order", 2, &order));
        if (order < 1 || order > 3)
            return cfg_fail_at(c, "rk_order",
                               "%lld; expected 1 (linear consistency), 2 (quadratic, the "
                               "paper's) or 3 (cubic where the family fits one)",
                               (long long)order);
        cfg->rk_order = (int)order;
        int frame;
        TRY(cfg_opt_enum(c, "frame", CPD_FRAME_NAMES, CPD_FRAME_LAGRANGIAN, &frame));
        if (frame == CPD_FRAME_SEMI_LAGRANGIAN && force != CPD_FORCE_BOND_ASSOCIATED)
            return cfg_fail_at(c, "frame",
                               "semi_lagrangian with the %s force: the semi-Lagrangian form "
                               "is the bond-associated force's; expected force: "
                               "bond_associated, or frame: lagrangian",
                               CPD_FORCE_NAMES[force]);
        cfg->frame = (CpdFrame)frame;
        TRY(cfg_end_map(c));
    }
    cfg->force = (CpdForce)force;
    cfg->stabilisation = force == CPD_FORCE_CLASSIC ? stabilisation : 0.0;
    cfg->family = (CpdFamily)family;
    pd->integrator = PD_VELOCITY_VERLET;
    return NSPD_OK;
}

static const char *const FORMULATION_NAMES[] = {"bond", "correspondence", NULL};

int case_read_solid(CfgNode *s, SolidConfig *out) {
    memset(out, 0, sizeof *out);
    cfg_node_place(s, out->where, sizeof out->where);
    int formulation;
    TRY(cfg_opt_enum(s, "formulation", FORMULATION_NAMES, 0, &formulation));
    /* the kind is set with the model's configuration, so that
     * solid_config_free frees what a failed read left */
    if (formulation == 1) {
        CpdConfig *cpd;
        TRY(nspd_alloc(&cpd, 1, sizeof *cpd));
        out->kind = SOLID_CORRESPONDENCE;
        out->model = cpd;
        /* a mesh's sets are read while the solid is (case_mesh.h) */
        CaseMesh mesh = {0};
        const int status = read_correspondence(s, cpd, &mesh);
        case_mesh_free(&mesh);
        TRY(status);
    } else {
        PdConfig *pd;
        TRY(nspd_alloc(&pd, 1, sizeof *pd));
        out->kind = SOLID_BOND;
        out->model = pd;
        TRY(read_bond(s, pd));
    }
    return cfg_end_map(s);
}
