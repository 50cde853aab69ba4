#include "core/checkpoint.h"

#include "core/hash.h"
#include "core/mem.h"
#include "core/out_file.h"
#include "core/status.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

static const char MAGIC[8] = {'N', 'S', 'P', 'D', 'C', 'K', 'P', 'T'};
enum { STREAM_BUFFER = 1 << 20 };

struct Checkpoint {
    bool reading;
    OutFile out; /* writing */
    FILE *in;    /* reading */
    char path[4096];
    Hash64 hash;       /* writing: of every byte so far */
    uint64_t bytes;    /* writing: so far; reading: the file's size */
    uint64_t position; /* reading: where the next record starts */
    bool failed;       /* writing: a write failed (out_file_close says why) */
    bool discard;      /* writing to no file (checkpoint_create with no path) */
};

bool checkpoint_reading(const Checkpoint *ck) {
    return ck->reading;
}

uint64_t checkpoint_bytes(const Checkpoint *ck) {
    return ck->bytes;
}

static void put(Checkpoint *ck, const void *data, size_t bytes) {
    if (ck->failed || bytes == 0) return;
    if (!ck->discard && fwrite(data, 1, bytes, ck->out.f) != bytes) ck->failed = true;
    hash64_add(&ck->hash, data, bytes);
    ck->bytes += bytes;
}

static int get(Checkpoint *ck, void *data, size_t bytes, const char *what) {
    if (bytes == 0) return NSPD_OK;
    if (ck->position + bytes + sizeof(uint64_t) > ck->bytes ||
        fread(data, 1, bytes, ck->in) != bytes)
        return NSPD_FAIL(NSPD_ERR_INPUT, "checkpoint '%s' ends inside %s", ck->path, what);
    ck->position += bytes;
    return NSPD_OK;
}

static void put_header(Checkpoint *ck, const CheckpointHeader *h) {
    const uint32_t format = CHECKPOINT_FORMAT;
    put(ck, MAGIC, sizeof MAGIC);
    put(ck, &format, sizeof format);
    put(ck, h, sizeof *h);
}

int checkpoint_create(Checkpoint **out, const char *path, const CheckpointHeader *header) {
    Checkpoint *ck;
    TRY(nspd_alloc(&ck, 1, sizeof *ck));
    ck->discard = path == NULL;
    snprintf(ck->path, sizeof ck->path, "%s", path ? path : "(none)");
    int status = ck->discard ? NSPD_OK : out_file_open(&ck->out, path);
    if (status != NSPD_OK) {
        nspd_free(&ck);
        return status;
    }
    if (!ck->discard) setvbuf(ck->out.f, NULL, _IOFBF, STREAM_BUFFER);
    hash64_init(&ck->hash);
    put_header(ck, header);
    *out = ck;
    return NSPD_OK;
}

/* The hash of the file's first `bytes` bytes. */
static int hash_prefix(FILE *f, uint64_t bytes, uint64_t *out) {
    static const size_t CHUNK = 1 << 16;
    unsigned char buf[1 << 16];
    Hash64 h;
    hash64_init(&h);
    while (bytes > 0) {
        const size_t n = bytes < CHUNK ? (size_t)bytes : CHUNK;
        if (fread(buf, 1, n, f) != n)
            return NSPD_FAIL(NSPD_ERR_IO, "the checkpoint ends %llu bytes early",
                             (unsigned long long)bytes);
        hash64_add(&h, buf, n);
        bytes -= n;
    }
    *out = hash64_final(&h);
    return NSPD_OK;
}

int checkpoint_open(Checkpoint **out, const char *path, CheckpointHeader *header) {
    Checkpoint *ck;
    TRY(nspd_alloc(&ck, 1, sizeof *ck));
    ck->reading = true;
    snprintf(ck->path, sizeof ck->path, "%s", path);
    ck->in = fopen(path, "rb");
    struct stat st;
    int status = NSPD_OK;
    if (!ck->in || fstat(fileno(ck->in), &st) != 0)
        status = NSPD_FAIL(NSPD_ERR_IO, "cannot read '%s' (%s)", path, strerror(errno));
    if (status == NSPD_OK) {
        setvbuf(ck->in, NULL, _IOFBF, STREAM_BUFFER);
        ck->bytes = (uint64_t)st.st_size;
        const uint64_t head = sizeof MAGIC + sizeof(uint32_t) + sizeof *header;
        uint64_t computed = 0, stored = 0;
        if (ck->bytes < head + sizeof stored)
            status = NSPD_FAIL(NSPD_ERR_INPUT, "'%s' is too short to be a checkpoint", path);
        else if (hash_prefix(ck->in, ck->bytes - sizeof stored, &computed) != NSPD_OK ||
                 fread(&stored, sizeof stored, 1, ck->in) != 1)
            status = NSPD_FAIL(NSPD_ERR_IO, "cannot read '%s' (%s)", path,
                               errno ? strerror(errno) : "short read");
        else if (computed != stored)
            status = NSPD_FAIL(NSPD_ERR_INPUT,
                               "checkpoint '%s' is damaged (its checksum does not match its "
                               "contents)",
                               path);
    }
    if (status == NSPD_OK) {
        rewind(ck->in);
        char magic[sizeof MAGIC];
        uint32_t format = 0;
        status = get(ck, magic, sizeof magic, "its header");
        if (status == NSPD_OK) status = get(ck, &format, sizeof format, "its header");
        if (status == NSPD_OK && memcmp(magic, MAGIC, sizeof MAGIC) != 0)
            status = NSPD_FAIL(NSPD_ERR_INPUT, "'%s' is not an nspd checkpoint", path);
        if (status == NSPD_OK && format != CHECKPOINT_FORMAT)
            status = NSPD_FAIL(NSPD_ERR_INPUT,
                               "checkpoint '%s' has format %u; this nspd reads format %d", path,
                               format, CHECKPOINT_FORMAT);
        if (status == NSPD_OK) status = get(ck, header, sizeof *header, "its header");
        header->version[CHECKPOINT_MAX_TEXT - 1] = '\0';
        header->layout[CHECKPOINT_MAX_TEXT - 1] = '\0';
    }
    if (status != NSPD_OK) {
        checkpoint_abort(&ck);
        return status;
    }
    *out = ck;
    return NSPD_OK;
}

/* fsync of the directory holding `path` (its new entry); best effort: some
 * file systems refuse it, and the file itself is already on the disk. */
static void sync_directory(const char *path) {
    char dir[4096];
    snprintf(dir, sizeof dir, "%s", path);
    char *slash = strrchr(dir, '/');
    if (slash)
        *slash = '\0';
    else
        snprintf(dir, sizeof dir, ".");
    const int fd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    (void)fsync(fd);
    close(fd);
}

int checkpoint_close(Checkpoint **p) {
    Checkpoint *ck = *p;
    if (!ck) return NSPD_OK;
    int status = NSPD_OK;
    if (ck->reading) {
        status = ck->position + sizeof(uint64_t) == ck->bytes
                     ? NSPD_OK
                     : NSPD_FAIL(NSPD_ERR_INPUT,
                                 "checkpoint '%s' holds more than this case reads: it was "
                                 "written for another case",
                                 ck->path);
        fclose(ck->in);
    } else if (!ck->discard) {
        const uint64_t sum = hash64_final(&ck->hash);
        if (!ck->failed && fwrite(&sum, sizeof sum, 1, ck->out.f) != 1) ck->failed = true;
        /* on the disk before it takes the real name, and the name with it:
         * a checkpoint is what a crash of the machine leaves to resume from */
        if (!ck->failed && (fflush(ck->out.f) != 0 || fsync(fileno(ck->out.f)) != 0))
            ck->failed = true;
        status = out_file_close(&ck->out, ck->failed);
        if (status == NSPD_OK) sync_directory(ck->path);
    }
    nspd_free(p);
    return status;
}

void checkpoint_abort(Checkpoint **p) {
    Checkpoint *ck = *p;
    if (!ck) return;
    if (ck->reading) {
        if (ck->in) fclose(ck->in);
    } else if (!ck->discard) {
        out_file_abort(&ck->out);
    }
    nspd_free(p);
}

/* A record's name and size: written, or read and compared. */
static int record(Checkpoint *ck, const char *name, uint64_t bytes) {
    uint32_t len = (uint32_t)strnlen(name, CHECKPOINT_MAX_NAME - 1);
    if (!ck->reading) {
        put(ck, &len, sizeof len);
        put(ck, name, len);
        put(ck, &bytes, sizeof bytes);
        return NSPD_OK;
    }
    char found[CHECKPOINT_MAX_NAME];
    uint32_t found_len = 0;
    uint64_t found_bytes = 0;
    TRY(get(ck, &found_len, sizeof found_len, "a record name"));
    if (found_len >= CHECKPOINT_MAX_NAME)
        return NSPD_FAIL(NSPD_ERR_INPUT, "checkpoint '%s' has a record name of %u bytes", ck->path,
                         found_len);
    TRY(get(ck, found, found_len, "a record name"));
    found[found_len] = '\0';
    TRY(get(ck, &found_bytes, sizeof found_bytes, "a record size"));
    if (strcmp(found, name) != 0)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "checkpoint '%s' holds '%s' where this case reads '%s': it was written "
                         "for another case",
                         ck->path, found, name);
    if (found_bytes != bytes)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "checkpoint '%s' holds %llu bytes of '%s' where this case has %llu: it "
                         "was written for another case",
                         ck->path, (unsigned long long)found_bytes, name,
                         (unsigned long long)bytes);
    return NSPD_OK;
}

int checkpoint_io(Checkpoint *ck, const char *name, void *data, size_t bytes) {
    TRY(record(ck, name, bytes));
    if (!ck->reading) {
        put(ck, data, bytes);
        return NSPD_OK;
    }
    return get(ck, data, bytes, name);
}

int checkpoint_io_array(Checkpoint *ck, const char *name, void *data, size_t size, int64_t *count,
                        int64_t capacity) {
    char count_name[CHECKPOINT_MAX_NAME + 8];
    snprintf(count_name, sizeof count_name, "%s.count", name);
    TRY(checkpoint_io(ck, count_name, count, sizeof *count));
    if (*count < 0 || *count > capacity)
        return NSPD_FAIL(NSPD_ERR_INPUT,
                         "checkpoint '%s' holds %lld entries of '%s' where this case has room "
                         "for %lld: it was written for another case",
                         ck->path, (long long)*count, name, (long long)capacity);
    return checkpoint_io(ck, name, data, (size_t)*count * size);
}

int checkpoint_io_double(Checkpoint *ck, const char *name, double *v) {
    return checkpoint_io(ck, name, v, sizeof *v);
}

int checkpoint_io_int64(Checkpoint *ck, const char *name, int64_t *v) {
    return checkpoint_io(ck, name, v, sizeof *v);
}

int checkpoint_io_int(Checkpoint *ck, const char *name, int *v) {
    return checkpoint_io(ck, name, v, sizeof *v);
}
