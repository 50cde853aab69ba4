/* The GKS flow's side of a volumetric coupling (flow.h FlowOps.transfer,
 * lumped, add_lumped), on plain grid and field arrays: the weights that
 * move velocity from cells to points and forces back, and the cells' mass
 * and momentum per metre of depth. */
#ifndef NSPD_FLOW_GKS_TRANSFER_H
#define NSPD_FLOW_GKS_TRANSFER_H

#include "flow/flow.h"
#include "flow/gks/grid.h"
#include "flow/gks/solver.h"

#include <stdint.h>

/* Point p's weights into cell[p * width ..], w[p * width ..] (width =
 * flow_transfer_width(mode)): nearest, bilinear between the centres around
 * it, or the quadratic B-spline centred on its cell (in that cell's width:
 * exact on a uniform grid). A wall folds a missing neighbour's weight onto
 * the edge cell; a periodic axis wraps; cells that are not FLUID are left
 * out and the rest renormalised. A point off the grid gets cell -1, w 0. */
void gks_transfer(const Grid *g, const uint8_t *kind, FlowTransferKind mode, int64_t n,
                  const double *x, const double *y, int64_t *cell, double *w);

/* Mass and momentum per metre of depth of cells[k] (indices of
 * grid_index). */
void gks_lumped(const Grid *g, const GksFields *f, int64_t n, const int64_t *cells, double *mass,
                double *momentum_x, double *momentum_y);

/* The area of cells[k] (m^2 per metre of depth). */
void gks_lumped_volume(const Grid *g, int64_t n, const int64_t *cells, double *volume);

/* Adds momentum and total energy (per metre of depth; a NULL array: none
 * of that). */
void gks_add_lumped(const Grid *g, GksFields *f, int64_t n, const int64_t *cells, const double *dmx,
                    const double *dmy, const double *de);

#endif
