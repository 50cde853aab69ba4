/* Regular lattice of material points inside a ShapeSet, in Morton order. */
#ifndef NSPD_SOLID_PD_LATTICE_H
#define NSPD_SOLID_PD_LATTICE_H

#include "core/shape.h"

#include <stdbool.h>
#include <stdint.h>

typedef struct {
    int64_t n;
    double *x[3];      /* positions, m */
    int32_t *index[3]; /* integer lattice coordinates */
} Lattice;

/* The lattice points inside `geometry`, sorted along the Morton curve of
 * their lattice indices: origin + k dx (k integer per axis) when `origin` is
 * given, else a lattice centred in the geometry's bounding box with as many
 * points per axis as cells of size dx fit in it (for a box, the points sit
 * half a spacing inside its faces). `dim` is 2 or 3 (z = 0 in 2D). `lat`
 * must be zeroed or hold a previous lattice. NSPD_ERR_INPUT if no point
 * falls inside; NSPD_ERR_NOMEM; NSPD_ERR_INTERNAL for another dim. */
int lattice_fill(Lattice *lat, const ShapeSet *geometry, int dim, double dx, const double *origin);
/* The lattice sites in the geometry's bounding box and the fraction of them
 * inside it, estimated from at most about 10^6 evenly strided sites without
 * allocating (the memory estimate a case is checked against before it is
 * built). False if the geometry adds no shape. */
bool lattice_estimate(const ShapeSet *geometry, int dim, double dx, double *sites,
                      double *inside_fraction);

void lattice_free(Lattice *lat);

/* Morton key of non-negative lattice indices (2D: 32 bits per axis, 3D: 21). */
uint64_t morton_key(int dim, uint32_t i, uint32_t j, uint32_t k);

#endif
