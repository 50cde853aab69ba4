/* The isentropic vortex (Yee et al. 1999), an exact solution of the Euler
 * equations that every compressible flow can start from and be measured
 * against: a free stream (rho_inf, u_inf, v_inf, p_inf) carrying a vortex
 * of strength `strength` centred at (x0, y0), with T = p/(rho R). With
 * R = 1, rho_inf = p_inf = 1:
 *   du = -eps/(2 pi) (y - y0) exp((1 - r^2)/2), dv = eps/(2 pi) (x - x0) exp((1 - r^2)/2),
 *   T = 1 - (gamma - 1) eps^2 / (8 gamma pi^2) exp(1 - r^2), rho = T^(1/(gamma-1)).
 * The general form scales T and rho by the free stream (isentropic).
 * Coordinates on a periodic box [lo, lo + period] take the nearest image
 * (period <= 0: none). */
#ifndef NSPD_FLOW_VORTEX_H
#define NSPD_FLOW_VORTEX_H

typedef struct {
    double x0, y0, strength, gamma;
    double rho_inf, u_inf, v_inf, p_inf;
    double period_x, period_y, lo_x, lo_y;
} FlowVortex;

/* The state at (x, y): out = (rho, u, v, p). */
void flow_vortex_state(const FlowVortex *vx, double x, double y, double out[4]);

#endif
