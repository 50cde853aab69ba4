/* Correspondence PD (paper 003, CpdBody) as a solid model: the SolidOps
 * table over cpd_body.h. */
#ifndef NSPD_SOLID_CPD_SOLID_H
#define NSPD_SOLID_CPD_SOLID_H

#include "solid/cpd_body.h"
#include "solid/solid.h"

extern const SolidOps CPD_SOLID_OPS;

/* The checked accessor: the CpdBody of a correspondence solid, NULL for any
 * other model. */
CpdBody *cpd_solid_body(Solid *s);

/* Connected components of the graph of intact bonds (damage < 1) among the
 * points that keep one (fragments), and the points that keep none (debris).
 * Sequential union-find; allocates. -1 on NOMEM. */
int64_t cpd_fragment_count(const CpdBody *b, int64_t *debris);
/* Eq. 24 of paper 003: the mass fraction of points whose (mean) damage is
 * at least 0.99; `damage` per point. */
double cpd_mass_loss(const CpdBody *b, const double *damage);

#endif
