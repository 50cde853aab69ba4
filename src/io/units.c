#include "io/units.h"

#include <stdio.h>
#include <string.h>

/* Longest suffixes first: "_kg_per_m3" before "_m3", "_m_per_s" before "_s". */
static const char *const SUFFIX[][2] = {{"_kg_per_m3", "kg/m³"},
                                        {"_m_per_s", "m/s"},
                                        {"_kg_per_m", "kg/m"},
                                        {"_kg_per_s", "kg/s"},
                                        {"_J_per_m", "J/m"},
                                        {"_N_per_m", "N/m"},
                                        {"_per_s", "1/s"},
                                        {"_deg", "°"},
                                        {"_mb", "MB"},
                                        {"_Pa", "Pa"},
                                        {"_J", "J"},
                                        {"_K", "K"},
                                        {"_s", "s"},
                                        {"_m", "m"}};

static int suffix_of(const char *key) {
    const size_t len = strlen(key);
    for (size_t k = 0; k < sizeof SUFFIX / sizeof SUFFIX[0]; k++) {
        const size_t l = strlen(SUFFIX[k][0]);
        if (len > l && strcmp(key + len - l, SUFFIX[k][0]) == 0) return (int)k;
    }
    return -1;
}

const char *units_of_key(const char *key) {
    const int k = suffix_of(key);
    return k < 0 ? "" : SUFFIX[k][1];
}

void units_strip(const char *key, char *buf, size_t size) {
    const int k = suffix_of(key);
    const size_t keep = strlen(key) - (k < 0 ? 0 : strlen(SUFFIX[k][0]));
    snprintf(buf, size, "%.*s", (int)keep, key);
}
