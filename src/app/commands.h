/* The subcommands of `nspd`; each returns the process exit status. */
#ifndef NSPD_APP_COMMANDS_H
#define NSPD_APP_COMMANDS_H

#include <stdbool.h>
#include <stdio.h>

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

/* One command's help (app/help.c): what `nspd --help` lists and `nspd CMD
 * --help` prints. Texts are lines separated by '\n'. */
typedef struct {
    const char *name;     /* "run" */
    const char *synopsis; /* "run CASE.yaml [-o DIR] ...": one line per form of the command;
                             a line that starts with spaces continues the one before */
    const char *summary;  /* what it does, a line or two */
    const char *options;  /* the options, one to a line, for CMD --help; NULL: none */
} CommandHelp;

/* The help of command `name`; NULL when there is no such command. */
const CommandHelp *command_help(const char *name);
/* "usage: nspd CMD ..." to `out`; `full`: with the summary, the options and
 * the exit statuses (CMD --help), else one line pointing at CMD --help (the
 * end of a usage error). */
void command_usage(FILE *out, const CommandHelp *c, bool full);
/* `nspd --help`: every command's synopsis and summary. */
void commands_usage(FILE *out);
/* Whether an argument of a command is --help or -h (a --set value is not). */
bool command_asks_help(int argc, char **argv);

/* Maps an NspdStatus to the exit status above. */
int exit_status_of(int status);

#endif
