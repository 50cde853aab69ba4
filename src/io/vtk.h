/* VTK XML writers that ParaView and VTK's own readers open:
 *   .vtu  material points (UnstructuredGrid of vertex cells) with point data
 *   .vtr  a rectilinear grid with cell data (and point data at its nodes)
 *   .pvtr, .pvtu  the pieces of one of those written by several processes
 *   .pvd  a time series pointing at the files above
 * Data are binary, appended raw (little-endian, UInt64 block headers): the
 * fastest form to write and read, and exact (Float64). */
#ifndef NSPD_IO_VTK_H
#define NSPD_IO_VTK_H

#include "core/fields.h"

#include <stdint.h>

/* A field given as one array per component (struct of arrays); `data[c]`
 * holds n values. Components: 1 (scalar) or 3 (vector; NULL components are
 * written as zeros, e.g. z in 2D). The same record models hand to output. */
typedef FieldRef VtkField;

/* n points at positions pos[0..2] (NULL component = 0). */
int vtk_write_points(const char *path, int64_t n, const double *const pos[3],
                     const VtkField *fields, int field_count);

/* Cells of a rectilinear grid with nx * ny * nz cells; face coordinates
 * xf[0..nx], yf[0..ny], zf[0..nz]; fields hold nx*ny*nz values, x fastest;
 * point_fields (point_count of them, 0: no PointData element) hold the
 * (nx+1)(ny+1) values of one layer of nodes, x fastest, written on each of
 * the nz + 1 layers (a 2D grid is one cell thick). */
int vtk_write_rectilinear(const char *path, int nx, int ny, int nz, const double *xf,
                          const double *yf, const double *zf, const VtkField *fields,
                          int field_count, const VtkField *point_fields, int point_count);

/* One piece of a 2D grid written by several processes: the cells
 * cells = {i0, i1, j0, j1} of the whole grid, [i0, i1) x [j0, j1), one
 * cell thick; faces xf[0..i1-i0], yf[0..j1-j0]; fields hold its cells, x
 * fastest. A .vtr of its own, its extent the whole grid's numbering. */
int vtk_write_rectilinear_piece(const char *path, const int cells[4], const double *xf,
                                const double *yf, const VtkField *fields, int field_count);
/* The parallel files that name the pieces (ParaView's .pvtr, .pvtu):
 * sources[p] is piece p's file name, relative to the parallel file; the
 * fields' names and components declare the pieces' arrays (their data
 * pointers are not read). A .pvtr's grid has nx x ny cells, one thick,
 * and cells[p] is piece p's as above; a .pvtu's pieces are point sets. */
int vtk_write_pvtr(const char *path, int nx, int ny, int piece_count, const int (*cells)[4],
                   const char *const *sources, const VtkField *fields, int field_count);
int vtk_write_pvtu(const char *path, int piece_count, const char *const *sources,
                   const VtkField *fields, int field_count);

/* A .pvd collection, rewritten whole after each addition so that it is
 * valid even if the run stops early. */
typedef struct {
    int count, cap;
    double *times;
    char **files;
} PvdSeries;

int pvd_add(PvdSeries *series, const char *pvd_path, double time, const char *file_name);
/* The two halves of pvd_add: an entry added in memory; the file rewritten
 * whole from the entries. */
int pvd_append(PvdSeries *series, double time, const char *file_name);
int pvd_write(const PvdSeries *series, const char *pvd_path);
void pvd_free(PvdSeries *series);

#endif
