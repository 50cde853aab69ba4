/* The PDDO incompressible flow of paper 002 (pddo_cloud, pddo_ops, pddo_ppe,
 * pddo_step) as a flow model: its case configuration and the FlowOps table.
 *
 * The unknowns live on the nodes of a lattice cloud (MESH_POINTS): outputs
 * are the physical nodes (fluid and side nodes; the fictitious layers are
 * left out) with velocity, pressure, vorticity and divergence, pictures of
 * speed, pressure and vorticity, and up to two line tables (u, v, p along a
 * lattice row or column, the cavity's centrelines by default). The
 * driver's point probes read u, v, p interpolated from the nodes
 * (flow/pddo/sample.h; FlowOps.probe_add). The flow takes no sources and
 * has no general `sample` (couplings need a grid): both are refused with
 * an input error by the interface. Bodies: circles on polar patches, each
 * with its force (flow/pddo/forces.h): the first body's under the plain
 * names of the history and summary, the others' under <name>_ (the GKS
 * flow's rule; docs/CASES.md). A steady-state tolerance on max |du/dt| ends the run
 * early through FlowOps.finished. */
#ifndef NSPD_FLOW_PDDO_MODEL_H
#define NSPD_FLOW_PDDO_MODEL_H

#include "flow/pddo/cloud.h"
#include "flow/pddo/step.h"

#include <stdbool.h>

enum { PDDO_MAX_LINES = 2, PDDO_LINE_NAME = 32, PDDO_MAX_BODIES = 8 };

/* A line table: the lattice row (along x) or column (along y) through
 * `at`, linearly interpolated between the two nearest when `at` lies
 * between them. */
typedef struct {
    char name[PDDO_LINE_NAME]; /* the file line_<name>_NNNNN.csv */
    double at[2];              /* m */
    int along;                 /* 0: x, 1: y */
} PddoLine;

typedef struct {
    PddoCloudSpec cloud; /* holes and polar set from bodies/polar when built */
    int body_count;      /* circular bodies on polar patches (at most PDDO_MAX_BODIES) */
    PddoHole bodies[PDDO_MAX_BODIES];
    char body_name[PDDO_MAX_BODIES][PDDO_LINE_NAME]; /* the prefix of the second and later
                                                        bodies' columns: <name>_drag_n ... */
    PddoPolarSpec polar[PDDO_MAX_BODIES];            /* the patch around each body */
    double average_from;       /* s: force means and the lift's periods from this time on
                                  (create takes FlowConfig.average_from, the driver's) */
    PddoStepParams step;       /* step.dt: the step of the case (given or chosen) */
    double velocity_scale;     /* m/s: the lid, 1.5 times the inlet, or a body force's
                                  Poiseuille maximum; sets the stable step and pictures */
    double steady_tolerance;   /* m/s^2: the run ends once max |du/dt| falls below; 0: never */
    bool pressure_runs;        /* flow.pressure_solve: runs (pddo_ppe_use_runs), else umfpack */
    PddoPpeSolver pressure;    /* flow.pressure_solve: mumps or boomeramg (PETSc), with
                                  flow.pressure_tolerance; else UMFPACK */
    double reference_length;   /* m: `reference.length`, else the body's diameter, else the
                                  rectangle's shorter side (Reynolds number, coefficients) */
    double reference_velocity; /* m/s: the lid, the inlet's mean, or a body force's
                                  Poiseuille mean (the Reynolds number) */
    int line_count;
    PddoLine lines[PDDO_MAX_LINES];
} PddoFlowConfig;

/* The spacing the stable step sees, the smallest horizon over 3: notes
 * 1.5's limit is for the paper's delta = 3 dx, and the Laplacian's largest
 * symbol scales as 1/delta^2 (measured on the Re 10 cylinder at dx 0.05 m:
 * with horizon_factor 2 a step of 2.5e-3 s blew up and 1.5e-3 s did not,
 * against 1.78e-3 s from delta / 3; with 3, 3.5e-3 s is stable against
 * 4e-3). The lattice's, or a polar patch's wall ring's with a local
 * horizon (flow/pddo/polar.h). */
double pddo_flow_smallest_spacing(const PddoFlowConfig *c);

/* The largest stable step of a configuration (notes/pddo.md 1.5):
 * min(1.61 h^2 / nu, 2 nu / U^2) with U its velocity scale, h the smallest
 * spacing. */
double pddo_flow_dt_limit(const PddoFlowConfig *c);

extern const struct FlowOps PDDO_FLOW_OPS;

#endif
