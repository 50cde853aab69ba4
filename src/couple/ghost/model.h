/* The ghost-cell immersed-boundary coupling (paper 000 Sec. 3.3) as a
 * coupling model. Its walls are either
 *   - the surface of a bond-based PD solid (two-way: couple/ghost/fsi.h), or
 *   - rigid fixed bodies (flow.bodies), when the case has no solid: the
 *     walls stay where they are, the flow feels them, and their loads are
 *     measured (force coefficients, surface pressure and friction).
 * It needs the GKS grid (gks_flow_solver) and a 2D solid (any model: the
 * walls are its PdPoints' surface, debris its detached points); other flows
 * and 3D solids are refused at create with an input error. */
#ifndef NSPD_COUPLE_GHOST_MODEL_H
#define NSPD_COUPLE_GHOST_MODEL_H

#include "couple/ghost/fsi.h"
#include "couple/ghost/markers.h"

typedef struct {
    FsiConfig fsi;     /* the walls' condition, soft start, ghost faces, reference state */
    IbmBodySet bodies; /* rigid walls (owned); empty when a solid gives the walls */
} GhostCouplingConfig;

void ghost_coupling_config_free(GhostCouplingConfig *cfg);

struct CouplingOps;
extern const struct CouplingOps GHOST_COUPLING_OPS;

/* Views for tests and tools (NULL if the coupling is not a ghost-cell one):
 * the immersed boundary and the surface loads of the last computation. */
typedef struct Coupling Coupling;
const Ibm *ghost_coupling_ibm(Coupling *c);
const IbmSurface *ghost_coupling_surface(Coupling *c);

#endif
