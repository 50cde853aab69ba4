/* A correspondence-PD body (paper 003 Sec. 2; notes 1c): the material
 * points of a bond-based body (same lattice, regions and integrator), the
 * bond-associated force of solid/correspondence/bac_force.h with RK gradient weights of
 * quadratic consistency (solid/correspondence/rk_gradient.h), a hypoelastic J2 material
 * per bond (solid/correspondence/j2_kernel.h), and bond damage (ductile or brittle).
 *
 * Points (struct of arrays): x, u, v, force (internal + pressure loads),
 * external (couplings), u_prev (u at the start of the step, for the
 * stress increment), volume, region, the pressure load's face normals.
 * Bonds (compressed rows, each pair stored from both ends, so no atomics
 * and no cross-writes): neighbour, reverse bond, its pair, kernel omega,
 * RK weights phi (dim), damage, 1 - damage (the same bits at both ends),
 * and what the force keeps between damage changes (bac_coefficients: c,
 * the reverse bond's phi times V_j). Bond pairs (BacPairs, struct of
 * arrays): the unrotated stress sigma (4), equivalent plastic strain, the
 * last maximum principal stress, an inversion flag, the bond deformation
 * gradient F_b (4) and the scratch P_b (dim^2), formed once per pair:
 * CPD_BYTES_PER_BOND in all.
 *
 * Damage (notes 1c.8) never decreases; a bond whose damage grew rescales
 * its kernel (omega (1 - d)) and its points' RK weights are recomputed. A
 * bond whose F_b inverts (det <= 0) breaks. A point whose moment matrix
 * becomes singular (too few or collinear intact neighbours for a quadratic
 * fit) is debris: its bonds break (from both ends, each end deciding from
 * the flags of both), it moves on with its momentum and no stress, and
 * counts in the mass loss. Nothing divides by a vanished family (w0 = 0:
 * no force), so damage never makes a NaN.
 *
 * cfg.force = CPD_FORCE_CLASSIC swaps the force for the classic one of
 * solid/correspondence/classic_force.h (shape tensor K_i, the Silling 2017 penalty of
 * weight cfg.stabilisation) with the same J2 material per POINT: sigma,
 * eqps, principal and inverted are then arrays of n, phi is not allocated,
 * ok[i] says K_i is invertible (with the damaged kernel), and a bond's
 * damage follows the larger of its two points' plastic strains (ductile)
 * or principal stresses (brittle), or is 1 if either point inverted: the
 * same bits from both ends. Everything else (lattice, families, kernel,
 * damage bookkeeping, debris, integrator, stable step) is shared. */
#ifndef NSPD_SOLID_CORRESPONDENCE_BODY_H
#define NSPD_SOLID_CORRESPONDENCE_BODY_H

#include "core/comm.h"
#include "solid/correspondence/bac_force.h"
#include "solid/correspondence/sl_force.h"
#include "solid/correspondence/config.h"
#include "solid/correspondence/j2_kernel.h"
#include "solid/pd/contact.h"
#include "solid/pd/regions.h"

#include <stdbool.h>
#include <stdint.h>

/* Per bond in 2D, the bond-associated force: 80 bytes per bond (nbr and
 * pairs.of 4 each, reverse, omega, damage, scale and c 8 each, phi and
 * phi_rev 16 each) and 125 per pair, so 62.5 per bond (sigma, F_b and P_b
 * 32 each, eqps and principal 8 each, inverted 1, pairs.bond 8,
 * pairs.point 4): 143 rounded up; plane stress adds 8 (strain_zz and the
 * force's flag, 8 each per pair). The classic force (notes 1c.3,
 * solid/correspondence/classic_force.h) keeps no RK weights and its material state per point
 * instead (sigma, eqps, principal and inverted are then arrays of n, not of bond_count): 52 bytes
 * per bond (nbr 4, reverse, omega, damage, scale 8 each, T 16) and CPD_CLASSIC_BYTES_PER_POINT more
 * per point (sigma 32, eqps and principal 8 each, inverted 1). */
enum { CPD_BYTES_PER_BOND = 143, CPD_CLASSIC_BYTES_PER_BOND = 52 };
enum { CPD_CLASSIC_BYTES_PER_POINT = 49 };

typedef struct {
    CpdConfig cfg; /* owned copy */
    int dim;
    int64_t n;
    double spacing, delta;
    double *x[3], *u[3], *v[3], *force[3], *external[3], *u_prev[3];
    double *volume;
    int16_t *region;
    PdBoundaryTable boundary;
    int32_t *lattice[3];
    int16_t *load;       /* pressure load index of the point, or -1 */
    double *load_dir[3]; /* the sum of its cell faces' inward normals on the pressurised side */

    int64_t bond_count;
    int64_t *first;
    int32_t *nbr;
    int64_t *reverse;
    BacPairs pairs; /* the bond-associated force's bond pairs; the state is per pair */
    double *inv_w0; /* the bond-associated force's 1 / w0 per point (cpd_settle_weights
                       refreshes it: damage is what changes it) */
    /* the bond-associated force's bac_coefficients (c per bond, phi_rev dim
     * per bond, phi_sum dim per point), refreshed with inv_w0 */
    double *coef_c, *phi_rev, *phi_sum;
    double *omega, *phi; /* phi: NULL for the classic force */
    uint8_t *ok;         /* per point: 1 while its moment matrix (classic: K_i) is invertible */
    uint8_t *redo;       /* per point: damage grew in its family this step */
    uint8_t *dirty;      /* per point: its family's damage changed since inv_w0 was formed */
    uint8_t *near;       /* scratch: the dirty points and their neighbours */
    double *sigma, *eqps, *damage, *scale, *principal; /* classic: sigma, eqps, principal */
    uint8_t *inverted;
    double *strain_zz; /* plane stress: the thickness's log strain, per bond (per point
                          for classic); NULL in plane strain */                                 /* and inverted per point */
    double *work_point, *work_bond;

    J2Material material;
    double lambda, mu; /* Lame constants, Pa */
    int64_t step;
    double time;
    bool force_valid;
    /* The bond-associated force's F_b per pair (4 each, in-plane, 2D;
     * BacState.Fb): at the current u and weights while Fb_now (set by a
     * stateful force, cleared by damage growth), then, from the step's
     * start, given to the next stateful force as F_b at u_prev while
     * Fb_given */
    double *Fb;
    bool Fb_now, Fb_given;
    double stable_dt;     /* s, by power iteration at creation (step.c) */
    double stable_now;    /* s, the same at the current damage (re-estimated as it grows) */
    double *mode[3];      /* the highest mode's last iterate (warm start) */
    int64_t estimated_at; /* step of the last estimate */
    bool damage_grew;     /* since the last estimate */
    int64_t substeps_max; /* the most sub-steps one step took (cpd_step) */
    /* On several processes (solid/correspondence/halo.h): n is this rank's
     * run of points, the ghosts after them (positions, volumes, u, ok and
     * the force's exchanged per-point values; no bonds), and the halo */
    int64_t ghosts;
    struct CpdHalo *halo;
    /* Contact between points (cfg.pd.contact.enabled; solid/pd/contact.h),
     * added by cpd_force; one process only. Its stiffness is that of the
     * bond-based micromodulus of the same E (a scale, not a bond). */
    bool has_contact;
    PdContact contact;
    /* cfg.frame semi_lagrangian: sl_force's scratch (Fb above is then each
     * pair's F_b at u_prev, the state; the Lagrangian phi, ok and F stay
     * for the fits' checks, the stable step and the outputs) */
    SlWork sl;
    double *fit_norm0; /* per point: the intact family's cpd_fit_norm (bond-associated) */
} CpdBody;

/* Point i's gradient weights' size, sum_j |phi_ij| V_j (the 1-norm over
 * the components): the scale of the force its family's fit makes of a
 * unit displacement difference. */
double cpd_fit_norm(const CpdBody *b, int64_t i);

/* A point whose damaged family's fit needs weights larger than this many
 * times its intact family's (cpd_fit_norm) has failed: its bonds break,
 * as those of a point whose family can fit no gradient at all. On the
 * square lattice a nearly singular damaged family is exactly singular and
 * refused by the pivot test (RK_MIN_PIVOT); on the polar lattice's
 * irregular cloud it passes it, and its weights stiffen the point faster
 * than the stable step's re-estimate follows (the brittle ring blew up
 * within 3 us of its first broken bonds). Measured on the coarse brittle
 * cylinder (paper 003 Sec. 4.3, weak coupling, 0.3 ms): the square
 * lattice's accepted fits grow to at most 8.8 times; the polar lattice's
 * grow smoothly to 4.7 and then jump to 75, 102, 190, 3,400 and 6,800
 * times, each within a few us of the blow-up. 25 lies in that gap: no
 * square-lattice case moves (the golden set is unchanged), and the polar
 * ring runs to the end (docs/VALIDATION.md, the polar lattice). */
#define CPD_FIT_GROWTH_LIMIT 25.0

/* Builds the body (taking ownership of *cfg, zeroing it): lattice points,
 * regions, families (square |xi|_inf <= delta or disc |xi| <= delta),
 * kernel, RK weights, pressure directions, the stable step. NSPD_ERR_INPUT
 * if the geometry holds no point or a point has no RK weights at the
 * start (a body thinner than the family needs: say which); NSPD_ERR_NOMEM. */
int cpd_body_create(CpdBody *b, CpdConfig *cfg);
/* The same on the processes of `comm`, each keeping its part
 * (solid/correspondence/halo.h; on one process cpd_body_create). */
int cpd_body_create_divided(CpdBody *b, CpdConfig *cfg, const NspdComm *comm);
void cpd_body_destroy(CpdBody *b);
/* The bond-associated force's arrays of one entry a pair (the material
 * state, zero; F_b; the force's scratch) for b->pairs, anew. NSPD_ERR_NOMEM. */
int cpd_body_pair_arrays(CpdBody *b);

/* One step of dt: velocity Verlet sub-steps (pressure loads at each new
 * time). Damage stiffens what is left of a family (its stress integral and
 * RK weights rest on fewer bonds), so the stable step falls as cracks
 * grow (measured: 2.76e-7 s to 1.5e-7 s in 40 us of the hollow cylinder):
 * when damage grew, the step is re-estimated at most every
 * CPD_REESTIMATE_STEPS steps, and once it has fallen below the undamaged
 * body's, a step longer than CPD_DAMAGED_SAFETY of it (time.safety_factor's
 * default) is taken in as many equal sub-steps as that needs. */
/* 30 cold iterations: the estimate is within 0.2 % of the converged one
 * after 20 and 0.02 % after 40 on 16^2 to 64^2 blocks (measured), inside
 * the 2 % margin of cpd_stable_dt; 80 made the set-up cost 95 steps */
enum { CPD_REESTIMATE_STEPS = 20, CPD_COLD_ITERATIONS = 30 };
#define CPD_DAMAGED_SAFETY 0.8
int cpd_step(CpdBody *b, double dt);
/* One step whose velocities a coupling prescribed (SolidOps.step_constrained):
 * u += dt v, the force at the new u, v += dt f / rho; no sub-steps. */
int cpd_step_constrained(CpdBody *b, double dt);
/* The force density at the current u into b->force, advancing the bond
 * stresses from u_prev and the damage (what cpd_step calls); the contact
 * force added where the body has contact. NSPD_ERR_NOMEM if contact's
 * candidate lists cannot be rebuilt. */
int cpd_force(CpdBody *b, double t);
/* The weights of the points flagged in b->redo recomputed with the damaged
 * kernel (and the bond-associated force's 1 / w0 of every point); a point left without weights is
 * debris and its bonds break from both ends (each end reads both points' flags), which may leave
 * its neighbours without weights in turn: repeated until no point changes. Returns the number of
 * bonds broken this way. */
int64_t cpd_settle_weights(CpdBody *b);
/* b->inv_w0 and the force's coefficients from the current damage, for
 * every point (bac_inverse_weights, bac_coefficients): after anything that
 * changed scale behind the damage bookkeeping (a checkpoint's restore;
 * cpd_settle_weights refreshes only the points whose damage changed). */
void cpd_inverse_weights(CpdBody *b);

/* dt = 2 / sqrt(lambda_max) of the linearised operator (K / rho) at the
 * current damage, by power iteration (notes 1c.10 C6): `iterations` from
 * the lattice checkerboard (cold) or from b->mode (warm, with a part of the
 * checkerboard mixed in so a new stiff spot is not missed). */
double cpd_stable_dt(CpdBody *b, int iterations, bool warm);

/* ok[i] for the points with redo[i] != 0 (redo NULL: all, and the RK
 * weights of every point): the bond-associated force's RK weights (ok: the
 * moment matrix was invertible) or the classic force's K_i. Returns the
 * number of those points not ok. */
int64_t cpd_shape_check(CpdBody *b, const uint8_t *redo);

/* Point damage: the mean damage of its initial bonds (PdShell's, the
 * default) and the volume-weighted fraction of them broken. */
void cpd_point_damage(const CpdBody *b, double *mean, double *broken);

#endif
