/* What a model hands to output: named arrays on its mesh, the pictures to
 * draw of them and tables to write, as plain pointers into the model's own
 * memory (valid until its next step). The generic writer (sim/sim_output.c,
 * through io/) turns a FieldSet into .vtu/.vtr + .pvd, PNG and CSV files;
 * no model knows a file format, and a new model needs no edit there. */
#ifndef NSPD_CORE_FIELDS_H
#define NSPD_CORE_FIELDS_H

#include <stdbool.h>
#include <stdint.h>

typedef enum { COLORMAP_VIRIDIS, COLORMAP_GRAY, COLORMAP_INFERNO } ColormapKind;

typedef enum {
    MESH_NONE = 0, /* tables only */
    MESH_POINTS,   /* scattered points (PD material points, node clouds): .vtu */
    MESH_GRID,     /* a 2D tensor-product grid of cells: .vtr */
} MeshKind;

/* A field: `components` arrays of one value per point or cell; a NULL component of
 * a vector is written as zeros. */
typedef struct {
    const char *name;
    int components; /* 1 or 3 */
    const double *data[3];
} FieldRef;

/* A picture series <file>_NNNNN.png of one field over [lo, hi], its colour
 * bar labelled "label [units]" ("Mach number [-]", "pressure [Pa]"). On a
 * grid, `overlay_file` (if set) asks for a second picture,
 * <overlay_file>_NNNNN.png, with the overlay picture of a coupled points
 * mesh (FieldSet.overlay_picture) drawn on top, coloured with that
 * picture's `overlay_map` and labelled with its label and units on a
 * second bar, in a window round those points. `coupled_only`: the picture
 * and its overlay are drawn only where there is such a mesh (a coupled
 * case), none otherwise. */
typedef struct {
    const char *file;
    const char *label, *units;
    const double *values;
    double lo, hi;
    ColormapKind map;
    const char *overlay_file;
    ColormapKind overlay_map;
    bool coupled_only;
} PictureRef;

/* A table <file>_NNNNN.csv: a "# t = ... s" line, the header, then `rows`
 * rows of the columns (%.9g; the columns of `integer_cols`, bit c for
 * column c, as integers; those of `short_cols` with 6 digits). */
enum { TABLE_MAX_COLUMNS = 12 };
typedef struct {
    const char *file;
    const char *header;
    int64_t rows;
    int ncol;
    const double *col[TABLE_MAX_COLUMNS];
    uint32_t integer_cols;
    uint32_t short_cols;
} TableRef;

/* tables: the PDDO flow's two lines and a wall table for each of its 8 bodies */
enum { FIELDSET_MAX_FIELDS = 12, FIELDSET_MAX_PICTURES = 4, FIELDSET_MAX_TABLES = 10 };

/* This process's part of a mesh that several processes share (issue 28).
 * Each writes its piece as a file of its own (<series>_NNNNN_pPPPP.vtr or
 * .vtu), and the writer (rank 0) a ParaView parallel file (.pvtr, .pvtu)
 * that names them all; no process holds the whole mesh's fields for it.
 * count 0: no pieces (one process, or a model that gathers its mesh). */
typedef struct {
    int index, count; /* this piece, of `count` */
    /* MESH_GRID: every piece's cells of the whole grid, {i0, i1, j0, j1}
     * for [i0, i1) x [j0, j1), `count` of them, in piece order */
    const int (*cells)[4];
    /* this piece's mesh: MESH_POINTS, n points at `position` (pieces in
     * order make the whole set's points); MESH_GRID, the cells of
     * cells[index], between the faces face[0][0..nx], face[1][0..ny] */
    int64_t n;
    const double *position[3];
    int nx, ny;
    const double *face[2];
    /* its fields, the same names and components on every piece */
    int field_count;
    FieldRef field[FIELDSET_MAX_FIELDS];
} FieldPiece;

typedef struct {
    const char *series; /* the files' stem: "solid" -> solid_NNNNN.vtu and solid.pvd */
    MeshKind mesh;
    /* MESH_POINTS: n points at `position` (current, m), each drawn as a
     * square of side `spacing` */
    int64_t n;
    int dim;
    const double *position[3];
    double spacing;
    /* MESH_GRID: nx x ny cells between the faces face[0][0..nx], face[1][0..ny];
     * `blank[c]` non-zero leaves cell c out of pictures (a body's cells) */
    int nx, ny;
    const double *face[2];
    const uint8_t *blank;
    int field_count;
    FieldRef field[FIELDSET_MAX_FIELDS];
    /* MESH_GRID: fields at the (nx + 1) x (ny + 1) grid nodes, x fastest
     * (written as the .vtr's point data beside the cells'; a field defined
     * between the cells, such as a spline's, sampled at the corners) */
    int point_field_count;
    FieldRef point_field[FIELDSET_MAX_FIELDS];
    int picture_count;
    PictureRef picture[FIELDSET_MAX_PICTURES];
    /* MESH_POINTS: the `file` of the picture a coupled grid's overlays
     * draw on top; NULL, or no picture of that name: the first */
    const char *overlay_picture;
    int table_count;
    TableRef table[FIELDSET_MAX_TABLES];
    /* piece.count > 1: the VTK file is written in pieces from `piece` (on
     * every process), and the mesh and fields above serve the pictures and
     * tables only (on the writer) */
    FieldPiece piece;
} FieldSet;

#endif
