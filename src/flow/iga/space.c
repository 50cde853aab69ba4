#include "flow/iga/space.h"

#include "core/mem.h"
#include "core/status.h"

#include <math.h>
#include <string.h>

/* Gauss-Legendre points and weights on [-1, 1], 2 to 4 points. */
static void gauss_rule(int n, double *x, double *w) {
    switch (n) {
    case 2:
        x[0] = -1.0 / sqrt(3.0), x[1] = -x[0];
        w[0] = w[1] = 1.0;
        break;
    case 3:
        x[0] = -sqrt(0.6), x[1] = 0.0, x[2] = sqrt(0.6);
        w[0] = w[2] = 5.0 / 9.0, w[1] = 8.0 / 9.0;
        break;
    default: {
        const double a = sqrt(3.0 / 7.0 - 2.0 / 7.0 * sqrt(1.2)),
                     b = sqrt(3.0 / 7.0 + 2.0 / 7.0 * sqrt(1.2));
        x[0] = -b, x[1] = -a, x[2] = a, x[3] = b;
        w[1] = w[2] = (18.0 + sqrt(30.0)) / 36.0;
        w[0] = w[3] = (18.0 - sqrt(30.0)) / 36.0;
    }
    }
}

/* The p + 1 non-zero functions of knot span `span` at x and their first
 * derivatives (The NURBS Book A2.2 and A2.3 for the first derivative). */
static void basis_funs(const double *U, int span, int p, double x, double *N, double *dN) {
    double left[IGA_MAX_LOCAL], right[IGA_MAX_LOCAL], ndu[IGA_MAX_LOCAL][IGA_MAX_LOCAL];
    ndu[0][0] = 1.0;
    for (int j = 1; j <= p; j++) {
        left[j] = x - U[span + 1 - j];
        right[j] = U[span + j] - x;
        double saved = 0.0;
        for (int r = 0; r < j; r++) {
            ndu[j][r] = right[r + 1] + left[j - r]; /* the lower triangle: knot differences */
            const double t = ndu[r][j - 1] / ndu[j][r];
            ndu[r][j] = saved + right[r + 1] * t;
            saved = left[j - r] * t;
        }
        ndu[j][j] = saved;
    }
    for (int r = 0; r <= p; r++) N[r] = ndu[r][p];
    if (!dN) return;
    /* N'_{i,p} = p (N_{i,p-1}/(u_{i+p} - u_i) - N_{i+1,p-1}/(u_{i+p+1} - u_{i+1})) */
    for (int r = 0; r <= p; r++) {
        double d = 0.0;
        if (r >= 1) d += ndu[r - 1][p - 1] / ndu[p][r - 1];
        if (r <= p - 1) d -= ndu[r][p - 1] / ndu[p][r];
        dN[r] = p * d;
    }
}

int iga_axis_create(IgaAxis *a, int degree, int elements, double lo, double hi, bool periodic) {
    memset(a, 0, sizeof *a);
    if (degree < 1 || degree > IGA_MAX_DEGREE)
        return NSPD_FAIL(NSPD_ERR_INPUT, "B-spline degree %d; expected 1, 2 or 3", degree);
    if (elements < (periodic ? degree + 1 : 1) || !(hi > lo))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "%d elements on [%g, %g]; expected an interval and at least %d elements",
                         elements, lo, hi, periodic ? degree + 1 : 1);
    const int p = degree, n = elements;
    a->degree = p, a->elements = n, a->periodic = periodic;
    a->lo = lo, a->hi = hi, a->h = (hi - lo) / n;
    a->count = periodic ? n : n + p;
    a->gauss = p + 1;
    const int nk = n + 2 * p + 1, nq = n * a->gauss;
    TRY(nspd_alloc(&a->knots, (size_t)nk, sizeof(double)));
    for (int k = 0; k < nk; k++) {
        int m = k - p;
        if (!periodic) m = m < 0 ? 0 : m > n ? n : m;
        a->knots[k] = m == n ? hi : lo + m * a->h; /* the last knot exactly hi */
    }
    TRY(nspd_alloc(&a->value, (size_t)nq * (size_t)(p + 1), sizeof(double)));
    TRY(nspd_alloc(&a->slope, (size_t)nq * (size_t)(p + 1), sizeof(double)));
    TRY(nspd_alloc(&a->weight, (size_t)a->gauss, sizeof(double)));
    TRY(nspd_alloc(&a->point, (size_t)nq, sizeof(double)));
    double gx[IGA_MAX_LOCAL], gw[IGA_MAX_LOCAL];
    gauss_rule(a->gauss, gx, gw);
    for (int q = 0; q < a->gauss; q++) a->weight[q] = 0.5 * a->h * gw[q];
    for (int e = 0; e < n; e++)
        for (int q = 0; q < a->gauss; q++) {
            const int k = e * a->gauss + q;
            const double x0 = a->knots[e + p], x1 = a->knots[e + p + 1];
            a->point[k] = 0.5 * (x0 + x1) + 0.5 * (x1 - x0) * gx[q];
            basis_funs(a->knots, e + p, p, a->point[k], a->value + (size_t)k * (size_t)(p + 1),
                       a->slope + (size_t)k * (size_t)(p + 1));
        }
    return NSPD_OK;
}

void iga_axis_destroy(IgaAxis *a) {
    nspd_free(&a->knots);
    nspd_free(&a->value);
    nspd_free(&a->slope);
    nspd_free(&a->weight);
    nspd_free(&a->point);
    memset(a, 0, sizeof *a);
}

int iga_axis_element(const IgaAxis *a, double x) {
    double s = (x - a->lo) / a->h;
    if (a->periodic) s -= a->elements * floor(s / a->elements);
    int e = (int)floor(s);
    return e < 0 ? 0 : e >= a->elements ? a->elements - 1 : e;
}

void iga_axis_eval(const IgaAxis *a, int e, double x, double *value, double *slope) {
    if (a->periodic) { /* into the element's own copy of the interval */
        const double x0 = a->knots[e + a->degree];
        x -= (a->hi - a->lo) * floor((x - x0) / (a->hi - a->lo) + 1e-12);
    }
    basis_funs(a->knots, e + a->degree, a->degree, x, value, slope);
}

double iga_axis_greville(const IgaAxis *a, int k) {
    double x = 0.0;
    for (int j = 1; j <= a->degree; j++) x += a->knots[k + j];
    x /= a->degree;
    if (a->periodic && x < a->lo) x += a->hi - a->lo;
    return x;
}

double iga_axis_integral(const IgaAxis *a, int k) {
    /* (u_{k+p+1} - u_k)/(p + 1) on the extended knots; periodic: h */
    if (a->periodic) return a->h;
    return (a->knots[k + a->degree + 1] - a->knots[k]) / (a->degree + 1);
}
