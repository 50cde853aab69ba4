/* Correspondence PD (paper 003, CpdBody) as a solid model: the SolidOps
 * table over body.h. */
#ifndef NSPD_SOLID_CORRESPONDENCE_MODEL_H
#define NSPD_SOLID_CORRESPONDENCE_MODEL_H

#include "solid/correspondence/body.h"
#include "solid/solid.h"

extern const SolidOps CPD_SOLID_OPS;

/* The checked accessor: the CpdBody of a correspondence solid, NULL for any
 * other model. */
CpdBody *cpd_solid_body(Solid *s);

/* Connected components of the graph of intact bonds (damage < 1) among the
 * points that keep one (fragments), and the points that keep none (debris).
 * Sequential union-find; allocates. -1 on NOMEM. */
/* `nspd bench cpd` (SolidOps.bench, bench.c): a J2 steel block with about
 * `points` points, `steps` timed velocity Verlet steps, into *out. */
int cpd_bench(long points, long steps, Report *out);

int64_t cpd_fragment_count(const CpdBody *b, int64_t *debris);
/* Eq. 24 of paper 003: the mass fraction of points whose (mean) damage is
 * at least 0.99; `damage` per point. */
double cpd_mass_loss(const CpdBody *b, const double *damage);
/* The mass fraction of points damaged but not lost, 0 < damage < 0.99: the
 * flanks of the cracks. Beside the mass loss it measures how wide the
 * cracks' fully damaged bands are (docs/VALIDATION.md, the hollow square). */
double cpd_partly_damaged(const CpdBody *b, const double *damage);
/* The number of points whose damage is at least 0.99, the points the mass
 * loss weighs (paper 003 Fig. 8's "fully damaged PD nodes"), over the whole
 * body: each rank's own points counted, summed exactly (collective). */
int64_t cpd_fully_damaged(const CpdBody *b, const double *damage);

#endif
