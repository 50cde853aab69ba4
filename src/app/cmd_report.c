/* nspd report: one HTML page that sums up a run (OUTDIR/report.html).
 *
 * The page is a single self-contained file: pictures and movies are
 * embedded as data: URIs and the styling is inline, so it opens anywhere,
 * offline, and can be mailed or archived on its own. It shows the case name
 * and description, the headline numbers of summary.json with their units,
 * the timing split and the machine, the history plots (history_*.png, when
 * the run wrote them), the last picture of every series (and the one of a
 * chosen output, --frame N), the movies (*.mp4, from nspd movie) and the
 * resolved case, collapsed. summary.json and case.yaml are read with the
 * case reader's YAML parser (JSON is YAML). Written as report.html.part and
 * renamed, like every output. */
#include "app/commands.h"
#include "core/out_file.h"
#include "core/status.h"
#include "io/cfg_tree.h"
#include "io/units.h"

#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/utsname.h>
#include <unistd.h>

enum { MAX_PATH = 4096 + 256, MAX_SERIES = 64, MAX_NAME = 128 };

/* Writes s with the characters HTML gives a meaning escaped. */
static void html_text(FILE *f, const char *s) {
    for (; *s; s++) {
        switch (*s) {
        case '<':
            fputs("&lt;", f);
            break;
        case '>':
            fputs("&gt;", f);
            break;
        case '&':
            fputs("&amp;", f);
            break;
        case '"':
            fputs("&quot;", f);
            break;
        default:
            fputc(*s, f);
        }
    }
}

/* The file at path as base64 (a data: URI's payload); false if unreadable. */
static bool base64_file(FILE *out, const char *path) {
    static const char ALPHABET[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    FILE *in = fopen(path, "rb");
    if (!in) return false;
    unsigned char b[3 * 1024];
    size_t n;
    while ((n = fread(b, 1, sizeof b, in)) > 0) {
        for (size_t i = 0; i < n; i += 3) {
            const unsigned v = (unsigned)b[i] << 16 | (i + 1 < n ? (unsigned)b[i + 1] << 8 : 0u) |
                               (i + 2 < n ? (unsigned)b[i + 2] : 0u);
            fputc(ALPHABET[v >> 18 & 63], out);
            fputc(ALPHABET[v >> 12 & 63], out);
            fputc(i + 1 < n ? ALPHABET[v >> 6 & 63] : '=', out);
            fputc(i + 2 < n ? ALPHABET[v & 63] : '=', out);
        }
        if (n < sizeof b) break; /* fread fills the buffer but at the end */
    }
    const bool ok = !ferror(in);
    fclose(in);
    return ok;
}

static const char *scalar(const CfgNode *map, const char *key) {
    const CfgNode *n = map ? cfg_map_find(map, key) : NULL;
    return n && n->kind == CFG_SCALAR && !n->is_null ? n->text : NULL;
}

/* The time of output `index` from the series' .pvd (NaN when unknown). */
static double output_time(const char *dir, int index) {
    static const char *const PVD[] = {"flow.pvd", "solid.pvd"};
    char want[32];
    snprintf(want, sizeof want, "_%05d.", index);
    for (int k = 0; k < 2; k++) {
        char path[MAX_PATH];
        snprintf(path, sizeof path, "%.4000s/%s", dir, PVD[k]);
        FILE *f = fopen(path, "r");
        if (!f) continue;
        char line[1024];
        double t = (double)NAN;
        while (fgets(line, sizeof line, f)) {
            const char *ts = strstr(line, "timestep=\"");
            if (ts && strstr(line, want)) {
                t = strtod(ts + 10, NULL);
                break;
            }
        }
        fclose(f);
        if (!isnan(t)) return t;
    }
    return (double)NAN;
}

typedef struct {
    char name[MAX_NAME];
    int last; /* highest output index */
} Series;

/* Picture series NAME_NNNNN.png (pictures of history plots excluded). */
static int picture_series(const char *dir, Series *out) {
    int count = 0;
    DIR *d = opendir(dir);
    if (!d) return 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        const char *n = e->d_name;
        const size_t len = strlen(n);
        if (len < 11 || len - 10 >= MAX_NAME || strcmp(n + len - 4, ".png") != 0 ||
            n[len - 10] != '_')
            continue;
        char *end;
        const long index = strtol(n + len - 9, &end, 10);
        if (end != n + len - 4) continue;
        const size_t stem = len - 10;
        int k = 0;
        while (k < count && !(strlen(out[k].name) == stem && strncmp(out[k].name, n, stem) == 0))
            k++;
        if (k == count) {
            if (count == MAX_SERIES) continue;
            memcpy(out[k].name, n, stem);
            out[k].name[stem] = '\0';
            out[k].last = -1;
            count++;
        }
        if (index > out[k].last) out[k].last = (int)index;
    }
    closedir(d);
    return count;
}

static int by_name(const void *a, const void *b) {
    return strcmp(((const Series *)a)->name, ((const Series *)b)->name);
}

/* Files of dir that end in `suffix` and start with `prefix`, sorted. */
static int files_like(const char *dir, const char *prefix, const char *suffix,
                      char names[][MAX_NAME], int max) {
    int count = 0;
    DIR *d = opendir(dir);
    if (!d) return 0;
    struct dirent *e;
    while ((e = readdir(d)) && count < max) {
        const size_t len = strlen(e->d_name), ls = strlen(suffix), lp = strlen(prefix);
        if (len < ls + lp || len >= MAX_NAME || strncmp(e->d_name, prefix, lp) != 0 ||
            strcmp(e->d_name + len - ls, suffix) != 0)
            continue;
        snprintf(names[count++], MAX_NAME, "%.127s", e->d_name);
    }
    closedir(d);
    qsort(names, (size_t)count, MAX_NAME, (int (*)(const void *, const void *))strcmp);
    return count;
}

static void figure(FILE *f, const char *dir, const char *file, const char *caption) {
    char path[MAX_PATH];
    snprintf(path, sizeof path, "%.4000s/%.200s", dir, file);
    fputs("<figure><img alt=\"", f);
    html_text(f, file);
    fputs("\" src=\"data:image/png;base64,", f);
    base64_file(f, path);
    fputs("\"><figcaption>", f);
    html_text(f, caption);
    fputs("</figcaption></figure>\n", f);
}

static void snapshot(FILE *f, const char *dir, const Series *s, int index) {
    char file[MAX_NAME + 16], caption[MAX_NAME + 96];
    snprintf(file, sizeof file, "%.120s_%05d.png", s->name, index);
    const double t = output_time(dir, index);
    if (!isnan(t))
        snprintf(caption, sizeof caption, "%.120s, output %d, t = %g s", s->name, index, t);
    else
        snprintf(caption, sizeof caption, "%.120s, output %d", s->name, index);
    figure(f, dir, file, caption);
}

static void summary_table(FILE *f, const CfgNode *summary) {
    static const char *const MACHINE[] = {"wall_s",  "flow_s",      "solid_s", "coupling_s",
                                          "threads", "peak_rss_mb", NULL};
    fputs("<h2>Results (summary.json)</h2>\n<table>\n<tr><th>quantity</th><th>value</th>"
          "<th>unit</th></tr>\n",
          f);
    for (int k = 0; summary && k < summary->count; k++) {
        const CfgNode *n = summary->child[k];
        if (n->kind != CFG_SCALAR || !n->key) continue;
        bool machine = strstr(n->key, "_per_s") && strstr(n->key, "updates");
        for (int m = 0; MACHINE[m]; m++) machine |= strcmp(n->key, MACHINE[m]) == 0;
        if (machine) continue; /* in the timing table */
        fputs("<tr><td>", f);
        html_text(f, n->key);
        fputs("</td><td class=\"num\">", f);
        html_text(f, n->is_null ? "-" : n->text);
        fputs("</td><td>", f);
        html_text(f, units_of_key(n->key));
        fputs("</td></tr>\n", f);
    }
    fputs("</table>\n", f);
}

static void timing_table(FILE *f, const CfgNode *summary) {
    const char *wall = scalar(summary, "wall_s");
    const double total = wall ? strtod(wall, NULL) : 0.0;
    static const char *const PARTS[][2] = {
        {"flow_s", "flow"}, {"solid_s", "solid"}, {"coupling_s", "coupling"}};
    fputs("<h2>Time</h2>\n<table>\n<tr><th>part</th><th>wall time, s</th><th>share</th></tr>\n", f);
    double parts = 0.0;
    for (int k = 0; k < 3; k++) {
        const char *v = scalar(summary, PARTS[k][0]);
        if (!v) continue;
        const double s = strtod(v, NULL);
        parts += s;
        fprintf(f,
                "<tr><td>%s</td><td class=\"num\">%.3f</td><td class=\"num\">%.1f %%</td></tr>\n",
                PARTS[k][1], s, total > 0 ? 100.0 * s / total : 0.0);
    }
    fprintf(f,
            "<tr><td>outputs and the rest</td><td class=\"num\">%.3f</td><td class=\"num\">%.1f "
            "%%</td></tr>\n<tr><th>run</th><th class=\"num\">%.3f</th><th></th></tr>\n</table>\n",
            total - parts, total > 0 ? 100.0 * (total - parts) / total : 0.0, total);
    static const char *const RATES[] = {"bond_updates_per_s", "cell_updates_per_s", NULL};
    for (int k = 0; RATES[k]; k++) {
        const char *v = scalar(summary, RATES[k]);
        if (v) fprintf(f, "<p>%s: %s</p>\n", RATES[k], v);
    }
}

static void machine(FILE *f, const CfgNode *summary) {
    struct utsname u;
    char cpu[256] = "unknown";
    FILE *info = fopen("/proc/cpuinfo", "r");
    if (info) {
        char line[512];
        while (fgets(line, sizeof line, info))
            if (strncmp(line, "model name", 10) == 0 && strchr(line, ':')) {
                snprintf(cpu, sizeof cpu, "%s", strchr(line, ':') + 2);
                cpu[strcspn(cpu, "\n")] = '\0';
                break;
            }
        fclose(info);
    }
    const char *threads = scalar(summary, "threads");
    const char *rss = scalar(summary, "peak_rss_mb");
    fputs("<h2>Machine</h2>\n<p>", f);
    if (uname(&u) == 0) {
        html_text(f, u.sysname);
        fputc(' ', f);
        html_text(f, u.release);
        fputs(", ", f);
        html_text(f, u.machine);
        fputs("; ", f);
    }
    html_text(f, cpu);
    fprintf(f, "; %ld cores online; the run used %s threads and peaked at %s MB; nspd %s</p>\n",
            sysconf(_SC_NPROCESSORS_ONLN), threads ? threads : "?", rss ? rss : "?", NSPD_VERSION);
}

static void resolved_case(FILE *f, const char *path) {
    FILE *in = fopen(path, "r");
    if (!in) return;
    fputs("<h2>Case</h2>\n<details><summary>the resolved case (case.yaml)</summary><pre>", f);
    char line[4096];
    while (fgets(line, sizeof line, in)) html_text(f, line);
    fclose(in);
    fputs("</pre></details>\n", f);
}

static const char STYLE[] =
    "body{font-family:sans-serif;max-width:1200px;margin:2em auto;padding:0 1em;color:#222}"
    "h1{margin-bottom:0.2em}table{border-collapse:collapse;margin:0.5em 0}"
    "td,th{border-bottom:1px solid #ddd;padding:0.25em 0.8em;text-align:left}"
    ".num{text-align:right;font-variant-numeric:tabular-nums}"
    "figure{display:inline-block;margin:0.5em;vertical-align:top;max-width:48%}"
    "figure img,video{max-width:100%;max-height:480px;border:1px solid #ccc}"
    "figcaption{font-size:0.9em;color:#555}pre{background:#f6f6f6;padding:1em;overflow:auto}";

static int write_report(FILE *f, const char *dir, int frame) {
    char path[MAX_PATH];
    CfgDoc summary_doc = {0}, case_doc = {0};
    snprintf(path, sizeof path, "%.4000s/summary.json", dir);
    if (cfg_doc_load_file(&summary_doc, path) != NSPD_OK) {
        fprintf(stderr, "nspd report: cannot read %s: %s; expected a run's output directory\n",
                path, nspd_error_message());
        return EXIT_BAD_INPUT;
    }
    snprintf(path, sizeof path, "%.4000s/case.yaml", dir);
    const bool have_case = cfg_doc_load_file(&case_doc, path) == NSPD_OK;
    const CfgNode *summary = summary_doc.root;
    const char *name = scalar(summary, "case");
    const char *description = have_case ? scalar(case_doc.root, "description") : NULL;

    fputs("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>nspd: ", f);
    html_text(f, name ? name : dir);
    fprintf(f, "</title><style>%s</style></head><body>\n<h1>", STYLE);
    html_text(f, name ? name : dir);
    fputs("</h1>\n", f);
    if (description) {
        fputs("<p class=\"description\">", f);
        html_text(f, description);
        fputs("</p>\n", f);
    }
    const char *completed = scalar(summary, "completed");
    const char *stopped = scalar(summary, "stopped_by");
    fprintf(f, "<p>run to t = %s s in %s steps: %s</p>\n",
            scalar(summary, "time_s") ? scalar(summary, "time_s") : "?",
            scalar(summary, "steps") ? scalar(summary, "steps") : "?",
            completed && strcmp(completed, "true") == 0 ? "completed"
            : stopped                                   ? "stopped"
                                                        : "incomplete");
    if (stopped) {
        fputs("<p><strong>stopped by:</strong> ", f);
        html_text(f, stopped);
        fputs("</p>\n", f);
    }
    summary_table(f, summary);

    char names[MAX_SERIES][MAX_NAME];
    int n = files_like(dir, "history_", ".png", names, MAX_SERIES);
    if (n > 0) fputs("<h2>Histories</h2>\n", f);
    for (int k = 0; k < n; k++) figure(f, dir, names[k], names[k]);

    Series series[MAX_SERIES];
    const int ns = picture_series(dir, series);
    qsort(series, (size_t)ns, sizeof *series, by_name);
    if (ns > 0) fputs("<h2>Pictures</h2>\n", f);
    for (int k = 0; k < ns; k++) {
        if (strncmp(series[k].name, "history", 7) == 0) continue;
        if (frame >= 0 && frame < series[k].last) snapshot(f, dir, &series[k], frame);
        snapshot(f, dir, &series[k], series[k].last);
    }

    n = files_like(dir, "", ".mp4", names, MAX_SERIES);
    if (n > 0) fputs("<h2>Movies</h2>\n", f);
    for (int k = 0; k < n; k++) {
        snprintf(path, sizeof path, "%.4000s/%.200s", dir, names[k]);
        fputs("<figure><video controls loop muted playsinline src=\"data:video/mp4;base64,", f);
        base64_file(f, path);
        fputs("\"></video><figcaption>", f);
        html_text(f, names[k]);
        fputs("</figcaption></figure>\n", f);
    }

    timing_table(f, summary);
    machine(f, summary);
    snprintf(path, sizeof path, "%.4000s/case.yaml", dir);
    resolved_case(f, path);
    fputs("</body></html>\n", f);
    cfg_doc_free(&summary_doc);
    if (have_case) cfg_doc_free(&case_doc);
    return 0;
}

int cmd_report(int argc, char **argv) {
    const char *dir = NULL;
    int frame = -1;
    for (int i = 0; i < argc; i++) {
        if (strcmp(argv[i], "--frame") == 0 && i + 1 < argc) {
            char *end;
            const long v = strtol(argv[++i], &end, 10);
            if (*end != '\0' || v < 0 || v > 99999) {
                fprintf(stderr, "nspd report: --frame needs an output number, 0 to 99999\n");
                return EXIT_BAD_INPUT;
            }
            frame = (int)v;
        } else if (argv[i][0] != '-' && !dir) {
            dir = argv[i];
        } else {
            fprintf(stderr, "nspd report: unexpected '%s'\n", argv[i]);
            command_usage(stderr, command_help("report"), false);
            return EXIT_BAD_INPUT;
        }
    }
    if (!dir || strlen(dir) > 4000) {
        fprintf(stderr, "nspd report: which run?%s\n",
                dir ? " (a directory name of at most 4000 characters)" : "");
        command_usage(stderr, command_help("report"), false);
        return EXIT_BAD_INPUT;
    }
    struct stat st;
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode)) {
        fprintf(stderr, "nspd report: '%s' is not a directory; expected a run's output directory\n",
                dir);
        return EXIT_BAD_INPUT;
    }
    char path[MAX_PATH];
    snprintf(path, sizeof path, "%s/report.html", dir);
    OutFile out;
    if (out_file_open(&out, path) != NSPD_OK) {
        fprintf(stderr, "nspd report: %s\n", nspd_error_message());
        return EXIT_RUN_FAILED;
    }
    const int status = write_report(out.f, dir, frame);
    if (status != 0) {
        out_file_abort(&out);
        return status;
    }
    if (out_file_close(&out, 0) != NSPD_OK) {
        fprintf(stderr, "nspd report: %s\n", nspd_error_message());
        return EXIT_RUN_FAILED;
    }
    printf("%s\n", path);
    return 0;
}
