/* Point samples of the PDDO flow's nodal fields: the flow's probes
 * (`output.probes` with `on: flow`, docs/CASES.md).
 *
 * The value at a point c that need not be a node is the moving least
 * squares quadratic of pddo_ops_interpolation (the operators' Gaussian
 * weight and moments, the basis 1, xi1, xi2, xi1^2, xi2^2, xi1 xi2) over
 * the physical nodes within the horizon delta of c - fluid, side and wall
 * ring nodes, lattice or polar patch alike (the junction needs no special
 * case: the stencil is whatever lies within delta) - so it is exact for
 * every quadratic field and second order otherwise, and it never reads a
 * fictitious node (their values are boundary devices: the paper's zero
 * wall ghosts would bias a probe near a wall). Near a side or a body the
 * stencil is one-sided, like the lattice's truncated families. A point on
 * a physical node (within 1e-9 dx) reads that node's value: the fit does
 * not interpolate, and at a wall node, where the solution has a kink the
 * quadratic cannot follow (a boundary layer thinner than delta), it would
 * read 1 m/s of slip at the coarse confined cylinder's front (dx 0.2)
 * instead of the wall's 0 - and the paper's wall probes are node values.
 * Exactness for quadratics holds either way.
 *
 * Stencils are found once (core/neighbours.h, neighbours_query) and their
 * weights computed once when a point is added; a sample is one dot
 * product, allocation free, read only. */
#ifndef NSPD_FLOW_PDDO_SAMPLE_H
#define NSPD_FLOW_PDDO_SAMPLE_H

#include "flow/pddo/cloud.h"

#include <stdint.h>

typedef struct {
    int64_t n;      /* points */
    int64_t *first; /* n + 1 offsets: point k's stencil is nbr[first[k] .. first[k + 1]) */
    int32_t *nbr;   /* cloud nodes */
    double *w;      /* their weights: f(point k) = sum w f(nbr) */
} PddoSample;

/* Appends the point (x, y) (`name` for messages: the probe's) to s (zeroed
 * before the first call); its index is s->n - 1 after the call.
 * NSPD_ERR_INPUT for a point outside the rectangle of the cloud's lattice
 * (its sides included), inside a body (closer than the radius to a polar
 * patch's centre) or whose stencil cannot carry a quadratic fit
 * (operators.h's rule); NSPD_ERR_NOMEM. s is unchanged on failure. */
int pddo_sample_add(PddoSample *s, const PddoCloud *cloud, double x, double y, const char *name);

/* The value of the nodal field f at point k. */
double pddo_sample_at(const PddoSample *s, const double *f, int64_t k);

void pddo_sample_free(PddoSample *s);

#endif
