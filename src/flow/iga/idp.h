/* The invariant-domain-preserving pieces of the isogeometric flow's
 * limiter (docs/IGA_LIMITER.md): conservative states U = (rho, rho u,
 * rho v, rho E) of a calorically perfect gas, their Euler fluxes, the
 * guaranteed upper bound on the largest wave speed of a 1D Riemann problem
 * (Guermond & Popov, J. Comput. Phys. 321, 2016), and the largest step
 * towards a high-order state that keeps the local bounds (Guermond,
 * Nazarov, Popov & Tomas, SIAM J. Sci. Comput. 40, 2018, Sec. 4). One
 * source for the CPU and a GPU (NSPD_KERNEL). */
#ifndef NSPD_FLOW_IGA_IDP_H
#define NSPD_FLOW_IGA_IDP_H

#include "core/kernel.h"

#include <math.h>
#include <stdbool.h>

/* rho e = rho E - |rho u|^2 / (2 rho) */
NSPD_KERNEL double idp_internal(const double U[4]) {
    return U[3] - 0.5 * (U[1] * U[1] + U[2] * U[2]) / U[0];
}

/* the specific-entropy surrogate rho e / rho^gamma (Guermond et al.'s s) */
NSPD_KERNEL double idp_entropy(double gamma, const double U[4]) {
    return idp_internal(U) * pow(U[0], -gamma);
}

/* (p, u, v, T) -> U; cv = R / (gamma - 1) */
NSPD_KERNEL void idp_from_primitive(double R, double cv, const double Y[4], double U[4]) {
    const double rho = Y[0] / (R * Y[3]);
    U[0] = rho, U[1] = rho * Y[1], U[2] = rho * Y[2];
    U[3] = rho * (cv * Y[3] + 0.5 * (Y[1] * Y[1] + Y[2] * Y[2]));
}

/* U -> (p, u, v, T) */
NSPD_KERNEL void idp_to_primitive(double R, double cv, const double U[4], double Y[4]) {
    const double e = idp_internal(U) / U[0];
    Y[1] = U[1] / U[0], Y[2] = U[2] / U[0], Y[3] = e / cv;
    Y[0] = U[0] * R * Y[3];
}

/* The Euler flux of U along (nx, ny), and the pressure. */
NSPD_KERNEL double idp_flux(double gamma, const double U[4], double nx, double ny, double F[4]) {
    const double p = (gamma - 1.0) * idp_internal(U);
    const double un = (U[1] * nx + U[2] * ny) / U[0];
    F[0] = U[0] * un;
    F[1] = U[1] * un + p * nx;
    F[2] = U[2] * un + p * ny;
    F[3] = (U[3] + p) * un;
    return p;
}

/* The per-state pieces of the wave-speed bound: normal velocity aside,
 * pressure p, sound speed c and p^(-(gamma - 1) / (2 gamma)). */
typedef struct {
    double p, c, q;
} IdpWaves;

NSPD_KERNEL IdpWaves idp_waves(double gamma, const double U[4]) {
    IdpWaves w;
    w.p = (gamma - 1.0) * idp_internal(U);
    w.c = sqrt(gamma * w.p / U[0]);
    w.q = pow(w.p, -(gamma - 1.0) / (2.0 * gamma));
    return w;
}

/* An upper bound of the largest wave speed of the Riemann problem between
 * a left state of normal velocity ul and a right one of ur: the
 * two-rarefaction pressure bounds p* from above for 1 < gamma <= 5/3
 * (Guermond & Popov 2016, Lemma 4.3), and the outer waves' speeds are
 * monotone in p. Symmetric: (ul, a, ur, b) and (-ur, b, -ul, a) give the
 * same bits. */
NSPD_KERNEL double idp_lambda_waves(double gamma, double ul, IdpWaves a, double ur, IdpWaves b) {
    const double ex = (gamma - 1.0) / (2.0 * gamma);
    const double num = a.c + b.c - 0.5 * (gamma - 1.0) * (ur - ul);
    double pstar = 0.0; /* num <= 0: a vacuum forms; the outer waves are the rarefactions' heads */
    if (num > 0.0) pstar = pow(num / (a.c * a.q + b.c * b.q), 1.0 / ex);
    const double k = (gamma + 1.0) / (2.0 * gamma);
    const double l1 = ul - a.c * sqrt(1.0 + k * fmax(0.0, (pstar - a.p) / a.p));
    const double l3 = ur + b.c * sqrt(1.0 + k * fmax(0.0, (pstar - b.p) / b.p));
    return fmax(fmax(-l1, 0.0), fmax(l3, 0.0));
}

/* The same between the states a = U_i and b = U_j along the unit vector n. */
NSPD_KERNEL double idp_lambda_max(double gamma, const double a[4], const double b[4], double nx,
                                  double ny) {
    const double ul = (a[1] * nx + a[2] * ny) / a[0], ur = (b[1] * nx + b[2] * ny) / b[0];
    return idp_lambda_waves(gamma, ul, idp_waves(gamma, a), ur, idp_waves(gamma, b));
}

/* The bounds a limited state keeps at one control point. */
typedef struct {
    double rho_min, rho_max; /* density */
    double s_min;            /* rho e / rho^gamma (entropy mode) */
    double e_min;            /* rho e (positivity mode) */
} IdpBounds;

/* phi(U) = rho e - s_min rho^gamma, concave in U for gamma >= 1 (rho e is
 * concave, rho^gamma convex), so {phi >= 0} is convex. */
NSPD_KERNEL double idp_entropy_margin(double gamma, const IdpBounds *b, const double U[4]) {
    return idp_internal(U) - (b->s_min > 0.0 ? b->s_min * pow(U[0], gamma) : 0.0) - b->e_min;
}

/* The largest l in [0, 1] with UL + l (UH - UL) inside the bounds, given
 * that UL is inside them: the density bounds are linear in l; phi is
 * concave in l, so from a feasible start the feasible set is an interval
 * [0, l*] and bisection on phi finds l* (to 2^-40; the result is kept on
 * the feasible side). A UH that is not finite gives 0. */
NSPD_KERNEL double idp_blend(double gamma, const IdpBounds *b, const double UL[4],
                             const double UH[4]) {
    double d[4];
    for (int v = 0; v < 4; v++) d[v] = UH[v] - UL[v];
    if (!isfinite(d[0] + d[1] + d[2] + d[3])) return 0.0;
    double l = 1.0;
    if (UL[0] + d[0] > b->rho_max && d[0] > 0.0) l = fmin(l, (b->rho_max - UL[0]) / d[0]);
    if (UL[0] + d[0] < b->rho_min && d[0] < 0.0) l = fmin(l, (b->rho_min - UL[0]) / d[0]);
    l = fmax(l, 0.0);
    double U[4];
    for (int v = 0; v < 4; v++) U[v] = UL[v] + l * d[v];
    if (U[0] > 0.0 && idp_entropy_margin(gamma, b, U) >= 0.0) return l;
    double lo = 0.0, hi = l;
    for (int it = 0; it < 40; it++) {
        const double mid = 0.5 * (lo + hi);
        for (int v = 0; v < 4; v++) U[v] = UL[v] + mid * d[v];
        if (U[0] > 0.0 && idp_entropy_margin(gamma, b, U) >= 0.0)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

#endif
