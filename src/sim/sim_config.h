/* A whole case as read from its YAML file: what to simulate (a solid, a
 * flow, a coupling; each an interface's configuration: the model's kind
 * and an opaque pointer to the model's own), for how long, and what to
 * write. Filled by case/case_read.c, consumed by sim_create(). Units SI. */
#ifndef NSPD_SIM_SIM_CONFIG_H
#define NSPD_SIM_SIM_CONFIG_H

#include "core/shape.h"
#include "couple/coupling.h"
#include "flow/flow.h"
#include "solid/solid.h"

#include <stdbool.h>

typedef enum {
    PROBE_CRACK_TIP,
    PROBE_POINT,
    PROBE_LINE,
    PROBE_BRANCHES,
    PROBE_KIND_COUNT
} ProbeKind;
extern const char *const PROBE_KIND_NAMES[PROBE_KIND_COUNT + 1];

enum { SIM_MAX_NAME = 64 };

typedef enum { PROBE_ON_SOLID, PROBE_ON_FLOW } ProbeTarget;

typedef struct {
    ProbeKind kind;
    ProbeTarget target; /* point and line probes: the solid's points or the flow's cells */
    char name[SIM_MAX_NAME];
    /* "FILE:LINE:COL: output.probes[i].at" (or the --set) of the probe's
     * point (its entry when it has none), for messages about it found when
     * the model is built */
    char where[400];
    /* crack_tip: the damaged point (damage > threshold) furthest along
     * `direction`, optionally only inside `region`; branches: the damaged
     * points ahead of `at` along `direction` (sim/probes.c) */
    double direction[3];
    double damage_threshold;
    double length; /* branches: how far ahead of `at` to look, m (0: no limit) */
    /* branches: the measurement is kept from the first history sample at
     * which the branches span `extent` along `direction` (m; 0: measured at
     * the end of the run only) */
    double extent;
    /* point: the material point nearest to `at` (reference configuration),
     * or the flow cell containing it */
    double at[3];
    /* line: the points inside `region`, sorted along axis `sort_axis`; on the
     * flow, the row (sort_axis x) or column (y) of cells through `at` */
    ShapeSet region;
    int sort_axis;
} ProbeConfig;

typedef struct {
    double field_interval;   /* s between VTK/PNG outputs */
    double average_from;     /* s: force coefficients are averaged from this time on */
    double history_interval; /* s between history.csv rows */
    /* checkpoints: s of simulated time between them (0: none), s of wall
     * time between them (0: none); one is also written when the run is
     * interrupted (Ctrl-C, SIGTERM, SIGUSR1) */
    double checkpoint_interval, checkpoint_wall_interval;
    bool vtk, png;
    bool plots; /* history_<column>.png of every history column at the end (io/history_plot.h) */
    int png_max_pixels; /* longest side of a PNG */
    /* output.mach_range: the Mach pictures' colour scale [lo, hi] for the
     * whole series, when given; else each flow fixes it from its data
     * (flow_mach_picture_top) */
    bool mach_range_given;
    double mach_range[2];
    int probe_count;
    ProbeConfig *probes;
} OutputConfig;

typedef struct {
    char name[SIM_MAX_NAME];
    double end_time; /* s */
    /* "FILE:LINE:COL" (or the --set) of time.end, for messages about it */
    char end_time_at[320];
    double dt; /* s; computed from the stable step when !dt_given */
    bool dt_given;
    double safety_factor;    /* dt = safety_factor * stable step */
    SolidConfig solid;       /* kind SOLID_NONE: the case has no solid */
    FlowConfig flow;         /* method FLOW_METHOD_NONE: no flow */
    CouplingConfig coupling; /* kind COUPLING_NONE: nothing couples (a flow's fixed
                                bodies are a coupling with rigid walls) */
    OutputConfig output;
    /* nspd info's estimate: how many times the solid's cost per sub-step
     * may grow over the run once it yields and breaks (the case reader's,
     * measured: docs/PERFORMANCE.md "nspd info's estimate"); 1: it stays */
    double solid_cost_growth;
    double max_memory_bytes; /* the estimate's limit (--max-memory); 0: this machine's memory */
    bool check_only;         /* `nspd check`: models validate, skip costly setup; never stepped */
    /* the processes the run shares (size 0 or 1: this one alone): every
     * rank builds and steps the same case; the flow is divided between
     * them, rank 0 writes the outputs (sim.h) */
    NspdComm comm;
    /* `--processes PXxPY`: the flow's process grid (flow.h); 0: its own */
    int processes[2];
} SimConfig;

void sim_config_free(SimConfig *cfg);

#endif
