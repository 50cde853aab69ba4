/* nspd run | check | info: the commands that take a case file. */
#include "app/commands.h"
#include "app/options.h"
#include "core/comm.h"
#include "core/interrupt.h"
#include "core/log.h"
#include "core/mem.h"
#include "core/progress.h"
#include "core/status.h"
#include "core/timer.h"
#include "case/case_read.h"
#include "sim/sim.h"
#include "solid/solid.h"

#include <dirent.h>
#include <errno.h>
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <string.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

int exit_status_of(int status) {
    switch (status) {
    case NSPD_OK:
        return 0;
    case NSPD_ERR_INPUT:
        return EXIT_BAD_INPUT;
    case NSPD_ERR_INTERRUPTED:
        return EXIT_INTERRUPTED;
    default:
        return EXIT_RUN_FAILED;
    }
}

/* Prints a failure: bad input as the bare "FILE:LINE:COL: what; expected"
 * message (editors jump to it), anything else as "nspd: error: ...". The
 * log file, if open, gets it too, with the C source location and the
 * traceback of the TRYs it passed through. */
static int report(int status) {
    if (status == NSPD_OK || status == NSPD_ERR_INTERRUPTED) return exit_status_of(status);
    if (status == NSPD_ERR_INPUT)
        fprintf(stderr, "%s\n", nspd_error_message());
    else
        fprintf(stderr, "nspd: error: %s\n", nspd_error_message());
    nspd_log_file(LOG_ERROR, "%s (raised at %s)", nspd_error_message(), nspd_error_origin());
    if (nspd_error_trace_depth() > 0) nspd_log_file(LOG_DEBUG, "via %s", nspd_error_traceback());
    return exit_status_of(status);
}

/* Reads the case and builds the simulation. Any failure here is the user's
 * input (an unreadable file included): exit status 2, nothing written. */
static int load(const CaseOptions *opt, bool check_only, CfgDoc *doc, Sim *sim) {
    SimConfig cfg;
    int status = case_read(opt->case_path, opt->overrides, opt->override_count, doc, &cfg);
    if (status == NSPD_ERR_IO) status = NSPD_ERR_INPUT;
    if (status != NSPD_OK) return status;
    cfg.max_memory_bytes = opt->max_memory_mb * 1e6;
    cfg.check_only = check_only;
    cfg.comm = comm_world(); /* the processes of `mpirun nspd run` (this one alone otherwise) */
    cfg.processes[0] = opt->processes[0];
    cfg.processes[1] = opt->processes[1];
    status = sim_create(sim, &cfg);
    if (status != NSPD_OK) {
        sim_config_free(&cfg);
        cfg_doc_free(doc);
    }
    return status;
}

/* A case too large for check to build: its sizes, step and steps from the
 * estimates, and what was left to the build. */
static void describe_unbuilt(const Sim *sim, char *buf, size_t size) {
    const SolidEstimate *s = &sim->solid_estimate;
    const FlowEstimate *f = &sim->flow_estimate;
    int len = 0;
    if (sim->cfg.solid.kind != SOLID_NONE)
        len += snprintf(buf + len, size - (size_t)len, "about %.3g points, %.3g bonds, ", s->points,
                        s->bonds / 2);
    if (sim->cfg.flow.method != FLOW_METHOD_NONE && (size_t)len < size)
        len += snprintf(buf + len, size - (size_t)len, "about %.3g %s, ", f->cells,
                        f->items ? f->items : "cells");
    if ((size_t)len >= size) return;
    if (sim->dt > 0.0)
        len += snprintf(buf + len, size - (size_t)len, "dt %s%.4g s, about %lld steps",
                        sim->cfg.dt_given ? "" : "about ", sim->dt, (long long)sim->steps);
    else
        len += snprintf(buf + len, size - (size_t)len, "dt and steps known once built");
    if ((size_t)len >= size) return;
    snprintf(buf + len, size - (size_t)len,
             ", %.3g GB; checked from its configuration, not built: building it would take "
             "about %.2g s, over check's %.2g s; the checks that need its points, cells or "
             "nodes run when it is built (nspd info, nspd run)",
             sim->estimate_bytes / 1e9, s->check_s + f->check_s, sim_check_budget_s());
}

/* "253000 points, 3523910 bonds, dt 1.3e-08 s, 1250 steps" or the flow's
 * equivalent. */
static void describe(const Sim *sim, char *buf, size_t size) {
    if (!sim->built) {
        describe_unbuilt(sim, buf, size);
        return;
    }
    int len = 0;
    if (sim->solid) {
        solid_brief(sim->solid, buf, size);
        len = (int)strlen(buf);
    }
    if (sim->flow) {
        flow_brief(sim->flow, buf + len, size - (size_t)len);
        len = (int)strlen(buf);
    }
    snprintf(buf + len, size - (size_t)len, "dt %.4g s, %s%lld steps", sim->dt,
             sim->flow && !sim->cfg.dt_given ? "about " : "", (long long)sim->steps);
}

int cmd_check(int argc, char **argv) {
    CaseOptions opt;
    if (!options_parse(argc, argv, false, "check", &opt)) return EXIT_BAD_INPUT;
    CfgDoc doc;
    Sim sim;
    int status = load(&opt, true, &doc, &sim);
    if (status != NSPD_OK) return report(status);
    char what[640];
    describe(&sim, what, sizeof what);
    printf("%s: ok (case '%s': %s)\n", opt.case_path, sim.cfg.name, what);
    sim_destroy(&sim);
    cfg_doc_free(&doc);
    return 0;
}

/* nspd info's estimate of the run (outputs excluded; docs/PERFORMANCE.md,
 * "nspd info's estimate", has it against measured runs). */
typedef struct {
    int64_t steps;         /* the steps to time.end: from the step after the timed ones */
    double step_s;         /* s per step at that step */
    double seconds;        /* steps x step_s */
    double seconds_broken; /* the same with the solid's cost grown (SimConfig.solid_cost_growth) */
} RunEstimate;

/* A few steps timed part by part, after one untimed (the first touches
 * every array: page faults cost the plate of paper 000 six of its steps).
 * What the first steps' cost times the first step's count left out, each
 * a factor on the coupled blasts (issue 61; docs/PERFORMANCE.md "nspd
 * info's estimate"):
 * - the flow's step moves as the gas does: a blast's first CFL step, set
 *   by the charge at rest, is 1.6 times the one five steps later, which
 *   is shorter than the later ones again; the run's steps, measured, lie
 *   between the counts at those two steps (within 1.25 of their mean on
 *   the six blasts and detonations), so the estimate takes the mean;
 * - the solid's cost follows its sub-steps, so the solid is its time per
 *   sub-step, timed, times the sub-steps of the mean step;
 * - a solid whose cost per sub-step grows once it breaks
 *   (SimConfig.solid_cost_growth, the case reader's) gives a second
 *   figure with its growth.
 * The coupling's own iterations (the penalty's CG) change little over a
 * run (13 to 22 on the blasts), so it is taken per step as timed. */
static int estimate_run(Sim *sim, RunEstimate *out) {
    const int64_t first_steps = sim->steps; /* from the first step's size */
    const int64_t warm = sim->steps > 1 ? 1 : 0;
    const int64_t probe = sim->steps - warm < 5 ? sim->steps - warm : 5;
    TRY(sim_advance(sim, warm));
    double part0[SIM_PART_COUNT];
    memcpy(part0, sim->part_s, sizeof part0);
    const double t0 = nspd_wall_time();
    int64_t substeps = 0, done = 0;
    for (; done < probe && sim->time < sim->cfg.end_time * (1.0 - 1e-12); done++) {
        TRY(sim_advance(sim, 1));
        if (sim->solid) substeps += solid_last_substeps(sim->solid);
    }
    const double wall = nspd_wall_time() - t0;
    const double n = (double)(done > 0 ? done : 1);
    const double flow_s = (sim->part_s[SIM_PART_FLOW] - part0[SIM_PART_FLOW]) / n;
    const double coupling_s = (sim->part_s[SIM_PART_COUPLING] - part0[SIM_PART_COUPLING]) / n;
    const double solid_total = sim->part_s[SIM_PART_SOLID] - part0[SIM_PART_SOLID];
    /* what no part's clock holds (the step's own bookkeeping) */
    const double rest_s = fmax(0.0, wall / n - (flow_s + coupling_s + solid_total / n));
    double solid_s = solid_total / n;
    int64_t steps = first_steps;
    if (sim->flow && !sim->cfg.dt_given && done > 0 && sim->dt > 0.0) {
        const double end = sim->cfg.end_time;
        const double now = (double)sim->step + fmax(0.0, ceil((end - sim->time) / sim->dt - 1e-9));
        steps = (int64_t)ceil(0.5 * ((double)first_steps + now));
        if (sim->solid && substeps > 0) {
            const double per = ceil(end / (double)steps / sim->solid_substep * (1.0 - 1e-12));
            solid_s = solid_total / (double)substeps * fmax(per, 1.0);
        }
    }
    out->steps = steps;
    out->step_s = flow_s + coupling_s + solid_s + rest_s;
    out->seconds = out->step_s * (double)steps;
    const double growth = sim->cfg.solid_cost_growth > 1.0 ? sim->cfg.solid_cost_growth : 1.0;
    out->seconds_broken = (out->step_s + (growth - 1.0) * solid_s) * (double)steps;
    return NSPD_OK;
}

int cmd_info(int argc, char **argv) {
    CaseOptions opt;
    if (!options_parse(argc, argv, false, "info", &opt)) return EXIT_BAD_INPUT;
    CfgDoc doc;
    Sim sim;
    double t0 = nspd_wall_time();
    int status = load(&opt, false, &doc, &sim);
    if (status != NSPD_OK) return report(status);
    double setup_s = nspd_wall_time() - t0;
    size_t memory = nspd_mem_live_bytes();
    /* what the models say of themselves and the step, taken before the
     * timed steps below move them: "at the start" must mean the start */
    char solid_text[4096] = "", flow_text[4096] = "";
    if (sim.solid) solid_info(sim.solid, memory, solid_text, sizeof solid_text);
    if (sim.flow) flow_info(sim.flow, memory, flow_text, sizeof flow_text);
    const double start_dt = sim.dt;
    RunEstimate est;
    status = estimate_run(&sim, &est);
    if (status != NSPD_OK) {
        sim_destroy(&sim);
        cfg_doc_free(&doc);
        return report(status);
    }
    char eta[32], eta_broken[32];
    progress_format_duration(est.seconds, eta, sizeof eta);
    progress_format_duration(est.seconds_broken, eta_broken, sizeof eta_broken);
    printf("case                 %s\n", sim.cfg.name);
    fputs(solid_text, stdout);
    fputs(flow_text, stdout);
    if (sim.solid && sim.flow && sim.constrained)
        printf("time step            %.6g s (%s); the strong coupling constrains the solid at "
               "every step\n",
               start_dt, sim.cfg.dt_given ? "given" : "the solid's step, below the CFL step");
    else if (sim.solid && sim.flow)
        printf("time step            %.6g s (%s); the solid sub-steps at most %.6g s\n", start_dt,
               sim.cfg.dt_given ? "given" : "the flow's CFL step", sim.solid_substep);
    else
        printf("time step            %.6g s (%s)\n", start_dt,
               sim.cfg.dt_given ? "given"
               : sim.solid      ? "safety factor x stable"
                                : "CFL; it follows the flow");
    printf("steps                %s%lld to t = %.6g s\n", sim.flow ? "about " : "",
           (long long)sim.steps, sim.flow ? sim.cfg.end_time : (double)sim.steps * sim.dt);
    printf("memory estimate      %.1f MB before building (%.1f MB allocated after; the case is "
           "refused before building if the estimate exceeds this machine or --max-memory)\n",
           sim.estimate_bytes / 1e6, (double)memory / 1e6);
    printf("threads              %d\n", omp_get_max_threads());
    printf("setup                %.3g s\n", setup_s);
    if (est.seconds_broken > est.seconds)
        printf("estimated run time   %s, or %s if the solid yields and breaks (%.3g s per step "
               "over about %lld steps, outputs excluded)\n",
               eta, eta_broken, est.step_s, (long long)est.steps);
    else
        printf("estimated run time   %s (%.3g s per step over %s%lld steps, outputs excluded)\n",
               eta, est.step_s, sim.flow ? "about " : "", (long long)est.steps);
    sim_destroy(&sim);
    cfg_doc_free(&doc);
    return 0;
}

/* Output files nspd writes, for --force to clear before a new run: every
 * series of docs/CASES.md, and any "*.part" a stopped run left half
 * written (core/out_file.h). */
static bool is_part_file(const char *name) {
    const size_t len = strlen(name);
    return len > 5 && strcmp(name + len - 5, ".part") == 0;
}

static bool is_output_file(const char *name) {
    static const char *const exact[] = {"case.yaml", "log.txt",  "history.csv", "summary.json",
                                        "solid.pvd", "flow.pvd", NULL};
    static const char *const prefix[] = {"solid_", "damage_",    "line_",    "flow_",       "mach_",
                                         "speed_", "schlieren_", "surface_", "checkpoint_", NULL};
    if (is_part_file(name)) return true;
    const size_t len = strlen(name); /* nspd movie's and nspd report's */
    if ((len > 4 && strcmp(name + len - 4, ".mp4") == 0) || strcmp(name, "report.html") == 0)
        return true;
    for (int i = 0; exact[i]; i++)
        if (strcmp(name, exact[i]) == 0) return true;
    for (int i = 0; prefix[i]; i++)
        if (strncmp(name, prefix[i], strlen(prefix[i])) == 0) return true;
    return false;
}

/* Removes the files of dir whose names `match`. */
static int remove_files(const char *dir, bool (*match)(const char *name)) {
    DIR *d = opendir(dir);
    if (!d) return NSPD_FAIL(NSPD_ERR_IO, "cannot read directory '%s'", dir);
    struct dirent *e;
    char path[8192];
    while ((e = readdir(d)))
        if (match(e->d_name)) {
            snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
            remove(path);
        }
    closedir(d);
    return NSPD_OK;
}

static int make_dirs(const char *path) {
    char buf[4096];
    snprintf(buf, sizeof buf, "%s", path);
    for (char *p = buf + 1; *p; p++) {
        if (*p != '/') continue;
        *p = '\0';
        if (mkdir(buf, 0777) != 0 && errno != EEXIST)
            return NSPD_FAIL(NSPD_ERR_IO, "cannot create directory '%s': %s", buf, strerror(errno));
        *p = '/';
    }
    if (mkdir(buf, 0777) != 0 && errno != EEXIST)
        return NSPD_FAIL(NSPD_ERR_IO, "cannot create directory '%s': %s", buf, strerror(errno));
    return NSPD_OK;
}

/* Takes the directory's lock (DIR/.nspd.lock, an flock held until the
 * process ends, so a killed run releases it): a second run into a
 * directory a live run is writing is refused, --force or not. */
static int lock_dir(const char *dir, int *fd) {
    char path[4200];
    snprintf(path, sizeof path, "%s/.nspd.lock", dir);
    *fd = open(path, O_CREAT | O_RDWR | O_CLOEXEC, 0644);
    if (*fd < 0) return NSPD_FAIL(NSPD_ERR_IO, "cannot create '%s' (%s)", path, strerror(errno));
    if (flock(*fd, LOCK_EX | LOCK_NB) != 0) {
        const int busy = errno == EWOULDBLOCK;
        char pid[32] = "";
        const ssize_t n = read(*fd, pid, sizeof pid - 1);
        pid[n > 0 ? n : 0] = '\0';
        pid[strcspn(pid, "\n")] = '\0';
        close(*fd);
        *fd = -1;
        if (busy)
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "output directory '%s' is in use by a running nspd (pid %s); "
                             "expected another directory (-o DIR) or the end of that run",
                             dir, pid[0] ? pid : "unknown");
        return NSPD_FAIL(NSPD_ERR_IO, "cannot lock '%s' (%s)", path, strerror(errno));
    }
    char pid[32];
    const int len = snprintf(pid, sizeof pid, "%ld\n", (long)getpid());
    if (ftruncate(*fd, 0) != 0 || write(*fd, pid, (size_t)len) != len) {
        /* the pid is for the message of a refused second run only */
    }
    return NSPD_OK;
}

static int prepare_dir(const char *dir, bool force, int *lock_fd) {
    struct stat st;
    if (stat(dir, &st) == 0) {
        if (!S_ISDIR(st.st_mode))
            return NSPD_FAIL(NSPD_ERR_INPUT, "'%s' exists and is not a directory", dir);
        if (!force) /* refused with nothing written, not even the lock */
            return NSPD_FAIL(NSPD_ERR_INPUT,
                             "output directory '%s' exists; expected a new directory (use "
                             "--force to replace its results, or -o DIR)",
                             dir);
        /* a live run's directory is refused before any of its files is touched */
        TRY(lock_dir(dir, lock_fd));
        return remove_files(dir, is_output_file);
    }
    TRY(make_dirs(dir));
    return lock_dir(dir, lock_fd);
}

/* --resume: the directory of the run to continue, locked; its log goes on. */
static int reopen_dir(const char *dir, int *lock_fd) {
    struct stat st;
    if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode))
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "cannot resume: output directory '%s' does not exist; expected the "
                         "directory of the run to continue (-o DIR)",
                         dir);
    TRY(lock_dir(dir, lock_fd));
    /* what a killed run left half written is never a result */
    return remove_files(dir, is_part_file);
}

/* Where the run writes (rank 0 of several): the directory prepared (or
 * reopened to resume), the resolved case and the log. */
static int open_outputs(const CaseOptions *opt, const char *dir, CfgDoc *doc, int *lock_fd) {
    TRY(opt->resume ? reopen_dir(dir, lock_fd) : prepare_dir(dir, opt->force, lock_fd));
    char path[8192];
    if (!opt->resume) {
        snprintf(path, sizeof path, "%s/case.yaml", dir);
        TRY(case_write_resolved(doc, path));
    }
    snprintf(path, sizeof path, "%s/log.txt", dir);
    return nspd_log_open(path, opt->resume);
}

int cmd_run(int argc, char **argv) {
    /* under mpirun every rank runs this; rank 0 prints and writes, and
     * what fails on any rank is agreed (comm_agree), so all stop together
     * with the message of the rank that failed, printed once by rank 0 */
    const NspdComm world = comm_world();
    const bool writer = world.rank == 0;
    if (!writer) {
        nspd_log_set_console_level(LOG_QUIET);
        if (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr)) {
            /* still quiet through the log level; nothing else prints here */
        }
    }
    CaseOptions opt;
    if (!options_parse(argc, argv, true, "run", &opt)) return EXIT_BAD_INPUT;
    CfgDoc doc;
    Sim sim;
    const int loaded = load(&opt, false, &doc, &sim);
    int status = comm_agree(&world, loaded, NULL, 0);
    if (status != NSPD_OK) {
        if (loaded == NSPD_OK) { /* another rank failed */
            sim_destroy(&sim);
            cfg_doc_free(&doc);
        }
        return report(status);
    }
    char dir[4096];
    if (opt.out_dir)
        snprintf(dir, sizeof dir, "%s", opt.out_dir);
    else
        snprintf(dir, sizeof dir, "out/%s", sim.cfg.name);
    int lock_fd = -1;
    status = case_resolved_hash(&doc, &sim.case_hash);
    if (status == NSPD_OK && writer) status = open_outputs(&opt, dir, &doc, &lock_fd);
    status = comm_agree(&world, status, NULL, 0);
    if (status == NSPD_OK && opt.quiet) nspd_log_set_console_level(LOG_WARN);
    if (status == NSPD_OK && !writer) nspd_log_set_console_level(LOG_QUIET);
    if (status == NSPD_OK)
        nspd_log(LOG_INFO, "nspd %s: case '%s' from %s -> %s%s", NSPD_VERSION, sim.cfg.name,
                 opt.case_path, dir, opt.resume ? " (resumed)" : "");
    /* every rank reads the checkpoint (its own rows of it) */
    if (status == NSPD_OK && opt.resume)
        status = comm_agree(&world, sim_resume(&sim, dir), NULL, 0);
    if (status == NSPD_OK) {
        char what[256];
        describe(&sim, what, sizeof what);
        if (comm_distributed(&world))
            nspd_log(LOG_INFO, "%s, %d processes x %d threads", what, world.size,
                     omp_get_max_threads());
        else
            nspd_log(LOG_INFO, "%s, %d threads", what, omp_get_max_threads());
        interrupt_install();
        SimRunOptions ro = {writer ? dir : NULL, !opt.quiet && writer,
                            comm_distributed(&world) ? dir : NULL};
        status = sim_run(&sim, &ro);
        if (status == NSPD_OK || status == NSPD_ERR_INTERRUPTED) {
            if (sim.flow && flow_fallbacks_total(sim.flow) > 0)
                nspd_log(LOG_INFO,
                         "flow: %lld first-order fallbacks (a limited slope would have made the "
                         "density or pressure negative at a face); per step in history.csv",
                         (long long)flow_fallbacks_total(sim.flow));
            nspd_log(LOG_INFO, "done: %lld steps to t = %g s in %.2f s; results in %s/",
                     (long long)sim.step, sim.time, sim.wall_s, dir);
        }
    }
    int code = report(status);
    nspd_log_close();
    sim_destroy(&sim);
    cfg_doc_free(&doc);
    if (lock_fd >= 0) close(lock_fd); /* releases the directory */
    return code;
}
