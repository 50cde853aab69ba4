/* Private data of the immersed boundary (ibm.c, geometry.c, stencil.c,
 * wall_loads.c). Not part of the interface: use ibm.h.
 *
 * Invariants:
 *   - markers of all bodies are concatenated: body b owns markers
 *     first[b] .. first[b] + count[b] - 1; segment s starts at marker s and
 *     ends at seg_end[s] (the next marker of the same body, cyclically);
 *   - `inside[k]` (interior cells) is 1 iff the cell centre is inside or on a
 *     body; kind[k] = FLUID if !inside, GHOST if inside and a cell within
 *     Manhattan distance IBM_REACH is fluid, SOLID otherwise;
 *   - slot[k] = index of cell k in the ghost list, or -1; the ghost list is
 *     sorted by cell index;
 *   - the bucket grid holds every segment in each bucket its bounding box
 *     touches (flat lists), and per bucket row every segment whose y-range
 *     meets the row (the winding-number test walks one row list). */
#ifndef NSPD_COUPLE_GHOST_IBM_INTERNAL_H
#define NSPD_COUPLE_GHOST_IBM_INTERNAL_H

#include "couple/ghost/ibm.h"
#include "flow/gks/grid.h"

#include <math.h>
#include <stdint.h>

/* Ghost layers: a fluid cell's face flux reads its neighbour (distance 1)
 * and that neighbour's slopes, which read the neighbour's neighbours
 * (Manhattan distance 2, diagonals included). */
enum { IBM_REACH = 2 };

/* Surface probes sit at 1 and 2 times IBM_PROBE_STEP cell widths from the
 * wall. Half a cell: the one-sided estimates p_w = (4 p_1 - p_2)/3 and
 * du/dn = (4 u_1 - u_2)/(2 delta) err by O(delta^3 / r^2) near a stagnation
 * point of nose radius r (potential flow: -16 q (delta/r)^3 for p_w), which
 * at one cell was 7 % of q on an airfoil nose of 4 cells; at half a cell it
 * is 1.5 %. */
#define IBM_PROBE_STEP 0.5

/* The level of a ghost entry another process fills (on several
 * processes an update builds only the stencils this one reads). */
enum { IBM_LEVEL_ELSEWHERE = 254 };

/* Stencil node slot states (rseg). */
enum { IBM_NODE_FLUID = -1, IBM_NODE_UNUSED = -2 };

typedef struct IbmShare IbmShare;

/* The conserved fields a stencil reads, by the Ibm's cell numbers (the
 * whole grid's padded cells, `stride` a row): on one process the solver's
 * own arrays (lo 0, row = stride); on several, the share's shadow, a
 * window of rows lo[1].. and columns lo[0].. + row of the whole grid that
 * holds what this process's stencils read (share.c). */
typedef struct {
    double *w[4];
    int64_t stride; /* the whole grid's padded row */
    int lo[2];      /* the window's first padded cell (column, row) */
    int64_t row;    /* the window's row */
} IbmFieldView;

/* One process: the solver's arrays, numbered as the Ibm's cells. */
static inline IbmFieldView ibm_solver_view(const GksSolver *s) {
    const GksFields f = gks_solver_fields((GksSolver *)s);
    const int64_t stride = gks_solver_grid(s)->stride;
    return (IbmFieldView){{f.w[0], f.w[1], f.w[2], f.w[3]}, stride, {0, 0}, stride};
}

static inline int64_t ibm_view_index(const IbmFieldView *f, int64_t k) {
    if (f->row == f->stride && f->lo[0] == 0 && f->lo[1] == 0) return k;
    return (k / f->stride - f->lo[1]) * f->row + (k % f->stride - f->lo[0]);
}

typedef struct {
    int nbx, nby;
    double x0, y0, size, inv_size;
    int *first, *items;         /* CSR over buckets (row-major), segment ids */
    int *row_first, *row_items; /* CSR over bucket rows */
    int items_cap, row_items_cap;
} IbmBuckets;

/* Where a stencil entry stands (read by queries only, hence a struct per
 * entry rather than more arrays). */
typedef struct {
    double bix, biy; /* ghost: its boundary point BI, m; probe: 0 */
    double nx, ny;   /* ghost: outward unit normal at BI; probe: 0 */
    double dist;     /* ghost: distance from the cell centre to BI; probe: from the wall, m */
    double px, py;   /* the point P the weights interpolate to, m */
} IbmStencilGeo;

/* A set of point stencils, struct of arrays. Entry e has 4 node slots at
 * 4e .. 4e+3. */
typedef struct {
    int n, cap;
    int64_t *cell;      /* ghost: its cell; probe/fresh: the cell holding the point */
    int64_t *node;      /* 4 per entry: fluid node's cell (rseg = IBM_NODE_FLUID) */
    double *wd, *wn;    /* 4 per entry: weights for Dirichlet / Neumann variables */
    int32_t *rseg;      /* 4 per entry: replaced node: segment of its boundary point */
    double *rt;         /* 4 per entry: parameter of that boundary point on its segment */
    int32_t *seg;       /* ghost: own boundary point's segment; probe: -1 */
    double *t;          /* its parameter */
    double *ratio;      /* ghost: d / |P - BI| (1 for Eq. 39); probe: distance to the wall */
    double *wu, *wv;    /* ghost: its wall point's velocity at the last fill */
    IbmStencilGeo *geo; /* per entry */
    double *dep;        /* 4 per entry: bounding box (xlo, xhi, ylo, yhi) of what it read */
    uint8_t *level;     /* IbmStencilLevel */
    uint8_t *nrep;      /* replaced nodes (0, 1, 2: the paper's cases 1, 2, 3) */
    uint8_t *body;      /* body of the own boundary point */
} IbmStencilSet;

struct Ibm {
    const Grid *grid;
    int nx, ny;
    int64_t cells; /* grid->size */
    /* bodies and markers */
    int body_count;
    int *first, *count; /* per body */
    int *thermal;       /* per body */
    double *wall_t;     /* per body */
    int *le, *te;       /* per body: given edge markers (global index) or -1 */
    int nm, nm_cap;     /* markers (= segments) */
    double *mx, *my, *mvx, *mvy;
    int *seg_end, *seg_body;
    int *old_count; /* per body, markers at the last build */
    double *old_mx, *old_my;
    int old_nm, old_cap;
    IbmBuckets bk;
    /* cells */
    uint8_t *inside, *kind, *mark;
    int32_t *slot;
    /* stencils */
    IbmStencilSet ghosts, spare; /* spare: the next ghost list during an update */
    IbmStencilSet probes;        /* 2 per segment: at 1 and 2 probe distances */
    /* work lists */
    int64_t *list_a, *list_b;
    int list_cap_a, list_cap_b;
    double *swept; /* ibm_update: boxes of moved walls, 4 doubles (xlo, xhi, ylo, yhi) each */
    int swept_cap;
    uint8_t *moved_bucket;
    int moved_cap;
    IbmUpdateStats last;
    IbmGhostFaces faces;
    IbmShare *share; /* several processes (share.c); NULL on one */
};

/* ------------------------------------------------------------ geometry */

/* A point on the walls, found as the nearest one to a query point. */
typedef struct {
    int seg;       /* its segment; -1 when there are no walls */
    double t;      /* parameter on seg: 0 at marker seg, 1 at marker seg_end[seg] */
    double bx, by; /* the point (the paper's BI), m */
    double d;      /* its distance from the query point, m */
} IbmWallPoint;

int ibm_buckets_build(Ibm *ibm);
void ibm_buckets_free(IbmBuckets *bk);
/* Nearest point of all walls to (x, y); ties go to the lower segment. */
IbmWallPoint ibm_nearest(const Ibm *ibm, double x, double y);
/* 1 if (x, y) is inside a body or on a wall (winding number != 0). */
int ibm_point_inside(const Ibm *ibm, double x, double y);
/* 1 if the segment p-q meets a wall (touching counts). */
int ibm_blocked(const Ibm *ibm, double px, double py, double qx, double qy);
/* Outward unit normal at the wall point w, the nearest one of (x, y);
 * `inside`: (x, y) is in the body. */
void ibm_normal(const Ibm *ibm, const IbmWallPoint *w, double x, double y, int inside, double *nx,
                double *ny);
/* Interior-or-first-box-layer cell kind with the box-layer rule of bc.c. */
int ibm_node_kind(const Ibm *ibm, int i, int j);

/* ------------------------------------------------------------ stencils */
int ibm_stencils_reserve(IbmStencilSet *s, int n);
void ibm_stencils_free(IbmStencilSet *s);
void ibm_stencils_copy_entry(IbmStencilSet *dst, int e, const IbmStencilSet *src, int f);
/* Builds ghost entry e of `set` for interior cell (i, j). */
void ibm_build_ghost(const Ibm *ibm, int i, int j, IbmStencilSet *set, int e);
/* Builds a point stencil (no Eq. 39) at (px, py) for a point at `dist` from
 * the wall; `exclude` (may be NULL): cells flagged there are not usable. */
void ibm_build_point(const Ibm *ibm, double px, double py, double dist, const uint8_t *exclude,
                     IbmStencilSet *set, int e);
/* ibm_build_point's entry without the stencil (the point, its cell and
 * its distance; level IBM_LEVEL_ELSEWHERE): a probe another process
 * evaluates. */
void ibm_place_point(const Ibm *ibm, double px, double py, double dist, IbmStencilSet *set, int e);

/* ------------------------------------------------------------ processes */
/* share.c: the plan of which ghosts and probes this process evaluates and
 * which cells it fetches, built by ibm_attach when the solver runs on
 * several processes. */
int ibm_share_create(Ibm *ibm, GksSolver *s);
/* The plan again, for the ghosts and probes of moved walls (ibm_update):
 * each process lists the cells its own stencils read and asks their
 * owners for them (collective). */
int ibm_share_replan(Ibm *ibm);
/* Whether this process fills the ghost cell `cell` (its block and the
 * two-cell halo around it) and evaluates a probe whose point lies in
 * `cell` (its block); both true on one process (no share). */
bool ibm_share_fills(const Ibm *ibm, int64_t cell);
bool ibm_share_evaluates(const Ibm *ibm, int64_t cell);
/* The current values of the n cells (the same list on every rank, each
 * cell once) into the shadow, from the ranks that hold them; collective. */
int ibm_share_fetch(const Ibm *ibm, int n, const int64_t *cells);
/* Makes room in the shadow for the cells in [lo, hi) of the whole grid's
 * padded numbering, per axis (what this process's fresh stencils read,
 * before they are fetched); what the shadow held stays. */
int ibm_share_cover(const Ibm *ibm, const int lo[2], const int hi[2]);
IbmFieldView ibm_share_shadow(const Ibm *ibm);
void ibm_share_free(IbmShare **sh);
/* The shadow of the conserved fields, current where this process's
 * stencils read (collective: every rank calls). */
IbmFieldView ibm_share_refresh(const Ibm *ibm, GksSolver *s);
/* The ghost entries this process fills, the probe entries it evaluates. */
const int *ibm_share_ghosts(const Ibm *ibm, int *count);
const int *ibm_share_probes(const Ibm *ibm, int *count);
/* The solver's index of the Ibm's cell `cell` (the whole grid's padded
 * numbering) on this process, -1 outside its block and ghost layers;
 * `cell` itself on one process. */
int64_t ibm_share_local(const Ibm *ibm, const GksSolver *s, int64_t cell);
/* The ghost slots (-1: none) of the solver's cells on this process, as
 * gks_solver_set_ghost_walls reads them. */
const int32_t *ibm_share_slots(const Ibm *ibm);
/* Every probe's 4 values (u, v, p, T at entry e: q[4 e ..]) from the 4
 * values of this process's probes (mine[4 e ..] for its entries e);
 * collective. */
int ibm_share_probe_values(const Ibm *ibm, const double *mine, double *q);

/* ------------------------------------------------------------ evaluation */
static inline void ibm_wall_velocity(const Ibm *ibm, int s, double t, double *u, double *v) {
    const int e = ibm->seg_end[s];
    *u = (1.0 - t) * ibm->mvx[s] + t * ibm->mvx[e];
    *v = (1.0 - t) * ibm->mvy[s] + t * ibm->mvy[e];
}

/* The primitive state (u, v, p, T) at the point P of stencil entry e, from
 * the fluid state w: Dirichlet sums for u, v (and T on isothermal walls, with
 * the wall temperature Tw at replaced nodes), Neumann sums for p (and T on
 * adiabatic walls), the latter clipped to the fluid nodes' range. */
typedef struct {
    double u, v, p, T;
} IbmPrim;

static inline IbmPrim ibm_stencil_eval(const Ibm *ibm, const IbmStencilSet *S, int e,
                                       const IbmFieldView *f, double gm1, double R, int iso,
                                       double Tw) {
    double *const *w = f->w;
    double ui = 0.0, vi = 0.0, td = 0.0, pn = 0.0, tn = 0.0;
    double pmin = (double)INFINITY, pmax = -(double)INFINITY, tmin = (double)INFINITY,
           tmax = -(double)INFINITY;
    for (int m = 0; m < 4; m++) {
        const int rs = S->rseg[4 * e + m];
        if (rs == IBM_NODE_UNUSED) continue;
        const double wd = S->wd[4 * e + m], wn = S->wn[4 * e + m];
        if (rs == IBM_NODE_FLUID) {
            const int64_t k = ibm_view_index(f, S->node[4 * e + m]);
            const double rho = w[0][k], ir = 1.0 / rho;
            const double u = w[1][k] * ir, v = w[2][k] * ir;
            const double p = gm1 * (w[3][k] - 0.5 * (w[1][k] * u + w[2][k] * v));
            const double T = p * ir / R;
            ui += wd * u;
            vi += wd * v;
            td += wd * T;
            pn += wn * p;
            tn += wn * T;
            pmin = fmin(pmin, p), pmax = fmax(pmax, p);
            tmin = fmin(tmin, T), tmax = fmax(tmax, T);
        } else {
            double uw, vw;
            ibm_wall_velocity(ibm, rs, S->rt[4 * e + m], &uw, &vw);
            ui += wd * uw;
            vi += wd * vw;
            td += wd * Tw;
        }
    }
    IbmPrim q;
    q.u = ui;
    q.v = vi;
    q.p = fmin(fmax(pn, pmin), pmax);
    q.T = iso ? td : fmin(fmax(tn, tmin), tmax);
    return q;
}

#endif
