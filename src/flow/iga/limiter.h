/* Convex limiting of the isogeometric flow's step (docs/IGA_LIMITER.md):
 * a low-order invariant-domain-preserving update of the conservative
 * control values, the graph-viscosity scheme of Guermond & Popov (SIAM J.
 * Numer. Anal. 54, 2016) on the B-spline space, blended per control point
 * with the high-order SUPG/DC step as far as local bounds allow (Guermond,
 * Nazarov, Popov & Tomas 2018). The B-splines are non-negative and a
 * partition of unity, so a control net of admissible states gives an
 * admissible field everywhere. */
#ifndef NSPD_FLOW_IGA_LIMITER_H
#define NSPD_FLOW_IGA_LIMITER_H

#include "flow/iga/decomp.h"
#include "flow/iga/idp.h"
#include "flow/iga/space.h"

#include <stdint.h>

/* none: the high-order step alone (the paper's scheme); positivity: the
 * high-order state unless density or internal energy would fall below
 * a fraction of the low-order one's; convex: density within the local
 * minimum and maximum and rho e / rho^gamma above the local minimum
 * (the low-order scheme's own bounds, relaxed by (m_i/|domain|)^0.75) */
typedef enum { IGA_LIMITER_NONE = 0, IGA_LIMITER_POSITIVITY, IGA_LIMITER_CONVEX } IgaLimiterKind;

/* a case's flow.iga.limiter when it names none */
enum { IGA_LIMITER_DEFAULT = IGA_LIMITER_NONE };

/* Every per-point array is of this process's window (decomp.h): n[a]
 * points along axis a, global index g[a][i]; only the own points' results
 * are right (the window's halo of 3 p is what they read). */
typedef struct {
    IgaLimiterKind kind;
    int n[2], p;
    int count[2];        /* the whole axis's points */
    const int *g[2];     /* borrowed: the global index of local point i */
    bool wrap[2];        /* periodic on local indices (the whole axis in the window) */
    int own0[2], own[2]; /* the own points: local [own0, own0 + own) */
    bool periodic[2];
    bool wall[4];  /* slip sides: the normal momentum of their points is 0 */
    bool fixed[4]; /* fixed sides: their points keep their state */
    double gamma, R, cv;
    /* per axis and global control point k, offset o in -p..p: int N_k
     * N_(k+o) and int N_k N'_(k+o), at [k (2p + 1) + o + p] */
    double *mass1[2], *grad1[2];
    double *m;       /* int N_i per control point */
    double *U;       /* the step's start, conservative (4 a point) */
    double *flux;    /* F_x(U), F_y(U) (8 a point) */
    IdpWaves *waves; /* per point: p, c, p^-ex of U */
    double *entropy; /* per point: rho e / rho^gamma of U */
    double *relax;   /* per point: the bounds' relaxation (m_i / |domain|)^0.75 */
    double *acc;     /* the low-order spatial rate times m_i (4 a point) */
    double *dsum;    /* sum of d_ij over j != i */
    IdpBounds *bounds;
    double *dij;  /* per point and offset: the graph viscosity d_ij */
    double *lij;  /* per point and offset: the pair's factor from i's side */
    double *rate; /* the lumped Galerkin rate (4 a point) */
    double *UL;   /* the low-order state (4 a point) */
    /* last step's statistics, of the own points */
    int64_t limited;  /* control points blended below 1 */
    double alpha_min; /* their smallest blending factor */
} IgaLimiter;

int iga_limiter_create(IgaLimiter *l, IgaLimiterKind kind, const IgaAxis ax[2], const IgaDecomp *dc,
                       const bool wall[4], const bool fixed[4], double gamma, double R);
void iga_limiter_destroy(IgaLimiter *l);

/* From the conservative control values U (4 a point): the fluxes, the
 * low-order rate, the viscosities d_ij and the bounds; returns the
 * largest step the low-order update keeps invariant, min_i m_i / (2
 * sum_j d_ij) over the own points. */
double iga_limiter_prepare(IgaLimiter *l, const double *U);

/* One forward-Euler stage of dt (at most what prepare returned) from the
 * prepared U into Uout: the low-order state plus the antidiffusive
 * fluxes towards the consistent-mass Galerkin update, each pair's flux
 * scaled by the smaller of the two factors that keep both points'
 * bounds (Guermond et al. 2018, Sec. 4.3). src: per control point the
 * momentum and power sources (3 a point), or NULL. */
void iga_limiter_stage(IgaLimiter *l, double dt, const double *src, double *Uout);

#endif
