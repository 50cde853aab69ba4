#include "core/shared_lib.h"

#include "core/status.h"

#include <dlfcn.h>
#include <pthread.h>
#include <stdio.h>

/* SharedLib.status once tried (0: not tried) */
enum { LOADED = 1, REFUSED = 2 };

static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;

static int open_lib(SharedLib *lib) {
    /* RTLD_NOW: a missing symbol in its dependencies fails here, not mid-picture */
    void *handle = dlopen(lib->soname, RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        (void)snprintf(lib->failure, sizeof lib->failure,
                       "%s, needed for %s, could not be opened (%s); scripts/deps.sh installs it",
                       lib->soname, lib->purpose, dlerror());
        return REFUSED;
    }
    for (size_t i = 0; i < lib->count; i++) {
        lib->slots[i] = dlsym(handle, lib->names[i]);
        if (!lib->slots[i]) {
            (void)snprintf(lib->failure, sizeof lib->failure, "%s, needed for %s, lacks %s",
                           lib->soname, lib->purpose, lib->names[i]);
            return REFUSED;
        }
    }
    /* never closed: the functions stay in use until the process ends */
    return LOADED;
}

int shared_lib_load(SharedLib *lib) {
    (void)pthread_mutex_lock(&lock);
    if (lib->status == 0) lib->status = open_lib(lib);
    const int status = lib->status;
    /* copied under the lock: the status record the message goes to is per thread */
    char text[sizeof lib->failure];
    if (status != LOADED) (void)snprintf(text, sizeof text, "%s", lib->failure);
    (void)pthread_mutex_unlock(&lock);
    if (status == LOADED) return NSPD_OK;
    return NSPD_FAIL(NSPD_ERR_IO, "%s", text);
}
