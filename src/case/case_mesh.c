#include "case/case_mesh.h"

#include "core/mem.h"
#include "core/status.h"
#include "io/cfg_read.h"
#include "io/in_file.h"

#include <math.h>
#include <string.h>

/* A set region's elements are polygons that every point is tested against
 * (points x elements tests at the build): a boundary's rows, not the body */
enum { CASE_MAX_SET_ELEMENTS = 1 << 20 };

int case_read_abaqus(CfgNode *lattice, int dim, CaseMesh *mesh, MeshPoints *points,
                     double *mean_size) {
    const char *file;
    TRY(cfg_req_string(lattice, "file", &file));
    cfg_resolve_path(cfg_map_find(lattice, "file"), file, mesh->path, sizeof mesh->path);
    const double zero[3] = {0, 0, 0};
    TRY(cfg_opt_double(lattice, "scale", 1.0, &mesh->scale));
    TRY(cfg_check_positive(lattice, "scale", mesh->scale, "the factor from the file's units to m"));
    TRY(cfg_opt_vec(lattice, "translate", dim, zero, mesh->shift));
    for (int d = dim; d < 3; d++) mesh->shift[d] = 0.0;
    InpReadError err;
    const int st = inp_read_file(mesh->path, INP_MAX_BYTES, &mesh->inp, &err);
    if (st == NSPD_ERR_IO)
        return cfg_fail_at(lattice, "file", "cannot read '%s' (%s); expected an Abaqus .inp file",
                           mesh->path, in_file_error(err.os_error));
    if (st == NSPD_ERR_INPUT) {
        if (err.line > 0)
            return cfg_fail_at(lattice, "file", "%s:%d: %s", mesh->path, err.line, err.text);
        return cfg_fail_at(lattice, "file", "%s: byte %lld: %s", mesh->path, (long long)err.offset,
                           err.text);
    }
    TRY(st);
    mesh->loaded = true;
    const InpMesh *m = &mesh->inp;
    if (m->dim != dim)
        return cfg_fail_at(lattice, "file", "%s: %dD elements for a %dD solid; expected %s",
                           mesh->path, m->dim, dim,
                           dim == 2 ? "area elements (CPS3, CPS4, CPE4, S4, ...)"
                                    : "solid elements (C3D4, C3D8)");
    const int64_t n = m->element_count;
    points->n = n;
    for (int d = 0; d < 3; d++) TRY(nspd_alloc(&points->x[d], (size_t)n, sizeof(double)));
    TRY(nspd_alloc(&points->measure, (size_t)n, sizeof(double)));
    const double factor = dim == 2 ? mesh->scale * mesh->scale : pow(mesh->scale, 3);
    double total = 0.0;
    for (int64_t e = 0; e < n; e++) {
        for (int d = 0; d < 3; d++)
            points->x[d][e] = d < dim ? mesh->scale * m->centroid[3 * e + d] + mesh->shift[d] : 0.0;
        points->measure[e] = factor * m->measure[e];
        total += points->measure[e];
    }
    if (!(total > 0.0 && isfinite(total)) || !(factor > 0.0 && isfinite(factor)))
        return cfg_fail_at(lattice, "scale",
                           "%g takes the mesh's %s to %g; expected a scale that keeps it finite "
                           "and above 0",
                           mesh->scale, dim == 2 ? "area" : "volume", total);
    *mean_size = dim == 2 ? sqrt(total / (double)n) : cbrt(total / (double)n);
    return NSPD_OK;
}

/* The elements of the set named `name` marked (1 each) in mark. */
static int set_elements(const CfgNode *where, const CaseMesh *mesh, const char *name, uint8_t *mark,
                        uint8_t *nodes) {
    const InpMesh *m = &mesh->inp;
    const InpSet *es = inp_find_set(m, name, true);
    if (es) {
        inp_set_mark(m, es, mark);
        return NSPD_OK;
    }
    const InpSet *ns = inp_find_set(m, name, false);
    if (!ns) {
        char known[200] = "";
        size_t len = 0;
        for (int k = 0; k < m->set_count && len + 90 < sizeof known; k++)
            len += (size_t)snprintf(known + len, sizeof known - len, "%s%s", len ? ", " : "",
                                    m->sets[k].name);
        return cfg_fail(where,
                        "'%s': %s defines no set of that name; expected one of its sets%s%s%s",
                        name, mesh->path, known[0] ? " (" : "", known, known[0] ? ")" : "");
    }
    memset(nodes, 0, (size_t)m->node_count);
    inp_set_mark(m, ns, nodes);
    for (int64_t e = 0; e < m->element_count; e++) {
        const int count_nodes = inp_shape_nodes((InpShape)m->element_shape[e]);
        bool all = true;
        for (int k = 0; k < count_nodes && all; k++)
            all = nodes[m->element_node[INP_MAX_ELEMENT_NODES * e + k]] != 0;
        if (all) mark[e] = 1;
    }
    return NSPD_OK;
}

int case_read_set_region(CfgNode *item, const char *key, const CaseMesh *mesh, ShapeSet *region,
                         bool *given) {
    CfgNode *node = cfg_map_find(item, key);
    *given = node != NULL && !(node->kind == CFG_SCALAR && node->is_null);
    if (!*given) return NSPD_OK;
    if (!mesh || !mesh->loaded)
        return cfg_fail(node, "a set of the solid's mesh, but the solid has none; expected a "
                              "region (shapes), or solid.lattice: {kind: abaqus, file: ...}");
    const InpMesh *m = &mesh->inp;
    if (m->dim != 2) return cfg_fail(node, "sets of a 3D mesh; expected a region (shapes)");
    uint8_t *mark = NULL, *nodes = NULL;
    TRY(nspd_alloc(&mark, (size_t)m->element_count, 1));
    int status = nspd_alloc(&nodes, (size_t)m->node_count + 1, 1);
    if (node->kind == CFG_SEQ) {
        node->used = true;
        if (status == NSPD_OK && node->count == 0)
            status = cfg_fail(node, "an empty list; expected set names");
        for (int i = 0; i < node->count && status == NSPD_OK; i++) {
            const CfgNode *c = node->child[i];
            if (c->kind != CFG_SCALAR || c->is_null)
                status = cfg_fail(c, "not a set's name; expected a name of the mesh file's sets");
            else
                status = set_elements(c, mesh, c->text, mark, nodes);
        }
    } else if (status == NSPD_OK) {
        const char *name;
        status = cfg_req_string(item, key, &name);
        if (status == NSPD_OK) status = set_elements(node, mesh, name, mark, nodes);
    }
    nspd_free(&nodes);
    int64_t selected = 0;
    for (int64_t e = 0; e < m->element_count && status == NSPD_OK; e++) selected += mark[e];
    if (status == NSPD_OK && selected == 0)
        status = cfg_fail(node, "the set selects no element (a node set selects the elements "
                                "whose nodes it holds all); expected a set of elements");
    if (status == NSPD_OK && selected > CASE_MAX_SET_ELEMENTS)
        status = cfg_fail(node,
                          "%lld elements (every point is tested against each); expected at most "
                          "%d, or a region of shapes for a large part",
                          (long long)selected, CASE_MAX_SET_ELEMENTS);
    if (status == NSPD_OK) {
        memset(region, 0, sizeof *region);
        status = nspd_alloc(&region->shapes, (size_t)selected, sizeof(Shape));
    }
    for (int64_t e = 0; e < m->element_count && status == NSPD_OK; e++) {
        if (!mark[e]) continue;
        Shape *s = &region->shapes[region->count++];
        const int nv = inp_shape_nodes((InpShape)m->element_shape[e]);
        s->kind = SHAPE_POLYGON;
        s->vertex_count = nv;
        status = nspd_alloc(&s->vertices, 2 * (size_t)nv, sizeof(double));
        for (int k = 0; k < nv && status == NSPD_OK; k++) {
            const double *x = &m->node_x[3 * m->element_node[INP_MAX_ELEMENT_NODES * e + k]];
            for (int d = 0; d < 2; d++)
                s->vertices[2 * k + d] = mesh->scale * x[d] + mesh->shift[d];
        }
    }
    nspd_free(&mark);
    return status;
}

void case_mesh_free(CaseMesh *mesh) {
    inp_mesh_free(&mesh->inp);
    mesh->loaded = false;
}
