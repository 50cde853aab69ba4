#include "flow/sedov.h"

#include <math.h>

/* The similarity ODEs for eta = r / r_s, u = r_s' U(eta), rho = rho0
 * G(eta), p = rho0 r_s'^2 P(eta), delta = 2 / (nu + 2) (mass, momentum and
 * entropy along particle paths), solved for (U', G', P'):
 *   G U' + (U - eta) G' = -(nu - 1) U G / eta
 *   (U - eta) U' + P' / G = -(1 - 1/delta) U
 *   (U - eta) (P'/P - gamma G'/G) = -2 (1 - 1/delta) */
static void slopes(int nu, double gamma, double eta, const double y[3], double dy[3]) {
    const double d = 2.0 / (nu + 2.0), U = y[0], G = y[1], P = y[2], W = U - eta;
    const double a = -(nu - 1) * U * G / eta, b = -(1.0 - 1.0 / d) * U, c = -2.0 * (1.0 - 1.0 / d);
    const double Gp = (b - W * a / G - P * c / (W * G)) / (gamma * P / (G * G) - W * W / G);
    dy[0] = (a - W * Gp) / G;
    dy[1] = Gp;
    dy[2] = P * (c / W + gamma * Gp / G);
}

/* kinetic and internal energy density of the profiles times eta^(nu-1) */
static double energy_density(int nu, double gamma, double eta, const double y[3]) {
    return (0.5 * y[1] * y[0] * y[0] + y[2] / (gamma - 1.0)) * pow(eta, nu - 1);
}

double sedov_front_constant(int nu, double gamma) {
    /* strong-shock jumps at eta = 1; RK4 inwards to eta = 1/n (the
     * profiles' energy near the centre vanishes as eta^(nu)); the
     * trapezoidal energy integral. 20,000 steps: xi0 to 1e-7 (against
     * 200,000). */
    enum { STEPS = 20000 };
    double y[3] = {2.0 / (gamma + 1.0), (gamma + 1.0) / (gamma - 1.0), 2.0 / (gamma + 1.0)};
    const double h = -1.0 / STEPS;
    double eta = 1.0, J = 0.0;
    for (int s = 0; s < STEPS - 1; s++) {
        double k[4][3], t[3];
        const double f0 = energy_density(nu, gamma, eta, y);
        slopes(nu, gamma, eta, y, k[0]);
        for (int v = 0; v < 3; v++) t[v] = y[v] + 0.5 * h * k[0][v];
        slopes(nu, gamma, eta + 0.5 * h, t, k[1]);
        for (int v = 0; v < 3; v++) t[v] = y[v] + 0.5 * h * k[1][v];
        slopes(nu, gamma, eta + 0.5 * h, t, k[2]);
        for (int v = 0; v < 3; v++) t[v] = y[v] + h * k[2][v];
        slopes(nu, gamma, eta + h, t, k[3]);
        for (int v = 0; v < 3; v++)
            y[v] += h / 6.0 * (k[0][v] + 2.0 * k[1][v] + 2.0 * k[2][v] + k[3][v]);
        eta += h;
        J -= 0.5 * h * (f0 + energy_density(nu, gamma, eta, y));
    }
    /* E = sigma rho0 r_s'^2 r_s^nu J and r_s' = delta r_s / t */
    const double d = 2.0 / (nu + 2.0);
    const double sigma = nu == 1 ? 2.0 : nu == 2 ? 2.0 * M_PI : 4.0 * M_PI;
    return pow(1.0 / (d * d * sigma * J), 1.0 / (nu + 2.0));
}

double sedov_front_radius(int nu, double gamma, double energy, double rho0, double t) {
    return sedov_front_constant(nu, gamma) * pow(energy * t * t / rho0, 1.0 / (nu + 2.0));
}
