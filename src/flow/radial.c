#include "flow/radial.h"

#include "core/mem.h"
#include "core/status.h"

#include <math.h>
#include <string.h>

enum { GHOSTS = 2 }; /* the minmod slope of a face's outer cell needs its neighbour */

/* scratch layout: primitive (rho, u, p) with ghosts, 3 (n + 4); the stage's
 * conserved state, 3 n; the face fluxes, 3 (n + 1) */
static size_t scratch_size(long n) {
    const size_t m = (size_t)n;
    return 3 * (m + 2 * GHOSTS) + 3 * m + 3 * (m + 1);
}

/* r^nu / nu: the volume (per radian^(nu-1)) inside r */
static double volume_inside(int nu, double r) {
    return pow(r, nu) / nu;
}
static double face_area(int nu, double r) {
    return nu == 1 ? 1.0 : pow(r, nu - 1);
}

static double cell_width(const RadialSolver *s) {
    return s->cfg.length / (double)s->cfg.cells;
}

/* cells is bounded far below 2^53: (double)i is exact */
static double face_radius(const RadialSolver *s, long i) {
    return (double)i * cell_width(s);
}

static double cell_volume(const RadialSolver *s, long i) {
    return volume_inside(s->cfg.nu, face_radius(s, i + 1)) -
           volume_inside(s->cfg.nu, face_radius(s, i));
}

int radial_create(const RadialConfig *cfg, const RadialState *ambient, RadialSolver *out) {
    memset(out, 0, sizeof *out);
    if (cfg->nu < 1 || cfg->nu > 3 || !(cfg->gamma > 1) || !(cfg->length > 0) || cfg->cells < 2 ||
        !(cfg->cfl > 0 && cfg->cfl <= 0.5))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "radial grid: nu must be 1, 2 or 3, gamma > 1, length > 0, cells >= 2 and "
                         "0 < cfl <= 0.5 (got nu %d, gamma %g, length %g, cells %ld, cfl %g)",
                         cfg->nu, cfg->gamma, cfg->length, cfg->cells, cfg->cfl);
    if (!(ambient->rho > 0 && ambient->p > 0 && isfinite(ambient->u)))
        return NSPD_FAIL(NSPD_ERR_INPUT, "radial grid: the ambient state needs rho > 0 and p > 0");
    out->cfg = *cfg;
    const size_t n = (size_t)cfg->cells;
    int st = nspd_alloc(&out->rho, n, sizeof(double));
    if (st == NSPD_OK) st = nspd_alloc(&out->mom, n, sizeof(double));
    if (st == NSPD_OK) st = nspd_alloc(&out->energy, n, sizeof(double));
    if (st == NSPD_OK) st = nspd_alloc(&out->volume, n, sizeof(double));
    if (st == NSPD_OK) st = nspd_alloc(&out->area, n + 1, sizeof(double));
    if (st == NSPD_OK) st = nspd_alloc(&out->scratch, scratch_size(cfg->cells), sizeof(double));
    if (st != NSPD_OK) {
        radial_free(out);
        TRY(st);
    }
    for (long i = 0; i < cfg->cells; i++) out->volume[i] = cell_volume(out, i);
    for (long i = 0; i <= cfg->cells; i++) out->area[i] = face_area(cfg->nu, face_radius(out, i));
    radial_set_charge(out, 0.0, ambient, ambient);
    return NSPD_OK;
}

void radial_free(RadialSolver *s) {
    nspd_free(&s->rho);
    nspd_free(&s->mom);
    nspd_free(&s->energy);
    nspd_free(&s->volume);
    nspd_free(&s->area);
    nspd_free(&s->scratch);
}

void radial_set_charge(RadialSolver *s, double r0, const RadialState *charge,
                       const RadialState *ambient) {
    const double g1 = s->cfg.gamma - 1;
    const RadialState *st[2] = {charge, ambient};
    double U[2][3];
    for (int k = 0; k < 2; k++) {
        U[k][0] = st[k]->rho;
        U[k][1] = st[k]->rho * st[k]->u;
        U[k][2] = st[k]->p / g1 + 0.5 * st[k]->rho * st[k]->u * st[k]->u;
    }
    const int nu = s->cfg.nu;
    for (long i = 0; i < s->cfg.cells; i++) {
        const double lo = face_radius(s, i), hi = face_radius(s, i + 1);
        double f = 0;
        if (r0 >= hi)
            f = 1;
        else if (r0 > lo)
            f = (volume_inside(nu, r0) - volume_inside(nu, lo)) / s->volume[i];
        s->rho[i] = f * U[0][0] + (1 - f) * U[1][0];
        s->mom[i] = f * U[0][1] + (1 - f) * U[1][1];
        s->energy[i] = f * U[0][2] + (1 - f) * U[1][2];
    }
}

RadialState radial_state(const RadialSolver *s, long i) {
    const double rho = s->rho[i], u = s->mom[i] / rho;
    return (RadialState){rho, u, (s->cfg.gamma - 1) * (s->energy[i] - 0.5 * s->mom[i] * u)};
}

void radial_totals(const RadialSolver *s, double *mass, double *energy) {
    double m = 0, e = 0;
    for (long i = 0; i < s->cfg.cells; i++) {
        const double v = s->volume[i];
        m += v * s->rho[i];
        e += v * s->energy[i];
    }
    *mass = m;
    *energy = e;
}

static double minmod(double a, double b) {
    if (a * b <= 0) return 0;
    return fabs(a) < fabs(b) ? a : b;
}

/* HLLC flux (Toro sec. 10.4, Eqs. 10.37-10.39) with the Einfeldt-Roe wave
 * speeds of Batten et al. (their Eq. 45): S_L = min(u_L - c_L, u~ - c~),
 * S_R = max(u_R + c_R, u~ + c~). */
static void hllc_flux(double g, const double wl[3], const double wr[3], double f[3]) {
    const double rl = wl[0], ul = wl[1], pl = wl[2], rr = wr[0], ur = wr[1], pr = wr[2];
    const double el = pl / (g - 1) + 0.5 * rl * ul * ul, er = pr / (g - 1) + 0.5 * rr * ur * ur;
    const double cl = sqrt(g * pl / rl), cr = sqrt(g * pr / rr);
    const double sl_ = sqrt(rl), sr_ = sqrt(rr);
    const double ut = (sl_ * ul + sr_ * ur) / (sl_ + sr_);
    const double ht = (sl_ * (el + pl) / rl + sr_ * (er + pr) / rr) / (sl_ + sr_);
    const double ct = sqrt(fmax((g - 1) * (ht - 0.5 * ut * ut), 0.0));
    const double SL = fmin(ul - cl, ut - ct), SR = fmax(ur + cr, ut + ct);
    const double sm =
        (pr - pl + rl * ul * (SL - ul) - rr * ur * (SR - ur)) / (rl * (SL - ul) - rr * (SR - ur));
    if (SL >= 0) {
        f[0] = rl * ul;
        f[1] = rl * ul * ul + pl;
        f[2] = ul * (el + pl);
    } else if (SR <= 0) {
        f[0] = rr * ur;
        f[1] = rr * ur * ur + pr;
        f[2] = ur * (er + pr);
    } else {
        /* the star state on the side the face sees, then F* = F_K + S_K (U*_K - U_K) */
        const bool left = sm >= 0;
        const double r = left ? rl : rr, u = left ? ul : ur, p = left ? pl : pr;
        const double e = left ? el : er, S = left ? SL : SR;
        const double k = r * (S - u) / (S - sm);
        const double us[3] = {k, k * sm, k * (e / r + (sm - u) * (sm + p / (r * (S - u))))};
        const double U[3] = {r, r * u, e}, F[3] = {r * u, r * u * u + p, u * (e + p)};
        for (int q = 0; q < 3; q++) f[q] = F[q] + S * (us[q] - U[q]);
    }
}

/* The primitive state with its ghosts: r = 0 always reflects (the axis or
 * centre of symmetry), r = length reflects or copies. NSPD_ERR_NUMERIC at
 * the first cell out of range. */
static int primitives(const RadialSolver *s, const double *rho, const double *mom,
                      const double *energy, double *w) {
    const long n = s->cfg.cells;
    const double g1 = s->cfg.gamma - 1;
    double *wr = w, *wu = w + n + 2 * GHOSTS, *wp = w + 2 * (n + 2 * GHOSTS);
    for (long i = 0; i < n; i++) {
        const double r = rho[i], u = mom[i] / r, p = g1 * (energy[i] - 0.5 * mom[i] * u);
        if (!(r > 0) || !(p > 0))
            return NSPD_FAIL(NSPD_ERR_NUMERIC,
                             "radial solver: %s %.6g in cell %ld (r = %.6g) at step %ld, t = %.6g",
                             r > 0 ? "pressure" : "density", r > 0 ? p : r, i,
                             (face_radius(s, i) + face_radius(s, i + 1)) / 2, s->steps, s->time);
        wr[i + GHOSTS] = r;
        wu[i + GHOSTS] = u;
        wp[i + GHOSTS] = p;
    }
    for (long k = 0; k < GHOSTS; k++) {
        const long in = GHOSTS + k, gi = GHOSTS - 1 - k; /* mirror about r = 0 */
        const long on = GHOSTS + n - 1 - k, go = GHOSTS + n + k;
        wr[gi] = wr[in];
        wu[gi] = -wu[in];
        wp[gi] = wp[in];
        wr[go] = wr[on];
        wu[go] = s->cfg.outer_wall ? -wu[on] : wu[on];
        wp[go] = wp[on];
    }
    return NSPD_OK;
}

/* The face fluxes times the face areas, A_{i+1/2} F_{i+1/2}, i = -1 .. n-1 */
static void face_fluxes(const RadialSolver *s, const double *w, double *af) {
    const long n = s->cfg.cells, m = n + 2 * GHOSTS;
    const double *w0 = w, *w1 = w + m, *w2 = w + 2 * m;
    for (long f = 0; f <= n; f++) {
        /* face f lies between cells f-1 and f: ghost-indexed j = f-1+G, j+1 */
        const long j = f - 1 + GHOSTS;
        double wl[3], wr[3];
        const double *c[3] = {w0, w1, w2};
        for (int q = 0; q < 3; q++) {
            const double *v = c[q];
            wl[q] = v[j] + 0.5 * minmod(v[j] - v[j - 1], v[j + 1] - v[j]);
            wr[q] = v[j + 1] - 0.5 * minmod(v[j + 1] - v[j], v[j + 2] - v[j + 1]);
        }
        double flux[3];
        hllc_flux(s->cfg.gamma, wl, wr, flux);
        const double a = s->area[f];
        for (int q = 0; q < 3; q++) af[3 * f + q] = a * flux[q];
    }
}

/* dt = cfl min_i 2 V_i / ((A_{i-1/2} + A_{i+1/2}) s_i), s_i the fastest
 * signal |u| + c of the cell and its neighbours: the flux-difference form's
 * step bound, which at the centre of a sphere (V = dr^3/3, A = dr^2) is
 * 2/3 of the planar dr / s. */
static double stable_step(const RadialSolver *s, const double *w) {
    const long n = s->cfg.cells, m = n + 2 * GHOSTS;
    const double g = s->cfg.gamma;
    double dt = INFINITY;
    for (long i = 0; i < n; i++) {
        double speed = 0;
        for (long j = i + GHOSTS - 1; j <= i + GHOSTS + 1; j++)
            speed = fmax(speed, fabs(w[m + j]) + sqrt(g * w[2 * m + j] / w[j]));
        dt = fmin(dt, 2 * s->volume[i] / ((s->area[i] + s->area[i + 1]) * speed));
    }
    return s->cfg.cfl * dt;
}

/* u_out = a u0 + b (u + dt L(u)), L the finite-volume right-hand side */
static void stage(const RadialSolver *s, const double *w, const double *af, double dt, double a,
                  double b, const double *const u0[3], double *const u[3]) {
    const long n = s->cfg.cells, m = n + 2 * GHOSTS;
    for (long i = 0; i < n; i++) {
        const double v = s->volume[i];
        const double src = w[2 * m + i + GHOSTS] * (s->area[i + 1] - s->area[i]);
        for (int q = 0; q < 3; q++) {
            const double rhs = (af[3 * i + q] - af[3 * (i + 1) + q] + (q == 1 ? src : 0)) / v;
            u[q][i] = a * u0[q][i] + b * (u[q][i] + dt * rhs);
        }
    }
}

int radial_step(RadialSolver *s, double t_end) {
    if (!(s->time < t_end)) return NSPD_OK;
    const long n = s->cfg.cells;
    double *w = s->scratch, *stage_u = w + 3 * (n + 2 * GHOSTS), *af = stage_u + 3 * n;
    double *const u[3] = {s->rho, s->mom, s->energy};
    double *const v[3] = {stage_u, stage_u + n, stage_u + 2 * n};
    const double *const u_c[3] = {s->rho, s->mom, s->energy};
    TRY(primitives(s, s->rho, s->mom, s->energy, w));
    double dt = stable_step(s, w);
    const bool last = s->time + dt >= t_end;
    if (last) dt = t_end - s->time;
    /* Heun: v = u + dt L(u); u = (u + v + dt L(v)) / 2 */
    for (int q = 0; q < 3; q++) memcpy(v[q], u[q], (size_t)n * sizeof(double));
    face_fluxes(s, w, af);
    stage(s, w, af, dt, 0.0, 1.0, u_c, v);
    TRY(primitives(s, v[0], v[1], v[2], w));
    face_fluxes(s, w, af);
    stage(s, w, af, dt, 0.5, 0.5, u_c, v);
    for (int q = 0; q < 3; q++) memcpy(u[q], v[q], (size_t)n * sizeof(double));
    s->time = last ? t_end : s->time + dt;
    s->steps++;
    return NSPD_OK;
}

int radial_advance(RadialSolver *s, double t_end) {
    while (s->time < t_end) TRY(radial_step(s, t_end));
    /* the end state checked as every stage's */
    return primitives(s, s->rho, s->mom, s->energy, s->scratch);
}
