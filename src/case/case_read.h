/* Reading a whole case file into a SimConfig. */
#ifndef NSPD_CASE_CASE_READ_H
#define NSPD_CASE_CASE_READ_H

#include "io/cfg_tree.h"
#include "sim/sim_config.h"

#include <stdint.h>

/* Loads `path`, applies the --set overrides in order, reads and checks
 * every section. On success *doc holds the resolved tree (defaults filled
 * in) for writing case.yaml, and *cfg the configuration; the caller frees
 * both. On failure both are freed and the status is NSPD_ERR_INPUT (bad
 * case) or NSPD_ERR_IO (unreadable file), with a FILE:LINE:COL message. */
int case_read(const char *path, char *const *overrides, int override_count, CfgDoc *doc,
              SimConfig *cfg);

/* A hash of the resolved case (the text case.yaml holds): a checkpoint
 * belongs to the case it was written from. */
int case_resolved_hash(const CfgDoc *doc, uint64_t *hash);

/* Writes the resolved case (with a header comment) to `path`. */
int case_write_resolved(const CfgDoc *doc, const char *path);

#endif
