/* Triangulated surfaces from STL files (issue 61: geometry import), binary
 * and ASCII, read without a library (the format is two pages: an 80-byte
 * header, a uint32 count and 50 bytes a triangle; or "solid ... facet
 * normal ... outer loop vertex x y z (x3) endloop endfacet ... endsolid").
 * A binary file is told by its size (84 + 50 n bytes for the count n it
 * states), since binary headers may also begin with "solid". The facet
 * normals are ignored (the containment test does not need them). */
#ifndef NSPD_IO_STL_READ_H
#define NSPD_IO_STL_READ_H

#include "io/in_file.h"

#include <stdint.h>

typedef InFileError StlReadError; /* io/in_file.h */

enum { STL_MAX_TRIANGLES = 20000000 };

/* Reads the triangles into *tri (9 doubles each, the caller frees with
 * nspd_free) and their count. NSPD_ERR_IO if the file cannot be opened,
 * NSPD_ERR_INPUT for a file that is not STL (described in *err: the line
 * or byte offset, what was expected), NSPD_ERR_NOMEM. */
int stl_read_file(const char *path, double **tri, int64_t *count, StlReadError *err);

#endif
