/* The `flow:` section of a PDDO case -> PddoFlowConfig (case_pddo.h). */
#include "case/case_pddo.h"

#include "core/status.h"
#include "io/cfg_read.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const char *const SIDE_KEYS[PDDO_SIDES] = {"x_min", "x_max", "y_min", "y_max"};
static const char *const SIDE_TYPES[] = {"wall", "lid", "inlet", "outlet", "periodic", NULL};
enum { T_WALL, T_LID, T_INLET, T_OUTLET, T_PERIODIC };
static const char *const PROFILES[] = {"uniform", "parabolic", NULL};
static const char *const INLET_CORNERS[] = {"wall", "inlet", NULL};
static const char *const WALL_GHOSTS[] = {"paper", "antisymmetric", NULL};
static const char *const DIVERGENCE_TERM[] = {"paper", "updated", NULL};
static const char *const WALL_PRESSURE[] = {"zero_gradient", "momentum", NULL};
static const char *const PRESSURE_SOLVES[] = {"umfpack", "runs", "mumps", "boomeramg", NULL};
static const char *const AXES[] = {"x", "y", NULL};
static const char *const BODY_SHAPES[] = {"circle", NULL};
/* a patch's horizon: the cloud's one (the paper), or its rings' own
 * (flow/pddo/polar.h) */
static const char *const PATCH_HORIZONS[] = {"lattice", "local", NULL};

/* A `name` (default `fallback`) into out (PDDO_LINE_NAME chars): letters,
 * digits, _ (a file or column name), unlike the k names before it, which
 * lie at seen + j stride (j < k). */
static int read_name(CfgNode *m, const char *fallback, char *out, const char *seen, size_t stride,
                     int k, const char *use) {
    const char *name;
    TRY(cfg_opt_string(m, "name", fallback, &name));
    size_t len = strlen(name);
    bool ok = len > 0 && len < PDDO_LINE_NAME;
    for (const char *ch = name; *ch; ch++)
        ok = ok && ((*ch >= 'a' && *ch <= 'z') || (*ch >= 'A' && *ch <= 'Z') ||
                    (*ch >= '0' && *ch <= '9') || *ch == '_');
    if (!ok)
        return cfg_fail_at(m, "name", "'%s'; expected 1 to %d letters, digits or _ (%s)", name,
                           PDDO_LINE_NAME - 1, use);
    for (int j = 0; j < k; j++)
        if (strcmp(seen + (size_t)j * stride, name) == 0)
            return cfg_fail_at(m, "name", "'%s' used twice; expected unique names", name);
    snprintf(out, PDDO_LINE_NAME, "%s", name);
    return NSPD_OK;
}

/* flow.seed: {spin, until}: the bodies' walls turn counterclockwise at
 * `spin` m/s until `until` s, then stop. A mirror-symmetric cloud holds the
 * lift at round-off until the wake's instability has grown from it (at Re
 * 100 on the paper's lattice, most of the paper's 2 s); a brief spin
 * gives it a finite start, as a body-fitted mesh's asymmetry does. */
static int read_seed(CfgNode *flow, PddoFlowConfig *c) {
    CfgNode *seed;
    TRY(cfg_opt_map(flow, "seed", &seed));
    if (!seed) return NSPD_OK;
    if (c->body_count == 0)
        return cfg_fail(seed, "a seed without bodies; expected flow.bodies to turn");
    TRY(cfg_req_double(seed, "spin", &c->step.spin_speed)); /* m/s, counterclockwise positive */
    TRY(cfg_req_double(seed, "until", &c->step.spin_until));
    TRY(cfg_check_positive(seed, "until", c->step.spin_until,
                           "the time in s at which the walls stop"));
    return cfg_end_map(seed);
}

/* `bodies`: circles on polar patches (paper 002 Sec. 4.1.2), at most
 * PDDO_MAX_BODIES, each with its own patch options. Two patches must stay
 * apart by their reaches (r_cut) plus a horizon, the room the cloud
 * demands (flow/pddo/cloud.c): then no family holds the rings of both. */
static int read_bodies(CfgNode *flow, PddoFlowConfig *c) {
    CfgNode *seq;
    TRY(cfg_opt_seq(flow, "bodies", &seq));
    if (!seq) return NSPD_OK;
    if (seq->count > PDDO_MAX_BODIES)
        return cfg_fail(seq, "%d bodies; expected at most %d (one polar patch each)", seq->count,
                        PDDO_MAX_BODIES);
    const double dx = c->cloud.dx;
    PddoPolarPatch patches[PDDO_MAX_BODIES];
    for (int b = 0; b < seq->count; b++) {
        CfgNode *m = seq->child[b];
        if (m->kind != CFG_MAP)
            return cfg_fail(m, "not a body; expected {shape: circle, center, radius}");
        int shape;
        TRY(cfg_req_enum(m, "shape", BODY_SHAPES, &shape));
        char fallback[16];
        snprintf(fallback, sizeof fallback, "body%d", b);
        TRY(read_name(m, fallback, c->body_name[b], c->body_name[0], sizeof c->body_name[0], b,
                      "the prefix of its columns"));
        PddoHole *h = &c->bodies[b];
        double centre[2];
        TRY(cfg_req_vec(m, "center", 2, centre));
        h->x = centre[0], h->y = centre[1];
        TRY(cfg_req_double(m, "radius", &h->radius));
        TRY(cfg_check_positive(m, "radius", h->radius, "the circle's radius in m"));
        if (!(h->x - h->radius > c->cloud.lo[0] && h->x + h->radius < c->cloud.hi[0] &&
              h->y - h->radius > c->cloud.lo[1] && h->y + h->radius < c->cloud.hi[1]))
            return cfg_fail_at(m, "center",
                               "[%g, %g] with radius %g m is not inside the rectangle; expected "
                               "a circle inside it",
                               h->x, h->y, h->radius);
        double r_patch, dtheta, dr;
        TRY(cfg_opt_double(m, "patch_radius", 3.0 * h->radius, &r_patch));
        TRY(cfg_check_range(m, "patch_radius", r_patch, h->radius + 2.0 * dx, 1e30,
                            "the polar patch's outer radius in m, at least the radius plus two "
                            "spacings"));
        TRY(cfg_opt_double(m, "dtheta", dx / r_patch, &dtheta));
        TRY(cfg_check_range(m, "dtheta", dtheta, 1e-4, M_PI / 4.0,
                            "the ring's angular spacing in rad (default spacing / patch_radius)"));
        TRY(cfg_opt_double(m, "dr_over_spacing", PDDO_POLAR_DR_OVER_DX, &dr));
        TRY(cfg_check_range(m, "dr_over_spacing", dr, 0.1, 2.0,
                            "the rings' radial spacing over the lattice spacing (the paper: "
                            "0.69)"));
        int patch_horizon;
        TRY(cfg_opt_enum(m, "horizon", PATCH_HORIZONS, 0, &patch_horizon));
        c->polar[b] =
            (PddoPolarSpec){.dtheta = dtheta,
                            .dr = dr * dx,
                            .r_patch = r_patch,
                            .local_horizon = patch_horizon ? c->cloud.horizon_factor : 0.0};
        PddoPolarPatch *patch = &patches[b];
        if (pddo_polar_layout(patch, h->x, h->y, h->radius, &c->polar[b], dx) != NSPD_OK)
            return cfg_fail_at(m, "radius",
                               "%g m with patch_radius %g m, dtheta %g, dr %g m: no polar patch "
                               "fits (%s); expected a radius above three rings and a patch with "
                               "more fluid rings than three",
                               h->radius, r_patch, dtheta, dr * dx, nspd_error_message());
        /* the cloud's room: two fictitious layers' depth beyond r_cut */
        const double reach = patch->r_cut + 2.0 * c->cloud.layers * dx;
        if (!(h->x - reach > c->cloud.lo[0] && h->x + reach < c->cloud.hi[0] &&
              h->y - reach > c->cloud.lo[1] && h->y + reach < c->cloud.hi[1]))
            return cfg_fail_at(m, "patch_radius",
                               "%g m: the patch and 2 x 3 fictitious layers reach %g m from "
                               "the centre, beyond the rectangle; expected a smaller patch",
                               r_patch, reach);
        const double horizon = c->cloud.horizon_factor * dx;
        for (int a = 0; a < b; a++) {
            const double apart = patch->r_cut + patches[a].r_cut + horizon;
            if (!(hypot(h->x - c->bodies[a].x, h->y - c->bodies[a].y) >= apart))
                return cfg_fail_at(m, "center",
                                   "[%g, %g]: its polar patch (reach %g m) overlaps that of "
                                   "body %d at [%g, %g] (reach %g m); expected the centres at "
                                   "least %g m apart (both reaches and a horizon)",
                                   h->x, h->y, patch->r_cut, a, c->bodies[a].x, c->bodies[a].y,
                                   patches[a].r_cut, apart);
        }
        TRY(cfg_end_map(m));
        c->body_count = b + 1;
    }
    return NSPD_OK;
}

/* One side's condition; *lid and *inlet the speeds read (0 if none). */
static int read_side(CfgNode *bcs, int s, PddoFlowConfig *c, int *type, double *lid,
                     double *inlet) {
    CfgNode *m;
    TRY(cfg_req_map(bcs, SIDE_KEYS[s], &m));
    TRY(cfg_req_enum(m, "type", SIDE_TYPES, type));
    PddoStepParams *p = &c->step;
    const int normal = s / 2; /* 0: the side is normal to x */
    const double into = s % 2 == 0 ? 1.0 : -1.0;
    switch (*type) {
    case T_WALL:
        c->cloud.side[s] = PDDO_SIDE_WALL;
        break;
    case T_LID:
        c->cloud.side[s] = PDDO_SIDE_WALL;
        TRY(cfg_req_double(m, "velocity", lid));
        if (!isfinite(*lid) || *lid == 0.0)
            return cfg_fail_at(m, "velocity",
                               "%g m/s; expected the lid's non-zero speed along the side "
                               "(positive along +x or +y)",
                               *lid);
        if (normal == 0)
            p->wall_v[s] = *lid;
        else
            p->wall_u[s] = *lid;
        break;
    case T_INLET: {
        c->cloud.side[s] = PDDO_SIDE_INLET;
        TRY(cfg_req_double(m, "velocity", inlet));
        TRY(cfg_check_positive(m, "velocity", *inlet,
                               "the mean inflow speed into the rectangle in m/s"));
        int profile;
        TRY(cfg_opt_enum(m, "profile", PROFILES, PDDO_INLET_UNIFORM, &profile));
        p->inlet_profile = (PddoInletProfile)profile;
        int corners;
        TRY(cfg_opt_enum(m, "corners", INLET_CORNERS, PDDO_INLET_CORNERS_WALL, &corners));
        p->inlet_corners = (PddoInletCorners)corners;
        if (normal == 0)
            p->inlet_u = into * *inlet;
        else
            p->inlet_v = into * *inlet;
        break;
    }
    case T_OUTLET:
        c->cloud.side[s] = PDDO_SIDE_OUTLET;
        break;
    default:
        c->cloud.side[s] = PDDO_SIDE_PERIODIC;
        break;
    }
    return cfg_end_map(m);
}

static int read_boundaries(CfgNode *flow, PddoFlowConfig *c, double *lid, double *inlet) {
    CfgNode *bcs;
    TRY(cfg_req_map(flow, "boundaries", &bcs));
    int type[PDDO_SIDES];
    int inlets = 0, inlet_side = -1;
    *lid = *inlet = 0.0;
    for (int s = 0; s < PDDO_SIDES; s++) {
        double l = 0, in = 0;
        TRY(read_side(bcs, s, c, &type[s], &l, &in));
        *lid = fmax(*lid, fabs(l));
        if (type[s] == T_INLET) {
            if (inlets++)
                return cfg_fail_at(bcs, SIDE_KEYS[s],
                                   "a second inlet; expected at most one inlet side");
            *inlet = in, inlet_side = s;
        }
    }
    for (int a = 0; a < 2; a++)
        if ((type[2 * a] == T_PERIODIC) != (type[2 * a + 1] == T_PERIODIC))
            return cfg_fail_at(bcs, SIDE_KEYS[type[2 * a] == T_PERIODIC ? 2 * a + 1 : 2 * a],
                               "the opposite side %s is periodic; expected both periodic or "
                               "neither",
                               SIDE_KEYS[type[2 * a] == T_PERIODIC ? 2 * a : 2 * a + 1]);
    if (inlet_side >= 0 && c->step.inlet_profile == PDDO_INLET_PARABOLIC &&
        type[inlet_side < 2 ? 2 : 0] == T_PERIODIC)
        return cfg_fail_at(cfg_map_find(bcs, SIDE_KEYS[inlet_side]), "profile",
                           "a parabolic inflow between periodic sides; expected walls on the "
                           "sides it spans, or a uniform profile");
    return cfg_end_map(bcs);
}

/* The rectangle and its spacing: `spacing` or `intervals_x`. */
static int read_lattice(CfgNode *flow, PddoFlowConfig *c) {
    CfgNode *d;
    TRY(cfg_req_map(flow, "domain", &d));
    const double origin[2] = {0.0, 0.0};
    TRY(cfg_opt_vec(d, "min", 2, origin, c->cloud.lo));
    TRY(cfg_req_vec(d, "max", 2, c->cloud.hi));
    for (int a = 0; a < 2; a++)
        if (!(c->cloud.hi[a] > c->cloud.lo[a]) || !isfinite(c->cloud.hi[a] - c->cloud.lo[a]))
            return cfg_fail_at(d, "max", "[%g, %g] is not above min [%g, %g]; expected a rectangle",
                               c->cloud.hi[0], c->cloud.hi[1], c->cloud.lo[0], c->cloud.lo[1]);
    TRY(cfg_end_map(d));
    const double len[2] = {c->cloud.hi[0] - c->cloud.lo[0], c->cloud.hi[1] - c->cloud.lo[1]};
    bool has_h, has_n;
    double h = 0, n = 0;
    TRY(cfg_maybe_double(flow, "spacing", &h, &has_h));
    CfgNode *nn = cfg_map_find(flow, "intervals_x");
    has_n = nn && !nn->is_null;
    if (has_n) {
        int64_t count;
        TRY(cfg_req_int(flow, "intervals_x", &count));
        if (count < 2 || count > 100000)
            return cfg_fail_at(flow, "intervals_x", "%lld; expected 2 to 1e5 spacings along x",
                               (long long)count);
        n = (double)count;
    } else if (nn) {
        nn->used = true;
    }
    if (has_h == has_n)
        return cfg_fail(flow,
                        "%s; expected the lattice spacing as either spacing (m) or "
                        "intervals_x (spacings along x)",
                        has_h ? "both spacing and intervals_x given" : "no spacing or intervals_x");
    if (has_h) TRY(cfg_check_positive(flow, "spacing", h, "the lattice spacing in m"));
    c->cloud.dx = has_h ? h : len[0] / n;
    for (int a = 0; a < 2; a++) {
        const double q = len[a] / c->cloud.dx, whole = round(q);
        if (!(fabs(q - whole) <= 1e-9 * fmax(1.0, q)) || whole < 2 || whole > 100000)
            return cfg_fail_at(flow, has_h ? "spacing" : "intervals_x",
                               "%g m gives %.10g spacings along %c (side %g m); expected a whole "
                               "number from 2 to 1e5 along both sides",
                               c->cloud.dx, q, "xy"[a], len[a]);
    }
    return NSPD_OK;
}

static int read_lines(CfgNode *flow, PddoFlowConfig *c) {
    const double mid[2] = {0.5 * (c->cloud.lo[0] + c->cloud.hi[0]),
                           0.5 * (c->cloud.lo[1] + c->cloud.hi[1])};
    CfgNode *seq;
    TRY(cfg_opt_seq(flow, "lines", &seq));
    if (!seq) { /* the two centrelines */
        c->line_count = 2;
        c->lines[0] = (PddoLine){.name = "vertical", .at = {mid[0], mid[1]}, .along = 1};
        c->lines[1] = (PddoLine){.name = "horizontal", .at = {mid[0], mid[1]}, .along = 0};
        return NSPD_OK;
    }
    if (seq->count > PDDO_MAX_LINES)
        return cfg_fail(seq, "%d lines; expected at most %d", seq->count, PDDO_MAX_LINES);
    c->line_count = seq->count;
    for (int l = 0; l < seq->count; l++) {
        CfgNode *m = seq->child[l];
        if (m->kind != CFG_MAP) return cfg_fail(m, "not a line; expected {name, at, along}");
        PddoLine *line = &c->lines[l];
        char fallback[16];
        snprintf(fallback, sizeof fallback, "line%d", l);
        TRY(read_name(m, fallback, line->name, c->lines[0].name, sizeof c->lines[0], l,
                      "a file name"));
        TRY(cfg_opt_vec(m, "at", 2, mid, line->at));
        TRY(cfg_opt_enum(m, "along", AXES, 1, &line->along));
        const int across = 1 - line->along;
        if (!(line->at[across] >= c->cloud.lo[across] && line->at[across] <= c->cloud.hi[across]))
            return cfg_fail_at(m, "at",
                               "%c = %g m is outside the rectangle's [%g, %g] m; expected a line "
                               "through it",
                               "xy"[across], line -> at[across], c -> cloud.lo[across],
                               c->cloud.hi[across]);
        TRY(cfg_end_map(m));
    }
    return NSPD_OK;
}

int case_read_pddo(CfgNode *flow, CfgNode *time_map, bool dt_given, double dt, PddoFlowConfig *c) {
    memset(c, 0, sizeof *c);
    c->cloud.layers = 3; /* the paper's three fictitious layers (Sec. 4) */
    TRY(read_lattice(flow, c));
    TRY(cfg_opt_double(flow, "horizon_factor", 3.0, &c->cloud.horizon_factor));
    TRY(cfg_check_range(flow, "horizon_factor", c->cloud.horizon_factor, 1.5, 3.0,
                        "the horizon over the spacing, 1.5 to 3 (three fictitious layers "
                        "cover at most 3)"));
    CfgNode *fluid;
    TRY(cfg_req_map(flow, "fluid", &fluid));
    TRY(cfg_req_double(fluid, "density", &c->step.rho));
    TRY(cfg_check_positive(fluid, "density", c->step.rho, "a density in kg/m^3"));
    TRY(cfg_req_double(fluid, "viscosity", &c->step.mu));
    TRY(cfg_check_positive(fluid, "viscosity", c->step.mu, "the dynamic viscosity in Pa s"));
    TRY(cfg_end_map(fluid));
    double lid, inlet;
    TRY(read_boundaries(flow, c, &lid, &inlet));
    int walls;
    TRY(cfg_opt_enum(flow, "walls", WALL_GHOSTS, PDDO_WALL_ZERO, &walls));
    c->step.walls = (PddoWallGhosts)walls;
    int divergence;
    TRY(cfg_opt_enum(flow, "divergence_term", DIVERGENCE_TERM, PDDO_DIVERGENCE_ALL_ROWS,
                     &divergence));
    c->step.divergence = (PddoDivergenceTerm)divergence;
    TRY(cfg_opt_double(flow, "divergence_time", 0.0, &c->step.divergence_time));
    TRY(cfg_check_range(
        flow, "divergence_time", c->step.divergence_time, 0.0, 1e30,
        "tau of the PPE's (rho/tau) div u in s, at least dt; 0 for dt (the paper)"));
    int wall_pressure;
    TRY(cfg_opt_enum(flow, "wall_pressure", WALL_PRESSURE, PDDO_WALL_PRESSURE_ZERO_GRADIENT,
                     &wall_pressure));
    c->step.wall_pressure = (PddoWallPressure)wall_pressure;
    int solve;
    TRY(cfg_opt_enum(flow, "pressure_solve", PRESSURE_SOLVES, 1, &solve)); /* runs */
    c->pressure_runs = solve == 1;
    c->pressure.petsc = solve >= 2;
    c->pressure.method = solve == 3 ? PPE_PETSC_BOOMERAMG : PPE_PETSC_MUMPS;
    if (c->pressure.petsc && !ppe_petsc_built())
        return cfg_fail_at(flow, "pressure_solve",
                           "this nspd was built without PETSc; expected runs or umfpack, or a "
                           "build with MPI and petsc-dev (scripts/deps.sh installs it)");
    /* 1e-8: the Re 100 cylinder's drag, lift amplitude and period within
     * 1.7e-8 of the direct solve's on 1-4 ranks (docs/VALIDATION.md) */
    TRY(cfg_opt_double(flow, "pressure_tolerance", 1e-8, &c->pressure.tolerance));
    TRY(cfg_check_range(flow, "pressure_tolerance", c->pressure.tolerance, 1e-15, 1e-2,
                        "boomeramg's relative residual ||R - K p|| / ||R||"));
    const double zero[2] = {0, 0};
    double force[2];
    TRY(cfg_opt_vec(flow, "body_force", 2, zero, force));
    c->step.force_x = force[0], c->step.force_y = force[1];
    TRY(cfg_opt_double(flow, "steady_tolerance", 0.0, &c->steady_tolerance));
    TRY(cfg_check_range(flow, "steady_tolerance", c->steady_tolerance, 0.0, 1e30,
                        "max |du/dt| in m/s^2 below which the run ends, 0 for never"));
    TRY(read_lines(flow, c));
    TRY(read_bodies(flow, c));
    TRY(read_seed(flow, c));
    /* scales: the lid, the inlet (a channel's middle reaches 1.5 times its
     * mean), a body force's Poiseuille maximum F H^2 / (8 nu) */
    const double len[2] = {c->cloud.hi[0] - c->cloud.lo[0], c->cloud.hi[1] - c->cloud.lo[1]};
    const double nu = c->step.mu / c->step.rho;
    const double driven =
        fmax(fabs(force[0]) * len[1] * len[1], fabs(force[1]) * len[0] * len[0]) / (8.0 * nu);
    c->velocity_scale = fmax(fmax(lid, 1.5 * inlet), driven);
    c->reference_length = c->body_count > 0 ? 2.0 * c->bodies[0].radius : fmin(len[0], len[1]);
    c->reference_velocity = lid > 0.0 ? lid : inlet > 0.0 ? inlet : 2.0 / 3.0 * driven;
    CfgNode *ref;
    TRY(cfg_opt_map(flow, "reference", &ref));
    if (ref) {
        TRY(cfg_opt_double(ref, "velocity", c->reference_velocity, &c->reference_velocity));
        TRY(cfg_check_positive(ref, "velocity", c->reference_velocity,
                               "the reference speed of Re, cd and cl in m/s"));
        TRY(cfg_opt_double(ref, "length", c->reference_length, &c->reference_length));
        TRY(cfg_check_positive(ref, "length", c->reference_length,
                               "the reference length of Re, cd and cl in m"));
        TRY(cfg_end_map(ref));
    }
    if (!(c->velocity_scale > 0.0))
        return cfg_fail_at(flow, "boundaries",
                           "nothing drives the flow; expected a lid, an inlet or a body_force");
    const double limit = pddo_flow_dt_limit(c);
    if (dt_given && dt > limit)
        return cfg_fail_at(time_map, "dt",
                           "%g s exceeds the PDDO flow's stable limit %.4g s = min(1.6 h^2/nu, "
                           "2 nu/U^2) with h %g m (the smallest horizon over 3), nu %g m^2/s, U "
                           "%g m/s; expected at most "
                           "%.4g s (or no dt: half the limit)",
                           dt, limit, pddo_flow_smallest_spacing(c), nu, c->velocity_scale, limit);
    c->step.dt = dt_given ? dt : 0.5 * limit;
    if (c->step.divergence_time != 0.0 && !(c->step.divergence_time >= c->step.dt))
        return cfg_fail_at(flow, "divergence_time",
                           "%g s is shorter than the step, %g s; expected at least the step (the "
                           "paper's tau is dt; a shorter one over-corrects the divergence, and "
                           "under dt/2 it grows), or 0 for dt",
                           c->step.divergence_time, c->step.dt);
    return cfg_end_map(flow);
}
