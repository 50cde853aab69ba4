/* The Saint Venant-Kirchhoff material of the correspondence forces
 * (solid/correspondence/bac_force.h, solid/correspondence/classic_force.h): one law, one piece of
 * code, so that the bond-associative model and its classic control differ only in how they
 * discretise, never in the material. E = (F^T F - I) / 2,   S = lambda tr(E) I + 2 mu E,   P = F S
 * In 2D (plane strain) F is embedded in 3 x 3 with F_33 = 1 and zero
 * out-of-plane shears, so S_33 = lambda tr(E) is carried but unused. */
#ifndef NSPD_SOLID_CORRESPONDENCE_SVK_H
#define NSPD_SOLID_CORRESPONDENCE_SVK_H

/* First Piola-Kirchhoff stress P (row-major 3 x 3, Pa) of the deformation
 * gradient F (row-major 3 x 3; for dim 2 only its upper 2 x 2 is read). */
void svk_stress(int dim, const double F[9], double lambda, double mu, double P[9]);

#endif
