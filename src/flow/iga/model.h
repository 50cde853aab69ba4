/* The isogeometric flow of paper 003 behind FlowOps (flow.method: iga;
 * docs/CASES.md). Its configuration: the solver's (solver.h) with the
 * initial regions it owns. */
#ifndef NSPD_FLOW_IGA_MODEL_H
#define NSPD_FLOW_IGA_MODEL_H

#include "flow/flow.h"
#include "flow/iga/solver.h"

typedef struct {
    IgaConfig solver;
    int region_count;
    IgaRegion *regions; /* owned, with their shapes */
} IgaFlowConfig;

void iga_flow_config_free(IgaFlowConfig *c);

extern const FlowOps IGA_FLOW_OPS;

#endif
