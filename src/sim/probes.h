/* Case-specific measurements taken during a run (sim_config.h ProbeConfig):
 * crack tip position, point displacements, and line samples. */
#ifndef NSPD_SIM_PROBES_H
#define NSPD_SIM_PROBES_H

#include "sim/sim_config.h"
#include "solid/pd_body.h"

#include <stdio.h>

typedef struct {
    const ProbeConfig *cfg;
    int64_t point;    /* PROBE_POINT: index of the nearest material point */
    int64_t *members; /* PROBE_LINE: points inside the region, sorted */
    int64_t member_count;
    /* PROBE_CRACK_TIP history: position along `direction` at each sample */
    double *times, *along;
    int samples, capacity;
    double last_tip[3];
} ProbeState;

/* Sets up the probes of `cfg` on `body` (nearest points, line members,
 * history buffers for `max_samples` samples). */
int probes_create(ProbeState **probes, const OutputConfig *cfg, const PdBody *body,
                  int max_samples);
void probes_destroy(ProbeState **probes, int count);

/* True if some probe needs the damage field at every history sample. */
bool probes_need_damage(const OutputConfig *cfg);

/* Appends this probe set's column names to the CSV header line. */
void probes_write_header(const ProbeState *probes, int count, int dim, FILE *csv);
/* Samples every probe at the current state (damage: the current damage
 * field, or NULL if no probe needs it) and appends the values to the row. */
void probes_sample(ProbeState *probes, int count, const PdBody *body, const double *damage,
                   FILE *csv);
/* Writes line_<name>_<index>.csv files for the line probes. */
int probes_write_lines(const ProbeState *probes, int count, const PdBody *body,
                       const double *damage, const char *dir, int index);

/* Crack speed from the tip history: (s_end - s_start) / (t_end - t_start)
 * where t_start is the last sample before the tip first advanced and t_end
 * the first sample at which it reached its final position; 0 if it never
 * moved, NaN if never detected. */
double probe_crack_speed(const ProbeState *p);

#endif
