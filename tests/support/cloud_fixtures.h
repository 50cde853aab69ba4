/* Test clouds for the correspondence solid's kernels (solid/correspondence/rk_gradient.h,
 * solid/correspondence/bac_force.h, solid/correspondence/classic_force.h): a lattice moved at
 * random, with square (cube) families |xi|_inf <= delta = 2.5 h, found by brute force. */
#ifndef NSPD_TEST_CLOUD_FIXTURES_H
#define NSPD_TEST_CLOUD_FIXTURES_H

#include <stdint.h>

typedef struct {
    int dim;
    int64_t n;
    double h, delta;
    double *x[3], *volume;
    int64_t *first;
    int32_t *nbr;
} Cloud;

/* side^dim points of spacing h, each moved by up to `jitter` h (a fixed
 * pseudo-random sequence), volume h^dim. */
void cloud_make(Cloud *c, int dim, int side, double h, double jitter);
/* A periodic 2D patch of side x side points made into a finite cloud by
 * tiling: tiles x tiles copies (wide = side tiles points a row, point
 * i = I + wide J at lattice site (I, J)), each patch point p = I % side +
 * side (J % side) moved by the same `jitter` h in every copy. Far enough
 * inside (see tests/unit/solid/correspondence/test_zero_energy.c) a point's force
 * depends only on images whose families are whole, so it is the periodic
 * patch's force: the kernels need no periodic bond vectors. */
void cloud_make_tiled(Cloud *c, int side, int tiles, double h, double jitter);
/* The kernel omega of every bond (rk_kernel, support delta): omega[k]
 * for bond k of the family CSR. */
void cloud_omega(const Cloud *c, double *omega);
void cloud_free(Cloud *c);

#endif
