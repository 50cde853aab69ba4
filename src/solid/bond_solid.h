/* Bond-based PD (paper 000, PdBody) as a solid model: the SolidOps table
 * over pd_body.h, pd_integrate.h and pd_diagnostics.h. */
#ifndef NSPD_SOLID_BOND_SOLID_H
#define NSPD_SOLID_BOND_SOLID_H

#include "solid/pd_body.h"
#include "solid/solid.h"

extern const SolidOps BOND_SOLID_OPS;

/* The checked accessor: the PdBody of a bond-based solid, NULL for any other
 * model (a coupling that needs the bonds refuses those at create). */
PdBody *bond_solid_body(Solid *s);

/* The PdPoints view of a body's arrays (the model's own, and for tools and
 * tests that build a PdBody directly). */
void bond_solid_points_of(PdBody *b, PdPoints *pts);

#endif
