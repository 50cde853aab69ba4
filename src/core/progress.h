/* Progress reporting for long runs.
 *
 * On a terminal: one live line (step, simulated time, percent, ETA) redrawn
 * at most 5 times a second. Otherwise (a pipe, a CI log): one plain line at
 * every 10 %. Silent when disabled. */
#ifndef NSPD_CORE_PROGRESS_H
#define NSPD_CORE_PROGRESS_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

typedef struct {
    FILE *stream;
    bool enabled, live;
    double end_time;       /* simulated end time, s */
    double start_fraction; /* of end_time done when this process started (a resumed run) */
    double wall_start, last_draw;
    int last_decile;
} Progress;

/* start_time: the simulated time this process starts from (0, or a
 * checkpoint's); the ETA is from this process's own rate. */
void progress_start(Progress *p, FILE *stream, double start_time, double end_time, bool enabled);
void progress_update(Progress *p, int64_t step, double time);
void progress_finish(Progress *p, int64_t step, double time);
/* "1h02m", "3m05s", "12.3s": writes into buf (at least 16 bytes). */
void progress_format_duration(double seconds, char *buf, int size);

#endif
