/* Stretched tensor-product Cartesian grid (2D, cell-centred, ghost layers).
 *
 * Each axis is a list of segments laid end to end from `lo`. A segment is
 * uniform (h_end <= 0 or h_end == h_start) or geometrically stretched from
 * h_start to h_end; see grid_axis_create for how the cell count and the ratio
 * are chosen so that the segment is filled exactly.
 *
 * Invariants of a GridAxis (n interior cells, NG = GRID_NG ghost layers):
 *   face[i]   i = -NG .. n + NG     cell i spans [face[i], face[i+1]]
 *   center[i], width[i], inv_width[i]   i = -NG .. n + NG - 1
 *   inv_dl[i] = 1 / (center[i] - center[i-1]),  i = -NG+1 .. n+NG-1
 *   inv_dr[i] = 1 / (center[i+1] - center[i]),  i = -NG .. n+NG-2
 * The pointers are offset so that negative indices are valid. Ghost cells
 * mirror the interior widths at the boundary (width[-1-k] = width[k]), or
 * repeat the opposite end on a periodic axis (width[-1-k] = width[n-1-k]),
 * so that centre-to-centre distances across a boundary are those the
 * boundary condition implies.
 *
 * Field storage: one array per variable of grid->size doubles, x fastest,
 * rows of `stride` >= nx + 2 NG entries (padded to 8 doubles = 64 bytes, so
 * that every row starts on a cache line). grid_index(g, i, j) is the offset
 * of cell (i, j), i = -NG .. nx+NG-1, j = -NG .. ny+NG-1. */
#ifndef NSPD_FLOW_GKS_GRID_H
#define NSPD_FLOW_GKS_GRID_H

#include <stdbool.h>
#include <stdint.h>

enum { GRID_NG = 2 }; /* MUSCL slopes of the first ghost cell need a second one */

typedef struct {
    double length;  /* m, > 0 */
    double h_start; /* spacing at the segment's start, m (> 0 unless cells > 0 and uniform) */
    double h_end;   /* spacing at its end; <= 0 or == h_start: uniform */
    int cells;      /* > 0: use exactly this many cells (uniform: h = length/cells;
                       stretched: ratio from h_start alone) */
} GridSegment;

typedef struct {
    int n;         /* interior cells */
    double lo, hi; /* domain extent, m */
    bool periodic;
    double *face, *center, *width, *inv_width, *inv_dl, *inv_dr;
    double *block_; /* owned allocation behind the pointers */
} GridAxis;

typedef struct {
    GridAxis ax[2];
    int nx, ny;   /* interior cells */
    int stride;   /* row length of field arrays (doubles) */
    int64_t size; /* doubles per field array */
} Grid;

/* Builds an axis from `count` segments starting at `lo`.
 * Uniform segment: n = cells or max(1, round(length / h_start)), h = length / n.
 * Stretched segment: with r0 = (L - h_start)/(L - h_end) (the ratio of a
 * progression from h_start to h_end with sum L), n = cells or
 * max(1, round(1 + ln(h_end/h_start)/ln(r0))); then r solves
 * h_start (r^n - 1)/(r - 1) = L exactly, so the first spacing is h_start and
 * the last h_start r^(n-1) is within one ratio factor of h_end.
 * NSPD_ERR_INPUT for non-positive lengths or spacings, or h >= L on a
 * stretched segment; NSPD_ERR_NOMEM. */
int grid_axis_create(GridAxis *axis, double lo, int count, const GridSegment *segments,
                     bool periodic);
void grid_axis_destroy(GridAxis *axis);

/* The most cells an axis may have (segments and their sum): counts stay
 * far inside int, and a grid of 1e8 x 1e8 is refused by the memory check
 * long before. */
enum { GRID_MAX_AXIS_CELLS = 100000000 };

/* The cells a valid segment will have, as a double (so a huge length over a
 * tiny spacing cannot overflow): what the grid will build, for checks
 * before anything is built. */
double grid_segment_cells(const GridSegment *segment);

/* Spacing of each interior cell of a segment list without building an axis:
 * writes up to max cells into h (if h != NULL) and returns the cell count, or
 * a negative status. */
int grid_segments_spacing(int count, const GridSegment *segments, double *h, int max);

/* The smallest spacing of a segment list without building the axis (0 for
 * an invalid one; the failure is recorded, and create reports it). */
double grid_segments_min_spacing(int count, const GridSegment *segments);

/* Builds a grid from segment lists per axis. */
int grid_create(Grid *g, double x0, int nsx, const GridSegment *sx, bool periodic_x, double y0,
                int nsy, const GridSegment *sy, bool periodic_y);
/* The cells first[a] .. first[a] + count[a] - 1 along each axis of grid g
 * as a grid of their own (one process's block, core/comm.h): each axis a
 * slice of g's, its ghost layers the neighbouring cells' true widths
 * inside g and g's own ghosts at g's ends, so that every stretched-grid
 * weight of the block is the whole grid's; rows padded as grid_create
 * pads them (a block of the whole width has g's stride). `periodic` stays
 * the whole axis' property. */
int grid_slice(Grid *out, const Grid *g, const int first[2], const int count[2]);
/* Uniform grid of nx x ny cells on [x0, x1] x [y0, y1]. */
int grid_create_uniform(Grid *g, double x0, double x1, int nx, double y0, double y1, int ny,
                        bool periodic_x, bool periodic_y);
void grid_destroy(Grid *g);

/* The searches over an axis (core/search.h), O(log n), thread-safe, never
 * failing.
 * The cell holding x, face[i] <= x < face[i+1], clamped to 0 .. n-1 (0 for a
 * NaN x): search_bracket(a->face, 0, a->n, x). */
int grid_axis_cell_of(const GridAxis *a, double x);
/* The interior centres around x: i in -1 .. n-1 with center[i] <= x <
 * center[i+1], where center[-1] counts as -infinity and center[n] as
 * +infinity (-1 for a NaN x): search_bracket(a->center, -1, a->n, x). */
int grid_axis_bracket(const GridAxis *a, double x);

static inline int64_t grid_index(const Grid *g, int i, int j) {
    return (int64_t)(j + GRID_NG) * g->stride + (i + GRID_NG);
}

#endif
