/* A 64-bit streaming hash (FNV-1a over 64-bit little-endian words, then a
 * final avalanche): the same value whatever the chunks the bytes arrive in.
 * For checksums and identities (checkpoint integrity, the case and binary a
 * checkpoint belongs to), not for security. */
#ifndef NSPD_CORE_HASH_H
#define NSPD_CORE_HASH_H

#include <stddef.h>
#include <stdint.h>

typedef struct {
    uint64_t h;
    uint64_t tail; /* bytes not yet making a whole word */
    int tail_len;
    uint64_t length;
} Hash64;

void hash64_init(Hash64 *s);
void hash64_add(Hash64 *s, const void *data, size_t bytes);
uint64_t hash64_final(const Hash64 *s);
/* The hash of one buffer. */
uint64_t hash64(const void *data, size_t bytes);
/* The hash of a whole file (NSPD_ERR_IO if it cannot be read). */
int hash64_file(const char *path, uint64_t *out);

#endif
