/* MUSCL slopes (see recon.h). Each limiter gets its own vectorised loop: the
 * limiter is a compile-time constant of an always-inline body. */
#include "flow/recon.h"

#include "flow/flow_solver.h"

#include <math.h>
#include <stddef.h>

#define RECON_INLINE static inline __attribute__((always_inline))

RECON_INLINE double limit(int limiter, double a, double b, double wl, double wr) {
    switch (limiter) {
    case LIMITER_VAN_LEER:
        return (a * fabs(b) + fabs(a) * b) / (fabs(a) + fabs(b) + 1e-300);
    case LIMITER_VAN_ALBADA: {
        const double ab = a * b;
        return (ab > 0.0 ? ab : 0.0) * (a + b) / (a * a + b * b + 1e-300);
    }
    case LIMITER_NONE:
        return (a * wl + b * wr) / (wl + wr);
    default:
        return 0.0;
    }
}

/* The body shared by both directions: cell k has neighbours m (minus) and p
 * (plus). per_cell selects array or scalar geometry. */
RECON_INLINE int64_t slopes(int n, int limiter, const double *const wm[4],
                            const double *const w0[4], const double *const wp[4],
                            const uint8_t *restrict km, const uint8_t *restrict k0,
                            const uint8_t *restrict kp, const double *restrict idla,
                            const double *restrict idra, const double *restrict hwa, double idls,
                            double idrs, double hws, int per_cell, double *const s[4]) {
    const double *restrict m0 = wm[0], *restrict m1 = wm[1], *restrict m2 = wm[2],
                           *restrict m3 = wm[3];
    const double *restrict c0 = w0[0], *restrict c1 = w0[1], *restrict c2 = w0[2],
                           *restrict c3 = w0[3];
    const double *restrict p0 = wp[0], *restrict p1 = wp[1], *restrict p2 = wp[2],
                           *restrict p3 = wp[3];
    double *restrict s0 = s[0], *restrict s1 = s[1], *restrict s2 = s[2], *restrict s3 = s[3];
    int64_t fallbacks = 0;
#pragma GCC ivdep
    for (int k = 0; k < n; k++) {
        const double idl = per_cell ? idla[k] : idls, idr = per_cell ? idra[k] : idrs;
        const double hw = per_cell ? hwa[k] : hws;
        const double cm[4] = {m0[k], m1[k], m2[k], m3[k]};
        const double cc[4] = {c0[k], c1[k], c2[k], c3[k]};
        const double cp[4] = {p0[k], p1[k], p2[k], p3[k]};
        double sl[4], lo[4], hi[4];
        for (int v = 0; v < 4; v++) {
            sl[v] = limit(limiter, (cc[v] - cm[v]) * idl, (cp[v] - cc[v]) * idr, idl, idr);
            lo[v] = cc[v] - sl[v] * hw;
            hi[v] = cc[v] + sl[v] * hw;
        }
        /* p > 0  <=>  2 rho (rho E) - |rho U|^2 > 0 when rho > 0 */
        const double plo = 2.0 * lo[0] * lo[3] - lo[1] * lo[1] - lo[2] * lo[2];
        const double phi = 2.0 * hi[0] * hi[3] - hi[1] * hi[1] - hi[2] * hi[2];
        const int ok = (lo[0] > 0.0) & (hi[0] > 0.0) & (plo > 0.0) & (phi > 0.0);
        const int solid =
            (km[k] == FLOW_CELL_SOLID) | (k0[k] == FLOW_CELL_SOLID) | (kp[k] == FLOW_CELL_SOLID);
        const int keep = ok & !solid;
        fallbacks += !ok & !solid;
        s0[k] = keep ? sl[0] : 0.0;
        s1[k] = keep ? sl[1] : 0.0;
        s2[k] = keep ? sl[2] : 0.0;
        s3[k] = keep ? sl[3] : 0.0;
    }
    return fallbacks;
}

int64_t recon_slopes_x(int n, int limiter, const double *const w[4], const uint8_t *kind,
                       const double *inv_dl, const double *inv_dr, const double *half_width,
                       double *const s[4]) {
    const double *wm[4], *wp[4];
    for (int v = 0; v < 4; v++) {
        wm[v] = w[v] - 1;
        wp[v] = w[v] + 1;
    }
    switch (limiter) {
    case LIMITER_VAN_LEER:
        return slopes(n, LIMITER_VAN_LEER, wm, w, wp, kind - 1, kind, kind + 1, inv_dl, inv_dr,
                      half_width, 0, 0, 0, 1, s);
    case LIMITER_VAN_ALBADA:
        return slopes(n, LIMITER_VAN_ALBADA, wm, w, wp, kind - 1, kind, kind + 1, inv_dl, inv_dr,
                      half_width, 0, 0, 0, 1, s);
    case LIMITER_NONE:
        return slopes(n, LIMITER_NONE, wm, w, wp, kind - 1, kind, kind + 1, inv_dl, inv_dr,
                      half_width, 0, 0, 0, 1, s);
    default:
        return slopes(n, LIMITER_FIRST_ORDER, wm, w, wp, kind - 1, kind, kind + 1, inv_dl, inv_dr,
                      half_width, 0, 0, 0, 1, s);
    }
}

int64_t recon_slopes_y(int n, int limiter, const double *const wm[4], const double *const w0[4],
                       const double *const wp[4], const uint8_t *km, const uint8_t *k0,
                       const uint8_t *kp, double inv_dl, double inv_dr, double half_width,
                       double *const s[4]) {
    switch (limiter) {
    case LIMITER_VAN_LEER:
        return slopes(n, LIMITER_VAN_LEER, wm, w0, wp, km, k0, kp, NULL, NULL, NULL, inv_dl, inv_dr,
                      half_width, 0, s);
    case LIMITER_VAN_ALBADA:
        return slopes(n, LIMITER_VAN_ALBADA, wm, w0, wp, km, k0, kp, NULL, NULL, NULL, inv_dl,
                      inv_dr, half_width, 0, s);
    case LIMITER_NONE:
        return slopes(n, LIMITER_NONE, wm, w0, wp, km, k0, kp, NULL, NULL, NULL, inv_dl, inv_dr,
                      half_width, 0, s);
    default:
        return slopes(n, LIMITER_FIRST_ORDER, wm, w0, wp, km, k0, kp, NULL, NULL, NULL, inv_dl,
                      inv_dr, half_width, 0, s);
    }
}
