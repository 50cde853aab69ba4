#include "flow/pddo/umfpack_lib.h"

#include "core/shared_lib.h"

void *umfpack_lib_slots[UMFPACK_LIB_COUNT];

static const char *const names[] = {
#define UMFPACK_LIB_NAME(f) #f,
    UMFPACK_LIB_FUNCTIONS(UMFPACK_LIB_NAME)
#undef UMFPACK_LIB_NAME
};

static SharedLib umfpack = {.soname = NSPD_UMFPACK_SONAME,
                            .purpose = "the PDDO pressure solve",
                            .names = names,
                            .count = UMFPACK_LIB_COUNT,
                            .slots = umfpack_lib_slots};

int umfpack_lib_load(void) {
    return shared_lib_load(&umfpack);
}
