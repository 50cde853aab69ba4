/* Plots of a run's history.csv: every column (or the ones named) against
 * time, one picture each, DIR/history_<column>.png (and .svg): labelled
 * axes with units (io/units.h), the case name in the title
 * (io/figure.h draws them). Written at the end of a run (output.plots) and
 * by `nspd plot`. */
#ifndef NSPD_IO_HISTORY_PLOT_H
#define NSPD_IO_HISTORY_PLOT_H

#include <stdbool.h>

/* Plots the columns of dir/history.csv named in columns[0..count) (count 0:
 * every column but step and time_s). NSPD_ERR_INPUT for a missing or
 * malformed history or an unknown column (naming the ones there);
 * NSPD_ERR_IO when a picture cannot be written. *written: pictures made. */
int history_plots(const char *dir, const char *case_name, char *const *columns, int count, bool svg,
                  int *written);

#endif
