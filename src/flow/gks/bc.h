/* Boundary conditions on the four faces of the box, applied by filling the
 * GRID_NG ghost layers of the conservative fields.
 *
 * Each face carries up to FLOW_BC_MAX_SEGMENTS segments along it; segment k
 * applies to the ghost cells whose centre coordinate along the face is
 * >= seg[k].start (seg[0] applies from the start of the face). So a flat
 * plate is a bottom face with symmetry up to the leading edge and a no-slip
 * wall after it.
 *
 * Methods (n: the face's outward normal; u_n, u_t the normal and tangential
 * velocity; "image" = the interior cell mirrored through the face, k-th
 * ghost layer <-> k-th interior layer):
 *   SUPERSONIC_INFLOW   ghost = prescribed state (all layers).
 *   MOVING_SHOCK_INFLOW ghost = prescribed post-shock state: the shock tube's
 *                       driver gas entering through the face (paper 000 Sec.
 *                       4.3, Table 3); flow_shock_post_state() gives the state
 *                       behind a shock of Mach number Ms running into a gas.
 *   SUBSONIC_INFLOW     characteristic far-field: outgoing Riemann invariant
 *                       u_n + 2c/(gamma-1) from the first interior cell,
 *                       incoming one u_n - 2c/(gamma-1) from the prescribed
 *                       state; entropy and u_t from the state where the flow
 *                       enters, from the interior where it leaves; supersonic
 *                       normal speeds take everything from the upwind side.
 *                       (It is therefore also the far-field boundary.)
 *   SUBSONIC_OUTFLOW    prescribed back pressure p_b with the interior
 *                       entropy, u_t and outgoing invariant: rho_b = rho_i
 *                       (p_b/p_i)^(1/gamma), u_n = u_n,i + 2 (c_i - c_b)/(gamma-1);
 *                       supersonic outflow extrapolates.
 *   EXTRAPOLATION       ghost = first interior cell (zeroth order).
 *   SLIP_WALL, SYMMETRY image with u_n negated.
 *   NOSLIP_ADIABATIC    image with u_n negated and u_t -> 2 u_wall - u_t.
 *   NOSLIP_ISOTHERMAL   as adiabatic, with T_g = 2 T_wall - T_image (floored
 *                       at T_wall/4) and p_g = p_image, so T is T_wall and
 *                       dp/dn = 0 at the face to second order.
 *   PERIODIC            copy from the opposite end (both faces periodic,
 *                       one segment; the grid axis must be periodic).
 * Wall faces: a no-slip ghost (both velocity components reversed) is not a
 * mirror image, so the 2D flux through the wall would carry a small mass flux
 * (from its tangential-slope terms); the flow operator therefore sets the mass
 * flux of every wall face to zero, and the energy flux too where the wall is
 * adiabatic and at rest (slip, symmetry, resting adiabatic no-slip).
 * Ghost corners: x-faces are filled for the interior rows first, then the
 * y-faces for every column including the x ghosts, so corners take the
 * y-face rule applied to the x-ghost values. Cell kinds are copied into the
 * ghost layers from the image cells (periodic: from the opposite end). */
#ifndef NSPD_FLOW_GKS_BC_H
#define NSPD_FLOW_GKS_BC_H

#include "flow/gks/flux_kernel.h"
#include "flow/gks/grid.h"

#include <stdint.h>

typedef enum {
    BC_EXTRAPOLATION = 0,
    BC_SUPERSONIC_INFLOW,
    BC_SUBSONIC_INFLOW,
    BC_SUBSONIC_OUTFLOW,
    BC_SLIP_WALL,
    BC_NOSLIP_ADIABATIC,
    BC_NOSLIP_ISOTHERMAL,
    BC_SYMMETRY,
    BC_PERIODIC,
    BC_MOVING_SHOCK_INFLOW,
    BC_KIND_COUNT
} FlowBcKind;

extern const char *const FLOW_BC_NAMES[BC_KIND_COUNT + 1]; /* "extrapolation", ..., NULL */

/* A primitive state: density kg/m^3, velocity m/s, pressure Pa. */
typedef struct {
    double rho, u, v, p;
} FlowPrim;

typedef struct {
    FlowBcKind kind;
    FlowPrim state;          /* inflow / far-field / post-shock state */
    double pressure;         /* back pressure, Pa (SUBSONIC_OUTFLOW) */
    double wall_velocity;    /* wall speed along +x (y-faces) or +y (x-faces), m/s */
    double wall_temperature; /* K (NOSLIP_ISOTHERMAL) */
    double start;            /* coordinate along the face where this segment begins, m
                                (ignored for seg[0], which covers everything before seg[1]) */
} FlowBc;

enum { FLOW_BC_MAX_SEGMENTS = 4 };
enum { FLOW_FACE_XLO = 0, FLOW_FACE_XHI = 1, FLOW_FACE_YLO = 2, FLOW_FACE_YHI = 3 };

typedef struct {
    int count; /* segments in use, >= 1 */
    FlowBc seg[FLOW_BC_MAX_SEGMENTS];
} FlowFaceBc;

/* Checks a set of four face conditions against the grid (periodic pairs,
 * segment order, positive states). NSPD_ERR_INPUT with a message. */
int bc_validate(const Grid *g, const FlowFaceBc bc[4]);

/* Fills the ghost layers of w[0..3] (and kind, if not NULL) on all four
 * faces. gas supplies gamma and R. Serial; touches only ghost cells. */
void bc_fill(const Grid *g, const FlowFaceBc bc[4], const GksParams *gas, double *const w[4],
             uint8_t *kind);
/* The same on the faces of the mask (bit 1 << FLOW_FACE_*) only, in the
 * same order: a process's slab fills the whole grid's faces it holds and
 * takes the others from its neighbours (flow/gks/solver.h). */
void bc_fill_faces(const Grid *g, const FlowFaceBc bc[4], const GksParams *gas, double *const w[4],
                   uint8_t *kind, unsigned faces);

/* The state behind a shock of Mach number ms (> 1) moving into `pre` along
 * +x (direction = +1) or -x (-1), by the Rankine-Hugoniot relations. The
 * post-shock velocity is pre.u + direction * (change); v is kept. */
void flow_shock_post_state(const FlowPrim *pre, double ms, double gamma, int direction,
                           FlowPrim *post);

/* Conservative <-> primitive for a gas of ratio gamma. */
void flow_prim_to_cons(const FlowPrim *q, double gamma, double w[4]);
void flow_cons_to_prim(const double w[4], double gamma, FlowPrim *q);

#endif
