/* Pre-cracks: bonds whose segment crosses a crack start broken. */
#ifndef NSPD_SOLID_PD_PRECRACK_H
#define NSPD_SOLID_PD_PRECRACK_H

#include "solid/pd/config.h"

#include <stdbool.h>

/* True if the bond segment p-q crosses the crack. 2D: proper intersection
 * with the segment a-b (touching an end does not count). 3D: p and q lie on
 * strictly opposite sides of the parallelogram's plane and the crossing point
 * falls inside it. */
bool precrack_cuts(const PdPrecrack *crack, int dim, const double p[3], const double q[3]);

#endif
