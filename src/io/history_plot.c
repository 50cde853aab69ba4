#include "io/history_plot.h"

#include "core/mem.h"
#include "core/status.h"
#include "io/figure.h"
#include "io/units.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_COLUMNS = 1024, MAX_LINE = 1 << 16 };

typedef struct {
    int ncol;
    char *names[MAX_COLUMNS];
    int64_t rows, cap;
    double *values; /* rows x ncol */
} History;

static void history_free(History *h) {
    for (int c = 0; c < h->ncol; c++) free(h->names[c]);
    nspd_free(&h->values);
    memset(h, 0, sizeof *h);
}

/* Reads the header and every whole row ("nan" and empty cells as NaN). */
static int history_read(const char *path, History *h) {
    memset(h, 0, sizeof *h);
    FILE *f = fopen(path, "r");
    if (!f) return NSPD_FAIL(NSPD_ERR_INPUT, "cannot read '%s' (%s)", path, strerror(errno));
    char *line = malloc(MAX_LINE);
    int status = line ? NSPD_OK : NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
    if (status == NSPD_OK && !fgets(line, MAX_LINE, f))
        status = NSPD_FAIL(NSPD_ERR_INPUT, "'%s' is empty", path);
    if (status == NSPD_OK) {
        line[strcspn(line, "\r\n")] = '\0';
        for (char *tok = strtok(line, ","); tok && status == NSPD_OK; tok = strtok(NULL, ",")) {
            if (h->ncol == MAX_COLUMNS) {
                status =
                    NSPD_FAIL(NSPD_ERR_INPUT, "'%s' has more than %d columns", path, MAX_COLUMNS);
                break;
            }
            h->names[h->ncol] = strdup(tok);
            if (!h->names[h->ncol++]) status = NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
        }
    }
    while (status == NSPD_OK && fgets(line, MAX_LINE, f)) {
        if (!strchr(line, '\n')) break; /* a row cut short (a run killed while writing it) */
        if (h->rows == h->cap) {
            const int64_t cap = h->cap ? 2 * h->cap : 256;
            status = nspd_realloc(&h->values, (size_t)(h->cap * h->ncol), (size_t)(cap * h->ncol),
                                  sizeof(double));
            if (status != NSPD_OK) break;
            h->cap = cap;
        }
        double *row = h->values + h->rows * h->ncol;
        char *p = line;
        for (int c = 0; c < h->ncol; c++) {
            char *end;
            row[c] = strtod(p, &end);
            if (end == p) row[c] = (double)NAN;
            p = strchr(end, ',');
            if (!p) {
                for (int k = c + 1; k < h->ncol; k++) row[k] = (double)NAN;
                break;
            }
            p++;
        }
        h->rows++;
    }
    free(line);
    fclose(f);
    if (status != NSPD_OK) history_free(h);
    return status;
}

static int column_of(const History *h, const char *name) {
    for (int c = 0; c < h->ncol; c++)
        if (strcmp(h->names[c], name) == 0) return c;
    return -1;
}

static int plot_column(const char *dir, const char *case_name, const History *h, int c, int tc,
                       bool svg, double *x, double *y) {
    for (int64_t r = 0; r < h->rows; r++) {
        x[r] = h->values[r * h->ncol + tc];
        y[r] = h->values[r * h->ncol + c];
    }
    char label[256], title[512], path[4096 + 300];
    units_strip(h->names[c], label, sizeof label);
    snprintf(title, sizeof title, "%s - %s", case_name ? case_name : "", label);
    const FigureLine line = {.title = title,
                             .x_label = "time",
                             .y_label = label,
                             .y_units = units_of_key(h->names[c]),
                             .n = h->rows,
                             .x = x,
                             .y = y};
    snprintf(path, sizeof path, "%.4000s/history_%.250s.png", dir, h->names[c]);
    TRY(figure_write_line_plot(path, &line, false));
    if (!svg) return NSPD_OK;
    snprintf(path, sizeof path, "%.4000s/history_%.250s.svg", dir, h->names[c]);
    return figure_write_line_plot(path, &line, true);
}

int history_plots(const char *dir, const char *case_name, char *const *columns, int count, bool svg,
                  int *written) {
    *written = 0;
    char path[4096 + 32];
    snprintf(path, sizeof path, "%.4000s/history.csv", dir);
    History h;
    TRY(history_read(path, &h));
    const int tc = column_of(&h, "time_s");
    int status = tc >= 0 ? NSPD_OK : NSPD_FAIL(NSPD_ERR_INPUT, "'%s' has no time_s column", path);
    for (int k = 0; k < count && status == NSPD_OK; k++)
        if (column_of(&h, columns[k]) < 0) {
            char names[2048] = "";
            for (int c = 0; c < h.ncol; c++)
                snprintf(names + strlen(names), sizeof names - strlen(names), "%s%s", c ? ", " : "",
                         h.names[c]);
            status = NSPD_FAIL(NSPD_ERR_INPUT, "'%s' has no column '%s'; expected one of: %s", path,
                               columns[k], names);
        }
    double *x = NULL, *y = NULL;
    if (status == NSPD_OK) status = nspd_alloc(&x, (size_t)h.rows + 1, sizeof *x);
    if (status == NSPD_OK) status = nspd_alloc(&y, (size_t)h.rows + 1, sizeof *y);
    for (int c = 0; c < h.ncol && status == NSPD_OK; c++) {
        bool wanted = count == 0 && c != tc && strcmp(h.names[c], "step") != 0;
        for (int k = 0; k < count; k++) wanted |= strcmp(h.names[c], columns[k]) == 0;
        if (!wanted) continue;
        status = plot_column(dir, case_name, &h, c, tc, svg, x, y);
        if (status == NSPD_OK) (*written)++;
    }
    nspd_free(&x);
    nspd_free(&y);
    history_free(&h);
    return status;
}
