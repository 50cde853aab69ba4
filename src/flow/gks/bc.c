/* Box boundary conditions: ghost-layer filling (see bc.h for the methods). */
#include "flow/gks/bc.h"

#include "core/status.h"

#include <math.h>
#include <stddef.h>

const char *const FLOW_BC_NAMES[BC_KIND_COUNT + 1] = {"extrapolation",
                                                      "supersonic_inflow",
                                                      "subsonic_inflow",
                                                      "subsonic_outflow",
                                                      "slip_wall",
                                                      "noslip_adiabatic",
                                                      "noslip_isothermal",
                                                      "symmetry",
                                                      "periodic",
                                                      "moving_shock_inflow",
                                                      NULL};

void flow_prim_to_cons(const FlowPrim *q, double gamma, double w[4]) {
    w[0] = q->rho;
    w[1] = q->rho * q->u;
    w[2] = q->rho * q->v;
    w[3] = q->p / (gamma - 1.0) + 0.5 * q->rho * (q->u * q->u + q->v * q->v);
}

void flow_cons_to_prim(const double w[4], double gamma, FlowPrim *q) {
    q->rho = w[0];
    q->u = w[1] / w[0];
    q->v = w[2] / w[0];
    q->p = (gamma - 1.0) * (w[3] - 0.5 * (w[1] * q->u + w[2] * q->v));
}

void flow_shock_post_state(const FlowPrim *pre, double ms, double gamma, int direction,
                           FlowPrim *post) {
    const double m2 = ms * ms, c1 = sqrt(gamma * pre->p / pre->rho);
    post->rho = pre->rho * (gamma + 1.0) * m2 / ((gamma - 1.0) * m2 + 2.0);
    post->p = pre->p * (2.0 * gamma * m2 - (gamma - 1.0)) / (gamma + 1.0);
    post->u = pre->u + direction * 2.0 * c1 * (m2 - 1.0) / ((gamma + 1.0) * ms);
    post->v = pre->v;
}

int bc_validate(const Grid *g, const FlowFaceBc bc[4]) {
    static const char *face_names[4] = {"x_lo", "x_hi", "y_lo", "y_hi"};
    for (int f = 0; f < 4; f++) {
        const FlowFaceBc *b = &bc[f];
        if (b->count < 1 || b->count > FLOW_BC_MAX_SEGMENTS)
            return NSPD_FAIL(NSPD_ERR_INPUT, "boundary %s: %d segments (1..%d allowed)",
                             face_names[f], b->count, FLOW_BC_MAX_SEGMENTS);
        for (int k = 0; k < b->count; k++) {
            const FlowBc *s = &b->seg[k];
            if ((int)s->kind < 0 || s->kind >= BC_KIND_COUNT)
                return NSPD_FAIL(NSPD_ERR_INPUT, "boundary %s: unknown kind", face_names[f]);
            if (k > 1 && !(s->start > b->seg[k - 1].start))
                return NSPD_FAIL(NSPD_ERR_INPUT, "boundary %s: segment starts must increase",
                                 face_names[f]);
            if (s->kind == BC_PERIODIC && b->count != 1)
                return NSPD_FAIL(NSPD_ERR_INPUT, "boundary %s: periodic must be its only segment",
                                 face_names[f]);
            const bool needs_state = s->kind == BC_SUPERSONIC_INFLOW ||
                                     s->kind == BC_SUBSONIC_INFLOW ||
                                     s->kind == BC_MOVING_SHOCK_INFLOW;
            if (needs_state && !(s->state.rho > 0.0 && s->state.p > 0.0))
                return NSPD_FAIL(NSPD_ERR_INPUT, "boundary %s (%s): state needs rho > 0 and p > 0",
                                 face_names[f], FLOW_BC_NAMES[s->kind]);
            if (s->kind == BC_SUBSONIC_OUTFLOW && !(s->pressure > 0.0))
                return NSPD_FAIL(NSPD_ERR_INPUT, "boundary %s: back pressure must be > 0",
                                 face_names[f]);
            if (s->kind == BC_NOSLIP_ISOTHERMAL && !(s->wall_temperature > 0.0))
                return NSPD_FAIL(NSPD_ERR_INPUT, "boundary %s: wall temperature must be > 0",
                                 face_names[f]);
        }
    }
    for (int a = 0; a < 2; a++) {
        const bool plo = bc[2 * a].seg[0].kind == BC_PERIODIC;
        const bool phi = bc[2 * a + 1].seg[0].kind == BC_PERIODIC;
        if (plo != phi)
            return NSPD_FAIL(NSPD_ERR_INPUT, "boundary: periodic on %s needs periodic on %s",
                             face_names[plo ? 2 * a : 2 * a + 1],
                             face_names[plo ? 2 * a + 1 : 2 * a]);
        if (plo != g->ax[a].periodic)
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "boundary: periodic %s faces need a periodic grid axis",
                             a == 0 ? "x" : "y");
    }
    return NSPD_OK;
}

/* Which segment covers coordinate s along the face. */
static const FlowBc *segment_at(const FlowFaceBc *b, double s) {
    int k = 0;
    while (k + 1 < b->count && s >= b->seg[k + 1].start) k++;
    return &b->seg[k];
}

/* Ghost primitive (normal frame: un along the outward normal, ut along the
 * face) from the image primitive `im` and the first interior cell `in`. */
static void ghost_state(const FlowBc *bc, double gamma, double R, int outward, int normal_axis,
                        const FlowPrim *im, const FlowPrim *in, FlowPrim *gh) {
    /* outward-normal and tangential components in the face frame */
    const double un_im = outward * (normal_axis == 0 ? im->u : im->v);
    const double ut_im = normal_axis == 0 ? im->v : im->u;
    const double un_in = outward * (normal_axis == 0 ? in->u : in->v);
    const double ut_in = normal_axis == 0 ? in->v : in->u;
    double rho = im->rho, un, ut = ut_im, p = im->p; /* every case that breaks sets un */
    const double gm1 = gamma - 1.0;
    switch (bc->kind) {
    case BC_SUPERSONIC_INFLOW:
    case BC_MOVING_SHOCK_INFLOW:
        *gh = bc->state;
        return;
    case BC_EXTRAPOLATION:
        *gh = *in;
        return;
    case BC_SLIP_WALL:
    case BC_SYMMETRY:
        un = -un_im;
        break;
    case BC_NOSLIP_ADIABATIC:
        un = -un_im;
        ut = 2.0 * bc->wall_velocity - ut_im;
        break;
    case BC_NOSLIP_ISOTHERMAL: {
        un = -un_im;
        ut = 2.0 * bc->wall_velocity - ut_im;
        const double t_im = im->p / (R * im->rho);
        double tg = 2.0 * bc->wall_temperature - t_im;
        if (tg < 0.25 * bc->wall_temperature) tg = 0.25 * bc->wall_temperature;
        p = im->p;
        rho = p / (R * tg);
        break;
    }
    case BC_SUBSONIC_INFLOW: {
        const FlowPrim *f = &bc->state;
        const double un_f = outward * (normal_axis == 0 ? f->u : f->v);
        const double ut_f = normal_axis == 0 ? f->v : f->u;
        const double c_in = sqrt(gamma * in->p / in->rho), c_f = sqrt(gamma * f->p / f->rho);
        if (un_in >= c_in) { /* supersonic outflow */
            *gh = *in;
            return;
        }
        if (un_f <= -c_f) { /* supersonic inflow */
            *gh = *f;
            return;
        }
        const double rp = un_in + 2.0 * c_in / gm1; /* leaves the domain */
        const double rm = un_f - 2.0 * c_f / gm1;   /* enters it */
        un = 0.5 * (rp + rm);
        const double c = 0.25 * gm1 * (rp - rm);
        const bool entering = un < 0.0;
        const double s = entering ? f->p / pow(f->rho, gamma) : in->p / pow(in->rho, gamma);
        ut = entering ? ut_f : ut_in;
        rho = pow(c * c / (gamma * s), 1.0 / gm1);
        p = rho * c * c / gamma;
        break;
    }
    case BC_SUBSONIC_OUTFLOW: {
        const double c_in = sqrt(gamma * in->p / in->rho);
        if (un_in >= c_in) {
            *gh = *in;
            return;
        }
        p = bc->pressure;
        rho = in->rho * pow(p / in->p, 1.0 / gamma);
        const double c = sqrt(gamma * p / rho);
        un = un_in + 2.0 * (c_in - c) / gm1;
        ut = ut_in;
        break;
    }
    default: /* periodic is handled by the caller */
        *gh = *im;
        return;
    }
    gh->rho = rho;
    gh->p = p;
    if (normal_axis == 0) {
        gh->u = outward * un;
        gh->v = ut;
    } else {
        gh->v = outward * un;
        gh->u = ut;
    }
}

static void load(double *const w[4], int64_t k, double gamma, FlowPrim *q) {
    const double c[4] = {w[0][k], w[1][k], w[2][k], w[3][k]};
    flow_cons_to_prim(c, gamma, q);
}

static void store(double *const w[4], int64_t k, double gamma, const FlowPrim *q) {
    double c[4];
    flow_prim_to_cons(q, gamma, c);
    for (int v = 0; v < 4; v++) w[v][k] = c[v];
}

/* Fills the ghost layers of one face. Along-face cells: t = t0 .. t1-1 (x
 * faces: rows; y faces: columns). */
static void fill_face(const Grid *g, int face, const FlowFaceBc *b, const GksParams *gas,
                      double *const w[4], uint8_t *kind, int t0, int t1) {
    const int axis = face / 2, hi = face % 2, outward = hi ? 1 : -1;
    const int n = g->ax[axis].n;
    const GridAxis *along = &g->ax[1 - axis];
    for (int t = t0; t < t1; t++) {
        const FlowBc *bc = segment_at(b, along->center[t]);
        for (int k = 0; k < GRID_NG; k++) {
            /* ghost index, image index (mirror), first interior, periodic source */
            const int ig = hi ? n + k : -1 - k;
            const int im = hi ? n - 1 - k : k;
            const int i0 = hi ? n - 1 : 0;
            const int ip = hi ? k : n - 1 - k;
            const int64_t kg = axis == 0 ? grid_index(g, ig, t) : grid_index(g, t, ig);
            const int64_t km = axis == 0 ? grid_index(g, im, t) : grid_index(g, t, im);
            const int64_t k0 = axis == 0 ? grid_index(g, i0, t) : grid_index(g, t, i0);
            const int64_t kp = axis == 0 ? grid_index(g, ip, t) : grid_index(g, t, ip);
            if (bc->kind == BC_PERIODIC) {
                for (int v = 0; v < 4; v++) w[v][kg] = w[v][kp];
                if (kind) kind[kg] = kind[kp];
                continue;
            }
            FlowPrim qm, q0, qg;
            load(w, km, gas->gamma, &qm);
            load(w, k0, gas->gamma, &q0);
            ghost_state(bc, gas->gamma, gas->R, outward, axis, &qm, &q0, &qg);
            store(w, kg, gas->gamma, &qg);
            if (kind) kind[kg] = kind[km];
        }
    }
}

void bc_fill_faces(const Grid *g, const FlowFaceBc bc[4], const GksParams *gas, double *const w[4],
                   uint8_t *kind, unsigned faces) {
    /* x faces for the interior rows, then y faces over every column */
    for (int face = 0; face < 4; face++) {
        if (!(faces >> face & 1u)) continue;
        if (face < 2)
            fill_face(g, face, &bc[face], gas, w, kind, 0, g->ny);
        else
            fill_face(g, face, &bc[face], gas, w, kind, -GRID_NG, g->nx + GRID_NG);
    }
}

void bc_fill(const Grid *g, const FlowFaceBc bc[4], const GksParams *gas, double *const w[4],
             uint8_t *kind) {
    bc_fill_faces(g, bc, gas, w, kind, 15u);
}
