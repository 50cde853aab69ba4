/* The `flow:` section of a case file -> FlowCaseConfig. */
#ifndef NSPD_IO_CASE_FLOW_H
#define NSPD_IO_CASE_FLOW_H

#include "io/cfg_tree.h"
#include "sim/sim_config.h"

/* Reads and checks the section (keys in docs/CASES.md). The solver's
 * initial-condition hook for a vortex is set by sim_create, once the
 * configuration has its final address. On failure *fc may be partly filled:
 * free it with flow_case_config_free. */
int case_read_flow(CfgNode *section, FlowCaseConfig *fc);

#endif
