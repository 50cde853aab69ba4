/* Each block carries a 64-byte header holding its size, so that accounting
 * needs no table and the user pointer stays 64-byte aligned. */
#include "core/mem.h"

#include "core/status.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <sys/resource.h>

enum { HEADER = 64 };

static size_t live_bytes, peak_bytes;
static long fail_countdown = -1;

static int injected_failure(void) {
    if (fail_countdown < 0) return 0;
    if (fail_countdown == 0) return 1;
    fail_countdown--;
    return 0;
}

int nspd_alloc(void *out, size_t count, size_t size) {
    void **result = out;
    *result = NULL;
    if (count == 0 || size == 0) return NSPD_OK;
    if (count > (SIZE_MAX - HEADER) / size || injected_failure())
        return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory allocating %zu x %zu bytes", count, size);
    size_t bytes = count * size;
    char *block = aligned_alloc(HEADER, ((bytes + HEADER) + HEADER - 1) / HEADER * HEADER);
    if (!block)
        return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory allocating %zu x %zu bytes", count, size);
    memcpy(block, &bytes, sizeof bytes);
    memset(block + HEADER, 0, bytes);
    live_bytes += bytes;
    if (live_bytes > peak_bytes) peak_bytes = live_bytes;
    *result = block + HEADER;
    return NSPD_OK;
}

int nspd_realloc(void *inout, size_t old_count, size_t new_count, size_t size) {
    void **ptr = inout;
    void *fresh;
    TRY(nspd_alloc(&fresh, new_count, size));
    size_t keep = old_count < new_count ? old_count : new_count;
    if (*ptr && fresh && keep) memcpy(fresh, *ptr, keep * size);
    nspd_free(ptr);
    *ptr = fresh;
    return NSPD_OK;
}

void nspd_free(void *pp) {
    void **ptr = pp;
    if (!*ptr) return;
    char *block = (char *)*ptr - HEADER;
    size_t bytes;
    memcpy(&bytes, block, sizeof bytes);
    live_bytes -= bytes;
    free(block);
    *ptr = NULL;
}

size_t nspd_mem_live_bytes(void) {
    return live_bytes;
}

size_t nspd_mem_peak_bytes(void) {
    return peak_bytes;
}

double nspd_peak_rss_mb(void) {
    struct rusage usage;
    if (getrusage(RUSAGE_SELF, &usage) != 0) return 0.0;
    return (double)usage.ru_maxrss / 1024.0; /* Linux reports kilobytes */
}

void nspd_mem_fail_after(long n) {
    fail_countdown = n;
}

double nspd_mem_physical_bytes(void) {
    const long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && size > 0 ? (double)pages * (double)size : 0.0;
}
