/* The `solid:` section of a case file -> PdConfig. */
#ifndef NSPD_CASE_CASE_SOLID_H
#define NSPD_CASE_CASE_SOLID_H

#include "io/cfg_tree.h"
#include "solid/pd_config.h"

/* Reads and checks the section; every key is documented in docs/CASES.md.
 * On failure *cfg may be partly filled: free it with pd_config_free. */
int case_read_solid(CfgNode *section, PdConfig *cfg);

#endif
