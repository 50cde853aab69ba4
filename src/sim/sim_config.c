#include "sim/sim_config.h"

#include "core/mem.h"

#include <string.h>

const char *const PROBE_KIND_NAMES[PROBE_KIND_COUNT + 1] = {"crack_tip", "point", "line",
                                                            "branches", NULL};

void sim_config_free(SimConfig *cfg) {
    solid_config_free(&cfg->solid);
    flow_config_free(&cfg->flow);
    coupling_config_free(&cfg->coupling);
    for (int i = 0; i < cfg->output.probe_count; i++) shapeset_free(&cfg->output.probes[i].region);
    nspd_free(&cfg->output.probes);
    memset(cfg, 0, sizeof *cfg);
}
