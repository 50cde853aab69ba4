/* Points taken from a mesh (solid.lattice kind abaqus, issue 61): one per
 * element at its centroid, with the element's area (2D: times the solid's
 * thickness, as the polar lattice's elements) or volume, Peridynamics.jl's
 * convention for an imported mesh. The mesh is read by the case layer
 * (io/inp_read.h); the solid sees only the points. */
#ifndef NSPD_SOLID_PD_MESH_POINTS_H
#define NSPD_SOLID_PD_MESH_POINTS_H

#include "core/shape.h"
#include "solid/pd/lattice.h"

#include <stdint.h>

typedef struct {
    int64_t n;       /* elements */
    double *x[3];    /* their centroids, m (z = 0 in 2D) */
    double *measure; /* their areas, m^2 (2D), or volumes, m^3 */
} MeshPoints;

/* The elements whose centroids `filter` holds (all when it adds no shape)
 * as a Lattice, in the Morton order of their cells of size dx from the
 * centroids' lower corner (ties in the elements' order): index[0] and
 * index[1] are those cells' (the stable step's checkerboard start reads
 * them), index[2] the element's number in `mesh` (the 2D solids' third
 * index is otherwise 0), so that a process's ghosts, which carry their
 * indices, find their measures too (mesh_points_measure). 2D only (no 3D
 * solid runs on points off a lattice). NSPD_ERR_INPUT for another dim, an
 * empty mesh, or no centroid inside; NSPD_ERR_NOMEM. */
int mesh_points_fill(Lattice *lat, const MeshPoints *mesh, int dim, double dx,
                     const ShapeSet *filter);
/* The measure of the point with those lattice indices' element. */
double mesh_points_measure(const MeshPoints *mesh, int32_t index2);
void mesh_points_free(MeshPoints *mesh);

#endif
