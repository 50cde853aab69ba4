/* The classic correspondence force of Silling et al. (2007), with the
 * zero-energy-mode penalty of Silling (2017) in the form Peridynamics.jl
 * codes it (../shared/notes/correspondence_and_penalty.md 1c.3): the
 * control model of issue 14's correspondence solid. It is what most codes
 * run, and unstabilised it has the spurious zero-energy modes that the
 * bond-associative force (solid/bac_force.h) is built to avoid; the
 * zero-energy test (tests/unit/solid/test_zero_energy.c, C5) needs a model
 * that fails it to show that it can fail.
 *
 * Per point i and bond ij (xi = X_j - X_i, Y = y_j - y_i, omega = omega_ij):
 *     K_i  = sum_j omega xi (x) xi V_j                       (shape tensor)
 *     F_i  = (sum_j omega Y (x) xi V_j) K_i^-1
 *          = I + (sum_j omega (u_j - u_i) (x) xi V_j) K_i^-1
 *     P_i  = F_i S(E_i)                       (Saint Venant-Kirchhoff, solid/svk.h)
 *     z_ij = Y - F_i xi = (u_j - u_i) - (F_i - I) xi        (the non-affine part)
 *     T_ij = omega P_i K_i^-1 xi + omega (C_s c / delta) z_ij
 *     L_i  = sum_j (T_ij - T_ji) V_j                       (force density, N/m^3)
 * F_i is formed from displacements, not from Y, so that small strains keep
 * their digits (Y = xi + du would cancel xi's).
 * The penalty's scale c is the bond-based micromodulus that matches the
 * bulk modulus K for a family of constant influence: 3D, c = 18 K / (pi
 * delta^4), K = lambda + 2 mu / 3 (Peridynamics.jl's constant); 2D (plane
 * strain), c = 12 K / (pi delta^3) with the in-plane bulk modulus
 * K = lambda + mu, from the same energy match on a disc (1/4 c s^2 int |xi|
 * dA = 2 K s^2 under an isotropic stretch s). Only its order matters: it
 * makes C_s a dimensionless weight of the penalty against the elastic
 * stiffness. C_s = 0 is the bare Silling (2007) model.
 * Degenerate families: a point whose K_i is singular (scaled determinant,
 * det K / prod K_aa, below CLASSIC_MIN_SHAPE: fewer than dim independent
 * bond directions) has no F_i, so its bonds carry no force state of their
 * own, T_ij = 0 (no stress and no penalty); its neighbours' T_ji still act
 * on it.
 * Families must be symmetric. No atomics: T is formed per bond by its
 * owner, then each point gathers its own bonds and, through the
 * reverse-bond index (bac_reverse_bonds), its neighbours' (the same bits
 * on any thread count). dim is 2 or 3. */
#ifndef NSPD_SOLID_CLASSIC_FORCE_H
#define NSPD_SOLID_CLASSIC_FORCE_H

#include <stdint.h>

/* Smallest accepted det K_i / prod_a (K_i)_aa: below it the family's bonds
 * span fewer than dim directions and K_i has no usable inverse. */
#define CLASSIC_MIN_SHAPE 1e-10

typedef struct {
    int dim;
    int64_t n;
    const double *x[3];   /* reference positions, m */
    const double *volume; /* m^3 (2D: m^2 per unit thickness) */
    const int64_t *first; /* family CSR, symmetric */
    const int32_t *nbr;
    const int64_t *reverse; /* reverse[k]: the bond j -> i of bond k = i -> j */
    const double *omega;    /* influence per bond */
    double lambda, mu;      /* Lame constants, Pa */
    double delta;           /* horizon, m: the penalty's scale */
    double stabilisation;   /* C_s of the zero-energy penalty; 0: none */
} ClassicSystem;

/* Force densities L (N/m^3, dim arrays of n) for displacements u.
 * work_point: 18 n doubles; on return F_i (9 i ..) and P_i (9 n + 9 i ..),
 * row-major 3 x 3 (identity and zero at a point with a singular K_i);
 * work_bond: dim per bond (T). Returns the number of points whose K_i was
 * singular. */
int64_t classic_force(const ClassicSystem *s, const double *const u[3], double *const force[3],
                      double *work_point, double *work_bond);

#endif
