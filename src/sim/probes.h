/* Case-specific measurements taken during a run (sim_config.h ProbeConfig):
 * crack tip position, point values and line samples, on the solid's points
 * or the flow's cells. */
#ifndef NSPD_SIM_PROBES_H
#define NSPD_SIM_PROBES_H

#include "core/checkpoint.h"
#include "core/fields.h"
#include "core/report.h"
#include "flow/flow.h"
#include "sim/sim_config.h"
#include "solid/solid.h"

/* Crack branching ahead of probe->at along probe->direction, measured on the
 * damage field (PROBE_BRANCHES). Points with damage above the threshold and
 * below 0.99 (detached debris is not a crack face), with
 * s = (x - at).direction in (0, length], are binned by s in bins of one
 * spacing; in each bin the damaged points split into clusters across the
 * direction wherever neighbours are more than two spacings apart. The crack
 * has branched where three successive bins hold two or more clusters; from
 * there on, lines n = a + b s are fitted by least squares to the outermost
 * cluster centroids on each side, and the branch angle is the angle between
 * them. Reference positions are used (the crack path, not its opening). */
typedef struct {
    bool branched;
    double angle_deg;            /* between the two branches */
    double upper_deg, lower_deg; /* each branch against `direction` (+ to its left) */
    double point[2];             /* where the two fitted lines meet, m */
    int samples;                 /* bins used in the fits */
    double span;                 /* samples x spacing: how far along `direction` they reach, m */
} BranchResult;

typedef struct {
    const ProbeConfig *cfg;
    int64_t point;    /* PROBE_POINT: the nearest material point, the flow cell (grid index) or
                         the flow's probe handle (flow_probe_add) */
    int64_t *members; /* PROBE_LINE: points inside the region sorted, or the cells of the line */
    int64_t member_count;
    /* PROBE_CRACK_TIP history: position along `direction` at each sample */
    double *times, *along;
    int samples, capacity;
    double last_tip[3];
    /* PROBE_POINT on the solid: the largest displacement along x and when */
    double dx_max, t_dx_max;
    /* PROBE_BRANCHES: the first measurement whose branches span `extent`,
     * and its time (NaN until then) */
    BranchResult first_branch;
    double t_first_branch;
    /* PROBE_LINE: the table written at each field output */
    TableRef table;
    char table_file[SIM_MAX_NAME + 8];
    char table_header[160];
    double *table_data;                       /* ncol x member_count */
    double *table_columns[TABLE_MAX_COLUMNS]; /* into table_data */
} ProbeState;

/* Sets up the probes of `cfg` on the solid and/or flow (either may be
 * NULL): nearest points, line members, history buffers for `max_samples`
 * samples; a point probe on a flow without a grid has the flow prepare
 * its interpolation (flow_probe_add: that much changes the flow).
 * NSPD_ERR_INPUT if a probe targets a part the case lacks, or finds
 * nothing. */
int probes_create(ProbeState **probes, const OutputConfig *cfg, const PdPoints *body, Flow *flow,
                  int max_samples);
void probes_destroy(ProbeState **probes, int count);

/* True if some probe needs the damage field at every history sample. */
bool probes_need_damage(const OutputConfig *cfg);

/* The branch measurement a run reports for a PROBE_BRANCHES probe: with
 * `extent` > 0, the first one that spanned `extent` (not branched if none
 * did); with `extent` 0, the measurement on `damage` now. *time is its time
 * (NaN for `now` and for none). */
int probe_branch_report(const ProbeState *p, const PdPoints *body, const double *damage,
                        BranchResult *out, double *time);

/* Samples every probe at the current state (damage: the current damage
 * field, or NULL if no probe needs it), keeps what the probes record (the
 * crack tip history) and appends the values to the history row. */
void probes_sample(ProbeState *probes, int count, const PdPoints *body, const double *damage,
                   const Flow *flow, double time, Report *row);
/* A line probe's table at the current state (line_<name>_NNNNN.csv), in
 * the probe's own storage; NULL for the other kinds. */
const TableRef *probe_line_table(ProbeState *p, const PdPoints *body, const double *damage,
                                 const Flow *flow);

int probe_branches(const ProbeConfig *c, const PdPoints *body, const double *damage,
                   BranchResult *out);

/* Crack speed from the tip history: (s_end - s_start) / (t_end - t_start)
 * where t_start is the last sample before the tip first advanced and t_end
 * the first sample at which it reached its final position; 0 if it never
 * moved, NaN if never detected. */
double probe_crack_speed(const ProbeState *p);

/* The time of the first sample at which the probe saw a damaged point (in
 * its region): where a crack starts, read against other regions' probes;
 * NaN if never. */
double probe_crack_onset(const ProbeState *p);

/* The probes' summary keys: per solid point probe its largest x
 * displacement and when; per branch probe its measurement, then the overall
 * branch angle; per crack tip probe its last position and speed. */
int probes_summary(ProbeState *probes, int count, const PdPoints *body, const double *damage,
                   Report *out);

/* Writes or reads what the probes carry between samples (core/checkpoint.h). */
int probes_checkpoint(ProbeState *probes, int count, Checkpoint *ck);

#endif
