#include "iga_fixtures.h"

#include <math.h>

IgaConfig iga_fixture_strip(int nx) {
    return (IgaConfig){.lo = {0.0, 0.0},
                       .hi = {1.0, 2.0 / nx},
                       .elements = {nx, 2},
                       .degree = 2,
                       .side = {IGA_SIDE_SLIP, IGA_SIDE_SLIP, IGA_SIDE_SLIP, IGA_SIDE_SLIP},
                       .gamma = 1.4,
                       .R = 1.0,
                       .mu = 0.0,
                       .prandtl = 1.0,
                       .initial = {0.1, 0.0, 0.0, 0.8},
                       .init = IGA_INIT_NODAL,
                       .c_dc = 2.5,
                       .dc_cap = true,
                       .passes = 3,
                       .rho_inf = 0.5,
                       .db_iterations = 10,
                       .cfl = 0.3};
}

void iga_fixture_symmetry(IgaSolver *s, double *p_rel, double *uv_rel) {
    const int m = iga_solver_axis(s, 0)->count;
    const double *Y = iga_solver_values(s);
    double worst = 0.0, scale = 0.0, vworst = 0.0, vscale = 0.0;
    for (int j = 0; j < m; j++)
        for (int i = 0; i < m; i++) {
            const double p = Y[4 * (i + m * j)];
            const double images[3] = {Y[4 * (j + m * i)], Y[4 * ((m - 1 - i) + m * j)],
                                      Y[4 * (i + m * (m - 1 - j))]};
            for (int k = 0; k < 3; k++) worst = fmax(worst, fabs(p - images[k]));
            scale = fmax(scale, fabs(p));
            /* u and v swap under x <-> y */
            vworst = fmax(vworst, fabs(Y[4 * (i + m * j) + 1] - Y[4 * (j + m * i) + 2]));
            vscale = fmax(vscale, fabs(Y[4 * (i + m * j) + 1]));
        }
    *p_rel = worst / scale;
    *uv_rel = vscale > 0.0 ? vworst / vscale : (double)INFINITY;
}
