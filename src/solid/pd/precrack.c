#include "solid/pd/precrack.h"

static double orient2(const double a[3], const double b[3], const double c[3]) {
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

static bool cuts_2d(const PdPrecrack *crack, const double p[3], const double q[3]) {
    double o1 = orient2(crack->a, crack->b, p), o2 = orient2(crack->a, crack->b, q);
    double o3 = orient2(p, q, crack->a), o4 = orient2(p, q, crack->b);
    return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

static bool cuts_3d(const PdPrecrack *crack, const double p[3], const double q[3]) {
    const double *a = crack->a, *e1 = crack->e1, *e2 = crack->e2;
    double nrm[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                     e1[0] * e2[1] - e1[1] * e2[0]};
    double dp = 0, dq = 0;
    for (int d = 0; d < 3; d++) {
        dp += nrm[d] * (p[d] - a[d]);
        dq += nrm[d] * (q[d] - a[d]);
    }
    if (!((dp > 0 && dq < 0) || (dp < 0 && dq > 0))) return false;
    double t = dp / (dp - dq), r[3];
    for (int d = 0; d < 3; d++) r[d] = p[d] + t * (q[d] - p[d]) - a[d];
    /* solve r = s e1 + u e2 in the plane (Gram system) */
    double g11 = 0, g12 = 0, g22 = 0, r1 = 0, r2 = 0;
    for (int d = 0; d < 3; d++) {
        g11 += e1[d] * e1[d];
        g12 += e1[d] * e2[d];
        g22 += e2[d] * e2[d];
        r1 += r[d] * e1[d];
        r2 += r[d] * e2[d];
    }
    double det = g11 * g22 - g12 * g12;
    if (det <= 0) return false;
    double s = (r1 * g22 - r2 * g12) / det, u = (r2 * g11 - r1 * g12) / det;
    return s >= 0 && s <= 1 && u >= 0 && u <= 1;
}

bool precrack_cuts(const PdPrecrack *crack, int dim, const double p[3], const double q[3]) {
    return dim == 2 ? cuts_2d(crack, p, q) : cuts_3d(crack, p, q);
}
