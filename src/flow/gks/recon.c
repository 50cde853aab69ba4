/* MUSCL slopes (see recon.h): the row loops over recon_slopes_cell
 * (recon_kernel.h). Each limiter gets its own vectorised loop: the limiter is
 * a compile-time constant of an always-inline body. */
#include "flow/gks/recon.h"

#include "core/kernel.h"
#include "flow/gks/recon_kernel.h"

#include <stddef.h>

/* The row body is inlined into one loop per limiter. */
#define RECON_INLINE static inline __attribute__((always_inline))

/* The body shared by both directions: cell k has neighbours m (minus) and p
 * (plus). per_cell selects array or scalar geometry. */
RECON_INLINE int64_t slopes(int n, FlowLimiter limiter, const double *const wm[4],
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
    NSPD_IVDEP /* vectorised: tests/unit/core/vectorised.sh */
        for (int k = 0; k < n; k++) {
        const double idl = per_cell ? idla[k] : idls, idr = per_cell ? idra[k] : idrs;
        const double hw = per_cell ? hwa[k] : hws;
        const double w[3][4] = {{m0[k], m1[k], m2[k], m3[k]},
                                {c0[k], c1[k], c2[k], c3[k]},
                                {p0[k], p1[k], p2[k], p3[k]}};
        const uint8_t kind[3] = {km[k], k0[k], kp[k]};
        double sl[4];
        fallbacks += recon_slopes_cell(limiter, w, kind, idl, idr, hw, sl);
        s0[k] = sl[0];
        s1[k] = sl[1];
        s2[k] = sl[2];
        s3[k] = sl[3];
    }
    return fallbacks;
}

int64_t recon_slopes_x(int n, FlowLimiter limiter, const double *const w[4], const uint8_t *kind,
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

int64_t recon_slopes_y(int n, FlowLimiter limiter, const double *const wm[4],
                       const double *const w0[4], const double *const wp[4], const uint8_t *km,
                       const uint8_t *k0, const uint8_t *kp, double inv_dl, double inv_dr,
                       double half_width, double *const s[4]) {
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
