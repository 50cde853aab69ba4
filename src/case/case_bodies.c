/* The `bodies:` list of a case file (keys in case_bodies.h). */
#include "case/case_bodies.h"

#include "case/case_shapes.h"
#include "core/mem.h"
#include "core/status.h"
#include "io/cfg_read.h"
#include "io/in_file.h"
#include "io/xy_read.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { DEFAULT_MARKERS = 1024, DEFAULT_MARKERS_PER_SIDE = 64 };

static int read_markers(CfgNode *item, const char *key, int64_t def, int64_t lo, int *out) {
    int64_t v;
    TRY(cfg_opt_int(item, key, def, &v));
    if (v < lo || v > 10000000)
        return cfg_fail_at(item, key, "%lld markers; expected %lld to 10000000", (long long)v,
                           (long long)lo);
    *out = (int)v;
    return NSPD_OK;
}

static int check_polygon(CfgNode *item, IbmBodyConfig *b);

static int read_csv(CfgNode *item, IbmBodyConfig *b) {
    const char *file;
    TRY(cfg_req_string(item, "file", &file));
    cfg_resolve_path(cfg_map_find(item, "file"), file, b->path, sizeof b->path);
    int n;
    XyReadError err;
    const int st = xy_read_file(b->path, &b->vertices, &n, &err);
    if (st == NSPD_ERR_IO)
        return cfg_fail_at(item, "file", "cannot read '%s' (%s); expected a CSV file of x, y",
                           b->path, in_file_error(err.os_error));
    if (st == NSPD_ERR_INPUT)
        return cfg_fail_at(item, "file",
                           "%s:%d: '%s' is not a vertex; expected two numbers x, y per line",
                           b->path, err.line, err.text);
    TRY(st);
    b->vertex_count = n;
    return check_polygon(item, b);
}

/* The vertices of a polygon body (from a CSV file or an STL section):
 * at least 3, around an area, no two consecutive ones equal; then its
 * max_spacing. */
static int check_polygon(CfgNode *item, IbmBodyConfig *b) {
    const int n = b->vertex_count;
    if (n < 3)
        return cfg_fail_at(item, "file", "'%s' has %d vertices; expected at least 3", b->path, n);
    double area = 0.0;
    for (int i = 0; i < n; i++) {
        const int j = (i + 1) % n;
        area += b->vertices[2 * i] * b->vertices[2 * j + 1] -
                b->vertices[2 * j] * b->vertices[2 * i + 1];
    }
    if (area == 0.0)
        return cfg_fail_at(item, "file",
                           "the polygon in '%s' has zero area; expected vertices "
                           "around an area",
                           b->path);
    for (int i = 0; i < n; i++) {
        const int j = (i + 1) % n;
        if (b->vertices[2 * i] == b->vertices[2 * j] &&
            b->vertices[2 * i + 1] == b->vertices[2 * j + 1])
            return cfg_fail_at(item, "file",
                               "'%s': vertices %d and %d coincide; expected "
                               "distinct consecutive vertices",
                               b->path, i + 1, j + 1);
    }
    TRY(cfg_opt_double(item, "max_spacing", 0.0, &b->max_spacing));
    if (b->max_spacing < 0.0)
        return cfg_fail_at(item, "max_spacing", "%g is negative; expected a length in m or 0",
                           b->max_spacing);
    return NSPD_OK;
}

/* {shape: stl, file, scale, translate, section_z}: a polygon body, the
 * section of a closed STL surface by the plane z = section_z (after the
 * scale and the translation), core/shape_mesh.h */
static int read_stl_section(CfgNode *item, IbmBodyConfig *b) {
    double z;
    TRY(cfg_opt_double(item, "section_z", 0.0, &z));
    ShapeMesh *m;
    TRY(case_read_stl_mesh(item, &m, b->path, sizeof b->path));
    char why[256];
    const int made = shape_mesh_section(m, z, &b->vertices, &b->vertex_count, why, sizeof why);
    shape_mesh_free(&m);
    if (made == NSPD_ERR_INPUT) return cfg_fail_at(item, "file", "%s: %s", b->path, why);
    TRY(made);
    return check_polygon(item, b);
}

static int read_body(CfgNode *item, int index, IbmBodyConfig *b) {
    if (item->kind != CFG_MAP)
        return cfg_fail(item, "not a body; expected a map such as {shape: circle, center: [x, y], "
                              "radius: r}");
    /* shape: stl is a polygon body from a surface's section (the model
     * sees a polygon) */
    const CfgNode *shape = cfg_map_find(item, "shape");
    const bool stl =
        shape && shape->kind == CFG_SCALAR && shape->text && strcmp(shape->text, "stl") == 0;
    int kind = IBM_BODY_POLYGON;
    if (stl) {
        const char *ignored;
        TRY(cfg_req_string(item, "shape", &ignored));
    } else {
        TRY(cfg_req_enum(item, "shape", IBM_BODY_NAMES, &kind));
    }
    b->kind = (IbmBodyKind)kind;
    char def[IBM_NAME_MAX];
    snprintf(def, sizeof def, "body%d", index);
    const char *name;
    TRY(cfg_opt_string(item, "name", def, &name));
    if (strlen(name) == 0 || strlen(name) >= IBM_NAME_MAX)
        return cfg_fail_at(item, "name", "expected a name of 1 to %d characters", IBM_NAME_MAX - 1);
    for (const char *c = name; *c; c++)
        if (!((*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z') || (*c >= '0' && *c <= '9') ||
              *c == '_' || *c == '-'))
            return cfg_fail_at(item, "name", "'%s' has a '%c'; expected letters, digits, _ or -",
                               name, *c);
    snprintf(b->name, sizeof b->name, "%s", name);
    switch (b->kind) {
    case IBM_BODY_CIRCLE:
        TRY(cfg_req_vec(item, "center", 2, b->center));
        TRY(cfg_req_double(item, "radius", &b->radius));
        TRY(cfg_check_positive(item, "radius", b->radius, "a radius in m"));
        TRY(read_markers(item, "markers", DEFAULT_MARKERS, 8, &b->markers));
        break;
    case IBM_BODY_NACA: {
        const char *d;
        TRY(cfg_req_string(item, "digits", &d));
        const bool four = strlen(d) == 4 && strspn(d, "0123456789") == 4;
        if (!four)
            return cfg_fail_at(item, "digits",
                               "'%s' is not a 4-digit series; expected e.g. \"0012\"", d);
        if (d[2] == '0' && d[3] == '0')
            return cfg_fail_at(item, "digits", "NACA %s has zero thickness; expected TT > 0", d);
        if ((d[0] == '0') != (d[1] == '0'))
            return cfg_fail_at(item, "digits",
                               "NACA %s: camber and its position must both be zero or both "
                               "not; expected e.g. 0012 or 2412",
                               d);
        memcpy(b->digits, d, 5);
        TRY(cfg_req_double(item, "chord", &b->chord));
        TRY(cfg_check_positive(item, "chord", b->chord, "the chord in m"));
        const double zero[2] = {0.0, 0.0};
        TRY(cfg_opt_vec(item, "leading_edge", 2, zero, b->leading_edge));
        TRY(cfg_opt_double(item, "angle_deg", 0.0, &b->angle_deg));
        TRY(cfg_check_range(item, "angle_deg", b->angle_deg, -90.0, 90.0,
                            "an angle of attack in degrees, -90 to 90"));
        TRY(read_markers(item, "markers", DEFAULT_MARKERS, 8, &b->markers));
        if (b->markers % 2)
            return cfg_fail_at(item, "markers", "%d markers; expected an even number", b->markers);
        break;
    }
    case IBM_BODY_RECTANGLE:
        TRY(cfg_req_vec(item, "min", 2, b->min));
        TRY(cfg_req_vec(item, "max", 2, b->max));
        for (int d = 0; d < 2; d++)
            if (!(b->max[d] > b->min[d]))
                return cfg_fail_at(item, "max",
                                   "max[%d] = %g is not above min[%d] = %g; expected max > min on "
                                   "every axis",
                                   d, b->max[d], d, b->min[d]);
        TRY(read_markers(item, "markers_per_side", DEFAULT_MARKERS_PER_SIDE, 1,
                         &b->markers_per_side));
        break;
    case IBM_BODY_POLYGON:
        TRY(stl ? read_stl_section(item, b) : read_csv(item, b));
        break;
    default:
        break;
    }
    int wall;
    TRY(cfg_opt_enum(item, "wall", IBM_WALL_NAMES, IBM_WALL_ADIABATIC, &wall));
    b->thermal = wall;
    if (wall == IBM_WALL_ISOTHERMAL) {
        TRY(cfg_req_double(item, "wall_temperature", &b->wall_temperature));
        TRY(cfg_check_positive(item, "wall_temperature", b->wall_temperature,
                               "a temperature in K"));
    } else if (cfg_map_find(item, "wall_temperature")) {
        return cfg_fail_at(item, "wall_temperature",
                           "given for an adiabatic wall; expected it only with wall: isothermal");
    }
    return cfg_end_map(item);
}

int case_read_bodies(CfgNode *map, const char *key, bool required, IbmBodySet *set) {
    memset(set, 0, sizeof *set);
    CfgNode *seq;
    TRY(required ? cfg_req_seq(map, key, &seq) : cfg_opt_seq(map, key, &seq));
    if (!seq) return NSPD_OK;
    if (seq->count == 0) return cfg_fail(seq, "an empty list; expected at least one body");
    if (seq->count > 255) return cfg_fail(seq, "%d bodies; expected at most 255", seq->count);
    TRY(nspd_alloc(&set->bodies, (size_t)seq->count, sizeof(IbmBodyConfig)));
    set->count = seq->count;
    for (int i = 0; i < seq->count; i++) TRY(read_body(seq->child[i], i, &set->bodies[i]));
    for (int i = 0; i < seq->count; i++)
        for (int j = 0; j < i; j++)
            if (strcmp(set->bodies[i].name, set->bodies[j].name) == 0)
                return cfg_fail_at(seq->child[i], "name",
                                   "'%s' is also the name of body %d; expected unique names",
                                   set->bodies[i].name, j);
    return NSPD_OK;
}
