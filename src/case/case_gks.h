/* The `flow:` section of a case file -> the GKS solver's configuration
 * and the walls of its fixed bodies. */
#ifndef NSPD_CASE_CASE_GKS_H
#define NSPD_CASE_CASE_GKS_H

#include "couple/ghost/model.h"
#include "flow/gks/model.h"
#include "io/cfg_tree.h"

/* Reads and checks the section (keys in docs/CASES.md): the solver into
 * *fc, the fixed bodies (flow.bodies, soft_start, ghost_faces) into *walls.
 * The initial-condition hook for a vortex or a field is set when the solver
 * is created, once the configuration has its final address. On failure both
 * may be partly filled: free them with gks_case_config_free and
 * ghost_coupling_config_free. */
int case_read_gks(CfgNode *section, GksCaseConfig *fc, GhostCouplingConfig *walls);

#endif
