/* Two-way coupling of the GKS flow and a 2D PD solid (any model: it reads the
 * solid's PdPoints and asks it which points are still attached) through the ghost-cell
 * immersed boundary (paper 000 Sec. 3.3.4 and Fig. 3).
 *
 * The interface is the solid's own surface (solid/pd/surface.h): one closed
 * polyline per surface loop, whose markers are the surface points at their
 * current positions and whose wall velocities are the points' velocities.
 * Per fluid step (through couple/ghost/model.c, called by sim/sim.c):
 *   1. fsi_move_interface: markers <- points; ibm_update re-tags the cells
 *      near the moved walls, fills the cells the solid uncovered ("fresh"
 *      cells, by interpolation from fluid neighbours) and rebuilds the ghost
 *      stencils that changed;
 *   2. the flow step (the ghost hook imposes no-slip at the wall velocity);
 *   3. fsi_apply_loads: pressure (minus the ambient pressure the solid was
 *      built in) and viscous traction per segment, from the flow just
 *      computed, become force densities on the surface points
 *      (pd_surface_apply_tractions: traction x segment length x thickness /
 *      point volume, half to each end);
 *   4. (the driver's solid_advance) the PD sub-steps: n = ceil(dt_fluid /
 *      dt_pd) steps of dt_fluid / n,
 *      with the load held over the sub-steps (the flow state it comes from
 *      is the one at the end of the fluid step: a first-order, explicit,
 *      loosely coupled scheme, as in the paper), so both clocks end on the
 *      same time.
 * The force the solid receives equals the force the surface integration
 * takes from the fluid, to round-off (tested).
 *
 * Holding a body in place (hold: balance): a free body accelerates under the
 * net fluid force F; adding the uniform force density -F / (sum of the point
 * volumes / thickness) to every point is the d'Alembert load of that
 * acceleration, so the internal stresses are those of the free body, while
 * the body does not translate (its rotation is not removed). The gas keeps
 * the free-stream velocity relative to the body, as in a wind tunnel.
 *
 * Debris: a surface point that is no longer attached (bond PD: it has lost
 * all its bonds) belongs to no body; it
 * leaves the interface (its loop joins its neighbours) and takes no load, so
 * that a point knocked off the surface does not drag the wall after it.
 *
 * Cracks: the loops are traced once on the reference lattice, so a crack that
 * reaches the surface stays closed to the flow - the polyline bridges its
 * mouth. This keeps the grid consistent however far the crack opens
 * (documented limitation; tests/verify/fsi_*). A segment stretched beyond
 * 2.5 spacings (an opened mouth, a gap left by debris) is such a bridge: it
 * carries no load (IbmReference.bridge_length). */
#ifndef NSPD_COUPLE_GHOST_FSI_H
#define NSPD_COUPLE_GHOST_FSI_H

#include "couple/ghost/ibm.h"
#include "couple/ghost/wall_loads.h"
#include "flow/gks/solver.h"
#include "solid/pd/surface.h"
#include "solid/solid.h"

typedef enum {
    FSI_HOLD_NONE = 0, /* the solid moves freely under the fluid's load */
    FSI_HOLD_BALANCE,  /* a uniform body force cancels the net fluid force */
    FSI_HOLD_COUNT
} FsiHold;

extern const char *const FSI_HOLD_NAMES[FSI_HOLD_COUNT + 1];

typedef struct {
    int hold;                /* FsiHold */
    int thermal;             /* IbmWallThermal of the solid's surface */
    double wall_temperature; /* K, isothermal walls */
    double soft_start;       /* m: ibm_soft_start length at t = 0 (0: none) */
    int ghost_faces;         /* IbmGhostFaces of the solid's surface */
    IbmReference reference;  /* free stream and the ambient pressure of the tractions */
} FsiConfig;

typedef struct {
    FsiConfig cfg;
    PdSurface surface; /* all surface points, traced on the reference lattice */
    PdSurface wetted;  /* this step's interface: `surface` without debris */
    int loop_count;
    IbmPolyline *polylines; /* one per surface loop; markers point into the arrays below */
    double *mx, *my, *mvx, *mvy;
    Ibm *ibm;
    IbmSurface loads;
    double force_on_solid[2]; /* N per m of depth, from the last fsi_apply_loads */
    int64_t substeps;         /* PD sub-steps in the last coupled step */
} Fsi;

/* Traces the solid's surface, builds the immersed boundary on the flow's
 * grid from it and attaches it to the solver (cell kinds, ghost hook,
 * optional soft start). The body must be 2D and lie inside the grid.
 * NSPD_ERR_INPUT for a 3D body or an interface the immersed boundary refuses. */
int fsi_create(Fsi *fsi, const FsiConfig *cfg, const Solid *solid, GksSolver *flow);
void fsi_destroy(Fsi *fsi);

/* Step 1 above. */
int fsi_move_interface(Fsi *fsi, Solid *solid, GksSolver *flow);

/* Step 3 above: replaces the solid's external force density with the
 * fluid's tractions. */
int fsi_apply_loads(Fsi *fsi, Solid *solid, GksSolver *flow);

/* Writes or reads the interface's state (core/checkpoint.h); read back, the
 * immersed boundary stands where it stood when the checkpoint was written. */
int fsi_checkpoint(Fsi *fsi, Checkpoint *ck);

#endif
