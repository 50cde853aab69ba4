/* Reading shapes and regions (lists of shapes) from a case file. */
#ifndef NSPD_CASE_CASE_SHAPES_H
#define NSPD_CASE_CASE_SHAPES_H

#include "core/shape.h"
#include "core/shape_mesh.h"
#include "io/cfg_tree.h"

/* Reads map[key], a list of shapes, into *set (which it allocates). Each
 * item: `shape:` one of rectangle, disc, annulus, polygon (2D) or box,
 * sphere, cylinder (3D), its own keys, and `op: add | subtract` (default
 * add). The shapes must match `dim`. Absent key and !required: empty set. */
int case_read_shapes(CfgNode *map, const char *key, int dim, bool required, ShapeSet *set);

/* The closed surface of item's STL `file` (relative to the case file;
 * its path into `path`), x -> `scale` x + `translate`: read and checked,
 * refused at item.file with the file's line or byte (shape: stl of solids
 * and of the flow's bodies). */
int case_read_stl_mesh(CfgNode *item, ShapeMesh **mesh, char *path, size_t path_size);

#endif
