/* Ghost-cell and point stencils (paper 000 Eqs. 31-39) and their degenerate
 * cases.
 *
 * The bilinear fit (Eq. 33) is solved in the cell-centre box around the
 * point P, in coordinates scaled by the centre spacings (xi, eta in [0, 1]),
 * so that the 4x4 matrix has O(1) entries whatever the cell size:
 *   fluid node m:        [1, xi_m, eta_m, xi_m eta_m]           (Eq. 34)
 *   replaced, Dirichlet: [1, xi_B, eta_B, xi_B eta_B]           (Eqs. 35, 37)
 *   replaced, Neumann:   [0, n_x h/hx, n_y h/hy, h (n_x eta_B/hx + n_y xi_B/hy)]  (Eqs. 36, 38)
 * with B the replaced node's own nearest wall point and n the outward normal
 * there (h = min(hx, hy) only scales the row). Instead of the coefficients w
 * we solve A^T c = (1, xi_P, eta_P, xi_P eta_P) for the weights c of the
 * node values, phi_P = sum_m c_m phi_m: the same number for any phi, and the
 * weights are what the per-step fill needs.
 *
 * A node is usable ("fluid") if its kind is FLUID, the straight line from P
 * to its centre does not meet a wall (a fluid cell on the far side of a thin
 * body or a trailing edge is not a neighbour), and it is not excluded (fresh
 * cells during an update). Otherwise it is replaced.
 *
 * Acceptance of a stencil at P (else the next level is tried):
 *   P is inside the box of first-layer box ghosts and not inside a body;
 *   at least 2 usable nodes (the paper's cases 1-3: 0, 1 or 2 replaced; with 3
 *   replaced the Neumann rows have nearly parallel normals and the system is
 *   close to singular); no pivot below 1e-10; sum |c| <= IBM_WEIGHT_MAX in the
 *   Dirichlet fit and over the usable nodes of the Neumann fit (a bounded
 *   interpolation, not an extrapolation).
 *
 * Ghost cells, in order:
 *   IMAGE     P = IP = GC + 2 d n (Eq. 31); Dirichlet phi_GC = 2 phi_BI - phi_IP.
 *   EXTENDED  P = BI + (d + k h) n, k = 1..4, h the ghost cell's diagonal: the
 *             image point moved out of a crowded corner, a thin region or a
 *             singular system; phi_GC = phi_BI + (d / (d + k h)) (phi_BI - phi_P)
 *             (linear along the normal; Eq. 39 is the case k = 0). Also used
 *             when d = 0 (cell centre on the wall: phi_GC = phi_BI).
 *   NEAREST   inverse-distance (1/r^2) mean of up to 4 usable fluid cells in the
 *             5 x 5 block around the ghost, seen from just outside BI; the
 *             ratio is d over the mean's distance from the wall (at most 1).
 *             A ghost always has a fluid cell within 2 cells, so this level
 *             never fails.
 * Neumann variables take phi_GC = phi_P at every level (zero normal gradient).
 *
 * Every stencil records the bounding box of all the geometry it consulted
 * (points, nodes, the discs of the nearest-point searches), so that an
 * update can tell which stencils a moved wall can change. */
#include "couple/ghost/ibm_internal.h"

#include "core/mem.h"
#include "core/status.h"
#include "flow/gks/solver.h"

#include <math.h>
#include <string.h>

/* Largest accepted sum of |weights|: a bilinear interpolation inside its box
 * has sum 1 (all weights positive); wall rows near a node push it up.
 * Measured: the cylinder and airfoil ghosts stay at 1.0 to 1.2, the tilted
 * wall and corner tests below 4; the bound only turns away fits that
 * extrapolate (a near-singular system has weights of order 1/pivot). */
#define IBM_WEIGHT_MAX 8.0

/* -------------------------------------------------------------- storage */

int ibm_stencils_reserve(IbmStencilSet *s, int n) {
    if (n <= s->cap) return NSPD_OK;
    int cap = s->cap > 0 ? s->cap : 64;
    while (cap < n) cap *= 2;
    const size_t o = (size_t)s->cap, c = (size_t)cap;
    TRY(nspd_realloc(&s->cell, o, c, sizeof(int64_t)));
    TRY(nspd_realloc(&s->node, 4 * o, 4 * c, sizeof(int64_t)));
    TRY(nspd_realloc(&s->wd, 4 * o, 4 * c, sizeof(double)));
    TRY(nspd_realloc(&s->wn, 4 * o, 4 * c, sizeof(double)));
    TRY(nspd_realloc(&s->rseg, 4 * o, 4 * c, sizeof(int32_t)));
    TRY(nspd_realloc(&s->rt, 4 * o, 4 * c, sizeof(double)));
    TRY(nspd_realloc(&s->seg, o, c, sizeof(int32_t)));
    TRY(nspd_realloc(&s->t, o, c, sizeof(double)));
    TRY(nspd_realloc(&s->ratio, o, c, sizeof(double)));
    TRY(nspd_realloc(&s->wu, o, c, sizeof(double)));
    TRY(nspd_realloc(&s->wv, o, c, sizeof(double)));
    TRY(nspd_realloc(&s->geo, o, c, sizeof(IbmStencilGeo)));
    TRY(nspd_realloc(&s->dep, 4 * o, 4 * c, sizeof(double)));
    TRY(nspd_realloc(&s->level, o, c, 1));
    TRY(nspd_realloc(&s->nrep, o, c, 1));
    TRY(nspd_realloc(&s->body, o, c, 1));
    s->cap = cap;
    return NSPD_OK;
}

void ibm_stencils_free(IbmStencilSet *s) {
    nspd_free(&s->cell);
    nspd_free(&s->node);
    nspd_free(&s->wd);
    nspd_free(&s->wn);
    nspd_free(&s->rseg);
    nspd_free(&s->rt);
    nspd_free(&s->seg);
    nspd_free(&s->t);
    nspd_free(&s->ratio);
    nspd_free(&s->wu);
    nspd_free(&s->wv);
    nspd_free(&s->geo);
    nspd_free(&s->dep);
    nspd_free(&s->level);
    nspd_free(&s->nrep);
    nspd_free(&s->body);
    memset(s, 0, sizeof *s);
}

void ibm_stencils_copy_entry(IbmStencilSet *d, int e, const IbmStencilSet *s, int f) {
    d->cell[e] = s->cell[f];
    for (int m = 0; m < 4; m++) {
        d->node[4 * e + m] = s->node[4 * f + m];
        d->wd[4 * e + m] = s->wd[4 * f + m];
        d->wn[4 * e + m] = s->wn[4 * f + m];
        d->rseg[4 * e + m] = s->rseg[4 * f + m];
        d->rt[4 * e + m] = s->rt[4 * f + m];
        d->dep[4 * e + m] = s->dep[4 * f + m];
    }
    d->seg[e] = s->seg[f];
    d->t[e] = s->t[f];
    d->ratio[e] = s->ratio[f];
    d->wu[e] = s->wu[f];
    d->wv[e] = s->wv[f];
    d->geo[e] = s->geo[f];
    d->level[e] = s->level[f];
    d->nrep[e] = s->nrep[f];
    d->body[e] = s->body[f];
}

/* ------------------------------------------------------------- 4x4 solve */

/* Solves M c = r (M row-major 4x4) by Gaussian elimination with partial
 * pivoting; -1 if a pivot is below 1e-10 of the largest entry. */
static int solve4(double M[4][4], double r[4], double c[4]) {
    double big = 0.0;
    for (int i = 0; i < 4; i++)
        for (int k = 0; k < 4; k++) big = fmax(big, fabs(M[i][k]));
    if (!(big > 0.0)) return -1;
    for (int k = 0; k < 4; k++) {
        int p = k;
        for (int i = k + 1; i < 4; i++)
            if (fabs(M[i][k]) > fabs(M[p][k])) p = i;
        if (!(fabs(M[p][k]) > 1e-10 * big)) return -1;
        if (p != k) {
            for (int q = 0; q < 4; q++) {
                const double tmp = M[k][q];
                M[k][q] = M[p][q];
                M[p][q] = tmp;
            }
            const double tmp = r[k];
            r[k] = r[p];
            r[p] = tmp;
        }
        for (int i = k + 1; i < 4; i++) {
            const double f = M[i][k] / M[k][k];
            for (int q = k; q < 4; q++) M[i][q] -= f * M[k][q];
            r[i] -= f * r[k];
        }
    }
    for (int k = 3; k >= 0; k--) {
        double s = r[k];
        for (int q = k + 1; q < 4; q++) s -= M[k][q] * c[q];
        c[k] = s / M[k][k];
    }
    return 0;
}

int ibm_bilinear_weights(double px, double py, double hx, double hy, const int fluid[4],
                         const double bx[4], const double by[4], const double nx[4],
                         const double ny[4], double wd[4], double wn[4]) {
    static const double XI[4] = {0.0, 1.0, 0.0, 1.0}, ETA[4] = {0.0, 0.0, 1.0, 1.0};
    const double h = fmin(hx, hy);
    double D[4][4], N[4][4];
    for (int m = 0; m < 4; m++) {
        /* column m of A^T is row m of A */
        if (fluid[m]) {
            D[0][m] = N[0][m] = 1.0;
            D[1][m] = N[1][m] = XI[m];
            D[2][m] = N[2][m] = ETA[m];
            D[3][m] = N[3][m] = XI[m] * ETA[m];
        } else {
            D[0][m] = 1.0;
            D[1][m] = bx[m];
            D[2][m] = by[m];
            D[3][m] = bx[m] * by[m];
            const double ax = nx[m] * h / hx, ay = ny[m] * h / hy;
            N[0][m] = 0.0;
            N[1][m] = ax;
            N[2][m] = ay;
            N[3][m] = ax * by[m] + ay * bx[m];
        }
    }
    double rd[4] = {1.0, px, py, px * py}, rn[4] = {1.0, px, py, px * py};
    if (solve4(D, rd, wd) < 0) return -1;
    if (solve4(N, rn, wn) < 0) return -1;
    return 0;
}

/* ------------------------------------------------------------- building */

typedef struct {
    double xlo, xhi, ylo, yhi;
} Box;

static inline void box_add(Box *b, double x, double y, double r) {
    b->xlo = fmin(b->xlo, x - r);
    b->xhi = fmax(b->xhi, x + r);
    b->ylo = fmin(b->ylo, y - r);
    b->yhi = fmax(b->yhi, y + r);
}

/* Index i0 in [-1, n-1] with c[i0] <= x < c[i0+1], or -2 outside. */
static int locate(const GridAxis *a, double x) {
    if (!(x >= a->center[-1]) || !(x < a->center[a->n])) return -2;
    return grid_axis_bracket(a, x);
}

/* The candidate stencil at P (one attempt). */
typedef struct {
    int64_t node[4];
    int32_t rseg[4];
    double rt[4], wd[4], wn[4];
    int nrep;
    double wsum;
    double mx, my; /* nearest_mean only: the weighted centre of its cells */
} Attempt;

/* Tries the bilinear stencil at (px, py); 0 on success. */
static int try_point(const Ibm *ibm, double px, double py, const uint8_t *exclude, Attempt *a,
                     Box *dep) {
    const Grid *g = ibm->grid;
    box_add(dep, px, py, 0.0);
    const int i0 = locate(&g->ax[0], px), j0 = locate(&g->ax[1], py);
    if (i0 < -1 || j0 < -1) return -1;
    if (ibm_point_inside(ibm, px, py)) return -1;
    const double *cx = g->ax[0].center, *cy = g->ax[1].center;
    const double hx = cx[i0 + 1] - cx[i0], hy = cy[j0 + 1] - cy[j0];
    int fluid[4], nf = 0;
    double bx[4], by[4], nx[4], ny[4];
    for (int m = 0; m < 4; m++) {
        const int i = i0 + (m & 1), j = j0 + (m >> 1);
        const double x = cx[i], y = cy[j];
        box_add(dep, x, y, 0.0);
        const int64_t k = grid_index(g, i, j);
        const int kind = ibm_node_kind(ibm, i, j);
        const bool interior = i >= 0 && j >= 0 && i < g->nx && j < g->ny;
        int ok = kind == FLOW_CELL_FLUID && !(exclude && interior && exclude[k]);
        if (ok && ibm_blocked(ibm, px, py, x, y)) ok = 0;
        fluid[m] = ok;
        a->node[m] = k;
        a->rseg[m] = IBM_NODE_FLUID;
        a->rt[m] = 0.0;
        bx[m] = by[m] = nx[m] = ny[m] = 0.0;
        if (ok) {
            nf++;
            continue;
        }
        const IbmWallPoint wp = ibm_nearest(ibm, x, y);
        box_add(dep, x, y, wp.d);
        double vx, vy;
        ibm_normal(ibm, &wp, x, y, kind != FLOW_CELL_FLUID, &vx, &vy);
        a->rseg[m] = wp.seg;
        a->rt[m] = wp.t;
        bx[m] = (wp.bx - cx[i0]) / hx;
        by[m] = (wp.by - cy[j0]) / hy;
        nx[m] = vx;
        ny[m] = vy;
    }
    a->nrep = 4 - nf;
    if (nf < 2) return -1;
    if (ibm_bilinear_weights((px - cx[i0]) / hx, (py - cy[j0]) / hy, hx, hy, fluid, bx, by, nx, ny,
                             a->wd, a->wn) < 0)
        return -1;
    double sd = 0.0, sn = 0.0;
    for (int m = 0; m < 4; m++) {
        sd += fabs(a->wd[m]);
        if (fluid[m]) sn += fabs(a->wn[m]);
    }
    a->wsum = fmax(sd, sn);
    if (!(a->wsum <= IBM_WEIGHT_MAX)) return -1;
    return 0;
}

/* Inverse-distance mean of up to 4 usable fluid cells of the 5 x 5 block
 * around cell (ic, jc), nearest to the reference point (qx, qy). Weights go
 * to both wd and wn, their weighted centre to a->mx, a->my; returns the
 * number of cells used. */
static int nearest_mean(const Ibm *ibm, int ic, int jc, double qx, double qy, int check_sight,
                        const uint8_t *exclude, Attempt *a, Box *dep) {
    const Grid *g = ibm->grid;
    const double *cx = g->ax[0].center, *cy = g->ax[1].center;
    int64_t cand[4];
    double cd2[4];
    int nc = 0;
    for (int pass = 0; pass < 2 && nc == 0; pass++) {
        for (int b = -2; b <= 2; b++)
            for (int q = -2; q <= 2; q++) {
                const int i = ic + q, j = jc + b;
                if (i < 0 || j < 0 || i >= g->nx || j >= g->ny) continue;
                const int64_t k = grid_index(g, i, j);
                box_add(dep, cx[i], cy[j], 0.0);
                if (ibm->kind[k] != FLOW_CELL_FLUID || (exclude && exclude[k])) continue;
                if (pass == 0 && check_sight && ibm_blocked(ibm, qx, qy, cx[i], cy[j])) continue;
                const double d2 = (cx[i] - qx) * (cx[i] - qx) + (cy[j] - qy) * (cy[j] - qy);
                /* keep the 4 nearest, ties by cell index (insertion sort) */
                int pos = nc < 4 ? nc : 4;
                while (pos > 0 && (d2 < cd2[pos - 1] || (d2 == cd2[pos - 1] && k < cand[pos - 1])))
                    pos--;
                if (pos >= 4) continue;
                for (int r = (nc < 4 ? nc : 3); r > pos; r--) {
                    cand[r] = cand[r - 1];
                    cd2[r] = cd2[r - 1];
                }
                cand[pos] = k;
                cd2[pos] = d2;
                if (nc < 4) nc++;
            }
    }
    double wsum = 0.0, w[4] = {0, 0, 0, 0};
    for (int m = 0; m < nc; m++) {
        w[m] = 1.0 / (cd2[m] + 1e-300);
        wsum += w[m];
    }
    a->mx = a->my = 0.0;
    for (int m = 0; m < 4; m++) {
        a->rt[m] = 0.0;
        if (m < nc) {
            a->node[m] = cand[m];
            a->rseg[m] = IBM_NODE_FLUID;
            a->wd[m] = a->wn[m] = w[m] / wsum;
            /* centre of the mean, from the cell's (i, j) */
            const int64_t k = cand[m];
            const int j = (int)(k / g->stride) - GRID_NG, i = (int)(k % g->stride) - GRID_NG;
            a->mx += a->wd[m] * cx[i];
            a->my += a->wd[m] * cy[j];
        } else {
            a->node[m] = -1;
            a->rseg[m] = IBM_NODE_UNUSED;
            a->wd[m] = a->wn[m] = 0.0;
        }
    }
    a->nrep = 0;
    a->wsum = nc > 0 ? 1.0 : 0.0;
    return nc;
}

static void store(IbmStencilSet *set, int e, const Attempt *a, int level, const Box *dep) {
    for (int m = 0; m < 4; m++) {
        set->node[4 * e + m] = a->node[m];
        set->rseg[4 * e + m] = a->rseg[m];
        set->rt[4 * e + m] = a->rt[m];
        set->wd[4 * e + m] = a->wd[m];
        set->wn[4 * e + m] = a->wn[m];
    }
    set->level[e] = (uint8_t)level;
    set->nrep[e] = (uint8_t)a->nrep;
    /* grown by a hair so that a wall exactly on the edge counts as touching */
    const double pad = 1e-9 * fmax(dep->xhi - dep->xlo, dep->yhi - dep->ylo) + 1e-300;
    set->dep[4 * e + 0] = dep->xlo - pad;
    set->dep[4 * e + 1] = dep->xhi + pad;
    set->dep[4 * e + 2] = dep->ylo - pad;
    set->dep[4 * e + 3] = dep->yhi + pad;
}

void ibm_build_ghost(const Ibm *ibm, int i, int j, IbmStencilSet *set, int e) {
    const Grid *g = ibm->grid;
    const double xc = g->ax[0].center[i], yc = g->ax[1].center[j];
    const IbmWallPoint w = ibm_nearest(ibm, xc, yc);
    const double d = w.d, bx = w.bx, by = w.by;
    double nx, ny;
    ibm_normal(ibm, &w, xc, yc, 1, &nx, &ny);
    Box dep = {xc, xc, yc, yc};
    box_add(&dep, xc, yc, d);
    const double h = hypot(g->ax[0].width[i], g->ax[1].width[j]);
    Attempt a;
    int level = -1;
    double px = xc, py = yc, ratio = 1.0;
    if (d > 0.0) {
        px = xc + 2.0 * d * nx; /* Eq. 31 */
        py = yc + 2.0 * d * ny;
        if (try_point(ibm, px, py, NULL, &a, &dep) == 0) level = IBM_LEVEL_IMAGE;
    }
    for (int k = 1; k <= 4 && level < 0; k++) {
        const double dk = d + k * h;
        px = bx + dk * nx;
        py = by + dk * ny;
        if (try_point(ibm, px, py, NULL, &a, &dep) == 0) {
            level = IBM_LEVEL_EXTENDED;
            ratio = d / dk;
        }
    }
    if (level < 0) {
        /* seen from just outside the wall point */
        const double qx = bx + 0.05 * h * nx, qy = by + 0.05 * h * ny;
        const int sight = !ibm_point_inside(ibm, qx, qy);
        nearest_mean(ibm, i, j, qx, qy, sight, NULL, &a, &dep);
        const double dm = (a.mx - bx) * nx + (a.my - by) * ny;
        ratio = dm > d ? d / dm : 1.0;
        px = a.mx;
        py = a.my;
        level = IBM_LEVEL_NEAREST;
    }
    set->cell[e] = grid_index(g, i, j);
    set->seg[e] = w.seg;
    set->t[e] = w.t;
    set->ratio[e] = ratio;
    set->body[e] = (uint8_t)ibm->seg_body[w.seg];
    set->geo[e] = (IbmStencilGeo){
        .bix = w.bx, .biy = w.by, .nx = nx, .ny = ny, .dist = w.d, .px = px, .py = py};
    store(set, e, &a, level, &dep);
}

void ibm_place_point(const Ibm *ibm, double px, double py, double dist, IbmStencilSet *set, int e) {
    const Grid *g = ibm->grid;
    set->cell[e] =
        grid_index(g, grid_axis_cell_of(&g->ax[0], px), grid_axis_cell_of(&g->ax[1], py));
    set->seg[e] = -1;
    set->t[e] = 0.0;
    set->ratio[e] = dist;
    set->body[e] = 0;
    set->geo[e] = (IbmStencilGeo){.dist = dist, .px = px, .py = py};
    set->level[e] = IBM_LEVEL_ELSEWHERE;
}

void ibm_build_point(const Ibm *ibm, double px, double py, double dist, const uint8_t *exclude,
                     IbmStencilSet *set, int e) {
    const Grid *g = ibm->grid;
    Box dep = {px, px, py, py};
    Attempt a;
    int level = IBM_LEVEL_IMAGE;
    if (try_point(ibm, px, py, exclude, &a, &dep) < 0) {
        level = IBM_LEVEL_NEAREST;
        const int ic = grid_axis_cell_of(&g->ax[0], px), jc = grid_axis_cell_of(&g->ax[1], py);
        nearest_mean(ibm, ic, jc, px, py, !ibm_point_inside(ibm, px, py), exclude, &a, &dep);
    }
    ibm_place_point(ibm, px, py, dist, set, e);
    store(set, e, &a, level, &dep);
}
