/* The one-face BGK-NS flux: exact limits it must reproduce. */
#include "test_support.h"

#include "core/kernel.h"
#include "flow/gks/bc.h"
#include "flow/gks/flux.h"

#include <math.h>
#include <string.h>

static const double GAMMA = 1.4, RGAS = 287.0;

static GksParams viscous(double mu, double pr) {
    GksParams p;
    gks_params_default(&p, GAMMA, RGAS);
    p.law = mu > 0.0 ? VISCOSITY_CONSTANT : VISCOSITY_NONE;
    p.mu_ref = mu;
    p.prandtl = pr;
    return p;
}

static void euler_flux(const FlowPrim *q, double f[4]) {
    double w[4];
    flow_prim_to_cons(q, GAMMA, w);
    f[0] = q->rho * q->u;
    f[1] = q->rho * q->u * q->u + q->p;
    f[2] = q->rho * q->u * q->v;
    f[3] = (w[3] + q->p) * q->u;
}

/* A uniform state gives dt times the Euler flux, whatever tau and tau_n. */
static void test_uniform_state_is_euler(void **state) {
    (void)state;
    const FlowPrim qs[] = {
        {1.2, 0.0, 0.0, 1e5}, {1.2, 250.0, -40.0, 1e5}, {0.3, -700.0, 90.0, 4e4}};
    const double mus[] = {0.0, 1.8e-5, 0.5, 50.0}; /* tau/dt from 0 to >> 1 */
    const double zero[4] = {0, 0, 0, 0};
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 4; b++) {
            GksParams p = viscous(mus[b], 0.72);
            p.eps_dt = b == 2 ? 0.3 : 0.0;
            double w[4], f[4], e[4];
            flow_prim_to_cons(&qs[a], GAMMA, w);
            const double dt = 1e-6;
            gks_flux_face(w, zero, zero, w, zero, zero, zero, zero, dt, &p, f);
            euler_flux(&qs[a], e);
            const double scale = qs[a].p + qs[a].rho * qs[a].u * qs[a].u + fabs(e[3]);
            for (int n = 0; n < 4; n++) assert_close(f[n], e[n] * dt, 1e-14 * scale * dt);
        }
}

/* Mirror x -> -x: swapping the sides and negating normal velocities and
 * normal derivatives gives the mirrored flux (mass flux negated). */
static void mirror(const double w[4], double sign, double out[4]) {
    out[0] = sign * w[0];
    out[1] = -sign * w[1];
    out[2] = sign * w[2];
    out[3] = sign * w[3];
}

static void test_mirror_symmetry(void **state) {
    (void)state;
    GksParams p = viscous(2e-3, 0.72);
    const FlowPrim ql = {1.0, 120.0, 30.0, 1.0e5}, qr = {0.4, -60.0, 10.0, 0.3e5};
    double wl[4], wr[4];
    flow_prim_to_cons(&ql, GAMMA, wl);
    flow_prim_to_cons(&qr, GAMMA, wr);
    const double nl[4] = {3.0, 200.0, -50.0, 4e5}, nr[4] = {-1.0, 80.0, 20.0, -1e5};
    const double tl[4] = {0.5, 10.0, 70.0, 2e4}, tr[4] = {-0.2, -30.0, 40.0, 1e4};
    const double n0[4] = {-6.0, -400.0, 30.0, -7e5}, t0[4] = {0.1, 5.0, 60.0, 1e4};
    const double dt = 2e-6;
    double f[4], g[4];
    gks_flux_face(wl, nl, tl, wr, nr, tr, n0, t0, dt, &p, f);
    double mwl[4], mwr[4], mnl[4], mnr[4], mtl[4], mtr[4], mn0[4], mt0[4];
    mirror(wr, 1.0, mwl);
    mirror(wl, 1.0, mwr);
    mirror(nr, -1.0, mnl);
    mirror(nl, -1.0, mnr);
    mirror(tr, 1.0, mtl);
    mirror(tl, 1.0, mtr);
    mirror(n0, -1.0, mn0);
    mirror(t0, 1.0, mt0);
    gks_flux_face(mwl, mnl, mtl, mwr, mnr, mtr, mn0, mt0, dt, &p, g);
    for (int n = 0; n < 4; n++) assert_true(isfinite(f[n]));
    assert_close(g[0], -f[0], 1e-13 * fabs(f[0]) + 1e-18);
    assert_close(g[1], f[1], 1e-13 * fabs(f[1]));
    assert_close(g[2], -f[2], 1e-13 * fabs(f[2]) + 1e-18);
    assert_close(g[3], -f[3], 1e-13 * fabs(f[3]) + 1e-18);
}

/* Linear shear: the tangential-momentum flux is -mu dV/dn dt (V along the face,
 * varying along the normal), and -mu dU/dt_ dt for the normal velocity varying
 * along the face. Continuous data make the scheme's tau-terms sum to exactly
 * -tau dt (t1 + t4), so this holds to round-off at any tau/dt. */
static void test_linear_shear_is_newtonian(void **state) {
    (void)state;
    const double mu = 0.8, rho = 1.1, pr = 1e5, s = 3.0e3; /* 1/s */
    GksParams p = viscous(mu, 0.72);
    const FlowPrim q = {rho, 0.0, 0.0, pr};
    double w[4];
    flow_prim_to_cons(&q, GAMMA, w);
    const double zero[4] = {0, 0, 0, 0};
    const double dv[4] = {0.0, 0.0, rho * s, 0.0}; /* d(rho V)/dn */
    const double du[4] = {0.0, rho * s, 0.0, 0.0}; /* d(rho U)/dt_ */
    const double dts[] = {1e-7, 1e-5, 1e-3};
    for (int k = 0; k < 3; k++) {
        const double dt = dts[k];
        double f[4];
        gks_flux_face(w, dv, zero, w, dv, zero, dv, zero, dt, &p, f);
        assert_close(f[2], -mu * s * dt, 1e-12 * mu * s * dt);
        assert_close(f[0], 0.0, 1e-12 * rho * dt);
        assert_close(f[1], pr * dt, 1e-13 * pr * dt);
        gks_flux_face(w, zero, du, w, zero, du, zero, du, dt, &p, f);
        assert_close(f[2], -mu * s * dt, 1e-12 * mu * s * dt);
    }
}

/* Linear temperature at constant pressure and rest: the energy flux is
 * Fourier's -kappa dT/dn dt with kappa = c_p mu / Pr (the Prandtl fix). */
static void test_linear_temperature_is_fourier(void **state) {
    (void)state;
    const double mu = 0.3, pr = 1e5, T = 300.0, G = 2.0e3; /* K/m */
    const double prandtls[] = {1.0, 0.72, 2.0};
    for (int k = 0; k < 3; k++) {
        GksParams p = viscous(mu, prandtls[k]);
        const double rho = pr / (RGAS * T);
        const FlowPrim q = {rho, 0.0, 0.0, pr};
        double w[4];
        flow_prim_to_cons(&q, GAMMA, w);
        const double dw[4] = {-rho * G / T, 0.0, 0.0, 0.0}; /* rho E = p/(gamma-1) is uniform */
        const double zero[4] = {0, 0, 0, 0};
        const double cp = GAMMA * RGAS / (GAMMA - 1.0);
        for (double dt = 1e-7; dt < 1e-2; dt *= 100.0) {
            double f[4];
            gks_flux_face(w, dw, zero, w, dw, zero, dw, zero, dt, &p, f);
            const double fourier = -cp * mu / prandtls[k] * G * dt;
            assert_close(f[3], fourier, 1e-12 * fabs(fourier));
            assert_close(f[0], 0.0, 1e-12 * rho * dt);
        }
    }
}

/* The row loop gives the same bits as the single-face function. */
static void test_row_matches_face(void **state) {
    (void)state;
    enum { N = 37 };
    GksParams p = viscous(1e-3, 0.72);
    p.law = VISCOSITY_SUTHERLAND;
    p.mu_ref = 1.716e-5;
    p.T_ref = 273.15;
    p.sutherland_S = 110.4;
    double w[4][N + 1], sn[4][N + 1], st[4][N + 1], f[4][N];
    for (int i = 0; i <= N; i++) {
        const FlowPrim q = {1.0 + 0.1 * sin(i), 30.0 * cos(0.3 * i), 10.0 * sin(0.7 * i),
                            1e5 * (1.0 + 0.2 * cos(i))};
        double c[4];
        flow_prim_to_cons(&q, GAMMA, c);
        for (int v = 0; v < 4; v++) {
            w[v][i] = c[v];
            sn[v][i] = 0.01 * c[v] * sin(1.3 * i + v);
            st[v][i] = 0.02 * c[v] * cos(0.9 * i + v);
        }
    }
    uint8_t kind[N + 1];
    memset(kind, 0, sizeof kind);
    kind[5] = kind[6] = 1; /* face 5 (cells 5, 6) has no fluid cell */
    GksRowSide L, R;
    for (int v = 0; v < 4; v++) {
        L.w[v] = w[v], L.sn[v] = sn[v], L.st[v] = st[v];
        R.w[v] = w[v] + 1, R.sn[v] = sn[v] + 1, R.st[v] = st[v] + 1;
    }
    L.kind = kind, R.kind = kind + 1;
    double dl[N], dr[N], idc[N];
    for (int i = 0; i < N; i++)
        dl[i] = 0.01 * (1 + i % 3), dr[i] = 0.012, idc[i] = 1.0 / (dl[i] + dr[i]);
    double *fp[4] = {f[0], f[1], f[2], f[3]};
    const double dt = 1e-6;
    gks_flux_row_x(N, &L, &R, dl, dr, idc, dt, &p, fp);
    for (int i = 0; i < N; i++) {
        double wl[4], wr[4], nl[4], nr[4], tl[4], tr[4], n0[4], t0[4], g[4];
        for (int v = 0; v < 4; v++) {
            wl[v] = NSPD_FMA(sn[v][i], dl[i], w[v][i]); /* as the row reconstructs */
            wr[v] = NSPD_FMA(-sn[v][i + 1], dr[i], w[v][i + 1]);
            nl[v] = sn[v][i], nr[v] = sn[v][i + 1], tl[v] = st[v][i], tr[v] = st[v][i + 1];
            n0[v] = (w[v][i + 1] - w[v][i]) * idc[i];
            t0[v] = 0.5 * (tl[v] + tr[v]);
        }
        gks_flux_face(wl, nl, tl, wr, nr, tr, n0, t0, dt, &p, g);
        for (int v = 0; v < 4; v++) {
            if (i == 5)
                assert_true(f[v][i] == 0.0);
            else
                assert_true(f[v][i] == g[v]);
        }
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_uniform_state_is_euler),
        cmocka_unit_test(test_mirror_symmetry),
        cmocka_unit_test(test_linear_shear_is_newtonian),
        cmocka_unit_test(test_linear_temperature_is_fourier),
        cmocka_unit_test(test_row_matches_face),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
