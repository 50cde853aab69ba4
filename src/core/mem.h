/* Aligned, zeroed allocation with accounting and failure injection.
 *
 * All hot arrays come from nspd_alloc: 64-byte aligned (one cache line, one
 * AVX-512 vector) and zero-filled. The module counts live bytes and their
 * peak so that `nspd info` and benchmarks report memory honestly. Tests can
 * make the N-th allocation fail (as Lua's test build does) to exercise every
 * error path. Not thread-safe: allocate outside parallel regions. */
#ifndef NSPD_CORE_MEM_H
#define NSPD_CORE_MEM_H

#include <stddef.h>

/* *out = 64-byte aligned, zeroed block of count*size bytes (count may be 0:
 * *out is then NULL and the call succeeds). NSPD_ERR_NOMEM on failure or
 * overflow, with *out = NULL. */
int nspd_alloc(void *out, size_t count, size_t size);
/* Resizes a block from nspd_alloc, keeping the first min(old,new) elements
 * and zeroing any growth. */
int nspd_realloc(void *inout, size_t old_count, size_t new_count, size_t size);
/* Frees the block *pp (pointer to the pointer) and sets *pp = NULL. */
void nspd_free(void *pp);

size_t nspd_mem_live_bytes(void);
size_t nspd_mem_peak_bytes(void);
double nspd_peak_rss_mb(void);        /* the process's peak resident set (getrusage) */
double nspd_mem_physical_bytes(void); /* this machine's memory (0 if unknown) */

/* Test hook: the allocation after `n` more successful ones fails; n < 0 turns
 * injection off. */
void nspd_mem_fail_after(long n);

#endif
