/* Time stepping of a correspondence-PD body (body.h): the force with
 * its stress update and damage, velocity Verlet, and the stable step. */
#include "solid/correspondence/body.h"

#include "core/kernel.h"
#include "core/mem.h"
#include "core/parallel.h"
#include "core/reduce.h"
#include "core/status.h"
#include "solid/correspondence/bac_force.h"
#include "solid/correspondence/classic_force.h"
#include "solid/correspondence/halo.h"
#include "solid/correspondence/rk_gradient.h"
#include "solid/correspondence/sl_force.h"

#include <math.h>
#include <string.h>

/* BacSystem.exchange on several processes: a per-point array's ghosts */
static void exchange_points(void *body, double *array, int width) {
    void *arrays[1] = {array};
    cpd_halo_exchange(body, arrays, 1, (size_t)width * sizeof(double));
}

static BacSystem system_of(const CpdBody *b) {
    BacSystem s = {.dim = b->dim,
                   .n = b->n,
                   .volume = b->volume,
                   .first = b->first,
                   .nbr = b->nbr,
                   .reverse = b->reverse,
                   .phi = b->phi,
                   .omega = b->omega,
                   .lambda = b->lambda,
                   .mu = b->mu,
                   .bond_scale = b->scale,
                   .pairs = b->pairs,
                   .inv_w0 = b->inv_w0,
                   .c = b->coef_c,
                   .phi_rev = b->phi_rev,
                   .phi_sum = b->phi_sum,
                   .n_all = b->n + b->ghosts,
                   .exchange = b->halo ? exchange_points : NULL,
                   .exchange_context = (void *)b};
    for (int d = 0; d < 3; d++) s.x[d] = b->x[d];
    return s;
}

/* ClassicSystem.exchange_bonds on several processes: the crossing bonds'
 * reverse T from their owners */
static void exchange_reverse_bonds(void *body, double *T) {
    cpd_halo_bonds(body, T);
}

static ClassicSystem classic_of(const CpdBody *b) {
    ClassicSystem s = {.dim = b->dim,
                       .n = b->n,
                       .volume = b->volume,
                       .first = b->first,
                       .nbr = b->nbr,
                       .reverse = b->reverse,
                       .omega = b->omega,
                       .lambda = b->lambda,
                       .mu = b->mu,
                       .delta = b->delta,
                       .thickness = b->dim == 2 ? b->cfg.pd.thickness : 0.0,
                       .stabilisation = b->cfg.stabilisation,
                       .bond_scale = b->scale,
                       .exchange_bonds = b->halo ? exchange_reverse_bonds : NULL,
                       .exchange_context = (void *)b};
    for (int d = 0; d < 3; d++) s.x[d] = b->x[d];
    return s;
}

double cpd_fit_norm(const CpdBody *b, int64_t i) {
    double s = 0.0;
    for (int64_t k = b->first[i]; k < b->first[i + 1]; k++)
        for (int a = 0; a < b->dim; a++)
            s += fabs(b->phi[(int64_t)b->dim * k + a]) * b->volume[b->nbr[k]];
    return s;
}

int64_t cpd_shape_check(CpdBody *b, const uint8_t *redo) {
    if (b->cfg.force == CPD_FORCE_CLASSIC) {
        const ClassicSystem s = classic_of(b);
        return classic_shape_check(&s, redo, b->ok);
    }
    int64_t missing = rk_gradient_weights_of(b->cfg.rk_order, b->cfg.kernel, b->dim, b->n,
                                             (const double *const *)b->x, b->volume, b->first,
                                             b->nbr, b->delta, b->scale, redo, b->phi, b->ok);
    if (!b->fit_norm0) return missing;
    for (int64_t i = 0; i < b->n; i++) {
        if ((redo && !redo[i]) || !b->ok[i]) continue;
        if (cpd_fit_norm(b, i) <= CPD_FIT_GROWTH_LIMIT * b->fit_norm0[i]) continue;
        b->ok[i] = 0; /* failed: cpd_settle_weights breaks its bonds */
        for (int64_t k = b->first[i]; k < b->first[i + 1]; k++)
            for (int a = 0; a < b->dim; a++) b->phi[(int64_t)b->dim * k + a] = 0.0;
        missing++;
    }
    return missing;
}

/* The damage law of the configuration for the state of bond k = (i -> j)
 * (notes 1c.8). The bond-associated force keeps it per bond pair; the classic
 * one per point, and the bond then takes the larger of its two points'
 * values (plastic strain, principal stress; inverted if either is): fmax
 * is exact and commutative, so both ends of a pair get the same damage
 * bits, and a bond fails as soon as either end's material does.
 * update_damage takes the bond-associated ductile and brittle laws from
 * pair_damage instead (the same bits, once per pair). */
static double damage_law(const CpdBody *b, int64_t i, int64_t k) {
    const CpdConfig *c = &b->cfg;
    int64_t p, q;
    if (c->force == CPD_FORCE_CLASSIC)
        p = i, q = b->nbr[k];
    else
        p = q = b->pairs.of[k];
    if (b->inverted[p] || b->inverted[q]) return 1.0;
    switch (c->damage) {
    case CPD_DAMAGE_DUCTILE:
        return j2_damage_ductile(j2_fmax(b->eqps[p], b->eqps[q]), c->plastic_strain_threshold,
                                 c->plastic_strain_critical);
    case CPD_DAMAGE_BRITTLE:
        return j2_damage_brittle(j2_fmax(b->principal[p], b->principal[q]), c->critical_stress,
                                 c->damage_ramp);
    case CPD_DAMAGE_STRETCH: {
        /* |xi + (u_j - u_i)|^2 against (1 + s_c)^2 |xi|^2: the same bits
         * from both ends (negated operands, squares) */
        const int64_t j = b->nbr[k];
        double y2 = 0.0, x2 = 0.0;
        for (int a = 0; a < b->dim; a++) {
            const double xi = b->x[a][j] - b->x[a][i];
            const double y = xi + (b->u[a][j] - b->u[a][i]);
            y2 += y * y;
            x2 += xi * xi;
        }
        const double limit = 1.0 + c->critical_stretch;
        return y2 > limit * limit * x2 ? 1.0 : 0.0;
    }
    default:
        return 0.0;
    }
}

/* The bond-associated force's ductile or brittle law per pair (its state is
 * per pair), into d: damage_law's bits (the fmax of a value with itself is
 * the value), formed once per pair instead of once per bond, in SIMD lanes.
 * Returns the number of pairs whose damage grew. */
static int64_t pair_damage(const CpdBody *b, double *d) {
    const CpdConfig *c = &b->cfg;
    const int64_t np = b->pairs.count;
    const double *damage = b->damage;
    const int64_t *bond = b->pairs.bond;
    /* the pairs whose damage the law grows, counted in a double (exact
     * below 2^53) in the same lanes: an int beside the doubles would keep
     * the loop scalar */
    double grown = 0.0;
    if (c->damage == CPD_DAMAGE_DUCTILE) {
        const double *eqps = b->eqps, lo = c->plastic_strain_threshold,
                     hi = c->plastic_strain_critical;
#pragma omp parallel for simd schedule(simd : static) reduction(+ : grown) if (np >= PARALLEL_MIN_ITEMS)
        for (int64_t p = 0; p < np; p++) {
            /* vectorised x1: tests/unit/core/vectorised.sh */
            d[p] = j2_damage_ductile(eqps[p], lo, hi);
            grown += NSPD_GT(d[p], damage[bond[p]]) ? 1.0 : 0.0;
        }
    } else {
        const double *principal = b->principal, cr = c->critical_stress, ramp = c->damage_ramp;
#pragma omp parallel for simd schedule(simd : static) reduction(+ : grown) if (np >= PARALLEL_MIN_ITEMS)
        for (int64_t p = 0; p < np; p++) {
            /* vectorised x1: tests/unit/core/vectorised.sh */
            d[p] = j2_damage_brittle(principal[p], cr, ramp);
            grown += NSPD_GT(d[p], damage[bond[p]]) ? 1.0 : 0.0;
        }
    }
    /* an inverted pair has failed (counted if the law had not grown it):
     * apart, because a byte read beside the doubles keeps GCC 12 from
     * vectorising the laws' loops */
    int64_t failed = 0;
#pragma omp parallel for schedule(static) reduction(+ : failed) if (np >= PARALLEL_MIN_ITEMS)
    for (int64_t p = 0; p < np; p++)
        if (b->inverted[p]) {
            const double old = damage[bond[p]];
            failed += !(d[p] > old) && 1.0 > old ? 1 : 0;
            d[p] = 1.0;
        }
    return (int64_t)grown + failed;
}

/* Damage grows (never falls) by the law, then the weights settle
 * (cpd_settle_weights). Returns the number of bonds whose damage grew. */
static int64_t update_damage(CpdBody *b) {
    int64_t grown = 0;
    /* the pairs' laws, in the force's T scratch (free until the next force) */
    const bool by_pair =
        b->cfg.force != CPD_FORCE_CLASSIC &&
        (b->cfg.damage == CPD_DAMAGE_DUCTILE || b->cfg.damage == CPD_DAMAGE_BRITTLE);
    double *dpair = b->work_bond;
    /* most steps break nothing: then the pass over the bonds is skipped
     * (b->redo is read only when something grew) */
    if (by_pair && cpd_halo_sum(b, pair_damage(b, dpair)) == 0) return 0; /* all ranks alike */
    if (b->cfg.force == CPD_FORCE_CLASSIC) {
        /* the law reads both ends' point state: the ghosts' from their owners */
        void *state[2] = {b->eqps, b->principal}, *inverted[1] = {b->inverted};
        cpd_halo_exchange(b, state, 2, sizeof(double));
        cpd_halo_exchange(b, inverted, 1, 1);
    }
#pragma omp parallel for schedule(static) reduction(+ : grown) if (b->bond_count >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < b->n; i++) {
        uint8_t redo = 0;
        for (int64_t k = b->first[i]; k < b->first[i + 1]; k++) {
            const double d = by_pair ? dpair[b->pairs.of[k]] : damage_law(b, i, k);
            if (d > b->damage[k]) {
                b->damage[k] = d;
                b->scale[k] = 1.0 - d;
                redo = 1;
                grown++;
            }
        }
        b->redo[i] = redo;
        b->dirty[i] |= redo;
    }
    grown = cpd_halo_sum(b, grown); /* the weights settle on every rank or none */
    return grown > 0 ? grown + cpd_settle_weights(b) : 0;
}

/* b->inv_w0 of the points flagged in b->dirty (their family's damage
 * changed since the last call) and the force's coefficients of them and
 * their neighbours (bac_coefficients), the flags then cleared. */
static void refresh_weights(CpdBody *b) {
    if (b->inv_w0) {
        BacSystem s = system_of(b);
        s.inv_w0 = NULL;
        s.c = s.phi_rev = s.phi_sum = NULL;
        bac_inverse_weights(&s, b->dirty, b->inv_w0);
        /* several processes: the ghosts' 1 / w0 and whether their
         * families changed */
        void *w0[1] = {b->inv_w0}, *dirty[1] = {b->dirty};
        cpd_halo_exchange(b, w0, 1, sizeof(double));
        cpd_halo_exchange(b, dirty, 1, 1);
        uint8_t *near = b->near;
        memcpy(near, b->dirty, (size_t)(b->n + b->ghosts));
        /* serial: few points change at a step, and a neighbour may be
         * marked from several */
        for (int64_t i = 0; i < b->n; i++)
            if (b->dirty[i])
                for (int64_t k = b->first[i]; k < b->first[i + 1]; k++) near[b->nbr[k]] = 1;
        /* a point next to a dirty ghost, through its bond to it (families
         * are symmetric) */
        const CpdHalo *h = b->halo;
        for (int64_t q = 0; h && q < h->bonds.ghosts; q++)
            if (b->dirty[b->nbr[h->cross_bond[q]]]) near[h->cross_point[q]] = 1;
        bac_coefficients(&s, b->inv_w0, near, b->coef_c, b->phi_rev, b->phi_sum);
        cpd_halo_reverse_weights(b); /* the crossing bonds' phi_ji V_j */
    }
    memset(b->dirty, 0, (size_t)(b->n + b->ghosts));
}

int64_t cpd_settle_weights(CpdBody *b) {
    int64_t grown = 0;
    for (int pass = 0; pass < 1000; pass++) {
        if (cpd_halo_sum(b, cpd_shape_check(b, b->redo)) == 0) break; /* all ranks alike */
        void *ok[1] = {b->ok};
        cpd_halo_exchange(b, ok, 1, 1); /* a bond breaks from both ends */
        int64_t broke = 0;
#pragma omp parallel for schedule(static) reduction(+ : broke) if (b->first[b->n] >= PARALLEL_MIN_ITEMS)
        for (int64_t i = 0; i < b->n; i++) {
            uint8_t redo = 0;
            for (int64_t k = b->first[i]; k < b->first[i + 1]; k++)
                if ((!b->ok[i] || !b->ok[b->nbr[k]]) && b->damage[k] < 1.0) {
                    b->damage[k] = 1.0;
                    b->scale[k] = 0.0;
                    redo = 1;
                    broke++;
                }
            b->redo[i] = redo && b->ok[i];
            b->dirty[i] |= redo;
        }
        broke = cpd_halo_sum(b, broke);
        if (broke == 0) break;
        grown += broke;
    }
    refresh_weights(b);
    return grown;
}

void cpd_inverse_weights(CpdBody *b) {
    memset(b->dirty, 1, (size_t)b->n);
    refresh_weights(b);
}

/* The force density at displacements u into L: with the body's material
 * state advanced from u_prev (state true), or stateless (SVK). */
static void body_force(CpdBody *b, bool state, const double *const u[3], double *const L[3]) {
    if (b->cfg.force == CPD_FORCE_CLASSIC) {
        const ClassicSystem s = classic_of(b);
        ClassicState st = {.material = &b->material,
                           .sigma = b->sigma,
                           .eqps = b->eqps,
                           .principal = b->principal,
                           .inverted = b->inverted,
                           .strain_zz = b->strain_zz};
        for (int d = 0; d < 3; d++) st.u_prev[d] = b->u_prev[d];
        classic_force(&s, state ? &st : NULL, u, L, b->work_point, b->work_bond);
        return;
    }
    const BacSystem s = system_of(b);
    BacState st = {.material = &b->material,
                   .sigma = b->sigma,
                   .eqps = b->eqps,
                   .principal = b->principal,
                   .inverted = b->inverted,
                   .strain_zz = b->strain_zz};
    for (int d = 0; d < 3; d++) st.u_prev[d] = b->u_prev[d];
    /* F at u in work_point's first 9 n (what the outputs show), the next 9 n
     * scratch: F at u_prev where the pairs' F_b at u_prev must be formed,
     * and the stateless force's F */
    st.Fb = b->Fb;
    st.fb_given = b->Fb_given ? 1 : 0;
    const int64_t na = b->n + b->ghosts; /* the ghosts' F and S after the run's */
    st.F_prev = b->work_point + 9 * na;
    if (state && b->cfg.frame == CPD_FRAME_SEMI_LAGRANGIAN) {
        /* the outputs' F_i on the reference weights, as the Lagrangian
         * force's; the force and the state on the current ones */
        rk_deformation_gradient(b->dim, b->n, u, NULL, b->volume, b->first, b->nbr, b->phi,
                                b->work_point, NULL);
        const SlWeights w = {.order = b->cfg.rk_order, .kernel = b->cfg.kernel, .delta = b->delta};
        (void)sl_force(&s, &w, &st, u, L, &b->sl, b->work_point + 18 * na);
        return;
    }
    bac_force(&s, state ? &st : NULL, u, L, state ? b->work_point : b->work_point + 9 * na,
              b->work_point + 18 * na, b->work_bond);
    if (state) {
        b->Fb_now = true;
        b->Fb_given = false;
    }
}

int cpd_force(CpdBody *b, double t) {
    body_force(b, true, (const double *const *)b->u, b->force);
    const CpdConfig *c = &b->cfg;
    if (c->pressure_count > 0) {
        double p[64];
        const int count = c->pressure_count < 64 ? c->pressure_count : 64;
        /* a pressure that varies in space: expressions[e[r] - 1] at each point */
        uint16_t e[64] = {0};
        const Expr *expressions = b->boundary.expressions; /* the body's copy of the case's */
        for (int r = 0; r < count; r++) {
            const uint16_t k = c->pressures[r].expr;
            const double X[EXPR_VARIABLES] = {t, 0.0, 0.0, 0.0};
            if (k && expr_uses_position(&expressions[k - 1]))
                e[r] = k;
            else
                p[r] =
                    (k ? expr_eval(&expressions[k - 1], X) : cpd_pressure_at(&c->pressures[r], t)) /
                    b->spacing;
        }
#pragma omp parallel for schedule(static) if (b->n >= PARALLEL_MIN_ITEMS)
        for (int64_t i = 0; i < b->n; i++)
            if (b->load[i] >= 0 && b->load[i] < count) {
                const int r = b->load[i];
                double pr = p[r];
                if (e[r]) {
                    const double X[EXPR_VARIABLES] = {t, b->x[0][i], b->x[1][i], b->x[2][i]};
                    pr = expr_eval(&expressions[e[r] - 1], X) / b->spacing;
                }
                for (int a = 0; a < b->dim; a++) b->force[a][i] += pr * b->load_dir[a][i];
            }
    }
    if (b->has_contact)
        TRY(pd_contact_add(&b->contact, (const double *const *)b->x, (const double *const *)b->u,
                           b->volume, b->force));
    if (c->damage != CPD_DAMAGE_NONE && update_damage(b) > 0) {
        b->damage_grew = true;
        b->Fb_now = false; /* the weights changed */
    }
    return NSPD_OK;
}

static PdMotion motion_of(CpdBody *b) {
    PdMotion m = {.dim = b->dim,
                  .n = b->n,
                  .density = b->cfg.pd.density,
                  .body_force = b->cfg.pd.body_force,
                  .x = {b->x[0], b->x[1], b->x[2]},
                  .region = b->region,
                  .boundary = &b->boundary};
    for (int d = 0; d < 3; d++) {
        m.u[d] = b->u[d];
        m.v[d] = b->v[d];
        m.force[d] = b->force[d];
        m.external[d] = b->external[d];
    }
    return m;
}

/* u_prev = u, the step's start; and, where the last force was formed at
 * this u with these weights (the step's start is the last step's end: the
 * kicks move only v), its pairs' F_b are F_b at u_prev, so the next force
 * forms F only at u (the same bits as forming both). */
static void remember_u(CpdBody *b) {
    for (int d = 0; d < b->dim; d++) /* the ghosts' too: exchanged after the last drift */
        memcpy(b->u_prev[d], b->u[d], (size_t)(b->n + b->ghosts) * sizeof(double));
    b->Fb_given = b->Fb_now;
    b->Fb_now = false;
}

/* The step's middle, from b->time to b->time + dt: u_prev = u, u += dt v
 * (*bad: a displacement not finite, on any rank: all fail together), the
 * ghosts' u, the force at the new u. */
static int drift_then_force(CpdBody *b, const PdMotion *m, double dt, bool *bad) {
    const double t = b->time;
    remember_u(b);
    *bad = cpd_halo_sum(b, pd_drift(m, dt, t + dt)) > 0;
    cpd_halo_exchange(b, (void *const *)b->u, b->dim, sizeof(double));
    return cpd_force(b, t + dt);
}

static int substep(CpdBody *b, double dt) {
    const PdMotion m = motion_of(b);
    if (!b->force_valid) {
        remember_u(b); /* no increment: the stresses stay */
        TRY(cpd_force(b, b->time));
    }
    const double t = b->time;
    pd_kick(&m, 0.5 * dt, t, t + 0.5 * dt);
    bool bad;
    TRY(drift_then_force(b, &m, dt, &bad));
    pd_kick(&m, 0.5 * dt, t + dt, t + dt);
    b->force_valid = true;
    if (bad)
        return NSPD_FAIL(NSPD_ERR_NUMERIC,
                         "a correspondence solid point has a non-finite displacement at step "
                         "%lld (t = %g s); the time step is probably above the stable limit",
                         (long long)b->step + 1, b->time);
    b->time += dt;
    return NSPD_OK;
}

int cpd_step_constrained(CpdBody *b, double dt) {
    const PdMotion m = motion_of(b);
    const double t = b->time;
    bool bad; /* the last force was formed at this u: the coupling moved only v */
    TRY(drift_then_force(b, &m, dt, &bad));
    pd_kick(&m, dt, t + dt, t + dt);
    b->force_valid = true;
    if (b->substeps_max < 1) b->substeps_max = 1;
    if (bad)
        return NSPD_FAIL(NSPD_ERR_NUMERIC,
                         "a constrained correspondence solid point has a non-finite displacement "
                         "at step %lld (t = %g s): the prescribed velocities are not finite",
                         (long long)b->step + 1, b->time);
    b->time += dt;
    b->step++;
    return NSPD_OK;
}

/* Warm re-estimates: cheaper than the first (the mode moves little between
 * them), still enough for the Rayleigh quotient to settle within the
 * margin (tests/unit/solid/correspondence/test_solid.c). */
enum { CPD_WARM_ITERATIONS = 16 };

int cpd_step(CpdBody *b, double dt) {
    if (b->damage_grew && b->step - b->estimated_at >= CPD_REESTIMATE_STEPS) {
        b->stable_now = cpd_stable_dt(b, CPD_WARM_ITERATIONS, true);
        b->estimated_at = b->step;
        b->damage_grew = false;
    }
    int64_t n = 1;
    const double allowed = CPD_DAMAGED_SAFETY * b->stable_now;
    if (b->stable_now < b->stable_dt && dt > allowed) n = (int64_t)ceil(dt / allowed);
    if (n > b->substeps_max) b->substeps_max = n;
    const double h = dt / (double)n;
    for (int64_t k = 0; k < n; k++) TRY(substep(b, h));
    b->step++;
    return NSPD_OK;
}

/* sum_i a_i b_i over both components, in the fixed order of core/reduce.h
 * over the whole body; on several processes the products gathered in its
 * order (products: dim n doubles of scratch), so every rank adds what one
 * process adds. */
static double dot(const CpdBody *b, double *const a[3], double *const c[3], double *products) {
    const int dim = b->dim;
    const double *terms = products;
    double *whole = NULL;
    if (b->halo) {
        for (int64_t i = 0; i < b->n; i++)
            for (int d = 0; d < dim; d++) products[dim * i + d] = a[d][i] * c[d][i];
        whole = cpd_halo_whole(b, products, dim);
        if (!whole) return (double)NAN;
        terms = whole;
    }
    const int64_t n = cpd_whole_points(b);
    double partial[REDUCE_CHUNKS];
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int ch = 0; ch < REDUCE_CHUNKS; ch++) {
        int64_t lo, hi;
        reduce_chunk(n, ch, &lo, &hi);
        double s = 0.0;
        if (whole)
            for (int64_t i = lo; i < hi; i++)
                for (int d = 0; d < dim; d++) s += terms[dim * i + d];
        else
            for (int64_t i = lo; i < hi; i++)
                for (int d = 0; d < dim; d++) s += a[d][i] * c[d][i];
        partial[ch] = s;
    }
    nspd_free(&whole);
    return reduce_combine(partial);
}

/* Power iteration on K / rho, K the Saint Venant-Kirchhoff stiffness at
 * u = 0 with the current damage (the elastic tangent bounds the plastic
 * one from above, so the step holds while the body yields), applied as the
 * central difference (L(e v) - L(-e v)) / (2 e) of the stateless force, e
 * such that the typical point moves 1e-7 spacings: exact but for the SVK's
 * cubic term. Started from the lattice checkerboard (the highest mode's
 * shape) with a fixed pseudo-random part so no mode is missed. The
 * Rayleigh quotient converges from below: the margin is in
 * CPD_POWER_MARGIN. Allocates its scratch (3 dim n doubles, once per
 * estimate); on failure returns the previous estimate. The body's state
 * (u, force, stresses) is untouched: the probes go through the stateless
 * force (the configured one: classic with its zero-energy penalty, which
 * stiffens the highest modes). */
static const double CPD_POWER_MARGIN = 1.02;

double cpd_stable_dt(CpdBody *b, int iterations, bool warm) {
    const int dim = b->dim;
    /* the run's points, with their ghosts (the probes'), and the whole body's */
    const int64_t n = b->n, na = b->n + b->ghosts, whole = cpd_whole_points(b);
    double *mem = NULL;
    if (nspd_alloc(&mem, (size_t)(4 * dim) * (size_t)na, sizeof(double)) != NSPD_OK)
        return b->stable_now;
    double *v[3] = {NULL}, *probe[3] = {NULL}, *Lp[3] = {NULL}, *Lm[3] = {NULL};
    double *products = mem + (int64_t)(3 * dim) * na;
    for (int d = 0; d < dim; d++) {
        v[d] = b->mode[d];
        probe[d] = mem + (int64_t)d * na;
        Lp[d] = mem + (int64_t)(dim + d) * na;
        Lm[d] = mem + (int64_t)(2 * dim + d) * na;
    }
    double vnorm = 0.0;
    if (warm) vnorm = sqrt(dot(b, v, v, products) / (double)whole);
    /* the pseudo-random sequence runs over the whole body's points: a
     * run's starts where its first point's does */
    uint64_t h = 0x9E3779B97F4A7C15ull;
    const int64_t skipped = b->halo ? b->halo->points.first * dim : 0;
    for (int64_t k = 0; k < skipped; k++) h ^= h << 13, h ^= h >> 7, h ^= h << 17;
    for (int64_t i = 0; i < n; i++)
        for (int d = 0; d < dim; d++) {
            h ^= h << 13, h ^= h >> 7, h ^= h << 17;
            const double r = (double)(h >> 11) * 0x1.0p-53 - 0.5;
            const int parity =
                (b->lattice[0][i] + b->lattice[1][i] + (dim == 3 ? b->lattice[2][i] : 0) + d) & 1;
            const double fresh = (parity ? 1.0 : -1.0) + 0.5 * r;
            v[d][i] = warm && vnorm > 0.0 ? v[d][i] / vnorm + 0.05 * fresh : fresh;
        }
    double lambda = 0.0;
    for (int it = 0; it < iterations; it++) {
        const double norm = sqrt(dot(b, v, v, products));
        if (!(norm > 0.0)) break;
        const double e = 1e-7 * b->spacing * sqrt((double)whole);
        for (int d = 0; d < dim; d++)
            for (int64_t i = 0; i < n; i++) v[d][i] /= norm;
        for (int d = 0; d < dim; d++)
            for (int64_t i = 0; i < n; i++) probe[d][i] = e * v[d][i];
        cpd_halo_exchange(b, (void *const *)probe, dim, sizeof(double));
        body_force(b, false, (const double *const *)probe, Lp);
        for (int d = 0; d < dim; d++)
            for (int64_t i = 0; i < n; i++) probe[d][i] = -e * v[d][i];
        cpd_halo_exchange(b, (void *const *)probe, dim, sizeof(double));
        body_force(b, false, (const double *const *)probe, Lm);
        for (int d = 0; d < dim; d++)
            for (int64_t i = 0; i < n; i++)
                Lp[d][i] = -(Lp[d][i] - Lm[d][i]) / (2.0 * e * b->cfg.pd.density);
        lambda = dot(b, v, Lp, products);
        for (int d = 0; d < dim; d++) memcpy(v[d], Lp[d], (size_t)n * sizeof(double));
    }
    nspd_free(&mem);
    return lambda > 0.0 ? 2.0 / sqrt(lambda * CPD_POWER_MARGIN) : b->stable_now;
}

void cpd_point_damage(const CpdBody *b, double *mean, double *broken) {
#pragma omp parallel for schedule(static) if (b->first[b->n] >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < b->n; i++) {
        const int64_t lo = b->first[i], hi = b->first[i + 1];
        double sum = 0.0, gone = 0.0, all = 0.0;
        for (int64_t k = lo; k < hi; k++) {
            const double V = b->volume[b->nbr[k]];
            sum += b->damage[k];
            all += V;
            gone += b->damage[k] >= 1.0 ? V : 0.0;
        }
        if (mean) mean[i] = hi > lo ? sum / (double)(hi - lo) : 1.0;
        if (broken) broken[i] = all > 0.0 ? gone / all : 1.0;
    }
}
