/* The PDDO pressure matrix and a sequence of its right-hand sides and
 * UMFPACK solutions, as dump.patch writes them (README.md): A.bin holds
 * n, nnz, pinned (int64), the row pointers (n + 1 int32), the columns and
 * values of the compressed rows; b%04d.bin / p%04d.bin hold n doubles. */
#ifndef PPE_DUMP_H
#define PPE_DUMP_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

typedef struct {
    int n, nnz;
    int32_t *ap, *ai;
    double *ax;
} Dump;

static inline double now_s(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static inline void read_or_die(void *to, size_t size, size_t count, FILE *f, const char *path) {
    if (fread(to, size, count, f) != count) {
        fprintf(stderr, "%s: short file\n", path);
        exit(2);
    }
}

static inline Dump dump_matrix(const char *dir) {
    char path[1024];
    snprintf(path, sizeof path, "%s/A.bin", dir);
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "%s: cannot open (see bench/ppe_solvers/README.md)\n", path);
        exit(2);
    }
    int64_t head[3];
    read_or_die(head, sizeof head, 1, f, path);
    Dump d = {(int)head[0], (int)head[1], NULL, NULL, NULL};
    d.ap = malloc(((size_t)d.n + 1) * sizeof(int32_t));
    d.ai = malloc((size_t)d.nnz * sizeof(int32_t));
    d.ax = malloc((size_t)d.nnz * sizeof(double));
    read_or_die(d.ap, sizeof(int32_t), (size_t)d.n + 1, f, path);
    read_or_die(d.ai, sizeof(int32_t), (size_t)d.nnz, f, path);
    read_or_die(d.ax, sizeof(double), (size_t)d.nnz, f, path);
    fclose(f);
    return d;
}

/* vector `name` of solve `count`, or NULL where the dump has none */
static inline double *dump_vector(const char *dir, const char *name, int count, int n) {
    char path[1024];
    snprintf(path, sizeof path, "%s/%s%04d.bin", dir, name, count);
    FILE *f = fopen(path, "rb");
    if (!f) return NULL;
    double *v = malloc((size_t)n * sizeof(double));
    read_or_die(v, sizeof(double), (size_t)n, f, path);
    fclose(f);
    return v;
}

/* max |x - ref| / max |ref| */
static inline double relative_error(const double *x, const double *ref, int n) {
    double e = 0.0, m = 0.0;
    for (int i = 0; i < n; i++) e = fmax(e, fabs(x[i] - ref[i])), m = fmax(m, fabs(ref[i]));
    return e / m;
}

static inline int by_value(const void *a, const void *b) {
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static inline double median(double *v, int count) {
    qsort(v, (size_t)count, sizeof *v, by_value);
    return v[count / 2];
}

#endif
