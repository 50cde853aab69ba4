/* The semi-Lagrangian bond-associated correspondence force of paper 003's
 * ref. [10] (Behzadinasab and Foster 2020; the last paragraph of
 * ../shared/notes/correspondence_and_penalty.md 1c.5), 2D, with the J2
 * material: the option `solid.correspondence.frame: semi_lagrangian` beside
 * the Lagrangian force of bac_force.h.
 *
 * The families stay the reference ones (a bond is the same pair of points
 * for ever; damage breaks it), but the kernel and the RK gradient weights
 * are those of the configuration the points are in, and the stress that the
 * bonds carry is the Kirchhoff stress on the current bond vectors. With
 * phi(y) the weights of rk_gradient.h built on positions y (the kernel
 * omega(y) scaled by 1 - damage), per step from y_n = X + u_prev to
 * y_{n+1} = X + u:
 *     G_i = I + sum_j (du_j - du_i) (x) phi_ij(y_n) V_j            (the step's
 *           relative deformation gradient, du = u - u_prev: L_i dt of [10])
 *     Gm  = (G_i + G_j) / 2,  G_b = Gm + (Y_{n+1} - Gm y) (x) y / |y|^2,  y = Y_n
 *           (the bond's, which maps the bond's own vector exactly: G_b Y_n = Y_{n+1})
 *     F_b^{n+1} = G_b F_b^n                                          (kept per pair)
 *     sigma_b: j2_step_2d from F_b^n to F_b^{n+1} (Green-Naghdi rate, radial return)
 *     tau_b = J_b sigma_b = P_b F_b^T                                 (Kirchhoff)
 * and the force is bac_force's sums with P_b -> tau_b, xi -> Y_{n+1}, phi ->
 * phi(y_{n+1}) and omega -> omega(y_{n+1}): the internal power sum_i V_i
 * sum_j (omega_ij / w0_i) V_j tau_b : L_b with L_b = Lm + (V_ij - Lm y) (x)
 * y / |y|^2 has bac_force's structure in the current configuration (tau
 * per reference volume, so the volumes stay the reference ones). The
 * weights' own change with y is not varied (the "semi" of [10]: energy is
 * not exactly conserved, momentum is: the forces are pairwise).
 *
 * Under a homogeneous motion the RK weights reproduce it exactly in either
 * configuration, so F_b is the motion's F and the stresses are the
 * Lagrangian force's (tests/unit/solid/correspondence/test_sl_force.c);
 * the forms part with damage (weights refitted to the deformed, broken
 * family) and large distortion. A bond stretched or turned past the
 * kernel's support (|y|_inf > delta for the tensor kernel, |y| > delta for
 * the radial one) stops carrying weight without breaking. The tensor
 * kernel measured on current bonds follows their direction against the
 * axes, so a rotated body's quadrature is not the unrotated one's; the
 * radial kernel is rotation invariant (the test's objectivity check).
 *
 * Cost: a weight fit per force (a moment matrix and its Cholesky factor
 * per point; the fit at y_n is the last force's at y_{n+1}, kept), two
 * where damage grew or the positions moved between forces. One process
 * only. */
#ifndef NSPD_SOLID_CORRESPONDENCE_SL_FORCE_H
#define NSPD_SOLID_CORRESPONDENCE_SL_FORCE_H

#include "solid/correspondence/bac_force.h"
#include "solid/correspondence/rk_gradient.h"

#include <stdbool.h>
#include <stdint.h>

/* The semi-Lagrangian force's scratch, sized by sl_work_create for n
 * points and nb bonds in np pairs (nspd_alloc'd; sl_work_free). */
typedef struct {
    double *y[3], *y_prev[3], *du[3]; /* n each */
    double *phi;                      /* dim per bond */
    double *omega, *c, *phi_rev;      /* per bond (phi_rev dim per bond) */
    double *phi_sum, *inv_w0;         /* per point (phi_sum dim) */
    double *G;                        /* 9 per point */
    double *tau;                      /* 4 per pair */
    uint8_t *ok;                      /* per point */
    /* what phi and ok were last fitted to: the positions (y) and the
     * damage scale per bond, copied; the next step's start is this step's
     * end (the kicks move only v), so its first fit is skipped when both are
     * bit for bit the same (the same weights a fit would give) */
    double *scale_fit;
    bool fitted;
} SlWork;

int sl_work_create(int dim, int64_t n, int64_t nb, int64_t np, SlWork *w);
void sl_work_free(SlWork *w);

/* What the semi-Lagrangian force needs beyond the reference BacSystem: the
 * weights' order, kernel and support half-width. */
typedef struct {
    int order;
    RkKernel kernel;
    double delta;
} SlWeights;

/* Force densities L (N/m^3) at displacements u, the J2 state of *st
 * advanced from st->u_prev to u; st->Fb holds each pair's F_b at u_prev on
 * entry and at u on return (identity for an undeformed body: the state, not
 * a cache). s is the reference system (families, volumes, bond_scale,
 * pairs; its weights and coefficients are not read). work_point as
 * bac_force's. Returns the number of points whose current family cannot
 * fit the weights (they see no deformation and exert only the bonds'
 * direct forces). 2D, one process (s->exchange NULL). */
int64_t sl_force(const BacSystem *s, const SlWeights *weights, BacState *st,
                 const double *const u[3], double *const force[3], SlWork *w, double *work_point);

#endif
