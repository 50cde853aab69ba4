#include "flow/vortex.h"

#include <math.h>

void flow_vortex_state(const FlowVortex *vx, double x, double y, double out[4]) {
    double dx = x - vx->x0, dy = y - vx->y0;
    if (vx->period_x > 0.0) dx -= vx->period_x * round(dx / vx->period_x);
    if (vx->period_y > 0.0) dy -= vx->period_y * round(dy / vx->period_y);
    const double r2 = dx * dx + dy * dy, g = vx->gamma, eps = vx->strength;
    const double f = exp(0.5 * (1.0 - r2)) * eps / (2.0 * M_PI);
    /* The formula is in units of the free stream (R T_inf = p_inf/rho_inf = 1,
     * velocities per sqrt(R T_inf)); scale back. */
    const double T_inf = vx->p_inf / vx->rho_inf;
    const double Tr = 1.0 - (g - 1.0) * eps * eps / (8.0 * g * M_PI * M_PI) * exp(1.0 - r2);
    const double scale = sqrt(T_inf);
    out[0] = vx->rho_inf * pow(Tr, 1.0 / (g - 1.0));
    out[1] = vx->u_inf - f * dy * scale;
    out[2] = vx->v_inf + f * dx * scale;
    out[3] = vx->p_inf * pow(Tr, g / (g - 1.0));
}
