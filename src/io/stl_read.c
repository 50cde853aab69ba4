#include "io/stl_read.h"

#include "core/mem.h"
#include "core/status.h"
#include "io/in_file.h"

#include <ctype.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static uint32_t le32(const unsigned char *b) {
    return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

static double le_float(const unsigned char *b) {
    const uint32_t u = le32(b);
    float f;
    memcpy(&f, &u, sizeof f);
    return (double)f;
}

static int read_binary(const unsigned char *data, int64_t size, double **tri, int64_t *count,
                       StlReadError *err) {
    const int64_t n = le32(data + 80);
    if (n > STL_MAX_TRIANGLES)
        return in_file_refuse(err, 0, 80, "%lld triangles; expected at most %d", (long long)n,
                              STL_MAX_TRIANGLES);
    (void)size; /* the caller matched it to n */
    TRY(nspd_alloc(tri, (size_t)(9 * n), sizeof(double)));
    for (int64_t t = 0; t < n; t++) {
        const unsigned char *f = data + 84 + 50 * t + 12; /* past the normal */
        for (int k = 0; k < 9; k++) {
            const double v = le_float(f + 4 * k);
            if (!isfinite(v)) {
                nspd_free(tri);
                return in_file_refuse(
                    err, 0, 84 + 50 * t + 12 + 4 * k,
                    "triangle %lld has a coordinate that is not finite; expected a "
                    "number",
                    (long long)t + 1);
            }
            (*tri)[9 * t + k] = v;
        }
    }
    *count = n;
    return NSPD_OK;
}

/* The ASCII reader's position: the text, where it is, its line. */
typedef struct {
    const char *p, *end;
    int line;      /* where p is */
    int word_line; /* the line of the last word read: where errors point */
    char word[64];
} Tokens;

/* The next word (up to 63 characters) into t->word; false at the end. */
static bool next_word(Tokens *t) {
    while (t->p < t->end && isspace((unsigned char)*t->p)) {
        if (*t->p == '\n') t->line++;
        t->p++;
    }
    if (t->p >= t->end) return false;
    t->word_line = t->line;
    size_t n = 0;
    while (t->p < t->end && !isspace((unsigned char)*t->p)) {
        if (n < sizeof t->word - 1) t->word[n++] = *t->p;
        t->p++;
    }
    t->word[n] = '\0';
    return true;
}

/* The next word must be `want`. */
static int expect(Tokens *t, const char *want, StlReadError *err) {
    if (!next_word(t))
        return in_file_refuse(err, t->word_line, 0, "the file ends; expected '%s'", want);
    if (strcmp(t->word, want) != 0)
        return in_file_refuse(err, t->word_line, 0, "'%s'; expected '%s'", t->word, want);
    return NSPD_OK;
}

static int number(Tokens *t, double *out, StlReadError *err) {
    if (!next_word(t))
        return in_file_refuse(err, t->word_line, 0, "the file ends; expected a coordinate");
    char *end;
    *out = strtod(t->word, &end);
    if (end == t->word || *end != '\0' || !isfinite(*out))
        return in_file_refuse(err, t->word_line, 0, "'%s' is not a number; expected a coordinate",
                              t->word);
    return NSPD_OK;
}

static int read_ascii(const char *text, int64_t size, double **tri, int64_t *count,
                      StlReadError *err) {
    Tokens t = {text, text + size, 1, 1, ""};
    TRY(expect(&t, "solid", err));
    /* the solid's name: the rest of the line */
    while (t.p < t.end && *t.p != '\n') t.p++;
    int64_t n = 0, cap = 0;
    *tri = NULL;
    int status = NSPD_OK;
    for (;;) {
        if (!next_word(&t)) {
            status = in_file_refuse(err, t.word_line, 0,
                                    "the file ends; expected 'facet' or 'endsolid'");
            break;
        }
        if (strcmp(t.word, "endsolid") == 0) break;
        if (strcmp(t.word, "facet") != 0) {
            status =
                in_file_refuse(err, t.word_line, 0, "'%s'; expected 'facet' or 'endsolid'", t.word);
            break;
        }
        double normal[3];
        status = expect(&t, "normal", err);
        for (int k = 0; k < 3 && status == NSPD_OK; k++) status = number(&t, &normal[k], err);
        if (status == NSPD_OK) status = expect(&t, "outer", err);
        if (status == NSPD_OK) status = expect(&t, "loop", err);
        if (status == NSPD_OK && n == cap) {
            if (n >= STL_MAX_TRIANGLES) {
                status = in_file_refuse(err, t.word_line, 0, "more than %d triangles",
                                        STL_MAX_TRIANGLES);
                break;
            }
            const int64_t grown = cap ? 2 * cap : 256;
            status = nspd_realloc(tri, (size_t)(9 * cap), (size_t)(9 * grown), sizeof(double));
            cap = grown;
        }
        for (int v = 0; v < 3 && status == NSPD_OK; v++) {
            status = expect(&t, "vertex", err);
            for (int k = 0; k < 3 && status == NSPD_OK; k++)
                status = number(&t, &(*tri)[9 * n + 3 * v + k], err);
        }
        if (status == NSPD_OK) status = expect(&t, "endloop", err);
        if (status == NSPD_OK) status = expect(&t, "endfacet", err);
        if (status != NSPD_OK) break;
        n++;
    }
    if (status != NSPD_OK) {
        nspd_free(tri);
        return status;
    }
    *count = n;
    return NSPD_OK;
}

int stl_read_file(const char *path, double **tri, int64_t *count, StlReadError *err) {
    memset(err, 0, sizeof *err);
    *tri = NULL;
    *count = 0;
    FILE *f = in_file_open(path, &err->os_error);
    if (!f) return NSPD_FAIL(NSPD_ERR_IO, "%s: cannot open it", path); /* err: for the caller's */
    unsigned char *data = NULL;
    int64_t size = 0, cap = 0;
    int status = NSPD_OK;
    for (;;) { /* the whole file: STL files are read once, whole */
        if (size == cap) {
            const int64_t grown = cap ? 2 * cap : 1 << 16;
            status = nspd_realloc(&data, (size_t)cap, (size_t)grown + 1, 1);
            if (status != NSPD_OK) break;
            cap = grown;
        }
        const size_t got = fread(data + size, 1, (size_t)(cap - size), f);
        size += (int64_t)got;
        if (got == 0) break;
    }
    fclose(f);
    if (status == NSPD_OK) {
        if (size >= 84 && size == 84 + 50 * (int64_t)le32(data + 80))
            status = read_binary(data, size, tri, count, err);
        else if (size >= 5 && memcmp(data, "solid", 5) == 0 && !memchr(data, 0, (size_t)size))
            status = read_ascii((const char *)data, size, tri, count, err);
        else if (size < 84)
            status = in_file_refuse(
                err, 0, size,
                "the file is %lld bytes, not text; expected an ASCII STL ('solid ...') or a "
                "binary one (84 + 50 bytes a triangle)",
                (long long)size);
        else
            status =
                in_file_refuse(err, 0, 80,
                               "the binary header states %lu triangles, which take %lld bytes, "
                               "but the file has %lld; expected a complete binary STL or an "
                               "ASCII one ('solid ...')",
                               (unsigned long)le32(data + 80), 84 + 50 * (long long)le32(data + 80),
                               (long long)size);
    }
    nspd_free(&data);
    return status;
}
