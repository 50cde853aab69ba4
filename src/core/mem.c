/* Each block carries, just before its 64-byte aligned user pointer, its
 * size (so that accounting needs no table) and the pointer calloc gave.
 * calloc, not aligned_alloc and memset: a large block comes zeroed from
 * the kernel's fresh pages, and pages nobody touches are never faulted in
 * (measured: memset and its page faults were 44 % of a one-step PDDO run,
 * the Re 10 cylinder at dx 0.05 m, whose arrays are sized for the most
 * and packed after; docs/PERFORMANCE.md). */
#include "core/mem.h"

#include "core/status.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <sys/mman.h>
#include <sys/resource.h>

enum { HEADER = 64 };

/* Blocks from this size on ask for transparent huge pages (2 MB): on this
 * project's VMs a page fault costs about 10 us, and a PDDO setup touches
 * tens of thousands of 4 KB pages (docs/PERFORMANCE.md). */
#define HUGE_FROM ((size_t)4 << 20)
#define HUGE_PAGE ((uintptr_t)2 << 20)

/* The whole huge pages inside [raw, raw + total) marked for THP where the
 * system lets a program ask (transparent_hugepage "madvise" or "always");
 * a refusal changes nothing but the page size. */
static void ask_huge_pages(char *raw, size_t total) {
    const uintptr_t lo = ((uintptr_t)raw + HUGE_PAGE - 1) & ~(HUGE_PAGE - 1);
    const uintptr_t hi = ((uintptr_t)raw + total) & ~(HUGE_PAGE - 1);
#ifdef MADV_HUGEPAGE
    if (hi > lo) (void)madvise((void *)lo, hi - lo, MADV_HUGEPAGE);
#else
    (void)lo, (void)hi;
#endif
}

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
    if (count > (SIZE_MAX - 2 * HEADER) / size || injected_failure())
        return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory allocating %zu x %zu bytes", count, size);
    size_t bytes = count * size;
    /* room for the two words before the first 64-byte boundary past them */
    char *raw = calloc(1, bytes + 2 * HEADER);
    if (!raw)
        return NSPD_FAIL(NSPD_ERR_NOMEM, "out of memory allocating %zu x %zu bytes", count, size);
    if (bytes >= HUGE_FROM) ask_huge_pages(raw, bytes + 2 * HEADER);
    const uintptr_t words = (uintptr_t)raw + sizeof bytes + sizeof raw;
    char *user = raw + ((words + HEADER - 1) / HEADER * HEADER - (uintptr_t)raw);
    memcpy(user - sizeof bytes - sizeof raw, &bytes, sizeof bytes);
    memcpy(user - sizeof raw, &raw, sizeof raw);
    live_bytes += bytes;
    if (live_bytes > peak_bytes) peak_bytes = live_bytes;
    *result = user;
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
    char *user = *ptr, *raw;
    size_t bytes;
    memcpy(&bytes, user - sizeof bytes - sizeof raw, sizeof bytes);
    memcpy(&raw, user - sizeof raw, sizeof raw);
    live_bytes -= bytes;
    free(raw);
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
