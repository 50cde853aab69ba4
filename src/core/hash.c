#include "core/hash.h"

#include "core/status.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

enum { HASH_CHUNK = 1 << 16 };
static const uint64_t FNV_OFFSET = 0xcbf29ce484222325ULL;
static const uint64_t FNV_PRIME = 0x100000001b3ULL;

void hash64_init(Hash64 *s) {
    memset(s, 0, sizeof *s);
    s->h = FNV_OFFSET;
}

static inline uint64_t mix_word(uint64_t h, uint64_t w) {
    return (h ^ w) * FNV_PRIME;
}

void hash64_add(Hash64 *s, const void *data, size_t bytes) {
    const unsigned char *p = data;
    s->length += bytes;
    /* finish a partial word first, so the value does not depend on chunking */
    while (s->tail_len > 0 && s->tail_len < 8 && bytes > 0) {
        s->tail |= (uint64_t)*p++ << (8 * s->tail_len++);
        bytes--;
    }
    if (s->tail_len == 8) {
        s->h = mix_word(s->h, s->tail);
        s->tail = 0;
        s->tail_len = 0;
    }
    uint64_t h = s->h;
    for (; bytes >= 8; bytes -= 8, p += 8) {
        uint64_t w = 0;
        for (int b = 0; b < 8; b++) w |= (uint64_t)p[b] << (8 * b);
        h = mix_word(h, w);
    }
    s->h = h;
    for (; bytes > 0; bytes--) s->tail |= (uint64_t)*p++ << (8 * s->tail_len++);
}

uint64_t hash64_final(const Hash64 *s) {
    uint64_t h = s->h;
    if (s->tail_len > 0) h = mix_word(h, s->tail);
    h = mix_word(h, s->length);
    /* avalanche (the finaliser of MurmurHash3) so that every input bit
     * reaches every output bit */
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdULL;
    h ^= h >> 33;
    h *= 0xc4ceb9fe1a85ec53ULL;
    h ^= h >> 33;
    return h;
}

uint64_t hash64(const void *data, size_t bytes) {
    Hash64 s;
    hash64_init(&s);
    hash64_add(&s, data, bytes);
    return hash64_final(&s);
}

int hash64_file(const char *path, uint64_t *out) {
    FILE *f = fopen(path, "rb");
    if (!f) return NSPD_FAIL(NSPD_ERR_IO, "cannot read '%s' (%s)", path, strerror(errno));
    unsigned char buf[HASH_CHUNK];
    Hash64 s;
    hash64_init(&s);
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, f)) > 0) hash64_add(&s, buf, n);
    const int failed = ferror(f);
    fclose(f);
    if (failed) return NSPD_FAIL(NSPD_ERR_IO, "cannot read '%s'", path);
    *out = hash64_final(&s);
    return NSPD_OK;
}
