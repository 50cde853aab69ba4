#include "core/report.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

void report_clear(Report *r) {
    r->n = 0;
    r->overflow = false;
}

static ReportItem *add(Report *r, const char *name, ReportKind kind) {
    static ReportItem dropped; /* written when full, never read */
    if (r->n >= REPORT_MAX_ITEMS) {
        r->overflow = true;
        return &dropped;
    }
    ReportItem *it = &r->item[r->n++];
    snprintf(it->name, sizeof it->name, "%s", name);
    it->kind = kind;
    it->real = 0.0;
    it->count = 0;
    it->text = "";
    return it;
}

void report_real(Report *r, const char *name, double value) {
    add(r, name, REPORT_REAL)->real = value;
}

void report_precise(Report *r, const char *name, double value) {
    add(r, name, REPORT_PRECISE)->real = value;
}

void report_int(Report *r, const char *name, int64_t value) {
    add(r, name, REPORT_INT)->count = value;
}

void report_bool(Report *r, const char *name, bool value) {
    add(r, name, REPORT_BOOL)->count = value;
}

void report_text(Report *r, const char *name, const char *value) {
    add(r, name, REPORT_TEXT)->text = value;
}

void report_realf(Report *r, double value, const char *fmt, ...) {
    char name[REPORT_MAX_NAME];
    va_list ap;
    va_start(ap, fmt);
    /* va_start above; clang-tidy 14 false positive in multi-file runs (llvm-project#40656)
     * NOLINTNEXTLINE(clang-analyzer-valist.Uninitialized) */
    vsnprintf(name, sizeof name, fmt, ap);
    va_end(ap);
    report_real(r, name, value);
}

const ReportItem *report_find(const Report *r, const char *name) {
    for (int k = 0; k < r->n; k++)
        if (strcmp(r->item[k].name, name) == 0) return &r->item[k];
    return NULL;
}
