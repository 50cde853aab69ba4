/* Typed, checked reading of a CfgNode tree: the building blocks of every
 * case-file schema.
 *
 * Each getter looks `key` up in `map`, marks it used, converts it and returns
 * NSPD_OK, or NSPD_ERR_INPUT with the message
 *     FILE:LINE:COL: dotted.key: what is wrong; what is expected
 * An optional key that is absent (or null: `key: ~`) takes its default, and
 * the default is written into the tree, so that writing the tree afterwards
 * gives the fully resolved case. After reading a map, cfg_end_map() refuses
 * any key the schema did not read (with a did-you-mean suggestion). */
#ifndef NSPD_IO_CFG_READ_H
#define NSPD_IO_CFG_READ_H

#include "io/cfg_tree.h"

#include <stdbool.h>
#include <stdint.h>

/* Formats "WHERE: PATH: <message>" at `node` and returns NSPD_ERR_INPUT. */
int cfg_fail(const CfgNode *node, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* Same, at map[key] if present, else at the map itself. */
int cfg_fail_at(const CfgNode *map, const char *key, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

int cfg_req_double(CfgNode *map, const char *key, double *out);
int cfg_opt_double(CfgNode *map, const char *key, double def, double *out);
/* Like cfg_opt_double, but an absent key leaves *out unset and *given false
 * (for values with computed defaults such as a stable time step). */
int cfg_maybe_double(CfgNode *map, const char *key, double *out, bool *given);
int cfg_req_int(CfgNode *map, const char *key, int64_t *out);
int cfg_opt_int(CfgNode *map, const char *key, int64_t def, int64_t *out);
int cfg_opt_bool(CfgNode *map, const char *key, bool def, bool *out);
/* Strings point into the tree: valid until cfg_doc_free. */
int cfg_req_string(CfgNode *map, const char *key, const char **out);
int cfg_opt_string(CfgNode *map, const char *key, const char *def, const char **out);
/* One of `names` (NULL-terminated); *out is its index. */
int cfg_req_enum(CfgNode *map, const char *key, const char *const *names, int *out);
int cfg_opt_enum(CfgNode *map, const char *key, const char *const *names, int def, int *out);
/* A list of exactly n numbers: [x, y] */
int cfg_req_vec(CfgNode *map, const char *key, int n, double *out);
int cfg_opt_vec(CfgNode *map, const char *key, int n, const double *def, double *out);
/* Nested maps and lists. Optional ones give *out = NULL when absent. */
int cfg_req_map(CfgNode *map, const char *key, CfgNode **out);
int cfg_opt_map(CfgNode *map, const char *key, CfgNode **out);
int cfg_req_seq(CfgNode *map, const char *key, CfgNode **out);
int cfg_opt_seq(CfgNode *map, const char *key, CfgNode **out);
/* Converts an already-found scalar node (e.g. a list item). */
int cfg_node_double(const CfgNode *node, double *out);

/* Range checks that report at map[key]: "must be > 0, got -1". */
int cfg_check_positive(const CfgNode *map, const char *key, double value, const char *expected);
int cfg_check_range(const CfgNode *map, const char *key, double value, double lo, double hi,
                    const char *expected);

/* Refuses the first key of `map` that no getter read. */
int cfg_end_map(const CfgNode *map);

/* The path `file`, named by `node`, relative to the directory of the case
 * file it came from (absolute paths and --set values as given), into out. */
void cfg_resolve_path(const CfgNode *node, const char *file, char *out, size_t size);

#endif
