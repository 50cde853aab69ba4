/* A closed triangulated surface as a shape (issue 61: geometry from STL
 * files): whether a point lies inside, by the parity of a ray's crossings
 * along +x, the triangles binned on a grid over (y, z) so that a query
 * tests the few whose shadow holds the point. A ray through an edge or a
 * vertex is counted once: the shadows are tested with the top-left rule of
 * rasterisation (each point of the (y, z) plane belongs to exactly one of
 * the shadows that meet at an edge from opposite sides, to both or neither
 * where they fold over it), so the parity is right on any closed surface.
 * A point on the surface is inside (closed, as every shape). */
#ifndef NSPD_CORE_SHAPE_MESH_H
#define NSPD_CORE_SHAPE_MESH_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

typedef struct ShapeMesh ShapeMesh;

/* Builds the shape of `count` triangles (9 doubles each: three vertices),
 * copied. Refuses (NSPD_ERR_INPUT, the reason in `why`) a surface that is
 * not closed - an edge not shared by exactly two triangles, vertices
 * matched by their exact coordinates - or holds no triangle of non-zero
 * area. NSPD_ERR_NOMEM. */
int shape_mesh_create(const double *triangles, int64_t count, ShapeMesh **out, char *why,
                      size_t why_size);
void shape_mesh_free(ShapeMesh **m);

bool shape_mesh_contains(const ShapeMesh *m, const double p[3]);
/* The section of the surface by the plane z = z as one closed polygon
 * (the flow's bodies in 2D): *xy its vertices (x0, y0, x1, y1, ..., the
 * caller frees with nspd_free), *count their number. Each triangle that
 * the plane cuts gives a segment (a vertex on the plane counts as above
 * it, so a segment never degenerates and each edge's crossing is computed
 * once, from its ends in one order); the segments are chained by their
 * exact end points. NSPD_ERR_INPUT (reason in `why`) if the plane misses
 * the surface or cuts it in more than one loop. */
int shape_mesh_section(const ShapeMesh *m, double z, double **xy, int *count, char *why,
                       size_t why_size);

/* The bounding box of the vertices. */
void shape_mesh_bounds(const ShapeMesh *m, double lo[3], double hi[3]);
int64_t shape_mesh_triangles(const ShapeMesh *m);

#endif
