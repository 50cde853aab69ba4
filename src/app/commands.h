/* The subcommands of `nspd`; each returns the process exit status. */
#ifndef NSPD_APP_COMMANDS_H
#define NSPD_APP_COMMANDS_H

enum { EXIT_RUN_FAILED = 1, EXIT_BAD_INPUT = 2, EXIT_INTERRUPTED = 130 };

int cmd_run(int argc, char **argv);
int cmd_check(int argc, char **argv);
int cmd_info(int argc, char **argv);
int cmd_bench(int argc, char **argv);
int cmd_riemann(int argc, char **argv);
int cmd_radial(int argc, char **argv);
int cmd_movie(int argc, char **argv);
int cmd_report(int argc, char **argv);
int cmd_plot(int argc, char **argv);

/* Maps an NspdStatus to the exit status above. */
int exit_status_of(int status);

#endif
