#include "sim/probes.h"

#include "core/mem.h"
#include "core/status.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *const AXIS[] = {"x", "y", "z"};

/* The name of axis d ("x", "y", "z"). */
static const char *axis_name(int d) {
    return d >= 0 && d < 3 ? AXIS[d] : "?";
}

bool probes_need_damage(const OutputConfig *cfg) {
    for (int i = 0; i < cfg->probe_count; i++)
        if (cfg->probes[i].kind == PROBE_CRACK_TIP || cfg->probes[i].kind == PROBE_BRANCHES)
            return true;
    return false;
}

typedef struct {
    double key;
    int64_t point;
} Keyed;

static int compare_keyed(const void *a, const void *b) {
    double xa = ((const Keyed *)a)->key, xb = ((const Keyed *)b)->key;
    return (xa > xb) - (xa < xb);
}

/* Sorts the line members by their coordinate along the probe's axis. */
static int sort_members(ProbeState *p, const PdPoints *body) {
    Keyed *keyed;
    TRY(nspd_alloc(&keyed, (size_t)p->member_count, sizeof *keyed));
    for (int64_t m = 0; m < p->member_count; m++) {
        keyed[m].point = p->members[m];
        keyed[m].key = body->x[p->cfg->sort_axis][p->members[m]];
    }
    qsort(keyed, (size_t)p->member_count, sizeof *keyed, compare_keyed);
    for (int64_t m = 0; m < p->member_count; m++) p->members[m] = keyed[m].point;
    nspd_free(&keyed);
    return NSPD_OK;
}

static int setup_flow(ProbeState *p, Flow *flow) {
    const ProbeConfig *c = p->cfg;
    const FlowMesh mesh = flow_mesh(flow);
    /* a node cloud, or a flow whose field is defined between its cells
     * (B-splines): the solver prepares the point's interpolation */
    if (c->kind == PROBE_POINT && (mesh.kind != MESH_GRID || flow_has_point_probes(flow)))
        return flow_probe_add(flow, c->name, c->at[0], c->at[1], &p->point);
    /* a grid: the cell that holds the point, and a line's row or column through it */
    TRY(flow_cell_at(flow, c->name, c->at[0], c->at[1], &p->point));
    if (c->kind == PROBE_POINT) return NSPD_OK;
    return flow_grid_line(flow, c->name, p->point, c->sort_axis, &p->members, &p->member_count);
}

static int setup_one(ProbeState *p, const PdPoints *body, Flow *flow, int max_samples) {
    const ProbeConfig *c = p->cfg;
    if (c->kind != PROBE_CRACK_TIP && c->target == PROBE_ON_FLOW) {
        if (!flow)
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "probe '%s' is on the flow, but the case has "
                             "none; expected a flow section or a probe on the solid",
                             c->name);
        return setup_flow(p, flow);
    }
    if (!body)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "probe '%s' needs the solid, but the case has none; expected a solid "
                         "section or a probe on the flow",
                         c->name);
    if (c->kind == PROBE_POINT) {
        double best = INFINITY;
        for (int64_t i = 0; i < body->n; i++) {
            double d2 = 0;
            for (int d = 0; d < body->dim; d++) d2 += pow(body->x[d][i] - c->at[d], 2);
            if (d2 < best) {
                best = d2;
                p->point = i;
            }
        }
    } else if (c->kind == PROBE_LINE) {
        for (int pass = 0; pass < 2; pass++) {
            int64_t m = 0;
            for (int64_t i = 0; i < body->n; i++) {
                double x[3] = {body->x[0][i], body->x[1][i], body->x[2][i]};
                if (!shapeset_contains(&c->region, x)) continue;
                if (pass == 1) p->members[m] = i;
                m++;
            }
            if (pass == 0) {
                if (m == 0)
                    return NSPD_FAIL(NSPD_ERR_INPUT,
                                     "line probe '%s': its region holds no material point; "
                                     "expected a region that overlaps the body",
                                     c->name);
                TRY(nspd_alloc(&p->members, (size_t)m, sizeof(int64_t)));
                p->member_count = m;
            }
        }
        TRY(sort_members(p, body));
    } else if (c->kind == PROBE_BRANCHES) {
        p->t_first_branch = (double)NAN;
    } else {
        p->capacity = max_samples;
        TRY(nspd_alloc(&p->times, (size_t)max_samples, sizeof(double)));
        TRY(nspd_alloc(&p->along, (size_t)max_samples, sizeof(double)));
    }
    return NSPD_OK;
}

/* A line probe's table: its file name, header and column storage (filled
 * at each output, so nothing is allocated then). */
static int setup_table(ProbeState *p, const PdPoints *body) {
    const ProbeConfig *c = p->cfg;
    if (c->kind != PROBE_LINE) return NSPD_OK;
    TableRef *t = &p->table;
    snprintf(p->table_file, sizeof p->table_file, "line_%s", c->name);
    t->file = p->table_file;
    t->header = p->table_header;
    t->rows = p->member_count;
    if (c->target == PROBE_ON_FLOW) {
        snprintf(p->table_header, sizeof p->table_header,
                 "x_m,y_m,rho_kg_per_m3,u_m_per_s,v_m_per_s,p_Pa,T_K,mach");
        t->ncol = 8;
    } else {
        const int dim = body->dim;
        int len = 0;
        for (int d = 0; d < dim; d++)
            len += snprintf(p->table_header + len, sizeof p->table_header - (size_t)len, "%s%s_m",
                            d ? "," : "", axis_name(d));
        for (int d = 0; d < dim; d++)
            len += snprintf(p->table_header + len, sizeof p->table_header - (size_t)len, ",u%s_m",
                            axis_name(d));
        for (int d = 0; d < dim; d++)
            len += snprintf(p->table_header + len, sizeof p->table_header - (size_t)len,
                            ",v%s_m_per_s", axis_name(d));
        snprintf(p->table_header + len, sizeof p->table_header - (size_t)len, ",damage");
        t->ncol = 3 * dim + 1;
        t->short_cols = 1u << (3 * dim); /* damage: 6 digits */
    }
    TRY(nspd_alloc(&p->table_data, (size_t)(t->ncol * p->member_count), sizeof(double)));
    for (int k = 0; k < t->ncol; k++)
        t->col[k] = p->table_columns[k] = p->table_data + k * p->member_count;
    return NSPD_OK;
}

int probes_create(ProbeState **probes, const OutputConfig *cfg, const PdPoints *body, Flow *flow,
                  int max_samples) {
    *probes = NULL;
    if (cfg->probe_count == 0) return NSPD_OK;
    TRY(nspd_alloc(probes, (size_t)cfg->probe_count, sizeof(ProbeState)));
    for (int i = 0; i < cfg->probe_count; i++) {
        (*probes)[i].cfg = &cfg->probes[i];
        /* found on the built model: said at the probe's key */
        int status =
            nspd_error_at(setup_one(&(*probes)[i], body, flow, max_samples), cfg->probes[i].where);
        if (status == NSPD_OK) status = setup_table(&(*probes)[i], body);
        if (status != NSPD_OK) {
            probes_destroy(probes, cfg->probe_count);
            return status;
        }
    }
    return NSPD_OK;
}

void probes_destroy(ProbeState **probes, int count) {
    if (!*probes) return;
    for (int i = 0; i < count; i++) {
        nspd_free(&(*probes)[i].members);
        nspd_free(&(*probes)[i].times);
        nspd_free(&(*probes)[i].along);
        nspd_free(&(*probes)[i].table_data);
    }
    nspd_free(probes);
}

/* The damaged point furthest along the probe's direction; -1 if none. */
static int64_t crack_tip(const ProbeConfig *c, const PdPoints *body, const double *damage) {
    int64_t best = -1;
    double best_along = -(double)INFINITY;
    for (int64_t i = 0; i < body->n; i++) {
        if (!(damage[i] > c->damage_threshold)) continue;
        double x[3] = {body->x[0][i], body->x[1][i], body->x[2][i]};
        if (c->region.count && !shapeset_contains(&c->region, x)) continue;
        double along = 0;
        for (int d = 0; d < body->dim && d < 3; d++) along += x[d] * c->direction[d];
        if (along > best_along) {
            best_along = along;
            best = i;
        }
    }
    return best;
}

void probes_sample(ProbeState *probes, int count, const PdPoints *body, const double *damage,
                   const Flow *flow, double time, Report *row) {
    for (int k = 0; k < count; k++) {
        ProbeState *p = &probes[k];
        const ProbeConfig *c = p->cfg;
        if (c->kind == PROBE_CRACK_TIP) {
            int64_t tip = crack_tip(c, body, damage);
            double along = (double)NAN;
            for (int d = 0; d < body->dim; d++)
                p->last_tip[d] = tip >= 0 ? body->x[d][tip] : (double)NAN;
            if (tip >= 0) {
                along = 0;
                for (int d = 0; d < body->dim; d++) along += body->x[d][tip] * c->direction[d];
            }
            if (p->samples < p->capacity) {
                p->times[p->samples] = time;
                p->along[p->samples] = along;
                p->samples++;
            }
            for (int d = 0; d < body->dim; d++)
                report_realf(row, p->last_tip[d], "%s_tip_%s_m", c->name, axis_name(d));
        } else if (c->kind == PROBE_BRANCHES) {
            BranchResult r;
            if (probe_branches(c, body, damage, &r) != NSPD_OK) r.angle_deg = (double)NAN;
            if (c->extent > 0 && isnan(p->t_first_branch) && r.branched && r.span >= c->extent) {
                p->first_branch = r;
                p->t_first_branch = time;
            }
            report_realf(row, r.angle_deg, "%s_branch_angle_deg", c->name);
        } else if (c->kind == PROBE_POINT && c->target == PROBE_ON_FLOW) {
            static const char *const QUANTITY[5] = {"rho_kg_per_m3", "u_m_per_s", "v_m_per_s",
                                                    "p_Pa", "T_K"};
            double q[5];
            const bool grid = flow_mesh(flow).kind == MESH_GRID;
            if (grid && !flow_has_point_probes(flow))
                flow_cell_state(flow, p->point, q);
            else
                flow_probe_state(flow, p->point, q);
            /* a node cloud (incompressible) has u, v, p */
            for (int m = grid ? 0 : 1; m < (grid ? 5 : 4); m++)
                report_realf(row, q[m], "%s_%s", c->name, QUANTITY[m]);
        } else if (c->kind == PROBE_POINT) {
            double ux = body->u[0][p->point];
            if (p->samples++ == 0 || ux > p->dx_max) {
                p->dx_max = ux;
                p->t_dx_max = time;
            }
            for (int d = 0; d < body->dim; d++)
                report_realf(row, body->u[d][p->point], "%s_d%s_m", c->name, axis_name(d));
            for (int d = 0; d < body->dim; d++)
                report_realf(row, body->v[d][p->point], "%s_v%s_m_per_s", c->name, axis_name(d));
        }
    }
}

/* The cells of a flow line: coordinates and primitive values. */
static void flow_line(ProbeState *p, const Flow *flow) {
    const double gamma = flow_reference(flow).gamma;
    double *const *col = p->table_columns;
    for (int64_t m = 0; m < p->member_count; m++) {
        int64_t cell = p->members[m];
        double q[5], centre[2];
        flow_cell_state(flow, cell, q);
        flow_cell_centre(flow, cell, centre);
        col[0][m] = centre[0];
        col[1][m] = centre[1];
        for (int k = 0; k < 5; k++) col[2 + k][m] = q[k];
        col[7][m] = sqrt(q[1] * q[1] + q[2] * q[2]) / sqrt(gamma * q[3] / q[0]);
    }
}

/* The points of a solid line: reference position, displacement, velocity, damage. */
static void solid_line(ProbeState *p, const PdPoints *body, const double *damage) {
    double *const *col = p->table_columns;
    const int dim = body->dim;
    for (int64_t m = 0; m < p->member_count; m++) {
        int64_t i = p->members[m];
        for (int d = 0; d < dim; d++) {
            col[d][m] = body->x[d][i];
            col[dim + d][m] = body->u[d][i];
            col[2 * dim + d][m] = body->v[d][i];
        }
        col[3 * dim][m] = damage ? damage[i] : 0.0;
    }
}

const TableRef *probe_line_table(ProbeState *p, const PdPoints *body, const double *damage,
                                 const Flow *flow) {
    if (p->cfg->kind != PROBE_LINE) return NULL;
    if (p->cfg->target == PROBE_ON_FLOW)
        flow_line(p, flow);
    else
        solid_line(p, body, damage);
    return &p->table;
}

/* The samples the tip arrays hold (the first `capacity`). */
static int kept_samples(const ProbeState *p) {
    return p->samples < p->capacity ? p->samples : p->capacity;
}

/* The first sample with a damaged point in the probe's region, or -1. */
static int first_tip_sample(const ProbeState *p) {
    for (int s = 0; s < kept_samples(p); s++)
        if (!isnan(p->along[s])) return s;
    return -1;
}

double probe_crack_onset(const ProbeState *p) {
    const int first = first_tip_sample(p);
    return first < 0 ? (double)NAN : p->times[first];
}

double probe_crack_speed(const ProbeState *p) {
    const int first = first_tip_sample(p);
    if (first < 0) return NAN;
    const int last = kept_samples(p) - 1;
    double start = p->along[first], end = p->along[last];
    if (isnan(end) || end <= start) return 0.0;
    int s0 = first, s1 = last;
    while (s0 + 1 <= last && p->along[s0 + 1] == start) s0++;
    while (s1 > s0 && p->along[s1 - 1] == end) s1--;
    return (end - start) / (p->times[s1] - p->times[s0]);
}

/* ------------------------------------------------------------ branches */

typedef struct {
    int64_t bin;
    double n;
} BinnedPoint;

static int compare_binned(const void *a, const void *b) {
    const BinnedPoint *p = a, *q = b;
    if (p->bin != q->bin) return (p->bin > q->bin) - (p->bin < q->bin);
    return (p->n > q->n) - (p->n < q->n);
}

/* Least-squares line n = a + b s through (s[k], n[k]). */
static void fit_line(const double *s, const double *n, int count, double *a, double *b) {
    double ss = 0, sn = 0, s1 = 0, n1 = 0;
    for (int k = 0; k < count; k++) {
        s1 += s[k];
        n1 += n[k];
        ss += s[k] * s[k];
        sn += s[k] * n[k];
    }
    double det = count * ss - s1 * s1;
    *b = det != 0 ? (count * sn - s1 * n1) / det : 0.0;
    *a = (n1 - *b * s1) / count;
}

/* The crack-face points ahead of `at` (damage above the threshold, not
 * detached debris), binned by their distance s along `direction` in bins
 * of one spacing and sorted by bin, then by their offset n across. */
static int collect_points(const ProbeConfig *c, const PdPoints *body, const double *damage,
                          BinnedPoint **out, int64_t *count) {
    const double dx = body->spacing, *dir = c->direction, perp[2] = {-dir[1], dir[0]};
    BinnedPoint *pts;
    TRY(nspd_alloc(&pts, (size_t)body->n, sizeof *pts));
    int64_t m = 0;
    for (int64_t i = 0; i < body->n; i++) {
        /* crack faces, not detached debris (damage 1) */
        if (!(damage[i] > c->damage_threshold) || damage[i] >= 0.99) continue;
        double rx = body->x[0][i] - c->at[0], ry = body->x[1][i] - c->at[1];
        double s = rx * dir[0] + ry * dir[1];
        if (s <= 0 || (c->length > 0 && s > c->length)) continue;
        pts[m].bin = (int64_t)floor(s / dx);
        pts[m].n = rx * perp[0] + ry * perp[1];
        m++;
    }
    qsort(pts, (size_t)m, sizeof *pts, compare_binned);
    *out = pts;
    *count = m;
    return NSPD_OK;
}

/* Per bin: the number of clusters across (split where neighbours are more
 * than 2 dx apart), the bin's centre s and the centroids of its outermost
 * clusters (nl the first, nu the last). */
typedef struct {
    int64_t bins;
    double *s, *nu, *nl;
    int *clusters;
} BranchBins;

static void branch_bins_free(BranchBins *b) {
    nspd_free(&b->s);
    nspd_free(&b->nu);
    nspd_free(&b->nl);
    nspd_free(&b->clusters);
}

static int branch_bins(const BinnedPoint *pts, int64_t m, double dx, BranchBins *out) {
    memset(out, 0, sizeof *out);
    out->bins = m ? pts[m - 1].bin + 1 : 0;
    const size_t n = (size_t)out->bins + 1;
    int status = nspd_alloc(&out->s, n, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&out->nu, n, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&out->nl, n, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&out->clusters, n, sizeof(int));
    if (status != NSPD_OK) {
        branch_bins_free(out);
        return status;
    }
    for (int64_t lo = 0; lo < m;) {
        int64_t hi = lo;
        while (hi < m && pts[hi].bin == pts[lo].bin) hi++;
        int64_t b = pts[lo].bin;
        int count = 1;
        double first_sum = pts[lo].n, last_sum = 0;
        int64_t first_n = 1, last_n = 0, cluster_lo = lo;
        for (int64_t q = lo + 1; q < hi; q++) {
            if (pts[q].n - pts[q - 1].n > 2.0 * dx) {
                count++;
                cluster_lo = q;
            }
            if (count == 1) {
                first_sum += pts[q].n;
                first_n++;
            }
        }
        for (int64_t q = cluster_lo; q < hi; q++) {
            last_sum += pts[q].n;
            last_n++;
        }
        out->clusters[b] = count;
        out->s[b] = ((double)b + 0.5) * dx;
        out->nl[b] = first_sum / (double)first_n;
        out->nu[b] = last_sum / (double)last_n;
        lo = hi;
    }
    return NSPD_OK;
}

/* From the first of three successive bins with two or more clusters on,
 * lines fitted to the outermost clusters give the branches (fills *out). */
static int fit_branches(const ProbeConfig *c, const BranchBins *bb, double dx, BranchResult *out) {
    int64_t start = -1;
    for (int64_t b = 0; b + 2 < bb->bins && start < 0; b++)
        if (bb->clusters[b] >= 2 && bb->clusters[b + 1] >= 2 && bb->clusters[b + 2] >= 2) start = b;
    if (start < 0) return NSPD_OK;
    double *s_fit, *u_fit, *l_fit;
    int status = nspd_alloc(&s_fit, (size_t)bb->bins, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&u_fit, (size_t)bb->bins, sizeof(double));
    if (status == NSPD_OK) status = nspd_alloc(&l_fit, (size_t)bb->bins, sizeof(double));
    int count = 0;
    for (int64_t b = start; b < bb->bins && status == NSPD_OK; b++) {
        if (bb->clusters[b] < 2) continue;
        s_fit[count] = bb->s[b];
        u_fit[count] = bb->nu[b];
        l_fit[count] = bb->nl[b];
        count++;
    }
    if (status == NSPD_OK && count >= 3) {
        const double *dir = c->direction, perp[2] = {-dir[1], dir[0]};
        double au, bu, al, bl;
        fit_line(s_fit, u_fit, count, &au, &bu);
        fit_line(s_fit, l_fit, count, &al, &bl);
        out->branched = true;
        out->samples = count;
        out->span = count * dx;
        out->upper_deg = atan(bu) * 180.0 / M_PI;
        out->lower_deg = atan(bl) * 180.0 / M_PI;
        out->angle_deg = out->upper_deg - out->lower_deg;
        double s_meet = bu != bl ? (al - au) / (bu - bl) : 0.0, n_meet = au + bu * s_meet;
        out->point[0] = c->at[0] + s_meet * dir[0] + n_meet * perp[0];
        out->point[1] = c->at[1] + s_meet * dir[1] + n_meet * perp[1];
    }
    nspd_free(&s_fit);
    nspd_free(&u_fit);
    nspd_free(&l_fit);
    return status;
}

int probe_branches(const ProbeConfig *c, const PdPoints *body, const double *damage,
                   BranchResult *out) {
    memset(out, 0, sizeof *out);
    out->angle_deg = out->upper_deg = out->lower_deg = NAN;
    out->point[0] = out->point[1] = NAN;
    BinnedPoint *pts;
    int64_t m;
    TRY(collect_points(c, body, damage, &pts, &m));
    BranchBins bins;
    int status = branch_bins(pts, m, body->spacing, &bins);
    nspd_free(&pts);
    TRY(status);
    status = fit_branches(c, &bins, body->spacing, out);
    branch_bins_free(&bins);
    return status;
}

int probe_branch_report(const ProbeState *p, const PdPoints *body, const double *damage,
                        BranchResult *out, double *time) {
    if (!isnan(p->t_first_branch)) {
        *out = p->first_branch;
        *time = p->t_first_branch;
        return NSPD_OK;
    }
    *time = (double)NAN;
    if (p->cfg->extent > 0) { /* the branches never spanned `extent` */
        memset(out, 0, sizeof *out);
        out->angle_deg = out->upper_deg = out->lower_deg = (double)NAN;
        out->point[0] = out->point[1] = (double)NAN;
        return NSPD_OK;
    }
    return probe_branches(p->cfg, body, damage, out);
}

int probes_summary(ProbeState *probes, int count, const PdPoints *body, const double *damage,
                   Report *out) {
    for (int k = 0; k < count && body; k++) {
        const ProbeState *p = &probes[k];
        if (p->cfg->kind != PROBE_POINT || p->cfg->target != PROBE_ON_SOLID) continue;
        report_realf(out, p->dx_max, "%s_dx_max_m", p->cfg->name);
        report_realf(out, p->t_dx_max, "t_%s_dx_max_s", p->cfg->name);
    }
    /* branches: per probe, then the overall answer - the side that branched
     * (the first listed if both did) */
    BranchResult best = {0};
    const char *best_side = NULL;
    for (int k = 0; k < count && body; k++) {
        const ProbeState *p = &probes[k];
        if (p->cfg->kind != PROBE_BRANCHES) continue;
        BranchResult br;
        double t_branch;
        if (probe_branch_report(p, body, damage, &br, &t_branch) != NSPD_OK) continue;
        const char *name = p->cfg->name;
        report_realf(out, t_branch, "%s_branch_time_s", name);
        char key[REPORT_MAX_NAME];
        snprintf(key, sizeof key, "%s_branched", name);
        report_bool(out, key, br.branched);
        report_realf(out, br.angle_deg, "%s_branch_angle_deg", name);
        report_realf(out, br.upper_deg, "%s_branch_upper_deg", name);
        report_realf(out, br.lower_deg, "%s_branch_lower_deg", name);
        report_realf(out, br.point[0], "%s_branch_point_x_m", name);
        report_realf(out, br.point[1], "%s_branch_point_y_m", name);
        if (br.branched && !best_side) {
            best = br;
            best_side = name;
        }
    }
    if (best_side) {
        report_real(out, "branch_angle_deg", best.angle_deg);
        report_text(out, "branch_side", best_side);
    } else {
        for (int k = 0; k < count; k++)
            if (probes[k].cfg->kind == PROBE_BRANCHES) {
                report_real(out, "branch_angle_deg", (double)NAN);
                break;
            }
    }
    for (int k = 0; k < count; k++) {
        const ProbeState *p = &probes[k];
        if (p->cfg->kind != PROBE_CRACK_TIP) continue;
        for (int d = 0; d < (body ? body->dim : 0); d++)
            report_realf(out, p->last_tip[d], "%s_tip_%s_m", p->cfg->name, axis_name(d));
        report_realf(out, probe_crack_speed(p), "%s_speed_m_per_s", p->cfg->name);
        report_realf(out, probe_crack_onset(p), "%s_onset_s", p->cfg->name);
    }
    return NSPD_OK;
}

/* What the probes carry from sample to sample: the crack tip's history,
 * the largest displacement and the first branch measurement. */
int probes_checkpoint(ProbeState *probes, int count, Checkpoint *ck) {
    for (int k = 0; k < count; k++) {
        ProbeState *p = &probes[k];
        /* samples counts the point probes' samples too; the crack tip's
         * arrays hold the first `capacity` */
        TRY(checkpoint_io_int(ck, "probe.samples", &p->samples));
        if (p->samples < 0)
            return NSPD_FAIL(NSPD_ERR_INPUT, "checkpoint: %d probe samples", p->samples);
        const size_t kept = (size_t)(p->samples < p->capacity ? p->samples : p->capacity);
        TRY(checkpoint_io(ck, "probe.times", p->times, kept * sizeof(double)));
        TRY(checkpoint_io(ck, "probe.along", p->along, kept * sizeof(double)));
        TRY(checkpoint_io(ck, "probe.last_tip", p->last_tip, sizeof p->last_tip));
        TRY(checkpoint_io_double(ck, "probe.dx_max", &p->dx_max));
        TRY(checkpoint_io_double(ck, "probe.t_dx_max", &p->t_dx_max));
        TRY(checkpoint_io(ck, "probe.first_branch", &p->first_branch, sizeof p->first_branch));
        TRY(checkpoint_io_double(ck, "probe.t_first_branch", &p->t_first_branch));
    }
    return NSPD_OK;
}
