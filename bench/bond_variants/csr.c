/* Issue 27 experiment (docs/PERFORMANCE.md, "Rooflines of the kernels"):
 * the bond-based force's point loop (a copy of solid/bond/force_kernel.h's
 * 2D body, CSR, an omp simd reduction over a point's bonds) on the 500 x 500
 * plate in row-major order, against the same loop with 1/|y| by a bit-level
 * guess and four Newton steps (vectorisable, no division or square root)
 * in two forms. Standalone; prints bond updates/s.
 *   gcc -O3 -march=native -fno-math-errno -fopenmp-simd csr.c -lm && ./a.out */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* the reference kernel */
static inline __attribute__((always_inline)) void
ref(int64_t i, const double *restrict x, const double *restrict y, const double *restrict ux,
    const double *restrict uy, const int64_t *restrict first, const int32_t *restrict nbr,
    float *restrict coef, double scale, double limit2, double *restrict fx, double *restrict fy) {
    const double xi = x[i], yi = y[i], uxi = ux[i], uyi = uy[i];
    double sx = 0.0, sy = 0.0;
    const int64_t b0 = first[i], b1 = first[i + 1];
#pragma omp simd reduction(+ : sx, sy)
    for (int64_t b = b0; b < b1; b++) {
        const int32_t j = nbr[b];
        float k = coef[b];
        const double ex = x[j] - xi, ey = y[j] - yi;
        const double rx = ex + (ux[j] - uxi), ry = ey + (uy[j] - uyi);
        const double e2 = ex * ex + ey * ey, r2 = rx * rx + ry * ry;
        const double f = (double)fabsf(k) * (1.0 - sqrt(e2 / r2));
        if ((k > 0.0f) & (r2 > limit2 * e2)) coef[b] = 0.0f;
        sx += f * rx;
        sy += f * ry;
    }
    fx[i] = scale * sx;
    fy[i] = scale * sy;
}

/* 1/sqrt(a) by the bit-level first guess and Newton steps: plain
 * arithmetic the compiler vectorises */
#pragma omp declare simd
static inline double rsqrt_newton(double a) {
    int64_t bits;
    memcpy(&bits, &a, 8);
    bits = 0x5fe6eb50c7b537a9LL - (bits >> 1);
    double r;
    memcpy(&r, &bits, 8);
    const double h = 0.5 * a;
    r = r * (1.5 - h * r * r);
    r = r * (1.5 - h * r * r);
    r = r * (1.5 - h * r * r);
    r = r * (1.5 - h * r * r);
    return r;
}

static inline __attribute__((always_inline)) void
fast(int64_t i, const double *restrict x, const double *restrict y, const double *restrict ux,
     const double *restrict uy, const int64_t *restrict first, const int32_t *restrict nbr,
     float *restrict coef, double scale, double limit2, double *restrict fx, double *restrict fy) {
    const double xi = x[i], yi = y[i], uxi = ux[i], uyi = uy[i];
    double sx = 0.0, sy = 0.0;
    const int64_t b0 = first[i], b1 = first[i + 1];
#pragma omp simd reduction(+ : sx, sy)
    for (int64_t b = b0; b < b1; b++) {
        const int32_t j = nbr[b];
        float k = coef[b];
        const double ex = x[j] - xi, ey = y[j] - yi;
        const double rx = ex + (ux[j] - uxi), ry = ey + (uy[j] - uyi);
        const double e2 = ex * ex + ey * ey, r2 = rx * rx + ry * ry;
        const double f = (double)fabsf(k) * (1.0 - rsqrt_newton(r2 / e2));
        if ((k > 0.0f) & (r2 > limit2 * e2)) coef[b] = 0.0f;
        sx += f * rx;
        sy += f * ry;
    }
    fx[i] = scale * sx;
    fy[i] = scale * sy;
}

static inline __attribute__((always_inline)) void
fast2(int64_t i, const double *restrict x, const double *restrict y, const double *restrict ux,
      const double *restrict uy, const int64_t *restrict first, const int32_t *restrict nbr,
      float *restrict coef, double scale, double limit2, double *restrict fx, double *restrict fy) {
    const double xi = x[i], yi = y[i], uxi = ux[i], uyi = uy[i];
    double sx = 0.0, sy = 0.0;
    const int64_t b0 = first[i], b1 = first[i + 1];
#pragma omp simd reduction(+ : sx, sy)
    for (int64_t b = b0; b < b1; b++) {
        const int32_t j = nbr[b];
        float k = coef[b];
        const double ex = x[j] - xi, ey = y[j] - yi;
        const double rx = ex + (ux[j] - uxi), ry = ey + (uy[j] - uyi);
        const double e2 = ex * ex + ey * ey, r2 = rx * rx + ry * ry;
        const double f = (double)fabsf(k) * (1.0 - sqrt(e2) * rsqrt_newton(r2));
        if ((k > 0.0f) & (r2 > limit2 * e2)) coef[b] = 0.0f;
        sx += f * rx;
        sy += f * ry;
    }
    fx[i] = scale * sx;
    fy[i] = scale * sy;
}

/* Every point's force by variant v (0 reference, 1 and 2 the Newton forms). */
static void run(int v, int64_t n, const double *x, const double *y, const double *ux,
                const double *uy, const int64_t *first, const int32_t *nbr, float *coef, double *fx,
                double *fy) {
    for (int64_t i = 0; i < n; i++) {
        if (v == 0)
            ref(i, x, y, ux, uy, first, nbr, coef, 1.0, 1e9, fx, fy);
        else if (v == 1)
            fast(i, x, y, ux, uy, first, nbr, coef, 1.0, 1e9, fx, fy);
        else
            fast2(i, x, y, ux, uy, first, nbr, coef, 1.0, 1e9, fx, fy);
    }
}

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

int main(void) {
    const int N = 500;
    const int64_t n = (int64_t)N * N;
    const double dx = 1e-3, delta = 3.015 * dx;
    double *x = malloc(n * 8), *y = malloc(n * 8), *ux = malloc(n * 8), *uy = malloc(n * 8),
           *fx = malloc(n * 8), *fy = malloc(n * 8), *gx = malloc(n * 8), *gy = malloc(n * 8);
    int64_t *first = malloc((n + 1) * 8);
    int32_t *nbr = malloc(n * 30 * 4);
    float *coef = malloc(n * 30 * 4);
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            int64_t k = (int64_t)j * N + i;
            x[k] = i * dx;
            y[k] = j * dx;
            ux[k] = 1e-3 * x[k] + 1e-7 * sin(k);
            uy[k] = -3e-4 * y[k];
        }
    int64_t b = 0;
    first[0] = 0;
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            for (int q = -3; q <= 3; q++)
                for (int p = -3; p <= 3; p++) {
                    if (!p && !q) continue;
                    int ii = i + p, jj = j + q;
                    if (ii < 0 || jj < 0 || ii >= N || jj >= N) continue;
                    if ((p * p + q * q) * dx * dx > delta * delta) continue;
                    nbr[b] = jj * N + ii;
                    coef[b] = 1.0f;
                    b++;
                }
            first[(int64_t)j * N + i + 1] = b;
        }
    printf("%lld bonds\n", (long long)b);
    run(0, n, x, y, ux, uy, first, nbr, coef, fx, fy);
    run(1, n, x, y, ux, uy, first, nbr, coef, gx, gy);
    double err = 0, big = 0;
    for (int64_t i = 0; i < n; i++) {
        err = fmax(err, fabs(gx[i] - fx[i]));
        big = fmax(big, fabs(fx[i]));
    }
    printf("fast: max diff %.3g of max %.3g\n", err, big);
    run(2, n, x, y, ux, uy, first, nbr, coef, gx, gy);
    err = 0;
    for (int64_t i = 0; i < n; i++) err = fmax(err, fabs(gx[i] - fx[i]));
    printf("fast2: max diff %.3g of max %.3g\n", err, big);
    for (int rep = 0; rep < 3; rep++) {
        double t0 = now();
        for (int s = 0; s < 10; s++) run(0, n, x, y, ux, uy, first, nbr, coef, fx, fy);
        double t1 = now();
        for (int s = 0; s < 10; s++) run(1, n, x, y, ux, uy, first, nbr, coef, fx, fy);
        double t2 = now();
        for (int s = 0; s < 10; s++) run(2, n, x, y, ux, uy, first, nbr, coef, fx, fy);
        double t3 = now();
        printf("ref %.3g  fast %.3g  fast2 %.3g bonds/s\n", 10 * b / (t1 - t0), 10 * b / (t2 - t1),
               10 * b / (t3 - t2));
    }
}
