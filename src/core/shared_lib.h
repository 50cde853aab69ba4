/* A shared library opened on its first use (dlopen), its functions found
 * by name (dlsym).
 *
 * Why: the loader maps and relocates every library an executable links at
 * each start, and most runs of nspd use neither cairo (pictures) nor UMFPACK
 * (the PDDO pressure solve). Linked, those two and the 27 libraries they
 * pull in made 8 of the 14.5 ms that `nspd --version` took (2026-12-04,
 * docs/PERFORMANCE.md); `nspd check` is called thousands of times by the
 * test suite and by a user's parameter sweep. Opened on first use, a run
 * that draws or solves pays that once, and one that does not never does.
 *
 * A user lists the library's functions in an X-macro, keeps a slot per
 * function, and calls each through a macro of the function's own name
 * that casts its slot to the function's type (io/cairo_lib.h,
 * flow/pddo/umfpack_lib.h), so the calling code reads as plain calls. */
#ifndef NSPD_CORE_SHARED_LIB_H
#define NSPD_CORE_SHARED_LIB_H

#include <stddef.h>

typedef struct {
    const char *soname;       /* the file the loader looks for ("libcairo.so.2": CMake reads it) */
    const char *purpose;      /* for the message: "pictures" */
    const char *const *names; /* the functions, in the order of slots */
    size_t count;
    void **slots;
    int status;        /* 0: not tried yet; then loaded or refused, kept */
    char failure[320]; /* the failure's text, repeated to later callers */
} SharedLib;

/* Opens lib and fills its slots on the first call (thread-safe); NSPD_OK
 * at once after that. NSPD_ERR_IO, saying which library or function is
 * missing and what needed it, on every call once the first has failed. */
int shared_lib_load(SharedLib *lib);

#endif
