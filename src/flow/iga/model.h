/* The isogeometric flow of paper 003 behind FlowOps (flow.method: iga;
 * docs/CASES.md). Its configuration: the solver's (solver.h) with the
 * initial regions it owns, or an initial vortex. */
#ifndef NSPD_FLOW_IGA_MODEL_H
#define NSPD_FLOW_IGA_MODEL_H

#include "flow/flow.h"
#include "flow/iga/solver.h"
#include "flow/vortex.h"

#include <stdbool.h>

typedef struct {
    IgaConfig solver;
    int region_count;
    IgaRegion *regions; /* owned, with their shapes */
    bool has_vortex;    /* the initial state is `vortex` (its periods set by create) */
    FlowVortex vortex;
} IgaFlowConfig;

void iga_flow_config_free(IgaFlowConfig *c);

extern const FlowOps IGA_FLOW_OPS;

#endif
