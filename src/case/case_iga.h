/* The `flow:` section of an isogeometric case (flow.method: iga) ->
 * IgaFlowConfig. The keys it shares with the GKS flow (gas, grid,
 * boundaries, initial) are read by that flow's reader, so a case runs on
 * either background by `--set flow.method=...`; the method's own keys are
 * under flow.iga (docs/CASES.md). */
#ifndef NSPD_CASE_CASE_IGA_H
#define NSPD_CASE_CASE_IGA_H

#include "flow/iga/model.h"
#include "io/cfg_tree.h"

/* Reads and checks the section into *out; on failure *out may be partly
 * filled: free it with iga_flow_config_free. */
int case_read_iga(CfgNode *flow, IgaFlowConfig *out);

/* flow.iga in a case on another background: read as case_read_iga would
 * (the same refusals, a misspelt key's did-you-mean included) from a copy,
 * so the case is left as it was but for flow.iga marked used. */
int case_check_iga_method(CfgNode *flow);

#endif
