/* Building a correspondence-PD body (body.h). Order, each step on the
 * previous: lattice points (lattice.c, as the bond-based body), volumes,
 * regions and initial velocities (solid/pd/regions.c), families, reverse bonds,
 * kernel and RK weights, pressure-load directions, the stable step. */
#include "solid/correspondence/body.h"

#include "core/mem.h"
#include "core/parallel.h"
#include "core/status.h"
#include "solid/correspondence/bac_force.h"
#include "solid/correspondence/halo.h"
#include "solid/correspondence/sl_force.h"
#include "core/neighbours.h"
#include "solid/pd/lattice.h"
#include "solid/pd/precrack.h"
#include "solid/correspondence/rk_gradient.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The rows of the points with rows[i] (NULL: all) of the family: the
 * square family |xi|_inf <= delta is the disc search of radius sqrt(dim)
 * delta, filtered in place (one neighbour search in the code base); the
 * same 1e-12 margin as neighbours_find, so lattice neighbours at exactly
 * delta are in. */
static int find_rows(CpdBody *b, const uint8_t *rows) {
    const bool square = b->cfg.family == CPD_FAMILY_SQUARE;
    const double reach = square ? b->delta * sqrt((double)b->dim) : b->delta;
    TRY(neighbours_find_rows(b->n, b->dim, (const double *const *)b->x, reach, rows, &b->first,
                             &b->nbr));
    if (square) {
        const double limit = b->delta * (1.0 + 1e-12);
        int64_t kept = 0;
        for (int64_t i = 0; i < b->n; i++) {
            const int64_t lo = b->first[i], hi = b->first[i + 1];
            b->first[i] = kept;
            for (int64_t k = lo; k < hi; k++) {
                const int32_t j = b->nbr[k];
                bool in = true;
                for (int a = 0; a < b->dim; a++) in = in && fabs(b->x[a][j] - b->x[a][i]) <= limit;
                if (in) b->nbr[kept++] = j;
            }
        }
        b->first[b->n] = kept;
        /* the disc search's rows were longer (36 against 24 at m = 2.5):
         * give the slack back */
        int32_t *tight;
        TRY(nspd_alloc(&tight, (size_t)(kept > 0 ? kept : 1), sizeof(int32_t)));
        memcpy(tight, b->nbr, (size_t)kept * sizeof(int32_t));
        nspd_free(&b->nbr);
        b->nbr = tight;
    }
    b->bond_count = b->first[b->n];
    return NSPD_OK;
}

/* The families of the whole body, or on several processes (comm) those
 * of this rank's run (halo.h) and of the points they reach, whose rows
 * hold the reverse bonds; every other row empty. So a rank never holds
 * the whole body's bonds. */
static int find_families(CpdBody *b, const NspdComm *comm) {
    if (!comm) return find_rows(b, NULL);
    const int64_t n = b->n, lo = point_halo_run_start(n, comm->size, comm->rank),
                  hi = point_halo_run_start(n, comm->size, comm->rank + 1);
    uint8_t *rows = NULL;
    TRY(nspd_alloc(&rows, (size_t)n + 1, 1));
    for (int64_t i = lo; i < hi; i++) rows[i] = 1;
    int status = find_rows(b, rows);
    if (status == NSPD_OK) { /* the run's neighbours too, then all their rows */
        for (int64_t k = b->first[lo]; k < b->first[hi]; k++) rows[b->nbr[k]] = 1;
        nspd_free(&b->first);
        nspd_free(&b->nbr);
        status = find_rows(b, rows);
    }
    nspd_free(&rows);
    return status;
}

/* sigma (4), eqps, principal, inverted and, in plane stress, strain_zz of
 * `count` points (classic) or pairs. */
static int state_arrays(CpdBody *b, size_t count) {
    TRY(nspd_alloc(&b->sigma, 4 * count, sizeof(double)));
    TRY(nspd_alloc(&b->eqps, count, sizeof(double)));
    TRY(nspd_alloc(&b->principal, count, sizeof(double)));
    TRY(nspd_alloc(&b->inverted, count, 1));
    if (b->cfg.pd.model == PD_PLANE_STRESS) TRY(nspd_alloc(&b->strain_zz, count, sizeof(double)));
    return NSPD_OK;
}

int cpd_body_pair_arrays(CpdBody *b) {
    nspd_free(&b->sigma);
    nspd_free(&b->eqps);
    nspd_free(&b->principal);
    nspd_free(&b->inverted);
    nspd_free(&b->strain_zz);
    nspd_free(&b->Fb);
    nspd_free(&b->work_bond);
    TRY(state_arrays(b, (size_t)b->pairs.count));
    if (b->dim == 2) TRY(nspd_alloc(&b->Fb, 4 * (size_t)b->pairs.count, sizeof(double)));
    /* the force's scratch with the coefficients kept (P_b per pair, and
     * a flag per pair in plane stress) */
    const BacSystem kept = {
        .dim = b->dim, .n = b->n, .first = b->first, .pairs = b->pairs, .c = b->coef_c};
    const int plane_stress = b->cfg.pd.model == PD_PLANE_STRESS ? 1 : 0;
    return nspd_alloc(&b->work_bond, (size_t)bac_work_bond(&kept, plane_stress), sizeof(double));
}

/* Per point (the run's and the ghosts') and per bond (the run's rows; phi
 * with room for the crossing bonds' reverse weights after them, halo.h). */
static int alloc_arrays(CpdBody *b) {
    const size_t n = (size_t)(b->n + b->ghosts), nb = (size_t)b->bond_count;
    const size_t crossing = b->halo ? (size_t)b->halo->bonds.ghosts : 0;
    for (int d = 0; d < 3; d++) {
        TRY(nspd_alloc(&b->u[d], n, sizeof(double)));
        TRY(nspd_alloc(&b->v[d], n, sizeof(double)));
        TRY(nspd_alloc(&b->force[d], n, sizeof(double)));
        TRY(nspd_alloc(&b->external[d], n, sizeof(double)));
        TRY(nspd_alloc(&b->u_prev[d], n, sizeof(double)));
        TRY(nspd_alloc(&b->load_dir[d], n, sizeof(double)));
        TRY(nspd_alloc(&b->mode[d], n, sizeof(double)));
    }
    TRY(nspd_alloc(&b->volume, n, sizeof(double)));
    TRY(nspd_alloc(&b->region, n, sizeof(int16_t)));
    TRY(nspd_alloc(&b->load, n, sizeof(int16_t)));
    TRY(nspd_alloc(&b->ok, n, 1));
    TRY(nspd_alloc(&b->redo, n, 1));
    TRY(nspd_alloc(&b->dirty, n, 1));
    TRY(nspd_alloc(&b->near, n, 1));
    memset(b->dirty, 1, n); /* nothing formed yet */
    /* F and F at u_prev (the classic force: F and P), then the bond-
     * associated force's per-point scratch */
    TRY(nspd_alloc(&b->work_point, (size_t)(18 + bac_work_per_point(b->dim)) * n, sizeof(double)));
    TRY(nspd_alloc(&b->omega, nb, sizeof(double)));
    /* the material state: per point for the classic force (which needs no
     * RK weights); per pair for the bond-associated one, allocated once
     * the pairs are known (state_arrays) */
    const bool classic = b->cfg.force == CPD_FORCE_CLASSIC;
    if (!classic) TRY(nspd_alloc(&b->phi, (size_t)b->dim * (nb + crossing), sizeof(double)));
    TRY(nspd_alloc(&b->damage, nb, sizeof(double)));
    TRY(nspd_alloc(&b->scale, nb, sizeof(double)));
    if (classic) TRY(state_arrays(b, n));
    /* T (dim per bond, and per crossing bond its reverse's); the bond-associated force's P_b (dim^2
     * per pair) comes with the pairs */
    if (classic) TRY(nspd_alloc(&b->work_bond, (size_t)b->dim * (nb + crossing), sizeof(double)));
    return NSPD_OK;
}

/* A pressure acts on the faces of the points' lattice cells that border
 * the pressurised space (the load's region): for point i, every axis
 * neighbour site x_i +- dx e_a inside the region exposes one face, pushed
 * by p dx (times the thickness) along -+e_a. load_dir holds the sum of
 * those face normals, so the force density is p / dx * load_dir. On a
 * staircase boundary this is the exact pressure force of the staircase:
 * its resultant over any part is the pressure times the projected length,
 * and zero over a closed cavity. */
static void pressure_directions(CpdBody *b) {
    const CpdConfig *cfg = &b->cfg;
#pragma omp parallel for schedule(static) if (b->n >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < b->n; i++) {
        b->load[i] = -1;
        for (int d = 0; d < 3; d++) b->load_dir[d][i] = 0.0;
        for (int r = 0; r < cfg->pressure_count && b->load[i] < 0; r++) {
            double dir[3] = {0, 0, 0};
            bool any = false;
            for (int a = 0; a < b->dim; a++)
                for (int s = -1; s <= 1; s += 2) {
                    double p[3] = {b->x[0][i], b->x[1][i], b->x[2][i]};
                    p[a] += (double)s * b->spacing;
                    if (shapeset_contains(&cfg->pressures[r].region, p)) {
                        dir[a] -= (double)s;
                        any = true;
                    }
                }
            if (!any) continue;
            b->load[i] = (int16_t)r;
            for (int a = 0; a < b->dim; a++) b->load_dir[a][i] = dir[a];
        }
    }
}

/* The first point (the whole body's lowest index, on any number of
 * processes) left without RK weights (or an invertible K_i) by the intact
 * body, refused: the body is thinner than its family there. */
static int refuse_thin(const CpdBody *b) {
    int64_t first = INT64_MAX, missing = 0;
    char text[400] = "";
    for (int64_t i = 0; i < b->n; i++) {
        if (b->ok[i]) continue;
        missing++;
        if (first != INT64_MAX) continue;
        first = b->halo ? point_halo_global(&b->halo->points, i) : i;
        snprintf(text, sizeof text, "(%g, %g) m", b->x[0][i], b->x[1][i]);
    }
    missing = cpd_halo_sum(b, missing);
    if (missing == 0) return NSPD_OK;
    if (b->halo) (void)comm_first_failure(&b->halo->points.comm, first, text, (int)sizeof text);
    return NSPD_FAIL(NSPD_ERR_INPUT,
                     "%lld points, the first at %s, have too few neighbours for "
                     "the correspondence gradient (%s over |xi| <= %g m): the "
                     "body is thinner than its family there; expected a smaller spacing or "
                     "a larger horizon_factor",
                     (long long)missing, text,
                     b->cfg.force == CPD_FORCE_CLASSIC ? "an invertible shape tensor"
                                                       : "a quadratic fit",
                     b->delta);
}

/* The semi-Lagrangian force's scratch, and each pair's F_b at the start:
 * the identity (the body starts undeformed; for this frame F_b is state,
 * sl_force.h). */
static int semi_lagrangian(CpdBody *b, bool divided) {
    if (divided)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "solid.correspondence.frame: semi_lagrangian runs on one process (its "
                         "refit of the weights on the current positions would need the ghosts' "
                         "positions each step, which the halo does not exchange); expected one "
                         "process, or frame: lagrangian");
    if (b->dim != 2 || b->cfg.force != CPD_FORCE_BOND_ASSOCIATED)
        return NSPD_FAIL(NSPD_ERR_INPUT, "the semi-Lagrangian frame is the 2D bond-associated "
                                         "force's; expected frame: lagrangian");
    TRY(sl_work_create(b->dim, b->n, b->bond_count, b->pairs.count, &b->sl));
    const int64_t np = b->pairs.count;
    for (int64_t p = 0; p < np; p++) {
        b->Fb[p] = b->Fb[3 * np + p] = 1.0;
        b->Fb[np + p] = b->Fb[2 * np + p] = 0.0;
    }
    return NSPD_OK;
}

static int build(CpdBody *b, CpdConfig *cfg, const NspdComm *comm) {
    memset(b, 0, sizeof *b);
    b->cfg = *cfg;
    memset(cfg, 0, sizeof *cfg);
    cfg = &b->cfg;
    PdConfig *pd = &cfg->pd;
    if (cfg->rk_order == 0) cfg->rk_order = 2; /* a configuration built in code */
    b->dim = pd->dim;
    const bool polar = pd->lattice_kind == PD_LATTICE_POLAR;
    const bool mesh = pd->lattice_kind == PD_LATTICE_ABAQUS;
    if ((polar || mesh) && cfg->pressure_count > 0)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "pressure loads act on the square lattice's cell faces; expected no "
                         "pressure_loads with a %s lattice",
                         polar ? "polar" : "mesh's");
    if (polar) pd->spacing = lattice_polar_spacing(&pd->polar); /* the radial spacing */
    b->spacing = pd->spacing;
    b->delta = pd->horizon_factor * pd->spacing;
    const double E = pd->youngs_modulus, nu = cfg->poisson_ratio;
    b->mu = E / (2.0 * (1.0 + nu));
    b->lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    b->material =
        j2_material(E, nu, cfg->yield_stress, cfg->hardening, pd->model == PD_PLANE_STRESS ? 1 : 0);

    Lattice lat = {0};
    if (polar && b->dim != 2)
        return NSPD_FAIL(NSPD_ERR_INPUT, "the polar lattice is 2D; expected a 2D model");
    if (polar)
        TRY(lattice_fill_polar(&lat, &pd->polar, &pd->geometry));
    else if (mesh)
        TRY(mesh_points_fill(&lat, &pd->mesh, b->dim, pd->spacing, &pd->geometry));
    else
        TRY(lattice_fill(&lat, &pd->geometry, b->dim, pd->spacing,
                         pd->has_lattice_origin ? pd->lattice_origin : NULL));
    b->n = lat.n;
    for (int d = 0; d < 3; d++) {
        b->x[d] = lat.x[d];
        b->lattice[d] = lat.index[d];
    }
    TRY(find_families(b, comm));
    TRY(nspd_alloc(&b->reverse, (size_t)b->bond_count + 1, sizeof(int64_t)));
    /* several processes: the run's part of the families from here on
     * (its bonds' reverse bonds are in its neighbours' rows; the
     * neighbours' bonds to points further away have none here), and
     * everything below for the part alone (halo.h) */
    const int64_t missing = bac_reverse_bonds(b->n, b->first, b->nbr, b->reverse);
    if (comm)
        TRY(cpd_body_divide(b, comm));
    else if (missing != 0)
        return NSPD_FAIL(NSPD_ERR_INTERNAL, "the correspondence families are not symmetric");
    if (!comm && cfg->force != CPD_FORCE_CLASSIC)
        TRY(bac_pairs_create(b->n, b->first, b->reverse, &b->pairs));
    TRY(alloc_arrays(b));
    const int64_t na = b->n + b->ghosts;
    const double v_ref = pow(pd->spacing, b->dim) * (b->dim == 2 ? pd->thickness : 1.0);
    /* a polar element's area is its ring's (lattice index 1), a mesh
     * element's is its number's (index 2), so the ghosts of several
     * processes get theirs from their indices too */
    for (int64_t i = 0; i < na; i++)
        b->volume[i] = polar  ? lattice_polar_area(&pd->polar, b->lattice[1][i]) * pd->thickness
                       : mesh ? mesh_points_measure(&pd->mesh, b->lattice[2][i]) * pd->thickness
                              : v_ref;
    pd_regions_assign(pd, na, (const double *const *)b->x, b->region, b->v);
    TRY(pd_boundary_table_build(&b->boundary, pd));

    if (cfg->force != CPD_FORCE_CLASSIC) {
        const size_t n = (size_t)na, nb = (size_t)b->bond_count, dim = (size_t)b->dim;
        TRY(nspd_alloc(&b->inv_w0, n, sizeof(double)));
        TRY(nspd_alloc(&b->coef_c, nb, sizeof(double)));
        TRY(nspd_alloc(&b->phi_rev, dim * nb, sizeof(double)));
        TRY(nspd_alloc(&b->phi_sum, dim * n, sizeof(double)));
        TRY(cpd_body_pair_arrays(b));
    }
#pragma omp parallel for schedule(static) if (b->first[b->n] >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < b->n; i++)
        for (int64_t k = b->first[i]; k < b->first[i + 1]; k++) {
            double xi[3] = {0, 0, 0};
            for (int a = 0; a < b->dim; a++) xi[a] = b->x[a][b->nbr[k]] - b->x[a][i];
            b->omega[k] = rk_kernel_of(cfg->kernel, b->dim, xi, b->delta);
            b->scale[k] = 1.0;
            const double xj[3] = {b->x[0][b->nbr[k]], b->x[1][b->nbr[k]], b->x[2][b->nbr[k]]};
            const double xp[3] = {b->x[0][i], b->x[1][i], b->x[2][i]};
            for (int c = 0; c < pd->precrack_count; c++)
                if (precrack_cuts(&pd->precracks[c], b->dim, xp, xj)) b->damage[k] = 1.0;
        }
    /* the intact body must give every point weights (else it is thinner
     * than a family: refused); then the pre-cracks break their bonds and
     * the weights settle like damage's (a point a pre-crack isolates is
     * debris) */
    (void)cpd_shape_check(b, NULL);
    TRY(refuse_thin(b));
    if (b->phi) {
        TRY(nspd_alloc(&b->fit_norm0, (size_t)(b->n > 0 ? b->n : 1), sizeof(double)));
        for (int64_t i = 0; i < b->n; i++) b->fit_norm0[i] = cpd_fit_norm(b, i);
    }
    void *ok[1] = {b->ok};
    cpd_halo_exchange(b, ok, 1, 1); /* the ghosts' (several processes) */
    for (int64_t i = 0; i < b->n; i++) {
        b->redo[i] = 0;
        for (int64_t k = b->first[i]; k < b->first[i + 1]; k++)
            if (b->damage[k] >= 1.0) b->scale[k] = 0.0, b->redo[i] = 1;
    }
    cpd_settle_weights(b);
    pressure_directions(b);
    b->stable_dt = b->stable_now = cpd_stable_dt(b, CPD_COLD_ITERATIONS, false);
    if (pd->contact.enabled) {
        if (comm)
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "solid.contact: contact runs on one process (a fragment's "
                             "candidates may leave a process's halo); expected one process, or "
                             "no contact");
        b->has_contact = true;
        TRY(pd_contact_create(&b->contact, &pd->contact, b->dim, b->n, pd->spacing, b->delta,
                              pd_micromodulus(pd)));
    }
    if (b->cfg.frame == CPD_FRAME_SEMI_LAGRANGIAN) TRY(semi_lagrangian(b, comm != NULL));
    return NSPD_OK;
}

int cpd_body_create(CpdBody *b, CpdConfig *cfg) {
    int status = build(b, cfg, NULL);
    if (status != NSPD_OK) cpd_body_destroy(b);
    return status;
}

int cpd_body_create_divided(CpdBody *b, CpdConfig *cfg, const NspdComm *comm) {
    int status = build(b, cfg, comm_distributed(comm) ? comm : NULL);
    if (status != NSPD_OK) cpd_body_destroy(b);
    return status;
}

void cpd_body_destroy(CpdBody *b) {
    for (int d = 0; d < 3; d++) {
        nspd_free(&b->x[d]);
        nspd_free(&b->u[d]);
        nspd_free(&b->v[d]);
        nspd_free(&b->force[d]);
        nspd_free(&b->external[d]);
        nspd_free(&b->u_prev[d]);
        nspd_free(&b->load_dir[d]);
        nspd_free(&b->mode[d]);
        nspd_free(&b->lattice[d]);
    }
    nspd_free(&b->volume);
    nspd_free(&b->region);
    nspd_free(&b->load);
    pd_boundary_table_free(&b->boundary);
    pd_contact_free(&b->contact);
    nspd_free(&b->first);
    nspd_free(&b->nbr);
    nspd_free(&b->reverse);
    bac_pairs_free(&b->pairs);
    nspd_free(&b->inv_w0);
    nspd_free(&b->coef_c);
    nspd_free(&b->phi_rev);
    nspd_free(&b->phi_sum);
    nspd_free(&b->Fb);
    nspd_free(&b->omega);
    nspd_free(&b->phi);
    nspd_free(&b->ok);
    nspd_free(&b->redo);
    nspd_free(&b->dirty);
    nspd_free(&b->near);
    nspd_free(&b->sigma);
    nspd_free(&b->eqps);
    nspd_free(&b->damage);
    nspd_free(&b->scale);
    nspd_free(&b->principal);
    nspd_free(&b->inverted);
    nspd_free(&b->strain_zz);
    nspd_free(&b->work_point);
    nspd_free(&b->work_bond);
    cpd_halo_free(&b->halo);
    sl_work_free(&b->sl);
    nspd_free(&b->fit_norm0);
    cpd_config_free(&b->cfg);
    memset(b, 0, sizeof *b);
}
