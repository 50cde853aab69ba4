/* Issue 27 experiment (docs/PERFORMANCE.md, "Rooflines of the kernels"):
 * the bond-based force's kernel (solid/bond/force_kernel.h, CSR, an omp
 * simd reduction over a point's bonds, four gathers a bond) on the plate of
 * plate.h, against the same arithmetic with each point's x, y, ux, uy
 * packed in 32 bytes (refreshed once a step: a copy of 4 doubles a point)
 * and four bonds at a time loaded as four 256-bit rows and transposed in
 * registers (AVX2 intrinsics) instead of gathered. The same sums per lane
 * (lane l: the bonds l, l + 4, ...) and the lanes added as GCC's reduction
 * adds them is not promised: the forces are compared with a stated bound.
 * Prints bond updates/s of both.
 *   gcc -O3 -march=native -fno-math-errno -fopenmp-simd -I../../src packed.c -lm && ./a.out */
#include "plate.h"
#include "solid/bond/force_kernel.h"

#include <immintrin.h>
#include <stdio.h>

/* Four bonds b .. b + 3 of point (xi, yi, uxi, uyi): their terms f rx and
 * f ry added to the lanes (sx, sy); the broken ones' coefficients zeroed. */
static inline void four_bonds(const double *restrict p, const int32_t *restrict nbr,
                              float *restrict coef, int64_t b, __m256d xi, __m256d yi, __m256d uxi,
                              __m256d uyi, __m256d lim, __m256d *sx, __m256d *sy) {
    /* four neighbours' rows, transposed: x, y, ux, uy of the four */
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
    const __m256d k = _mm256_cvtps_pd(_mm_andnot_ps(_mm_set1_ps(-0.0f), kf));
    const __m256d ex = _mm256_sub_pd(xj, xi), ey = _mm256_sub_pd(yj, yi);
    const __m256d rx = _mm256_add_pd(ex, _mm256_sub_pd(uxj, uxi));
    const __m256d ry = _mm256_add_pd(ey, _mm256_sub_pd(uyj, uyi));
    const __m256d e2 = _mm256_add_pd(_mm256_mul_pd(ex, ex), _mm256_mul_pd(ey, ey));
    const __m256d q2 = _mm256_add_pd(_mm256_mul_pd(rx, rx), _mm256_mul_pd(ry, ry));
    const __m256d f =
        _mm256_mul_pd(k, _mm256_sub_pd(_mm256_set1_pd(1.0), _mm256_sqrt_pd(_mm256_div_pd(e2, q2))));
    /* the failure test: a breakable bond (k > 0) stretched past s_c */
    const __m128 live = _mm_cmpgt_ps(kf, _mm_setzero_ps());
    const __m256d over = _mm256_cmp_pd(q2, _mm256_mul_pd(lim, e2), _CMP_GT_OQ);
    const __m128 brk = _mm_and_ps(live, _mm256_cvtpd_ps(over)); /* all-ones lanes stay NaN-ones */
    if (_mm_movemask_ps(brk)) _mm_storeu_ps(coef + b, _mm_andnot_ps(brk, kf));
    *sx = _mm256_add_pd(*sx, _mm256_mul_pd(f, rx));
    *sy = _mm256_add_pd(*sy, _mm256_mul_pd(f, ry));
}

/* point i of the packed layout p[4 j ..] = (x, y, ux, uy) of j, with
 * force_kernel.h's bits: GCC's omp simd reduction there keeps 8 lanes
 * (bond b0 + 8 t + l in lane l), adds the last m mod 8 bonds (all of a
 * row shorter than 8) into lane 0 in order, and sums the lanes from 0 to 7
 * onto 0.0 */
static inline void packed_point(int64_t i, const double *restrict p, const int64_t *restrict first,
                                const int32_t *restrict nbr, float *restrict coef, double limit2,
                                double *restrict fx, double *restrict fy) {
    const double *pi = p + 4 * i;
    const __m256d xi = _mm256_set1_pd(pi[0]), yi = _mm256_set1_pd(pi[1]);
    const __m256d uxi = _mm256_set1_pd(pi[2]), uyi = _mm256_set1_pd(pi[3]);
    const __m256d lim = _mm256_set1_pd(limit2);
    __m256d sx0 = _mm256_setzero_pd(), sy0 = sx0, sx1 = sx0, sy1 = sx0;
    const int64_t b0 = first[i], b1 = first[i + 1];
    int64_t b = b0;
    if (b1 - b0 >= 8)
        for (; b + 8 <= b1; b += 8) {
            four_bonds(p, nbr, coef, b, xi, yi, uxi, uyi, lim, &sx0, &sy0);
            four_bonds(p, nbr, coef, b + 4, xi, yi, uxi, uyi, lim, &sx1, &sy1);
        }
    double lx[8], ly[8];
    _mm256_storeu_pd(lx, sx0), _mm256_storeu_pd(lx + 4, sx1);
    _mm256_storeu_pd(ly, sy0), _mm256_storeu_pd(ly + 4, sy1);
    for (; b + 4 <= b1; b += 4) { /* the rest of the row, into lane 0 in order */
        __m256d tx4 = _mm256_setzero_pd(), ty4 = tx4;
        four_bonds(p, nbr, coef, b, xi, yi, uxi, uyi, lim, &tx4, &ty4);
        double ax[4], ay[4];
        _mm256_storeu_pd(ax, tx4), _mm256_storeu_pd(ay, ty4);
        for (int q = 0; q < 4; q++) lx[0] += ax[q], ly[0] += ay[q];
    }
    for (; b < b1; b++) {
        const int64_t j = nbr[b];
        const float kk = coef[b];
        const double ex = p[4 * j] - pi[0], ey = p[4 * j + 1] - pi[1];
        const double rx = ex + (p[4 * j + 2] - pi[2]), ry = ey + (p[4 * j + 3] - pi[3]);
        const double e2 = ex * ex + ey * ey, q2 = rx * rx + ry * ry;
        const double f = (double)fabsf(kk) * (1.0 - sqrt(e2 / q2));
        if ((kk > 0.0f) & (q2 > limit2 * e2)) coef[b] = 0.0f;
        lx[0] += f * rx;
        ly[0] += f * ry;
    }
    double tx = 0.0, ty = 0.0;
    for (int l = 0; l < 8; l++) tx += lx[l], ty += ly[l];
    fx[i] = tx;
    fy[i] = ty;
}

int main(void) {
    const int64_t n = (int64_t)PLATE_N * PLATE_N;
    double *x, *y, *ux, *uy;
    plate_points(&x, &y, &ux, &uy);
    double *fx = malloc(n * 8), *fy = malloc(n * 8), *gx = malloc(n * 8), *gy = malloc(n * 8);
    double *p = aligned_alloc(32, (size_t)n * 32);
    int64_t *first = malloc((n + 1) * 8);
    int32_t *nbr = malloc(n * 32 * 4);
    float *coef = malloc(n * 32 * 4);
    first[0] = 0;
    for (int64_t i = 0; i < n; i++) {
        const int m = plate_family(i, nbr + first[i]);
        for (int q = 0; q < m; q++) coef[first[i] + q] = 1.0f;
        first[i + 1] = first[i] + m;
    }
    const int64_t bonds = first[n];
    printf("%lld bonds\n", (long long)bonds);
    for (int64_t i = 0; i < n; i++)
        p[4 * i] = x[i], p[4 * i + 1] = y[i], p[4 * i + 2] = ux[i], p[4 * i + 3] = uy[i];
    for (int64_t i = 0; i < n; i++) {
        bond_force_point_2d(i, x, y, ux, uy, first, nbr, coef, 1.0, 1e9, fx, fy);
        packed_point(i, p, first, nbr, coef, 1e9, gx, gy);
    }
    double err = 0, big = 0;
    for (int64_t i = 0; i < n; i++) {
        err = fmax(err, fmax(fabs(gx[i] - fx[i]), fabs(gy[i] - fy[i])));
        big = fmax(big, fabs(fx[i]));
    }
    printf("packed: max difference %.3g of max %.3g\n", err, big);
    int64_t diff = 0, diff4 = 0;
    for (int64_t i = 0; i < n; i++)
        if (gx[i] != fx[i] || gy[i] != fy[i]) {
            diff++;
            diff4 += (first[i + 1] - first[i]) % 4 == 0;
        }
    printf("%lld points differ, %lld of them with a multiple of 4 bonds\n", (long long)diff,
           (long long)diff4);
    for (int rep = 0; rep < 3; rep++) {
        const double t0 = plate_now();
        for (int s = 0; s < 10; s++)
            for (int64_t i = 0; i < n; i++)
                bond_force_point_2d(i, x, y, ux, uy, first, nbr, coef, 1.0, 1e9, fx, fy);
        const double t1 = plate_now();
        for (int s = 0; s < 10; s++) {
            for (int64_t i = 0; i < n; i++) /* the packing, once a step */
                p[4 * i] = x[i], p[4 * i + 1] = y[i], p[4 * i + 2] = ux[i], p[4 * i + 3] = uy[i];
            for (int64_t i = 0; i < n; i++) packed_point(i, p, first, nbr, coef, 1e9, fx, fy);
        }
        const double t2 = plate_now();
        printf("kernel %.3g  packed %.3g bonds/s\n", 10 * bonds / (t1 - t0),
               10 * bonds / (t2 - t1));
    }
    return 0;
}
