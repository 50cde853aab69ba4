/* The 1D radial Euler equations of an ideal gas in planar, cylindrical or
 * spherical symmetry, solved on a fine uniform grid of (0, R) as the
 * project's converged reference for blasts (issue 57: the 2D backgrounds'
 * L1 errors, the chamber's arrival times and peaks). Finite volumes in the
 * r^(nu-1)-weighted form
 *   d/dt (V_i U_i) + A_{i+1/2} F_{i+1/2} - A_{i-1/2} F_{i-1/2} = S_i,
 *   V_i = (r_{i+1/2}^nu - r_{i-1/2}^nu) / nu, A = r^(nu-1),
 *   S_i = (0, p_i (A_{i+1/2} - A_{i-1/2}), 0),
 * which keeps a gas at rest exactly at rest and conserves mass and total
 * energy to round-off. The face flux is HLLC (Toro, "Riemann Solvers and
 * Numerical Methods for Fluid Dynamics", 3rd ed., sec. 10.4) with the
 * Einfeldt-Roe wave speeds, positively conservative (Batten et al., SIAM J.
 * Sci. Comput. 18, 1997); the face states are minmod-limited linear
 * reconstructions of (rho, u, p), so they lie between the neighbours' and
 * stay positive; time is SSP-RK2 (Heun). Second order where the flow is
 * smooth. */
#ifndef NSPD_FLOW_RADIAL_H
#define NSPD_FLOW_RADIAL_H

#include <stdbool.h>

typedef struct {
    int nu;          /* 1 planar, 2 cylindrical, 3 spherical (as flow/sedov.h) */
    double gamma;    /* 1 < gamma */
    double length;   /* the grid spans (0, length) */
    long cells;      /* uniform cells */
    bool outer_wall; /* r = length: a reflecting wall (true) or transmissive */
    double cfl;      /* of the geometric step bound (radial_stable_step); <= 0.5 */
} RadialConfig;

typedef struct {
    RadialConfig cfg;
    double *rho, *mom, *energy; /* conserved cell averages, `cells` each */
    double *volume, *area;      /* V_i (cells) and A_{i+1/2} (cells + 1) */
    double *scratch;            /* the RK stage and the right-hand side */
    double time;
    long steps;
} RadialSolver;

typedef struct {
    double rho, u, p;
} RadialState;

/* Allocates the grid, filled with `ambient`. NSPD_ERR_INPUT for a config
 * out of range. */
int radial_create(const RadialConfig *cfg, const RadialState *ambient, RadialSolver *out);
void radial_free(RadialSolver *s);

/* A charge: `charge` in r < r0, the cells cut by r0 given the volume-weighted
 * mix of the conserved states (the charge's mass and energy exact on any
 * grid, as the 2D cases' area_fractions). */
void radial_set_charge(RadialSolver *s, double r0, const RadialState *charge,
                       const RadialState *ambient);

/* Advances to time t_end (> s->time) with steps of the stable bound, the
 * last one shortened to land on t_end. NSPD_ERR_NUMERIC, naming the cell,
 * its radius, the step and the quantity, if density or pressure leaves
 * the positive range. */
int radial_advance(RadialSolver *s, double t_end);

/* One step of radial_advance (none when s->time >= t_end). */
int radial_step(RadialSolver *s, double t_end);

/* The primitive state of cell i (centre r = (i + 1/2) length / cells). */
RadialState radial_state(const RadialSolver *s, long i);

/* sum_i V_i rho_i and sum_i V_i (rho E)_i (per radian^(nu-1) of the
 * geometry): conserved to round-off with an outer wall. */
void radial_totals(const RadialSolver *s, double *mass, double *energy);

#endif
