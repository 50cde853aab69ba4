/* Correspondence bodies built in code for the tests (solid/correspondence/body.h):
 * paper 003's steel block, homogeneous fields, plane-wave speeds, energy. */
#ifndef NSPD_TEST_CPD_FIXTURES_H
#define NSPD_TEST_CPD_FIXTURES_H

#include "solid/correspondence/body.h"

/* paper 003's steel: E, nu, rho, sigma_Y, H */
#define CPD_STEEL_E         200e9
#define CPD_STEEL_NU        0.29
#define CPD_STEEL_RHO       7870.0
#define CPD_STEEL_YIELD     0.4e9
#define CPD_STEEL_HARDENING 0.1e9

/* An nx x ny steel block of spacing h, plane strain, square families of
 * 2.5 h, the given force (classic: C_s = 0.5, the case default), elastic
 * and undamaged unless the caller changes it. */
CpdConfig cpd_fixture_block(int nx, int ny, double h, CpdForce force);

/* u = (F - I) X on every point, F = [[a, b], [c, d]] row-major. */
void cpd_fixture_homogeneous(const CpdBody *b, double *const u[3], const double F[4]);

/* The speed omega / k of a plane wave u = A e sin(k x . n) (A = 1e-9, from
 * a stress-free state) at the points at least 3.5 delta inside: their
 * force is the infinite lattice's; omega^2 by least squares
 * -sum L.u / (rho sum u.u). Overwrites u, u_prev, the stresses and force. */
double cpd_fixture_plane_wave_speed(CpdBody *b, double wavelength, const double n[2],
                                    const double e[2]);

/* A free 16 x 16 block (spacing 1 mm) of the given force from a random
 * velocity of 1e-3 m/s per point (seed 7), run for up to 1000 steps of
 * `factor` times its power-iteration step, stopping at a 1e6-fold growth;
 * returns the largest kinetic energy over the first one's (the C6 check
 * of the stable step) and prints the steps taken. */
double cpd_fixture_energy_growth(CpdForce force, double factor);

/* The kinetic energy, J (sequential). */
double cpd_fixture_kinetic(const CpdBody *b);

#endif
