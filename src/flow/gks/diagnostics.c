/* Diagnostics of the flow operator: primitive fields and conserved totals. */
#include "flow/gks/solver.h"

#include "core/status.h"
#include "flow/gks/solver_internal.h"

#include <math.h>

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
            default:
                v = 0.0;
            }
            out[(int64_t)j * g->nx + i] = v;
        }
}

int gks_solver_primitive_whole(const GksSolver *s, FlowField field, double *slab, double *out) {
    if (!comm_distributed(&s->comm)) {
        gks_solver_primitive(s, field, out);
        return NSPD_OK;
    }
    gks_solver_primitive(s, field, slab);
    return comm_gatherv(&s->comm, slab, s->grid.nx * s->grid.ny, out);
}

int gks_solver_kinds_whole(const GksSolver *s, double *slab, double *out) {
    const Grid *g = &s->grid;
    double *mine = comm_distributed(&s->comm) ? slab : out;
    for (int j = 0; j < g->ny; j++)
        for (int i = 0; i < g->nx; i++) mine[(int64_t)j * g->nx + i] = s->kind[grid_index(g, i, j)];
    if (mine == out) return NSPD_OK;
    return comm_gatherv(&s->comm, slab, g->nx * g->ny, out);
}

int gks_solver_row_owner(const GksSolver *s, int row) {
    int r = 0;
    while (r + 1 < s->comm.size && gks_solver_slab_first(s, r + 1) <= row) r++;
    return r;
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
        TRY(comm_gatherv(&s->comm, slab, g->nx * g->ny, all));
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
 * thread, then the row sums in row order. */
void gks_solver_totals(const GksSolver *s, double totals[4]) {
    const Grid *g = &s->grid;
    double *rs = s->row_sums;
    const int big = (int64_t)g->nx * g->ny >= PARALLEL_MIN_CELLS;
#pragma omp parallel for schedule(static) if (big)
    for (int j = 0; j < g->ny; j++) {
        double acc[4] = {0.0, 0.0, 0.0, 0.0};
        for (int i = 0; i < g->nx; i++) {
            const int64_t k = grid_index(g, i, j);
            if (s->kind[k] != FLOW_CELL_FLUID) continue;
            const double vol = g->ax[0].width[i] * g->ax[1].width[j];
            for (int v = 0; v < 4; v++) acc[v] += s->w[v][k] * vol;
        }
        for (int v = 0; v < 4; v++) rs[4 * j + v] = acc[v];
    }
    int rows = g->ny;
    if (s->row_sums_all) { /* several processes: every row's sums, in row order */
        (void)comm_allgatherv(&s->comm, rs, 4 * g->ny, s->row_sums_all);
        rs = s->row_sums_all, rows = s->rows;
    }
    for (int v = 0; v < 4; v++) totals[v] = 0.0;
    for (int j = 0; j < rows; j++)
        for (int v = 0; v < 4; v++) totals[v] += rs[4 * j + v];
}
