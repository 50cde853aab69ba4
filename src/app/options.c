#include "app/options.h"

#include "app/commands.h"
#include "core/comm.h"

#include <omp.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

bool options_parse(int argc, char **argv, bool allow_output, const char *command,
                   CaseOptions *opt) {
    memset(opt, 0, sizeof *opt);
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i];
        const char *value = NULL;
        if (strcmp(a, "--set") == 0 || strcmp(a, "-s") == 0) {
            if (i + 1 >= argc) {
                fprintf(stderr, "nspd %s: --set needs key=value\n", command);
                return false;
            }
            value = argv[++i];
        } else if (strncmp(a, "--set=", 6) == 0) {
            value = a + 6;
        }
        if (value) {
            if (opt->override_count == MAX_OVERRIDES) {
                fprintf(stderr, "nspd %s: more than %d --set options\n", command, MAX_OVERRIDES);
                return false;
            }
            opt->overrides[opt->override_count++] = (char *)value;
        } else if (allow_output && strcmp(a, "-o") == 0) {
            if (i + 1 >= argc) {
                fprintf(stderr, "nspd %s: -o needs a directory\n", command);
                return false;
            }
            opt->out_dir = argv[++i];
        } else if (allow_output && strcmp(a, "--force") == 0) {
            opt->force = true;
        } else if (allow_output && strcmp(a, "--resume") == 0) {
            opt->resume = true;
        } else if (strcmp(a, "--quiet") == 0 || strcmp(a, "-q") == 0) {
            opt->quiet = true;
        } else if (strcmp(a, "--threads") == 0) {
            if (i + 1 >= argc || atoi(argv[i + 1]) < 1) {
                fprintf(stderr, "nspd %s: --threads needs a positive number\n", command);
                return false;
            }
            opt->threads = atoi(argv[++i]);
        } else if (strcmp(a, "--processes") == 0) {
            int px = 0, py = 0, used = 0;
            if (i + 1 >= argc || sscanf(argv[i + 1], "%dx%d%n", &px, &py, &used) != 2 ||
                argv[i + 1][used] != '\0' || px < 1 || py < 1) {
                fprintf(stderr,
                        "nspd %s: --processes needs the flow's process grid as PXxPY (blocks "
                        "along x and along y, e.g. 4x2)\n",
                        command);
                return false;
            }
            /* any case: a solid alone, divided by points, takes none but
             * the count's, and a grid of another count is a mistake */
            const int p = comm_world().size;
            if ((int64_t)px * py != p) {
                fprintf(stderr,
                        "nspd %s: --processes %dx%d makes %lld blocks for %d process%s; expected "
                        "PXxPY with PX times PY = %d\n",
                        command, px, py, (long long)px * py, p, p == 1 ? "" : "es", p);
                return false;
            }
            opt->processes[0] = px;
            opt->processes[1] = py;
            i++;
        } else if (strcmp(a, "--max-memory") == 0) {
            char *end = NULL;
            const double mb = i + 1 < argc ? strtod(argv[i + 1], &end) : 0.0;
            if (i + 1 >= argc || end == argv[i + 1] || *end != '\0' || !(mb > 0)) {
                fprintf(stderr, "nspd %s: --max-memory needs a positive number of MB\n", command);
                return false;
            }
            opt->max_memory_mb = mb;
            i++;
        } else if (a[0] == '-') {
            fprintf(stderr, "nspd %s: unknown option '%s'\n", command, a);
            command_usage(stderr, command_help(command), false);
            return false;
        } else if (!opt->case_path) {
            opt->case_path = a;
        } else {
            fprintf(stderr, "nspd %s: one case file at a time ('%s' and '%s')\n", command,
                    opt->case_path, a);
            return false;
        }
    }
    if (!opt->case_path) {
        fprintf(stderr, "nspd %s: which case?\n", command);
        command_usage(stderr, command_help(command), false);
        return false;
    }
    if (opt->force && opt->resume) {
        fprintf(stderr,
                "nspd %s: --force (start again) and --resume (continue) exclude each other\n",
                command);
        return false;
    }
    if (opt->threads > 0) omp_set_num_threads(opt->threads);
    return true;
}

bool option_parse_triple(const char *text, double out[3]) {
    const char *p = text;
    for (int i = 0; i < 3; i++) {
        char *end;
        out[i] = strtod(p, &end);
        if (end == p || *end != (i < 2 ? ',' : '\0')) return false;
        p = end + 1;
    }
    return true;
}

bool option_parse_number(const char *text, double *out) {
    char *end;
    *out = strtod(text, &end);
    return end != text && *end == '\0';
}
