/* Marker generation for fixed bodies (see markers.h).
 *
 * NACA 4-digit sections (Abbott and von Doenhoff, Theory of Wing Sections,
 * Sec. 6.4), with the closed-trailing-edge coefficient a4 = -0.1036 instead
 * of -0.1015 so that y_t(1) = 0:
 *   y_t = 5 t (0.2969 sqrt(x) - 0.1260 x - 0.3516 x^2 + 0.2843 x^3 - 0.1036 x^4)
 *   camber y_c = m/p^2 (2 p x - x^2) (x < p), m/(1-p)^2 ((1 - 2p) + 2 p x - x^2) (x >= p)
 *   upper (x - y_t sin th, y_c + y_t cos th), lower (x + y_t sin th, y_c - y_t cos th),
 *   th = atan(dy_c/dx).
 * Chord stations x_k = (1 - cos(pi k / h)) / 2, k = 0 .. h (h = markers/2):
 * cosine spacing clusters markers at the leading edge, where the curvature
 * is largest (radius 1.1019 t^2 c), and at the trailing edge.
 *
 * Symmetry: a symmetric section at zero incidence gets lower markers that are
 * the exact negatives of the upper ones (y is computed once and negated), and
 * a circle's markers are mirror pairs about the horizontal through its
 * centre (one sine and cosine per pair), so a symmetric flow sees a symmetric
 * wall to the last bit of the marker coordinates. */
#include "couple/ghost/markers.h"

#include "core/mem.h"
#include "core/status.h"

#include <math.h>
#include <string.h>

const char *const IBM_WALL_NAMES[IBM_WALL_COUNT + 1] = {"adiabatic", "isothermal", NULL};
const char *const IBM_BODY_NAMES[IBM_BODY_KIND_COUNT + 1] = {"circle", "naca", "rectangle",
                                                             "polygon", NULL};

void ibm_body_set_free(IbmBodySet *set) {
    if (!set) return;
    for (int i = 0; i < set->count; i++) nspd_free(&set->bodies[i].vertices);
    nspd_free(&set->bodies);
    set->count = 0;
}

double naca4_half_thickness(double x, double t) {
    if (x <= 0.0) return 0.0;
    if (x >= 1.0) return 0.0; /* closed trailing edge: exactly zero, not 1e-17 */
    return 5.0 * t *
           (0.2969 * sqrt(x) + x * (-0.1260 + x * (-0.3516 + x * (0.2843 + x * -0.1036))));
}

static bool naca_digits_ok(const char *d) {
    if (strlen(d) != 4) return false;
    for (int i = 0; i < 4; i++)
        if (d[i] < '0' || d[i] > '9') return false;
    return true;
}

int ibm_body_validate(const IbmBodyConfig *b) {
    const char *nm = b->name[0] ? b->name : "body";
    switch (b->kind) {
    case IBM_BODY_CIRCLE:
        if (!(b->radius > 0.0))
            return NSPD_FAIL(NSPD_ERR_INPUT, "%s: circle radius must be > 0", nm);
        if (b->markers < 8)
            return NSPD_FAIL(NSPD_ERR_INPUT, "%s: a circle needs >= 8 markers (got %d)", nm,
                             b->markers);
        break;
    case IBM_BODY_NACA: {
        if (!naca_digits_ok(b->digits))
            return NSPD_FAIL(NSPD_ERR_INPUT, "%s: NACA digits '%s' are not 4 digits", nm,
                             b->digits);
        if (b->digits[2] == '0' && b->digits[3] == '0')
            return NSPD_FAIL(NSPD_ERR_INPUT, "%s: NACA %s has zero thickness", nm, b->digits);
        if ((b->digits[0] == '0') != (b->digits[1] == '0'))
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "%s: NACA %s: camber and its position must both be zero or both "
                             "non-zero",
                             nm, b->digits);
        if (!(b->chord > 0.0)) return NSPD_FAIL(NSPD_ERR_INPUT, "%s: chord must be > 0", nm);
        if (b->markers < 8 || b->markers % 2)
            return NSPD_FAIL(NSPD_ERR_INPUT, "%s: an airfoil needs an even number >= 8 of markers",
                             nm);
        break;
    }
    case IBM_BODY_RECTANGLE:
        if (!(b->max[0] > b->min[0]) || !(b->max[1] > b->min[1]))
            return NSPD_FAIL(NSPD_ERR_INPUT, "%s: rectangle max must exceed min on both axes", nm);
        if (b->markers_per_side < 1)
            return NSPD_FAIL(NSPD_ERR_INPUT, "%s: markers_per_side must be >= 1", nm);
        break;
    case IBM_BODY_POLYGON:
        if (b->vertex_count < 3 || !b->vertices)
            return NSPD_FAIL(NSPD_ERR_INPUT, "%s: a polygon needs >= 3 vertices", nm);
        break;
    default:
        return NSPD_FAIL(NSPD_ERR_INPUT, "%s: unknown body shape", nm);
    }
    if (b->thermal != IBM_WALL_ADIABATIC && b->thermal != IBM_WALL_ISOTHERMAL)
        return NSPD_FAIL(NSPD_ERR_INPUT, "%s: unknown wall thermal condition", nm);
    if (b->thermal == IBM_WALL_ISOTHERMAL && !(b->wall_temperature > 0.0))
        return NSPD_FAIL(NSPD_ERR_INPUT, "%s: an isothermal wall needs a temperature > 0", nm);
    return NSPD_OK;
}

static int alloc_polyline(IbmPolyline *p, int n) {
    memset(p, 0, sizeof *p);
    p->leading_edge = p->trailing_edge = -1;
    int st = nspd_alloc(&p->x, (size_t)n, sizeof(double));
    if (st == NSPD_OK) st = nspd_alloc(&p->y, (size_t)n, sizeof(double));
    if (st == NSPD_OK) st = nspd_alloc(&p->vx, (size_t)n, sizeof(double));
    if (st == NSPD_OK) st = nspd_alloc(&p->vy, (size_t)n, sizeof(double));
    if (st < 0) {
        ibm_polyline_free(p);
        return st;
    }
    p->n = n;
    return NSPD_OK;
}

void ibm_polyline_free(IbmPolyline *p) {
    nspd_free(&p->x);
    nspd_free(&p->y);
    nspd_free(&p->vx);
    nspd_free(&p->vy);
    memset(p, 0, sizeof *p);
    p->leading_edge = p->trailing_edge = -1;
}

double ibm_polyline_area(const IbmPolyline *p) {
    /* shoelace about the first marker: less cancellation far from the origin */
    double a = 0.0;
    const double x0 = p->x[0], y0 = p->y[0];
    for (int k = 1; k + 1 < p->n; k++)
        a += (p->x[k] - x0) * (p->y[k + 1] - y0) - (p->x[k + 1] - x0) * (p->y[k] - y0);
    return 0.5 * a;
}

int ibm_polyline_check(const IbmPolyline *p, int index) {
    if (p->n < 3 || !p->x || !p->y)
        return NSPD_FAIL(NSPD_ERR_INPUT, "immersed body %d: needs >= 3 markers (got %d)", index,
                         p->n);
    for (int k = 0; k < p->n; k++) {
        const int q = (k + 1) % p->n;
        if (!isfinite(p->x[k]) || !isfinite(p->y[k]))
            return NSPD_FAIL(NSPD_ERR_INPUT, "immersed body %d: marker %d is not finite", index, k);
        if (p->x[k] == p->x[q] && p->y[k] == p->y[q])
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "immersed body %d: markers %d and %d coincide at (%g, %g)", index, k,
                             q, p->x[k], p->y[k]);
    }
    if (!(ibm_polyline_area(p) > 0.0))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "immersed body %d: the markers enclose a signed area of %g m^2; expected "
                         "a counter-clockwise outline of positive area (coordinates that keep "
                         "the body's size: not over about 1e12 times it)",
                         index, ibm_polyline_area(p));
    if (p->thermal != IBM_WALL_ADIABATIC && p->thermal != IBM_WALL_ISOTHERMAL)
        return NSPD_FAIL(NSPD_ERR_INPUT, "immersed body %d: unknown thermal condition", index);
    if (p->thermal == IBM_WALL_ISOTHERMAL && !(p->wall_temperature > 0.0))
        return NSPD_FAIL(NSPD_ERR_INPUT, "immersed body %d: wall temperature must be > 0", index);
    return NSPD_OK;
}

static void make_circle(const IbmBodyConfig *b, IbmPolyline *p) {
    const int n = b->markers;
    const double cx = b->center[0], cy = b->center[1], r = b->radius;
    /* marker k at angle pi + 2 pi k / n; k and n - k are mirror images */
    for (int k = 0; 2 * k <= n; k++) {
        const double a = 2.0 * M_PI * k / n;
        const double c = r * cos(a), s = r * sin(a);
        p->x[k] = cx - c;
        p->y[k] = cy - s;
        if (k > 0 && 2 * k < n) {
            p->x[n - k] = cx - c;
            p->y[n - k] = cy + s;
        }
    }
    p->leading_edge = 0;
    p->trailing_edge = n % 2 == 0 ? n / 2 : -1;
}

static void make_naca(const IbmBodyConfig *b, IbmPolyline *p) {
    const int n = b->markers, h = n / 2;
    const double m = (b->digits[0] - '0') / 100.0, pc = (b->digits[1] - '0') / 10.0;
    const double t = ((b->digits[2] - '0') * 10 + (b->digits[3] - '0')) / 100.0;
    const double al = b->angle_deg * M_PI / 180.0, ca = cos(al), sa = sin(al);
    const double c = b->chord, x0 = b->leading_edge[0], y0 = b->leading_edge[1];
    /* station k (0 = LE .. h = TE): upper marker h - k, lower marker h + k (mod n) */
    for (int k = 0; k <= h; k++) {
        const double x = k == h ? 1.0 : 0.5 * (1.0 - cos(M_PI * k / h));
        const double yt = naca4_half_thickness(x, t);
        double yc = 0.0, dyc = 0.0;
        if (m > 0.0) {
            if (x < pc) {
                yc = m / (pc * pc) * (2.0 * pc * x - x * x);
                dyc = 2.0 * m / (pc * pc) * (pc - x);
            } else {
                yc = m / ((1.0 - pc) * (1.0 - pc)) * ((1.0 - 2.0 * pc) + 2.0 * pc * x - x * x);
                dyc = 2.0 * m / ((1.0 - pc) * (1.0 - pc)) * (pc - x);
            }
        }
        const double th = atan(dyc), st = sin(th), ct = cos(th);
        const double xu = x - yt * st, yu = yc + yt * ct;
        const double xl = x + yt * st, yl = yc - yt * ct;
        const int iu = h - k, il = (h + k) % n;
        /* chord frame -> flow frame: turned clockwise by the angle of attack */
        p->x[iu] = x0 + c * (xu * ca + yu * sa);
        p->y[iu] = y0 + c * (-xu * sa + yu * ca);
        if (k > 0 && k < h) {
            p->x[il] = x0 + c * (xl * ca + yl * sa);
            p->y[il] = y0 + c * (-xl * sa + yl * ca);
        }
    }
    p->leading_edge = h;
    p->trailing_edge = 0;
}

static void make_rectangle(const IbmBodyConfig *b, IbmPolyline *p) {
    const int m = b->markers_per_side;
    const double cx[4] = {b->min[0], b->max[0], b->max[0], b->min[0]};
    const double cy[4] = {b->min[1], b->min[1], b->max[1], b->max[1]};
    for (int s = 0; s < 4; s++) {
        const int e = (s + 1) % 4;
        for (int k = 0; k < m; k++) {
            const double f = (double)k / m;
            p->x[s * m + k] = cx[s] + f * (cx[e] - cx[s]);
            p->y[s * m + k] = cy[s] + f * (cy[e] - cy[s]);
        }
    }
}

/* Vertices refined so that no segment exceeds max_spacing; counter-clockwise. */
static int make_polygon(const IbmBodyConfig *b, IbmPolyline *p) {
    const int nv = b->vertex_count;
    const double *v = b->vertices;
    double area = 0.0;
    for (int i = 0; i < nv; i++) {
        const int j = (i + 1) % nv;
        area += v[2 * i] * v[2 * j + 1] - v[2 * j] * v[2 * i + 1];
    }
    if (area == 0.0) return NSPD_FAIL(NSPD_ERR_INPUT, "%s: the polygon has zero area", b->name);
    const bool flip = area < 0.0;
    int total = 0;
    for (int i = 0; i < nv; i++) {
        const int j = (i + 1) % nv;
        const double len = hypot(v[2 * j] - v[2 * i], v[2 * j + 1] - v[2 * i + 1]);
        total += b->max_spacing > 0.0 ? (int)fmax(1.0, ceil(len / b->max_spacing)) : 1;
    }
    TRY(alloc_polyline(p, total));
    int k = 0;
    for (int e = 0; e < nv; e++) {
        /* walk the edges in counter-clockwise order */
        const int i = flip ? (nv - e) % nv : e, j = flip ? (nv - e - 1 + nv) % nv : (e + 1) % nv;
        const double len = hypot(v[2 * j] - v[2 * i], v[2 * j + 1] - v[2 * i + 1]);
        const int parts = b->max_spacing > 0.0 ? (int)fmax(1.0, ceil(len / b->max_spacing)) : 1;
        for (int q = 0; q < parts; q++) {
            const double f = (double)q / parts;
            p->x[k] = v[2 * i] + f * (v[2 * j] - v[2 * i]);
            p->y[k] = v[2 * i + 1] + f * (v[2 * j + 1] - v[2 * i + 1]);
            k++;
        }
    }
    return NSPD_OK;
}

int ibm_body_markers(const IbmBodyConfig *b, IbmPolyline *out) {
    memset(out, 0, sizeof *out);
    out->leading_edge = out->trailing_edge = -1;
    TRY(ibm_body_validate(b));
    switch (b->kind) {
    case IBM_BODY_CIRCLE:
        TRY(alloc_polyline(out, b->markers));
        make_circle(b, out);
        break;
    case IBM_BODY_NACA:
        TRY(alloc_polyline(out, b->markers));
        make_naca(b, out);
        break;
    case IBM_BODY_RECTANGLE:
        TRY(alloc_polyline(out, 4 * b->markers_per_side));
        make_rectangle(b, out);
        break;
    case IBM_BODY_POLYGON:
        TRY(make_polygon(b, out));
        break;
    default:
        return NSPD_FAIL(NSPD_ERR_INPUT, "unknown body shape");
    }
    out->thermal = b->thermal;
    out->wall_temperature = b->wall_temperature;
    const int st = ibm_polyline_check(out, 0);
    if (st < 0) ibm_polyline_free(out);
    return st;
}
