#include "core/out_file.h"

#include "core/status.h"

#include <errno.h>
#include <string.h>

int out_file_open(OutFile *o, const char *path) {
    snprintf(o->path, sizeof o->path, "%s", path);
    snprintf(o->part, sizeof o->part, "%s.part", path);
    o->f = fopen(o->part, "wb");
    if (!o->f) return NSPD_FAIL(NSPD_ERR_IO, "cannot create '%s' (%s)", o->path, strerror(errno));
    return NSPD_OK;
}

int out_file_close(OutFile *o, int failed) {
    /* a failed fwrite leaves the stream's error flag set; flushing the rest
     * retries the device and sets errno to its reason */
    errno = 0;
    int err = fflush(o->f) != 0 || ferror(o->f) || failed ? (errno ? errno : EIO) : 0;
    if (fclose(o->f) != 0 && !err) err = errno ? errno : EIO;
    o->f = NULL;
    if (!err && rename(o->part, o->path) != 0) err = errno;
    if (err) {
        remove(o->part);
        return NSPD_FAIL(NSPD_ERR_IO, "cannot write '%s' (%s)", o->path, strerror(err));
    }
    return NSPD_OK;
}

void out_file_abort(OutFile *o) {
    if (o->f) fclose(o->f);
    o->f = NULL;
    remove(o->part);
}
