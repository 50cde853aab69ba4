/* A whole case as read from its YAML file: what to simulate (a solid now;
 * flow and coupling join later), for how long, and what to write. Filled by
 * io/case_read.c, consumed by sim_create(). Units SI. */
#ifndef NSPD_SIM_SIM_CONFIG_H
#define NSPD_SIM_SIM_CONFIG_H

#include "core/shape.h"
#include "solid/pd_config.h"

#include <stdbool.h>

typedef enum { PROBE_CRACK_TIP, PROBE_POINT, PROBE_LINE, PROBE_KIND_COUNT } ProbeKind;
extern const char *const PROBE_KIND_NAMES[PROBE_KIND_COUNT + 1];

enum { SIM_MAX_NAME = 64 };

typedef struct {
    ProbeKind kind;
    char name[SIM_MAX_NAME];
    /* crack_tip: the damaged point (damage > threshold) furthest along
     * `direction`, optionally only inside `region` */
    double direction[3];
    double damage_threshold;
    /* point: the material point nearest to `at` (reference configuration) */
    double at[3];
    /* line: the points inside `region`, sorted along axis `sort_axis` */
    ShapeSet region;
    int sort_axis;
} ProbeConfig;

typedef struct {
    double field_interval;   /* s between VTK/PNG outputs */
    double history_interval; /* s between history.csv rows */
    bool vtk, png;
    int png_max_pixels; /* longest side of a PNG */
    int probe_count;
    ProbeConfig *probes;
} OutputConfig;

typedef struct {
    char name[SIM_MAX_NAME];
    double end_time; /* s */
    double dt;       /* s; computed from the stable step when !dt_given */
    bool dt_given;
    double safety_factor; /* dt = safety_factor * stable step */
    bool has_solid;
    PdConfig solid;
    OutputConfig output;
} SimConfig;

void sim_config_free(SimConfig *cfg);

#endif
