/* Regular lattice of material points inside a ShapeSet, in Morton order;
 * or the polar lattice of a ring (paper 003 Sec. 4.3). */
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

/* A ring r_i <= r <= r_o about `center` cut into `rings` rings of equal
 * width dr = (r_o - r_i) / rings and, in every ring, `sectors` equal
 * sectors of angle 2 pi / sectors (the same in every ring: uniform along
 * theta, as paper 003's Fig. 10). One point per annular-sector element, at
 * its centroid; its volume is the element's area times the thickness. */
typedef struct {
    double center[2];
    double inner_radius, outer_radius; /* m, 0 < r_i < r_o */
    int32_t rings, sectors;            /* >= 1; >= 4 and even */
} PolarLattice;

/* The polar lattice's points whose centroid `filter` holds (all when it
 * adds no shape), in the Morton order of their lattice indices (sector,
 * ring, 0). Point k of ring q sits at the angle (k + 1/2) 2 pi / sectors,
 * its direction built from the first octant's (or quadrant's) by exact
 * reflections, so the point set is mirrored bit for bit about the
 * centre's horizontal and vertical lines (and its diagonals when sectors
 * is a multiple of 4) up to the rounding of centre + r cos. An even count
 * keeps the index parity (sector + ring) alternating across the seam.
 * NSPD_ERR_INPUT for a bad spec or no point inside; NSPD_ERR_NOMEM. */
int lattice_fill_polar(Lattice *lat, const PolarLattice *spec, const ShapeSet *filter);
/* The area of an element of ring `ring` (0 innermost), m^2:
 * (pi / sectors) (r_{q+1}^2 - r_q^2), whose sum over the lattice is
 * pi (r_o^2 - r_i^2) to round-off. */
double lattice_polar_area(const PolarLattice *spec, int32_t ring);
/* The radial spacing (r_o - r_i) / rings, m. */
double lattice_polar_spacing(const PolarLattice *spec);
/* The default sector count for radial spacing dr: near-square elements at
 * the mid radius, 2 pi r_mid / dr rounded to a multiple of 4 (at least 4). */
int64_t lattice_polar_sectors(double inner_radius, double outer_radius, double dr);

void lattice_free(Lattice *lat);

/* Morton key of non-negative lattice indices (2D: 32 bits per axis, 3D: 21). */
uint64_t morton_key(int dim, uint32_t i, uint32_t j, uint32_t k);

#endif
