/* A YAML document as a tree that remembers where each value came from.
 *
 * Invariants:
 *  - every node knows its file and 1-based line/column (0 for nodes that did
 *    not come from the file: --set overrides and schema defaults), its
 *    parent, and its key (maps) or index (sequences), so any message can name
 *    both the place in the file and the dotted key path;
 *  - map keys are unique (duplicates are refused at load time);
 *  - `used` marks map entries consumed by the schema; what is left unused
 *    after reading is an unknown key;
 *  - a map's `asked` holds every key the schema looked up in it
 *    (cfg_map_find, which every getter calls), given or not: the keys the
 *    map accepts, from which an unknown key's did-you-mean is chosen;
 *  - a scalar keeps its text exactly; `quoted` scalars are strings only.
 * The tree owns all its memory; cfg_doc_free releases it. */
#ifndef NSPD_IO_CFG_TREE_H
#define NSPD_IO_CFG_TREE_H

#include <stdbool.h>
#include <stdio.h>

typedef enum { CFG_SCALAR, CFG_MAP, CFG_SEQ } CfgKind;
typedef enum { CFG_FROM_FILE, CFG_FROM_OVERRIDE, CFG_FROM_DEFAULT } CfgOrigin;

typedef struct CfgNode CfgNode;
struct CfgNode {
    CfgKind kind;
    CfgOrigin origin;
    const char *file; /* the document's file name, or the --set text for overrides */
    int line, col;    /* 1-based; 0 when not from the file */
    char *text;       /* SCALAR: the value as written */
    bool quoted;      /* SCALAR: written in quotes, so never a number or bool */
    bool is_null;     /* SCALAR: ~, null or empty */
    CfgNode *parent;
    char *key;    /* key in the parent map; NULL in a sequence or at the root */
    int index;    /* position in the parent sequence */
    bool used;    /* read by the schema */
    char **asked; /* MAP: the keys looked up in it, each once, in order */
    int asked_count, asked_cap;
    int count, cap; /* MAP, SEQ: children */
    CfgNode **child;
};

typedef struct {
    char *file;
    CfgNode *root;         /* always a map (an empty document is an empty map) */
    char **override_texts; /* the --set strings, owned here so nodes can point at them */
    int override_count;
} CfgDoc;

/* Parses a YAML file / string into *doc. NSPD_ERR_INPUT with a message
 * "FILE:LINE:COL: what; expected" for syntax errors, duplicate keys, aliases,
 * multiple documents or a top level that is not a map. NSPD_ERR_IO if the
 * file cannot be read. */
int cfg_doc_load_file(CfgDoc *doc, const char *path);
int cfg_doc_load_string(CfgDoc *doc, const char *name, const char *text);
void cfg_doc_free(CfgDoc *doc);

/* Applies "dotted.key=value" (sequence items by number: "a.b.0.c=1", or
 * as messages print paths, "a.b[0].c=1"). The
 * value is parsed as YAML, so "[1, 2]" gives a sequence. Missing maps on the
 * path are created; a missing sequence item is an error. */
int cfg_doc_override(CfgDoc *doc, const char *assignment);

/* Writes the tree as YAML (the resolved case: file values, overrides and the
 * defaults the schema filled in). */
int cfg_doc_write(const CfgDoc *doc, FILE *out);
/* Writes `header` (comment lines, each starting with '#') and the document
 * to `path`. NSPD_ERR_IO, with the OS's reason, if it cannot. */
int cfg_doc_save(const CfgDoc *doc, const char *path, const char *header);

/* map[key], or NULL. Records `key` in map->asked (the one thing a lookup
 * changes; a failed allocation only loses the suggestion), so call it for
 * keys the schema accepts: the case readers' lookups. */
CfgNode *cfg_map_find(const CfgNode *map, const char *key);
/* Whether the schema looked `key` up in `map`. */
bool cfg_map_asked(const CfgNode *map, const char *key);
/* A deep copy of `node` (keys, texts, places; `used` and `asked` cleared)
 * whose parent is `parent`, which does not list it: messages about the
 * copy name the original's path. NULL on allocation failure; free it with
 * cfg_node_free. */
CfgNode *cfg_node_clone(const CfgNode *node, CfgNode *parent);
void cfg_node_free(CfgNode *node);
/* Adds key -> new scalar / empty collection to a map, or a scalar to a
 * sequence (key NULL); returns the new node or NULL on allocation failure. */
CfgNode *cfg_map_add_scalar(CfgNode *map, const char *key, const char *text, CfgOrigin origin);
CfgNode *cfg_map_add_collection(CfgNode *map, const char *key, CfgKind kind, CfgOrigin origin);
CfgNode *cfg_seq_add_scalar(CfgNode *seq, const char *text, CfgOrigin origin);

/* "solid.boundaries[1].velocity" */
void cfg_node_path(const CfgNode *node, char *buf, int size);
/* "case.yaml:12:5", or "--set a.b=1" for overrides, or the parent's place for
 * defaults. */
void cfg_node_where(const CfgNode *node, char *buf, int size);
/* "case.yaml:12:5: solid.boundaries[1]": where and what, the prefix of a
 * refusal that a model finds when it is built (SolidConfig.where, ...). */
void cfg_node_place(const CfgNode *node, char *buf, int size);

#endif
