#include "pd_fixtures.h"

#include "core/mem.h"

#include <math.h>
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

double fixture_closest_unbonded(int64_t n, int dim, const double *const x[3],
                                const double *const u[3], double reference) {
    double best = INFINITY;
    for (int64_t i = 0; i < n; i++)
        for (int64_t j = i + 1; j < n; j++) {
            double d2 = 0.0, xi2 = 0.0;
            for (int d = 0; d < dim; d++) {
                const double xi = x[d][j] - x[d][i], dy = xi + u[d][j] - u[d][i];
                d2 += dy * dy;
                xi2 += xi * xi;
            }
            if (xi2 > reference * reference) best = fmin(best, d2);
        }
    return sqrt(best);
}
