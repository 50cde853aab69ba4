#include "case/case_loads.h"

#include "core/expr.h"
#include "core/mem.h"
#include "core/status.h"
#include "io/cfg_read.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

/* Whether a scalar is written as a number (else it is an expression). */
static bool is_number(const CfgNode *node) {
    if (node->quoted) return false;
    char *end;
    errno = 0;
    (void)strtod(node->text, &end);
    while (*end == ' ') end++;
    return end != node->text && *end == '\0';
}

int case_read_load(const CfgNode *node, PdConfig *cfg, double *value, uint16_t *expr) {
    *expr = 0;
    if (node->kind != CFG_SCALAR || node->is_null || is_number(node))
        return cfg_node_double(node, value); /* a number, or its refusal */
    Expr e;
    ExprError err;
    if (!expr_compile(node->text, &e, &err))
        return cfg_fail(node, "column %d of the load expression '%s': %s", err.column, node->text,
                        err.message);
    if (cfg->expression_count >= PD_MAX_EXPRESSIONS)
        return cfg_fail(node, "too many load expressions; expected at most %d in one solid",
                        PD_MAX_EXPRESSIONS);
    const size_t count = (size_t)cfg->expression_count;
    TRY(nspd_realloc(&cfg->expressions, count, count + 1, sizeof(Expr)));
    cfg->expressions[cfg->expression_count++] = e;
    *expr = (uint16_t)cfg->expression_count;
    *value = 0.0;
    return NSPD_OK;
}

int case_maybe_load(CfgNode *map, const char *key, PdConfig *cfg, double *value, uint16_t *expr,
                    bool *given) {
    CfgNode *node = cfg_map_find(map, key);
    *given = false;
    if (!node) return NSPD_OK;
    node->used = true;
    if (node->kind == CFG_SCALAR && node->is_null) return NSPD_OK;
    *given = true;
    return case_read_load(node, cfg, value, expr);
}

static int load_vec(CfgNode *node, int n, PdConfig *cfg, double *value, uint16_t *expr) {
    if (node->kind != CFG_SEQ || node->count != n) {
        if (node->kind == CFG_SEQ)
            return cfg_fail(node, "a list of %d values; expected exactly %d ([%s])", node->count, n,
                            n == 2 ? "x, y" : "x, y, z");
        return cfg_fail(node, "not a list; expected a list of %d numbers or load expressions", n);
    }
    for (int i = 0; i < n; i++) TRY(case_read_load(node->child[i], cfg, &value[i], &expr[i]));
    return NSPD_OK;
}

int case_opt_load_vec(CfgNode *map, const char *key, int n, const double *def, PdConfig *cfg,
                      double *value, uint16_t *expr) {
    CfgNode *node = cfg_map_find(map, key);
    if (!node || (node->kind == CFG_SCALAR && node->is_null)) {
        for (int i = 0; i < n; i++) expr[i] = 0;
        return cfg_opt_vec(map, key, n, def, value);
    }
    node->used = true;
    return load_vec(node, n, cfg, value, expr);
}

int case_req_load_vec(CfgNode *map, const char *key, int n, PdConfig *cfg, double *value,
                      uint16_t *expr) {
    CfgNode *node = cfg_map_find(map, key);
    if (!node || (node->kind == CFG_SCALAR && node->is_null)) {
        for (int i = 0; i < n; i++) expr[i] = 0;
        return cfg_req_vec(map, key, n, value); /* its "missing required key" */
    }
    node->used = true;
    return load_vec(node, n, cfg, value, expr);
}
