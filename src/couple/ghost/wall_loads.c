/* Surface loads (see wall_loads.h for the formulas).
 *
 * Why probes and not the ghost values: a ghost value is an extrapolation
 * into the solid that also serves the flux; the wall quantities are
 * better read on the fluid side. Two probes along the normal give the
 * one-sided second-order estimates of p_w (with dp/dn = 0) and du_t/dn (with
 * u = u_w at the wall); the first probe sits one cell out, where its
 * stencil still leans on the wall rows, so the estimate uses the boundary
 * condition twice: in the interpolation and in the one-sided formula. */
#include "couple/ghost/wall_loads.h"

#include "core/mem.h"
#include "core/parallel.h"
#include "core/status.h"
#include "couple/ghost/ibm_internal.h"
#include "flow/gks/flux_kernel.h"

#include <math.h>
#include <string.h>

int ibm_surface_reserve(const Ibm *ibm, IbmSurface *o) {
    const int n = ibm->nm;
    if (n > o->cap) {
        const size_t a = (size_t)o->cap, c = (size_t)n;
        TRY(nspd_realloc(&o->body, a, c, sizeof(int)));
        double **arrays[] = {&o->arc, &o->x,   &o->y,  &o->nx, &o->ny, &o->ds,
                             &o->p,   &o->tau, &o->fx, &o->fy, &o->cp, &o->cf};
        for (size_t q = 0; q < sizeof arrays / sizeof arrays[0]; q++)
            TRY(nspd_realloc(arrays[q], a, c, sizeof(double)));
        TRY(nspd_realloc(&o->upper, a, c, 1));
        TRY(nspd_realloc(&o->probe_q, 8 * a, 8 * c, sizeof(double)));
        o->cap = n;
    }
    if (ibm->body_count > o->body_count) {
        TRY(nspd_realloc(&o->forces, (size_t)o->body_count, (size_t)ibm->body_count,
                         sizeof(IbmBodyForces)));
        o->body_count = ibm->body_count;
    }
    o->n = n;
    return NSPD_OK;
}

void ibm_surface_free(IbmSurface *o) {
    nspd_free(&o->body);
    double **arrays[] = {&o->arc, &o->x,   &o->y,  &o->nx, &o->ny, &o->ds,
                         &o->p,   &o->tau, &o->fx, &o->fy, &o->cp, &o->cf};
    for (size_t q = 0; q < sizeof arrays / sizeof arrays[0]; q++) nspd_free(arrays[q]);
    nspd_free(&o->probe_q);
    nspd_free(&o->upper);
    nspd_free(&o->forces);
    memset(o, 0, sizeof *o);
}

/* Leading and trailing edge markers (global) of body b. */
static void edges(const Ibm *ibm, int b, double ex, double ey, int *le, int *te) {
    *le = ibm->le[b];
    *te = ibm->te[b];
    if (*le >= 0 && *te >= 0) return;
    const int f = ibm->first[b], n = ibm->count[b];
    int lo = f, hi = f;
    for (int k = f; k < f + n; k++) {
        const double a = ibm->mx[k] * ex + ibm->my[k] * ey;
        if (a < ibm->mx[lo] * ex + ibm->my[lo] * ey) lo = k;
        if (a > ibm->mx[hi] * ex + ibm->my[hi] * ey) hi = k;
    }
    if (*le < 0) *le = lo;
    if (*te < 0) *te = hi;
}

/* What the segments of every body share. */
typedef struct {
    const GksParams *gas;
    double gm1;
    const IbmReference *ref;
    double iq;     /* 1 / dynamic pressure (0 without a reference speed) */
    double ex, ey; /* unit drag direction: the reference velocity's, else +x */
} SurfaceFlow;

/* One body's place among the segments. */
typedef struct {
    int b, fb, n; /* body, its first segment, its segment count */
    int iso;      /* isothermal wall */
    double Tw;    /* its wall temperature, K */
    int le, te;   /* leading and trailing edge markers (global) */
    int span;     /* upper segments: span of them from te */
} SurfaceBody;

/* Wall values, traction and coefficients of segment k of body B. */
static void segment_loads(const Ibm *ibm, const SurfaceFlow *F, const SurfaceBody *B, int k,
                          IbmSurface *o) {
    const IbmStencilSet *P = &ibm->probes;
    const IbmReference *ref = F->ref;
    const int sg = B->fb + k, e = ibm->seg_end[sg], n = B->n;
    const double ax = ibm->mx[sg], ay = ibm->my[sg], bx = ibm->mx[e], by = ibm->my[e];
    const double ds = hypot(bx - ax, by - ay);
    const double tx = (bx - ax) / ds, ty = (by - ay) / ds, nx = ty, ny = -tx;
    const double *at = o->probe_q + 8 * sg;
    const IbmPrim q1 = {at[0], at[1], at[2], at[3]}, q2 = {at[4], at[5], at[6], at[7]};
    const double d = P->ratio[2 * sg];
    /* A probe with no fluid cell in reach (it left the grid, or the normal
     * points into another part of the body: a folded surface, the bridged
     * mouth of a crack) evaluates to -inf: that segment is not wetted and
     * carries no load. With only the far probe dry, the near one gives
     * first-order values. */
    const int bridge = ref->bridge_length > 0.0 && ds > ref->bridge_length;
    const int wet1 = !bridge && isfinite(q1.p) && isfinite(q1.u) && isfinite(q1.v);
    const int wet2 = wet1 && isfinite(q2.p) && isfinite(q2.u) && isfinite(q2.v);
    double pw = ref->p_ambient, tau = 0.0;
    const double uw = 0.5 * (ibm->mvx[sg] + ibm->mvx[e]);
    const double vw = 0.5 * (ibm->mvy[sg] + ibm->mvy[e]);
    if (wet1) {
        const double ut1 = (q1.u - uw) * tx + (q1.v - vw) * ty;
        double Twall = B->iso ? B->Tw : q1.T;
        pw = q1.p;
        double dudn = ut1 / d;
        if (wet2) {
            pw = (4.0 * q1.p - q2.p) / 3.0;
            if (!(pw > 0.0)) pw = q1.p;
            if (!B->iso) Twall = (4.0 * q1.T - q2.T) / 3.0;
            if (!(Twall > 0.0)) Twall = q1.T;
            const double ut2 = (q2.u - uw) * tx + (q2.v - vw) * ty;
            dudn = (4.0 * ut1 - ut2) / (2.0 * d);
        }
        tau = gks_viscosity(F->gas, Twall, F->gas->law) * dudn;
    }
    const int up = ((k - (B->te - B->fb)) % n + n) % n < B->span;
    o->body[sg] = B->b;
    o->x[sg] = 0.5 * (ax + bx);
    o->y[sg] = 0.5 * (ay + by);
    o->nx[sg] = nx;
    o->ny[sg] = ny;
    o->ds[sg] = ds;
    o->p[sg] = pw;
    o->tau[sg] = tau;
    o->fx[sg] = -(pw - ref->p_ambient) * nx + tau * tx;
    o->fy[sg] = -(pw - ref->p_ambient) * ny + tau * ty;
    o->cp[sg] = wet1 ? (pw - ref->p) * F->iq : (double)NAN;
    o->cf[sg] = wet1 ? (up ? -tau : tau) * F->iq : (double)NAN;
    o->upper[sg] = (uint8_t)up;
}

/* Arc lengths, force sums (in marker order), coefficients and edges of body
 * B, from its segments' values. */
static void body_forces(const Ibm *ibm, const SurfaceFlow *F, const SurfaceBody *B, IbmSurface *o) {
    const IbmReference *ref = F->ref;
    const double ex = F->ex, ey = F->ey;
    const int le = B->le, te = B->te;
    IbmBodyForces *f = &o->forces[B->b];
    memset(f, 0, sizeof *f);
    double arc = 0.0, cpmax = -(double)INFINITY;
    for (int k = 0; k < B->n; k++) {
        const int sg = B->fb + k;
        o->arc[sg] = arc + 0.5 * o->ds[sg];
        arc += o->ds[sg];
        if (isnan(o->cp[sg])) continue; /* not wetted: no load */
        const double dp = o->p[sg] - ref->p;
        f->pressure[0] -= dp * o->nx[sg] * o->ds[sg];
        f->pressure[1] -= dp * o->ny[sg] * o->ds[sg];
        f->viscous[0] += o->tau[sg] * -o->ny[sg] * o->ds[sg];
        f->viscous[1] += o->tau[sg] * o->nx[sg] * o->ds[sg];
        if (o->cp[sg] > cpmax) {
            cpmax = o->cp[sg];
            f->stagnation[0] = o->x[sg];
            f->stagnation[1] = o->y[sg];
        }
    }
    const double L = ref->length > 0.0 ? ref->length : 1.0;
    const double c = F->iq / L;
    f->cd_pressure = (f->pressure[0] * ex + f->pressure[1] * ey) * c;
    f->cl_pressure = (-f->pressure[0] * ey + f->pressure[1] * ex) * c;
    f->cd_viscous = (f->viscous[0] * ex + f->viscous[1] * ey) * c;
    f->cl_viscous = (-f->viscous[0] * ey + f->viscous[1] * ex) * c;
    f->cd = f->cd_pressure + f->cd_viscous;
    f->cl = f->cl_pressure + f->cl_viscous;
    f->cp_stagnation = cpmax;
    f->leading_edge[0] = ibm->mx[le], f->leading_edge[1] = ibm->my[le];
    f->trailing_edge[0] = ibm->mx[te], f->trailing_edge[1] = ibm->my[te];
    f->chord = (ibm->mx[te] - ibm->mx[le]) * ex + (ibm->my[te] - ibm->my[le]) * ey;
}

/* Separation of body B: the first sign change of cf from + to - on the upper
 * side, from the leading edge back (segments le-1, le-2, ..., te); NaN when
 * there is none. Needs body_forces' chord. */
static void body_separation(const Ibm *ibm, const SurfaceFlow *F, const SurfaceBody *B,
                            IbmSurface *o) {
    IbmBodyForces *f = &o->forces[B->b];
    const int fb = B->fb, n = B->n, le = B->le;
    f->x_separation_over_c = (double)NAN;
    f->separation[0] = f->separation[1] = (double)NAN;
    int seen_positive = 0, prev = -1;
    for (int step = 1; step <= B->span; step++) {
        const int sg = fb + (((le - fb) - step) % n + n) % n;
        const double cf = o->cf[sg];
        if (cf > 0.0) seen_positive = 1;
        if (seen_positive && cf < 0.0 && prev >= 0) {
            const double c0 = o->cf[prev], a = c0 / (c0 - cf);
            const double xs = o->x[prev] + a * (o->x[sg] - o->x[prev]);
            const double ys = o->y[prev] + a * (o->y[sg] - o->y[prev]);
            f->separation[0] = xs;
            f->separation[1] = ys;
            f->x_separation_over_c =
                ((xs - ibm->mx[le]) * F->ex + (ys - ibm->my[le]) * F->ey) / f->chord;
            break;
        }
        prev = sg;
    }
}

/* Probe entry e's (u, v, p, T) into q[4 e ..]. */
static void probe_value(const Ibm *ibm, int e, const IbmFieldView *w, double gm1, double R,
                        double *q) {
    const int b = ibm->seg_body[e / 2];
    const IbmPrim v = ibm_stencil_eval(ibm, &ibm->probes, e, w, gm1, R,
                                       ibm->thermal[b] == IBM_WALL_ISOTHERMAL, ibm->wall_t[b]);
    q[4 * e] = v.u, q[4 * e + 1] = v.v, q[4 * e + 2] = v.p, q[4 * e + 3] = v.T;
}

/* Every probe's values into o->probe_q: evaluated here, or on several
 * processes each by the process whose rows hold it, then shared. */
static int probe_values(const Ibm *ibm, GksSolver *s, IbmSurface *o) {
    const GksParams *gas = gks_solver_gas(s);
    const double gm1 = gas->gamma - 1.0, R = gas->R;
    if (!ibm->share) {
        const IbmFieldView w = ibm_solver_view(s);
        const int n = ibm->probes.n;
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
        for (int e = 0; e < n; e++) probe_value(ibm, e, &w, gm1, R, o->probe_q);
        return NSPD_OK;
    }
    const IbmFieldView shadow = ibm_share_refresh(ibm, s);
    int n;
    const int *mine = ibm_share_probes(ibm, &n);
    /* this process's probes in place, then everyone's (the share reads
     * them out before it writes) */
    for (int i = 0; i < n; i++) probe_value(ibm, mine[i], &shadow, gm1, R, o->probe_q);
    return ibm_share_probe_values(ibm, o->probe_q, o->probe_q);
}

int ibm_surface_compute(const Ibm *ibm, GksSolver *s, const IbmReference *ref, IbmSurface *o) {
    if (o->cap < ibm->nm || o->body_count < ibm->body_count)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "immersed boundary: surface arrays not reserved for %d segments", ibm->nm);
    o->n = ibm->nm;
    TRY(probe_values(ibm, s, o));
    const GksParams *gas = gks_solver_gas(s);
    const double U2 = ref->u * ref->u + ref->v * ref->v, Um = sqrt(U2);
    const double q = 0.5 * ref->rho * U2;
    const SurfaceFlow F = {
        .gas = gas,
        .gm1 = gas->gamma - 1.0,
        .ref = ref,
        .iq = q > 0.0 ? 1.0 / q : 0.0,
        .ex = Um > 0.0 ? ref->u / Um : 1.0,
        .ey = Um > 0.0 ? ref->v / Um : 0.0,
    };
    for (int b = 0; b < ibm->body_count; b++) {
        SurfaceBody B = {.b = b, .fb = ibm->first[b], .n = ibm->count[b]};
        edges(ibm, b, F.ex, F.ey, &B.le, &B.te);
        B.iso = ibm->thermal[b] == IBM_WALL_ISOTHERMAL;
        B.Tw = ibm->wall_t[b];
        B.span = ((B.le - B.te) % B.n + B.n) % B.n; /* upper segments from te */
        const int n = B.n;
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
        for (int k = 0; k < n; k++) segment_loads(ibm, &F, &B, k, o);
        body_forces(ibm, &F, &B, o);
        body_separation(ibm, &F, &B, o);
    }
    return NSPD_OK;
}

void ibm_surface_marker_forces(const Ibm *ibm, const IbmSurface *o, int b, double *fx, double *fy) {
    const int fb = ibm->first[b], n = ibm->count[b];
    for (int k = 0; k < n; k++) fx[k] = fy[k] = 0.0;
    for (int k = 0; k < n; k++) {
        const int sg = fb + k, k1 = (k + 1) % n;
        const double hx = 0.5 * o->fx[sg] * o->ds[sg], hy = 0.5 * o->fy[sg] * o->ds[sg];
        fx[k] += hx;
        fy[k] += hy;
        fx[k1] += hx;
        fy[k1] += hy;
    }
}

double ibm_cp_stagnation_isentropic(double g, double m) {
    const double p0 = pow(1.0 + 0.5 * (g - 1.0) * m * m, g / (g - 1.0));
    return (p0 - 1.0) / (0.5 * g * m * m);
}

double ibm_cp_stagnation_pitot(double g, double m) {
    if (m <= 1.0) return ibm_cp_stagnation_isentropic(g, m);
    const double m2 = m * m;
    const double a =
        pow((g + 1.0) * (g + 1.0) * m2 / (4.0 * g * m2 - 2.0 * (g - 1.0)), g / (g - 1.0));
    const double p02 = a * (1.0 - g + 2.0 * g * m2) / (g + 1.0);
    return (p02 - 1.0) / (0.5 * g * m2);
}
