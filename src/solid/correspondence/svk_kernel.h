/* The Saint Venant-Kirchhoff material of the correspondence forces
 * (solid/correspondence/bac_force.h, solid/correspondence/classic_force.h): one law, one piece of
 * code, so that the bond-associative model and its classic control differ only in how they
 * discretise, never in the material. E = (F^T F - I) / 2,   S = lambda tr(E) I + 2 mu E,   P = F S
 * In 2D (plane strain) F is embedded in 3 x 3 with F_33 = 1 and zero
 * out-of-plane shears, so S_33 = lambda tr(E) is carried but unused. */
#ifndef NSPD_SOLID_CORRESPONDENCE_SVK_KERNEL_H
#define NSPD_SOLID_CORRESPONDENCE_SVK_KERNEL_H

#include "core/kernel.h"

/* C = A B for 3 x 3 row-major matrices. */
NSPD_KERNEL void svk_matmul(const double A[9], const double B[9], double C[9]) {
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            double v = 0.0;
            for (int k = 0; k < 3; k++) v += A[3 * r + k] * B[3 * k + c];
            C[3 * r + c] = v;
        }
}

/* First Piola-Kirchhoff stress P (row-major 3 x 3, Pa) of the deformation
 * gradient F (row-major 3 x 3; for dim 2 only its upper 2 x 2 is read).
 * Inline (a kernel): with dim a constant the loops unroll and the 3 x 3
 * products stay in registers; the out-of-line call with its loops through
 * memory was 12 % of the hollow cylinder's run (the stable step's power
 * iterations). The operations, zero terms included, are the same. */
NSPD_KERNEL void svk_stress(int dim, const double F[9], double lambda, double mu, double P[9]) {
    double G[9];
    for (int q = 0; q < 9; q++) G[q] = F[q];
    if (dim == 2) G[2] = G[5] = G[6] = G[7] = 0.0, G[8] = 1.0;
    double E[9], tr = 0.0;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            double v = 0.0;
            for (int k = 0; k < 3; k++) v += G[3 * k + r] * G[3 * k + c];
            E[3 * r + c] = 0.5 * (v - (r == c ? 1.0 : 0.0));
        }
    for (int r = 0; r < 3; r++) tr += E[4 * r];
    double S[9];
    for (int q = 0; q < 9; q++) S[q] = 2.0 * mu * E[q];
    for (int r = 0; r < 3; r++) S[4 * r] += lambda * tr;
    svk_matmul(G, S, P);
}

#endif
