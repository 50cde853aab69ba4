/* Abaqus input files (.inp): the mesh part, read without a library (issue
 * 61: geometry import; Debian packages no C reader of .inp, and the format's
 * mesh part is a page): *NODE (id, x, y[, z]), *ELEMENT with TYPE= one of
 * the linear 2D area elements (CPS3, CPE3, S3, S3R: triangles; CPS4, CPE4,
 * CPS4R, CPE4R, CPS4I, CPE4I, S4, S4R: quadrilaterals; their hybrid H
 * variants), taken in the x-y plane, or the linear 3D solids (C3D4; C3D8,
 * C3D8R, C3D8I and H variants), *NSET and *ELSET (ids, GENERATE ranges,
 * earlier sets' names) and the NSET= and ELSET= of *NODE and *ELEMENT.
 * Keywords, parameters and set names are case-insensitive; `**` lines are
 * comments; a data line of element connectivity that ends in a comma goes on
 * on the next line; every other keyword (*HEADING, *PART, *INSTANCE,
 * *MATERIAL, *STEP, ... ) is skipped with its data lines, but *INCLUDE and
 * INPUT= are refused (the mesh would be read in part). Several parts'
 * nodes and elements are read as one mesh in the file's coordinates (an
 * *INSTANCE's translation is not applied): one part per file.
 *
 * Every element's centroid and measure (area in 2D, volume in 3D) are
 * computed exactly for its straight-sided (bilinear, trilinear) shape: a
 * triangle's and tetrahedron's from their vertices, a quadrilateral's from
 * its two triangles, a hexahedron's by 2 x 2 x 2 Gauss points, exact for the
 * trilinear map's det J (degree 2 in each coordinate) and x det J (3). The
 * first moment is kept, so the centroid of a distorted quadrilateral is not
 * its nodes' mean (Peridynamics.jl's read_inp takes the mean; the two agree
 * for parallelograms and parallelepipeds). */
#ifndef NSPD_IO_INP_READ_H
#define NSPD_IO_INP_READ_H

#include <stdbool.h>
#include "io/in_file.h"

#include <stdint.h>

typedef InFileError InpReadError; /* io/in_file.h */

typedef enum { INP_TRI3, INP_QUAD4, INP_TET4, INP_HEX8, INP_SHAPE_COUNT } InpShape;

enum {
    INP_MAX_ELEMENT_NODES = 8,
    INP_MAX_NAME = 81,       /* Abaqus's 80 characters and the NUL */
    INP_MAX_SETS = 4096,     /* sets of one kind */
    INP_MAX_BYTES = 1 << 28, /* 256 MiB: about 5 million hexahedra with their nodes */
};

/* ids first, first + step, ... <= last: a single id has first = last */
typedef struct {
    int64_t first, last, step;
    int32_t line; /* where it is written */
    bool generated;
} InpRange;

typedef struct {
    char name[INP_MAX_NAME]; /* upper case: names are case-insensitive */
    bool elements;           /* an element set (*ELSET, ELSET=); else a node set */
    int line;                /* where it is first defined */
    int64_t range_count, range_capacity;
    InpRange *ranges;
} InpSet;

typedef struct {
    int dim; /* 2: area elements in the x-y plane; 3: solid elements */
    int64_t node_count, element_count;
    int64_t *node_id;       /* the file's numbers, in its order */
    double *node_x;         /* 3 per node (z = 0 when not given) */
    int64_t *element_id;    /* the file's numbers, in its order */
    uint8_t *element_shape; /* InpShape */
    int32_t *element_line;  /* where each element is written */
    int64_t *element_node;  /* INP_MAX_ELEMENT_NODES per element: node indices, -1 unused */
    double *centroid;       /* 3 per element */
    double *measure;        /* m^2 (2D) or m^3 (3D) in the file's units: > 0 */
    int set_count;
    InpSet *sets;
    int64_t *node_order, *element_order; /* indices sorted by id (the sets' lookup) */
} InpMesh;

/* Reads the file (at most max_bytes, INP_MAX_BYTES for a case) into *mesh
 * (zeroed first; inp_mesh_free frees it, also after a failure).
 * NSPD_ERR_IO if it cannot be opened, NSPD_ERR_INPUT for a file that is not
 * a mesh nspd takes (described in *err: the line, or for the whole file
 * the byte offset, what was expected): a field that is not a number,
 * duplicate node or element numbers, an element naming a node no *NODE
 * defines, a node count that is not its type's, an unknown element type,
 * 2D and 3D elements together, an element of zero or negative area or
 * volume (its nodes in the wrong order: inverted) or folded, a set naming
 * what is not defined, no element, a file over max_bytes; NSPD_ERR_NOMEM. */
int inp_read_file(const char *path, int64_t max_bytes, InpMesh *mesh, InpReadError *err);
/* The same from `size` bytes of text in memory. */
int inp_read_text(const char *text, int64_t size, InpMesh *mesh, InpReadError *err);
void inp_mesh_free(InpMesh *mesh);

/* The set of that name (case-insensitive) and kind, or NULL. */
const InpSet *inp_find_set(const InpMesh *mesh, const char *name, bool elements);
/* Sets mark[i] = 1 for every node (node set) or element (element set) i
 * the set holds, leaving the others as they are; mark has node_count or
 * element_count bytes. Returns how many it marked that were 0. A generated
 * range skips the numbers no node or element has. */
int64_t inp_set_mark(const InpMesh *mesh, const InpSet *set, uint8_t *mark);
/* Nodes per element of a shape: 3, 4, 4, 8. */
int inp_shape_nodes(InpShape shape);

#endif
