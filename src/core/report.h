/* Named values a model reports: the columns of a history row, the keys of
 * summary.json. Models fill a Report; only the generic writers
 * (io/run_files.c) turn it into text, so a model never formats or opens a
 * file and a new model needs no edit in them.
 *
 * A Report is a fixed-capacity value (no allocation; about 140 kB, so keep
 * it on the heap): REPORT_MAX_ITEMS items of REPORT_MAX_NAME characters.
 * The number of items follows the case (seven per immersed body, a few per
 * probe), so adding past the capacity is not a crash: the item is dropped,
 * `overflow` is set and the writers refuse the report with NSPD_ERR_INPUT. */
#ifndef NSPD_CORE_REPORT_H
#define NSPD_CORE_REPORT_H

#include <stdbool.h>
#include <stdint.h>

enum { REPORT_MAX_ITEMS = 1024, REPORT_MAX_NAME = 96 };

typedef enum {
    REPORT_REAL,    /* history: %.9g; summary: a JSON number */
    REPORT_PRECISE, /* history: %.12g (conserved totals, where the 10th digit matters) */
    REPORT_INT,     /* an integer count */
    REPORT_BOOL,    /* summary only */
    REPORT_TEXT,    /* summary only: a string */
} ReportKind;

typedef struct {
    char name[REPORT_MAX_NAME];
    ReportKind kind;
    double real;
    int64_t count;    /* REPORT_INT; REPORT_BOOL as 0/1 */
    const char *text; /* REPORT_TEXT: borrowed, must outlive the report's use */
} ReportItem;

typedef struct {
    int n;
    bool overflow; /* an item was dropped: more than REPORT_MAX_ITEMS */
    ReportItem item[REPORT_MAX_ITEMS];
} Report;

/* What the run knows that a model's summary needs. */
typedef struct {
    int64_t steps; /* steps of the driver (the flow's, when it sets the pace) */
    double wall_s; /* wall time of the run */
} RunStats;

void report_clear(Report *r);
void report_real(Report *r, const char *name, double value);
void report_precise(Report *r, const char *name, double value);
void report_int(Report *r, const char *name, int64_t value);
void report_bool(Report *r, const char *name, bool value);
void report_text(Report *r, const char *name, const char *value);
/* The item called `name`, NULL if none. */
const ReportItem *report_find(const Report *r, const char *name);
/* printf-style name: report_realf(r, v, "%s_cd", body). */
void report_realf(Report *r, double value, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

#endif
