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
 * The point body, its SIMD reduction over the bonds and the conditional
 * store that breaks a bond are in force_kernel.h. */
#include "solid/bond/force.h"
#include "core/parallel.h"
#include "solid/bond/force_kernel.h"

#include <math.h>
#if defined(__AVX2__)
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

#if defined(__AVX2__)
/* Four bonds b .. b + 3 of point (xi, yi, uxi, uyi) in 256-bit lanes:
 * the neighbours' packed rows loaded whole and transposed in registers
 * (four loads and eight shuffles where the plain kernel gathers four
 * arrays), their terms f rx and f ry added to (sx, sy), the bonds the step
 * stretched past s_c broken. The arithmetic of bond_force_point_2d, op
 * for op. */
static inline __attribute__((always_inline)) void
four_bonds(const double *restrict p, const int32_t *restrict nbr, float *restrict coef, int64_t b,
           __m256d xi, __m256d yi, __m256d uxi, __m256d uyi, __m256d lim, __m256d *sx,
           __m256d *sy) {
    const __m256d r0 = _mm256_load_pd(p + 4 * (int64_t)nbr[b]);
    const __m256d r1 = _mm256_load_pd(p + 4 * (int64_t)nbr[b + 1]);
    const __m256d r2 = _mm256_load_pd(p + 4 * (int64_t)nbr[b + 2]);
    const __m256d r3 = _mm256_load_pd(p + 4 * (int64_t)nbr[b + 3]);
    const __m256d t0 = _mm256_unpacklo_pd(r0, r1), t1 = _mm256_unpackhi_pd(r0, r1);
    const __m256d t2 = _mm256_unpacklo_pd(r2, r3), t3 = _mm256_unpackhi_pd(r2, r3);
    const __m256d xj = _mm256_permute2f128_pd(t0, t2, 0x20);
    const __m256d yj = _mm256_permute2f128_pd(t1, t3, 0x20);
    const __m256d uxj = _mm256_permute2f128_pd(t0, t2, 0x31);
    const __m256d uyj = _mm256_permute2f128_pd(t1, t3, 0x31);
    const __m128 kf = _mm_loadu_ps(coef + b);
    const __m256d k = _mm256_cvtps_pd(_mm_andnot_ps(_mm_set1_ps(-0.0f), kf)); /* |k| */
    const __m256d ex = _mm256_sub_pd(xj, xi), ey = _mm256_sub_pd(yj, yi);
    const __m256d rx = _mm256_add_pd(ex, _mm256_sub_pd(uxj, uxi));
    const __m256d ry = _mm256_add_pd(ey, _mm256_sub_pd(uyj, uyi));
    const __m256d e2 = _mm256_add_pd(_mm256_mul_pd(ex, ex), _mm256_mul_pd(ey, ey));
    const __m256d r2s = _mm256_add_pd(_mm256_mul_pd(rx, rx), _mm256_mul_pd(ry, ry));
    const __m256d root = _mm256_sqrt_pd(_mm256_div_pd(e2, r2s));
    const __m256d f = _mm256_mul_pd(k, _mm256_sub_pd(_mm256_set1_pd(1.0), root));
    /* a breakable bond (k > 0) stretched past s_c: its coefficient to 0 */
    const __m128 live = _mm_cmpgt_ps(kf, _mm_setzero_ps());
    const __m256d over = _mm256_cmp_pd(r2s, _mm256_mul_pd(lim, e2), _CMP_GT_OQ);
    const __m128 broken = _mm_and_ps(live, _mm256_cvtpd_ps(over)); /* the mask, narrowed */
    if (_mm_movemask_ps(broken)) _mm_storeu_ps(coef + b, _mm_andnot_ps(broken, kf));
    *sx = _mm256_add_pd(*sx, _mm256_mul_pd(f, rx));
    *sy = _mm256_add_pd(*sy, _mm256_mul_pd(f, ry));
}
#endif

void pd_force_kernel_2d_packed(int64_t lo, int64_t hi, const double *restrict x,
                               const double *restrict y, const double *restrict ux,
                               const double *restrict uy, const double *restrict p,
                               const int64_t *restrict first, const int32_t *restrict nbr,
                               float *restrict coef, double scale, double limit2,
                               double *restrict fx, double *restrict fy) {
#if defined(__AVX2__)
    (void)x, (void)y, (void)ux, (void)uy;
    const __m256d lim = _mm256_set1_pd(limit2);
    for (int64_t i = lo; i < hi; i++) {
        const double *pi = p + 4 * i;
        const __m256d xi = _mm256_set1_pd(pi[0]), yi = _mm256_set1_pd(pi[1]);
        const __m256d uxi = _mm256_set1_pd(pi[2]), uyi = _mm256_set1_pd(pi[3]);
        __m256d sx0 = _mm256_setzero_pd(), sy0 = sx0, sx1 = sx0, sy1 = sx0;
        const int64_t b0 = first[i], b1 = first[i + 1];
        int64_t b = b0;
        /* GCC's omp simd reduction in bond_force_point_2d (-O3, AVX-512
         * with 256-bit vectors: tests/unit/solid/bond/test_force.c holds
         * this to it bit for bit) keeps 8 lanes, bond b0 + 8 t + l in lane
         * l, while 8 bonds are left; adds the rest of the row (all of a
         * row of fewer than 8) into lane 0 in order; and sums the lanes 0
         * to 7 onto 0.0 */
        if (b1 - b0 >= 8)
            for (; b + 8 <= b1; b += 8) {
                four_bonds(p, nbr, coef, b, xi, yi, uxi, uyi, lim, &sx0, &sy0);
                four_bonds(p, nbr, coef, b + 4, xi, yi, uxi, uyi, lim, &sx1, &sy1);
            }
        double lx[8], ly[8];
        _mm256_storeu_pd(lx, sx0), _mm256_storeu_pd(lx + 4, sx1);
        _mm256_storeu_pd(ly, sy0), _mm256_storeu_pd(ly + 4, sy1);
        for (; b + 4 <= b1; b += 4) { /* terms in lanes, added into lane 0 in order */
            __m256d tx = _mm256_setzero_pd(), ty = tx;
            four_bonds(p, nbr, coef, b, xi, yi, uxi, uyi, lim, &tx, &ty);
            double ax[4], ay[4];
            _mm256_storeu_pd(ax, tx), _mm256_storeu_pd(ay, ty);
            for (int q = 0; q < 4; q++) lx[0] += ax[q], ly[0] += ay[q];
        }
        for (; b < b1; b++) {
            const int64_t j = nbr[b];
            const float k = coef[b];
            const double ex = p[4 * j] - pi[0], ey = p[4 * j + 1] - pi[1];
            const double rx = ex + (p[4 * j + 2] - pi[2]), ry = ey + (p[4 * j + 3] - pi[3]);
            const double e2 = ex * ex + ey * ey, r2 = rx * rx + ry * ry;
            const double f = (double)fabsf(k) * (1.0 - sqrt(e2 / r2));
            if ((k > 0.0f) & (r2 > limit2 * e2)) coef[b] = 0.0f;
            lx[0] += f * rx;
            ly[0] += f * ry;
        }
        double sx = 0.0, sy = 0.0;
        for (int l = 0; l < 8; l++) sx += lx[l], sy += ly[l];
        fx[i] = scale * sx;
        fy[i] = scale * sy;
    }
#else
    (void)p; /* no AVX2: the plain kernel */
    pd_force_kernel_2d(lo, hi, x, y, ux, uy, first, nbr, coef, scale, limit2, fx, fy);
#endif
}

#if defined(__AVX2__)
/* The 3D form of four_bonds: packed rows of 8 (x, y, z, 0, ux, uy, uz,
 * 0), two 256-bit loads a bond. */
static inline __attribute__((always_inline)) void
four_bonds_3d(const double *restrict p, const int32_t *restrict nbr, float *restrict coef,
              int64_t b, const __m256d c[6], __m256d lim, __m256d s[3]) {
    __m256d col[8]; /* x, y, z, -, ux, uy, uz, - of the four */
    for (int half = 0; half < 2; half++) {
        const __m256d r0 = _mm256_load_pd(p + 8 * (int64_t)nbr[b] + 4 * half);
        const __m256d r1 = _mm256_load_pd(p + 8 * (int64_t)nbr[b + 1] + 4 * half);
        const __m256d r2 = _mm256_load_pd(p + 8 * (int64_t)nbr[b + 2] + 4 * half);
        const __m256d r3 = _mm256_load_pd(p + 8 * (int64_t)nbr[b + 3] + 4 * half);
        const __m256d t0 = _mm256_unpacklo_pd(r0, r1), t1 = _mm256_unpackhi_pd(r0, r1);
        const __m256d t2 = _mm256_unpacklo_pd(r2, r3), t3 = _mm256_unpackhi_pd(r2, r3);
        col[4 * half] = _mm256_permute2f128_pd(t0, t2, 0x20);
        col[4 * half + 1] = _mm256_permute2f128_pd(t1, t3, 0x20);
        col[4 * half + 2] = _mm256_permute2f128_pd(t0, t2, 0x31);
    }
    const __m128 kf = _mm_loadu_ps(coef + b);
    const __m256d k = _mm256_cvtps_pd(_mm_andnot_ps(_mm_set1_ps(-0.0f), kf)); /* |k| */
    __m256d e[3], r[3];
    for (int a = 0; a < 3; a++) {
        e[a] = _mm256_sub_pd(col[a], c[a]);
        r[a] = _mm256_add_pd(e[a], _mm256_sub_pd(col[4 + a], c[3 + a]));
    }
    const __m256d e2 =
        _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(e[0], e[0]), _mm256_mul_pd(e[1], e[1])),
                      _mm256_mul_pd(e[2], e[2]));
    const __m256d r2s =
        _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(r[0], r[0]), _mm256_mul_pd(r[1], r[1])),
                      _mm256_mul_pd(r[2], r[2]));
    const __m256d root = _mm256_sqrt_pd(_mm256_div_pd(e2, r2s));
    const __m256d f = _mm256_mul_pd(k, _mm256_sub_pd(_mm256_set1_pd(1.0), root));
    const __m128 live = _mm_cmpgt_ps(kf, _mm_setzero_ps());
    const __m256d over = _mm256_cmp_pd(r2s, _mm256_mul_pd(lim, e2), _CMP_GT_OQ);
    const __m128 broken = _mm_and_ps(live, _mm256_cvtpd_ps(over));
    if (_mm_movemask_ps(broken)) _mm_storeu_ps(coef + b, _mm_andnot_ps(broken, kf));
    for (int a = 0; a < 3; a++) s[a] = _mm256_add_pd(s[a], _mm256_mul_pd(f, r[a]));
}
#endif

void pd_force_kernel_3d_packed(int64_t lo, int64_t hi, const double *const x[3],
                               const double *const u[3], const double *restrict p,
                               const int64_t *restrict first, const int32_t *restrict nbr,
                               float *restrict coef, double scale, double limit2,
                               double *const force[3]) {
#if defined(__AVX2__)
    (void)x, (void)u;
    const __m256d lim = _mm256_set1_pd(limit2);
    for (int64_t i = lo; i < hi; i++) {
        const double *pi = p + 8 * i;
        const __m256d c[6] = {_mm256_set1_pd(pi[0]), _mm256_set1_pd(pi[1]), _mm256_set1_pd(pi[2]),
                              _mm256_set1_pd(pi[4]), _mm256_set1_pd(pi[5]), _mm256_set1_pd(pi[6])};
        __m256d s0[3], s1[3];
        for (int a = 0; a < 3; a++) s0[a] = s1[a] = _mm256_setzero_pd();
        const int64_t b0 = first[i], b1 = first[i + 1];
        int64_t b = b0;
        /* the 2D kernel's lanes and order (pd_force_kernel_2d_packed) */
        if (b1 - b0 >= 8)
            for (; b + 8 <= b1; b += 8) {
                four_bonds_3d(p, nbr, coef, b, c, lim, s0);
                four_bonds_3d(p, nbr, coef, b + 4, c, lim, s1);
            }
        double lane[3][8];
        for (int a = 0; a < 3; a++)
            _mm256_storeu_pd(lane[a], s0[a]), _mm256_storeu_pd(lane[a] + 4, s1[a]);
        for (; b + 4 <= b1; b += 4) {
            __m256d t[3] = {_mm256_setzero_pd(), _mm256_setzero_pd(), _mm256_setzero_pd()};
            four_bonds_3d(p, nbr, coef, b, c, lim, t);
            for (int a = 0; a < 3; a++) {
                double v[4];
                _mm256_storeu_pd(v, t[a]);
                for (int q = 0; q < 4; q++) lane[a][0] += v[q];
            }
        }
        for (; b < b1; b++) {
            const int64_t j = nbr[b];
            const float k = coef[b];
            const double *pj = p + 8 * j;
            const double ex = pj[0] - pi[0], ey = pj[1] - pi[1], ez = pj[2] - pi[2];
            const double rx = ex + (pj[4] - pi[4]), ry = ey + (pj[5] - pi[5]),
                         rz = ez + (pj[6] - pi[6]);
            const double e2 = ex * ex + ey * ey + ez * ez, r2 = rx * rx + ry * ry + rz * rz;
            const double f = (double)fabsf(k) * (1.0 - sqrt(e2 / r2));
            if ((k > 0.0f) & (r2 > limit2 * e2)) coef[b] = 0.0f;
            lane[0][0] += f * rx;
            lane[1][0] += f * ry;
            lane[2][0] += f * rz;
        }
        for (int a = 0; a < 3; a++) {
            double sum = 0.0;
            for (int l = 0; l < 8; l++) sum += lane[a][l];
            force[a][i] = scale * sum;
        }
    }
#else
    (void)p; /* no AVX2: the plain kernel */
    pd_force_kernel_3d(lo, hi, x[0], x[1], x[2], u[0], u[1], u[2], first, nbr, coef, scale, limit2,
                       force[0], force[1], force[2]);
#endif
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

/* Rows per OpenMP chunk: large enough to amortise scheduling, small enough
 * to balance two threads on a body of a few thousand points (the panel's
 * 3,224: 13 blocks). The team is taken by the bond count (core/parallel.h). */
enum { FORCE_BLOCK = 256 };

void pd_force_compute(BondBody *body) {
    const int64_t n = body->n, blocks = (n + FORCE_BLOCK - 1) / FORCE_BLOCK;
    const double scale = body->coef_scale, limit2 = body->stretch_limit2;
    if (body->dim == 2) {
        const int64_t all = n + body->ghosts;
        double *p = body->packed;
#pragma omp parallel for schedule(static) if (all >= PARALLEL_MIN_ITEMS)
        for (int64_t i = 0; i < all; i++) {
            p[4 * i] = body->x[0][i], p[4 * i + 1] = body->x[1][i];
            p[4 * i + 2] = body->u[0][i], p[4 * i + 3] = body->u[1][i];
        }
#pragma omp parallel for schedule(static) if (body->bond_count >= PARALLEL_MIN_ITEMS)
        for (int64_t blk = 0; blk < blocks; blk++) {
            int64_t lo = blk * FORCE_BLOCK, hi = lo + FORCE_BLOCK < n ? lo + FORCE_BLOCK : n;
            pd_force_kernel_2d_packed(lo, hi, body->x[0], body->x[1], body->u[0], body->u[1], p,
                                      body->bond_first, body->bond_nbr, body->bond_coef, scale,
                                      limit2, body->force[0], body->force[1]);
        }
    } else {
        const int64_t all = n + body->ghosts;
        double *p = body->packed;
#pragma omp parallel for schedule(static) if (all >= PARALLEL_MIN_ITEMS)
        for (int64_t i = 0; i < all; i++)
            for (int a = 0; a < 3; a++)
                p[8 * i + a] = body->x[a][i], p[8 * i + 4 + a] = body->u[a][i];
#pragma omp parallel for schedule(static) if (body->bond_count >= PARALLEL_MIN_ITEMS)
        for (int64_t blk = 0; blk < blocks; blk++) {
            int64_t lo = blk * FORCE_BLOCK, hi = lo + FORCE_BLOCK < n ? lo + FORCE_BLOCK : n;
            pd_force_kernel_3d_packed(lo, hi, (const double *const *)body->x,
                                      (const double *const *)body->u, p, body->bond_first,
                                      body->bond_nbr, body->bond_coef, scale, limit2, body->force);
        }
    }
}
