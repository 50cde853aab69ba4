/* Derived fields and integrals of a PD body: damage, energies, momentum,
 * broken bonds. All reductions use core/reduce.h, so they are bitwise the
 * same at any thread count. Operators: call between steps. */
#ifndef NSPD_SOLID_BOND_DIAGNOSTICS_H
#define NSPD_SOLID_BOND_DIAGNOSTICS_H

#include "solid/bond/body.h"

/* damage_i = 1 - (sum over intact bonds of nu_ij V_j) / (same over the
 * initial family), in [0, 1]; written to damage[0..n). */
void pd_damage(const BondBody *body, double *damage);

/* Number of broken bonds, each counted once (not once per end). Pre-cracks
 * included. */
int64_t pd_broken_bonds(const BondBody *body);

/* Material k's (cfg.materials; several materials only) mass (kg), kinetic
 * energy (J) and mean velocity (m/s, 3 components), summed in point order. */
void pd_material_totals(const BondBody *body, int k, double *mass, double *kinetic,
                        double velocity[3]);

/* Kinetic energy sum_i rho V_i |v_i|^2 / 2, J. */
double pd_kinetic_energy(const BondBody *body);

/* Elastic (bond) energy sum_i V_i W_i with W_i = (1/4) sum_j k_ij (|y|-|xi|)^2
 * over intact bonds, J: the energy whose negative gradient is pd_force.
 * Read from the lattice view where the body has one (stencil.h; its
 * displacements refreshed), with the bits of the rows' sum. */
double pd_elastic_energy(const BondBody *body);

/* Linear momentum sum_i rho V_i v_i, kg m/s. */
void pd_momentum(const BondBody *body, double p[3]);

#endif
