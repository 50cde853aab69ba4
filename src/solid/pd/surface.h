/* The surface of a 2D PD body as closed polylines of its own points, and the
 * transfer of surface tractions to those points (paper 000 Sec. 3.3.4: the
 * fluid-solid interface comes from the solid).
 *
 * Invariants of a PdSurface:
 *  - loop k is point[loop_start[k] .. loop_start[k+1]), closed implicitly
 *    (the last point joins the first), counter-clockwise in the reference
 *    configuration (the solid on the left of the direction of travel);
 *  - one loop per connected part of the lattice (8-connectivity) with at
 *    least 3 points: the outer boundary only. Interior cavities and cracks
 *    are not part of the surface, so the flow never enters them (a crack that
 *    reaches the surface stays closed to the flow: docs/ARCHITECTURE.md);
 *  - the loops are traced once, on the reference lattice; the polylines move
 *    with their points (x + u), which is what the immersed boundary sees.
 * A point on a thin part (a strip one or two points wide) may appear twice in
 * a loop: once going out and once coming back. */
#ifndef NSPD_SOLID_PD_SURFACE_H
#define NSPD_SOLID_PD_SURFACE_H

#include "solid/solid.h"

typedef struct {
    int loop_count;
    int64_t *loop_start; /* loop_count + 1 offsets into point */
    int32_t *point;      /* surface point indices, loop by loop */
    int64_t length;      /* = loop_start[loop_count] */
} PdSurface;

/* Traces the outer boundary of each connected part of a 2D body's lattice
 * (Moore-neighbour tracing with Jacob's stopping rule). NSPD_ERR_INPUT for a
 * 3D body. Allocates the arrays of *surface. */
int pd_surface_trace(const PdPoints *body, PdSurface *surface);
void pd_surface_free(PdSurface *surface);

/* Current positions and velocities of the surface points, loop by loop, into
 * caller arrays of surface->length entries (the polylines the immersed
 * boundary needs each step). */
void pd_surface_positions(const PdPoints *body, const PdSurface *surface, double *x, double *y,
                          double *vx, double *vy);

/* Adds surface tractions to the body's external force density. traction_x/y
 * hold one value per segment (segment m of a loop joins its m-th point to the
 * next; same indexing as the points), in N/m^2 on the solid. The force of a
 * segment per unit depth, t |segment|, is split equally between its two end
 * points and divided by their volume per unit depth (V / thickness), so
 * sum_i V_i external_i equals thickness x sum_segments t |segment| to
 * round-off. Segment lengths are taken in the current configuration. Writes
 * the total force per unit depth it applied into total[2] (N/m). Adds to
 * `external`: clear it first if the tractions replace earlier ones. */
void pd_surface_apply_tractions(PdPoints *body, const PdSurface *surface, const double *traction_x,
                                const double *traction_y, double total[2]);

#endif
