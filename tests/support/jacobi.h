/* Eigenvalues of a small dense symmetric matrix by the cyclic Jacobi
 * method (Golub & Van Loan, Matrix Computations, 4th ed., Alg. 8.5.3):
 * rotations zero the off-diagonal entries one by one until their norm is
 * round-off of the whole. Slow (n^3 a sweep, ~10 sweeps) but accurate for
 * small eigenvalues of a matrix with large ones (relative to the norm),
 * which is what the zero-energy-mode count needs, and short. */
#ifndef NSPD_TEST_JACOBI_H
#define NSPD_TEST_JACOBI_H

/* Eigenvalues of the symmetric n x n row-major matrix A (destroyed; only
 * its symmetric part is used) into w, ascending. Returns the sweeps taken,
 * or -1 if 100 sweeps did not converge. */
int jacobi_eigenvalues(int n, double *A, double *w);

#endif
