/* An output file that is written whole or not at all: the bytes go to
 * "<path>.part" and out_file_close renames that to <path> only once every
 * byte was written and the file closed without error. A reader (ParaView
 * following a .pvd, a script polling a directory) therefore never sees a
 * truncated result under its real name, whatever stops the run: a full
 * disk, a quota, SIGKILL. On failure the partial file is removed and the
 * error gives the OS's reason ("No space left on device").
 *
 * history.csv is the one output that is not written this way: it grows by a
 * row per sample while the run goes on (io/run_files.h). */
#ifndef NSPD_CORE_OUT_FILE_H
#define NSPD_CORE_OUT_FILE_H

#include <stdio.h>

typedef struct {
    FILE *f;
    char path[4096];
    char part[4096 + 8];
} OutFile;

/* Creates <path>.part for writing (binary). NSPD_ERR_IO with the reason if
 * it cannot. */
int out_file_open(OutFile *o, const char *path);
/* Flushes and closes, then renames <path>.part to <path>. If anything
 * written since out_file_open failed (or `failed` is set by the caller's
 * own check), removes <path>.part and returns NSPD_ERR_IO naming <path> and
 * the OS's reason. */
int out_file_close(OutFile *o, int failed);
/* Closes and removes <path>.part (another error is being reported). */
void out_file_abort(OutFile *o);

#endif
