/* What a fuzz harness provides (libFuzzer's entry point) and what it may use
 * (a private scratch directory for the readers that take only a path).
 * Built two ways (tests/fuzz/CMakeLists.txt): with clang's libFuzzer for
 * `make fuzz`, and with replay_main.c for the corpus replay in `make test`. */
#ifndef NSPD_TESTS_FUZZ_TARGET_H
#define NSPD_TESTS_FUZZ_TARGET_H

#include <stddef.h>
#include <stdint.h>

/* Runs one input; always returns 0 (libFuzzer's contract). A crash, a
 * sanitizer report or a leak is the finding. */
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/* The process's own scratch directory (created on first use under $TMPDIR
 * or /tmp, removed with everything in it at exit); NULL if it cannot be
 * created. */
const char *fuzz_scratch_dir(void);

/* scratch_dir/name into buf; false if it does not fit or there is no
 * scratch directory. */
int fuzz_scratch_path(const char *name, char *buf, size_t size);

/* Writes size bytes to path (replacing it); 0 on success. Opens and closes
 * the file each time, so no descriptor outlives the call. */
int fuzz_write_file(const char *path, const void *data, size_t size);

#endif
