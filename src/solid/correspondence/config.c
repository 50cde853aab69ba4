#include "solid/correspondence/config.h"

#include "core/mem.h"

#include <string.h>

const char *const CPD_FORCE_NAMES[CPD_FORCE_COUNT + 1] = {"bond_associated", "classic", NULL};
const char *const CPD_FRAME_NAMES[CPD_FRAME_COUNT + 1] = {"lagrangian", "semi_lagrangian", NULL};
const char *const CPD_FAMILY_NAMES[CPD_FAMILY_COUNT + 1] = {"square", "disc", NULL};
const char *const CPD_DAMAGE_NAMES[CPD_DAMAGE_COUNT + 1] = {"none", "ductile", "brittle", "stretch",
                                                            NULL};

double cpd_pressure_at(const CpdPressure *p, double t) {
    if (t <= 0.0) return 0.0;
    if (t < p->rise) return p->peak * t / p->rise;
    const double t_hold = t - p->rise;
    if (p->fall <= 0.0 || t_hold <= p->hold) return p->peak;
    const double t_fall = t_hold - p->hold;
    return t_fall < p->fall ? p->peak * (1.0 - t_fall / p->fall) : 0.0;
}

void cpd_config_free(CpdConfig *cfg) {
    pd_config_free(&cfg->pd);
    for (int i = 0; i < cfg->pressure_count; i++) shapeset_free(&cfg->pressures[i].region);
    nspd_free(&cfg->pressures);
    memset(cfg, 0, sizeof *cfg);
}
