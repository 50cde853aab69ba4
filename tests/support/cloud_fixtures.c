#include "cloud_fixtures.h"

#include "solid/correspondence/rk_gradient.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* A deterministic pseudo-random number in [-1, 1]. */
static double uniform(uint64_t *s) {
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) / (double)(1ULL << 53) * 2.0 - 1.0;
}

/* Square (cube) families |xi|_inf <= delta, by brute force. */
static void families(Cloud *c) {
    c->first = calloc((size_t)c->n + 1, sizeof(int64_t));
    const int64_t cap = c->n * 130;
    int64_t m = 0;
    c->nbr = calloc((size_t)cap, sizeof(int32_t));
    for (int64_t i = 0; i < c->n; i++) {
        c->first[i] = m;
        for (int64_t j = 0; j < c->n; j++) {
            if (j == i) continue;
            double far = 0.0;
            for (int a = 0; a < c->dim; a++) far = fmax(far, fabs(c->x[a][j] - c->x[a][i]));
            if (far <= c->delta && m < cap) c->nbr[m++] = (int32_t)j;
        }
    }
    c->first[c->n] = m;
}

void cloud_make(Cloud *c, int dim, int side, double h, double jitter) {
    memset(c, 0, sizeof *c);
    c->dim = dim;
    c->h = h;
    c->delta = 2.5 * h;
    c->n = dim == 3 ? (int64_t)side * side * side : (int64_t)side * side;
    for (int a = 0; a < 3; a++) c->x[a] = calloc((size_t)c->n, sizeof(double));
    c->volume = calloc((size_t)c->n, sizeof(double));
    uint64_t seed = 12345;
    for (int64_t i = 0; i < c->n; i++) {
        const int64_t ijk[3] = {i % side, (i / side) % side, i / ((int64_t)side * side)};
        for (int a = 0; a < dim; a++) c->x[a][i] = h * ((double)ijk[a] + jitter * uniform(&seed));
        c->volume[i] = pow(h, dim);
    }
    families(c);
}

void cloud_make_tiled(Cloud *c, int side, int tiles, double h, double jitter) {
    memset(c, 0, sizeof *c);
    c->dim = 2;
    c->h = h;
    c->delta = 2.5 * h;
    const int64_t wide = (int64_t)side * tiles;
    c->n = wide * wide;
    for (int a = 0; a < 3; a++) c->x[a] = calloc((size_t)c->n, sizeof(double));
    c->volume = calloc((size_t)c->n, sizeof(double));
    /* one jitter per patch point, the same for all its images */
    double *shift = calloc((size_t)(2 * side * side), sizeof(double));
    uint64_t seed = 12345;
    for (int64_t p = 0; p < 2 * (int64_t)side * side; p++) shift[p] = jitter * uniform(&seed);
    for (int64_t i = 0; i < c->n; i++) {
        const int64_t I = i % wide, J = i / wide, p = I % side + side * (J % side);
        c->x[0][i] = h * ((double)I + shift[2 * p]);
        c->x[1][i] = h * ((double)J + shift[2 * p + 1]);
        c->volume[i] = h * h;
    }
    free(shift);
    families(c);
}

void cloud_omega(const Cloud *c, double *omega) {
    for (int64_t i = 0; i < c->n; i++)
        for (int64_t k = c->first[i]; k < c->first[i + 1]; k++) {
            double xi[3] = {0, 0, 0};
            for (int a = 0; a < c->dim; a++) xi[a] = c->x[a][c->nbr[k]] - c->x[a][i];
            omega[k] = rk_kernel(c->dim, xi, c->delta);
        }
}

void cloud_free(Cloud *c) {
    for (int a = 0; a < 3; a++) free(c->x[a]);
    free(c->volume);
    free(c->first);
    free(c->nbr);
    memset(c, 0, sizeof *c);
}
