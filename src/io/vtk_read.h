/* Reads back the rectilinear-grid files nspd writes (io/vtk.h), whole or
 * in pieces (.pvtr), and its point sets (.vtu, .pvtu): the XML
 * header, then the raw appended block of Float64 arrays, each behind a
 * UInt64 byte count. Only that form is accepted (what vtk_write_rectilinear
 * produces: little-endian, header_type UInt64, encoding raw, Float64 cell
 * data and coordinates); anything else is refused with a message that says
 * what was found. Used to start a flow from an earlier run's field. */
#ifndef NSPD_IO_VTK_READ_H
#define NSPD_IO_VTK_READ_H

#include <stdint.h>

enum { VTK_MAX_ARRAYS = 16, VTK_MAX_NAME = 64 };

typedef struct {
    char name[VTK_MAX_NAME];
    int components;
    double *data; /* cells * components values, components interleaved, x fastest */
} VtkCellArray;

typedef struct {
    int n[3];        /* cells along x, y, z */
    double *face[3]; /* face coordinates, n[a] + 1 each */
    int array_count;
    VtkCellArray arrays[VTK_MAX_ARRAYS];
} VtkRectilinear;

/* Reads `path` into *out (allocating its arrays; free with
 * vtk_rectilinear_free, also after a failure). Fails with NSPD_ERR_IO when
 * the file cannot be read and NSPD_ERR_INPUT when it is not such a file. */
int vtk_read_rectilinear(const char *path, VtkRectilinear *out);

/* The cell array called `name` with `components` components, or NULL. */
const VtkCellArray *vtk_find_cell_array(const VtkRectilinear *grid, const char *name,
                                        int components);

void vtk_rectilinear_free(VtkRectilinear *grid);

/* The point sets nspd writes (.vtu: a solid's material points), or the
 * .pvtu of the pieces several processes wrote, read back whole: the
 * pieces' points in piece order (for a divided solid, the whole body's
 * order). The vertex cells are not read (they number the points of their
 * own file). */
typedef struct {
    int64_t n;
    double *points; /* 3 n coordinates, components interleaved */
    int array_count;
    VtkCellArray arrays[VTK_MAX_ARRAYS]; /* the point data: n * components values */
} VtkPointSet;

int vtk_read_points(const char *path, VtkPointSet *out);
void vtk_point_set_free(VtkPointSet *set);

#endif
