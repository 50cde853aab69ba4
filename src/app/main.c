/* The nspd command: dispatches to the subcommands. */
#include "app/commands.h"
#include "core/comm.h"

#include <signal.h>
#include <stdio.h>
#include <string.h>

int main(int argc, char **argv) {
    if (argc < 2) {
        commands_usage(stderr);
        return 2;
    }
    /* past a file-size limit (ulimit -f, a quota) the write fails with EFBIG
     * and nspd says so, instead of the process dying of SIGXFSZ */
    signal(SIGXFSZ, SIG_IGN);
    const char *cmd = argv[1];
    /* nspd CMD --help: that command's usage, whatever else is on the line */
    const CommandHelp *help = command_help(cmd);
    if (help && command_asks_help(argc - 2, argv + 2)) {
        command_usage(stdout, help, true);
        return 0;
    }
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
        /* nspd help CMD is nspd CMD --help */
        const CommandHelp *of = argc > 2 ? command_help(argv[2]) : NULL;
        if (of)
            command_usage(stdout, of, true);
        else
            commands_usage(stdout);
        return 0;
    }
    fprintf(stderr, "nspd: unknown command '%s'\n\n", cmd);
    commands_usage(stderr);
    return 2;
}
