#include "io/cfg_read.h"

#include "core/status.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------ messages */

static int vfail(const CfgNode *node, const char *fmt, va_list args) {
    char where[512], path[512], what[1024];
    cfg_node_where(node, where, sizeof where);
    cfg_node_path(node, path, sizeof path);
    /* va_start in the caller; clang-tidy 14 false positive in multi-file runs (llvm-project#40656)
     * NOLINTNEXTLINE(clang-analyzer-valist.Uninitialized) */
    vsnprintf(what, sizeof what, fmt, args);
    return NSPD_FAIL(NSPD_ERR_INPUT, "%s: %s: %s", where, path, what);
}

int cfg_fail(const CfgNode *node, const char *fmt, ...) {
    va_list args;
    va_start(args, fmt);
    int status = vfail(node, fmt, args);
    va_end(args);
    return status;
}

int cfg_fail_at(const CfgNode *map, const char *key, const char *fmt, ...) {
    const CfgNode *node = cfg_map_find(map, key);
    va_list args;
    va_start(args, fmt);
    int status;
    if (node) {
        status = vfail(node, fmt, args);
    } else {
        char where[512], path[512], what[1024];
        cfg_node_where(map, where, sizeof where);
        cfg_node_path(map, path, sizeof path);
        /* va_start above; clang-tidy 14 false positive in multi-file runs (llvm-project#40656)
         * NOLINTNEXTLINE(clang-analyzer-valist.Uninitialized) */
        vsnprintf(what, sizeof what, fmt, args);
        status = map->parent ? NSPD_FAIL(NSPD_ERR_INPUT, "%s: %s.%s: %s", where, path, key, what)
                             : NSPD_FAIL(NSPD_ERR_INPUT, "%s: %s: %s", where, key, what);
    }
    va_end(args);
    return status;
}

static const char *kind_name(const CfgNode *node) {
    if (node->kind == CFG_MAP) return "a map";
    if (node->kind == CFG_SEQ) return "a list";
    return "a single value";
}

/* ------------------------------------------------------------ lookup */

/* Finds map[key] and marks it used; NULL (no error) when absent or null. */
static CfgNode *take(CfgNode *map, const char *key) {
    CfgNode *node = cfg_map_find(map, key);
    if (!node) return NULL;
    node->used = true;
    if (node->kind == CFG_SCALAR && node->is_null) return NULL;
    return node;
}

static int missing(const CfgNode *map, const char *key, const char *expected) {
    return cfg_fail_at(map, key, "missing required key; expected %s", expected);
}

/* Formats a double with the fewest digits that read back exactly. */
static void format_double(double v, char *buf, int size) {
    for (int digits = 6; digits <= 17; digits++) {
        snprintf(buf, (size_t)size, "%.*g", digits, v);
        if (strtod(buf, NULL) == v) return;
    }
}

static int put_default(CfgNode *map, const char *key, const char *text) {
    CfgNode *old = cfg_map_find(map, key);
    if (old) { /* an explicit null: replace its text so the resolved case shows the value */
        free(old->text);
        size_t n = strlen(text) + 1;
        old->text = malloc(n);
        if (!old->text) return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
        memcpy(old->text, text, n);
        old->is_null = false;
        return NSPD_OK;
    }
    CfgNode *node = cfg_map_add_scalar(map, key, text, CFG_FROM_DEFAULT);
    if (!node) return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
    node->used = true;
    return NSPD_OK;
}

/* ------------------------------------------------------------ scalars */

int cfg_node_double(const CfgNode *node, double *out) {
    if (node->kind != CFG_SCALAR || node->quoted || node->is_null)
        return cfg_fail(node, "got %s; expected a number",
                        node->kind == CFG_SCALAR ? (node->is_null ? "nothing" : "text in quotes")
                                                 : kind_name(node));
    char *end;
    errno = 0;
    double v = strtod(node->text, &end);
    while (*end == ' ') end++;
    if (end == node->text || *end != '\0' || errno == ERANGE)
        return cfg_fail(node, "'%s' is not a number; expected a number such as 2.5e-3", node->text);
    if (!isfinite(v))
        return cfg_fail(node, "'%s' is not finite; expected a finite number", node->text);
    *out = v;
    return NSPD_OK;
}

int cfg_req_double(CfgNode *map, const char *key, double *out) {
    CfgNode *node = take(map, key);
    if (!node) return missing(map, key, "a number");
    return cfg_node_double(node, out);
}

int cfg_opt_double(CfgNode *map, const char *key, double def, double *out) {
    CfgNode *node = take(map, key);
    if (node) return cfg_node_double(node, out);
    char text[40];
    format_double(def, text, sizeof text);
    *out = def;
    return put_default(map, key, text);
}

int cfg_maybe_double(CfgNode *map, const char *key, double *out, bool *given) {
    CfgNode *node = take(map, key);
    *given = node != NULL;
    return node ? cfg_node_double(node, out) : NSPD_OK;
}

static int node_int(const CfgNode *node, int64_t *out) {
    double v;
    TRY(cfg_node_double(node, &v));
    if (v != floor(v) || fabs(v) > 9.0e15)
        return cfg_fail(node, "'%s' is not a whole number; expected an integer", node->text);
    *out = (int64_t)v;
    return NSPD_OK;
}

int cfg_req_int(CfgNode *map, const char *key, int64_t *out) {
    CfgNode *node = take(map, key);
    if (!node) return missing(map, key, "an integer");
    return node_int(node, out);
}

int cfg_opt_int(CfgNode *map, const char *key, int64_t def, int64_t *out) {
    CfgNode *node = take(map, key);
    if (node) return node_int(node, out);
    char text[32];
    snprintf(text, sizeof text, "%lld", (long long)def);
    *out = def;
    return put_default(map, key, text);
}

int cfg_opt_bool(CfgNode *map, const char *key, bool def, bool *out) {
    CfgNode *node = take(map, key);
    if (!node) {
        *out = def;
        return put_default(map, key, def ? "true" : "false");
    }
    static const char *const yes[] = {"true", "True", "TRUE"}, *const no[] = {"false", "False",
                                                                              "FALSE"};
    if (node->kind == CFG_SCALAR && !node->quoted) {
        for (int i = 0; i < 3; i++) {
            if (strcmp(node->text, yes[i]) == 0) {
                *out = true;
                return NSPD_OK;
            }
            if (strcmp(node->text, no[i]) == 0) {
                *out = false;
                return NSPD_OK;
            }
        }
    }
    return cfg_fail(node, "'%s' is not a yes/no value; expected true or false",
                    node->kind == CFG_SCALAR ? node->text : kind_name(node));
}

static int node_string(const CfgNode *node, const char **out) {
    if (node->kind != CFG_SCALAR) return cfg_fail(node, "got %s; expected a word", kind_name(node));
    *out = node->text;
    return NSPD_OK;
}

int cfg_req_string(CfgNode *map, const char *key, const char **out) {
    CfgNode *node = take(map, key);
    if (!node) return missing(map, key, "a word");
    return node_string(node, out);
}

int cfg_opt_string(CfgNode *map, const char *key, const char *def, const char **out) {
    CfgNode *node = take(map, key);
    if (node) return node_string(node, out);
    TRY(put_default(map, key, def));
    *out = cfg_map_find(map, key)->text;
    return NSPD_OK;
}

static int node_enum(const CfgNode *node, const char *const *names, int *out) {
    char options[512] = "";
    int len = 0;
    for (int i = 0; names[i]; i++) {
        if (node->kind == CFG_SCALAR && strcmp(node->text, names[i]) == 0) {
            *out = i;
            return NSPD_OK;
        }
        len +=
            snprintf(options + len, sizeof options - (size_t)len, "%s%s", i ? ", " : "", names[i]);
    }
    return cfg_fail(node, "'%s' is not a known choice; expected one of: %s",
                    node->kind == CFG_SCALAR ? node->text : kind_name(node), options);
}

int cfg_req_enum(CfgNode *map, const char *key, const char *const *names, int *out) {
    CfgNode *node = take(map, key);
    if (!node) return missing(map, key, "a choice");
    return node_enum(node, names, out);
}

int cfg_opt_enum(CfgNode *map, const char *key, const char *const *names, int def, int *out) {
    CfgNode *node = take(map, key);
    if (node) return node_enum(node, names, out);
    *out = def;
    return put_default(map, key, names[def]);
}

static int node_vec(const CfgNode *node, int n, double *out) {
    if (node->kind != CFG_SEQ || node->count != n) {
        if (node->kind == CFG_SEQ)
            return cfg_fail(node, "a list of %d numbers; expected exactly %d ([%s])", node->count,
                            n,
                            n == 2   ? "x, y"
                            : n == 3 ? "x, y, z"
                                     : "...");
        return cfg_fail(node, "got %s; expected a list of %d numbers", kind_name(node), n);
    }
    for (int i = 0; i < n; i++) TRY(cfg_node_double(node->child[i], &out[i]));
    return NSPD_OK;
}

int cfg_req_vec(CfgNode *map, const char *key, int n, double *out) {
    CfgNode *node = take(map, key);
    if (!node) return missing(map, key, "a list of numbers");
    return node_vec(node, n, out);
}

int cfg_opt_vec(CfgNode *map, const char *key, int n, const double *def, double *out) {
    CfgNode *node = take(map, key);
    if (node) return node_vec(node, n, out);
    CfgNode *seq = cfg_map_find(map, key);
    if (seq) { /* an explicit null becomes the default list */
        free(seq->text);
        seq->text = NULL;
        seq->kind = CFG_SEQ;
        seq->is_null = false;
    } else {
        seq = cfg_map_add_collection(map, key, CFG_SEQ, CFG_FROM_DEFAULT);
        if (!seq) return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
    }
    seq->used = true;
    for (int i = 0; i < n; i++) {
        char text[40];
        format_double(def[i], text, sizeof text);
        if (!cfg_seq_add_scalar(seq, text, CFG_FROM_DEFAULT))
            return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
        out[i] = def[i];
    }
    return NSPD_OK;
}

/* ------------------------------------------------------------ collections */

static int collection(CfgNode *map, const char *key, CfgKind kind, bool required, CfgNode **out) {
    *out = NULL;
    CfgNode *node = take(map, key);
    const char *expected = kind == CFG_MAP ? "a map of 'key: value' entries" : "a list";
    if (!node) return required ? missing(map, key, expected) : NSPD_OK;
    if (node->kind != kind) return cfg_fail(node, "got %s; expected %s", kind_name(node), expected);
    *out = node;
    return NSPD_OK;
}

int cfg_req_map(CfgNode *map, const char *key, CfgNode **out) {
    return collection(map, key, CFG_MAP, true, out);
}
int cfg_opt_map(CfgNode *map, const char *key, CfgNode **out) {
    return collection(map, key, CFG_MAP, false, out);
}
int cfg_req_seq(CfgNode *map, const char *key, CfgNode **out) {
    return collection(map, key, CFG_SEQ, true, out);
}
int cfg_opt_seq(CfgNode *map, const char *key, CfgNode **out) {
    return collection(map, key, CFG_SEQ, false, out);
}

/* ------------------------------------------------------------ checks */

int cfg_check_positive(const CfgNode *map, const char *key, double value, const char *expected) {
    if (value > 0) return NSPD_OK;
    return cfg_fail_at(map, key, "must be positive, got %g; expected %s", value, expected);
}

int cfg_check_range(const CfgNode *map, const char *key, double value, double lo, double hi,
                    const char *expected) {
    if (value >= lo && value <= hi) return NSPD_OK;
    return cfg_fail_at(map, key, "%g is out of range; expected %s", value, expected);
}

/* Levenshtein distance, for "did you mean" on unknown keys. */
static int edit_distance(const char *a, const char *b) {
    int la = (int)strlen(a), lb = (int)strlen(b);
    if (la > 63 || lb > 63) return 99;
    int row[64];
    for (int j = 0; j <= lb; j++) row[j] = j;
    for (int i = 1; i <= la; i++) {
        int diag = row[0];
        row[0] = i;
        for (int j = 1; j <= lb; j++) {
            int up = row[j];
            int best = diag + (a[i - 1] != b[j - 1]);
            if (up + 1 < best) best = up + 1;
            if (row[j - 1] + 1 < best) best = row[j - 1] + 1;
            row[j] = best;
            diag = up;
        }
    }
    return row[lb];
}

/* The keys `map` accepts: those the schema looked up in it (cfg_map_asked),
 * given or not, but for one it looked at and left unread (a key refused
 * as unknown is never offered as what was expected). */
static bool accepted(const CfgNode *map, const char *key) {
    const CfgNode *node = cfg_map_find(map, key);
    return !node || node->used;
}

int cfg_end_map(const CfgNode *map) {
    for (int i = 0; i < map->count; i++) {
        const CfgNode *node = map->child[i];
        if (node->used) continue;
        char known[1024] = "";
        int len = 0, best = 99;
        const char *suggestion = NULL;
        /* the asked list can grow below (cfg_map_find records): the count first */
        const int asked = map->asked_count;
        for (int k = 0; k < asked; k++) {
            const char *key = map->asked[k];
            if (!accepted(map, key)) continue;
            if (len < (int)sizeof known)
                len +=
                    snprintf(known + len, sizeof known - (size_t)len, "%s%s", len ? ", " : "", key);
            if (len >= (int)sizeof known) len = (int)sizeof known - 1;
            int d = edit_distance(node->key, key);
            if (d < best) {
                best = d;
                suggestion = key;
            }
        }
        if (suggestion && best <= 2)
            return cfg_fail(node, "unknown key (did you mean '%s'?); expected one of: %s",
                            suggestion, known);
        return cfg_fail(node, "unknown key; expected one of: %s", known[0] ? known : "(none)");
    }
    return NSPD_OK;
}

void cfg_resolve_path(const CfgNode *node, const char *file, char *out, size_t size) {
    const char *slash =
        node->origin == CFG_FROM_FILE && node->file ? strrchr(node->file, '/') : NULL;
    if (file[0] == '/' || !slash) {
        snprintf(out, size, "%s", file);
        return;
    }
    snprintf(out, size, "%.*s/%s", (int)(slash - node->file), node->file, file);
}
