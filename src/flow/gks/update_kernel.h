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
 * the two cells; pressure, viscous stress and heat conduction are kept.
 * Sealed faces inside a solid (the penalty coupling's remedy for leakage)
 * carry only the locked gas, advected with the solid. */
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

/* What gks_ghost_face and gks_seal_face read of the solver: per-cell
 * arrays indexed like the state, per-wall-element and per-seal
 * velocities. */
typedef struct {
    const uint8_t *kind;           /* FLOW_CELL_* */
    const int32_t *wall_slot;      /* wall element of a GHOST cell, or < 0 */
    const double *wall_u, *wall_v; /* wall velocity per element, m/s */
    const int32_t *seal_slot;      /* seal of a FLUID cell a solid locks, or < 0 */
    const double *seal_u, *seal_v; /* the locking solid's velocity per seal, m/s */
    const double *w[4];            /* conservative state */
    double gamma;                  /* ratio of specific heats */
} GksGhostFaces;

/* Sets the mass flux through face i (cells ka, kb on its two sides) to
 * `mass` and takes from its momentum and energy fluxes what the removed
 * mass carried, at the face means of u, v and H = (rho E + p) / rho of the
 * two cells. */
NSPD_KERNEL void gks_keep_mass_flux(const GksGhostFaces *g, int64_t ka, int64_t kb, double mass,
                                    double *const f[4], int64_t i) {
    double u = 0.0, v = 0.0, h = 0.0; /* face means */
    const int64_t ks[2] = {ka, kb};
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
    const double removed = f[0][i] - mass;
    f[0][i] = mass;
    f[1][i] -= removed * u;
    f[2][i] -= removed * v;
    f[3][i] -= removed * h;
}

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
    const double un = dir == 0 ? g->wall_u[e] : g->wall_v[e];
    gks_keep_mass_flux(g, kf, kg, dt * g->w[0][kf] * un, f, i);
}

/* Sealed faces inside a solid (gks_solver_set_seals in solver.h): if both
 * cells kl and kr are FLUID cells a solid locks, the face carries the gas
 * as cargo of the solid, advected at u_s.n, the mean of the two cells'
 * solid velocities, and nothing else:
 *     F = dt u_s.n (rho, rho u, rho v, rho E)_upwind
 * (upwind: the cell the face moves away from, stable for the flow's step
 * since |u_s| stays below the gas's signal speed; zero for a solid at
 * rest).
 * No pressure either: a pressure gradient across gas the penalty holds at
 * the solid's velocity would be turned into heat every step (the penalty
 * dissipates the gas's acceleration). The load on the solid comes through
 * the unsealed faces of its outer cells, where the gas's pressure acts on
 * the locked gas and the penalty hands it on. Leaves other faces alone. */
NSPD_KERNEL void gks_seal_face(const GksGhostFaces *g, int64_t kl, int64_t kr, int dir, double dt,
                               double *const f[4], int64_t i) {
    const int32_t sl = g->seal_slot[kl], sr = g->seal_slot[kr];
    if (sl < 0 || sr < 0 || g->kind[kl] != FLOW_CELL_FLUID || g->kind[kr] != FLOW_CELL_FLUID)
        return;
    const double *us = dir == 0 ? g->seal_u : g->seal_v;
    const double move = 0.5 * dt * (us[sl] + us[sr]);
    const int64_t up = move > 0.0 ? kl : kr;
    for (int v = 0; v < 4; v++) f[v][i] = move * g->w[v][up];
}

#endif
