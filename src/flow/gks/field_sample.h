/* A flow field given on the cells of a rectilinear grid (an earlier run's
 * output), sampled at any point as an initial condition: grid sequencing
 * (a fine grid started from the settled flow of a coarse one) and
 * continuing a run.
 *
 * The primitive variables (rho, u, v, p) are interpolated bilinearly
 * between the four cell centres around the point. Cells marked invalid
 * (inside a body: they hold no gas) are left out and the weights of the
 * others renormalised, so the state next to a wall comes from the gas and
 * the ghost cells around it only; where the valid ones carry no weight (the
 * point is an invalid cell's centre) the nearest valid one is taken, and
 * where none is valid the nearest of the four (the point then lies inside a
 * body on the new grid too, where the value is never used). Outside the
 * field's cell centres the
 * nearest centre's value holds (constant extrapolation). Every sample is a
 * convex combination of stored states, so density and pressure stay
 * positive. */
#ifndef NSPD_FLOW_GKS_FIELD_SAMPLE_H
#define NSPD_FLOW_GKS_FIELD_SAMPLE_H

#include "flow/gks/solver.h"

#include <stdint.h>

typedef struct {
    int nx, ny;
    double *xc, *yc;         /* cell centres, increasing: nx and ny values */
    double *rho, *u, *v, *p; /* nx * ny values, x fastest */
    uint8_t *valid;          /* nx * ny: 1 where the cell holds gas */
} FlowFieldSource;

/* Allocates the arrays of an nx x ny source (zeroed; `valid` all 1) and
 * sets the centres from the face coordinates xf[0..nx], yf[0..ny], which
 * must increase. */
int flow_field_source_create(FlowFieldSource *src, int nx, int ny, const double *xf,
                             const double *yf);
void flow_field_source_free(FlowFieldSource *src);

/* A FlowInitFn: the state at (x, y); `source` is a FlowFieldSource.
 * Thread-safe (reads only). */
void flow_field_sample(void *source, double x, double y, FlowPrim *out);

#endif
