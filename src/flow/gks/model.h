/* The GKS flow solver (solver.h) as a flow model: its case configuration
 * and the FlowOps table. */
#ifndef NSPD_FLOW_GKS_MODEL_H
#define NSPD_FLOW_GKS_MODEL_H

#include "flow/gks/bc.h"
#include "flow/gks/field_sample.h"
#include "flow/gks/solver.h"
#include "core/report.h"

#include <stdbool.h>

/* The GKS part of a case: the solver's configuration plus what it borrows
 * (initial-condition regions and their shapes, the vortex, a field to
 * start from), owned here. */
typedef struct {
    GksConfig solver;
    int region_count;
    FlowRegion *regions; /* owned, with their shapes */
    bool has_vortex;
    FlowVortex vortex; /* the initial condition when has_vortex */
    bool has_field;
    FlowFieldSource field; /* initial.from, owned; sampled for the initial condition */
    /* the free stream, when the case defines one: the reference of Mach
     * number, pressure coefficient and force coefficients */
    bool has_free_stream;
    FlowPrim free_stream;
    double reference_length; /* m; 0 if not given */
} GksCaseConfig;

void gks_case_config_free(GksCaseConfig *c);

extern const struct FlowOps GKS_FLOW_OPS;

typedef struct Flow Flow;
/* The checked accessor: the GKS solver of a flow, NULL for any other solver
 * (a coupling that needs the grid refuses those at create). */
GksSolver *gks_flow_solver(Flow *f);

/* `nspd bench gks` (FlowOps.bench): gks_bench on about `cells` cells with
 * the current OpenMP threads, `steps` timed steps, into *out. */
int gks_bench_report(long cells, long steps, Report *out);

#endif
