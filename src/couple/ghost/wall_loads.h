/* Surface loads of immersed bodies: pressure, wall shear, tractions, force
 * coefficients, stagnation pressure, separation point.
 *
 * Per wall segment (midpoint M, outward normal n, unit tangent t along the
 * counter-clockwise marker order, length ds), from two probe points
 * P_k = M + k delta n (k = 1, 2; delta = the larger cell width at M) whose
 * values come from the same bilinear stencils as the ghost cells (wall rows
 * where a node is not fluid), built once per geometry:
 *   p_w   = (4 p_1 - p_2) / 3                 (quadratic with dp/dn = 0 at the wall)
 *   T_w   = wall temperature (isothermal) or (4 T_1 - T_2) / 3 (adiabatic)
 *   du_t/dn = (4 (u_1 - u_w).t - (u_2 - u_w).t) / (2 delta)   (quadratic through u_w)
 *   tau_w = mu(T_w) du_t/dn                   (the normal viscous stress vanishes
 *                                              at a steady no-slip wall and is omitted)
 *   traction on the wall (force per unit area, Pa) = -(p_w - p_ambient) n + tau_w t
 *   Cp = (p_w - p_inf) / q,  Cf = tau_w (t . s) / q,  q = rho_inf |U_inf|^2 / 2,
 * where s is the direction from the leading to the trailing edge along the
 * side the segment is on (so Cf > 0 where attached flow runs from the
 * leading edge back). Edges: the markers given by the polyline
 * (IbmPolyline.leading_edge/trailing_edge), else the most upstream and most
 * downstream markers along the free stream. The upper side runs
 * counter-clockwise from the trailing to the leading edge.
 * Forces per unit depth (N/m) are sums over segments in marker order:
 * pressure part -sum (p_w - p_inf) n ds, viscous part sum tau_w t ds; drag
 * along the free stream, lift 90 degrees counter-clockwise from it,
 * coefficients over q L_ref. */
#ifndef NSPD_COUPLE_GHOST_WALL_LOADS_H
#define NSPD_COUPLE_GHOST_WALL_LOADS_H

#include "couple/ghost/ibm.h"

#include <stdint.h>

typedef struct {
    double rho, u, v, p; /* free stream: the reference of Cp, Cf and the coefficients */
    double length;       /* reference length (diameter, chord), m */
    double p_ambient;    /* pressure subtracted in the tractions (the solid's unloaded
                            state; the free-stream pressure, or 0 for absolute loads) */
    /* Segments longer than this (m; 0: no limit) are bridges - across the
     * opened mouth of a crack, or a gap left by debris, on a PD surface:
     * they keep the fluid out but are not wetted and carry no load. Loaded,
     * a bridge would put its whole force on its two end points (measured:
     * the base-pressure suction on the mouth of the 30 MPa cylinder crack,
     * concentrated on the lips, eroded the rear of the cylinder point by
     * point from the mouth outward). */
    double bridge_length;
} IbmReference;

typedef struct {
    double pressure[2], viscous[2]; /* force on the body per unit depth, N/m */
    double cd, cl, cd_pressure, cd_viscous, cl_pressure, cl_viscous;
    double cp_stagnation;       /* max Cp over the body */
    double stagnation[2];       /* where (segment midpoint) */
    double x_separation_over_c; /* first Cf sign change + -> - on the upper side,
                                   (x - x_LE).e_D / chord; NaN if none */
    double separation[2];       /* the point (NaN if none) */
    double leading_edge[2], trailing_edge[2];
    double chord; /* (x_TE - x_LE).e_D, m */
} IbmBodyForces;

/* Per-segment results, struct of arrays over all segments of all bodies
 * (global segment s of body b starts at its marker s - first(b)). */
typedef struct {
    int n, cap;      /* segments */
    int body_count;  /* entries of forces */
    int *body;       /* body of each segment */
    double *arc;     /* arc length from the body's marker 0 to the midpoint, m */
    double *x, *y;   /* midpoint, m */
    double *nx, *ny; /* outward normal */
    double *ds;      /* length, m */
    double *p, *tau; /* wall pressure (Pa), wall shear along t (Pa) */
    double *fx, *fy; /* traction on the wall, Pa (see above) */
    double *cp, *cf;
    uint8_t *upper;  /* 1 on the upper side */
    double *probe_q; /* scratch: u, v, p, T at the two probe points of each segment (8 each) */
    IbmBodyForces *forces;
} IbmSurface;

/* Sizes *out for the Ibm's current segments (grows, never shrinks; call
 * again after an update that changes marker counts). May reallocate: when
 * the segments or bodies outnumber its capacity, every array of *out moves
 * (pointers taken from it before are invalid), so call it outside parallel
 * regions; otherwise it allocates nothing. */
int ibm_surface_reserve(const Ibm *ibm, IbmSurface *out);
void ibm_surface_free(IbmSurface *out);

/* Computes everything above from the solver's current state. *out must have
 * been reserved for the current segments (NSPD_ERR_INPUT otherwise). No
 * allocation; deterministic (sums in marker order). */
int ibm_surface_compute(const Ibm *ibm, GksSolver *s, const IbmReference *ref, IbmSurface *out);

/* Lumps the tractions of body b onto its markers: marker k receives half of
 * ds * traction from each of its two segments (N per m of depth). fx, fy
 * have the body's marker count. */
void ibm_surface_marker_forces(const Ibm *ibm, const IbmSurface *surf, int b, double *fx,
                               double *fy);

/* Stagnation pressure coefficients for tests and reports (gamma, Mach):
 * isentropic (subsonic) and behind a normal shock (Rayleigh pitot formula). */
double ibm_cp_stagnation_isentropic(double gamma, double mach);
double ibm_cp_stagnation_pitot(double gamma, double mach);

#endif
