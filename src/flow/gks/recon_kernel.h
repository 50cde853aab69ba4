/* MUSCL slopes of one cell along one direction (kernel; recon.h has the
 * method, the row loops are in recon.c).
 *
 * Cell 0 with neighbours m (minus) and p (plus), one-sided differences over
 * centre-to-centre distances, a = (W_0 - W_m) / dl, b = (W_p - W_0) / dr, and
 * the slope limiter(a, b) per conservative variable. The slopes are zero if
 * the cell or a neighbour is SOLID, and zero (counted as a fall-back) if the
 * limited slope would give rho <= 0 or p <= 0 at either face of the cell. */
#ifndef NSPD_FLOW_GKS_RECON_KERNEL_H
#define NSPD_FLOW_GKS_RECON_KERNEL_H

#include "core/kernel.h"
#include "flow/gks/cell_kind.h"

#include <math.h>
#include <stdint.h>

typedef enum {
    LIMITER_VAN_LEER = 0, /* harmonic mean of the one-sided slopes */
    LIMITER_VAN_ALBADA,   /* smoother: max(ab,0)(a+b)/(a^2+b^2) */
    LIMITER_NONE,         /* unlimited central slope (smooth-flow verification only) */
    LIMITER_FIRST_ORDER,  /* zero slopes */
    LIMITER_COUNT
} FlowLimiter;

/* The limited slope from the one-sided slopes a (minus side) and b (plus
 * side); wl = 1/dl and wr = 1/dr weigh the unlimited central slope. The
 * row loops pass `limiter` as a compile-time constant, so the switch folds
 * and the loop vectorises. The 1e-300 keeps 0/0 (a = b = 0) at 0. */
NSPD_KERNEL double recon_limit(FlowLimiter limiter, double a, double b, double wl, double wr) {
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

/* Slopes s[v] of one cell along one direction.
 *   w[0], w[1], w[2]   conservative states of the minus neighbour, the cell
 *                      and the plus neighbour
 *   kind[0..2]         their kinds (FLOW_CELL_*)
 *   idl, idr           1 / centre distance to the minus and plus neighbour, 1/m
 *   hw                 half the cell width, m (face states are W -+ s hw)
 * Returns 1 if positivity sent the cell back to first order, else 0 (a
 * zero slope in or next to a SOLID cell is not counted). */
NSPD_KERNEL int recon_slopes_cell(FlowLimiter limiter, const double w[3][4], const uint8_t kind[3],
                                  double idl, double idr, double hw, double s[4]) {
    double sl[4], lo[4], hi[4];
    for (int v = 0; v < 4; v++) {
        sl[v] =
            recon_limit(limiter, (w[1][v] - w[0][v]) * idl, (w[2][v] - w[1][v]) * idr, idl, idr);
        lo[v] = w[1][v] - sl[v] * hw;
        hi[v] = w[1][v] + sl[v] * hw;
    }
    /* p > 0  <=>  2 rho (rho E) - |rho U|^2 > 0 when rho > 0 */
    const double plo = 2.0 * lo[0] * lo[3] - lo[1] * lo[1] - lo[2] * lo[2];
    const double phi = 2.0 * hi[0] * hi[3] - hi[1] * hi[1] - hi[2] * hi[2];
    const int ok = (lo[0] > 0.0) & (hi[0] > 0.0) & (plo > 0.0) & (phi > 0.0);
    const int solid =
        (kind[0] == FLOW_CELL_SOLID) | (kind[1] == FLOW_CELL_SOLID) | (kind[2] == FLOW_CELL_SOLID);
    const int keep = ok & !solid;
    for (int v = 0; v < 4; v++) s[v] = keep ? sl[v] : 0.0;
    return !ok & !solid;
}

#endif
