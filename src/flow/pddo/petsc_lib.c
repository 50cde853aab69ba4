#include "flow/pddo/petsc_lib.h"

#ifdef NSPD_HAVE_PETSC
#include "core/shared_lib.h"

void *petsc_lib_slots[PETSC_LIB_COUNT];

static const char *const names[] = {
#define PETSC_LIB_NAME(f) #f,
    PETSC_LIB_FUNCTIONS(PETSC_LIB_NAME)
#undef PETSC_LIB_NAME
};

static SharedLib petsc = {.soname = NSPD_PETSC_SONAME,
                          .purpose = "the PDDO pressure solve on PETSc",
                          .names = names,
                          .count = PETSC_LIB_COUNT,
                          .slots = petsc_lib_slots};

int petsc_lib_load(void) {
    return shared_lib_load(&petsc);
}
#endif
