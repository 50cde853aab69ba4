/* core/checkpoint and core/hash: a checkpoint reads back what was written,
 * refuses what was not written for the reader (another name, size or
 * count), a damaged or truncated file, and a file that is not one; the
 * hash does not depend on how the bytes are chunked. Runs under ASan too
 * (the whole-run resume tests are release-only: tests/cli/test_resume.sh). */
#include "test_support.h"

#include "core/checkpoint.h"
#include "core/hash.h"
#include "core/status.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char dir[64];
static char path[128];

static int setup(void **state) {
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/nspd_ckpt_XXXXXX");
    if (!mkdtemp(dir)) return -1;
    snprintf(path, sizeof path, "%s/c.nspd", dir);
    return 0;
}

static int teardown(void **state) {
    (void)state;
    remove(path);
    rmdir(dir);
    return 0;
}

static CheckpointHeader header(void) {
    CheckpointHeader h;
    memset(&h, 0, sizeof h);
    h.case_hash = 42;
    h.binary_hash = 7;
    snprintf(h.version, sizeof h.version, "test");
    snprintf(h.layout, sizeof h.layout, "serial");
    h.step = 12;
    h.time = 0.5;
    return h;
}

/* A small state: a scalar, an array, a variable-length list. */
typedef struct {
    double t;
    double u[5];
    int64_t n;
    int32_t list[8];
} State;

static int state_io(Checkpoint *ck, State *s) {
    TRY(checkpoint_io_double(ck, "t", &s->t));
    TRY(checkpoint_io(ck, "u", s->u, sizeof s->u));
    return checkpoint_io_array(ck, "list", s->list, sizeof(int32_t), &s->n, 8);
}

static void write_state(State *s) {
    CheckpointHeader h = header();
    Checkpoint *ck;
    assert_int_equal(checkpoint_create(&ck, path, &h), NSPD_OK);
    assert_false(checkpoint_reading(ck));
    assert_int_equal(state_io(ck, s), NSPD_OK);
    assert_int_equal(checkpoint_close(&ck), NSPD_OK);
    assert_null(ck);
}

static State sample(void) {
    State s = {.t = 1.25, .u = {1, -2, 3.5, 1e-300, -0.0}, .n = 3, .list = {4, 5, 6}};
    return s;
}

static void test_round_trip(void **state) {
    (void)state;
    State s = sample();
    write_state(&s);
    assert_int_equal(access(path, F_OK), 0);
    CheckpointHeader h;
    Checkpoint *ck;
    assert_int_equal(checkpoint_open(&ck, path, &h), NSPD_OK);
    assert_true(checkpoint_reading(ck));
    assert_int_equal(h.case_hash, 42);
    assert_int_equal(h.step, 12);
    assert_string_equal(h.layout, "serial");
    State r;
    memset(&r, 0, sizeof r);
    assert_int_equal(state_io(ck, &r), NSPD_OK);
    assert_int_equal(checkpoint_close(&ck), NSPD_OK);
    assert_memory_equal(&r, &s, sizeof s); /* bit for bit, -0.0 included */
}

/* A reader that asks for other records than were written. */
static int other_name(Checkpoint *ck, State *s) {
    TRY(checkpoint_io_double(ck, "time", &s->t));
    return NSPD_OK;
}

static int other_size(Checkpoint *ck, State *s) {
    TRY(checkpoint_io_double(ck, "t", &s->t));
    return checkpoint_io(ck, "u", s->u, 4 * sizeof(double));
}

static int less_room(Checkpoint *ck, State *s) {
    TRY(checkpoint_io_double(ck, "t", &s->t));
    TRY(checkpoint_io(ck, "u", s->u, sizeof s->u));
    return checkpoint_io_array(ck, "list", s->list, sizeof(int32_t), &s->n, 2);
}

static int reads_less(Checkpoint *ck, State *s) {
    return checkpoint_io_double(ck, "t", &s->t);
}

static void refused(int (*reader)(Checkpoint *, State *), const char *message, bool on_close) {
    CheckpointHeader h;
    Checkpoint *ck;
    assert_int_equal(checkpoint_open(&ck, path, &h), NSPD_OK);
    State r;
    memset(&r, 0, sizeof r);
    int status = reader(ck, &r);
    if (on_close) {
        assert_int_equal(status, NSPD_OK);
        status = checkpoint_close(&ck);
    } else {
        checkpoint_abort(&ck);
    }
    assert_int_equal(status, NSPD_ERR_INPUT);
    assert_non_null(strstr(nspd_error_message(), message));
}

static void test_refuses_another_layout(void **state) {
    (void)state;
    State s = sample();
    write_state(&s);
    refused(other_name, "holds 't' where this case reads 'time'", false);
    refused(other_size, "holds 40 bytes of 'u' where this case has 32", false);
    refused(less_room, "holds 3 entries of 'list' where this case has room for 2", false);
    refused(reads_less, "holds more than this case reads", true);
}

/* Every single flipped byte and every truncation is refused before a
 * record is read. */
static void test_refuses_damage(void **state) {
    (void)state;
    State s = sample();
    write_state(&s);
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    unsigned char good[1024];
    const size_t size = fread(good, 1, sizeof good, f);
    fclose(f);
    assert_true(size > 100 && size < sizeof good);
    for (size_t at = 0; at < size; at += 7) {
        unsigned char bad[1024];
        memcpy(bad, good, size);
        bad[at] ^= 0x10;
        f = fopen(path, "wb");
        fwrite(bad, 1, size, f);
        fclose(f);
        CheckpointHeader h;
        Checkpoint *ck = NULL;
        assert_int_equal(checkpoint_open(&ck, path, &h), NSPD_ERR_INPUT);
        assert_null(ck);
    }
    for (size_t len = 0; len < size; len += 13) {
        f = fopen(path, "wb");
        fwrite(good, 1, len, f);
        fclose(f);
        CheckpointHeader h;
        Checkpoint *ck = NULL;
        assert_int_equal(checkpoint_open(&ck, path, &h), NSPD_ERR_INPUT);
    }
    f = fopen(path, "wb");
    fputs("name: not a checkpoint but long enough to hold a header of one, and then some more "
          "bytes for good measure, more than the header and the hash need to be read at all",
          f);
    fclose(f);
    CheckpointHeader h;
    Checkpoint *ck = NULL;
    assert_int_equal(checkpoint_open(&ck, path, &h), NSPD_ERR_INPUT);
    remove(path);
    assert_int_equal(checkpoint_open(&ck, path, &h), NSPD_ERR_IO);
}

/* An abandoned write leaves nothing under either name. */
static void test_abort_leaves_nothing(void **state) {
    (void)state;
    remove(path);
    CheckpointHeader h = header();
    Checkpoint *ck;
    assert_int_equal(checkpoint_create(&ck, path, &h), NSPD_OK);
    double x = 1;
    assert_int_equal(checkpoint_io_double(ck, "x", &x), NSPD_OK);
    checkpoint_abort(&ck);
    char part[160];
    snprintf(part, sizeof part, "%s.part", path);
    assert_int_not_equal(access(path, F_OK), 0);
    assert_int_not_equal(access(part, F_OK), 0);
}

static void test_hash_independent_of_chunks(void **state) {
    (void)state;
    unsigned char data[1000];
    for (int i = 0; i < 1000; i++) data[i] = (unsigned char)(i * 37 + 11);
    const uint64_t whole = hash64(data, sizeof data);
    for (size_t chunk = 1; chunk < 20; chunk++) {
        Hash64 h;
        hash64_init(&h);
        for (size_t at = 0; at < sizeof data; at += chunk)
            hash64_add(&h, data + at, at + chunk <= sizeof data ? chunk : sizeof data - at);
        assert_int_equal(hash64_final(&h), whole);
    }
    /* every length and every single-bit change gives another value */
    assert_int_not_equal(hash64(data, 999), whole);
    data[500] ^= 1;
    assert_int_not_equal(hash64(data, sizeof data), whole);
    assert_int_not_equal(hash64("", 0), hash64("\0", 1));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_round_trip),
        cmocka_unit_test(test_refuses_another_layout),
        cmocka_unit_test(test_refuses_damage),
        cmocka_unit_test(test_abort_leaves_nothing),
        cmocka_unit_test(test_hash_independent_of_chunks),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
