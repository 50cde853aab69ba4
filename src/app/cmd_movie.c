/* nspd movie: a run's picture series (NAME_00000.png, NAME_00001.png, ...)
 * as an MP4 movie (H.264, yuv420p, so that browsers and slide software
 * play it), encoded by ffmpeg. nspd draws the frames; ffmpeg, a well-kept
 * encoder, does the video. The movie is written as NAME.mp4.part and
 * renamed when ffmpeg has finished, like every nspd output. */
#include "app/commands.h"

#include <dirent.h>
#include <errno.h>
#include <spawn.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

enum { MAX_SERIES = 64, MAX_NAME = 128, FRAME_DIGITS = 5, MAX_DIR = 4096 };
/* a path in the directory: the directory, a name, "_NNNNN.png" or ".mp4.part" */
enum { MAX_PATH = MAX_DIR + MAX_NAME + 32 };

/* "NAME_NNNNN.png" -> NAME; false for other names. */
static bool frame_name(const char *file, char *name, size_t size) {
    const size_t len = strlen(file);
    const size_t tail = 1 + FRAME_DIGITS + 4; /* "_NNNNN.png" */
    if (len <= tail || len - tail >= size || strcmp(file + len - 4, ".png") != 0) return false;
    const char *digits = file + len - 4 - FRAME_DIGITS;
    if (digits[-1] != '_') return false;
    for (int k = 0; k < FRAME_DIGITS; k++)
        if (digits[k] < '0' || digits[k] > '9') return false;
    memcpy(name, file, len - tail);
    name[len - tail] = '\0';
    return true;
}

typedef struct {
    char name[MAX_NAME];
    long frames; /* frames 0 .. frames-1 are all there */
} Series;

/* The picture series of dir whose frames run without a gap from 0. */
static int find_series(const char *dir, Series *out, int *count) {
    DIR *d = opendir(dir);
    if (!d) {
        fprintf(stderr, "nspd movie: cannot read '%s' (%s); expected a run's output directory\n",
                dir, strerror(errno));
        return EXIT_BAD_INPUT;
    }
    *count = 0;
    struct dirent *e;
    char name[MAX_NAME];
    while ((e = readdir(d))) {
        if (!frame_name(e->d_name, name, sizeof name)) continue;
        int k = 0;
        while (k < *count && strcmp(out[k].name, name) != 0) k++;
        if (k == *count) {
            if (*count == MAX_SERIES) continue;
            snprintf(out[k].name, sizeof out[k].name, "%s", name);
            out[k].frames = 0;
            (*count)++;
        }
    }
    closedir(d);
    /* frames counted from 0 while the next one exists */
    for (int k = 0; k < *count; k++) {
        char path[MAX_PATH];
        struct stat st;
        for (;;) {
            snprintf(path, sizeof path, "%.4000s/%.120s_%05ld.png", dir, out[k].name,
                     out[k].frames);
            if (stat(path, &st) != 0) break;
            out[k].frames++;
        }
    }
    return 0;
}

/* ffmpeg -framerate fps -i dir/name_%05d.png ... out.part; 0 or a message. */
static int encode(const char *dir, const Series *s, double fps, const char *out) {
    char input[MAX_PATH], rate[32], part[MAX_PATH];
    snprintf(input, sizeof input, "%.4000s/%.120s_%%05d.png", dir, s->name);
    snprintf(rate, sizeof rate, "%g", fps);
    snprintf(part, sizeof part, "%.4000s/%.120s.mp4.part", dir, s->name);
    /* even width and height (yuv420p needs them), padded, not scaled */
    char *const argv[] = {"ffmpeg",
                          "-nostdin",
                          "-y",
                          "-loglevel",
                          "error",
                          "-framerate",
                          rate,
                          "-start_number",
                          "0",
                          "-i",
                          input,
                          "-vf",
                          "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                          "-c:v",
                          "libx264",
                          "-pix_fmt",
                          "yuv420p",
                          "-movflags",
                          "+faststart",
                          "-f",
                          "mp4",
                          part,
                          NULL};
    pid_t pid;
    const int err = posix_spawnp(&pid, "ffmpeg", NULL, NULL, argv, environ);
    if (err != 0) {
        fprintf(stderr,
                "nspd movie: cannot run ffmpeg (%s); expected ffmpeg on the PATH (Debian: "
                "apt-get install ffmpeg, or scripts/deps.sh build)\n",
                strerror(err));
        return EXIT_RUN_FAILED;
    }
    int status;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return EXIT_RUN_FAILED;
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        remove(part);
        fprintf(stderr, "nspd movie: ffmpeg failed on %s (status %d); no movie written\n", input,
                WIFEXITED(status) ? WEXITSTATUS(status) : -1);
        return EXIT_RUN_FAILED;
    }
    if (rename(part, out) != 0) {
        fprintf(stderr, "nspd movie: cannot write '%s' (%s)\n", out, strerror(errno));
        remove(part);
        return EXIT_RUN_FAILED;
    }
    return 0;
}

int cmd_movie(int argc, char **argv) {
    const char *dir = NULL, *field = NULL;
    double fps = 10.0;
    for (int i = 0; i < argc; i++) {
        if (strcmp(argv[i], "--field") == 0 && i + 1 < argc) {
            field = argv[++i];
        } else if (strcmp(argv[i], "--fps") == 0 && i + 1 < argc) {
            char *end;
            fps = strtod(argv[++i], &end);
            if (*end != '\0' || !(fps >= 0.1 && fps <= 120)) {
                fprintf(stderr, "nspd movie: --fps needs frames per second, 0.1 to 120\n");
                return EXIT_BAD_INPUT;
            }
        } else if (argv[i][0] != '-' && !dir) {
            dir = argv[i];
        } else {
            fprintf(stderr, "nspd movie: unexpected '%s'\n", argv[i]);
            command_usage(stderr, command_help("movie"), false);
            return EXIT_BAD_INPUT;
        }
    }
    if (dir && strlen(dir) > 4000) { /* the paths below print at most 4000 of it */
        fprintf(stderr, "nspd movie: the directory name is too long\n");
        return EXIT_BAD_INPUT;
    }
    if (!dir) {
        fprintf(stderr, "nspd movie: which run?\n");
        command_usage(stderr, command_help("movie"), false);
        return EXIT_BAD_INPUT;
    }
    Series series[MAX_SERIES];
    int count;
    const int found = find_series(dir, series, &count);
    if (found != 0) return found;
    int made = 0;
    for (int k = 0; k < count; k++) {
        if (field && strcmp(series[k].name, field) != 0) continue;
        if (series[k].frames < 2) {
            if (field) {
                fprintf(stderr,
                        "nspd movie: '%s' has %ld frame(s) from %s_00000.png; expected "
                        "at least 2\n",
                        series[k].name, series[k].frames, series[k].name);
                return EXIT_BAD_INPUT;
            }
            continue;
        }
        char out[MAX_PATH];
        snprintf(out, sizeof out, "%.4000s/%.120s.mp4", dir, series[k].name);
        const int status = encode(dir, &series[k], fps, out);
        if (status != 0) return status;
        printf("%s: %ld frames at %g per second\n", out, series[k].frames, fps);
        made++;
    }
    if (made == 0) {
        fprintf(stderr,
                "nspd movie: no picture series %s%sin '%s' (NAME_00000.png, "
                "NAME_00001.png, ...)\n",
                field ? field : "", field ? " " : "", dir);
        return EXIT_BAD_INPUT;
    }
    return 0;
}
