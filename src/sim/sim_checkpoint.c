/* Checkpoints of a whole run, and resuming from them.
 *
 * A checkpoint (core/checkpoint.h) holds, in order: the driver's clock and
 * output schedule (step, time, the last dt, the next output and checkpoint
 * times, the field index, history.csv's length, the .pvd series), then the
 * solid's, the flow's and the coupling's state (each model's own
 * checkpoint operation), then the probes'. It is written after a step's
 * outputs, so a resumed run repeats nothing and skips nothing: the steps,
 * outputs, history rows and summary after it are those of the run that was
 * never stopped, bit for bit, at any thread count (every result in nspd is
 * independent of the thread count; tests/cli/test_resume.sh).
 *
 * Files: DIR/checkpoint_<step, 12 digits>.nspd, the newest
 * SIM_CHECKPOINTS_KEPT kept (the newest could be the one a crash damaged;
 * its checksum then fails and the one before is used). */
#include "sim/sim.h"

#include "core/checkpoint.h"
#include "core/hash.h"
#include "core/log.h"
#include "core/mem.h"
#include "core/status.h"
#include "core/timer.h"

#include <dirent.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* How the state is laid out in a checkpoint: as one process holds it all
 * (written so by a run on several processes too; sim_checkpoint_write). */
static const char *const LAYOUT = "serial";
enum { MAX_CHECKPOINT_FILES = 256, MAX_PVD_NAME = 4096 };

/* The executable's own bytes: a checkpoint continues bit for bit only in
 * the binary that wrote it (another build may round differently). */
static uint64_t binary_hash(void) {
    static uint64_t hash;
    static bool known;
    if (!known) {
        if (hash64_file("/proc/self/exe", &hash) != NSPD_OK) {
            hash = hash64(NSPD_VERSION, sizeof NSPD_VERSION); /* no /proc: the version */
            nspd_error_clear();
        }
        known = true;
    }
    return hash;
}

/* A .pvd series: its times and its file names (as one block of
 * NUL-terminated names). */
static int pvd_io(Checkpoint *ck, PvdSeries *pvd) {
    int64_t count = pvd->count, bytes = 0;
    for (int i = 0; i < pvd->count; i++) bytes += (int64_t)strlen(pvd->files[i]) + 1;
    TRY(checkpoint_io_int64(ck, "pvd.count", &count));
    TRY(checkpoint_io_int64(ck, "pvd.name_bytes", &bytes));
    if (count < 0 || count > INT32_MAX || bytes < count || bytes > count * MAX_PVD_NAME)
        return NSPD_FAIL(NSPD_ERR_INPUT, "checkpoint: a .pvd series of %lld files in %lld bytes",
                         (long long)count, (long long)bytes);
    double *times = NULL;
    char *names = NULL;
    int status = nspd_alloc(&times, (size_t)count + 1, sizeof *times);
    if (status == NSPD_OK) status = nspd_alloc(&names, (size_t)bytes + 1, 1);
    if (status == NSPD_OK && !checkpoint_reading(ck)) {
        char *at = names;
        for (int i = 0; i < pvd->count; i++) {
            times[i] = pvd->times[i];
            const size_t len = strlen(pvd->files[i]) + 1;
            memcpy(at, pvd->files[i], len);
            at += len;
        }
    }
    if (status == NSPD_OK)
        status = checkpoint_io(ck, "pvd.times", times, (size_t)count * sizeof *times);
    if (status == NSPD_OK) status = checkpoint_io(ck, "pvd.files", names, (size_t)bytes);
    if (status == NSPD_OK && checkpoint_reading(ck)) {
        pvd_free(pvd);
        names[bytes] = '\0';
        const char *name = names;
        for (int64_t i = 0; i < count && status == NSPD_OK; i++) {
            if (name >= names + bytes)
                status = NSPD_FAIL(NSPD_ERR_INPUT, "checkpoint: a .pvd series lacks names");
            else
                status = pvd_append(pvd, times[i], name);
            name += strlen(name) + 1;
        }
    }
    nspd_free(&times);
    nspd_free(&names);
    return status;
}

/* Everything a run carries from step to step, written or read. */
static int state_io(Sim *sim, Checkpoint *ck) {
    TRY(checkpoint_io_int64(ck, "sim.step", &sim->step));
    TRY(checkpoint_io_double(ck, "sim.time", &sim->time));
    TRY(checkpoint_io_double(ck, "sim.dt", &sim->dt));
    TRY(checkpoint_io_int64(ck, "sim.steps", &sim->steps));
    TRY(checkpoint_io_double(ck, "sim.next_field", &sim->next_field));
    TRY(checkpoint_io_double(ck, "sim.next_history", &sim->next_history));
    TRY(checkpoint_io_double(ck, "sim.next_checkpoint", &sim->next_checkpoint));
    TRY(checkpoint_io_int(ck, "sim.field_index", &sim->field_index));
    TRY(checkpoint_io_int64(ck, "sim.history_bytes", &sim->history_bytes));
    TRY(checkpoint_io_double(ck, "sim.wall_s", &sim->wall_s));
    TRY(checkpoint_io(ck, "sim.part_s", sim->part_s, sizeof sim->part_s));
    for (int k = 0; k < 2; k++) TRY(pvd_io(ck, &sim->pvd[k]));
    /* the coupling's after the models', which it may read */
    if (sim->solid) TRY(solid_checkpoint(sim->solid, ck));
    if (sim->flow) TRY(flow_checkpoint(sim->flow, ck));
    if (sim->coupling) TRY(coupling_checkpoint(sim->coupling, ck));
    return probes_checkpoint(sim->probes, sim->cfg.output.probe_count, ck);
}

static bool checkpoint_name(const char *name, long long *step) {
    char tail[8];
    int used = 0;
    if (sscanf(name, "checkpoint_%12lld%7s%n", step, tail, &used) != 2) return false;
    return strcmp(tail, ".nspd") == 0 && (size_t)used == strlen(name) && strlen(name) == 28;
}

static int by_step_descending(const void *a, const void *b) {
    const long long x = *(const long long *)a, y = *(const long long *)b;
    return x < y ? 1 : x > y ? -1 : 0;
}

/* The steps of the checkpoints in `dir`, newest first. */
static int list_checkpoints(const char *dir, long long *steps, int *count) {
    *count = 0;
    DIR *d = opendir(dir);
    if (!d) return NSPD_FAIL(NSPD_ERR_INPUT, "cannot read directory '%s'", dir);
    struct dirent *e;
    long long step;
    while ((e = readdir(d)))
        if (checkpoint_name(e->d_name, &step) && *count < MAX_CHECKPOINT_FILES)
            steps[(*count)++] = step;
    closedir(d);
    qsort(steps, (size_t)*count, sizeof *steps, by_step_descending);
    return NSPD_OK;
}

static void checkpoint_path(const char *dir, long long step, char *out, size_t size) {
    snprintf(out, size, "%s/checkpoint_%012lld.nspd", dir, step);
}

int sim_checkpoint_write(Sim *sim) {
    /* on several processes all take part (the flow gathers its state into
     * the one layout) and the one with the directory writes */
    const bool writes = sim->dir != NULL;
    if (!writes && !comm_distributed(&sim->cfg.comm)) return NSPD_OK;
    const double t0 = nspd_wall_time();
    sim->wall_s = t0 - sim->wall_start;
    if (writes) TRY(history_bytes(&sim->history, &sim->history_bytes));
    CheckpointHeader h;
    memset(&h, 0, sizeof h);
    h.case_hash = sim->case_hash;
    h.binary_hash = binary_hash();
    snprintf(h.version, sizeof h.version, "%s", NSPD_VERSION);
    snprintf(h.layout, sizeof h.layout, "%s", LAYOUT);
    h.step = sim->step;
    h.time = sim->time;
    char path[4200] = "";
    if (writes) checkpoint_path(sim->dir, (long long)sim->step, path, sizeof path);
    Checkpoint *ck;
    TRY(checkpoint_create(&ck, writes ? path : NULL, &h));
    const int status = state_io(sim, ck);
    if (status != NSPD_OK) {
        checkpoint_abort(&ck);
        return status;
    }
    const double mb = (double)checkpoint_bytes(ck) / 1e6;
    TRY(checkpoint_close(&ck));
    sim->checkpoint_wall = nspd_wall_time();
    if (!writes) return NSPD_OK;
    /* the older ones go once the new one is whole */
    long long steps[MAX_CHECKPOINT_FILES];
    int count;
    TRY(list_checkpoints(sim->dir, steps, &count));
    for (int k = SIM_CHECKPOINTS_KEPT; k < count; k++) {
        char old[4200];
        checkpoint_path(sim->dir, steps[k], old, sizeof old);
        remove(old);
    }
    sim->checkpoints_written++;
    nspd_log(LOG_INFO, "checkpoint at step %lld (t = %g s): %s, %.1f MB in %.2f s",
             (long long)sim->step, sim->time, path, mb, sim->checkpoint_wall - t0);
    return NSPD_OK;
}

/* The header against this run: a mismatch is the user's to resolve. */
static int check_header(const char *path, const CheckpointHeader *h, const Sim *sim) {
    if (strcmp(h->layout, LAYOUT) != 0)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "checkpoint '%s' was written with the state laid out as '%s'; this run "
                         "lays it out as '%s'",
                         path, h->layout, LAYOUT);
    if (h->binary_hash != binary_hash())
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "checkpoint '%s' was written by another nspd binary (version %s; this "
                         "is %s, built differently), which would not continue the run bit for "
                         "bit; expected the binary that wrote it",
                         path, h->version, NSPD_VERSION);
    if (h->case_hash != sim->case_hash)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "checkpoint '%s' was written for another case (the resolved case "
                         "differs); expected the case file and --set options of the run that "
                         "wrote it",
                         path);
    return NSPD_OK;
}

int sim_resume(Sim *sim, const char *dir) {
    long long steps[MAX_CHECKPOINT_FILES];
    int count;
    TRY(list_checkpoints(dir, steps, &count));
    if (count == 0)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "cannot resume: '%s' holds no checkpoint (checkpoint_*.nspd); expected "
                         "the directory of a run that wrote one (output.checkpoint_interval, "
                         "output.checkpoint_wall_interval, or stopped by a signal)",
                         dir);
    const double t0 = nspd_wall_time();
    for (int k = 0; k < count; k++) {
        char path[4200];
        checkpoint_path(dir, steps[k], path, sizeof path);
        CheckpointHeader h;
        Checkpoint *ck;
        const int status = checkpoint_open(&ck, path, &h);
        if (status != NSPD_OK) {
            if (k + 1 == count) return status;
            nspd_log(LOG_WARN, "passing over %s: %s", path, nspd_error_message());
            nspd_error_clear();
            continue;
        }
        int st = check_header(path, &h, sim);
        if (st == NSPD_OK) st = state_io(sim, ck);
        if (st != NSPD_OK) {
            checkpoint_abort(&ck);
            return st;
        }
        TRY(checkpoint_close(&ck));
        sim->resumed = true;
        nspd_log(LOG_INFO, "resuming from %s: step %lld, t = %g s (read in %.2f s)", path,
                 (long long)sim->step, sim->time, nspd_wall_time() - t0);
        return NSPD_OK;
    }
    return NSPD_OK;
}
