/* Diagnostics of the flow operator: primitive fields and conserved totals. */
#include "flow/gks/solver.h"

#include "core/blocks.h"
#include "core/status.h"
#include "flow/gks/solver_internal.h"

#include <math.h>
#include <string.h>

void gks_solver_primitive(const GksSolver *s, FlowField field, double *out) {
    const Grid *g = &s->grid;
    const double gamma = s->gas.gamma, R = s->gas.R;
    const int big = (int64_t)g->nx * g->ny >= PARALLEL_MIN_CELLS;
#pragma omp parallel for schedule(static) if (big)
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) {
            const int64_t k = grid_index(g, i, j);
            const double w[4] = {s->w[0][k], s->w[1][k], s->w[2][k], s->w[3][k]};
            FlowPrim q;
            flow_cons_to_prim(w, gamma, &q);
            double v;
            switch (field) {
            case FLOW_DENSITY:
                v = q.rho;
                break;
            case FLOW_VELOCITY_X:
                v = q.u;
                break;
            case FLOW_VELOCITY_Y:
                v = q.v;
                break;
            case FLOW_PRESSURE:
                v = q.p;
                break;
            case FLOW_TEMPERATURE:
                v = q.p / (R * q.rho);
                break;
            case FLOW_MACH:
                v = sqrt((q.u * q.u + q.v * q.v) * q.rho / (gamma * q.p));
                break;
            case FLOW_SPEED: /* gks_fields' from u and v: the same bits */
                v = sqrt(q.u * q.u + q.v * q.v);
                break;
            default:
                v = 0.0;
            }
            out[(int64_t)j * g->nx + i] = v;
        }
}

/* Each rank's nx * ny values of its block (x fastest) into the whole
 * grid's out[] (x fastest) on rank 0: gathered in rank order, which on
 * slabs is the row order; on a 2D process grid each block then placed. */
static int gather_blocks(const GksSolver *s, const double *mine, double *out) {
    const Grid *g = &s->grid;
    if (s->dims[0] == 1) return comm_gatherv(&s->comm, mine, g->nx * g->ny, out);
    TRY(comm_gatherv(&s->comm, mine, g->nx * g->ny, s->gather));
    if (s->comm.rank == 0) gks_solver_place_blocks(s, s->gather, sizeof *out, out, s->whole.nx, 0);
    return NSPD_OK;
}

void gks_solver_place_blocks(const GksSolver *s, const void *blocks, size_t elem, void *out,
                             int64_t stride, int pad) {
    const unsigned char *at = blocks;
    unsigned char *to = out;
    for (int r = 0; r < s->comm.size; r++) {
        int first[2], count[2];
        gks_solver_block(s, r, first, count);
        const size_t run = (size_t)count[0] * elem;
        for (int j = 0; j < count[1]; j++, at += run)
            memcpy(to + ((int64_t)(first[1] + j + pad) * stride + first[0] + pad) * (int64_t)elem,
                   at, run);
    }
}

int gks_solver_primitive_whole(const GksSolver *s, FlowField field, double *slab, double *out) {
    if (!comm_distributed(&s->comm)) {
        gks_solver_primitive(s, field, out);
        return NSPD_OK;
    }
    gks_solver_primitive(s, field, slab);
    return gather_blocks(s, slab, out);
}

void gks_solver_kinds(const GksSolver *s, double *out) {
    const Grid *g = &s->grid;
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) out[(int64_t)j * g->nx + i] = s->kind[grid_index(g, i, j)];
}

int gks_solver_kinds_whole(const GksSolver *s, double *slab, double *out) {
    if (!comm_distributed(&s->comm)) {
        gks_solver_kinds(s, out);
        return NSPD_OK;
    }
    gks_solver_kinds(s, slab);
    return gather_blocks(s, slab, out);
}

/* The block along an axis of n cells in p blocks that holds cell i (the
 * ghost layers beyond the ends: the end blocks). */
static int axis_owner(int n, int p, int i) {
    return blocks_owner(n, p, i < 0 ? 0 : i >= n ? n - 1 : i);
}

int gks_solver_cell_owner(const GksSolver *s, int i, int j) {
    if (!comm_distributed(&s->comm)) return 0;
    return axis_owner(s->whole.ny, s->dims[1], j) * s->dims[0] +
           axis_owner(s->whole.nx, s->dims[0], i);
}

int64_t gks_solver_local_cell(const GksSolver *s, int64_t cell) {
    if (!comm_distributed(&s->comm)) return cell;
    const Grid *g = &s->grid;
    const int64_t stride = s->whole.stride;
    const int i = (int)(cell % stride) - s->first[0], j = (int)(cell / stride) - s->first[1];
    /* (i, j): padded indices of this block's arrays */
    if (i < 0 || i >= g->nx + 2 * GRID_NG || j < 0 || j >= g->ny + 2 * GRID_NG) return -1;
    return (int64_t)j * g->stride + i;
}

/* Each fluid cell's pressure times its area (NaN marks the others), then
 * the sums in cell order over the whole grid on rank 0, which sends the
 * mean to the others: the same additions in the same order on any number
 * of processes. */
int gks_solver_mean_pressure(const GksSolver *s, double *slab, double *all, double *mean) {
    const Grid *g = &s->grid;
    const double gm1 = s->gas.gamma - 1.0;
    double *mine = comm_distributed(&s->comm) ? slab : all;
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) {
            const int64_t k = grid_index(g, i, j);
            const double a = g->ax[0].width[i] * g->ax[1].width[j];
            const double ke =
                0.5 * (s->w[1][k] * s->w[1][k] + s->w[2][k] * s->w[2][k]) / s->w[0][k];
            mine[(int64_t)j * g->nx + i] =
                s->kind[k] == FLOW_CELL_FLUID ? gm1 * (s->w[3][k] - ke) * a : (double)NAN;
        }
    if (mine != all) {
        TRY(gather_blocks(s, slab, all));
        if (s->comm.rank != 0) return comm_bcast(&s->comm, mean, (int)sizeof *mean, 0);
    }
    const Grid *w = gks_solver_whole_grid(s);
    double sum = 0.0, area = 0.0;
    for (int j = 0; j < w->ny; j++)
        for (int i = 0; i < w->nx; i++) {
            const double term = all[(int64_t)j * w->nx + i];
            if (isnan(term)) continue;
            sum += term;
            area += w->ax[0].width[i] * w->ax[1].width[j];
        }
    *mean = area > 0 ? sum / area : (double)NAN;
    return comm_bcast(&s->comm, mean, (int)sizeof *mean, 0);
}

/* Deterministic at any thread count: each row is summed in index order by one
 * thread, then the row sums in row order. On a 2D process grid a row's sum
 * passes along x from block to block, each adding its cells to its left
 * neighbour's partial sums (the one-process order of additions), and the
 * last block of each row of blocks gives the row sums. */
void gks_solver_totals(const GksSolver *s, double totals[4]) {
    const Grid *g = &s->grid;
    double *rs = s->row_sums;
    const int bytes = 4 * g->ny * (int)sizeof *rs;
    const int left = s->coord[0] > 0 ? s->comm.rank - 1 : -1;
    const int right = s->coord[0] < s->dims[0] - 1 ? s->comm.rank + 1 : -1;
    if (s->dims[0] > 1) /* a failed exchange is MPI's abort */
        (void)comm_sendrecv(&s->comm, rs, bytes, -1, rs, left);
    if (left < 0)
        for (int k = 0; k < 4 * g->ny; k++) rs[k] = 0.0;
    const int big = (int64_t)g->nx * g->ny >= PARALLEL_MIN_CELLS;
#pragma omp parallel for schedule(static) if (big)
    for (int j = 0; j < g->ny; j++) {
        double acc[4] = {rs[4 * j], rs[4 * j + 1], rs[4 * j + 2], rs[4 * j + 3]};
        for (int i = 0; i < g->nx; i++) {
            const int64_t k = grid_index(g, i, j);
            if (s->kind[k] != FLOW_CELL_FLUID) continue;
            const double vol = g->ax[0].width[i] * g->ax[1].width[j];
            for (int v = 0; v < 4; v++) acc[v] += s->w[v][k] * vol;
        }
        for (int v = 0; v < 4; v++) rs[4 * j + v] = acc[v];
    }
    int rows = g->ny;
    if (s->dims[0] > 1) (void)comm_sendrecv(&s->comm, rs, bytes, right, rs, -1);
    if (s->row_sums_all) { /* several processes: every row's sums, in row order */
        (void)comm_allgatherv(&s->comm, rs, right < 0 ? 4 * g->ny : 0, s->row_sums_all);
        rs = s->row_sums_all, rows = s->rows;
    }
    for (int v = 0; v < 4; v++) totals[v] = 0.0;
    for (int j = 0; j < rows; j++)
        for (int v = 0; v < 4; v++) totals[v] += rs[4 * j + v];
}
