/* nspd plot OUTDIR [COLUMNS...] [--svg]: history.csv's columns against time,
 * as OUTDIR/history_<column>.png (and .svg), the pictures a run writes at
 * its end (output.plots); for a run that did not, or for other columns. */
#include "app/commands.h"
#include "core/status.h"
#include "io/cfg_tree.h"
#include "io/history_plot.h"

#include <stdio.h>
#include <string.h>

enum { MAX_COLUMNS = 256 };

int cmd_plot(int argc, char **argv) {
    const char *dir = NULL;
    char *columns[MAX_COLUMNS];
    int count = 0;
    bool svg = false;
    for (int i = 0; i < argc; i++) {
        if (strcmp(argv[i], "--svg") == 0) {
            svg = true;
        } else if (argv[i][0] == '-') {
            fprintf(stderr, "nspd plot: unknown option '%s'\n", argv[i]);
            command_usage(stderr, command_help("plot"), false);
            return EXIT_BAD_INPUT;
        } else if (!dir) {
            dir = argv[i];
        } else if (count < MAX_COLUMNS) {
            columns[count++] = argv[i];
        }
    }
    if (!dir || strlen(dir) > 4000) {
        fprintf(stderr, "nspd plot: which run?%s\n",
                dir ? " (a directory name of at most 4000 characters)" : "");
        command_usage(stderr, command_help("plot"), false);
        return EXIT_BAD_INPUT;
    }
    /* the case's name for the titles, from the resolved case */
    char path[4096 + 16];
    snprintf(path, sizeof path, "%s/case.yaml", dir);
    CfgDoc doc = {0};
    const char *name = "";
    const bool have_case = cfg_doc_load_file(&doc, path) == NSPD_OK;
    if (have_case) {
        const CfgNode *n = cfg_map_find(doc.root, "name");
        if (n && n->kind == CFG_SCALAR && !n->is_null) name = n->text;
    }
    int written = 0;
    const int status = history_plots(dir, name, columns, count, svg, &written);
    if (have_case) cfg_doc_free(&doc);
    if (status != NSPD_OK) {
        fprintf(stderr, "nspd plot: %s\n", nspd_error_message());
        return status == NSPD_ERR_INPUT ? EXIT_BAD_INPUT : EXIT_RUN_FAILED;
    }
    printf("%s: %d plots (history_<column>.png%s)\n", dir, written, svg ? " and .svg" : "");
    return 0;
}
