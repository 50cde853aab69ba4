/* Bond-based PD (paper 000, BondBody) as a solid model: the SolidOps table
 * over body.h, integrate.h and diagnostics.h. */
#ifndef NSPD_SOLID_BOND_MODEL_H
#define NSPD_SOLID_BOND_MODEL_H

#include "solid/bond/body.h"
#include "solid/solid.h"

extern const SolidOps BOND_SOLID_OPS;

/* The checked accessor: the BondBody of a bond-based solid, NULL for any other
 * model (a coupling that needs the bonds refuses those at create). */
BondBody *bond_solid_body(Solid *s);

/* The PdPoints view of a body's arrays (the model's own, and for tools and
 * tests that build a BondBody directly). */
void bond_solid_points_of(BondBody *b, PdPoints *pts);

/* `nspd bench pd` (SolidOps.bench, bench.c): the plate of paper 000
 * Sec. 4.2 with about `points` points, `steps` timed steps, into *out. */
int bond_bench(long points, long steps, Report *out);

#endif
