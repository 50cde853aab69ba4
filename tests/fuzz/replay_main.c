/* The corpus replay: feeds every file named on the command line, and every
 * file in every directory named, to LLVMFuzzerTestOneInput, once each, in
 * name order. Linked with a harness into an ordinary (gcc, ASan + UBSan in
 * build-asan) executable, so `make test` replays the seed corpus and the
 * regression inputs without libFuzzer. A crash, a sanitizer report or a
 * leak (LeakSanitizer, at exit) fails the run; so does an unreadable
 * argument or no input at all (a replay of nothing would pass silently: at
 * least one input must be found, though a directory of
 * regression inputs may be empty).
 *
 * With --mutate K first, each input is also replayed K times more, each
 * with one --set override of a real key of its case set to an extreme
 * value (set_mutator.h, seeds 0..K-1): the case harnesses' own mutator,
 * deterministic. */
#include "fuzz_target.h"
#include "set_mutator.h"

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

enum { REPLAY_MAX_BYTES = 1 << 20 }; /* the corpora hold files of at most 64 kB */

static int mutations; /* --mutate K */
static long mutated;  /* inputs the mutator made */

static int replay_file(const char *path) {
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "replay: cannot open '%s'\n", path);
        return -1;
    }
    unsigned char *data = malloc(REPLAY_MAX_BYTES);
    if (!data) {
        fclose(f);
        return -1;
    }
    const size_t size = fread(data, 1, REPLAY_MAX_BYTES, f);
    const int bad = ferror(f) || !feof(f);
    fclose(f);
    if (bad) {
        fprintf(stderr, "replay: cannot read '%s' whole (over %d bytes?)\n", path,
                REPLAY_MAX_BYTES);
        free(data);
        return -1;
    }
    /* the harness gets exactly size bytes, as from libFuzzer */
    unsigned char *exact = malloc(size ? size : 1);
    if (!exact) {
        free(data);
        return -1;
    }
    memcpy(exact, data, size);
    LLVMFuzzerTestOneInput(exact, size);
    free(exact);
    for (int k = 0; k < mutations; k++) {
        memcpy(exact = data + REPLAY_MAX_BYTES / 2, data, size); /* room after it */
        const size_t n = size < REPLAY_MAX_BYTES / 4
                             ? fuzz_set_mutate(exact, size, REPLAY_MAX_BYTES / 2, (unsigned)k)
                             : 0;
        if (n == 0) break; /* nothing to override in this input */
        unsigned char *input = malloc(n);
        if (!input) break;
        memcpy(input, exact, n);
        LLVMFuzzerTestOneInput(input, n);
        free(input);
        mutated++;
    }
    free(data);
    return 0;
}

static int by_name(const void *a, const void *b) {
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Replays the regular files of dir; the number replayed, or -1. */
static int replay_dir(const char *dir) {
    DIR *d = opendir(dir);
    if (!d) {
        fprintf(stderr, "replay: cannot open directory '%s'\n", dir);
        return -1;
    }
    char **names = NULL;
    size_t count = 0, cap = 0;
    struct dirent *e;
    int failed = 0;
    while ((e = readdir(d)) != NULL && !failed) {
        if (e->d_name[0] == '.') continue; /* ., .. and hidden files such as .gitkeep */
        if (count == cap) {
            cap = cap ? 2 * cap : 64;
            char **grown = realloc(names, cap * sizeof *grown);
            if (!grown) {
                failed = 1;
                break;
            }
            names = grown;
        }
        const size_t len = strlen(dir) + strlen(e->d_name) + 2;
        names[count] = malloc(len);
        if (!names[count]) {
            failed = 1;
            break;
        }
        snprintf(names[count], len, "%s/%s", dir, e->d_name);
        count++;
    }
    closedir(d);
    if (count > 1) qsort(names, count, sizeof *names, by_name);
    int replayed = 0;
    for (size_t i = 0; i < count; i++) {
        struct stat st;
        if (!failed && stat(names[i], &st) == 0 && S_ISREG(st.st_mode)) {
            if (replay_file(names[i]) != 0)
                failed = 1;
            else
                replayed++;
        }
        free(names[i]);
    }
    free(names);
    return failed ? -1 : replayed;
}

int main(int argc, char **argv) {
    int first = 1;
    if (argc > 2 && strcmp(argv[1], "--mutate") == 0) {
        mutations = atoi(argv[2]);
        first = 3;
    }
    if (argc <= first) {
        fprintf(stderr, "usage: %s [--mutate K] FILE|DIR...\n", argv[0]);
        return 2;
    }
    int total = 0;
    for (int i = first; i < argc; i++) {
        struct stat st;
        if (stat(argv[i], &st) != 0) {
            fprintf(stderr, "replay: no such file or directory '%s'\n", argv[i]);
            return 1;
        }
        int n;
        if (S_ISDIR(st.st_mode)) {
            n = replay_dir(argv[i]);
        } else {
            n = replay_file(argv[i]) == 0 ? 1 : -1;
        }
        if (n < 0) return 1;
        printf("%s: %d inputs\n", argv[i], n);
        total += n;
    }
    printf("replayed %d inputs", total);
    if (mutations > 0) printf(", and %ld with a --set by the mutator", mutated);
    printf("\n");
    return total > 0 ? 0 : 1;
}
