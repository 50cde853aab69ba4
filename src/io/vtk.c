#include "io/vtk.h"

#include "core/status.h"
#include "core/out_file.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A data array in the appended block. */
typedef struct {
    const char *name;
    const char *type; /* Float64, Int64, UInt8 */
    int components;
    int64_t count; /* tuples */
    int elem_size;
} ArrayInfo;

static uint64_t block_bytes(const ArrayInfo *a) {
    return (uint64_t)a->count * (uint64_t)a->components * (uint64_t)a->elem_size;
}

static void declare(FILE *f, const ArrayInfo *a, uint64_t *offset) {
    fprintf(f,
            "        <DataArray type=\"%s\" Name=\"%s\" NumberOfComponents=\"%d\" "
            "format=\"appended\" offset=\"%llu\"/>\n",
            a->type, a->name, a->components, (unsigned long long)*offset);
    *offset += sizeof(uint64_t) + block_bytes(a);
}

enum { CHUNK = 4096 };

/* Writes the block header and n tuples of a SoA double field, interleaving
 * components through a small buffer. */
/* One block of n values a component, written `layers` times over (the
 * same values on each layer of a grid's nodes; 1: once). */
static int write_soa_layers(FILE *f, int64_t n, int layers, int components,
                            const double *const data[3]) {
    uint64_t bytes = (uint64_t)n * (uint64_t)layers * (uint64_t)components * sizeof(double);
    if (fwrite(&bytes, sizeof bytes, 1, f) != 1) return -1;
    double buf[CHUNK * 3];
    for (int layer = 0; layer < layers; layer++)
        for (int64_t lo = 0; lo < n; lo += CHUNK) {
            int64_t hi = lo + CHUNK < n ? lo + CHUNK : n;
            for (int64_t i = lo; i < hi; i++)
                for (int c = 0; c < components; c++)
                    buf[(i - lo) * components + c] = data[c] ? data[c][i] : 0.0;
            size_t count = (size_t)((hi - lo) * components);
            if (fwrite(buf, sizeof(double), count, f) != count) return -1;
        }
    return 0;
}

static int write_soa(FILE *f, int64_t n, int components, const double *const data[3]) {
    return write_soa_layers(f, n, 1, components, data);
}

int vtk_write_points(const char *path, int64_t n, const double *const pos[3],
                     const VtkField *fields, int field_count) {
    OutFile out;
    TRY(out_file_open(&out, path));
    FILE *f = out.f;
    uint64_t offset = 0;
    fprintf(f,
            "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
            "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n  <UnstructuredGrid>\n"
            "    <Piece NumberOfPoints=\"%lld\" NumberOfCells=\"%lld\">\n      <PointData>\n",
            (long long)n, (long long)n);
    for (int k = 0; k < field_count; k++) {
        ArrayInfo a = {fields[k].name, "Float64", fields[k].components, n, 8};
        declare(f, &a, &offset);
    }
    fprintf(f, "      </PointData>\n      <Points>\n");
    ArrayInfo points = {"Points", "Float64", 3, n, 8};
    declare(f, &points, &offset);
    fprintf(f, "      </Points>\n      <Cells>\n");
    ArrayInfo conn = {"connectivity", "Int64", 1, n, 8}, offs = {"offsets", "Int64", 1, n, 8},
              types = {"types", "UInt8", 1, n, 1};
    declare(f, &conn, &offset);
    declare(f, &offs, &offset);
    declare(f, &types, &offset);
    fprintf(f, "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n  <AppendedData "
               "encoding=\"raw\">\n_");
    int err = 0;
    for (int k = 0; k < field_count && !err; k++)
        err = write_soa(f, n, fields[k].components, fields[k].data);
    if (!err) err = write_soa(f, n, 3, pos);
    /* vertex cells: cell i is point i */
    uint64_t bytes = (uint64_t)n * 8;
    int64_t ibuf[CHUNK];
    for (int pass = 0; pass < 2 && !err; pass++) {
        err = fwrite(&bytes, sizeof bytes, 1, f) != 1;
        for (int64_t lo = 0; lo < n && !err; lo += CHUNK) {
            int64_t hi = lo + CHUNK < n ? lo + CHUNK : n;
            for (int64_t i = lo; i < hi; i++) ibuf[i - lo] = pass == 0 ? i : i + 1;
            err = fwrite(ibuf, sizeof(int64_t), (size_t)(hi - lo), f) != (size_t)(hi - lo);
        }
    }
    uint64_t type_bytes = (uint64_t)n;
    uint8_t tbuf[CHUNK];
    memset(tbuf, 1, sizeof tbuf); /* VTK_VERTEX */
    if (!err) err = fwrite(&type_bytes, sizeof type_bytes, 1, f) != 1;
    for (int64_t lo = 0; lo < n && !err; lo += CHUNK) {
        size_t count = (size_t)(lo + CHUNK < n ? CHUNK : n - lo);
        err = fwrite(tbuf, 1, count, f) != count;
    }
    fprintf(f, "\n  </AppendedData>\n</VTKFile>\n");
    return out_file_close(&out, err);
}

/* The cells [ext[0], ext[1]) x [ext[2], ext[3]) x [ext[4], ext[5]) of a
 * grid, a file of their own: the whole grid (origin 0) or one piece of it. */
static int write_rectilinear(const char *path, const int ext[6], const double *xf, const double *yf,
                             const double *zf, const VtkField *fields, int field_count,
                             const VtkField *point_fields, int point_count) {
    OutFile out;
    TRY(out_file_open(&out, path));
    FILE *f = out.f;
    const int nx = ext[1] - ext[0], ny = ext[3] - ext[2], nz = ext[5] - ext[4];
    int64_t cells = (int64_t)nx * ny * nz, layer = (int64_t)(nx + 1) * (ny + 1),
            nodes = layer * (nz + 1);
    uint64_t offset = 0;
    char extent[128];
    snprintf(extent, sizeof extent, "%d %d %d %d %d %d", ext[0], ext[1], ext[2], ext[3], ext[4],
             ext[5]);
    fprintf(f,
            "<?xml version=\"1.0\"?>\n<VTKFile type=\"RectilinearGrid\" version=\"1.0\" "
            "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
            "  <RectilinearGrid WholeExtent=\"%s\">\n"
            "    <Piece Extent=\"%s\">\n",
            extent, extent);
    if (point_count > 0) {
        fprintf(f, "      <PointData>\n");
        for (int k = 0; k < point_count; k++) {
            ArrayInfo a = {point_fields[k].name, "Float64", point_fields[k].components, nodes, 8};
            declare(f, &a, &offset);
        }
        fprintf(f, "      </PointData>\n");
    }
    fprintf(f, "      <CellData>\n");
    for (int k = 0; k < field_count; k++) {
        ArrayInfo a = {fields[k].name, "Float64", fields[k].components, cells, 8};
        declare(f, &a, &offset);
    }
    fprintf(f, "      </CellData>\n      <Coordinates>\n");
    ArrayInfo cx = {"x", "Float64", 1, nx + 1, 8}, cy = {"y", "Float64", 1, ny + 1, 8},
              cz = {"z", "Float64", 1, nz + 1, 8};
    declare(f, &cx, &offset);
    declare(f, &cy, &offset);
    declare(f, &cz, &offset);
    fprintf(f, "      </Coordinates>\n    </Piece>\n  </RectilinearGrid>\n  <AppendedData "
               "encoding=\"raw\">\n_");
    int err = 0;
    for (int k = 0; k < point_count && !err; k++)
        err = write_soa_layers(f, layer, nz + 1, point_fields[k].components, point_fields[k].data);
    for (int k = 0; k < field_count && !err; k++)
        err = write_soa(f, cells, fields[k].components, fields[k].data);
    const double *axes[3] = {xf, yf, zf};
    int counts[3] = {nx + 1, ny + 1, nz + 1};
    for (int a = 0; a < 3 && !err; a++) {
        const double *one[3] = {axes[a], NULL, NULL};
        err = write_soa(f, counts[a], 1, one);
    }
    fprintf(f, "\n  </AppendedData>\n</VTKFile>\n");
    return out_file_close(&out, err);
}

int vtk_write_rectilinear(const char *path, int nx, int ny, int nz, const double *xf,
                          const double *yf, const double *zf, const VtkField *fields,
                          int field_count, const VtkField *point_fields, int point_count) {
    const int ext[6] = {0, nx, 0, ny, 0, nz};
    return write_rectilinear(path, ext, xf, yf, zf, fields, field_count, point_fields, point_count);
}

int vtk_write_rectilinear_piece(const char *path, const int cells[4], const double *xf,
                                const double *yf, const VtkField *fields, int field_count) {
    const int ext[6] = {cells[0], cells[1], cells[2], cells[3], 0, 1};
    const double zf[2] = {0.0, 0.0};
    return write_rectilinear(path, ext, xf, yf, zf, fields, field_count, NULL, 0);
}

/* The PDataArray declarations of a parallel file's fields. */
static void declare_parallel(FILE *f, const char *element, const VtkField *fields,
                             int field_count) {
    fprintf(f, "    <%s>\n", element);
    for (int k = 0; k < field_count; k++)
        fprintf(f, "      <PDataArray type=\"Float64\" Name=\"%s\" NumberOfComponents=\"%d\"/>\n",
                fields[k].name, fields[k].components);
    fprintf(f, "    </%s>\n", element);
}

int vtk_write_pvtr(const char *path, int nx, int ny, int piece_count, const int (*cells)[4],
                   const char *const *sources, const VtkField *fields, int field_count) {
    OutFile out;
    TRY(out_file_open(&out, path));
    FILE *f = out.f;
    fprintf(f,
            "<?xml version=\"1.0\"?>\n<VTKFile type=\"PRectilinearGrid\" version=\"1.0\" "
            "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
            "  <PRectilinearGrid WholeExtent=\"0 %d 0 %d 0 1\" GhostLevel=\"0\">\n",
            nx, ny);
    declare_parallel(f, "PCellData", fields, field_count);
    static const VtkField axes[3] = {{"x", 1, {0}}, {"y", 1, {0}}, {"z", 1, {0}}};
    declare_parallel(f, "PCoordinates", axes, 3);
    for (int p = 0; p < piece_count; p++)
        fprintf(f, "    <Piece Extent=\"%d %d %d %d 0 1\" Source=\"%s\"/>\n", cells[p][0],
                cells[p][1], cells[p][2], cells[p][3], sources[p]);
    fprintf(f, "  </PRectilinearGrid>\n</VTKFile>\n");
    return out_file_close(&out, 0);
}

int vtk_write_pvtu(const char *path, int piece_count, const char *const *sources,
                   const VtkField *fields, int field_count) {
    OutFile out;
    TRY(out_file_open(&out, path));
    FILE *f = out.f;
    fprintf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" "
               "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
               "  <PUnstructuredGrid GhostLevel=\"0\">\n");
    declare_parallel(f, "PPointData", fields, field_count);
    static const VtkField points = {"Points", 3, {0}};
    declare_parallel(f, "PPoints", &points, 1);
    for (int p = 0; p < piece_count; p++) fprintf(f, "    <Piece Source=\"%s\"/>\n", sources[p]);
    fprintf(f, "  </PUnstructuredGrid>\n</VTKFile>\n");
    return out_file_close(&out, 0);
}

int pvd_append(PvdSeries *s, double time, const char *file_name) {
    if (s->count == s->cap) {
        int cap = s->cap ? 2 * s->cap : 16;
        double *times = realloc(s->times, (size_t)cap * sizeof *times);
        if (!times) return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
        s->times = times;
        char **files = realloc(s->files, (size_t)cap * sizeof *files);
        if (!files) return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
        s->files = files;
        s->cap = cap;
    }
    size_t len = strlen(file_name) + 1;
    s->files[s->count] = malloc(len);
    if (!s->files[s->count]) return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory");
    memcpy(s->files[s->count], file_name, len);
    s->times[s->count++] = time;
    return NSPD_OK;
}

int pvd_write(const PvdSeries *s, const char *pvd_path) {
    OutFile out;
    TRY(out_file_open(&out, pvd_path));
    FILE *f = out.f;
    fprintf(f, "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"1.0\" "
               "byte_order=\"LittleEndian\">\n  <Collection>\n");
    for (int i = 0; i < s->count; i++)
        fprintf(f, "    <DataSet timestep=\"%.12g\" part=\"0\" file=\"%s\"/>\n", s->times[i],
                s->files[i]);
    fprintf(f, "  </Collection>\n</VTKFile>\n");
    return out_file_close(&out, 0);
}

int pvd_add(PvdSeries *s, const char *pvd_path, double time, const char *file_name) {
    TRY(pvd_append(s, time, file_name));
    return pvd_write(s, pvd_path);
}

void pvd_free(PvdSeries *s) {
    for (int i = 0; i < s->count; i++) free(s->files[i]);
    free(s->files);
    free(s->times);
    memset(s, 0, sizeof *s);
}
