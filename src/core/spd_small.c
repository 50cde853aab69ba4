#include "core/spd_small.h"

#include <math.h>

bool spd_small_factor(double M[SPD_SMALL_MAX][SPD_SMALL_MAX], int m, double scale[SPD_SMALL_MAX],
                      double min_pivot) {
    for (int r = 0; r < m; r++) {
        if (!(M[r][r] > 0.0)) return false;
        scale[r] = 1.0 / sqrt(M[r][r]);
    }
    for (int r = 0; r < m; r++)
        for (int c = 0; c <= r; c++) M[r][c] *= scale[r] * scale[c];
    for (int c = 0; c < m; c++) {
        double d = M[c][c];
        for (int k = 0; k < c; k++) d -= M[c][k] * M[c][k];
        if (!(d > min_pivot)) return false;
        const double l = sqrt(d);
        M[c][c] = l;
        for (int r = c + 1; r < m; r++) {
            double v = M[r][c];
            for (int k = 0; k < c; k++) v -= M[r][k] * M[c][k];
            M[r][c] = v / l;
        }
    }
    return true;
}

/* (S L L^T S) z = q with S = diag(1/scale): forward, backward, unscale. */
void spd_small_solve(const double L[SPD_SMALL_MAX][SPD_SMALL_MAX], int m,
                     const double scale[SPD_SMALL_MAX], const double q[SPD_SMALL_MAX],
                     double z[SPD_SMALL_MAX]) {
    double y[SPD_SMALL_MAX] = {0};
    for (int r = 0; r < m; r++) {
        double v = q[r] * scale[r];
        for (int k = 0; k < r; k++) v -= L[r][k] * y[k];
        y[r] = v / L[r][r];
    }
    for (int r = m - 1; r >= 0; r--) {
        double v = y[r];
        for (int k = r + 1; k < m; k++) v -= L[k][r] * z[k];
        z[r] = v / L[r][r];
    }
    for (int r = 0; r < m; r++) z[r] *= scale[r];
}
