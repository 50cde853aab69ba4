/* The cell update of the GKS step and the flux correction of a face between
 * a fluid cell and an immersed-wall ghost cell (kernels; step.c has
 * the row loops).
 *
 * Update (paper 000 Eq. 20 on a Cartesian cell of widths dx, dy):
 *     W^{n+1} = W^n - (F_e - F_w) / dx - (G_n - G_s) / dy,
 * F, G the fluxes integrated over the step (flux_kernel.h) per unit face
 * length. Only FLUID cells change; a fluid cell whose new state has
 * rho <= 0 or p <= 0 (or NaN) is reported.
 *
 * Sealed ghost faces (gks_solver_set_ghost_walls in solver.h). Across
 * a face between a FLUID cell and a GHOST cell of an immersed wall the mass
 * flux is the one the wall's motion displaces, F_rho' = dt rho_f u_w.n, and
 * the momentum and energy fluxes lose what the removed mass carried,
 * (F_rho - F_rho') times the face means of u, v and H = (rho E + p) / rho of
 * the two cells; pressure, viscous stress and heat conduction are kept. */
#ifndef NSPD_FLOW_GKS_UPDATE_KERNEL_H
#define NSPD_FLOW_GKS_UPDATE_KERNEL_H

#include "core/kernel.h"
#include "flow/gks/cell_kind.h"

#include <stdint.h>

/* W^{n+1} of one cell.
 *   kind      the cell's kind (FLOW_CELL_*); only FLUID cells change
 *   w         W^n (rho, rho u, rho v, rho E)
 *   fx[0, 1]  fluxes through the low-x and high-x faces
 *   gy[0, 1]  fluxes through the low-y and high-y faces
 *   idx, idy  1 / cell widths, 1/m
 *   wn        out: W^{n+1} (= w unless FLUID)
 * Returns 1 if the cell is FLUID and its new state not physical, else 0. */
NSPD_KERNEL int gks_update_cell(uint8_t kind, const double w[4], const double fx[2][4],
                                const double gy[2][4], double idx, double idy, double wn[4]) {
    const int fluid = kind == FLOW_CELL_FLUID;
    double u[4];
    for (int v = 0; v < 4; v++) {
        u[v] = w[v] - (fx[1][v] - fx[0][v]) * idx - (gy[1][v] - gy[0][v]) * idy;
        wn[v] = fluid ? u[v] : w[v];
    }
    /* 2 rho (rho E) - |rho U|^2 = 2 rho^2 e_int > 0, and NaN fails it */
    const double pp = 2.0 * u[0] * u[3] - u[1] * u[1] - u[2] * u[2];
    return fluid & !((u[0] > 0.0) & (pp > 0.0));
}

/* What gks_ghost_face reads of the solver: per-cell arrays indexed like the
 * state, per-wall-element velocities. */
typedef struct {
    const uint8_t *kind;           /* FLOW_CELL_* */
    const int32_t *wall_slot;      /* wall element of a GHOST cell, or < 0 */
    const double *wall_u, *wall_v; /* wall velocity per element, m/s */
    const double *w[4];            /* conservative state */
    double gamma;                  /* ratio of specific heats */
} GksGhostFaces;

/* Corrects f[v][i], the flux through the face with normal `dir` (0: x,
 * 1: y) between cells kl (low side) and kr, if one of them is FLUID and the
 * other a GHOST cell with a wall element; leaves it alone otherwise. */
NSPD_KERNEL void gks_ghost_face(const GksGhostFaces *g, int64_t kl, int64_t kr, int dir, double dt,
                                double *const f[4], int64_t i) {
    const uint8_t al = g->kind[kl], ar = g->kind[kr];
    int64_t kf, kg;
    if (al == FLOW_CELL_FLUID && ar == FLOW_CELL_GHOST)
        kf = kl, kg = kr;
    else if (al == FLOW_CELL_GHOST && ar == FLOW_CELL_FLUID)
        kf = kr, kg = kl;
    else
        return;
    const int32_t e = g->wall_slot[kg];
    if (e < 0) return;
    double u = 0.0, v = 0.0, h = 0.0; /* face means */
    const int64_t ks[2] = {kf, kg};
    for (int c = 0; c < 2; c++) {
        const int64_t k = ks[c];
        const double w[4] = {g->w[0][k], g->w[1][k], g->w[2][k], g->w[3][k]};
        /* primitives as flow_cons_to_prim (bc.c) computes them */
        const double uc = w[1] / w[0], vc = w[2] / w[0];
        const double p = (g->gamma - 1.0) * (w[3] - 0.5 * (w[1] * uc + w[2] * vc));
        u += 0.5 * uc;
        v += 0.5 * vc;
        h += 0.5 * (w[3] + p) / w[0];
    }
    const double un = dir == 0 ? g->wall_u[e] : g->wall_v[e];
    const double mass = dt * g->w[0][kf] * un;
    const double removed = f[0][i] - mass;
    f[0][i] = mass;
    f[1][i] -= removed * u;
    f[2][i] -= removed * v;
    f[3][i] -= removed * h;
}

#endif
