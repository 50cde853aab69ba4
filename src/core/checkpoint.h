/* Checkpoints: the whole state of a run in one binary file, from which the
 * run continues bit for bit.
 *
 * A checkpoint is a header and a sequence of named records, then a 64-bit
 * hash of every byte before it:
 *     "NSPDCKPT" u32 format
 *     header: the case's hash, the binary's hash, the version, the layout,
 *             the step and time
 *     records: u32 name length, name, u64 byte count, bytes
 *     u64 hash (core/hash.h) of everything above
 * It is written as <path>.part and renamed when whole (core/out_file.h), so
 * a file under its real name is complete; its hash is checked before any
 * of it is read, so a damaged file is refused whole.
 *
 * One function per model both writes and reads its state: it calls
 * checkpoint_io on each piece in a fixed order, and the same calls copy the
 * pieces out (writing) or back in (reading, into the arrays of a model just
 * built from the same case). A record read back must have the name and
 * size the reader asks for; anything else is a checkpoint of another case
 * or layout, refused.
 *
 * Values are the bits in memory (native endianness and struct layout): a
 * checkpoint is for the same binary on the same kind of machine, which the
 * header's binary hash enforces. */
#ifndef NSPD_CORE_CHECKPOINT_H
#define NSPD_CORE_CHECKPOINT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

enum { CHECKPOINT_FORMAT = 1, CHECKPOINT_MAX_NAME = 64, CHECKPOINT_MAX_TEXT = 64 };

typedef struct {
    uint64_t case_hash;   /* the resolved case it was written from */
    uint64_t binary_hash; /* the executable that wrote it */
    char version[CHECKPOINT_MAX_TEXT];
    /* how the state is laid out: "serial" (the whole state as one process
     * holds it; the same at any thread count, and written so by a run on
     * several processes, which any number of processes reads back) */
    char layout[CHECKPOINT_MAX_TEXT];
    int64_t step;
    double time;
} CheckpointHeader;

typedef struct Checkpoint Checkpoint;

/* Starts writing `path` (as <path>.part). NSPD_ERR_IO with the OS's reason.
 * path NULL: a checkpoint written to no file (the processes other than
 * the writer of a run on several, which take part in its gathers). */
int checkpoint_create(Checkpoint **ck, const char *path, const CheckpointHeader *header);
/* Opens `path` for reading: checks its format and hash (the whole file is
 * read once for it) and returns its header. NSPD_ERR_IO when it cannot be
 * read, NSPD_ERR_INPUT when it is not a whole checkpoint of this format. */
int checkpoint_open(Checkpoint **ck, const char *path, CheckpointHeader *header);
/* Writing: appends the hash and renames the file to its real name.
 * Reading: NSPD_ERR_INPUT if records were left unread. Frees *ck either
 * way. */
int checkpoint_close(Checkpoint **ck);
/* Gives up (an error is being reported): removes a file being written. */
void checkpoint_abort(Checkpoint **ck);

bool checkpoint_reading(const Checkpoint *ck);
/* The bytes written so far (writing) or in the file (reading). */
uint64_t checkpoint_bytes(const Checkpoint *ck);

/* One record of `bytes` bytes at `data`: written, or read back into it. */
int checkpoint_io(Checkpoint *ck, const char *name, void *data, size_t bytes);
/* A record of *count elements of `size` bytes: writes *count and the
 * elements; reading, sets *count and fills data, refusing more than
 * `capacity` elements. */
int checkpoint_io_array(Checkpoint *ck, const char *name, void *data, size_t size, int64_t *count,
                        int64_t capacity);

/* Typed shorthands for scalars. */
int checkpoint_io_double(Checkpoint *ck, const char *name, double *v);
int checkpoint_io_int64(Checkpoint *ck, const char *name, int64_t *v);
int checkpoint_io_int(Checkpoint *ck, const char *name, int *v);

#endif
