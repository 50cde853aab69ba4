/* The scratch directory the harnesses write their inputs into (fuzz_target.h).
 * One per process, so two harnesses (or two ctest replays) never share
 * files; everything in it is removed at exit. */
#include "fuzz_target.h"

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char scratch[4096];
static int scratch_state; /* 0 not tried, 1 ready, -1 failed */

static void remove_scratch(void) {
    DIR *d = opendir(scratch);
    if (d) {
        struct dirent *e;
        char path[8192];
        while ((e = readdir(d)) != NULL) {
            if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0) continue;
            snprintf(path, sizeof path, "%s/%s", scratch, e->d_name);
            remove(path);
        }
        closedir(d);
    }
    rmdir(scratch);
}

const char *fuzz_scratch_dir(void) {
    if (scratch_state == 0) {
        const char *tmp = getenv("TMPDIR");
        if (!tmp || !tmp[0]) tmp = "/tmp";
        snprintf(scratch, sizeof scratch, "%s/nspd-fuzz-XXXXXX", tmp);
        scratch_state = mkdtemp(scratch) ? 1 : -1;
        if (scratch_state == 1) atexit(remove_scratch);
    }
    return scratch_state == 1 ? scratch : NULL;
}

int fuzz_scratch_path(const char *name, char *buf, size_t size) {
    const char *dir = fuzz_scratch_dir();
    if (!dir) return 0;
    const int n = snprintf(buf, size, "%s/%s", dir, name);
    return n > 0 && (size_t)n < size;
}

int fuzz_write_file(const char *path, const void *data, size_t size) {
    FILE *f = fopen(path, "wb");
    if (!f) return -1;
    const size_t put = size ? fwrite(data, 1, size, f) : 0;
    const int closed = fclose(f);
    return put == size && closed == 0 ? 0 : -1;
}
