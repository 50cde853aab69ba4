#include "couple/ghost/fsi.h"

#include "core/mem.h"
#include "core/status.h"

#include <math.h>
#include <stdbool.h>
#include <string.h>

const char *const FSI_HOLD_NAMES[FSI_HOLD_COUNT + 1] = {"none", "balance", NULL};

/* The polylines of the wetted loops, over the marker arrays. */
static void polylines_from_markers(Fsi *f) {
    const PdSurface *w = &f->wetted;
    for (int k = 0; k < f->loop_count; k++) {
        int64_t lo = w->loop_start[k];
        IbmPolyline *p = &f->polylines[k];
        p->n = (int)(w->loop_start[k + 1] - lo);
        p->x = f->mx + lo;
        p->y = f->my + lo;
        p->vx = f->mvx + lo;
        p->vy = f->mvy + lo;
    }
}

/* This step's interface: the surface loops without debris (points with no
 * intact bond), their markers at the points' current positions and
 * velocities. A loop keeps all its points if fewer than 3 would remain. */
static void markers_from_points(Fsi *f, const Solid *solid) {
    const PdPoints *body = solid_points_const(solid);
    const PdSurface *all = &f->surface;
    PdSurface *w = &f->wetted;
    int64_t used = 0;
    for (int k = 0; k < all->loop_count; k++) {
        int64_t lo = all->loop_start[k], hi = all->loop_start[k + 1], start = used;
        w->loop_start[k] = used;
        for (int64_t m = lo; m < hi; m++)
            if (solid_attached(solid, all->point[m])) w->point[used++] = all->point[m];
        if (used - start < 3) { /* keep the loop whole rather than lose the body */
            used = start;
            for (int64_t m = lo; m < hi; m++) w->point[used++] = all->point[m];
        }
    }
    w->loop_start[all->loop_count] = used;
    w->length = used;
    pd_surface_positions(body, w, f->mx, f->my, f->mvx, f->mvy);
    polylines_from_markers(f);
}

int fsi_create(Fsi *f, const FsiConfig *cfg, const Solid *solid, GksSolver *flow) {
    const PdPoints *body = solid_points_const(solid);
    memset(f, 0, sizeof *f);
    f->cfg = *cfg;
    /* neighbouring surface points are 1 or sqrt(2) spacings apart; 2.5
     * spacings leaves room for 75 % stretch before a segment counts as a
     * bridge, and a single dropped debris point (2 spacings) still loads
     * its neighbours */
    f->cfg.reference.bridge_length = 2.5 * body->spacing;
    int status = pd_surface_trace(body, &f->surface);
    if (status == NSPD_OK && f->surface.loop_count == 0)
        status = NSPD_FAIL(NSPD_ERR_INPUT, "the solid has no surface loop to couple to the flow");
    size_t n = (size_t)f->surface.length;
    if (status == NSPD_OK) status = nspd_alloc(&f->mx, n, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&f->my, n, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&f->mvx, n, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&f->mvy, n, sizeof(double));
    if (status == NSPD_OK)
        status = nspd_alloc(&f->polylines, (size_t)f->surface.loop_count, sizeof(IbmPolyline));
    if (status == NSPD_OK)
        status =
            nspd_alloc(&f->wetted.loop_start, (size_t)f->surface.loop_count + 1, sizeof(int64_t));
    if (status == NSPD_OK) status = nspd_alloc(&f->wetted.point, n, sizeof(int32_t));
    if (status != NSPD_OK) {
        fsi_destroy(f);
        return status;
    }
    f->loop_count = f->surface.loop_count;
    f->wetted.loop_count = f->loop_count;
    for (int k = 0; k < f->loop_count; k++) {
        IbmPolyline *p = &f->polylines[k];
        p->thermal = cfg->thermal;
        p->wall_temperature = cfg->wall_temperature;
        p->leading_edge = p->trailing_edge = -1;
    }
    markers_from_points(f, solid);
    status = ibm_create(&f->ibm, gks_solver_whole_grid(flow), f->polylines, f->loop_count);
    if (status == NSPD_OK) ibm_set_ghost_faces(f->ibm, (IbmGhostFaces)cfg->ghost_faces);
    if (status == NSPD_OK) status = ibm_attach(f->ibm, flow);
    if (status == NSPD_OK && cfg->soft_start > 0) ibm_soft_start(f->ibm, flow, cfg->soft_start);
    if (status == NSPD_OK) status = ibm_surface_reserve(f->ibm, &f->loads);
    if (status != NSPD_OK) fsi_destroy(f);
    return status;
}

void fsi_destroy(Fsi *f) {
    ibm_destroy(&f->ibm);
    ibm_surface_free(&f->loads);
    pd_surface_free(&f->surface);
    pd_surface_free(&f->wetted);
    nspd_free(&f->polylines);
    nspd_free(&f->mx);
    nspd_free(&f->my);
    nspd_free(&f->mvx);
    nspd_free(&f->mvy);
    memset(f, 0, sizeof *f);
}

int fsi_move_interface(Fsi *f, Solid *solid, GksSolver *flow) {
    /* a divided solid's view of the surface points (solid.h), which is all
     * this coupling reads of its motion */
    TRY(solid_sync_points(solid, f->surface.length, f->surface.point));
    markers_from_points(f, solid);
    TRY(ibm_update(f->ibm, f->polylines, f->loop_count, flow));
    return ibm_surface_reserve(f->ibm, &f->loads); /* the marker count may change */
}

int fsi_apply_loads(Fsi *f, Solid *solid, GksSolver *flow) {
    TRY(solid_sync_points(solid, f->surface.length, f->surface.point));
    PdPoints *body = solid_points(solid);
    TRY(ibm_surface_compute(f->ibm, flow, &f->cfg.reference, &f->loads));
    /* Parts of the solid outside the flow's box (the panel's clamp below the
     * floor) have no fluid on them: no load. */
    const Grid *g = gks_solver_whole_grid(flow);
    for (int k = 0; k < f->loads.n; k++)
        if (f->loads.x[k] < g->ax[0].lo || f->loads.x[k] > g->ax[0].hi ||
            f->loads.y[k] < g->ax[1].lo || f->loads.y[k] > g->ax[1].hi)
            f->loads.fx[k] = f->loads.fy[k] = 0.0;
    /* a non-finite load would silently wreck the solid: stop and say where */
    for (int k = 0; k < f->loads.n; k++)
        if (!isfinite(f->loads.fx[k]) || !isfinite(f->loads.fy[k]))
            return NSPD_FAIL(NSPD_ERR_NUMERIC,
                             "the flow's load on the solid surface is not finite at (%g, %g) m "
                             "(wall pressure %g Pa, shear %g Pa) at t = %g s: the surface has "
                             "probably folded or fragmented beyond what the immersed boundary "
                             "resolves",
                             f->loads.x[k], f->loads.y[k], f->loads.p[k], f->loads.tau[k],
                             gks_solver_time(flow));
    for (int d = 0; d < body->dim; d++)
        memset(body->external[d], 0, (size_t)body->n * sizeof(double));
    /* the segments of the immersed boundary are this step's loops', in order */
    pd_surface_apply_tractions(body, &f->wetted, f->loads.fx, f->loads.fy, f->force_on_solid);
    if (f->cfg.hold == FSI_HOLD_BALANCE) {
        double volume = 0.0; /* per unit depth */
        for (int64_t i = 0; i < body->n; i++) volume += body->volume[i] / body->thickness;
        for (int d = 0; d < 2; d++) {
            double b = -f->force_on_solid[d] / volume;
            for (int64_t i = 0; i < body->n; i++) body->external[d][i] += b;
        }
    }
    return NSPD_OK;
}

/* The walls the flow last saw are the markers of the last
 * fsi_move_interface, the solid's state one step back: they are kept, not
 * recomputed from the solid, so that the next move uncovers the same fresh
 * cells. Read back, the immersed boundary moves to them without touching
 * the flow (whose cell kinds the flow's own checkpoint restores): the same
 * bits as if it had been built on them (ibm_update). */
int fsi_checkpoint(Fsi *f, Checkpoint *ck) {
    PdSurface *w = &f->wetted;
    const int64_t cap = f->surface.length;
    TRY(checkpoint_io(ck, "fsi.loop_start", w->loop_start,
                      (size_t)(f->loop_count + 1) * sizeof(int64_t)));
    int64_t len = w->length;
    TRY(checkpoint_io_array(ck, "fsi.points", w->point, sizeof(int32_t), &len, cap));
    w->length = len;
    TRY(checkpoint_io_array(ck, "fsi.mx", f->mx, sizeof(double), &len, cap));
    TRY(checkpoint_io_array(ck, "fsi.my", f->my, sizeof(double), &len, cap));
    TRY(checkpoint_io_array(ck, "fsi.mvx", f->mvx, sizeof(double), &len, cap));
    TRY(checkpoint_io_array(ck, "fsi.mvy", f->mvy, sizeof(double), &len, cap));
    TRY(checkpoint_io(ck, "fsi.force_on_solid", f->force_on_solid, sizeof f->force_on_solid));
    TRY(checkpoint_io_int64(ck, "fsi.substeps", &f->substeps));
    if (!checkpoint_reading(ck)) return NSPD_OK;
    if (w->length != w->loop_start[f->loop_count])
        return NSPD_FAIL(NSPD_ERR_INPUT, "checkpoint: the interface's loops do not add up");
    polylines_from_markers(f);
    TRY(ibm_update(f->ibm, f->polylines, f->loop_count, NULL));
    return ibm_surface_reserve(f->ibm, &f->loads);
}
