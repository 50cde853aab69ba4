/* Bond-based PD force.
 *
 * Eq. 29 gives the pair force density of bond i-j as
 *     f_ij = c s_ij (y_ij / |y_ij|),   s_ij = (|y_ij| - |xi_ij|) / |xi_ij|,
 * and Eq. 28 sums f_ij beta_ij nu_ij V_j over the family. Folding the
 * constant factors into k_ij = c beta_ij nu_ij V_j / |xi_ij| gives
 *     force_i = sum_j k_ij (|y| - |xi|) y / |y| = sum_j k_ij (1 - |xi|/|y|) y,
 * and |xi|/|y| = sqrt(|xi|^2 / |y|^2) costs one division and one square root
 * per bond. The failure test s >= s_c is |y|^2 >= (1 + s_c)^2 |xi|^2, with no
 * root at all.
 *
 * Order of force and failure: lambda_s of Eq. 17 is a history variable. The
 * force at step n uses the bond state left by step n-1, and the bonds
 * stretched past s_c are broken afterwards, for step n+1 - the order of
 * Madenci and Oterkus' reference code. On the 20 m/s plate the other order
 * (break, then take the force) made one crack tip branch at x = -17 mm while
 * the reference (and this order) runs straight to +-22 mm.
 *
 * The point body (the reference, a sequential sum over the row) and the
 * conditional store that breaks a bond are in force_kernel.h; what the CPU
 * runs is the same arithmetic on the body's lattice view (stencil.h),
 * eight points at a time, below. */
#include "solid/bond/force.h"

#include "core/status.h"
#include "core/balance.h"
#include "core/parallel.h"
#include "solid/bond/force_kernel.h"
#include "solid/bond/stencil.h"

#include <math.h>
#if defined(__AVX512F__)
#include <immintrin.h>
#endif

void pd_force_kernel_2d(int64_t lo, int64_t hi, const double *restrict x, const double *restrict y,
                        const double *restrict ux, const double *restrict uy,
                        const int64_t *restrict first, const int32_t *restrict nbr,
                        float *restrict coef, double scale, double limit2, double *restrict fx,
                        double *restrict fy) {
    for (int64_t i = lo; i < hi; i++)
        bond_force_point_2d(i, x, y, ux, uy, first, nbr, coef, scale, limit2, fx, fy);
}

void pd_force_kernel_3d(int64_t lo, int64_t hi, const double *restrict x, const double *restrict y,
                        const double *restrict z, const double *restrict ux,
                        const double *restrict uy, const double *restrict uz,
                        const int64_t *restrict first, const int32_t *restrict nbr,
                        float *restrict coef, double scale, double limit2, double *restrict fx,
                        double *restrict fy, double *restrict fz) {
    for (int64_t i = lo; i < hi; i++)
        bond_force_point_3d(i, x, y, z, ux, uy, uz, first, nbr, coef, scale, limit2, fx, fy, fz);
}

/* Breaks, in the body's rows, the bond of the point in `cell` to the one
 * `shift` cells on (the view's copy is already 0): rare, so found by a
 * walk along the row. */
static void break_in_row(int64_t cell, int64_t shift, const int32_t *restrict cell_point,
                         const int64_t *restrict first, const int32_t *restrict nbr,
                         float *restrict bond_coef) {
    const int32_t i = cell_point[cell], j = cell_point[cell + shift];
    for (int64_t e = first[i]; e < first[i + 1]; e++)
        if (nbr[e] == j) {
            bond_coef[e] = 0.0f;
            return;
        }
}

/* The sums of a chunk's eight cells (sum[axis][lane]) to the forces of
 * its held points. */
static void store_chunk(int dim, int64_t cell, double sum[3][8], const int32_t *restrict cell_point,
                        int64_t held, double scale, double *const force[3]) {
    for (int l = 0; l < 8; l++) {
        const int32_t i = cell_point[cell + l];
        if (i >= 0 && i < held)
            for (int a = 0; a < dim; a++) force[a][i] = scale * sum[a][l];
    }
}

/* Chunks [lo, hi) of a view of DIM axes (2 or 3, a constant in each
 * instance below): per chunk, its eight cells' bonds offset by offset,
 * bond_force_point_2d / _3d's arithmetic op for op, a lane a point. */
static inline __attribute__((always_inline)) void
stencil_chunks(const int DIM, int64_t lo, int64_t hi, const int64_t *restrict chunk_cell,
               int offsets, const int64_t *restrict shift, const double *const x[3],
               const double *const u[3], uint16_t *restrict state, const int32_t *restrict block,
               const float *restrict magnitude, const int32_t *restrict cell_point, int64_t held,
               const int64_t *restrict first, const int32_t *restrict nbr,
               float *restrict bond_coef, double scale, double limit2, double *const force[3]) {
#if defined(__AVX512F__) && defined(__AVX512VL__)
    const __m512d lim = _mm512_set1_pd(limit2), one = _mm512_set1_pd(1.0);
    for (int64_t q = lo; q < hi; q++) {
        const int64_t c = chunk_cell[q];
        uint16_t *sq = state + q * offsets;
        const float *kq = magnitude + (int64_t)block[q] * offsets * 8;
        __m512d xi[3], ui[3], s[3];
        for (int a = 0; a < DIM; a++) {
            xi[a] = _mm512_load_pd(x[a] + c), ui[a] = _mm512_load_pd(u[a] + c);
            s[a] = _mm512_setzero_pd();
        }
        for (int o = 0; o < offsets; o++) {
            const int64_t j = c + shift[o];
            const unsigned st = sq[o];
            const __mmask8 bonded = (__mmask8)st, live = (__mmask8)(st >> 8 & st);
            const __m512d k = _mm512_cvtps_pd(_mm256_load_ps(kq + 8 * o));
            __m512d e[3], r[3];
            for (int a = 0; a < DIM; a++) {
                e[a] = _mm512_sub_pd(_mm512_loadu_pd(x[a] + j), xi[a]);
                r[a] = _mm512_add_pd(e[a], _mm512_sub_pd(_mm512_loadu_pd(u[a] + j), ui[a]));
            }
            __m512d e2 = _mm512_add_pd(_mm512_mul_pd(e[0], e[0]), _mm512_mul_pd(e[1], e[1]));
            __m512d r2 = _mm512_add_pd(_mm512_mul_pd(r[0], r[0]), _mm512_mul_pd(r[1], r[1]));
            if (DIM == 3) {
                e2 = _mm512_add_pd(e2, _mm512_mul_pd(e[2], e[2]));
                r2 = _mm512_add_pd(r2, _mm512_mul_pd(r[2], r[2]));
            }
            const __m512d root = _mm512_sqrt_pd(_mm512_div_pd(e2, r2));
            /* no bond: no force, whatever the cells hold */
            const __m512d f = _mm512_maskz_mul_pd(bonded, k, _mm512_sub_pd(one, root));
            /* a breakable bond stretched past s_c: broken */
            const __mmask8 over =
                _mm512_mask_cmp_pd_mask(live, r2, _mm512_mul_pd(lim, e2), _CMP_GT_OQ);
            if (over) {
                sq[o] = (uint16_t)(st & ~(unsigned)over);
                for (int l = 0; l < 8; l++)
                    if (over >> l & 1)
                        break_in_row(c + l, shift[o], cell_point, first, nbr, bond_coef);
            }
            for (int a = 0; a < DIM; a++) s[a] = _mm512_add_pd(s[a], _mm512_mul_pd(f, r[a]));
        }
        double sum[3][8];
        for (int a = 0; a < DIM; a++) _mm512_storeu_pd(sum[a], s[a]);
        store_chunk(DIM, c, sum, cell_point, held, scale, force);
    }
#else
    for (int64_t q = lo; q < hi; q++) {
        const int64_t c = chunk_cell[q];
        uint16_t *sq = state + q * offsets;
        const float *kq = magnitude + (int64_t)block[q] * offsets * 8;
        double sum[3][8] = {{0}};
        for (int o = 0; o < offsets; o++) {
            const int64_t sh = shift[o];
            const float *k8 = kq + 8 * o;
            const unsigned st = sq[o];
            unsigned broke = 0;
#pragma omp simd reduction(| : broke)
            for (int l = 0; l < 8; l++) {
                const int64_t i = c + l, j = i + sh;
                double e[3], r[3];
                for (int a = 0; a < DIM; a++) {
                    e[a] = x[a][j] - x[a][i];
                    r[a] = e[a] + (u[a][j] - u[a][i]);
                }
                double e2 = e[0] * e[0] + e[1] * e[1], r2 = r[0] * r[0] + r[1] * r[1];
                if (DIM == 3) e2 += e[2] * e[2], r2 += r[2] * r[2];
                const double g = (double)k8[l] * (1.0 - sqrt(e2 / r2));
                const double f = st >> l & 1 ? g : 0.0; /* a select: g is formed either way */
                const unsigned live = st >> (8 + l) & st >> l & 1u;
                broke |= (live & (unsigned)(r2 > limit2 * e2)) << l;
                for (int a = 0; a < DIM; a++) sum[a][l] += f * r[a];
            }
            if (broke) sq[o] = (uint16_t)(st & ~broke);
            for (int l = 0; broke && l < 8; l++)
                if (broke >> l & 1) break_in_row(c + l, sh, cell_point, first, nbr, bond_coef);
        }
        store_chunk(DIM, c, sum, cell_point, held, scale, force);
    }
#endif
}

void pd_force_kernel_stencil(int dim, int64_t lo, int64_t hi, const int64_t *restrict chunk_cell,
                             int offsets, const int64_t *restrict shift, const double *const x[3],
                             const double *const u[3], uint16_t *restrict state,
                             const int32_t *restrict block, const float *restrict magnitude,
                             const int32_t *restrict cell_point, int64_t held,
                             const int64_t *restrict first, const int32_t *restrict nbr,
                             float *restrict bond_coef, double scale, double limit2,
                             double *const force[3]) {
    if (dim == 2)
        stencil_chunks(2, lo, hi, chunk_cell, offsets, shift, x, u, state, block, magnitude,
                       cell_point, held, first, nbr, bond_coef, scale, limit2, force);
    else
        stencil_chunks(3, lo, hi, chunk_cell, offsets, shift, x, u, state, block, magnitude,
                       cell_point, held, first, nbr, bond_coef, scale, limit2, force);
}

/* Points [lo, hi) by the plain kernels (no view: stencil.h, too sparse
 * a box), whose bits are the view's. */
static void force_plain(BondBody *b, int64_t lo, int64_t hi, double scale, double limit2) {
    if (b->dim == 2)
        pd_force_kernel_2d(lo, hi, b->x[0], b->x[1], b->u[0], b->u[1], b->bond_first, b->bond_nbr,
                           b->bond_coef, scale, limit2, b->force[0], b->force[1]);
    else
        pd_force_kernel_3d(lo, hi, b->x[0], b->x[1], b->x[2], b->u[0], b->u[1], b->u[2],
                           b->bond_first, b->bond_nbr, b->bond_coef, scale, limit2, b->force[0],
                           b->force[1], b->force[2]);
}

int pd_force_compute(BondBody *body) {
    const double scale = body->coef_scale, limit2 = body->stretch_limit2;
    BondStencil *s = body->stencil;
    if (s) {
        if (!s->u_current) bond_stencil_refresh(s, body);
        s->u_current = false; /* whoever writes u next need not know of the view */
    }
    /* the view's active chunks, or the points; each thread a contiguous
     * share, moved toward equal times step by step (core/balance.h: a
     * point's force is its own arithmetic, whichever thread takes it) */
    const int64_t items = s ? s->chunks : body->n;
#pragma omp parallel if (body->bond_count >= PARALLEL_MIN_ITEMS)
    {
        int64_t lo, hi;
        const double started = balance_begin(&body->force_balance, items, &lo, &hi);
        if (s)
            pd_force_kernel_stencil(body->dim, lo, hi, s->chunk_cell, s->offsets, s->shift,
                                    (const double *const *)s->x, (const double *const *)s->u,
                                    s->state, s->block, s->magnitude, s->cell_point, body->n,
                                    body->bond_first, body->bond_nbr, body->bond_coef, scale,
                                    limit2, body->force);
        else
            force_plain(body, lo, hi, scale, limit2);
        balance_end(&body->force_balance, started);
    }
    balance_update(&body->force_balance);
    if (body->has_contact)
        return pd_contact_add(&body->contact, (const double *const *)body->x,
                              (const double *const *)body->u, body->volume, body->force);
    return NSPD_OK;
}
