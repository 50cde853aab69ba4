#include "sim/sim_config.h"

#include "core/mem.h"

#include <string.h>

const char *const PROBE_KIND_NAMES[PROBE_KIND_COUNT + 1] = {"crack_tip", "point", "line",
                                                            "branches", NULL};

void flow_case_config_free(FlowCaseConfig *flow) {
    ibm_body_set_free(&flow->bodies);
    for (int i = 0; i < flow->region_count; i++) shapeset_free(&flow->regions[i].shapes);
    nspd_free(&flow->regions);
    flow->region_count = 0;
    flow_field_source_free(&flow->field);
    flow->has_field = false;
}

void sim_config_free(SimConfig *cfg) {
    if (cfg->has_solid) pd_config_free(&cfg->solid);
    if (cfg->has_flow) flow_case_config_free(&cfg->flow);
    for (int i = 0; i < cfg->output.probe_count; i++) shapeset_free(&cfg->output.probes[i].region);
    nspd_free(&cfg->output.probes);
    memset(cfg, 0, sizeof *cfg);
}
