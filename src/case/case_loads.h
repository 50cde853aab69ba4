/* Reading loads that may vary (issue 61): a solid's prescribed velocity,
 * displacement, force density, body force, initial velocity and pressure
 * are each a number or a load expression of t, x, y, z in quotes
 * ("20*t", core/expr.h), compiled here once into the body's
 * PdConfig.expressions. A number stays a number (the same bits as
 * before expressions existed). */
#ifndef NSPD_CASE_CASE_LOADS_H
#define NSPD_CASE_CASE_LOADS_H

#include "io/cfg_tree.h"
#include "solid/pd/config.h"

#include <stdbool.h>
#include <stdint.h>

/* A scalar node: a number into *value and *expr = 0, or an expression
 * appended to cfg->expressions with *expr its index + 1 (and *value 0).
 * An expression that does not compile is refused at the node with the
 * column in the expression (the node's own place is its key's, as for
 * every value). */
int case_read_load(const CfgNode *node, PdConfig *cfg, double *value, uint16_t *expr);

/* map[key] as case_read_load; *given false (and nothing set) when absent. */
int case_maybe_load(CfgNode *map, const char *key, PdConfig *cfg, double *value, uint16_t *expr,
                    bool *given);

/* map[key], a list of n loads ([x, y] or [x, y, z]); absent: def, written
 * into the tree as cfg_opt_vec does. */
int case_opt_load_vec(CfgNode *map, const char *key, int n, const double *def, PdConfig *cfg,
                      double *value, uint16_t *expr);

/* The list map[key] of n loads, required. */
int case_req_load_vec(CfgNode *map, const char *key, int n, PdConfig *cfg, double *value,
                      uint16_t *expr);

#endif
