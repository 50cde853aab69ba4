/* Building a PD body from its configuration (paper 000 Sec. 3.2).
 *
 * Order of construction, each step depending on the previous:
 *  1. lattice points inside the geometry, Morton-ordered, by default centred
 *     in its bounding box so symmetric bodies get exactly symmetric points
 *     (lattice.c);
 *  2. point volumes (dx^dim, times the thickness in 2D), regions (and their
 *     flat table for the integrator), initial velocities;
 *  3. bonds within the horizon |xi| <= delta (core/neighbours.c). The family is the
 *     horizon itself, as in Madenci and Oterkus' code (28 neighbours in 2D and
 *     122 in 3D for delta = 3.015 dx); the partial-volume factor nu_ij then
 *     weighs the bonds whose neighbour cell the horizon cuts. Each row is
 *     put in offset order (stencil.h);
 *  4. surface correction factors on the intact body (corrections.c);
 *  5. bond coefficients k_ij = c beta_ij nu_ij V_j / |xi_ij|, stored as
 *     float32 relative to coef_scale = c V_ref / dx so that they are O(1);
 *     sign = breakable or not (failure switch and failure region, decided
 *     at the bond midpoint so both ends agree);
 *  6. pre-cracks: crossing bonds set to 0 (broken);
 *  7. the damage denominator sum_j nu_ij V_j over the initial family. */
#include "solid/bond/body.h"
#include "core/parallel.h"

#include "core/mem.h"
#include "core/status.h"
#include "core/neighbours.h"
#include "solid/bond/corrections.h"
#include "solid/bond/halo.h"
#include "solid/bond/stencil.h"
#include "solid/pd/lattice.h"
#include "solid/pd/precrack.h"

#include <math.h>
#include <string.h>

static int alloc_points(BondBody *body) {
    size_t n = (size_t)body->n;
    for (int d = 0; d < 3; d++) {
        TRY(nspd_alloc(&body->u[d], n, sizeof(double)));
        TRY(nspd_alloc(&body->v[d], n, sizeof(double)));
        TRY(nspd_alloc(&body->force[d], n, sizeof(double)));
        TRY(nspd_alloc(&body->external[d], n, sizeof(double)));
    }
    TRY(nspd_alloc(&body->volume, n, sizeof(double)));
    TRY(nspd_alloc(&body->region, n, sizeof(int16_t)));
    TRY(nspd_alloc(&body->initial_bond_volume, n, sizeof(double)));
    return NSPD_OK;
}

/* A bond's micromodulus over the first material's (c is linear in E): its
 * material's E, or two materials' in series, 2 E_i E_j / (E_i + E_j), over
 * E of the first. */
static double pair_stiffness(const BondBody *body, int64_t i, int64_t j) {
    const PdMaterial *m = body->cfg.materials;
    const double ei = m[body->material[i]].youngs_modulus, ej = m[body->material[j]].youngs_modulus;
    const double e = body->material[i] == body->material[j] ? ei : 2.0 * ei * ej / (ei + ej);
    return e / body->cfg.youngs_modulus;
}

/* Each point's material (the first whose region holds it; a region-less
 * last material takes the rest) and density. */
static int assign_materials(BondBody *body) {
    const PdConfig *cfg = &body->cfg;
    TRY(nspd_alloc(&body->material, (size_t)body->n, sizeof(uint8_t)));
    TRY(nspd_alloc(&body->density, (size_t)body->n, sizeof(double)));
    for (int64_t i = 0; i < body->n; i++) {
        const double p[3] = {body->x[0][i], body->x[1][i], body->x[2][i]};
        int k = 0;
        while (k < cfg->material_count - 1 && cfg->materials[k].region.count > 0 &&
               !shapeset_contains(&cfg->materials[k].region, p))
            k++;
        body->material[i] = (uint8_t)k;
        body->density[i] = cfg->materials[k].density;
    }
    return NSPD_OK;
}

/* Drops the bonds between points of two materials (the bodies they make
 * meet only through contact), keeping each row's order. */
static void drop_cross_bonds(BondBody *body) {
    int64_t kept = 0, start = 0;
    for (int64_t i = 0; i < body->n; i++) {
        const int64_t end = body->bond_first[i + 1];
        for (int64_t k = start; k < end; k++)
            if (body->material[body->bond_nbr[k]] == body->material[i])
                body->bond_nbr[kept++] = body->bond_nbr[k];
        start = end;
        body->bond_first[i + 1] = kept;
    }
}

/* Steps 5-7 above. `g` are the per-point surface factors (NULL: none). */
static void assign_coefficients(BondBody *body, double *const g[3]) {
    const PdConfig *cfg = &body->cfg;
    const int dim = body->dim;
    const double dx = body->spacing, horizon = body->horizon;
    const bool any_region = cfg->failure_region.count > 0;
#pragma omp parallel for schedule(static) if (body->n >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < body->n; i++) {
        double xi_pt[3] = {body->x[0][i], body->x[1][i], body->x[2][i]};
        double gi[3] = {1, 1, 1}, bond_volume = 0.0;
        if (g)
            for (int d = 0; d < dim; d++) gi[d] = g[d][i];
        for (int64_t b = body->bond_first[i]; b < body->bond_first[i + 1]; b++) {
            int32_t j = body->bond_nbr[b];
            double xj_pt[3] = {body->x[0][j], body->x[1][j], body->x[2][j]};
            double e[3] = {0, 0, 0}, len2 = 0.0;
            for (int d = 0; d < dim; d++) {
                e[d] = xj_pt[d] - xi_pt[d];
                len2 += e[d] * e[d];
            }
            double len = sqrt(len2);
            double nu = pd_volume_factor(len, horizon, dx, cfg->volume_correction);
            double beta = 1.0;
            if (g) {
                double n[3] = {e[0] / len, e[1] / len, e[2] / len}, gj[3] = {1, 1, 1};
                for (int d = 0; d < dim; d++) gj[d] = g[d][j];
                beta = pd_surface_beta(dim, n, gi, gj);
            }
            double k = body->micromodulus * beta * nu * body->volume[j] / len;
            if (body->material) k *= pair_stiffness(body, i, j);
            float coef = (float)(k / body->coef_scale);
            bool breakable = cfg->failure;
            if (breakable && any_region) {
                double mid[3] = {0.5 * (xi_pt[0] + xj_pt[0]), 0.5 * (xi_pt[1] + xj_pt[1]),
                                 0.5 * (xi_pt[2] + xj_pt[2])};
                breakable = shapeset_contains(&cfg->failure_region, mid);
            }
            for (int c = 0; c < cfg->precrack_count; c++)
                if (precrack_cuts(&cfg->precracks[c], dim, xi_pt, xj_pt)) coef = 0.0f;
            body->bond_coef[b] = breakable ? coef : -coef;
            bond_volume += nu * body->volume[j];
        }
        body->initial_bond_volume[i] = bond_volume;
    }
}

/* The bonds of the points this process will keep (the run [lo, hi) of
 * `part`, halo.h) and of their ghosts, whose surface factors the kept
 * points' bonds read; every other row empty. NULL part: every row. */
static int find_bonds(BondBody *body, const NspdComm *part) {
    const double *const *x = (const double *const *)body->x;
    if (!comm_distributed(part))
        return neighbours_find(body->n, body->dim, x, body->horizon, &body->bond_first,
                               &body->bond_nbr);
    const int64_t n = body->n, lo = n * part->rank / part->size;
    const int64_t hi = n * (part->rank + 1) / part->size;
    uint8_t *rows = NULL;
    TRY(nspd_alloc(&rows, (size_t)n, 1));
    for (int64_t i = lo; i < hi; i++) rows[i] = 1;
    int status = neighbours_find_rows(n, body->dim, x, body->horizon, rows, &body->bond_first,
                                      &body->bond_nbr);
    if (status == NSPD_OK) { /* the kept points' neighbours too, then all their rows */
        for (int64_t k = body->bond_first[lo]; k < body->bond_first[hi]; k++)
            rows[body->bond_nbr[k]] = 1;
        nspd_free(&body->bond_first);
        nspd_free(&body->bond_nbr);
        status = neighbours_find_rows(n, body->dim, x, body->horizon, rows, &body->bond_first,
                                      &body->bond_nbr);
    }
    nspd_free(&rows);
    return status;
}

static int build(BondBody *body, PdConfig *cfg, const NspdComm *part) {
    memset(body, 0, sizeof *body);
    body->cfg = *cfg;
    memset(cfg, 0, sizeof *cfg);
    cfg = &body->cfg;
    body->dim = cfg->dim;
    body->spacing = cfg->spacing;
    body->horizon = cfg->horizon_factor * cfg->spacing;
    body->micromodulus = pd_micromodulus(cfg);
    double s_c = cfg->critical_stretch;
    body->stretch_limit2 = (1.0 + s_c) * (1.0 + s_c);

    /* the force runs on the square lattice's view (stencil.h: bonds at
     * fixed lattice offsets) and every bond's coefficient takes one volume */
    if (cfg->lattice_kind != PD_LATTICE_SQUARE)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "the bond-based solid runs on the square lattice; expected "
                         "solid.lattice.kind: square, or formulation: correspondence for a "
                         "polar lattice");
    Lattice lat = {0};
    TRY(lattice_fill(&lat, &cfg->geometry, cfg->dim, cfg->spacing,
                     cfg->has_lattice_origin ? cfg->lattice_origin : NULL));
    body->n = lat.n;
    for (int d = 0; d < 3; d++) {
        body->x[d] = lat.x[d];
        body->lattice[d] = lat.index[d];
    }
    TRY(alloc_points(body));
    double v_ref = pow(cfg->spacing, cfg->dim) * (cfg->dim == 2 ? cfg->thickness : 1.0);
    for (int64_t i = 0; i < body->n; i++) body->volume[i] = v_ref;
    body->coef_scale = body->micromodulus * v_ref / cfg->spacing;
    pd_regions_assign(cfg, body->n, (const double *const *)body->x, body->region, body->v);
    TRY(pd_boundary_table_build(&body->boundary, cfg));

    if (cfg->material_count > 1) {
        if (comm_distributed(part))
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "solid.material: several materials run on one process; expected "
                             "one process, or one material");
        TRY(assign_materials(body));
    }
    TRY(find_bonds(body, part));
    if (body->material && !cfg->materials_bonded) drop_cross_bonds(body);
    bond_rows_in_offset_order(body);
    body->bond_count = body->bond_first[body->n];
    TRY(nspd_alloc(&body->bond_coef, (size_t)body->bond_count, sizeof(float)));

    if (cfg->surface_correction == PD_SURFACE_ENERGY) {
        double *g[3] = {NULL, NULL, NULL};
        int status = NSPD_OK;
        for (int d = 0; d < body->dim && status == NSPD_OK; d++)
            status = nspd_alloc(&g[d], (size_t)body->n, sizeof(double));
        const PdFamilies families = {
            cfg,           body->dim,        body->n,        {body->x[0], body->x[1], body->x[2]},
            body->volume,  body->bond_first, body->bond_nbr, body->micromodulus,
            body->horizon, body->spacing};
        if (status == NSPD_OK) status = pd_surface_factors(&families, g);
        if (status == NSPD_OK) assign_coefficients(body, g);
        for (int d = 0; d < 3; d++) nspd_free(&g[d]);
        TRY(status);
    } else {
        assign_coefficients(body, NULL);
    }
    if (cfg->contact.enabled) {
        body->has_contact = true;
        TRY(pd_contact_create(&body->contact, &cfg->contact, body->dim, body->n, body->spacing,
                              body->horizon, body->micromodulus));
    }
    return NSPD_OK;
}

/* The lattice view the force reads (stencil.h), for the part kept. */
static int create_view(BondBody *body) {
    return bond_stencil_create(body, &body->stencil);
}

int bond_body_create(BondBody *body, PdConfig *cfg) {
    int status = build(body, cfg, NULL);
    if (status == NSPD_OK) status = create_view(body);
    if (status != NSPD_OK) bond_body_destroy(body);
    return status;
}

int bond_body_create_divided(BondBody *body, PdConfig *cfg, const NspdComm *comm) {
    if (cfg->contact.enabled && comm_distributed(comm))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "solid.contact: contact runs on one process (a fragment's candidates "
                         "may leave a process's halo); expected one process, or no contact");
    int status = build(body, cfg, comm);
    if (status == NSPD_OK) status = bond_body_divide(body, comm);
    if (status == NSPD_OK) status = create_view(body);
    if (status != NSPD_OK) bond_body_destroy(body);
    return status;
}

double bond_bytes_per_bond(const BondBody *body) {
    const BondStencil *s = body->stencil;
    if (!s || body->bond_count == 0) return PD_BYTES_PER_BOND;
    int64_t blocks = 1;
    for (int64_t q = 0; q < s->chunks; q++) blocks += s->block[q] != 0;
    const double view = (double)s->chunks * s->offsets * sizeof(uint16_t) +
                        (double)s->chunks * sizeof(int32_t) +
                        (double)blocks * s->offsets * 8 * sizeof(float);
    return PD_BYTES_PER_BOND + view / (double)body->bond_count;
}

void bond_body_destroy(BondBody *body) {
    for (int d = 0; d < 3; d++) {
        nspd_free(&body->x[d]);
        nspd_free(&body->u[d]);
        nspd_free(&body->v[d]);
        nspd_free(&body->force[d]);
        nspd_free(&body->external[d]);
        nspd_free(&body->lattice[d]);
    }
    nspd_free(&body->volume);
    nspd_free(&body->region);
    pd_boundary_table_free(&body->boundary);
    nspd_free(&body->initial_bond_volume);
    nspd_free(&body->bond_first);
    nspd_free(&body->bond_nbr);
    nspd_free(&body->bond_coef);
    bond_stencil_free(&body->stencil);
    pd_contact_free(&body->contact);
    nspd_free(&body->material);
    nspd_free(&body->density);
    pd_config_free(&body->cfg);
    bond_halo_free(&body->halo);
    memset(body, 0, sizeof *body);
}
