#include "io/inp_read.h"

#include "core/mem.h"
#include "core/status.h"
#include "io/in_file.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

int inp_shape_nodes(InpShape shape) {
    static const int NODES[INP_SHAPE_COUNT] = {3, 4, 4, 8};
    return shape >= 0 && shape < INP_SHAPE_COUNT ? NODES[shape] : 0;
}

static int shape_dim(InpShape shape) {
    return shape == INP_TET4 || shape == INP_HEX8 ? 3 : 2;
}

typedef struct {
    const char *name;
    InpShape shape;
} ElementType;

/* The linear elements: their reduced (R), incompatible-mode (I) and hybrid
 * (H) variants have the same nodes and shape. */
static const ElementType TYPES[] = {
    {"CPS3", INP_TRI3},    {"CPE3", INP_TRI3},    {"CPE3H", INP_TRI3},  {"S3", INP_TRI3},
    {"S3R", INP_TRI3},     {"CPS4", INP_QUAD4},   {"CPS4R", INP_QUAD4}, {"CPS4I", INP_QUAD4},
    {"CPE4", INP_QUAD4},   {"CPE4R", INP_QUAD4},  {"CPE4I", INP_QUAD4}, {"CPE4H", INP_QUAD4},
    {"CPE4RH", INP_QUAD4}, {"CPE4IH", INP_QUAD4}, {"S4", INP_QUAD4},    {"S4R", INP_QUAD4},
    {"C3D4", INP_TET4},    {"C3D4H", INP_TET4},   {"C3D8", INP_HEX8},   {"C3D8R", INP_HEX8},
    {"C3D8I", INP_HEX8},   {"C3D8H", INP_HEX8},   {"C3D8RH", INP_HEX8}, {"C3D8IH", INP_HEX8},
};

static const char *const TYPE_LIST =
    "CPS3, CPE3, S3, S3R (triangles), CPS4, CPE4, CPS4R, CPE4R, CPS4I, CPE4I, S4, S4R "
    "(quadrilaterals), C3D4 (tetrahedra) or C3D8, C3D8R, C3D8I (hexahedra), or their H variants";

/* ---- lines and fields ---------------------------------------------------- */

typedef struct {
    const char *s, *e; /* [s, e) */
} Span;

static Span trim(Span f) {
    while (f.s < f.e && (*f.s == ' ' || *f.s == '\t')) f.s++;
    while (f.e > f.s && (f.e[-1] == ' ' || f.e[-1] == '\t')) f.e--;
    return f;
}

/* Splits a line into at most `max` trimmed fields; *count is how many there
 * were (more than max: max + 1), *trailing whether the line ends with a
 * comma (its empty last field is not counted). */
static void split_fields(Span line, Span *fields, int max, int *count, bool *trailing) {
    int n = 0;
    const char *p = line.s;
    *trailing = false;
    for (;;) {
        const char *comma = memchr(p, ',', (size_t)(line.e - p));
        Span f = trim((Span){p, comma ? comma : line.e});
        if (!comma) {
            if (f.s == f.e && n > 0) { /* nothing after the last comma */
                *trailing = true;
            } else {
                if (n < max) fields[n] = f;
                n++;
            }
            break;
        }
        if (n < max) fields[n] = f;
        n++;
        p = comma + 1;
    }
    *count = n > max ? max + 1 : n;
}

/* The field as printable text for a message (at most 40 characters). */
static const char *shown(Span f, char *buf, size_t size) {
    size_t n = 0;
    for (const char *c = f.s; c < f.e && n + 4 < size && n < 40; c++)
        buf[n++] = isprint((unsigned char)*c) ? *c : '?';
    if (f.e - f.s > 40 && n + 4 < size) buf[n++] = '.', buf[n++] = '.', buf[n++] = '.';
    buf[n] = '\0';
    return buf;
}

static bool parse_double(Span f, double *out) {
    const size_t n = (size_t)(f.e - f.s);
    if (n == 0 || n >= 64) return false;
    char buf[64];
    for (size_t k = 0; k < n; k++) {
        const char c = f.s[k];
        /* digits, sign, point and exponent only: strtod's inf, nan and hex
         * floats are not Abaqus numbers */
        if (!(isdigit((unsigned char)c) || c == '+' || c == '-' || c == '.' || c == 'e' ||
              c == 'E'))
            return false;
        buf[k] = c;
    }
    buf[n] = '\0';
    char *end;
    *out = strtod(buf, &end);
    return end == buf + n && isfinite(*out);
}

/* A node or element number: 1 to 2^31 - 1, digits only. */
static bool parse_id(Span f, int64_t *out) {
    const char *c = f.s;
    if (c < f.e && *c == '+') c++;
    if (c == f.e || f.e - c > 10) return false;
    int64_t v = 0;
    for (; c < f.e; c++) {
        if (!isdigit((unsigned char)*c)) return false;
        v = 10 * v + (*c - '0');
    }
    if (v < 1 || v > INT32_MAX) return false;
    *out = v;
    return true;
}

/* ---- the reader's state -------------------------------------------------- */

typedef enum { BLOCK_SKIP, BLOCK_NODE, BLOCK_ELEMENT, BLOCK_SET } Block;

typedef struct {
    InpMesh *m;
    InpReadError *err;
    int line;
    int64_t node_cap, element_cap;
    int32_t *node_line;
    int64_t entry_budget; /* set ranges still allowed: a set copying sets must not explode */
    int set_cap;
    Block block;
    InpShape shape;
    int set; /* the set the block's lines add to, -1 none */
    bool generate;
    /* an element's numbers, gathered over its continuation lines */
    int64_t pending[1 + INP_MAX_ELEMENT_NODES];
    int pending_count, pending_line;
    bool continuing;
} Reader;

/* Room for `need` items in arrays of `count` x `size` bytes each (all of
 * one capacity *cap, doubled as needed). */
static int grow_all(int64_t *cap, int64_t need, int count, void *const *arrays,
                    const size_t *size) {
    if (need <= *cap) return NSPD_OK;
    int64_t grown = *cap ? *cap : 256;
    while (grown < need) grown *= 2;
    for (int k = 0; k < count; k++)
        TRY(nspd_realloc(arrays[k], (size_t)*cap * size[k], (size_t)grown * size[k], 1));
    *cap = grown;
    return NSPD_OK;
}

static int push_range(InpSet *s, InpRange g) {
    if (s->range_count == s->range_capacity) {
        const int64_t grown = s->range_capacity ? 2 * s->range_capacity : 8;
        TRY(nspd_realloc(&s->ranges, (size_t)s->range_capacity, (size_t)grown, sizeof(InpRange)));
        s->range_capacity = grown;
    }
    s->ranges[s->range_count++] = g;
    return NSPD_OK;
}

static int over_budget(Reader *r) {
    if (r->entry_budget-- > 0) return NSPD_OK;
    return in_file_refuse(
        r->err, r->line, 0,
        "the sets hold more entries than the file has bytes; expected sets that name "
        "each number or set a few times");
}

static void upper(char *s) {
    for (; *s; s++) *s = (char)toupper((unsigned char)*s);
}

/* The set of that upper-case name and kind, -1 if none. */
static int set_index(const InpMesh *m, const char *name, bool elements) {
    for (int k = 0; k < m->set_count; k++)
        if (m->sets[k].elements == elements && strcmp(m->sets[k].name, name) == 0) return k;
    return -1;
}

static int find_or_add_set(Reader *r, const char *name, bool elements, int *out) {
    InpMesh *m = r->m;
    *out = set_index(m, name, elements);
    if (*out >= 0) return NSPD_OK; /* defined again: the members are added */
    if (m->set_count >= INP_MAX_SETS)
        return in_file_refuse(r->err, r->line, 0, "more than %d sets; expected fewer",
                              INP_MAX_SETS);
    if (m->set_count == r->set_cap) {
        const int grown = r->set_cap ? 2 * r->set_cap : 16;
        TRY(nspd_realloc(&m->sets, (size_t)r->set_cap, (size_t)grown, sizeof(InpSet)));
        r->set_cap = grown;
    }
    InpSet *s = &m->sets[m->set_count];
    memset(s, 0, sizeof *s);
    snprintf(s->name, sizeof s->name, "%s", name);
    s->elements = elements;
    s->line = r->line;
    *out = m->set_count++;
    return NSPD_OK;
}

/* Adds ids first..last by step to set k. A single id extends the set's
 * last explicit run when it follows it, written on the same line (a missing
 * one is then refused at its line) or `defined` by the line (NSET= of
 * *NODE, ELSET= of *ELEMENT: a set of all nodes is one run). */
static int add_range(Reader *r, int k, int64_t first, int64_t last, int64_t step, bool generated,
                     bool defined) {
    InpSet *s = &r->m->sets[k];
    if (!generated && s->range_count > 0) {
        InpRange *prev = &s->ranges[s->range_count - 1];
        if (!prev->generated && prev->step == 1 && first == last && first == prev->last + 1 &&
            (defined || prev->line == r->line)) {
            prev->last = first;
            return NSPD_OK;
        }
    }
    TRY(over_budget(r));
    return push_range(
        s,
        (InpRange){
            .first = first, .last = last, .step = step, .line = r->line, .generated = generated});
}

/* ---- keyword lines -------------------------------------------------------- */

enum { MAX_PARAMS = 16 };

typedef struct {
    char key[32];
    char value[INP_MAX_NAME];
    bool has_value;
} Param;

typedef struct {
    char keyword[32];
    int count;
    Param p[MAX_PARAMS];
} Keyword;

static const Param *param(const Keyword *k, const char *key) {
    for (int i = 0; i < k->count; i++)
        if (strcmp(k->p[i].key, key) == 0) return &k->p[i];
    return NULL;
}

/* "*Element, type=CPS4, elset=Plate" (from after the '*'): the keyword in
 * upper case with its spaces collapsed, then KEY[=value] parameters. */
static int parse_params(Reader *r, Span rest, Keyword *k) {
    Span f[MAX_PARAMS + 1];
    int n;
    bool trailing;
    split_fields(rest, f, MAX_PARAMS, &n, &trailing);
    if (n > MAX_PARAMS) n = MAX_PARAMS; /* the rest are parameters nspd does not read */
    for (int i = 0; i < n; i++) {
        if (f[i].s == f[i].e) continue;
        if (k->count >= MAX_PARAMS) break;
        Param *p = &k->p[k->count];
        const char *eq = memchr(f[i].s, '=', (size_t)(f[i].e - f[i].s));
        Span key = trim((Span){f[i].s, eq ? eq : f[i].e});
        snprintf(p->key, sizeof p->key, "%.*s", (int)(key.e - key.s), key.s);
        upper(p->key);
        p->has_value = eq != NULL;
        p->value[0] = '\0';
        if (eq) {
            Span v = trim((Span){eq + 1, f[i].e});
            if (v.e - v.s >= 2 && *v.s == '"' && v.e[-1] == '"') v.s++, v.e--;
            if (v.e - v.s >= INP_MAX_NAME) {
                char buf[64];
                return in_file_refuse(
                    r->err, r->line, 0,
                    "the value of %s, '%s', has more than %d characters; expected a "
                    "name of at most %d",
                    p->key, shown(v, buf, sizeof buf), INP_MAX_NAME - 1, INP_MAX_NAME - 1);
            }
            snprintf(p->value, sizeof p->value, "%.*s", (int)(v.e - v.s), v.s);
        }
        k->count++;
    }
    return NSPD_OK;
}

static void parse_keyword_name(Span line, Keyword *k, Span *rest) {
    const char *p = line.s + 1; /* past the '*' */
    const char *comma = memchr(p, ',', (size_t)(line.e - p));
    Span name = trim((Span){p, comma ? comma : line.e});
    size_t n = 0;
    bool space = false;
    for (const char *c = name.s; c < name.e && n + 1 < sizeof k->keyword; c++) {
        if (*c == ' ' || *c == '\t') {
            space = true;
            continue;
        }
        if (space && n > 0) k->keyword[n++] = ' ';
        space = false;
        if (n + 1 < sizeof k->keyword) k->keyword[n++] = (char)toupper((unsigned char)*c);
    }
    k->keyword[n] = '\0';
    *rest = comma ? (Span){comma + 1, line.e} : (Span){line.e, line.e};
}

static int start_block(Reader *r, const Keyword *k) {
    InpMesh *m = r->m;
    r->block = BLOCK_SKIP;
    r->set = -1;
    r->generate = false;
    const bool node = strcmp(k->keyword, "NODE") == 0, element = strcmp(k->keyword, "ELEMENT") == 0,
               nset = strcmp(k->keyword, "NSET") == 0, elset = strcmp(k->keyword, "ELSET") == 0;
    if (strcmp(k->keyword, "INCLUDE") == 0)
        return in_file_refuse(
            r->err, r->line, 0,
            "*INCLUDE: nspd reads one file; expected the mesh in this file (paste the "
            "included file in)");
    if (!(node || element || nset || elset)) return NSPD_OK; /* skipped with its data lines */
    if (param(k, "INPUT"))
        return in_file_refuse(r->err, r->line, 0,
                              "*%s with INPUT=: nspd reads one file; expected the data lines here",
                              k->keyword);
    if (node) {
        const Param *sys = param(k, "SYSTEM");
        if (sys && strcasecmp(sys->value, "R") != 0)
            return in_file_refuse(
                r->err, r->line, 0,
                "*NODE, SYSTEM=%s: expected rectangular coordinates (SYSTEM=R or none)",
                sys->value);
        const Param *ns = param(k, "NSET");
        if (ns && ns->value[0]) {
            char name[INP_MAX_NAME];
            snprintf(name, sizeof name, "%s", ns->value);
            upper(name);
            TRY(find_or_add_set(r, name, false, &r->set));
        }
        r->block = BLOCK_NODE;
        return NSPD_OK;
    }
    if (element) {
        const Param *type = param(k, "TYPE");
        if (!type || !type->value[0])
            return in_file_refuse(r->err, r->line, 0, "*ELEMENT without TYPE=; expected TYPE=%s",
                                  "CPS4 or another element type");
        char name[INP_MAX_NAME];
        snprintf(name, sizeof name, "%s", type->value);
        upper(name);
        int t = -1;
        for (size_t i = 0; i < sizeof TYPES / sizeof *TYPES; i++)
            if (strcmp(TYPES[i].name, name) == 0) t = (int)i;
        if (t < 0)
            return in_file_refuse(r->err, r->line, 0, "unknown element type %s; expected %s",
                                  type->value, TYPE_LIST);
        r->shape = TYPES[t].shape;
        const int dim = shape_dim(r->shape);
        if (m->dim && m->dim != dim)
            return in_file_refuse(r->err, r->line, 0,
                                  "%s, a %dD element, after %dD ones; expected elements of one "
                                  "dimension",
                                  TYPES[t].name, dim, m->dim);
        m->dim = dim;
        const Param *es = param(k, "ELSET");
        if (es && es->value[0]) {
            snprintf(name, sizeof name, "%s", es->value);
            upper(name);
            TRY(find_or_add_set(r, name, true, &r->set));
        }
        r->block = BLOCK_ELEMENT;
        return NSPD_OK;
    }
    const char *key = nset ? "NSET" : "ELSET";
    const Param *named = param(k, key);
    if (!named || !named->value[0])
        return in_file_refuse(r->err, r->line, 0, "*%s without %s=; expected %s=NAME", key, key,
                              key);
    char name[INP_MAX_NAME];
    snprintf(name, sizeof name, "%s", named->value);
    upper(name);
    TRY(find_or_add_set(r, name, elset, &r->set));
    r->generate = param(k, "GENERATE") != NULL;
    r->block = BLOCK_SET;
    return NSPD_OK;
}

/* ---- data lines -------------------------------------------------------- */

static const char *const AXES[3] = {"x", "y", "z"};

static int node_line(Reader *r, Span line) {
    InpMesh *m = r->m;
    Span f[8];
    int n;
    bool trailing;
    split_fields(line, f, 7, &n, &trailing);
    char buf[64];
    if (n < 3 || n > 7)
        return in_file_refuse(r->err, r->line, 0,
                              "%d fields in a *NODE line; expected node number, x, y[, z]", n);
    int64_t id;
    if (!parse_id(f[0], &id))
        return in_file_refuse(r->err, r->line, 0,
                              "'%s' is not a node number; expected a whole number from 1 to %d",
                              shown(f[0], buf, sizeof buf), INT32_MAX);
    double x[6] = {0, 0, 0, 0, 0, 0};
    for (int k = 1; k < n; k++)
        if (!parse_double(f[k], &x[k - 1]))
            return in_file_refuse(r->err, r->line, 0,
                                  "'%s' is not a number; expected node %lld's %s",
                                  shown(f[k], buf, sizeof buf), (long long)id,
                                  k <= 3 ? AXES[k - 1] : "normal's direction cosine");
    if (m->node_count >= INT32_MAX)
        return in_file_refuse(r->err, r->line, 0, "more than %d nodes; expected fewer", INT32_MAX);
    void *const arrays[3] = {&m->node_id, &m->node_x, &r->node_line};
    const size_t sizes[3] = {sizeof(int64_t), 3 * sizeof(double), sizeof(int32_t)};
    TRY(grow_all(&r->node_cap, m->node_count + 1, 3, arrays, sizes));
    const int64_t i = m->node_count++;
    m->node_id[i] = id;
    for (int d = 0; d < 3; d++) m->node_x[3 * i + d] = x[d];
    r->node_line[i] = r->line;
    if (r->set >= 0) TRY(add_range(r, r->set, id, id, 1, false, true));
    return NSPD_OK;
}

static int finish_element(Reader *r) {
    InpMesh *m = r->m;
    const int nodes = inp_shape_nodes(r->shape);
    if (m->element_count >= INT32_MAX)
        return in_file_refuse(r->err, r->line, 0, "more than %d elements; expected fewer",
                              INT32_MAX);
    const int64_t e = m->element_count;
    void *const arrays[4] = {&m->element_id, &m->element_shape, &m->element_line, &m->element_node};
    const size_t sizes[4] = {sizeof(int64_t), 1, sizeof(int32_t),
                             INP_MAX_ELEMENT_NODES * sizeof(int64_t)};
    TRY(grow_all(&r->element_cap, e + 1, 4, arrays, sizes));
    m->element_id[e] = r->pending[0];
    m->element_shape[e] = (uint8_t)r->shape;
    m->element_line[e] = r->pending_line;
    for (int k = 0; k < INP_MAX_ELEMENT_NODES; k++)
        m->element_node[INP_MAX_ELEMENT_NODES * e + k] = k < nodes ? r->pending[1 + k] : -1;
    m->element_count++;
    r->pending_count = 0;
    r->continuing = false;
    if (r->set >= 0) TRY(add_range(r, r->set, m->element_id[e], m->element_id[e], 1, false, true));
    return NSPD_OK;
}

static int element_line(Reader *r, Span line) {
    const int nodes = inp_shape_nodes(r->shape);
    Span f[18];
    int n;
    bool trailing;
    split_fields(line, f, 17, &n, &trailing);
    if (!r->continuing) r->pending_line = r->line, r->pending_count = 0;
    char buf[64];
    const char *type_name = "its type";
    for (size_t i = 0; i < sizeof TYPES / sizeof *TYPES; i++)
        if (TYPES[i].shape == r->shape) {
            type_name = TYPES[i].name;
            break;
        }
    for (int k = 0; k < n && k < 17; k++) {
        int64_t id;
        if (f[k].s == f[k].e)
            return in_file_refuse(r->err, r->line, 0, "an empty field; expected %s",
                                  r->pending_count == 0 ? "the element's number" : "a node number");
        if (!parse_id(f[k], &id))
            return in_file_refuse(
                r->err, r->line, 0, "'%s' is not %s; expected a whole number from 1 to %d",
                shown(f[k], buf, sizeof buf),
                r->pending_count == 0 ? "an element number" : "a node number", INT32_MAX);
        if (r->pending_count == 1 + nodes)
            return in_file_refuse(
                r->err, r->line, 0,
                "element %lld has more than %d nodes; expected %d for a %s (linear "
                "elements only)",
                (long long)r->pending[0], nodes, nodes, type_name);
        r->pending[r->pending_count++] = id;
    }
    if (n > 17)
        return in_file_refuse(r->err, r->line, 0, "more than 17 fields; expected %d nodes for a %s",
                              nodes, type_name);
    if (r->pending_count == 1 + nodes) return finish_element(r);
    if (trailing) {
        r->continuing = true; /* its nodes go on on the next line */
        return NSPD_OK;
    }
    return in_file_refuse(
        r->err, r->line, 0,
        "element %lld has %d nodes; expected %d for a %s (or a comma at the line's end "
        "to go on on the next)",
        (long long)r->pending[0], r->pending_count - 1, nodes, type_name);
}

static int set_line(Reader *r, Span line) {
    InpMesh *m = r->m;
    const bool elements = m->sets[r->set].elements;
    const char *what = elements ? "element" : "node", *a_what = elements ? "an element" : "a node";
    Span f[18];
    int n;
    bool trailing;
    split_fields(line, f, 17, &n, &trailing);
    char buf[64];
    if (r->generate) {
        int64_t v[3] = {0, 0, 1};
        if (n < 2 || n > 3)
            return in_file_refuse(r->err, r->line, 0,
                                  "%d fields in a GENERATE line; expected first, last[, step]", n);
        for (int k = 0; k < n; k++)
            if (!parse_id(f[k], &v[k]))
                return in_file_refuse(r->err, r->line, 0,
                                      "'%s' is not %s number; expected first, last[, step] (whole "
                                      "numbers from 1)",
                                      shown(f[k], buf, sizeof buf), a_what);
        if (v[1] < v[0])
            return in_file_refuse(r->err, r->line, 0,
                                  "the range %lld to %lld runs backwards; expected "
                                  "first <= last",
                                  (long long)v[0], (long long)v[1]);
        return add_range(r, r->set, v[0], v[1], v[2], true, false);
    }
    for (int k = 0; k < n && k < 17; k++) {
        if (f[k].s == f[k].e)
            return in_file_refuse(r->err, r->line, 0,
                                  "an empty field; expected %s number or a set's name", a_what);
        int64_t id;
        if (parse_id(f[k], &id)) {
            TRY(add_range(r, r->set, id, id, 1, false, false));
            continue;
        }
        char name[INP_MAX_NAME];
        Span v = f[k];
        if (v.e - v.s >= 2 && *v.s == '"' && v.e[-1] == '"') v.s++, v.e--;
        const int other = v.e - v.s < INP_MAX_NAME
                              ? (snprintf(name, sizeof name, "%.*s", (int)(v.e - v.s), v.s),
                                 upper(name), set_index(m, name, elements))
                              : -1;
        if (other < 0)
            return in_file_refuse(
                r->err, r->line, 0,
                "'%s' is not %s number or the name of an earlier %s set; expected "
                "one of them",
                shown(f[k], buf, sizeof buf), a_what, what);
        const int64_t count = m->sets[other].range_count;
        for (int64_t q = 0; q < count; q++) {
            const InpRange copy = m->sets[other].ranges[q]; /* by value: adding may move them */
            TRY(over_budget(r));
            TRY(push_range(&m->sets[r->set], copy));
        }
    }
    if (n > 17)
        return in_file_refuse(r->err, r->line, 0,
                              "more than 16 entries in a set's line; expected at most "
                              "16");
    return NSPD_OK;
}

/* ---- after the last line ------------------------------------------------- */

typedef struct {
    int64_t id, index;
} Keyed;

static int compare_keyed(const void *a, const void *b) {
    const Keyed *x = a, *y = b;
    if (x->id != y->id) return (x->id > y->id) - (x->id < y->id);
    return (x->index > y->index) - (x->index < y->index);
}

/* order[] = indices sorted by id; a repeated id refused at its later line. */
static int sort_ids(Reader *r, const int64_t *id, int64_t n, const int32_t *line, const char *what,
                    int64_t **order) {
    Keyed *k;
    TRY(nspd_alloc(&k, (size_t)n + 1, sizeof *k));
    for (int64_t i = 0; i < n; i++) k[i] = (Keyed){id[i], i};
    qsort(k, (size_t)n, sizeof *k, compare_keyed);
    int64_t twice = -1, first = -1;
    for (int64_t i = 1; i < n; i++)
        if (k[i].id == k[i - 1].id && (twice < 0 || line[k[i].index] < line[twice]))
            twice = k[i].index, first = k[i - 1].index;
    int status = nspd_alloc(order, (size_t)n + 1, sizeof(int64_t));
    if (status == NSPD_OK)
        for (int64_t i = 0; i < n; i++) (*order)[i] = k[i].index;
    nspd_free(&k);
    TRY(status);
    if (twice >= 0)
        return in_file_refuse(
            r->err, line[twice], 0,
            "%s %lld is defined again (first at line %d); expected each %s number once "
            "(several parts' numbers are not told apart: one part a file)",
            what, (long long)id[twice], (int)line[first], what);
    return NSPD_OK;
}

/* The index of the first sorted id >= v. */
static int64_t lower_bound(const int64_t *id, const int64_t *order, int64_t n, int64_t v) {
    int64_t lo = 0, hi = n;
    while (lo < hi) {
        const int64_t mid = lo + (hi - lo) / 2;
        if (id[order[mid]] < v)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

static int64_t find_id(const int64_t *id, const int64_t *order, int64_t n, int64_t v) {
    const int64_t k = lower_bound(id, order, n, v);
    return k < n && id[order[k]] == v ? order[k] : -1;
}

static double cross2(double ax, double ay, double bx, double by) {
    return ax * by - ay * bx;
}

/* A triangle's or quadrilateral's area and centroid (x-y; see the header). */
static void area_2d(const double *p[4], int nodes, double *area, double c[3], double *corner_min,
                    int *corner) {
    if (nodes == 3) {
        *area = 0.5 *
                cross2(p[1][0] - p[0][0], p[1][1] - p[0][1], p[2][0] - p[0][0], p[2][1] - p[0][1]);
        for (int d = 0; d < 2; d++) c[d] = (p[0][d] + p[1][d] + p[2][d]) / 3.0;
        *corner_min = *area;
        *corner = 0;
    } else {
        /* x = a0 + a1 s + a2 t + a3 s t on [-1, 1]^2; det J = c0 + c1 s + c2 t
         * with c0 = a1 x a2, c1 = a1 x a3, c2 = a3 x a2: area 4 c0, centroid
         * a0 + (a1 c1 + a2 c2) / (3 c0), a0 exactly for a parallelogram */
        double a0[2], a1[2], a2[2], a3[2];
        for (int d = 0; d < 2; d++) {
            a0[d] = 0.25 * ((p[0][d] + p[1][d]) + (p[2][d] + p[3][d]));
            a1[d] = 0.25 * ((p[1][d] + p[2][d]) - (p[0][d] + p[3][d]));
            a2[d] = 0.25 * ((p[2][d] + p[3][d]) - (p[0][d] + p[1][d]));
            a3[d] = 0.25 * ((p[0][d] + p[2][d]) - (p[1][d] + p[3][d]));
        }
        *area = 0.5 *
                cross2(p[2][0] - p[0][0], p[2][1] - p[0][1], p[3][0] - p[1][0], p[3][1] - p[1][1]);
        const double c0 = 0.25 * *area, c1 = cross2(a1[0], a1[1], a3[0], a3[1]),
                     c2 = cross2(a3[0], a3[1], a2[0], a2[1]);
        for (int d = 0; d < 2; d++)
            c[d] = c0 > 0.0 ? a0[d] + (a1[d] * c1 + a2[d] * c2) / (3.0 * c0) : a0[d];
        *corner_min = INFINITY;
        *corner = 0;
        for (int i = 0; i < 4; i++) { /* the turn at each node: > 0 counter-clockwise */
            const double *a = p[(i + 3) % 4], *b = p[i], *q = p[(i + 1) % 4];
            const double turn = cross2(b[0] - a[0], b[1] - a[1], q[0] - b[0], q[1] - b[1]);
            if (turn < *corner_min) *corner_min = turn, *corner = i;
        }
    }
    c[2] = p[0][2];
}

static double det3(const double a[3], const double b[3], const double c[3]) {
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
           a[2] * (b[0] * c[1] - b[1] * c[0]);
}

/* A tetrahedron's or hexahedron's volume and centroid; *det_min the
 * smallest det J (hexahedron: at the Gauss points) and its point. */
static void volume_3d(const double *p[8], int nodes, double *volume, double c[3], double *det_min) {
    if (nodes == 4) {
        double a[3], b[3], q[3];
        for (int d = 0; d < 3; d++)
            a[d] = p[1][d] - p[0][d], b[d] = p[2][d] - p[0][d], q[d] = p[3][d] - p[0][d];
        *volume = det3(a, b, q) / 6.0;
        for (int d = 0; d < 3; d++) c[d] = 0.25 * ((p[0][d] + p[1][d]) + (p[2][d] + p[3][d]));
        *det_min = *volume;
        return;
    }
    /* x = sum_k a_k m_k(s, t, u), m = 1, s, t, u, st, tu, su, stu; the
     * nodes at the corners (-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1,
     * -1), then the same at u = 1 */
    static const double S[8] = {-1, 1, 1, -1, -1, 1, 1, -1}, T[8] = {-1, -1, 1, 1, -1, -1, 1, 1},
                        U[8] = {-1, -1, -1, -1, 1, 1, 1, 1};
    double a[8][3];
    for (int d = 0; d < 3; d++) {
        double m[8] = {0};
        for (int i = 0; i < 8; i++) {
            const double x = p[i][d];
            m[0] += x, m[1] += S[i] * x, m[2] += T[i] * x, m[3] += U[i] * x;
            m[4] += S[i] * T[i] * x, m[5] += T[i] * U[i] * x, m[6] += S[i] * U[i] * x;
            m[7] += S[i] * T[i] * U[i] * x;
        }
        for (int k = 0; k < 8; k++) a[k][d] = 0.125 * m[k];
    }
    const double g = 1.0 / sqrt(3.0);
    double vol = 0.0, moment[3] = {0, 0, 0};
    *det_min = INFINITY;
    /* the Gauss points in antipodal pairs, so that for a parallelepiped
     * (a_4..a_7 = 0: the same det J at every point) the pairs' moments
     * cancel exactly and the centroid is a_0 */
    for (int pair = 0; pair < 4; pair++) {
        double pair_moment[3] = {0, 0, 0};
        for (int side = 0; side < 2; side++) {
            const double sg = side ? -1.0 : 1.0;
            const double s = sg * (pair & 1 ? g : -g), t = sg * (pair & 2 ? g : -g), u = sg * -g;
            double js[3], jt[3], ju[3], dx[3];
            for (int d = 0; d < 3; d++) {
                js[d] = a[1][d] + a[4][d] * t + a[6][d] * u + a[7][d] * t * u;
                jt[d] = a[2][d] + a[4][d] * s + a[5][d] * u + a[7][d] * s * u;
                ju[d] = a[3][d] + a[5][d] * t + a[6][d] * s + a[7][d] * s * t;
                dx[d] = a[1][d] * s + a[2][d] * t + a[3][d] * u + a[4][d] * s * t +
                        a[5][d] * t * u + a[6][d] * s * u + a[7][d] * s * t * u;
            }
            const double det = det3(js, jt, ju);
            if (det < *det_min) *det_min = det;
            vol += det;
            for (int d = 0; d < 3; d++) pair_moment[d] += det * dx[d];
        }
        for (int d = 0; d < 3; d++) moment[d] += pair_moment[d];
    }
    *volume = vol;
    for (int d = 0; d < 3; d++) c[d] = vol > 0.0 ? a[0][d] + moment[d] / vol : a[0][d];
}

static int element_geometry(Reader *r, int64_t e) {
    InpMesh *m = r->m;
    const InpShape shape = (InpShape)m->element_shape[e];
    const int nodes = inp_shape_nodes(shape);
    const double *p[8];
    for (int k = 0; k < nodes; k++)
        p[k] = &m->node_x[3 * m->element_node[INP_MAX_ELEMENT_NODES * e + k]];
    const int line = m->element_line[e];
    const long long id = (long long)m->element_id[e];
    double *c = &m->centroid[3 * e], measure;
    if (shape_dim(shape) == 2) {
        for (int k = 1; k < nodes; k++)
            if (p[k][2] != p[0][2])
                return in_file_refuse(
                    r->err, line, 0,
                    "element %lld's nodes have z = %g and %g; expected an area element "
                    "in a plane z = constant (it is taken in the x-y plane)",
                    id, p[0][2], p[k][2]);
        double corner_min;
        int corner;
        area_2d(p, nodes, &measure, c, &corner_min, &corner);
        if (!(measure > 0.0))
            return in_file_refuse(
                r->err, line, 0,
                "element %lld has area %g: %s; expected its nodes counter-clockwise in "
                "the x-y plane (Abaqus's order)",
                id, measure,
                measure < 0.0 ? "inverted (its nodes go clockwise)"
                              : "zero (its nodes on a line, or crossing over)");
        if (corner_min < 0.0)
            return in_file_refuse(
                r->err, line, 0,
                "element %lld is folded (not convex) at its node %lld; expected a "
                "convex quadrilateral with its nodes counter-clockwise",
                id, (long long)m->node_id[m->element_node[INP_MAX_ELEMENT_NODES * e + corner]]);
    } else {
        double det_min;
        volume_3d(p, nodes, &measure, c, &det_min);
        if (!(measure > 0.0))
            return in_file_refuse(
                r->err, line, 0,
                "element %lld has volume %g: %s; expected its nodes in Abaqus's order "
                "(%s)",
                id, measure,
                measure < 0.0 ? "inverted (its nodes in mirrored order)"
                              : "zero (its nodes in a plane)",
                nodes == 4 ? "node 4 on the side from which 1, 2, 3 turn "
                             "counter-clockwise"
                           : "1-4 counter-clockwise seen from 5-8, then 5-8 above "
                             "them");
        if (!(det_min > 0.0))
            return in_file_refuse(
                r->err, line, 0,
                "element %lld is folded (its Jacobian is not positive throughout); "
                "expected a hexahedron that is not turned inside out",
                id);
    }
    if (!isfinite(measure) || !isfinite(c[0]) || !isfinite(c[1]) || !isfinite(c[2]))
        return in_file_refuse(
            r->err, line, 0, "element %lld's %s overflows; expected coordinates of a sensible size",
            id, shape_dim(shape) == 2 ? "area" : "volume");
    m->measure[e] = measure;
    return NSPD_OK;
}

/* The sets' numbers against the nodes and elements: an explicit one must
 * exist, a generated range must hold one that does. */
static int check_sets(Reader *r) {
    const InpMesh *m = r->m;
    for (int k = 0; k < m->set_count; k++) {
        const InpSet *s = &m->sets[k];
        const int64_t *id = s->elements ? m->element_id : m->node_id;
        const int64_t *order = s->elements ? m->element_order : m->node_order;
        const int64_t n = s->elements ? m->element_count : m->node_count;
        const char *what = s->elements ? "element" : "node";
        for (int64_t q = 0; q < s->range_count; q++) {
            const InpRange *g = &s->ranges[q];
            const int64_t lo = lower_bound(id, order, n, g->first);
            const int64_t hi = lower_bound(id, order, n, g->last + 1);
            if (g->generated) {
                bool any = false;
                for (int64_t i = lo; i < hi && !any; i++)
                    any = (id[order[i]] - g->first) % g->step == 0;
                if (!any)
                    return in_file_refuse(r->err, g->line, 0,
                                          "the range %lld to %lld of %s set %s holds no %s any *%s "
                                          "defines; expected a range over defined %ss",
                                          (long long)g->first, (long long)g->last, what, s->name,
                                          what, s->elements ? "ELEMENT" : "NODE", what);
                continue;
            }
            if (hi - lo == g->last - g->first + 1) continue;
            int64_t missing = g->first; /* the first number of the run not defined */
            for (int64_t i = lo; i < hi && id[order[i]] == missing; i++) missing++;
            return in_file_refuse(
                r->err, g->line, 0,
                "%s set %s names %s %lld, which no *%s defines; expected defined %ss", what,
                s->name, what, (long long)missing, s->elements ? "ELEMENT" : "NODE", what);
        }
    }
    return NSPD_OK;
}

static int finish(Reader *r, int last_line, int64_t size) {
    InpMesh *m = r->m;
    if (r->continuing)
        return in_file_refuse(
            r->err, r->pending_line, 0,
            "element %lld's line ends with a comma but no nodes follow; expected its "
            "%d nodes",
            (long long)r->pending[0], inp_shape_nodes(r->shape));
    TRY(sort_ids(r, m->node_id, m->node_count, r->node_line, "node", &m->node_order));
    if (m->element_count == 0)
        return in_file_refuse(
            r->err, last_line > 0 ? last_line : 0, size,
            "the file defines no element; expected *ELEMENT, TYPE=... and its lines "
            "(an empty mesh)");
    TRY(sort_ids(r, m->element_id, m->element_count, m->element_line, "element",
                 &m->element_order));
    for (int64_t e = 0; e < m->element_count; e++) {
        const int nodes = inp_shape_nodes((InpShape)m->element_shape[e]);
        for (int k = 0; k < nodes; k++) {
            int64_t *slot = &m->element_node[INP_MAX_ELEMENT_NODES * e + k];
            const int64_t node = find_id(m->node_id, m->node_order, m->node_count, *slot);
            if (node < 0)
                return in_file_refuse(
                    r->err, m->element_line[e], 0,
                    "element %lld names node %lld, which no *NODE defines; expected "
                    "defined nodes",
                    (long long)m->element_id[e], (long long)*slot);
            *slot = node;
        }
    }
    TRY(nspd_alloc(&m->centroid, 3 * (size_t)m->element_count, sizeof(double)));
    TRY(nspd_alloc(&m->measure, (size_t)m->element_count, sizeof(double)));
    for (int64_t e = 0; e < m->element_count; e++) TRY(element_geometry(r, e));
    return check_sets(r);
}

static int read_lines(Reader *r, const char *text, int64_t size) {
    const char *p = text, *end = text + size;
    int line = 0;
    while (p < end) {
        const char *nl = memchr(p, '\n', (size_t)(end - p));
        Span l = {p, nl ? nl : end};
        p = nl ? nl + 1 : end;
        r->line = ++line;
        if (l.e > l.s && l.e[-1] == '\r') l.e--;
        l = trim(l);
        if (l.s == l.e) continue;
        if (l.e - l.s >= 2 && l.s[0] == '*' && l.s[1] == '*') continue; /* a comment */
        if (l.s[0] == '*') {
            if (r->continuing)
                return in_file_refuse(
                    r->err, r->line, 0,
                    "a keyword where element %lld's nodes go on (its line ended with "
                    "a comma); expected its remaining nodes",
                    (long long)r->pending[0]);
            Keyword k = {.count = 0};
            Span rest;
            parse_keyword_name(l, &k, &rest);
            TRY(parse_params(r, rest, &k));
            /* a keyword line that ends with a comma goes on on the next */
            while (l.e > l.s && l.e[-1] == ',' && p < end) {
                nl = memchr(p, '\n', (size_t)(end - p));
                l = (Span){p, nl ? nl : end};
                p = nl ? nl + 1 : end;
                r->line = ++line;
                if (l.e > l.s && l.e[-1] == '\r') l.e--;
                l = trim(l);
                TRY(parse_params(r, l, &k));
            }
            TRY(start_block(r, &k));
            continue;
        }
        switch (r->block) {
        case BLOCK_NODE:
            TRY(node_line(r, l));
            break;
        case BLOCK_ELEMENT:
            TRY(element_line(r, l));
            break;
        case BLOCK_SET:
            TRY(set_line(r, l));
            break;
        default: /* before any keyword, or a keyword nspd skips */
            break;
        }
    }
    return finish(r, line, size);
}

int inp_read_text(const char *text, int64_t size, InpMesh *mesh, InpReadError *err) {
    memset(mesh, 0, sizeof *mesh);
    memset(err, 0, sizeof *err);
    if (size > INT32_MAX)
        return in_file_refuse(err, 0, INT32_MAX, "the text is over 2 GiB; expected a smaller mesh");
    Reader r = {.m = mesh, .err = err, .set = -1};
    r.entry_budget = size / 2 + 1024;
    int status = read_lines(&r, text, size);
    nspd_free(&r.node_line);
    if (status != NSPD_OK) inp_mesh_free(mesh);
    return status;
}

int inp_read_file(const char *path, int64_t max_bytes, InpMesh *mesh, InpReadError *err) {
    memset(mesh, 0, sizeof *mesh);
    memset(err, 0, sizeof *err);
    FILE *f = in_file_open(path, &err->os_error);
    if (!f) return NSPD_FAIL(NSPD_ERR_IO, "%s: cannot open it", path); /* err: for the caller's */
    char *data = NULL;
    int64_t size = 0, cap = 0;
    int status = NSPD_OK;
    for (;;) { /* the whole file, up to one byte past the limit */
        if (size == cap) {
            const int64_t grown = cap ? 2 * cap : 1 << 16;
            status = nspd_realloc(&data, (size_t)cap, (size_t)grown + 1, 1);
            if (status != NSPD_OK) break;
            cap = grown;
        }
        const int64_t want = cap - size < max_bytes + 1 - size ? cap - size : max_bytes + 1 - size;
        const size_t got = want > 0 ? fread(data + size, 1, (size_t)want, f) : 0;
        size += (int64_t)got;
        if (got == 0 || size > max_bytes) break;
    }
    fclose(f);
    if (status == NSPD_OK && size > max_bytes)
        status =
            in_file_refuse(err, 0, max_bytes,
                           "the file is larger than %lld bytes; expected a mesh of at most %lld "
                           "bytes",
                           (long long)max_bytes, (long long)max_bytes);
    if (status == NSPD_OK) {
        InpReadError inner;
        status = inp_read_text(data, size, mesh, &inner);
        const int os = err->os_error;
        *err = inner;
        err->os_error = os;
    }
    nspd_free(&data);
    return status;
}

void inp_mesh_free(InpMesh *mesh) {
    nspd_free(&mesh->node_id);
    nspd_free(&mesh->node_x);
    nspd_free(&mesh->element_id);
    nspd_free(&mesh->element_shape);
    nspd_free(&mesh->element_line);
    nspd_free(&mesh->element_node);
    nspd_free(&mesh->centroid);
    nspd_free(&mesh->measure);
    nspd_free(&mesh->node_order);
    nspd_free(&mesh->element_order);
    for (int k = 0; k < mesh->set_count; k++) nspd_free(&mesh->sets[k].ranges);
    nspd_free(&mesh->sets);
    memset(mesh, 0, sizeof *mesh);
}

const InpSet *inp_find_set(const InpMesh *mesh, const char *name, bool elements) {
    char key[INP_MAX_NAME];
    snprintf(key, sizeof key, "%s", name);
    upper(key);
    const int k = set_index(mesh, key, elements);
    return k >= 0 ? &mesh->sets[k] : NULL;
}

int64_t inp_set_mark(const InpMesh *mesh, const InpSet *set, uint8_t *mark) {
    const int64_t *id = set->elements ? mesh->element_id : mesh->node_id;
    const int64_t *order = set->elements ? mesh->element_order : mesh->node_order;
    const int64_t n = set->elements ? mesh->element_count : mesh->node_count;
    int64_t marked = 0;
    for (int64_t q = 0; q < set->range_count; q++) {
        const InpRange *g = &set->ranges[q];
        const int64_t hi = lower_bound(id, order, n, g->last + 1);
        for (int64_t i = lower_bound(id, order, n, g->first); i < hi; i++) {
            const int64_t k = order[i];
            if ((id[k] - g->first) % g->step != 0 || mark[k]) continue;
            mark[k] = 1;
            marked++;
        }
    }
    return marked;
}
