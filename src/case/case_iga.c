/* The `flow:` section of an IGA case -> IgaFlowConfig (case_iga.h). */
#include "case/case_iga.h"

#include "case/case_gks.h"
#include "core/mem.h"
#include "core/status.h"
#include "io/cfg_read.h"

#include <math.h>
#include <string.h>

static const char *const INITS[] = {"lumped_l2", "nodal", "l2", NULL};
static const char *const YDOT0S[] = {"zero", "consistent", NULL};
static const char *const LIMITERS[] = {"none", "positivity", "convex", NULL};
static const char *const FACE_KEYS[4] = {"x_min", "x_max", "y_min", "y_max"};

/* flow.iga: the method's own keys, with the paper's code's values as
 * defaults (../shared/notes/iga_flow.md), except the DC cap (on: uncapped,
 * a 2D strip is unstable from round-off, docs/VALIDATION.md). */
static int read_method_map(CfgNode *m, IgaConfig *c) {
    int64_t degree = 2, passes = 3, iterations = 10;
    int init = IGA_INIT_LUMPED_L2, ydot0 = IGA_YDOT0_ZERO, limiter = IGA_LIMITER_DEFAULT;
    c->c_dc = 2.5, c->dc_cap = true, c->rho_inf = 0.5, c->tau_dt = 0.0, c->cfl = 0.3;
    if (m) {
        TRY(cfg_opt_int(m, "degree", 2, &degree));
        if (degree < 1 || degree > 3)
            return cfg_fail_at(m, "degree", "%lld; expected 1, 2 (the paper's) or 3",
                               (long long)degree);
        TRY(cfg_opt_double(m, "dc", 2.5, &c->c_dc));
        TRY(cfg_check_range(m, "dc", c->c_dc, 0.0, 100.0,
                            "the discontinuity-capturing constant (2.5; 0: off)"));
        TRY(cfg_opt_bool(m, "dc_cap", true, &c->dc_cap));
        TRY(cfg_opt_int(m, "passes", 3, &passes));
        if (passes < 1 || passes > 100)
            return cfg_fail_at(m, "passes", "%lld; expected 1 to 100 corrector passes",
                               (long long)passes);
        TRY(cfg_opt_double(m, "rho_inf", 0.5, &c->rho_inf));
        TRY(cfg_check_range(m, "rho_inf", c->rho_inf, 0.0, 1.0,
                            "the spectral radius at infinity in [0, 1]"));
        TRY(cfg_opt_int(m, "tau_iterations", 10, &iterations));
        if (iterations < 1 || iterations > 50)
            return cfg_fail_at(m, "tau_iterations", "%lld; expected 1 to 50",
                               (long long)iterations);
        TRY(cfg_opt_double(m, "tau_dt", 0.0, &c->tau_dt));
        TRY(cfg_check_range(m, "tau_dt", c->tau_dt, 0.0, 1e30,
                            "the time step in s that tau uses (0: the step taken)"));
        TRY(cfg_opt_double(m, "cfl", 0.3, &c->cfl));
        TRY(cfg_check_range(m, "cfl", c->cfl, 1e-6, 0.5,
                            "a Courant number of at most 0.5 (the explicit passes blow up "
                            "above about 0.6)"));
        TRY(cfg_opt_enum(m, "init", INITS, IGA_INIT_LUMPED_L2, &init));
        TRY(cfg_opt_enum(m, "ydot0", YDOT0S, IGA_YDOT0_ZERO, &ydot0));
        TRY(cfg_opt_enum(m, "limiter", LIMITERS, IGA_LIMITER_DEFAULT, &limiter));
        TRY(cfg_end_map(m));
    }
    c->degree = (int)degree, c->passes = (int)passes, c->db_iterations = (int)iterations;
    c->init = (IgaInit)init, c->ydot0 = (IgaYdot0)ydot0, c->limiter = (IgaLimiterKind)limiter;
    return NSPD_OK;
}

static int read_method(CfgNode *flow, IgaConfig *c) {
    CfgNode *m;
    TRY(cfg_opt_map(flow, "iga", &m));
    return read_method_map(m, c);
}

int case_check_iga_method(CfgNode *flow) {
    CfgNode *m;
    TRY(cfg_opt_map(flow, "iga", &m));
    if (!m) return NSPD_OK;
    /* the copy takes the defaults; its parent is flow, so that a refusal
     * names flow.iga.KEY at the original's place */
    CfgNode *copy = cfg_node_clone(m, flow);
    if (!copy) return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
    IgaConfig scratch;
    const int status = read_method_map(copy, &scratch);
    cfg_node_free(copy);
    return status;
}

/* One uniform segment per axis: its elements. */
static int axis_elements(CfgNode *flow, int a, const GksConfig *g, IgaConfig *c) {
    const GridSegment *s = &g->segments[a][0];
    const bool uniform = !(s->h_end > 0.0) || s->h_end == s->h_start;
    CfgNode *grid = cfg_map_find(flow, "grid");
    if (g->segment_count[a] != 1 || !uniform)
        return cfg_fail_at(grid, a == 0 ? "x" : "y",
                           "%d segment(s)%s; expected one uniform segment (the IGA flow's "
                           "B-splines have uniform knots)",
                           g->segment_count[a], uniform ? "" : ", stretched");
    const double cells = grid_segment_cells(s);
    if (!(cells >= 1.0 && cells <= 1e6))
        return cfg_fail_at(grid, a == 0 ? "x" : "y", "%.3g elements; expected 1 to 1e6", cells);
    c->elements[a] = (int)cells;
    c->lo[a] = a == 0 ? g->x0 : g->y0;
    c->hi[a] = c->lo[a] + s->length;
    return NSPD_OK;
}

static IgaState state_of(const FlowPrim *q, double R) {
    return (IgaState){q->p, q->u, q->v, q->p / (q->rho * R)};
}

static int convert(CfgNode *flow, GksCaseConfig *g, IgaFlowConfig *out) {
    const GksConfig *s = &g->solver;
    IgaConfig *c = &out->solver;
    for (int a = 0; a < 2; a++) TRY(axis_elements(flow, a, s, c));
    CfgNode *bcs = cfg_map_find(flow, "boundaries");
    for (int f = 0; f < 4; f++) {
        const FlowBcKind k = s->bc[f].seg[0].kind;
        if (s->bc[f].count != 1 || (k != BC_SLIP_WALL && k != BC_PERIODIC))
            return cfg_fail_at(bcs, FACE_KEYS[f],
                               "%s; expected slip_wall or periodic (what the IGA flow has)",
                               s->bc[f].count != 1 ? "several segments" : FLOW_BC_NAMES[k]);
        c->side[f] = k == BC_PERIODIC ? IGA_SIDE_PERIODIC : IGA_SIDE_SLIP;
    }
    if (s->viscosity != VISCOSITY_NONE && s->viscosity != VISCOSITY_CONSTANT)
        return cfg_fail_at(cfg_map_find(flow, "gas"), "viscosity",
                           "law '%s'; expected none or constant for the IGA flow",
                           s->viscosity == VISCOSITY_POWER ? "power" : "sutherland");
    c->gamma = s->gamma, c->R = s->gas_constant, c->prandtl = s->prandtl;
    c->mu = s->viscosity == VISCOSITY_CONSTANT ? s->mu_ref : 0.0;
    if (g->has_field || g->has_free_stream)
        return cfg_fail_at(flow, g->has_free_stream ? "free_stream" : "initial",
                           "%s; expected an initial state, regions or a vortex for the IGA flow",
                           g->has_field ? "an initial field from a file" : "a free stream");
    out->has_vortex = g->has_vortex;
    out->vortex = g->vortex;
    c->initial = state_of(&s->initial, s->gas_constant);
    c->exact_areas = s->init_area_fractions;
    /* the regions, their shapes moved over */
    if (g->region_count > 0) {
        TRY(nspd_alloc(&out->regions, (size_t)g->region_count, sizeof(IgaRegion)));
        for (int r = 0; r < g->region_count; r++) {
            out->regions[r].shapes = g->regions[r].shapes;
            memset(&g->regions[r].shapes, 0, sizeof g->regions[r].shapes);
            out->regions[r].state = state_of(&g->regions[r].state, s->gas_constant);
            out->region_count = r + 1;
        }
    }
    return iga_config_check(c) == NSPD_OK ? NSPD_OK : cfg_fail(flow, "%s", nspd_error_message());
}

int case_read_iga(CfgNode *flow, IgaFlowConfig *out) {
    memset(out, 0, sizeof *out);
    TRY(read_method(flow, &out->solver));
    /* the GKS flow's numerics are read (and checked) with the rest of its
     * keys and not used: flow.iga has this flow's (one case, either
     * background) */
    GksCaseConfig gks;
    GhostCouplingConfig walls;
    int status = case_read_gks(flow, &gks, &walls);
    if (status == NSPD_OK && walls.bodies.count > 0)
        status = cfg_fail_at(flow, "bodies",
                             "immersed bodies in an IGA case; expected none (they are the GKS "
                             "flow's ghost cells)");
    if (status == NSPD_OK) status = convert(flow, &gks, out);
    gks_case_config_free(&gks);
    ghost_coupling_config_free(&walls);
    return status;
}
