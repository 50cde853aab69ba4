/* The `flow:` section of a case with `method: pddo` -> PddoFlowConfig
 * (keys in docs/CASES.md, "flow (method: pddo)"). */
#ifndef NSPD_CASE_CASE_PDDO_H
#define NSPD_CASE_CASE_PDDO_H

#include "flow/pddo/model.h"
#include "io/cfg_tree.h"

#include <stdbool.h>

/* Reads and checks the section into *c. The time step: `dt` when
 * `dt_given` (refused at time_map's `dt` when above the stable limit),
 * else half the limit. */
int case_read_pddo(CfgNode *section, CfgNode *time_map, bool dt_given, double dt,
                   PddoFlowConfig *c);

#endif
