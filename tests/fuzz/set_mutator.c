/* The --set mutator (set_mutator.h). */
#include "set_mutator.h"

#include "core/status.h"
#include "io/cfg_tree.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_OVERRIDES = 8, MAX_KEYS = 4096 };

static const char *const EXTREMES[] = {
    "0",          "-1",      "-0.5",
    "1e-300",     "-1e-300", "1e300",
    "-1e300",     "1e11",    "123456789012345678901",
    "nan",        "inf",     "[]",
    "2147483648",
};
enum { EXTREME_COUNT = sizeof EXTREMES / sizeof EXTREMES[0] };

/* The scalars under node, depth first, into keys (at most MAX_KEYS). */
static void collect(const CfgNode *node, const CfgNode **keys, int *count) {
    if (*count >= MAX_KEYS) return;
    if (node->kind == CFG_SCALAR) {
        if (node->parent) keys[(*count)++] = node;
        return;
    }
    for (int k = 0; k < node->count; k++) collect(node->child[k], keys, count);
}

/* "a.b[1].c" as --set writes it: "a.b.1.c". */
static void dotted(const char *path, char *out, size_t size) {
    size_t n = 0;
    for (const char *p = path; *p && n + 1 < size; p++) {
        if (*p == ']') continue;
        out[n++] = *p == '[' ? '.' : *p;
    }
    out[n] = '\0';
}

size_t fuzz_set_separator(const uint8_t *data, size_t size) {
    static const char mark[] = "#--set";
    const size_t len = sizeof mark - 1;
    for (size_t i = 0; i + len <= size; i++)
        if ((i == 0 || data[i - 1] == '\n') && memcmp(data + i, mark, len) == 0 &&
            (i + len == size || data[i + len] == '\n'))
            return i;
    return size;
}

size_t fuzz_set_mutate(uint8_t *data, size_t size, size_t max_size, unsigned seed) {
    const size_t cut = fuzz_set_separator(data, size);
    int overrides = 0; /* the lines after the mark's (an upper bound: blank ones count) */
    for (size_t i = cut; i < size; i++) overrides += data[i] == '\n';
    if (cut < size && overrides > 0) overrides--;
    if (overrides >= MAX_OVERRIDES) return 0;
    char *text = malloc(cut + 1);
    if (!text) return 0;
    memcpy(text, data, cut);
    text[cut] = '\0';
    CfgDoc doc;
    size_t result = 0;
    if (strlen(text) == cut && cfg_doc_load_string(&doc, "case.yaml", text) == 0) {
        static const CfgNode *keys[MAX_KEYS];
        int count = 0;
        collect(doc.root, keys, &count);
        if (count > 0) {
            char path[512], line[700];
            /* the key and the value from two halves of a mixed seed, so
             * that consecutive seeds spread over both */
            uint64_t h = (uint64_t)seed * 0x9E3779B97F4A7C15u;
            h ^= h >> 29;
            h *= 0xBF58476D1CE4E5B9u;
            h ^= h >> 32;
            cfg_node_path(keys[(uint32_t)h % (unsigned)count], path, sizeof path);
            char set[512];
            dotted(path, set, sizeof set);
            const char *value = EXTREMES[(h >> 32) % EXTREME_COUNT];
            /* a separator line first when the input has none */
            const int len =
                snprintf(line, sizeof line, "%s%s%s=%s\n", cut == size ? "\n#--set\n" : "",
                         size > 0 && data[size - 1] != '\n' && cut < size ? "\n" : "", set, value);
            if (len > 0 && (size_t)len < sizeof line && size + (size_t)len <= max_size) {
                memcpy(data + size, line, (size_t)len);
                result = size + (size_t)len;
            }
        }
        cfg_doc_free(&doc);
    }
    nspd_error_clear(); /* a case part that did not parse is no finding */
    free(text);
    return result;
}
