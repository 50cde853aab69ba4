/* Point samples of the PDDO flow's nodal fields; see sample.h.
 *
 * Invariant: first[n] = the stencils' total size; the arrays grow with
 * each point added (setup only), never while sampling. */
#include "flow/pddo/sample.h"

#include "core/mem.h"
#include "core/neighbours.h"
#include "core/status.h"
#include "flow/pddo/operators.h"

#include <math.h>
#include <string.h>

/* NSPD_ERR_INPUT, with the message, where (x, y) may not be sampled. */
static int check_fluid(const PddoCloud *c, double x, double y, const char *name) {
    /* the lattice's sides from its node (0, 0), always there (a side node
     * or, on a periodic axis, the first unknown) */
    const int64_t origin = pddo_cloud_node(c, 0, 0);
    const double lo[2] = {c->x[origin], c->y[origin]};
    const double hi[2] = {lo[0] + c->nx * c->dx, lo[1] + c->ny * c->dx};
    const double slack = 1e-9 * c->dx;
    if (!(x >= lo[0] - slack && x <= hi[0] + slack && y >= lo[1] - slack && y <= hi[1] + slack))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "probe '%s': at [%g, %g] m is outside the flow's rectangle [%g, %g] x "
                         "[%g, %g] m; expected a point in the fluid",
                         name, x, y, lo[0], hi[0], lo[1], hi[1]);
    for (int h = 0; h < c->npatches; h++) {
        const PddoPolarPatch *p = &c->patch[h];
        const double r = hypot(x - p->x, y - p->y);
        if (r < p->radius * (1.0 - 1e-12))
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "probe '%s': at [%g, %g] m is inside body %d (centre [%g, %g] m, "
                             "radius %g m); expected a point in the fluid or on the wall",
                             name, x, y, h, p->x, p->y, p->radius);
    }
    return NSPD_OK;
}

int pddo_sample_add(PddoSample *s, const PddoCloud *c, double x, double y, const char *name) {
    TRY(check_fluid(c, x, y, name));
    const double qx[1] = {x}, qy[1] = {y};
    const double *const xyz[3] = {c->x, c->y, NULL}, *const q[3] = {qx, qy, NULL};
    int64_t *first = NULL;
    int32_t *all = NULL;
    /* the cloud families' margin: lattice nodes at exactly delta are in */
    TRY(neighbours_query(c->n, 2, xyz, 1, q, c->delta * (1.0 + 1e-9), &first, &all));
    int64_t count = 0, on = -1; /* the physical ones, in place; one at the point */
    for (int64_t m = 0; m < first[1]; m++) {
        const int32_t j = all[m];
        if (!pddo_node_physical(c->kind[j])) continue;
        if (hypot(c->x[j] - x, c->y[j] - y) <= 1e-9 * c->dx) on = j;
        all[count++] = j;
    }
    nspd_free(&first);
    if (on >= 0) all[0] = (int32_t)on, count = 1; /* a node: its own value */
    const int64_t n = s->n, total = n > 0 ? s->first[n] : 0;
    double *w = NULL;
    int status = nspd_alloc(&w, (size_t)count, sizeof(double));
    double cond = INFINITY;
    if (status == NSPD_OK && on >= 0)
        w[0] = 1.0, cond = 1.0;
    else if (status == NSPD_OK)
        cond = pddo_ops_interpolation(x, y, count, all, c->x, c->y, c->area, c->delta, w);
    if (status == NSPD_OK && !(cond <= PDDO_COND_MAX))
        status = NSPD_FAIL(NSPD_ERR_INPUT,
                           "probe '%s': at [%g, %g] m its %lld fluid nodes within the horizon "
                           "give a shape matrix of condition %g (limit %g); expected a point "
                           "with nodes around it that span the quadratics",
                           name, x, y, (long long)count, cond, PDDO_COND_MAX);
    /* grow the three arrays (first from n + 1, or 0, to n + 2 entries) */
    if (status == NSPD_OK)
        status = nspd_realloc(&s->first, n > 0 ? (size_t)n + 1 : 0, (size_t)n + 2, sizeof(int64_t));
    if (status == NSPD_OK)
        status = nspd_realloc(&s->nbr, (size_t)total, (size_t)(total + count), sizeof(int32_t));
    if (status == NSPD_OK)
        status = nspd_realloc(&s->w, (size_t)total, (size_t)(total + count), sizeof(double));
    if (status == NSPD_OK) {
        memcpy(s->nbr + total, all, (size_t)count * sizeof(int32_t));
        memcpy(s->w + total, w, (size_t)count * sizeof(double));
        s->first[n] = total;
        s->first[n + 1] = total + count;
        s->n = n + 1;
    }
    nspd_free(&w);
    nspd_free(&all);
    return status;
}

double pddo_sample_at(const PddoSample *s, const double *f, int64_t k) {
    double sum = 0.0;
    for (int64_t m = s->first[k]; m < s->first[k + 1]; m++) sum += s->w[m] * f[s->nbr[m]];
    return sum;
}

void pddo_sample_free(PddoSample *s) {
    nspd_free(&s->first);
    nspd_free(&s->nbr);
    nspd_free(&s->w);
    memset(s, 0, sizeof *s);
}
