/* The usage text of every subcommand, once: `nspd --help` lists each
 * command's synopsis and summary, `nspd CMD --help` prints that command's
 * synopsis, summary and options, and a command's usage error ends with its
 * synopsis. A new command or option is written here and nowhere else. */
#include "app/commands.h"

#include <stdio.h>
#include <string.h>

/* run, check and info share these (lines of at most 80 columns, as in
 * every text here: the synopses at most 66, so that "usage: nspd " fits) */
#define CASE_OPTIONS                                                                               \
    "  --set KEY=VALUE   replace or add one key of the case (also -s; repeatable):\n"              \
    "                    KEY is its path as the error messages print it, maps by\n"                \
    "                    name and list items by number (solid.boundaries[0].velocity\n"            \
    "                    or solid.boundaries.0.velocity); VALUE is YAML ([1, 2],\n"                \
    "                    {shape: circle, radius: 0.1})\n"                                          \
    "  --threads T       OpenMP threads (default: OMP_NUM_THREADS, else every core)\n"             \
    "  --max-memory MB   refuse a case whose memory estimate exceeds MB\n"                         \
    "                    (default: this machine's memory)\n"                                       \
    "  --quiet, -q       warnings and errors only\n"

/* what every bench takes */
#define BENCH_OPTIONS                                                                              \
    "  --points N, --cells N   the problem's size (flops: iterations per chain)\n"                 \
    "  --steps S               steps timed (memory, flops: repeats, the best kept)\n"              \
    "  --threads T             OpenMP threads\n"

static const CommandHelp COMMANDS[] = {
    {"run",
     "run CASE.yaml [-o DIR] [--force | --resume] [--set KEY=VALUE ...]\n"
     "    [--quiet] [--threads T] [--max-memory MB] [--processes PXxPY]",
     "run a case into DIR (default out/<case name>);\n"
     "--resume continues it from its last checkpoint; under\n"
     "`mpirun -n P` the run is shared by P processes",
     "  -o DIR            the output directory (default out/<case name>)\n"
     "  --force           replace the results in an existing DIR\n"
     "  --resume          continue the run in DIR from its last checkpoint\n" CASE_OPTIONS
     "  --processes PXxPY under `mpirun -n P nspd run`: the flow on PX x PY blocks\n"
     "                    (PX times PY = P; default: the fewest halo cells); GKS\n"
     "                    flows, their bodies and coupled solids, a bond solid\n"
     "                    alone; the same results on any number of processes\n"},
    {"check", "check CASE.yaml [--set KEY=VALUE ...] [--threads T]\n    [--max-memory MB]",
     "validate a case file; write nothing", CASE_OPTIONS},
    {"info", "info CASE.yaml [--set KEY=VALUE ...] [--threads T]\n    [--max-memory MB]",
     "derived numbers: points, bonds, cells, time step,\n"
     "memory, the run time estimated from a few timed steps",
     CASE_OPTIONS},
    {"bench",
     "bench pd [--points N] [--threads T] [--steps S]\n"
     "bench cpd [--points N] [--threads T] [--steps S]\n"
     "bench gks [--cells N] [--threads T] [--steps S]\n"
     "bench memory [--points N] [--threads T] [--steps REPEATS]\n"
     "bench flops [--points ITERATIONS] [--threads T] [--steps REPEATS]",
     "throughput, one JSON object: pd the bond-based PD force\n"
     "and integration, cpd the correspondence solid's, gks\n"
     "the viscous GKS flow step, memory the STREAM triad's\n"
     "bandwidth, flops the FP64 peak (SIMD and scalar)",
     BENCH_OPTIONS},
    {"movie", "movie OUTDIR [--field NAME] [--fps N]",
     "MP4 movies (H.264, by ffmpeg) of a run's picture series",
     "  --field NAME      only the series NAME_00000.png, NAME_00001.png, ...\n"
     "                    (default: every series of two or more frames)\n"
     "  --fps N           frames per second, 0.1 to 120 (default 10)\n"},
    {"plot", "plot OUTDIR [COLUMN ...] [--svg]",
     "history.csv's columns against time:\n"
     "OUTDIR/history_<column>.png",
     "  COLUMN ...        the columns to draw (default: every one)\n"
     "  --svg             an .svg beside each .png\n"},
    {"report", "report OUTDIR [--frame N]",
     "OUTDIR/report.html: one self-contained page of the run",
     "  --frame N         the field output whose pictures it shows (default: the last)\n"},
    {"riemann",
     "riemann [--left RHO,U,P] [--right RHO,U,P] [--gamma G] [--time T]\n"
     "    [--x0 X] [--length L] [--cells N]",
     "the exact shock-tube solution as CSV (the reference of\n"
     "the shock-tube cases)",
     "  defaults: Sod's problem on (0, 1), the diaphragm at x0 0.5, gamma 1.4, at\n"
     "  t = 0.2 on 400 cells\n"},
    {"radial",
     "radial [--geometry planar|cylindrical|spherical] [--gamma G]\n"
     "    [--charge RHO,U,P] [--ambient RHO,U,P] [--radius R0]\n"
     "    [--length L] [--cells N] [--time T] [--outer wall|open]\n"
     "    [--cfl C] [--probes R1,R2,...]",
     "a blast's converged 1D radial solution as CSV: the\n"
     "profile at T, or with --probes the pressure histories\n"
     "at those radii (the strong-shock cases' reference)",
     "  defaults: cylindrical, gamma 1.4, charge 1,0,1 in r < 0.25, ambient 1,0,1e-4,\n"
     "  L 1.5, 20000 cells, t 0.5, outer wall, cfl 0.4: the strong cylindrical shock\n"
     "  of cases/strong_shock_cylindrical.yaml\n"},
    {"version", "version", "print the version", NULL},
};

enum { COMMAND_COUNT = (int)(sizeof COMMANDS / sizeof COMMANDS[0]) };
/* the column the main list's summaries start in */
enum { SUMMARY_COLUMN = 25 };

const CommandHelp *command_help(const char *name) {
    for (int i = 0; i < COMMAND_COUNT; i++)
        if (strcmp(COMMANDS[i].name, name) == 0) return &COMMANDS[i];
    return NULL;
}

/* Each line of `text` after `first` (the first line) or `rest` (the others). */
static void put_lines(FILE *out, const char *text, const char *first, const char *rest) {
    for (int k = 0; *text; k++) {
        const size_t len = strcspn(text, "\n");
        fprintf(out, "%s%.*s\n", k == 0 ? first : rest, (int)len, text);
        text += len + (text[len] == '\n');
    }
}

/* "usage: nspd bench pd ...\n       nspd bench cpd ...": every synopsis line
 * that starts a form of the command gets "nspd", continuations are indented */
static void put_synopsis(FILE *out, const CommandHelp *c, const char *lead) {
    const char *text = c->synopsis;
    const int indent = (int)strlen(lead);
    for (int k = 0; *text; k++) {
        const size_t len = strcspn(text, "\n");
        const bool continued = text[0] == ' ';
        if (k == 0)
            fputs(lead, out);
        else
            fprintf(out, "%*s", indent, "");
        fprintf(out, "%s%.*s\n", continued ? "     " : "nspd ", (int)len, text);
        text += len + (text[len] == '\n');
    }
}

void command_usage(FILE *out, const CommandHelp *c, bool full) {
    put_synopsis(out, c, "usage: ");
    if (!full) {
        fprintf(out, "(nspd %s --help says more)\n", c->name);
        return;
    }
    fputc('\n', out);
    put_lines(out, c->summary, "", "");
    if (c->options) {
        fputs("\noptions:\n", out);
        fputs(c->options, out);
    }
    fputs("\nexit status: 0 success, 1 run-time failure, 2 bad input, 130 interrupted\n", out);
}

void commands_usage(FILE *out) {
    fputs("usage: nspd <command> [options]      nspd <command> --help: its options\n"
          "\n"
          "commands:\n",
          out);
    char indent[SUMMARY_COLUMN + 1];
    memset(indent, ' ', SUMMARY_COLUMN);
    indent[SUMMARY_COLUMN] = '\0';
    for (int i = 0; i < COMMAND_COUNT; i++) {
        const CommandHelp *c = &COMMANDS[i];
        const size_t len = strlen(c->synopsis);
        if (!strchr(c->synopsis, '\n') && len + 3 < SUMMARY_COLUMN) {
            /* "  version                print the version" */
            char first[SUMMARY_COLUMN + 1];
            snprintf(first, sizeof first, "  %-*s", SUMMARY_COLUMN - 2, c->synopsis);
            put_lines(out, c->summary, first, indent);
        } else {
            put_lines(out, c->synopsis, "  ", "  ");
            put_lines(out, c->summary, indent, indent);
        }
    }
    fputs("\nexit status: 0 success, 1 run-time failure, 2 bad input, 130 interrupted\n", out);
}

bool command_asks_help(int argc, char **argv) {
    for (int i = 0; i < argc; i++) {
        /* the value of --set or -s is a key=value, never a request */
        if (strcmp(argv[i], "--set") == 0 || strcmp(argv[i], "-s") == 0) {
            i++;
            continue;
        }
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) return true;
    }
    return false;
}
