/* Gas-kinetic BGK-NS flux: public entry points.
 *
 * The arithmetic lives in flux_kernel.h (inline, one face in its normal
 * frame). This module offers it two ways:
 *   gks_flux_face  one face, plain doubles in, flux * dt out (tests, the
 *                  immersed boundary, anything that needs a single face);
 *   gks_flux_row_x / gks_flux_row_y
 *                  a row of faces over struct-of-arrays data, reconstructing
 *                  the face states from cell averages and limited slopes on
 *                  the fly; the loop is vectorised (omp simd).
 * Both are pure kernels: no allocation, no I/O, thread-safe. A y-face is an
 * x-face with the velocity components and the slope directions swapped; the
 * row functions take the component pointers already permuted. */
#ifndef NSPD_FLOW_GKS_FLUX_H
#define NSPD_FLOW_GKS_FLUX_H

#include "flow/gks/flux_kernel.h"

#include <stdint.h>

/* Internal degrees of freedom of a 2D gas with ratio of specific heats gamma:
 * K = (4 - 2 gamma) / (gamma - 1) (K = 3 for gamma = 1.4). */
double gks_internal_dof(double gamma);

/* Fills p for a gas (gamma, R) with no viscosity, Pr = 1, C = 1, eps = 0. */
void gks_params_default(GksParams *p, double gamma, double R);

/* One face, normal frame; components (rho, rho u_n, rho u_t, rho E).
 * wl, wr: face states; nl, nr: their normal derivatives; tl, tr: tangential
 * derivatives; n0, t0: derivatives of the interface equilibrium. Writes
 * f = \int_0^dt F dt per unit face length. */
void gks_flux_face(const double wl[4], const double nl[4], const double tl[4], const double wr[4],
                   const double nr[4], const double tr[4], const double n0[4], const double t0[4],
                   double dt, const GksParams *p, double f[4]);

/* The cells on one side of a row of faces: face k uses element k of each
 * array (the caller offsets the pointers). Components in the face's normal
 * frame order (rho, rho u_n, rho u_t, rho E). */
typedef struct {
    const double *w[4];  /* cell averages */
    const double *sn[4]; /* limited slopes along the face normal, per metre */
    const double *st[4]; /* limited slopes along the face, per metre */
    const uint8_t *kind; /* cell kinds (FLOW_CELL_*; 0 = fluid) */
} GksRowSide;

/* n faces whose geometry varies per face: dl[k], dr[k] = distances from the
 * left / right cell centre to the face, inv_dc[k] = 1 / (dl[k] + dr[k]).
 * Face states: W_L = w_L + sn_L dl, W_R = w_R - sn_R dr; the equilibrium's
 * normal slope is (w_R - w_L) inv_dc, its tangential slope (st_L + st_R)/2.
 * f[c][k] = flux * dt of face k, or 0 where neither cell is fluid. */
void gks_flux_row_x(int n, const GksRowSide *left, const GksRowSide *right, const double *dl,
                    const double *dr, const double *inv_dc, double dt, const GksParams *p,
                    double *const f[4]);

/* The same with one geometry for the whole row (faces between two rows). */
void gks_flux_row_y(int n, const GksRowSide *left, const GksRowSide *right, double dl, double dr,
                    double dt, const GksParams *p, double *const f[4]);

#endif
