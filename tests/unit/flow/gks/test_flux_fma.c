/* The fused GKS flux against its unfused reference (NSPD_FMA, core/kernel.h).
 * ctest-sources: flux_unfused.c */
#include "test_support.h"

#include "flow/gks/bc.h"
#include "flow/gks/flux.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>

void flux_unfused(const double wl[4], const double nl[4], const double tl[4], const double wr[4],
                  const double nr[4], const double tr[4], const double n0[4], const double t0[4],
                  double dt, const GksParams *par, double f[4]);

static const double GAMMA = 1.4, RGAS = 287.0;

static uint64_t seed = 0x9e3779b97f4a7c15u;
static double uniform(double lo, double hi) { /* xorshift64*, [lo, hi) */
    seed ^= seed >> 12, seed ^= seed << 25, seed ^= seed >> 27;
    return lo + (hi - lo) * (double)((seed * 0x2545f4914f6cdd1du) >> 11) * 0x1p-53;
}

static void random_state(double w[4], double *c) {
    const FlowPrim q = {uniform(0.2, 3.0), uniform(-400.0, 400.0), uniform(-400.0, 400.0),
                        uniform(2e4, 3e5)};
    flow_prim_to_cons(&q, GAMMA, w);
    *c = sqrt(GAMMA * q.p / q.rho);
}

static void random_slope(const double w[4], double s[4]) { /* up to 100 W per metre */
    for (int v = 0; v < 4; v++)
        s[v] = uniform(-100.0, 100.0) * (v == 0 || v == 3 ? w[v] : w[0] * 400.0);
}

/* Over random faces of every viscosity law, the fused flux's departure
 * from the unfused one, per component, in units of the component's scale
 * dt rho c^(1, 2, 2, 3) at the left state (so that a component near zero
 * by cancellation does not blow the ratio up). Both are roundings of the
 * same real number; the bound is the measured 3.0e-14 (20,000 faces, the
 * largest in the energy flux of strong jumps, where the flux is a
 * difference of terms some 100 times larger) with a margin of 3. */
static void test_fused_is_unfused_to_round_off(void **state) {
    (void)state;
    const ViscosityLaw laws[] = {VISCOSITY_NONE, VISCOSITY_CONSTANT, VISCOSITY_POWER,
                                 VISCOSITY_SUTHERLAND};
    double worst = 0.0, worst_rel = 0.0;
    int differ = 0, faces = 0;
    for (int l = 0; l < 4; l++) {
        GksParams p;
        gks_params_default(&p, GAMMA, RGAS);
        p.law = laws[l];
        p.mu_ref = 1.8e-5;
        p.T_ref = 273.15;
        p.omega = 0.76;
        p.sutherland_S = 110.4;
        p.prandtl = 0.72;
        for (int k = 0; k < 5000; k++, faces++) {
            double wl[4], wr[4], nl[4], nr[4], tl[4], tr[4], n0[4], t0[4], cl, cr, f[4], g[4];
            random_state(wl, &cl);
            random_state(wr, &cr);
            random_slope(wl, nl), random_slope(wr, nr);
            random_slope(wl, tl), random_slope(wr, tr);
            random_slope(wl, n0), random_slope(wr, t0);
            const double dt = 0.5e-3 / (fabs(wl[1] / wl[0]) + cl + 400.0) * uniform(0.1, 1.0);
            gks_flux_face(wl, nl, tl, wr, nr, tr, n0, t0, dt, &p, f);
            flux_unfused(wl, nl, tl, wr, nr, tr, n0, t0, dt, &p, g);
            const double scale[4] = {dt * wl[0] * cl, dt * wl[0] * cl * cl, dt * wl[0] * cl * cl,
                                     dt * wl[0] * cl * cl * cl};
            int same = 1;
            for (int v = 0; v < 4; v++) {
                assert_true(isfinite(f[v]) && isfinite(g[v]));
                const double e = fabs(f[v] - g[v]) / scale[v];
                worst = e > worst ? e : worst;
                if (fabs(f[v]) > 0.1 * scale[v]) {
                    const double r = fabs(f[v] - g[v]) / fabs(f[v]);
                    worst_rel = r > worst_rel ? r : worst_rel;
                }
                same &= f[v] == g[v];
            }
            differ += !same;
        }
    }
    printf("fused against unfused, %d faces (%d differ): at most %.2e of the component's scale, "
           "%.2e of the flux where it exceeds a tenth of the scale\n",
           faces, differ, worst, worst_rel);
#if defined(FP_FAST_FMA)
    assert_true(differ > faces / 2); /* the fused kernel is in use, so it must differ */
#endif
    assert_true(worst < 1e-13);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_fused_is_unfused_to_round_off),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
