/* The `solid:` section of a case file -> SolidConfig: bond-based PD
 * (PdConfig) or, with `formulation: correspondence`, CpdConfig. */
#ifndef NSPD_CASE_CASE_SOLID_H
#define NSPD_CASE_CASE_SOLID_H

#include "io/cfg_tree.h"
#include "solid/solid.h"

/* Reads and checks the section; every key is documented in docs/CASES.md.
 * On failure *cfg may be partly filled: free it with solid_config_free. */
int case_read_solid(CfgNode *section, SolidConfig *cfg);

#endif
