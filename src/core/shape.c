#include "core/shape.h"

#include "core/mem.h"
#include "core/shape_mesh.h"

#include <math.h>

const char *const SHAPE_NAMES[SHAPE_KIND_COUNT + 1] = {
    "rectangle", "disc", "annulus", "polygon", "box", "sphere", "cylinder", "stl", NULL};

bool shape_is_3d(ShapeKind kind) {
    return kind == SHAPE_BOX || kind == SHAPE_SPHERE || kind == SHAPE_CYLINDER;
}

/* Crossing-number test with the half-open rule (an edge owns its lower end),
 * so a ray through a vertex is counted once; points on an edge count as
 * inside through the explicit on-segment check. */
static bool polygon_contains(const double *v, int n, double x, double y) {
    bool inside = false;
    for (int i = 0, j = n - 1; i < n; j = i++) {
        double xi = v[2 * i], yi = v[2 * i + 1], xj = v[2 * j], yj = v[2 * j + 1];
        double cross = (xj - xi) * (y - yi) - (yj - yi) * (x - xi);
        double len2 = (xj - xi) * (xj - xi) + (yj - yi) * (yj - yi);
        if (fabs(cross) <= 1e-12 * len2 && x >= fmin(xi, xj) && x <= fmax(xi, xj) &&
            y >= fmin(yi, yj) && y <= fmax(yi, yj))
            return true; /* on the edge */
        if ((yi > y) != (yj > y)) {
            double x_cross = xi + (y - yi) * (xj - xi) / (yj - yi);
            if (x < x_cross) inside = !inside;
        }
    }
    return inside;
}

bool shape_contains(const Shape *s, const double x[3]) {
    double dx = x[0] - s->center[0], dy = x[1] - s->center[1], dz = x[2] - s->center[2];
    switch (s->kind) {
    case SHAPE_RECTANGLE:
        return x[0] >= s->lo[0] && x[0] <= s->hi[0] && x[1] >= s->lo[1] && x[1] <= s->hi[1];
    case SHAPE_DISC:
        return dx * dx + dy * dy <= s->radius * s->radius;
    case SHAPE_ANNULUS: {
        double r2 = dx * dx + dy * dy;
        return r2 <= s->radius * s->radius && r2 >= s->inner_radius * s->inner_radius;
    }
    case SHAPE_POLYGON:
        return polygon_contains(s->vertices, s->vertex_count, x[0], x[1]);
    case SHAPE_BOX:
        return x[0] >= s->lo[0] && x[0] <= s->hi[0] && x[1] >= s->lo[1] && x[1] <= s->hi[1] &&
               x[2] >= s->lo[2] && x[2] <= s->hi[2];
    case SHAPE_SPHERE:
        return dx * dx + dy * dy + dz * dz <= s->radius * s->radius;
    case SHAPE_CYLINDER:
        return dx * dx + dy * dy <= s->radius * s->radius && fabs(dz) <= 0.5 * s->length;
    case SHAPE_STL: {
        const double p[3] = {x[0], x[1], s->section ? s->section_z : x[2]};
        return shape_mesh_contains(s->mesh, p);
    }
    default:
        return false;
    }
}

bool shapeset_contains(const ShapeSet *set, const double x[3]) {
    bool inside = false;
    for (int i = 0; i < set->count; i++)
        if (shape_contains(&set->shapes[i], x)) inside = !set->shapes[i].subtract;
    return inside;
}

static void shape_bounds(const Shape *s, double lo[3], double hi[3]) {
    for (int d = 0; d < 3; d++) {
        lo[d] = s->center[d] - s->radius;
        hi[d] = s->center[d] + s->radius;
    }
    switch (s->kind) {
    case SHAPE_RECTANGLE:
    case SHAPE_BOX:
        for (int d = 0; d < 3; d++) {
            lo[d] = s->lo[d];
            hi[d] = s->hi[d];
        }
        break;
    case SHAPE_POLYGON:
        lo[0] = hi[0] = s->vertices[0];
        lo[1] = hi[1] = s->vertices[1];
        for (int i = 1; i < s->vertex_count; i++) {
            lo[0] = fmin(lo[0], s->vertices[2 * i]);
            hi[0] = fmax(hi[0], s->vertices[2 * i]);
            lo[1] = fmin(lo[1], s->vertices[2 * i + 1]);
            hi[1] = fmax(hi[1], s->vertices[2 * i + 1]);
        }
        lo[2] = hi[2] = 0.0;
        break;
    case SHAPE_CYLINDER:
        lo[2] = s->center[2] - 0.5 * s->length;
        hi[2] = s->center[2] + 0.5 * s->length;
        break;
    case SHAPE_STL:
        shape_mesh_bounds(s->mesh, lo, hi);
        if (s->section) lo[2] = hi[2] = 0.0;
        break;
    default:
        break;
    }
}

bool shapeset_bounds(const ShapeSet *set, int dim, double lo[3], double hi[3]) {
    bool any = false;
    for (int i = 0; i < set->count; i++) {
        if (set->shapes[i].subtract) continue;
        double slo[3], shi[3];
        shape_bounds(&set->shapes[i], slo, shi);
        for (int d = 0; d < dim && d < 3; d++) { /* dim <= 3: slo, shi have 3 */
            lo[d] = any ? fmin(lo[d], slo[d]) : slo[d];
            hi[d] = any ? fmax(hi[d], shi[d]) : shi[d];
        }
        any = true;
    }
    for (int d = dim; d < 3; d++) lo[d] = hi[d] = 0.0;
    return any;
}

double polygon_signed_area(const double *xy, int n) {
    double a = 0.0;
    for (int i = 0, j = n - 1; i < n; j = i++)
        a += xy[2 * j] * xy[2 * i + 1] - xy[2 * i] * xy[2 * j + 1];
    return 0.5 * a;
}

void shapeset_free(ShapeSet *set) {
    for (int i = 0; i < set->count; i++) {
        nspd_free(&set->shapes[i].vertices);
        shape_mesh_free(&set->shapes[i].mesh);
    }
    nspd_free(&set->shapes);
    set->count = 0;
}

/* The integral of sqrt(r^2 - t^2) dt from 0 to t (|t| <= r). */
static double chord_integral(double t, double r) {
    const double c = t / r;
    return 0.5 * (t * sqrt(fmax(r * r - t * t, 0.0)) + r * r * asin(c > 1 ? 1 : c < -1 ? -1 : c));
}

/* The area of the disc of radius r at the origin with x' <= x and y' <= y. */
static double disc_corner_area(double x, double y, double r) {
    if (x <= -r || y <= -r) return 0.0;
    const double X = fmin(x, r);
    if (y >= r) return 2.0 * (chord_integral(X, r) - chord_integral(-r, r));
    /* |y| < r: the column height at t is 2 s(t) where s(t) <= y (y >= 0), 0
     * where s(t) <= -y (y < 0), and y + s(t) for |t| < a */
    const double a = sqrt(r * r - y * y);
    double area = 0.0;
    const double cuts[4] = {-r, -a, a, r};
    for (int k = 0; k < 3; k++) {
        const double p = cuts[k], q = fmin(cuts[k + 1], X);
        if (p >= X) break;
        if (q <= p) continue; /* an empty piece (y = 0 leaves a = r) */
        const double g = chord_integral(q, r) - chord_integral(p, r);
        if (k == 1)
            area += y * (q - p) + g;
        else if (y >= 0.0)
            area += 2.0 * g;
    }
    return area;
}

double shape_area_in_rect(const Shape *s, double x0, double x1, double y0, double y1) {
    if (s->kind == SHAPE_RECTANGLE) {
        const double w = fmin(x1, s->hi[0]) - fmax(x0, s->lo[0]);
        const double h = fmin(y1, s->hi[1]) - fmax(y0, s->lo[1]);
        return w > 0.0 && h > 0.0 ? w * h : 0.0;
    }
    if (s->kind != SHAPE_DISC) return -1.0;
    const double cx = s->center[0], cy = s->center[1], r = s->radius;
    /* not clamped at 0: a cell the circle only touches may come out at
     * -1e-11 of r^2, and a clamp would break the telescoping that makes a
     * tiling's cells sum to the disc's area */
    return disc_corner_area(x1 - cx, y1 - cy, r) - disc_corner_area(x0 - cx, y1 - cy, r) -
           disc_corner_area(x1 - cx, y0 - cy, r) + disc_corner_area(x0 - cx, y0 - cy, r);
}
