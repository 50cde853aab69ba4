/* UMFPACK opened on the first factorisation of a PDDO pressure matrix
 * (core/shared_lib.h says why). Included by flow/pddo/ppe.c only: each
 * name below, used as a call, goes through the slot shared_lib_load
 * filled. umfpack_lib_load() must succeed before the first call. */
#ifndef NSPD_FLOW_PDDO_UMFPACK_LIB_H
#define NSPD_FLOW_PDDO_UMFPACK_LIB_H

#include <umfpack.h>

/* every function flow/pddo/ppe.c calls */
#define UMFPACK_LIB_FUNCTIONS(X)                                                                   \
    X(umfpack_di_defaults)                                                                         \
    X(umfpack_di_free_numeric)                                                                     \
    X(umfpack_di_free_symbolic)                                                                    \
    X(umfpack_di_get_lunz)                                                                         \
    X(umfpack_di_get_numeric)                                                                      \
    X(umfpack_di_numeric)                                                                          \
    X(umfpack_di_solve)                                                                            \
    X(umfpack_di_symbolic)

enum {
#define UMFPACK_LIB_INDEX(f) UMFPACK_LIB_##f,
    UMFPACK_LIB_FUNCTIONS(UMFPACK_LIB_INDEX) UMFPACK_LIB_COUNT
#undef UMFPACK_LIB_INDEX
};

extern void *umfpack_lib_slots[UMFPACK_LIB_COUNT];

/* Opens UMFPACK on the first call; NSPD_ERR_IO (with what is missing) if it cannot. */
int umfpack_lib_load(void);

/* f's slot as a pointer to f's own type (f, inside its own macro, names
 * the declared function) */
#define UMFPACK_LIB_CALL(f)      ((__typeof__(f) *)umfpack_lib_slots[UMFPACK_LIB_##f])
#define umfpack_di_defaults      UMFPACK_LIB_CALL(umfpack_di_defaults)
#define umfpack_di_free_numeric  UMFPACK_LIB_CALL(umfpack_di_free_numeric)
#define umfpack_di_free_symbolic UMFPACK_LIB_CALL(umfpack_di_free_symbolic)
#define umfpack_di_get_lunz      UMFPACK_LIB_CALL(umfpack_di_get_lunz)
#define umfpack_di_get_numeric   UMFPACK_LIB_CALL(umfpack_di_get_numeric)
#define umfpack_di_numeric       UMFPACK_LIB_CALL(umfpack_di_numeric)
#define umfpack_di_solve         UMFPACK_LIB_CALL(umfpack_di_solve)
#define umfpack_di_symbolic      UMFPACK_LIB_CALL(umfpack_di_symbolic)

#endif
