/* Immersed bodies as closed polylines of markers, and the shapes that make them.
 *
 * A body's wall is a closed polyline (paper 000 Sec. 3.3: "discrete body
 * markers connected by linear segments"): markers x[k], y[k], k = 0 .. n-1,
 * segment k joins marker k to marker (k + 1) mod n. Invariants the immersed
 * boundary relies on:
 *   - counter-clockwise order (positive signed area), so the outward normal
 *     of segment a -> b is (b_y - a_y, a_x - b_x) / |b - a|;
 *   - n >= 3, no zero-length segment;
 *   - vx, vy: the wall velocity at each marker (NULL: the wall is at rest);
 *     between markers the wall velocity is linear along the segment (Eq. 32);
 *   - one thermal condition per polyline.
 * A deforming solid hands the immersed boundary polylines with the same
 * layout every step (IbmPolyline); the shapes below make them for fixed
 * bodies. Coordinates m, velocities m/s, temperatures K. */
#ifndef NSPD_COUPLE_GHOST_MARKERS_H
#define NSPD_COUPLE_GHOST_MARKERS_H

#include <stdbool.h>

typedef enum {
    IBM_WALL_ADIABATIC = 0,  /* dT/dn = 0 (Neumann rows, Eqs. 36, 38) */
    IBM_WALL_ISOTHERMAL = 1, /* T = wall_temperature (Dirichlet rows, Eqs. 35, 37) */
    IBM_WALL_COUNT
} IbmWallThermal;

extern const char *const IBM_WALL_NAMES[IBM_WALL_COUNT + 1]; /* "adiabatic", "isothermal", NULL */

/* One closed, counter-clockwise wall. The arrays are borrowed by the
 * functions that take a polyline, owned by whoever made it (free it with
 * ibm_polyline_free when it came from ibm_body_markers). */
typedef struct {
    int n;                   /* markers, >= 3 */
    double *x, *y;           /* marker positions, m */
    double *vx, *vy;         /* wall velocity per marker, m/s; NULL: at rest */
    int thermal;             /* IbmWallThermal */
    double wall_temperature; /* K (isothermal) */
    /* Optional, for surface outputs: the markers at the leading and
     * trailing edge (airfoils), -1 when not given; then the most upstream
     * and most downstream markers along the free stream are used. */
    int leading_edge, trailing_edge;
} IbmPolyline;

typedef enum {
    IBM_BODY_CIRCLE = 0,
    IBM_BODY_NACA,
    IBM_BODY_RECTANGLE,
    IBM_BODY_POLYGON,
    IBM_BODY_KIND_COUNT
} IbmBodyKind;

extern const char *const IBM_BODY_NAMES[IBM_BODY_KIND_COUNT + 1]; /* "circle", "naca", ... */

enum { IBM_NAME_MAX = 64 };

/* A fixed body as a case file describes it (io/case_bodies.c reads it). */
typedef struct {
    IbmBodyKind kind;
    char name[IBM_NAME_MAX]; /* for outputs: "body0", "cylinder", ... */
    /* circle: centre, radius; `markers` equally spaced in angle, the first
     * at the most upstream point (angle pi), so the marker set is symmetric
     * about the horizontal through the centre. */
    double center[2], radius;
    /* naca: 4-digit series "MPTT" (max camber M %, its position P/10, thickness
     * TT %), chord (m), leading-edge point, angle of attack (deg, nose up for a
     * flow along +x: the airfoil is turned clockwise about its leading edge).
     * Closed trailing edge (a4 = -0.1036); `markers` (even) with cosine
     * spacing along the chord; marker 0 is the trailing edge, marker
     * markers/2 the leading edge. */
    char digits[5];
    double chord, leading_edge[2], angle_deg;
    /* circle, naca: total markers (>= 8; even for naca) */
    int markers;
    /* rectangle: corners; markers_per_side markers on each side, starting at min */
    double min[2], max[2];
    int markers_per_side;
    /* polygon: vertices (owned, x y pairs; read from a CSV file by io/),
     * refined so that no segment is longer than max_spacing (<= 0: as given);
     * reordered counter-clockwise if given clockwise. */
    int vertex_count;
    double *vertices;
    double max_spacing;
    char path[256]; /* the file it came from, for messages */
    /* wall */
    int thermal; /* IbmWallThermal */
    double wall_temperature;
} IbmBodyConfig;

/* A list of bodies (owned arrays). */
typedef struct {
    int count;
    IbmBodyConfig *bodies;
} IbmBodySet;

void ibm_body_set_free(IbmBodySet *set);

/* Half-thickness of a NACA 4-digit section at x (chord fraction, 0..1), for
 * thickness ratio t (0.12 for "0012"), closed trailing edge:
 *   y_t = 5 t (0.2969 sqrt(x) - 0.1260 x - 0.3516 x^2 + 0.2843 x^3 - 0.1036 x^4). */
double naca4_half_thickness(double x, double t);

/* Checks a body configuration (positive sizes, marker counts, digits);
 * NSPD_ERR_INPUT with a message naming the body. */
int ibm_body_validate(const IbmBodyConfig *b);

/* Makes the markers of a body: allocates out->x, y, vx, vy (zero wall
 * velocity), sets the thermal condition and the edge markers. The result is
 * counter-clockwise. NSPD_ERR_INPUT for an invalid body, NSPD_ERR_NOMEM. */
int ibm_body_markers(const IbmBodyConfig *b, IbmPolyline *out);

/* Frees arrays made by ibm_body_markers (or nspd_alloc) and zeroes *p. */
void ibm_polyline_free(IbmPolyline *p);

/* Signed area (m^2) of a closed polyline, > 0 counter-clockwise. */
double ibm_polyline_area(const IbmPolyline *p);

/* Checks the invariants above (n >= 3, finite coordinates, no zero-length
 * segment, counter-clockwise); NSPD_ERR_INPUT naming polyline `index`. */
int ibm_polyline_check(const IbmPolyline *p, int index);

#endif
