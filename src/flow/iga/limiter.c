#include "flow/iga/limiter.h"

#include "core/mem.h"
#include "core/parallel.h"
#include "core/status.h"

#include <math.h>
#include <string.h>

/* the fraction of the low-order state's density and internal energy that
 * the positivity mode keeps at least */
static const double POSITIVITY_FRACTION = 0.01;

/* int N_k N_l and int N_k N_l' along one axis, by offset (Gauss with p + 1
 * points: exact for these polynomials of degree 2p and 2p - 1). */
static int axis_tables(IgaLimiter *l, int axis, const IgaAxis *a) {
    const int p = a->degree, n = a->count, w = 2 * p + 1;
    TRY(nspd_alloc(&l->mass1[axis], (size_t)n * (size_t)w, sizeof(double)));
    TRY(nspd_alloc(&l->grad1[axis], (size_t)n * (size_t)w, sizeof(double)));
    for (int e = 0; e < a->elements; e++)
        for (int q = 0; q < a->gauss; q++) {
            const double *N =
                a->value + ((size_t)e * (size_t)a->gauss + (size_t)q) * (size_t)(p + 1);
            const double *D =
                a->slope + ((size_t)e * (size_t)a->gauss + (size_t)q) * (size_t)(p + 1);
            for (int i = 0; i <= p; i++)
                for (int j = 0; j <= p; j++) {
                    const int ki = iga_axis_index(a, e, i), kj = iga_axis_index(a, e, j);
                    int o = kj - ki;
                    if (o > p) o -= n; /* periodic: the nearest image */
                    if (o < -p) o += n;
                    l->mass1[axis][ki * w + o + p] += a->weight[q] * N[i] * N[j];
                    l->grad1[axis][ki * w + o + p] += a->weight[q] * N[i] * D[j];
                }
        }
    return NSPD_OK;
}

void iga_limiter_destroy(IgaLimiter *l) {
    for (int a = 0; a < 2; a++) nspd_free(&l->mass1[a]), nspd_free(&l->grad1[a]);
    nspd_free(&l->m);
    nspd_free(&l->U);
    nspd_free(&l->flux);
    nspd_free(&l->waves);
    nspd_free(&l->entropy);
    nspd_free(&l->relax);
    nspd_free(&l->acc);
    nspd_free(&l->dsum);
    nspd_free(&l->bounds);
    nspd_free(&l->dij);
    nspd_free(&l->lij);
    nspd_free(&l->rate);
    nspd_free(&l->UL);
}

int iga_limiter_create(IgaLimiter *l, IgaLimiterKind kind, const IgaAxis ax[2], const IgaDecomp *dc,
                       const bool wall[4], const bool fixed[4], double gamma, double R) {
    memset(l, 0, sizeof *l);
    l->kind = kind;
    l->p = ax[0].degree;
    l->gamma = gamma, l->R = R, l->cv = R / (gamma - 1.0);
    for (int f = 0; f < 4; f++) l->wall[f] = wall[f], l->fixed[f] = fixed[f];
    l->alpha_min = 1.0;
    if (kind == IGA_LIMITER_NONE) return NSPD_OK;
    for (int a = 0; a < 2; a++) {
        const IgaWindowAxis *w = &dc->ax[a];
        l->n[a] = w->n;
        l->count[a] = ax[a].count;
        l->g[a] = w->global;
        l->wrap[a] = w->whole && ax[a].periodic;
        l->own0[a] = w->own0, l->own[a] = w->own;
        l->periodic[a] = ax[a].periodic;
        /* a periodic axis of fewer than 2p + 1 functions would meet the
         * same neighbour at two offsets */
        if (ax[a].periodic && ax[a].count < 2 * l->p + 1)
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "iga: %d periodic elements along %c with the limiter; expected at "
                             "least %d (2 degree + 1)",
                             ax[a].elements, a == 0 ? 'x' : 'y', 2 * l->p + 1);
    }
    int status = NSPD_OK;
    for (int a = 0; a < 2 && status == NSPD_OK; a++) status = axis_tables(l, a, &ax[a]);
    const size_t ncp = (size_t)l->n[0] * (size_t)l->n[1];
    if (status == NSPD_OK) status = nspd_alloc(&l->m, ncp, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&l->U, 4 * ncp, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&l->flux, 8 * ncp, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&l->waves, ncp, sizeof(IdpWaves));
    if (status == NSPD_OK) status = nspd_alloc(&l->entropy, ncp, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&l->relax, ncp, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&l->acc, 4 * ncp, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&l->dsum, ncp, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&l->bounds, ncp, sizeof(IdpBounds));
    const size_t pairs = ncp * (size_t)(2 * l->p + 1) * (size_t)(2 * l->p + 1);
    if (status == NSPD_OK) status = nspd_alloc(&l->dij, pairs, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&l->lij, pairs, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&l->rate, 4 * ncp, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&l->UL, 4 * ncp, sizeof(double));
    if (status != NSPD_OK) {
        iga_limiter_destroy(l);
        return status;
    }
    /* the bounds are relaxed by r = (m_i / |domain|)^(1.5/2): a smooth
     * extremum's high-order overshoot is O(h^2), so r > it on fine meshes
     * and the order is kept (Guermond et al. 2018, Sec. 4.7) */
    const double area = (ax[0].hi - ax[0].lo) * (ax[1].hi - ax[1].lo);
    for (int j = 0; j < l->n[1]; j++)
        for (int i = 0; i < l->n[0]; i++) {
            const int64_t k = i + (int64_t)l->n[0] * j;
            l->m[k] = iga_axis_integral(&ax[0], l->g[0][i]) * iga_axis_integral(&ax[1], l->g[1][j]);
            l->relax[k] = pow(l->m[k] / area, 0.75);
        }
    return NSPD_OK;
}

/* (local) point (i, j) on a fixed side */
static bool is_fixed(const IgaLimiter *l, int i, int j) {
    const int gi = l->g[0][i], gj = l->g[1][j];
    return (l->fixed[0] && gi == 0) || (l->fixed[1] && gi == l->count[0] - 1) ||
           (l->fixed[2] && gj == 0) || (l->fixed[3] && gj == l->count[1] - 1);
}

static bool is_own(const IgaLimiter *l, int i, int j) {
    return i >= l->own0[0] && i < l->own0[0] + l->own[0] && j >= l->own0[1] &&
           j < l->own0[1] + l->own[1];
}

/* The neighbour of local index i at offset o along an axis, or -1 (off
 * the whole axis, or off the window: a rim point's, never read for an
 * own one). */
static int neighbour(const IgaLimiter *l, int axis, int i, int o) {
    const int n = l->n[axis];
    int k = i + o;
    if (l->wrap[axis]) return (k + n) % n;
    return k >= 0 && k < n ? k : -1;
}

/* The graph viscosity of the pair (i, j) -> (jx, jy) at offset (ox, oy):
 * d_ij = max(lambda_max(n_ij) |c_ij|, lambda_max(n_ji) |c_ji|), c_ij =
 * int N_i grad N_j (Guermond & Popov 2016, Eq. 3.5); symmetric, so each
 * pair is evaluated once. */
static double pair_viscosity(const IgaLimiter *l, int i, int j, int ox, int oy, int jx, int jy) {
    const int p = l->p, w = 2 * p + 1;
    const int64_t k = i + (int64_t)l->n[0] * j, kj = jx + (int64_t)l->n[0] * jy;
    const double *Ui = l->U + 4 * k, *Uj = l->U + 4 * kj;
    const int gi = l->g[0][i], gj = l->g[1][j], gx = l->g[0][jx], gy = l->g[1][jy];
    const double cx = l->grad1[0][gi * w + ox + p] * l->mass1[1][gj * w + oy + p];
    const double cy = l->mass1[0][gi * w + ox + p] * l->grad1[1][gj * w + oy + p];
    const double bx = l->grad1[0][gx * w - ox + p] * l->mass1[1][gy * w - oy + p];
    const double by = l->mass1[0][gx * w - ox + p] * l->grad1[1][gy * w - oy + p];
    const double ni = hypot(cx, cy), nj = hypot(bx, by);
    const IdpWaves wi = l->waves[k], wj = l->waves[kj];
    double li = 0.0, lj = 0.0;
    if (ni > 0.0)
        li = ni * idp_lambda_waves(l->gamma, (Ui[1] * cx + Ui[2] * cy) / (ni * Ui[0]), wi,
                                   (Uj[1] * cx + Uj[2] * cy) / (ni * Uj[0]), wj);
    /* inside the domain c_ji = -c_ij, and the bound is the same bits from
     * j's side (idp_lambda_waves) */
    if (bx == -cx && by == -cy)
        lj = li;
    else if (nj > 0.0)
        lj = nj * idp_lambda_waves(l->gamma, (Uj[1] * bx + Uj[2] * by) / (nj * Uj[0]), wj,
                                   (Ui[1] * bx + Ui[2] * by) / (nj * Ui[0]), wi);
    return fmax(li, lj);
}

/* Point (i, j)'s viscosities with the neighbours at the later half of the
 * offsets, written to both points' rows (each pair has one writer); a
 * fixed point's row stays 0. */
static void viscosity_point(IgaLimiter *l, int i, int j) {
    const int p = l->p, w = 2 * p + 1;
    const int64_t k = i + (int64_t)l->n[0] * j;
    const bool fi = is_fixed(l, i, j);
    for (int oy = 0; oy <= p; oy++) {
        const int jy = neighbour(l, 1, j, oy);
        if (jy < 0) continue;
        for (int ox = oy == 0 ? 1 : -p; ox <= p; ox++) {
            const int jx = neighbour(l, 0, i, ox);
            if (jx < 0) continue;
            const bool fj = is_fixed(l, jx, jy);
            if (fi && fj) continue;
            const double d = pair_viscosity(l, i, j, ox, oy, jx, jy);
            const int slot = (oy + p) * w + ox + p;
            if (!fi) l->dij[k * w * w + slot] = d;
            if (!fj) l->dij[(jx + (int64_t)l->n[0] * jy) * w * w + w * w - 1 - slot] = d;
        }
    }
}

/* Point k's low-order rate m_i dU_i/dt = -sum_j c_ij . (F_j - F_i) +
 * sum_j d_ij (U_j - U_i) (Guermond & Popov 2016, Eq. 3.2 with sum_j c_ij
 * = 0, the partition of unity); and the bounds from the bar states
 * Ubar_ij = (U_i + U_j)/2 - c_ij . (F_j - F_i) / (2 d_ij), of which the
 * update is a convex combination when dt <= m_i / (2 sum_j d_ij). */
static void low_order_point(IgaLimiter *l, int i, int j) {
    const int p = l->p, w = 2 * p + 1, nx = l->n[0];
    const int64_t k = i + (int64_t)nx * j;
    const double *Ui = l->U + 4 * k, *Fi = l->flux + 8 * k;
    double acc[4] = {0}, ds = 0.0;
    const double *dij = l->dij + k * w * w;
    double rmin = Ui[0], rmax = Ui[0], smin = l->entropy[k];
    for (int oy = -p; oy <= p; oy++) {
        const int jy = neighbour(l, 1, j, oy);
        if (jy < 0) continue;
        for (int ox = -p; ox <= p; ox++) {
            const int jx = neighbour(l, 0, i, ox);
            const double d = dij[(oy + p) * w + ox + p];
            if (jx < 0 || !(d > 0.0)) continue;
            const int64_t kj = jx + (int64_t)nx * jy;
            const double *Uj = l->U + 4 * kj, *Fj = l->flux + 8 * kj;
            const int gi = l->g[0][i], gj = l->g[1][j];
            const double cx = l->grad1[0][gi * w + ox + p] * l->mass1[1][gj * w + oy + p];
            const double cy = l->mass1[0][gi * w + ox + p] * l->grad1[1][gj * w + oy + p];
            double bar[4];
            for (int v = 0; v < 4; v++) {
                const double df = cx * (Fj[v] - Fi[v]) + cy * (Fj[4 + v] - Fi[4 + v]);
                acc[v] += d * (Uj[v] - Ui[v]) - df;
                bar[v] = 0.5 * (Ui[v] + Uj[v]) - 0.5 * df / d;
            }
            ds += d;
            rmin = fmin(rmin, fmin(Uj[0], bar[0]));
            rmax = fmax(rmax, fmax(Uj[0], bar[0]));
            /* the positivity mode sets its own bounds (iga_limiter_stage) */
            if (l->kind == IGA_LIMITER_CONVEX)
                smin = fmin(smin, fmin(l->entropy[kj], idp_entropy(l->gamma, bar)));
        }
    }
    for (int v = 0; v < 4; v++) l->acc[4 * k + v] = acc[v];
    l->dsum[k] = ds;
    const double r = l->relax[k];
    l->bounds[k] = (IdpBounds){.rho_min = fmax(rmin, 0.0) * (1.0 - r),
                               .rho_max = rmax * (1.0 + r),
                               .s_min = fmax(smin, 0.0) * (1.0 - r),
                               .e_min = 0.0};
}

double iga_limiter_prepare(IgaLimiter *l, const double *Uin) {
    const int64_t ncp = (int64_t)l->n[0] * l->n[1];
    /* a fixed point's pairs are skipped: no viscosity, no flux */
    memset(l->dij, 0, sizeof(double) * (size_t)ncp * (size_t)((2 * l->p + 1) * (2 * l->p + 1)));
#pragma omp parallel for schedule(static) if (ncp >= PARALLEL_MIN_ITEMS)
    for (int64_t k = 0; k < ncp; k++) {
        double *U = l->U + 4 * k;
        for (int v = 0; v < 4; v++) U[v] = Uin[4 * k + v];
        idp_flux(l->gamma, U, 1.0, 0.0, l->flux + 8 * k);
        idp_flux(l->gamma, U, 0.0, 1.0, l->flux + 8 * k + 4);
        l->waves[k] = idp_waves(l->gamma, U);
        l->entropy[k] = idp_entropy(l->gamma, U);
    }
    double dt = (double)INFINITY;
    const int work = (2 * l->p + 1) * (2 * l->p + 1);
#pragma omp parallel for schedule(static) if (ncp * work >= PARALLEL_MIN_ITEMS)
    for (int64_t k = 0; k < ncp; k++) viscosity_point(l, (int)(k % l->n[0]), (int)(k / l->n[0]));
#pragma omp parallel for schedule(static) reduction(min : dt) if (ncp * work >= PARALLEL_MIN_ITEMS)
    for (int64_t k = 0; k < ncp; k++) {
        const int i = (int)(k % l->n[0]), j = (int)(k / l->n[0]);
        low_order_point(l, i, j);
        if (is_own(l, i, j) && l->dsum[k] > 0.0) dt = fmin(dt, l->m[k] / (2.0 * l->dsum[k]));
    }
    return dt;
}

/* A slip wall's control point keeps no normal momentum. */
static void remove_wall_normal(const IgaLimiter *l, int i, int j, double U[4]) {
    const int gi = l->g[0][i], gj = l->g[1][j];
    if ((l->wall[0] && gi == 0) || (l->wall[1] && gi == l->count[0] - 1)) U[1] = 0.0;
    if ((l->wall[2] && gj == 0) || (l->wall[3] && gj == l->count[1] - 1)) U[2] = 0.0;
}

/* Point k's low-order state: the step's start and dt / m_k its rate and
 * sources, the slip walls' normal momentum removed (rho and rho E kept,
 * so rho e only grows). */
static void low_order_state(const IgaLimiter *l, int64_t k, double dt, const double *src,
                            double UL[4]) {
    const int i = (int)(k % l->n[0]), j = (int)(k / l->n[0]);
    const double f = dt / l->m[k];
    for (int v = 0; v < 4; v++) UL[v] = l->U[4 * k + v] + f * l->acc[4 * k + v];
    if (src)
        for (int v = 0; v < 3; v++) UL[1 + v] += f * src[3 * k + v];
    remove_wall_normal(l, i, j, UL);
}

/* The antidiffusive flux A_ij = dt m_ij (Udot_i - Udot_j) - dt d_ij (U_j
 * - U_i) that turns the low-order update into the Galerkin one with the
 * consistent mass (one correction of the lumped rate, Guermond et al.
 * 2018, Eq. 3.11 with no high-order viscosity); skew-symmetric, so
 * conservative. */
static void antidiffusive_flux(const IgaLimiter *l, int64_t k, int64_t kj, int i, int j, int slot,
                               double dt, double A[4]) {
    const int w = 2 * l->p + 1;
    const double mij =
        l->mass1[0][l->g[0][i] * w + slot % w] * l->mass1[1][l->g[1][j] * w + slot / w];
    const double d = l->dij[k * w * w + slot];
    for (int v = 0; v < 4; v++)
        A[v] = dt * (mij * (l->rate[4 * k + v] - l->rate[4 * kj + v]) -
                     d * (l->U[4 * kj + v] - l->U[4 * k + v]));
}

enum { MAX_PAIRS = (2 * IGA_MAX_DEGREE + 1) * (2 * IGA_MAX_DEGREE + 1) };

/* Point (i, j)'s neighbours j != i: their points and offset slots (oy + p)
 * (2p + 1) + ox + p; their number returned. */
static int pairs_of(const IgaLimiter *l, int i, int j, int64_t *kj, int *slot) {
    const int p = l->p, w = 2 * p + 1;
    int n = 0;
    for (int oy = -p; oy <= p; oy++) {
        const int jy = neighbour(l, 1, j, oy);
        for (int ox = -p; ox <= p && jy >= 0; ox++) {
            const int jx = neighbour(l, 0, i, ox);
            if (jx < 0 || (ox == 0 && oy == 0)) continue;
            kj[n] = jx + (int64_t)l->n[0] * jy;
            slot[n++] = (oy + p) * w + ox + p;
        }
    }
    return n;
}

void iga_limiter_stage(IgaLimiter *l, double dt, const double *src, double *Uout) {
    const int64_t ncp = (int64_t)l->n[0] * l->n[1];
    const int w = 2 * l->p + 1, work = w * w;
    const bool par = ncp * work >= PARALLEL_MIN_ITEMS;
    /* the lumped Galerkin rate, the low-order state and its bounds */
#pragma omp parallel for schedule(static) if (par)
    for (int64_t k = 0; k < ncp; k++) {
        const int i = (int)(k % l->n[0]), j = (int)(k / l->n[0]);
        double b[4];
        for (int v = 0; v < 4; v++) b[v] = l->acc[4 * k + v];
        if (src)
            for (int v = 0; v < 3; v++) b[1 + v] += src[3 * k + v];
        int64_t kj[MAX_PAIRS];
        int slot[MAX_PAIRS];
        const int n = pairs_of(l, i, j, kj, slot);
        for (int q = 0; q < n; q++)
            for (int v = 0; v < 4; v++)
                b[v] -= l->dij[k * work + slot[q]] * (l->U[4 * kj[q] + v] - l->U[4 * k + v]);
        for (int v = 0; v < 4; v++) l->rate[4 * k + v] = b[v] / l->m[k];
        double *UL = l->UL + 4 * k;
        low_order_state(l, k, dt, src, UL);
        if (l->kind == IGA_LIMITER_POSITIVITY)
            l->bounds[k] = (IdpBounds){.rho_min = POSITIVITY_FRACTION * UL[0],
                                       .rho_max = (double)INFINITY,
                                       .s_min = 0.0,
                                       .e_min = POSITIVITY_FRACTION * idp_internal(UL)};
    }
    /* each pair's largest factor from i's side: UL_i + l P_ij within i's
     * bounds, P_ij = A_ij / (m_i lambda_i), lambda_i = 1 / (neighbours) */
#pragma omp parallel for schedule(static) if (par)
    for (int64_t k = 0; k < ncp; k++) {
        const int i = (int)(k % l->n[0]), j = (int)(k / l->n[0]);
        int64_t kj[MAX_PAIRS];
        int slot[MAX_PAIRS];
        const int n = pairs_of(l, i, j, kj, slot);
        for (int q = 0; q < n; q++) {
            double A[4], UP[4];
            antidiffusive_flux(l, k, kj[q], i, j, slot[q], dt, A);
            for (int v = 0; v < 4; v++) UP[v] = l->UL[4 * k + v] + n * A[v] / l->m[k];
            l->lij[k * work + slot[q]] = idp_blend(l->gamma, &l->bounds[k], l->UL + 4 * k, UP);
        }
    }
    /* U_i = UL_i + sum_j min(l_ij, l_ji) A_ij / m_i: a convex combination
     * of states within i's bounds */
    int64_t limited = 0;
    double amin = 1.0;
#pragma omp parallel for schedule(static) reduction(+ : limited) reduction(min : amin) if (par)
    for (int64_t k = 0; k < ncp; k++) {
        const int i = (int)(k % l->n[0]), j = (int)(k / l->n[0]);
        double *U = Uout + 4 * k;
        for (int v = 0; v < 4; v++) U[v] = l->UL[4 * k + v];
        if (is_fixed(l, i, j)) {
            for (int v = 0; v < 4; v++) U[v] = l->U[4 * k + v];
            continue;
        }
        double lo = 1.0;
        int64_t kj[MAX_PAIRS];
        int slot[MAX_PAIRS];
        const int n = pairs_of(l, i, j, kj, slot);
        for (int q = 0; q < n; q++) {
            double A[4];
            antidiffusive_flux(l, k, kj[q], i, j, slot[q], dt, A);
            /* the reverse pair's slot: the offset negated */
            const double f =
                fmin(l->lij[k * work + slot[q]], l->lij[kj[q] * work + work - 1 - slot[q]]);
            lo = fmin(lo, f);
            for (int v = 0; v < 4; v++) U[v] += f * A[v] / l->m[k];
        }
        remove_wall_normal(l, i, j, U);
        if (!is_own(l, i, j)) continue; /* the statistics of the own points */
        if (lo < 1.0) limited++;
        amin = fmin(amin, lo);
    }
    l->limited = limited;
    l->alpha_min = amin;
}
