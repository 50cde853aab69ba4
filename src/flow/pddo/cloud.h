/* Node clouds of the PDDO flow solver (paper 002, Sec. 4 and Figs. 7-10).
 *
 * A uniform lattice of spacing dx in a rectangle [lo, hi], the nodes on its
 * sides included ("wall nodes", the red nodes of Fig. 7), and `layers`
 * layers of fictitious nodes outside each side (three in the paper, to match
 * the horizon delta = 3 dx: every fluid node then has its full family of 28).
 * Node (i, j) sits at centre + (i - nx/2, j - ny/2) dx with centre the middle
 * of the rectangle (docs/STYLE.md: mirrored nodes get exactly mirrored
 * coordinates), i in [-layers, nx + layers], j in [-layers, ny + layers].
 *
 * Each side is a wall (no-slip wall or moving lid), an inlet or an outlet,
 * and that sets the pressure image of its fictitious nodes (Sec. 4):
 *   wall   p_g = p(mirror image across the side)        (Eqs. 40-43, 56)
 *   inlet  p_g = p(the node on the side, same row)      (Eqs. 62, 71)
 *   outlet p_g = -p(mirror image), p = 0 on the side    (Eqs. 50, 51)
 * A fictitious node beyond two sides (a block corner, which the paper does
 * not specify) takes the image across both, with the product of the signs.
 * A periodic pair of sides (not in the paper; for the Taylor-Green test,
 * notes V5) has no side nodes: along that axis the nodes 0 .. n-1 are the
 * unknowns, and the nodes from n on and below 0 are fictitious copies of
 * index mod n (p_g = p(image), u_g = u(image)).
 *
 * Holes: a circular body removes the lattice nodes inside it, except those
 * within `layers` spacings of its edge, which become fictitious body nodes.
 * Their pressure image is the fluid node nearest to their mirror point
 * across the circle (dp/dr = 0 to first order only): a lattice staircase.
 * With spec.polar, every hole gets instead the paper's polar patch (Sec.
 * 4.1.2, Fig. 9; flow/pddo/polar.h): the lattice nodes within its r_cut
 * are removed, and its rings are appended after the lattice nodes, hole by
 * hole (fictitious rings PDDO_NODE_BODY with their exact images on the
 * fluid rings, the wall ring PDDO_NODE_WALL, fluid rings PDDO_NODE_FLUID;
 * lattice indices i = j = INT32_MIN, sides 0, areas r dr dtheta).
 *
 * Areas: dx^2 for every node (the PDDO weights depend only on relative
 * areas, so a uniform lattice needs none; the array is there for the polar
 * patch, r dr dtheta). Families: every node, fictitious ones included, gets
 * all nodes within delta (1 + 1e-9) from core/neighbours.h; the margin
 * keeps the four lattice nodes at exactly 3 dx that round-off would decide
 * (28 neighbours with them, 24 without: notes 1.2). Nodes on the outermost
 * fictitious layers have truncated (one-sided) families. A polar patch
 * with a local horizon (polar.h) gives its ring nodes a smaller one,
 * node_delta: their families hold the nodes within it (the same margin). */
#ifndef NSPD_FLOW_PDDO_CLOUD_H
#define NSPD_FLOW_PDDO_CLOUD_H

#include "flow/pddo/polar.h"

#include <stdbool.h>
#include <stdint.h>

enum { PDDO_LEFT, PDDO_RIGHT, PDDO_BOTTOM, PDDO_TOP, PDDO_SIDES };

typedef enum {
    PDDO_SIDE_WALL = 0, /* no-slip wall or moving lid: even pressure images */
    PDDO_SIDE_INLET,    /* pressure copied from the side's node of the same row or column */
    PDDO_SIDE_OUTLET,   /* p = 0 on the side, odd pressure images */
    PDDO_SIDE_PERIODIC, /* with the opposite side: copies of the nodes one period away */
} PddoSideKind;

typedef enum {
    PDDO_NODE_FLUID = 0, /* strictly inside the rectangle and outside every hole */
    PDDO_NODE_SIDE,      /* on a side of the rectangle (wall, lid, inlet node, exit layer) */
    PDDO_NODE_GHOST,     /* fictitious, outside the rectangle */
    PDDO_NODE_BODY,      /* fictitious, inside a hole within `layers` spacings of its edge
                            (staircase) or on a polar patch's fictitious rings */
    PDDO_NODE_WALL,      /* on a polar patch's wall ring (r = R): at rest, a PPE row */
} PddoNodeKind;

/* The nodes that carry the solution (outputs, totals, probes): fluid, side
 * and wall ring nodes; the fictitious ones are boundary devices. */
static inline bool pddo_node_physical(uint8_t kind) {
    return kind == PDDO_NODE_FLUID || kind == PDDO_NODE_SIDE || kind == PDDO_NODE_WALL;
}

typedef struct {
    double x, y, radius; /* m */
} PddoHole;

typedef struct {
    double lo[2], hi[2];   /* the rectangle, m; (hi - lo) / dx must be whole numbers */
    double dx;             /* lattice spacing, m */
    int layers;            /* fictitious layers per side, >= 1 (the paper: 3) */
    double horizon_factor; /* delta / dx (the paper: 3) */
    PddoSideKind side[PDDO_SIDES];
    const PddoHole *holes; /* circles inside the rectangle, at least one spacing from its sides */
    int nholes;
    const PddoPolarSpec *polar; /* NULL: holes are lattice staircases; else one patch per hole */
} PddoCloudSpec;

typedef struct {
    int64_t n;              /* nodes */
    double *x, *y, *area;   /* m, m^2 */
    int32_t *i, *j;         /* lattice indices */
    uint8_t *kind;          /* PddoNodeKind */
    uint8_t *sides;         /* bit s: on or beyond side s (1u << PDDO_LEFT, ...) */
    int32_t *image;         /* fictitious node: the node its pressure follows; -1 else */
    int8_t *image_sign;     /* +1 even image, -1 odd (outlet); 0 for non-fictitious */
    int32_t nx, ny, layers; /* intervals along x and y; fictitious layers */
    double dx, delta;       /* spacing and horizon, m */
    double *node_delta;     /* per node, its own horizon (delta but on local-horizon rings), m */
    PddoSideKind side[PDDO_SIDES];
    int64_t *first; /* families: nbr[first[k] .. first[k+1]), ascending */
    int32_t *nbr;
    int32_t *slot;         /* (i + layers) + (j + layers) (nx + 2 layers + 1) -> node, or -1 */
    PddoPolarPatch *patch; /* one per hole with spec.polar, else NULL */
    int npatches;
} PddoCloud;

/* Builds the cloud of `spec` into c (zeroed or freed before). Node order is
 * row by row (j, then i), holes skipped. NSPD_ERR_INPUT for a spacing that
 * does not divide the rectangle, layers < 1, a horizon factor <= 0, a hole
 * that is not inside (with a polar patch: its r_cut plus the horizon), a
 * periodic side facing one that is not, a period shorter than the layers,
 * a polar patch pddo_polar_layout refuses or two patches that overlap;
 * NSPD_ERR_NOMEM. */
int pddo_cloud_build(PddoCloud *c, const PddoCloudSpec *spec);

/* The spec's checks that need no nodes (its spacing, sides, periodic axes,
 * holes against the sides), as pddo_cloud_build makes them first. */
int pddo_cloud_check(const PddoCloudSpec *spec);

void pddo_cloud_free(PddoCloud *c);

/* The node at lattice indices (i, j), or -1 (outside the cloud or removed). */
int64_t pddo_cloud_node(const PddoCloud *c, int i, int j);

#endif
