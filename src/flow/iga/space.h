/* The B-spline space of the isogeometric flow along one axis (paper 003
 * Sec. 3; ../shared/notes/iga_flow.md Sec. 2.1): degree p (1 to 3), n
 * uniform elements on [lo, hi], single interior knots (C^(p-1)).
 *   open:     knots lo (p+1 times), lo + h, ..., hi (p+1 times); n + p
 *             functions, the first and last interpolatory at the ends;
 *   periodic: knots lo + (k - p) h, k = 0 .. n + 2p; n functions, the
 *             function k + n identified with k.
 * Element e carries the functions first(e) .. first(e) + p (mod the count
 * when periodic). The geometry map is linear, so the Greville abscissae
 * are where the functions "sit". Basis values by Cox-de Boor (The NURBS
 * Book A2.2-A2.3), tabulated once at the p + 1 Gauss points of each
 * element. */
#ifndef NSPD_FLOW_IGA_SPACE_H
#define NSPD_FLOW_IGA_SPACE_H

#include <stdbool.h>

enum { IGA_MAX_DEGREE = 3, IGA_MAX_LOCAL = IGA_MAX_DEGREE + 1 };

typedef struct {
    int degree;   /* p */
    int elements; /* n */
    bool periodic;
    double lo, hi, h;
    int count;     /* functions: n + p open, n periodic */
    int gauss;     /* quadrature points per element: p + 1 */
    double *knots; /* n + 2p + 1 */
    /* at Gauss point q of element e, local function a: value and d/dx */
    double *value, *slope; /* [(e * gauss + q) * (p + 1) + a] */
    double *weight;        /* [q]: Gauss weight times h/2 (the element's Jacobian) */
    double *point;         /* [e * gauss + q]: the Gauss point's x */
} IgaAxis;

/* Builds the axis (NSPD_ERR_INPUT for a degree outside 1..3, fewer than
 * p + 1 elements when periodic or 1 when open, or an empty interval). */
int iga_axis_create(IgaAxis *a, int degree, int elements, double lo, double hi, bool periodic);
void iga_axis_destroy(IgaAxis *a);

/* The global index of local function `local` of element e. */
static inline int iga_axis_index(const IgaAxis *a, int e, int local) {
    const int k = e + local;
    return a->periodic ? k % a->count : k;
}

/* The element that holds x (clamped to the interval; periodic: wrapped). */
int iga_axis_element(const IgaAxis *a, double x);

/* The p + 1 values (and slopes, if not NULL) of element e's functions at x
 * (in or at the edge of the element). */
void iga_axis_eval(const IgaAxis *a, int e, double x, double *value, double *slope);

/* The Greville abscissa of function k (periodic: within [lo, hi)). */
double iga_axis_greville(const IgaAxis *a, int k);

/* The integral of function k over the interval. */
double iga_axis_integral(const IgaAxis *a, int k);

#endif
