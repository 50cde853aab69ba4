/* Contact between points that are not held together by bonds (issue 61):
 * the short-range force of Silling and Askari (2005, Sec. 5, EMU), pair by
 * pair between any two points of a body, so fragments of one body (and,
 * once a case holds several, bodies) push each other apart instead of
 * passing through one another.
 *
 * A pair i, j at deformed distance d = |y_j - y_i| repels when d < d_s:
 *     f_i += -c_s / delta (d_s - d) (y_j - y_i) / d V_j       (N/m^3)
 *     d_s  = min(compression |x_j - x_i|, distance dx)
 * with c_s = stiffness c (c the bond micromodulus, Eq. 15), so a lattice
 * neighbour feels it only once compressed below `compression` of its
 * reference distance, and points that meet from afar (two fragments) at
 * `distance` spacings. Its energy, whose negative gradient the force is:
 *     W = 1/2 sum_i sum_j c_s / (2 delta) (d_s - d)^2 V_i V_j    (J)
 * Both ends of a pair compute the same bits with negated operands, so the
 * pair forces cancel exactly and momentum is kept to round-off; each point
 * sums only its own row (no atomics, the same bits at any thread count).
 *
 * The candidate pairs are those within distance dx + skin of each other
 * when the lists were built (core/neighbours.h on the deformed positions);
 * they are rebuilt when a point has moved by more than skin / 2 since, so
 * no pair within distance dx is ever missing. One process only (the
 * candidates of a fragment that leaves its process's halo are not there). */
#ifndef NSPD_SOLID_PD_CONTACT_H
#define NSPD_SOLID_PD_CONTACT_H

#include <stdbool.h>
#include <stdint.h>

/* solid.contact of a case file */
typedef struct {
    bool enabled;
    double distance;    /* d_s between points that meet from afar, in spacings (1.35) */
    double compression; /* d_s of near points as a fraction of their reference distance (0.9) */
    double stiffness;   /* c_s / c (15) */
    double skin;        /* the candidates' margin, in spacings (0.5) */
} PdContactConfig;

typedef struct {
    int dim;
    int64_t n;
    double spacing, cutoff, skin; /* m: distance dx, and the margin */
    double compression;
    double coef;        /* c_s / delta, N/m^7 (2D: per thickness, as c) */
    double *y[3];       /* the deformed positions of the last build */
    double *u_built[3]; /* the displacements at the last build */
    int64_t *first;     /* candidates of point i: nbr[first[i] .. first[i + 1]) */
    int32_t *nbr;
    int64_t builds; /* how often the lists were built (a diagnostic) */
} PdContact;

/* Sets up contact for n points of dimension dim, lattice spacing dx,
 * horizon delta and micromodulus c; no lists yet (built at the first
 * pd_contact_add). NSPD_ERR_NOMEM. */
int pd_contact_create(PdContact *c, const PdContactConfig *cfg, int dim, int64_t n, double dx,
                      double horizon, double micromodulus);
void pd_contact_free(PdContact *c);

/* Adds the contact force density at x + u to force, first rebuilding the
 * candidate lists if a point has moved by more than skin / 2 since they
 * were built. NSPD_ERR_NOMEM if a rebuild fails. */
int pd_contact_add(PdContact *c, const double *const x[3], const double *const u[3],
                   const double *volume, double *const force[3]);

/* The contact energy W at x + u, J (over the candidates: call after a
 * pd_contact_add at this u or one within skin / 2 of it). */
double pd_contact_energy(const PdContact *c, const double *const x[3], const double *const u[3],
                         const double *volume);

/* The smallest deformed distance between two points whose reference
 * distance exceeds `reference` (the horizon: points never bonded, such as
 * two bodies' or two far parts of one), m, over the candidates (infinity
 * if none is within the cutoff and skin); a diagnostic of
 * interpenetration. */
double pd_contact_min_distance(const PdContact *c, const double *const x[3],
                               const double *const u[3], double reference);

#endif
