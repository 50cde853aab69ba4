/* The polar node patch of paper 002 Sec. 4.1.2; see polar.h. */
#include "flow/pddo/polar.h"

#include "core/status.h"

#include <math.h>

int pddo_polar_layout(PddoPolarPatch *p, double x, double y, double radius, const PddoPolarSpec *s,
                      double dx) {
    const double dtheta = s->dtheta > 0.0 ? s->dtheta : PDDO_POLAR_DTHETA;
    const double dr = s->dr > 0.0 ? s->dr : PDDO_POLAR_DR_OVER_DX * dx;
    const double r_patch = s->r_patch > 0.0 ? s->r_patch : dx / dtheta;
    const double gap = s->gap > 0.0 ? s->gap : 0.5 * dx;
    if (!(dx > 0.0) || !(radius > 0.0) || s->dtheta < 0.0 || s->dr < 0.0 || s->gap < 0.0 ||
        s->r_patch < 0.0 || s->rings_inside < 0 || !(s->local_horizon >= 0.0))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "PDDO polar patch: dx %g, radius %g, dtheta %g, dr %g, r_patch %g, gap "
                         "%g, rings inside %d, local horizon %g; expected positive (or 0 for "
                         "the default)",
                         dx, radius, s->dtheta, s->dr, s->r_patch, s->gap, s->rings_inside,
                         s->local_horizon);
    const double half = round(M_PI / dtheta);
    if (!(half >= 4.0 && half < 1e7))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "PDDO polar patch: dtheta %g rad gives %.0f nodes per ring; expected "
                         "8 to 2e7",
                         dtheta, 2.0 * half);
    /* the wall ring's local horizon over dr, rounded up: its family whole */
    const double wall_reach = s->local_horizon * fmax(1.0, radius * (M_PI / half) / dr);
    int inside = s->rings_inside > 0 ? s->rings_inside : 3;
    if (s->rings_inside == 0 && s->local_horizon > 0.0 && wall_reach < 1e6)
        inside = (int)fmax(3.0, ceil(wall_reach * (1.0 - 1e-12)));
    if (gap < 0.25 * dx * (1.0 - 1e-12))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "PDDO polar patch: gap %g m is under dx/4 = %g m; expected a junction "
                         "with no two nodes closer than dx/4",
                         gap, 0.25 * dx);
    const int outside = (int)floor((r_patch - radius) / dr * (1.0 + 1e-12));
    if (outside < inside || inside * dr >= radius)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "PDDO polar patch: %d fluid rings of %g m up to %g m around radius %g m "
                         "and %d fictitious rings; expected at least as many fluid rings as "
                         "fictitious ones (their pressure images) and the fictitious ones "
                         "inside the body",
                         outside, dr, r_patch, radius, inside);
    p->x = x, p->y = y, p->radius = radius;
    p->ntheta = (int32_t)(2.0 * half);
    p->dtheta = 2.0 * M_PI / p->ntheta;
    p->dr = dr;
    p->rings_inside = inside;
    p->rings = inside + 1 + outside;
    p->r_out = pddo_polar_radius(p, p->rings - 1);
    p->r_cut = p->r_out + gap;
    p->local_horizon = s->local_horizon;
    p->first = 0;
    return NSPD_OK;
}

double pddo_polar_radius(const PddoPolarPatch *p, int q) {
    return p->radius + (q - p->rings_inside) * p->dr;
}

double pddo_polar_horizon(const PddoPolarPatch *p, int q, double delta) {
    if (!(p->local_horizon > 0.0)) return delta;
    const double r = pddo_polar_radius(p, q);
    const double h = fmax(p->dr, fmax(r, p->radius) * p->dtheta);
    /* towards the junction it grows to the lattice's: the outer rings'
     * families reach the lattice beyond the gap as the lattice's reach them */
    return fmin(delta, fmax(p->local_horizon * h, delta - (p->r_out - r)));
}

void pddo_polar_angle(const PddoPolarPatch *p, int t, double *c, double *s) {
    /* angles past pi from their mirror t' = ntheta - t: the same cos, sin negated */
    const int half = p->ntheta / 2;
    const int tt = t <= half ? t : p->ntheta - t;
    const double a = tt * p->dtheta;
    /* 0 and pi lie on the line: their sine is exactly 0 (sin(pi) is not) */
    const double sa = tt == 0 || tt == half ? 0.0 : sin(a);
    *c = cos(a);
    *s = t <= half ? sa : -sa;
}

void pddo_polar_node(const PddoPolarPatch *p, int q, int t, double *x, double *y, double *area) {
    const double r = pddo_polar_radius(p, q);
    double c, s;
    pddo_polar_angle(p, t, &c, &s);
    *x = p->x + r * c;
    *y = p->y + r * s;
    *area = r * p->dr * p->dtheta;
}

int64_t pddo_polar_count(const PddoPolarPatch *p) {
    return (int64_t)p->rings * p->ntheta;
}
