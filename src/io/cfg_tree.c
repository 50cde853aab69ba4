/* YAML -> CfgNode tree with libyaml's event parser, and back with its emitter.
 * Anchors and aliases are refused: case files are small and explicit, and an
 * alias would make one node appear under two paths. */
#include "io/cfg_tree.h"

#include "core/status.h"
#include "core/out_file.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <yaml.h>

/* ------------------------------------------------------------ nodes */

static char *dup_string(const char *s) {
    size_t n = strlen(s) + 1;
    char *d = malloc(n);
    if (d) memcpy(d, s, n);
    return d;
}

static CfgNode *node_new(CfgKind kind, const char *file, int line, int col, CfgOrigin origin) {
    CfgNode *node = calloc(1, sizeof *node);
    if (!node) return NULL;
    node->kind = kind;
    node->file = file;
    node->line = line;
    node->col = col;
    node->origin = origin;
    return node;
}

static void node_free(CfgNode *node) {
    if (!node) return;
    for (int i = 0; i < node->count; i++) node_free(node->child[i]);
    free(node->child);
    free(node->text);
    free(node->key);
    for (int i = 0; i < node->asked_count; i++) free(node->asked[i]);
    free(node->asked);
    free(node);
}

void cfg_node_free(CfgNode *node) {
    node_free(node);
}

static int node_append(CfgNode *parent, CfgNode *child) {
    if (parent->count == parent->cap) {
        int cap = parent->cap ? 2 * parent->cap : 8;
        CfgNode **grown = realloc(parent->child, (size_t)cap * sizeof *grown);
        if (!grown) return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory reading a case file");
        parent->child = grown;
        parent->cap = cap;
    }
    child->parent = parent;
    child->index = parent->count;
    parent->child[parent->count++] = child;
    return NSPD_OK;
}

/* Puts `node` (key and all) in the place of `old` under old's parent, and
 * frees `old`. */
static void node_replace(CfgNode *old, CfgNode *node) {
    CfgNode *parent = old->parent;
    node->key = old->key;
    old->key = NULL;
    node->index = old->index;
    node->parent = parent;
    parent->child[old->index] = node;
    node_free(old);
}

static bool scalar_is_null(const char *text, bool quoted) {
    return !quoted && (text[0] == '\0' || strcmp(text, "~") == 0 || strcmp(text, "null") == 0 ||
                       strcmp(text, "Null") == 0 || strcmp(text, "NULL") == 0);
}

/* map[key] without recording the key (the parser's and --set's lookups). */
static CfgNode *lookup(const CfgNode *map, const char *key) {
    if (!map || map->kind != CFG_MAP) return NULL;
    for (int i = 0; i < map->count; i++)
        if (strcmp(map->child[i]->key, key) == 0) return map->child[i];
    return NULL;
}

bool cfg_map_asked(const CfgNode *map, const char *key) {
    for (int i = 0; map && i < map->asked_count; i++)
        if (strcmp(map->asked[i], key) == 0) return true;
    return false;
}

static void record_asked(CfgNode *map, const char *key) {
    if (cfg_map_asked(map, key)) return;
    if (map->asked_count == map->asked_cap) {
        const int cap = map->asked_cap ? 2 * map->asked_cap : 8;
        char **grown = realloc(map->asked, (size_t)cap * sizeof *grown);
        if (!grown) return;
        map->asked = grown;
        map->asked_cap = cap;
    }
    char *copy = dup_string(key);
    if (copy) map->asked[map->asked_count++] = copy;
}

CfgNode *cfg_map_find(const CfgNode *map, const char *key) {
    if (!map || map->kind != CFG_MAP) return NULL;
    /* every tree's nodes are allocated by it, none is a const object: the
     * record is bookkeeping of the schema's reading, like `used` */
    record_asked((CfgNode *)map, key);
    return lookup(map, key);
}

CfgNode *cfg_node_clone(const CfgNode *node, CfgNode *parent) {
    CfgNode *copy = node_new(node->kind, node->file, node->line, node->col, node->origin);
    if (!copy) return NULL;
    copy->quoted = node->quoted;
    copy->is_null = node->is_null;
    copy->index = node->index;
    copy->parent = parent;
    if ((node->text && !(copy->text = dup_string(node->text))) ||
        (node->key && !(copy->key = dup_string(node->key)))) {
        node_free(copy);
        return NULL;
    }
    for (int i = 0; i < node->count; i++) {
        CfgNode *child = cfg_node_clone(node->child[i], copy);
        if (!child || node_append(copy, child) != NSPD_OK) {
            node_free(child);
            node_free(copy);
            return NULL;
        }
    }
    return copy;
}

CfgNode *cfg_map_add_scalar(CfgNode *map, const char *key, const char *text, CfgOrigin origin) {
    CfgNode *node = node_new(CFG_SCALAR, map->file, 0, 0, origin);
    if (!node) return NULL;
    node->key = dup_string(key);
    node->text = dup_string(text);
    if (!node->key || !node->text || node_append(map, node) != NSPD_OK) {
        node_free(node);
        return NULL;
    }
    node->is_null = scalar_is_null(text, false);
    return node;
}

CfgNode *cfg_map_add_collection(CfgNode *map, const char *key, CfgKind kind, CfgOrigin origin) {
    CfgNode *node = node_new(kind, map->file, 0, 0, origin);
    if (!node) return NULL;
    node->key = dup_string(key);
    if (!node->key || node_append(map, node) != NSPD_OK) {
        node_free(node);
        return NULL;
    }
    return node;
}

CfgNode *cfg_seq_add_scalar(CfgNode *seq, const char *text, CfgOrigin origin) {
    CfgNode *node = node_new(CFG_SCALAR, seq->file, 0, 0, origin);
    if (!node) return NULL;
    node->text = dup_string(text);
    if (!node->text || node_append(seq, node) != NSPD_OK) {
        node_free(node);
        return NULL;
    }
    return node;
}

void cfg_node_path(const CfgNode *node, char *buf, int size) {
    const CfgNode *chain[64];
    int depth = 0;
    for (const CfgNode *n = node; n && n->parent && depth < 64; n = n->parent) chain[depth++] = n;
    int len = 0;
    buf[0] = '\0';
    for (int d = depth - 1; d >= 0 && len < size; d--) {
        const CfgNode *n = chain[d];
        if (n->key)
            len += snprintf(buf + len, (size_t)(size - len), "%s%s", len ? "." : "", n->key);
        else
            len += snprintf(buf + len, (size_t)(size - len), "[%d]", n->index);
    }
    if (depth == 0) snprintf(buf, (size_t)size, "(top level)");
}

void cfg_node_where(const CfgNode *node, char *buf, int size) {
    while (node->origin == CFG_FROM_DEFAULT && node->parent) node = node->parent;
    if (node->origin == CFG_FROM_OVERRIDE) {
        /* the node inherits the text of the --set that created it */
        snprintf(buf, (size_t)size, "--set %s", node->file);
    } else {
        snprintf(buf, (size_t)size, "%s:%d:%d", node->file, node->line ? node->line : 1,
                 node->col ? node->col : 1);
    }
}

void cfg_node_place(const CfgNode *node, char *buf, int size) {
    char where[320], path[64];
    cfg_node_where(node, where, sizeof where);
    cfg_node_path(node, path, sizeof path);
    snprintf(buf, (size_t)size, "%s: %s", where, path);
}

/* ------------------------------------------------------------ parsing */

/* Maps and sequences nest at most this deep. A case file needs 6 levels;
 * the limit keeps the recursive reader (and every walk of the tree) within
 * its stack whatever a file holds: a file nested 100,000 levels once
 * crashed `nspd check`. */
enum { CFG_MAX_DEPTH = 64 };
/* The other bounds on what a case file may hold, each far above what a case
 * needs (the largest case file is 3 kB; long polygons come from their own
 * CSV files): what a generated or corrupted file can make the reader
 * allocate stays small. */
enum {
    CFG_MAX_FILE_BYTES = 16 << 20, /* 16 MiB */
    CFG_MAX_SCALAR = 4096,         /* characters in one value */
    CFG_MAX_ITEMS = 100000,        /* entries in one list or map */
};

typedef struct {
    yaml_parser_t parser;
    const char *file;
    CfgOrigin origin;
    int depth; /* of the collection being read */
    bool depth_exceeded;
} Reader;

static int syntax_error(Reader *r) {
    yaml_parser_t *p = &r->parser;
    const char *problem = p->problem ? p->problem : "malformed YAML";
    int line = (int)p->problem_mark.line + 1, col = (int)p->problem_mark.column + 1;
    if (p->context)
        return NSPD_FAIL(NSPD_ERR_INPUT, "%s:%d:%d: YAML syntax error: %s %s; expected valid YAML",
                         r->file, line, col, problem, p->context);
    return NSPD_FAIL(NSPD_ERR_INPUT, "%s:%d:%d: YAML syntax error: %s; expected valid YAML",
                     r->file, line, col, problem);
}

static int next_event(Reader *r, yaml_event_t *event) {
    if (!yaml_parser_parse(&r->parser, event)) return syntax_error(r);
    return NSPD_OK;
}

static int parse_node(Reader *r, yaml_event_t *event, CfgNode **out);

/* Reads children until the closing event of a map or sequence. */
static int parse_children(Reader *r, CfgNode *node, yaml_event_type_t end) {
    for (;;) {
        yaml_event_t event;
        TRY(next_event(r, &event));
        if (event.type == end) {
            yaml_event_delete(&event);
            return NSPD_OK;
        }
        if (node->count >= CFG_MAX_ITEMS) {
            yaml_event_delete(&event);
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "%s:%d:%d: more than %d entries in one %s; expected a case file",
                             r->file, node->line, node->col, CFG_MAX_ITEMS,
                             node->kind == CFG_MAP ? "map" : "list");
        }
        char *key = NULL;
        int key_line = 0, key_col = 0;
        if (node->kind == CFG_MAP) {
            if (event.type != YAML_SCALAR_EVENT) {
                int line = (int)event.start_mark.line + 1, col = (int)event.start_mark.column + 1;
                yaml_event_delete(&event);
                return NSPD_FAIL(NSPD_ERR_INPUT,
                                 "%s:%d:%d: a map key must be a plain word; expected 'key: value'",
                                 r->file, line, col);
            }
            key = dup_string((const char *)event.data.scalar.value);
            key_line = (int)event.start_mark.line + 1;
            key_col = (int)event.start_mark.column + 1;
            yaml_event_delete(&event);
            if (!key) return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory reading a case file");
            const CfgNode *twin = lookup(node, key);
            if (twin) {
                int status = NSPD_FAIL(NSPD_ERR_INPUT,
                                       "%s:%d:%d: duplicate key '%s' (first given at line %d); "
                                       "expected each key once",
                                       r->file, key_line, key_col, key, twin->line);
                free(key);
                return status;
            }
            int status = next_event(r, &event);
            if (status != NSPD_OK) {
                free(key);
                return status;
            }
        }
        CfgNode *child = NULL;
        int status = parse_node(r, &event, &child);
        if (status == NSPD_OK) status = node_append(node, child);
        if (status != NSPD_OK) {
            node_free(child);
            free(key);
            return status;
        }
        if (key) {
            child->key = key;
            /* messages about a value point at its key: that is where users look */
            child->line = key_line;
            child->col = key_col;
        }
    }
}

/* Builds the node that starts with `event` (consumed). */
static int parse_node(Reader *r, yaml_event_t *event, CfgNode **out) {
    int line = (int)event->start_mark.line + 1, col = (int)event->start_mark.column + 1;
    *out = NULL;
    switch (event->type) {
    case YAML_SCALAR_EVENT: {
        if (event->data.scalar.length > CFG_MAX_SCALAR) {
            const size_t length = event->data.scalar.length;
            yaml_event_delete(event);
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "%s:%d:%d: a value of %zu characters; expected at most %d", r->file,
                             line, col, length, CFG_MAX_SCALAR);
        }
        CfgNode *node = node_new(CFG_SCALAR, r->file, line, col, r->origin);
        if (!node) break;
        node->text = dup_string((const char *)event->data.scalar.value);
        node->quoted = event->data.scalar.style == YAML_SINGLE_QUOTED_SCALAR_STYLE ||
                       event->data.scalar.style == YAML_DOUBLE_QUOTED_SCALAR_STYLE;
        yaml_event_delete(event);
        if (!node->text) {
            node_free(node);
            break;
        }
        node->is_null = scalar_is_null(node->text, node->quoted);
        *out = node;
        return NSPD_OK;
    }
    case YAML_MAPPING_START_EVENT:
    case YAML_SEQUENCE_START_EVENT: {
        bool is_map = event->type == YAML_MAPPING_START_EVENT;
        yaml_event_delete(event);
        if (r->depth >= CFG_MAX_DEPTH) {
            r->depth_exceeded = true;
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "%s:%d:%d: maps and lists nested more than %d deep; expected a case "
                             "file (its sections nest a few levels)",
                             r->file, line, col, CFG_MAX_DEPTH);
        }
        CfgNode *node = node_new(is_map ? CFG_MAP : CFG_SEQ, r->file, line, col, r->origin);
        if (!node) break;
        r->depth++;
        int status =
            parse_children(r, node, is_map ? YAML_MAPPING_END_EVENT : YAML_SEQUENCE_END_EVENT);
        r->depth--;
        if (status != NSPD_OK) {
            node_free(node);
            return status;
        }
        *out = node;
        return NSPD_OK;
    }
    case YAML_ALIAS_EVENT:
        yaml_event_delete(event);
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "%s:%d:%d: YAML aliases (*name) are not supported; expected the value "
                         "written out",
                         r->file, line, col);
    default:
        yaml_event_delete(event);
        return NSPD_FAIL(NSPD_ERR_INPUT, "%s:%d:%d: unexpected YAML structure; expected a value",
                         r->file, line, col);
    }
    return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory reading a case file");
}

/* Parses one YAML document; *root may be a scalar (for --set values). An
 * empty stream gives *root = NULL. */
static int parse_document(Reader *r, CfgNode **root) {
    yaml_event_t event;
    *root = NULL;
    TRY(next_event(r, &event)); /* STREAM_START */
    yaml_event_delete(&event);
    TRY(next_event(r, &event));
    if (event.type == YAML_STREAM_END_EVENT) {
        yaml_event_delete(&event);
        return NSPD_OK;
    }
    yaml_event_delete(&event); /* DOCUMENT_START */
    TRY(next_event(r, &event));
    if (event.type == YAML_MAPPING_START_EVENT || event.type == YAML_SEQUENCE_START_EVENT) {
        /* anchors on collections are refused too, for the same reason as aliases */
        const yaml_char_t *anchor = event.type == YAML_MAPPING_START_EVENT
                                        ? event.data.mapping_start.anchor
                                        : event.data.sequence_start.anchor;
        if (anchor) {
            int line = (int)event.start_mark.line + 1, col = (int)event.start_mark.column + 1;
            yaml_event_delete(&event);
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "%s:%d:%d: YAML anchors (&name) are not supported; expected plain "
                             "values",
                             r->file, line, col);
        }
    }
    TRY(parse_node(r, &event, root));
    int status = next_event(r, &event); /* DOCUMENT_END */
    if (status == NSPD_OK) {
        yaml_event_delete(&event);
        status = next_event(r, &event);
    }
    if (status == NSPD_OK && event.type != YAML_STREAM_END_EVENT) {
        int line = (int)event.start_mark.line + 1;
        yaml_event_delete(&event);
        status = NSPD_FAIL(NSPD_ERR_INPUT,
                           "%s:%d:1: a second YAML document ('---'); expected one case per file",
                           r->file, line);
    } else if (status == NSPD_OK) {
        yaml_event_delete(&event);
    }
    if (status != NSPD_OK) {
        node_free(*root);
        *root = NULL;
    }
    return status;
}

static int load(CfgDoc *doc, const char *name, const unsigned char *text, size_t length) {
    memset(doc, 0, sizeof *doc);
    doc->file = dup_string(name);
    if (!doc->file) return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory reading a case file");
    Reader r = {.file = doc->file, .origin = CFG_FROM_FILE};
    if (!yaml_parser_initialize(&r.parser)) {
        cfg_doc_free(doc);
        return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory starting the YAML parser");
    }
    yaml_parser_set_input_string(&r.parser, text, length);
    int status = parse_document(&r, &doc->root);
    yaml_parser_delete(&r.parser);
    if (status == NSPD_OK && !doc->root) {
        doc->root = node_new(CFG_MAP, doc->file, 1, 1, CFG_FROM_FILE);
        if (!doc->root) status = NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
    } else if (status == NSPD_OK && doc->root->kind != CFG_MAP) {
        status = NSPD_FAIL(NSPD_ERR_INPUT,
                           "%s:%d:%d: the case file is a %s; expected a map of 'key: value' "
                           "entries at the top level",
                           doc->file, doc->root->line, doc->root->col,
                           doc->root->kind == CFG_SEQ ? "list" : "single value");
    }
    if (status != NSPD_OK) cfg_doc_free(doc);
    return status;
}

int cfg_doc_load_string(CfgDoc *doc, const char *name, const char *text) {
    return load(doc, name, (const unsigned char *)text, strlen(text));
}

int cfg_doc_load_file(CfgDoc *doc, const char *path) {
    memset(doc, 0, sizeof *doc);
    FILE *f = fopen(path, "rb");
    if (!f) return NSPD_FAIL(NSPD_ERR_IO, "%s: cannot open the case file", path);
    size_t cap = 1 << 16, length = 0;
    unsigned char *text = malloc(cap);
    while (text) {
        length += fread(text + length, 1, cap - length, f);
        /* stop reading as soon as the file is known to be too large */
        if (length > CFG_MAX_FILE_BYTES) {
            free(text);
            fclose(f);
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "%s: larger than %d MiB; expected a case file (a few kB; long "
                             "polygons go in CSV files of their own)",
                             path, CFG_MAX_FILE_BYTES >> 20);
        }
        if (length < cap) break;
        cap *= 2;
        unsigned char *grown = realloc(text, cap);
        if (!grown) free(text);
        text = grown;
    }
    int read_error = ferror(f);
    fclose(f);
    if (!text) return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory reading '%s'", path);
    if (read_error) {
        free(text);
        return NSPD_FAIL(NSPD_ERR_IO, "%s: read error", path);
    }
    int status = load(doc, path, text, length);
    free(text);
    return status;
}

void cfg_doc_free(CfgDoc *doc) {
    node_free(doc->root);
    for (int i = 0; i < doc->override_count; i++) free(doc->override_texts[i]);
    free(doc->override_texts);
    free(doc->file);
    memset(doc, 0, sizeof *doc);
}

/* ------------------------------------------------------------ overrides */

static void mark_origin(CfgNode *node, const char *file) {
    node->origin = CFG_FROM_OVERRIDE;
    node->file = file;
    node->line = node->col = 0;
    for (int i = 0; i < node->count; i++) mark_origin(node->child[i], file);
}

static bool is_index(const char *s) {
    if (!*s) return false;
    for (; *s; s++)
        if (*s < '0' || *s > '9') return false;
    return true;
}

/* The key path as messages print it (cfg_node_path: "a.b[0].c") into
 * the dotted one the walk below takes ("a.b.0.c"), into out (len + 1 bytes
 * at least: the dotted form is never longer). False for a bracket that
 * holds no index or does not end one segment. */
static bool bracketed_to_dotted(const char *text, size_t len, char *out) {
    size_t o = 0;
    for (size_t i = 0; i < len; i++) {
        if (text[i] == ']') return false; /* one without its '[' */
        if (text[i] != '[') {
            out[o++] = text[i];
            continue;
        }
        size_t j = i + 1;
        while (j < len && text[j] >= '0' && text[j] <= '9') j++;
        if (j == i + 1 || j >= len || text[j] != ']' || i == 0) return false;
        if (j + 1 < len && text[j + 1] != '.' && text[j + 1] != '[') return false;
        out[o++] = '.';
        memcpy(out + o, text + i + 1, j - i - 1);
        o += j - i - 1;
        i = j; /* past the ']' */
    }
    out[o] = '\0';
    return true;
}

int cfg_doc_override(CfgDoc *doc, const char *assignment) {
    const char *eq = strchr(assignment, '=');
    if (!eq || eq == assignment)
        return NSPD_FAIL(NSPD_ERR_INPUT, "--set %s: expected dotted.key=value", assignment);
    char **grown = realloc(doc->override_texts, (size_t)(doc->override_count + 1) * sizeof *grown);
    if (!grown) return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
    doc->override_texts = grown;
    char *text = dup_string(assignment);
    if (!text) return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
    doc->override_texts[doc->override_count++] = text;

    /* parse the value as a YAML document of its own */
    CfgNode *value = NULL;
    Reader r = {.file = text, .origin = CFG_FROM_OVERRIDE};
    if (!yaml_parser_initialize(&r.parser)) return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
    const char *value_text = eq + 1;
    yaml_parser_set_input_string(&r.parser, (const unsigned char *)value_text, strlen(value_text));
    int status = parse_document(&r, &value);
    yaml_parser_delete(&r.parser);
    if (status != NSPD_OK && r.depth_exceeded)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "--set %s: the value's lists and maps are nested more than %d deep; "
                         "expected a number, word, or [list]",
                         assignment, CFG_MAX_DEPTH);
    if (status != NSPD_OK)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "--set %s: the value is not valid YAML; expected a "
                         "number, word, or [list]",
                         assignment);
    if (!value) {
        value = node_new(CFG_SCALAR, text, 0, 0, CFG_FROM_OVERRIDE);
        if (!value || !(value->text = dup_string(""))) {
            node_free(value);
            return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
        }
        value->is_null = true;
    }
    mark_origin(value, text);

    /* walk the dotted path, creating maps as needed */
    size_t path_len = (size_t)(eq - assignment);
    char path[512];
    if (path_len >= sizeof path) {
        node_free(value);
        return NSPD_FAIL(NSPD_ERR_INPUT, "--set %s: key path too long", assignment);
    }
    if (!bracketed_to_dotted(assignment, path_len, path)) {
        node_free(value);
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "--set %s: a '[' or ']' that is not a list index; expected "
                         "key[N] (or key.N) with N the item's number",
                         assignment);
    }
    CfgNode *node = doc->root;
    char *save = NULL;
    char *segment = strtok_r(path, ".", &save);
    while (segment) {
        char *next = strtok_r(NULL, ".", &save);
        CfgNode *child = NULL;
        if (node->kind == CFG_SEQ) {
            /* nine digits at most: a longer one would wrap an int */
            const int idx = is_index(segment) && strlen(segment) <= 9 ? atoi(segment) : -1;
            if (idx < 0 || idx >= node->count) {
                node_free(value);
                return NSPD_FAIL(NSPD_ERR_INPUT,
                                 "--set %s: '%s' is not an item of a %d-item list; expected an "
                                 "index from 0 to %d",
                                 assignment, segment, node->count, node->count - 1);
            }
            child = node->child[idx];
        } else if (node->kind == CFG_MAP) {
            child = lookup(node, segment);
        } else {
            node_free(value);
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "--set %s: '%s' is inside a single value; expected a path of maps",
                             assignment, segment);
        }
        if (!next) { /* last segment: put the value here */
            if (child) {
                node_replace(child, value);
            } else {
                value->key = dup_string(segment);
                if (!value->key || node_append(node, value) != NSPD_OK) {
                    node_free(value);
                    return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
                }
            }
            return NSPD_OK;
        }
        if (!child) {
            child = node_new(CFG_MAP, text, 0, 0, CFG_FROM_OVERRIDE);
            if (!child || !(child->key = dup_string(segment)) ||
                node_append(node, child) != NSPD_OK) {
                node_free(child);
                node_free(value);
                return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
            }
        }
        node = child;
        segment = next;
    }
    node_free(value);
    return NSPD_FAIL(NSPD_ERR_INPUT, "--set %s: empty key path; expected dotted.key=value",
                     assignment);
}

/* ------------------------------------------------------------ writing */

static bool emit_scalar(yaml_emitter_t *e, const char *text, bool quoted) {
    yaml_event_t event;
    yaml_scalar_style_t style = quoted ? YAML_DOUBLE_QUOTED_SCALAR_STYLE : YAML_ANY_SCALAR_STYLE;
    yaml_scalar_event_initialize(&event, NULL, NULL, (yaml_char_t *)text, (int)strlen(text), 1, 1,
                                 style);
    return yaml_emitter_emit(e, &event);
}

static bool all_scalars(const CfgNode *node) {
    for (int i = 0; i < node->count; i++)
        if (node->child[i]->kind != CFG_SCALAR) return false;
    return true;
}

static bool emit_node(yaml_emitter_t *e, const CfgNode *node) {
    yaml_event_t event;
    if (node->kind == CFG_SCALAR)
        return emit_scalar(e, node->is_null ? "~" : node->text, node->quoted);
    if (node->kind == CFG_MAP) {
        yaml_mapping_start_event_initialize(&event, NULL, NULL, 1, YAML_BLOCK_MAPPING_STYLE);
        if (!yaml_emitter_emit(e, &event)) return false;
        for (int i = 0; i < node->count; i++)
            if (!emit_scalar(e, node->child[i]->key, false) || !emit_node(e, node->child[i]))
                return false;
        yaml_mapping_end_event_initialize(&event);
        return yaml_emitter_emit(e, &event);
    }
    /* short lists of numbers read best inline: [x, y] */
    yaml_sequence_style_t style =
        all_scalars(node) ? YAML_FLOW_SEQUENCE_STYLE : YAML_BLOCK_SEQUENCE_STYLE;
    yaml_sequence_start_event_initialize(&event, NULL, NULL, 1, style);
    if (!yaml_emitter_emit(e, &event)) return false;
    for (int i = 0; i < node->count; i++)
        if (!emit_node(e, node->child[i])) return false;
    yaml_sequence_end_event_initialize(&event);
    return yaml_emitter_emit(e, &event);
}

int cfg_doc_write(const CfgDoc *doc, FILE *out) {
    yaml_emitter_t e;
    yaml_event_t event;
    if (!yaml_emitter_initialize(&e)) return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
    yaml_emitter_set_output_file(&e, out);
    yaml_emitter_set_width(&e, 100);
    yaml_emitter_set_unicode(&e, 1);
    bool ok = true;
    yaml_stream_start_event_initialize(&event, YAML_UTF8_ENCODING);
    ok = ok && yaml_emitter_emit(&e, &event);
    yaml_document_start_event_initialize(&event, NULL, NULL, NULL, 1);
    ok = ok && yaml_emitter_emit(&e, &event);
    ok = ok && emit_node(&e, doc->root);
    yaml_document_end_event_initialize(&event, 1);
    ok = ok && yaml_emitter_emit(&e, &event);
    yaml_stream_end_event_initialize(&event);
    ok = ok && yaml_emitter_emit(&e, &event);
    yaml_emitter_delete(&e);
    if (!ok) return NSPD_FAIL(NSPD_ERR_IO, "cannot write the resolved case");
    return NSPD_OK;
}

int cfg_doc_save(const CfgDoc *doc, const char *path, const char *header) {
    OutFile out;
    TRY(out_file_open(&out, path));
    fputs(header, out.f);
    int status = cfg_doc_write(doc, out.f);
    if (status != NSPD_OK) {
        out_file_abort(&out);
        return status;
    }
    return out_file_close(&out, 0);
}
