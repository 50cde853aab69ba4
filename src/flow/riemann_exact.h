/* Exact solution of the Riemann problem of the 1D Euler equations for an
 * ideal gas (Toro, "Riemann Solvers and Numerical Methods for Fluid
 * Dynamics", 3rd ed., ch. 4): star pressure by Newton iteration on
 * f_L(p) + f_R(p) + u_R - u_L = 0, then sampling of the self-similar
 * solution at x/t. For the shock-tube tests and validation plots. */
#ifndef NSPD_FLOW_RIEMANN_EXACT_H
#define NSPD_FLOW_RIEMANN_EXACT_H

typedef struct {
    double rho, u, p;
} RiemannState;

typedef struct {
    RiemannState left, right;
    double gamma;
    double p_star, u_star;
    double rho_star_left, rho_star_right;
} RiemannSolution;

/* Solves the problem. NSPD_ERR_INPUT if a state is not physical or the data
 * generate vacuum (pressure positivity condition violated). */
int riemann_exact_solve(const RiemannState *left, const RiemannState *right, double gamma,
                        RiemannSolution *out);

/* The state at speed s = (x - x_diaphragm) / t. */
void riemann_exact_sample(const RiemannSolution *sol, double s, RiemannState *out);

/* The cell average over [x_lo, x_hi] at time t (> 0) of rho, rho u or the total energy
 * rho E: averaged by the composite Simpson rule on `sub` (even) intervals. */
void riemann_exact_average(const RiemannSolution *sol, double x_diaphragm, double t, double x_lo,
                           double x_hi, int sub, double cons[3]);

#endif
