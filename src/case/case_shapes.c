#include "case/case_shapes.h"

#include "core/mem.h"
#include "core/shape_mesh.h"
#include "core/status.h"
#include "io/cfg_read.h"
#include "io/in_file.h"
#include "io/stl_read.h"

#include <math.h>
#include <string.h>

static const char *const OPS[] = {"add", "subtract", NULL};

static int read_min_max(CfgNode *item, int n, Shape *s) {
    TRY(cfg_req_vec(item, "min", n, s->lo));
    TRY(cfg_req_vec(item, "max", n, s->hi));
    for (int d = 0; d < n; d++)
        if (!(s->hi[d] > s->lo[d]))
            return cfg_fail_at(item, "max",
                               "max[%d] = %g is not above min[%d] = %g; expected max > min on "
                               "every axis",
                               d, s->hi[d], d, s->lo[d]);
    return NSPD_OK;
}

static int read_polygon(CfgNode *item, Shape *s) {
    CfgNode *seq;
    TRY(cfg_req_seq(item, "vertices", &seq));
    if (seq->count < 3)
        return cfg_fail(seq, "%d vertices; expected at least 3 [x, y] pairs", seq->count);
    TRY(nspd_alloc(&s->vertices, (size_t)seq->count * 2, sizeof(double)));
    s->vertex_count = seq->count;
    for (int v = 0; v < seq->count; v++) {
        CfgNode *pt = seq->child[v];
        if (pt->kind != CFG_SEQ || pt->count != 2)
            return cfg_fail(pt, "not a vertex; expected a pair [x, y]");
        TRY(cfg_node_double(pt->child[0], &s->vertices[2 * v]));
        TRY(cfg_node_double(pt->child[1], &s->vertices[2 * v + 1]));
    }
    if (fabs(polygon_signed_area(s->vertices, s->vertex_count)) == 0.0)
        return cfg_fail(seq, "the polygon has zero area; expected vertices around an area");
    return NSPD_OK;
}

int case_read_stl_mesh(CfgNode *item, ShapeMesh **mesh, char *path, size_t path_size) {
    const char *file;
    TRY(cfg_req_string(item, "file", &file));
    cfg_resolve_path(cfg_map_find(item, "file"), file, path, path_size);
    double scale, zero[3] = {0, 0, 0}, shift[3];
    TRY(cfg_opt_double(item, "scale", 1.0, &scale));
    TRY(cfg_check_positive(item, "scale", scale, "the factor from the file's units to m"));
    TRY(cfg_opt_vec(item, "translate", 3, zero, shift));
    double *tri;
    int64_t n;
    StlReadError err;
    const int st = stl_read_file(path, &tri, &n, &err);
    if (st == NSPD_ERR_IO)
        return cfg_fail_at(item, "file", "cannot read '%s' (%s); expected an STL file", path,
                           in_file_error(err.os_error));
    if (st == NSPD_ERR_INPUT) {
        if (err.line > 0) return cfg_fail_at(item, "file", "%s:%d: %s", path, err.line, err.text);
        return cfg_fail_at(item, "file", "%s: byte %lld: %s", path, (long long)err.offset,
                           err.text);
    }
    TRY(st);
    for (int64_t k = 0; k < 3 * n; k++)
        for (int d = 0; d < 3; d++) tri[3 * k + d] = scale * tri[3 * k + d] + shift[d];
    char why[256];
    const int made = shape_mesh_create(tri, n, mesh, why, sizeof why);
    nspd_free(&tri);
    if (made == NSPD_ERR_INPUT) return cfg_fail_at(item, "file", "%s: %s", path, why);
    return made;
}

/* {shape: stl, ...}: the mesh; in 2D its section by z = section_z */
static int read_stl(CfgNode *item, int dim, Shape *s) {
    char path[4096];
    if (dim == 2) {
        s->section = true;
        TRY(cfg_opt_double(item, "section_z", 0.0, &s->section_z));
    }
    return case_read_stl_mesh(item, &s->mesh, path, sizeof path);
}

static int read_shape(CfgNode *item, int dim, Shape *s) {
    if (item->kind != CFG_MAP)
        return cfg_fail(item, "not a shape; expected a map such as {shape: rectangle, min: [x, y], "
                              "max: [x, y]}");
    int kind, op;
    TRY(cfg_req_enum(item, "shape", SHAPE_NAMES, &kind));
    TRY(cfg_opt_enum(item, "op", OPS, 0, &op));
    s->kind = (ShapeKind)kind;
    s->subtract = op == 1;
    if (s->kind != SHAPE_STL && shape_is_3d(s->kind) != (dim == 3))
        return cfg_fail_at(item, "shape", "'%s' is a %dD shape in a %dD case; expected %s",
                           SHAPE_NAMES[kind], shape_is_3d(s->kind) ? 3 : 2, dim,
                           dim == 3 ? "box, sphere, cylinder or stl"
                                    : "rectangle, disc, annulus, polygon or stl");
    switch (s->kind) {
    case SHAPE_RECTANGLE:
        TRY(read_min_max(item, 2, s));
        break;
    case SHAPE_BOX:
        TRY(read_min_max(item, 3, s));
        break;
    case SHAPE_DISC:
    case SHAPE_SPHERE:
        TRY(cfg_req_vec(item, "center", dim, s->center));
        TRY(cfg_req_double(item, "radius", &s->radius));
        TRY(cfg_check_positive(item, "radius", s->radius, "a radius in m"));
        break;
    case SHAPE_ANNULUS:
        TRY(cfg_req_vec(item, "center", 2, s->center));
        TRY(cfg_req_double(item, "inner_radius", &s->inner_radius));
        TRY(cfg_req_double(item, "radius", &s->radius));
        TRY(cfg_check_positive(item, "inner_radius", s->inner_radius, "a radius in m"));
        if (!(s->radius > s->inner_radius))
            return cfg_fail_at(item, "radius",
                               "radius %g is not above inner_radius %g; expected the outer "
                               "radius",
                               s->radius, s->inner_radius);
        break;
    case SHAPE_CYLINDER:
        TRY(cfg_req_vec(item, "center", 3, s->center));
        TRY(cfg_req_double(item, "radius", &s->radius));
        TRY(cfg_req_double(item, "length", &s->length));
        TRY(cfg_check_positive(item, "radius", s->radius, "a radius in m"));
        TRY(cfg_check_positive(item, "length", s->length, "a length along z in m"));
        break;
    case SHAPE_POLYGON:
        TRY(read_polygon(item, s));
        break;
    case SHAPE_STL:
        TRY(read_stl(item, dim, s));
        break;
    default:
        break;
    }
    return cfg_end_map(item);
}

int case_read_shapes(CfgNode *map, const char *key, int dim, bool required, ShapeSet *set) {
    memset(set, 0, sizeof *set);
    CfgNode *seq;
    TRY(required ? cfg_req_seq(map, key, &seq) : cfg_opt_seq(map, key, &seq));
    if (!seq) return NSPD_OK;
    if (seq->count == 0) return cfg_fail(seq, "an empty list; expected at least one shape");
    TRY(nspd_alloc(&set->shapes, (size_t)seq->count, sizeof(Shape)));
    set->count = seq->count;
    for (int i = 0; i < seq->count; i++) TRY(read_shape(seq->child[i], dim, &set->shapes[i]));
    if (set->shapes[0].subtract)
        return cfg_fail(seq->child[0], "the first shape subtracts from nothing; expected 'op: add' "
                                       "first");
    return NSPD_OK;
}
