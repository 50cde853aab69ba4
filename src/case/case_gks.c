/* The `flow:` section of a case file -> GksCaseConfig.
 *
 * A flow state is written {density, velocity: [u, v], pressure} or with
 * temperature instead of pressure (p = rho R T), or as the word
 * `free_stream`. The free stream itself may be given in SI, or by Mach and
 * Reynolds numbers over a reference length (docs/CASES.md, "Non-dimensional
 * cases"): then U = Ma sqrt(gamma p/rho) along `angle_deg`, and the
 * viscosity at the free-stream temperature is mu = rho U L / Re. */
#include "case/case_gks.h"

#include "core/mem.h"
#include "core/status.h"
#include "couple/ghost/ibm.h"
#include "flow/gks/field_sample.h"
#include "case/case_bodies.h"
#include "case/case_shapes.h"
#include "io/vtk_read.h"
#include "io/cfg_read.h"

#include <math.h>
#include <string.h>

static const char *const VISCOSITY_NAMES[] = {"none", "constant", "power", "sutherland", NULL};
static const char *const FACE_KEYS[4] = {"x_min", "x_max", "y_min", "y_max"};

typedef struct {
    double gamma, R;
    const GksCaseConfig *flow; /* for `free_stream` */
} StateContext;

/* map[key] as a state: a map or the word free_stream. */
static int read_state(CfgNode *map, const char *key, const StateContext *sc, FlowPrim *out) {
    CfgNode *node = cfg_map_find(map, key);
    if (!node || node->is_null)
        return cfg_fail_at(map, key,
                           "missing required key; expected a "
                           "state {density, velocity, pressure} "
                           "or free_stream");
    if (node->kind == CFG_SCALAR) {
        node->used = true;
        if (strcmp(node->text, "free_stream") != 0)
            return cfg_fail(node,
                            "'%s' is not a state; expected free_stream or a map {density, "
                            "velocity, pressure}",
                            node->text);
        if (!sc->flow->has_free_stream)
            return cfg_fail(node, "no free_stream is defined; expected flow.free_stream first");
        *out = sc->flow->free_stream;
        return NSPD_OK;
    }
    CfgNode *m;
    TRY(cfg_req_map(map, key, &m));
    double v[2] = {0, 0}, zero[2] = {0, 0};
    TRY(cfg_req_double(m, "density", &out->rho));
    TRY(cfg_check_positive(m, "density", out->rho, "a density in kg/m^3"));
    TRY(cfg_opt_vec(m, "velocity", 2, zero, v));
    out->u = v[0];
    out->v = v[1];
    bool has_p, has_t;
    double T = 0;
    TRY(cfg_maybe_double(m, "pressure", &out->p, &has_p));
    TRY(cfg_maybe_double(m, "temperature", &T, &has_t));
    if (has_p == has_t)
        return cfg_fail(m, "%s; expected either pressure or temperature",
                        has_p ? "both pressure and temperature given"
                              : "no pressure or temperature");
    if (has_t) {
        TRY(cfg_check_positive(m, "temperature", T, "a temperature in K"));
        out->p = out->rho * sc->R * T;
    }
    TRY(cfg_check_positive(m, has_p ? "pressure" : "temperature", out->p, "a positive pressure"));
    return cfg_end_map(m);
}

static int read_gas(CfgNode *flow, GksConfig *c) {
    CfgNode *g;
    TRY(cfg_opt_map(flow, "gas", &g));
    if (!g) {
        g = cfg_map_add_collection(flow, "gas", CFG_MAP, CFG_FROM_DEFAULT);
        if (!g) return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
        g->used = true;
    }
    TRY(cfg_opt_double(g, "gamma", 1.4, &c->gamma));
    if (!(c->gamma > 1.0 && c->gamma <= 5.0 / 3.0 + 1e-12))
        return cfg_fail_at(g, "gamma",
                           "%g is outside (1, 5/3]; expected the ratio of specific "
                           "heats of a gas",
                           c->gamma);
    TRY(cfg_opt_double(g, "gas_constant", 287.0, &c->gas_constant));
    TRY(cfg_check_positive(g, "gas_constant", c->gas_constant, "R in J/(kg K)"));
    TRY(cfg_opt_double(g, "prandtl", 0.72, &c->prandtl));
    TRY(cfg_check_positive(g, "prandtl", c->prandtl, "the Prandtl number"));
    return NSPD_OK; /* gas.viscosity is read (and gas closed) after the free stream */
}

/* gas.viscosity needs the free stream when mu comes from a Reynolds number. */
static int read_viscosity(CfgNode *flow, GksCaseConfig *fc, bool has_reynolds, double mu_inf,
                          double T_inf) {
    GksConfig *c = &fc->solver;
    CfgNode *g = cfg_map_find(flow, "gas");
    CfgNode *v;
    TRY(cfg_opt_map(g, "viscosity", &v));
    if (!v) {
        v = cfg_map_add_collection(g, "viscosity", CFG_MAP, CFG_FROM_DEFAULT);
        if (!v) return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
        v->used = true;
    }
    int law;
    TRY(cfg_opt_enum(v, "law", VISCOSITY_NAMES, has_reynolds ? VISCOSITY_CONSTANT : VISCOSITY_NONE,
                     &law));
    c->viscosity = (ViscosityLaw)law;
    if (law != VISCOSITY_NONE) {
        if (has_reynolds) {
            if (cfg_map_find(v, "mu"))
                return cfg_fail_at(v, "mu",
                                   "given together with free_stream.reynolds; expected "
                                   "one of them");
            c->mu_ref = mu_inf;
        } else {
            TRY(cfg_req_double(v, "mu", &c->mu_ref));
            TRY(cfg_check_positive(v, "mu", c->mu_ref, "the dynamic viscosity in Pa s"));
        }
    }
    if (law == VISCOSITY_POWER || law == VISCOSITY_SUTHERLAND) {
        if (has_reynolds && cfg_map_find(v, "T_ref"))
            return cfg_fail_at(v, "T_ref",
                               "with free_stream.reynolds the reference temperature is "
                               "the free stream's; expected no T_ref");
        if (has_reynolds)
            c->T_ref = T_inf;
        else
            TRY(cfg_req_double(v, "T_ref", &c->T_ref));
        TRY(cfg_check_positive(v, "T_ref", c->T_ref, "the reference temperature in K"));
    }
    if (law == VISCOSITY_POWER) TRY(cfg_opt_double(v, "omega", 0.76, &c->omega));
    if (law == VISCOSITY_SUTHERLAND) {
        TRY(cfg_opt_double(v, "S", 110.4, &c->sutherland_S));
        TRY(cfg_check_positive(v, "S", c->sutherland_S, "Sutherland's constant in K"));
    }
    TRY(cfg_end_map(v));
    return cfg_end_map(g);
}

/* free_stream: SI state, or {mach, reynolds, length, density, pressure|temperature, angle_deg}. */
static int read_free_stream(CfgNode *flow, GksCaseConfig *fc, bool *has_reynolds, double *mu_inf) {
    GksConfig *c = &fc->solver;
    *has_reynolds = false;
    CfgNode *f = cfg_map_find(flow, "free_stream");
    if (!f || f->is_null) {
        if (f) f->used = true;
        return NSPD_OK;
    }
    fc->has_free_stream = true;
    if (cfg_map_find(f, "mach")) {
        TRY(cfg_req_map(flow, "free_stream", &f));
        double mach, angle, T = 0;
        TRY(cfg_req_double(f, "mach", &mach));
        TRY(cfg_check_positive(f, "mach", mach, "the free-stream Mach number"));
        TRY(cfg_req_double(f, "density", &fc->free_stream.rho));
        TRY(cfg_check_positive(f, "density", fc->free_stream.rho, "a density"));
        bool has_p, has_t;
        TRY(cfg_maybe_double(f, "pressure", &fc->free_stream.p, &has_p));
        TRY(cfg_maybe_double(f, "temperature", &T, &has_t));
        if (has_p == has_t) return cfg_fail(f, "expected either pressure or temperature");
        if (has_t) fc->free_stream.p = fc->free_stream.rho * c->gas_constant * T;
        TRY(cfg_check_positive(f, has_p ? "pressure" : "temperature", fc->free_stream.p,
                               "a positive pressure"));
        TRY(cfg_opt_double(f, "angle_deg", 0.0, &angle));
        double speed = mach * sqrt(c->gamma * fc->free_stream.p / fc->free_stream.rho);
        fc->free_stream.u = speed * cos(angle * M_PI / 180.0);
        fc->free_stream.v = speed * sin(angle * M_PI / 180.0);
        TRY(cfg_opt_double(f, "length", 1.0, &fc->reference_length));
        TRY(cfg_check_positive(f, "length", fc->reference_length, "the reference length in m"));
        bool has_re;
        double re = 0;
        TRY(cfg_maybe_double(f, "reynolds", &re, &has_re));
        if (has_re) {
            TRY(cfg_check_positive(f, "reynolds", re, "the Reynolds number rho U L / mu"));
            *has_reynolds = true;
            *mu_inf = fc->free_stream.rho * speed * fc->reference_length / re;
        }
        return cfg_end_map(f);
    }
    StateContext sc = {c->gamma, c->gas_constant, fc};
    TRY(read_state(flow, "free_stream", &sc, &fc->free_stream));
    return NSPD_OK;
}

static int read_axis(CfgNode *grid, const char *key, double *start, int *count,
                     GridSegment *segments) {
    CfgNode *a;
    TRY(cfg_req_map(grid, key, &a));
    TRY(cfg_opt_double(a, "start", 0.0, start));
    CfgNode *seq;
    TRY(cfg_req_seq(a, "segments", &seq));
    if (seq->count < 1 || seq->count > FLOW_MAX_SEGMENTS)
        return cfg_fail(seq, "%d segments; expected 1 to %d", seq->count, FLOW_MAX_SEGMENTS);
    *count = seq->count;
    double total = 0.0; /* the axis's cells so far */
    for (int i = 0; i < seq->count; i++) {
        CfgNode *s = seq->child[i];
        GridSegment *g = &segments[i];
        if (s->kind != CFG_MAP)
            return cfg_fail(s, "not a segment; expected {length, cells} or {length, spacing} or "
                               "{length, spacing_start, spacing_end}");
        TRY(cfg_req_double(s, "length", &g->length));
        TRY(cfg_check_positive(s, "length", g->length, "the segment length in m"));
        int64_t cells = 0;
        bool has_h, has_h0, has_h1;
        double h = 0;
        TRY(cfg_maybe_double(s, "spacing", &h, &has_h));
        TRY(cfg_maybe_double(s, "spacing_start", &g->h_start, &has_h0));
        TRY(cfg_maybe_double(s, "spacing_end", &g->h_end, &has_h1));
        CfgNode *cn = cfg_map_find(s, "cells");
        if (cn && !cn->is_null) {
            TRY(cfg_req_int(s, "cells", &cells));
            if (cells < 1 || cells > 100000000)
                return cfg_fail_at(s, "cells", "%lld cells; expected 1 to 1e8", (long long)cells);
        } else if (cn) {
            cn->used = true;
        }
        g->cells = (int)cells;
        if (has_h0 != has_h1)
            return cfg_fail(s, "a stretched segment needs both spacing_start and spacing_end");
        if (has_h && has_h0)
            return cfg_fail(s, "spacing given with spacing_start/end; expected one form");
        if (has_h) {
            TRY(cfg_check_positive(s, "spacing", h, "the cell size in m"));
            if (h > g->length)
                return cfg_fail_at(
                    s, "spacing",
                    "%g m, larger than the segment's %g m; expected at most its length", h,
                    g->length);
            g->h_start = h;
            g->h_end = 0;
        } else if (has_h0) {
            TRY(cfg_check_positive(s, "spacing_start", g->h_start, "the first cell size in m"));
            TRY(cfg_check_positive(s, "spacing_end", g->h_end, "the last cell size in m"));
            if (g->h_start + g->h_end >= g->length)
                return cfg_fail(s,
                                "spacings %g and %g do not fit in a segment of %g m; expected a "
                                "longer segment or smaller cells",
                                g->h_start, g->h_end, g->length);
        } else if (!cells) {
            return cfg_fail(s, "no cell size; expected cells, spacing, or spacing_start and "
                               "spacing_end");
        } else {
            g->h_start = g->length / (double)cells;
        }
        total += grid_segment_cells(g); /* as the grid will count them, before it is built */
        if (!(total <= GRID_MAX_AXIS_CELLS))
            return cfg_fail_at(s, "length",
                               "%.3g cells on the %s axis up to this segment (%g m in cells of %g "
                               "m); expected at most %d: larger cells or a shorter segment",
                               total, key, g->length, g->h_start, GRID_MAX_AXIS_CELLS);
        TRY(cfg_end_map(s));
    }
    return cfg_end_map(a);
}

static int read_face(CfgNode *bcs, int face, const StateContext *sc, FlowFaceBc *out) {
    CfgNode *node = cfg_map_find(bcs, FACE_KEYS[face]);
    if (!node)
        return cfg_fail_at(bcs, FACE_KEYS[face],
                           "missing required key; expected a "
                           "boundary condition {type: ...}");
    node->used = true;
    int count = node->kind == CFG_SEQ ? node->count : 1;
    if (node->kind == CFG_SCALAR || count < 1 || count > FLOW_BC_MAX_SEGMENTS)
        return cfg_fail(node,
                        "expected a boundary condition {type: ...} or a list of 1 to %d of "
                        "them along the face",
                        FLOW_BC_MAX_SEGMENTS);
    out->count = count;
    for (int k = 0; k < count; k++) {
        CfgNode *m = node->kind == CFG_SEQ ? node->child[k] : node;
        FlowBc *bc = &out->seg[k];
        if (m->kind != CFG_MAP) return cfg_fail(m, "expected a boundary condition {type: ...}");
        int kind;
        TRY(cfg_req_enum(m, "type", FLOW_BC_NAMES, &kind));
        bc->kind = (FlowBcKind)kind;
        if (k > 0) {
            TRY(cfg_req_double(m, "from", &bc->start));
            if (bc->start <= out->seg[k - 1].start && k > 1)
                return cfg_fail_at(m, "from", "segments out of order; expected increasing 'from'");
        }
        switch (bc->kind) {
        case BC_SUPERSONIC_INFLOW:
        case BC_SUBSONIC_INFLOW:
            TRY(read_state(m, "state", sc, &bc->state));
            break;
        case BC_MOVING_SHOCK_INFLOW:
            if (cfg_map_find(m, "shock_mach")) {
                double ms;
                FlowPrim ahead;
                TRY(cfg_req_double(m, "shock_mach", &ms));
                if (!(ms > 1.0)) return cfg_fail_at(m, "shock_mach", "expected a Mach number > 1");
                TRY(read_state(m, "ahead", sc, &ahead));
                int dir = face == 0 || face == 2 ? +1 : -1;
                flow_shock_post_state(&ahead, ms, sc->gamma, dir, &bc->state);
            } else {
                TRY(read_state(m, "state", sc, &bc->state));
            }
            break;
        case BC_SUBSONIC_OUTFLOW:
            TRY(cfg_req_double(m, "pressure", &bc->pressure));
            TRY(cfg_check_positive(m, "pressure", bc->pressure, "the back pressure in Pa"));
            break;
        case BC_NOSLIP_ISOTHERMAL:
            TRY(cfg_req_double(m, "temperature", &bc->wall_temperature));
            TRY(cfg_check_positive(m, "temperature", bc->wall_temperature,
                                   "the wall temperature "
                                   "in K"));
            TRY(cfg_opt_double(m, "wall_velocity", 0.0, &bc->wall_velocity));
            break;
        case BC_NOSLIP_ADIABATIC:
            TRY(cfg_opt_double(m, "wall_velocity", 0.0, &bc->wall_velocity));
            break;
        default:
            break;
        }
        TRY(cfg_end_map(m));
    }
    return NSPD_OK;
}

/* The source of initial.from from the file's arrays (path for messages). */
static int fill_source(const char *path, const VtkRectilinear *vtr, FlowFieldSource *f) {
    const VtkCellArray *rho = vtk_find_cell_array(vtr, "density", 1),
                       *vel = vtk_find_cell_array(vtr, "velocity", 3),
                       *p = vtk_find_cell_array(vtr, "pressure", 1),
                       *kind = vtk_find_cell_array(vtr, "cell_kind", 1);
    if (!rho || !vel || !p)
        return NSPD_FAIL(NSPD_ERR_INPUT, "'%s' has no %s array", path,
                         !rho   ? "density"
                         : !vel ? "velocity (3 components)"
                                : "pressure");
    if (vtr->n[2] != 1)
        return NSPD_FAIL(NSPD_ERR_INPUT, "'%s' is %d cells deep; expected a 2D field", path,
                         vtr->n[2]);
    TRY(flow_field_source_create(f, vtr->n[0], vtr->n[1], vtr->face[0], vtr->face[1]));
    for (int64_t k = 0; k < (int64_t)f->nx * f->ny; k++) {
        f->rho[k] = rho->data[k];
        f->u[k] = vel->data[3 * k];
        f->v[k] = vel->data[3 * k + 1];
        f->p[k] = p->data[k];
        f->valid[k] = !kind || kind->data[k] != FLOW_CELL_SOLID;
        if (f->valid[k] && !(f->rho[k] > 0.0 && f->p[k] > 0.0))
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "'%s': cell %lld holds density %g, pressure %g; expected a "
                             "physical state",
                             path, (long long)k, f->rho[k], f->p[k]);
    }
    return NSPD_OK;
}

/* initial.from: an earlier run's flow_NNNNN.vtr, loaded into fc->field. */
static int read_field(CfgNode *ini, GksCaseConfig *fc) {
    const char *file;
    TRY(cfg_req_string(ini, "from", &file));
    CfgNode *node = cfg_map_find(ini, "from");
    for (const char *const *key = (const char *const[]){"state", "regions", "vortex", NULL}; *key;
         key++)
        if (cfg_map_find(ini, *key))
            return cfg_fail_at(ini, *key, "given together with 'from'; expected one of them");
    if (!fc->has_free_stream)
        return cfg_fail(node, "no flow.free_stream; a case started from a field needs one as the "
                              "reference state of its coefficients");
    char path[4096];
    cfg_resolve_path(node, file, path, sizeof path);
    VtkRectilinear vtr;
    int status = vtk_read_rectilinear(path, &vtr);
    if (status == NSPD_OK) status = fill_source(path, &vtr, &fc->field);
    fc->has_field = status == NSPD_OK;
    vtk_rectilinear_free(&vtr);
    if (status == NSPD_OK) return NSPD_OK;
    char why[1024]; /* cfg_fail replaces the message it is given */
    snprintf(why, sizeof why, "%s", nspd_error_message());
    return cfg_fail(node, "%s", why);
}

static int read_initial(CfgNode *flow, GksCaseConfig *fc, const StateContext *sc) {
    GksConfig *c = &fc->solver;
    CfgNode *ini;
    TRY(cfg_req_map(flow, "initial", &ini));
    if (cfg_map_find(ini, "from")) {
        TRY(read_field(ini, fc));
        c->initial = fc->free_stream; /* unused by the field; kept as the reference */
    } else {
        TRY(read_state(ini, "state", sc, &c->initial));
    }
    CfgNode *seq;
    TRY(cfg_opt_seq(ini, "regions", &seq));
    if (seq) {
        TRY(nspd_alloc(&fc->regions, (size_t)seq->count, sizeof(FlowRegion)));
        fc->region_count = seq->count;
        for (int i = 0; i < seq->count; i++) {
            CfgNode *m = seq->child[i];
            if (m->kind != CFG_MAP) return cfg_fail(m, "expected {region: [shapes], state: {...}}");
            TRY(case_read_shapes(m, "region", 2, true, &fc->regions[i].shapes));
            TRY(read_state(m, "state", sc, &fc->regions[i].state));
            TRY(cfg_end_map(m));
        }
        c->regions = fc->regions;
        c->region_count = fc->region_count;
    }
    CfgNode *v;
    TRY(cfg_opt_map(ini, "vortex", &v));
    if (v) {
        if (seq) return cfg_fail(v, "vortex with regions; expected one of them");
        fc->has_vortex = true;
        FlowVortex *vx = &fc->vortex;
        double centre[2];
        TRY(cfg_req_vec(v, "center", 2, centre));
        TRY(cfg_req_double(v, "strength", &vx->strength));
        vx->x0 = centre[0];
        vx->y0 = centre[1];
        vx->gamma = c->gamma;
        vx->rho_inf = c->initial.rho;
        vx->u_inf = c->initial.u;
        vx->v_inf = c->initial.v;
        vx->p_inf = c->initial.p;
        TRY(cfg_end_map(v));
    }
    int64_t quadrature;
    TRY(cfg_opt_int(ini, "quadrature", 1, &quadrature));
    TRY(cfg_check_range(ini, "quadrature", (double)quadrature, 1, 4,
                        "Gauss points per cell and axis, 1 to 4"));
    c->init_quadrature = (int)quadrature;
    TRY(cfg_opt_bool(ini, "area_fractions", false, &c->init_area_fractions));
    if (c->init_area_fractions) {
        if (!seq || v)
            return cfg_fail_at(ini, "area_fractions",
                               "true without regions (or with a vortex); expected regions");
        for (int i = 0; i < fc->region_count; i++) {
            const ShapeSet *s = &fc->regions[i].shapes;
            if (s->count != 1 ||
                (s->shapes[0].kind != SHAPE_DISC && s->shapes[0].kind != SHAPE_RECTANGLE))
                return cfg_fail(seq->child[i],
                                "a region of %d shapes (or not a disc or rectangle) with "
                                "area_fractions; expected one disc or rectangle per region",
                                s->count);
            double lo[3], hi[3];
            shapeset_bounds(s, 2, lo, hi);
            for (int k = 0; k < i; k++) {
                double lo2[3], hi2[3];
                shapeset_bounds(&fc->regions[k].shapes, 2, lo2, hi2);
                if (lo[0] < hi2[0] && lo2[0] < hi[0] && lo[1] < hi2[1] && lo2[1] < hi[1])
                    return cfg_fail(seq->child[i],
                                    "this region's box overlaps region %d's with "
                                    "area_fractions; expected regions apart",
                                    k);
            }
        }
    }
    return cfg_end_map(ini);
}

static int read_numerics(CfgNode *flow, GksConfig *c) {
    CfgNode *n;
    TRY(cfg_opt_map(flow, "numerics", &n));
    if (!n) {
        n = cfg_map_add_collection(flow, "numerics", CFG_MAP, CFG_FROM_DEFAULT);
        if (!n) return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
        n->used = true;
    }
    int limiter;
    TRY(cfg_opt_enum(n, "limiter", FLOW_LIMITER_NAMES, LIMITER_VAN_LEER, &limiter));
    c->limiter = (FlowLimiter)limiter;
    TRY(cfg_opt_double(n, "cfl", 0.5, &c->cfl));
    TRY(cfg_check_range(n, "cfl", c->cfl, 1e-6, 1.0, "a CFL number in (0, 1]"));
    TRY(cfg_opt_double(n, "shock_dissipation", 1.0, &c->tau_jump_c));
    TRY(cfg_check_range(n, "shock_dissipation", c->tau_jump_c, 0.0, 100.0,
                        "C >= 0 in tau_n = tau + C dt |pL - pR| / (pL + pR)"));
    TRY(cfg_opt_double(n, "collision_floor", 0.0, &c->tau_eps));
    TRY(cfg_check_range(n, "collision_floor", c->tau_eps, 0.0, 1.0, "eps >= 0 in tau_n += eps dt"));
    return cfg_end_map(n);
}

int case_read_gks(CfgNode *flow, GksCaseConfig *fc, GhostCouplingConfig *walls) {
    memset(fc, 0, sizeof *fc);
    memset(walls, 0, sizeof *walls);
    GksConfig *c = &fc->solver;
    gks_config_default(c);
    TRY(read_gas(flow, c));
    bool has_reynolds;
    double mu_inf = 0;
    TRY(read_free_stream(flow, fc, &has_reynolds, &mu_inf));
    double T_inf =
        fc->has_free_stream ? fc->free_stream.p / (fc->free_stream.rho * c->gas_constant) : 0.0;
    TRY(read_viscosity(flow, fc, has_reynolds, mu_inf, T_inf));
    CfgNode *grid;
    TRY(cfg_req_map(flow, "grid", &grid));
    TRY(read_axis(grid, "x", &c->x0, &c->segment_count[0], c->segments[0]));
    TRY(read_axis(grid, "y", &c->y0, &c->segment_count[1], c->segments[1]));
    TRY(cfg_end_map(grid));
    TRY(read_numerics(flow, c));
    StateContext sc = {c->gamma, c->gas_constant, fc};
    CfgNode *bcs;
    TRY(cfg_req_map(flow, "boundaries", &bcs));
    for (int f = 0; f < 4; f++) TRY(read_face(bcs, f, &sc, &c->bc[f]));
    TRY(cfg_end_map(bcs));
    TRY(read_initial(flow, fc, &sc));
    /* the fixed bodies are walls of a ghost-cell coupling with no solid */
    TRY(case_read_bodies(flow, "bodies", false, &walls->bodies));
    FsiConfig *w = &walls->fsi;
    TRY(cfg_opt_double(flow, "soft_start", 0.0, &w->soft_start));
    TRY(cfg_check_range(flow, "soft_start", w->soft_start, 0.0, 1e30,
                        "a length >= 0 in m over which the flow starts at the wall velocity"));
    TRY(cfg_opt_enum(flow, "ghost_faces", IBM_GHOST_FACE_NAMES, IBM_FACES_REFLECTED,
                     &w->ghost_faces));
    if (w->soft_start > 0 && walls->bodies.count == 0)
        return cfg_fail_at(flow, "soft_start",
                           "a soft start without flow.bodies; expected bodies "
                           "(a coupled solid takes coupling.soft_start)");
    if (w->soft_start > 0 && fc->has_field)
        return cfg_fail_at(flow, "soft_start",
                           "a soft start would stop the flow of initial.from near the bodies; "
                           "expected soft_start: 0");
    return cfg_end_map(flow);
}
