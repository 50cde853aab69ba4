/* MUSCL slopes with a limiter, per row of cells (kernel layer).
 *
 * Variables: the conservative ones (rho, rho u, rho v, rho E), limited
 * component-wise. The GKS needs conservative slopes anyway (the micro slopes
 * a, b solve rho <a psi> = dW, Eq. 25), conservative limiting is cheap and
 * keeps the face states consistent with the cell averages, and the
 * pressure-jump term of tau_n damps the small oscillations that component-wise
 * limiting lets through at strong shocks (characteristic limiting would cost a
 * 4x4 eigen-projection per cell and direction). Positivity is enforced
 * separately: if a limited slope would give rho <= 0 or p <= 0 at either face
 * of the cell, that cell's slopes in that direction are set to zero (first
 * order) and the event is counted.
 *
 * One-sided differences use centre-to-centre distances, so stretched grids
 * need no special case: a = (W_i - W_{i-1}) / (x_i - x_{i-1}),
 * b = (W_{i+1} - W_i) / (x_{i+1} - x_i), slope = limiter(a, b):
 *   van Leer   (a |b| + |a| b) / (|a| + |b|)      (= 2ab/(a+b) if ab > 0, else 0)
 *   van Albada max(ab, 0) (a + b) / (a^2 + b^2)
 *   none       (a (x_{i+1}-x_i) + b (x_i-x_{i-1})) / (x_{i+1} - x_{i-1})   (unlimited)
 * A slope is also zero in a SOLID cell and next to one (kinds from
 * cell_kind.h). The arithmetic of one cell is recon_slopes_cell
 * (recon_kernel.h). */
#ifndef NSPD_FLOW_GKS_RECON_H
#define NSPD_FLOW_GKS_RECON_H

#include "flow/gks/recon_kernel.h" /* FlowLimiter */

#include <stdint.h>

/* Slopes along x of n consecutive cells of a row. w[v], kind, inv_dl,
 * inv_dr, half_width point at the first cell; its neighbours at -1 and +1
 * are read. s[v][k] receives the slope of cell k. Returns the number of
 * cells that fell back to first order. */
int64_t recon_slopes_x(int n, FlowLimiter limiter, const double *const w[4], const uint8_t *kind,
                       const double *inv_dl, const double *inv_dr, const double *half_width,
                       double *const s[4]);

/* Slopes along y of n consecutive cells of row j: wm, w0, wp are rows j-1,
 * j, j+1 (pointers at the first cell), with their kinds; geometry is one
 * value for the row. */
int64_t recon_slopes_y(int n, FlowLimiter limiter, const double *const wm[4],
                       const double *const w0[4], const double *const wp[4], const uint8_t *km,
                       const uint8_t *k0, const uint8_t *kp, double inv_dl, double inv_dr,
                       double half_width, double *const s[4]);

#endif
