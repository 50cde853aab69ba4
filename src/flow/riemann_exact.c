/* Exact Riemann solver (Toro ch. 4). f_K(p) is the velocity change across
 * the wave of side K: a shock (p > p_K, Rankine-Hugoniot) or a rarefaction
 * (p <= p_K, isentropic). */
#include "flow/riemann_exact.h"

#include "core/status.h"

#include <math.h>

static void wave_function(double p, const RiemannState *k, double g, double *f, double *df) {
    const double c = sqrt(g * k->p / k->rho);
    if (p > k->p) {
        const double A = 2.0 / ((g + 1.0) * k->rho), B = (g - 1.0) / (g + 1.0) * k->p;
        const double q = sqrt(A / (p + B));
        *f = (p - k->p) * q;
        *df = q * (1.0 - 0.5 * (p - k->p) / (B + p));
    } else {
        const double pr = p / k->p;
        *f = 2.0 * c / (g - 1.0) * (pow(pr, (g - 1.0) / (2.0 * g)) - 1.0);
        *df = 1.0 / (k->rho * c) * pow(pr, -(g + 1.0) / (2.0 * g));
    }
}

int riemann_exact_solve(const RiemannState *l, const RiemannState *r, double g,
                        RiemannSolution *out) {
    if (!(l->rho > 0 && r->rho > 0 && l->p > 0 && r->p > 0 && g > 1.0))
        return NSPD_FAIL(NSPD_ERR_INPUT, "riemann: states need rho > 0, p > 0, gamma > 1");
    const double cl = sqrt(g * l->p / l->rho), cr = sqrt(g * r->p / r->rho);
    const double du = r->u - l->u;
    if (2.0 * (cl + cr) / (g - 1.0) <= du)
        return NSPD_FAIL(NSPD_ERR_INPUT, "riemann: the data generate vacuum");
    /* two-rarefaction guess, then Newton */
    const double z = (g - 1.0) / (2.0 * g);
    double p =
        pow((cl + cr - 0.5 * (g - 1.0) * du) / (cl / pow(l->p, z) + cr / pow(r->p, z)), 1.0 / z);
    if (!(p > 0.0)) p = 1e-8 * fmin(l->p, r->p);
    for (int it = 0; it < 100; it++) {
        double fl, dfl, fr, dfr;
        wave_function(p, l, g, &fl, &dfl);
        wave_function(p, r, g, &fr, &dfr);
        double pn = p - (fl + fr + du) / (dfl + dfr);
        if (pn < 1e-12 * p) pn = 1e-12 * p;
        const double change = 2.0 * fabs(pn - p) / (pn + p);
        p = pn;
        if (change < 1e-15) break;
    }
    double fl, dfl, fr, dfr;
    wave_function(p, l, g, &fl, &dfl);
    wave_function(p, r, g, &fr, &dfr);
    out->left = *l;
    out->right = *r;
    out->gamma = g;
    out->p_star = p;
    out->u_star = 0.5 * (l->u + r->u) + 0.5 * (fr - fl);
    const double gr = (g - 1.0) / (g + 1.0);
    out->rho_star_left = p > l->p ? l->rho * (p / l->p + gr) / (gr * p / l->p + 1.0)
                                  : l->rho * pow(p / l->p, 1.0 / g);
    out->rho_star_right = p > r->p ? r->rho * (p / r->p + gr) / (gr * p / r->p + 1.0)
                                   : r->rho * pow(p / r->p, 1.0 / g);
    return NSPD_OK;
}

void riemann_exact_sample(const RiemannSolution *sol, double s, RiemannState *out) {
    const double g = sol->gamma, ps = sol->p_star, us = sol->u_star;
    /* Sample in the frame where the side of interest is the left: mirror the
     * right side (x -> -x, u -> -u). */
    const int left = s <= us;
    RiemannState k = left ? sol->left : sol->right;
    const double sign = left ? 1.0 : -1.0;
    const double ss = sign * s, uk = sign * k.u, ust = sign * us;
    const double rs = left ? sol->rho_star_left : sol->rho_star_right;
    const double c = sqrt(g * k.p / k.rho);
    RiemannState q;
    if (ps > k.p) { /* shock */
        const double speed =
            uk - c * sqrt((g + 1.0) / (2.0 * g) * ps / k.p + (g - 1.0) / (2.0 * g));
        if (ss <= speed)
            q = (RiemannState){k.rho, uk, k.p};
        else
            q = (RiemannState){rs, ust, ps};
    } else { /* rarefaction */
        const double head = uk - c, cs = c * pow(ps / k.p, (g - 1.0) / (2.0 * g)), tail = ust - cs;
        if (ss <= head) {
            q = (RiemannState){k.rho, uk, k.p};
        } else if (ss >= tail) {
            q = (RiemannState){rs, ust, ps};
        } else {
            const double f = 2.0 / (g + 1.0) + (g - 1.0) / ((g + 1.0) * c) * (uk - ss);
            q.rho = k.rho * pow(f, 2.0 / (g - 1.0));
            q.u = 2.0 / (g + 1.0) * (c + 0.5 * (g - 1.0) * uk + ss);
            q.p = k.p * pow(f, 2.0 * g / (g - 1.0));
        }
    }
    q.u *= sign;
    *out = q;
}

void riemann_exact_average(const RiemannSolution *sol, double x0, double t, double a, double b,
                           int sub, double cons[3]) {
    if (sub < 2) sub = 2;
    if (sub % 2) sub++;
    const double h = (b - a) / sub, g = sol->gamma;
    cons[0] = cons[1] = cons[2] = 0.0;
    for (int k = 0; k <= sub; k++) {
        const double w = (k == 0 || k == sub) ? 1.0 : (k % 2 ? 4.0 : 2.0);
        RiemannState q;
        riemann_exact_sample(sol, (a + k * h - x0) / t, &q);
        cons[0] += w * q.rho;
        cons[1] += w * q.rho * q.u;
        cons[2] += w * (q.p / (g - 1.0) + 0.5 * q.rho * q.u * q.u);
    }
    for (int v = 0; v < 3; v++) cons[v] *= h / (3.0 * (b - a));
}
