/* The 500 x 500 plate of the bond-kernel variants (csr.c, ell.c): points on
 * a row-major lattice of 1 mm, a horizon of 3.015 spacings (28 neighbours
 * inside), and a displacement field that stretches every bond a little. */
#ifndef BOND_VARIANTS_PLATE_H
#define BOND_VARIANTS_PLATE_H

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <time.h>

enum { PLATE_N = 500, PLATE_REACH = 3 };
static const double PLATE_DX = 1e-3, PLATE_DELTA = 3.015e-3;

/* Positions and displacements of the PLATE_N^2 points (malloc'd). */
static void plate_points(double **x, double **y, double **ux, double **uy) {
    const int64_t n = (int64_t)PLATE_N * PLATE_N;
    *x = malloc(n * sizeof(double)), *y = malloc(n * sizeof(double));
    *ux = malloc(n * sizeof(double)), *uy = malloc(n * sizeof(double));
    for (int64_t k = 0; k < n; k++) {
        (*x)[k] = (double)(k % PLATE_N) * PLATE_DX;
        (*y)[k] = (double)(k / PLATE_N) * PLATE_DX;
        (*ux)[k] = 1e-3 * (*x)[k] + 1e-7 * sin((double)k);
        (*uy)[k] = -3e-4 * (*y)[k];
    }
}

/* Point k's neighbours, in stencil order, into nb; returns their count. */
static int plate_family(int64_t k, int32_t nb[32]) {
    const int i = (int)(k % PLATE_N), j = (int)(k / PLATE_N);
    int m = 0;
    for (int q = -PLATE_REACH; q <= PLATE_REACH; q++)
        for (int p = -PLATE_REACH; p <= PLATE_REACH; p++) {
            const int a = i + p, c = j + q;
            if ((!p && !q) || a < 0 || c < 0 || a >= PLATE_N || c >= PLATE_N) continue;
            if ((p * p + q * q) * PLATE_DX * PLATE_DX > PLATE_DELTA * PLATE_DELTA) continue;
            nb[m++] = c * PLATE_N + a;
        }
    return m;
}

static double plate_now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

#endif
