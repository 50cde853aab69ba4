/* Bond-based PD (paper 000, BondBody) as a solid model: the SolidOps table
 * over bond_body.h, pd_integrate.h and pd_diagnostics.h. */
#ifndef NSPD_SOLID_BOND_SOLID_H
#define NSPD_SOLID_BOND_SOLID_H

#include "solid/bond_body.h"
#include "solid/solid.h"

extern const SolidOps BOND_SOLID_OPS;

/* The checked accessor: the BondBody of a bond-based solid, NULL for any other
 * model (a coupling that needs the bonds refuses those at create). */
BondBody *bond_solid_body(Solid *s);

/* The PdPoints view of a body's arrays (the model's own, and for tools and
 * tests that build a BondBody directly). */
void bond_solid_points_of(BondBody *b, PdPoints *pts);

#endif
