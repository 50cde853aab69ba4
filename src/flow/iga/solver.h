/* The isogeometric compressible-flow solver of paper 003 (Sec. 3;
 * ../shared/notes/iga_flow.md): tensor-product B-splines of degree 1-3 on a
 * uniform rectangle, pressure-primitive control values Y = (p, u, v, T),
 * Galerkin + SUPG + discontinuity capturing (kernel.h), and the explicit
 * generalised-alpha predictor-multicorrector with the lumped A0 block of
 * each control point (notes 3.2). Element results go to element-owned
 * slots and are gathered per control point in ascending element order, so
 * any thread count gives the same bits. */
#ifndef NSPD_FLOW_IGA_SOLVER_H
#define NSPD_FLOW_IGA_SOLVER_H

#include "core/checkpoint.h"
#include "core/comm.h"
#include "core/shape.h"
#include "flow/iga/decomp.h"
#include "flow/iga/kernel.h"
#include "flow/iga/limiter.h"
#include "flow/iga/space.h"

#include <stdint.h>

typedef enum { IGA_SIDE_SLIP = 0, IGA_SIDE_PERIODIC, IGA_SIDE_FIXED, IGA_SIDE_KINDS } IgaSideKind;

/* lumped_l2: int N_A Y0 / int N_A; nodal: Y0 at the Greville points (the
 * paper's code); l2: the L2 projection (the consistent mass matrix, by
 * conjugate gradients: for order studies of smooth data) */
typedef enum { IGA_INIT_LUMPED_L2 = 0, IGA_INIT_NODAL, IGA_INIT_L2 } IgaInit;

typedef enum { IGA_YDOT0_ZERO = 0, IGA_YDOT0_CONSISTENT } IgaYdot0;

/* A primitive state: p (Pa), u, v (m/s), T (K). */
typedef struct {
    double p, u, v, T;
} IgaState;

typedef struct {
    ShapeSet shapes; /* borrowed */
    IgaState state;
} IgaRegion;

typedef struct {
    double lo[2], hi[2];
    int elements[2];
    int degree;
    IgaSideKind side[4]; /* x_min, x_max, y_min, y_max (periodic in pairs) */
    double gamma, R, mu, prandtl;
    IgaState initial;
    int region_count;
    const IgaRegion *regions; /* borrowed during create; later regions win */
    IgaInit init;
    /* optional: the initial state (p, u, v, T) at (x, y) instead of
     * `initial` and `regions` (smooth test data) */
    void (*init_fn)(void *ctx, double x, double y, double out[4]);
    void *init_ctx;
    bool exact_areas; /* lumped_l2: each single disc or rectangle region at its exact area */
    IgaYdot0 ydot0;
    double c_dc;
    bool dc_cap;
    int passes;             /* corrector passes per step (3) */
    double rho_inf;         /* spectral radius at infinity (0.5) */
    int db_iterations;      /* tau's Denman-Beavers iterations (10) */
    double tau_dt;          /* s: tau's time step; 0: the step taken */
    double cfl;             /* (|u| + c) dt / h of the stable step (0.3) */
    IgaLimiterKind limiter; /* convex limiting of each step (limiter.h) */
    /* the processes that share the flow (NULL or one: this one alone;
     * borrowed during create) and the process grid asked for ({0, 0}: the
     * fewest halo points), decomp.h */
    const NspdComm *comm;
    int processes[2];
} IgaConfig;

typedef struct IgaSolver IgaSolver;

/* Builds the space, the initial control values and, with ydot0
 * consistent, the starting rate at the step dt0 (> 0). */
int iga_solver_create(IgaSolver **out, const IgaConfig *cfg, double dt0);
void iga_solver_destroy(IgaSolver **s);

/* The configuration's checks that need no control points (also made by
 * create). */
int iga_config_check(const IgaConfig *cfg);

/* cfl min(hx, hy) / max over control points of (|u| + c); with a
 * limiter, at most the low-order update's invariant step at the last
 * step's start (a step longer than the current one is taken in equal
 * substeps that each keep it). */
double iga_solver_stable_dt(const IgaSolver *s);

/* The same from the configuration alone: the initial and region states
 * (0 for an initial function or an invalid configuration). */
double iga_config_stable_dt(const IgaConfig *cfg, const IgaRegion *regions, int count);

/* One step of dt (notes 3.2); NSPD_ERR_NUMERIC naming the control point
 * where p or T left the physical range. */
int iga_solver_step(IgaSolver *s, double dt);

double iga_solver_time(const IgaSolver *s);
int64_t iga_solver_steps(const IgaSolver *s);
const IgaAxis *iga_solver_axis(const IgaSolver *s, int axis);
const IgaConfig *iga_solver_config(const IgaSolver *s);

/* The control values (4 a point) and their rates: on one process the
 * whole's, point k = i + nx j; on several this process's window
 * (decomp.h). */
double *iga_solver_values(IgaSolver *s);
double *iga_solver_rates(IgaSolver *s);
/* The whole's control points. */
int64_t iga_solver_control_count(const IgaSolver *s);
/* This process's share (decomp.h). */
const IgaDecomp *iga_solver_decomp(const IgaSolver *s);

/* The field at (x, y): Y into out[4] (p, u, v, T); false (and NaN) where
 * the element that holds (x, y) is not in this process's window. */
bool iga_solver_eval(const IgaSolver *s, double x, double y, double out[4]);

/* The process that owns the element holding (x, y) (0 on one). */
int iga_solver_point_owner(const IgaSolver *s, double x, double y);

/* Integrals of rho, rho u, rho v, rho E over the rectangle (Gauss, exact
 * sums; collective). */
void iga_solver_totals(const IgaSolver *s, double totals[4]);

/* The area-mean of the pressure field, Pa (a closed box's late mean
 * pressure is its energy balance's). */
double iga_solver_mean_pressure(const IgaSolver *s);

/* The largest DC viscosity of the last residual, m^2/s. */
double iga_solver_nu_max(const IgaSolver *s);

/* The last step's limiting: control points blended below the high-order
 * state, their smallest blending factor (1: none) and the substeps it
 * took (collective). */
void iga_solver_limiting(const IgaSolver *s, int64_t *limited, double *alpha_min, int *substeps);

/* Writes or reads what a step changes (values, rates, clock). */
int iga_solver_checkpoint(IgaSolver *s, Checkpoint *ck);

/* The control points (global, k = i + nx j) and basis values N_A(x, y) of the
 * element that holds (x, y): (p + 1)^2 of each, their number returned; 0
 * off the rectangle. */
int iga_solver_point_basis(const IgaSolver *s, double x, double y, int64_t *cp, double *w);

/* Point sources for the steps that follow: point q at (x[q], y[q]) gives
 * the gas the force (fx[q], fy[q]) and the power power[q] (per metre of
 * depth; power NULL: none). Each enters the momentum and energy rows of
 * its element's control points as the Galerkin term of a point load,
 * R_A -= N_A(x_q) f_q, so the partition of unity hands over exactly f_q
 * (notes T12; the strong residual of SUPG and DC sees no delta). Points
 * off the rectangle are dropped and counted in *outside; n = 0 clears the
 * sources. On several processes every one passes every point. */
int iga_solver_set_sources(IgaSolver *s, int64_t n, const double *x, const double *y,
                           const double *fx, const double *fy, const double *power,
                           int64_t *outside);

/* The lumped mass int N_A rho^h (kg per metre of depth) of control points
 * cps[q] (global indices) and their momentum (the mass times the control
 * velocity); NaN for the points another process owns. */
void iga_solver_lumped(const IgaSolver *s, int64_t n, const int64_t *cps, double *mass, double *mx,
                       double *my);

/* int N_A (m^2 per metre of depth) of control points cps[q] (as lumped). */
void iga_solver_lumped_volume(const IgaSolver *s, int64_t n, const int64_t *cps, double *volume);

/* Adds momentum (dmx, dmy) and total energy de (per metre of depth; NULL:
 * none) to the distinct control points cps[q], between steps: the control
 * velocity by the momentum over the lumped mass, the temperature by the
 * energy, the density at the control point kept (p follows T); on
 * several processes each adds to its own points and drops the others,
 * then the halo is exchanged (collective). */
void iga_solver_add_lumped(IgaSolver *s, int64_t n, const int64_t *cps, const double *dmx,
                           const double *dmy, const double *de);

/* Bytes per control point and per element of the solver's arrays. */
double iga_solver_bytes(int degree, double control_points, double elements);

#endif
