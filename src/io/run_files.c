#include "io/run_files.h"

#include "core/mem.h"
#include "core/status.h"
#include "io/json.h"
#include "core/out_file.h"
#include "io/figure.h" /* figure_format_time */
#include "io/render.h"

#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int history_open(HistoryFile *h, const char *dir) {
    memset(h, 0, sizeof *h);
    snprintf(h->path, sizeof h->path, "%s/history.csv", dir);
    h->file = fopen(h->path, "w");
    if (!h->file)
        return NSPD_FAIL(NSPD_ERR_IO, "cannot create '%s' (%s)", h->path, strerror(errno));
    return NSPD_OK;
}

int history_resume(HistoryFile *h, const char *dir, int64_t bytes) {
    memset(h, 0, sizeof *h);
    snprintf(h->path, sizeof h->path, "%s/history.csv", dir);
    struct stat st;
    if (stat(h->path, &st) != 0)
        return NSPD_FAIL(NSPD_ERR_INPUT, "cannot resume: '%s' is missing (%s)", h->path,
                         strerror(errno));
    if ((int64_t)st.st_size < bytes)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "cannot resume: '%s' has %lld bytes, fewer than the %lld the checkpoint "
                         "counted (was it edited or replaced?)",
                         h->path, (long long)st.st_size, (long long)bytes);
    /* the rows after the checkpoint (a run killed later) are written again */
    if (truncate(h->path, (off_t)bytes) != 0)
        return NSPD_FAIL(NSPD_ERR_IO, "cannot truncate '%s' (%s)", h->path, strerror(errno));
    h->file = fopen(h->path, "a");
    if (!h->file)
        return NSPD_FAIL(NSPD_ERR_IO, "cannot append to '%s' (%s)", h->path, strerror(errno));
    h->header_written = bytes > 0;
    return NSPD_OK;
}

int history_bytes(HistoryFile *h, int64_t *bytes) {
    *bytes = 0;
    if (!h->file) return NSPD_OK;
    const long at = fflush(h->file) == 0 ? ftell(h->file) : -1;
    if (at < 0) return NSPD_FAIL(NSPD_ERR_IO, "cannot write '%s' (%s)", h->path, strerror(errno));
    *bytes = at;
    return NSPD_OK;
}

static int check_capacity(const Report *r, const char *what) {
    if (!r->overflow) return NSPD_OK;
    return NSPD_FAIL(NSPD_ERR_INPUT,
                     "the case asks for more than %d %s (bodies, probes); expected fewer",
                     REPORT_MAX_ITEMS, what);
}

int history_write(HistoryFile *h, const Report *row) {
    TRY(check_capacity(row, "history columns"));
    if (!h->file) return NSPD_OK;
    if (!h->header_written) {
        for (int k = 0; k < row->n; k++) fprintf(h->file, "%s%s", k ? "," : "", row->item[k].name);
        fputc('\n', h->file);
        h->header_written = true;
    }
    for (int k = 0; k < row->n; k++) {
        const ReportItem *it = &row->item[k];
        const char *sep = k ? "," : "";
        switch (it->kind) {
        case REPORT_PRECISE:
            fprintf(h->file, "%s%.12g", sep, it->real);
            break;
        case REPORT_INT:
        case REPORT_BOOL:
            fprintf(h->file, "%s%lld", sep, (long long)it->count);
            break;
        case REPORT_TEXT:
            fprintf(h->file, "%s%s", sep, it->text);
            break;
        case REPORT_REAL:
        default:
            fprintf(h->file, "%s%.9g", sep, it->real);
            break;
        }
    }
    fputc('\n', h->file);
    if (fflush(h->file) != 0 || ferror(h->file))
        return NSPD_FAIL(NSPD_ERR_IO, "cannot write '%s' (%s)", h->path,
                         strerror(errno ? errno : EIO));
    return NSPD_OK;
}

void history_close(HistoryFile *h) {
    if (h->file) fclose(h->file);
    h->file = NULL;
}

int summary_write(const char *dir, const Report *summary) {
    TRY(check_capacity(summary, "summary keys"));
    char path[4096];
    snprintf(path, sizeof path, "%s/summary.json", dir);
    OutFile out;
    TRY(out_file_open(&out, path));
    FILE *f = out.f;
    JsonWriter w;
    json_begin(&w, f);
    for (int k = 0; k < summary->n; k++) {
        const ReportItem *it = &summary->item[k];
        switch (it->kind) {
        case REPORT_INT:
            json_int(&w, it->name, it->count);
            break;
        case REPORT_BOOL:
            json_bool(&w, it->name, it->count != 0);
            break;
        case REPORT_TEXT:
            json_string(&w, it->name, it->text);
            break;
        case REPORT_REAL:
        case REPORT_PRECISE:
        default:
            json_number(&w, it->name, it->real);
            break;
        }
    }
    json_end(&w);
    return out_file_close(&out, 0);
}

/* A piece's file name: "flow_00003_p0001.vtr". */
static void piece_name(const FieldSet *fs, int index, int piece, char *buf, size_t size) {
    snprintf(buf, size, "%s_%05d_p%04d.%s", fs->series, index, piece,
             fs->mesh == MESH_GRID ? "vtr" : "vtu");
}

/* The parallel file that names the pieces of output `index`. */
static int write_parallel(const char *path, int index, const FieldSet *fs) {
    const FieldPiece *pc = &fs->piece;
    char(*names)[64];
    const char **sources;
    TRY(nspd_alloc(&names, (size_t)pc->count, sizeof *names));
    int status = nspd_alloc(&sources, (size_t)pc->count, sizeof *sources);
    for (int p = 0; p < pc->count && status == NSPD_OK; p++) {
        piece_name(fs, index, p, names[p], sizeof names[p]);
        sources[p] = names[p];
    }
    if (status == NSPD_OK)
        status = fs->mesh == MESH_GRID
                     ? vtk_write_pvtr(path, fs->nx, fs->ny, pc->count, pc->cells, sources,
                                      pc->field, pc->field_count)
                     : vtk_write_pvtu(path, pc->count, sources, pc->field, pc->field_count);
    nspd_free(&sources);
    nspd_free(&names);
    return status;
}

static int write_vtk(const char *dir, int index, double t, const FieldSet *fs, PvdSeries *pvd) {
    char name[256], path[4096];
    const bool pieces = fs->piece.count > 1;
    const char *ext = fs->mesh == MESH_GRID ? (pieces ? "pvtr" : "vtr") : (pieces ? "pvtu" : "vtu");
    snprintf(name, sizeof name, "%s_%05d.%s", fs->series, index, ext);
    snprintf(path, sizeof path, "%s/%s", dir, name);
    if (pieces) {
        TRY(write_parallel(path, index, fs));
    } else if (fs->mesh == MESH_GRID) {
        const double zf[2] = {0.0, 0.0};
        TRY(vtk_write_rectilinear(path, fs->nx, fs->ny, 1, fs->face[0], fs->face[1], zf, fs->field,
                                  fs->field_count, fs->point_field, fs->point_field_count));
    } else {
        TRY(vtk_write_points(path, fs->n, fs->position, fs->field, fs->field_count));
    }
    char pvd_path[4096];
    snprintf(pvd_path, sizeof pvd_path, "%s/%s.pvd", dir, fs->series);
    return pvd_add(pvd, pvd_path, t, name);
}

int field_set_write_piece(const char *dir, int index, const FieldSet *fs,
                          const FieldOutputOptions *opt) {
    const FieldPiece *pc = &fs->piece;
    if (pc->count <= 1 || fs->mesh == MESH_NONE || !opt->vtk) return NSPD_OK;
    char name[256], path[4096];
    piece_name(fs, index, pc->index, name, sizeof name);
    snprintf(path, sizeof path, "%s/%s", dir, name);
    if (fs->mesh == MESH_GRID)
        return vtk_write_rectilinear_piece(path, pc->cells[pc->index], pc->face[0], pc->face[1],
                                           pc->field, pc->field_count);
    return vtk_write_points(path, pc->n, pc->position, pc->field, pc->field_count);
}

/* The overlay's window: the points' box, enlarged by its own size on each side. */
static void overlay_window(const FieldSet *pts, double window[4]) {
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-(double)INFINITY, -(double)INFINITY};
    for (int64_t i = 0; i < pts->n; i++)
        for (int d = 0; d < 2; d++) {
            lo[d] = fmin(lo[d], pts->position[d][i]);
            hi[d] = fmax(hi[d], pts->position[d][i]);
        }
    double size = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    window[0] = lo[0] - size;
    window[1] = lo[1] - size;
    window[2] = hi[0] + size;
    window[3] = hi[1] + size;
}

/* A picture's title: "plate_crack - damage - t = 16.7 µs". */
static void picture_title(char *buf, size_t size, const char *case_name, const char *what,
                          double t) {
    char when[64];
    figure_format_time(t, when, sizeof when);
    snprintf(buf, size, "%s%s%s - t = %s", case_name ? case_name : "", case_name ? " - " : "", what,
             when);
}

/* Whether `overlay` is a points mesh with a picture to draw over a grid. */
static bool has_overlay(const FieldSet *overlay) {
    return overlay && overlay->mesh == MESH_POINTS && overlay->picture_count > 0;
}

static int write_picture(const char *dir, int index, double t, const FieldSet *fs,
                         const PictureRef *pic, const FieldSet *overlay,
                         const FieldOutputOptions *opt) {
    char path[4096], title[512];
    const char *label = pic->label ? pic->label : pic->file;
    snprintf(path, sizeof path, "%s/%s_%05d.png", dir, pic->file, index);
    picture_title(title, sizeof title, opt->case_name, label, t);
    RenderOptions ro = {pic->lo,      pic->hi, pic->map, opt->png_max_pixels,
                        {0, 0, 0, 0}, title,   label,    pic->units};
    if (fs->mesh == MESH_POINTS)
        return render_points_png(path, fs->n, fs->position, pic->values, fs->spacing, &ro);
    TRY(render_grid_png(path, fs->nx, fs->ny, fs->face[0], fs->face[1], pic->values, fs->blank, &ro,
                        NULL));
    if (!pic->overlay_file || !has_overlay(overlay)) return NSPD_OK;
    const PictureRef *top = &overlay->picture[0];
    for (int k = 0; k < overlay->picture_count && overlay->overlay_picture; k++)
        if (strcmp(overlay->picture[k].file, overlay->overlay_picture) == 0)
            top = &overlay->picture[k];
    const char *top_label = top->label ? top->label : top->file;
    RenderPoints pts = {overlay->n,       {overlay->position[0], overlay->position[1]},
                        top->values,      overlay->spacing,
                        top->lo,          top->hi,
                        top->overlay_map, top_label,
                        top->units};
    snprintf(path, sizeof path, "%s/%s_%05d.png", dir, pic->overlay_file, index);
    char what[256];
    snprintf(what, sizeof what, "%s with %s", label, top_label);
    picture_title(title, sizeof title, opt->case_name, what, t);
    overlay_window(overlay, ro.window);
    return render_grid_png(path, fs->nx, fs->ny, fs->face[0], fs->face[1], pic->values, fs->blank,
                           &ro, &pts);
}

int table_write(const char *dir, int index, double t, const TableRef *tab) {
    char path[4096];
    snprintf(path, sizeof path, "%s/%s_%05d.csv", dir, tab->file, index);
    OutFile out;
    TRY(out_file_open(&out, path));
    FILE *f = out.f;
    fprintf(f, "# t = %.9g s\n%s\n", t, tab->header);
    for (int64_t r = 0; r < tab->rows; r++) {
        for (int c = 0; c < tab->ncol; c++) {
            const char *sep = c ? "," : "";
            const double v = tab->col[c][r];
            if (tab->integer_cols & (1u << c))
                fprintf(f, "%s%lld", sep, (long long)v);
            else if (tab->short_cols & (1u << c))
                fprintf(f, "%s%.6g", sep, v);
            else
                fprintf(f, "%s%.9g", sep, v);
        }
        fputc('\n', f);
    }
    return out_file_close(&out, 0);
}

int field_set_write(const char *dir, int index, double t, const FieldSet *fs,
                    const FieldSet *overlay, const FieldOutputOptions *opt, PvdSeries *pvd) {
    if (fs->mesh != MESH_NONE && opt->vtk) TRY(write_vtk(dir, index, t, fs, pvd));
    for (int k = 0; k < fs->picture_count && opt->png && fs->mesh != MESH_NONE; k++)
        if (!fs->picture[k].coupled_only || has_overlay(overlay))
            TRY(write_picture(dir, index, t, fs, &fs->picture[k], overlay, opt));
    for (int k = 0; k < fs->table_count; k++) TRY(table_write(dir, index, t, &fs->table[k]));
    return NSPD_OK;
}
