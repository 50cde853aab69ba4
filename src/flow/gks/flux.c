/* Gas-kinetic BGK-NS flux: the single-face wrapper and the row loops.
 *
 * The row loops are where the solver spends its time. Each face is
 * independent, so the loop body (reconstruction of the two face states and
 * the kernel of flux_kernel.h) is vectorised across faces with omp simd; the
 * kernel is branch-free apart from selects, and its transcendental functions
 * come from special_functions.h. Each viscosity law gets its own instantiation of the
 * loop, so no law is evaluated that is not in use. Faces with no fluid cell on either side get a
 * zero flux through a select (never a multiply: their inputs may be garbage). */
#include "flow/gks/flux.h"

#include "core/kernel.h"

#include <stddef.h>

double gks_internal_dof(double gamma) {
    return (4.0 - 2.0 * gamma) / (gamma - 1.0);
}

void gks_params_default(GksParams *p, double gamma, double R) {
    *p = (GksParams){.gamma = gamma,
                     .K = gks_internal_dof(gamma),
                     .R = R,
                     .law = VISCOSITY_NONE,
                     .T_ref = 1.0,
                     .prandtl = 1.0,
                     .c_jump = 1.0,
                     .eps_dt = 0.0};
}

void gks_flux_face(const double wl[4], const double nl[4], const double tl[4], const double wr[4],
                   const double nr[4], const double tr[4], const double n0[4], const double t0[4],
                   double dt, const GksParams *p, double f[4]) {
    gks_flux_kernel(wl, nl, tl, wr, nr, tr, n0, t0, dt, p, p->law, f);
}

/* Row body shared by the two entry points; per_face selects the geometry
 * arrays (a compile-time constant after inlining). */
static inline __attribute__((always_inline)) void
flux_row(int n, const GksRowSide *restrict L, const GksRowSide *restrict R,
         const double *restrict dla, const double *restrict dra, const double *restrict idca,
         double dls, double drs, int per_face, double dt, const GksParams *restrict p,
         ViscosityLaw law, double *const f[4]) {
    const double *restrict lw0 = L->w[0], *restrict lw1 = L->w[1], *restrict lw2 = L->w[2],
                           *restrict lw3 = L->w[3];
    const double *restrict rw0 = R->w[0], *restrict rw1 = R->w[1], *restrict rw2 = R->w[2],
                           *restrict rw3 = R->w[3];
    const double *restrict ln0 = L->sn[0], *restrict ln1 = L->sn[1], *restrict ln2 = L->sn[2],
                           *restrict ln3 = L->sn[3];
    const double *restrict rn0 = R->sn[0], *restrict rn1 = R->sn[1], *restrict rn2 = R->sn[2],
                           *restrict rn3 = R->sn[3];
    const double *restrict lt0 = L->st[0], *restrict lt1 = L->st[1], *restrict lt2 = L->st[2],
                           *restrict lt3 = L->st[3];
    const double *restrict rt0 = R->st[0], *restrict rt1 = R->st[1], *restrict rt2 = R->st[2],
                           *restrict rt3 = R->st[3];
    const uint8_t *restrict lk = L->kind, *restrict rk = R->kind;
    double *restrict f0 = f[0], *restrict f1 = f[1], *restrict f2 = f[2], *restrict f3 = f[3];
    const GksParams par = *p;
    const double idcs = 1.0 / (dls + drs);
    /* GCC ivdep, not omp simd: GCC lowers omp simd before inlining and then
     * cannot vectorise the kernel's local arrays; the plain vectoriser can. */
    NSPD_IVDEP /* vectorised: tests/unit/core/vectorised.sh */
        for (int k = 0; k < n; k++) {
        const double dl = per_face ? dla[k] : dls, dr = per_face ? dra[k] : drs;
        const double idc = per_face ? idca[k] : idcs;
        const double nl[4] = {ln0[k], ln1[k], ln2[k], ln3[k]};
        const double nr[4] = {rn0[k], rn1[k], rn2[k], rn3[k]};
        const double tl[4] = {lt0[k], lt1[k], lt2[k], lt3[k]};
        const double tr[4] = {rt0[k], rt1[k], rt2[k], rt3[k]};
        const double cl[4] = {lw0[k], lw1[k], lw2[k], lw3[k]};
        const double cr[4] = {rw0[k], rw1[k], rw2[k], rw3[k]};
        double wl[4], wr[4], n0[4], t0[4], fl[4];
        for (int c = 0; c < 4; c++) {
            wl[c] = NSPD_FMA(nl[c], dl, cl[c]);
            wr[c] = NSPD_FMA(-nr[c], dr, cr[c]);
            n0[c] = (cr[c] - cl[c]) * idc;
            t0[c] = 0.5 * (tl[c] + tr[c]);
        }
        gks_flux_kernel(wl, nl, tl, wr, nr, tr, n0, t0, dt, &par, law, fl);
        f0[k] = fl[0];
        f1[k] = fl[1];
        f2[k] = fl[2];
        f3[k] = fl[3];
    }
    /* faces with no fluid cell on either side: zero, whatever the kernel
     * made of their inputs. A pass of its own: the cells' kinds (bytes)
     * in the loop above kept GCC from vectorising it (no vector mode fits
     * bytes and doubles together there), and it then ran one face at a
     * time. */
    for (int k = 0; k < n; k++)
        if (lk[k] != 0 && rk[k] != 0) f0[k] = f1[k] = f2[k] = f3[k] = 0.0;
}

void gks_flux_row_x(int n, const GksRowSide *left, const GksRowSide *right, const double *dl,
                    const double *dr, const double *inv_dc, double dt, const GksParams *p,
                    double *const f[4]) {
    switch (p->law) {
    case VISCOSITY_CONSTANT:
        flux_row(n, left, right, dl, dr, inv_dc, 0.0, 0.0, 1, dt, p, VISCOSITY_CONSTANT, f);
        break;
    case VISCOSITY_POWER:
        flux_row(n, left, right, dl, dr, inv_dc, 0.0, 0.0, 1, dt, p, VISCOSITY_POWER, f);
        break;
    case VISCOSITY_SUTHERLAND:
        flux_row(n, left, right, dl, dr, inv_dc, 0.0, 0.0, 1, dt, p, VISCOSITY_SUTHERLAND, f);
        break;
    default:
        flux_row(n, left, right, dl, dr, inv_dc, 0.0, 0.0, 1, dt, p, VISCOSITY_NONE, f);
    }
}

void gks_flux_row_y(int n, const GksRowSide *left, const GksRowSide *right, double dl, double dr,
                    double dt, const GksParams *p, double *const f[4]) {
    switch (p->law) {
    case VISCOSITY_CONSTANT:
        flux_row(n, left, right, NULL, NULL, NULL, dl, dr, 0, dt, p, VISCOSITY_CONSTANT, f);
        break;
    case VISCOSITY_POWER:
        flux_row(n, left, right, NULL, NULL, NULL, dl, dr, 0, dt, p, VISCOSITY_POWER, f);
        break;
    case VISCOSITY_SUTHERLAND:
        flux_row(n, left, right, NULL, NULL, NULL, dl, dr, 0, dt, p, VISCOSITY_SUTHERLAND, f);
        break;
    default:
        flux_row(n, left, right, NULL, NULL, NULL, dl, dr, 0, dt, p, VISCOSITY_NONE, f);
    }
}
