/* The bond-associative correspondence force (paper 003 Sec. 2, the
 * Lagrangian form of ../shared/notes/correspondence_and_penalty.md 1c.5),
 * for a hyperelastic Saint Venant-Kirchhoff material: the second piece of
 * the correspondence solid of issue 14, verified alone
 * (tests/unit/solid/correspondence/test_bac_force.c: momentum and objectivity on any
 * cloud; on nspd's regular lattice the patch test and the divergence of a
 * quadratic field, exactly; on perturbed clouds the patch test fails, as
 * for any nodal integration without a consistency correction); plasticity,
 * damage and the model behind the solid interface come next.
 *
 * With the RK weights phi (solid/correspondence/rk_gradient.h), per point i and bond ij
 * (xi = X_j - X_i, Y = y_j - y_i, omega_ij the kernel):
 *     F_i  = I + sum_j (u_j - u_i) (x) phi_ij V_j
 *     Fm   = (F_i + F_j) / 2,   F_b = Fm + (Y - Fm xi) (x) xi / |xi|^2     (the bond's F)
 *     P_b  = F_b S(E_b),  E_b = (F_b^T F_b - I) / 2,  S = lambda tr(E) I + 2 mu E
 *     w0_i = sum_j omega_ij V_j
 *     S_i  = sum_k omega_ik (1 / (2 w0_i) + 1 / (2 w0_k)) P_b(ik) (I - xi (x) xi / |xi|^2) V_k
 *     T_ij = (omega_ij / w0_i) P_b(ij) xi / |xi|^2 + S_i phi_ij
 *     L_i  = sum_j (T_ij - T_ji) V_j                                     (force density)
 * F_b(ij) = F_b(ji), so each pair's P_b is computed from either end alike.
 * Families must be symmetric (j in H_i exactly when i in H_j). No atomics:
 * T is formed per bond, then each point gathers its own bonds and, through
 * the reverse-bond index, its neighbours' (the same bits on any thread
 * count). The material is solid/correspondence/svk_kernel.h (2D: plane strain). */
#ifndef NSPD_SOLID_CORRESPONDENCE_BAC_FORCE_H
#define NSPD_SOLID_CORRESPONDENCE_BAC_FORCE_H

#include "solid/correspondence/j2_kernel.h"

#include <stdint.h>

/* The bond pairs (i -> j, j -> i) of a symmetric family: the bond-
 * associated force forms each pair's P_b and material state once, and
 * stores them per pair. Pair p is known by its canonical bond bond[p] (the
 * lower-numbered of the two, in bond order) and that bond's point
 * point[p]; of[k] is bond k's pair. */
typedef struct {
    int64_t count;
    int64_t *bond;
    int32_t *point;
    int64_t *of;
} BacPairs;

typedef struct {
    int dim;
    int64_t n;
    const double *x[3];   /* reference positions, m */
    const double *volume; /* m^3 */
    const int64_t *first; /* family CSR, symmetric */
    const int32_t *nbr;
    const int64_t *reverse; /* reverse[k]: the bond j -> i of bond k = i -> j */
    const double *phi;      /* RK weights, dim per bond */
    const double *omega;    /* kernel per bond */
    double lambda, mu;      /* Lame constants, Pa */
    /* 1 - damage per bond (NULL: 1): multiplies omega in w0, S_i and T_ij
     * (phi must have been computed with the same scale) */
    const double *bond_scale;
    BacPairs pairs; /* bac_pairs_create */
    /* 1 / w0 per point (bac_inverse_weights), kept by the caller while
     * omega, bond_scale and the volumes stay; NULL: formed at each call */
    const double *inv_w0;
} BacSystem;

/* The state of the hypoelastic J2 material (solid/correspondence/j2_kernel.h;
 * 2D only), per bond pair (F_b(ij) = F_b(ji) bit for bit, negated operands;
 * STYLE.md): the pair's stress is updated from the change of its F_b over
 * the step instead of being a function of F_b. Struct of arrays: sigma's
 * component c of pair p is sigma[c pairs.count + p]. */
typedef struct {
    const J2Material *material;
    const double *u_prev[3]; /* displacements at the start of the step */
    /* 1: work_point's F at u_prev (9 n from 9 n) is given, formed by an
     * earlier call at those displacements and weights (the body keeps it
     * from its last step), and not formed again */
    int fp_given;
    double *sigma;     /* unrotated Cauchy stress, 4 per pair [xx, yy, zz, xy], Pa */
    double *eqps;      /* equivalent plastic strain per pair */
    double *principal; /* out: the pair's maximum principal Cauchy stress, Pa */
    uint8_t *inverted; /* out: 1 where det F_b <= 0 (the pair carried no stress) */
    /* plane stress: the logarithmic thickness strain per pair, sum of
     * de_zz, whose stretch exp() scales P_b (NULL: plane strain) */
    double *strain_zz;
} BacState;

/* The owner-computes gather of both correspondence forces: L_i = sum_j
 * (T_ij - T_ji) V_j in bond order, T_ji read through the reverse-bond
 * index (dim values per bond); each point writes only its own force, so
 * no atomics and the same bits at any thread count. */
void bac_gather(int dim, int64_t n, const int64_t *first, const int32_t *nbr,
                const int64_t *reverse, const double *volume, const double *T,
                double *const force[3]);

/* The reverse-bond index of a symmetric family CSR: for bond k = (i -> j),
 * reverse[k] is the bond (j -> i); -1 where the family is not symmetric.
 * Returns the number of bonds without a reverse. */
int64_t bac_reverse_bonds(int64_t n, const int64_t *first, const int32_t *nbr, int64_t *reverse);

/* The pairs of a symmetric family CSR with its reverse-bond index (a bond
 * without a reverse is a pair of its own), in arrays allocated with
 * nspd_alloc; bac_pairs_free frees them. NSPD_ERR_NOMEM. */
int bac_pairs_create(int64_t n, const int64_t *first, const int64_t *reverse, BacPairs *pairs);
void bac_pairs_free(BacPairs *pairs);

/* 1 / w0_i = 1 / sum_j omega_ij (1 - d_ij) V_j per point (0 where w0 = 0:
 * every bond broken), into inv_w0 (n): what bac_force forms when
 * s->inv_w0 is NULL. */
void bac_inverse_weights(const BacSystem *s, double *inv_w0);

/* Force densities L (N/m^3, dim arrays of n) for displacements u, with the
 * hyperelastic Saint Venant-Kirchhoff law (state NULL) or the hypoelastic
 * J2 material of *state, whose stresses it advances by the step from
 * state->u_prev to u (2D). work_point: 19 n doubles (F, F at u_prev and
 * 1 / w0 per point); work_bond: dim + dim^2 per bond (T per bond, P_b per
 * pair, component c of pair p at [c pairs.count + p]). Four passes: F_i and
 * w0_i; per pair its P_b (and state update) once; per point S_i and T_ij; per
 * point the gather of T_ij - T_ji. A point with w0 = 0 (every bond broken)
 * exerts no force. */
/* The doubles of work_bond per bond that bac_force needs at most: T and
 * P_b (which is per pair: half that with every bond in a pair). */
static inline int bac_work_per_bond(int dim) {
    return dim + dim * dim;
}

void bac_force(const BacSystem *s, BacState *state, const double *const u[3],
               double *const force[3], double *work_point, double *work_bond);

#endif
