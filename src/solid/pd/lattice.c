/* Lattice filling and Morton ordering.
 *
 * Candidate points cover the bounding box of the geometry; each is kept if
 * the ShapeSet contains it. Morton (Z-order) sorting of the integer lattice
 * indices keeps most of a point's horizon within a few kilobytes of it,
 * which is what makes the gather in the force loop cheap. A Hilbert curve
 * would be slightly better but measured no faster on the 2D plate. */
#include "solid/pd/lattice.h"
#include "core/parallel.h"

#include "core/mem.h"
#include "core/status.h"

#include <math.h>
#include <stdlib.h>

static uint64_t spread2(uint32_t v) {
    uint64_t x = v;
    x = (x | (x << 16)) & 0x0000FFFF0000FFFFull;
    x = (x | (x << 8)) & 0x00FF00FF00FF00FFull;
    x = (x | (x << 4)) & 0x0F0F0F0F0F0F0F0Full;
    x = (x | (x << 2)) & 0x3333333333333333ull;
    x = (x | (x << 1)) & 0x5555555555555555ull;
    return x;
}

static uint64_t spread3(uint32_t v) {
    uint64_t x = v & 0x1FFFFF;
    x = (x | (x << 32)) & 0x001F00000000FFFFull;
    x = (x | (x << 16)) & 0x001F0000FF0000FFull;
    x = (x | (x << 8)) & 0x100F00F00F00F00Full;
    x = (x | (x << 4)) & 0x10C30C30C30C30C3ull;
    x = (x | (x << 2)) & 0x1249249249249249ull;
    return x;
}

uint64_t morton_key(int dim, uint32_t i, uint32_t j, uint32_t k) {
    if (dim == 2) return spread2(i) | (spread2(j) << 1);
    return spread3(i) | (spread3(j) << 1) | (spread3(k) << 2);
}

typedef struct {
    uint64_t key;
    int64_t slot;
} KeyedPoint;

static int compare_keys(const void *a, const void *b) {
    uint64_t ka = ((const KeyedPoint *)a)->key, kb = ((const KeyedPoint *)b)->key;
    return (ka > kb) - (ka < kb);
}

/* n points' positions and indices in *lat (freed again on failure). */
static int lattice_allocate(Lattice *lat, int64_t n) {
    int status = NSPD_OK;
    lat->n = n;
    for (int d = 0; d < 3 && status == NSPD_OK; d++) {
        status = nspd_alloc(&lat->x[d], (size_t)n, sizeof(double));
        if (status == NSPD_OK) status = nspd_alloc(&lat->index[d], (size_t)n, sizeof(int32_t));
    }
    if (status != NSPD_OK) lattice_free(lat);
    return status;
}

int lattice_fill(Lattice *lat, const ShapeSet *geometry, int dim, double dx, const double *origin) {
    lattice_free(lat);
    if (dim != 2 && dim != 3)
        return NSPD_FAIL(NSPD_ERR_INTERNAL, "lattice_fill: dim is %d; expected 2 or 3", dim);
    double lo[3], hi[3];
    if (!shapeset_bounds(geometry, dim, lo, hi))
        return NSPD_FAIL(NSPD_ERR_INPUT, "the solid geometry adds no shape");
    /* Point k along an axis sits at centre + (k - mid) dx. With a given
     * origin, centre = origin + mid dx reproduces origin + k dx; by default
     * the lattice is centred in the bounding box, centre = (lo + hi) / 2,
     * which is exactly 0 for a box written symmetrically, so that mirrored
     * points have exactly mirrored coordinates (k - mid is a half-integer,
     * exact, and the product rounds symmetrically). */
    int64_t first[3] = {0, 0, 0}, count[3] = {1, 1, 1};
    double centre[3] = {0, 0, 0}, mid[3] = {0, 0, 0};
    for (int d = 0; d < dim; d++) {
        if (origin) {
            first[d] = (int64_t)ceil((lo[d] - origin[d]) / dx - 1e-9);
            count[d] = (int64_t)floor((hi[d] - origin[d]) / dx + 1e-9) - first[d] + 1;
        } else {
            count[d] = (int64_t)floor((hi[d] - lo[d]) / dx + 1e-6);
            if (count[d] < 1) count[d] = 1;
        }
        if (count[d] <= 0 || count[d] > (dim == 2 ? (1 << 30) : (1 << 20)))
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "the solid lattice has %lld points along axis %d; expected 1 to %d",
                             (long long)count[d], d, dim == 2 ? (1 << 30) : (1 << 20));
        mid[d] = (double)first[d] + 0.5 * (double)(count[d] - 1);
        centre[d] = origin ? origin[d] + mid[d] * dx : 0.5 * (lo[d] + hi[d]);
    }
    int64_t candidates = count[0] * count[1] * count[2];

    /* pass 1: which candidates are inside (one byte each) */
    uint8_t *inside;
    TRY(nspd_alloc(&inside, (size_t)candidates, 1));
#pragma omp parallel for schedule(static) if (candidates >= PARALLEL_MIN_ITEMS)
    for (int64_t c = 0; c < candidates; c++) {
        int64_t i = c % count[0], j = (c / count[0]) % count[1], k = c / (count[0] * count[1]);
        double p[3] = {centre[0] + ((double)(first[0] + i) - mid[0]) * dx,
                       centre[1] + ((double)(first[1] + j) - mid[1]) * dx,
                       dim == 3 ? centre[2] + ((double)(first[2] + k) - mid[2]) * dx : 0.0};
        inside[c] = shapeset_contains(geometry, p);
    }
    int64_t n = 0;
    for (int64_t c = 0; c < candidates; c++) n += inside[c];
    if (n == 0) {
        nspd_free(&inside);
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "no lattice point of spacing %g m falls inside the solid geometry; "
                         "expected a spacing smaller than the body",
                         dx);
    }
    if (n > INT32_MAX) {
        nspd_free(&inside);
        return NSPD_FAIL(NSPD_ERR_INPUT, "%lld points exceed the 2^31 limit of one body",
                         (long long)n);
    }

    /* pass 2: Morton keys, sorted */
    KeyedPoint *keyed;
    int status = nspd_alloc(&keyed, (size_t)n, sizeof *keyed);
    if (status != NSPD_OK) {
        nspd_free(&inside);
        return status;
    }
    int64_t m = 0;
    for (int64_t c = 0; c < candidates; c++) {
        if (!inside[c]) continue;
        uint32_t i = (uint32_t)(c % count[0]), j = (uint32_t)((c / count[0]) % count[1]),
                 k = (uint32_t)(c / (count[0] * count[1]));
        keyed[m].key = morton_key(dim, i, j, k);
        keyed[m].slot = c;
        m++;
    }
    nspd_free(&inside);
    qsort(keyed, (size_t)n, sizeof *keyed, compare_keys);

    status = lattice_allocate(lat, n);
    if (status != NSPD_OK) {
        nspd_free(&keyed);
        return status;
    }
#pragma omp parallel for schedule(static) if (n >= PARALLEL_MIN_ITEMS)
    for (int64_t p = 0; p < n; p++) {
        int64_t c = keyed[p].slot;
        int64_t idx[3] = {c % count[0], (c / count[0]) % count[1], c / (count[0] * count[1])};
        for (int d = 0; d < 3; d++) {
            lat->index[d][p] = (int32_t)(first[d] + idx[d]);
            lat->x[d][p] = d < dim ? centre[d] + ((double)(first[d] + idx[d]) - mid[d]) * dx : 0.0;
        }
    }
    nspd_free(&keyed);
    return NSPD_OK;
}

double lattice_polar_spacing(const PolarLattice *spec) {
    return (spec->outer_radius - spec->inner_radius) / (double)spec->rings;
}

/* r_q, q = 0 .. rings: the ends exact */
static double ring_radius(const PolarLattice *spec, int32_t q) {
    if (q <= 0) return spec->inner_radius;
    if (q >= spec->rings) return spec->outer_radius;
    return spec->inner_radius +
           (spec->outer_radius - spec->inner_radius) * ((double)q / (double)spec->rings);
}

double lattice_polar_area(const PolarLattice *spec, int32_t ring) {
    const double a = ring_radius(spec, ring), b = ring_radius(spec, ring + 1);
    return M_PI / (double)spec->sectors * (b - a) * (b + a);
}

int64_t lattice_polar_sectors(double inner_radius, double outer_radius, double dr) {
    const double around = M_PI * (inner_radius + outer_radius) / dr; /* 2 pi r_mid / dr */
    const double quarters = fmax(1.0, floor(around / 4.0 + 0.5));
    return quarters < 1e9 ? 4 * (int64_t)quarters : (int64_t)4e9;
}

/* The unit direction of sector k of n (n even) at angle (k + 1/2) 2 pi / n,
 * from one in the first quadrant (first octant when 4 divides n) by exact
 * reflections: sector n - 1 - k is k mirrored about the horizontal line
 * (s -> -s), n/2 - 1 - k about the vertical (c -> -c), n/4 - 1 - k about
 * the diagonal (c <-> s). */
static void polar_direction(int64_t k, int64_t n, double *c, double *s) {
    const bool lower = k >= n / 2;
    if (lower) k = n - 1 - k;
    const int64_t half = n / 2;
    const bool left = k > half - 1 - k;
    if (left) k = half - 1 - k;
    const double step = 2.0 * M_PI / (double)n;
    double cc, ss;
    if (k == half - 1 - k) { /* on the vertical line: n/2 odd */
        cc = 0.0;
        ss = 1.0;
    } else if (n % 4 == 0 && k == n / 4 - 1 - k) { /* on the diagonal */
        cc = ss = sqrt(0.5);
    } else if (n % 4 == 0 && k > n / 4 - 1 - k) {
        const double angle = ((double)(n / 4 - 1 - k) + 0.5) * step;
        cc = sin(angle);
        ss = cos(angle);
    } else {
        const double angle = ((double)k + 0.5) * step;
        cc = cos(angle);
        ss = sin(angle);
    }
    *c = left ? -cc : cc;
    *s = lower ? -ss : ss;
}

int lattice_fill_polar(Lattice *lat, const PolarLattice *spec, const ShapeSet *filter) {
    lattice_free(lat);
    const int32_t rings = spec->rings, sectors = spec->sectors;
    if (!(spec->inner_radius > 0.0 && spec->outer_radius > spec->inner_radius))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "the polar lattice's radii are %g and %g m; expected 0 < inner < outer",
                         spec->inner_radius, spec->outer_radius);
    if (rings < 1 || sectors < 4 || sectors % 2 != 0)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "the polar lattice has %d rings and %d sectors; expected at least 1 "
                         "ring and an even number of sectors, at least 4",
                         (int)rings, (int)sectors);
    const int64_t candidates = (int64_t)rings * (int64_t)sectors;
    if (candidates > INT32_MAX)
        return NSPD_FAIL(NSPD_ERR_INPUT, "%lld points exceed the 2^31 limit of one body",
                         (long long)candidates);
    const bool filtered = filter && filter->count > 0;
    /* the centroid radius of each ring: (2/3) (b^3 - a^3) / (b^2 - a^2)
     * sin(h) / h, h half the sector angle */
    double *radius;
    TRY(nspd_alloc(&radius, (size_t)rings, sizeof(double)));
    const double h = M_PI / (double)sectors;
    for (int32_t q = 0; q < rings; q++) {
        const double a = ring_radius(spec, q), b = ring_radius(spec, q + 1);
        radius[q] = 2.0 / 3.0 * (a * a + a * b + b * b) / (a + b) * (sin(h) / h);
    }
    KeyedPoint *keyed;
    int status = nspd_alloc(&keyed, (size_t)candidates, sizeof *keyed);
    if (status != NSPD_OK) {
        nspd_free(&radius);
        return status;
    }
    int64_t n = 0;
    for (int64_t c = 0; c < candidates; c++) {
        const int64_t k = c % sectors, q = c / sectors;
        if (filtered) {
            double dc, ds;
            polar_direction(k, sectors, &dc, &ds);
            const double p[3] = {spec->center[0] + radius[q] * dc, spec->center[1] + radius[q] * ds,
                                 0.0};
            if (!shapeset_contains(filter, p)) continue;
        }
        keyed[n].key = morton_key(2, (uint32_t)k, (uint32_t)q, 0);
        keyed[n].slot = c;
        n++;
    }
    if (n == 0) {
        nspd_free(&radius);
        nspd_free(&keyed);
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "no element centroid of the polar lattice falls inside the solid "
                         "geometry; expected the geometry to cover the ring");
    }
    qsort(keyed, (size_t)n, sizeof *keyed, compare_keys);
    status = lattice_allocate(lat, n);
    if (status == NSPD_OK)
        for (int64_t p = 0; p < n; p++) {
            const int64_t c = keyed[p].slot, k = c % sectors, q = c / sectors;
            double dc, ds;
            polar_direction(k, sectors, &dc, &ds);
            lat->x[0][p] = spec->center[0] + radius[q] * dc;
            lat->x[1][p] = spec->center[1] + radius[q] * ds;
            lat->x[2][p] = 0.0;
            lat->index[0][p] = (int32_t)k;
            lat->index[1][p] = (int32_t)q;
            lat->index[2][p] = 0;
        }
    nspd_free(&radius);
    nspd_free(&keyed);
    return status;
}

void lattice_free(Lattice *lat) {
    for (int d = 0; d < 3; d++) {
        nspd_free(&lat->x[d]);
        nspd_free(&lat->index[d]);
    }
    lat->n = 0;
}

bool lattice_estimate(const ShapeSet *geometry, int dim, double dx, double *sites,
                      double *inside_fraction) {
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    if (!shapeset_bounds(geometry, dim, lo, hi)) return false;
    double count[3] = {1, 1, 1};
    *sites = 1.0;
    for (int d = 0; d < dim && d < 3; d++) {
        count[d] = fmax(1.0, floor((hi[d] - lo[d]) / dx + 1e-6));
        *sites *= count[d];
    }
    /* a sub-lattice of at most ~100 (3D) or ~1000 (2D) sites per axis */
    const double per_axis = dim == 3 ? 100.0 : 1000.0;
    double step[3], n[3] = {1, 1, 1};
    for (int d = 0; d < 3; d++) {
        step[d] = fmax(1.0, ceil(count[d] / per_axis));
        n[d] = d < dim ? ceil(count[d] / step[d]) : 1.0;
    }
    int64_t in = 0, total = 0;
    for (int64_t k = 0; k < (int64_t)n[2]; k++)
        for (int64_t j = 0; j < (int64_t)n[1]; j++)
            for (int64_t i = 0; i < (int64_t)n[0]; i++) {
                const int64_t idx[3] = {i, j, k};
                double p[3] = {0, 0, 0};
                for (int d = 0; d < dim && d < 3; d++)
                    p[d] = lo[d] + (0.5 + (double)idx[d] * step[d]) * dx;
                in += shapeset_contains(geometry, p);
                total++;
            }
    *inside_fraction = total ? (double)in / (double)total : 0.0;
    return true;
}
