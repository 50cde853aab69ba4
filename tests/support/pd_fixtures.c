#include "pd_fixtures.h"

#include "core/mem.h"

#include <stdlib.h>

PdConfig fixture_block(int dim, int nx, int ny, int nz, double dx) {
    PdConfig cfg = {0};
    cfg.model = dim == 3 ? PD_3D : PD_PLANE_STRESS;
    cfg.dim = dim;
    cfg.spacing = dx;
    cfg.thickness = dx;
    cfg.horizon_factor = 3.015;
    cfg.density = 8000;
    cfg.youngs_modulus = 192e9;
    cfg.volume_correction = PD_VOLUME_LINEAR;
    cfg.surface_correction = PD_SURFACE_ENERGY;
    cfg.integrator = PD_VELOCITY_VERLET;
    if (nspd_alloc(&cfg.geometry.shapes, 1, sizeof(Shape)) != 0) abort();
    cfg.geometry.count = 1;
    Shape *s = &cfg.geometry.shapes[0];
    s->kind = dim == 3 ? SHAPE_BOX : SHAPE_RECTANGLE;
    s->hi[0] = nx * dx;
    s->hi[1] = ny * dx;
    s->hi[2] = dim == 3 ? nz * dx : 0.0;
    return cfg;
}
