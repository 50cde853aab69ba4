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
 * Families must be symmetric (j in H_i exactly when i in H_j), and so are
 * omega and the damage. T is never stored: with c_ij = omega_ij (1 / (2
 * w0_i) + 1 / (2 w0_j)) V_j and g = xi / |xi|^2, the same L_i reads
 *     L_i  = 2 sum_j c_ij P_b(ij) g + S_i sum_j phi_ij V_j - sum_j S_j phi_ji V_j
 * (the direct terms of T_ij and T_ji share P_b and -g), so each point
 * gathers its neighbours' S_j instead of their bonds' T_ji, and c_ij,
 * phi_ji V_j and sum_j phi_ij V_j, which change only with the damage, are
 * kept (BacCoefficients). No atomics: each point writes only its own S_i
 * and force (the same bits on any thread count). The material is
 * solid/correspondence/svk_kernel.h (2D: plane strain). */
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
    int32_t *of;
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
    /* bac_coefficients' c, phi_rev and phi_sum, kept by the caller while
     * omega, bond_scale, phi and the volumes stay; NULL: formed at each
     * call (in work_bond and work_point) */
    const double *c, *phi_rev, *phi_sum;
    /* On several processes (solid/correspondence/halo.h): the points
     * with the ghosts after the n owned ones, the per-point scratch's
     * length (0: n), and what fills the ghosts' entries of a per-point
     * array of `width` doubles a point from their owners: F (and F at
     * u_prev) after the first pass, S before the last (NULL: one process) */
    int64_t n_all;
    void (*exchange)(void *context, double *array, int width);
    void *exchange_context;
} BacSystem;

/* The state of the hypoelastic J2 material (solid/correspondence/j2_kernel.h;
 * 2D only), per bond pair (F_b(ij) = F_b(ji) bit for bit, negated operands;
 * STYLE.md): the pair's stress is updated from the change of its F_b over
 * the step instead of being a function of F_b. Struct of arrays: sigma's
 * component c of pair p is sigma[c pairs.count + p]. */
typedef struct {
    const J2Material *material;
    const double *u_prev[3]; /* displacements at the start of the step */
    /* The pairs' bond deformation gradients, 4 per pair (in-plane,
     * row-major, component q of pair p at [q pairs.count + p]): on entry
     * F_b at u_prev when fb_given is 1 (an earlier call's at those
     * displacements and weights: the body keeps its last step's), else
     * formed here from F_prev; on return F_b at u. */
    double *Fb;
    int fb_given;
    double *F_prev;    /* 9 n scratch: F at u_prev, formed when fb_given is 0 */
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
 * nspd_alloc; bac_pairs_free frees them. NSPD_ERR_NOMEM; NSPD_ERR_INPUT
 * beyond INT32_MAX pairs. */
int bac_pairs_create(int64_t n, const int64_t *first, const int64_t *reverse, BacPairs *pairs);
void bac_pairs_free(BacPairs *pairs);

/* 1 / w0_i = 1 / sum_j omega_ij (1 - d_ij) V_j per point (0 where w0 = 0:
 * every bond broken), into inv_w0 (n), for the points with only[i] != 0
 * (NULL: all): what bac_force forms when s->inv_w0 is NULL. */
void bac_inverse_weights(const BacSystem *s, const uint8_t *only, double *inv_w0);

/* What the force's sums take from the weights and the damage alone
 * (constant between damage changes): per bond k = (i -> j) the stress
 * integral's weight c[k] = omega_ij s_ij (1 / (2 w0_i) + 1 / (2 w0_j)) V_j
 * (s = bond_scale) and the reverse bond's RK weight times V_j,
 * phi_rev[dim k + a] = phi_ji,a V_j; per point phi_sum[dim i + a] = sum_j
 * phi_ij,a V_j. inv_w0: bac_inverse_weights'. Only for the points i with
 * only[i] != 0 (NULL: all): after damage, those whose family's damage grew
 * and their neighbours (c reads both ends' w0, phi_rev the neighbour's phi). */
void bac_coefficients(const BacSystem *s, const double *inv_w0, const uint8_t *only, double *c,
                      double *phi_rev, double *phi_sum);

/* Force densities L (N/m^3, dim arrays of n) for displacements u, with the
 * hyperelastic Saint Venant-Kirchhoff law (state NULL) or the hypoelastic
 * J2 material of *state, whose stresses it advances by the step from
 * state->u_prev to u (2D); F (9 n) receives the points' F at u.
 * work_point: bac_work_per_point(dim) n doubles (n_all with ghosts) (1 / w0, S and the direct
 * force per point, and phi_sum when s has none); work_bond:
 * bac_work_bond(s, plane stress) doubles (P_b per pair, component c of
 * pair p at [c pairs.count + p]; in plane stress a flag per pair; c and
 * phi_rev per bond when s has none). Four passes: F_i; per pair its P_b
 * (and state update) once; per point S_i and the direct force; per point
 * the gather of S_j. A point with w0 = 0 (every bond broken) exerts no
 * force. */
static inline int64_t bac_work_per_point(int dim) {
    return 1 + dim * dim + 2 * dim;
}
/* at most, per bond (a pair has one bond or two), with no coefficients kept */
static inline int64_t bac_work_per_bond(int dim) {
    return dim * dim + 2 + dim;
}
static inline int64_t bac_work_bond(const BacSystem *s, int plane_stress) {
    const int64_t nb = s->first[s->n];
    return (s->dim * s->dim + (s->c ? plane_stress : 1)) * s->pairs.count +
           (s->c ? 0 : (1 + s->dim) * nb);
}

void bac_force(const BacSystem *s, BacState *state, const double *const u[3],
               double *const force[3], double *F, double *work_point, double *work_bond);

/* bac_force's last two passes alone: the forces L_i of given pair
 * stresses Pb (component c of pair p at Pb[c pairs.count + p]) through
 * the geometry of s (its x as the bonds' vectors) and the coefficients c,
 * phi_rev, phi_sum (bac_coefficients'); work_point as bac_force's (its
 * S and D parts). The semi-Lagrangian force (sl_force.h) hands it the
 * Kirchhoff stresses and the current configuration. */
void bac_stress_force(const BacSystem *s, const double *c, const double *phi_rev,
                      const double *phi_sum, const double *Pb, double *const force[3],
                      double *work_point);

#endif
