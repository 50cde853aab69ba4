/* Issue 27 experiment (docs/PERFORMANCE.md, "Rooflines of the kernels"):
 * the bond-based force vectorised across points instead of across a
 * point's bonds: ELLPACK bond slots (28 per point, padded with broken
 * bonds), blocks of 8 points, each SIMD lane one point summing its bonds in
 * order (so still bitwise the same at any thread count), on the 500 x 500
 * plate. Standalone; prints bond updates/s.
 *   gcc -O3 -march=native -fno-math-errno -fopenmp-simd ell.c -lm && ./a.out */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}
enum { W = 28 };
/* ELL: slot-major within blocks of B points: nbr[(blk*W + k)*B + l] */
enum { B = 8 };
static void ell(int64_t n, const double *restrict x, const double *restrict y,
                const double *restrict ux, const double *restrict uy, const int32_t *restrict nbr,
                float *restrict coef, double limit2, double *restrict fx, double *restrict fy) {
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
        for (int l = 0; l < B; l++) {
            fx[i0 + l] = sx[l];
            fy[i0 + l] = sy[l];
        }
    }
}
int main(void) {
    const int N = 500;
    const int64_t n = (int64_t)N * N;
    const double dx = 1e-3, delta = 3.015 * dx;
    double *x = malloc(n * 8), *y = malloc(n * 8), *ux = malloc(n * 8), *uy = malloc(n * 8),
           *fx = malloc(n * 8), *fy = malloc(n * 8);
    int32_t *nbr = malloc(n * W * 4);
    float *coef = malloc(n * W * 4);
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            int64_t k = (int64_t)j * N + i;
            x[k] = i * dx;
            y[k] = j * dx;
            ux[k] = 1e-3 * x[k] + 1e-7 * sin(k);
            uy[k] = -3e-4 * y[k];
        }
    int64_t bonds = 0;
    for (int64_t i = 0; i < n; i++) {
        int ii = i % N, jj = i / N, k = 0;
        int64_t blk = i / B, l = i % B;
        for (int q = -3; q <= 3; q++)
            for (int p = -3; p <= 3; p++) {
                if (!p && !q) continue;
                int a = ii + p, c = jj + q;
                if (a < 0 || c < 0 || a >= N || c >= N) continue;
                if ((p * p + q * q) * dx * dx > delta * delta) continue;
                nbr[(blk * W + k) * B + l] = c * N + a;
                coef[(blk * W + k) * B + l] = 1.0f;
                k++;
                bonds++;
            }
        for (; k < W; k++) {
            nbr[(blk * W + k) * B + l] = (int32_t)i ^ 1;
            coef[(blk * W + k) * B + l] = 0.0f;
        }
    }
    printf("%lld bonds\n", (long long)bonds);
    for (int rep = 0; rep < 3; rep++) {
        double t0 = now();
        for (int s = 0; s < 10; s++) ell(n, x, y, ux, uy, nbr, coef, 1e9, fx, fy);
        double t1 = now();
        printf("ell %.3g bonds/s\n", 10 * bonds / (t1 - t0));
    }
}
