/* Test configurations of the isogeometric flow (flow/iga/solver.h). */
#ifndef NSPD_TEST_IGA_FIXTURES_H
#define NSPD_TEST_IGA_FIXTURES_H

#include "flow/iga/solver.h"

/* A strip of nx x 2 quadratic elements on the unit tube, slip walls all
 * round, Sod's right state (R = 1, gamma = 1.4, inviscid), nodal start,
 * the paper's code's scheme with the DC cap, Courant 0.3. */
IgaConfig iga_fixture_strip(int nx);

/* How far the control values of a square mesh are from the symmetries of
 * the square (x <-> y and the two mirrors), relative to the largest: p
 * into *p_rel, u against the mirrored v into *uv_rel (notes T6). */
void iga_fixture_symmetry(IgaSolver *s, double *p_rel, double *uv_rel);

#endif
