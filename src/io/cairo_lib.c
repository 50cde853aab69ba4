#include "io/cairo_lib.h"

#include "core/shared_lib.h"

void *cairo_lib_slots[CAIRO_LIB_COUNT];

static const char *const names[] = {
#define CAIRO_LIB_NAME(f) #f,
    CAIRO_LIB_FUNCTIONS(CAIRO_LIB_NAME)
#undef CAIRO_LIB_NAME
};

static SharedLib cairo = {.soname = NSPD_CAIRO_SONAME,
                          .purpose = "pictures",
                          .names = names,
                          .count = CAIRO_LIB_COUNT,
                          .slots = cairo_lib_slots};

int cairo_lib_load(void) {
    return shared_lib_load(&cairo);
}
