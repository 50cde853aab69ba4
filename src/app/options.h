/* Command-line options shared by run, check and info. */
#ifndef NSPD_APP_OPTIONS_H
#define NSPD_APP_OPTIONS_H

#include <stdbool.h>

enum { MAX_OVERRIDES = 128 };

typedef struct {
    const char *case_path;
    const char *out_dir; /* -o */
    bool force, quiet;
    bool resume;      /* --resume: continue the run in the output directory from its checkpoint */
    int threads;      /* --threads, 0 = OpenMP default */
    int processes[2]; /* --processes PXxPY: the flow's process grid; 0: its own */
    double
        max_memory_mb; /* --max-memory: the case's estimate may not exceed it; 0: the machine's */
    char *overrides[MAX_OVERRIDES];
    int override_count;
} CaseOptions;

/* Parses argv; on a usage error prints it and returns false. `allow_output`
 * enables -o/--force (run only). */
bool options_parse(int argc, char **argv, bool allow_output, const char *command, CaseOptions *opt);

/* Parses "A,B,C" (e.g. a gas state RHO,U,P) into out[0..2]; false unless
 * the whole text is three numbers separated by commas. */
bool option_parse_triple(const char *text, double out[3]);

/* Parses one number; false unless the whole text is a number. */
bool option_parse_number(const char *text, double *out);

#endif
