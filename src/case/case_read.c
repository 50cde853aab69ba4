#include "case/case_read.h"

#include "core/hash.h"
#include "core/mem.h"
#include "core/status.h"
#include "case/case_gks.h"
#include "case/case_iga.h"
#include "case/case_pddo.h"
#include "case/case_shapes.h"
#include "case/case_solid.h"
#include "couple/penalty/model.h"
#include "io/cfg_read.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int read_time(CfgNode *root, SimConfig *cfg) {
    CfgNode *t;
    TRY(cfg_req_map(root, "time", &t));
    TRY(cfg_req_double(t, "end", &cfg->end_time));
    TRY(cfg_check_positive(t, "end", cfg->end_time, "the simulated end time in s"));
    /* where time.end was given, for the step-count check made once the
     * stable step is known (sim/sim.c) */
    cfg_node_where(cfg_map_find(t, "end"), cfg->end_time_at, sizeof cfg->end_time_at);
    /* `dt: stable` is the default said aloud: what a --set gives back
     * where a case file fixes its step (the paper's, in the blast cases) */
    const CfgNode *dt = cfg_map_find(t, "dt");
    if (dt && dt->kind == CFG_SCALAR && strcmp(dt->text, "stable") == 0) {
        const char *word;
        TRY(cfg_opt_string(t, "dt", NULL, &word)); /* used */
        cfg->dt = 0.0, cfg->dt_given = false;
    } else {
        TRY(cfg_maybe_double(t, "dt", &cfg->dt, &cfg->dt_given));
        if (cfg->dt_given) TRY(cfg_check_positive(t, "dt", cfg->dt, "a time step in s"));
    }
    TRY(cfg_opt_double(t, "safety_factor", 0.8, &cfg->safety_factor));
    TRY(cfg_check_range(t, "safety_factor", cfg->safety_factor, 1e-6, 1.0,
                        "a fraction of the stable time step in (0, 1]"));
    return cfg_end_map(t);
}

static const char *const SORT_AXES[] = {"x", "y", "z", NULL};

static const char *const TARGETS[] = {"solid", "flow", NULL};
static const char *const FLOW_METHODS[] = {"gks", "pddo", "iga", NULL};

static int read_probe(CfgNode *item, int dim, bool has_solid, ProbeConfig *p, int index) {
    if (item->kind != CFG_MAP)
        return cfg_fail(item, "not a probe; expected a map with 'type: crack_tip | point | line'");
    int kind;
    TRY(cfg_req_enum(item, "type", PROBE_KIND_NAMES, &kind));
    p->kind = (ProbeKind)kind;
    const char *name;
    char fallback[32];
    snprintf(fallback, sizeof fallback, kind == PROBE_CRACK_TIP ? "crack" : "probe%d", index);
    TRY(cfg_opt_string(item, "name", fallback, &name));
    for (const char *c = name; *c; c++)
        if (!((*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z') || (*c >= '0' && *c <= '9') ||
              *c == '_'))
            return cfg_fail_at(item, "name",
                               "'%s' has characters other than letters, digits and _; "
                               "expected a name usable in file and column names",
                               name);
    snprintf(p->name, sizeof p->name, "%s", name);
    int target = has_solid ? PROBE_ON_SOLID : PROBE_ON_FLOW;
    if (p->kind == PROBE_POINT || p->kind == PROBE_LINE)
        TRY(cfg_opt_enum(item, "on", TARGETS, target, &target));
    p->target = (ProbeTarget)target;
    /* its refusals said at `at` where the kind has one (looked up only
     * then: a lookup makes the key one the probe accepts) */
    const bool takes_at =
        p->target == PROBE_ON_FLOW || p->kind == PROBE_POINT || p->kind == PROBE_BRANCHES;
    const CfgNode *at = takes_at ? cfg_map_find(item, "at") : NULL;
    cfg_node_place(at ? at : item, p->where, sizeof p->where);
    if (p->target == PROBE_ON_FLOW) {
        /* a flow point: the cell holding `at`; a flow line: the row or
         * column of cells through `at` */
        TRY(cfg_req_vec(item, "at", 2, p->at));
        if (p->kind == PROBE_LINE) {
            int axis;
            TRY(cfg_opt_enum(item, "along", SORT_AXES, 0, &axis));
            if (axis > 1)
                return cfg_fail_at(item, "along", "no z axis in a 2D flow; expected x or y");
            p->sort_axis = axis;
        }
        return cfg_end_map(item);
    }
    switch (p->kind) {
    case PROBE_CRACK_TIP: {
        double ex[3] = {1, 0, 0}, len2 = 0;
        TRY(cfg_opt_vec(item, "direction", dim, ex, p->direction));
        for (int d = 0; d < dim; d++) len2 += p->direction[d] * p->direction[d];
        if (len2 == 0) return cfg_fail_at(item, "direction", "zero vector; expected a direction");
        TRY(cfg_opt_double(item, "damage_threshold", 0.35, &p->damage_threshold));
        TRY(cfg_check_range(item, "damage_threshold", p->damage_threshold, 0.0, 1.0,
                            "a damage value in [0, 1]"));
        TRY(case_read_shapes(item, "region", dim, false, &p->region));
        break;
    }
    case PROBE_POINT:
        TRY(cfg_req_vec(item, "at", dim, p->at));
        break;
    case PROBE_BRANCHES: {
        if (dim != 2) return cfg_fail_at(item, "type", "branches are measured in 2D only");
        double ex[3] = {1, 0, 0};
        TRY(cfg_req_vec(item, "at", 2, p->at));
        TRY(cfg_opt_vec(item, "direction", 2, ex, p->direction));
        double len = hypot(p->direction[0], p->direction[1]);
        if (len == 0) return cfg_fail_at(item, "direction", "zero vector; expected a direction");
        p->direction[0] /= len;
        p->direction[1] /= len;
        TRY(cfg_opt_double(item, "damage_threshold", 0.35, &p->damage_threshold));
        TRY(cfg_check_range(item, "damage_threshold", p->damage_threshold, 0.0, 1.0,
                            "a damage value in [0, 1]"));
        TRY(cfg_opt_double(item, "length", 0.0, &p->length));
        TRY(cfg_check_range(item, "length", p->length, 0.0, 1e30,
                            "how far ahead to look, m (0: no limit)"));
        TRY(cfg_opt_double(item, "extent", 0.0, &p->extent));
        TRY(cfg_check_range(item, "extent", p->extent, 0.0, 1e30,
                            "the branch span at which to measure, m (0: at the end)"));
        break;
    }
    case PROBE_LINE: {
        TRY(case_read_shapes(item, "region", dim, true, &p->region));
        int axis;
        TRY(cfg_opt_enum(item, "sort", SORT_AXES, 0, &axis));
        if (axis >= dim) return cfg_fail_at(item, "sort", "no z axis in 2D; expected x or y");
        p->sort_axis = axis;
        break;
    }
    default:
        break;
    }
    return cfg_end_map(item);
}

enum { CASE_MAX_HISTORY_ROWS = 10000000, CASE_MAX_FIELD_OUTPUTS = 99999 };

static int read_output(CfgNode *root, SimConfig *cfg, int dim, bool has_solid) {
    CfgNode *o;
    TRY(cfg_opt_map(root, "output", &o));
    if (!o) { /* all defaults: give the resolved case an explicit section */
        o = cfg_map_add_collection(root, "output", CFG_MAP, CFG_FROM_DEFAULT);
        if (!o) return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
        o->used = true;
    }
    OutputConfig *out = &cfg->output;
    TRY(cfg_opt_double(o, "field_interval", cfg->end_time / 10, &out->field_interval));
    TRY(cfg_check_positive(o, "field_interval", out->field_interval, "seconds between outputs"));
    TRY(cfg_opt_double(o, "average_from", cfg->end_time / 2, &out->average_from));
    TRY(cfg_check_range(o, "average_from", out->average_from, 0.0, cfg->end_time,
                        "the time (s) from which force coefficients are averaged, <= time.end"));
    TRY(cfg_opt_double(o, "history_interval", cfg->end_time / 200, &out->history_interval));
    TRY(cfg_check_positive(o, "history_interval", out->history_interval,
                           "seconds between history rows"));
    /* counts that follow from the input are bounded before anything is
     * allocated: the probes keep a record per history row, and field files
     * are numbered with five digits */
    const double rows = cfg->end_time / out->history_interval;
    if (!(rows <= CASE_MAX_HISTORY_ROWS))
        return cfg_fail_at(o, "history_interval",
                           "%g s gives %.3g history rows over time.end = %g s; expected at most "
                           "%.0e rows (a larger interval)",
                           out->history_interval, rows, cfg->end_time,
                           (double)CASE_MAX_HISTORY_ROWS);
    const double fields = cfg->end_time / out->field_interval;
    if (!(fields <= CASE_MAX_FIELD_OUTPUTS))
        return cfg_fail_at(o, "field_interval",
                           "%g s gives %.3g field outputs over time.end = %g s; expected at most "
                           "%d (a larger interval)",
                           out->field_interval, fields, cfg->end_time, CASE_MAX_FIELD_OUTPUTS);
    /* checkpoints (sim/sim_checkpoint.c): by simulated time, by wall time */
    TRY(cfg_opt_double(o, "checkpoint_interval", 0.0, &out->checkpoint_interval));
    TRY(cfg_check_range(o, "checkpoint_interval", out->checkpoint_interval, 0.0, 1e300,
                        "seconds of simulated time between checkpoints, 0 for none"));
    if (out->checkpoint_interval > 0 &&
        !(cfg->end_time / out->checkpoint_interval <= CASE_MAX_FIELD_OUTPUTS))
        return cfg_fail_at(o, "checkpoint_interval",
                           "%g s gives %.3g checkpoints over time.end = %g s; expected at most "
                           "%d (a larger interval)",
                           out->checkpoint_interval, cfg->end_time / out->checkpoint_interval,
                           cfg->end_time, CASE_MAX_FIELD_OUTPUTS);
    TRY(cfg_opt_double(o, "checkpoint_wall_interval", 3600.0, &out->checkpoint_wall_interval));
    TRY(cfg_check_range(o, "checkpoint_wall_interval", out->checkpoint_wall_interval, 0.0, 1e300,
                        "seconds of wall-clock time between checkpoints, 0 for none"));
    TRY(cfg_opt_bool(o, "vtk", true, &out->vtk));
    TRY(cfg_opt_bool(o, "png", true, &out->png));
    TRY(cfg_opt_bool(o, "plots", true, &out->plots));
    int64_t pixels;
    TRY(cfg_opt_int(o, "png_max_pixels", 1000, &pixels));
    TRY(cfg_check_range(o, "png_max_pixels", (double)pixels, 16, 8192,
                        "the longest PNG side in pixels, 16 to 8192"));
    out->png_max_pixels = (int)pixels;
    /* no default is written into case.yaml: without the key the scale
     * comes from the data, which a number there would not repeat */
    out->mach_range_given = cfg_map_find(o, "mach_range") != NULL;
    if (out->mach_range_given) {
        TRY(cfg_req_vec(o, "mach_range", 2, out->mach_range));
        if (!(out->mach_range[0] >= 0.0 && out->mach_range[1] > out->mach_range[0]))
            return cfg_fail_at(o, "mach_range", "[%g, %g]; expected [lo, hi] with 0 <= lo < hi",
                               out->mach_range[0], out->mach_range[1]);
        if (cfg->flow.method != FLOW_METHOD_GKS && cfg->flow.method != FLOW_METHOD_IGA)
            return cfg_fail_at(o, "mach_range",
                               "%s draws no Mach picture; expected no mach_range (a "
                               "compressible flow: flow.method gks or iga)",
                               cfg->flow.method == FLOW_METHOD_NONE ? "a case without a flow"
                                                                    : "the PDDO flow");
    }
    CfgNode *seq;
    TRY(cfg_opt_seq(o, "probes", &seq));
    if (seq) {
        TRY(nspd_alloc(&out->probes, (size_t)seq->count, sizeof(ProbeConfig)));
        out->probe_count = seq->count;
        for (int i = 0; i < seq->count; i++) {
            TRY(read_probe(seq->child[i], dim, has_solid, &out->probes[i], i));
            for (int k = 0; k < i; k++)
                if (strcmp(out->probes[k].name, out->probes[i].name) == 0)
                    return cfg_fail(seq->child[i],
                                    "probe name '%s' used twice; expected unique "
                                    "names",
                                    out->probes[i].name);
        }
    }
    return cfg_end_map(o);
}

/* nspd info's estimate (SimConfig.solid_cost_growth): a correspondence
 * solid with a failure law costs more per sub-step once it breaks: its
 * stable step is then re-estimated by power iteration every 20 steps, and
 * its own sub-steps double where damage lowers that step (substeps_max 2
 * on both blasts); the rest of the growth is not attributed here. The
 * cost per driver sub-step over a whole run against that of the first
 * steps, measured (docs/PERFORMANCE.md "nspd info's estimate"): 2.65 and
 * 3.1 (blast_hollow_square on the GKS and IGA backgrounds), 2.8 and 2.1
 * (blast_hollow_cylinder); this is their mean. An unbreakable body
 * (chamber_detonation's block, plastic) kept its first steps' cost; a
 * bond-based one only loses bonds. */
#define CASE_BREAKING_CPD_GROWTH 2.7

static double breaking_solid_growth(const CfgNode *solid) {
    const CfgNode *form = cfg_map_find(solid, "formulation");
    const CfgNode *failure = cfg_map_find(solid, "failure");
    const CfgNode *law = failure && failure->kind == CFG_MAP ? cfg_map_find(failure, "law") : NULL;
    const bool cpd = form && form->kind == CFG_SCALAR && strcmp(form->text, "correspondence") == 0;
    const bool breaks = law && law->kind == CFG_SCALAR && strcmp(law->text, "none") != 0;
    return cpd && breaks ? CASE_BREAKING_CPD_GROWTH : 1.0;
}

static const char *const WALLS[] = {"adiabatic", "isothermal", NULL};

/* The `coupling:` section: the wall condition of the solid's surface, the
 * start-up and the reference state of the surface loads. */
static int read_coupling(CfgNode *m, SimConfig *cfg) {
    FsiConfig *c = &((GhostCouplingConfig *)cfg->coupling.model)->fsi;
    const GksCaseConfig *f = cfg->flow.model;
    TRY(cfg_opt_enum(m, "hold", FSI_HOLD_NAMES, FSI_HOLD_NONE, &c->hold));
    TRY(cfg_opt_enum(m, "wall", WALLS, IBM_WALL_ADIABATIC, &c->thermal));
    if (c->thermal == IBM_WALL_ISOTHERMAL) {
        TRY(cfg_req_double(m, "wall_temperature", &c->wall_temperature));
        TRY(cfg_check_positive(m, "wall_temperature", c->wall_temperature, "a temperature in K"));
    }
    TRY(cfg_opt_double(m, "soft_start", 0.0, &c->soft_start));
    TRY(cfg_check_range(m, "soft_start", c->soft_start, 0.0, 1e30, "a length >= 0 in m"));
    TRY(cfg_opt_enum(m, "ghost_faces", IBM_GHOST_FACE_NAMES, IBM_FACES_REFLECTED, &c->ghost_faces));
    /* the solid is built unloaded in the gas at its initial pressure */
    const FlowPrim *ref = f->has_free_stream ? &f->free_stream : &f->solver.initial;
    c->reference = (IbmReference){.rho = ref->rho,
                                  .u = ref->u,
                                  .v = ref->v,
                                  .p = ref->p,
                                  .length = f->reference_length > 0 ? f->reference_length : 1.0};
    TRY(cfg_opt_double(m, "ambient_pressure", f->solver.initial.p, &c->reference.p_ambient));
    TRY(cfg_check_range(m, "ambient_pressure", c->reference.p_ambient, 0.0, 1e30,
                        "the pressure (Pa) in which the solid carries no load"));
    return cfg_end_map(m);
}

static const char *const COUPLING_KINDS[] = {"ghost_cell", "penalty", NULL};

/* `coupling: {kind: penalty, ...}`: the volumetric penalty of paper 003
 * (couple/penalty/model.h). */
static int read_penalty(CfgNode *m, SimConfig *cfg) {
    PenaltyConfig *c = cfg->coupling.model;
    TRY(cfg_opt_double(m, "beta", 1.0, &c->beta));
    TRY(cfg_check_range(m, "beta", c->beta, 1e-12, 1e30,
                        "a penalty factor > 0 (the paper's 1/3 to 9)"));
    TRY(cfg_opt_bool(m, "strong", false, &c->strong));
    int integration;
    TRY(cfg_opt_enum(m, "integration", PENALTY_INTEGRATION_NAMES, PENALTY_IMPLICIT, &integration));
    c->integration = (PenaltyIntegration)integration;
    if (c->strong && c->integration == PENALTY_EXPLICIT)
        return cfg_fail_at(m, "integration",
                           "the strong coupling is the penalty's infinite limit, which only the "
                           "implicit relaxation reaches; expected integration: implicit or "
                           "strong: false");
    int constraint;
    TRY(cfg_opt_enum(m, "strong_constraint", PENALTY_STRONG_CONSTRAINT_NAMES,
                     PENALTY_STRONG_EVERY_STEP, &constraint));
    c->strong_constraint = (PenaltyStrongConstraint)constraint;
    TRY(cfg_opt_bool(m, "subtract_fluid", c->strong, &c->subtract_fluid));
    if (c->subtract_fluid && !c->strong)
        return cfg_fail_at(m, "subtract_fluid",
                           "Eq. 20's subtraction of the fluid over the solid belongs to the "
                           "strong coupling; expected strong: true or subtract_fluid: false");
    TRY(cfg_opt_bool(m, "damaged", false, &c->damaged));
    TRY(cfg_opt_double(m, "h", 0.0, &c->h));
    TRY(cfg_check_range(m, "h", c->h, 0.0, 1e30, "a length in m (0: the solid's lattice spacing)"));
    TRY(cfg_opt_double(m, "dt", 0.0, &c->dt));
    TRY(cfg_check_range(m, "dt", c->dt, 0.0, 1e30, "a time in s (0: the solid's stable step)"));
    int transfer, thickness, energy;
    TRY(cfg_opt_enum(m, "transfer", FLOW_TRANSFER_NAMES, FLOW_TRANSFER_QUADRATIC, &transfer));
    TRY(cfg_opt_enum(m, "thickness", PENALTY_THICKNESS_NAMES, PENALTY_DEPTH_CONSISTENT,
                     &thickness));
    TRY(cfg_opt_enum(m, "energy", PENALTY_ENERGY_NAMES, PENALTY_ENERGY_TOTAL, &energy));
    TRY(cfg_opt_bool(m, "seal", false, &c->seal));
    TRY(cfg_opt_double(m, "seal_fraction", 0.75, &c->seal_fraction));
    TRY(cfg_check_range(m, "seal_fraction", c->seal_fraction, 1e-6, 1.0,
                        "the covered fraction of a cell's area in (0, 1] above which its faces "
                        "to other such cells are sealed"));
    c->transfer = (FlowTransferKind)transfer;
    c->thickness = (PenaltyThickness)thickness;
    c->energy = (PenaltyEnergy)energy;
    return cfg_end_map(m);
}

static int read_all(CfgDoc *doc, SimConfig *cfg) {
    CfgNode *root = doc->root;
    const char *name;
    TRY(cfg_req_string(root, "name", &name));
    if (!name[0] || strlen(name) >= SIM_MAX_NAME || strchr(name, '/'))
        return cfg_fail_at(root, "name",
                           "'%s' is not usable as a directory name; expected 1 to %d "
                           "characters without '/'",
                           name, SIM_MAX_NAME - 1);
    snprintf(cfg->name, sizeof cfg->name, "%s", name);
    const char *description;
    TRY(cfg_opt_string(root, "description", "", &description));
    TRY(read_time(root, cfg));
    CfgNode *solid, *flow;
    TRY(cfg_opt_map(root, "solid", &solid));
    TRY(cfg_opt_map(root, "flow", &flow));
    if (!solid && !flow)
        return cfg_fail(root, "nothing to simulate; expected a 'solid' or a 'flow' section");
    if (solid) {
        TRY(case_read_solid(solid, &cfg->solid));
        cfg->solid_cost_growth = breaking_solid_growth(solid);
    }
    GhostCouplingConfig walls = {0};
    int method = 0; /* gks; method is read only when given (gks cases stay as they were) */
    if (flow && cfg_map_find(flow, "method"))
        TRY(cfg_req_enum(flow, "method", FLOW_METHODS, &method));
    if (flow) cfg_node_place(flow, cfg->flow.where, sizeof cfg->flow.where);
    if (flow && method == 1) {
        if (solid)
            return cfg_fail_at(flow, "method",
                               "pddo with a solid; expected no solid section (the PDDO flow "
                               "takes no coupling yet)");
        cfg->flow.method = FLOW_METHOD_PDDO;
        TRY(nspd_alloc(&cfg->flow.model, 1, sizeof(PddoFlowConfig)));
        TRY(case_read_pddo(flow, cfg_map_find(root, "time"), cfg->dt_given, cfg->dt,
                           cfg->flow.model));
    } else if (flow && method == 2) {
        cfg->flow.method = FLOW_METHOD_IGA;
        TRY(nspd_alloc(&cfg->flow.model, 1, sizeof(IgaFlowConfig)));
        TRY(case_read_iga(flow, cfg->flow.model));
    } else if (flow) {
        cfg->flow.method = FLOW_METHOD_GKS;
        /* the IGA flow's own keys: kept, so that one case runs on either
         * background by --set flow.method (docs/CASES.md), and checked as
         * the IGA flow would, so that a misspelt one is found here too */
        TRY(case_check_iga_method(flow));
        int status = nspd_alloc(&cfg->flow.model, 1, sizeof(GksCaseConfig));
        if (status == NSPD_OK) status = case_read_gks(flow, cfg->flow.model, &walls);
        if (status != NSPD_OK) {
            ghost_coupling_config_free(&walls);
            return status;
        }
    }
    if (walls.bodies.count > 0 && !solid) {
        /* fixed bodies: a ghost-cell coupling with rigid walls, measured
         * against the free stream (else the initial state) */
        GhostCouplingConfig *ghost;
        const int status = nspd_alloc(&ghost, 1, sizeof *ghost);
        if (status != NSPD_OK) {
            ghost_coupling_config_free(&walls);
            return status;
        }
        *ghost = walls;
        cfg->coupling = (CouplingConfig){.kind = COUPLING_GHOST_CELL, .model = ghost};
        /* its refusals (a body whose markers cannot be built) said at the bodies */
        cfg_node_place(cfg_map_find(flow, "bodies"), cfg->coupling.where,
                       (int)sizeof cfg->coupling.where);
        const GksCaseConfig *f = cfg->flow.model;
        const FlowPrim *q = f->has_free_stream ? &f->free_stream : &f->solver.initial;
        ghost->fsi.reference =
            (IbmReference){.rho = q->rho,
                           .u = q->u,
                           .v = q->v,
                           .p = q->p,
                           .length = f->reference_length > 0 ? f->reference_length : 1.0,
                           .p_ambient = q->p};
        memset(&walls, 0, sizeof walls);
    }
    CfgNode *coupling;
    TRY(cfg_opt_map(root, "coupling", &coupling));
    if (solid && flow) {
        if (solid_config_dim(&cfg->solid) != 2) {
            ghost_coupling_config_free(&walls);
            return cfg_fail_at(solid, "model",
                               "a solid coupled to the 2D flow must be 2D; "
                               "expected plane_stress or plane_strain");
        }
        if (walls.bodies.count > 0) {
            ghost_coupling_config_free(&walls);
            return cfg_fail_at(flow, "bodies",
                               "fixed bodies together with a coupled solid are not "
                               "supported; expected one of them");
        }
        if (!coupling) {
            coupling = cfg_map_add_collection(root, "coupling", CFG_MAP, CFG_FROM_DEFAULT);
            if (!coupling) return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
            coupling->used = true;
        }
        cfg_node_place(coupling, cfg->coupling.where, sizeof cfg->coupling.where);
        int kind = 0;
        TRY(cfg_opt_enum(coupling, "kind", COUPLING_KINDS, 0, &kind));
        if (kind == 1) {
            cfg->coupling.kind = COUPLING_PENALTY;
            TRY(nspd_alloc(&cfg->coupling.model, 1, sizeof(PenaltyConfig)));
            TRY(read_penalty(coupling, cfg));
        } else {
            /* the ghost cells' walls are the surface traced on the square
             * lattice's indices (solid/pd/surface.h) */
            const CfgNode *lattice = cfg_map_find(solid, "lattice");
            const CfgNode *lk =
                lattice && lattice->kind == CFG_MAP ? cfg_map_find(lattice, "kind") : NULL;
            if (lk && lk->kind == CFG_SCALAR && strcmp(lk->text, "polar") == 0)
                return cfg_fail_at(coupling, "kind",
                                   "ghost_cell with solid.lattice.kind: polar: its walls are "
                                   "traced on the square lattice; expected kind: penalty, or a "
                                   "square lattice");
            cfg->coupling.kind = COUPLING_GHOST_CELL;
            TRY(nspd_alloc(&cfg->coupling.model, 1, sizeof(GhostCouplingConfig)));
            TRY(read_coupling(coupling, cfg));
        }
    } else if (coupling) {
        return cfg_fail(coupling, "a coupling needs both a solid and a flow section");
    }
    ghost_coupling_config_free(&walls); /* read but not used: no bodies */
    TRY(read_output(root, cfg, solid ? solid_config_dim(&cfg->solid) : 2, solid != NULL));
    return cfg_end_map(root);
}

int case_read(const char *path, char *const *overrides, int override_count, CfgDoc *doc,
              SimConfig *cfg) {
    memset(cfg, 0, sizeof *cfg);
    TRY(cfg_doc_load_file(doc, path));
    int status = NSPD_OK;
    for (int i = 0; i < override_count && status == NSPD_OK; i++)
        status = cfg_doc_override(doc, overrides[i]);
    if (status == NSPD_OK) status = read_all(doc, cfg);
    if (status != NSPD_OK) {
        sim_config_free(cfg);
        cfg_doc_free(doc);
    }
    return status;
}

int case_resolved_hash(const CfgDoc *doc, uint64_t *hash) {
    char *text = NULL;
    size_t size = 0;
    FILE *f = open_memstream(&text, &size);
    if (!f) return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
    const int status = cfg_doc_write(doc, f);
    fclose(f);
    if (status == NSPD_OK) *hash = hash64(text, size);
    free(text);
    return status;
}

int case_write_resolved(const CfgDoc *doc, const char *path) {
    char header[4096 + 256];
    snprintf(header, sizeof header,
             "# The resolved case: the file %s with every --set override and every default\n"
             "# written out. `nspd run` on this file repeats the run exactly.\n",
             doc->file);
    return cfg_doc_save(doc, path, header);
}
