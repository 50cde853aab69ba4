/* The BGK-NS flux of one face, in the face's normal frame (inline kernel).
 *
 * Xu, JCP 171 (2001) 289; paper 000 Eqs. 1-8 and 21-27; shared/notes/gks_flux.md.
 * Everything here is pure arithmetic on doubles, inlined into the row loop of
 * flux.c so that the compiler vectorises it across faces.
 *
 * Notation (normal frame: u along the face normal, v tangential):
 *   W = (rho, rho U, rho V, rho E), lambda = rho / (2 p) = 1 / (2 R T),
 *   psi = (1, u, v, (u^2 + v^2 + xi^2)/2), K internal degrees of freedom,
 *   K = (4 - 2 gamma) / (gamma - 1) in 2D (gamma = (K + 4) / (K + 2)),
 *   <.> = (1/rho) \int (.) g dXi for the Maxwellian g of the state at hand.
 *
 * Micro slopes (Eq. 25). A slope of W along a direction is held as the
 * polynomial a = a1 + a2 u + a3 v + a4 psi4 with rho <a psi> = dW; then a g is
 * the derivative of the Maxwellian, so a = d(ln g):
 *   a4 = -2 dlambda,  a2 = 2 (lambda dU + U dlambda),  a3 = 2 (lambda dV + V dlambda),
 *   a1 = drho/rho + (K+2)/2 dlambda/lambda - dlambda (U^2+V^2) - 2 lambda (U dU + V dV).
 * This is the notes' solve (R2, R3, R4 form) written in primitive variables;
 * tests/unit/flow/gks/test_moments checks rho <a psi> = dW by quadrature.
 *
 * Time slopes. The compatibility condition \int psi (a u + b v + A) g = 0 says
 * rho <A psi> = -(dF/dW dW_x + dG/dW dW_y): the Euler time derivative. It is
 * evaluated in primitive form (rho_t, U_t, V_t, p_t from the Euler equations,
 * lambda_t = lambda (rho_t/rho - p_t/p)), which is exact and far cheaper than
 * the moments; the unit test checks it against the moment form.
 *
 * Half-space moments (u > 0 for the left state, u < 0 for the right):
 *   <u^0>_{>0} = erfc(-sqrt(lambda) U)/2,  <u^1>_{>0} = U <u^0>_{>0} + e^{-lambda U^2}/(2 sqrt(pi
 * lambda)), <u^{n+2}> = U <u^{n+1}> + (n+1)/(2 lambda) <u^n>   (full or half space), the u < 0 half
 * with erfc(+sqrt(lambda) U)/2 and a minus sign on the exponential. One exp and one erfc per side:
 * erfc(|x|) = erfcx(|x|) exp(-x^2) shares the exponential with <u^1>, and erfc(-|x|) = 2 -
 * erfc(|x|). Full-space: <v^0> = 1, <v^1> = V, same recursion; <xi^2> = K/(2 lambda), <xi^4> = K
 * (K+2)/(4 lambda^2). Moments up to u^6 and v^5 are needed.
 *
 * Interface distribution (Eq. 26 with the notes' two collision times) and its
 * time integral over [0, dt]:
 *   dt F = t0 [rho_L <u psi>_{>0,L} + rho_R <u psi>_{<0,R}]
 *        + t1 [rho_L <u (a_L u + b_L v) psi>_{>0,L} + (R)] + t2 [rho_L <u A_L psi>_{>0,L} + (R)]
 *        + rho_0 (t3 <u psi>_0 + t4 <u (abar u + bbar v) psi>_0 + t5 <u Abar psi>_0)
 * with eta = exp(-dt/tau_n),
 *   t0 = tau_n (1 - eta);  t1 = tau_n (eta (dt + tau_n) - tau_n) + tau tau_n (eta - 1);
 *   t2 = tau tau_n (eta - 1);  t3 = dt - tau_n (1 - eta);
 *   t4 = tau_n (tau_n - eta (dt + tau_n) - tau (eta - 1)) - dt tau;
 *   t5 = dt^2/2 - tau tau_n (eta - 1) - tau dt.
 * Derived here from Eq. 21 with tau_n in the exponentials and the physical tau
 * in the Chapman-Enskog terms; they satisfy t0 + t3 = dt, t1 + t4 = -tau dt and
 * t2 + t5 = dt^2/2 - tau dt, so continuous data (L = R, equal slopes) give
 * exactly the time integral of the Navier-Stokes distribution
 * g0 (1 - tau (abar u + bbar v + Abar) + t Abar), whatever tau_n is.
 *
 * Interface equilibrium: W0 = rho_L <psi>_{>0,L} + rho_R <psi>_{<0,R}. Its
 * slopes are inputs (the operator passes the central difference of the cell
 * averages across the face for the normal one and the mean of the two cells'
 * tangential slopes for the tangential one); Abar by compatibility.
 *
 * Collision times: tau = mu(T0) / p0 (physical, zero for inviscid gas) and
 * tau_n = tau + (eps + C |p_L - p_R| / (p_L + p_R)) dt.
 *
 * Prandtl fix. The BGK model has Pr = 1. The Chapman-Enskog heat flux of the
 * scheme over the step is q = -tau dt rho0 \int c_u |c|^2/2 (abar u + bbar v + Abar) g0,
 * c the peculiar velocity; with Abar from compatibility it reduces exactly to
 *   q = tau dt rho0 (K + 4) lambda_n / (8 lambda0^3) = -dt mu c_p dT/dn,
 * lambda_n the normal derivative of lambda in abar. The energy flux gets
 * (1/Pr - 1) q, so the conductivity becomes mu c_p / Pr. (The notes' "heat flux
 * of the equilibrium part" taken literally as t4 ... + t5 <u Abar psi>-moments
 * would also scale the enthalpy carried by the equilibrium's own time
 * evolution, dt^2/2 rho0 h U_t, which is not conduction and stays non-zero at
 * mu = 0: a first-order-in-time error in the energy flux.) */
#ifndef NSPD_FLOW_GKS_FLUX_KERNEL_H
#define NSPD_FLOW_GKS_FLUX_KERNEL_H

#include "core/kernel.h"
#include "flow/gks/special_functions.h"

#include <math.h>

/* Viscosity laws: mu(T) for the collision time tau = mu / p. */
typedef enum {
    VISCOSITY_NONE = 0,   /* inviscid: tau = 0 (Euler) */
    VISCOSITY_CONSTANT,   /* mu = mu_ref */
    VISCOSITY_POWER,      /* mu = mu_ref (T / T_ref)^omega */
    VISCOSITY_SUTHERLAND, /* mu = mu_ref (T / T_ref)^1.5 (T_ref + S) / (T + S) */
} ViscosityLaw;

/* Everything the kernel needs besides the states: gas, viscosity, dissipation. */
typedef struct {
    double gamma;        /* ratio of specific heats */
    double K;            /* internal degrees of freedom, (4 - 2 gamma)/(gamma - 1) */
    double R;            /* specific gas constant, J/(kg K) */
    ViscosityLaw law;    /* how mu depends on T */
    double mu_ref;       /* Pa s */
    double T_ref;        /* K (power law, Sutherland) */
    double omega;        /* power-law exponent */
    double sutherland_S; /* Sutherland constant, K */
    double prandtl;      /* Pr; the energy flux is corrected to it */
    double c_jump;       /* C in tau_n: pressure-jump dissipation (Xu: 1) */
    double eps_dt;       /* eps in tau_n: a floor eps dt (0 by default) */
} GksParams;

/* mu(T), Pa s. `law` is a compile-time constant at every vectorised call
 * site (the row loops are instantiated per law), so the switch folds away and
 * no unused law is evaluated. */
NSPD_KERNEL double gks_viscosity(const GksParams *p, double T, ViscosityLaw law) {
    switch (law) {
    case VISCOSITY_CONSTANT:
        return p->mu_ref;
    case VISCOSITY_POWER:
        return p->mu_ref * gks_exp(p->omega * gks_log(T / p->T_ref));
    case VISCOSITY_SUTHERLAND: {
        const double r = T * (1.0 / p->T_ref);
        return p->mu_ref * r * sqrt(r) * (p->T_ref + p->sutherland_S) / (T + p->sutherland_S);
    }
    default:
        return 0.0;
    }
}

/* Primitive description of a Maxwellian, with the reciprocals of its
 * density and lambda: formed once per state, they turn the kernel's
 * divisions by them into products (a division takes the core's divider
 * 16 cycles for 8 lanes, and the face flux divided by these two some 40
 * times). */
typedef struct {
    double rho, U, V, lam;
    double ir, il; /* 1 / rho, 1 / lambda */
} GksPrim;

NSPD_KERNEL GksPrim gks_prim(double rho, double U, double V, double lam) {
    const GksPrim q = {rho, U, V, lam, 1.0 / rho, 1.0 / lam};
    return q;
}

NSPD_KERNEL GksPrim gks_prim_from_w(const double w[4], double K) {
    GksPrim q;
    q.rho = w[0];
    q.ir = 1.0 / w[0];
    q.U = w[1] * q.ir;
    q.V = w[2] * q.ir;
    /* rho e = rho E - rho |U|^2 / 2 = (K + 2) rho / (4 lambda) */
    const double rho_e = w[3] - 0.5 * NSPD_FMA(w[1], q.U, w[2] * q.V);
    q.lam = 0.25 * (K + 2.0) * w[0] / rho_e;
    q.il = 4.0 / (K + 2.0) * rho_e * q.ir;
    return q;
}

/* A derivative of the primitive variables (rho, U, V, lambda). */
typedef struct {
    double rho, U, V, lam;
} GksDPrim;

/* d(prim) from d(W) at state q. */
NSPD_KERNEL GksDPrim gks_dprim(const GksPrim *q, const double dw[4], double K) {
    GksDPrim d;
    const double ir = q->ir;
    d.rho = dw[0];
    d.U = NSPD_FMA(-q->U, dw[0], dw[1]) * ir;
    d.V = NSPD_FMA(-q->V, dw[0], dw[2]) * ir;
    /* internal energy density e = rho E - rho |U|^2/2 = (K+2) rho / (4 lambda):
     * 1 / e = 4 lambda / ((K+2) rho) */
    const double de = NSPD_FMA(0.5 * NSPD_FMA(q->U, q->U, q->V * q->V), dw[0],
                               dw[3] - NSPD_FMA(q->U, dw[1], q->V * dw[2]));
    const double ie = 4.0 / (K + 2.0) * q->lam * ir;
    d.lam = q->lam * NSPD_FMA(dw[0], ir, -de * ie);
    return d;
}

/* Micro slope a (a[0..3] = a1..a4) of a primitive derivative: a = d ln g. */
NSPD_KERNEL void gks_micro(const GksPrim *q, const GksDPrim *d, double K, double a[4]) {
    a[3] = -2.0 * d->lam;
    a[1] = 2.0 * NSPD_FMA(q->lam, d->U, q->U * d->lam);
    a[2] = 2.0 * NSPD_FMA(q->lam, d->V, q->V * d->lam);
    double a0 = NSPD_FMA(0.5 * (K + 2.0) * d->lam, q->il, d->rho * q->ir);
    a0 = NSPD_FMA(-d->lam, NSPD_FMA(q->U, q->U, q->V * q->V), a0);
    a[0] = NSPD_FMA(-2.0 * q->lam, NSPD_FMA(q->U, d->U, q->V * d->V), a0);
}

/* Euler time derivative of the primitives from the normal (x) and tangential
 * (y) derivatives: the compatibility condition in primitive form. */
NSPD_KERNEL GksDPrim gks_dprim_dt(const GksPrim *q, const GksDPrim *dx, const GksDPrim *dy,
                                  double gamma) {
    const double ir = q->ir, il = q->il, p = 0.5 * q->rho * il, ip = 2.0 * q->lam * ir;
    /* p = rho / (2 lambda): dp = (drho - rho dlambda / lambda) / (2 lambda) */
    const double px = 0.5 * il * NSPD_FMA(-q->rho * dx->lam, il, dx->rho);
    const double py = 0.5 * il * NSPD_FMA(-q->rho * dy->lam, il, dy->rho);
    GksDPrim t;
    t.rho =
        -NSPD_FMA(q->rho, dy->V, NSPD_FMA(q->V, dy->rho, NSPD_FMA(q->rho, dx->U, q->U * dx->rho)));
    t.U = -NSPD_FMA(px, ir, NSPD_FMA(q->V, dy->U, q->U * dx->U));
    t.V = -NSPD_FMA(py, ir, NSPD_FMA(q->V, dy->V, q->U * dx->V));
    const double pt = -NSPD_FMA(gamma * p, dx->U + dy->V, NSPD_FMA(q->V, py, q->U * px));
    t.lam = q->lam * NSPD_FMA(t.rho, ir, -pt * ip);
    return t;
}

/* Moments of one Maxwellian: u[] full or half space, v[] full, xi even. */
typedef struct {
    double u[7], v[6], xi2, xi4;
} GksMoments;

/* Fills v[0..2], xi2 and, from u[0] and u[1], u[2] by the recursion: the
 * moments the interface equilibrium takes. */
NSPD_KERNEL void gks_moments_fill_low(GksMoments *m, const GksPrim *q, double K) {
    const double h = 0.5 * q->il;
    m->v[0] = 1.0;
    m->v[1] = q->V;
    m->v[2] = NSPD_FMA(q->V, m->v[1], h * m->v[0]);
    m->u[2] = NSPD_FMA(q->U, m->u[1], h * m->u[0]);
    m->xi2 = K * h;
}

/* The rest of them, v[3..5], u[3..6] and xi4, by the same recursion. */
NSPD_KERNEL void gks_moments_fill_high(GksMoments *m, const GksPrim *q, double K) {
    const double h = 0.5 * q->il;
    NSPD_UNROLL(8)
    for (int n = 1; n < 4; n++) m->v[n + 2] = NSPD_FMA(q->V, m->v[n + 1], (n + 1) * h * m->v[n]);
    NSPD_UNROLL(8)
    for (int n = 1; n < 5; n++) m->u[n + 2] = NSPD_FMA(q->U, m->u[n + 1], (n + 1) * h * m->u[n]);
    m->xi4 = K * (K + 2.0) * h * h;
}

/* Fills v[], xi and, from u[0] and u[1], the rest of u[] by the recursion. */
NSPD_KERNEL void gks_moments_fill(GksMoments *m, const GksPrim *q, double K) {
    gks_moments_fill_low(m, q, K);
    gks_moments_fill_high(m, q, K);
}

/* side > 0: u > 0 half of q; side < 0: u < 0 half; side == 0: full space.
 * erfcx_abs = erfcx(|sqrt(lambda) U|) and ex = exp(-lambda U^2) are passed in
 * so that the caller computes them once per state. */
NSPD_KERNEL void gks_moments_half_start(GksMoments *m, const GksPrim *q, double side, double ex,
                                        double erfcx_abs) {
    const double rsl = sqrt(q->lam) * q->il; /* 1 / sqrt(lambda) */
    const double e = erfcx_abs * ex;         /* erfc(|x|), x = sqrt(lambda) U */
    /* erfc(-side x)/2: the positive-side half holds more than half the mass
     * when side*U > 0. */
    const double su = side * q->U;
    const double m0 = su >= 0.0 ? 1.0 - 0.5 * e : 0.5 * e;
    m->u[0] = m0;
    m->u[1] = NSPD_FMA(q->U, m0, side * ex * (0.28209479177387814347 * rsl)); /* 1/(2 sqrt(pi)) */
}

NSPD_KERNEL void gks_moments_half(GksMoments *m, const GksPrim *q, double K, double side, double ex,
                                  double erfcx_abs) {
    gks_moments_half_start(m, q, side, ex, erfcx_abs);
    gks_moments_fill(m, q, K);
}

NSPD_KERNEL void gks_moments_full(GksMoments *m, const GksPrim *q, double K) {
    m->u[0] = 1.0;
    m->u[1] = q->U;
    gks_moments_fill(m, q, K);
}

/* <u^a v^b> */
#define GKS_M(m, a, b) ((m)->u[a] * (m)->v[b])
/* <u^a v^b psi4>, psi4 = (u^2 + v^2 + xi^2)/2 */
#define GKS_E(m, a, b)                                                                             \
    (0.5 * NSPD_FMA(GKS_M(m, a, b), (m)->xi2,                                                      \
                    NSPD_FMA((m)->u[a], (m)->v[(b) + 2], GKS_M(m, (a) + 2, b))))

/* <u^a v^b psi4^2> */
NSPD_KERNEL double gks_e2(const GksMoments *m, int a, int b) {
    double e = NSPD_FMA(m->u[a], m->v[b + 4], GKS_M(m, a + 4, b));
    e = NSPD_FMA(GKS_M(m, a, b), m->xi4, e);
    e = NSPD_FMA(2.0 * m->u[a + 2], m->v[b + 2], e);
    e = NSPD_FMA(2.0 * NSPD_FMA(m->u[a], m->v[b + 2], GKS_M(m, a + 2, b)), m->xi2, e);
    return 0.25 * e;
}

/* c[0] m0 + c[1] m1 + c[2] m2 + c[3] m3, left to right, fused */
NSPD_KERNEL double gks_dot4(const double c[4], double m0, double m1, double m2, double m3) {
    return NSPD_FMA(c[3], m3, NSPD_FMA(c[2], m2, NSPD_FMA(c[1], m1, c[0] * m0)));
}

/* out += s <u^a v^b c psi> for a micro polynomial c = c1 + c2 u + c3 v + c4 psi4. */
NSPD_KERNEL void gks_moment_add(const GksMoments *m, int a, int b, const double c[4], double s,
                                double out[4]) {
    const double e00 = GKS_E(m, a, b), e10 = GKS_E(m, a + 1, b), e01 = GKS_E(m, a, b + 1);
    /* each sum fused in the order written; its addition to out is not
     * (see gks_moment_add_unit) */
    out[0] += s * gks_dot4(c, GKS_M(m, a, b), GKS_M(m, a + 1, b), GKS_M(m, a, b + 1), e00);
    out[1] += s * gks_dot4(c, GKS_M(m, a + 1, b), GKS_M(m, a + 2, b), GKS_M(m, a + 1, b + 1), e10);
    out[2] += s * gks_dot4(c, GKS_M(m, a, b + 1), GKS_M(m, a + 1, b + 1), GKS_M(m, a, b + 2), e01);
    out[3] += s * gks_dot4(c, e00, e10, e01, gks_e2(m, a, b));
}

/* out += s <u^a v^b psi> (gks_moment_add with c = (1, 0, 0, 0), without the
 * products by the zero coefficients; 15 flops instead of 84). The addition
 * to out is not fused, here or in gks_moment_add: out gathers the two
 * sides, and a + b is b + a where fma(x, y, a) is not fma(z, w, b), so a
 * gas at rest keeps an exactly zero mass flux (the two half-spaces cancel;
 * fused, 1.6e-15 of dt p was left: unit.flow.gks.flux) and a face and its
 * mirror image the same interface equilibrium. */
NSPD_KERNEL void gks_moment_add_unit(const GksMoments *m, int a, int b, double s, double out[4]) {
    out[0] += s * GKS_M(m, a, b);
    out[1] += s * GKS_M(m, a + 1, b);
    out[2] += s * GKS_M(m, a, b + 1);
    out[3] += s * GKS_E(m, a, b);
}

/* One side of the face (left: side = +1, its u > 0 half; right: side = -1). */
typedef struct {
    GksPrim q;
    GksMoments m;
    double a[4], b[4], A[4]; /* normal, tangential and time micro slopes */
    double p;                /* pressure */
} GksSide;

/* The side's state, pressure and lowest half-space moments (what the
 * interface equilibrium needs). */
NSPD_KERNEL void gks_side_init(GksSide *s, const double w[4], const GksParams *par, double side) {
    s->q = gks_prim_from_w(w, par->K);
    s->p = 0.5 * s->q.rho * s->q.il;
    const double x = sqrt(s->q.lam) * s->q.U, ax = fabs(x);
    gks_moments_half_start(&s->m, &s->q, side, gks_exp(-x * x), gks_erfcx(ax));
    gks_moments_fill_low(&s->m, &s->q, par->K);
}

/* Its higher moments and micro slopes, formed only when its flux is taken:
 * they are not needed before, and so 19 fewer values a side live across
 * the interface's work (the row loop spills its vector registers). */
NSPD_KERNEL void gks_side_finish(GksSide *s, const double dn[4], const double dt_[4],
                                 const GksParams *par) {
    const GksDPrim dx = gks_dprim(&s->q, dn, par->K), dy = gks_dprim(&s->q, dt_, par->K);
    const GksDPrim dtp = gks_dprim_dt(&s->q, &dx, &dy, par->gamma);
    gks_micro(&s->q, &dx, par->K, s->a);
    gks_micro(&s->q, &dy, par->K, s->b);
    gks_micro(&s->q, &dtp, par->K, s->A);
    gks_moments_fill_high(&s->m, &s->q, par->K);
}

/* f += the side's share of the initial-data terms (t0, t1, t2). */
NSPD_KERNEL void gks_side_flux(const GksSide *s, double c0, double c1, double c2, double f[4]) {
    double c[4];
    c[0] = NSPD_FMA(c2, s->A[0], c0);
    for (int n = 1; n < 4; n++) c[n] = c2 * s->A[n];
    gks_moment_add(&s->m, 1, 0, c, s->q.rho, f);
    gks_moment_add(&s->m, 2, 0, s->a, c1 * s->q.rho, f);
    gks_moment_add(&s->m, 1, 1, s->b, c1 * s->q.rho, f);
}

/* The flux of one face times dt, in the normal frame.
 *   wl, wr     reconstructed states on the two sides (conservative)
 *   nl, nr     their normal derivatives (d/dn of W, per metre)
 *   tl, tr     their tangential derivatives
 *   n0, t0     normal and tangential derivatives of the interface equilibrium
 *   dt         time step, s
 *   law        par->law, passed separately so that vectorised callers can make it a constant
 *   f          out: \int_0^dt F dt per unit face length (rho, rho u_n, rho u_t, rho E)
 * Pure: no allocation, no side effects besides f. */
NSPD_KERNEL void gks_flux_kernel(const double wl[4], const double nl[4], const double tl[4],
                                 const double wr[4], const double nr[4], const double tr[4],
                                 const double n0[4], const double t0[4], double dt,
                                 const GksParams *par, ViscosityLaw law, double f[4]) {
    const double K = par->K;
    GksSide L, R;
    gks_side_init(&L, wl, par, 1.0);
    gks_side_init(&R, wr, par, -1.0);

    /* Interface equilibrium from the colliding half-space particles. */
    double w0[4] = {0.0, 0.0, 0.0, 0.0};
    gks_moment_add_unit(&L.m, 0, 0, L.q.rho, w0);
    gks_moment_add_unit(&R.m, 0, 0, R.q.rho, w0);
    const GksPrim q0 = gks_prim_from_w(w0, K);

    const GksDPrim dx0 = gks_dprim(&q0, n0, K), dy0 = gks_dprim(&q0, t0, K);
    const GksDPrim dt0 = gks_dprim_dt(&q0, &dx0, &dy0, par->gamma);
    double a0[4], b0[4], A0[4];
    gks_micro(&q0, &dx0, K, a0);
    gks_micro(&q0, &dy0, K, b0);
    gks_micro(&q0, &dt0, K, A0);

    /* Collision times and the time-integrated weights. */
    const double T0 = 0.5 / par->R * q0.il;
    const double tau = gks_viscosity(par, T0, law) * (2.0 * q0.lam * q0.ir); /* mu / p0 */
    const double tau_n = tau + (par->eps_dt + par->c_jump * fabs(L.p - R.p) / (L.p + R.p)) * dt;
    const double eta = gks_exp(-dt / tau_n);
    const double c0 = tau_n * (1.0 - eta);
    const double c1 = tau_n * (eta * (dt + tau_n) - tau_n) + tau * tau_n * (eta - 1.0);
    const double c2 = tau * tau_n * (eta - 1.0);
    const double c3 = dt - c0;
    const double c4 = tau_n * (tau_n - eta * (dt + tau_n) - tau * (eta - 1.0)) - dt * tau;
    const double c5 = 0.5 * dt * dt - tau * tau_n * (eta - 1.0) - tau * dt;

    f[0] = f[1] = f[2] = f[3] = 0.0;
    /* Free transport of the initial, non-equilibrium data. */
    gks_side_finish(&L, nl, tl, par);
    gks_side_flux(&L, c0, c1, c2, f);
    gks_side_finish(&R, nr, tr, par);
    gks_side_flux(&R, c0, c1, c2, f);
    /* The equilibrium part. */
    GksMoments m0;
    gks_moments_full(&m0, &q0, K);
    double c[4];
    c[0] = NSPD_FMA(c5, A0[0], c3);
    for (int n = 1; n < 4; n++) c[n] = c5 * A0[n];
    gks_moment_add(&m0, 1, 0, c, q0.rho, f);
    gks_moment_add(&m0, 2, 0, a0, c4 * q0.rho, f);
    gks_moment_add(&m0, 1, 1, b0, c4 * q0.rho, f);

    /* Prandtl fix: add (1/Pr - 1) times the Chapman-Enskog heat flux. */
    const double il = q0.il;
    const double q = tau * dt * q0.rho * (K + 4.0) * dx0.lam * 0.125 * il * il * il;
    f[3] += (1.0 / par->prandtl - 1.0) * q;
}

#undef GKS_M
#undef GKS_E

#endif
