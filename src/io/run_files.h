/* The files of a run's directory, written from what the models report
 * (core/report.h, core/fields.h) without knowing the models:
 *   history.csv        one Report per row; the header from the first row's names
 *   summary.json       one Report
 *   <series>_NNNNN.vtu/.vtr + <series>.pvd, <picture>_NNNNN.png,
 *   <table>_NNNNN.csv  from a FieldSet */
#ifndef NSPD_IO_RUN_FILES_H
#define NSPD_IO_RUN_FILES_H

#include "core/fields.h"
#include "core/report.h"
#include "io/vtk.h"

#include <stdbool.h>
#include <stdio.h>

typedef struct {
    FILE *file;
    bool header_written;
    char path[4096];
} HistoryFile;

/* Creates dir/history.csv (NSPD_ERR_IO with the reason if it cannot). */
int history_open(HistoryFile *h, const char *dir);
/* Appends one row: the first call writes the header (the items' names). */
int history_write(HistoryFile *h, const Report *row);
void history_close(HistoryFile *h);
/* Reopens dir/history.csv to continue a run from a checkpoint: cut back to
 * the `bytes` it had then (rows written after it are written again), then
 * appended to. NSPD_ERR_INPUT if it is missing or shorter. */
int history_resume(HistoryFile *h, const char *dir, int64_t bytes);
/* Flushes the file and gives its length (0 when none is open). */
int history_bytes(HistoryFile *h, int64_t *bytes);

/* Writes dir/summary.json with the items in order. */
int summary_write(const char *dir, const Report *summary);

typedef struct {
    bool vtk, png;
    int png_max_pixels;
    const char *case_name; /* the pictures' titles begin with it (NULL: none) */
} FieldOutputOptions;

/* Writes the files of one output (index) of a field set at time t:
 * its VTK file (added to *pvd; of a set in pieces, the .pvtr or .pvtu
 * that names them), its pictures (titled "case - field - t = ...")
 * and its tables. `overlay`
 * (NULL: none) is the points mesh drawn on the pictures that ask for it;
 * a `coupled_only` picture is drawn only with one. */
int field_set_write(const char *dir, int index, double t, const FieldSet *fs,
                    const FieldSet *overlay, const FieldOutputOptions *opt, PvdSeries *pvd);
/* A set in pieces (fs->piece.count > 1): this process's piece of output
 * `index`, <series>_NNNNN_pPPPP.vtr or .vtu, which every process of the
 * set writes (nothing otherwise, or without VTK output). */
int field_set_write_piece(const char *dir, int index, const FieldSet *fs,
                          const FieldOutputOptions *opt);

/* Writes dir/<table.file>_NNNNN.csv (see TableRef). */
int table_write(const char *dir, int index, double t, const TableRef *table);

#endif
