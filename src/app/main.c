/* The nspd command: dispatches to the subcommands. */
#include "app/commands.h"
#include "core/comm.h"

#include <signal.h>
#include <stdio.h>
#include <string.h>

static void usage(FILE *out) {
    fputs("usage: nspd <command> [options]\n"
          "\n"
          "commands:\n"
          "  run CASE.yaml [-o DIR] [--force | --resume] [--set key=value ...] [--quiet]\n"
          "                         run a case; results go to DIR (default out/<case name>);\n"
          "                         --resume continues it from its last checkpoint\n"
          "  mpirun -n P nspd run CASE.yaml [--processes PXxPY] ...\n"
          "                         the same run shared by P processes (GKS flows, their\n"
          "                         bodies and coupled solids, a bond solid alone; the same\n"
          "                         results); the flow on PX x PY blocks (default: the\n"
          "                         fewest halo cells)\n"
          "  (run, check, info also take --threads T and --max-memory MB: refuse a case\n"
          "   whose memory estimate exceeds MB; default this machine's memory)\n"
          "  check CASE.yaml [--set key=value ...]\n"
          "                         validate a case file; write nothing\n"
          "  info CASE.yaml [--set key=value ...]\n"
          "                         derived numbers: points, bonds, time step, memory, run time\n"
          "  bench pd [--points N] [--threads T] [--steps S]\n"
          "                         PD force + integration throughput, one JSON object\n"
          "  bench gks [--cells N] [--threads T] [--steps S]\n"
          "                         viscous GKS flow step throughput, one JSON object\n"
          "  movie OUTDIR [--field NAME] [--fps N]\n"
          "                         MP4 movies of a run's picture series (ffmpeg)\n"
          "  plot OUTDIR [COLUMN ...] [--svg]\n"
          "                         history.csv's columns against time: history_<column>.png\n"
          "  report OUTDIR [--frame N]\n"
          "                         OUTDIR/report.html: one self-contained page of the run\n"
          "  riemann [--left R,U,P] [--right R,U,P] [--time T] [--cells N] ...\n"
          "                         exact shock-tube solution as CSV (the reference)\n"
          "  radial [--geometry planar|cylindrical|spherical] [--cells N] [--probes R,...] ...\n"
          "                         a blast's converged 1D radial solution as CSV (the\n"
          "                         reference of the strong-shock cases)\n"
          "  version                print the version\n"
          "\n"
          "exit status: 0 success, 1 run-time failure, 2 bad input, 130 interrupted\n",
          out);
}

int main(int argc, char **argv) {
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    /* past a file-size limit (ulimit -f, a quota) the write fails with EFBIG
     * and nspd says so, instead of the process dying of SIGXFSZ */
    signal(SIGXFSZ, SIG_IGN);
    const char *cmd = argv[1];
    if (strcmp(cmd, "run") == 0) {
        /* under an MPI launcher the run is shared by its processes */
        comm_init(&argc, &argv);
        const int code = cmd_run(argc - 2, argv + 2);
        comm_finalize();
        return code;
    }
    if (strcmp(cmd, "check") == 0) return cmd_check(argc - 2, argv + 2);
    if (strcmp(cmd, "info") == 0) return cmd_info(argc - 2, argv + 2);
    if (strcmp(cmd, "bench") == 0) return cmd_bench(argc - 2, argv + 2);
    if (strcmp(cmd, "movie") == 0) return cmd_movie(argc - 2, argv + 2);
    if (strcmp(cmd, "plot") == 0) return cmd_plot(argc - 2, argv + 2);
    if (strcmp(cmd, "report") == 0) return cmd_report(argc - 2, argv + 2);
    if (strcmp(cmd, "riemann") == 0) return cmd_riemann(argc - 2, argv + 2);
    if (strcmp(cmd, "radial") == 0) return cmd_radial(argc - 2, argv + 2);
    if (strcmp(cmd, "version") == 0 || strcmp(cmd, "--version") == 0) {
        printf("nspd %s\n", NSPD_VERSION);
        return 0;
    }
    if (strcmp(cmd, "help") == 0 || strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0) {
        usage(stdout);
        return 0;
    }
    fprintf(stderr, "nspd: unknown command '%s'\n\n", cmd);
    usage(stderr);
    return 2;
}
