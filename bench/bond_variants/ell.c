/* Issue 27 experiment (docs/PERFORMANCE.md, "Rooflines of the kernels"):
 * the bond-based force vectorised across points instead of across a
 * point's bonds: ELLPACK bond slots (W a point, padded with broken bonds),
 * blocks of B points, each SIMD lane one point summing its bonds in order
 * (so still bitwise the same at any thread count), on the plate of
 * plate.h. Prints bond updates/s.
 *   gcc -O3 -march=native -fno-math-errno -fopenmp-simd ell.c -lm && ./a.out */
#include "plate.h"

#include <stdio.h>

enum { W = 28, B = 8 }; /* slots a point; points a block */

/* Slot k of point l of block blk: nbr[(blk W + k) B + l], likewise coef. */
static void ell_force(int64_t n, const double *restrict x, const double *restrict y,
                      const double *restrict ux, const double *restrict uy,
                      const int32_t *restrict nbr, float *restrict coef, double limit2,
                      double *restrict fx, double *restrict fy) {
    for (int64_t blk = 0; blk < n / B; blk++) {
        double sx[B] = {0}, sy[B] = {0};
        const int64_t i0 = blk * B;
        for (int k = 0; k < W; k++) {
            const int32_t *nb = nbr + (blk * W + k) * B;
            float *cf = coef + (blk * W + k) * B;
#pragma omp simd
            for (int l = 0; l < B; l++) {
                const int64_t i = i0 + l;
                const int32_t j = nb[l];
                const float kk = cf[l];
                const double ex = x[j] - x[i], ey = y[j] - y[i];
                const double rx = ex + (ux[j] - ux[i]), ry = ey + (uy[j] - uy[i]);
                const double e2 = ex * ex + ey * ey, r2 = rx * rx + ry * ry;
                const double f = (double)fabsf(kk) * (1.0 - sqrt(e2 / r2));
                if ((kk > 0.0f) & (r2 > limit2 * e2)) cf[l] = 0.0f;
                sx[l] += f * rx;
                sy[l] += f * ry;
            }
        }
        for (int l = 0; l < B; l++) fx[i0 + l] = sx[l], fy[i0 + l] = sy[l];
    }
}

int main(void) {
    const int64_t n = (int64_t)PLATE_N * PLATE_N;
    double *x, *y, *ux, *uy;
    plate_points(&x, &y, &ux, &uy);
    double *fx = malloc(n * 8), *fy = malloc(n * 8);
    int32_t *nbr = malloc(n * W * 4);
    float *coef = malloc(n * W * 4);
    int64_t bonds = 0;
    for (int64_t i = 0; i < n; i++) {
        int32_t nb[32];
        const int m = plate_family(i, nb);
        const int64_t blk = i / B, l = i % B;
        for (int k = 0; k < W; k++) { /* padding: a broken bond to a neighbour point */
            nbr[(blk * W + k) * B + l] = k < m ? nb[k] : (int32_t)(i ^ 1);
            coef[(blk * W + k) * B + l] = k < m ? 1.0f : 0.0f;
        }
        bonds += m;
    }
    printf("%lld bonds\n", (long long)bonds);
    for (int rep = 0; rep < 3; rep++) {
        const double t0 = plate_now();
        for (int s = 0; s < 10; s++) ell_force(n, x, y, ux, uy, nbr, coef, 1e9, fx, fy);
        printf("ELLPACK %.3g bonds/s\n", 10 * bonds / (plate_now() - t0));
    }
    return 0;
}
