#include "core/progress.h"

#include "core/timer.h"

#include <unistd.h>

void progress_format_duration(double seconds, char *buf, int size) {
    if (seconds < 0 || seconds != seconds) {
        snprintf(buf, (size_t)size, "?");
    } else if (seconds < 60) {
        snprintf(buf, (size_t)size, "%.1fs", seconds);
    } else if (seconds < 3600) {
        snprintf(buf, (size_t)size, "%dm%02ds", (int)(seconds / 60), (int)seconds % 60);
    } else {
        snprintf(buf, (size_t)size, "%dh%02dm", (int)(seconds / 3600), (int)(seconds / 60) % 60);
    }
}

void progress_start(Progress *p, FILE *stream, double start_time, double end_time, bool enabled) {
    p->stream = stream;
    p->enabled = enabled;
    p->live = enabled && isatty(fileno(stream));
    p->end_time = end_time;
    p->start_fraction = end_time > 0 ? start_time / end_time : 0.0;
    p->wall_start = nspd_wall_time();
    p->last_draw = -1.0;
    p->last_decile = (int)(p->start_fraction * 10.0 + 1e-9);
}

static void draw(Progress *p, int64_t step, double time, double fraction, bool final) {
    double elapsed = nspd_wall_time() - p->wall_start;
    /* the rate of this process (a resumed run started part way) */
    const double done = fraction - p->start_fraction;
    double eta = done > 0 ? elapsed * (1.0 - fraction) / done : -1.0;
    char eta_text[32], elapsed_text[32];
    progress_format_duration(final ? 0.0 : eta, eta_text, sizeof eta_text);
    progress_format_duration(elapsed, elapsed_text, sizeof elapsed_text);
    fprintf(p->stream, "%sstep %lld  t = %.4e s  %5.1f %%  elapsed %s  ETA %s%s",
            p->live ? "\r" : "", (long long)step, time, 100.0 * fraction, elapsed_text, eta_text,
            p->live ? "\033[K" : "\n");
    fflush(p->stream);
}

void progress_update(Progress *p, int64_t step, double time) {
    if (!p->enabled || p->end_time <= 0) return;
    double fraction = time / p->end_time;
    if (fraction > 1) fraction = 1;
    if (p->live) {
        double now = nspd_wall_time();
        if (now - p->last_draw < 0.2) return;
        p->last_draw = now;
        draw(p, step, time, fraction, false);
    } else {
        int decile = (int)(fraction * 10.0 + 1e-9);
        if (decile > p->last_decile && decile < 10) {
            p->last_decile = decile;
            draw(p, step, time, fraction, false);
        }
    }
}

void progress_finish(Progress *p, int64_t step, double time) {
    if (!p->enabled) return;
    double fraction = p->end_time > 0 ? time / p->end_time : 1.0;
    draw(p, step, time, fraction > 1 ? 1 : fraction, true);
    if (p->live) fputc('\n', p->stream);
}
