#include "solid/correspondence/svk.h"

/* C = A B for 3 x 3 row-major matrices. */
static void matmul(const double A[9], const double B[9], double C[9]) {
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            double v = 0.0;
            for (int k = 0; k < 3; k++) v += A[3 * r + k] * B[3 * k + c];
            C[3 * r + c] = v;
        }
}

void svk_stress(int dim, const double F[9], double lambda, double mu, double P[9]) {
    double G[9];
    for (int q = 0; q < 9; q++) G[q] = F[q]; /* a loop: the memcpy was a library call */
    if (dim == 2) G[2] = G[5] = G[6] = G[7] = 0.0, G[8] = 1.0;
    double E[9], tr = 0.0;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            double v = 0.0;
            for (int k = 0; k < 3; k++) v += G[3 * k + r] * G[3 * k + c];
            E[3 * r + c] = 0.5 * (v - (r == c ? 1.0 : 0.0));
        }
    for (int r = 0; r < 3; r++) tr += E[4 * r];
    double S[9];
    for (int q = 0; q < 9; q++) S[q] = 2.0 * mu * E[q];
    for (int r = 0; r < 3; r++) S[4 * r] += lambda * tr;
    matmul(G, S, P);
}
