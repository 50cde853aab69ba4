/* A bond-based peridynamic body: material points and their bonds.
 *
 * Points (struct of arrays, one array per component, 64-byte aligned):
 *   x  reference position; u displacement; v velocity (all m, m/s)
 *   force     PD internal force density sum_j f_ij V_j (N/m^3), Eq. 28
 *   external  force density from outside (body force, region loads, the
 *             fluid's surface traction), N/m^3; sum of the two drives Eq. 30
 *   volume    point volume (m^3; 2D: dx^2 * thickness)
 *   region    index of the boundary region holding the point, or -1
 * Points are ordered along a Morton (Z-order) curve of their lattice indices
 * so that a point's neighbours sit close to it in memory.
 *
 * Bonds are compressed rows: the bonds of point i are
 * bond_nbr[bond_first[i] .. bond_first[i+1]), in offset order (dz, dy,
 * then dx, of the lattice indices: the order the force sums in,
 * stencil.h). Each point owns the full list
 * of its bonds, so bond i-j is stored (and evaluated) once from each end:
 * the force loop writes only to point i and needs no atomics, and results do
 * not depend on the thread count. Per bond, 8 bytes:
 *   bond_nbr   int32 neighbour index
 *   bond_coef  float32 dimensionless stiffness k_ij / coef_scale, where
 *              k_ij = c beta_ij nu_ij V_j / |xi_ij| (micromodulus, surface and
 *              volume corrections, neighbour volume, reference length), so the
 *              pair force density is k_ij (|y| - |xi|) y/|y| (Eq. 29).
 *              The sign carries the failure state: > 0 intact and breakable,
 *              < 0 intact and unbreakable (outside the failure region, or
 *              failure off), 0 broken. Both ends of a bond break together
 *              because both evaluate bitwise the same stretch.
 * The reference bond vector is recomputed from x (cheaper than storing it:
 * the gather is in cache after Morton ordering). */
#ifndef NSPD_SOLID_BOND_BODY_H
#define NSPD_SOLID_BOND_BODY_H

#include "core/balance.h"
#include "core/comm.h"
#include "solid/pd/config.h"
#include "solid/pd/contact.h"
#include "solid/pd/regions.h"

#include <stdint.h>

struct BondHalo;
struct BondStencil;

typedef struct {
    PdConfig cfg; /* owned copy of the configuration (shapes included) */
    int dim;
    int64_t n;
    double *x[3], *u[3], *v[3];
    double *force[3]; /* PD internal force density, N/m^3 */
    /* External force density, N/m^3: the entry point for loads from outside
     * the solid (the fluid's surface traction: traction x segment length x
     * thickness / point volume on surface points). Whoever sets it owns it;
     * it stays until changed, and pd_step adds the case's body force and
     * region force densities on top. */
    double *external[3];
    double *volume;
    int16_t *region;          /* boundary region index or -1 */
    PdBoundaryTable boundary; /* cfg.boundaries for the integrator */
    int32_t *lattice[3];      /* integer lattice coordinates (for images and symmetry checks) */

    int64_t bond_count;
    int64_t *bond_first; /* n + 1 */
    int32_t *bond_nbr;
    float *bond_coef;
    double coef_scale;           /* k_ij = coef_scale * |bond_coef| */
    double stretch_limit2;       /* (1 + s_c)^2: a bond breaks when |y|^2 > this |xi|^2 */
    double micromodulus;         /* c of Eq. 15 */
    double horizon;              /* delta, m */
    double spacing;              /* dx, m */
    double *initial_bond_volume; /* sum_j nu_ij V_j over all initial bonds (damage denominator) */

    /* Several materials (cfg.material_count > 1; else NULL): each point's
     * material and density (kg/m^3). Its Young's modulus enters through the
     * bonds' coefficients, its density through the kick. One process. */
    uint8_t *material;
    double *density;

    /* Contact between points (cfg.contact.enabled): added to force by
     * pd_force_compute (contact.h). One process only. */
    bool has_contact;
    PdContact contact;

    int64_t step;
    double time;
    bool force_valid; /* force[] holds the force at the current u (velocity Verlet) */
    /* The lattice view the force runs on (stencil.h), or NULL (a box too
     * sparse). Whoever writes bond_coef other than the force calls
     * bond_stencil_take. */
    struct BondStencil *stencil;
    /* The threads' shares of the force's and of the kick and drift's
     * loops (core/balance.h): scheduling only, no bits depend on them. */
    Balance force_balance, motion_balance;

    /* On several processes (halo.h): the ghosts after the n points this
     * process holds (their displacements from their owners, no bonds of
     * their own), and the exchange; 0 and NULL on one process. */
    int64_t ghosts;
    struct BondHalo *halo;
} BondBody;

/* Builds the body: lattice points inside the geometry, Morton ordering,
 * bonds within the horizon, volume and surface corrections, pre-cracks,
 * boundary regions and initial velocities. Takes ownership of *cfg (its
 * shapes and arrays) and zeroes it. NSPD_ERR_INPUT if the geometry holds
 * no point; NSPD_ERR_NOMEM. */
int bond_body_create(BondBody *body, PdConfig *cfg);
/* The same on several processes (comm; one process: bond_body_create):
 * this process's part of the body (halo.h), whose build finds only the
 * bonds of its points and of their ghosts (the surface factors of a
 * ghost need its own bonds), so that its bonds' memory is its part's. */
int bond_body_create_divided(BondBody *body, PdConfig *cfg, const NspdComm *comm);
void bond_body_destroy(BondBody *body);

/* Bytes of bond storage per bond in the rows (neighbour index +
 * coefficient). */
enum { PD_BYTES_PER_BOND = (int)(sizeof(int32_t) + sizeof(float)) };
/* All of a body's bond storage per bond: the rows' and the lattice view's
 * (stencil.h: its state bits and magnitude blocks, the chunks' cells with
 * no bond included). */
double bond_bytes_per_bond(const BondBody *body);

#endif
