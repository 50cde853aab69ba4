/* Reader of nspd's own .vtr files (vtk_read.h).
 *
 * The header is small XML that vtk_write_rectilinear prints line by line;
 * rather than pull in an XML library for one known layout, it is scanned
 * for the attributes that matter (WholeExtent; per DataArray: type, Name,
 * NumberOfComponents, format, offset) and the appended block is located by
 * its `_` marker. Point data (a spline flow's corner values) is skipped:
 * what starts a flow is the cells'. Each block's UInt64 byte count is checked against the
 * size the extent implies, so a truncated or foreign file fails cleanly. */
#include "io/vtk_read.h"

#include "io/in_file.h"

#include "core/mem.h"
#include "core/status.h"

#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { HEADER_MAX = 1 << 16 };

typedef struct {
    uint64_t offset;
    char name[VTK_MAX_NAME];
    int components;
    int is_coordinate;
    int is_point; /* in PointData: node values, not read (the cells' are) */
} Declared;

/* The value of attribute `key` in the tag starting at `tag` (up to '>'),
 * copied into buf; 0 if absent. */
static int attribute(const char *tag, const char *key, char *buf, size_t size) {
    const char *end = strchr(tag, '>');
    char pattern[64];
    snprintf(pattern, sizeof pattern, " %s=\"", key);
    const char *p = strstr(tag, pattern);
    if (!p || (end && p > end)) return 0;
    p += strlen(pattern);
    const char *q = strchr(p, '"');
    if (!q || (size_t)(q - p) >= size) return 0;
    memcpy(buf, p, (size_t)(q - p));
    buf[q - p] = '\0';
    return 1;
}

/* The attributes of the DataArray tag at `p` into *d: Float64, appended,
 * 1 to 3 components (exactly 3 with `three`). */
static int declare_array(const char *path, const char *p, bool three, Declared *d) {
    char type[32], format[32], comps[16], off[32];
    if (!attribute(p, "Name", d->name, sizeof d->name) ||
        !attribute(p, "type", type, sizeof type) ||
        !attribute(p, "format", format, sizeof format) || !attribute(p, "offset", off, sizeof off))
        return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': a DataArray without Name, type or offset", path);
    if (strcmp(type, "Float64") != 0 || strcmp(format, "appended") != 0)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "'%s': array '%s' is %s, %s; expected Float64, appended (as nspd "
                         "writes it)",
                         path, d->name, type, format);
    d->components = attribute(p, "NumberOfComponents", comps, sizeof comps) ? atoi(comps) : 1;
    if (d->components < 1 || d->components > 3 || (three && d->components != 3))
        return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': array '%s' has %d components", path, d->name,
                         d->components);
    d->offset = strtoull(off, NULL, 10);
    return NSPD_OK;
}

static int parse_header(const char *path, const char *h, VtkRectilinear *out, Declared *decl,
                        int *decl_count) {
    if (!strstr(h, "<VTKFile type=\"RectilinearGrid\""))
        return NSPD_FAIL(NSPD_ERR_INPUT, "'%s' is not a VTK rectilinear grid (.vtr) file", path);
    if (!strstr(h, "byte_order=\"LittleEndian\"") || !strstr(h, "header_type=\"UInt64\""))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "'%s': expected little-endian data with UInt64 block headers, as nspd "
                         "writes them",
                         path);
    const char *grid = strstr(h, "<RectilinearGrid");
    char buf[128];
    int e[6];
    if (!grid || !attribute(grid, "WholeExtent", buf, sizeof buf) ||
        sscanf(buf, "%d %d %d %d %d %d", &e[0], &e[1], &e[2], &e[3], &e[4], &e[5]) != 6)
        return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': no WholeExtent in the header", path);
    for (int a = 0; a < 3; a++) {
        /* the difference in 64 bits: "-2147483648 2147483647" overflowed int
         * (hostile input, tests/fuzz/regressions/vtk/extent_overflow.vtr) */
        const long long n = (long long)e[2 * a + 1] - (long long)e[2 * a];
        if (n < 1 || n > (1 << 24))
            return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': WholeExtent '%s' is not a grid of cells", path,
                             buf);
        out->n[a] = (int)n;
    }
    const char *coords = strstr(h, "<Coordinates>");
    const char *points = strstr(h, "<PointData>"), *points_end = strstr(h, "</PointData>");
    *decl_count = 0;
    for (const char *p = strstr(h, "<DataArray"); p; p = strstr(p + 1, "<DataArray")) {
        if (*decl_count == VTK_MAX_ARRAYS + 3)
            return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': more than %d arrays", path, VTK_MAX_ARRAYS);
        Declared *d = &decl[(*decl_count)++];
        TRY(declare_array(path, p, false, d));
        d->is_coordinate = coords && p > coords;
        d->is_point = points && points_end && p > points && p < points_end;
    }
    return NSPD_OK;
}

/* Reads the block at `offset` into *data (count doubles). `room` is what
 * the file holds from the start of the appended data (`base`) on: the
 * offset and the block are checked against it before anything is added or
 * allocated (hostile input, tests/fuzz/regressions/vtk/: an offset near
 * 2^63 overflowed base + offset, and a 1 kB file whose header declared a
 * 2^24 x 256 grid, with the matching byte count, made the reader allocate
 * and zero 32 GB before finding the data missing). */
static int read_block(FILE *f, const char *path, long base, uint64_t room, const Declared *d,
                      uint64_t count, double **data) {
    uint64_t bytes;
    if (d->offset > room || room - d->offset < sizeof bytes ||
        fseek(f, base + (long)d->offset, SEEK_SET) != 0 || fread(&bytes, sizeof bytes, 1, f) != 1)
        return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': array '%s' lies past the end of the file", path,
                         d->name);
    if (count > UINT64_MAX / sizeof(double) || bytes != count * sizeof(double))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "'%s': array '%s' holds %" PRIu64 " bytes; the grid needs %" PRIu64
                         " values of 8 bytes",
                         path, d->name, bytes, count);
    if (bytes > room - d->offset - sizeof bytes)
        return NSPD_FAIL(NSPD_ERR_INPUT, "'%s' is truncated in array '%s'", path, d->name);
    TRY(nspd_alloc(data, (size_t)count, sizeof(double)));
    if (fread(*data, sizeof(double), (size_t)count, f) != (size_t)count)
        return NSPD_FAIL(NSPD_ERR_INPUT, "'%s' is truncated in array '%s'", path, d->name);
    return NSPD_OK;
}

/* The XML header of one of nspd's files with appended raw data, as text
 * (*header, freed by the caller), the data's start in the file (*base)
 * and the bytes from there to the end (*room). `what` names the kind of
 * file expected, for the message. */
static int read_header(FILE *f, const char *path, const char *what, char **header, long *base,
                       uint64_t *room) {
    long size;
    if (fseek(f, 0, SEEK_END) != 0 || (size = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0)
        return NSPD_FAIL(NSPD_ERR_IO, "cannot read '%s' (%s)", path, strerror(errno));
    TRY(nspd_alloc(header, HEADER_MAX + 1, 1));
    size_t got = fread(*header, 1, HEADER_MAX, f);
    const char *marker = strstr(*header, "<AppendedData encoding=\"raw\">");
    const char *underscore = marker ? strchr(marker, '_') : NULL;
    if (!underscore) {
        nspd_free(header);
        return got == 0 ? NSPD_FAIL(NSPD_ERR_INPUT, "'%s' is empty", path)
                        : NSPD_FAIL(NSPD_ERR_INPUT,
                                    "'%s': no raw <AppendedData> block in the first %d bytes; "
                                    "expected a %s written by nspd",
                                    path, HEADER_MAX, what);
    }
    *base = (long)(underscore + 1 - *header);
    (*header)[marker - *header] = '\0'; /* the binary data after it is not text */
    *room = size > *base ? (uint64_t)(size - *base) : 0;
    return NSPD_OK;
}

static int read_file(FILE *f, const char *path, VtkRectilinear *out) {
    char *header = NULL;
    long base = 0;
    uint64_t room = 0;
    TRY(read_header(f, path, ".vtr", &header, &base, &room));
    Declared decl[VTK_MAX_ARRAYS + 3];
    int decl_count = 0;
    int status = parse_header(path, header, out, decl, &decl_count);
    nspd_free(&header);
    TRY(status);
    /* each axis is at most 2^24 cells, so the product of all three could
     * wrap past 2^64 (and read as 0 cells); a grid whose cells need more
     * doubles than the file has bytes for is refused here */
    const uint64_t cells_xy = (uint64_t)out->n[0] * (uint64_t)out->n[1];
    if (cells_xy > room / sizeof(double) / (uint64_t)out->n[2])
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "'%s': %d x %d x %d cells; the file cannot hold their data", path,
                         out->n[0], out->n[1], out->n[2]);
    const uint64_t cells = cells_xy * (uint64_t)out->n[2];
    for (int k = 0; k < decl_count; k++) {
        const Declared *d = &decl[k];
        if (d->is_point) continue;
        if (d->is_coordinate) {
            int a = d->name[0] - 'x';
            if (d->name[1] != '\0' || a < 0 || a > 2 || out->face[a])
                return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': unexpected coordinate array '%s'", path,
                                 d->name);
            TRY(read_block(f, path, base, room, d, (uint64_t)out->n[a] + 1, &out->face[a]));
        } else {
            if (out->array_count == VTK_MAX_ARRAYS)
                return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': more than %d cell arrays", path,
                                 VTK_MAX_ARRAYS);
            VtkCellArray *c = &out->arrays[out->array_count++];
            memcpy(c->name, d->name, sizeof c->name);
            c->components = d->components;
            TRY(read_block(f, path, base, room, d, cells * (uint64_t)d->components, &c->data));
        }
    }
    for (int a = 0; a < 3; a++)
        if (!out->face[a])
            return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': no coordinate array '%c'", path, 'x' + a);
    return NSPD_OK;
}

/* A file's reader: the file open, `path` for messages, the result. */
typedef int (*FileReader)(FILE *f, const char *path, void *out);

/* `read` on the file at `path`, opened as a case's file is (in_file.h). */
static int read_path(const char *path, FileReader read, void *out) {
    int open_error = 0;
    FILE *f = in_file_open(path, &open_error);
    if (!f) return NSPD_FAIL(NSPD_ERR_IO, "cannot open '%s' (%s)", path, in_file_error(open_error));
    const int status = read(f, path, out);
    fclose(f);
    return status;
}

static int read_grid(FILE *f, const char *path, void *out) {
    memset(out, 0, sizeof(VtkRectilinear));
    return read_file(f, path, out);
}

/* The head of the file (up to HEADER_MAX bytes, as text) into *header
 * (freed by the caller): enough to tell a parallel file from a whole one. */
static int read_head(FILE *f, const char *path, void *header) {
    (void)path;
    char **h = header;
    TRY(nspd_alloc(h, HEADER_MAX + 1, 1));
    (*h)[fread(*h, 1, HEADER_MAX, f)] = '\0';
    return NSPD_OK;
}

/* The file a <Piece Source="..."> names, relative to the parallel file
 * `path`'s directory unless absolute. */
static int piece_source(const char *path, const char *tag, char *piece_path, size_t size) {
    char source[1024];
    if (!attribute(tag, "Source", source, sizeof source))
        return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': a <Piece> without Source", path);
    const char *slash = strrchr(path, '/');
    const int dir = source[0] == '/' || !slash ? 0 : (int)(slash - path + 1);
    snprintf(piece_path, size, "%.*s%s", dir, path, source);
    return NSPD_OK;
}

/* A piece's failure, said for the parallel file (NSPD_FAIL replaces the
 * message it is given, so the piece's is copied first). */
static int piece_failed(const char *path, int piece, int status) {
    char why[1024];
    snprintf(why, sizeof why, "%s", nspd_error_message());
    return NSPD_FAIL(status, "'%s': piece %d: %s", path, piece, why);
}

/* Piece p of a .pvtr: its cells' extent and its file, from the <Piece>
 * tag at `tag`. */
static int piece_tag(const char *path, const char *tag, int ext[6], char *piece_path, size_t size) {
    char buf[128];
    if (!attribute(tag, "Extent", buf, sizeof buf) ||
        sscanf(buf, "%d %d %d %d %d %d", &ext[0], &ext[1], &ext[2], &ext[3], &ext[4], &ext[5]) != 6)
        return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': a <Piece> without Extent or Source", path);
    return piece_source(path, tag, piece_path, size);
}

/* Piece `pc` (read from its file) into the whole grid `out` at cells
 * ext[]: its faces must be the whole axes' where they meet, its arrays the
 * first piece's. */
static int place_piece(const char *path, const VtkRectilinear *pc, const int ext[6],
                       VtkRectilinear *out, int first, uint8_t *covered) {
    for (int a = 0; a < 3; a++) {
        const long long n = (long long)ext[2 * a + 1] - ext[2 * a];
        if (ext[2 * a] < 0 || n != pc->n[a] || ext[2 * a + 1] > out->n[a])
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "'%s': a piece's extent %d..%d along %c is not its file's %d cells "
                             "inside the whole grid's %d",
                             path, ext[2 * a], ext[2 * a + 1], 'x' + a, pc->n[a], out->n[a]);
        for (int i = 0; i <= pc->n[a]; i++) {
            double *at = &out->face[a][ext[2 * a] + i];
            if (!first && !isnan(*at) && memcmp(at, &pc->face[a][i], sizeof *at) != 0)
                return NSPD_FAIL(NSPD_ERR_INPUT,
                                 "'%s': two pieces disagree on the %c face %d (%.17g, %.17g)", path,
                                 'x' + a, ext[2 * a] + i, *at, pc->face[a][i]);
            *at = pc->face[a][i];
        }
    }
    for (int z = 0; z < pc->n[2]; z++)
        for (int j = 0; j < pc->n[1]; j++)
            for (int i = 0; i < pc->n[0]; i++) {
                uint8_t *c = &covered[(((int64_t)ext[4] + z) * out->n[1] + ext[2] + j) * out->n[0] +
                                      ext[0] + i];
                if (*c)
                    return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': two pieces hold cell (%d, %d, %d)",
                                     path, ext[0] + i, ext[2] + j, ext[4] + z);
                *c = 1;
            }
    if (pc->array_count != out->array_count)
        return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': its pieces hold %d and %d cell arrays", path,
                         out->array_count, pc->array_count);
    for (int k = 0; k < pc->array_count; k++) {
        const VtkCellArray *from = &pc->arrays[k];
        VtkCellArray *to = &out->arrays[k];
        if (strcmp(from->name, to->name) != 0 || from->components != to->components)
            return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': its pieces' array %d is '%s' and '%s'", path, k,
                             to->name, from->name);
        const size_t run = (size_t)pc->n[0] * (size_t)from->components * sizeof(double);
        for (int z = 0; z < pc->n[2]; z++)
            for (int j = 0; j < pc->n[1]; j++) {
                const int64_t src = ((int64_t)z * pc->n[1] + j) * pc->n[0];
                const int64_t dst =
                    (((int64_t)ext[4] + z) * out->n[1] + ext[2] + j) * out->n[0] + ext[0];
                memcpy(to->data + dst * from->components, from->data + src * from->components, run);
            }
    }
    return NSPD_OK;
}

/* The whole grid of a .pvtr (ParaView's parallel rectilinear grid, what
 * several processes write: io/vtk.h), its pieces read one at a time. Every
 * cell must be covered by exactly one piece. */
static int read_parallel(const char *path, const char *h, VtkRectilinear *out) {
    const char *grid = strstr(h, "<PRectilinearGrid");
    char buf[128];
    int e[6];
    if (!grid || !attribute(grid, "WholeExtent", buf, sizeof buf) ||
        sscanf(buf, "%d %d %d %d %d %d", &e[0], &e[1], &e[2], &e[3], &e[4], &e[5]) != 6)
        return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': no WholeExtent in the header", path);
    int64_t cells = 1;
    for (int a = 0; a < 3; a++) {
        const long long n = (long long)e[2 * a + 1] - (long long)e[2 * a];
        if (e[2 * a] != 0 || n < 1 || n > (1 << 24))
            return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': WholeExtent '%s' is not a grid of cells", path,
                             buf);
        out->n[a] = (int)n;
        cells *= n;
    }
    int64_t covered = 0;
    uint8_t *held; /* 1: a piece holds the cell */
    TRY(nspd_alloc(&held, (size_t)cells, 1));
    int status = NSPD_OK, pieces = 0;
    for (const char *tag = strstr(grid, "<Piece"); tag && status == NSPD_OK;
         tag = strstr(tag + 1, "<Piece"), pieces++) {
        int ext[6];
        char piece_path[5200];
        VtkRectilinear pc;
        memset(&pc, 0, sizeof pc);
        status = piece_tag(path, tag, ext, piece_path, sizeof piece_path);
        if (status == NSPD_OK && (status = read_path(piece_path, read_grid, &pc)) != NSPD_OK)
            status = piece_failed(path, pieces, status);
        if (status == NSPD_OK && pieces == 0) { /* the whole grid's arrays, as the first piece's */
            for (int a = 0; a < 3 && status == NSPD_OK; a++) {
                status = nspd_alloc(&out->face[a], (size_t)out->n[a] + 1, sizeof(double));
                for (int i = 0; i <= out->n[a] && status == NSPD_OK; i++) out->face[a][i] = NAN;
            }
            for (int k = 0; k < pc.array_count && status == NSPD_OK; k++) {
                VtkCellArray *to = &out->arrays[out->array_count++];
                memcpy(to->name, pc.arrays[k].name, sizeof to->name);
                to->components = pc.arrays[k].components;
                status =
                    nspd_alloc(&to->data, (size_t)cells * (size_t)to->components, sizeof(double));
            }
        }
        if (status == NSPD_OK) status = place_piece(path, &pc, ext, out, pieces == 0, held);
        covered += (int64_t)pc.n[0] * pc.n[1] * pc.n[2];
        vtk_rectilinear_free(&pc);
    }
    nspd_free(&held);
    TRY(status);
    if (pieces == 0 || covered != cells)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "'%s': its %d pieces hold %lld cells; the whole grid has %lld", path,
                         pieces, (long long)covered, (long long)cells);
    return NSPD_OK;
}

int vtk_read_rectilinear(const char *path, VtkRectilinear *out) {
    memset(out, 0, sizeof *out);
    /* a .pvtr names its pieces in a short header, no appended data */
    char *header = NULL;
    TRY(read_path(path, read_head, &header));
    const bool parallel = strstr(header, "<VTKFile type=\"PRectilinearGrid\"") != NULL;
    const int status =
        parallel ? read_parallel(path, header, out) : read_path(path, read_grid, out);
    nspd_free(&header);
    return status;
}

/* A .vtu's header: its points' count, and its point data and points
 * arrays into decl (the cells' arrays, vertex cells numbered in the file,
 * are not read). */
static int parse_points_header(const char *path, const char *h, VtkPointSet *out, Declared *decl,
                               int *decl_count) {
    if (!strstr(h, "<VTKFile type=\"UnstructuredGrid\""))
        return NSPD_FAIL(NSPD_ERR_INPUT, "'%s' is not a VTK point set (.vtu) file", path);
    if (!strstr(h, "byte_order=\"LittleEndian\"") || !strstr(h, "header_type=\"UInt64\""))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "'%s': expected little-endian data with UInt64 block headers, as nspd "
                         "writes them",
                         path);
    const char *piece = strstr(h, "<Piece");
    char buf[64];
    if (!piece || !attribute(piece, "NumberOfPoints", buf, sizeof buf))
        return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': no <Piece NumberOfPoints> in the header", path);
    const long long n = atoll(buf);
    if (n < 0) return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': %lld points", path, n);
    out->n = n;
    const char *data = strstr(h, "<PointData>"), *data_end = strstr(h, "</PointData>");
    const char *points = strstr(h, "<Points>"), *points_end = strstr(h, "</Points>");
    *decl_count = 0;
    for (const char *p = strstr(h, "<DataArray"); p; p = strstr(p + 1, "<DataArray")) {
        const bool in_data = data && data_end && p > data && p < data_end;
        const bool in_points = points && points_end && p > points && p < points_end;
        if (!in_data && !in_points) continue;
        if (*decl_count == VTK_MAX_ARRAYS + 1)
            return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': more than %d arrays", path, VTK_MAX_ARRAYS);
        Declared *d = &decl[(*decl_count)++];
        TRY(declare_array(path, p, in_points, d));
        d->is_coordinate = in_points;
        d->is_point = in_data;
    }
    return NSPD_OK;
}

static int read_points_file(FILE *f, const char *path, VtkPointSet *out) {
    char *header = NULL;
    long base = 0;
    uint64_t room = 0;
    TRY(read_header(f, path, ".vtu", &header, &base, &room));
    Declared decl[VTK_MAX_ARRAYS + 1];
    int decl_count = 0;
    const int status = parse_points_header(path, header, out, decl, &decl_count);
    nspd_free(&header);
    TRY(status);
    /* three doubles a point at least (its position): more points than the
     * file could hold are refused before anything is allocated */
    if ((uint64_t)out->n > room / (3 * sizeof(double)))
        return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': %lld points; the file cannot hold their data", path,
                         (long long)out->n);
    for (int k = 0; k < decl_count; k++) {
        const Declared *d = &decl[k];
        const uint64_t count = (uint64_t)out->n * (uint64_t)d->components;
        if (d->is_coordinate) {
            if (out->points) return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': two <Points> arrays", path);
            TRY(read_block(f, path, base, room, d, count, &out->points));
            continue;
        }
        if (out->array_count == VTK_MAX_ARRAYS)
            return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': more than %d point arrays", path,
                             VTK_MAX_ARRAYS);
        VtkCellArray *a = &out->arrays[out->array_count++];
        memcpy(a->name, d->name, sizeof a->name);
        a->components = d->components;
        TRY(read_block(f, path, base, room, d, count, &a->data));
    }
    if (!out->points) return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': no <Points> array", path);
    return NSPD_OK;
}

static int read_points(FILE *f, const char *path, void *out) {
    memset(out, 0, sizeof(VtkPointSet));
    return read_points_file(f, path, out);
}

/* Appends piece `pc` to the whole set `out` (grown to hold it): its
 * arrays must be the first piece's. */
static int append_piece(const char *path, int index, VtkPointSet *pc, VtkPointSet *out) {
    if (index == 0) {
        out->array_count = pc->array_count;
        for (int k = 0; k < pc->array_count; k++) {
            memcpy(out->arrays[k].name, pc->arrays[k].name, sizeof out->arrays[k].name);
            out->arrays[k].components = pc->arrays[k].components;
        }
    }
    if (pc->array_count != out->array_count)
        return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': its pieces hold %d and %d point arrays", path,
                         out->array_count, pc->array_count);
    const size_t n0 = (size_t)out->n, n1 = n0 + (size_t)pc->n;
    TRY(nspd_realloc(&out->points, 3 * n0, 3 * n1, sizeof(double)));
    memcpy(out->points + 3 * n0, pc->points, 3 * (size_t)pc->n * sizeof(double));
    for (int k = 0; k < pc->array_count; k++) {
        VtkCellArray *to = &out->arrays[k];
        const VtkCellArray *from = &pc->arrays[k];
        if (strcmp(from->name, to->name) != 0 || from->components != to->components)
            return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': its pieces' array %d is '%s' and '%s'", path, k,
                             to->name, from->name);
        const size_t c = (size_t)to->components;
        TRY(nspd_realloc(&to->data, c * n0, c * n1, sizeof(double)));
        memcpy(to->data + c * n0, from->data, c * (size_t)pc->n * sizeof(double));
    }
    out->n = (int64_t)n1;
    return NSPD_OK;
}

/* The whole set of a .pvtu: its pieces' points in piece order. */
static int read_points_parallel(const char *path, const char *h, VtkPointSet *out) {
    const char *grid = strstr(h, "<PUnstructuredGrid");
    if (!grid) return NSPD_FAIL(NSPD_ERR_INPUT, "'%s': no <PUnstructuredGrid> element", path);
    int status = NSPD_OK, pieces = 0;
    for (const char *tag = strstr(grid, "<Piece"); tag && status == NSPD_OK;
         tag = strstr(tag + 1, "<Piece"), pieces++) {
        char piece_path[5200];
        VtkPointSet pc;
        memset(&pc, 0, sizeof pc);
        status = piece_source(path, tag, piece_path, sizeof piece_path);
        if (status == NSPD_OK && (status = read_path(piece_path, read_points, &pc)) != NSPD_OK)
            status = piece_failed(path, pieces, status);
        if (status == NSPD_OK) status = append_piece(path, pieces, &pc, out);
        vtk_point_set_free(&pc);
    }
    TRY(status);
    if (pieces == 0) return NSPD_FAIL(NSPD_ERR_INPUT, "'%s' names no pieces", path);
    return NSPD_OK;
}

int vtk_read_points(const char *path, VtkPointSet *out) {
    memset(out, 0, sizeof *out);
    char *header = NULL;
    TRY(read_path(path, read_head, &header));
    const bool parallel = strstr(header, "<VTKFile type=\"PUnstructuredGrid\"") != NULL;
    const int status =
        parallel ? read_points_parallel(path, header, out) : read_path(path, read_points, out);
    nspd_free(&header);
    return status;
}

void vtk_point_set_free(VtkPointSet *set) {
    nspd_free(&set->points);
    for (int k = 0; k < set->array_count; k++) nspd_free(&set->arrays[k].data);
    memset(set, 0, sizeof *set);
}

const VtkCellArray *vtk_find_cell_array(const VtkRectilinear *grid, const char *name,
                                        int components) {
    for (int k = 0; k < grid->array_count; k++)
        if (strcmp(grid->arrays[k].name, name) == 0 && grid->arrays[k].components == components)
            return &grid->arrays[k];
    return NULL;
}

void vtk_rectilinear_free(VtkRectilinear *grid) {
    for (int a = 0; a < 3; a++) nspd_free(&grid->face[a]);
    for (int k = 0; k < grid->array_count; k++) nspd_free(&grid->arrays[k].data);
    memset(grid, 0, sizeof *grid);
}
