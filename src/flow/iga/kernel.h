/* The quadrature-point body of the isogeometric flow's residual (paper 003
 * Eqs. 1-5; ../shared/notes/iga_flow.md Secs. 1.1-1.5): pressure-primitive
 * Y = (p, u, v, T), the rows the conservation of mass, x and y momentum
 * and total energy, for a calorically perfect gas. One source for the CPU
 * and a GPU (NSPD_KERNEL); 4 x 4 matrices row-major. */
#ifndef NSPD_FLOW_IGA_KERNEL_H
#define NSPD_FLOW_IGA_KERNEL_H

#include "core/kernel.h"

#include <math.h>
#include <stdbool.h>

typedef struct {
    double R, cv;      /* gas constant and c_v = R/(gamma - 1), J/(kg K) */
    double mu, lambda; /* viscosity and second viscosity (-2 mu/3), Pa s */
    double kappa;      /* conductivity mu gamma c_v / Pr, W/(m K) */
    double c_dc;       /* discontinuity capturing constant (2.5; 0: off) */
    bool dc_cap;       /* nu <= sqrt(u G^-1 u + c^2 tr G^-1) */
    int db_iterations; /* Denman-Beavers iterations of tau (10) */
    double tau_s;      /* 4/dt^2 with tau's dt, 1/s^2 */
    double G[2];       /* the metric on [-1, 1] elements: 4/hx^2, 4/hy^2 */
} IgaQpParams;

/* A0 = dU/dY and the full inviscid Jacobians A1 = dF_x/dY, A2 = dF_y/dY
 * (notes 1.2). */
NSPD_KERNEL void iga_jacobians(const IgaQpParams *g, const double Y[4], double A0[16],
                               double A1[16], double A2[16]) {
    const double p = Y[0], u = Y[1], v = Y[2], T = Y[3];
    const double rho = p / (g->R * T), E = g->cv * T + 0.5 * (u * u + v * v);
    const double rb = rho / p, ra = rho / T, re = rho * (g->cv - E / T);
    const double a0[16] = {rb,     0.0, 0.0, -ra,     rb * u, rho,     0.0,     -ra * u,
                           rb * v, 0.0, rho, -ra * v, rb * E, rho * u, rho * v, re};
    const double a1[16] = {rb * u,
                           rho,
                           0.0,
                           -ra * u,
                           rb * u * u + 1.0,
                           2.0 * rho * u,
                           0.0,
                           -ra * u * u,
                           rb * u * v,
                           rho * v,
                           rho * u,
                           -ra * u * v,
                           (rb * E + 1.0) * u,
                           rho * E + rho * u * u + p,
                           rho * u * v,
                           re * u};
    const double a2[16] = {rb * v,
                           0.0,
                           rho,
                           -ra * v,
                           rb * u * v,
                           rho * v,
                           rho * u,
                           -ra * u * v,
                           rb * v * v + 1.0,
                           0.0,
                           2.0 * rho * v,
                           -ra * v * v,
                           (rb * E + 1.0) * v,
                           rho * u * v,
                           rho * E + rho * v * v + p,
                           re * v};
    for (int k = 0; k < 16; k++) A0[k] = a0[k], A1[k] = a1[k], A2[k] = a2[k];
}

/* A0^-1 in closed form (notes 1.2, with alpha_p e = c_v). */
NSPD_KERNEL void iga_a0_inverse(const IgaQpParams *g, const double Y[4], double Ai[16]) {
    const double p = Y[0], u = Y[1], v = Y[2], T = Y[3];
    const double rho = p / (g->R * T), q2 = u * u + v * v, E = g->cv * T + 0.5 * q2;
    const double gm1 = g->R / g->cv, rc = 1.0 / (rho * g->cv);
    const double a[16] = {
        0.5 * gm1 * q2, -gm1 * u, -gm1 * v,  gm1, -u / rho,      1.0 / rho, 0.0,     0.0,
        -v / rho,       0.0,      1.0 / rho, 0.0, (q2 - E) * rc, -u * rc,   -v * rc, rc};
    for (int k = 0; k < 16; k++) Ai[k] = a[k];
}

NSPD_KERNEL void iga_mat4_mul(const double a[16], const double b[16], double c[16]) {
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double s = 0.0;
            for (int k = 0; k < 4; k++) s += a[4 * i + k] * b[4 * k + j];
            c[4 * i + j] = s;
        }
}

NSPD_KERNEL void iga_mat4_vec(const double a[16], const double x[4], double y[4]) {
    for (int i = 0; i < 4; i++)
        y[i] = a[4 * i] * x[0] + a[4 * i + 1] * x[1] + a[4 * i + 2] * x[2] + a[4 * i + 3] * x[3];
}

/* The inverse of a 4 x 4 matrix by Gauss-Jordan elimination with partial
 * pivoting; false when it is singular. */
NSPD_KERNEL bool iga_mat4_inverse(const double a[16], double inv[16]) {
    double m[16];
    for (int k = 0; k < 16; k++) m[k] = a[k], inv[k] = (k % 5 == 0) ? 1.0 : 0.0;
    for (int c = 0; c < 4; c++) {
        int piv = c;
        for (int r = c + 1; r < 4; r++)
            if (fabs(m[4 * r + c]) > fabs(m[4 * piv + c])) piv = r;
        if (!(m[4 * piv + c] != 0.0)) return false;
        if (piv != c)
            for (int k = 0; k < 4; k++) {
                double t = m[4 * c + k];
                m[4 * c + k] = m[4 * piv + k], m[4 * piv + k] = t;
                t = inv[4 * c + k];
                inv[4 * c + k] = inv[4 * piv + k], inv[4 * piv + k] = t;
            }
        const double d = 1.0 / m[4 * c + c];
        for (int k = 0; k < 4; k++) m[4 * c + k] *= d, inv[4 * c + k] *= d;
        for (int r = 0; r < 4; r++) {
            if (r == c) continue;
            const double f = m[4 * r + c];
            for (int k = 0; k < 4; k++)
                m[4 * r + k] -= f * m[4 * c + k], inv[4 * r + k] -= f * inv[4 * c + k];
        }
    }
    return true;
}

/* tau_c = M^(-1/2) for M = s I + sum_i G_i At_i At_i (notes 1.4): the
 * Denman-Beavers iteration on M/s from Z = I, both inverses from the old
 * pair, then Z/sqrt(s). */
NSPD_KERNEL void iga_tau_c(const IgaQpParams *g, const double At1[16], const double At2[16],
                           double tau_c[16]) {
    double m1[16], m2[16], Yk[16], Zk[16], Yi[16], Zi[16];
    iga_mat4_mul(At1, At1, m1);
    iga_mat4_mul(At2, At2, m2);
    const double is = 1.0 / g->tau_s;
    for (int k = 0; k < 16; k++) {
        Yk[k] = (g->G[0] * m1[k] + g->G[1] * m2[k]) * is + (k % 5 == 0 ? 1.0 : 0.0);
        Zk[k] = k % 5 == 0 ? 1.0 : 0.0;
    }
    for (int it = 0; it < g->db_iterations; it++) {
        if (!iga_mat4_inverse(Yk, Yi) || !iga_mat4_inverse(Zk, Zi)) break;
        bool moved = false;
        for (int k = 0; k < 16; k++) {
            const double y = 0.5 * (Yk[k] + Zi[k]), z = 0.5 * (Zk[k] + Yi[k]);
            moved = moved || y != Yk[k] || z != Zk[k];
            Yk[k] = y, Zk[k] = z;
        }
        /* a pair that an iteration leaves as it was is a fixed point: the
         * remaining iterations would give the same bits (4 to 5 of the 10
         * at Courant 0.3, iga_flow.md 1.4) */
        if (!moved) break;
    }
    const double r = sqrt(is);
    for (int k = 0; k < 16; k++) tau_c[k] = Zk[k] * r;
}

/* One quadrature point (notes 1.3): from the state Y, its rate Yd and its
 * gradients Yx, Yy, the vectors that multiply N_a (gal), N_a,x (fx) and
 * N_a,y (fy) in row i of basis a's residual, the point's A0 (for the
 * lumped mass) and the largest DC viscosity (m^2/s). */
NSPD_KERNEL void iga_point_residual(const IgaQpParams *g, const double Y[4], const double Yd[4],
                                    const double Yx[4], const double Yy[4], double gal[4],
                                    double fx[4], double fy[4], double A0[16], double *nu_max) {
    double A1[16], A2[16], Ai[16], At1[16], At2[16], tc[16], tau[16];
    iga_jacobians(g, Y, A0, A1, A2);
    iga_a0_inverse(g, Y, Ai);
    double a0d[4], a1x[4], a2y[4], res[4], dUx[4], dUy[4];
    iga_mat4_vec(A0, Yd, a0d);
    iga_mat4_vec(A1, Yx, a1x);
    iga_mat4_vec(A2, Yy, a2y);
    for (int i = 0; i < 4; i++) res[i] = a0d[i] + a1x[i] + a2y[i];
    /* Galerkin, advective form without the momentum rows' pressure
     * gradient, which goes by parts into fx, fy */
    for (int i = 0; i < 4; i++) gal[i] = res[i];
    gal[1] -= Yx[0];
    gal[2] -= Yy[0];
    /* SUPG: A_i tau Res, tau = A0^-1 M^(-1/2) */
    iga_mat4_mul(A1, Ai, At1);
    iga_mat4_mul(A2, Ai, At2);
    iga_tau_c(g, At1, At2, tc);
    iga_mat4_mul(Ai, tc, tau);
    double tr[4];
    iga_mat4_vec(tau, res, tr);
    iga_mat4_vec(A1, tr, fx);
    iga_mat4_vec(A2, tr, fy);
    /* pressure, by parts */
    fx[1] -= Y[0];
    fy[2] -= Y[0];
    /* viscous stress and heat flux, by parts */
    const double u = Y[1], v = Y[2];
    const double div = Yx[1] + Yy[2];
    const double txx = 2.0 * g->mu * Yx[1] + g->lambda * div,
                 tyy = 2.0 * g->mu * Yy[2] + g->lambda * div;
    const double txy = g->mu * (Yy[1] + Yx[2]);
    fx[1] += txx, fx[2] += txy, fx[3] += u * txx + v * txy + g->kappa * Yx[3];
    fy[1] += txy, fy[2] += tyy, fy[3] += u * txy + v * tyy + g->kappa * Yy[3];
    /* discontinuity capturing per group {mass}, {momentum}, {energy}: nu
     * = C sqrt(|Res_g|^2 / (grad U_g . G grad U_g)), none where grad U_g is
     * at round-off of the state */
    *nu_max = 0.0;
    if (!(g->c_dc > 0.0)) return;
    iga_mat4_vec(A0, Yx, dUx);
    iga_mat4_vec(A0, Yy, dUy);
    const double rho = Y[0] / (g->R * Y[3]), c2 = (1.0 + g->R / g->cv) * g->R * Y[3];
    const double ref[3] = {rho, rho * sqrt(c2), Y[0] * g->cv / g->R};
    const int first[4] = {0, 1, 3, 4};
    const double cap = sqrt((u * u + c2) / g->G[0] + (v * v + c2) / g->G[1]);
    for (int grp = 0; grp < 3; grp++) {
        double h = 0.0, r2 = 0.0;
        for (int i = first[grp]; i < first[grp + 1]; i++) {
            h += g->G[0] * dUx[i] * dUx[i] + g->G[1] * dUy[i] * dUy[i];
            r2 += res[i] * res[i];
        }
        /* a gradient of 1e-12 of the state across an element */
        const double gsum = g->G[0] + g->G[1];
        const double guard = 1e-24 * ref[grp] * ref[grp] * gsum * gsum;
        double nu = 0.0;
        if (h > guard) nu = g->c_dc * sqrt(r2 / h);
        if (g->dc_cap && nu > cap) nu = cap;
        for (int i = first[grp]; i < first[grp + 1]; i++)
            fx[i] += nu * dUx[i], fy[i] += nu * dUy[i];
        if (nu > *nu_max) *nu_max = nu;
    }
}

#endif
