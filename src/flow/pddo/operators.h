/* Peridynamic differential operators in 2D, second order (paper 002,
 * Sec. 3.1, Eqs. 10-19; notes/pddo.md 1.2).
 *
 * For node k with family H_k (xi = x_j - x_k, area A_j):
 *     w(xi)   = exp(-(2 |xi| / delta)^2)                         (Eq. 12j)
 *     P(xi)   = (xi1, xi2, xi1^2, xi2^2, xi1 xi2)^T
 *     A_k     = sum_j w P P^T A_j                               (Eq. 14b; its printed entry
 *                                                                (4,3) xi1 xi2^2 is a misprint
 *                                                                for xi1^2 xi2^2)
 *     a       = A_k^-1 b,  b = diag(1, 1, 2, 2, 1)              (Eqs. 13, 14a, 14c)
 *     g^pq(j) = w P^T a(:, pq)                                  (Eqs. 12a-e)
 *     f_,pq(k) = sum_j (f_j - f_k) g^pq(j) A_j                  (Eqs. 10a-e)
 * so the row weight c_kj = g^pq(j) A_j of each operator makes it exact for
 * every polynomial of degree <= 2 wherever A_k is well conditioned, on full
 * and truncated (one-sided) families alike. The Laplacian (Eqs. 17, 19,
 * 30) is the row g^20 + g^02; gradient and divergence (Eqs. 15, 16, 18) are
 * the rows g^10, g^01; the mixed derivative g^11 is built though the flow
 * scheme never uses it.
 *
 * Conditioning rule: A_k is built in coordinates scaled by delta (entries
 * from dx^2 to dx^4 otherwise) with areas over delta^2, scaled to a unit
 * diagonal and factorised by Cholesky (core/spd_small.h). A node is refused
 * (NSPD_ERR_INPUT, naming it) when a squared pivot falls to 1e-12 or the
 * 1-norm condition number of that equilibrated matrix exceeds
 * PDDO_COND_MAX: its family cannot carry a quadratic fit (fewer than five
 * neighbours, all on a line or a conic) and its weights would lose more
 * than half the digits of float64. Measured largest: 71.7 on a lattice
 * cloud with three fictitious layers (the outermost corner's quarter-disc
 * family of 10), 106 on a lattice jittered by 0.3 dx
 * (tests/unit/flow/pddo/test_operators.c).
 *
 * Plain arrays in, weights out: the operators know nothing of node kinds or
 * boundaries. Each node's row is computed from its own family only, so the
 * weights are the same bits at any thread count. */
#ifndef NSPD_FLOW_PDDO_OPERATORS_H
#define NSPD_FLOW_PDDO_OPERATORS_H

#include "flow/pddo/polar.h"

#include <stdbool.h>
#include <stdint.h>

typedef enum {
    PDDO_D_X = 0, /* d/dx   (g^10) */
    PDDO_D_Y,     /* d/dy   (g^01) */
    PDDO_LAP,     /* d2/dx2 + d2/dy2 (g^20 + g^02) */
    PDDO_D_XY,    /* d2/dxdy (g^11) */
    PDDO_OPS
} PddoOp;

#define PDDO_COND_MAX 1e8

/* The weights are stored in slices of PDDO_LANES consecutive nodes, each
 * slice's members row by row (row r holds member r of each of its nodes,
 * a node's members in its family's order, then padding: the node itself
 * with weight 0, which adds an exact zero), so that a slice's sums run
 * in SIMD lanes, one node a lane, each lane adding its node's members in
 * the family's order: the bits of the sum one node alone makes.
 *
 * Templates: on a uniform lattice most slices are alike. Their 8 nodes
 * have the same family in lattice offsets, so member r of lane l is node
 * s PDDO_LANES + l + off[r], and (with xi taken from the lattice indices,
 * PddoLattice) the same weights, bit for bit, in every lane and in every
 * such slice. Such a slice keeps no slots: it names its template, one
 * offset and one weight of each operator per row, and its sums broadcast
 * the row's weight across the lanes: the same products, so the same bits,
 * while the step streams no weights or neighbours there (docs/
 * PERFORMANCE.md: on the paper's cylinder most of the operators' bytes).
 *
 * Turned templates: on a polar patch's ring (polar.h) a node's family,
 * seen in its own frame (xi along the radius, eta along the ring), is the
 * same at every angle. A ring node whose members are all of its patch
 * takes its weights in that frame, from the exact polar offsets (g^10,
 * g^01, the Laplacian, g^11 and g^20 - g^02), and turns them by its angle
 * (c, s) whenever they are read:
 *     d/dx = c g^10 - s g^01,   d/dy = s g^10 + c g^01,
 *     d2/dxdy = (c s) (g^20 - g^02) + (c c - s s) g^11,
 * the Laplacian unturned. So 8 consecutive nodes of one ring share one
 * template as a lattice slice does, each lane turning the row's weights
 * by its own angle: the patch's slices stream no weights either. The
 * slices that cross a ring's end, or the angle's wrap within their
 * families, keep their own slots, turned once when built. */
enum { PDDO_LANES = 8 };

typedef struct {
    int64_t n;
    const int64_t *first; /* borrowed: the families the weights belong to (must outlive) */
    const int32_t *nbr;
    int64_t *slice_first; /* per slice of PDDO_LANES nodes, its first slot; the slots' count last */
    int32_t *slice_tpl;   /* per slice, its template, or -1: its own slots */
    int32_t *slot_nbr;    /* per slot, the member's node (padding: the slot's own node) */
    double *w[PDDO_OPS];  /* per slot: c_kj in 1/m (D_X, D_Y) or 1/m^2; padding 0 */
    int32_t templates;    /* template t: rows tpl_first[t] .. tpl_first[t + 1] */
    int64_t *tpl_first;
    int32_t *tpl_off;        /* per template row, the member's offset from the lane's node */
    double *tpl_w[PDDO_OPS]; /* per template row, the weight of every lane */
    uint8_t *tpl_turned;     /* per template: 1 when its weights are in the nodes' polar frame */
    double *tpl_dif;         /* per template row: g^20 - g^02 (turned templates; else 0) */
    double *turn_c, *turn_s; /* per node (padded to whole slices): its angle's cos and sin on a
                                polar patch whose weights are turned, else 1 and 0 */
    uint8_t *turned;         /* per node (padded): 1 when its weights are turned */
    double *dif;             /* while building: per slot, g^20 - g^02 of a turned node */
    int64_t templated;       /* slices that use a template */
    int64_t *cost_before;    /* per slice, the cost of the slices before it; the total last */
    int64_t own_lo, own_hi;  /* the slices this process computes (pddo_ops_share's range):
                                all of them, or its part on several processes (share.h) */
    double cond_max;         /* largest condition number met (the rule above) */
    int64_t cond_node;       /* where */
} PddoOps;

/* The nodes' lattice indices, so that xi between two lattice nodes is
 * taken from them, (i_j - i_k) dx, the same bits wherever the pair lies
 * (from the rounded coordinates x_j - x_k differs by an ulp from place
 * to place, and no two slices' weights would be the same bits), and the
 * polar patches, whose ring nodes take their weights in their own frame
 * (turned templates, above). */
typedef struct {
    const int32_t *i, *j; /* INT32_MIN: not a lattice node (a polar ring) */
    double dx;
    const PddoPolarPatch *patch; /* the polar patches (their nodes: polar.h), or NULL */
    int patches;
} PddoLattice;

/* The slot of member m of node k, in a slice that keeps its own slots. */
static inline int64_t pddo_ops_slot(const PddoOps *ops, int64_t k, int64_t m) {
    return ops->slice_first[k / PDDO_LANES] + (m - ops->first[k]) * PDDO_LANES + k % PDDO_LANES;
}

/* Template row r's weight of op turned by (c, s) (turned templates, above). */
static inline double pddo_ops_turned(const PddoOps *ops, PddoOp op, int64_t r, double c, double s) {
    const double *const *w = (const double *const *)ops->tpl_w;
    switch (op) {
    case PDDO_D_X:
        return c * w[PDDO_D_X][r] - s * w[PDDO_D_Y][r];
    case PDDO_D_Y:
        return s * w[PDDO_D_X][r] + c * w[PDDO_D_Y][r];
    case PDDO_D_XY:
        return (c * s) * ops->tpl_dif[r] + (c * c - s * s) * w[PDDO_D_XY][r];
    default:
        return w[op][r];
    }
}

/* The weight of member m of node k for operator op. */
static inline double pddo_ops_weight(const PddoOps *ops, PddoOp op, int64_t k, int64_t m) {
    const int32_t t = ops->slice_tpl[k / PDDO_LANES];
    if (t < 0) return ops->w[op][pddo_ops_slot(ops, k, m)];
    const int64_t r = ops->tpl_first[t] + (m - ops->first[k]);
    return ops->tpl_turned[t] ? pddo_ops_turned(ops, op, r, ops->turn_c[k], ops->turn_s[k])
                              : ops->tpl_w[op][r];
}

static inline int64_t pddo_ops_slices(const PddoOps *ops) {
    return (ops->n + PDDO_LANES - 1) / PDDO_LANES;
}

/* A row of a slice with its own slots costs this many rows of a
 * template's slice (it streams a neighbour and a weight per lane and
 * operator, where a template's row reads its weights from cache). */
enum { PDDO_OWN_ROW_COST = 3 };

/* Slices [*lo, *hi) of thread t of nt within the process's own slices
 * (own_lo .. own_hi, all of them on one process): contiguous ranges of
 * about equal cost (cost_before), so that the threads of a loop over slices finish
 * together: on the paper's cylinder the polar patch's slices, the last
 * third, kept their own slots before the turned templates, and equal
 * counts of slices left one thread waiting for the other (docs/
 * PERFORMANCE.md). Each slice is computed alone, so the bits do not
 * depend on the split. */
void pddo_ops_share(const PddoOps *ops, int t, int nt, int64_t *lo, int64_t *hi);

/* Slices [*lo, *hi) of part t of nt of all the slices, by the same rule:
 * the processes' own ranges (share.h), which their threads then share. */
void pddo_ops_cut(const PddoOps *ops, int t, int nt, int64_t *lo, int64_t *hi);

/* Builds the weights of the n nodes at (x, y) with areas `area` (only their
 * ratios matter) and families first/nbr (each node's neighbours, itself
 * excluded), horizon delta (m), or node k's own node_delta[k] where
 * node_delta is not NULL (a local horizon, polar.h); lattice: the nodes' lattice indices, or
 * NULL (xi from the coordinates only; no slice will match a template but
 * by chance). ops is zeroed or freed before. Fails with NSPD_ERR_INPUT for
 * a node breaking the conditioning rule, NSPD_ERR_NOMEM. */
int pddo_ops_build(PddoOps *ops, int64_t n, const double *x, const double *y, const double *area,
                   const int64_t *first, const int32_t *nbr, double delta, const double *node_delta,
                   const PddoLattice *lattice);

/* The conditioning rule of pddo_ops_build alone, with its refusal, and
 * ops->cond_max; no weights (`nspd check`: the per-member solves are most
 * of the build's time and cannot fail once the rule holds). */
int pddo_ops_check(PddoOps *ops, int64_t n, const double *x, const double *y, const double *area,
                   const int64_t *first, const int32_t *nbr, double delta,
                   const double *node_delta);

/* out[k] = sum_j c_kj (f_j - f_k) for operator op at every node (Eq. 10);
 * parallel, the same bits at any thread count. out must not alias f. */
void pddo_ops_apply(const PddoOps *ops, PddoOp op, const double *f, double *out);

/* The same at one node. */
double pddo_ops_at(const PddoOps *ops, PddoOp op, const double *f, int64_t k);

/* Up to PDDO_FUSED_MAX applications in one pass over the families:
 * out[o] = operator op[o] of field f[o], each the same bits as
 * pddo_ops_apply alone. The flow step applies six operators to the same
 * nodes; one pass reads each member's neighbour index once instead of six
 * times (docs/PERFORMANCE.md). No out[o] may alias any f. */
#define PDDO_FUSED_MAX 6
void pddo_ops_apply_many(const PddoOps *ops, int count, const PddoOp *op, const double *const *f,
                         double *const *out);

/* The same at one node: sum[o] for o < count. */
void pddo_ops_at_many(const PddoOps *ops, int count, const PddoOp *op, const double *const *f,
                      int64_t k, double *sum);

/* The same at the PDDO_LANES nodes of slice s, in SIMD lanes: sum[o
 * PDDO_LANES + l] for node s PDDO_LANES + l (lanes past the last node
 * hold nothing); the bits of pddo_ops_at_many at each node. */
void pddo_ops_slice_many(const PddoOps *ops, int count, const PddoOp *op, const double *const *f,
                         int64_t s, double *sum);

void pddo_ops_free(PddoOps *ops);

/* Interpolation at a point (xc, yc) that need not be a node (the flow's
 * probes): moving least squares with the operators' weight w(xi) and
 * moments, the basis (1, P(xi)) with xi = x_j - (xc, yc), so f(c) =
 * sum_j w_j f_j is the weighted least-squares quadratic's value at c and
 * exact for every polynomial of degree <= 2 (but not interpolating at the
 * nodes). Writes the `count` weights of the nodes nbr[] into w and
 * returns the condition number of the 6 x 6 shape matrix (the rule
 * above), INFINITY when it is singular (then w is not written). Pure:
 * thread safe, allocates nothing. */
double pddo_ops_interpolation(double xc, double yc, int64_t count, const int32_t *nbr,
                              const double *x, const double *y, const double *area, double delta,
                              double *w);

#endif
