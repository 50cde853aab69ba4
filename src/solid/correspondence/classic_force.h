/* The classic correspondence force of Silling et al. (2007), with the
 * zero-energy-mode penalty of Silling (2017) in the form Peridynamics.jl
 * codes it (../shared/notes/correspondence_and_penalty.md 1c.3): the
 * control model of issue 14's correspondence solid. It is what most codes
 * run, and unstabilised it has the spurious zero-energy modes that the
 * bond-associative force (solid/correspondence/bac_force.h) is built to avoid; the
 * zero-energy test (tests/unit/solid/correspondence/test_zero_energy.c, C5) needs a model
 * that fails it to show that it can fail.
 *
 * Per point i and bond ij (xi = X_j - X_i, Y = y_j - y_i, omega = omega_ij):
 *     K_i  = sum_j omega xi (x) xi V_j                       (shape tensor)
 *     F_i  = (sum_j omega Y (x) xi V_j) K_i^-1
 *          = I + (sum_j omega (u_j - u_i) (x) xi V_j) K_i^-1
 *     P_i  = F_i S(E_i)                       (Saint Venant-Kirchhoff,
 * solid/correspondence/svk_kernel.h) z_ij = Y - F_i xi = (u_j - u_i) - (F_i - I) xi        (the
 * non-affine part) T_ij = omega P_i K_i^-1 xi + omega (C_s c / delta) z_ij L_i  = sum_j (T_ij -
 * T_ji) V_j                       (force density, N/m^3) F_i is formed from displacements, not from
 * Y, so that small strains keep their digits (Y = xi + du would cancel xi's). The penalty's scale c
 * is the bond-based micromodulus that matches the bulk modulus K for a family of constant
 * influence: 3D, c = 18 K / (pi delta^4), K = lambda + 2 mu / 3 (Peridynamics.jl's constant); 2D
 * (plane strain), c = 12 K / (pi delta^3) with the in-plane bulk modulus K = lambda + mu, from the
 * same energy match on a disc (1/4 c s^2 int |xi| dA = 2 K s^2 under an isotropic stretch s). Only
 * its order matters: it makes C_s a dimensionless weight of the penalty against the elastic
 * stiffness. In 2D with volumes of thickness t (the body's V = h^2 t) the
 * energy match is per volume, c = 12 K / (pi delta^3 t): the stress term
 * does not depend on t (K_i and the gather both carry it), so neither may
 * the penalty. C_s = 0 is the bare Silling (2007) model.
 * Degenerate families: a point whose K_i is singular (scaled determinant,
 * det K / prod K_aa, below CLASSIC_MIN_SHAPE: fewer than dim independent
 * bond directions) has no F_i, so its bonds carry no force state of their
 * own, T_ij = 0 (no stress and no penalty); its neighbours' T_ji still act
 * on it.
 * Damage: bond_scale (1 - d per bond) multiplies omega everywhere (K_i,
 * F_i, the stress term and the penalty), so a broken bond neither shapes
 * F_i nor carries force.
 * Material: Saint Venant-Kirchhoff (state NULL, P_i = F_i S(E_i)), or the
 * hypoelastic J2 material of solid/correspondence/j2_kernel.h per POINT (ClassicState,
 * 2D): the analogue of the bond-associated model's per-bond state, with
 * the same midpoint increment (F_mid = (F_i^n + F_i^{n+1}) / 2, dF =
 * F_i^{n+1} - F_i^n, Green-Naghdi unrotated increment, radial return,
 * P_i = J sigma F_i^-T). F_i^n is formed from u_prev with the current
 * bond_scale, so a step that breaks bonds does not count the change of the
 * family as a strain increment.
 * Families must be symmetric. No atomics: T is formed per bond by its
 * owner, then each point gathers its own bonds and, through the
 * reverse-bond index (bac_reverse_bonds), its neighbours' (the same bits
 * on any thread count). dim is 2 or 3. */
#ifndef NSPD_SOLID_CORRESPONDENCE_CLASSIC_FORCE_H
#define NSPD_SOLID_CORRESPONDENCE_CLASSIC_FORCE_H

#include "solid/correspondence/j2_kernel.h"

#include <stdint.h>

/* Smallest accepted det K_i / prod_a (K_i)_aa: below it the family's bonds
 * span fewer than dim directions and K_i has no usable inverse. */
#define CLASSIC_MIN_SHAPE 1e-10

typedef struct {
    int dim;
    int64_t n;
    const double *x[3];   /* reference positions, m */
    const double *volume; /* m^3 (2D: m^2 times `thickness`) */
    const int64_t *first; /* family CSR, symmetric */
    const int32_t *nbr;
    const int64_t *reverse; /* reverse[k]: the bond j -> i of bond k = i -> j */
    const double *omega;    /* influence per bond */
    double lambda, mu;      /* Lame constants, Pa */
    double delta;           /* horizon, m: the penalty's scale */
    double thickness;       /* 2D: the thickness the volumes carry, m (0: 1, per unit thickness) */
    double stabilisation;   /* C_s of the zero-energy penalty; 0: none */
    const double *bond_scale; /* 1 - damage per bond (NULL: 1): multiplies omega */
    /* Several processes (solid/correspondence/halo.h): called with T
     * between its pass and the gather, it puts the T of the reverse bonds
     * that other processes own after the run's bonds, where reverse[]
     * points for them (the points j past n are ghosts, with u and x but no
     * bonds of their own). NULL on one process. */
    void (*exchange_bonds)(void *context, double *T);
    void *exchange_context;
} ClassicSystem;

/* The per-point state of the hypoelastic J2 material (2D only). */
typedef struct {
    const J2Material *material;
    const double *u_prev[3]; /* displacements at the start of the step */
    double *sigma;           /* unrotated Cauchy stress, 4 per point [xx, yy, zz, xy], Pa */
    double *eqps;            /* equivalent plastic strain per point */
    double *principal;       /* out: the point's maximum principal Cauchy stress, Pa */
    uint8_t *inverted;       /* out: 1 where det F_i <= 0 (the point carried no stress); a point
                                with a singular K_i: 0 (its stress is left as it was) */
    double *strain_zz;       /* plane stress: the thickness's logarithmic strain per point
                                (NULL: plane strain), as BacState's */
} ClassicState;

/* Force densities L (N/m^3, dim arrays of n) for displacements u, with
 * the SVK law (state NULL) or the J2 material of *state, whose stresses it
 * advances by the step from state->u_prev to u (2D).
 * work_point: 18 n doubles; on return F_i (9 i ..) and P_i (9 n + 9 i ..),
 * row-major 3 x 3 (identity and zero at a point with a singular K_i);
 * work_bond: dim per bond (T), and dim per reverse bond exchange_bonds
 * brings. Returns the number of points whose K_i was
 * singular. */
int64_t classic_force(const ClassicSystem *s, ClassicState *state, const double *const u[3],
                      double *const force[3], double *work_point, double *work_bond);

/* ok[i] = 1 where K_i (with bond_scale) is invertible by the rule of
 * CLASSIC_MIN_SHAPE, else 0, for the points with redo[i] != 0 (redo NULL:
 * all; the others' ok untouched). Returns the number of those points
 * without an invertible K_i. */
int64_t classic_shape_check(const ClassicSystem *s, const uint8_t *redo, uint8_t *ok);

#endif
