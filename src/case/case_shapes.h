/* Reading shapes and regions (lists of shapes) from a case file. */
#ifndef NSPD_CASE_CASE_SHAPES_H
#define NSPD_CASE_CASE_SHAPES_H

#include "core/shape.h"
#include "io/cfg_tree.h"

/* Reads map[key], a list of shapes, into *set (which it allocates). Each
 * item: `shape:` one of rectangle, disc, annulus, polygon (2D) or box,
 * sphere, cylinder (3D), its own keys, and `op: add | subtract` (default
 * add). The shapes must match `dim`. Absent key and !required: empty set. */
int case_read_shapes(CfgNode *map, const char *key, int dim, bool required, ShapeSet *set);

#endif
