/* Issue 27 experiment (docs/PERFORMANCE.md, "Rooflines of the kernels"):
 * the bond-based force's kernel (solid/bond/force_kernel.h, CSR, an omp
 * simd reduction over a point's bonds) on the plate of plate.h, against the
 * same loop with |xi| / |y| by a bit-level first guess of 1/sqrt and four
 * Newton steps (vectorisable, no division or square root). Prints bond
 * updates/s of both.
 *   gcc -O3 -march=native -fno-math-errno -fopenmp-simd -I../../src csr.c -lm && ./a.out */
#include "plate.h"
#include "solid/bond/force_kernel.h"

#include <stdio.h>
#include <string.h>

/* 1/sqrt(a) by the bit-level guess and four Newton steps: plain arithmetic
 * the compiler vectorises. */
#pragma omp declare simd
static inline double rsqrt_newton(double a) {
    int64_t bits;
    memcpy(&bits, &a, 8);
    bits = 0x5fe6eb50c7b537a9LL - (bits >> 1);
    double r;
    memcpy(&r, &bits, 8);
    const double h = 0.5 * a;
    for (int k = 0; k < 4; k++) r = r * (1.5 - h * r * r);
    return r;
}

/* force_kernel.h's 2D body with sqrt(e2 / r2) replaced by rsqrt_newton. */
static inline void newton_point(int64_t i, const double *restrict x, const double *restrict y,
                                const double *restrict ux, const double *restrict uy,
                                const int64_t *restrict first, const int32_t *restrict nbr,
                                float *restrict coef, double limit2, double *restrict fx,
                                double *restrict fy) {
    const double xi = x[i], yi = y[i], uxi = ux[i], uyi = uy[i];
    double sx = 0.0, sy = 0.0;
#pragma omp simd reduction(+ : sx, sy)
    for (int64_t b = first[i]; b < first[i + 1]; b++) {
        const int32_t j = nbr[b];
        const float k = coef[b];
        const double ex = x[j] - xi, ey = y[j] - yi;
        const double rx = ex + (ux[j] - uxi), ry = ey + (uy[j] - uyi);
        const double e2 = ex * ex + ey * ey, r2 = rx * rx + ry * ry;
        const double f = (double)fabsf(k) * (1.0 - rsqrt_newton(r2 / e2));
        if ((k > 0.0f) & (r2 > limit2 * e2)) coef[b] = 0.0f;
        sx += f * rx;
        sy += f * ry;
    }
    fx[i] = sx;
    fy[i] = sy;
}

int main(void) {
    const int64_t n = (int64_t)PLATE_N * PLATE_N;
    double *x, *y, *ux, *uy;
    plate_points(&x, &y, &ux, &uy);
    double *fx = malloc(n * 8), *fy = malloc(n * 8), *gx = malloc(n * 8), *gy = malloc(n * 8);
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
    for (int64_t i = 0; i < n; i++) {
        bond_force_point_2d(i, x, y, ux, uy, first, nbr, coef, 1.0, 1e9, fx, fy);
        newton_point(i, x, y, ux, uy, first, nbr, coef, 1e9, gx, gy);
    }
    double err = 0, big = 0;
    for (int64_t i = 0; i < n; i++) {
        err = fmax(err, fabs(gx[i] - fx[i]));
        big = fmax(big, fabs(fx[i]));
    }
    printf("Newton: max difference %.3g of max %.3g\n", err, big);
    for (int rep = 0; rep < 3; rep++) {
        const double t0 = plate_now();
        for (int s = 0; s < 10; s++)
            for (int64_t i = 0; i < n; i++)
                bond_force_point_2d(i, x, y, ux, uy, first, nbr, coef, 1.0, 1e9, fx, fy);
        const double t1 = plate_now();
        for (int s = 0; s < 10; s++)
            for (int64_t i = 0; i < n; i++)
                newton_point(i, x, y, ux, uy, first, nbr, coef, 1e9, fx, fy);
        const double t2 = plate_now();
        printf("kernel %.3g  Newton %.3g bonds/s\n", 10 * bonds / (t1 - t0),
               10 * bonds / (t2 - t1));
    }
    return 0;
}
