/* Shapes and their union/difference, for filling lattices and selecting
 * regions (boundary layers, failure zones, initial conditions).
 *
 * 2D shapes: rectangle, disc, annulus, polygon. 3D: box, sphere, cylinder
 * (axis along z). Both: stl, a closed triangulated surface (shape_mesh.h;
 * in 2D its section by the plane z = section_z). A ShapeSet is evaluated in order: a point is
 * inside if the last shape that contains it was added (not subtracted). Boundaries are closed: a
 * point on an edge is inside. Coordinates in metres. */
#ifndef NSPD_CORE_SHAPE_H
#define NSPD_CORE_SHAPE_H

#include <stdbool.h>

typedef enum {
    SHAPE_RECTANGLE, /* lo[0..1], hi[0..1] */
    SHAPE_DISC,      /* center[0..1], radius */
    SHAPE_ANNULUS,   /* center, inner_radius, radius */
    SHAPE_POLYGON,   /* vertices (x, y pairs), closed implicitly */
    SHAPE_BOX,       /* lo[0..2], hi[0..2] */
    SHAPE_SPHERE,    /* center[0..2], radius */
    SHAPE_CYLINDER,  /* center[0..2] (mid-height), radius, length along z */
    SHAPE_STL,       /* mesh; 2D: its section at z = section_z */
    SHAPE_KIND_COUNT
} ShapeKind;

typedef struct {
    ShapeKind kind;
    bool subtract;
    double lo[3], hi[3];
    double center[3];
    double radius, inner_radius, length;
    int vertex_count;
    double *vertices;       /* owned: 2 * vertex_count doubles */
    struct ShapeMesh *mesh; /* owned (SHAPE_STL) */
    bool section;           /* SHAPE_STL in 2D: the plane z = section_z through it */
    double section_z;
} Shape;

typedef struct {
    int count;
    Shape *shapes; /* owned */
} ShapeSet;

extern const char *const SHAPE_NAMES[SHAPE_KIND_COUNT + 1]; /* "rectangle", ..., NULL */

/* Whether the kind is 3D only (stl is both: false). */
bool shape_is_3d(ShapeKind kind);
bool shape_contains(const Shape *s, const double x[3]);
bool shapeset_contains(const ShapeSet *set, const double x[3]);
/* Bounding box of the added shapes (subtractions cannot grow it). Returns
 * false if the set adds nothing. */
bool shapeset_bounds(const ShapeSet *set, int dim, double lo[3], double hi[3]);
/* The area of a 2D shape inside the rectangle [x0, x1] x [y0, y1], exact (a
 * disc's by the closed-form integral of its chord; a rectangle's by its
 * overlap); -1 for the other kinds. */
double shape_area_in_rect(const Shape *s, double x0, double x1, double y0, double y1);

/* Area (2D) of a polygon with the sign of its orientation (+ counter-clockwise). */
double polygon_signed_area(const double *xy, int n);
void shapeset_free(ShapeSet *set);

#endif
