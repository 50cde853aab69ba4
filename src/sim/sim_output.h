/* What a run writes into its directory: history.csv, solid_NNNNN.vtu +
 * solid.pvd, damage_NNNNN.png, line probe CSVs and summary.json. Every
 * function is a no-op when the run has no directory. */
#ifndef NSPD_SIM_SIM_OUTPUT_H
#define NSPD_SIM_SIM_OUTPUT_H

#include "sim/sim.h"

int sim_output_open(Sim *sim);    /* history.csv and its header */
int sim_output_history(Sim *sim); /* one history row (and the probes) */
int sim_output_fields(Sim *sim);  /* VTK, PNG and line files of the current state */
/* summary.json; `status` is the run's outcome so far and `reason` its
 * message when it failed (written as "stopped_by") */
int sim_output_summary(Sim *sim, int status, const char *reason);
void sim_output_close(Sim *sim);

/* The history plots at the end of a run (output.plots), after history.csv
 * is closed. */
int sim_output_plots(Sim *sim);

#endif
