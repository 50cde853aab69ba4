#include "solid/correspondence/bac_force.h"

#include "core/mem.h"
#include "core/parallel.h"
#include "core/status.h"
#include "solid/correspondence/rk_gradient.h"
#include "solid/correspondence/svk_kernel.h"

#include <math.h>
#include <stdbool.h>
#include <string.h>

/* Point i's L_i = sum_j (T_ij - T_ji) V_j; dim is a constant at each call
 * (inlined into the loop: an OpenMP region is outlined before inlining). */
static inline __attribute__((always_inline)) void
point_gather(const int dim, int64_t i, const int64_t *first, const int32_t *nbr,
             const int64_t *reverse, const double *volume, const double *T,
             double *const force[3]) {
    double L[3] = {0, 0, 0};
    for (int64_t k = first[i]; k < first[i + 1]; k++) {
        const double V = volume[nbr[k]];
        const int64_t r = reverse[k];
        for (int a = 0; a < dim; a++)
            L[a] += (T[(int64_t)dim * k + a] - T[(int64_t)dim * r + a]) * V;
    }
    for (int a = 0; a < dim; a++) force[a][i] = L[a];
}

void bac_gather(int dim, int64_t n, const int64_t *first, const int32_t *nbr,
                const int64_t *reverse, const double *volume, const double *T,
                double *const force[3]) {
    if (dim == 2) {
#pragma omp parallel for schedule(static) if (first[n] >= PARALLEL_MIN_ITEMS)
        for (int64_t i = 0; i < n; i++) point_gather(2, i, first, nbr, reverse, volume, T, force);
    } else {
#pragma omp parallel for schedule(static) if (first[n] >= PARALLEL_MIN_ITEMS)
        for (int64_t i = 0; i < n; i++) point_gather(3, i, first, nbr, reverse, volume, T, force);
    }
}

int64_t bac_reverse_bonds(int64_t n, const int64_t *first, const int32_t *nbr, int64_t *reverse) {
    int64_t missing = 0;
#pragma omp parallel for schedule(static) reduction(+ : missing) if (first[n] >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < n; i++)
        for (int64_t k = first[i]; k < first[i + 1]; k++) {
            const int32_t j = nbr[k];
            reverse[k] = -1;
            for (int64_t m = first[j]; m < first[j + 1]; m++)
                if (nbr[m] == (int32_t)i) {
                    reverse[k] = m;
                    break;
                }
            missing += reverse[k] < 0 ? 1 : 0;
        }
    return missing;
}

/* The canonical bonds in bond order, and each bond's pair; count only when
 * pair_bond is NULL. */
static int64_t pair_list(int64_t n, const int64_t *first, const int64_t *reverse,
                         int64_t *pair_bond, int32_t *pair_point, int32_t *pair_of) {
    int64_t count = 0;
    for (int64_t i = 0; i < n; i++)
        for (int64_t k = first[i]; k < first[i + 1]; k++) {
            if (reverse[k] >= 0 && reverse[k] < k) continue; /* the pair's other bond */
            if (pair_bond) {
                pair_bond[count] = k, pair_point[count] = (int32_t)i;
                pair_of[k] = (int32_t)count;
                if (reverse[k] >= 0) pair_of[reverse[k]] = (int32_t)count;
            }
            count++;
        }
    return count;
}

int bac_pairs_create(int64_t n, const int64_t *first, const int64_t *reverse, BacPairs *pairs) {
    pairs->count = pair_list(n, first, reverse, NULL, NULL, NULL);
    const size_t m = (size_t)(pairs->count > 0 ? pairs->count : 1);
    TRY(nspd_alloc(&pairs->bond, m, sizeof(int64_t)));
    TRY(nspd_alloc(&pairs->point, m, sizeof(int32_t)));
    if (pairs->count > INT32_MAX)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "%lld bond pairs: the correspondence solid numbers them in 32 bits "
                         "(at most %d); expected a smaller body or a coarser spacing",
                         (long long)pairs->count, INT32_MAX);
    TRY(nspd_alloc(&pairs->of, (size_t)(first[n] > 0 ? first[n] : 1), sizeof(int32_t)));
    pair_list(n, first, reverse, pairs->bond, pairs->point, pairs->of);
    return NSPD_OK;
}

void bac_pairs_free(BacPairs *pairs) {
    nspd_free(&pairs->bond);
    nspd_free(&pairs->point);
    nspd_free(&pairs->of);
    pairs->count = 0;
}

/* The bond's deformation gradient F_b = Fm + (Y - Fm xi) (x) xi / |xi|^2,
 * with g = xi / |xi|^2 (one division a bond, formed by the caller), of the
 * points' F (9 entries, row-major 3 x 3). In 2D only the in-plane entries
 * are formed (Fb[0], Fb[1], Fb[3], Fb[4]); the rest are not touched. */
static inline __attribute__((always_inline)) void
bond_gradient(int dim, const double *Fi, const double *Fj, const double xi[3], const double g[3],
              const double Y[3], double Fb[9]) {
    if (dim == 2) {
        const double m00 = 0.5 * (Fi[0] + Fj[0]), m01 = 0.5 * (Fi[1] + Fj[1]);
        const double m10 = 0.5 * (Fi[3] + Fj[3]), m11 = 0.5 * (Fi[4] + Fj[4]);
        const double r0 = Y[0] - m00 * xi[0] - m01 * xi[1];
        const double r1 = Y[1] - m10 * xi[0] - m11 * xi[1];
        Fb[0] = m00 + r0 * g[0], Fb[1] = m01 + r0 * g[1];
        Fb[3] = m10 + r1 * g[0], Fb[4] = m11 + r1 * g[1];
        return;
    }
    for (int q = 0; q < 9; q++) Fb[q] = 0.5 * (Fi[q] + Fj[q]);
    double r[3] = {0.0, 0.0, 0.0};
    for (int a = 0; a < dim; a++) {
        r[a] = Y[a];
        for (int b = 0; b < dim; b++) r[a] -= Fb[3 * a + b] * xi[b];
    }
    for (int a = 0; a < dim; a++)
        for (int b = 0; b < dim; b++) Fb[3 * a + b] += r[a] * g[b];
}

/* Bond k = (i -> j): xi, g = xi / |xi|^2 and Y = xi + u_j - u_i. */
static inline __attribute__((always_inline)) void bond_vectors(int dim, const BacSystem *s,
                                                               const double *const u[3], int64_t i,
                                                               int64_t j, double xi[3], double g[3],
                                                               double Y[3]) {
    double xx = 0.0;
    for (int a = 0; a < 3; a++) xi[a] = g[a] = Y[a] = 0.0;
    for (int a = 0; a < dim; a++) {
        xi[a] = s->x[a][j] - s->x[a][i];
        Y[a] = xi[a] + (u[a][j] - u[a][i]);
        xx += xi[a] * xi[a];
    }
    const double inv_xx = 1.0 / xx;
    for (int a = 0; a < dim; a++) g[a] = xi[a] * inv_xx;
}

/* Pair p's hyperelastic (SVK) P_b (component c at Pb[c np + p]); dim is a
 * constant at each call. */
static inline __attribute__((always_inline)) void pair_svk(const int dim, const BacSystem *s,
                                                           const double *const u[3],
                                                           const double *F, double *Pb, int64_t p) {
    const int64_t np = s->pairs.count, k = s->pairs.bond[p], i = s->pairs.point[p], j = s->nbr[k];
    if (s->bond_scale && s->bond_scale[k] == 0.0) { /* broken: no stress */
        for (int q = 0; q < dim * dim; q++) Pb[q * np + p] = 0.0;
        return;
    }
    double xi[3], g[3], Y[3], Fb[9] = {0}, P[9];
    bond_vectors(dim, s, u, i, j, xi, g, Y);
    bond_gradient(dim, F + 9 * i, F + 9 * j, xi, g, Y, Fb);
    svk_stress(dim, Fb, s->lambda, s->mu, P);
    for (int a = 0; a < dim; a++)
        for (int b = 0; b < dim; b++) Pb[(dim * a + b) * np + p] = P[3 * a + b];
}

/* Per pair, the hyperelastic (SVK) P_b. */
static void pairs_svk(const BacSystem *s, const double *const u[3], const double *F, double *Pb) {
    const int64_t np = s->pairs.count;
    if (s->dim == 2) {
#pragma omp parallel for schedule(static) if (np >= PARALLEL_MIN_ITEMS)
        for (int64_t p = 0; p < np; p++) pair_svk(2, s, u, F, Pb, p);
    } else {
#pragma omp parallel for schedule(static) if (np >= PARALLEL_MIN_ITEMS)
        for (int64_t p = 0; p < np; p++) pair_svk(3, s, u, F, Pb, p);
    }
}

/* Where pair_j2_2d stores pair p's answers: at index o of arrays of
 * stride n (component c of sigma and P_b at [c n + o]): the state itself
 * (o = p), or a block's scratch (pairs_plane_stress). */
typedef struct {
    int64_t n;
    double *Pb, *sigma, *eqps, *principal, *strain_zz, *todo;
    uint8_t *inverted;
} PairOut;

/* What the 2D J2 pass over pairs reads and writes, as plain arrays: a
 * local copy in each thread, so that the loop loads them once (through
 * BacSystem and BacState the compiler must reload them after every store). */
typedef struct {
    J2Material material;
    int64_t np;
    const int64_t *pair_bond;
    const int32_t *pair_point, *nbr;
    const double *x0, *x1, *u0, *u1, *up0, *up1, *F, *Fp, *bond_scale;
    double *Fb;    /* in, F_b at u_prev (if given); out (pair_j2_2d's Fb_out), F_b at u */
    PairOut state; /* the pairs' state and P_b (stride np), and todo */
} PairView;

static PairView pair_view(const BacSystem *s, const BacState *st, const double *const u[3],
                          const double *F, double *Pb, double *todo) {
    return (PairView){.material = *st->material,
                      .np = s->pairs.count,
                      .pair_bond = s->pairs.bond,
                      .pair_point = s->pairs.point,
                      .nbr = s->nbr,
                      .x0 = s->x[0],
                      .x1 = s->x[1],
                      .u0 = u[0],
                      .u1 = u[1],
                      .up0 = st->u_prev[0],
                      .up1 = st->u_prev[1],
                      .F = F,
                      .Fp = st->F_prev,
                      .Fb = st->Fb,
                      .bond_scale = s->bond_scale,
                      .state = {.n = s->pairs.count,
                                .Pb = Pb,
                                .sigma = st->sigma,
                                .eqps = st->eqps,
                                .principal = st->principal,
                                .strain_zz = st->strain_zz,
                                .todo = todo,
                                .inverted = st->inverted}};
}

/* Pair p's J2 step in 2D (j2_step_2d) from its F_b at the step's start
 * (given: v->Fb; else formed from the points' F at u_prev, v->Fp, as F_b
 * now is from v->F): its P_b and its state, component c at [c np + p]; F_b
 * now into Fb_out[c fb_n + fb_o] unless Fb_out is NULL. plane_stress,
 * scaled, newton, given and whether Fb_out is NULL are constants at each
 * call. scaled says whether v->bond_scale exists (the SIMD loops can
 * not test a pointer before each load). newton > 0 (plane stress in SIMD
 * lanes): at most that many Newton iterations (j2_step_2d_lane), P_b
 * without the thickness stretch, the state stored only if they were
 * enough, and todo[p] says what finish_plane_stress has left to do: 0
 * nothing, 1 the stretch, 2 the whole pair again on the scalar path. */
static inline __attribute__((always_inline)) void
pair_j2_2d(const PairView *v, int64_t p, const int plane_stress, const int scaled, const int newton,
           const int given, const PairOut *out, int64_t o, double *Fb_out, int64_t fb_n,
           int64_t fb_o) {
    /* vectorised x2: tests/unit/core/vectorised.sh (plane strain, F_b given or formed) */
    const int64_t np = v->np, k = v->pair_bond[p], i = v->pair_point[p], j = v->nbr[k];
    const double xi[3] = {v->x0[j] - v->x0[i], v->x1[j] - v->x1[i], 0.0};
    const double Y[3] = {xi[0] + (v->u0[j] - v->u0[i]), xi[1] + (v->u1[j] - v->u1[i]), 0.0};
    const double inv_xx = 1.0 / (0.0 + xi[0] * xi[0] + xi[1] * xi[1]);
    const double g[3] = {xi[0] * inv_xx, xi[1] * inv_xx, 0.0};
    /* the points' in-plane F entries, indexed from the array's start (a
     * gather's offset must be one index times the element size) */
    const int64_t fi = 9 * i, fj = 9 * j;
    const double Fi[5] = {v->F[fi], v->F[fi + 1], 0.0, v->F[fi + 3], v->F[fi + 4]};
    const double Fj[5] = {v->F[fj], v->F[fj + 1], 0.0, v->F[fj + 3], v->F[fj + 4]};
    double Fb[9];
    bond_gradient(2, Fi, Fj, xi, g, Y, Fb);
    const double F2[4] = {Fb[0], Fb[1], Fb[3], Fb[4]};
    double Fp2[4];
    if (given) {
        for (int q = 0; q < 4; q++) Fp2[q] = v->Fb[q * np + p];
    } else {
        const double Yp[3] = {xi[0] + (v->up0[j] - v->up0[i]), xi[1] + (v->up1[j] - v->up1[i]),
                              0.0};
        const double Fpi[5] = {v->Fp[fi], v->Fp[fi + 1], 0.0, v->Fp[fi + 3], v->Fp[fi + 4]};
        const double Fpj[5] = {v->Fp[fj], v->Fp[fj + 1], 0.0, v->Fp[fj + 3], v->Fp[fj + 4]};
        double Fbp[9];
        bond_gradient(2, Fpi, Fpj, xi, g, Yp, Fbp);
        Fp2[0] = Fbp[0], Fp2[1] = Fbp[1], Fp2[2] = Fbp[3], Fp2[3] = Fbp[4];
    }
    if (Fb_out)
        for (int q = 0; q < 4; q++) Fb_out[q * fb_n + fb_o] = F2[q];
    const PairOut *old = &v->state;
    double sigma[4], eqps = old->eqps[p], zz = plane_stress ? old->strain_zz[p] : 0.0, P[4],
                     principal;
    for (int q = 0; q < 4; q++) sigma[q] = old->sigma[q * np + p];
    double finished = 1.0;
    const int inverted = newton > 0 ? j2_step_2d_lane(&v->material, plane_stress, newton, F2, Fp2,
                                                      sigma, &eqps, &zz, P, &principal, &finished)
                                    : j2_step_2d(&v->material, plane_stress, F2, Fp2, sigma, &eqps,
                                                 &zz, P, &principal);
    /* a broken pair keeps its state, and its P_b is 0 (the sums over
     * bonds weigh it by c = 0: a finite 0 keeps them finite) */
    const int64_t no = out->n;
    const int live = !scaled || v->bond_scale[k] != 0.0;
    for (int q = 0; q < 4; q++) out->Pb[q * no + o] = live ? P[q] : 0.0;
    if (newton > 0) out->todo[o] = finished == 0.0 ? 2.0 : live && !inverted ? 1.0 : 0.0;
    if (live && finished != 0.0) {
        for (int q = 0; q < 4; q++) out->sigma[q * no + o] = sigma[q];
        out->eqps[o] = eqps, out->principal[o] = principal, out->inverted[o] = (uint8_t)inverted;
        if (plane_stress) out->strain_zz[o] = zz;
    }
}

/* Plane stress in SIMD lanes, block by block of BAC_BLOCK pairs: first
 * every pair with BAC_LANE_NEWTON Newton iterations (an elastic pair needs
 * one), then the pairs that needed more, gathered into a list, with
 * BAC_LANE_NEWTON_MORE (a yielding pair needs two to four) into a scratch
 * of the block (contiguous: GCC 12 has no masked scatter) and copied out;
 * the few still unfinished, and the thickness stretch exp() (libm's bits:
 * no SIMD exp gives them), on the scalar path. Measured on the coarse
 * blast_hollow_square (one thread, solid_s): 15.3 s all scalar; 12.4, 12.9
 * and 13.6 s with 1, 2 and 3 iterations in one SIMD pass and the rest
 * scalar; with the second pass of 3, 4 and 6 iterations 12.0, 8.6 and
 * 9.1 s. */
enum { BAC_LANE_NEWTON = 1, BAC_LANE_NEWTON_MORE = 4, BAC_BLOCK = 256 };

/* The pairs [p0, p1) in plane stress, as above. (GCC names the SIMD loops
 * by the lines of their calls, which are marked for
 * tests/unit/core/vectorised.sh.) */
static inline __attribute__((always_inline)) void pairs_plane_stress(const PairView *v, int64_t p0,
                                                                     int64_t p1, const int given) {
    const PairOut *state = &v->state;
    double Pb[4 * BAC_BLOCK], sigma[4 * BAC_BLOCK], eqps[BAC_BLOCK], principal[BAC_BLOCK],
        zz[BAC_BLOCK], todo[BAC_BLOCK], Fb[4 * BAC_BLOCK];
    uint8_t inverted[BAC_BLOCK];
    int64_t list[BAC_BLOCK];
    const PairOut scratch = {.n = BAC_BLOCK,
                             .Pb = Pb,
                             .sigma = sigma,
                             .eqps = eqps,
                             .principal = principal,
                             .strain_zz = zz,
                             .todo = todo,
                             .inverted = inverted};
#pragma omp simd
    for (int64_t p = p0; p < p1; p++) /* vectorised x2: tests/unit/core/vectorised.sh */
        pair_j2_2d(v, p, 1, 1, BAC_LANE_NEWTON, given, state, p, Fb, BAC_BLOCK, p - p0);
    int64_t m = 0;
    for (int64_t p = p0; p < p1; p++)
        if (state->todo[p] == 2.0) list[m++] = p;
#pragma omp simd
    for (int64_t q = 0; q < m; q++) /* vectorised x2: tests/unit/core/vectorised.sh */
        pair_j2_2d(v, list[q], 1, 1, BAC_LANE_NEWTON_MORE, given, &scratch, q, NULL, 0, 0);
    for (int64_t q = 0; q < m; q++) {
        const int64_t p = list[q];
        if (todo[q] == 2.0) continue; /* still unfinished: the scalar path */
        state->todo[p] = todo[q];
        for (int c = 0; c < 4; c++) state->Pb[c * v->np + p] = Pb[c * BAC_BLOCK + q];
        if (v->bond_scale[v->pair_bond[p]] == 0.0) continue; /* broken: the state stays */
        for (int c = 0; c < 4; c++) state->sigma[c * v->np + p] = sigma[c * BAC_BLOCK + q];
        state->eqps[p] = eqps[q], state->principal[p] = principal[q];
        state->inverted[p] = inverted[q], state->strain_zz[p] = zz[q];
    }
    for (int64_t p = p0; p < p1; p++) {
        if (state->todo[p] == 1.0) {
            const double thick = exp(state->strain_zz[p]);
            for (int c = 0; c < 4; c++) state->Pb[c * v->np + p] *= thick;
        } else if (state->todo[p] == 2.0) {
            pair_j2_2d(v, p, 1, 1, 0, given, state, p, NULL, 0, 0);
        }
    }
    /* F_b now, kept apart until every pass of the block had read F_b at the
     * step's start */
    for (int c = 0; c < 4; c++)
        for (int64_t p = p0; p < p1; p++) v->Fb[c * v->np + p] = Fb[c * BAC_BLOCK + p - p0];
}

/* Per pair, the J2 P_b and state update (2D), in SIMD lanes across pairs
 * (each pair's arithmetic is its own, so the lanes give the scalar bits);
 * plane stress block by block (pairs_plane_stress). A system without
 * bond_scale (the body always has one) takes the scalar path. todo: a
 * double per pair of scratch. */
static void pairs_j2_2d(const BacSystem *s, const BacState *st, const double *const u[3],
                        const double *F, double *Pb, double *todo) {
    const int64_t np = s->pairs.count;
    const int plane_stress = st->material->plane_stress, scaled = s->bond_scale != NULL,
              given = st->fb_given;
#pragma omp parallel if (np >= PARALLEL_MIN_ITEMS)
    {
        const PairView v = pair_view(s, st, u, F, Pb, todo);
        if (!scaled) {
#pragma omp for schedule(static)
            for (int64_t p = 0; p < np; p++)
                pair_j2_2d(&v, p, plane_stress, 0, 0, given, &v.state, p, v.Fb, np, p);
        } else if (plane_stress) {
#pragma omp for schedule(static)
            for (int64_t b = 0; b < np; b += BAC_BLOCK) {
                const int64_t e = b + BAC_BLOCK < np ? b + BAC_BLOCK : np;
                if (given)
                    pairs_plane_stress(&v, b, e, 1);
                else
                    pairs_plane_stress(&v, b, e, 0);
            }
        } else if (given) {
#pragma omp for simd schedule(simd : static)
            for (int64_t p = 0; p < np; p++)
                pair_j2_2d(&v, p, 0, 1, 0, 1, &v.state, p, v.Fb, np, p);
        } else {
#pragma omp for simd schedule(simd : static)
            for (int64_t p = 0; p < np; p++)
                pair_j2_2d(&v, p, 0, 1, 0, 0, &v.state, p, v.Fb, np, p);
        }
    }
}

/* Point i's stress integral S_i = sum_k c_k P_b(ik) (I - xi (x) g) (dim^2
 * at S[dim^2 i ..], row-major) and its direct force D_i = 2 sum_k c_k
 * P_b(ik) g (dim at D[dim i ..]), g = xi / |xi|^2, c_k = c[k]. dim is a
 * constant at each call (inlined into the loop, not around it: an OpenMP
 * region is outlined before inlining, with dim a variable again). */
static inline __attribute__((always_inline)) void point_integrals(const int dim, const BacSystem *s,
                                                                  const double *c, const double *Pb,
                                                                  double *S, double *D, int64_t i) {
    const int64_t np = s->pairs.count;
    double Si[9] = {0}, Di[3] = {0};
    for (int64_t k = s->first[i]; k < s->first[i + 1]; k++) {
        const double ck = c[k]; /* 0 for a broken bond, whose P_b is 0 */
        const int32_t j = s->nbr[k];
        double xi[3] = {0, 0, 0}, xx = 0.0, g[3] = {0, 0, 0}, P[9];
        for (int a = 0; a < dim; a++) {
            xi[a] = s->x[a][j] - s->x[a][i];
            xx += xi[a] * xi[a];
        }
        const double inv_xx = 1.0 / xx; /* one division a bond: g = xi / |xi|^2 */
        for (int a = 0; a < dim; a++) g[a] = xi[a] * inv_xx;
        const int64_t pk = s->pairs.of[k];
        for (int q = 0; q < dim * dim; q++) P[q] = Pb[q * np + pk];
        for (int a = 0; a < dim; a++) {
            double Pxi = 0.0;
            for (int b = 0; b < dim; b++) Pxi += P[dim * a + b] * xi[b];
            for (int b = 0; b < dim; b++) Si[dim * a + b] += ck * (P[dim * a + b] - Pxi * g[b]);
            Di[a] += ck * (Pxi * inv_xx);
        }
    }
    for (int q = 0; q < dim * dim; q++) S[(int64_t)dim * dim * i + q] = Si[q];
    for (int a = 0; a < dim; a++) D[(int64_t)dim * i + a] = 2.0 * Di[a];
}

/* point_integrals in 2D with the bonds in SIMD lanes (the sums' order is
 * the lanes', fixed by the build: the same bits at any thread count). */
static inline __attribute__((always_inline)) void point_integrals_2d(const BacSystem *s,
                                                                     const double *c,
                                                                     const double *Pb, double *S,
                                                                     double *D, int64_t i) {
    const int64_t np = s->pairs.count;
    const int32_t *of = s->pairs.of;
    const int32_t *nbr = s->nbr;
    const double *x0 = s->x[0], *x1 = s->x[1], *P0 = Pb, *P1 = Pb + np, *P2 = Pb + 2 * np,
                 *P3 = Pb + 3 * np, xi0 = x0[i], xi1 = x1[i];
    double s00 = 0.0, s01 = 0.0, s10 = 0.0, s11 = 0.0, d0 = 0.0, d1 = 0.0;
#pragma omp simd reduction(+ : s00, s01, s10, s11, d0, d1)
    for (int64_t k = s->first[i]; k < s->first[i + 1]; k++) {
        /* vectorised x1: tests/unit/core/vectorised.sh */
        const int32_t j = nbr[k];
        const double e0 = x0[j] - xi0, e1 = x1[j] - xi1, ck = c[k];
        const double inv_xx = 1.0 / (e0 * e0 + e1 * e1), g0 = e0 * inv_xx, g1 = e1 * inv_xx;
        const int64_t p = of[k];
        const double p0 = P0[p], p1 = P1[p], p2 = P2[p], p3 = P3[p];
        const double a0 = p0 * e0 + p1 * e1, a1 = p2 * e0 + p3 * e1; /* P_b xi */
        s00 += ck * (p0 - a0 * g0);
        s01 += ck * (p1 - a0 * g1);
        s10 += ck * (p2 - a1 * g0);
        s11 += ck * (p3 - a1 * g1);
        d0 += ck * (a0 * inv_xx);
        d1 += ck * (a1 * inv_xx);
    }
    S[4 * i] = s00, S[4 * i + 1] = s01, S[4 * i + 2] = s10, S[4 * i + 3] = s11;
    D[2 * i] = 2.0 * d0, D[2 * i + 1] = 2.0 * d1;
}

static void stress_integrals(const BacSystem *s, const double *c, const double *Pb, double *S,
                             double *D) {
    if (s->dim == 2) {
#pragma omp parallel for schedule(static) if (s->first[s->n] >= PARALLEL_MIN_ITEMS)
        for (int64_t i = 0; i < s->n; i++) point_integrals_2d(s, c, Pb, S, D, i);
    } else {
#pragma omp parallel for schedule(static) if (s->first[s->n] >= PARALLEL_MIN_ITEMS)
        for (int64_t i = 0; i < s->n; i++) point_integrals(3, s, c, Pb, S, D, i);
    }
}

/* Point i's force L_i = D_i + S_i sum_j phi_ij V_j - sum_j S_j phi_ji V_j:
 * the stress integrals S_j gathered per neighbour (dim^2 doubles a point,
 * near in Morton order) with the kept phi_rev. dim is a constant at each
 * call. */
static inline __attribute__((always_inline)) void
point_force(const int dim, const BacSystem *s, const double *phi_rev, const double *phi_sum,
            const double *S, const double *D, double *const force[3], int64_t i) {
    const int dd = dim * dim;
    double L[3] = {0, 0, 0};
    for (int a = 0; a < dim; a++) {
        L[a] = D[(int64_t)dim * i + a];
        for (int b = 0; b < dim; b++)
            L[a] += S[(int64_t)dd * i + dim * a + b] * phi_sum[(int64_t)dim * i + b];
    }
    for (int64_t k = s->first[i]; k < s->first[i + 1]; k++) {
        const double *Sj = S + (int64_t)dd * s->nbr[k], *w = phi_rev + (int64_t)dim * k;
        for (int a = 0; a < dim; a++)
            for (int b = 0; b < dim; b++) L[a] -= Sj[dim * a + b] * w[b];
    }
    for (int a = 0; a < dim; a++) force[a][i] = L[a];
}

/* point_force in 2D: per bond, S_j (4 contiguous doubles) times (w0, w1,
 * w0, w1) added into four scalar sums, a0 and a1 their pairs. Scalar on
 * purpose: four loads of S_j a bond measured faster than the four 4-lane
 * gathers of the bonds in SIMD lanes (bench cpd 3.6e7 against 3.5e7). */
static inline __attribute__((always_inline)) void
point_force_2d(const BacSystem *s, const double *phi_rev, const double *phi_sum, const double *S,
               const double *D, double *const force[3], int64_t i) {
    const int32_t *nbr = s->nbr;
    double a00 = 0.0, a01 = 0.0, a10 = 0.0, a11 = 0.0;
    for (int64_t k = s->first[i]; k < s->first[i + 1]; k++) {
        const double *Sj = S + 4 * (int64_t)nbr[k]; /* row-major 2 x 2 */
        const double w0 = phi_rev[2 * k], w1 = phi_rev[2 * k + 1];
        a00 += Sj[0] * w0;
        a01 += Sj[1] * w1;
        a10 += Sj[2] * w0;
        a11 += Sj[3] * w1;
    }
    const double *Si = S + 4 * i, *sum = phi_sum + 2 * i;
    force[0][i] = D[2 * i] + Si[0] * sum[0] + Si[1] * sum[1] - (a00 + a01);
    force[1][i] = D[2 * i + 1] + Si[2] * sum[0] + Si[3] * sum[1] - (a10 + a11);
}

static void point_forces(const BacSystem *s, const double *phi_rev, const double *phi_sum,
                         const double *S, const double *D, double *const force[3]) {
    if (s->dim == 2) {
#pragma omp parallel for schedule(static) if (s->first[s->n] >= PARALLEL_MIN_ITEMS)
        for (int64_t i = 0; i < s->n; i++) point_force_2d(s, phi_rev, phi_sum, S, D, force, i);
    } else {
#pragma omp parallel for schedule(static) if (s->first[s->n] >= PARALLEL_MIN_ITEMS)
        for (int64_t i = 0; i < s->n; i++) point_force(3, s, phi_rev, phi_sum, S, D, force, i);
    }
}

void bac_coefficients(const BacSystem *s, const double *inv_w0, const uint8_t *only, double *c,
                      double *phi_rev, double *phi_sum) {
    const int dim = s->dim;
    /* dynamic: a mask is sparse and uneven; each point's values are its own */
#pragma omp parallel for schedule(dynamic, 256) if (s->first[s->n] >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < s->n; i++) {
        if (only && !only[i]) continue;
        double sum[3] = {0, 0, 0};
        for (int64_t k = s->first[i]; k < s->first[i + 1]; k++) {
            const int32_t j = s->nbr[k];
            const int64_t r = s->reverse[k];
            const double V = s->volume[j];
            const double omega = s->omega[k] * (s->bond_scale ? s->bond_scale[k] : 1.0);
            c[k] = omega * (0.5 * inv_w0[i] + 0.5 * inv_w0[j]) * V;
            for (int a = 0; a < dim; a++) {
                phi_rev[(int64_t)dim * k + a] = r >= 0 ? s->phi[(int64_t)dim * r + a] * V : 0.0;
                sum[a] += s->phi[(int64_t)dim * k + a] * V;
            }
        }
        for (int a = 0; a < dim; a++) phi_sum[(int64_t)dim * i + a] = sum[a];
    }
}

void bac_inverse_weights(const BacSystem *s, const uint8_t *only, double *inv_w0) {
#pragma omp parallel for schedule(dynamic, 256) if (s->first[s->n] >= PARALLEL_MIN_ITEMS)
    for (int64_t i = 0; i < s->n; i++) {
        if (only && !only[i]) continue;
        double w = 0.0;
        for (int64_t k = s->first[i]; k < s->first[i + 1]; k++)
            w += s->omega[k] * (s->bond_scale ? s->bond_scale[k] : 1.0) * s->volume[s->nbr[k]];
        inv_w0[i] = w > 0.0 ? 1.0 / w : 0.0;
    }
}

void bac_force(const BacSystem *s, BacState *st, const double *const u[3], double *const force[3],
               double *F, double *work_point, double *work_bond) {
    const int dim = s->dim;
    const int64_t n = s->n, nb = s->first[n], np = s->pairs.count, na = s->n_all ? s->n_all : n;
    double *inv_w0 = work_point, *S = work_point + na, *D = S + (int64_t)dim * dim * na,
           *Pb = work_bond;
    /* the plane-stress flags after P_b (where bac_work_bond counts them) */
    double *todo = st && st->material->plane_stress ? Pb + (int64_t)dim * dim * np : NULL;
    /* F at u_prev per point only when the pairs' F_b at u_prev must be formed */
    const bool form_fb = st && !st->fb_given;
    rk_deformation_gradient(dim, n, u, form_fb ? st->u_prev : NULL, s->volume, s->first, s->nbr,
                            s->phi, F, form_fb ? st->F_prev : NULL);
    if (s->exchange) { /* the pairs that cross read their ghost's F */
        s->exchange(s->exchange_context, F, 9);
        if (form_fb) s->exchange(s->exchange_context, st->F_prev, 9);
    }
    /* what only the damage changes, unless the caller keeps it */
    const double *c = s->c, *phi_rev = s->phi_rev, *phi_sum = s->phi_sum;
    if (!c) {
        const double *iw = s->inv_w0;
        if (!iw) {
            bac_inverse_weights(s, NULL, inv_w0);
            iw = inv_w0;
        }
        double *cw = Pb + (int64_t)(dim * dim + 1) * np, *rw = cw + nb, *sw = D + (int64_t)dim * n;
        bac_coefficients(s, iw, NULL, cw, rw, sw);
        c = cw, phi_rev = rw, phi_sum = sw;
    }
    /* per pair, from its canonical (lower-numbered) bond: F_b(ij) = F_b(ji)
     * bit for bit, so the pair's stress (and its state update) is computed
     * once, for both bonds */
    if (st)
        pairs_j2_2d(s, st, u, F, Pb, todo);
    else
        pairs_svk(s, u, F, Pb);
    bac_stress_force(s, c, phi_rev, phi_sum, Pb, force, work_point);
}

void bac_stress_force(const BacSystem *s, const double *c, const double *phi_rev,
                      const double *phi_sum, const double *Pb, double *const force[3],
                      double *work_point) {
    const int dim = s->dim;
    const int64_t na = s->n_all ? s->n_all : s->n;
    double *S = work_point + na, *D = S + (int64_t)dim * dim * na;
    stress_integrals(s, c, Pb, S, D);
    if (s->exchange) s->exchange(s->exchange_context, S, dim * dim); /* the gather reads S_j */
    point_forces(s, phi_rev, phi_sum, S, D, force);
}
