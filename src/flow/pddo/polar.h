/* The polar node patch around a circular body (paper 002, Sec. 4.1.2,
 * Fig. 9, Sec. 5.3; notes/pddo.md 1.6 and #20).
 *
 * Rings of ntheta nodes at radii r_q = R + (q - rings_inside) dr,
 * q = 0 .. rings - 1, angles theta_t = t dtheta (t = 0 .. ntheta - 1,
 * dtheta = 2 pi / ntheta):
 *   q <  rings_inside   fictitious body rings s_m (m = rings_inside - q),
 *                       u = 0 (Eqs. 44, 47), pressure image the fluid ring
 *                       f_m at R + m dr on the same ray, p(s_m) = p(f_m)
 *                       (Eq. 48): dp/dr = 0 at r = R to second order
 *                       (Eqs. 45-46, 69), exactly symmetric in r
 *   q == rings_inside   the wall ring f0 at r = R: u = 0 (Eq. 68), PPE row
 *   q >  rings_inside   fluid rings out to r_out = R + floor((r_patch -
 *                       R) / dr) dr
 * Node areas r dr dtheta (the paper never gives them; only ratios matter).
 * ntheta is even (2 round(pi / dtheta)): node t and node ntheta - t mirror
 * exactly about the centre's horizontal line (the same bits, sin negated).
 *
 * The junction (not described by the paper; notes 1.6): the lattice nodes
 * with distance from the centre < r_cut = r_out + gap are removed and the
 * two point sets are simply united, each node keeping its own area; every
 * family is all nodes within the one horizon delta = horizon_factor dx of
 * the cloud (the paper: delta = 3 dx everywhere). With gap >= dx/4 no
 * lattice node is closer than dx/4 to a ring node (radially at least gap).
 * Defaults are the paper's spacings: dtheta 0.0149 rad (422 nodes per
 * ring), dr = 0.69 dx, three fictitious rings, r_patch = dx / dtheta (where
 * the ring spacing r dtheta reaches dx: 2.01 m in Sec. 5.3) and gap = dx/2.
 *
 * Consequences of the paper's choices, measured in
 * tests/unit/flow/pddo/test_polar.c: with delta = 3 dx the wall ring's
 * families hold 161 nodes at the paper's spacings (notes 5.2: ~165), and
 * three fictitious rings reach only 3 dr = 2.07 dx into the body, so the
 * wall ring's family is truncated on the body side: its Laplacian tends to
 * first order (orders 1.50, 1.20 for h halved twice), like the lattice's
 * one-sided families; rings_inside = ceil(delta / dr) = 5 gives 2.05,
 * 1.91. First derivatives are second order everywhere, the junction's
 * Laplacian tends to first order (irregular families).
 *
 * The local horizon (not the paper; spec.local_horizon > 0): ring q's
 * nodes take the horizon delta_q = local_horizon h_q, h_q = max(dr,
 * max(r_q, R) dtheta) their own spacing, rising to the cloud's one delta
 * over the last delta before the outermost ring (delta_q >= delta - (r_out
 * - r_q)), so that the junction's families are the lattice's (measured:
 * without the ramp a patch of dr = dx/6 under a lattice of dx 0.1 m blew
 * up within 10 steps), and never above delta.
 * With the paper's one horizon the rings' spacing does not matter: the
 * operators' error is that of delta = 3 dx (measured: dr and dtheta
 * halved together at dx 0.1 m move the Re 10 cylinder's drag by 0.25 %,
 * dx halved by 3.8 %; docs/VALIDATION.md). With the local one a patch finer than
 * the lattice gives the wall operators of its own spacing, and the
 * fictitious rings default to enough to hold the wall ring's whole
 * family, ceil(delta_wall / dr), at least three. */
#ifndef NSPD_FLOW_PDDO_POLAR_H
#define NSPD_FLOW_PDDO_POLAR_H

#include <stdint.h>

/* Paper 002 Sec. 5.3. */
#define PDDO_POLAR_DTHETA     0.0149
#define PDDO_POLAR_DR_OVER_DX 0.69

typedef struct {
    double dtheta;        /* target angular spacing, rad (0: 0.0149); rounded to 2 pi / ntheta */
    double dr;            /* radial spacing, m (0: 0.69 dx) */
    double r_patch;       /* outermost ring at most here, m (0: dx / dtheta) */
    double gap;           /* lattice nodes removed within r_out + gap, m (0: dx / 2; >= dx / 4) */
    int rings_inside;     /* fictitious rings (0: 3, the paper; with local_horizon, enough for the
                             wall ring's horizon) */
    double local_horizon; /* > 0: the rings' horizon over their spacing (above); 0: the cloud's */
} PddoPolarSpec;

typedef struct {
    double x, y, radius;         /* the body's circle, m */
    double dtheta, dr;           /* rad, m */
    int32_t ntheta;              /* nodes per ring, even */
    int32_t rings_inside, rings; /* fictitious rings; all rings (fictitious, wall, fluid) */
    double r_out, r_cut;         /* outermost ring; lattice nodes removed with r < r_cut, m */
    double local_horizon;        /* the rings' horizon over their spacing, or 0 (above) */
    int64_t first;               /* the cloud's node of ring q, angle t: first + q ntheta + t */
} PddoPolarPatch;

/* Resolves the defaults and checks the patch of the circle (x, y, radius)
 * in a lattice of spacing dx: NSPD_ERR_INPUT for dtheta, dr or the patch
 * not positive, fewer than 8 nodes per ring, gap < dx/4, fewer fluid rings
 * than fictitious ones (their images), or rings_inside dr >= radius. */
int pddo_polar_layout(PddoPolarPatch *patch, double x, double y, double radius,
                      const PddoPolarSpec *spec, double dx);

/* Radius of ring q, m. */
double pddo_polar_radius(const PddoPolarPatch *patch, int q);

/* The horizon of ring q's nodes in a cloud whose one horizon is delta, m
 * (the local horizon above, else delta). */
double pddo_polar_horizon(const PddoPolarPatch *patch, int q, double delta);

/* cos and sin of the angle of index t (exactly mirrored about the
 * centre's horizontal line between t and ntheta - t: the same cos, sin
 * negated). */
void pddo_polar_angle(const PddoPolarPatch *patch, int t, double *c, double *s);

/* Position and area of the node of ring q at angle index t (exactly
 * mirrored about the centre's horizontal line between t and ntheta - t). */
void pddo_polar_node(const PddoPolarPatch *patch, int q, int t, double *x, double *y, double *area);

/* Nodes of the patch. */
int64_t pddo_polar_count(const PddoPolarPatch *patch);

#endif
