#include "jacobi.h"

#include <math.h>
#include <stdlib.h>

static int ascending(const void *a, const void *b) {
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int jacobi_eigenvalues(int n, double *A, double *w) {
    double total = 0.0;
    for (int r = 0; r < n; r++)
        for (int c = r; c < n; c++) {
            const double v = 0.5 * (A[r * n + c] + A[c * n + r]);
            A[r * n + c] = A[c * n + r] = v;
            total += (r == c ? 1.0 : 2.0) * v * v;
        }
    int sweeps = 0;
    for (; sweeps < 100; sweeps++) {
        double off = 0.0;
        for (int r = 0; r < n; r++)
            for (int c = r + 1; c < n; c++) off += 2.0 * A[r * n + c] * A[r * n + c];
        if (off <= 1e-32 * total) break;
        for (int p = 0; p < n; p++)
            for (int q = p + 1; q < n; q++) {
                const double apq = A[p * n + q];
                if (apq == 0.0) continue;
                /* the rotation (c, s) that zeroes A_pq (Alg. 8.5.1) */
                const double tau = (A[q * n + q] - A[p * n + p]) / (2.0 * apq);
                const double t = (tau >= 0.0 ? 1.0 : -1.0) / (fabs(tau) + sqrt(1.0 + tau * tau));
                const double c = 1.0 / sqrt(1.0 + t * t), s = t * c;
                for (int k = 0; k < n; k++) {
                    const double akp = A[k * n + p], akq = A[k * n + q];
                    A[k * n + p] = c * akp - s * akq;
                    A[k * n + q] = s * akp + c * akq;
                }
                for (int k = 0; k < n; k++) {
                    const double apk = A[p * n + k], aqk = A[q * n + k];
                    A[p * n + k] = c * apk - s * aqk;
                    A[q * n + k] = s * apk + c * aqk;
                }
            }
    }
    for (int r = 0; r < n; r++) w[r] = A[r * n + r];
    qsort(w, (size_t)n, sizeof *w, ascending);
    return sweeps < 100 ? sweeps : -1;
}
